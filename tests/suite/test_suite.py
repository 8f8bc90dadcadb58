"""``pendulum-fmu suite``: the cases, what the FMUs carry of them, the runs through engines, a
command template and a folder of results, and the reports CI reads (JUnit XML checked against
the schema's structure, JSON, the HTML page, the cross-check verdict files)."""

from __future__ import annotations

import hashlib
import importlib.util
import json
import math
import os
import posixpath
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu
from scipy.special import ellipj, ellipk

from junit_schema import check as check_junit
from junit_schema import properties
from pendulum_fmu.judge.experiment_files import read_ref_opt
from pendulum_fmu.suite.cases import SPLIT_STEPS, all_cases, read_data, select, split_cases

REPO = Path(__file__).resolve().parents[2]
FOLDER = "extra/org.fmi-standard.fmi-ls-ref/"
OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact"]


def _cli(*argv: str, timeout: float = 600) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", "suite", *argv], capture_output=True, text=True,
                          timeout=timeout, check=False)


def _pendulum_cases() -> list:
    return [case for case in all_cases() if case.kind == "pendulum"]


# --- the cases ----------------------------------------------------------------------------------

def test_the_registry_covers_both_versions_and_interfaces() -> None:
    cases = _pendulum_cases()
    assert len(cases) >= 12
    assert {(c.fmi, c.interface) for c in cases} == {("2.0", "cs"), ("2.0", "me"), ("3.0", "cs"), ("3.0", "me")}
    names = [c.name for c in all_cases()]
    assert len(set(names)) == len(names)
    for case in cases:
        assert case.catches and len(case.catches) < 200, case.name
        assert set(case.start_values) == {"theta", "omega", "L", "g"}
        assert case.stop > case.start and case.interval > 0 and case.tolerance > 0
    assert any(c.start != 0 for c in cases) and any(not float((c.stop - c.start) / c.interval).is_integer()
                                                    for c in cases)
    assert any(abs(c.start_values["omega"]) > 2 * math.sqrt(c.start_values["g"] / c.start_values["L"]) for c in cases)
    assert [c.interval for c in split_cases()] == list(SPLIT_STEPS) * 2
    assert read_data()[0] == "1"


def test_case_patterns_select_and_refuse() -> None:
    assert [c.name for c in select("me*")] == [c.name for c in all_cases() if c.name.startswith("me")]
    assert [c.name for c in select("cs3-baseline,cs2-baseline")] == ["cs3-baseline", "cs2-baseline"]
    with pytest.raises(ValueError, match="matches no case"):
        select("nothing-*")


def _manifest(archive: zipfile.ZipFile) -> list[ET.Element]:
    return ET.fromstring(archive.read(FOLDER + "fmi-ls-manifest.xml")).findall("Related")


def test_the_fmus_carry_the_registry(fmu_any: Path) -> None:
    archive = zipfile.ZipFile(fmu_any)
    version = "3.0" if "fmi3" in str(fmu_any) else "2.0"
    related = _manifest(archive)
    experiments = [r for r in related if r.get("role") == "experiment/validation"]
    assert [r.get("source") for r in experiments] == ["Pendulum.exp", "PendulumSuite.exp"]  # the default first
    root = ET.fromstring(archive.read(FOLDER + "PendulumSuite.exp"))
    assert root.tag == "Experiments" and "pendulum-suite-1" in root.get("description", "")
    wanted = [c for c in _pendulum_cases() if c.fmi == version]
    found = root.findall("Experiment")
    assert [e.get("name") for e in found] == [c.name for c in wanted]
    results = {r.get("source"): r for r in related if r.get("role") == "result"}
    for case, element in zip(wanted, found, strict=True):
        numbers = [float(element.get(n, "nan")) for n in ("startTime", "stopTime", "stepSize", "tolerance")]
        assert numbers == [case.start, case.stop, case.interval, case.tolerance], case.name
        given = {p.get("name"): float(p.get("value", "nan")) for p in element.iter("Parameter")}
        assert given == case.start_values, case.name
        source = element.find("References").get("source")  # type: ignore[union-attr]
        assert source == f"suite/{case.name}_ref.csv"
        entry = results[source]
        member = posixpath.join(FOLDER, source)
        assert entry.get("checksum") == hashlib.sha3_256(archive.read(member)).hexdigest()


def _from_rest(theta0: float, w0: float, t: np.ndarray) -> np.ndarray:
    """theta(t) = 2 arcsin(k cd(w0 t | k^2)), k = sin(theta0 / 2): released from rest (scipy's ellipj)."""
    k = math.sin(theta0 / 2)
    sn, cn, dn, _ = ellipj(w0 * t, k * k)
    return 2 * np.arcsin(k * cn / dn)


def test_each_case_reference_is_the_exact_solution_on_its_grid(fmu_any: Path) -> None:
    archive = zipfile.ZipFile(fmu_any)
    version = "3.0" if "fmi3" in str(fmu_any) else "2.0"
    for case in (c for c in _pendulum_cases() if c.fmi == version):
        data = np.genfromtxt(archive.open(f"{FOLDER}suite/{case.name}_ref.csv"), delimiter=",", names=True)
        t = data["time"]
        assert t[0] == case.start and t[-1] == case.stop and 2 <= t.size <= 201, case.name
        steps = (t[:-1] - case.start) / case.interval
        assert np.allclose(steps, np.rint(steps), atol=1e-6), case.name  # times the run outputs
        v = case.start_values
        energy = data["omega"] ** 2 / 2 - v["g"] / v["L"] * np.cos(data["theta"])
        start_energy = v["omega"] ** 2 / 2 - v["g"] / v["L"] * math.cos(v["theta"])
        assert np.max(np.abs(energy - start_energy)) <= 1e-12 * max(1.0, abs(start_energy)), case.name
        assert np.array_equal(data["theta"], data["theta_exact"])
        assert np.allclose(data["x"], v["L"] * np.sin(data["theta"]), rtol=0, atol=1e-15 * v["L"])
        if v["omega"] == 0 and abs(v["theta"]) < 3:
            w0 = math.sqrt(v["g"] / v["L"])
            assert np.max(np.abs(data["theta"] - _from_rest(v["theta"], w0, t - case.start))) <= 1e-12, case.name
    assert ellipk(0.5) > 0


def test_list_prints_every_case_one_a_line() -> None:
    done = _cli("list")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert [line.split()[0] for line in lines] == [c.name for c in all_cases()]
    for line, case in zip(lines, all_cases(), strict=True):
        assert f"FMI {case.fmi}" in line and f" {case.interface.upper()} " in line and case.catches in line
    me = _cli("list", "--cases", "me*")
    assert [line.split()[0] for line in me.stdout.splitlines()] == [c.name for c in select("me*")]


@pytest.mark.parametrize("argv, option", [
    (["run", "--engine", "fmpy", "--out", "{out}", "--cases", "nothing-*"], "--cases"),
    (["run", "--command", "tool {fmu} {nope}", "--out", "{out}"], "--command"),
    (["run", "--command", "tool {fmu", "--out", "{out}"], "--command"),
    (["run", "--engine", "openmodelica", "--out", "{out}"], "--engine"),
    (["run", "--results", "{out}/missing", "--out", "{out}"], "--results"),
    (["run", "--engine", "fmpy", "--out", "{out}", "--timeout", "0"], "--timeout"),
    (["run", "--results", "{out}", "--master", "jacobi", "--out", "{out}"], "--master"),
    (["run", "--out", "{out}"], "one of the arguments"),
])
def test_bad_arguments_are_one_line_and_exit_2(tmp_path: Path, argv: list[str], option: str) -> None:
    done = _cli(*[a.replace("{out}", str(tmp_path)) for a in argv])
    assert done.returncode == 2, (done.stdout, done.stderr)
    assert len(done.stderr.strip().splitlines()) == 1 and "Traceback" not in done.stderr
    assert option in done.stderr
    assert not (tmp_path / "junit.xml").exists()


# --- runs and reports ------------------------------------------------------------------------------

def test_fmpy_run_writes_reports_ci_reads(tmp_path: Path) -> None:
    chosen = "cs2-start-time,cs2-uneven-interval,me3-cvode"
    done = _cli("run", "--engine", "fmpy", "--cases", chosen, "--out", str(tmp_path))
    assert done.returncode == 0, done.stderr
    progress = [line for line in done.stderr.splitlines() if line.startswith("[")]
    assert [line.split()[1].rstrip(":") for line in progress] == chosen.split(",")
    cases = check_junit(ET.parse(tmp_path / "junit.xml").getroot())
    assert list(cases) == chosen.split(",")
    for name, case in cases.items():
        assert case.find("failure") is None and case.find("error") is None
        figures = properties(case)
        assert 0 < float(figures["bound_ratio"]) < 1 and 0 < float(figures["error_rad"]) < 1e-5, name
        assert (tmp_path / "cases" / name / "passed").is_file()
        assert not (tmp_path / "cases" / name / "failed").exists()
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["passed"] is True and summary["counts"] == {"passed": 3, "failed": 0, "error": 0}
    assert summary["engine"].startswith("fmpy ")
    page = (tmp_path / "report.html").read_text()
    assert page.count('src="data:image/png;base64,') == 3
    assert "<script" not in page and "http" not in page.replace("http://www.w3.org", "")
    for name in cases:
        assert f'id="{name}"' in page


def _run(fmu: Path, case_name: str, **changes: object) -> np.ndarray:
    case = select(case_name)[0]
    settings: dict[str, object] = dict(start_time=case.start, stop_time=case.stop, output_interval=case.interval,
                                       relative_tolerance=case.tolerance, start_values=dict(case.start_values),
                                       fmi_type="ModelExchange" if case.interface == "me" else "CoSimulation",
                                       output=OUTPUTS)
    settings.update(changes)
    return simulate_fmu(str(fmu), **settings)  # type: ignore[arg-type]


def _write(path: Path, rows: np.ndarray) -> None:
    names = rows.dtype.names or ()
    lines = [",".join(names)] + [",".join(repr(float(row[n])) for n in names) for row in rows]
    path.write_text("\n".join(lines) + "\n")


def test_wrong_results_never_pass(tmp_path: Path, fmu_path: Path) -> None:
    """Each case fails the run that gets its one thing wrong; a good run of another passes."""
    results = tmp_path / "results"
    results.mkdir()
    # the start time ignored: the same ten seconds from 0 (the pendulum is autonomous, so a run from 0
    # relabelled by +5 s would be right)
    _write(results / "cs2-start-time.csv", _run(fmu_path, "cs2-start-time", start_time=0.0, stop_time=10.0))
    _write(results / "cs2-uneven-interval.csv", _run(fmu_path, "cs2-uneven-interval")[:-1])  # short step dropped
    theta = select("cs2-parameters")[0].start_values["theta"]
    _write(results / "cs2-parameters.csv", _run(fmu_path, "cs2-parameters", start_values={"theta": theta}))  # no L, g
    _write(results / "me2-tolerance.csv", _run(fmu_path, "me2-tolerance", relative_tolerance=1e-4))
    wrapped = _run(fmu_path, "cs2-rotation")
    for name in ("theta", "theta_exact"):
        wrapped[name] = np.angle(np.exp(1j * wrapped[name]))  # wrapped into (-pi, pi]
    _write(results / "cs2-rotation.csv", wrapped)
    _write(results / "me2-cvode.csv", _run(fmu_path, "me2-cvode"))
    (results / "cs2-baseline.csv").write_text("this is not a result\n")
    chosen = "cs2-start-time,cs2-uneven-interval,cs2-parameters,me2-tolerance,cs2-rotation,me2-cvode,cs2-baseline," \
             "cs2-near-top"
    out = tmp_path / "out"
    done = _cli("run", "--results", str(results), "--cases", chosen, "--out", str(out))
    assert done.returncode == 1, done.stderr
    summary = {c["name"]: c for c in json.loads((out / "summary.json").read_text())["cases"]}
    expected = {"cs2-start-time": "failed", "cs2-uneven-interval": "failed", "cs2-parameters": "failed",
                "me2-tolerance": "failed", "cs2-rotation": "failed", "me2-cvode": "passed",
                "cs2-baseline": "error", "cs2-near-top": "error"}
    assert {name: c["status"] for name, c in summary.items()} == expected
    assert "FAIL (span)" in summary["cs2-uneven-interval"]["line"]
    assert "no result file cs2-near-top.csv" in summary["cs2-near-top"]["line"]
    cases = check_junit(ET.parse(out / "junit.xml").getroot())
    for name, status in expected.items():
        verdict = {"passed": None, "failed": "failure", "error": "error"}[status]
        element = cases[name].find(verdict) if verdict else None
        if verdict:
            assert element is not None and element.get("message") == summary[name]["line"], name
        folder = out / "cases" / name
        assert [p.name for p in folder.iterdir() if p.name in ("passed", "failed", "rejected")] == \
            [{"passed": "passed", "failed": "failed", "error": "rejected"}[status]], name


def test_a_template_that_crashes_hangs_or_writes_nothing_is_an_error_and_the_rest_go_on(tmp_path: Path) -> None:
    fmpy = Path(sys.executable).parent / "fmpy"
    template = ("case {case} in cs2-baseline) echo starting; echo boom >&2; exit 7;; "
                "cs2-start-time) sleep 100;; cs2-uneven-interval) echo done;; "
                f"*) {fmpy} simulate {{fmu}} --start-time {{start}} --stop-time {{stop}} "
                "--output-interval {interval} --relative-tolerance {tolerance} --start-values {start_value_pairs} "
                "--output-variables theta omega theta_exact omega_exact --output-file {output};; esac")
    done = _cli("run", "--command", template, "--cases", "cs2-baseline,cs2-start-time,cs2-uneven-interval,cs2-rotation",
                "--timeout", "10", "--out", str(tmp_path))
    assert done.returncode == 1, done.stderr
    summary = {c["name"]: c for c in json.loads((tmp_path / "summary.json").read_text())["cases"]}
    assert summary["cs2-baseline"]["status"] == "error"
    assert summary["cs2-baseline"]["line"] == "ERROR: exit status 7: boom"
    assert summary["cs2-baseline"]["output_tail"] == "starting\nboom"
    assert summary["cs2-start-time"]["status"] == "error" and "no answer within" in summary["cs2-start-time"]["line"]
    assert summary["cs2-uneven-interval"]["status"] == "error"
    assert "no result at" in summary["cs2-uneven-interval"]["line"]
    assert summary["cs2-rotation"]["status"] == "passed", summary["cs2-rotation"]["line"]
    error = check_junit(ET.parse(tmp_path / "junit.xml").getroot())["cs2-baseline"].find("error")
    assert error is not None and error.text == "starting\nboom"


def test_the_experiment_file_and_placeholders(tmp_path: Path) -> None:
    template = "cp {experiment} " + str(tmp_path / "{case}.json") + "; echo {start_values} {interface} {fmi_version}"
    done = _cli("run", "--command", template, "--cases", "me3-cvode", "--out", str(tmp_path / "out"))
    assert done.returncode == 1  # nothing written: an error
    written = json.loads((tmp_path / "me3-cvode.json").read_text())
    case = select("me3-cvode")[0]
    assert written["start_values"] == case.start_values and written["interface"] == "me"
    assert (written["start"], written["stop"], written["interval"], written["tolerance"]) == \
        (case.start, case.stop, case.interval, case.tolerance)
    assert written["fmu"].endswith("Pendulum.fmu") and written["output"].endswith("result.csv")
    said = (tmp_path / "out" / "cases" / "me3-cvode" / "output.txt").read_text().split()
    assert said == [f"{n}={v!r}" for n, v in case.start_values.items()] + ["me", "3.0"]


def _needs(module: str) -> None:
    if importlib.util.find_spec(module) is None:
        pytest.skip(f"{module} is not installed (python/requirements.lock)")


def test_libcosim_runs_fmi2_and_its_crash_on_fmi3_is_an_error(tmp_path: Path) -> None:
    _needs("libcosimpy")
    done = _cli("run", "--engine", "libcosim", "--cases", "cs2-baseline,cs3-baseline,me2-cvode", "--out",
                str(tmp_path))
    assert done.returncode == 1
    summary = {c["name"]: c for c in json.loads((tmp_path / "summary.json").read_text())["cases"]}
    assert summary["cs2-baseline"]["status"] == "passed", summary["cs2-baseline"]["line"]
    assert summary["cs3-baseline"]["line"].startswith("ERROR: killed by signal 11 (SIGSEGV)")
    assert summary["me2-cvode"]["line"] == "ERROR: cannot run: libcosim is a co-simulation master: no Model Exchange"


def test_split_cases_judge_the_master_the_engine_claims(tmp_path: Path) -> None:
    _needs("libcosimpy")
    libcosim = _cli("run", "--engine", "libcosim", "--cases", "split2-H0.1", "--out", str(tmp_path / "libcosim"))
    assert libcosim.returncode == 0, libcosim.stderr
    case = check_junit(ET.parse(tmp_path / "libcosim" / "junit.xml").getroot())["split2-H0.1"]
    assert 0 < float(properties(case)["bound_ratio"]) <= 1
    fmpy = _cli("run", "--engine", "fmpy", "--cases", "split2-H0.1", "--out", str(tmp_path / "fmpy"))
    assert fmpy.returncode == 1
    (entry,) = json.loads((tmp_path / "fmpy" / "summary.json").read_text())["cases"]
    assert entry["status"] == "failed" and entry["line"].startswith("FAIL (labels, start-dropped)")
    command = _cli("run", "--command", "true", "--cases", "split2-H0.1", "--out", str(tmp_path / "c"))
    assert command.returncode == 2 and "matches no case" in command.stderr  # a template runs one FMU


def test_export_in_the_cross_check_layout(tmp_path: Path, fmu_path: Path) -> None:
    done = _cli("export", str(tmp_path), "--cases", "cs2-start-time,me2-tolerance")
    assert done.returncode == 0, done.stderr
    folders = [Path(line) for line in done.stdout.splitlines()]
    assert {f.parts[-5] for f in folders} == {"cs", "me"} and all(f.parts[-6] == "2.0" for f in folders)
    for folder in folders:
        case = select(folder.name)[0]
        opt = read_ref_opt(folder / f"{case.name}_ref.opt")
        assert (opt.start_time, opt.stop_time, opt.step, opt.tolerance) == (case.start, case.stop, case.interval,
                                                                            case.tolerance)
        assert opt.interface == case.interface.upper()
        fmu_member = zipfile.ZipFile(folder / f"{case.name}.fmu").read(f"{FOLDER}suite/{case.name}_ref.csv")
        assert (folder / f"{case.name}_ref.csv").read_bytes() == fmu_member
        assert f"theta = {case.start_values['theta']!r}" in (folder / "ReadMe.txt").read_text()


# --- the docs -------------------------------------------------------------------------------------

def test_the_docs_list_the_cases_as_the_registry_has_them() -> None:
    page = (REPO / "docs" / "suite.md").read_text()
    for case in all_cases():
        assert f"| `{case.name}` | {case.fmi} | {case.interface.upper()} | {case.catches} |" in page, case.name


def test_the_compatibility_table_covers_every_case_and_engine() -> None:
    from pendulum_fmu.suite.adapters import ENGINES

    page = (REPO / "docs" / "suite-compatibility.md").read_text()
    header = next(line for line in page.splitlines() if line.startswith("| case |"))
    assert header == "| case | " + " | ".join(ENGINES) + " |"
    for case in all_cases():
        row = next(line for line in page.splitlines() if line.startswith(f"| `{case.name}` |"))
        assert row.count("|") == len(ENGINES) + 2, row
    assert os.environ.get("PENDULUM_FMU") is None or page.startswith("<!-- written by")


def test_a_junit_library_reads_the_report(tmp_path: Path, fmu_path: Path) -> None:
    """junitparser (5.0.3, to be pinned in python/requirements.lock) reads what CI reads."""
    junitparser = pytest.importorskip("junitparser")
    results = tmp_path / "results"
    results.mkdir()
    (results / "cs2-baseline.csv").write_text("not a result\n")
    _write(results / "cs2-uneven-interval.csv", _run(fmu_path, "cs2-uneven-interval")[:-1])
    done = _cli("run", "--results", str(results), "--cases", "cs2-baseline,cs2-uneven-interval,cs2-rotation",
                "--out", str(tmp_path / "out"))
    assert done.returncode == 1
    summary = {c["name"]: c for c in json.loads((tmp_path / "out" / "summary.json").read_text())["cases"]}
    report = junitparser.JUnitXml.fromfile(str(tmp_path / "out" / "junit.xml"))
    seen = {}
    for suite in report:
        assert suite.name == "pendulum-suite-1" and suite.tests == 3 and suite.failures == 1 and suite.errors == 2
        for case in suite:
            (verdict,) = case.result
            seen[case.name] = (type(verdict).__name__, verdict.message)
    assert seen == {"cs2-baseline": ("Error", summary["cs2-baseline"]["line"]),
                    "cs2-uneven-interval": ("Failure", summary["cs2-uneven-interval"]["line"]),
                    "cs2-rotation": ("Error", summary["cs2-rotation"]["line"])}
