"""The judge reads any file of any size, fast: this package's own ``simulate``
output, fmuCheck's extra final row, a DataFrame indexed by time, a numpy structured array;
2 million rows in seconds; fixed-step methods recognised at any length; the print resolution
of each cell as the cell-by-cell rule gives it."""

from __future__ import annotations

import csv
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from pendulum_fmu.judge import ReadError, judge
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.explain.fixed_step import identify_fixed_step
from pendulum_fmu.judge.print_format import Format
from pendulum_fmu.judge.reading import read_csv_bytes, read_result

THETA0 = math.radians(75.0)  # the model description's default start angle
C = 9.81  # g / L at the defaults


def cli(*args: str, timeout: float = 300) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", *args], capture_output=True, text=True,
                          timeout=timeout, check=False)


# --- independent references ----------------------------------------------------------------------

def euler_run(h: float, stop: float, parts: int = 1, symplectic: bool = False) -> list[tuple[float, float, float]]:
    """(t, theta, omega) of explicit (or symplectic) Euler with ``parts`` steps of h / parts per
    output, as fmuCheck steps: t_next = t + h, the last step cut to the stop time."""
    t, theta, omega = 0.0, THETA0, 0.0
    rows = [(t, theta, omega)]
    while t < stop:
        t_next = t + h
        if t_next > stop - h / 1e16:
            t_next = stop
        small = (t_next - t) / parts
        for _ in range(parts):
            if symplectic:
                omega = omega - small * C * math.sin(theta)
                theta = theta + small * omega
            else:
                theta, omega = theta + small * omega, omega - small * C * math.sin(theta)
        t = t_next
        rows.append((t, theta, omega))
    return rows


def cell_by_cell_format(cells: list[str]) -> tuple[int | None, int]:
    """(decimals, digits) by the rule on each cell's text: significant digits of the mantissa
    (sign, point and leading zeros not counted), decimals when there is no exponent; fixed
    when every cell has the same d > 0 decimals; digits at least 6."""
    digits, decimals = 0, set()
    for cell in cells:
        text = cell.strip().strip('"').lower()
        mantissa, mark, _ = text.partition("e")
        unsigned = mantissa.lstrip("+-")
        significant = unsigned.replace(".", "").lstrip("0")
        digits = max(digits, len(significant) if significant.isdigit() else 0)
        decimals.add(len(unsigned.split(".", 1)[1]) if "." in unsigned and not mark else -1)
    fixed = decimals.pop() if len(decimals) == 1 else -1
    return (fixed if fixed > 0 else None), max(digits, 6)


# --- the print's resolution ------------------------------------------------------------------------

@pytest.mark.parametrize(("cells", "decimals", "digits", "resolution"), [
    (["0.123457", "-1.500000", "10.000000"], 6, 8, [5e-7, 5e-7, 5e-7]),
    (["1.30899", "-0.0947533", "1e-05", "0"], None, 6, [5e-6, 5e-8, 5e-11, 0.0]),
    (['"1.3089969389957472"', " 0.01"], None, 17, [0.0, 0.0]),
    (["1.2345678901E+00", "-2.5000000000E-03"], None, 11, [5e-11, 5e-14]),
    (["-0.00120", "nan", "inf"], None, 6, [5e-9, 5e-6, 5e-6]),
])
def test_resolution_of_hand_written_cells(cells: list[str], decimals: int | None, digits: int,
                                          resolution: list[float]) -> None:
    form = Format.of(cells)
    assert (form.decimals, form.digits) == (decimals, digits)
    values = np.array([float(c.strip().strip('"')) for c in cells])
    assert form.resolution(values) == pytest.approx(resolution, rel=1e-12, abs=0)


def test_formats_equal_the_cell_by_cell_rule_on_random_prints() -> None:
    rng = np.random.default_rng(26)
    prints = ["%r", "%.17g", "%.16E", "%.6f", "%g", "%.15g", "%.10f", "%.8e", "%.3f", "%.12g"]
    for _ in range(200):
        values = rng.standard_normal(int(rng.integers(1, 40))) * 10.0 ** float(rng.integers(-9, 4))
        values[rng.random(values.size) < 0.1] = 0.0
        style = prints[int(rng.integers(len(prints)))]
        cells = [repr(float(v)) if style == "%r" else style % v for v in values]
        if rng.random() < 0.3:
            cells = [f' "{c}"' for c in cells]
        form = Format.of(cells)
        assert (form.decimals, form.digits) == cell_by_cell_format(cells), (style, cells)


def test_random_dialect_files_read_as_the_line_by_line_reader_reads_them(tmp_path: Path) -> None:
    """Arrow's path (the file itself, or its bytes after comments and blank lines go) against
    read_csv_text, which splits lines with the csv module and parses cells with float()."""
    from pendulum_fmu.judge.reading import read_csv_text

    rng = np.random.default_rng(5)
    prints = ["%r", "%.17g", "%.16E", "%.6f", "%g", "%.10f"]
    for trial in range(40):
        rows = int(rng.integers(2, 80))
        columns = {"time": np.arange(rows) * 0.01, "theta": rng.standard_normal(rows),
                   "omega": rng.standard_normal(rows) * 1e-4}
        styles = {name: prints[int(rng.integers(len(prints)))] for name in columns}
        delimiter = [",", ";", "\t", " ", ", "][trial % 5]
        quote = delimiter != " " and rng.random() < 0.4

        def cell(name: str, value: float, semicolon: bool = delimiter == ";", quoted: bool = quote,
                 styles: dict[str, str] = styles) -> str:
            text = repr(float(value)) if styles[name] == "%r" else styles[name] % value
            text = text.replace(".", ",") if semicolon else text
            return f'"{text}"' if quoted else text

        lines = [delimiter.join(columns)] + [delimiter.join(cell(n, columns[n][k]) for n in columns)
                                             for k in range(rows)]
        if trial % 3 == 0:
            lines.insert(1 + int(rng.integers(rows)), "# a comment")
        if trial % 4 == 0:
            lines.insert(1 + int(rng.integers(rows)), "   ")
        text = "\n".join(lines) + "\n"
        path = tmp_path / f"r{trial}.csv"
        path.write_text(text)
        expected, got = read_csv_text(text, str(path)), read_result(path)
        assert got.columns == expected.columns
        assert np.array_equal(got.time, expected.time)
        for name in ("theta", "omega"):
            assert np.array_equal(got.values[name], expected.values[name]), (trial, styles)
            assert np.array_equal(got.resolution[name], expected.resolution[name]), (trial, styles)
        assert got.formats == expected.formats


def test_a_semicolon_file_with_decimal_commas_keeps_its_resolution() -> None:
    result = read_csv_bytes(b"time;theta\n0;1,500\n0,01;1,250\n", "de.csv")
    assert result.values["theta"].tolist() == [1.5, 1.25]
    assert result.formats is not None and result.formats["theta"] == Format(3, 6)
    assert result.resolution["theta"].tolist() == [5e-4, 5e-4]
    assert result.resolution["time"] == pytest.approx([0.0, 5e-8], rel=1e-12, abs=0)


def test_comments_blank_lines_blanks_and_a_byte_order_mark() -> None:
    text = ("\ufeff# written by hand\n  time   theta   omega\n\n0  1.25  0\n   \n# a note\n"
            "0.5   1.0 -0.5\n")
    result = read_csv_bytes(text.encode(), "blanks.txt")
    assert result.time.tolist() == [0.0, 0.5]
    assert result.values["theta"].tolist() == [1.25, 1.0]
    assert result.values["omega"].tolist() == [0.0, -0.5]


def test_a_bad_cell_is_named_by_its_row_in_a_long_file(tmp_path: Path) -> None:
    rows = [f"{k * 0.01!r},{math.cos(k * 0.01)!r}" for k in range(50_000)]
    rows[41_234] = "412.34,oops"
    (tmp_path / "bad.csv").write_text("time,theta\n" + "\n".join(rows) + "\n")
    with pytest.raises(ReadError, match=r"row 41236, column 'theta': not a number: 'oops'"):
        read_result(tmp_path / "bad.csv")


# --- new dialects ------------------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_simulate_output_is_read_and_passes(tmp_path: Path, fmu_path: Path, suffix: str) -> None:
    out = tmp_path / f"run{suffix}"
    done = cli("simulate", "--periods", "3", "-o", str(out), "--fmu", str(fmu_path))
    assert done.returncode == 0, done.stderr
    result = read_result(out)
    assert result.columns == {"time": "time_s", "theta": "theta_rad", "omega": "omega_rad_s",
                              "theta_exact": "theta_exact_rad", "omega_exact": "omega_exact_rad_s"}
    import pyarrow.parquet as pq

    if suffix == ".csv":
        with out.open() as handle:
            table = {k: np.array([float(row[k]) for row in rows]) for rows in [list(csv.DictReader(handle))]
                     for k in rows[0]}
    else:
        table = {k: np.asarray(v) for k, v in pq.read_table(out).to_pydict().items()}
    assert np.array_equal(result.time, table["time_s"])
    assert np.array_equal(result.values["omega"], table["omega_rad_s"])
    assert np.array_equal(result.values["theta_exact"], table["theta_exact_rad"])
    # simulate's output step is the period / 50 (0.0448941288895513 s here), not a short decimal:
    # the judge takes the times' own step, with --step or without
    step = float(table["time_s"][1])
    for given in (step, None):
        verdict = judge(out, step=given)
        assert verdict.passed, verdict.line
    done = cli("judge", str(out), "--fmu", str(fmu_path))
    assert done.returncode == 0, done.stdout + done.stderr
    read = next(line for line in done.stdout.splitlines() if line.startswith("read"))
    assert "theta_rad, omega_rad_s, theta_exact_rad, omega_exact_rad_s" in read


def _run_columns(rows: int = 1001) -> dict[str, np.ndarray]:
    from pendulum_fmu import exact

    t = np.arange(rows) * 0.01
    theta, omega = exact(THETA0, 0.0, 1.0, 9.81, t)
    return {"time": t, "theta": theta, "omega": omega}


@pytest.mark.parametrize("index_name", ["time", None, "Time"])
def test_a_dataframe_indexed_by_time(tmp_path: Path, index_name: str | None) -> None:
    pd = pytest.importorskip("pandas", reason="pip install pandas==3.1.1")
    columns = _run_columns()
    frame = pd.DataFrame({"theta": columns["theta"], "omega": columns["omega"]},
                         index=pd.Index(columns["time"], name=index_name))
    frame.to_parquet(tmp_path / "frame.parquet")  # the index goes with it, named or as __index_level_0__
    for data in (frame, tmp_path / "frame.parquet"):
        result = read_result(data)
        assert np.array_equal(result.time, columns["time"])
        assert np.array_equal(result.values["theta"], columns["theta"])
        assert judge(data).passed


def test_a_dataframe_with_the_default_index_and_no_time_is_refused() -> None:
    pd = pytest.importorskip("pandas", reason="pip install pandas==3.1.1")
    with pytest.raises(ReadError, match="no time column"):
        read_result(pd.DataFrame({"theta": [1.0, 1.1], "omega": [0.0, 0.1]}))


def test_a_numpy_structured_array() -> None:
    columns = _run_columns()
    table = np.zeros(columns["time"].size, dtype=[("time", float), ("theta", float), ("omega", float)])
    for name, values in columns.items():
        table[name] = values
    result = read_result(table)
    assert result.source == "structured array"
    assert np.array_equal(result.values["omega"], columns["omega"])
    assert judge(table).passed


# --- fixed-step methods at any length -----------------------------------------------------------

def _write_fmucheck(path: Path, rows: list[tuple[float, float, float]]) -> Path:
    """fmuCheck's CSV: quoted names, every value as %.16E."""
    lines = ['"time","theta","omega"'] + [f"{t:.16E},{a:.16E},{b:.16E}" for t, a, b in rows]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("last", ["short step to the stop time", "repeated"])
def test_fmucheck_euler_with_an_extra_final_row(tmp_path: Path, last: str) -> None:
    rows = euler_run(0.01, 10.0)
    if last == "repeated":
        rows = rows[:-1] + [rows[-2]]  # the 9.99999999999983 row written twice
    else:
        assert rows[-1][0] == 10.0 and 0 < rows[-1][0] - rows[-2][0] < 1e-12  # fmuCheck's summed clock
    verdict = judge(_write_fmucheck(tmp_path / "fmucheck.csv", rows), interface="ME")
    grid = verdict.check("time grid")
    assert grid.status == "pass", grid.line
    assert grid.numbers["step"] == 0.01
    assert not verdict.passed
    assert verdict.check("diagnosis").numbers == {"cause": "fixed step", "method": "explicit Euler", "step": 0.01}
    assert "fixed step" in verdict.line and "explicit Euler" in verdict.line


@pytest.mark.parametrize(("symplectic", "parts", "name"), [(False, 1, "explicit Euler"),
                                                           (True, 2, "symplectic Euler")])
def test_a_fixed_step_method_is_recognised_on_100000_rows(symplectic: bool, parts: int, name: str) -> None:
    rows = np.array(euler_run(0.01, 999.99, parts, symplectic))
    assert rows.shape == (100_001, 3)  # the summed clock ends short of 999.99: a last step of 1e-10 s
    data = {"time": rows[:, 0], "theta": rows[:, 1], "omega": rows[:, 2]}
    began = time.perf_counter()
    verdict = judge(data, interface="ME")
    seconds = time.perf_counter() - began
    print(f"judged 100,000 {name} rows in {seconds:.2f} s")
    assert verdict.check("diagnosis").numbers == {"cause": "fixed step", "method": name, "step": 0.01 / parts}
    assert "fixed step" in verdict.line and name in verdict.line
    experiment, _ = make_experiment(None, "ME", None)
    found = identify_fixed_step(read_result(data), experiment, 0.01, 1.0)
    assert found is not None and found.rows_checked == 100_001 and found.every_step is not None
    assert found.every_step < 1e-9


@pytest.mark.slow
def test_two_million_euler_rows_recognised() -> None:
    """Every row checked on two million rows (its time is printed, and measured by
    ``pendulum-fmu bench judge``; no test asserts a timing)."""
    rows = np.array(euler_run(0.01, 19_999.99))
    data = read_result({"time": rows[:, 0], "theta": rows[:, 1], "omega": rows[:, 2]})
    assert data.rows >= 2_000_000
    experiment, _ = make_experiment(None, "ME", None)
    began = time.perf_counter()
    found = identify_fixed_step(data, experiment, 0.01, 1.0)
    seconds = time.perf_counter() - began
    print(f"explicit Euler recognised on {data.rows:,} rows in {seconds:.2f} s")
    assert found is not None and found.method == "explicit Euler" and found.step == 0.01
    assert found.rows_checked == data.rows


def test_one_changed_row_deep_in_the_file_is_not_a_fixed_step_method() -> None:
    rows = np.array(euler_run(0.01, 999.99))
    rows[77_777, 1] += 1e-6  # past the rerun prefix: only the check of every row sees it
    data = {"time": rows[:, 0], "theta": rows[:, 1], "omega": rows[:, 2]}
    experiment, _ = make_experiment(None, "ME", None)
    assert identify_fixed_step(read_result(data), experiment, 0.01, 1.0) is None


def test_an_honest_run_is_not_a_fixed_step_method(tmp_path: Path, fmu_path: Path) -> None:
    from pendulum_fmu.bench.judge import write_run

    result = read_result(write_run(fmu_path, 5_000, tmp_path / "rkn.csv"))
    experiment, _ = make_experiment(None, "ME", None)
    error = float(np.max(np.abs(result.values["theta"] - result.values["theta_exact"])))
    assert error > 0
    assert identify_fixed_step(result, experiment, 0.01, error) is None


# --- size and speed ------------------------------------------------------------------------------

@pytest.mark.slow
def test_two_million_rows_judged(tmp_path: Path, fmu_path: Path) -> None:
    """Two million rows judged whole (the time is printed; ``pendulum-fmu bench judge`` measures
    it; no test asserts a timing)."""
    from pendulum_fmu.bench.judge import write_run

    small = write_run(fmu_path, 1_000, tmp_path / "small.csv")
    began = time.perf_counter()
    assert judge(small).passed
    small_seconds = time.perf_counter() - began
    big = write_run(fmu_path, 2_000_000, tmp_path / "big.csv")
    began = time.perf_counter()
    verdict = judge(big)
    seconds = time.perf_counter() - began
    print(f"judged 1,000 rows in {small_seconds:.3f} s, 2,000,000 rows (CS) in {seconds:.2f} s")
    assert verdict.passed, verdict.line
    assert verdict.check("read").numbers["rows"] == 2_000_000


@pytest.mark.slow
def test_bench_judge_prints_its_table(fmu_path: Path) -> None:
    done = cli("bench", "judge", "--rows", "1000", "--interface", "CS", "ME", "--fmu", str(fmu_path))
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    # the figures alone: the targets they are held to are the lab's (tests/lab/judge_targets.py)
    assert any(line.startswith("| 1e3 | CS |") and line.endswith("| PASS |") for line in lines), done.stdout
    assert "target" not in done.stdout and "within" not in done.stdout
    assert any(line.startswith("| 1e3 | ME |") and "| PASS |" in line for line in lines), done.stdout
    figures = [line for line in lines if line.startswith("bench_judge rows=1000 interface=CS")]
    assert len(figures) == 1 and "passed=True" in figures[0]
