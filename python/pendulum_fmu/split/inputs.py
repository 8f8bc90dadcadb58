"""The input Body held over each step, read back from its outputs, and the defects it shows.

Body integrates theta' = omega, omega' = alpha in closed form, so over a step of h with its
input held, omega_(k+1) - omega_k = a_k h exactly (docs/split.md): a_k is the value the master
gave Body. Gravity's law is alpha = -(g/L) sin(theta). Two fits of a_k, no rerun needed:

- **held to round-off** (a zero-order hold, every row a communication point, a full print): a_k
  equals c F(s_(k-l)) to round-off for a signal s of Body's (theta when connected right), a ratio c
  (1 when the FMUs agree; -1 a wrong sign; else a parameter mismatch) and a lag l per step (0
  Gauss-Seidel, 1 Jacobi; more: an input stale by l - base exchanges). An input refreshed only
  every m-th step from the start on is a multirate master (legal); a stale input at other steps
  is a defect, counted.
- **on average** (interpolation, extrapolation, iteration, decimated rows, a short print): a_k is
  the mean of alpha over the step, c times the Simpson mean of F along the step, fitted by least
  squares; the same ratio and signal follow, to the fit's precision.

A constant a_k over every step is a dropped connection; a_k = 0 over the first steps only, an
input whose start value was dropped.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pendulum_fmu.split.diagnosis import Finding

EPS = float(np.finfo(float).eps)
MAX_LAG = 8
"""Largest lag looked for, in communication points."""
HELD_SHARE = 0.5
"""A zero-order-hold fit holds when it explains at least this share of the steps to round-off."""
RATIO_SLACK = 2e-4
"""On average, a ratio within this of 1 (or -1), or within :data:`RESIDUAL_FACTOR` times the fit's
relative residual, is the FMUs agreeing (or a sign error alone): an honest master's mean input
differs from the Simpson mean of F by its coupling error, O(H^p), which the fit's terms in h dF/dt
and h^2 d2F/dt2 take up but for a bias of up to 20 times the residual (measured on the tuning
part of tests/helpers/split_corpus.py: 1.1e-3 for a ramp extrapolated from past values at H = 0.02,
residual 1.5e-4)."""
RESIDUAL_FACTOR = 30.0
"""See :data:`RATIO_SLACK`."""
FIT_RESIDUAL = 0.2
"""On average, a fit whose relative residual is above this explains nothing."""


@dataclass(frozen=True)
class Law:
    """How Body's input followed Body's outputs.

    Attributes
    ----------
    signal : str
        ``"theta"`` (right), ``"omega"`` or ``"theta_exact"`` (Gravity fed that output), or
        ``"constant"`` (a_k never changed).
    ratio : float
        c in a_k = c * -(g/L) sin(signal), g/L the run's; for ``"constant"``, the constant.
    held : bool
        Fitted to round-off with a lag per step (else on average).
    share : float
        Share of the steps the fit explains (held) or its relative residual (on average).
    precision : float
        How far the ratio may sit from the truth (the print's and round-off's share in a held
        fit; :data:`RATIO_SLACK` or :data:`RESIDUAL_FACTOR` times the residual on average).
    lags : numpy.ndarray or None
        Per step: the lag (>= 0), -1 none, -2 an input of 0 (held fits only).
    """

    signal: str
    ratio: float
    held: bool
    share: float
    lags: np.ndarray | None = None
    precision: float = 1e-9


def _gravity(k: float, s: np.ndarray) -> np.ndarray:
    return -k * np.sin(s)


def _tolerance(a: np.ndarray, h: np.ndarray, omega: np.ndarray, res_omega: np.ndarray, k: float,
               res_signal: np.ndarray) -> np.ndarray:
    """How far a_k may sit from the held value: round-off of omega + a h, the print of omega
    and of the signal the value came from."""
    return (1e-9 * np.maximum(1.0, np.abs(a)) + 8 * EPS * (np.abs(omega[1:]) + np.abs(omega[:-1])) / h
            + (res_omega[1:] + res_omega[:-1]) / h + k * (np.max(res_signal) if res_signal.size else 0.0))


def _lag_match(a: np.ndarray, F: np.ndarray, tol: np.ndarray, lag: int) -> np.ndarray:
    """Per step k >= lag: whether a_k is F at k - lag."""
    out = np.zeros(a.size, dtype=bool)
    if lag < a.size:
        out[lag:] = np.abs(a[lag:] - F[: a.size - lag]) <= tol[lag:]
    return out


def held_fit(a: np.ndarray, tol: np.ndarray, signals: dict[str, np.ndarray], k: float) -> Law | None:
    """The zero-order-hold law that explains the most steps to round-off, with each step's lag;
    None when none explains :data:`HELD_SHARE` of them."""
    best: Law | None = None
    for name, s in signals.items():
        F = _gravity(k, s)
        for lag in (0, 1, 2):
            if a.size <= lag + 2:
                continue
            base = F[: a.size - lag]
            usable = np.abs(base) > 0.05 * k
            if np.count_nonzero(usable) < max(3, 0.05 * usable.size):
                continue
            ratios = a[lag:][usable] / base[usable]
            bins, counts = np.unique(np.round(ratios, 7), return_counts=True)
            ratio = float(np.median(ratios[np.round(ratios, 7) == bins[np.argmax(counts)]]))
            if abs(ratio) < 1e-3:  # an input of 0 against a Gravity that is not: no law of Gravity's
                continue
            precision = 1e-9 + 3 * float(np.median(tol[lag:][usable] / np.abs(base[usable])))
            for snap in (1.0, -1.0):
                if abs(ratio - snap) <= precision:
                    ratio = snap
            matched = np.zeros(a.size, dtype=bool)
            for other in range(MAX_LAG + 1):
                matched |= _lag_match(a, ratio * F, tol, other)
            # steps where F is near 0 fit any ratio: the share counts the others only
            share = float(np.mean(matched[lag:][usable]))
            if share >= HELD_SHARE and (best is None or share > best.share + 1e-12):
                best = Law(name, ratio, True, share, None, precision)
    if best is None:
        return None
    F = best.ratio * _gravity(k, signals[best.signal])
    matches = np.array([_lag_match(a, F, tol, lag) for lag in range(MAX_LAG + 1)])
    # the exchange's own lag (Gauss-Seidel 0, Jacobi 1) wins where several fit (near a turning
    # point theta barely moves over a step); elsewhere the smallest lag that fits
    own = 0 if np.count_nonzero(matches[0]) >= np.count_nonzero(matches[1]) else 1
    lags = np.where(matches.any(axis=0), np.argmax(matches, axis=0), -1)
    lags[matches[own]] = own
    lags[(lags == -1) & (np.abs(a) <= tol)] = -2
    return Law(best.signal, best.ratio, True, best.share, lags, best.precision)


def mean_fit(a: np.ndarray, h: np.ndarray, signals: dict[str, np.ndarray], omega: np.ndarray,
             k: float) -> Law | None:
    """The law a_k = c * Simpson mean of F(signal) over the step that fits best (least squares)."""
    best: Law | None = None
    for name, s in signals.items():
        if name == "theta":  # Hermite midpoint of theta from omega at both ends
            middle = (s[1:] + s[:-1]) / 2 + h * (omega[:-1] - omega[1:]) / 8
        else:
            middle = (s[1:] + s[:-1]) / 2
        mean = (_gravity(k, s[:-1]) + 4 * _gravity(k, middle) + _gravity(k, s[1:])) / 6
        # the coupling's own error: a shift in time (h dF/dt) and a curvature (h^2 d2F/dt2) of the input
        rate = (_gravity(k, s[1:]) - _gravity(k, s[:-1])) / h
        curve = np.zeros_like(rate)
        curve[1:-1] = (rate[2:] - rate[:-2]) / (h[2:] + h[:-2])
        design = np.column_stack([mean, h * rate, h * h * curve])
        weight = np.sqrt(h / np.sum(h))
        try:
            coef = np.linalg.lstsq(design * weight[:, None], a * weight, rcond=None)[0]
        except np.linalg.LinAlgError:
            continue
        ratio = float(coef[0])
        norm = float(np.sum(weight ** 2 * a * a))
        if norm <= 0:
            continue
        residual = float(np.sqrt(np.sum(weight ** 2 * (a - design @ coef) ** 2) / norm))
        # theta, the right signal, is tried first; another wins only by fitting ten times better
        if best is None or residual < (0.1 if best.signal == "theta" else 1.0) * best.share:
            best = Law(name, ratio, False, residual, None, max(RATIO_SLACK, RESIDUAL_FACTOR * residual))
    if best is None or best.share > FIT_RESIDUAL:
        return None
    return best


def read_law(time: np.ndarray, values: dict[str, np.ndarray], resolution: dict[str, np.ndarray],
             k: float) -> Law | None:
    """Body's input law (see the module's docstring), None when the file has no omega or no fit holds.

    Parameters
    ----------
    time : numpy.ndarray
        The communication points (the grid's exact times).
    values, resolution : dict of str to numpy.ndarray
        Body's columns and their print resolution.
    k : float
        The run's g / L.
    """
    if "omega" not in values or time.size < 4:
        return None
    omega = values["omega"]
    h = np.diff(time)
    a = np.diff(omega) / h
    tol = _tolerance(a, h, omega, resolution["omega"], k, resolution["theta"])
    if np.all(np.abs(a - a[0]) <= tol):
        gravity = _gravity(k, values["theta"][:-1])
        if np.all(np.abs(a - gravity) <= tol):  # at rest at theta = 0 (or pi): Gravity's alpha is constant too
            return Law("theta", 1.0, True, 1.0, np.zeros(a.size, dtype=int))
        return Law("constant", float(a[0]), True, 1.0, np.full(a.size, -1))
    signals = {"theta": values["theta"], "omega": omega}
    if "theta_exact" in values:
        signals["theta_exact"] = values["theta_exact"]
    return held_fit(a, tol, signals, k) or mean_fit(a, h, signals, omega, k)


def _multirate_period(lags: np.ndarray, base: int) -> int | None:
    """m when Body's input was refreshed at every m-th step from the first on, else None.

    Such a master's lag at step k is ``base + k mod m``; where theta barely moves over a step (a
    turning point) a held value also equals the fresh one to round-off and the step reads as
    ``base``, which fits too. The schedule must be what most held steps show, so an input stale
    now and then is not taken for one.
    """
    k = np.arange(lags.size)
    known = lags >= 0
    for m in range(2, MAX_LAG - base + 2):
        scheduled = base + k % m
        held = known & (scheduled > base)
        fits = (lags == scheduled) | (lags == base)
        if held.any() and np.all(fits[known]) and \
                np.count_nonzero(lags[held] == scheduled[held]) >= 0.5 * np.count_nonzero(held):
            return m
    return None


@dataclass(frozen=True)
class Schedule:
    """What the lags say of the master's exchanges.

    Attributes
    ----------
    base : int
        The lag of a fresh input: 0 Gauss-Seidel (Gravity's alpha of the same point), 1 Jacobi.
    multirate : int
        m > 1 when Body's input was refreshed at every m-th step only (from the first on), else 1.
    """

    base: int
    multirate: int = 1

    def describe(self) -> str:
        """The exchange in words."""
        order = "Gauss-Seidel order (Gravity's alpha of the same point)" if self.base == 0 else \
            "Jacobi order (Gravity's alpha of the point before)"
        if self.multirate > 1:
            return f"{order}, Body's input refreshed every {self.multirate} macro steps (multirate)"
        return order


def law_findings(law: Law, k: float, exact_signal_ok: bool = True) -> tuple[list[Finding], Schedule | None]:
    """The defects a law shows, and the exchange schedule (held fits with lags)."""
    findings: list[Finding] = []
    if law.signal == "constant":
        what = "0 (never set)" if law.ratio == 0 else f"{law.ratio:.9g} rad/s2"
        findings.append(Finding("dropped", f"a connection dropped: Body's input alpha stayed {what} over every step "
                                           "(Gravity's alpha never reached Body, or Body's theta never Gravity)"))
        return findings, None
    how = f"to round-off at {100 * law.share:.0f} % of the steps" if law.held else "on average over the run"
    if law.signal != "theta":
        findings.append(Finding("connection", f"wrong connection: Gravity's input theta is fed Body's {law.signal} "
                                              f"(Body's alpha = {law.ratio:.6g} * -(g/L) sin({law.signal}) "
                                              f"{how})"))
    slack = law.precision
    if law.ratio < 0:
        findings.append(Finding("sign", f"wrong sign: Body's input is +(g/L) sin({law.signal}) (alpha = "
                                        f"{law.ratio:.6g} * -(g/L) sin): Gravity's alpha enters Body negated"))
    size = abs(law.ratio)
    # on average, a wrong signal's ratio carries the fit's bias (its midpoint has no Hermite term)
    if abs(size - 1) > slack and (law.held or law.signal == "theta"):
        findings.append(Finding("parameter", f"parameter mismatch: Gravity computes g/L = {size * k:.6g} 1/s2 where "
                                             f"Body's pendulum has {k:.6g} (ratio {size:.6g}): Gravity's g = "
                                             f"{size * k:.6g} m/s2 for L = 1 m, or Gravity's L = {1 / size:.6g} "
                                             "times Body's"))
    if not law.held or law.lags is None:
        return findings, None
    more, schedule = _lag_findings(law.lags)
    return findings + more, schedule


def _lag_findings(lags: np.ndarray) -> tuple[list[Finding], Schedule | None]:
    total = lags.size
    leading = next((i for i, lag in enumerate(lags) if lag != -2), total)
    if 0 < leading < total:
        return [Finding("start-dropped", f"an input's start value dropped: Body's alpha was 0 over the first "
                                         f"{leading} step(s) instead of Gravity's")], None
    fresh = lags[lags >= 0]
    if fresh.size == 0:
        return [], None
    counted = np.bincount(fresh, minlength=MAX_LAG + 1)
    base = 0 if counted[0] > 0 and counted[0] >= 0.1 * fresh.size else 1
    findings: list[Finding] = []
    early = np.flatnonzero(lags == 0)
    early = early[early >= 1]  # at the first step Jacobi's alpha is Gravity's start, of the same point
    if base == 1 and early.size:
        findings.append(Finding("out-of-order", f"steps out of order: in a Jacobi exchange Body got Gravity's alpha of "
                                                f"the same communication point at {early.size} of {total} steps "
                                                f"(first at step {early[0]}): Gravity was fed and read before Body's "
                                                "input there"))
    period = _multirate_period(lags, base)
    if period is not None:
        return findings, Schedule(base, period)
    stale = lags - base
    late = stale[(stale > 0) & (lags >= 0)]
    if late.size:
        first = int(np.flatnonzero((stale > 0) & (lags >= 0))[0])
        counts = ", ".join(f"by {j} at {np.count_nonzero(late == j)}" for j in range(1, MAX_LAG + 1)
                           if np.count_nonzero(late == j))
        old = "one exchange" if late.max() == 1 else "several exchanges"
        findings.append(Finding("stale", f"inputs stale: Body's alpha was {old} "
                                         f"old at {late.size} of {total} steps "
                                         f"({100 * late.size / total:.3g} %; {counts}; first at step {first})"))
    return findings, Schedule(base)
