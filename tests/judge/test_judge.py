"""``pendulum-fmu judge`` on fmpy's runs of both FMUs and on the same results edited by hand:
the judge passes what is right and fails, with the right reason, what is not."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.util import write_csv

from pendulum_fmu.judge import ReadError, judge
from pendulum_fmu.judge.reading import read_result
from pendulum_fmu.judge.report import write_plot

OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact"]
THETA0 = math.radians(80.0)


def fmpy_run(fmu: Path, **options: object) -> np.ndarray:
    """10 s at 0.01 s, the four outputs."""
    options.setdefault("stop_time", 10.0)
    options.setdefault("output_interval", 0.01)
    return simulate_fmu(str(fmu), output=OUTPUTS, **options)  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def cs_run(fmu_path: Path) -> np.ndarray:
    return fmpy_run(fmu_path, start_values={"theta": THETA0})


def judge_cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", "judge", *args], capture_output=True, text=True,
                          timeout=120, check=False)


# --- what must pass ----------------------------------------------------------------------------

def test_fmpy_cs_passes_both_fmus(fmu_any: Path, tmp_path: Path) -> None:
    run = fmpy_run(fmu_any, start_values={"theta": THETA0})
    write_csv(tmp_path / "cs.csv", run)
    verdict = judge(tmp_path / "cs.csv", start={"theta": THETA0})
    assert verdict.passed, verdict.line
    assert [c.name for c in verdict.checks if c.status == "pass"] == ["time grid", "exact columns", "isolated values",
                                                                       "bound"]
    # the largest error the judge reports is the file's own theta - theta_exact (the FMU's exact output)
    assert verdict.check("theta error").numbers["largest"] == pytest.approx(
        float(np.max(np.abs(run["theta"] - run["theta_exact"]))), rel=1e-6, abs=1e-15)
    assert verdict.check("exact columns").numbers["largest"]["theta_exact"] <= 1e-15


@pytest.mark.parametrize("tolerance", [1e-6, 1e-8, 1e-10])
def test_fmpy_cvode_passes_at_its_stated_tolerance(fmu_path: Path, tolerance: float) -> None:
    run = fmpy_run(fmu_path, fmi_type="ModelExchange", relative_tolerance=tolerance, start_values={"theta": THETA0})
    verdict = judge(run, start={"theta": THETA0, "tolerance": tolerance}, interface="ME")
    assert verdict.passed, verdict.line
    assert verdict.check("bound").numbers["worst_ratio"] < 1.0
    # a file within the bound needs no cause: CVODE is not rerun for it
    assert "diagnosis" not in [c.name for c in verdict.checks]


# --- what must fail, and why -------------------------------------------------------------------

def test_euler_model_exchange_fails_as_explicit_euler(fmu_any: Path) -> None:
    run = fmpy_run(fmu_any, fmi_type="ModelExchange", solver="Euler", step_size=0.01, start_values={"theta": THETA0})
    verdict = judge(run, start={"theta": THETA0}, interface="ME")
    assert not verdict.passed
    assert verdict.check("bound").status == "fail"
    diagnosis = verdict.check("diagnosis")
    assert diagnosis.numbers == {"cause": "fixed step", "method": "explicit Euler", "step": 0.01}
    assert "explicit Euler at h = 0.01" in verdict.line


def test_cvode_at_1e_4_fails_as_tolerance_not_passed(fmu_path: Path) -> None:
    """What C fmusim does with --solver cvode: rtol 1e-4 whatever the experiment says (1e-8):
    the model description's default, or the tolerance the FMU's FMI-LS-REF experiment states."""
    run = fmpy_run(fmu_path, fmi_type="ModelExchange", relative_tolerance=1e-4, start_values={"theta": THETA0})
    verdict = judge(run, start={"theta": THETA0}, interface="ME", fmu=fmu_path, read_experiment_file=False)
    assert not verdict.passed and verdict.experiment_file is None
    diagnosis = verdict.check("diagnosis")
    assert 10 ** -4.5 < diagnosis.numbers["effective_tolerance"] < 10 ** -3.5
    assert "not the experiment's 1e-08: the importer did not pass the experiment's tolerance" in verdict.line
    stated = judge(run, start={"theta": THETA0}, interface="ME", fmu=fmu_path)
    assert stated.experiment_file is not None and stated.experiment_file.source.endswith("Pendulum.exp")
    assert "not the stated 1e-08: the importer did not pass the experiment's tolerance" in stated.line


@pytest.mark.parametrize("column", ["theta", "theta_exact", "omega"])
def test_one_value_changed_by_1e_6_fails(cs_run: np.ndarray, tmp_path: Path, column: str) -> None:
    edited = cs_run.copy()
    edited[column][437] += 1e-6
    write_csv(tmp_path / "edited.csv", edited)
    verdict = judge(tmp_path / "edited.csv", start={"theta": THETA0})
    assert not verdict.passed
    if column.endswith("_exact"):
        assert verdict.check("exact columns").numbers["rows"] == [438]
    else:
        check = verdict.check("isolated values")
        assert check.status == "fail" and check.numbers["rows"] == [438]
        assert check.numbers["jump"] == pytest.approx(1e-6, rel=1e-3)
    assert "mangled" in verdict.line
    # the untouched file passes: the edit alone made the difference
    assert judge(cs_run, start={"theta": THETA0}).passed


def test_changed_length_fails_and_the_judge_finds_it(fmu_path: Path) -> None:
    run = fmpy_run(fmu_path, start_values={"theta": THETA0, "L": 1.25})
    verdict = judge(run, start={"theta": THETA0})
    assert not verdict.passed
    fit = verdict.check("exact columns").numbers["fit"]
    assert fit["L"] == pytest.approx(1.25, rel=1e-9)
    assert fit["theta0"] == pytest.approx(THETA0, rel=1e-12)
    assert "L = 1.25 (not 1)" in verdict.line
    # without the exact columns, theta and omega themselves give L away
    bare = judge({"time": run["time"], "theta": run["theta"], "omega": run["omega"]}, start={"theta": THETA0})
    assert not bare.passed and "L = 1.25 (not 1)" in bare.line
    # judged with the L the run used, it passes
    assert judge(run, start={"theta": THETA0, "L": 1.25}).passed


def test_drifting_times_fail(cs_run: np.ndarray) -> None:
    """Values computed at k h, written at times that drift from k h: the clock, not the values."""
    drifted = cs_run.copy()
    drifted["time"][1:] += 1e-7 * np.arange(1, drifted.size) ** 2 / drifted.size
    verdict = judge(drifted, start={"theta": THETA0})
    grid = verdict.check("time grid")
    assert grid.status == "fail" and "times drift from k h" in verdict.line
    assert grid.numbers["largest_deviation"] == pytest.approx(1e-4, rel=1e-2)
    assert "the times are written wrong (the clock drifts)" in verdict.check("exact columns").line
    scaled = cs_run.copy()
    scaled["time"] *= 1 + 1e-7  # a clock that runs fast: a uniform grid, the values late in proportion to t
    verdict = judge(scaled, start={"theta": THETA0})
    assert verdict.check("time grid").status == "pass"
    assert "the clock runs 1.0000001 times fast" in verdict.line, verdict.line


def test_a_step_that_is_no_short_decimal_is_taken_from_the_times(fmu_path: Path) -> None:
    """A step that is a period over 50, 0.04489412888955134 s (simulate's grid)."""
    run = fmpy_run(fmu_path, stop_time=20.0, output_interval=0.04489412888955134)
    verdict = judge(run)
    assert verdict.passed, verdict.line
    assert verdict.check("time grid").numbers["step"] == pytest.approx(0.04489412888955134, rel=1e-12)


def test_summed_times_pass_with_their_drift_reported(cs_run: np.ndarray) -> None:
    """Ecos's clock: t += h, 1000 times (9.999999999999831 at the end), within rounding."""
    from pendulum_fmu import exact

    summed = cs_run.copy()
    summed["time"] = np.concatenate(([0.0], np.cumsum(np.full(summed.size - 1, 0.01))))
    assert summed["time"][-1] == 9.999999999999831
    summed["theta_exact"], summed["omega_exact"] = exact(THETA0, 0.0, 1.0, 9.81, summed["time"])
    verdict = judge(summed, start={"theta": THETA0})
    assert verdict.passed, verdict.line
    assert 1e-14 < abs(verdict.check("time grid").numbers["largest_deviation"]) < 1e-12


def test_non_monotone_times_fail(cs_run: np.ndarray) -> None:
    swapped = cs_run.copy()
    swapped["time"][[10, 11]] = swapped["time"][[11, 10]]
    check = judge(swapped, start={"theta": THETA0}).check("time grid")
    assert check.status == "fail" and "not monotone" in check.line and check.numbers["first_backstep_row"] == 12


def test_a_print_too_coarse_for_the_bound_fails_as_such(cs_run: np.ndarray, tmp_path: Path) -> None:
    """Six significant digits (C's %g) cannot show 1e-6: the judge says so."""
    lines = ["time,theta,omega"] + [f"{t:g},{a:g},{b:g}" for t, a, b in zip(cs_run["time"], cs_run["theta"],
                                                                          cs_run["omega"], strict=True)]
    (tmp_path / "g.csv").write_text("\n".join(lines) + "\n")
    verdict = judge(tmp_path / "g.csv", start={"theta": THETA0})
    assert not verdict.passed
    assert verdict.check("diagnosis").numbers["cause"] == "print precision"


# --- reading ---------------------------------------------------------------------------------

def _table(run: np.ndarray, names: list[str], quote: bool, delimiter: str = ",") -> str:
    header = delimiter.join(f'"{n}"' if quote else n for n in names)
    rows = [delimiter.join(repr(float(run[c][k])) for c in ["time", *OUTPUTS]) for k in range(run.size)]
    return "\n".join([header, *rows]) + "\n"


@pytest.mark.parametrize(("names", "quote", "delimiter"), [
    (["time", "theta", "omega", "theta_exact", "omega_exact"], True, ","),
    (["time", "theta", "omega", "theta_exact", "omega_exact"], False, ","),
    (["Time", "pend.theta", "pend.omega", "pend.theta_exact", "pend.omega_exact"], False, ","),
    (["time", "pend::theta", "pend::omega", "pend::theta_exact", "pend::omega_exact"], False, ", "),
    (["Time", "theta [3 REAL OUTPUT]", "omega [5 REAL OUTPUT]", "theta_exact [7 REAL OUTPUT]",
      "omega_exact [8 REAL OUTPUT]"], False, ","),
    (["time", "theta", "omega", "theta_exact", "omega_exact"], True, ";"),
    (["t", "theta", "omega", "theta_exact", "omega_exact"], False, "\t"),
])
def test_the_usual_csv_dialects_read_alike(cs_run: np.ndarray, tmp_path: Path, names: list[str], quote: bool,
                                           delimiter: str) -> None:
    (tmp_path / "r.csv").write_text(_table(cs_run, names, quote, delimiter))
    result = read_result(tmp_path / "r.csv")
    assert set(result.values) == set(OUTPUTS)
    for name in OUTPUTS:
        assert np.array_equal(result.values[name], cs_run[name])
    assert judge(tmp_path / "r.csv", start={"theta": THETA0}).passed


def test_parquet_and_dataframe(cs_run: np.ndarray, tmp_path: Path) -> None:
    import pandas as pd
    import pyarrow as pa
    import pyarrow.parquet as pq

    frame = pd.DataFrame({name: cs_run[name] for name in ["time", *OUTPUTS]})
    pq.write_table(pa.Table.from_pandas(frame), tmp_path / "r.parquet")
    for data in (frame, tmp_path / "r.parquet"):
        verdict = judge(data, start={"theta": THETA0})
        assert verdict.passed, verdict.line


def test_any_subset_of_columns(cs_run: np.ndarray) -> None:
    only_exact = judge({"time": cs_run["time"], "theta_exact": cs_run["theta_exact"]}, start={"theta": THETA0})
    # the FMU's exact outputs alone say nothing of the importer's numbers: nothing to pass
    assert not only_exact.passed and only_exact.check("bound").status == "info"
    assert "no theta or omega column" in only_exact.line
    only_omega = judge({"time": cs_run["time"], "omega": cs_run["omega"]}, start={"theta": THETA0})
    assert only_omega.passed and only_omega.check("bound").numbers["variable"] == "omega"


@pytest.mark.parametrize(("text", "message"), [
    ("", "empty"),
    ("time,theta\n", "a header and no rows"),
    ("a,b\n1,2\n", "no time column"),
    ("time,x\n0,1\n", "none of theta"),
    ("time,theta\n0,1\n0.01,oops\n", "row 3, column 'theta': not a number"),
    ("time,theta,omega\n0,1\n", "row 2 has 2 fields"),
    ("time,theta\n0,1\n", "1 row: a result needs at least two"),
    ("time,a.theta,b.theta\n0,1,1\n0.1,1,1\n", "several instances"),
])
def test_unreadable_input_is_one_line_and_exit_2(tmp_path: Path, text: str, message: str) -> None:
    (tmp_path / "bad.csv").write_text(text)
    with pytest.raises(ReadError, match=message):
        judge(tmp_path / "bad.csv")
    done = judge_cli(str(tmp_path / "bad.csv"))
    assert done.returncode == 2
    assert done.stdout == "" and len(done.stderr.strip().splitlines()) == 1 and message in done.stderr


def test_semicolons_with_decimal_commas(cs_run: np.ndarray, tmp_path: Path) -> None:
    rows = [";".join(repr(float(cs_run[c][k])).replace(".", ",") for c in ["time", "theta"])
            for k in range(cs_run.size)]
    (tmp_path / "de.csv").write_text("\n".join(["time;theta", *rows]) + "\n")
    result = read_result(tmp_path / "de.csv")
    assert np.array_equal(result.values["theta"], cs_run["theta"])


def test_nan_values_fail_and_nan_times_fail(cs_run: np.ndarray) -> None:
    broken = cs_run.copy()
    broken["theta"][3] = np.nan
    verdict = judge(broken, start={"theta": THETA0})
    assert not verdict.passed and verdict.check("theta error").status == "fail"
    broken = cs_run.copy()
    broken["time"][0] = np.nan
    assert judge(broken, start={"theta": THETA0}).check("time grid").status == "fail"


def test_binary_and_missing_files_exit_2(tmp_path: Path) -> None:
    (tmp_path / "x.bin").write_bytes(b"\xff\xfe\x00\x81garbage")
    for path in (tmp_path / "x.bin", tmp_path / "missing.csv"):
        done = judge_cli(str(path))
        assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1 and "Traceback" not in done.stderr


# --- the command line ---------------------------------------------------------------------------

@pytest.mark.slow
def test_cli_exit_codes_json_and_plot(cs_run: np.ndarray, fmu_path: Path, tmp_path: Path) -> None:
    write_csv(tmp_path / "good.csv", cs_run)
    done = judge_cli(str(tmp_path / "good.csv"), "--start", "theta=80deg", "--json", str(tmp_path / "v.json"),
                     "--plot", str(tmp_path / "v.png"))
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.strip().splitlines()
    assert [line.split()[0] for line in lines] == ["experiment", "read", "experiment", "time", "exact", "theta",
                                                    "omega", "isolated", "bound", "fmpy", "verdict"]
    assert lines[-1].split()[1] == "PASS:"
    report = json.loads((tmp_path / "v.json").read_text())
    assert report["passed"] is True and report["experiment"]["theta0"] == pytest.approx(THETA0)
    assert (tmp_path / "v.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    done = judge_cli(str(tmp_path / "good.csv"))  # judged at the default 75 deg: a different start value
    assert done.returncode == 1 and "theta = 1.396263402 (not 1.308996939)" in done.stdout
    done = judge_cli(str(tmp_path / "good.csv"), "--start", "L=-1")
    assert done.returncode == 2 and "argument --start" in done.stderr


def test_the_plot_draws_the_verdicts_series_without_the_file(cs_run: np.ndarray, tmp_path: Path) -> None:
    """The verdict carries what the plot needs: the file may be gone when it is drawn. Its
    series are the file's own numbers and the exact solution at its times (mpmath-checked
    elsewhere), and the allowed error is the bound of the certificate, 100 tol max(1, |theta_e|)."""
    path = tmp_path / "cs.csv"
    write_csv(str(path), cs_run)
    verdict = judge(path, start={"theta": THETA0}, read_experiment_file=False)
    path.unlink()
    series = verdict.series
    assert series is not None and verdict.passed, verdict.line
    assert np.array_equal(series.time, cs_run["time"]) and np.array_equal(series.values["theta"], cs_run["theta"])
    assert np.array_equal(series.errors["theta"], cs_run["theta"] - series.exact_theta)
    assert np.max(np.abs(series.exact_theta - cs_run["theta_exact"])) < 1e-13
    assert np.allclose(series.allowed_error["theta"], 100 * 1e-8 * np.maximum(1.0, np.abs(series.exact_theta)),
                       rtol=1e-15, atol=0.0)
    assert set(series.exact_column_differences) == {"theta_exact", "omega_exact"}
    write_plot(verdict, tmp_path / "cs.png")
    assert (tmp_path / "cs.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_json_keeps_its_keys(cs_run: np.ndarray) -> None:
    """The verdict's JSON: the experiment flat (the problem's theta0, omega0, L, g first), each
    check's numbers under "figures"; the series are not in it."""
    data = judge(cs_run, start={"theta": THETA0}, read_experiment_file=False).to_dict()
    assert list(data) == ["passed", "verdict", "source", "columns", "instance", "experiment", "checks"]
    assert list(data["experiment"]) == ["theta0", "omega0", "L", "g", "interface", "tolerance", "tolerance_stated",
                                        "solver", "given", "start_time"]
    assert data["experiment"]["theta0"] == THETA0 and data["experiment"]["given"] == ["theta"]
    assert all(list(check) == ["name", "status", "line", "figures"] for check in data["checks"])
    json.dumps(data)  # JSON-ready as it is: no array


@pytest.mark.parametrize(("arguments", "field", "words"), [
    ({"start": {"L": -1.0}}, "start", "L=-1.0: must be finite and > 0"),
    ({"start": {"theta": math.inf}}, "start", "must be finite"),
    ({"start": {"tolerance": "tight"}}, "start", "is not a number"),
    ({"start": {"amplitude": 1.0}}, "start", "unknown name 'amplitude'"),
    ({"start": ["theta=1.4"]}, "start", "a mapping of name to value"),
    ({"interface": "XX"}, "interface", "must be CS or ME"),
])
def test_a_bad_argument_names_its_field(cs_run: np.ndarray, arguments: dict[str, object], field: str,
                                        words: str) -> None:
    """The library names the field (the command line maps it to its flag: the next test)."""
    from pendulum_fmu.errors import UsageError

    with pytest.raises(UsageError) as raised:
        judge(cs_run, read_experiment_file=False, **arguments)  # type: ignore[arg-type]
    assert raised.value.field == field and words in raised.value.message


def test_the_command_parses_start_into_typed_values() -> None:
    """``--start NAME=VALUE`` becomes the judge's typed values in cli/ (degrees to radians, the
    solver a name); a bad pair says so with the text the user typed."""
    from pendulum_fmu.cli.judge import start_values
    from pendulum_fmu.errors import UsageError

    assert start_values(["theta=80deg", " L = 2 ", "solver=rk4", "startTime=5"]) == {
        "theta": math.radians(80.0), "L": 2.0, "solver": "rk4", "startTime": 5.0}
    for pair, words in (("L=-1", "L='-1': must be finite and > 0"), ("g=abc", "g='abc' is not a number"),
                        ("theta", "expected NAME=VALUE, got 'theta'"), ("foo=1", "unknown name 'foo'")):
        with pytest.raises(UsageError) as raised:
            start_values([pair])
        assert raised.value.field == "start" and words in raised.value.message


def test_plot_of_a_failing_run_draws_the_bound(fmu_path: Path, tmp_path: Path) -> None:
    run = fmpy_run(fmu_path, fmi_type="ModelExchange", solver="Euler", step_size=0.01)
    verdict = judge(run, interface="ME")
    write_plot(verdict, tmp_path / "euler.png")
    assert (tmp_path / "euler.png").stat().st_size > 20000


# --- the right reason, first ---------------------------------------------------------------------

def _columns(run: np.ndarray, names: tuple[str, ...] = ("time", *OUTPUTS)) -> dict[str, np.ndarray]:
    return {name: np.array(run[name]) for name in names}


def _lagged(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {**c, "time": c["time"] + 1e-4}


def _one_row_early(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {name: (v[:-1] if name == "time" else v[1:]) for name, v in c.items()}


def _scaled_clock(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {**c, "time": c["time"] * 1.001}


def _start_time_5(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {**c, "time": c["time"] + 5.0}


def _degrees(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {**c, "theta": np.degrees(c["theta"])}


def _rows_missing(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {name: np.delete(v, [100, 500, 501]) for name, v in c.items()}


def _row_twice(c: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    return {name: np.insert(v, 300, v[300]) for name, v in c.items()}


@pytest.mark.parametrize("bare", [False, True], ids=["with exact columns", "theta and omega only"])
@pytest.mark.parametrize(("edit", "reason"), [
    (_lagged, "shifted against their times by +0.0001 s"),
    (_one_row_early, "by one step, h = 0.01 s: the values are written one row early"),
    (_scaled_clock, "the clock runs 1.001 times fast"),
    (_start_time_5, "from startTime = 5 s, not 0 s"),
    (_degrees, "theta is in degrees"),
    (_rows_missing, "3 row(s) missing"),
    (_row_twice, "1 duplicate row(s): t = 3 s"),
])
def test_a_wrong_file_fails_with_its_own_reason(cs_run: np.ndarray, edit: object, reason: str, bare: bool) -> None:
    names = ("time", "theta", "omega") if bare else ("time", *OUTPUTS)
    verdict = judge(edit(_columns(cs_run, names)), start={"theta": THETA0})  # type: ignore[operator]
    assert not verdict.passed
    assert reason in verdict.line, verdict.line


@pytest.mark.parametrize(("start", "named"), [({"g": 9.80665}, "g = 9.80665 (not 9.81)"), ({"L": 2.0}, "L = 2 (not 1)"),
                                              ({"g": 1.62}, "g = 1.62 (not 9.81)")])
def test_a_parameter_not_given_is_named_as_a_person_set_it(fmu_path: Path, start: dict[str, float], named: str) -> None:
    """Only g/L enters the motion: the judge names the one of g and L that reads as set by hand."""
    run = fmpy_run(fmu_path, start_values={"theta": THETA0, **start})
    for names in (("time", *OUTPUTS), ("time", "theta", "omega")):
        verdict = judge(_columns(run, names), start={"theta": THETA0})
        assert not verdict.passed and named in verdict.line, verdict.line


def test_the_fmus_own_solver_at_another_tolerance_fails_as_tolerance_not_passed(fmu_path: Path) -> None:
    run = fmpy_run(fmu_path, relative_tolerance=1e-4, start_values={"theta": THETA0, "solver": 1})
    verdict = judge(run, start={"theta": THETA0, "tolerance": 1e-8, "solver": "1"})
    assert not verdict.passed
    assert "fits the FMU's dopri5 at tolerance ~1e-4, not the stated 1e-08" in verdict.line
    assert "did not pass the experiment's tolerance" in verdict.line


def test_a_mangled_value_in_model_exchange_is_named_as_such(fmu_path: Path) -> None:
    """Not blamed on the tolerance: the isolated value comes first."""
    run = fmpy_run(fmu_path, fmi_type="ModelExchange", relative_tolerance=1e-8, start_values={"theta": THETA0})
    edited = _columns(run)
    edited["theta"][400] += 1e-5
    verdict = judge(edited, start={"theta": THETA0, "tolerance": 1e-8}, interface="ME")
    assert not verdict.passed and "mangled value" in verdict.line and "CVODE" not in verdict.line, verdict.line


def test_a_nan_in_an_exact_column_is_named(cs_run: np.ndarray) -> None:
    broken = _columns(cs_run)
    broken["theta_exact"][7] = np.nan
    verdict = judge(broken, start={"theta": THETA0})
    assert not verdict.passed and "theta_exact is nan at t = 0.07 s (row 8" in verdict.line, verdict.line


def test_an_error_crossing_zero_beside_a_value_is_no_isolated_value(cs_run: np.ndarray) -> None:
    """A smooth error that passes through zero next to a row makes no spike of that row."""
    from pendulum_fmu import exact

    t = np.array(cs_run["time"])
    theta, omega = exact(THETA0, 0.0, 1.0, 9.81, t)
    error = 1e-7 * np.sin(2.0 * t + 0.3)  # an honest-looking error with many sign changes
    error[0] = 0.0
    verdict = judge({"time": t, "theta": theta + error, "omega": omega}, start={"theta": THETA0, "tolerance": 1e-6})
    assert verdict.check("isolated values").status == "pass", verdict.check("isolated values").line
