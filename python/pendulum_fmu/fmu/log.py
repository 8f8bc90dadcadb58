"""The FMU's log messages, kept per run: warnings for the user, errors for the failure's reason.

An FMU reports through the ``fmi2CallbackLogger`` it was given at ``fmi2Instantiate``
(FMI 2.0.x, section 2.1.5): status, category and message. fmpy formats the variadic message
in a small C proxy and hands it to a Python function. That proxy keeps one Python logger for
the whole process (the last one registered), so a logger per instance would be replaced by
the next one and, once collected, leave the proxy calling freed memory. Hence one logger for
the process, :func:`shared_callbacks`, kept alive for good, which routes each message by its
instance name to the :class:`FmuLog` registered for it (:func:`register`) and prints the
others as fmpy does. The name, not the component: the FMU's logger receives the
``componentEnvironment`` of the callbacks (FMI 2.0.x, 2.1.5), the same for every instance
given these callbacks, while each :class:`~pendulum_fmu.fmu.runner.FmuRunner` names its
instances uniquely (:func:`unique_instance_name`).
"""

from __future__ import annotations

import itertools
import threading
from ctypes import byref
from dataclasses import dataclass, field
from typing import Any

FMI2_WARNING = 1
"""fmi2Status fmi2Warning."""
FMI2_ERROR = 3
"""fmi2Status fmi2Error (fmi2Fatal is 4)."""


@dataclass
class FmuLog:
    """Messages logged by the FMU since the last :meth:`clear`.

    Attributes
    ----------
    entries : list of tuple
        (status, category, message) in the order logged.
    """

    entries: list[tuple[int, str, str]] = field(default_factory=list)

    def callback(self, component: Any, instance_name: bytes, status: int, category: bytes,
                 message: bytes) -> None:
        """The logger given to fmpy's ``instantiate_fmu`` (one call per message)."""
        self.entries.append((int(status), _text(category), _text(message)))

    def fmi3_callback(self, instance_environment: Any, status: int, category: bytes, message: bytes) -> None:
        """The ``fmi3LogMessageCallback`` of one FMI 3.0 instance (FMI 3.0 2.3.1): no routing
        needed, each instance gets its own."""
        self.entries.append((int(status), _text(category), _text(message)))

    def clear(self) -> None:
        """Forget the messages so far (at the start of a run)."""
        self.entries.clear()

    def warnings(self) -> tuple[str, ...]:
        """The messages logged with status fmi2Warning, each once, in order."""
        seen: dict[str, None] = {}
        for status, _, message in self.entries:
            if status == FMI2_WARNING:
                seen.setdefault(message, None)
        return tuple(seen)

    def last_error(self) -> str | None:
        """The last message logged with status fmi2Error or worse, if any."""
        errors = [message for status, _, message in self.entries if status >= FMI2_ERROR]
        return errors[-1] if errors else None


def _text(value: bytes | str | None) -> str:
    """A C string from the FMU as text (bytes that are not UTF-8 are replaced)."""
    if value is None:
        return ""
    return value.decode("utf-8", "replace") if isinstance(value, bytes) else str(value)


_routes: dict[str, FmuLog] = {}
_lock = threading.Lock()
_callbacks: Any = None


_names = itertools.count(1)


def unique_instance_name(prefix: str) -> str:
    """``prefix`` with a number no other instance of this process has (the routing key)."""
    return f"{prefix}_{next(_names)}"


def _dispatch(component: Any, instance_name: bytes, status: int, category: bytes, message: bytes) -> None:
    """The process's one logger: to the component's FmuLog, else printed like fmpy's default."""
    with _lock:
        log = _routes.get(_text(instance_name))
    if log is not None:
        log.callback(component, instance_name, status, category, message)
        return
    label = ("OK", "WARNING", "DISCARD", "ERROR", "FATAL", "PENDING")
    print(f"[{label[status] if 0 <= status < len(label) else status}] {_text(message)}")


def shared_callbacks() -> Any:
    """The ``fmi2CallbackFunctions`` every instance of this package is given (made once)."""
    global _callbacks
    with _lock:
        if _callbacks is None:
            from fmpy import calloc, free
            from fmpy.fmi2 import (
                fmi2CallbackAllocateMemoryTYPE,
                fmi2CallbackFreeMemoryTYPE,
                fmi2CallbackFunctions,
                fmi2CallbackLoggerTYPE,
            )
            from fmpy.logging import addLoggerProxy

            callbacks = fmi2CallbackFunctions()
            callbacks.logger = fmi2CallbackLoggerTYPE(_dispatch)
            callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
            callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
            addLoggerProxy(byref(callbacks))
            _callbacks = callbacks
    route_fmi2_messages()
    return _callbacks


_dispatcher: list[Any] = []
"""The ctypes logger of :func:`_dispatch`, made once and kept alive for the process."""


def route_fmi2_messages() -> None:
    """Point fmpy's FMI 2.0 logging proxy at this package's dispatcher (again).

    fmpy formats an FMI 2.0 message in one native proxy with a single target for the whole
    process, which every fmpy instantiation with a logger of its own (``simulate_fmu``, a
    container run) points elsewhere. Called before every FMI 2.0 instance and run of this
    package, so that its warnings reach the run's :class:`FmuLog` whatever ran in between.
    """
    from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
    from fmpy.logging import addLoggerProxy

    with _lock:
        if not _dispatcher:
            _dispatcher.append(fmi2CallbackLoggerTYPE(_dispatch))
        target = fmi2CallbackFunctions()
        target.logger = _dispatcher[0]
        addLoggerProxy(byref(target))  # the proxy's target becomes the dispatcher; ``target`` is not kept


def register(instance_name: str, log: FmuLog) -> None:
    """Route the messages of the instance named ``instance_name`` to ``log``."""
    with _lock:
        _routes[instance_name] = log


def unregister(instance_name: str) -> None:
    """Stop routing the messages of the instance named ``instance_name``."""
    with _lock:
        _routes.pop(instance_name, None)
