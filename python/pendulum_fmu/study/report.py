"""The study's reports: ``report.md`` and the self-contained ``report.html``."""

from __future__ import annotations

import csv
from collections.abc import Sequence
from pathlib import Path

from pendulum_fmu.output.report_html import Figure, Section, write_html_report
from pendulum_fmu.study.hard_cases import (
    CSV_COLUMNS,
    HARD_HEADER,
    LARGE_START_S,
    LONG_PERIODS,
    LONG_PERIODS_ME,
    HardRun,
    hard_record,
    hard_rows,
    hard_summary,
)
from pendulum_fmu.study.seed import ME_TOLERANCE, SEED_AMPLITUDES_DEG, TABLE_HEADER
from pendulum_fmu.study.speed import (
    CS_TOLERANCES,
    ME_TOLERANCES,
    POINT_COLUMNS,
    SPEED_HEADER,
    SpeedStudy,
    fastest_sentence,
    point_record,
    speed_rows,
)

SPEED_FIGURE = "speed_vs_error.png"
"""The work-precision figure's file."""


def markdown_table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    """A Markdown table of already formatted cells."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def write_records(path: Path, header: Sequence[str], records: Sequence[Sequence[str]]) -> None:
    """A CSV file: the header, then one line a record."""
    with path.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(header)
        writer.writerows(records)


def write_speed_and_hard_cases(out: Path, speed: SpeedStudy, hard: list[HardRun]) -> None:
    """``speed.csv`` (one line a method and tolerance) and ``hard_cases.csv`` (one line a run)."""
    write_records(out / "speed.csv", POINT_COLUMNS, [point_record(p) for p in speed.points])
    write_records(out / "hard_cases.csv", CSV_COLUMNS, [hard_record(r) for r in hard])


def speed_text(speed: SpeedStudy) -> list[str]:
    """The paragraphs above the speed table: what ran, how cost and error are counted, the fastest."""
    amplitudes = ", ".join(f"{a:g}" for a in speed.amplitudes_deg)
    return [
        (f"Every solver at the seed's amplitudes ({amplitudes} deg from rest, {speed.periods:g} exact periods each, "
         f"50 points a period): the FMU's four Co-Simulation solvers at tolerances {CS_TOLERANCES[0]:.0e} to "
         f"{CS_TOLERANCES[-1]:.0e}, Model Exchange through fmpy's CVODE at {ME_TOLERANCES[0]:.0e} to "
         f"{ME_TOLERANCES[-1]:.0e}. Error: the largest max |theta - theta_exact| of the four runs. Cost: their "
         "right-hand-side evaluations (the FMU's stats.rhs_evaluations; CVODE's fmi2GetDerivatives calls, its "
         "Jacobian's included), machine-independent, and their wall time per simulated period on this machine "
         "(best of 3 runs in Co-Simulation, of 2 through CVODE). A cell is the cost to reach the error level, "
         "read off the method's "
         "cheapest points by log-log interpolation; '-': not reached at any tolerance. The floor is the exact "
         "solution's own cost, the FMU's Jacobi-elliptic evaluation at the same points, which evaluates no "
         "right-hand side."),
        fastest_sentence(speed),
    ]


def hard_text(hard: list[HardRun]) -> list[str]:
    """The paragraphs above the hard cases' table: what ran, how a step's certificate is read, the count."""
    return [
        ("Every Co-Simulation solver at the FMU's default tolerance (1e-8) and CVODE (Model Exchange) at "
         f"{ME_TOLERANCE:g}, 50 points a period, on releases next to the top, a rotation just above the "
         f"separatrix, a creep over the top, a long run ({LONG_PERIODS:g} periods; CVODE {LONG_PERIODS_ME:g}, "
         f"since its Python call per evaluation would take about half a minute for all) and a start at "
         f"t0 = {LARGE_START_S:g} s. A Co-Simulation step returns OK only within 100 tol of the exact solution "
         "(the certificate, docs/certificate.md); 'every step certified?' counts the steps beyond that bound, "
         "recomputed from the run's outputs by the certificate's rule, and the warnings the FMU logged for "
         "them (a message at the first crossing and at each tenfold growth; 'hard case' when the solution is "
         "qualitatively wrong). Model Exchange is integrated by the importer, which the FMU cannot certify: "
         "its points beyond 100 tol are counted instead. A run that fails or ends early says so."),
        hard_summary(hard),
    ]


def write_report(out: Path, table: str, periods: float = 10.0, speed: SpeedStudy | None = None,
                 hard: list[HardRun] | None = None) -> None:
    """A short Markdown report beside the figures (with the speed and hard-case sections when given)."""
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
    if speed is not None:
        text += ("\n## Speed against error\n\n" + "\n\n".join(speed_text(speed)) + "\n\n"
                 + markdown_table(SPEED_HEADER, speed_rows(speed))
                 + f"\n\n- Work-precision figure: `{SPEED_FIGURE}`; every point: `speed.csv`\n")
    if hard is not None:
        text += ("\n## Hard cases\n\n" + "\n\n".join(hard_text(hard)) + "\n\n"
                 + markdown_table(HARD_HEADER, hard_rows(hard)) + "\n\n- Every run: `hard_cases.csv`\n")
    (out / "report.md").write_text(text)


def write_html(out: Path, rows: list[tuple[str, ...]], periods: float, speed: SpeedStudy | None = None,
               hard: list[HardRun] | None = None) -> Path:
    """``report.html``: the error table and the figures in one self-contained page (with the speed
    and hard-case sections when given)."""
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
    if speed is not None and hard is not None:
        intro.append("After the figures: speed against error (every solver over a range of tolerances, with the "
                     "fastest at each error level) and the hard cases (near and over the top, long, late), "
                     "each solver's error, certificate and cost.")
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
    files = [("runs.csv", "every run at every output point"), ("report.md", "this report's tables in Markdown")]
    sections = []
    if speed is not None:
        caption = ("Speed against error: max |theta - theta_exact| over the seed's amplitudes (more accurate to the "
                   "right) against right-hand-side evaluations (left) and wall time per simulated period (right, "
                   "with the exact solution's cost as the floor); one marker a tolerance, the loosest and the "
                   "tightest labelled on the left")
        sections.append(Section("Speed against error", speed_text(speed), SPEED_HEADER, speed_rows(speed),
                                (Figure(SPEED_FIGURE, caption),), left_columns=(0,), nowrap=True))
        files.append(("speed.csv", "every method at every tolerance: error, evaluations, wall time"))
    if hard is not None:
        sections.append(Section("Hard cases", hard_text(hard), HARD_HEADER, hard_rows(hard), left_columns=(0, 1, 4)))
        files.append(("hard_cases.csv", "every hard-case run: error, certificate, warnings, cost"))
    return write_html_report(out / "report.html", "The seed's study: the nonlinear pendulum at 75-90 deg", intro,
                             "Error table", TABLE_HEADER, rows, figures, files, sections)
