"""Which reference master a coupled result reproduces: every master of the registry rerun at the
file's own communication points.

Each master of :func:`pendulum_fmu.split.masters.masters_for` (FMI 2.0: all of them, a master
added there included) runs through the FMUs at the file's exact macro step H and is compared
with the file at the file's rows. A master reproduces the file when the two differ by at most
the round-off of two runs of the same scheme (measured below 5e-14 rad over 1,000 steps between
the FMUs and a closed form in numpy; allowed: 2e-13 max(1, |theta|) sqrt(n)) plus twice the
print's resolution of theta. A file that holds every m-th communication point only is tried at
H / m for m in :data:`DECIMATIONS` when no master reproduces it at H (over the first
:data:`DECIMATION_STEPS` macro steps; or at ``step``, given).
Long files are rerun over their first :data:`RERUN_BUDGET` / (number of masters) macro steps
(the identification and the rank then say so).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from pendulum_fmu.spec import InitialValueProblem

RERUN_BUDGET = 60_000
"""Most macro steps of all reference masters together (10,000 each for six, H = 1e-3 over 10 s: a judge call on 1e5 rows
stays under 5 s, ``pendulum-fmu bench masters --judge-rows 100000``)."""
DECIMATIONS: tuple[int, ...] = (2, 4, 5, 10)
"""Every m-th point written, tried when no master reproduces the file at its own H."""
DECIMATION_STEPS = 1_000
"""Most macro steps each master is rerun over when a decimation is tried."""
ROUNDOFF = 2e-13
"""Round-off allowed between two runs of one scheme: this times max(1, |theta|) sqrt(n) (rad)."""


@dataclass(frozen=True)
class Identification:
    """Which reference master the file reproduces.

    Attributes
    ----------
    master : str or None
        :attr:`Master.name` of the master reproduced, None: a master of its own.
    text : str
        In words: "Gauss-Seidel with zero-order hold" or "a master of its own (...)".
    H : float or None
        The macro step the masters were rerun at (None: not rerun).
    every : int
        The file holds every ``every``-th communication point.
    span : float
        The reruns' end time (s); the file's rows up to it were compared.
    truncated : bool
        The reruns stopped before the file's end (:func:`rerun_steps`).
    differences : dict of str to float
        Largest |theta_file - theta_master| per master over the compared rows.
    reference_errors : dict of str to float
        Each master's largest |theta - theta_exact| over the compared rows.
    rows : int
        The number of rows compared.
    """

    master: str | None
    text: str
    H: float | None = None
    every: int = 1
    span: float = math.nan
    truncated: bool = False
    differences: dict[str, float] = field(default_factory=dict)
    reference_errors: dict[str, float] = field(default_factory=dict)
    rows: int = 0


def rerun_steps() -> int:
    """Most macro steps each reference master is rerun over: :data:`RERUN_BUDGET` shared."""
    from pendulum_fmu.split.masters import masters_for

    return RERUN_BUDGET // max(1, len(masters_for(2)))


def _rerun(H: float, index: np.ndarray, theta: np.ndarray, problem: InitialValueProblem,
           allowed: np.ndarray, limit: int) -> tuple[dict[str, float], dict[str, float], float, int, str | None]:
    """Every master at H over the rows with index <= limit: differences, errors, end, rows, match."""
    from pendulum_fmu.split.masters import masters_for, run_master

    within = index <= limit
    rows = int(np.count_nonzero(within))
    last = int(index[within][-1])
    differences: dict[str, float] = {}
    errors: dict[str, float] = {}
    fits: list[str] = []
    for master in masters_for(2):
        try:
            run = run_master(master, H, last * H, problem)
        except Exception:  # noqa: BLE001 (a master that cannot run at this H names no file)
            continue
        if run.theta.size <= last:
            continue
        picked = run.theta[index[within]]
        apart = np.abs(theta[within] - picked)
        differences[master.name] = float(np.max(apart))
        if np.all(apart <= allowed[within]):  # each row within its own print
            fits.append(master.name)
        errors[master.name] = float(np.max(np.abs(picked - run.theta_exact[index[within]])))
    match = min(fits, key=lambda name: differences[name]) if fits else None
    return differences, errors, last * H, rows, match


def identify(index: np.ndarray | None, H: float | None, theta: np.ndarray,
             resolution: np.ndarray, problem: InitialValueProblem, step: float | None = None,
             own: str = "", decimated: bool = True) -> Identification:
    """The reference master the file reproduces (see the module's docstring).

    Parameters
    ----------
    index : numpy.ndarray or None
        Each row's communication point number k (t = t_0 + k H, relabelled), None on a variable grid.
    H : float or None
        The file's exact macro step.
    theta : numpy.ndarray
        Body's theta per row.
    resolution : numpy.ndarray
        Half a unit in theta's last printed digit, per row.
    problem : InitialValueProblem
        Parameters and start values of the reruns.
    step : float, optional
        The macro step the caller states (the file holds every m-th point when it is H / m).
    own : str
        What the file shows of its own master, said when no reference master reproduces it.
    decimated : bool
        Whether the rows may hold every m-th point only (False: :data:`DECIMATIONS` not tried).
    """
    from pendulum_fmu.split.masters import master_named

    if index is None or H is None or index[0] < 0:
        return Identification(None, f"a master of its own ({own or 'variable macro step'})")
    allowed = ROUNDOFF * max(1.0, float(np.max(np.abs(theta)))) * math.sqrt(max(1, int(index[-1]))) + 2 * resolution
    ratios = [round(H / step)] if step and abs(H / step - round(H / step)) < 1e-6 and round(H / step) >= 1 else [1]
    tried: Identification | None = None
    for every in ratios + (list(DECIMATIONS) if step is None and decimated else []):
        macro = H / every
        limit = rerun_steps() if every == ratios[0] else DECIMATION_STEPS
        if index[0] * every > limit:
            break
        differences, errors, span, rows, match = _rerun(macro, index * every, theta, problem, allowed, limit)
        result = Identification(match, master_named(match).describe() if match else "", macro, every, span,
                                int(index[-1]) * every > limit, differences, errors, rows)
        if tried is None:
            tried = result
        if match is not None:
            return result
    assert tried is not None
    nearest = min(tried.differences, key=lambda n: tried.differences[n]) if tried.differences else None
    text = "a master of its own" + (f" ({own})" if own else "")
    if nearest:
        text += f"; nearest {master_named(nearest).describe()}, {tried.differences[nearest]:.3g} rad apart"
    return Identification(None, text, tried.H, 1, tried.span, tried.truncated, tried.differences,
                          tried.reference_errors, tried.rows)
