"""How the suite runs a case: a built-in engine, an importer's command line, or files made elsewhere.

Every run is a command in a process of its own (:mod:`pendulum_fmu.suite.process`), so that a
crash or a hang ends that run only. Built-in adapters: ``fmpy`` (``simulate_fmu``), ``fmpy-cli``
(``fmpy simulate``), ``libcosim`` (libcosimpy), ``ecos`` (ecospy), ``fmucontainer`` (the FMU
Manipulation Toolbox's container, run by fmpy) and ``fmpy-container`` (fmpy's ``container_fmu``,
run by fmpy); the split cases go to the engines of :mod:`pendulum_fmu.split.engines`.
"""

from __future__ import annotations

import importlib.metadata
import shlex
import string
import sys
from dataclasses import dataclass, field
from pathlib import Path

from pendulum_fmu.errors import UsageError
from pendulum_fmu.suite.cases import Kind
from pendulum_fmu.suite.experiment import OUTPUTS, Run

PLACEHOLDERS: tuple[str, ...] = ("fmu", "interface", "start", "stop", "interval", "tolerance", "output",
                                 "start_values", "experiment", "fmi_version", "case", "interface_type",
                                 "start_value_pairs")
"""What a command template may name, each in braces; values are shell-quoted words."""
SEVERAL_WORDS: tuple[str, ...] = ("start_values", "start_value_pairs")
"""Placeholders that stand for several words, each quoted alone."""
DISTRIBUTIONS = {"fmpy": "fmpy", "fmpy-cli": "fmpy", "libcosim": "libcosimpy", "ecos": "ecospy",
                 "fmucontainer": "fmu-manipulation-toolbox", "fmpy-container": "fmpy"}
"""The installed distribution behind each built-in adapter (its version goes in the reports)."""
CLAIMED_MASTERS = {"fmpy": "jacobi-zoh", "libcosim": "jacobi-zoh", "ecos": "jacobi-zoh",
                   "fmucontainer": "jacobi-zoh", "fmpy-container": "gauss-seidel-zoh"}
"""The reference master each engine implements for the split pendulum (its documentation: fmpy's
``simulate_ssp``, libcosim's and Ecos's fixed-step algorithms and fmucontainer's parallel mode
exchange all outputs first, Jacobi; fmpy's container steps in sequence, Gauss-Seidel), with the
zero-order hold they all use. The split judge's bound is taken against it."""


@dataclass(frozen=True)
class Adapter:
    """One way to run the cases.

    Attributes
    ----------
    name : str
        ``fmpy``, ..., ``command`` or ``results``.
    kinds : tuple
        Which cases it runs (``pendulum``, ``split``).
    template : str
        The command template (``command`` only).
    results : Path or None
        The folder of result files (``results`` only).
    master : str or None
        The reference master the split cases are judged against.
    """

    name: str
    kinds: tuple[Kind, ...]
    template: str = ""
    results: Path | None = None
    master: str | None = None
    environment: dict[str, str] = field(default_factory=dict)

    def version(self) -> str:
        """The engine and its version, e.g. ``fmpy 0.3.32``; the template for a command."""
        if self.name == "command":
            return f"command: {self.template}"
        if self.name == "results":
            return f"results from {self.results}"
        try:
            return f"{DISTRIBUTIONS[self.name]} {importlib.metadata.version(DISTRIBUTIONS[self.name])}"
        except importlib.metadata.PackageNotFoundError:
            return f"{DISTRIBUTIONS[self.name]} (not installed)"

    def command(self, run: Run, experiment_file: Path) -> list[str] | str:
        """The command that runs ``run``: a list of words, or a shell line for a template."""
        if self.name == "command":
            return fill_template(self.template, run, experiment_file)
        if self.name == "fmpy-cli" and run.case.kind == "pendulum":
            return fmpy_cli_command(run)
        engine = "fmpy" if self.name == "fmpy-cli" else self.name
        return [sys.executable, "-m", "pendulum_fmu.suite.engine_child", engine, str(experiment_file)]


def fill_template(template: str, run: Run, experiment_file: Path) -> str:
    """The template with each ``{placeholder}`` replaced by its shell-quoted value.

    ``{start_values}`` becomes several words, ``name=value`` each; ``{start_value_pairs}`` the
    words ``name value name value ...`` (fmpy's ``--start-values``).

    Raises
    ------
    ValueError
        A placeholder the suite does not know, or a malformed brace.
    """
    values = run.placeholders(experiment_file)
    quoted = {name: shlex.quote(value) for name, value in values.items()}
    for name in SEVERAL_WORDS:
        quoted[name] = " ".join(shlex.quote(word) for word in values[name].split())
    check_template(template)
    return template.format_map(quoted)


def check_template(template: str) -> None:
    """UsageError (field ``command``) naming the first unknown placeholder, or a malformed brace, of ``template``."""
    try:
        fields = [name for _, name, _, _ in string.Formatter().parse(template) if name is not None]
    except ValueError as error:
        raise UsageError("command", f"{error} (write a literal brace as {{{{ or }}}})") from None
    for name in fields:
        if name not in PLACEHOLDERS:
            raise UsageError("command", f"unknown placeholder {{{name}}} (known: "
                                        f"{', '.join('{' + p + '}' for p in PLACEHOLDERS)})")


def fmpy_cli_command(run: Run) -> list[str]:
    """``fmpy simulate`` with the case's settings, as a user of fmpy's command line types it."""
    case = run.case
    fmpy = Path(sys.executable).parent / "fmpy"
    words = [str(fmpy) if fmpy.exists() else "fmpy", "simulate", str(run.fmu),
             "--start-time", repr(case.start), "--stop-time", repr(case.stop),
             "--output-interval", repr(case.interval), "--relative-tolerance", repr(case.tolerance),
             "--interface-type", "ModelExchange" if case.interface == "me" else "CoSimulation",
             "--output-variables", *OUTPUTS, "--output-file", str(run.output)]
    if case.interface == "me":
        words += ["--solver", "CVode"]
    else:
        words += ["--step-size", repr(case.interval)]
    pairs = [word for name, value in case.start_values.items() for word in (name, repr(value))]
    return words + (["--start-values", *pairs] if pairs else [])


ENGINES: tuple[str, ...] = ("fmpy", "fmpy-cli", "libcosim", "ecos", "fmucontainer", "fmpy-container")
"""The built-in adapters, for ``--engine``."""


def engine(name: str) -> Adapter:
    """The built-in adapter ``name``; UsageError (field ``engine``) listing them otherwise."""
    if name not in ENGINES:
        raise UsageError("engine", f"no engine {name!r} (one of {', '.join(ENGINES)})")
    kinds: tuple[Kind, ...] = ("pendulum",) if name == "fmpy-cli" else ("pendulum", "split")
    return Adapter(name, kinds, master=CLAIMED_MASTERS.get(name))


def command(template: str) -> Adapter:
    """An importer's command line, from a template (checked now, not at the first case)."""
    check_template(template)
    return Adapter("command", ("pendulum",), template=template)


def results(folder: Path, master: str | None = None) -> Adapter:
    """Result files made elsewhere: ``FOLDER/<case>.csv`` (or the one CSV in ``FOLDER/<case>/``)."""
    return Adapter("results", ("pendulum", "split"), results=folder, master=master)
