"""The study's reports: ``report.md`` and the self-contained ``report.html``."""

from __future__ import annotations

from pathlib import Path

from pendulum_fmu.output.report_html import Figure, write_html_report
from pendulum_fmu.study.seed import ME_TOLERANCE, SEED_AMPLITUDES_DEG, TABLE_HEADER


def write_report(out: Path, table: str, periods: float = 10.0) -> None:
    """A short Markdown report beside the figures."""
    text = f"""# The seed's study: the nonlinear pendulum released from rest at 75-90 deg

Co-Simulation uses the FMU's own solver at its default tolerance (1e-8); Model Exchange uses
fmpy's CVODE at relative tolerance {ME_TOLERANCE:g}. {periods:g} exact periods, 50 points a period.
The measured period is the slope of the downward zero crossings of theta.

{table}

- Figure 3 (numerical solution, one row per amplitude on a time axis in T0, period ends marked): `fig3_numeric.png`
- Figure 4 (exact Jacobi elliptic solution, the same panels): `fig4_exact.png`
- Figure 5 (numerical over exact, and |theta - theta_exact| of CS and ME on a log axis): `fig5_overlay.png`
- Period ratio T/T0 against amplitude, and its approach to 180 deg, with measured periods: `period_ratio.png`
- All runs: `runs.csv`
- Table and figures in one page: `report.html`
"""
    (out / "report.md").write_text(text)


def write_html(out: Path, rows: list[tuple[str, ...]], periods: float) -> Path:
    """``report.html``: the error table and the four figures in one self-contained page."""
    worst = max(rows, key=lambda row: float(row[-1]))
    intro = [
        ("The undamped pendulum theta'' + (g/L) sin(theta) = 0 (L = 1 m, g = 9.81 m/s^2), released from "
         f"rest at the seed's amplitudes {', '.join(f'{a:g}' for a in SEED_AMPLITUDES_DEG)} deg, simulated "
         f"for {periods:g} exact periods with 50 output points a period, and compared at every point with "
         "the exact Jacobi-elliptic solution that the FMU computes beside its numerical one."),
        ("Co-Simulation (CS) runs the FMU's default solver rkn (Runge-Kutta-Nystrom 12(10)) at its default "
         "tolerance 1e-8; "
         f"Model Exchange (ME) runs fmpy's CVODE at relative tolerance {ME_TOLERANCE:g}. The exact period is "
         "4 K(m)/w0 with m = sin^2(theta0/2); the measured period is the least-squares slope of the downward "
         "zero crossings of the numerical theta."),
        f"Largest error: {worst[-1]} rad ({worst[1]}, {worst[0]} deg).",
    ]
    figures = [
        Figure("fig3_numeric.png", "Figure 3: the numerical solution theta (FMU, Co-Simulation, rkn), one row per "
                                   "amplitude on one time axis in small-angle periods T0; triangles mark the end of "
                                   "each of the run's own periods T, which fall further behind the T0 grid lines "
                                   "the larger the amplitude; dashed lines at +theta0 and -theta0"),
        Figure("fig4_exact.png", "Figure 4: the exact solution (Jacobi elliptic functions, computed in the FMU); "
                                 "it matches Figure 3 to about 1e-12 rad, which Figure 5 shows"),
        Figure("fig5_overlay.png", "Figure 5: top, the last two periods, the numerical solution (thin line) inside "
                                   "the exact one (wide grey band); bottom, |theta - theta_exact| over the whole "
                                   "run on a log axis, Co-Simulation (rkn) and Model Exchange (CVODE), both against "
                                   "t/T0 as in Figures 3 and 4; errors exactly 0 as ticks in each interface's "
                                   "colour, CS's on the bottom edge, ME's a row above"),
        Figure("period_ratio.png", "The period ratio T/T0 against amplitude (left, linear) and its logarithmic "
                                   "growth toward 180 deg (right, against the distance 180 deg - theta0, which "
                                   "shrinks to the right), from the FMU's period output; circles: periods measured "
                                   "from simulations; crosses: scipy's 2K(m)/pi, on the FMU's curve"),
    ]
    files = [("runs.csv", "every run at every output point"), ("report.md", "this report's table in Markdown")]
    return write_html_report(out / "report.html", "The seed's study: the nonlinear pendulum at 75-90 deg", intro,
                             "Error table", TABLE_HEADER, rows, figures, files)
