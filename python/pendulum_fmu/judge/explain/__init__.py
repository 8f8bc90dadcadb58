"""Why a result fails: what the file's numbers are right for instead.

Each module reproduces the file by another question or another method, and is kept only when
the reproduction fits the file:

- ``alternatives``: the exact solution of a slightly different question (theta in degrees,
  another start time, a time shift, a clock that runs fast, other parameters or start values);
- ``inference``: a parameter fit, and the tolerance a rerun of the FMU's solver or CVODE meets;
- ``fixed_step``: which fixed-step method (Euler, symplectic Euler, Heun, RK4) at which step;
- ``diagnosis``: the order these are tried in when the bound fails, and the ``diagnosis``
  check that names the cause.
"""
