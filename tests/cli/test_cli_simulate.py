"""``simulate`` and ``compare`` on small inputs: the files written and their numbers."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest
from PIL import Image
from scipy.special import ellipk

from pendulum_fmu.cli.main import main
from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.output.tables import read_table
from pendulum_fmu.spec import CS_SOLVERS, InitialValueProblem, Method, TimeGrid


def exact_period(amplitude_rad: float, length: float, gravity: float = 9.81) -> float:
    """4 K(m) / w0, m = sin^2(theta0 / 2), released from rest."""
    return 4.0 * float(ellipk(math.sin(amplitude_rad / 2.0) ** 2)) / math.sqrt(gravity / length)


def test_simulate_writes_a_csv_whose_time_span_is_whole_exact_periods(fmu_path: Path, tmp_path: Path,
                                                                       capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "run.csv"
    assert main(["simulate", "--amplitude", "85", "--length", "2", "--periods", "3", "--points-per-period", "20",
                 "--out", str(out), "--fmu", str(fmu_path)]) == 0
    table = read_table(out).to_pydict()
    assert list(table) == ["time_s", "theta_rad", "omega_rad_s", "theta_exact_rad", "omega_exact_rad_s", "x_m",
                           "y_m", "theta_error_rad"]
    time, theta, exact = (np.array(table[c]) for c in ("time_s", "theta_rad", "theta_exact_rad"))
    period = exact_period(math.radians(85.0), 2.0)
    assert time.size == 61
    assert time[-1] == pytest.approx(3 * period, rel=1e-13)
    assert np.allclose(np.diff(time), period / 20, rtol=1e-9)
    assert theta[0] == math.radians(85.0)
    assert np.max(np.abs(theta - exact)) < 1e-7
    assert np.array_equal(np.array(table["theta_error_rad"]), theta - exact)
    assert np.allclose(table["x_m"], 2.0 * np.sin(theta), atol=1e-14)
    assert np.allclose(table["y_m"], -2.0 * np.cos(theta), atol=1e-14)
    # after whole periods the pendulum is back where it started
    assert theta[-1] == pytest.approx(math.radians(85.0), abs=1e-7)
    printed = capsys.readouterr().out
    assert f"period    {period:.9g} s" in printed and "written   " in printed


def test_simulate_model_exchange_to_parquet_with_the_run_in_its_metadata(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "run.parquet"
    assert main(["simulate", "-a", "1.2rad", "-L", "0.5", "-g", "3.7", "--interface", "ME", "--tolerance", "1e-10",
                 "-p", "2", "-o", str(out), "--fmu", str(fmu_path)]) == 0
    table = pq.read_table(out)
    meta = {k.decode(): v.decode() for k, v in table.schema.metadata.items()}
    assert meta["interface"] == "ME" and meta["solver"] == "cvode" and float(meta["tolerance"]) == 1e-10
    assert float(meta["period_s"]) == pytest.approx(exact_period(1.2, 0.5, 3.7), rel=1e-13)
    theta = table.column("theta_rad").to_numpy()
    assert theta[0] == 1.2
    assert np.max(np.abs(theta - table.column("theta_exact_rad").to_numpy())) < 1e-6


def test_simulate_stop_time_in_seconds_ends_there(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "run.csv"
    assert main(["simulate", "--stop-time", "1.7", "--solver", "rkn", "--out", str(out), "--fmu", str(fmu_path)]) == 0
    time = np.array(read_table(out).column("time_s"))
    assert time[-1] == 1.7 and time[0] == 0.0 and np.all(np.diff(time) > 0)


def test_every_cosimulation_solver_is_the_one_run(fmu_path: Path) -> None:
    """Each solver name reaches the FMU: different step counts, each within its tolerance."""
    counts = {}
    with FmuRunner(fmu_path) as runner:
        for solver in CS_SOLVERS:
            run = runner.run(InitialValueProblem.from_degrees(80.0), Method(solver, 1e-8), TimeGrid(2, "periods"))
            counts[solver] = (run.steps, run.rhs_evaluations)
            assert run.max_error < 1e-5, solver
    assert len(set(counts.values())) == len(CS_SOLVERS), counts


def test_compare_writes_one_png(fmu_path: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "compare.png"
    assert main(["compare", "-a", "170", "--solver", "rk4", "--tolerance", "1e-6", "-p", "3", "--out", str(out),
                 "--fmu", str(fmu_path)]) == 0
    with Image.open(out) as image:
        assert image.format == "PNG" and image.size[0] >= 1000
    printed = capsys.readouterr().out
    assert "method    CS rk4, tol 1e-06" in printed
    assert "max |theta - theta_exact| = " in printed


@pytest.mark.parametrize("solver", ["rkn", "cvode"])
def test_simulate_reads_the_fmu_once_and_initializes_it_once(fmu_path: Path, tmp_path: Path, solver: str,
                                                             monkeypatch: pytest.MonkeyPatch,
                                                             capsys: pytest.CaptureFixture[str]) -> None:
    """--fmu's check, the FMI version and the runner share one reading of the model description;
    the size check reads the period of the run's own initialization."""
    import fmpy

    from pendulum_fmu.fmu import identity, locate

    copy = tmp_path / "Pendulum.fmu"   # a file no earlier test has read
    copy.write_bytes(fmu_path.read_bytes())
    identity._read_description.cache_clear()
    locate._runnable_problem.cache_clear()
    readings: list[object] = []
    read = fmpy.read_model_description
    monkeypatch.setattr(fmpy, "read_model_description", lambda *a, **k: readings.append(a) or read(*a, **k))
    initializations: list[object] = []
    initialize = FmuRunner._initialize
    monkeypatch.setattr(FmuRunner, "_initialize",
                        lambda runner, *args: initializations.append(args) or initialize(runner, *args))
    assert main(["simulate", "-p", "1", "-s", solver, "--fmu", str(copy), "--fmi-version", "2"]) == 0
    assert "max |theta - theta_exact|" in capsys.readouterr().out
    assert len(readings) == 1
    assert len(initializations) == 1   # Model Exchange: fmpy's simulate_fmu initializes once more, itself
