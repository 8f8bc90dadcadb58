"""The FMU's log messages, kept per run: warnings for the user, errors for the failure's reason.

An FMU reports through the ``fmi2CallbackLogger`` it was given at ``fmi2Instantiate``
(FMI 2.0.x, section 2.1.5): status, category and message. fmpy formats the variadic message
and hands it to a Python function; :class:`FmuLog` is that function's home.
"""

from __future__ import annotations

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
