"""A held-out corpus of co-simulation masters for the split pendulum judge, written without the
package's master code.

Body (theta' = omega, omega' = u(s) for an input polynomial u0 + u1 s + u2 s^2 / 2 over a step)
is integrated in closed form, as the FMU does (docs/split.md); Gravity is alpha = -(g/L) sin(x).
The masters couple the two in plain numpy-free Python, each its own way:

- honest: Gauss-Seidel and Jacobi with zero-order hold; Gauss-Seidel with first-order input
  interpolation only; a second-order Taylor input; Jacobi with alpha extrapolated from its last two
  values; a ramp from the last two values; strong coupling (each step iterated to a fixed point);
  multirate (Gravity every m macro steps); a variable macro step; output decimated to every m-th
  point; other column layouts and print precisions;
- planted defects: a wrong sign, a wrong connection, parameter mismatches between the FMUs,
  inputs stale at random steps or always, rows out of order, labelled early or late, missing or
  doubled, start values other than the SSP's, a dropped connection.

Two parts from two seeds: ``tuning`` (what the judge was tuned on) and ``held-out`` (judged once,
when the judge was settled). ``python tests/helpers/split_corpus.py`` prints the table of both parts.
"""

from __future__ import annotations

import math
import multiprocessing
import os
import random
import sys
from dataclasses import dataclass, field
from pathlib import Path

SEEDS = {"tuning": 20261128, "held-out": 91173}
THETA0 = 1.3089969389957472
G, L = 9.81, 1.0


@dataclass(frozen=True)
class Case:
    """One file of the corpus: ``honest`` or the defect's kind the judge must name, the master that
    made it, the reference master it reproduces (None: its own), and the ``--start`` items."""

    name: str
    kind: str
    master: str
    reproduces: str | None
    path: Path
    start: tuple[str, ...] = ()
    step: float | None = None


@dataclass
class Setup:
    """A master and what is planted in it."""

    master: str
    H: float
    stop: float
    theta0: float = THETA0
    omega0: float = 0.0
    g_gravity: float = G
    L_gravity: float = L
    sign: float = 1.0
    signal: str = "theta"
    stale_at: frozenset[int] = frozenset()
    stale_always: bool = False
    drop: bool = False
    every: int = 1
    multirate: int = 1
    variable: bool = False
    rows: dict[str, object] = field(default_factory=dict)


def _body_step(theta: float, omega: float, u0: float, u1: float, u2: float, h: float) -> tuple[float, float]:
    """Body's closed form for the input u0 + u1 s + u2 s^2 / 2 over a step h."""
    return (theta + omega * h + u0 * h * h / 2 + u1 * h ** 3 / 6 + u2 * h ** 4 / 24,
            omega + u0 * h + u1 * h * h / 2 + u2 * h ** 3 / 6)


def run(setup: Setup) -> tuple[list[float], list[float], list[float]]:
    """The master's communication points: times, theta, omega."""
    k = setup.sign * setup.g_gravity / setup.L_gravity

    def gravity(x: float) -> float:
        return -k * math.sin(x)

    theta, omega = setup.theta0, setup.omega0
    given = [theta]  # what Gravity got at each point
    times, thetas, omegas = [0.0], [theta], [omega]
    held = gravity(theta)  # Body's input as last set
    alphas = [held]
    t = 0.0
    n = round(setup.stop / setup.H)
    for step in range(n):
        h = setup.H * (1 + 0.4 * math.sin(2 * math.pi * step / 37)) if setup.variable else setup.H
        x = omega if setup.signal == "omega" else theta
        master = setup.master
        u1 = u2 = 0.0
        refresh = step % setup.multirate == 0 and not (setup.drop and step > 0)
        if master == "jacobi-zoh":
            lag = 2 if setup.stale_always or step in setup.stale_at else 1
            source = given[max(0, len(given) - lag)]
            u0 = gravity(source) if refresh else held
        elif master == "gs-zoh":
            lag = 1 if step in setup.stale_at else 0
            source = x if lag == 0 else (given[-1] if given else x)
            u0 = gravity(source) if refresh else held
        elif master == "gs-interp1":
            u0 = gravity(x)
            u1 = -k * math.cos(x) * omega
        elif master == "gs-taylor2":
            u0 = gravity(x)
            u1 = -k * math.cos(x) * omega
            u2 = -k * (math.cos(x) * u0 - math.sin(x) * omega ** 2)
        elif master == "jacobi-past2":  # alpha extrapolated to mid-step from its last two values
            a1 = gravity(given[-1])
            a2 = gravity(given[-2]) if len(given) > 1 else a1
            u0 = a1 + 1.5 * (a1 - a2)
        elif master == "gs-ramp":  # the ramp through the last two values, continued over the step
            a1 = gravity(x)
            a2 = alphas[-1] if step else a1
            u0, u1 = a1, (a1 - a2) / h if step else 0.0
        elif master == "strong":  # u through alpha(t_k) with its slope and alpha(t_k+1), iterated to a fixed point
            a0 = gravity(x)
            slope = -k * math.cos(x) * omega if setup.signal == "theta" else None
            end = a0
            for _ in range(100):
                u1 = slope if slope is not None else (end - a0) / h
                u2 = 2 * (end - a0 - slope * h) / (h * h) if slope is not None else 0.0
                ends = _body_step(theta, omega, a0, u1, u2, h)
                new = gravity(ends[1] if setup.signal == "omega" else ends[0])
                if abs(new - end) <= 1e-15 * max(1.0, abs(new)):
                    end = new
                    break
                end = new
            u0 = a0
            u1 = slope if slope is not None else (end - a0) / h
            u2 = 2 * (end - a0 - slope * h) / (h * h) if slope is not None else 0.0
        else:
            raise ValueError(master)
        held = u0
        alphas.append(u0)
        given.append(x)
        theta, omega = _body_step(theta, omega, u0, u1, u2, h)
        t += h
        times.append(t)
        thetas.append(theta)
        omegas.append(omega)
    return times, thetas, omegas


LAYOUTS = [
    (("time", "Body.theta", "Body.omega"), ","),
    (("Time", "Body::theta", "Body::omega"), ";"),
    (("time", "theta", "omega"), ","),
    (("time", "Body.omega", "Body.theta"), "\t"),
]
PRINTS = ["repr", "%.17g", "%.12g", "%.9g", "%.7g"]


def write(path: Path, times: list[float], theta: list[float], omega: list[float], layout: int, fmt: str,
          gravity_columns: bool = False, exact: tuple[float, float, float] | None = None) -> Path:
    """The rows in one of :data:`LAYOUTS`, printed as ``fmt``; with ``exact`` = (theta0, omega0,
    shift) Body's theta_exact too (the exact pendulum at each row's time + shift, as Body's own
    column moves with its values when the rows are relabelled)."""
    layout_names, sep = LAYOUTS[layout]
    names: tuple[str, ...] = layout_names

    def show(v: float) -> str:
        return repr(v) if fmt == "repr" else fmt % v

    columns = {"theta": theta, "omega": omega}
    if exact is not None:
        import numpy as np

        from pendulum_fmu import exact as solution

        columns["theta_exact"] = [float(v) for v in solution(exact[0], exact[1], L, G, np.asarray(times) + exact[2])[0]]
        names = (*names, next(n for n in names if n.endswith("theta")) + "_exact")
    with open(path, "w") as stream:
        header = list(names) + (["Gravity.theta", "Gravity.alpha"] if gravity_columns else [])
        stream.write(sep.join(header) + "\n")
        for i, t in enumerate(times):
            cells = [show(t)] + [show(columns[name.split(".")[-1].split("::")[-1]][i]) for name in names[1:]]
            if gravity_columns:
                cells += [show(theta[i]), show(-G / L * math.sin(theta[i]))]
            stream.write(sep.join(cells) + "\n")
    return path


HONEST = {  # master -> the reference master it reproduces
    "gs-zoh": "gauss-seidel-zoh", "jacobi-zoh": "jacobi-zoh", "gs-interp1": None, "gs-taylor2": None,
    "jacobi-past2": None, "gs-ramp": None, "strong": "iterated-interpolation",
}
DEFECTS = ("sign", "connection", "parameter", "stale", "out-of-order", "labels", "missing", "doubled", "start",
           "dropped")


def _start(rng: random.Random) -> tuple[float, float]:
    return math.radians(rng.choice([20.0, 45.0, 75.0, 110.0, 150.0])), rng.choice([0.0, 0.0, 0.5, -1.0])


def generate(folder: Path, part: str) -> list[Case]:
    """Both kinds of case for one part, written under ``folder``."""
    rng = random.Random(SEEDS[part])
    folder.mkdir(parents=True, exist_ok=True)
    cases: list[Case] = []

    def emit(name: str, kind: str, setup: Setup, reproduces: str | None, stated: bool = True,
             rows: str = "", layout: int | None = None, fmt: str | None = None,
             step: float | None = None) -> None:
        times, theta, omega = run(setup)
        if setup.every > 1:
            times, theta, omega = times[:: setup.every], theta[:: setup.every], omega[:: setup.every]
        n = len(times)
        if rows == "early":
            times, theta, omega = times[:-1], theta[1:], omega[1:]
        elif rows == "late":
            times, theta, omega = times[1:], theta[:-1], omega[:-1]
        elif rows == "missing":
            i = rng.randrange(3, n - 3)
            times, theta, omega = times[:i] + times[i + 1:], theta[:i] + theta[i + 1:], omega[:i] + omega[i + 1:]
        elif rows == "doubled":
            i = rng.randrange(3, n - 3)
            times, theta, omega = times[:i] + times[i - 1:], theta[:i] + theta[i - 1:], omega[:i] + omega[i - 1:]
        elif rows == "swapped":
            i = rng.randrange(3, n - 3)
            for column in (times, theta, omega):
                column[i], column[i + 1] = column[i + 1], column[i]
        layout = rng.randrange(len(LAYOUTS)) if layout is None else layout
        fmt = rng.choice(PRINTS) if fmt is None else fmt
        shift = {"early": setup.H, "late": -setup.H}.get(rows, 0.0)
        with_exact = (setup.theta0, setup.omega0, shift) if rng.random() < 0.3 and setup.every == 1 else None
        path = write(folder / f"{len(cases):03d}-{name}.csv", times, theta, omega, layout, fmt,
                     gravity_columns=rng.random() < 0.25, exact=with_exact)
        start = (f"theta={setup.theta0!r}", f"omega={setup.omega0!r}") if stated else ()
        cases.append(Case(name, kind, setup.master, reproduces, path, start, step))

    steps = [0.02, 0.01, 0.005]
    for master, reproduces in HONEST.items():
        for _ in range(4):
            theta0, omega0 = _start(rng)
            H = rng.choice(steps)
            # a master of its own printed short may sit within the print of a reference master
            emit(f"honest-{master}", "honest", Setup(master, H, rng.choice([2.0, 3.0]), theta0, omega0), reproduces,
                 fmt=None if reproduces else rng.choice(PRINTS[:3]))
    for _ in range(3):
        theta0, omega0 = _start(rng)
        m = rng.choice([2, 3])
        emit("honest-multirate", "honest", Setup("gs-zoh", 0.01, 2.0, theta0, omega0, multirate=m), None)
        emit("honest-variable", "honest", Setup(rng.choice(["gs-interp1", "strong"]), 0.01, 2.0, theta0, omega0,
                                                variable=True), None)
        every = rng.choice([5, 10])
        master = rng.choice(["gs-zoh", "jacobi-zoh", "strong"])
        emit("honest-decimated", "honest", Setup(master, 0.002, 2.0, theta0, omega0, every=every),
             HONEST[master], fmt=None if HONEST[master] else rng.choice(PRINTS[:3]))
        emit("honest-print", "honest", Setup("gs-zoh", 0.01, 2.0, theta0, omega0), "gauss-seidel-zoh",
             fmt=rng.choice(["%.7g", "%.9g", "%.10g"]))
    for defect in DEFECTS:
        for _ in range(5):
            theta0, omega0 = _start(rng)
            H = rng.choice(steps)
            master = rng.choice(["gs-zoh", "jacobi-zoh"] if defect in ("stale", "dropped") else
                                ["gs-zoh", "jacobi-zoh", "gs-interp1", "strong"])
            if defect == "connection" and omega0 == 0:  # at rest, Gravity fed omega = 0 would be a dropped input
                omega0 = rng.choice([0.5, -1.0])
            setup = Setup(master, H, rng.choice([2.0, 3.0]), theta0, omega0)
            rows, stated = "", True
            if defect == "sign":
                setup.sign = -1.0
            elif defect == "connection":
                setup.signal = "omega"
            elif defect == "parameter":
                if rng.random() < 0.5:
                    setup.g_gravity = 9.80
                else:
                    setup.L_gravity = rng.choice([2.0, 1.1, 0.5])
            elif defect == "stale":
                n = round(setup.stop / H)
                if master == "jacobi-zoh" and rng.random() < 0.3:
                    setup.stale_always = True
                else:
                    setup.stale_at = frozenset(rng.sample(range(3, n), max(2, n // 100)))
            elif defect == "out-of-order":
                rows = "swapped"
            elif defect == "labels":
                rows = rng.choice(["early", "late"])
            elif defect in ("missing", "doubled"):
                rows = defect
            elif defect == "start":
                stated = False
                setup.theta0 = THETA0 + rng.choice([0.05, -0.2, 0.3])
            elif defect == "dropped":
                setup.drop = True
            emit(f"defect-{defect}-{master}", defect, setup, None, stated, rows)
    return cases


@dataclass(frozen=True)
class Outcome:
    """A case and what the judge said: ``ok``, ``honest-failed``, ``wrong-passed``, ``wrong-cause``
    (the planted defect not named, or another named beside it) or ``misidentified`` (an honest
    run of a reference master named otherwise, or another master named as one)."""

    case: Case
    status: str
    summary: str
    kinds: tuple[str, ...]


def judge(case: Case) -> Outcome:
    """The judge's verdict on one case."""
    from pendulum_fmu.cli.judge import split_problem
    from pendulum_fmu.split.judge import judge_split

    verdict = judge_split(case.path, problem=split_problem(list(case.start)), step=case.step)
    kinds = tuple(f.kind for f in verdict.findings)
    if case.kind == "honest":
        if not verdict.conformance.passed:
            status = "honest-failed"
        elif verdict.master != case.reproduces:
            status = "misidentified"
        else:
            status = "ok"
    elif verdict.conformance.passed:
        status = "wrong-passed"
    elif set(kinds) != {case.kind}:  # the planted defect, and nothing else
        status = "wrong-cause"
    else:
        status = "ok"
    return Outcome(case, status, verdict.summary, kinds)


def judge_all(cases: list[Case]) -> list[Outcome]:
    """The judge's verdicts on the cases, in order, in a process per core (the judge re-runs
    reference masters, single-threaded: a part takes a minute and a half in one process)."""
    with multiprocessing.get_context("fork").Pool(min(len(cases), os.cpu_count() or 1) or 1) as pool:
        return pool.map(judge, cases, chunksize=2)


def table(outcomes: dict[str, list[Outcome]]) -> list[str]:
    """The counts per part, Markdown."""
    lines = ["| part | honest | honest failed | misidentified | wrong | wrong passed | wrong causes |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for part, found in outcomes.items():
        honest = [o for o in found if o.case.kind == "honest"]
        wrong = [o for o in found if o.case.kind != "honest"]
        count = {s: sum(o.status == s for o in found) for s in
                 ("honest-failed", "misidentified", "wrong-passed", "wrong-cause")}
        lines.append(f"| {part} | {len(honest)} | {count['honest-failed']} | {count['misidentified']} | {len(wrong)} | "
                     f"{count['wrong-passed']} | {count['wrong-cause']} |")
    return lines


def main(folder: str) -> int:
    """Generate and judge both parts under ``folder``; print the misses and the table."""
    outcomes = {}
    for part in SEEDS:
        outcomes[part] = judge_all(generate(Path(folder) / part, part))
        for o in outcomes[part]:
            if o.status != "ok":
                print(f"{part} {o.case.path.name} {o.status}: expected {o.case.kind}/{o.case.reproduces}; "
                      f"{o.summary}")
    print("\n".join(table(outcomes)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "split-corpus"))
