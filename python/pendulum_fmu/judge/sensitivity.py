"""The Model Exchange allowance: an importer's local errors, propagated by the pendulum's
linearised flow and accumulated to every output time.

The pendulum x = (theta, omega), x' = f(x) = (omega, -c sin theta), c = g / L, keeps its
energy E = omega^2 / 2 - c cos theta; n = grad E = (c sin theta, omega) is normal to f
(n.f = 0) and |n| = |f|. Let Phi(t, s) be the state transition matrix of the linearisation
along the exact orbit and q(t) = Phi(t, 0) n(0) / |n(0)|^2 (the response to a start change
that adds 1 to E). Then X = [f, q] solves the variational equation, det X = n.q = 1, and after
one period T (or one revolution, for a rotation) q(t) = p(t) + kappa t f(t) with p
T-periodic and kappa = -T'(E) / T(E). Writing a local error delta made at time s as
delta = a(s) f(s) + e(s) p(s) gives the exact linearised propagation

    Phi(t, s) delta = a(s) f(t) + e(s) p(t) + kappa (t - s) e(s) f(t),

e(s) = n(s).delta (the energy error), a(s) = delta_theta p_omega(s) - delta_omega p_theta(s).
Local errors within eps_theta(s), eps_omega(s) per unit time therefore accumulate to at most

    |f_i(t)| int_0^t |a| ds + |p_i(t)| int_0^t |e| ds + |kappa| |f_i(t)| int_0^t (t - s) |e| ds

in component i, with |a| <= |p_omega| eps_theta + |p_theta| eps_omega and
|e| <= |n_theta| eps_theta + |n_omega| eps_omega. The integrands are T-periodic (for a
rotation, periodic plus 2 pi j times a periodic one in revolution j, from the angle's scale), so
each integral is a closed sum over whole periods plus a cumulative integral over one period,
tabulated once on :data:`GRID` points: O(rows) for any file.

The a and kappa terms shift the state along the orbit by a time within Delta(t) =
int_0^t |a| + |kappa| int_0^t (t - s) |e|; their effect on component i is bounded by Delta times
the largest |f_i| within Delta of t (mean value theorem), which also holds where f_i(t) = 0,
and |p_i| likewise by its largest value there.

The local error per unit time is eps = factor tol scale w0 / (2 pi) with the scales
max(1, |theta|) and max(w0, |omega|): ``factor`` tol per natural period 2 pi / w0. One more
factor tol scale at the output time itself covers the solver's interpolation there. Once the
allowed energy error reaches :data:`LINEAR_LIMIT` of the distance to the separatrix the run
may be on its other side, and nothing is refused from then on.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.special import ellipe, ellipkm1

from pendulum_fmu.judge.verdict import Experiment
from pendulum_fmu.spec import InitialValueProblem

GRID = 8192
"""Points over one period for p and the cumulative integrals (linear interpolation between)."""
SEPARATRIX_GAP = 1e-16
"""|cos^2(theta0 / 2) - (omega0 / (2 w0))^2| below this: on the separatrix as doubles resolve it
(T infinite; a finite difference along n cannot stay on one side)."""
HARMONIC_GAP = 1e-10
"""m = sin^2(theta0 / 2) + (omega0 / (2 w0))^2 below this: the harmonic oscillator's flow,
an isometry in (theta, omega / w0), bounds the propagation."""
LINEAR_LIMIT = 0.5
"""The linearisation is trusted while the allowed energy error stays below this fraction of the
start's energy distance to the separatrix; beyond, the run may be on the separatrix's other
side and no value is refused."""
SERIES_BELOW = 1e-6
"""K'(m) / K(m) from its series 1/4 + 7 m / 32 below this m (the closed form cancels there)."""

CAUSES = {
    "local": "the solver's local error at the output time",
    "along": "errors along the orbit (a shift in time)",
    "energy": "the energy error's change of the orbit",
    "phase": "the period's sensitivity to the energy (phase drift)",
    "separatrix": "the separatrix (T infinite): no linearised bound",
    "harmonic": "the harmonic flow at the bottom (errors add up)",
}
"""What the largest term of the allowance is, in words."""


@dataclass(frozen=True)
class Allowance:
    """The allowed |error| of theta and omega at each of the file's times, and its figures.

    Attributes
    ----------
    theta, omega : numpy.ndarray
        Allowed |theta - theta_exact| (rad) and |omega - omega_exact| (rad/s) per row
        (inf where no linearised bound holds).
    growth : numpy.ndarray
        Per row, the larger of theta / (factor tol max(1, |theta|)) and
        omega / (factor tol max(w0, |omega|)): how many local allowances the row gets.
    regime : str
        "libration", "rotation", "separatrix" or "harmonic".
    period : float
        T, s (the time of one revolution for a rotation; inf on the separatrix).
    kappa : float
        -T'(E) / T(E), s^2 / rad^2 per unit of E (0 for the harmonic flow, inf on the separatrix).
    largest_growth, at_time : float
        The largest finite growth and its time from the start (s).
    cause : str
        Key of :data:`CAUSES`: the largest term where the growth is largest.
    linear_until : float
        From this time (from the start) on, no value is refused (inf: never).
    """

    theta: np.ndarray
    omega: np.ndarray
    growth: np.ndarray
    regime: str
    period: float
    kappa: float
    largest_growth: float
    at_time: float
    cause: str
    linear_until: float

    def describe(self, start_time: float = 0.0) -> str:
        """"growth 3.1e+04 at t = 40 s, from the period's sensitivity to the energy ...", at
        absolute times (``start_time`` added to the times from the start)."""
        text = f"growth {self.largest_growth:.2g} at t = {start_time + self.at_time:.6g} s, from {CAUSES[self.cause]}"
        if self.regime in ("libration", "rotation"):
            text += f"; {self.regime}, T = {self.period:.6g} s, kappa = {self.kappa:.3g}"
        if math.isfinite(self.linear_until):
            text += (f"; from t = {start_time + self.linear_until:.6g} s the allowed energy error reaches "
                     "the separatrix: "
                     "no value refused")
        return text

    def numbers(self) -> dict[str, float | str]:
        """The scalar figures, JSON-ready."""
        return {"regime": self.regime, "period": self.period, "kappa": self.kappa, "growth": self.largest_growth,
                "growth_time": self.at_time, "cause": self.cause, "linear_until": self.linear_until}


def energy_gaps(theta0: float, omega0: float, w0: float) -> tuple[float, float]:
    """(d, m): d = cos^2(theta0 / 2) - (omega0 / (2 w0))^2 = (c - E) / (2 c), > 0 libration,
    < 0 rotation; m = sin^2(theta0 / 2) + (omega0 / (2 w0))^2 = (E + c) / (2 c)."""
    half_cos = abs(math.cos(theta0 / 2.0))
    speed = abs(omega0) / (2.0 * w0)
    return (half_cos - speed) * (half_cos + speed), math.sin(theta0 / 2.0) ** 2 + speed * speed


def _log_slope(parameter: float, complement: float) -> float:
    """K'(m) / K(m) for m = ``parameter``, 1 - m = ``complement``; K'(m) = (E(m) - (1 - m) K(m)) / (2 m (1 - m))."""
    if parameter < SERIES_BELOW:
        return 0.25 + 7.0 * parameter / 32.0
    k = float(ellipkm1(complement))
    return (float(ellipe(parameter)) - complement * k) / (2.0 * parameter * complement * k)


def period_and_kappa(d: float, m: float, w0: float) -> tuple[float, float]:
    """The period T (revolution time for a rotation) and kappa = -T'(E) / T(E).

    Libration: T = 4 K(m) / w0, m = (E + c) / (2 c). Rotation: T = 2 K(1/m) / (w0 sqrt(m)).
    With dm/dE = 1 / (2 c), c = w0^2.
    """
    c = w0 * w0
    if d > 0:
        return 4.0 * float(ellipkm1(d)) / w0, -_log_slope(m, d) / (2.0 * c)
    mu = 1.0 / m
    mu_complement = -d / m
    period = 2.0 * float(ellipkm1(mu_complement)) / (w0 * math.sqrt(m))
    return period, (_log_slope(mu, mu_complement) * mu * mu + 0.5 * mu) / (2.0 * c)


def flow_and_normal(theta: np.ndarray, omega: np.ndarray, c: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(f_theta, f_omega, n_theta) of the flow f = (omega, -c sin theta) and the energy gradient
    n = (c sin theta, omega); n_omega = f_theta."""
    c_sin = c * np.sin(theta)
    return omega, -c_sin, c_sin


def periodic_part(problem: InitialValueProblem, period: float, kappa: float, d: float, m: float,
                  tau: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """theta, omega and p = q - kappa tau f at ``tau`` within [0, T].

    q by a central difference along n(0) / |n(0)|^2 of step h in energy, h a small fraction of
    the energy's distance to the separatrix (and, for a libration, to the bottom) and small
    enough that the perturbed orbit's phase moves by at most 1e-2 rad in one period.
    """
    from pendulum_fmu.fmu.library import exact

    e = problem
    c = e.g / e.L
    w0 = math.sqrt(c)
    gap = abs(d) if d < 0 else min(d, m)
    h = min(1e-3, 1e-2 / (w0 * period)) * 2.0 * c * gap
    n_theta, n_omega = c * math.sin(e.theta0), e.omega0
    norm2 = n_theta * n_theta + n_omega * n_omega
    dt, dw = h * n_theta / norm2, h * n_omega / norm2
    theta, omega = exact(e.theta0, e.omega0, e.L, e.g, tau)
    up_theta, up_omega = exact(e.theta0 + dt, e.omega0 + dw, e.L, e.g, tau)
    down_theta, down_omega = exact(e.theta0 - dt, e.omega0 - dw, e.L, e.g, tau)
    f_theta, f_omega, _ = flow_and_normal(theta, omega, c)
    p_theta = (up_theta - down_theta) / (2.0 * h) - kappa * tau * f_theta
    p_omega = (up_omega - down_omega) / (2.0 * h) - kappa * tau * f_omega
    return theta, omega, p_theta, p_omega


class WindowMax:
    """max over [tau - half, tau + half] of T-periodic functions tabulated on ``grid``, for
    the same windows: a sparse table of maxima over 2^k cells of three periods side by side,
    O(1) a query (two table entries whose spans cover the window)."""

    def __init__(self, grid: np.ndarray, period: float, tau: np.ndarray, half: np.ndarray) -> None:
        n = self.cells = grid.size - 1
        step = period / n
        self.levels = int(math.log2(3 * n)) + 1
        centre = n + tau / step
        reach = np.minimum(half / step, n)  # a window of a whole period or more holds the maximum
        low = np.clip(np.floor(centre - reach).astype(np.int64) - 1, 0, 3 * n - 1)
        high = np.clip(np.ceil(centre + reach).astype(np.int64) + 1, 0, 3 * n - 1)
        level = np.floor(np.log2(high - low + 1)).astype(np.int64)
        self.first = level * (3 * n) + low
        self.second = level * (3 * n) + high - (1 << level) + 1

    def __call__(self, values: np.ndarray) -> np.ndarray:
        """The windows' maxima of ``values`` (on ``grid``, the last point equal to the first)."""
        n = self.cells
        table = np.full((self.levels, 3 * n), -np.inf)
        table[0] = np.tile(values[:-1], 3)
        for k in range(1, self.levels):
            width = 1 << (k - 1)
            table[k, : 3 * n - width] = np.maximum(table[k - 1, : 3 * n - width], table[k - 1, width:])
        flat = table.ravel()
        return np.maximum(flat[self.first], flat[self.second])


def _cumulative(tau: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Trapezoidal int_0^tau values, starting at 0."""
    return np.concatenate(([0.0], np.cumsum(0.5 * (values[1:] + values[:-1]) * np.diff(tau))))


def accumulate(grid: np.ndarray, base: np.ndarray, per_turn: np.ndarray | None, period: float,
               turns: np.ndarray, tau: np.ndarray, moment: bool = False) -> tuple[np.ndarray, np.ndarray | None]:
    """int_0^t h(s) ds and (with ``moment``) int_0^t s h(s) ds for h(s) = base(sigma) +
    j per_turn(sigma) (per_turn None: 0), s = j T + sigma (j whole periods), at t = turns T + tau.

    Over whole periods: sum_j (S0 + j S1) and sum_j (j T S0 + j^2 T S1 + R0 + j R1), S the
    period's integrals of base and per_turn, R those of sigma times them; the last part period
    from the cumulative integrals on ``grid``, linearly interpolated at ``tau``.
    """
    j = turns
    sum_j = j * (j - 1) / 2.0
    p0 = _cumulative(grid, base)
    part0 = np.interp(tau, grid, p0)
    first = j * p0[-1] + part0
    second = None
    if moment:
        q0 = _cumulative(grid, grid * base)
        second = period * p0[-1] * sum_j + j * q0[-1] + j * period * part0 + np.interp(tau, grid, q0)
    if per_turn is None:
        return first, second
    p1 = _cumulative(grid, per_turn)
    part1 = np.interp(tau, grid, p1)
    first += sum_j * p1[-1] + j * part1
    if second is not None:
        q1 = _cumulative(grid, grid * per_turn)
        sum_j2 = (j - 1) * j * (2 * j - 1) / 6.0
        second += (period * p1[-1] * sum_j2 + sum_j * q1[-1] + j * j * period * part1
                   + j * np.interp(tau, grid, q1))
    return first, second


def allowance(t: np.ndarray, theta: np.ndarray, omega: np.ndarray, experiment: Experiment,
              factor: float) -> Allowance:
    """The Model Exchange allowance at the times ``t`` (from the start) on the exact orbit.

    Parameters
    ----------
    t : numpy.ndarray
        Times from the experiment's start time, s (rows before the start get the local term).
    theta, omega : numpy.ndarray
        The exact solution at ``t``.
    experiment : Experiment
        The problem and the tolerance.
    factor : float
        The local error allowed per natural period 2 pi / w0, in units of tol times the scale.

    Returns
    -------
    Allowance
    """
    e = experiment.problem
    c = e.g / e.L
    w0 = math.sqrt(c)
    unit = factor * experiment.tolerance
    rate = unit * w0 / (2.0 * math.pi)
    scale_theta = np.maximum(1.0, np.abs(theta))
    scale_omega = np.maximum(w0, np.abs(omega))
    local_theta, local_omega = unit * scale_theta, unit * scale_omega
    elapsed = np.maximum(t, 0.0)
    d, m = energy_gaps(e.theta0, e.omega0, w0)

    def made(theta_bound: np.ndarray, omega_bound: np.ndarray, regime: str, period: float, kappa: float,
             cause: str, linear_until: float) -> Allowance:
        growth = np.maximum(theta_bound / local_theta, omega_bound / local_omega)
        finite = np.where(np.isfinite(growth), growth, -1.0)
        k = int(np.argmax(finite))
        return Allowance(theta_bound, omega_bound, growth, regime, period, kappa, float(max(finite[k], 1.0)),
                         float(t[k]), cause, linear_until)

    if abs(d) < SEPARATRIX_GAP:
        endless = np.where(elapsed > 0, np.inf, 1.0)
        return made(local_theta * endless, local_omega * endless, "separatrix", math.inf, math.inf, "separatrix", 0.0)
    if m < HARMONIC_GAP:
        # Phi(t, s) is a rotation of (theta, omega / w0): each error keeps its size; 2 = 1 + w0 / w0.
        added = 2.0 * rate * elapsed
        return made(local_theta + added, local_omega + w0 * added, "harmonic", 2 * math.pi / w0, 0.0,
                    "harmonic" if np.any(added > unit) else "local", math.inf)

    period, kappa = period_and_kappa(d, m, w0)
    grid = np.linspace(0.0, period, GRID + 1)
    g_theta, g_omega, p_theta, p_omega = periodic_part(e, period, kappa, d, m, grid)
    _, _, n_theta = flow_and_normal(g_theta, g_omega, c)
    rotation = d < 0
    # eps_theta <= rate (max(1, |theta(sigma)|) + 2 pi j) in revolution j; eps_omega = rate max(w0, |omega|)
    ms, mw = np.maximum(1.0, np.abs(g_theta)), np.maximum(w0, np.abs(g_omega))
    a_base = np.abs(p_omega) * ms + np.abs(p_theta) * mw
    e_base = np.abs(n_theta) * ms + np.abs(g_omega) * mw
    a_turn = 2.0 * math.pi * np.abs(p_omega) if rotation else None
    e_turn = 2.0 * math.pi * np.abs(n_theta) if rotation else None

    turns = np.floor(elapsed / period)
    tau = np.clip(elapsed - turns * period, 0.0, period)
    along, _ = accumulate(grid, a_base, a_turn, period, turns, tau)
    energy, energy_moment = accumulate(grid, e_base, e_turn, period, turns, tau, moment=True)
    assert energy_moment is not None
    drift = np.maximum(elapsed * energy - energy_moment, 0.0)
    shift = rate * (along + abs(kappa) * drift)
    # The a and kappa terms move the state along the orbit by a time within `shift`: by the mean
    # value theorem |x_i(t + u) - x_i(t)| <= shift max |f_i| over |u| <= shift, which holds where
    # f_i(t) = 0 too; p likewise over the same window (the orbit the energy error moves to).
    window = WindowMax(grid, period, tau, shift)
    f_grid = np.abs(g_omega), np.abs(c * np.sin(g_theta))
    p_grid = np.abs(p_theta), np.abs(p_omega)
    terms = {name: (local, shift * window(f_grid[i]), rate * energy * window(p_grid[i]))
             for i, (name, local) in enumerate((("theta", local_theta), ("omega", local_omega)))}
    # beyond LINEAR_LIMIT of the energy gap 2 c |d| the run may have crossed the separatrix
    crossed = rate * energy >= LINEAR_LIMIT * 2.0 * c * abs(d)
    linear_until = float(t[np.argmax(crossed)]) if np.any(crossed) else math.inf
    bounds = {name: np.where(crossed, np.inf, sum(parts)) for name, parts in terms.items()}
    result = made(bounds["theta"], bounds["omega"], regime="rotation" if rotation else "libration", period=period,
                  kappa=kappa, cause="local", linear_until=linear_until)
    k = int(np.argmax(np.where(np.isfinite(result.growth), result.growth, -1.0)))
    name = "theta" if result.growth[k] == bounds["theta"][k] / local_theta[k] else "omega"
    local, moved, orbit = (float(part[k]) for part in terms[name])
    phase = rate * abs(kappa) * float(drift[k]) / max(float(shift[k]), 1e-300) * moved
    cause = max((local, "local"), (moved - phase, "along"), (orbit, "energy"), (phase, "phase"))[1]
    return Allowance(result.theta, result.omega, result.growth, result.regime, period, kappa, result.largest_growth,
                     result.at_time, cause, linear_until)
