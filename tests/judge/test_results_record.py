"""A result says what it is: every time series the package writes records its experiment
(``pendulum_fmu.output.experiment_record``), and ``judge`` reads it.

The contract: for every FMI version, interface, solver and format, ``simulate ... -o F`` then
``judge F`` passes, at random start states from a seeded generator (libration up to
179.99 deg, rotation either way, random L and g) and at the fixed ones 179.99 deg from rest
and a rotation. The CSV stays plain for fmpy, pandas and the csv module; the record survives
gzip and Parquet; what the record states is what the run was; a stale or broken record is
named in one line.
"""

from __future__ import annotations

import csv
import gzip
import json
import math
import random
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest

from pendulum_fmu.cli.main import main
from pendulum_fmu.judge import judge
from pendulum_fmu.output.experiment_record import (
    FORMAT,
    PARQUET_KEY,
    ExperimentRecord,
    read_record,
    read_runs,
    sidecar_of,
    write_series,
)
from pendulum_fmu.spec import CS_SOLVERS

FORMATS = (".csv", ".parquet", ".csv.gz")
SOLVERS = (*CS_SOLVERS, "cvode")
SEED = 37_0001


def random_state(rng: random.Random) -> list[str]:
    """simulate's options for a random start state: libration to 179.99 deg or rotation either
    way, L and g over two decades."""
    length, gravity = 10.0 ** rng.uniform(-0.5, 0.5), 10.0 ** rng.uniform(0.0, 1.5)
    w0 = math.sqrt(gravity / length)
    if rng.random() < 0.6:
        amplitude, omega = rng.uniform(-179.99, 179.99), rng.uniform(-0.3, 0.3) * w0
    else:
        amplitude, omega = rng.uniform(-180.0, 180.0), rng.choice((-1, 1)) * rng.uniform(2.1, 4.0) * w0
    return ["-a", repr(amplitude), "-w", repr(omega), "-L", repr(length), "-g", repr(gravity)]


FIXED_STATES = {"179.99 deg from rest": ["-a", "179.99"], "rotation": ["-a", "30", "-w", "-8.5"]}


def _cases() -> list[tuple[int, str, str, str, list[str]]]:
    rng = random.Random(SEED)
    cases = []
    for version in (2, 3):
        for solver in SOLVERS:
            for suffix in FORMATS:
                cases.append((version, solver, suffix, "random", random_state(rng)))
            for name, state in FIXED_STATES.items():
                cases.append((version, solver, ".csv", name, state))
    return cases


CASES = _cases()


@pytest.mark.parametrize(("version", "solver", "suffix", "kind", "state"), CASES,
                         ids=[f"fmi{v}-{s}-{f.lstrip('.')}-{k}" for v, s, f, k, _ in CASES])
def test_simulate_then_judge_passes(tmp_path: Path, fmu_path: Path, fmu3_path: Path,
                                    capsys: pytest.CaptureFixture[str], version: int, solver: str, suffix: str,
                                    kind: str, state: list[str]) -> None:
    out = tmp_path / f"run{suffix}"
    fmu = fmu_path if version == 2 else fmu3_path
    assert main(["simulate", "-s", solver, "-p", "3", *state, "-o", str(out), "--fmu", str(fmu)]) == 0
    capsys.readouterr()
    code = main(["judge", str(out), "--fmu", str(fmu)])
    printed = capsys.readouterr().out
    assert code == 0, printed
    lines = {line[:16].strip(): line[16:] for line in printed.splitlines()}
    source = out.name + " (Parquet metadata)" if suffix == ".parquet" else out.name + ".experiment.json"
    assert source in lines["experiment file"], lines["experiment file"]
    assert f"from {Path(source).name}" in lines["experiment"] if suffix != ".parquet" else \
        f"from {out.name} (Parquet metadata)" in lines["experiment"], lines["experiment"]
    assert f"FMI {version}.0" in lines["experiment file"] and f"{'ME' if solver == 'cvode' else 'CS'}, " in \
        lines["experiment"]
    assert lines["verdict"].startswith("PASS")


def test_the_record_is_the_run(tmp_path: Path, fmu_path: Path, fmu3_path: Path,
                               capsys: pytest.CaptureFixture[str]) -> None:
    """Every field against what was asked and the file's own rows; the FMU's identity its
    model description's."""
    from fmpy import read_model_description

    out = tmp_path / "run.csv"
    assert main(["simulate", "-a", "100", "-w", "0.25", "-L", "2", "-g", "3.5", "-s", "rk4",
                 "-t", "1e-7", "-p", "2", "-n", "40", "-o", str(out), "--fmu", str(fmu3_path)]) == 0
    capsys.readouterr()
    found = read_record(out)
    assert found is not None and found.source == str(sidecar_of(out))
    r = found.record
    with out.open() as handle:
        rows = list(csv.DictReader(handle))
    times = np.array([float(row["time_s"]) for row in rows])
    token = read_model_description(str(fmu3_path)).instantiationToken
    assert (r.theta0, r.omega0, r.length, r.gravity) == (math.radians(100.0), 0.25, 2.0, 3.5)
    assert (r.interface, r.solver, r.tolerance, r.tolerance_asked, r.fmi_version) == ("CS", "rk4", 1e-7, None, "3.0")
    assert (r.start_time, r.stop_time) == (times[0], times[-1])
    assert r.step is not None and np.allclose(np.diff(times)[:-1], r.step, rtol=1e-12, atol=0)
    assert r.fmu == f"Pendulum.fmu (Pendulum, {token})" and r.writer.endswith(" simulate")


def test_the_csv_stays_plain_for_fmpy_pandas_and_csv(tmp_path: Path) -> None:
    """The numbers alone in the CSV: one header line, then rows, read as they are."""
    import pandas as pd
    from fmpy.util import read_csv

    out = write_series({"time": np.array([0.0, 0.5, 1.0]), "theta": np.array([1.0, 0.9, 0.7])}, tmp_path / "r.csv",
                       _record())
    assert out.read_text().splitlines()[0] == '"time","theta"'
    assert pd.read_csv(out)["theta"].tolist() == [1.0, 0.9, 0.7]
    assert read_csv(str(out))["theta"].tolist() == [1.0, 0.9, 0.7]
    document = json.loads(sidecar_of(out).read_text())
    assert document["format"] == FORMAT and document["file"] == "r.csv"
    assert ExperimentRecord.from_json(document["experiment"]) == _record()


def test_gzip_and_parquet_carry_it(tmp_path: Path) -> None:
    columns = {"time": np.array([0.0, 0.5, 1.0]), "theta": np.array([1.0, 0.9, 0.7])}
    gz = write_series(columns, tmp_path / "r.csv.gz", _record())
    assert gzip.decompress(gz.read_bytes()).decode().splitlines()[0] == '"time","theta"'
    assert sidecar_of(gz).is_file()
    parquet = write_series(columns, tmp_path / "r.parquet", _record(), metadata={"note": "kept"})
    metadata = pq.read_schema(parquet).metadata
    assert metadata[b"note"] == b"kept" and PARQUET_KEY.encode() in metadata
    assert not sidecar_of(parquet).exists()
    for path in (gz, parquet):
        found = read_record(path)
        assert found is not None and found.record == _record()


def test_a_parquet_file_from_before_records_is_read_by_its_flat_keys(tmp_path: Path, fmu_path: Path,
                                                                      capsys: pytest.CaptureFixture[str]) -> None:
    """simulate's Parquet files carried amplitude_rad, solver, tolerance, ... before records:
    the judge reads those too (the file as simulate wrote it, the JSON key removed)."""
    out = tmp_path / "b.parquet"
    assert main(["simulate", "-a", "85", "-s", "cvode", "-o", str(out), "--fmu", str(fmu_path)]) == 0
    capsys.readouterr()
    table = pq.read_table(out)
    earlier = {k: v for k, v in table.schema.metadata.items() if k != PARQUET_KEY.encode()}
    pq.write_table(table.replace_schema_metadata(earlier), out)
    found = read_record(out)
    assert found is not None and "amplitude_rad" in found.source
    assert (found.record.theta0, found.record.interface, found.record.solver) == (math.radians(85.0), "ME", "cvode")
    verdict = judge(out, fmu=fmu_path)
    assert verdict.passed and verdict.experiment.interface == "ME", verdict.line


def test_a_file_of_several_runs_records_each(tmp_path: Path) -> None:
    out = tmp_path / "runs.csv"
    one, two = _record(), _record(theta0=0.5)
    write_series({"run": ["a", "b"], "time": [0.0, 0.0]}, out, [({"run": "a"}, one), ({"run": "b"}, two)],
                 kinds={"run": "str", "time": "float"})
    found = read_runs(out)
    assert found is not None and found[0] == [({"run": "a"}, one), ({"run": "b"}, two)]
    assert read_record(out) is None  # no single experiment: judge falls back to the FMU's


def test_a_record_that_cannot_be_read_is_one_line(tmp_path: Path, fmu_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    out = write_series({"time": np.array([0.0, 0.5, 1.0]), "theta": np.array([1.0, 0.9, 0.7])}, tmp_path / "r.csv",
                       _record())
    sidecar_of(out).write_text('{"format": "pendulum-fmu experiment record 1", "file": "r.csv", '
                               '"experiment": {"theta0": "x"}}')
    with pytest.raises(SystemExit) as exit_code:
        main(["judge", str(out), "--fmu", str(fmu_path)])
    captured = capsys.readouterr()
    assert exit_code.value.code == 2
    assert captured.err.count("\n") == 1, captured.err
    assert "argument RESULT: its experiment record is unreadable" in captured.err, captured.err  # the field result
    assert "Traceback" not in captured.err
    sidecar_of(out).write_text(json.dumps({"format": FORMAT, "file": "other.csv", "experiment": _record().to_json()}))
    with pytest.raises(SystemExit) as exit_code:
        main(["judge", str(out), "--fmu", str(fmu_path)])
    assert exit_code.value.code == 2 and "describes 'other.csv', not 'r.csv'" in capsys.readouterr().err


def test_start_overrides_the_record(tmp_path: Path, fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """``--start`` beats the record, and the experiment line says which value came from where."""
    out = tmp_path / "run.csv"
    assert main(["simulate", "-a", "120", "-p", "2", "-o", str(out), "--fmu", str(fmu_path)]) == 0
    capsys.readouterr()
    verdict = judge(out, start={"theta": math.radians(121)}, fmu=fmu_path)
    stated = verdict.experiment_file
    assert stated is not None and stated.source == str(sidecar_of(out))
    assert not verdict.passed and "theta = " in verdict.line
    line = verdict.check("experiment").line
    assert "given: theta; from run.csv.experiment.json: " in line and "omega" in line and "tolerance" in line


def test_a_tolerance_below_the_floor_is_recorded_as_used(tmp_path: Path, fmu_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    """``simulate -t 1e-16`` runs at the FMU's floor, with its warning; the record states both
    tolerances and the judge certifies the run at the floor."""
    out = tmp_path / "floor.csv"
    assert main(["simulate", "-t", "1e-16", "-a", "100", "-p", "2", "-o", str(out), "--fmu", str(fmu_path)]) == 0
    printed = capsys.readouterr().out
    assert "tolerance 1e-16 is below 1e-14" in printed and "the run uses tolerance 1e-14" in printed
    found = read_record(out)
    assert found is not None and (found.record.tolerance, found.record.tolerance_asked) == (1e-14, 1e-16)
    verdict = judge(out, fmu=fmu_path)
    assert verdict.passed and "tol = 1e-14" in verdict.check("bound").line, verdict.line


def _record(**changes: object) -> ExperimentRecord:
    fields = {"theta0": 1.2, "omega0": 0.0, "length": 1.0, "gravity": 9.81, "interface": "CS", "solver": "rkn",
              "tolerance": 1e-8, "start_time": 0.0, "stop_time": 1.0, "step": 0.5, "fmi_version": "2.0",
              "fmu": "Pendulum.fmu (Pendulum, {x})", "writer": "test"}
    fields.update(changes)
    return ExperimentRecord(**fields)  # type: ignore[arg-type]


def test_the_records_floor_is_the_fmus() -> None:
    """The record's tolerance floor is the C instance's (fmu_src/solvers/integrator.h)."""
    import re

    from pendulum_fmu.output.experiment_record import TOLERANCE_FLOOR

    header = (Path(__file__).resolve().parents[2] / "fmu_src" / "solvers" / "integrator.h").read_text()
    match = re.search(r"#define INTEGRATOR_TOLERANCE_FLOOR (\S+)", header)
    assert match is not None and float(match.group(1)) == TOLERANCE_FLOOR
