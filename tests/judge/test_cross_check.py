"""The FMI world's own formats around the judge: the cross-check export (``pendulum-fmu
cross-check``) validated by fmpy's own cross-check validation for both FMI versions; the judge
taking the experiment from a cross-check ``_ref.opt`` and from the FMU's FMI-LS-REF ``.exp``;
the ``passed`` / ``failed`` / ``rejected`` file; and the "fmpy band" check, against fmpy's
``validate_result`` and ``validate_signal``."""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
import time
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.cross_check import validate_result, validate_signal
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu
from fmpy.util import read_ref_opt_file, write_csv

from pendulum_fmu.fmu.library import exact
from pendulum_fmu.judge import judge
from pendulum_fmu.judge.checks import reference
from pendulum_fmu.judge.cross_check_verdict import write_verdict_file
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.experiment_files import cross_check_opt, fmu_experiment, read_experiments
from pendulum_fmu.judge.fmpy_validation import LIMIT, fmpy_validation_check, outside_fraction, outside_fractions
from pendulum_fmu.judge.reading import read_result

EXP = "extra/org.fmi-standard.fmi-ls-ref/Pendulum.exp"
OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact"]


def pendulum_fmu(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", *args], capture_output=True, text=True,
                          timeout=300, check=False, cwd=cwd)


@pytest.fixture(scope="module")
def exported(fmu_path: Path, fmu3_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("xc")
    done = pendulum_fmu("cross-check", str(root), "--fmu", str(fmu_path), "--fmu", str(fmu3_path))
    assert done.returncode == 0, done.stderr
    return root


# --- the export ----------------------------------------------------------------------------------

def test_export_covers_every_version_interface_and_platform(exported: Path, fmu_path: Path,
                                                            fmu3_path: Path) -> None:
    folders = sorted(p.relative_to(exported / "fmus").parts[:3]
                     for p in exported.glob("fmus/*/*/*/PendulumFMU/*/Pendulum"))
    wanted_2 = {n.split("/")[1] for n in zipfile.ZipFile(fmu_path).namelist() if n.startswith("binaries/")
                and n.count("/") == 2 and n.split("/")[2]}
    names_3 = {"x86_64-linux": "linux64", "x86_64-windows": "win64", "x86_64-darwin": "darwin64",
               "aarch64-linux": "aarch64-linux"}
    wanted_3 = {names_3[n.split("/")[1]] for n in zipfile.ZipFile(fmu3_path).namelist()
                if n.startswith("binaries/") and n.count("/") == 2 and n.split("/")[2] and n.split("/")[1] in names_3}
    expected = sorted([("2.0", i, p) for i in ("cs", "me") for p in wanted_2]
                      + [("3.0", i, p) for i in ("cs", "me") for p in wanted_3])
    assert folders == expected and "linux64" in wanted_2 and "linux64" in wanted_3


def test_both_versions_validate_with_fmpy(exported: Path) -> None:
    folders = list(exported.glob("fmus/*/*/*/PendulumFMU/*/Pendulum"))
    assert {f.parts[-6] for f in folders} == {"2.0", "3.0"}
    for folder in folders:
        assert validate_test_fmu(str(folder)) == [], folder
        assert {p.name for p in folder.iterdir()} == {"Pendulum.fmu", "Pendulum_ref.csv", "Pendulum_ref.opt",
                                                      "ReadMe.txt"}
        header = (folder / "Pendulum_ref.csv").read_text().splitlines()[0]
        assert header.split(",")[0] == '"time"' and all(n.startswith('"') for n in header.split(","))


def test_the_options_are_the_default_experiment_and_the_reference_its_exact_solution(exported: Path,
                                                                                     fmu_path: Path) -> None:
    folder = exported / "fmus/2.0/me/linux64/PendulumFMU"
    (model,) = folder.glob("*/Pendulum")
    opts = read_ref_opt_file(str(model / "Pendulum_ref.opt"))
    from fmpy import read_model_description
    default = read_model_description(str(fmu_path)).defaultExperiment
    assert (opts["StartTime"], opts["StopTime"], opts["StepSize"], opts["RelTol"]) == (
        float(default.startTime), float(default.stopTime), float(default.stepSize), float(default.tolerance))
    table = np.genfromtxt(model / "Pendulum_ref.csv", delimiter=",", names=True, deletechars="")
    assert (table["time"][0], table["time"][-1]) == (opts["StartTime"], opts["StopTime"])
    experiment, _ = make_experiment(fmu=fmu_path)
    p = experiment.problem
    theta, omega = exact(p.theta0, p.omega0, p.L, p.g, table["time"])
    assert np.max(np.abs(table["theta"] - theta)) <= 1e-14 and np.max(np.abs(table["omega"] - omega)) <= 1e-13


def test_cross_check_command_refuses_a_file_that_is_no_fmu(tmp_path: Path) -> None:
    (tmp_path / "x.fmu").write_text("not a zip")
    done = pendulum_fmu("cross-check", str(tmp_path / "out"), "--fmu", str(tmp_path / "x.fmu"))
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1 and "--fmu" in done.stderr
    assert not (tmp_path / "out").exists()


# --- the experiment from a _ref.opt and from the .exp ---------------------------------------------

def _run_from(fmu: Path, start_time: float, interface: str = "CoSimulation", **options: object) -> np.ndarray:
    return simulate_fmu(str(fmu), fmi_type=interface, start_time=start_time, stop_time=start_time + 6.0,
                        output_interval=0.02, output=OUTPUTS, **options)  # type: ignore[arg-type]


@pytest.mark.slow
def test_judge_takes_the_experiment_from_a_ref_opt(fmu_path: Path, tmp_path: Path) -> None:
    """A run from t = 5 s: wrong against the default start time 0, right with the folder's
    _ref.opt, which also says Model Exchange (the folder's me) and its tolerance."""
    run = _run_from(fmu_path, 5.0, "ModelExchange", relative_tolerance=1e-6)
    results = tmp_path / "results/2.0/me/linux64/SomeTool/1.0/PendulumFMU/0.1.0/Pendulum"
    fmus = tmp_path / "fmus/2.0/me/linux64/PendulumFMU/0.1.0/Pendulum"
    for folder in (results, fmus):
        folder.mkdir(parents=True)
    write_csv(str(results / "Pendulum_out.csv"), run)
    without = judge(results / "Pendulum_out.csv", start={"tolerance": 1e-6}, interface="ME", fmu=fmu_path)
    assert not without.passed, without.line  # judged from t = 0
    (fmus / "Pendulum_ref.opt").write_text("StartTime, 5.0\nStopTime, 11.0\nStepSize, 0.02\nRelTol, 1e-6\n")
    assert cross_check_opt(results / "Pendulum_out.csv") == (fmus / "Pendulum_ref.opt").resolve()
    verdict = judge(results / "Pendulum_out.csv", fmu=fmu_path)
    stated = verdict.experiment_file
    assert stated is not None and stated.interface == "ME" and stated.start_time == 5.0
    assert verdict.experiment.interface == "ME" and verdict.experiment.start_time == 5.0
    assert verdict.experiment.tolerance == 1e-6 and verdict.passed, verdict.line
    done = pendulum_fmu("judge", str(results / "Pendulum_out.csv"), "--fmu", str(fmu_path),
                        "--cross-check-verdict", str(results))
    assert done.returncode == 0, done.stdout + done.stderr
    assert "Pendulum_ref.opt: startTime 5" in done.stdout.splitlines()[0]
    assert sorted(p.name for p in results.iterdir()) == ["Pendulum_out.csv", "passed"]
    # --start says otherwise: the run judged from t = 0 fails, and the verdict file follows
    done = pendulum_fmu("judge", str(results / "Pendulum_out.csv"), "--fmu", str(fmu_path), "--start",
                        "startTime=0", "--cross-check-verdict", str(results))
    assert done.returncode == 1
    assert sorted(p.name for p in results.iterdir()) == ["Pendulum_out.csv", "failed"]


def _fmu_with_experiment(fmu: Path, target: Path, start_time: str) -> Path:
    """A copy of ``fmu`` whose FMI-LS-REF experiment starts at ``start_time``."""
    with zipfile.ZipFile(fmu) as source, zipfile.ZipFile(target, "w", zipfile.ZIP_DEFLATED) as copy:
        for item in source.infolist():
            data = source.read(item.filename)
            if item.filename == EXP:
                data = data.replace(b'startTime="0"', f'startTime="{start_time}"'.encode())
                assert f'startTime="{start_time}"'.encode() in data
            copy.writestr(item, data)
    return target


def test_judge_takes_the_experiment_from_the_fmus_exp(fmu_any: Path, tmp_path: Path) -> None:
    run = _run_from(fmu_any, 5.0)
    write_csv(str(tmp_path / "run.csv"), run)
    verdict = judge(tmp_path / "run.csv", fmu=fmu_any)
    stated = verdict.experiment_file
    assert stated is not None and stated.source.endswith("Pendulum.exp") and stated.start_time == 0.0
    assert not verdict.passed  # the FMU's own experiment starts at 0
    moved = _fmu_with_experiment(fmu_any, tmp_path / "Pendulum.fmu", "5")
    verdict = judge(tmp_path / "run.csv", fmu=moved)
    stated = verdict.experiment_file
    assert stated is not None and stated.start_time == 5.0 and stated.tolerance == 1e-8
    assert verdict.experiment.start_time == 5.0 and verdict.passed, verdict.line


def test_a_run_of_the_experiment_is_judged_on_its_step(fmu_any: Path, tmp_path: Path) -> None:
    """fmpy's run of the default experiment (its own defaults: the DefaultExperiment's step,
    447 rows, the last step shorter) is judged on the experiment's step of 17 digits; without
    the experiment the judge takes the times' own step, since 6 digits of it would drift from
    k h by 5.7e-5 s over 446 steps."""
    stated = fmu_experiment(fmu_any)
    assert stated is not None and stated.step is not None
    run = simulate_fmu(str(fmu_any), output=OUTPUTS)
    assert stated.covers(float(run["time"][0]), float(run["time"][-1]), run.size)
    assert not stated.covers(0.0, stated.stop_time, 1001) and not stated.covers(1.0, stated.stop_time, run.size)
    write_csv(str(tmp_path / "default.csv"), run)
    verdict = judge(tmp_path / "default.csv", fmu=fmu_any)
    assert verdict.check("time grid").numbers["step"] == stated.step
    assert verdict.passed, verdict.line
    alone = judge(tmp_path / "default.csv", fmu=fmu_any, read_experiment_file=False)  # the times' step
    assert alone.passed, alone.line
    assert alone.check("time grid").numbers["step"] == pytest.approx(stated.step, rel=1e-12)


# --- the verdict file -------------------------------------------------------------------------------

def test_the_verdict_file_is_written_alone_and_replaces_another(tmp_path: Path) -> None:
    folder = tmp_path / "results" / "Pendulum"
    write_verdict_file(folder, "failed")
    assert [p.name for p in folder.iterdir()] == ["failed"] and (folder / "failed").read_bytes() == b""
    write_verdict_file(folder, "passed")
    assert [p.name for p in folder.iterdir()] == ["passed"]
    with pytest.raises(ValueError):
        write_verdict_file(folder, "maybe")  # type: ignore[arg-type]
    assert [p.name for p in folder.iterdir()] == ["passed"]


def test_an_unreadable_result_is_rejected(tmp_path: Path) -> None:
    (tmp_path / "out.csv").write_text("no,numbers\nat,all\n")
    done = pendulum_fmu("judge", str(tmp_path / "out.csv"), "--cross-check-verdict", str(tmp_path / "v"))
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert [p.name for p in (tmp_path / "v").iterdir()] == ["rejected"]
    (tmp_path / "file").write_text("")
    done = pendulum_fmu("judge", str(tmp_path / "out.csv"), "--cross-check-verdict", str(tmp_path / "file"))
    assert done.returncode == 2 and "--cross-check-verdict" in done.stderr and "Traceback" not in done.stderr


# --- the fmpy band ---------------------------------------------------------------------------------

def _structured(columns: dict[str, np.ndarray]) -> np.ndarray:
    table = np.zeros(next(iter(columns.values())).size, dtype=[(name, float) for name in columns])
    for name, values in columns.items():
        table[name] = values
    return table


CASES = {
    "honest": lambda t, y: y,
    "offset by 5 % of the range": lambda t, y: y + 0.05 * np.ptp(y),
    "offset by 15 % of the range": lambda t, y: y + 0.15 * np.ptp(y),
    "a quarter period late": lambda t, y: np.interp(t - 0.56, t, y),
    "half the amplitude": lambda t, y: 0.5 * y,
    "one in eight mangled": lambda t, y: np.where(np.arange(y.size) % 8 == 0, 3 * y + 1, y),
    "NaN rows": lambda t, y: np.where(np.arange(y.size) % 5 == 0, np.nan, y),
    "constant zero": lambda t, y: np.zeros_like(y),
}


@pytest.mark.parametrize("case", list(CASES))
def test_band_agrees_with_fmpy(case: str) -> None:
    t = np.linspace(0.0, 10.0, 1501)
    theta, omega = exact(math.radians(75.0), 0.0, 1.0, 9.81, t)
    for exact_values in (theta, omega, np.zeros_like(t), np.full_like(t, 2.0)):
        y = CASES[case](t, exact_values)
        _, _, _, outliers = validate_signal(t=t, y=y, t_ref=t, y_ref=exact_values, t_start=t[0], t_stop=t[-1])
        assert outside_fraction(t, y, t, exact_values) == np.sum(outliers) / outliers.size
    result = _structured({"time": t, "theta": CASES[case](t, theta), "omega": CASES[case](t, omega)})
    fmpy_passes = validate_result(result=result, reference=_structured({"time": t, "theta": theta, "omega": omega}),
                                  t_start=t[0], t_stop=t[-1]) is None
    read = read_result(io_table(result))
    experiment, _ = make_experiment({"theta": math.radians(75.0), "omega": 0.0, "L": 1.0, "g": 9.81})
    check = fmpy_validation_check(read, reference(read, experiment))
    assert check.status == "info" and check.numbers["passes"] == fmpy_passes


def io_table(table: np.ndarray) -> dict[str, np.ndarray]:
    return {name: table[name] for name in table.dtype.names}


WRONG = {
    "theta 50 ms late": lambda r: np.interp(r["time"] - 0.05, r["time"], r["theta"]),
    "theta + 5 % of its range": lambda r: r["theta"] + 0.05 * np.ptp(r["theta"]),
    "theta x 0.9": lambda r: 0.9 * r["theta"],
    "every 10th theta NaN": lambda r: np.where(np.arange(r.size) % 10 == 0, np.nan, r["theta"]),
}


def test_the_verdict_reports_the_band_on_an_honest_and_a_wrong_file(fmu_path: Path) -> None:
    """fmpy's band passes an honest run and each wrong run the judge fails; it fails theta
    with its sign flipped. Prints the table of docs/importers.md."""
    run = simulate_fmu(str(fmu_path), stop_time=10.0, output_interval=0.01, output=OUTPUTS)
    honest = judge(run)
    assert honest.passed and honest.check("fmpy band").numbers["passes"] is True
    assert honest.check("fmpy band").status == "info" and "would pass" in honest.check("fmpy band").line
    print("\n| file (fmpy CS, 75 deg, 10 s at 0.01 s) | judge | fmpy band | theta rows outside the band |")
    print("|---|---|---|---|")
    print(f"| honest | PASS | passes | {honest.check('fmpy band').numbers['outside']['theta']:.1%} |")
    for label, change in WRONG.items():
        wrong = run.copy()
        wrong["theta"] = change(run)
        verdict = judge(wrong)
        band = verdict.check("fmpy band").numbers
        print(f"| {label} | {'PASS' if verdict.passed else 'FAIL'} | {'passes' if band['passes'] else 'fails'} "
              f"| {band['outside']['theta']:.1%} |")
        assert not verdict.passed and band["passes"] is True, label  # the loose band lets it through
    flipped = run.copy()
    flipped["theta"] = -run["theta"]
    band = judge(flipped).check("fmpy band").numbers
    assert band["passes"] is False and band["outside"]["theta"] > LIMIT


def test_band_is_quick_on_two_million_rows() -> None:
    t = np.linspace(0.0, 2000.0, 2_000_001)
    theta, omega = exact(math.radians(75.0), 0.0, 1.0, 9.81, t)
    signals = {"theta": (theta, theta), "omega": (omega + 1e-9, omega), "theta_exact": (theta, theta),
               "omega_exact": (omega + 2 * np.ptp(omega), omega)}
    started = time.perf_counter()
    fractions = outside_fractions(t, t, signals)
    print(f"\nfmpy band on 2,000,001 rows, four signals: {time.perf_counter() - started:.3f} s (not asserted)")
    assert list(fractions.values())[:3] == [0.0, 0.0, 0.0] and fractions["omega_exact"] > LIMIT


def test_reading_an_exp_in_either_layout() -> None:
    attributes = b'<Experiments name="x"><Experiment name="a" startTime="1" stopTime="3" stepSize="0.5" ' \
                 b'tolerance="1e-6"/></Experiments>'
    child = b'<Experiments name="x"><Experiment name="a" tolerance="1e-6"><TransientSimulation startTime="1" ' \
            b'stopTime="3" stepSize="0.5"/></Experiment></Experiments>'
    for text in (attributes, child):
        stated = read_experiments(text, "x.exp")
        assert (stated.start_time, stated.stop_time, stated.step, stated.tolerance) == (1.0, 3.0, 0.5, 1e-6)
    with pytest.raises(ValueError, match="stopTime"):
        read_experiments(b'<Experiments name="x"><Experiment name="a" startTime="3" stopTime="1"/></Experiments>', "x")


def test_a_copied_folder_without_its_opt_falls_back_to_the_fmu(exported: Path, tmp_path: Path) -> None:
    (model,) = exported.glob("fmus/2.0/cs/linux64/PendulumFMU/*/Pendulum")
    shutil.copyfile(model / "Pendulum_ref.csv", tmp_path / "Pendulum_ref.csv")
    assert cross_check_opt(tmp_path / "Pendulum_ref.csv") is None
    assert cross_check_opt(model / "Pendulum_ref.csv") == (model / "Pendulum_ref.opt").resolve()
