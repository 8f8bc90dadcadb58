"""The judge's Model Exchange bound against honest integrators and a tolerance 100 times looser.

Each problem is run by fmpy's CVODE through both FMUs (Model Exchange, relative_tolerance =
tol) and by scipy's solve_ivp DOP853, LSODA, Radau and RK45 (rtol = tol, atol = tol (1, w0))
at tol = 1e-2, 1e-4, ..., 1e-12. A run is judged at its own tol (honest: the worst |error| /
bound must stay below 1) and at tol / 100 (the tolerance not passed on: must exceed 1). The
problems: libration from 10 to 179.99 deg, starts with omega0 != 0, rotations near the
separatrix in both directions, random L and g, 10 to 50 periods, fine and coarse output
intervals, one start time of 5 s. docs/importers.md quotes the table::

    .venv/bin/python tests/helpers/me_bound_table.py [--quick] 2> runs.log   (one line a run on stderr)
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import lru_cache
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from pendulum_fmu.judge import checks, sensitivity
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.reading import read_result
from pendulum_fmu.judge.sensitivity import energy_gaps, period_and_kappa

REPO = Path(__file__).resolve().parents[2]
FMUS = {"CVODE fmi2": REPO / "build/Pendulum.fmu", "CVODE fmi3": REPO / "build/fmi3/Pendulum.fmu"}
SCIPY_METHODS = ("DOP853", "LSODA", "Radau", "RK45")
TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
LOOSER = 100.0
TIGHTEST = {"Radau": 1e-8}
"""scipy's Radau (Python Newton iterations) takes 90 s for one 175 deg run at 1e-12: not below 1e-8."""
Run = dict[str, np.ndarray]


@dataclass(frozen=True)
class Problem:
    """One initial value problem and how long and how finely it is written."""

    name: str
    theta0: float
    omega0: float
    L: float
    g: float
    periods: float
    """Duration in periods of the motion (revolutions for a rotation)."""
    points: float
    """Output rows per period of the motion."""
    start_time: float = 0.0

    @property
    def w0(self) -> float:
        return math.sqrt(self.g / self.L)

    @property
    def period(self) -> float:
        d, m = energy_gaps(self.theta0, self.omega0, self.w0)
        return period_and_kappa(d, m, self.w0)[0]

    @property
    def times(self) -> np.ndarray:
        step = float(f"{self.period / self.points:.2g}")  # a step as a person writes it
        return self.start_time + np.arange(0.0, self.periods * self.period + 0.5 * step, step)

    def start(self, tolerance: float) -> dict[str, float | str]:
        return {"theta": self.theta0, "omega": self.omega0, "L": self.L, "g": self.g, "tolerance": tolerance,
                "startTime": self.start_time}


def problems(quick: bool = False) -> list[Problem]:
    """The validation problems (seeded: the same list on every run)."""
    rng = np.random.default_rng(26)
    found = []
    angles = (10, 45, 90, 135, 170, 175, 178, 179.9, 179.99)
    for k, degrees in enumerate(angles):
        L, g = (1.0, 9.81) if k % 3 == 0 else (float(rng.uniform(0.2, 5.0)), float(rng.uniform(1.0, 25.0)))
        found.append(Problem(f"{degrees} deg", math.radians(degrees), 0.0, L, g, float(rng.uniform(10, 50)),
                             200.0 if k % 2 == 0 else 2.7))
    for k, gap in enumerate((1e-2, 1e-4, 1e-6)):
        L, g = float(rng.uniform(0.2, 5.0)), float(rng.uniform(1.0, 25.0))
        sign = 1.0 if k % 2 == 0 else -1.0
        found.append(Problem(f"rotation {'+-'[k % 2]}(1+{gap:g})", 0.0, sign * 2 * math.sqrt(g / L) * (1 + gap), L, g,
                             float(rng.uniform(10, 30)), 100.0 if k % 2 else 3.3))
    found.append(Problem("2 rad, omega0 = -3", 2.0, -3.0, 1.0, 9.81, 20.0, 150.0, start_time=5.0))
    found.append(Problem("170 deg, omega0 = 1e-3", math.radians(170), 1e-3, 0.5, 1.62, 30.0, 50.0))
    if quick:
        return [p for p in found if p.name in ("175 deg", "179.9 deg", "179.99 deg", "rotation -(1+0.0001)")]
    return found


MAX_STEPS = 100_000
"""CVODE's mxstep, steps per output interval (fmpy's 500 refuse coarse intervals at tight tolerances)."""


@lru_cache(maxsize=2)
def _unzipped(fmu: Path) -> tuple[str, object]:
    from fmpy import extract, read_model_description
    from fmpy.sundials import CVodeSolver

    max_step, tolerance, _ = CVodeSolver.__init__.__defaults__
    CVodeSolver.__init__.__defaults__ = (max_step, tolerance, MAX_STEPS)
    return extract(str(fmu)), read_model_description(str(fmu))


def run_cvode(fmu: Path, problem: Problem, tolerance: float) -> Run:
    """fmpy's CVODE through ``fmu``, Model Exchange, relative_tolerance = ``tolerance``."""
    from fmpy import simulate_fmu

    folder, description = _unzipped(fmu)
    t = problem.times
    out = simulate_fmu(folder, model_description=description, fmi_type="ModelExchange", solver="CVode",
                       relative_tolerance=tolerance, start_time=float(t[0]), stop_time=float(t[-1]),
                       output_interval=float(t[1] - t[0]), output=["theta", "omega"],
                       start_values={"theta": problem.theta0, "omega": problem.omega0, "L": problem.L,
                                     "g": problem.g})
    return {"time": np.asarray(out["time"]), "theta": np.asarray(out["theta"]), "omega": np.asarray(out["omega"])}


def run_scipy(method: str, problem: Problem, tolerance: float) -> Run:
    """solve_ivp's ``method`` on theta'' = -(g/L) sin theta, rtol = tol, atol = tol (1, w0)."""
    c = problem.g / problem.L
    t = problem.times
    solution = solve_ivp(lambda _, y: [y[1], -c * math.sin(y[0])], (t[0], t[-1]), [problem.theta0, problem.omega0],
                         method=method, t_eval=t, rtol=tolerance, atol=[tolerance, tolerance * problem.w0])
    return {"time": t, "theta": solution.y[0], "omega": solution.y[1]}


def integrators() -> dict[str, Callable[[Problem, float], Run]]:
    """Each integrator by name: a function of the problem and the tolerance."""
    found: dict[str, Callable[[Problem, float], Run]] = {
        name: (lambda p, tol, f=fmu: run_cvode(f, p, tol)) for name, fmu in FMUS.items()}
    found.update({m: (lambda p, tol, m=m: run_scipy(m, p, tol)) for m in SCIPY_METHODS})
    return found


FACTORS = (30.0, 100.0, 300.0, 1000.0)
"""The summary's alternatives to checks.ME_FACTOR."""


def judged(run: Run, problem: Problem, tolerance: float, factor: float) -> tuple[float, float]:
    """The judge's worst |error| / ME bound over theta and omega, judged at ``tolerance`` with
    ME_FACTOR = ``factor``, and the time from the start from which the bound refuses nothing
    (inf: it holds to the end)."""
    result = read_result(run, None)
    experiment, _ = make_experiment(problem.start(tolerance), "ME")
    exact = checks.reference(result, replace(experiment, interface="CS"))
    allowance = sensitivity.allowance(exact.t, exact.theta, exact.omega, experiment, factor)
    ref = checks.Reference(exact.t, exact.theta, exact.omega, allowance)
    check = checks.bound_check(result, ref, experiment, checks.state_errors(result, ref))
    return float(check.numbers["worst_ratio"]), float(check.numbers["linear_until"])


@dataclass
class Tally:
    """The worst honest ratio, the smallest looser one where the bound holds to the end, and
    the looser runs it cannot judge (the allowed energy error reaches the separatrix)."""

    honest: tuple[float, str] = (-1.0, "")
    looser: tuple[float, str] = (math.inf, "")
    unjudged: int = 0
    runs: int = 0
    looser_failed: int = 0
    """Looser runs judged (the bound holding to the end) and found beyond the bound."""

    def add(self, other: Tally) -> None:
        self.honest = max(self.honest, other.honest)
        self.looser = min(self.looser, other.looser)
        self.unjudged += other.unjudged
        self.runs += other.runs
        self.looser_failed += other.looser_failed

    def cell(self) -> str:
        looser = f"{self.looser[0]:.2g}" if math.isfinite(self.looser[0]) else "-"
        mark = f" ({self.unjudged}*)" if self.unjudged else ""
        return f"{self.honest[0]:.2g} / {looser}{mark}"


def sweep(problem: Problem, name: str, run: Callable[[Problem, float], Run]) -> dict[float, Tally]:
    """The problem run by ``run`` at each tolerance, judged at its own and at 100 times less,
    with each of :data:`FACTORS` and checks.ME_FACTOR."""
    tallies = {f: Tally() for f in sorted({*FACTORS, checks.ME_FACTOR})}
    for tol in TOLERANCES:
        if tol < TIGHTEST.get(name, 0.0):
            continue
        where = f"{name}, {problem.name}, tol {tol:g}"
        own, loose = run(problem, tol), run(problem, tol * LOOSER)
        for factor, tally in tallies.items():
            honest, _ = judged(own, problem, tol, factor)
            looser, holds_until = judged(loose, problem, tol, factor)
            tally.honest = max(tally.honest, (honest, where))
            tally.runs += 2
            if math.isfinite(holds_until):
                tally.unjudged += 1
            else:
                tally.looser = min(tally.looser, (looser, where))
                tally.looser_failed += looser > 1.0
            print(f"# ME_FACTOR {factor:g}, {where}: honest {honest:.3g}, looser {looser:.3g}, refuses nothing "
                  f"from {holds_until:.3g} s", file=sys.stderr, flush=True)
    return tallies


def main(argv: list[str]) -> int:
    chosen = integrators()
    print(f"ME_FACTOR = {checks.ME_FACTOR:g}. Each cell: the worst |error| / bound of the runs at their own tol "
          "(< 1 passes) / the smallest of the runs at 100 tol judged as tol (> 1 fails); n*: n looser runs "
          "whose allowed energy error reaches the separatrix (no value refused from then on)")
    print(f"{'problem':24s}{'L':>6s}{'g':>6s}{'T':>7s}{'periods':>8s}{'rows':>6s}"
          + "".join(f"{n:>22s}" for n in chosen))
    totals: dict[str, dict[float, Tally]] = {}
    for problem in problems("--quick" in argv):
        cells = []
        for name, run in chosen.items():
            tallies = sweep(problem, name, run)
            for factor, tally in tallies.items():
                totals.setdefault(name, {}).setdefault(factor, Tally()).add(tally)
            cells.append(tallies[checks.ME_FACTOR].cell())
        print(f"{problem.name:24s}{problem.L:6.2f}{problem.g:6.2f}{problem.period:7.3g}{problem.periods:8.1f}"
              f"{problem.times.size:6d}" + "".join(f"{c:>22s}" for c in cells), flush=True)
    print("\nPer integrator and ME_FACTOR: largest honest ratio / smallest looser ratio (looser runs not judged)")
    factors = sorted({*FACTORS, checks.ME_FACTOR})
    print(f"{'integrator':12s}" + "".join(f"{'ME_FACTOR ' + format(f, 'g'):>24s}" for f in factors))
    overall = {f: Tally() for f in factors}
    for name, by_factor in totals.items():
        for f in factors:
            overall[f].add(by_factor[f])
        print(f"{name:12s}" + "".join(f"{by_factor[f].cell():>24s}" for f in factors))
    print(f"{'all':12s}" + "".join(f"{overall[f].cell():>24s}" for f in factors))
    print(f"\nLooser runs judged that fail, at ME_FACTOR {checks.ME_FACTOR:g}: " + ", ".join(
        f"{name} {by_factor[checks.ME_FACTOR].looser_failed} of "
        f"{by_factor[checks.ME_FACTOR].runs // 2 - by_factor[checks.ME_FACTOR].unjudged}"
        for name, by_factor in totals.items()))
    mine = overall[checks.ME_FACTOR]
    print(f"ME_FACTOR {checks.ME_FACTOR:g}, {mine.runs} runs: largest honest ratio {mine.honest[0]:.3g} "
          f"({mine.honest[1]}); smallest looser ratio {mine.looser[0]:.3g} ({mine.looser[1]}); {mine.unjudged} "
          "looser runs not judged (separatrix)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
