"""Human-readable lines about a run, printed by simulate, compare and animate."""

from __future__ import annotations

import math
import re

from pendulum_fmu.fmu.runner import Trajectory, reference_period


def pendulum_text(trajectory: Trajectory) -> str:
    """``amplitude 75 deg, omega0 0 rad/s, L 1 m, g 9.81 m/s^2``.

    The initial angle is the amplitude only when the pendulum is released from rest; with
    omega0 != 0 it swings further (or goes over the top), so it is called the initial angle.
    """
    p = trajectory.problem
    angle = "amplitude" if p.omega0 == 0.0 else "initial angle"
    return (f"{angle} {p.theta0_deg:.6g} deg, omega0 {p.omega0:g} rad/s, L {p.L:g} m, "
            f"g {p.g:g} m/s^2")


def periods_text(count: float) -> str:
    """``1 period``, ``2.5 periods`` (the number to 6 significant digits)."""
    text = f"{count:.6g}"
    return f"{text} period" if text == "1" else f"{text} periods"


def summary_lines(trajectory: Trajectory) -> list[str]:
    """What was run, the exact period, the cost and the error, one fact a line."""
    p, t = trajectory.problem, trajectory
    period = t.period
    stop = float(t.result["time"][-1])
    if math.isfinite(period):
        period_text = f"{period:.9g} s (exact, from the FMU), T/T0 = {period / p.small_angle_period:.6f}"
    else:
        period_text = "infinite (separatrix): times counted in T0 = 2 pi / w0"
    cost = f"{t.wall_time * 1e3:.1f} ms"
    if t.steps is not None:
        cost = (f"{t.steps} steps, {t.rejected_steps} rejected, {t.rhs_evaluations} right-hand-side "
                f"evaluations, {cost}")
    return [
        f"pendulum  {pendulum_text(t)} (w0 = {p.w0:.6g} rad/s)",
        f"method    {t.method.label}",
        f"period    {period_text}",
        (f"run       {t.result.size} output points to t = {stop:.6g} s "
         f"({periods_text(stop / reference_period(period, p))}); {cost}"),
        (f"error     max |theta - theta_exact| = {t.max_error:.3e} rad, "
         f"max |omega - omega_exact| = {t.max_omega_error:.3e} rad/s"),
    ] + warning_lines(t.warnings)


CERTIFICATE = re.compile(r"^certificate: at t = (\S+) the step is (\S+) times beyond its bound \(.*?\)\. (.*)$")
"""A certificate message of the FMU: the time, the ratio to the bound, the detail and the remedy."""


def certificate_line(messages: list[re.Match[str]]) -> str:
    """The FMU's certificate messages of one run (logged at the first miss and at each tenfold
    growth) said once: where it began, how far it grew, the remedy without its numbers."""
    first, last = messages[0], messages[-1]
    remedy = re.sub(r" \([^()]*\)", "", last[3]).rstrip(".")
    growth = f", growing to {last[2]} times" if len(messages) > 1 else ""
    return (f"warning   the step certificate failed from t = {float(first[1]):.6g} s on ({first[2]} times "
            f"its bound{growth}): {remedy[:1].lower()}{remedy[1:]}")


def warning_lines(warnings: tuple[str, ...]) -> list[str]:
    """What the FMU warned about during a run: the certificate's messages in one short line,
    any other warning in one line as the FMU logged it (nothing when it warned of nothing)."""
    # a hard case's message carries the certificate's of the same step at its end: said apart
    parts = [part for w in warnings for part in re.split(r" (?=certificate: at t = )", w)]
    matches = [CERTIFICATE.match(part) for part in parts]
    certificates = [m for m in matches if m is not None]
    others = [part for part, m in zip(parts, matches, strict=True) if m is None]
    lines = [f"warning   the FMU: {'; '.join(others)}"] if others else []
    return lines + ([certificate_line(certificates)] if certificates else [])
