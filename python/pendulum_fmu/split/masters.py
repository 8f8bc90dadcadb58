"""The reference masters: Jacobi and Gauss-Seidel, three ways to hand an input over, a fixed step H,
and strong coupling, each macro step iterated to convergence with rollback.

The yardstick the judge measures a master by (docs/masters.md). At each communication point
t_k = k H the master exchanges Body.theta -> Gravity.theta and Gravity.alpha -> Body.alpha,
then steps both FMUs from t_k to t_k + H.

Scheme (whose outputs feed the inputs at t_k):

- ``gauss-seidel``: Gravity's input is set to Body's theta at t_k first, then Gravity's output
  alpha(t_k) = -(g/L) sin(theta_k) is read and set into Body (Gravity is evaluated after Body
  has reached t_k);
- ``jacobi``: every output is read at t_k before any input is set, so Body gets the alpha
  that Gravity computed in its own last step, from the theta it was given at t_(k-1).

Coupling (how Body's input alpha is held over the step; Gravity gets theta likewise):

- ``zoh``: zero-order hold, the value at t_k;
- ``extrapolation``: first-order extrapolation from output derivatives, y + y' s, set as the
  held value its mean over the step, y + y' H / 2 (needs output derivatives, not
  ``canInterpolateInputs``);
- ``interpolation``: the FMU interpolates its input itself along y + y' s + y'' s^2 / 2, the
  output derivatives of orders 1 and 2 set with ``fmi2SetRealInputDerivatives``
  (``canInterpolateInputs``).

Gravity's output derivatives need theta's derivatives, so both derivative couplings pass
Body's output derivatives of theta (omega and alpha) on to Gravity as its input derivatives.
The FMI 3.0 FMUs have no input derivatives and Gravity no output derivatives: for them only
``zoh`` exists.

``iterated`` (strong coupling, with ``interpolation``): the exchange at t_k is Gauss-Seidel's
(alpha_k and alpha'_k from Gravity), then the macro step is iterated on the coupling signal's
value at its end, alpha_(k+1): Body interpolates the quadratic through alpha_k, alpha'_k and the
guess b of alpha_(k+1),

    u(s) = alpha_k + alpha'_k s + c s^2 / 2,   c = 2 (b - alpha_k - alpha'_k H) / H^2,

both FMUs step, Gravity's alpha at Body's new theta is the next guess, and both FMUs go back
to their states at t_k (``SetFMUstate``) for the next pass. The first guess is alpha_k +
alpha'_k H. A guess moves theta_(k+1) by H^2 / 12 of its change, so each pass shrinks the
change by (g/L) |cos theta| H^2 / 12 (8e-5 at H = 0.01): the iteration stops when the change is
below :data:`ROUND_OFF` times (g/L)(2 + |theta_(k+1)|), what rounding alone moves alpha by, or
after :data:`ITERATION_CAP` passes. The converged step is the implicit scheme of that
quadratic input, order 3 like Gauss-Seidel's interpolation, with a third of its error.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.pair import ALPHA, DEFAULT_PROBLEM, OMEGA, OMEGA_EXACT, THETA, THETA_EXACT, Pair

SCHEMES: tuple[str, ...] = ("jacobi", "gauss-seidel", "iterated")
COUPLINGS: tuple[str, ...] = ("zoh", "extrapolation", "interpolation")
SCHEME_WORDS = {"jacobi": "Jacobi", "gauss-seidel": "Gauss-Seidel", "iterated": "strong coupling"}
COUPLING_WORDS = {"zoh": "zero-order hold", "extrapolation": "first-order extrapolation",
                  "interpolation": "input interpolation"}
ITERATION_CAP = 50
"""The most passes of one macro step of the iterated master."""
ROUND_OFF = 8 * 2.0 ** -52
"""The iterated master's tolerance, in units of (g/L)(2 + |theta|): a few roundings of alpha."""


@dataclass(frozen=True)
class Master:
    """A reference master: a scheme of :data:`SCHEMES` and a coupling of :data:`COUPLINGS`."""

    scheme: str
    coupling: str

    @property
    def name(self) -> str:
        """``scheme-coupling``, e.g. ``gauss-seidel-zoh``: what ``--master`` takes."""
        return f"{self.scheme}-{self.coupling}"

    def describe(self) -> str:
        """In words, e.g. "Gauss-Seidel with zero-order hold", "strong coupling with input interpolation"."""
        return f"{SCHEME_WORDS[self.scheme]} with {COUPLING_WORDS[self.coupling]}"


MASTERS: tuple[Master, ...] = (*(Master(s, c) for c in COUPLINGS for s in SCHEMES[:2]),
                               Master("iterated", "interpolation"))
"""Every reference master: Jacobi and Gauss-Seidel, zero-order hold first, then strong coupling."""


def masters_for(fmi_version: int) -> tuple[Master, ...]:
    """The masters the FMUs of ``fmi_version`` allow (FMI 3.0: zero-order hold only)."""
    return MASTERS if fmi_version == 2 else tuple(m for m in MASTERS if m.coupling == "zoh")


def master_named(name: str) -> Master:
    """The master called ``name`` (:attr:`Master.name`); ValueError listing the names otherwise."""
    for master in MASTERS:
        if master.name == name:
            return master
    raise ValueError(f"no reference master {name!r}; one of {', '.join(m.name for m in MASTERS)}")


@dataclass(frozen=True)
class Coupled:
    """A coupled run at the communication points t_k = k H, k = 0..n.

    Attributes
    ----------
    time, theta, omega : numpy.ndarray
        Body's outputs.
    alpha : numpy.ndarray
        Gravity's output alpha as the master read it at each point.
    theta_exact, omega_exact : numpy.ndarray
        Body's exact pendulum at the same points.
    seconds : float
        Wall time of the stepping loop.
    iterations : numpy.ndarray or None
        The passes each macro step took (1 for a master that does not iterate; None where
        not recorded: one each); a step that reached :data:`ITERATION_CAP` did not converge.
    """

    time: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray
    theta_exact: np.ndarray
    omega_exact: np.ndarray
    seconds: float
    iterations: np.ndarray | None = None

    @property
    def converged(self) -> bool:
        """Whether every macro step converged before :data:`ITERATION_CAP` passes."""
        return self.iterations is None or bool(np.all(self.iterations < ITERATION_CAP))

    @property
    def error(self) -> float:
        """Largest |theta - theta_exact| over the points (rad)."""
        return float(np.max(np.abs(self.theta - self.theta_exact)))


def run_master(master: Master, H: float, stop: float, problem: InitialValueProblem = DEFAULT_PROBLEM,
               fmi_version: int = 2) -> Coupled:
    """Run ``master`` with macro step ``H`` from 0 to ``stop`` (n = round(stop / H) steps).

    Parameters
    ----------
    master : Master
        The scheme and coupling.
    H : float
        The macro step (s).
    stop : float
        The end time (s).
    problem : InitialValueProblem, optional
        Parameters and start values (default :data:`~pendulum_fmu.split.pair.DEFAULT_PROBLEM`, the SSP's).
    fmi_version : {2, 3}
        The FMUs' version (FMI 3.0: zero-order hold only).

    Returns
    -------
    Coupled
        The outputs at every communication point.
    """
    if master not in masters_for(fmi_version):
        raise ValueError(f"{master.describe()} needs input and output derivatives, which FMI {fmi_version}.0 "
                         "Co-Simulation FMUs do not have")
    n = round(stop / H)
    rows = np.empty((n + 1, 6))
    iterations = np.ones(n, dtype=int)
    with Pair(problem, fmi_version) as pair:
        began = time.perf_counter()
        if master.scheme == "iterated":
            tolerance = ROUND_OFF * problem.g / problem.L
            for k in range(n):
                rows[k], iterations[k] = _step_iterated(pair, k * H, H, tolerance)
        else:
            step = _STEPPERS[master.scheme]
            for k in range(n):
                rows[k] = step(pair, master.coupling, k * H, H)
        rows[n] = _outputs(pair, _exchange_gauss_seidel(pair, master.coupling)[0])
        seconds = time.perf_counter() - began
    times = np.arange(n + 1) * H
    return Coupled(times, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4], seconds, iterations)


ROW_REFERENCES = [THETA, OMEGA, THETA_EXACT, OMEGA_EXACT]
"""Body's outputs of a row, read in one call."""


def _outputs(pair: Pair, alpha: float) -> tuple[float, ...]:
    theta, omega, theta_exact, omega_exact = pair.get_all(pair.body, ROW_REFERENCES)
    return theta, omega, alpha, theta_exact, omega_exact, 0.0


def _feed_gravity(pair: Pair, coupling: str) -> None:
    """Body's theta (and its derivatives omega, alpha) into Gravity's input."""
    pair.set(pair.gravity, THETA, pair.get(pair.body, THETA))
    if coupling != "zoh":
        first, second = pair.derivatives(pair.body, THETA)
        pair.set_derivatives(pair.gravity, THETA, first, second)


def _feed_body(pair: Pair, coupling: str, alpha: float, first: float, second: float, H: float) -> None:
    """Gravity's alpha (value and derivatives read before) into Body's input."""
    if coupling == "extrapolation":
        pair.set(pair.body, ALPHA, alpha + first * H / 2)
        return
    pair.set(pair.body, ALPHA, alpha)
    if coupling == "interpolation":
        pair.set_derivatives(pair.body, ALPHA, first, second)


def _gravity_output(pair: Pair, coupling: str) -> tuple[float, float, float]:
    alpha = pair.get(pair.gravity, ALPHA)
    if coupling == "zoh":
        return alpha, 0.0, 0.0
    first, second = pair.derivatives(pair.gravity, ALPHA)
    return alpha, first, second


def _exchange_gauss_seidel(pair: Pair, coupling: str) -> tuple[float, float, float]:
    _feed_gravity(pair, coupling)
    return _gravity_output(pair, coupling)


def _step_gauss_seidel(pair: Pair, coupling: str, t: float, H: float) -> tuple[float, ...]:
    alpha, first, second = _exchange_gauss_seidel(pair, coupling)
    row = _outputs(pair, alpha)
    _feed_body(pair, coupling, alpha, first, second, H)
    pair.step(pair.body, t, H)
    pair.step(pair.gravity, t, H)
    return row


def _step_jacobi(pair: Pair, coupling: str, t: float, H: float) -> tuple[float, ...]:
    alpha, first, second = _gravity_output(pair, coupling)  # Gravity's, from its last step
    row = _outputs(pair, alpha)
    _feed_gravity(pair, coupling)
    _feed_body(pair, coupling, alpha, first, second, H)
    pair.step(pair.body, t, H)
    pair.step(pair.gravity, t, H)
    return row


_STEPPERS = {"gauss-seidel": _step_gauss_seidel, "jacobi": _step_jacobi}


def _step_iterated(pair: Pair, t: float, H: float, tolerance: float) -> tuple[tuple[float, ...], int]:
    """One macro step of strong coupling (module docstring): the row at t and the passes taken."""
    body, gravity = pair.body, pair.gravity
    alpha, first, _ = _exchange_gauss_seidel(pair, "interpolation")
    row = _outputs(pair, alpha)
    saved = pair.save()
    end = alpha + first * H  # the first guess of alpha at t + H
    passes = 0
    try:
        while passes < ITERATION_CAP:
            if passes:
                pair.restore(saved)
            passes += 1
            pair.set(body, ALPHA, alpha)
            pair.set_derivatives(body, ALPHA, first, 2 * (end - alpha - first * H) / (H * H))
            pair.step(body, t, H, rollback=True)
            pair.step(gravity, t, H, rollback=True)
            theta = pair.get(body, THETA)
            pair.set(gravity, THETA, theta)
            guess, end = end, pair.get(gravity, ALPHA)
            if abs(end - guess) <= tolerance * (2 + abs(theta)):
                break
    finally:
        pair.free(saved)
    return row, passes


def observed_orders(steps: list[float], errors: list[float]) -> list[float]:
    """log(e_i / e_(i+1)) / log(H_i / H_(i+1)) for consecutive macro steps."""
    return [math.log(errors[i] / errors[i + 1]) / math.log(steps[i] / steps[i + 1]) for i in range(len(steps) - 1)]
