"""The judge against its corpus (tests/helpers/judge_corpus.py): every honest run passes,
every wrong run fails and names its reason, in the tuning part and in the held-out part.

Both parts are generated once a session into a temporary folder and judged in two processes.
A failing test prints a compact table of every miss: file, engine, kind with the keywords it
expects, solver, regime, what went wrong, and the verdict line. The same table for people:
``.venv/bin/python tests/helpers/judge_corpus.py OUTDIR``.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

import judge_corpus as corpus
from engine_runs import missing
from judge_corpus import Case, Outcome

pytestmark = [pytest.mark.slow, pytest.mark.engines, pytest.mark.filterwarnings("ignore::RuntimeWarning")]


def _require_fmus() -> None:
    for version, path in corpus.FMUS.items():
        if not path.exists():
            pytest.fail(f"no FMI {version} FMU at {path}: bash scripts/study.sh builds it")


@pytest.fixture(scope="session")
def corpus_root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Both parts generated, each into its own folder; with ``PENDULUM_JUDGE_CORPUS=DIR`` the
    corpus that ``tests/helpers/judge_corpus.py DIR`` generated there (to judge it again quickly)."""
    _require_fmus()
    given = os.environ.get("PENDULUM_JUDGE_CORPUS")
    if given:
        root = Path(given)
        for part in corpus.PARTS:
            assert (root / part / "manifest.json").exists(), f"PENDULUM_JUDGE_CORPUS={given}: no {part}/manifest.json"
        return root
    root = tmp_path_factory.mktemp("judge_corpus")
    for part in corpus.PARTS:
        corpus.generate(root / part, part)
    return root


@pytest.fixture(scope="session")
def judged(corpus_root: Path) -> dict[str, list[Outcome]]:
    """Every case of each part with the judge's verdict."""
    return {part: corpus.judge_all(corpus_root / part, corpus.load(corpus_root / part)) for part in corpus.PARTS}


def _fail_with_misses(outcomes: list[Outcome], statuses: tuple[str, ...], what: str) -> None:
    missed = [o for o in outcomes if o.status in statuses]
    if missed:
        pytest.fail(f"{len(missed)} {what} of {len(outcomes)}:\n{corpus.misses(missed, limit=200)}", pytrace=False)


# --- the corpus itself -----------------------------------------------------------------------------

def test_corpus_sizes_and_kinds(corpus_root: Path) -> None:
    """At least 2,000 honest runs in all, every engine, FMI version, interface, regime and wrong
    kind in both parts, the held-out part about a quarter of the whole."""
    cases = {part: corpus.load(corpus_root / part) for part in corpus.PARTS}
    honest = {part: [c for c in found if c.kind == "honest"] for part, found in cases.items()}
    assert sum(len(h) for h in honest.values()) >= 2000
    share = len(honest["held-out"]) / sum(len(h) for h in honest.values())
    assert 0.2 <= share <= 0.3, share
    for part, found in cases.items():
        engines = {c.engine for c in honest[part]}
        assert {"fmpy CS FMI 2.0", "fmpy CS FMI 3.0", "fmpy ME FMI 2.0", "fmpy ME FMI 3.0"} <= engines, part
        assert {f"scipy {m}" for m in corpus.SCIPY_METHODS} <= engines, part
        assert {c.solver for c in honest[part] if c.engine.startswith("fmpy CS")} == set(corpus.SOLVERS.values())
        regimes = {c.regime for c in honest[part]}
        assert {"libration <90 deg", "libration 170-179.9 deg", "rotation near separatrix", "rotation"} <= regimes
        assert any("startTime" in c.start for c in honest[part]), part
        assert {c.kind for c in found if c.corpus == "wrong"} == set(corpus.WRONG_KINDS), part
        tolerances = [float(c.start["tolerance"]) for c in honest[part] if c.engine.startswith(("fmpy", "scipy"))]
        assert min(tolerances) < 1e-11 and max(tolerances) > 1e-5, part
        rows = [c.rows for c in honest[part]]
        assert min(rows) <= 20 and max(rows) >= 1500, part


def test_engine_runs_are_in_the_corpus(corpus_root: Path) -> None:
    """libcosim and Ecos runs: made when their Python packages are installed (every one of
    them; an fmpy or scipy run that fails is left out and listed in the manifest)."""
    for module in ("libcosimpy", "ecospy"):
        why_not = missing(module)
        if why_not:
            pytest.skip(why_not)
    for part in corpus.PARTS:
        manifest = json.loads((corpus_root / part / "manifest.json").read_text())
        not_made = [line for line in manifest["failures"] if line.startswith("honest/e")]
        assert not_made == [], not_made
        engines = Counter(c["engine"] for c in manifest["cases"])
        assert engines["libcosim FMI 2.0"] >= 3 and engines["Ecos FMI 2.0"] >= 1 and engines["Ecos FMI 3.0"] >= 1


def test_honest_runs_are_honest(corpus_root: Path) -> None:
    """Each honest file's exact columns are the exact solution of what the judge is told, so a
    false alarm is the judge's and not the corpus's (checked where the file has them)."""
    import pandas as pd

    from pendulum_fmu import exact

    checked = 0
    for part in corpus.PARTS:
        for case in corpus.load(corpus_root / part)[::7]:
            if case.corpus != "honest":
                continue
            table = pd.read_csv(corpus_root / part / case.name, skipinitialspace=True)
            column = {name: next(c for c in table.columns if name in c) for name in ("theta_exact", "omega_exact")}
            times = table[next(c for c in table.columns if c.lower() == "time")].to_numpy()
            start = float(case.start.get("startTime", 0.0))
            theta, omega = exact(case.start["theta"], case.start["omega"], case.start["L"], case.start["g"],
                                 times - start)
            scale = 1e-6 if case.engine.startswith("Ecos") else 1e-12  # Ecos prints %.6f
            w0 = math.sqrt(float(case.start["g"]) / float(case.start["L"]))
            largest = max(1.0, float(np.max(np.abs(theta))))
            assert np.max(np.abs(table[column["theta_exact"]] - theta)) <= scale * largest
            assert np.max(np.abs(table[column["omega_exact"]] - omega)) <= scale * max(w0, float(np.max(np.abs(omega))))
            checked += 1
    assert checked > 250


VISIBLE_IN_THE_VALUES = ("fixed step: explicit Euler", "fixed step: symplectic Euler", "fixed step: Heun",
                         "fixed step: RK4", "tolerance not passed on", "time lag", "values one step early",
                         "scaled clock", "g = 9.80665 not told", "L = 2 not told", "g = 1.62 not told", "wrong theta",
                         "wrong omega", "startTime 5 not told", "degrees for radians")
"""The wrong kinds whose theta or omega is off the exact solution of what the judge is told
by more than 10 times the bound (CS 100 tol; ME ME_FACTOR tol a period); the others are wrong in their
times, their rows or one value."""


def test_wrong_runs_are_wrong(corpus_root: Path) -> None:
    """Each wrong file of those kinds is far from the exact solution of what the judge is told,
    by pendulum_fmu.exact at the file's own times: the fault is in the file, not in the test."""
    import pandas as pd

    from pendulum_fmu import exact

    for part in corpus.PARTS:
        for case in corpus.load(corpus_root / part):
            if case.kind not in VISIBLE_IN_THE_VALUES:
                continue
            table = pd.read_csv(corpus_root / part / case.name)
            start = {**{"theta": corpus.DEFAULT_THETA, "omega": 0.0, "L": 1.0, "g": 9.81, "startTime": 0.0,
                        "tolerance": corpus.DEFAULT_TOLERANCE}, **case.start}
            t = table["time"].to_numpy() - float(start["startTime"])
            theta, omega = exact(start["theta"], start["omega"], start["L"], start["g"], t)
            w0 = math.sqrt(float(start["g"]) / float(start["L"]))
            off = max(float(np.max(np.abs(table["theta"].to_numpy() - theta) / np.maximum(1.0, np.abs(theta)))),
                      float(np.max(np.abs(table["omega"].to_numpy() - omega) / np.maximum(w0, np.abs(omega)))))
            bound = (100 if case.interface == "CS" else 1000) * float(start["tolerance"])
            assert off > 10 * bound, (part, case.name, case.kind, off, bound)


def _digest(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(folder.rglob("*.csv")):
        if "engines" not in path.parts:
            digest.update(path.name.encode() + path.read_bytes())
    return digest.hexdigest()


def test_corpus_is_deterministic_and_the_parts_differ(tmp_path: Path) -> None:
    """The same seed makes the same files; the two parts' seeds make different ones."""
    _require_fmus()
    made = {}
    for name, part in (("a", "tuning"), ("b", "tuning"), ("c", "held-out")):
        corpus.generate(tmp_path / name, part, engines=False, fraction=0.02)
        made[name] = _digest(tmp_path / name)
    assert made["a"] == made["b"]
    assert made["a"] != made["c"]


def test_the_contract_can_fail(tmp_path: Path) -> None:
    """The outcome's status: a failed honest run is a false alarm, a passed wrong run a false
    pass, a wrong run failed without its keywords a wrong reason."""
    honest = Case("h.csv", "honest", "fmpy CS FMI 2.0", "honest", {}, "CS", "rkn", "rotation", 10)
    wrong = Case("w.csv", "wrong", "fmpy CS FMI 2.0", "g = 1.62 not told", {}, "CS", "rkn", "rotation", 10)
    assert Outcome(honest, True, "PASS: fine", 0.0).status == "right"
    assert Outcome(honest, False, "FAIL (bound): x", 0.0).status == "false alarm"
    assert Outcome(wrong, True, "PASS: fine", 0.0).status == "false pass"
    assert Outcome(wrong, False, "FAIL (bound): mangled values", 0.0).status == "wrong reason"
    assert Outcome(wrong, False, "FAIL (exact columns): G = 1.62 (not 9.81)", 0.0).status == "right"
    table = corpus.confusion([Outcome(honest, False, "FAIL: x", 0.0), Outcome(wrong, True, "PASS", 0.0)])
    assert "false alarms: 1" in table and "false passes: 1" in table


# --- the contract ----------------------------------------------------------------------------------

def test_tuning_honest_runs_pass(judged: dict[str, list[Outcome]]) -> None:
    """No false alarm: every honest run of the tuning part passes."""
    _fail_with_misses([o for o in judged["tuning"] if o.case.corpus == "honest"], ("false alarm",), "false alarms")


def test_tuning_wrong_runs_fail_with_their_reason(judged: dict[str, list[Outcome]]) -> None:
    """No false pass, and the expected keywords in every wrong run's verdict line (tuning part)."""
    _fail_with_misses([o for o in judged["tuning"] if o.case.corpus == "wrong"], ("false pass", "wrong reason"),
                      "wrong runs missed")


def test_held_out_honest_runs_pass(judged: dict[str, list[Outcome]]) -> None:
    """No false alarm on the held-out part (never used to tune the judge)."""
    _fail_with_misses([o for o in judged["held-out"] if o.case.corpus == "honest"], ("false alarm",), "false alarms")


def test_held_out_wrong_runs_fail_with_their_reason(judged: dict[str, list[Outcome]]) -> None:
    """No false pass and the right reason on the held-out part (never used to tune the judge)."""
    _fail_with_misses([o for o in judged["held-out"] if o.case.corpus == "wrong"], ("false pass", "wrong reason"),
                      "wrong runs missed")
