"""The speed-against-error study's machinery: work-precision arithmetic, the C driver against
fmpy on the same runs, and a quick run of ``bench solvers``."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from fmpy import extract

from pendulum_fmu.bench.workprecision.analysis import Point, aggregate, cost_at, front
from pendulum_fmu.bench.workprecision.cdriver import parse, run_driver, shared_library
from pendulum_fmu.bench.workprecision.problems import cases, energy_errors, make_grid
from pendulum_fmu.bench.workprecision.runs import Run, run_fmu_cs, run_solve_ivp
from pendulum_fmu.cli.main import main


def _point(err: float, evals: int, tol: float = 1e-6) -> Point:
    return Point(problem="P1", runner="c", method="m", tol=tol, status="ok", max_err=err, rhs_evaluations=evals,
                 wall_s=evals * 1e-8, periods=40.0, energy_err_max=0.0, energy_err_first=0.0, energy_err_last=0.0,
                 flipped=False, rejected=0)


def test_front_drops_points_a_cheaper_one_beats() -> None:
    points = [_point(1e-2, 100), _point(1e-3, 300), _point(1e-4, 200), _point(1e-8, 400)]
    assert front(points) == [(1e-2, 100.0), (1e-4, 200.0), (1e-8, 400.0)]


def test_cost_at_interpolates_in_log_log_and_knows_what_is_out_of_reach() -> None:
    points = [_point(1e-2, 100), _point(1e-4, 200), _point(1e-8, 400)]
    assert cost_at(points, 1e-6) == pytest.approx(math.sqrt(200 * 400), rel=1e-12)
    assert cost_at(points, 1e-4) == pytest.approx(200.0, rel=1e-12)
    assert cost_at(points, 1e-1) == 100.0  # already below: the cheapest run
    assert cost_at(points, 1e-9) == math.inf
    assert cost_at(points, 1e-6, "wall_per_period") == pytest.approx(math.sqrt(200 * 400) * 1e-8 / 40, rel=1e-12)


def test_aggregate_takes_the_worst_error_and_sums_the_cost() -> None:
    runs = [Run("P1", a, 10.0, "c", "rkn", 1e-8, rhs_evaluations=100 + i, max_err=e, energy_err_max=0.0,
                energy_err_first=0.0, energy_err_last=0.0, max_abs_theta=1.0, wall_s=1.0)
            for i, (a, e) in enumerate(zip((75.0, 80.0, 85.0, 90.0), (1e-9, 3e-9, 2e-9, 1e-10), strict=True))]
    (p,) = aggregate(runs)
    assert (p.max_err, p.rhs_evaluations, p.periods, p.wall_per_period) == (3e-9, 406, 40.0, 0.1)
    runs[2].status = "skipped"
    (p,) = aggregate(runs)
    assert p.status == "skipped" and math.isnan(p.max_err)


def test_energy_errors_of_the_exact_motion_are_rounding() -> None:
    # theta = 2 asin(k sn), omega = 2 k w0 cn at 90 deg, from scipy: H stays at H0
    from scipy.special import ellipj, ellipk

    w0, k = math.sqrt(9.81), math.sin(math.radians(45.0))
    t = np.linspace(0.0, 4 * ellipk(k * k) / w0, 200)
    sn, cn, _, _ = ellipj(w0 * t + ellipk(k * k), k * k)
    theta, omega = 2 * np.arcsin(k * sn), 2 * k * w0 * cn
    worst, _, _ = energy_errors(theta, omega, cases("P1")[3])
    assert worst < 1e-13
    worst, _, _ = energy_errors(theta * 1.001, omega, cases("P1")[3])
    assert worst > 1e-4


@pytest.fixture(scope="module")
def unzipped(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return Path(extract(str(fmu_path), unzipdir=str(tmp_path_factory.mktemp("fmu"))))


@pytest.fixture(scope="module")
def driver(fmu_path: Path) -> Path:
    """The C driver ``tests/c/bench_solvers`` of the FMU's CMake build (the command never looks for it)."""
    exe = fmu_path.parent / "tests" / "c" / "bench_solvers"
    if not exe.is_file():
        pytest.skip("tests/c/bench_solvers is not built next to this FMU")
    return exe


def test_parse_reads_the_driver_lines() -> None:
    runs, floors = parse("floor problem=P2 amplitude_deg=179.99 periods=20 points=1001 period_s=13.7 wall_s=6e-05\n"
                         "run problem=P2 amplitude_deg=179.99 periods=20 points=1001 solver=rkn tol=1e-06 status=ok "
                         "rhs_evaluations=9541 steps=561 rejected=0 max_err=9.7e-07 energy_err_max=1e-12 "
                         "energy_err_first=1e-13 energy_err_last=2e-13 max_abs_theta=3.1414 wall_s=2e-4 setup_s=3e-6\n")
    assert floors[0].wall_s == 6e-05 and floors[0].points == 1001
    assert (runs[0].method, runs[0].rhs_evaluations, runs[0].max_err, runs[0].flipped) == ("rkn", 9541, 9.7e-07, False)


def test_c_driver_and_fmpy_measure_the_same_runs(unzipped: Path, driver: Path) -> None:
    c_runs, floors = run_driver(driver, shared_library(unzipped), ["P1"], [1e-6, 1e-9], 100.0, 50, repeat=1)
    assert len(floors) == 4 and all(f.wall_s > 0 for f in floors)
    assert len(c_runs) == 4 * 4 * 2 and all(r.status == "ok" for r in c_runs)
    for case in cases("P1")[::3]:
        grid = make_grid(unzipped, case, 50)
        for solver in ("rkn", "symplectic"):
            for tol in (1e-6, 1e-9):
                py = run_fmu_cs(unzipped, grid, solver, tol)
                (c,) = [r for r in c_runs if (r.amplitude_deg, r.method, r.tol) == (case.amplitude_deg, solver, tol)]
                assert (c.rhs_evaluations, c.steps) == (py.rhs_evaluations, py.steps)
                # the two measure the error at times that differ in the last bit
                assert c.max_err == pytest.approx(py.max_err, rel=1e-3, abs=1e-14)


def test_a_peer_run_is_measured_against_the_same_truth(unzipped: Path) -> None:
    grid = make_grid(unzipped, cases("P1")[1], 50)
    loose, tight = run_solve_ivp(grid, "DOP853", 1e-5), run_solve_ivp(grid, "DOP853", 1e-12)
    assert tight.max_err < 1e-10 < 1e-6 < loose.max_err < 1e-2
    assert tight.rhs_evaluations > 3 * loose.rhs_evaluations


@pytest.mark.slow
def test_bench_solvers_quick_run_writes_its_outputs(fmu_path: Path, driver: Path, tmp_path: Path) -> None:
    code = main(["bench", "solvers", "--fmu", str(fmu_path), "--driver", str(driver), "--out", str(tmp_path),
                 "--problems", "P1,P2", "--quick", "--no-peers"])
    assert code == 0  # every run ran (the targets are the lab's: tests/lab/solver_targets.py)
    report = (tmp_path / "report.md").read_text()
    assert "## Targets" not in report
    assert "| rkn (FMU, C driver) |" in report
    assert "equal the C driver's: 16 of 16 points" in report
    assert (tmp_path / "wp_P1.png").stat().st_size > 10_000 and (tmp_path / "wp_P2.png").exists()
    rows = (tmp_path / "runs.csv").read_text().splitlines()
    assert len(rows) == 1 + 2 * (4 + 1) * 4 * 2  # header, (C + fmpy) x 5 cases x 4 solvers x 2 tols
