"""``bench``: every benchmark a subcommand with its options, defaults and examples; ``bench sweep`` reports runs/s."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from pendulum_fmu.cli import bench
from pendulum_fmu.cli.bench.exact import GSL_ABSENT, both
from pendulum_fmu.cli.main import main


@pytest.mark.parametrize("name", ["accuracy", "exact", "fmi-versions", "solvers", "speed", "sweep"])
def test_bench_help_has_defaults_and_examples_and_no_rst(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["bench", name, "--help"])
    assert stop.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith(f"usage: pendulum-fmu bench {name}")
    assert "(default" in out and "examples:" in out and "``" not in out


@pytest.fixture(scope="module")
def bench_exact(fmu_path: Path) -> Path:
    """The test program ``tests/c/bench_exact`` of the FMU's CMake build (the command never looks for it)."""
    program = fmu_path.parent / "tests" / "c" / "bench_exact"
    assert program.is_file(), f"{program} is not built"
    return program


def test_bench_exact_times_the_library_against_scipy(bench_exact: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "exact", "-n", "20000", "--amplitudes", "80", "--exe", str(bench_exact)]) == 0
    line = re.search(r"^bench_exact amplitude_deg=80 n=20000 c_ns_per_point=(\S+) python_ns_per_point=(\S+) "
                     r"scipy_ns_per_point=(\S+)$", capsys.readouterr().out, re.MULTILINE)
    assert line is not None
    python_ns, scipy_ns = float(line.group(2)), float(line.group(3))
    assert 0 < python_ns < 1e4 and 0 < scipy_ns < 1e4


def test_bench_exact_prints_batch_gsl_and_new_states_side_by_side(bench_exact: Path,
                                                                  capsys: pytest.CaptureFixture[str]) -> None:
    """With the C benchmark of the build: eval, batch, GSL and new state + eval, each as best and median,
    beside the Python and scipy figures for one state and for a state per point."""
    argv = ["bench", "exact", "-n", "20000", "--amplitudes", "90", "--rounds", "2", "--exe", str(bench_exact)]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "GSL/eval" in out and "eval/batch" in out and "scipy/(init+eval)" in out
    line = re.search(r"^bench_exact_all amplitude_deg=90 n=20000 (.*)$", out, re.MULTILINE)
    assert line is not None
    values = dict(field.split("=") for field in line.group(1).split())
    assert "a new state per point" in out and "> 1: the denominator is faster" in out
    for kind in ("eval", "batch", "init_eval", "init_eval_batch", "python", "scipy", "python_states", "scipy_states"):
        best, median = float(values[f"{kind}_best"]), float(values[f"{kind}_median"])
        assert 0 < best <= median < 1e5, kind
    # the lock-step batch is the faster path, and a new state costs more than an evaluation
    assert float(values["batch_best"]) < float(values["eval_best"]) < float(values["init_eval_best"])
    if math.isnan(float(values["gsl_best"])):  # bench_exact configured without GSL: the command says so
        assert GSL_ABSENT in out and "nan" not in out.split("bench_exact ")[0]
        pytest.skip("GSL column not timed: apt-get install libgsl-dev, then cmake -S . -B build "
                    "and rebuild bench_exact")
    assert 0 < float(values["gsl_best"]) <= float(values["gsl_median"]) < 1e5
    # GSL's new state (K and one elljac) beside the port's, in the table of a new state per point
    assert 0 < float(values["gsl_init_eval_best"]) <= float(values["gsl_init_eval_median"]) < 1e5
    table = out.split("a new state per point: set-up and one evaluation", 1)[1]
    row = re.search(r"^\s+90 deg" + r"\s+(\S+)" * 8 + "$", table, re.MULTILINE)
    assert row is not None, table
    assert float(row.group(1)) == pytest.approx(float(values["init_eval_median"]), abs=0.06)
    assert float(row.group(2)) == pytest.approx(float(values["init_eval_batch_median"]), abs=0.06)
    assert float(row.group(3)) == pytest.approx(float(values["gsl_init_eval_median"]), abs=0.06)
    ratio = float(values["gsl_init_eval_median"]) / float(values["init_eval_median"])
    assert float(row.group(6)) == pytest.approx(ratio, abs=0.006)
    ratio = float(values["gsl_init_eval_median"]) / float(values["init_eval_batch_median"])
    assert float(row.group(7)) == pytest.approx(ratio, abs=0.006)
    assert GSL_ABSENT not in out


def test_bench_exact_without_exe_looks_for_no_program(capsys: pytest.CaptureFixture[str]) -> None:
    """Not even in a checkout whose build/ holds tests/c/bench_exact: the C columns are left out, in one line."""
    assert main(["bench", "exact", "-n", "1000", "--amplitudes", "80", "--rounds", "1"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == ("bench exact: the C benchmark (tests/c/bench_exact) is not installed with the "
                                   "package: timing Python and scipy only (the C columns: bash scripts/bench.sh exact "
                                   "in a source checkout)")
    assert "C ns/pt" not in out and "c_ns_per_point" not in out and "eval_best" not in out


def test_bench_solvers_without_driver_looks_for_no_program(fmu_path: Path, tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]) -> None:
    """Not even in a checkout whose build/ holds tests/c/bench_solvers: one line naming the script, exit 2."""
    from pendulum_fmu.cli.bench.solvers import NO_DRIVER

    assert main(["bench", "solvers", "--quick", "--fmu", str(fmu_path), "--out", str(tmp_path / "bench")]) == 2
    err = capsys.readouterr().err
    assert err.splitlines() == [f"pendulum-fmu bench solvers: error: {NO_DRIVER}"]
    assert "bash scripts/bench.sh solvers" in err and not (tmp_path / "bench" / "report.md").exists()


@pytest.mark.parametrize(("peers", "named"), [("Radau,BDF", "BDF"), ("dop853,", None), (",", "none given"),
                                              ("radau", "radau")])
def test_bench_solvers_names_an_unknown_peer_in_one_line(fmu_path: Path, tmp_path: Path, peers: str,
                                                        named: str | None, capsys: pytest.CaptureFixture[str]) -> None:
    """``--peers`` takes the peers' own names (case matters: scipy's Radau, Hairer's dop853):
    an unknown one or none is one line naming it and the choices, exit 2, before any run."""
    from pendulum_fmu.bench.workprecision.peers import PEERS

    driver = tmp_path / "driver"
    driver.write_text("#!/bin/sh\nexit 1\n")
    driver.chmod(0o755)
    code = main(["bench", "solvers", "--quick", "--fmu", str(fmu_path), "--driver", str(driver), "--peers", peers,
                 "--out", str(tmp_path / "bench")])
    err = capsys.readouterr().err
    if named is None:   # a trailing comma is no peer more: the run starts, and a driver that lists no run fails it
        assert code == 1 and "argument --peers" not in err and "printed no run (exit 1)" in err, err
        return
    assert code == 2 and len(err.splitlines()) == 1, err
    assert err.startswith("pendulum-fmu bench solvers: error: argument --peers:") and f"({named})" in err, err
    assert err.rstrip().endswith(", ".join(PEERS)) and not (tmp_path / "bench").exists(), err


def test_an_untimed_column_is_a_dash_not_nan() -> None:
    assert both(float("nan"), float("nan"), 1.0, 1.0) == "-"
    assert both(3.0, 4.0, 1.5, 2.0) == "  2.00 | 2.00  "


def test_bench_lists_the_benchmarks_available(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["bench", "--help"])
    out = capsys.readouterr().out
    assert "sweep" in out
    for module in bench.PARSED:
        assert module.NAME in out


@pytest.mark.slow
def test_bench_sweep_prints_runs_per_second(fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "sweep", "--runs", "24", "--periods", "2", "--workers", "1", "--repeat", "1",
                 "--fmu", str(fmu_path)]) == 0
    out = capsys.readouterr().out
    for loop in ("c", "python"):   # the workers' output loop in C and, for comparison, in Python
        match = re.search(rf"^bench_sweep loop={loop} workers=1 runs=24 rate=([0-9.]+) per_worker=([0-9.]+) ", out,
                          re.MULTILINE)
        assert match is not None, out
        assert float(match.group(1)) > 0 and float(match.group(2)) == pytest.approx(float(match.group(1)), rel=1e-3)
    assert re.search(r"^C loop / Python loop, 1 worker\(s\): [0-9.]+x runs per second per worker$", out, re.MULTILINE)


def test_bench_accuracy_prints_every_regime_within_5e_14(fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "accuracy", "--points", "21", "--fmu", str(fmu_path)]) == 0
    rows = [line.split("|")[1:-1] for line in capsys.readouterr().out.splitlines() if line.startswith("| ")]
    header, *cases = rows
    assert len(cases) == 12 and "separatrix, backward" in [c[0].strip() for c in cases]
    for case, theta_error, omega_error, _naive in cases:
        assert float(theta_error) <= 5e-14 and float(omega_error) <= 5e-14, case
    assert float(cases[-1][3]) > 1e-12  # the naive scipy evaluation after 1e6 periods is far worse


@pytest.mark.slow
def test_bench_speed_prints_the_package_beside_its_peers(fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Every row at the same error target; the package's rows (C loop, the Python loop before it,
    the C loop alone with 2, 4 and 6 outputs) and the peers' in machine-readable lines."""
    assert main(["bench", "speed", "--repeat", "2", "--fmu", str(fmu_path)]) == 0
    out = capsys.readouterr().out
    assert re.search(r"C loop \S*libpendulum_driver\.so$", out.splitlines()[0])
    rows = {m.group(1): (float(m.group(2)), float(m.group(3)), float(m.group(4))) for m in re.finditer(
        r"^bench_speed method='([^']+)' best_ms=(\S+) median_ms=(\S+) error=(\S+)$", out, re.MULTILINE)}
    expected = {"package, C loop (FmuRunner)", "package, Python loop (before)", "package C loop, theta and omega",
                "package C loop, + theta_exact, omega_exact", "package C loop, all 6 outputs",
                "fmpy FMU2Slave wrappers", "fmpy simulate_fmu", "fmpy simulate_fmu, tuned",
                "scipy ode dop853 (compiled)", "scipy solve_ivp DOP853"}
    assert expected <= set(rows), out
    for name, (best, median, error) in rows.items():
        assert 0 < best <= median and error <= 1e-9, name


def test_bench_fmi_versions_prints_both_tables(fmu_path: Path, fmu3_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "fmi-versions", "--fmi2", str(fmu_path), "--fmi3", str(fmu3_path)]) == 0
    out = capsys.readouterr().out
    seed = re.findall(r"^\| (75|80|85|90) \| (CS|ME) \| (\S+) \| (\S+) \| yes \|$", out, re.MULTILINE)
    assert len(seed) == 8 and all(float(two) == float(three) < 1e-6 for _, _, two, three in seed)
    regimes = re.findall(r"^\| (?:10 deg|90 deg|pi - 1e-6|separatrix [-+] 1e-9|rotation backward) "
                         r"\| (\S+) \| (\S+) \|$",
                         out, re.MULTILINE)
    assert len(regimes) == 6 and all(float(theta) < 1e-14 for theta, _ in regimes)
    cvode = re.findall(r"^FMI (2\.0|3\.0) +(difference q\.|FMU \(exact\)) +(\d+) +(\d+) +(\d+) ", out, re.MULTILINE)
    assert [(v, j) for v, j, *_ in cvode] == [(v, j) for v in ("2.0", "3.0") for j in ("difference q.", "FMU (exact)")]
    assert all(int(steps) > 0 for *_, steps, _, _ in cvode)
