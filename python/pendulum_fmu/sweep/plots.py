"""Summary plots of a sweep: period ratio, largest error and cost, each against what drives it."""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

from pendulum_fmu.fmu.period import exact_period_ratio

SOLVER_COLORS = {"dopri5": "tab:blue", "rk4": "tab:red", "rkn": "tab:green", "symplectic": "tab:purple",
                 "cvode": "tab:orange"}
MARKERS = "os^Dv<>ph*"


def _ok(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    return [row for row in rows if row["status"] == "ok"]


def _positive(values: Sequence[float]) -> np.ndarray:
    array = np.asarray(values, dtype=float)
    return np.where(array > 0.0, array, np.nan)


def _groups(rows: Sequence[dict[str, Any]], *columns: str) -> dict[tuple[Any, ...], list[dict[str, Any]]]:
    groups: dict[tuple[Any, ...], list[dict[str, Any]]] = defaultdict(list)
    for row in rows:
        groups[tuple(row[c] for c in columns)].append(row)
    return dict(sorted(groups.items(), key=lambda item: tuple(str(v) for v in item[0])))


def _method_style(solver: str, tolerance: float, tolerances: list[float]) -> dict[str, Any]:
    return {"color": SOLVER_COLORS.get(solver, "k"), "marker": MARKERS[tolerances.index(tolerance) % len(MARKERS)]}


def plot_period(rows: Sequence[dict[str, Any]], path: Path) -> None:
    """T/T0 against amplitude, one curve per initial velocity, with 2K(m)/pi for release from rest."""
    fig, ax = plt.subplots(figsize=(8, 4.8))
    for (omega0,), group in _groups(_ok(rows), "omega0_rad_s").items():
        group = sorted(group, key=lambda row: row["amplitude_deg"])
        ax.plot([r["amplitude_deg"] for r in group], [r["period_ratio"] for r in group], "o", ms=4,
                label=f"FMU period / T0, omega0 = {omega0:g} rad/s")
    amplitudes = [row["amplitude_deg"] for row in rows if row["omega0_rad_s"] == 0.0]
    if amplitudes:
        dense = np.linspace(min(amplitudes), max(amplitudes), 400)
        inside = np.abs(dense) < 180.0
        ax.plot(dense[inside], exact_period_ratio(np.radians(dense[inside])), "k--", lw=1,
                label="2 K(m) / pi, from rest (scipy)")
    ax.set_xlabel(r"amplitude $\theta_0$ (deg)")
    ax.set_ylabel(r"$T / T_0$,  $T_0 = 2\pi\sqrt{L/g}$")
    ax.set_title("Sweep: period against amplitude")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_error(rows: Sequence[dict[str, Any]], path: Path) -> None:
    """Largest |theta - theta_exact| against amplitude, one series per solver and tolerance."""
    ok = _ok(rows)
    tolerances = sorted({row["tolerance"] for row in ok})
    fig, ax = plt.subplots(figsize=(8.5, 4.8))
    for (solver, tol), group in _groups(ok, "solver", "tolerance").items():
        group = sorted(group, key=lambda row: row["amplitude_deg"])
        ax.semilogy([r["amplitude_deg"] for r in group], _positive([r["max_error_rad"] for r in group]), ms=3.5,
                    lw=0.8, label=_label(group[0]), **_method_style(solver, tol, tolerances))
    ax.set_xlabel(r"amplitude $\theta_0$ (deg)")
    ax.set_ylabel(r"max $|\theta - \theta_{exact}|$ (rad)")
    ax.set_title(f"Sweep: largest error over {ok[0]['periods']:g} periods" if ok else "Sweep: largest error")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _count(value: Any) -> float:
    """A solver counter of a row as a float: NaN where there is none (Model Exchange, or not read)."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        return math.nan
    return number if number > 0.0 else math.nan


def _label(row: dict[str, Any]) -> str:
    """``rkn (CS), tol 1e-08``: the solver, its interface and tolerance."""
    return f"{row['solver']} ({row['interface']}), tol {row['tolerance']:g}"


def plot_cost(rows: Sequence[dict[str, Any]], path: Path) -> None:
    """Work-precision: largest error against the FMU's right-hand-side evaluations per run.

    The count is the FMU's own and exact (wall time on a shared machine is noise). Model
    Exchange runs (fmpy's CVODE) have no such counter: they get a panel of their own against
    wall time, marked as Model Exchange.
    """
    ok = _ok(rows)
    tolerances = sorted({row["tolerance"] for row in ok})
    counted = [row for row in ok if math.isfinite(_count(row.get("rhs_evaluations")))]
    timed = [row for row in ok if row not in counted]
    panels = [(rows_, kind) for rows_, kind in ((counted, "rhs"), (timed, "wall")) if rows_]
    fig, axes = plt.subplots(1, len(panels), figsize=(8.5 + 3.5 * (len(panels) - 1), 4.8), sharey=True,
                             squeeze=False)
    for ax, (panel_rows, kind) in zip(axes[0], panels, strict=True):
        for _, group in _groups(panel_rows, "solver", "tolerance").items():
            x = ([_count(r["rhs_evaluations"]) for r in group] if kind == "rhs"
                 else [1e3 * r["wall_time_s"] for r in group])
            ax.loglog(x, _positive([r["max_error_rad"] for r in group]), ls="none", ms=4, alpha=0.7,
                      label=_label(group[0]), **_method_style(group[0]["solver"], group[0]["tolerance"], tolerances))
        # Labels at 1, 2 and 5 of each decade only: every minor tick labelled ran into its neighbours.
        ax.xaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        if kind == "rhs":
            ax.set_xlabel("right-hand-side evaluations per run (the FMU's count)")
            ax.set_title("Co-Simulation: error against the FMU's work")
        else:
            ax.set_xlabel("wall time per run (ms; no FMU counter)")
            ax.set_title("Model Exchange (fmpy's CVODE)")
        ax.grid(alpha=0.3, which="major")
    axes[0, 0].set_ylabel(r"max $|\theta - \theta_{exact}|$ (rad)")
    handles = [h for ax in axes[0] for h in ax.get_legend_handles_labels()[0]]
    labels = [label for ax in axes[0] for label in ax.get_legend_handles_labels()[1]]
    fig.legend(handles, labels, fontsize=7, loc="upper left", bbox_to_anchor=(0.8 if len(panels) > 1 else 0.77, 0.93))
    fig.suptitle("Sweep: error against cost")
    fig.tight_layout(rect=(0, 0, 0.8 if len(panels) > 1 else 0.77, 1))
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_sweep(rows: Sequence[dict[str, Any]], folder: Path) -> list[Path]:
    """Write ``sweep_period.png``, ``sweep_error.png`` and ``sweep_cost.png`` into ``folder``.

    A plot with nothing to show is not drawn (and one left by an earlier sweep into the same
    folder is removed): no period plot when every run failed, no error or cost plot (log
    axes) when no run has an error > 0.

    Returns
    -------
    list of Path
        The plots written.
    """
    ok = _ok(rows)
    measurable = [row for row in ok if np.isfinite(row["max_error_rad"]) and row["max_error_rad"] > 0.0]
    plots = [(plot_period, folder / "sweep_period.png", bool(ok)),
             (plot_error, folder / "sweep_error.png", bool(measurable)),
             (plot_cost, folder / "sweep_cost.png", bool(measurable))]
    written = []
    for plot, path, drawable in plots:
        if drawable:
            plot(rows, path)
            written.append(path)
        else:
            path.unlink(missing_ok=True)
    return written
