"""The verdict for people (one line per check), for CI (JSON) and as a figure (PNG)."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.judge.verdict import Verdict
from pendulum_fmu.output.atomic import write_whole


def lines(verdict: Verdict) -> list[str]:
    """One line per check (``name  STATUS  what``), then the verdict."""
    out = [f"{c.name:<16s}{c.status.upper():<6s}{c.line}" for c in verdict.checks]
    out.append(f"{'verdict':<16s}{verdict.line}")
    return out


def _replace_atomically(path: Path, write: Callable[[Path], object]) -> None:
    """Write whole or not at all (``write_whole``), into a folder created if missing."""
    path.parent.mkdir(parents=True, exist_ok=True)
    write_whole(path, write)


def _plain(value: Any) -> Any:
    """JSON-safe: non-finite floats as strings, numpy scalars as Python numbers."""
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    return value


def write_json(verdict: Verdict, path: Path) -> None:
    """The verdict as JSON (``Verdict.to_dict``), written whole or not at all."""
    text = json.dumps(_plain(verdict.to_dict()), indent=2) + "\n"
    _replace_atomically(path, lambda p: p.write_text(text))


def _log_values(values: np.ndarray) -> np.ndarray:
    """Values for a log axis: exact zeros (the error at t = 0) become NaN, not a plunge to a floor."""
    return np.where(values > 0.0, values, np.nan)


def _zero_ticks(ax: Any, time: np.ndarray, error: np.ndarray, color: str) -> None:
    """Mark the times where ``error`` is exactly 0 as ticks on the panel's bottom edge (labelled once)."""
    zero = error == 0.0
    if zero.any():
        ax.plot(time[zero], np.zeros(int(zero.sum())), "|", color=color, ms=9, mew=1.4, clip_on=False,
                transform=ax.get_xaxis_transform(), label="exactly 0 (ticks on the bottom edge)")


def write_plot(verdict: Verdict, path: Path) -> None:
    """|theta - exact| and |omega - exact| over time on a log scale, with the bound drawn
    (and the exact columns' differences when they are off).

    Parameters
    ----------
    verdict : Verdict
        The judged result's verdict: its series are drawn (nothing is read or computed again).
    path : Path
        The PNG to write.

    Raises
    ------
    ValueError
        A verdict without its series (one not made by :func:`pendulum_fmu.judge.judge`).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from pendulum_fmu.judge import checks

    series = verdict.series
    if series is None:
        raise ValueError("the verdict carries no series to plot")
    errors = series.errors
    fig, axes = plt.subplots(len(errors) or 1, 1, figsize=(9, 3.2 * max(1, len(errors))), sharex=True, squeeze=False)
    for ax, (name, error) in zip(axes[:, 0], errors.items(), strict=False):
        ax.semilogy(series.time, _log_values(np.abs(error)), lw=1, label=f"|{name} - {name}_exact|")
        _zero_ticks(ax, series.time, np.abs(error), "tab:blue")
        me = verdict.experiment.interface == "ME"
        factor = f"{checks.ME_FACTOR:g} tol" if me else f"{checks.CS_FACTOR:g} tol"
        scale = "max(1, |theta_e|)" if name == "theta" else "max(w0, |omega_e|)"
        ax.semilogy(series.time, series.allowed_error[name], "k--", lw=1.2,
                    label=f"bound {factor} {scale}" + (" x growth" if me else ""))
        exact_name = f"{name}_exact"
        difference = series.exact_column_differences.get(exact_name)
        if difference is not None and np.any(difference[0] > difference[1]):
            ax.semilogy(series.time, _log_values(difference[0]), color="tab:red", lw=1,
                        label=f"|{exact_name} column - pendulum_fmu.exact|")
        ax.set_ylabel(f"{name} error ({'rad' if name == 'theta' else 'rad/s'})")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=3, fontsize=8, frameon=False)  # off the curves
    if not errors:
        axes[0, 0].text(0.5, 0.5, "no theta or omega column", ha="center", transform=axes[0, 0].transAxes)
    axes[-1, 0].set_xlabel("time (s)")
    verdict_word = "PASS" if verdict.passed else "FAIL"
    e, problem = verdict.experiment, verdict.experiment.problem
    fig.suptitle(f"{Path(verdict.source).name}: {verdict_word}  ({e.interface}, tol {e.tolerance:g}, "
                 f"theta0 {problem.theta0_deg:.4g} deg, L {problem.L:g} m, g {problem.g:g} m/s$^2$)", fontsize=10)
    fig.tight_layout()
    _replace_atomically(path, lambda p: fig.savefig(p, dpi=110, format="png"))
    plt.close(fig)
