"""``pendulum-fmu judge RESULT --system split``: files the judge did not make itself.

The files come from tests/helpers/split_closed_form.py and tests/helpers/split_corpus.py (masters written again
without the FMUs or the package's master code, with planted defects), at other macro steps,
start values, column names and prints. Three answers are checked apart: conformance (each
planted defect named with its evidence, honest masters conformant), identification (the
reference master reproduced, or a master of its own), accuracy (the error against
pendulum_fmu.exact, its rank, the order over several runs; pass/fail only on a stated criterion).
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from pendulum_fmu import exact
from pendulum_fmu.cli.main import main
from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.grid import read_grid
from pendulum_fmu.split.judge import judge_runs, judge_split, reported_seconds
from pendulum_fmu.split.masters import MASTERS, Master
from pendulum_fmu.split.pair import DEFAULT_PROBLEM
from split_closed_form import exact_columns, simulate, write_csv
from split_corpus import Setup, run, write

THETA0 = math.radians(120)
OMEGA0 = 0.5
L = 2.0
SSP_THETA0 = 1.3089969389957472
SIX = [m for m in MASTERS if m.scheme in ("jacobi", "gauss-seidel")]  # the non-iterating masters
"""The masters tests/helpers/split_closed_form.py writes again (a master added to the registry is judged,
but not written again here)."""


@pytest.mark.parametrize("H", [0.02, 0.005])
@pytest.mark.parametrize("master", SIX, ids=lambda m: m.name)
def test_names_each_master(master: Master, H: float, tmp_path: Path) -> None:
    """120 deg, omega0 0.5 rad/s, L = 2 (given with --start), 1.5 s: conformant, named, and its
    error is that master's on the same rows (the rank says so)."""
    run_ = simulate(master.scheme, master.coupling, H, 1.5, THETA0, OMEGA0, L)
    path = write_csv(run_, tmp_path / "run.csv", names=("Time", "pendulum/theta", "pendulum/omega"), delimiter=";")
    verdict = judge_split(path, problem=InitialValueProblem(THETA0, OMEGA0, 2.0))
    assert verdict.master == master.name, verdict.lines
    assert verdict.H == H
    assert verdict.conformance.passed, verdict.lines
    assert verdict.passed  # no criterion stated: accuracy decides nothing
    assert verdict.error == pytest.approx(verdict.reference_errors[master.name], rel=1e-9)
    assert verdict.accuracy.rank.startswith(f"as {master.describe()}")
    assert verdict.summary.startswith(f"conformant; behaves as {master.describe()}; error ")


def test_the_macro_step_is_read_exactly() -> None:
    """Times made by adding H in binary (an engine's loop) or printed with 6 digits: H is the
    decimal the engine was given, where the median of the differences is off."""
    for H in (1e-4, 1e-5, 0.01, 0.002):
        n = round(1.0 / H)
        added = np.cumsum(np.concatenate(([0.0], np.full(n, H))))
        assert float(np.median(np.diff(added))) != H or H == 0.01
        grid = read_grid(added, np.zeros(added.size))
        assert grid.H == H and grid.index is not None and grid.index[-1] == n
        printed = np.array([float(f"{t:.6g}") for t in added])
        grid = read_grid(printed, np.array([5 * 10.0 ** (math.floor(math.log10(max(t, 1e-300))) - 6) for t in printed]))
        assert grid.H == H
    variable = np.cumsum(np.concatenate(([0.0], 0.01 * (1 + 0.3 * np.sin(np.arange(200))))))
    assert read_grid(variable, np.zeros(variable.size)).H is None


def test_a_short_print_is_judged_to_its_resolution(tmp_path: Path) -> None:
    """Gauss-Seidel with interpolation at H = 0.01 over 10 s printed with %.6g: identified (the
    print's rounding is in the match), conformant."""
    r = simulate("gauss-seidel", "interpolation", 0.01, 10.0)
    path = write(tmp_path / "short.csv", r.time, r.theta, r.omega, 0, "%.6g")
    verdict = judge_split(path)
    assert verdict.master == "gauss-seidel-interpolation" and verdict.conformance.passed, verdict.lines


def _kinds(path: Path) -> list[str]:
    return [f.kind for f in judge_split(path).findings]


@pytest.mark.parametrize(("defect", "kind", "evidence"), [
    ({"lag": 2}, "stale", "one exchange old at 198 of 200 steps"),
    ({"drop": True}, "dropped", "stayed -9.47573236 rad/s2 over every step"),
    ({"early_labels": True}, "labels", "Body.theta_exact is the exact pendulum at t + H"),
])
def test_each_planted_defect_is_named_with_its_evidence(tmp_path: Path, defect: dict[str, object], kind: str,
                                                        evidence: str) -> None:
    r = simulate("gauss-seidel", "zoh", 0.01, 2.0, **defect)  # type: ignore[arg-type]
    shift = 0.01 if defect.get("early_labels") else 0.0
    path = write_csv(r, tmp_path / "planted.csv", exact=exact_columns(r, SSP_THETA0, 0.0, 1.0, 9.81, shift=shift))
    verdict = judge_split(path)
    assert not verdict.passed and [f.kind for f in verdict.findings] == [kind], verdict.lines
    assert evidence in verdict.findings[0].line, verdict.findings[0].line
    assert verdict.lines[-1].startswith(f"summary         FAIL  not conformant: {kind}; ")


def test_mismatches_the_old_match_let_through(tmp_path: Path) -> None:
    """Gravity with g = 9.80 (Body 9.81) and Jacobi with 1 % of its inputs stale, at H = 0.01:
    each within 1 % of Jacobi's own error, each a defect named with its size."""
    times, theta, omega = run(Setup("jacobi-zoh", 0.01, 10.0, g_gravity=9.80))
    verdict = judge_split(write(tmp_path / "g.csv", times, theta, omega, 0, "repr"))
    assert [f.kind for f in verdict.findings] == ["parameter"], verdict.lines
    assert "g/L = 9.8 1/s2 where Body's pendulum has 9.81 (ratio 0.998981)" in verdict.findings[0].line
    stale = frozenset(range(5, 1000, 100))
    times, theta, omega = run(Setup("jacobi-zoh", 0.01, 10.0, stale_at=stale))
    verdict = judge_split(write(tmp_path / "s.csv", times, theta, omega, 0, "repr"))
    assert [f.kind for f in verdict.findings] == ["stale"], verdict.lines
    assert "one exchange old at 10 of 1000 steps (1 %; by 1 at 10; first at step 5)" in verdict.findings[0].line


@pytest.mark.parametrize(("planted", "kind", "evidence"), [
    ({"sign": -1.0}, "sign", "wrong sign"),
    ({"signal": "omega", "omega0": 0.5}, "connection", "Gravity's input theta is fed Body's omega"),
    ({"L_gravity": 2.0}, "parameter", "Gravity's L = 2 times Body's"),
])
@pytest.mark.parametrize("master", ["gs-zoh", "strong"])
def test_wrong_systems_are_named(tmp_path: Path, planted: dict[str, float], kind: str, evidence: str,
                                 master: str) -> None:
    """Read back from the inputs Body held, to round-off (zero-order hold) or on average (strong coupling)."""
    setup = Setup(master, 0.01, 2.0)
    for name, value in planted.items():
        setattr(setup, name, value)
    path = write(tmp_path / "w.csv", *run(setup), 0, "repr")
    verdict = judge_split(path, problem=replace(DEFAULT_PROBLEM, omega0=setup.omega0))
    assert [f.kind for f in verdict.findings] == [kind], verdict.lines
    assert evidence in verdict.findings[0].line


def test_rows_out_of_order_doubled_missing_or_shifted(tmp_path: Path) -> None:
    times, theta, omega = run(Setup("gs-zoh", 0.01, 1.0))
    cut = (times[:40] + times[41:], theta[:40] + theta[41:], omega[:40] + omega[41:])
    verdict = judge_split(write(tmp_path / "m.csv", *cut, 0, "repr"))
    assert [f.kind for f in verdict.findings] == ["missing"] and "no row at t = 0.4 s" in verdict.findings[0].line
    twice = (times[:40] + times[39:], theta[:40] + theta[39:], omega[:40] + omega[39:])
    assert _kinds(write(tmp_path / "d.csv", *twice, 0, "repr")) == ["doubled"]
    swapped = [list(c) for c in (times, theta, omega)]
    for c in swapped:
        c[30], c[31] = c[31], c[30]
    assert _kinds(write(tmp_path / "o.csv", *swapped, 0, "repr")) == ["out-of-order"]
    early = (times[:-1], theta[1:], omega[1:])  # no theta_exact column: the row at t = 0 tells
    assert _kinds(write(tmp_path / "e.csv", *early, 0, "repr")) == ["labels"]
    late = (times[1:], theta[:-1], omega[:-1])
    assert _kinds(write(tmp_path / "l.csv", *late, 0, "repr")) == ["labels"]


def test_a_value_that_is_not_a_number_is_a_finding(tmp_path: Path) -> None:
    times, theta, omega = run(Setup("gs-zoh", 0.01, 1.0))
    theta[50] = math.nan
    verdict = judge_split(write(tmp_path / "nan.csv", times, theta, omega, 0, "repr"))
    assert [f.kind for f in verdict.findings] == ["not-finite"] and "t = 0.5 s" in verdict.findings[0].line
    assert math.isfinite(verdict.error)
    at_rest = run(Setup("gs-zoh", 0.01, 1.0, theta0=0.0))  # Gravity's alpha is 0 throughout: not a dropped input
    rest = replace(DEFAULT_PROBLEM, theta0=0.0)
    assert judge_split(write(tmp_path / "rest.csv", *at_rest, 0, "repr"), problem=rest).conformance.passed


def test_another_start_is_a_finding_never_a_silent_new_start(tmp_path: Path) -> None:
    times, theta, omega = run(Setup("gs-zoh", 0.01, 2.0, theta0=math.radians(80)))
    path = write(tmp_path / "80.csv", times, theta, omega, 0, "repr")
    verdict = judge_split(path)
    assert [f.kind for f in verdict.findings] == ["start"] and "80 deg" in verdict.findings[0].line
    reference = exact(SSP_THETA0, 0.0, 1.0, 9.81, np.array(times))[0]
    assert verdict.error == pytest.approx(float(np.max(np.abs(np.array(theta) - reference))), rel=1e-12)
    assert verdict.master == "gauss-seidel-zoh"  # rerun from the file's own start, said so
    stated = judge_split(path, problem=replace(DEFAULT_PROBLEM, theta0=math.radians(80.0)))
    assert stated.conformance.passed and stated.master == "gauss-seidel-zoh", stated.lines


@pytest.mark.parametrize(("setup", "own"), [
    (Setup("gs-interp1", 0.01, 3.0), "a master of its own"),
    (Setup("jacobi-past2", 0.01, 3.0), "a master of its own"),
    (Setup("gs-zoh", 0.01, 2.0, multirate=2), "multirate: Body's input refreshed every 2 macro steps"),
    (Setup("gs-interp1", 0.01, 2.0, variable=True), "variable macro step"),
])
def test_honest_masters_of_their_own_are_conformant(tmp_path: Path, setup: Setup, own: str) -> None:
    verdict = judge_split(write(tmp_path / "own.csv", *run(setup), 1, "%.12g"))
    assert verdict.conformance.passed and verdict.passed, verdict.lines
    assert verdict.master is None and own in verdict.identification.text
    assert ("not ranked" in verdict.lines[-2]) == setup.variable, verdict.lines


def test_a_strong_coupling_master_is_the_iterated_reference_and_better_than_the_six(tmp_path: Path) -> None:
    """A strong-coupling master written here (each step iterated to a fixed point) reproduces the
    registry's iterated master to round-off, and is three times better than the best of the six."""
    verdict = judge_split(write(tmp_path / "strong.csv", *run(Setup("strong", 0.01, 10.0)), 0, "repr"))
    assert verdict.conformance.passed and verdict.master == "iterated-interpolation", verdict.lines
    six = [verdict.reference_errors[m.name] for m in SIX]
    assert verdict.error == pytest.approx(2.15e-5, rel=0.01) and verdict.error < min(six) / 3, verdict.lines


def test_decimated_output_is_identified_at_its_macro_step(tmp_path: Path) -> None:
    times, theta, omega = run(Setup("gs-zoh", 0.002, 2.0))
    path = write(tmp_path / "dec.csv", times[::5], theta[::5], omega[::5], 0, "repr")
    verdict = judge_split(path)
    assert verdict.conformance.passed and verdict.master == "gauss-seidel-zoh", verdict.lines
    assert verdict.identification.H == 0.002 and verdict.identification.every == 5
    assert judge_split(path, step=0.002).master == "gauss-seidel-zoh"


def test_accuracy_decides_only_on_a_stated_criterion(tmp_path: Path) -> None:
    paths = []
    for H in (0.02, 0.01, 0.005, 0.0025):
        r = simulate("jacobi", "zoh", H, 2.0)
        paths.append(write_csv(r, tmp_path / f"j{H}.csv"))
    single = judge_split(paths[1])
    assert single.passed and single.summary.startswith("conformant; behaves as Jacobi with zero-order hold; error ")
    assert not judge_split(paths[1], max_error=single.error / 2).passed
    assert judge_split(paths[1], max_error=single.error * 2).passed
    assert not judge_split(paths[1], master="gauss-seidel-zoh").passed
    for path, seconds in zip(paths, (0.5, 1.1, 2.3, 4.4), strict=True):  # an engine's wall time, in its header
        path.write_text(f"# engine X, wall time = {seconds}\n" + path.read_text())
    runs = judge_runs(paths, order=1.0)
    assert [reported_seconds(p) for p in paths] == [0.5, 1.1, 2.3, 4.4]  # read from the files, not timed
    assert "H = 0.01: " in runs.lines[-4] and " rad in 1.1 s" in runs.lines[-4], runs.lines
    assert runs.order is not None and runs.order.runs == 4 and 0.8 < runs.order.order < 1.3, runs.lines
    assert runs.passed and runs.summary.endswith(f"(order {runs.order.order:.1f} over 4 runs)"), runs.summary
    assert not judge_runs(paths, order=2.0).passed


def test_command_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write_csv(simulate("gauss-seidel", "zoh", 0.01, 0.5), tmp_path / "gs.csv")
    assert main(["judge", str(path), "--system", "split", "--master", "euler"]) == 2
    assert main(["judge", str(tmp_path / "missing.csv"), "--system", "split"]) == 2
    with pytest.raises(SystemExit, match="2"):  # a usage error: argparse's one line and exit
        main(["judge", str(path), "--system", "split", "--start", "mass=3"])
    assert main(["judge", str(path), "--system", "split", "--interface", "ME"]) == 2
    assert main(["judge", str(path), str(path)]) == 2
    assert main(["judge", str(path), "--system", "split", "--order", "1"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 5 and all(line.startswith("pendulum-fmu judge: ") for line in err), err
    report, figure = tmp_path / "v.json", tmp_path / "v.png"
    assert main(["judge", str(path), "--system", "split", "--json", str(report), "--plot", str(figure),
                 "--step", "0.01"]) == 0
    out = capsys.readouterr().out
    assert "identification  INFO  behaves as Gauss-Seidel with zero-order hold at H = 0.01" in out
    assert "summary         PASS  conformant; behaves as Gauss-Seidel with zero-order hold" in out
    data = json.loads(report.read_text())
    assert data["conformance"]["passed"] and data["identification"]["master"] == "gauss-seidel-zoh"
    assert data["accuracy"]["error"] == pytest.approx(judge_split(path).error, rel=1e-15)
    assert figure.stat().st_size > 10_000
    folder = tmp_path / "runs"
    folder.mkdir()
    for H in (0.02, 0.01):
        write_csv(simulate("gauss-seidel", "zoh", H, 1.0), folder / f"{H}.csv")
    assert main(["judge", str(folder), "--system", "split", "--json", str(report)]) == 0
    assert "order" in capsys.readouterr().out and len(json.loads(report.read_text())["runs"]) == 2
