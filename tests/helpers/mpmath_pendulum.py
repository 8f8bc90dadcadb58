"""The pendulum's true state from mpmath's Jacobi elliptic functions at 40 digits.

Written from the pendulum's closed form, not from the FMU's exact port: the independent reference
of the step certificate's tests (fmu/test_certificate_edges.py) and the study's speed and
hard-case tests (study/test_study_speed_hard_cases.py).
"""

from __future__ import annotations

import mpmath as mp

DIGITS = 40
"""mpmath's working precision for the reference."""


def true_state(theta0: float, omega0: float, g: float, length: float, elapsed: mp.mpf) -> tuple[mp.mpf, mp.mpf]:
    """theta and omega of theta'' = -(g/L) sin theta at ``elapsed`` after (theta0, omega0).

    With w0 = sqrt(g/L), s = sin(theta0/2), q = omega0 / (2 w0) and m = s^2 + q^2 (energy):
    in libration (m < 1, k = sqrt m) theta = c + 2 asin(k sn(u, m)), omega = 2 k w0 cn(u, m),
    u = w0 t + u0, sn(u0) = sin((theta0 - c)/2) / k, cn(u0) = q / k, c the multiple of 2 pi
    the swing is centred on; in rotation (m > 1) theta = 2 am(v, 1/m), omega = 2 sigma sqrt(m)
    w0 dn(v, 1/m), v = v0 + sigma sqrt(m) w0 t, am(v0) = theta0/2, sigma the sign of omega0.
    The inputs are the doubles as given, the arithmetic at ``DIGITS`` digits.

    Parameters
    ----------
    theta0, omega0 : float
        Start values (rad, rad/s).
    g, length : float
        Gravity (m/s^2) and length (m).
    elapsed : mpmath.mpf
        Time since the start (s), exact.

    Returns
    -------
    tuple of mpmath.mpf
        (theta, omega) at that time.
    """
    with mp.workdps(DIGITS):
        w0 = mp.sqrt(mp.mpf(g) / mp.mpf(length))
        q = mp.mpf(omega0) / (2 * w0)
        centre = 2 * mp.pi * mp.nint(mp.mpf(theta0) / (2 * mp.pi))
        half = (mp.mpf(theta0) - centre) / 2
        m = mp.sin(half) ** 2 + q ** 2
        if m < 1:
            k = mp.sqrt(m)
            if k == 0:
                return centre, mp.mpf(0)
            u = mp.ellipf(mp.atan2(mp.sin(half), q), m) + w0 * elapsed
            sn, cn = mp.ellipfun("sn", u, m=m), mp.ellipfun("cn", u, m=m)
            return centre + 2 * mp.asin(k * sn), 2 * k * w0 * cn
        sigma = 1 if omega0 > 0 else -1
        r = 1 / m
        v = mp.ellipf(mp.mpf(theta0) / 2, r) + sigma * mp.sqrt(m) * w0 * elapsed
        quarter = mp.ellipk(r)
        turns = mp.floor((v + quarter) / (2 * quarter))
        rest = v - 2 * quarter * turns   # in [-K, K): cn >= 0 there, am = atan2(sn, cn)
        amplitude = turns * mp.pi + mp.atan2(mp.ellipfun("sn", rest, m=r), mp.ellipfun("cn", rest, m=r))
        return 2 * amplitude, 2 * sigma * mp.sqrt(m) * w0 * mp.ellipfun("dn", v, m=r)
