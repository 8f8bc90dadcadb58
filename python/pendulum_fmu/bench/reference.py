"""Reference values of the exact solution from mpmath at 50 digits, independent of the C code.

The closed form with mpmath's own ``ellipfun``, ``ellipk`` and ``ellipf`` at the FMU's binary
inputs (theta0, omega0, t, L and g as given; w0 = sqrt(g / L) of those doubles unrounded, as
the FMU's exact port takes it), for
every regime; used by ``pendulum-fmu bench accuracy`` and by the tests.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import mpmath as mp
import numpy as np

DIGITS = 50
"""Working precision of every reference, in decimal digits."""


def frequency(length: float, gravity: float) -> float:
    """w0 = sqrt(g / L) rounded to a double (for scales and start values)."""
    return math.sqrt(gravity / length)


def exact_frequency(length: float, gravity: float) -> mp.mpf:
    """w0 = sqrt(g / L) of the two doubles at ``DIGITS`` digits: the FMU's exact port solves
    theta'' = -(g/L) sin theta for g and L as given."""
    with mp.workdps(DIGITS):
        return mp.sqrt(mp.mpf(gravity) / mp.mpf(length))


def closed_form(theta0: float, omega0: float, w0: float | mp.mpf, times: Sequence[float] | np.ndarray,
                t0: float = 0.0, digits: int = DIGITS) -> tuple[list[mp.mpf], list[mp.mpf], mp.mpf]:
    """Exact solution by mpmath's elliptic functions, at ``DIGITS`` digits.

    Parameters
    ----------
    theta0, omega0 : float
        Initial state at ``t0`` (taken exactly as binary doubles).
    w0 : float or mpmath.mpf
        sqrt(g / L) (the exact root of the doubles g / L, see :func:`exact_frequency`).
    times : sequence of float or ndarray
        Evaluation times.
    t0 : float
        Time at which the initial state is posed.
    digits : int
        Working precision in decimal digits.

    Returns
    -------
    theta, omega : list of mpmath.mpf
        The solution at ``times``.
    period : mpmath.mpf
        4 K(m) / w0 (libration), 2 K(1/m) / (sqrt(m) w0) (rotation), +inf (separatrix).

    Notes
    -----
    theta0 = 2 pi j + th, th in (-pi, pi]; s = sin(th/2), c = cos(th/2), q = omega0/(2 w0),
    m = s^2 + q^2, m1 = c^2 - q^2 (documentation/math.html). Libration: theta = 2 atan2(k sn u, dn u),
    omega = 2 k w0 cn u, u = w0 (t - t0) + F(atan2(s, q) | m). Rotation (sign d of omega0):
    theta = 2 pi j + 2 d am(v | 1/m), omega = 2 d sqrt(m) w0 dn(v | 1/m),
    v = sqrt(m) w0 (t - t0) + F(d th/2 | 1/m). Separatrix: theta = 2 pi j + 2 d atan(sinh u),
    omega = 2 d w0 sech u, u = w0 (t - t0) + asinh(d tan(th/2)). Arguments are reduced by
    the real period in mpmath before calling ellipfun.
    """
    with mp.workdps(digits):
        th0, om0, w, start = mp.mpf(theta0), mp.mpf(omega0), mp.mpf(w0), mp.mpf(t0)
        turns = mp.nint(th0 / (2 * mp.pi))
        th = th0 - 2 * mp.pi * turns
        if th > mp.pi:
            th, turns = th - 2 * mp.pi, turns + 1
        elif th <= -mp.pi:
            th, turns = th + 2 * mp.pi, turns - 1
        offset = 2 * mp.pi * turns
        s, c, q = mp.sin(th / 2), mp.cos(th / 2), om0 / (2 * w)
        m1 = (c - q) * (c + q)
        m = s * s + q * q
        thetas: list[mp.mpf] = []
        omegas: list[mp.mpf] = []
        if m1 > 0:
            k = mp.sqrt(m)
            K = mp.ellipk(m)
            phi0 = mp.atan2(s, q)
            turns_phi = mp.nint(phi0 / mp.pi)            # F(phi + n pi) = F(phi) + 2 n K
            u0 = mp.ellipf(phi0 - turns_phi * mp.pi, m) + 2 * turns_phi * K if k != 0 else mp.mpf(0)
            for t in times:
                u = w * (mp.mpf(t) - start) + u0
                u -= 4 * K * mp.floor(u / (4 * K))
                sn, cn, dn = (mp.ellipfun(kind, u, m) for kind in ("sn", "cn", "dn"))
                thetas.append(offset + 2 * mp.atan2(k * sn, dn))
                omegas.append(2 * k * w * cn)
            return thetas, omegas, 4 * K / w
        direction = 1 if om0 > 0 else -1
        if m1 < 0:
            mu = 1 / m
            K = mp.ellipk(mu)
            rate = mp.sqrt(m) * w
            v0 = mp.ellipf(direction * th / 2, mu)
            for t in times:
                v = rate * (mp.mpf(t) - start) + v0
                half_turns = mp.nint(v / (2 * K))          # am(v + 2K) = am(v) + pi
                vr = v - 2 * K * half_turns
                sn, cn, dn = (mp.ellipfun(kind, vr, mu) for kind in ("sn", "cn", "dn"))
                amplitude = half_turns * mp.pi + mp.atan2(sn, cn)
                thetas.append(offset + direction * 2 * amplitude)
                omegas.append(direction * 2 * rate * dn)
            return thetas, omegas, 2 * K / rate
        u0 = mp.asinh(direction * s / c)
        for t in times:
            u = w * (mp.mpf(t) - start) + u0
            thetas.append(offset + direction * 2 * mp.atan(mp.sinh(u)))
            omegas.append(direction * 2 * w / mp.cosh(u))
        return thetas, omegas, mp.inf


def max_abs_diff(values: np.ndarray, reference: Sequence[mp.mpf]) -> float:
    """max_i |values[i] - reference[i]| in mpmath (no rounding of the reference first)."""
    with mp.workdps(DIGITS):
        return max(float(abs(mp.mpf(float(v)) - r)) for v, r in zip(values, reference, strict=True))


def omega_scale(reference: Sequence[mp.mpf], w0: float) -> float:
    """Amplitude of omega for relative omega errors (at least 1e-300 for the rest state)."""
    return max(max(float(abs(r)) for r in reference), 1e-300 * w0)
