"""Every number the headline figures (docs/figures.md) and README.md's examples quote beside a
command is what that command prints.

Each test runs the command of a row of the headline table (or the README's example, as written
there) and compares the figure quoted with the one printed, at the page's own number of
significant digits: a change that moves a figure fails here until the page says so. Timings are
not compared (the table marks them "measured"); where the table quotes a ratio of timings, only
its direction is held, with generous bounds.

The headline table's last column says which rows this file holds ("test") and which are
measured on a quiet machine and not asserted ("measured").
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]
README = (REPO / "README.md").read_text(encoding="utf-8")
FIGURES = (REPO / "docs" / "figures.md").read_text(encoding="utf-8")
"""The headline figures: the table of measured figures, each with its command."""
TESTS_C = REPO / "build" / "tests" / "c"
NUMBER = r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?"


def headline(what: str) -> tuple[str, str]:
    """The (figure, held by) cells of the headline table's row whose first cell starts with ``what``."""
    for line in FIGURES.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("|") and cells[0].startswith(what):
            return cells[1], cells[-1]
    raise AssertionError(f"docs/figures.md's headline table has no row '{what} ...'")


def significant(quoted: str) -> int:
    """The significant digits of a number as the page writes it (``9.7e-13``: 2; ``471``: 3)."""
    mantissa = re.split(r"[eE]", quoted)[0].lstrip("+-").replace(".", "").lstrip("0")
    return max(len(mantissa), 1)


def agrees(quoted: str, printed: float) -> bool:
    """``printed`` rounded to the digits ``quoted`` shows is ``quoted``."""
    digits = significant(quoted)
    return float(f"{printed:.{digits - 1}e}") == float(quoted)


def run(*args: str, timeout: float = 600) -> str:
    """The standard output of ``args`` run in the repository, which must succeed."""
    done = subprocess.run(list(args), cwd=REPO, capture_output=True, text=True, timeout=timeout, check=False)
    assert done.returncode == 0, f"{' '.join(args)} failed: {done.stdout[-2000:]}{done.stderr[-2000:]}"
    return done.stdout


def cli(*args: str, timeout: float = 600) -> str:
    return run(sys.executable, "-m", "pendulum_fmu", *args, timeout=timeout)


def test_fmpy_example_prints_the_quoted_error(fmu_path: Path) -> None:
    """The README's fmpy example, run as written there (from the repository root)."""
    block = next(b for b in re.findall(r"```python\n(.*?)```", README, re.S) if "simulate_fmu" in b)
    quoted = re.search(rf"#\s*({NUMBER}) rad", block)
    assert quoted is not None, "the fmpy example no longer quotes its error"
    code = block.replace('"build/Pendulum.fmu"', repr(str(fmu_path)))
    printed = float(run(sys.executable, "-c", code).split()[-1])
    assert agrees(quoted.group(1), printed), f"the fmpy example prints {printed:.3g}; README.md says {quoted.group(1)}"


@pytest.fixture(scope="module")
def study_table(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[tuple[int, str], list[str]]:
    """The table ``pendulum-fmu study`` prints (the study of ``bash scripts/study.sh``), by
    (amplitude, interface)."""
    out = tmp_path_factory.mktemp("study")
    printed = cli("study", "--fmu", str(fmu_path), "--out", str(out))
    rows = {}
    for line in printed.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if len(cells) == 6 and cells[0].isdigit():
            rows[(int(cells[0]), cells[1])] = cells
    assert len(rows) == 8, f"study printed {len(rows)} rows, not 8:\n{printed}"
    return rows


@pytest.mark.parametrize(("what", "interface"), [("the seed's study", "CS"), ("the same through Model Exchange", "ME")])
def test_study_errors_are_the_printed_range(study_table: dict[tuple[int, str], list[str]], what: str,
                                            interface: str) -> None:
    figure, held = headline(what)
    assert held == "test"
    low, high = re.findall(NUMBER, figure.replace(" to ", " "))[:2]
    errors = [float(cells[5]) for (_, kind), cells in study_table.items() if kind == interface]
    assert agrees(low, min(errors)) and agrees(high, max(errors)), \
        f"docs/figures.md says {figure} for {interface}; the study prints {min(errors):.3g} to {max(errors):.3g}"


def test_study_page_table_is_the_printed_one(study_table: dict[tuple[int, str], list[str]]) -> None:
    """docs/study.md's table is the study's, row for row."""
    page = (REPO / "docs" / "study.md").read_text(encoding="utf-8")
    for cells in study_table.values():
        row = "| " + " | ".join(cells) + " |"
        assert row in page, f"docs/study.md lacks the study's row {row}"


@pytest.fixture(scope="module")
def accuracy(fmu_path: Path) -> dict[str, list[str]]:
    """``pendulum-fmu bench accuracy``'s table, by case."""
    rows = {}
    for line in cli("bench", "accuracy", "--fmu", str(fmu_path)).splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("|") and len(cells) >= 3 and re.fullmatch(NUMBER, cells[1]):
            rows[cells[0]] = cells
    assert "pi (the double)" in rows, f"bench accuracy printed no row 'pi (the double)': {sorted(rows)}"
    return rows


def test_accuracy_worst_case_is_the_printed_one(accuracy: dict[str, list[str]]) -> None:
    figure, held = headline("exact solution against mpmath")
    assert held == "test"
    quoted, where = re.fullmatch(rf"at most ({NUMBER}) rad \(theta0 = (\w+)\)", figure).groups()
    every_regime = {case: float(cells[1]) for case, cells in accuracy.items() if "1e6 periods" not in case}
    worst = max(every_regime, key=every_regime.__getitem__)
    assert agrees(quoted, every_regime[worst]), \
        f"docs/figures.md says {quoted}; bench accuracy prints {every_regime[worst]}"
    assert worst == "pi (the double)" and where == "pi", f"the worst case is now {worst}"


def test_accuracy_after_a_million_periods_is_the_printed_one(accuracy: dict[str, list[str]]) -> None:
    figure, held = headline("exact solution after 10^6 periods")
    assert held == "test"
    ours, naive = re.findall(NUMBER, figure)[:2]
    cells = next(cells for case, cells in accuracy.items() if "1e6 periods" in case)
    assert agrees(ours, float(cells[1])), f"docs/figures.md says {ours}; bench accuracy prints {cells[1]}"
    assert agrees(naive, float(cells[3])), f"docs/figures.md says scipy's {naive}; bench accuracy prints {cells[3]}"


def test_certificate_table_counts_are_the_printed_ones() -> None:
    """``build/tests/c/test_certificate table``: runs beyond the bound, every one warned."""
    program = TESTS_C / "test_certificate"
    assert program.exists(), f"{program} is missing: bash scripts/build-fmu.sh builds it"
    figure, held = headline("the step certificate near the separatrix")
    assert held == "test"
    beyond, runs = re.search(r"(\d+) of (\d+) runs beyond 100 tol", figure).groups()
    silent = re.search(r"(\d+) silent", figure).group(1)
    printed = run(str(program), "table")
    summary = re.search(r"separatrix grid: (\d+) runs, (\d+) beyond the bound at some step \(all warned\)", printed)
    assert summary is not None, f"test_certificate table no longer prints its summary:\n{printed[-1500:]}"
    assert (runs, beyond) == summary.groups(), f"docs/figures.md says {beyond} of {runs}; it prints {summary.group(0)}"
    # the grid's rows: 1 - m, c, tol, then one cell a solver ('*' warned, '-' beyond its reach);
    # a cell beyond the bound (> 1) without its '*' would be a silent run
    cells = [cell for line in printed.splitlines() if re.match(r"-?\d\.\d\de-\d\d\s", line)
             for cell in line.split()[3:]]
    assert len(cells) == int(runs), f"the grid has {len(cells)} cells, docs/figures.md says {runs} runs"
    beyond_cells = [cell for cell in cells if float(cell.rstrip("*-")) > 1]
    unwarned = [cell for cell in beyond_cells if "*" not in cell]
    assert len(beyond_cells) == int(beyond), f"{len(beyond_cells)} cells beyond the bound: {beyond_cells}"
    assert int(silent) == len(unwarned) == 0, f"runs beyond the bound without a warning: {unwarned}"


def test_solver_evaluation_ratio_is_the_printed_one(fmu_path: Path, tmp_path: Path) -> None:
    """``bench solvers --problems P1``: rkn's evaluations over DOP853's at the same error. The
    counts do not depend on the machine; with only the two DOP853 peers the run takes seconds
    (all seven peers: over 2 minutes on two shared cores, Radau and Euler most of it)."""
    driver = TESTS_C / "bench_solvers"
    assert driver.exists(), f"{driver} is missing: bash scripts/build-fmu.sh builds it"
    figure, held = headline("default solver `rkn` against DOP853")
    assert held == "test"
    low, high = re.findall(NUMBER, figure)[:2]
    done = subprocess.run([sys.executable, "-m", "pendulum_fmu", "bench", "solvers", "--fmu", str(fmu_path),
                           "--driver", str(driver), "--problems", "P1", "--peers", "DOP853,dop853",
                           "--out", str(tmp_path)], cwd=REPO, capture_output=True, text=True, timeout=1200, check=False)
    printed = done.stdout
    # The counts do not depend on the machine; the command judges no target (the lab does:
    # tests/lab/solver_targets.py), so it exits 0 when every run ran.
    assert done.returncode == 0, f"bench solvers failed: {printed[-2000:]}{done.stderr[-2000:]}"
    table = printed.split("| error | rkn | solve_ivp DOP853 | ode dop853 | ratio |", 1)
    assert len(table) == 2, f"bench solvers no longer prints the rkn / DOP853 table:\n{printed[-2000:]}"
    ratios = [float(line.strip("|").split("|")[-1]) for line in table[1].strip().splitlines()[1:]
              if line.startswith("| 1e-")]
    assert len(ratios) == 9, f"{len(ratios)} error levels, not 1e-4 .. 1e-12"
    assert agrees(low, min(ratios)) and agrees(high, max(ratios)), \
        f"docs/figures.md says {figure}; bench solvers prints {min(ratios)} to {max(ratios)}"


def test_speed_row_error_and_ratio_direction(fmu_path: Path) -> None:
    """``bench speed``: the error the speed row is measured at is the printed one (it does not
    depend on the machine); its timings are measured, and only their direction is held: the
    package's runner at least 5 times faster than fmpy's ``simulate_fmu`` (the table: 20x)."""
    figure, held = headline("100 periods from Python at error")
    assert held == "measured"
    quoted_error = re.search(rf"at error ({NUMBER})", FIGURES).group(1)
    printed = cli("bench", "speed", "--repeat", "3", "--fmu", str(fmu_path), timeout=600)
    runs = {m.group(1): (float(m.group(2)), float(m.group(3))) for m in re.finditer(
        rf"bench_speed method='([^']+)' best_ms=({NUMBER}) median_ms={NUMBER} error=({NUMBER})", printed)}
    runner_ms, runner_error = runs["package, C loop (FmuRunner)"]
    assert agrees(quoted_error, runner_error), \
        f"docs/figures.md says error {quoted_error}; bench speed prints {runner_error}"
    fmpy_ms, _ = runs["fmpy simulate_fmu"]
    assert fmpy_ms / runner_ms > 5, f"the runner is only {fmpy_ms / runner_ms:.1f} times faster than simulate_fmu"
    assert "20x fmpy's `simulate_fmu`" in figure


def test_judge_example_prints_the_quoted_diagnosis(fmu_path: Path, tmp_path: Path) -> None:
    """The README's ME judge example on fmpy's explicit Euler at h = 0.01 (its me.csv)."""
    quoted = re.search(rf"explicit Euler at h = 0.01 reproduces the file to ({NUMBER})", README)
    assert quoted is not None, "README.md no longer quotes the judge's diagnosis"
    me_csv = tmp_path / "me.csv"
    run(sys.executable, "-c", (
        "import sys; from fmpy import simulate_fmu; from fmpy.util import write_csv\n"
        "r = simulate_fmu(sys.argv[1], fmi_type='ModelExchange', solver='Euler', step_size=0.01, stop_time=10.0,"
        " output_interval=0.01, start_values={'theta': 1.4835},"
        " output=['theta', 'omega', 'theta_exact', 'omega_exact'])\n"
        "write_csv(sys.argv[2], r)"), str(fmu_path), str(me_csv))
    done = subprocess.run([sys.executable, "-m", "pendulum_fmu", "judge", str(me_csv), "--fmu", str(fmu_path),
                           "--interface", "ME", "--start", "theta=1.4835"],
                          cwd=REPO, capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 1, f"the judge should fail Euler's file (exit 1): {done.stdout[-1500:]}{done.stderr}"
    printed = re.search(rf"explicit Euler at h = 0.01 reproduces the file to ({NUMBER})", done.stdout)
    assert printed is not None, f"the judge no longer names explicit Euler:\n{done.stdout[-1500:]}"
    assert agrees(quoted.group(1), float(printed.group(1))), \
        f"README.md says {quoted.group(1)}; the judge prints {printed.group(1)}"


def test_every_headline_row_says_how_it_is_held() -> None:
    """Each row of the headline table is either compared here or marked as a measurement."""
    rows = [line for line in FIGURES.splitlines()
            if line.startswith("|") and not line.startswith("|---") and not line.startswith("| what")]
    assert len(rows) >= 8
    for line in rows:
        held = line.strip().strip("|").split("|")[-1].strip()
        assert held in {"test", "measured"}, f"the headline row {line[:60]!r} ends with {held!r}, not test or measured"
