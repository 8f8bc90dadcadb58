"""The whole study in one call: runs, figures, runs.csv, report.md and report.html."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.output.experiment_record import record_of, write_record
from pendulum_fmu.study.figures import plot_comparison_grid, plot_period_ratio, plot_solutions
from pendulum_fmu.study.report import write_html, write_report
from pendulum_fmu.study.seed import SEED_AMPLITUDES_DEG, format_table, period_curve, run_study, table_rows, write_csv


@dataclass(frozen=True)
class StudyOutcome:
    """What the study found: the Markdown error table and the FMU's warnings, if any."""

    table: str
    warnings: tuple[str, ...]


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
        The error table and the distinct warnings the FMU logged during the runs.
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
    say("runs.csv, report.md and report.html")
    write_csv(runs, out / "runs.csv")
    # each run's experiment, picked out by its interface and amplitude (docs/results.md)
    write_record(out / "runs.csv", [({"interface": run.method.interface,
                                      "amplitude_deg": f"{run.pendulum.amplitude_deg:g}"}, record_of(run, fmu, "study"))
                                    for run in runs])
    rows = table_rows(runs)
    table = format_table(rows)
    write_report(out, table, periods)
    write_html(out, rows, periods)
    warnings = tuple(dict.fromkeys(w for run in runs for w in run.warnings))
    return StudyOutcome(table, warnings)
