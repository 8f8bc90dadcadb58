"""The peers of the FMU's solvers in ``bench solvers``, by name (no imports: the command line
checks ``--peers`` and prints its help without loading a numerical package)."""

from __future__ import annotations

SOLVE_IVP_METHODS: tuple[str, ...] = ("RK45", "DOP853", "LSODA", "Radau")
"""The scipy ``solve_ivp`` peers."""

PEERS: tuple[str, ...] = (*SOLVE_IVP_METHODS, "dop853", "cvode", "euler")
"""Every peer: scipy's ``solve_ivp`` methods, scipy's ``ode`` dop853 (Hairer's code), CVODE
through fmpy on the Model Exchange interface and fmpy's fixed-step forward Euler."""
