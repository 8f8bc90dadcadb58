"""What each command needs beyond the core install, and the one line it prints when that is missing.

``pip install pendulum-fmu`` installs the core: what ``judge``, ``simulate``, ``compare``,
``study`` and ``pendulum_fmu.exact`` need. The other commands need an extra
(``pyproject.toml``'s ``[project.optional-dependencies]``); before any work they call
:func:`require_extra`, which answers a missing one with

    pendulum-fmu sweep: needs the sweep extra: pip install 'pendulum-fmu[sweep]' (not installed: distributed)

and exit code 2, never a traceback.
"""

from __future__ import annotations

import ast
import importlib.util
import sys
from collections.abc import Sequence

EXTRAS: dict[str, tuple[str, ...]] = {
    "sweep": ("dask", "distributed", "tqdm"),
    "animate": ("PIL", "imageio_ffmpeg"),
    "bench": ("mpmath", "dask", "distributed", "tqdm"),
}
"""Extra -> the modules its distributions provide (``pyproject.toml`` lists the distributions)."""


def missing_modules(modules: Sequence[str]) -> list[str]:
    """The modules of ``modules`` that cannot be imported here.

    Parameters
    ----------
    modules : sequence of str
        Top-level module names, e.g. ``("distributed", "tqdm")``.

    Returns
    -------
    list of str
        Those not found, in the order given; nothing is imported.
    """
    return [name for name in modules if importlib.util.find_spec(name) is None]


def extra_line(command: str, extra: str, missing: Sequence[str]) -> str:
    """The one line that says which extra ``command`` needs.

    Parameters
    ----------
    command : str
        The command as typed after ``pendulum-fmu``, e.g. ``"bench accuracy"``.
    extra : str
        The extra's name in ``pyproject.toml``.
    missing : sequence of str
        The modules that were not found.

    Returns
    -------
    str
        ``pendulum-fmu COMMAND: needs the EXTRA extra: pip install 'pendulum-fmu[EXTRA]' (not installed: ...)``.
    """
    return (f"pendulum-fmu {command}: needs the {extra} extra: pip install 'pendulum-fmu[{extra}]' "
            f"(not installed: {', '.join(missing)})")


def require_extra(command: str, extra: str, modules: Sequence[str] | None = None) -> None:
    """Stop ``command`` with one line and exit code 2 unless ``extra``'s modules are installed.

    Parameters
    ----------
    command : str
        The command as typed after ``pendulum-fmu``, e.g. ``"sweep"``.
    extra : str
        A key of :data:`EXTRAS`.
    modules : sequence of str, optional
        The modules this use needs (default: all of the extra's), e.g. only ``PIL`` for a GIF.

    Raises
    ------
    SystemExit
        With code 2, after printing :func:`extra_line` to stderr, when a module is missing.
    """
    missing = missing_modules(EXTRAS[extra] if modules is None else modules)
    if missing:
        print(extra_line(command, extra, missing), file=sys.stderr)
        raise SystemExit(2)


def module_docstring(module: str) -> str | None:
    """A module's docstring, read from its source without importing it.

    ``--help`` shows a benchmark module's docstring; reading it this way keeps the help (and
    ``pendulum-fmu`` itself) working when the module imports an extra that is not installed.

    Parameters
    ----------
    module : str
        The dotted module name, e.g. ``"pendulum_fmu.bench.accuracy"``.

    Returns
    -------
    str or None
        The docstring, or None when the module or its source cannot be found.
    """
    spec = importlib.util.find_spec(module)
    if spec is None or spec.loader is None or not hasattr(spec.loader, "get_source"):
        return None
    source = spec.loader.get_source(module)
    return None if source is None else ast.get_docstring(ast.parse(source), clean=False)
