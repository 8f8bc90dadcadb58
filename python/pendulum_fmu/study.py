"""The seed's study: amplitudes 75-90 deg, Co-Simulation and Model Exchange, numeric vs exact."""

from __future__ import annotations

import argparse
import csv
import math
import os
import shutil
import sys
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .arguments import existing_file, positive
from .build import REPO_ROOT, build_fmu
from .errors import BuildError
from .locate import locate_fmu
from .report_html import Figure, write_html_report

# fmpy, scipy and matplotlib are imported where they are used, so that building the
# command line's parser (which imports this module) stays quick.
if TYPE_CHECKING:
    from .simulate import Interface, Run

SEED_AMPLITUDES_DEG = (75.0, 80.0, 85.0, 90.0)
ME_TOLERANCE = 1e-10
TABLE_HEADER = ("amplitude (deg)", "interface", "exact period (s)", "measured period (s)",
                "T/T0", "max abs(theta - theta_exact) (rad)")


def run_study(fmu: Path, periods: float = 10.0) -> list[Run]:
    """Simulate every seed amplitude in CS (default tolerance) and ME (rtol 1e-10).

    Parameters
    ----------
    fmu : Path
        The FMU.
    periods : float
        Exact periods to simulate.

    Returns
    -------
    list of Run
        CS runs first, then ME runs, each in the order of the amplitudes.
    """
    from .simulate import Scenario, simulate

    runs = []
    settings: tuple[tuple[Interface, float | None], ...] = (("CS", None), ("ME", ME_TOLERANCE))
    for interface, tolerance in settings:
        for amplitude in SEED_AMPLITUDES_DEG:
            scenario = Scenario(amplitude_deg=amplitude, periods=periods)
            runs.append(simulate(fmu, scenario, interface, tolerance))
    return runs


def table_rows(runs: list[Run]) -> list[tuple[str, ...]]:
    """One row of TABLE_HEADER per run."""
    from .period import exact_period, measured_period

    rows: list[tuple[str, ...]] = []
    for run in runs:
        s = run.scenario
        period = exact_period(math.radians(s.amplitude_deg), s.w0)
        measured = measured_period(run.result["time"], run.result["theta"])
        rows.append((f"{s.amplitude_deg:g}", run.interface, f"{period:.9f}", f"{measured:.9f}",
                     f"{period * s.w0 / (2 * math.pi):.6f}", f"{run.max_error:.2e}"))
    return rows


def format_table(rows: list[tuple[str, ...]]) -> str:
    """A Markdown table of the rows under TABLE_HEADER."""
    lines = ["| " + " | ".join(TABLE_HEADER) + " |", "|" + "---|" * len(TABLE_HEADER)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def write_csv(runs: list[Run], path: Path) -> None:
    """All runs in one long CSV: one line per run and time point."""
    with path.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["interface", "amplitude_deg", "time_s", "w0t", "theta_rad", "theta_exact_rad",
                         "omega_rad_s", "omega_exact_rad_s"])
        for run in runs:
            r = run.result
            for i in range(r.size):
                writer.writerow([run.interface, run.scenario.amplitude_deg, repr(float(r["time"][i])),
                                 repr(float(run.scenario.w0 * r["time"][i])), repr(float(r["theta"][i])),
                                 repr(float(r["theta_exact"][i])), repr(float(r["omega"][i])),
                                 repr(float(r["omega_exact"][i]))])


def period_ratio_curve(fmu: Path) -> tuple[np.ndarray, np.ndarray]:
    """T / T0 from the FMU's ``period`` output, amplitudes from 1 deg to 179.999999 deg.

    One Model Exchange instance is reset and re-initialized for each amplitude (L = 1,
    g = 9.81), and ``period`` is read right after initialization.
    """
    from fmpy import extract, instantiate_fmu, read_model_description

    amplitudes = 180.0 - np.logspace(np.log10(179.0), -6, 120)
    md = read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    w0 = math.sqrt(9.81)
    unzipped = extract(str(fmu))
    instance = instantiate_fmu(unzipped, md, fmi_type="ModelExchange")
    ratios = []
    for amplitude in amplitudes:
        instance.reset()
        instance.setupExperiment(startTime=0.0)
        instance.enterInitializationMode()
        instance.setReal([vr["theta"]], [math.radians(amplitude)])
        instance.exitInitializationMode()
        ratios.append(instance.getReal([vr["period"]])[0] * w0 / (2 * math.pi))
    instance.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)
    return amplitudes, np.array(ratios)


def write_report(out: Path, table: str, periods: float = 10.0) -> None:
    """A short Markdown report beside the figures."""
    text = f"""# The seed's study: the nonlinear pendulum released from rest at 75-90 deg

Co-Simulation uses the FMU's own solver at its default tolerance (1e-8); Model Exchange uses
fmpy's CVODE at relative tolerance {ME_TOLERANCE:g}. {periods:g} exact periods, 50 points a period.
The measured period is the slope of the downward zero crossings of theta.

{table}

- Figure 3 (numerical solution): `fig3_numeric.png`
- Figure 4 (exact Jacobi elliptic solution): `fig4_exact.png`
- Figure 5 (both overlaid): `fig5_overlay.png`
- Period ratio T/T0 against amplitude: `period_ratio.png`
- All runs: `runs.csv`
- Table and figures in one page: `report.html`
"""
    (out / "report.md").write_text(text)


NAME = "study"
HELP = "the seed's study: 75-90 deg, Figures 3-5, period ratio, error table, HTML report"
DESCRIPTION = """\
The seed's study (the README's main job): build the FMU, release the pendulum from rest at
75, 80, 85 and 90 deg, simulate it in Co-Simulation (the FMU's default solver, rkn, at its
default tolerance 1e-8) and in Model Exchange (fmpy's CVODE at 1e-10), and write to --out:
Figures 3-5 (theta against w0 t: numerical, exact, overlaid), the period ratio T/T0 against
amplitude up to 179.999999 deg, runs.csv, report.md and report.html (table and figures in one
page). The error table is printed.
"""
EPILOG = """\
examples:
  pendulum-fmu study                      # writes out/study/
  pendulum-fmu study --out /tmp/study --periods 5
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``study``."""
    parser.add_argument("--out", type=Path, default=REPO_ROOT / "out" / "study", metavar="DIR",
                        help="output folder (default: out/study in the repository)")
    parser.add_argument("--build-dir", type=Path, default=REPO_ROOT / "build", metavar="DIR",
                        help="CMake build folder, built incrementally before the study (default: build/)")
    parser.add_argument("--fmu", type=existing_file, metavar="PATH",
                        help="run this FMU instead of building one (default: $PENDULUM_FMU if set, else build)")
    parser.add_argument("--periods", type=positive("periods", 1000), default=10.0,
                        help="exact periods to simulate, in (0, 1000] (default 10)")


def study_fmu(args: argparse.Namespace) -> Path:
    """The FMU of the study: ``--fmu``, else ``$PENDULUM_FMU``, else an incremental CMake build."""
    if args.fmu is not None or os.environ.get("PENDULUM_FMU"):
        return locate_fmu(args.fmu)
    try:
        return build_fmu(args.build_dir)
    except RuntimeError as error:
        tail = "\n".join(str(error).strip().splitlines()[-15:])
        raise BuildError(f"building the FMU in {args.build_dir} failed:\n{tail}") from error


def write_html(out: Path, rows: list[tuple[str, ...]], periods: float) -> Path:
    """``report.html``: the error table and the four figures in one self-contained page."""
    worst = max(rows, key=lambda row: float(row[-1]))
    intro = [
        ("The undamped pendulum theta'' + (g/L) sin(theta) = 0 (L = 1 m, g = 9.81 m/s^2), released from "
         f"rest at the seed's amplitudes {', '.join(f'{a:g}' for a in SEED_AMPLITUDES_DEG)} deg, simulated "
         f"for {periods:g} exact periods with 50 output points a period, and compared at every point with "
         "the exact Jacobi-elliptic solution that the FMU computes beside its numerical one."),
        ("Co-Simulation (CS) runs the FMU's default solver rkn (Runge-Kutta-Nystrom 12(10)) at its default tolerance 1e-8; "
         f"Model Exchange (ME) runs fmpy's CVODE at relative tolerance {ME_TOLERANCE:g}. The exact period is "
         "4 K(m)/w0 with m = sin^2(theta0/2); the measured period is the least-squares slope of the downward "
         "zero crossings of the numerical theta."),
        f"Largest error: {worst[-1]} rad ({worst[1]}, {worst[0]} deg).",
    ]
    figures = [
        Figure("fig3_numeric.png", "Figure 3: the numerical solution theta against w0 t (FMU, Co-Simulation)"),
        Figure("fig4_exact.png", "Figure 4: the exact solution (Jacobi elliptic functions, computed in the FMU)"),
        Figure("fig5_overlay.png", "Figure 5: numerical (lines) and exact (dots) overlaid"),
        Figure("period_ratio.png", "The period ratio T/T0 against amplitude, from the FMU's period output, "
                                   "with the small-angle and near-the-top asymptotes"),
    ]
    files = [("runs.csv", "every run at every output point"), ("report.md", "this report's table in Markdown")]
    return write_html_report(out / "report.html", "The seed's study: the nonlinear pendulum at 75-90 deg", intro,
                             "Error table", TABLE_HEADER, rows, figures, files)


def run(args: argparse.Namespace) -> int:
    """Run the study with parsed arguments; write plots, CSV, table and reports to ``args.out``."""
    from .plots import plot_period_ratio, plot_theta_against_w0t

    fmu = study_fmu(args)
    args.out.mkdir(parents=True, exist_ok=True)
    runs = run_study(fmu, args.periods)
    cs_runs = [r for r in runs if r.interface == "CS"]
    plot_theta_against_w0t(cs_runs, "numeric", "Figure 3: numerical solution (FMU, Co-Simulation)",
                           args.out / "fig3_numeric.png")
    plot_theta_against_w0t(cs_runs, "exact", "Figure 4: exact solution (Jacobi elliptic functions)",
                           args.out / "fig4_exact.png")
    plot_theta_against_w0t(cs_runs, "overlay", "Figure 5: numerical (lines) and exact (dots) overlaid",
                           args.out / "fig5_overlay.png")
    plot_period_ratio(*period_ratio_curve(fmu), args.out / "period_ratio.png")
    write_csv(runs, args.out / "runs.csv")
    rows = table_rows(runs)
    table = format_table(rows)
    write_report(args.out, table, args.periods)
    write_html(args.out, rows, args.periods)
    print(table)
    print(f"\nwritten to {args.out} (open report.html)")
    return 0


def main(argv: list[str] | None = None) -> int:
    """``python -m pendulum_fmu.study [options]``: the same as ``pendulum-fmu study``."""
    from .cli import main as cli_main

    return cli_main(["study", *(sys.argv[1:] if argv is None else argv)])


if __name__ == "__main__":
    raise SystemExit(main())
