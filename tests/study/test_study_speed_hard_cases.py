"""The study's speed-against-error and hard-case sections against independent references.

One ``pendulum-fmu study`` run writes ``speed.csv``, ``hard_cases.csv`` and the reports; the
tests re-run what they need through the same FMU and check the written numbers against
mpmath's Jacobi elliptic functions at 40 digits (``true_state``, independent of the FMU's own
exact port), against the solvers' documented evaluation counts, against a second count of
CVODE's derivative calls (the benchmark's), and the certificate's verdicts against the true
error: no step beyond the true bound reported certified, no run beyond it without a warning.
No timed assertion: wall times are only checked to be measured (finite, > 0).
"""

from __future__ import annotations

import contextlib
import csv
import io
import math
import re
from collections.abc import Iterator
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from fmpy import extract

from mpmath_pendulum import DIGITS, true_state
from pendulum_fmu.cli.main import main
from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.spec import CS_SOLVERS, InitialValueProblem, Method, TimeGrid
from pendulum_fmu.study.hard_cases import hard_cases
from pendulum_fmu.study.speed import LEVELS
from pendulum_fmu.study.tradeoff import cost_to_reach, pareto_front

AMPLITUDES = (75.0, 80.0, 85.0, 90.0)
GRID = TimeGrid(10, "periods", 50)


@pytest.fixture(scope="module")
def study(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, object]:
    """One study run: its folder, its printed output and its two CSV files."""
    out = tmp_path_factory.mktemp("study")
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        assert main(["study", "--out", str(out), "--fmu", str(fmu_path), "--periods", "1"]) == 0
    with open(out / "speed.csv", newline="") as file:
        speed = list(csv.DictReader(file))
    with open(out / "hard_cases.csv", newline="") as file:
        hard = list(csv.DictReader(file))
    return {"out": out, "printed": printed.getvalue(), "speed": speed, "hard": hard}


@pytest.fixture(scope="module")
def runner(fmu_path: Path) -> Iterator[FmuRunner]:
    with FmuRunner(fmu_path) as loaded:
        yield loaded


_references: dict[tuple[float, float, bytes], np.ndarray] = {}


def true_states(pendulum: InitialValueProblem, times: np.ndarray, start: float = 0.0) -> np.ndarray:
    """(theta, omega) at ``times`` by mpmath (40 digits), the time since ``start`` taken exactly;
    shape (2, len(times))."""
    key = (pendulum.theta0, pendulum.omega0, np.asarray(times).tobytes() + repr(start).encode())
    if key not in _references:
        with mp.workdps(DIGITS):
            _references[key] = np.array([[float(v) for v in true_state(
                pendulum.theta0, pendulum.omega0, pendulum.g, pendulum.L,
                mp.mpf(float(t)) - mp.mpf(start))] for t in times]).T
    return _references[key]


def true_theta(pendulum: InitialValueProblem, times: np.ndarray, start: float = 0.0) -> np.ndarray:
    """theta at ``times`` by mpmath (:func:`true_states`)."""
    return true_states(pendulum, times, start)[0]


# --- speed against error ----------------------------------------------------------------------
def test_every_method_and_tolerance_is_in_speed_csv(study: dict) -> None:
    rows = study["speed"]
    assert {r["method"] for r in rows} == {*CS_SOLVERS, "cvode"}
    assert sorted(float(r["tolerance"]) for r in rows if r["method"] == "rkn") == pytest.approx(
        [10.0 ** -k for k in range(12, 2, -1)])
    assert all(r["failure"] == "" and float(r["periods"]) == pytest.approx(40.0) for r in rows)
    assert all(math.isfinite(float(r["wall_per_period_s"])) and float(r["wall_per_period_s"]) > 0 for r in rows)


def test_the_error_column_is_the_true_error_by_mpmath(study: dict, runner: FmuRunner) -> None:
    """Each point re-run (the solvers are deterministic): its counts are the written ones, and its
    error against mpmath's solution is the written error to within the exact port's 5e-14."""
    for row in study["speed"]:
        method = Method(row["method"], float(row["tolerance"]))
        worst, rhs = 0.0, 0
        for amplitude in AMPLITUDES:
            pendulum = InitialValueProblem.from_degrees(amplitude)
            run = runner.run(pendulum, method, GRID)
            worst = max(worst, float(np.max(np.abs(run.result["theta"] - true_theta(pendulum, run.result["time"])))))
            rhs += run.rhs_evaluations if run.rhs_evaluations is not None else run.derivative_calls or 0
        assert int(row["rhs_evaluations"]) == rhs, row
        assert float(row["max_error_rad"]) == pytest.approx(worst, rel=1e-6, abs=1e-13), row


def test_fixed_step_methods_count_their_stages(study: dict) -> None:
    """rk4: k2, k3, k4 and the end slope (the next step's k1) a step, plus the start's f;
    symplectic: 15 sines and the interpolant's cos a step, plus the start's f and jerk
    (fmu_src/solvers/rk4.c, symplectic.c); neither rejects a step. Four runs a point."""
    runs = len(AMPLITUDES)
    for row in study["speed"]:
        rhs, steps = int(row["rhs_evaluations"]), int(row["steps"] or -1)
        if row["method"] == "rk4":
            assert rhs == 4 * steps + runs, row
        elif row["method"] == "symplectic":
            assert rhs == 16 * steps + 2 * runs, row
        elif row["method"] in ("dopri5", "rkn"):
            assert rhs > {"dopri5": 6, "rkn": 16}[row["method"]] * steps, row   # at least the stages a step


def test_cvode_evaluations_match_the_benchmarks_count(fmu_path: Path) -> None:
    """The runner's count of fmi2GetDerivatives is the one ``bench solvers`` makes its own way."""
    from pendulum_fmu.bench.workprecision.problems import Case, make_grid
    from pendulum_fmu.bench.workprecision.runs import run_fmu_me

    unzipped = Path(extract(str(fmu_path)))
    with FmuRunner(fmu_path) as loaded:
        for tol in (1e-6, 1e-10):
            theirs = run_fmu_me(unzipped, make_grid(unzipped, Case.from_rest("P1", 80.0, 10.0), 50), "cvode", tol)
            ours = loaded.run(InitialValueProblem.from_degrees(80.0), Method("cvode", tol), GRID)
            assert ours.derivative_calls == theirs.rhs_evaluations > 100
            assert ours.max_error == theirs.max_err


def test_the_fastest_sentence_names_the_cheapest_cell(study: dict) -> None:
    """The sentence and the table agree: at each level the named method has the least wall time."""
    report = (study["out"] / "report.md").read_text()
    sentence = next(line for line in report.splitlines() if line.startswith("Fastest to reach"))
    assert sentence in study["printed"]
    table = report[report.index("## Speed against error"):report.index("## Hard cases")]
    walls: dict[float, dict[str, float]] = {level: {} for level in LEVELS}
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != len(LEVELS) + 2 or "(" not in cells[0] or cells[0].startswith("exact"):
            continue
        for level, cell in zip(LEVELS, cells[1:], strict=False):
            if cell != "-":
                walls[level][cells[0].split(" ")[0]] = float(re.search(r"\(([\d .e+]+) us\)", cell)[1].replace(" ", ""))
    assert all(len(walls[level]) >= 3 for level in LEVELS[:3])
    for level, costs in walls.items():
        if not costs:
            assert f"{level:.0e} rad: none" in sentence
            continue
        named = re.search(rf"{level:.0e} rad: (\w+)", sentence)[1]
        assert costs[named] == min(costs.values()), (level, named, costs)


def test_the_front_and_the_interpolated_cost() -> None:
    """Hand-made points: the dominated one is dropped, and the cost between two front points is
    their geometric mean halfway in log error."""
    front = pareto_front([(10.0, 1e-2), (50.0, 1e-1), (100.0, 1e-4), (400.0, 1e-4), (20.0, 0.0)])
    assert front == [(1e-2, 10.0), (1e-4, 100.0)]
    assert cost_to_reach(front, 1e-3) == pytest.approx(math.sqrt(10.0 * 100.0))
    assert cost_to_reach(front, 1e-1) == 10.0
    assert cost_to_reach(front, 1e-4) == pytest.approx(100.0)
    assert cost_to_reach(front, 1e-5) == math.inf
    assert cost_to_reach([], 1.0) == math.inf


def test_the_report_carries_the_figure_and_both_tables(study: dict) -> None:
    out = study["out"]
    html = (out / "report.html").read_text()
    assert html.count("<img ") == 5 and 'id="speed_vs_error.png"' in html
    assert html.count("<table") == 3 and "Hard cases" in html and "Speed against error" in html
    report = (out / "report.md").read_text()
    assert report.count("| exact solution (floor) | 0 (") == 1
    assert "Hard cases:" in study["printed"] and "Of 24 Co-Simulation runs" in study["printed"]


# --- hard cases --------------------------------------------------------------------------------
def test_every_hard_case_and_solver_has_a_row(study: dict) -> None:
    rows = study["hard"]
    assert [(r["case"], r["solver"]) for r in rows] == [(c.name, s) for c in hard_cases()
                                                         for s in (*CS_SOLVERS, "cvode")]
    assert all(r["verdict"] for r in rows)
    assert not [r for r in rows if r["verdict"].startswith(("SILENT", "FAILED"))]


def test_a_warned_run_is_one_the_fmu_warned_about(study: dict) -> None:
    """Steps beyond the bound (recomputed from the outputs) and the FMU's certificate messages
    go together in every Co-Simulation run: a warning where it must, none where it need not."""
    for row in study["hard"]:
        if row["solver"] == "cvode":
            continue
        beyond, messages = int(row["steps_beyond"]), int(row["certificate_warnings"])
        assert (beyond > 0) == (messages > 0), row
        assert row["verdict"].startswith("WARNED" if beyond else "certified"), row


def test_the_creep_over_the_top_warns_for_every_solver(study: dict, runner: FmuRunner) -> None:
    """theta0 = pi, omega0 = 1e-15: every solver reverses at the top where the true motion goes on
    (mpmath), so every one must say so: the hard-case message."""
    case = next(c for c in hard_cases() if c.short == "creep over the top")
    rows = {r["solver"]: r for r in study["hard"] if r["case"] == case.name}
    for solver in CS_SOLVERS:
        run = runner.run(case.problem, Method(solver), TimeGrid(case.periods, "periods", 50))
        theta, omega = true_states(case.problem, run.result["time"][1:])
        assert abs(run.result["theta"][-1] - theta[-1]) > 1.0   # qualitatively wrong
        assert int(rows[solver]["hard_case_warnings"]) == 1 and rows[solver]["verdict"].startswith("WARNED")
        # the steps beyond the bound, counted against mpmath's state: the table's count, give or
        # take a step within the exact port's 5e-14 of the bound
        bound = 100 * 1e-8
        beyond = ((np.abs(run.result["theta"][1:] - theta) > bound * np.maximum(1.0, np.abs(theta)))
                  | (np.abs(run.result["omega"][1:] - omega) > bound * np.maximum(case.problem.w0, np.abs(omega))))
        assert abs(int(rows[solver]["steps_beyond"]) - int(np.count_nonzero(beyond))) <= 1, solver
    assert rows["cvode"]["verdict"].startswith("UNCERTIFIED (ME)")


@pytest.mark.parametrize("short", ["179.9999 deg release", "rotation above the separatrix", "large start time"])
def test_certified_runs_are_within_the_true_bound(study: dict, runner: FmuRunner, short: str) -> None:
    """Where the table says every step was certified, every output is within 100 tol of the true
    solution (mpmath, from the start time exactly), theta and omega's scales as the certificate's."""
    case = next(c for c in hard_cases() if c.short == short)
    rows = {r["solver"]: r for r in study["hard"] if r["case"] == case.name}
    for solver in ("rkn", "dopri5"):
        assert rows[solver]["verdict"].startswith("certified"), rows[solver]
        run = runner.run(case.problem, Method(solver), TimeGrid(case.periods, "periods", 50),
                         start_time=case.start_time)
        assert run.result["time"][0] == case.start_time
        truth = true_theta(case.problem, run.result["time"], case.start_time)
        bound = 100 * 1e-8 * np.maximum(1.0, np.abs(truth))
        assert np.all(np.abs(run.result["theta"] - truth) <= bound), solver
        assert float(rows[solver]["max_error_rad"]) == pytest.approx(run.max_error, rel=1e-12, abs=0.0)


def test_the_long_run_warns_where_the_last_point_is_beyond_the_bound(study: dict, runner: FmuRunner) -> None:
    """10^4 periods: at the last point, the true error (mpmath) beyond 100 tol means a warning."""
    case = next(c for c in hard_cases() if c.short == "long run")
    rows = {r["solver"]: r for r in study["hard"] if r["case"] == case.name}
    beyond = []
    grid = TimeGrid(case.periods, "periods", 50)
    for solver in CS_SOLVERS:
        run = runner.run(case.problem, Method(solver), grid)
        assert int(rows[solver]["points"]) == run.result.size - 1 == 500_000
        truth = true_theta(case.problem, run.result["time"][-1:])[0]
        if abs(run.result["theta"][-1] - truth) > 100 * 1e-8 * max(1.0, abs(truth)):
            beyond.append(solver)
            assert int(rows[solver]["certificate_warnings"]) > 0, rows[solver]
    assert beyond == ["rk4"]   # the table's one warned long run, found by the true error too
    assert float(rows["cvode"]["periods"]) == pytest.approx(1000.0)


def test_model_exchange_beyond_100_tol_is_said(study: dict) -> None:
    """CVODE has no certificate: a run whose error exceeds 100 tol says it is beyond, in words."""
    for row in study["hard"]:
        if row["solver"] != "cvode":
            continue
        assert row["verdict"].count("UNCERTIFIED") + row["verdict"].count("uncertified") == 1
        if float(row["max_error_rad"]) > 100 * 1e-10 * math.pi:
            assert int(row["steps_beyond"]) > 0 and "UNCERTIFIED (ME)" in row["verdict"], row
        if int(row["points"]) < 500 and int(row["points"]) > 0:
            assert row["verdict"].startswith("ENDED EARLY"), row


def test_a_start_time_that_is_not_finite_is_refused(runner: FmuRunner) -> None:
    with pytest.raises(UsageError, match="start_time"):
        runner.run(InitialValueProblem.from_degrees(75.0), Method(), GRID, start_time=math.nan)


def test_both_fmi_versions_count_cvode_calls_and_start_late(fmu_any: Path) -> None:
    """FMI 2.0 and 3.0 alike: Model Exchange counts its derivative calls (fmi2GetDerivatives,
    fmi3GetContinuousStateDerivatives) and Co-Simulation starts at a large start time, where the
    exact solution agrees with mpmath counted from that time and the run holds its bound."""
    pendulum = InitialValueProblem.from_degrees(75.0)
    grid = TimeGrid(2, "periods", 50)
    with FmuRunner(fmu_any) as loaded:
        me = loaded.run(pendulum, Method("cvode", 1e-8), grid)
        assert me.rhs_evaluations is None and me.derivative_calls is not None and me.derivative_calls > 100
        again = loaded.run(pendulum, Method("cvode", 1e-8), grid)
        assert again.derivative_calls == me.derivative_calls   # per run, not accumulated
        late = loaded.run(pendulum, Method(), grid, start_time=1e9)
    assert late.start_time == late.result["time"][0] == 1e9 and late.result.size == 101
    truth = true_theta(pendulum, late.result["time"], 1e9)
    assert np.max(np.abs(late.result["theta_exact"] - truth)) <= 1e-12
    assert np.all(np.abs(late.result["theta"] - truth) <= 100 * 1e-8 * np.maximum(1.0, np.abs(truth)))


def test_a_failed_or_silent_run_is_said_in_its_row() -> None:
    """The verdicts' logic on made-up rows: a failure, a step beyond the bound with no warning, a
    run that ended early and a Model Exchange run beyond 100 tol each say so in words."""
    from pendulum_fmu.study.hard_cases import HardRun
    from pendulum_fmu.study.speed import Floor, SpeedPoint, SpeedStudy, speed_rows

    case = hard_cases()[0]
    cs, me = Method("rkn"), Method("cvode", 1e-10)
    assert HardRun(case, cs, 10, math.nan, 0, 0, 0, 0, "", 0, math.nan, "DoStep returned Error").verdict \
        == "FAILED: DoStep returned Error"
    assert HardRun(case, cs, 10, 1e-3, 3, 500, 0, 0, "", 9, 1e-5, asked_points=500).verdict.startswith(
        "SILENT: 3 of 500 steps beyond the bound")
    assert HardRun(case, cs, 10, 1e-3, 3, 500, 1, 0, "certificate: ...", 9, 1e-5, asked_points=500).verdict \
        == "WARNED: 3 of 500 steps beyond the bound; 1 certificate message"
    assert HardRun(case, me, 9, 1e-3, 450, 450, 0, 0, "", 9, 1e-5, asked_points=500).verdict == \
        "ENDED EARLY after 450 of 500 points; UNCERTIFIED (ME): 450 of 450 points beyond 100 tol"
    points = (SpeedPoint("rkn", 1e-6, 1e-9, 100, 5, 1e-5, 40.0),
              SpeedPoint("rkn", 1e-8, math.nan, 0, None, math.nan, 0.0, "DoStep returned Error"))
    rows = speed_rows(SpeedStudy(points, Floor(math.nan, 2004, "not measured: no library"), AMPLITUDES, 10.0))
    rkn = next(row for row in rows if row[0] == "rkn (CS)")
    assert rkn[-1] == "1.00e-09 at 1e-06 (failed at tol 1e-08)"
    assert rows[-1][1] == "not measured: no library"
