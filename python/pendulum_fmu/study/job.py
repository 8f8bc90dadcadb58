"""The whole study in one call: runs, figures, runs.csv, report.md and report.html."""

from __future__ import annotations

from pathlib import Path

from pendulum_fmu.study.figures import plot_period_ratio, plot_theta_against_w0t
from pendulum_fmu.study.report import write_html, write_report
from pendulum_fmu.study.seed import format_table, period_ratio_curve, run_study, table_rows, write_csv


def write_study(fmu: Path, out: Path, periods: float = 10.0) -> str:
    """Run the seed's study on ``fmu`` and write every output into the existing folder ``out``.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    out : Path
        An existing folder.
    periods : float
        Exact periods to simulate.

    Returns
    -------
    str
        The error table in Markdown.
    """
    runs = run_study(fmu, periods)
    cs_runs = [r for r in runs if r.interface == "CS"]
    plot_theta_against_w0t(cs_runs, "numeric", "Figure 3: numerical solution (FMU, Co-Simulation)",
                           out / "fig3_numeric.png")
    plot_theta_against_w0t(cs_runs, "exact", "Figure 4: exact solution (Jacobi elliptic functions)",
                           out / "fig4_exact.png")
    plot_theta_against_w0t(cs_runs, "overlay", "Figure 5: numerical (lines) and exact (dots) overlaid",
                           out / "fig5_overlay.png")
    plot_period_ratio(*period_ratio_curve(fmu), out / "period_ratio.png")
    write_csv(runs, out / "runs.csv")
    rows = table_rows(runs)
    table = format_table(rows)
    write_report(out, table, periods)
    write_html(out, rows, periods)
    return table
