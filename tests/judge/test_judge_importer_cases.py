"""What real importers tripped on, and the rules that answer it.

- FMI4j writes t = k h and calls ``doStep(k h, h)``: the FMU's clock is fl(k h + h), one ulp
  from the written fl((k + 1) h) in about a third of the rows. The exact columns' allowance
  holds the time's own rounding at any time (runs of 100 s at h = 0.01 and 0.001 pass; a shift
  of ten ulps still fails).
- A Model Exchange file judged as Co-Simulation is named as one: fmpy's CVODE at the tolerance
  or explicit Euler at h reproduces it.
- One wild value in a smooth Model Exchange error curve fails the isolated-values check, at
  any row where the solution is smooth, while the unedited run passes.
- A gzipped CSV reads as the CSV.
"""

from __future__ import annotations

import gzip
import math
import random
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu

from pendulum_fmu.fmu.library import exact
from pendulum_fmu.judge import judge
from pendulum_fmu.judge.reading import read_result

OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact"]


def fmi4j_like(theta0: float, h: float, stop: float, shift_ulps: int = 0) -> dict[str, np.ndarray]:
    """A Co-Simulation run as FMI4j writes it: times k h, every column the FMU's value at its own
    clock fl(k h + h) (the exact solution, which the FMU's exact outputs equal bit for bit)."""
    n = round(stop / h)
    k = np.arange(n + 1, dtype=float)
    written = k * h
    clock = np.concatenate(([0.0], k[:-1] * h + h))
    if shift_ulps:
        clock = clock + shift_ulps * np.spacing(np.abs(clock))
    theta, omega = exact(theta0, 0.0, 1.0, 9.81, clock)
    return {"time": written, "theta": theta, "omega": omega, "theta_exact": theta, "omega_exact": omega}


@pytest.mark.parametrize("h", [0.01, 0.001])
@pytest.mark.parametrize("degrees", [75.0, 170.0])
def test_fmi4j_times_one_ulp_from_the_clock_pass(h: float, degrees: float) -> None:
    run = fmi4j_like(math.radians(degrees), h, 100.0)
    k = np.arange(1, run["time"].size, dtype=float)
    differ = np.mean((k - 1) * h + h != k * h)
    assert 0.2 < differ < 0.5   # about a third of the rows are one ulp off
    verdict = judge(run, start={"theta": math.radians(degrees)})
    assert verdict.passed, verdict.line
    assert verdict.check("exact columns").status == "pass"


def test_values_ten_ulps_off_their_times_still_fail() -> None:
    run = fmi4j_like(math.radians(75.0), 0.01, 100.0, shift_ulps=10)
    verdict = judge(run)
    assert not verdict.passed and verdict.check("exact columns").status == "fail", verdict.line


@pytest.fixture(scope="module")
def cvode_run(fmu_path: Path) -> dict[str, np.ndarray]:
    """fmpy's CVODE at 1e-8, 0..10 s at 0.01 s (1001 rows), 75 deg from rest."""
    r = simulate_fmu(str(fmu_path), fmi_type="ModelExchange", solver="CVode", relative_tolerance=1e-8,
                     stop_time=10.0, output_interval=0.01, output=OUTPUTS)
    return {name: np.array(r[name]) for name in r.dtype.names}


def test_an_unedited_cvode_run_passes(cvode_run: dict[str, np.ndarray]) -> None:
    verdict = judge(cvode_run, start={"tolerance": 1e-8}, interface="ME")
    assert verdict.passed, verdict.line


def test_one_value_moved_by_1e_6_at_5_s_fails(cvode_run: dict[str, np.ndarray]) -> None:
    """The reproducer: theta at t = 5 s moved by 1e-6 rad, an error of 8.9e-7 between neighbours
    at -1.1e-7."""
    edited = {name: values.copy() for name, values in cvode_run.items()}
    edited["theta"][500] += 1e-6
    error = edited["theta"] - edited["theta_exact"]
    assert error[500] > 0 > max(error[499], error[501])
    verdict = judge(edited, start={"tolerance": 1e-8}, interface="ME")
    check = verdict.check("isolated values")
    assert check.status == "fail" and check.numbers["at_time"] == pytest.approx(5.0), check.line
    assert verdict.line.startswith("FAIL (isolated values)")


def test_a_wild_value_anywhere_fails(cvode_run: dict[str, np.ndarray]) -> None:
    """Rows and sizes drawn at random (seeded): a value whose error is set to 4 to 20 times its
    neighbours', with the other sign, theta or omega, away from the error's zero crossings
    (there the neighbours have no common sign to stand against; a value 100 times off is
    caught there by the first rule)."""
    rng = random.Random(37_0003)
    tried = 0
    while tried < 20:
        row = rng.randrange(20, 980)
        name = rng.choice(("theta", "omega"))
        edited = {key: values.copy() for key, values in cvode_run.items()}
        error = edited[name] - edited[f"{name}_exact"]
        before, after = error[row - 1], error[row + 1]
        if before * after <= 0 or min(abs(before), abs(after)) < 0.5 * max(abs(before), abs(after)):
            continue
        tried += 1
        near = max(abs(before), abs(after))
        edited[name][row] += -math.copysign(rng.uniform(4.0, 20.0) * near, before) - error[row]
        verdict = judge(edited, start={"tolerance": 1e-8}, interface="ME")
        assert verdict.check("isolated values").status == "fail", (name, row, verdict.line)


@pytest.mark.parametrize(("solver", "tolerance", "named"), [("CVode", 1e-6, "CVODE at tolerance 1e-06"),
                                                           ("Euler", 1e-6, "explicit Euler at h = 0.01")])
def test_a_model_exchange_file_judged_as_co_simulation_is_named(fmu_path: Path, solver: str, tolerance: float,
                                                                named: str) -> None:
    r = simulate_fmu(str(fmu_path), fmi_type="ModelExchange", solver=solver, relative_tolerance=tolerance,
                     stop_time=100.0 if solver == "CVode" else 10.0, output_interval=0.01, step_size=0.01,
                     output=OUTPUTS)
    data = {name: np.array(r[name]) for name in r.dtype.names}
    verdict = judge(data, start={"tolerance": tolerance}, fmu=fmu_path)
    assert not verdict.passed
    assert f"this is a Model Exchange run of {named}" in verdict.line, verdict.line
    assert "judge it with --interface ME" in verdict.line
    assert verdict.check("diagnosis").numbers["cause"] == "model exchange"
    if solver == "CVode":
        assert judge(data, start={"tolerance": tolerance}, interface="ME", fmu=fmu_path).passed


def test_a_gzipped_csv_reads_as_the_csv(tmp_path: Path, cvode_run: dict[str, np.ndarray]) -> None:
    lines = ["time,theta,omega"] + [f"{float(t)!r},{float(a)!r},{float(b)!r}" for t, a, b in
                                    zip(cvode_run["time"], cvode_run["theta"], cvode_run["omega"], strict=True)]
    plain = tmp_path / "run.csv"
    plain.write_text("\n".join(lines) + "\n")
    zipped = tmp_path / "artifact.bin"   # by its signature, whatever its name
    zipped.write_bytes(gzip.compress(plain.read_bytes()))
    a, b = read_result(plain), read_result(zipped)
    assert np.array_equal(a.time, b.time) and all(np.array_equal(a.values[k], b.values[k]) for k in a.values)
    assert judge(zipped, start={"tolerance": 1e-8}, interface="ME").passed
    broken = tmp_path / "broken.csv.gz"
    broken.write_bytes(gzip.compress(plain.read_bytes())[:-40])
    with pytest.raises(Exception, match="cannot be uncompressed"):
        read_result(broken)
