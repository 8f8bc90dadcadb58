"""The whole study in one call: runs, figures, speed against error, hard cases, CSV files, report.md
and report.html."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.output.experiment_record import record_of, write_record
from pendulum_fmu.study.figures import plot_comparison_grid, plot_period_ratio, plot_solutions
from pendulum_fmu.study.hard_cases import HARD_HEADER, hard_rows, hard_summary, run_hard_cases
from pendulum_fmu.study.report import SPEED_FIGURE, markdown_table, write_html, write_report, write_speed_and_hard_cases
from pendulum_fmu.study.seed import (
    POINTS_PER_PERIOD,
    SEED_AMPLITUDES_DEG,
    format_table,
    period_curve,
    run_study,
    table_rows,
    write_csv,
)
from pendulum_fmu.study.speed import SPEED_HEADER, fastest_sentence, measure_speed, speed_rows
from pendulum_fmu.study.speed_figure import plot_work_precision

SPEED_PERIODS = 10.0
"""Periods of each speed-against-error run, whatever ``--periods`` says: the added work stays the same."""


@dataclass(frozen=True)
class StudyOutcome:
    """What the study found.

    Attributes
    ----------
    table : str
        The seed's error table (Markdown).
    warnings : tuple of str
        The distinct warnings the FMU logged during the seed's runs.
    fastest : str
        The sentence naming the fastest method at each error level.
    speed_table : str
        Speed against error (Markdown).
    hard_summary : str
        The hard cases in one sentence: certified, warned, silent, failed.
    hard_table : str
        The hard cases (Markdown).
    """

    table: str
    warnings: tuple[str, ...]
    fastest: str = ""
    speed_table: str = ""
    hard_summary: str = ""
    hard_table: str = ""


def write_study(fmu: Path, out: Path, periods: float = 10.0,
                progress: Callable[[str], None] | None = None) -> StudyOutcome:
    """Run the seed's study on ``fmu`` and write every output into the existing folder ``out``.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    out : Path
        An existing, writable folder.
    periods : float
        Exact periods to simulate.
    progress : callable, optional
        Called with one line at each step (each run, the period curve, the figures).

    Returns
    -------
    StudyOutcome
        The report's tables and sentences, and the distinct warnings the FMU logged during the
        seed's runs (the hard cases' warnings are in their table).
    """
    with FmuRunner(fmu) as runner:
        runs = run_study(runner, periods, progress)
        if progress is not None:
            progress("the period curve: the FMU's period at 477 amplitudes, and 15 runs that measure it")
        curve = period_curve(runner)
    say = progress if progress is not None else (lambda line: None)
    say("Figures 3 and 4 (fig3_numeric.png, fig4_exact.png)")
    cs_runs = [r for r in runs if r.method.interface == "CS"]
    me_runs = [r for r in runs if r.method.interface == "ME"]
    plot_solutions(cs_runs, "theta", "Figure 3: the numerical solution (FMU, Co-Simulation, rkn)",
                   out / "fig3_numeric.png")
    plot_solutions(cs_runs, "theta_exact", "Figure 4: the exact solution (Jacobi elliptic functions, in the FMU)",
                   out / "fig4_exact.png")
    say("Figure 5 (fig5_overlay.png)")
    plot_comparison_grid(cs_runs, me_runs, out / "fig5_overlay.png")
    say("the period ratio (period_ratio.png)")
    plot_period_ratio(curve, SEED_AMPLITUDES_DEG, out / "period_ratio.png")
    with FmuRunner(fmu) as runner:
        speed = measure_speed(runner, SEED_AMPLITUDES_DEG, SPEED_PERIODS, POINTS_PER_PERIOD, progress)
        hard = run_hard_cases(runner, POINTS_PER_PERIOD, progress)
    say(f"speed against error ({SPEED_FIGURE}), speed.csv and hard_cases.csv")
    plot_work_precision(speed, out / SPEED_FIGURE)
    write_speed_and_hard_cases(out, speed, hard)
    say("runs.csv, report.md and report.html")
    write_csv(runs, out / "runs.csv")
    # each run's experiment, picked out by its interface and amplitude (docs/results.md)
    write_record(out / "runs.csv", [({"interface": run.method.interface,
                                      "amplitude_deg": f"{run.problem.theta0_deg:g}"}, record_of(run, fmu, "study"))
                                    for run in runs])
    rows = table_rows(runs)
    table = format_table(rows)
    write_report(out, table, periods, speed, hard)
    write_html(out, rows, periods, speed, hard)
    warnings = tuple(dict.fromkeys(w for run in runs for w in run.warnings))
    return StudyOutcome(table, warnings, fastest_sentence(speed), markdown_table(SPEED_HEADER, speed_rows(speed)),
                        hard_summary(hard), markdown_table(HARD_HEADER, hard_rows(hard)))
