"""One case as an engine runs it: the experiment file (``{experiment}`` of a command template),
its placeholders, and the result file an engine writes."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.suite.cases import Case

OUTPUTS: tuple[str, ...] = ("theta", "omega", "theta_exact", "omega_exact")
"""The outputs a Pendulum run records."""


class CannotRun(RuntimeError):
    """An engine cannot run this case; the message says why (the engine's own words where it gave some)."""


@dataclass(frozen=True)
class Run:
    """A case to run: the case, the FMU (or SSP) it runs and the CSV the engine must write."""

    case: Case
    fmu: Path
    output: Path

    def placeholders(self, experiment_file: Path) -> dict[str, str]:
        """The values of a command template's placeholders (``{fmu}``, ``{interface}``, ...)."""
        case = self.case
        return {"fmu": str(self.fmu), "interface": case.interface, "start": repr(case.start),
                "stop": repr(case.stop), "interval": repr(case.interval), "tolerance": repr(case.tolerance),
                "output": str(self.output), "experiment": str(experiment_file),
                "start_values": " ".join(f"{name}={value!r}" for name, value in case.start_values.items()),
                "fmi_version": case.fmi, "case": case.name,
                "interface_type": "ModelExchange" if case.interface == "me" else "CoSimulation",
                "start_value_pairs": " ".join(f"{name} {value!r}" for name, value in case.start_values.items())}

    def as_json(self) -> dict[str, object]:
        """What ``experiment.json`` holds: every placeholder's value, start values as a mapping."""
        case = self.case
        return {"case": case.name, "fmi_version": case.fmi, "kind": case.kind, "fmu": str(self.fmu),
                "interface": case.interface, "start": case.start, "stop": case.stop, "interval": case.interval,
                "tolerance": case.tolerance, "start_values": dict(case.start_values), "output": str(self.output)}

    def write(self, path: Path) -> Path:
        """Write ``experiment.json`` at ``path``; return it."""
        path.write_text(json.dumps(self.as_json(), indent=1) + "\n")
        return path


def write_csv(path: Path, times: list[float], columns: dict[str, list[float]]) -> None:
    """A plain CSV: ``time`` and the columns, every value as ``repr`` (round-trips)."""
    with path.open("w") as file:
        file.write(",".join(["time", *columns]) + "\n")
        for k, t in enumerate(times):
            file.write(",".join([repr(float(t)), *(repr(float(c[k])) for c in columns.values())]) + "\n")
