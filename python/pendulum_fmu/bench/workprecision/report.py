"""Outputs of the speed-against-error study: CSV files, work-precision PNGs, Markdown tables."""

from __future__ import annotations

import csv
import dataclasses
import math
from pathlib import Path

from pendulum_fmu.bench.workprecision.analysis import Point, cost_at, curve
from pendulum_fmu.bench.workprecision.cdriver import Floor
from pendulum_fmu.bench.workprecision.runs import Run

LEVELS: tuple[float, ...] = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
"""Error levels of the tables."""

OUR_COLORS = {"rkn": "tab:green", "dopri5": "tab:blue", "rk4": "tab:red", "symplectic": "tab:purple"}
PEER_COLORS = {"DOP853": "tab:orange", "dop853": "tab:brown", "RK45": "tab:olive", "LSODA": "tab:cyan",
               "Radau": "tab:pink", "cvode": "tab:gray", "euler": "black"}


def write_csv(path: Path, rows: list[Run] | list[Point] | list[Floor]) -> None:
    """Writes dataclass records as CSV (one column per field, plus the Point label)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not rows:
        path.write_text("")
        return
    names = [f.name for f in dataclasses.fields(rows[0])]
    extra = ["label"] if isinstance(rows[0], Point) else []
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(names + extra)
        for row in rows:
            values = [getattr(row, n) for n in names]
            writer.writerow([f"{v:.6g}" if isinstance(v, float) else v for v in values]
                            + ([row.label] if isinstance(row, Point) else []))


def _series(points: list[Point], problem: str) -> list[tuple[str, str, list[Point]]]:
    """(runner, method, curve) of every method with points on the problem."""
    seen: list[tuple[str, str]] = []
    for p in points:
        if p.problem == problem and (p.runner, p.method) not in seen:
            seen.append((p.runner, p.method))
    return [(r, m, curve(points, problem, r, m)) for r, m in seen]


def plot_problem(points: list[Point], floors: list[Floor], problem: str, title: str, path: Path) -> None:
    """Work-precision diagram of one problem: error against evaluations and against wall time.

    Parameters
    ----------
    points : list of Point
        All points.
    floors : list of Floor
        The exact evaluation's cost (drawn as a horizontal line on the wall-time panel).
    problem : str
        The problem.
    title : str
        Figure title.
    path : Path
        PNG to write.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_ev, ax_wall) = plt.subplots(1, 2, figsize=(15, 8.5), constrained_layout=True)
    for runner, method, pts in _series(points, problem):
        if not pts:
            continue
        ours = runner in ("c", "fmpy")
        color = OUR_COLORS.get(method, "k") if ours else PEER_COLORS.get(method, "k")
        errors = [max(p.max_err, 1e-16) for p in pts]
        style = {"color": color, "marker": "o" if ours else "s", "markersize": 4,
                 "linewidth": 2.2 if method == "rkn" else 1.3}
        label = pts[0].label
        if runner != "fmpy":  # the FMU's counts are the same through fmpy and the C driver
            ax_ev.loglog(errors, [p.rhs_evaluations for p in pts], label=label.replace(", C driver", ""),
                         linestyle=":" if method == "euler" else "-", **style)
        ax_wall.loglog(errors, [p.wall_per_period for p in pts], label=label,
                       linestyle="--" if runner == "fmpy" else (":" if method == "euler" else "-"), **style)
        flips = [p for p in pts if p.flipped]
        for ax, key in ((ax_ev, "rhs_evaluations"), (ax_wall, "wall_per_period")):
            if flips and not (ax is ax_ev and runner == "fmpy"):
                ax.loglog([max(p.max_err, 1e-16) for p in flips], [getattr(p, key) for p in flips], "x",
                          color="red", markersize=9, markeredgewidth=2)
    case_floors = [f for f in floors if f.problem == problem]
    if case_floors:
        per_period = sum(f.wall_s for f in case_floors) / sum(f.periods for f in case_floors)
        ax_wall.axhline(per_period, color="k", linewidth=1, linestyle="-.",
                        label="floor: exact solution at the same points (C)")
    ax_ev.set_xlabel("max |theta - theta_exact| (rad)")
    ax_ev.set_ylabel("right-hand-side evaluations")
    ax_ev.set_title("cost in evaluations of sin (machine-independent)")
    ax_wall.set_xlabel("max |theta - theta_exact| (rad)")
    ax_wall.set_ylabel("wall time per simulated period (s)")
    ax_wall.set_title("cost in wall time (this machine)")
    for ax in (ax_ev, ax_wall):
        ax.grid(True, which="major", alpha=0.4)
        ax.invert_xaxis()
    ax_ev.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3)
    ax_wall.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3)
    fig.suptitle(title + "   (red x: a libration turned into a rotation)")
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _fmt_cost(evals: float, wall: float) -> str:
    if not math.isfinite(evals):
        return "-"
    return f"{evals:,.0f} ({wall * 1e6:.3g} us)".replace(",", " ")


def cost_table(points: list[Point], problem: str) -> str:
    """Markdown table: evaluations (and wall time per period) to reach each error level.

    Parameters
    ----------
    points : list of Point
        All points.
    problem : str
        The problem.

    Returns
    -------
    str
        One row per method: the cost at each of :data:`LEVELS` ("-": not reached), the best
        error reached, the tolerances at which a libration flipped.
    """
    head = ("| method | " + " | ".join(f"err {level:.0e}" for level in LEVELS)
            + " | best error | flipped at tol |")
    lines = [head, "|" + "---|" * (len(LEVELS) + 3)]
    for _runner, _method, pts in _series(points, problem):
        if not pts:
            continue
        cells = [_fmt_cost(cost_at(pts, level), cost_at(pts, level, "wall_per_period")) for level in LEVELS]
        flips = ", ".join(f"{p.tol:g}" for p in pts if p.flipped) or "none"
        best = min(p.max_err for p in pts)
        lines.append(f"| {pts[0].label} | " + " | ".join(cells) + f" | {best:.1e} | {flips} |")
    return "\n".join(lines)


def energy_table(points: list[Point], problem: str) -> str:
    """Markdown table of the energy behaviour: max |dH/H| over the first and the last tenth."""
    lines = ["| method | tol | max error | max \\|dH/H\\| first tenth | last tenth | evaluations |",
             "|---|---|---|---|---|---|"]
    for _, _, pts in _series(points, problem):
        for p in pts:
            if p.runner == "fmpy":
                continue
            evaluations = f"{p.rhs_evaluations:,}".replace(",", " ")
            lines.append(f"| {p.label} | {p.tol:g} | {p.max_err:.2e} | {p.energy_err_first:.2e} | "
                         f"{p.energy_err_last:.2e} | {evaluations} |")
    return "\n".join(lines)
