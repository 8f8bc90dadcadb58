"""No test compares a wall-clock measurement: timings live in ``pendulum-fmu bench``.

A test that asserts a measured duration (or a value computed from one: a rate, a speed-up, a
task size sized by a timed run) fails on a loaded machine while the code is right, as
``test_a_sweep_sends_tasks_of_a_tenth_of_a_second`` did (``assert 80 == 81``, a task size
from a run timed on a busy machine). This test reads every test module of ``tests/`` and
follows, inside each function, the values that come from a clock: a call of
``time.perf_counter``, ``time.monotonic``, ``time.time``, ``time.process_time`` (and their
``_ns`` forms) or ``timeit``, or of one of the package's measuring functions
(:data:`MEASURING`), and every name assigned from such a value (also through ``append``,
tuple unpacking and attributes). An ``assert`` may compare such a value only

- with ``> 0`` or ``>= 0`` (a measurement happened), or
- against a literal of at least :data:`HANG_GUARD` seconds (a guard against a hang, far above
  any honest run, like a subprocess's ``timeout=``).

Anything else (an equality, a ratio of two timings, a bound of a few seconds) is a timed test.
The rule is checked on this file's own examples too (:func:`test_the_rule_finds_timed_asserts`).
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1]

CLOCKS = frozenset({"perf_counter", "perf_counter_ns", "monotonic", "monotonic_ns", "process_time",
                    "process_time_ns", "thread_time", "thread_time_ns", "timeit", "repeat", "default_timer"})
"""Functions of ``time`` and ``timeit`` that read a clock (``time.time`` is matched as ``time.time``)."""
MEASURING = frozenset({("pendulum_fmu.bench.sweep", "measure"), ("pendulum_fmu.bench.sweep", "task_cost"),
                       ("pendulum_fmu.sweep.cluster", "measured_run_seconds"),
                       ("pendulum_fmu.bench.exact", "wrapper_overhead")})
"""The package's functions that return wall-clock or CPU-time figures, by module and name (a
call counts when the test module imports the name from that module)."""
TIMING_WORDS = ("seconds", "elapsed", "took", "duration", "wall", "rate", "cost")
"""A name unpacked from a call that takes a clock's value is one when it holds one of these."""
TIMED_FIELDS = frozenset({"wall_time", "seconds", "rate", "per_task", "elapsed"})
"""Attributes that hold a measured duration or a rate derived from one (``Trajectory.wall_time``,
a benchmark's ``seconds`` and ``rate``)."""
HANG_GUARD = 60.0
"""A measured duration may be asserted below a literal of at least this many seconds."""


_MEASURING_NAMES: set[str] = set()
"""The names of :data:`MEASURING` the module being read imports (set by :func:`timed_asserts`)."""


def _is_clock_call(node: ast.AST) -> bool:
    if not isinstance(node, ast.Call):
        return False
    function = node.func
    if isinstance(function, ast.Attribute):
        if function.attr in CLOCKS:
            return True
        return function.attr == "time" and isinstance(function.value, ast.Name) and function.value.id == "time"
    return isinstance(function, ast.Name) and (function.id in CLOCKS or function.id in _MEASURING_NAMES)


def _tainted(node: ast.AST, names: set[str], in_arguments: bool = False) -> bool:
    """Whether an expression holds a clock's value: a clock call, a tainted name, or a timed field
    (``run.wall_time``; not when it is only handed to a call, such as a constructor's argument)."""
    if _is_clock_call(node):
        return True
    if isinstance(node, ast.Name):
        return node.id in names
    if isinstance(node, ast.Attribute) and node.attr in TIMED_FIELDS and not in_arguments:
        return True
    if isinstance(node, ast.Call):
        return _tainted(node.func, names) or any(_tainted(a, names, True) for a in node.args) or \
            any(_tainted(k.value, names, True) for k in node.keywords)
    return any(_tainted(child, names, in_arguments) for child in ast.iter_child_nodes(node))


def _targets(target: ast.AST) -> list[str]:
    """The names a target binds (tuples, lists and starred ones included)."""
    return [n.id for n in ast.walk(target) if isinstance(n, ast.Name)]


def _bound(target: ast.AST, value: ast.AST, names: set[str]) -> list[str]:
    """The names of ``target`` that take a clock's value from ``value``: pairwise for a tuple of
    values; from a call's tuple, those named as durations unless the call itself reads a clock."""
    if isinstance(target, (ast.Tuple, ast.List)):
        if isinstance(value, (ast.Tuple, ast.List)) and len(value.elts) == len(target.elts):
            pairs = zip(target.elts, value.elts, strict=True)
            return [n for t, v in pairs if _tainted(v, names) for n in _bound(t, v, names)]
        raw = any(_is_clock_call(n) and not (isinstance(n.func, ast.Name) and n.func.id in _MEASURING_NAMES)
                  for n in ast.walk(value))
        if not raw:  # a helper's or a benchmark's tuple: its durations, not its other parts
            return [n for n in _targets(target) if any(word in n.lower() for word in TIMING_WORDS)]
    return _targets(target)


def _tainted_names(function: ast.AST) -> set[str]:
    """The names that hold a clock's value somewhere in ``function`` (to a fixed point)."""
    names: set[str] = set()
    while True:
        before = len(names)
        for node in ast.walk(function):
            if isinstance(node, (ast.Assign, ast.AugAssign, ast.AnnAssign)) and node.value is not None \
                    and _tainted(node.value, names):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                for target in targets:
                    names.update(_bound(target, node.value, names))
            elif isinstance(node, (ast.For, ast.comprehension)) and _tainted(node.iter, names):
                names.update(_bound(node.target, node.iter, names))
            elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                    and node.func.attr in ("append", "extend", "add", "update") \
                    and isinstance(node.func.value, ast.Name) and any(_tainted(a, names) for a in node.args):
                names.add(node.func.value.id)  # a list or set that collects clock values
            elif isinstance(node, ast.arg) and "seconds" in node.arg:
                names.add(node.arg)  # a callback's parameter named as a duration
        if len(names) == before:
            return names


def _allowed(compare: ast.Compare, names: set[str]) -> bool:
    """``x > 0``, ``x >= 0`` or ``x < LIMIT`` (``<=``) with LIMIT >= HANG_GUARD, for one clock value x."""
    if len(compare.ops) != 1:
        return False
    left, op, right = compare.left, compare.ops[0], compare.comparators[0]
    if isinstance(op, (ast.Is, ast.IsNot)):
        return True  # present or absent, not how long
    if _tainted(left, names) and _tainted(right, names):
        return False
    value, limit, op_on_value = (left, right, op) if _tainted(left, names) else (right, left, _flip(op))
    del value
    if not (isinstance(limit, ast.Constant) and isinstance(limit.value, (int, float))):
        return False
    number = float(limit.value)
    if isinstance(op_on_value, (ast.Gt, ast.GtE)) and number == 0:
        return True
    return isinstance(op_on_value, (ast.Lt, ast.LtE)) and number >= HANG_GUARD


def _flip(op: ast.cmpop) -> ast.cmpop:
    return {ast.Lt: ast.Gt(), ast.LtE: ast.GtE(), ast.Gt: ast.Lt(), ast.GtE: ast.LtE()}.get(type(op), op)


def timed_asserts(source: str, filename: str = "<test>") -> list[str]:
    """``file:line: the assert`` for every assert that compares a clock's value outside the rule."""
    tree = ast.parse(source, filename)
    _MEASURING_NAMES.clear()
    _MEASURING_NAMES.update(alias.asname or alias.name for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)
                            for alias in node.names if (node.module, alias.name) in MEASURING)
    helpers = [f for f in ast.walk(tree) if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))]
    while True:  # the module's own helpers that return a clock's value measure too
        before = len(_MEASURING_NAMES)
        for helper in helpers:
            names = _tainted_names(helper)
            if any(isinstance(n, ast.Return) and n.value is not None and _tainted(n.value, names)
                   for n in ast.walk(helper)):
                _MEASURING_NAMES.add(helper.name)
        if len(_MEASURING_NAMES) == before:
            break
    found = []
    for function in ast.walk(tree):
        if not isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        names = _tainted_names(function)
        for node in ast.walk(function):
            if not isinstance(node, ast.Assert):
                continue
            for compare in (n for n in ast.walk(node.test) if isinstance(n, ast.Compare)):
                if _tainted(compare, names) and not _allowed(compare, names):
                    found.append(f"{filename}:{node.lineno}: {ast.unparse(node.test)[:120]}")
                    break
    return sorted(set(found))


def test_the_rule_finds_timed_asserts() -> None:
    """The rule flags the kinds of timed asserts it exists for, and lets the allowed ones by."""
    flagged = '''
import time
def test_a(client):
    start = time.perf_counter()
    work()
    took = time.perf_counter() - start
    assert took < 1.0
def test_b(one, two):
    assert two.rate > 1.1 * one.rate
def test_c(measured):
    sizes = []
    def record(points, run_seconds=None):
        measured.append(run_seconds)
    (cost,) = measured
    assert size_of(cost) == 81
from pendulum_fmu.bench.exact import wrapper_overhead
def test_d():
    best = wrapper_overhead(10, 5)
    assert best[0] <= 1.2 * best[1]
'''
    assert sorted(int(line.split(":")[1]) for line in timed_asserts(flagged)) == [7, 9, 15, 19]
    allowed = '''
import time
def test_e():
    start = time.monotonic()
    run()
    assert time.monotonic() - start < 120
    cost = task_cost(None, 3)
    assert cost > 0
    code, seconds, stderr = interrupted(start)
    assert code == 130 and "Traceback" not in stderr
    warned = Trajectory(1, 2, run.wall_time)
    assert warned.lines == 3
'''
    assert timed_asserts(allowed) == []


def test_no_test_asserts_a_timing() -> None:
    """Every test module of the suite, by the rule of this module's docstring."""
    found: list[str] = []
    for path in sorted(TESTS.rglob("*.py")):
        found += timed_asserts(path.read_text(), str(path.relative_to(TESTS)))
    assert not found, "timed asserts (move the timing into pendulum-fmu bench):\n" + "\n".join(found)
