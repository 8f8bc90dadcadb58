"""The two model descriptions describe one model: the FMI 3.0 one (fmu_src/models/pendulum/FMI3.xml.in)
must agree with modelDescription.xml (FMI 2.0, which the C code's value references are
generated from) on every variable, the Solver items, the model structure and the experiment."""

from __future__ import annotations

from pathlib import Path

import pytest
from fmpy import read_model_description
from fmpy.model_description import ModelDescription

ATTRIBUTES = ("name", "valueReference", "causality", "variability", "initial", "start", "unit",
              "declaredType", "min", "displayUnit")


def _variables(md: ModelDescription) -> dict[str, dict[str, object]]:
    table = {}
    for variable in md.modelVariables:
        if variable.causality == "independent":  # FMI 3.0's `time`; FMI 2.0 has none
            continue
        row: dict[str, object] = {}
        for attribute in ATTRIBUTES:
            value = getattr(variable, attribute, None)
            if attribute == "unit" and value is None and variable.declaredType is not None:
                value = getattr(variable.declaredType, "unit", None)
            if attribute == "declaredType" and value is not None:
                value = value.name
            if attribute == "start" and value is not None:
                value = float(value)
            row[attribute] = value
        derivative = variable.derivative
        row["derivative"] = None if derivative is None else derivative.name
        row["integer"] = variable.type in ("Integer", "Int32", "Enumeration")
        table[variable.name] = row
    return table


def _structure(md: ModelDescription) -> dict[str, list[tuple[str, tuple[str, ...]]]]:
    def rows(unknowns: list) -> list[tuple[str, tuple[str, ...]]]:
        return [(u.variable.name, tuple(sorted(d.name for d in (u.dependencies or [])))) for u in unknowns]
    return {"outputs": rows(md.outputs), "derivatives": rows(md.derivatives),
            "initialUnknowns": rows(md.initialUnknowns)}


@pytest.fixture(scope="module")
def both(fmu_path: Path, fmu3_path: Path) -> tuple[ModelDescription, ModelDescription]:
    return read_model_description(str(fmu_path)), read_model_description(str(fmu3_path))


def test_same_variables(both: tuple[ModelDescription, ModelDescription]) -> None:
    fmi2, fmi3 = both
    assert _variables(fmi3) == _variables(fmi2)


def test_fmi3_time_is_the_independent_variable(both: tuple[ModelDescription, ModelDescription]) -> None:
    independent = [v for v in both[1].modelVariables if v.causality == "independent"]
    assert [(v.name, v.valueReference) for v in independent] == [("time", 0)]
    assert 0 not in {v.valueReference for v in both[0].modelVariables}


def test_same_solver_items(both: tuple[ModelDescription, ModelDescription]) -> None:
    def items(md: ModelDescription) -> list[tuple[str, str]]:
        (solver,) = [t for t in md.typeDefinitions if t.name == "Solver"]
        return [(item.name, str(item.value)) for item in solver.items]
    assert items(both[1]) == items(both[0])


def test_same_model_structure(both: tuple[ModelDescription, ModelDescription]) -> None:
    assert _structure(both[1]) == _structure(both[0])


def test_same_guid_experiment_and_log_categories(both: tuple[ModelDescription, ModelDescription]) -> None:
    fmi2, fmi3 = both
    assert fmi3.instantiationToken == fmi2.guid
    for attribute in ("startTime", "stopTime", "tolerance", "stepSize"):
        assert getattr(fmi3.defaultExperiment, attribute) == getattr(fmi2.defaultExperiment, attribute)
    assert [c.name for c in fmi3.logCategories] == [c.name for c in fmi2.logCategories]
    assert {u.name for u in fmi3.unitDefinitions} == {u.name for u in fmi2.unitDefinitions}


def test_the_default_experiment_is_one_every_importer_accepts(
        both: tuple[ModelDescription, ModelDescription]) -> None:
    """The importers' own rules on a DefaultExperiment, as each computes them in doubles:
    fmusim (fmi-rs) refuses an output interval unless the fractional part of
    (stop - start) / interval is 0; FMI4j refuses a doStep whose t + h passes stopTime unrounded,
    t written as k h; Ecos and fmpy sum the steps (t += h). Each must reach stopTime exactly
    after (stop - start) / h steps, and never pass it before."""
    import math
    for md in both:
        default = md.defaultExperiment
        start, stop, h = float(default.startTime), float(default.stopTime), float(default.stepSize)
        assert 0 < float(default.tolerance) < 1
        ratio = (stop - start) / h
        assert ratio == math.floor(ratio) and ratio >= 1                # fmusim: no fraction at all
        steps = int(ratio)
        summed = start
        for k in range(steps):
            assert start + k * h + h <= stop                            # FMI4j: the last doStep allowed
            assert summed + h <= stop                                   # a summing clock never passes it
            summed += h
        assert summed == stop and start + steps * h == stop             # both clocks land on stopTime
