"""The reference masters: Jacobi and Gauss-Seidel, three ways to hand an input over, a fixed step H.

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
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.split.pair import ALPHA, OMEGA, OMEGA_EXACT, THETA, THETA_EXACT, Pair, Problem

SCHEMES: tuple[str, ...] = ("jacobi", "gauss-seidel")
COUPLINGS: tuple[str, ...] = ("zoh", "extrapolation", "interpolation")
COUPLING_WORDS = {"zoh": "zero-order hold", "extrapolation": "first-order extrapolation",
                  "interpolation": "input interpolation"}


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
        """In words, e.g. "Gauss-Seidel with zero-order hold"."""
        scheme = "Gauss-Seidel" if self.scheme == "gauss-seidel" else "Jacobi"
        return f"{scheme} with {COUPLING_WORDS[self.coupling]}"


MASTERS: tuple[Master, ...] = tuple(Master(s, c) for c in COUPLINGS for s in SCHEMES)
"""Every reference master, zero-order hold first."""


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
    """

    time: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    alpha: np.ndarray
    theta_exact: np.ndarray
    omega_exact: np.ndarray
    seconds: float

    @property
    def error(self) -> float:
        """Largest |theta - theta_exact| over the points (rad)."""
        return float(np.max(np.abs(self.theta - self.theta_exact)))


def run_master(master: Master, H: float, stop: float, problem: Problem | None = None,
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
    problem : Problem, optional
        Parameters and start values (default: ``Problem()``).
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
    with Pair(Problem() if problem is None else problem, fmi_version) as pair:
        began = time.perf_counter()
        step = _STEPPERS[master.scheme]
        for k in range(n):
            rows[k] = step(pair, master.coupling, k * H, H)
        rows[n] = _outputs(pair, _exchange_gauss_seidel(pair, master.coupling)[0])
        seconds = time.perf_counter() - began
    times = np.arange(n + 1) * H
    return Coupled(times, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4], seconds)


def _outputs(pair: Pair, alpha: float) -> tuple[float, ...]:
    body = pair.body
    return (pair.get(body, THETA), pair.get(body, OMEGA), alpha, pair.get(body, THETA_EXACT),
            pair.get(body, OMEGA_EXACT), 0.0)


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


def observed_orders(steps: list[float], errors: list[float]) -> list[float]:
    """log(e_i / e_(i+1)) / log(H_i / H_(i+1)) for consecutive macro steps."""
    return [math.log(errors[i] / errors[i + 1]) / math.log(steps[i] / steps[i + 1]) for i in range(len(steps) - 1)]
