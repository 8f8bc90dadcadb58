"""``pendulum-fmu judge RESULT --system split``: files the judge did not make itself.

The files come from tests/split_closed_form.py (the masters written again without the FMUs,
with planted defects), at other macro steps, other start values and other column names. The
judge must name the master each file comes from, and fail each planted defect with its reason.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from pendulum_fmu.cli.main import main
from pendulum_fmu.split.judge import judge_split
from pendulum_fmu.split.masters import MASTERS, Master
from split_closed_form import exact_columns, simulate, write_csv

THETA0 = math.radians(120)
OMEGA0 = 0.5
L = 2.0


@pytest.mark.parametrize("H", [0.02, 0.005])
@pytest.mark.parametrize("master", MASTERS, ids=lambda m: m.name)
def test_names_each_master(master: Master, H: float, tmp_path: Path) -> None:
    """120 deg, omega0 0.5 rad/s, L = 2 (given with --start), 1.5 s: named, and it passes
    when it is the Gauss-Seidel master of its coupling (the best of the kind)."""
    run = simulate(master.scheme, master.coupling, H, 1.5, THETA0, OMEGA0, L)
    path = write_csv(run, tmp_path / "run.csv", names=("Time", "pendulum/theta", "pendulum/omega"), delimiter=";")
    verdict = judge_split(path, start=["L=2"])
    assert verdict.master == master.name, verdict.lines
    assert verdict.H == pytest.approx(H)
    assert not verdict.findings
    assert verdict.error == pytest.approx(verdict.reference_errors[master.name], rel=1e-9)
    if master.scheme == "gauss-seidel":
        assert verdict.passed, verdict.lines
    assert f"behaves as {master.describe()} at H = {H:g}" in "\n".join(verdict.lines)


def _planted(tmp_path: Path, **defect: object) -> Path:
    run = simulate("gauss-seidel", "zoh", 0.01, 2.0, **defect)  # type: ignore[arg-type]
    shift = 0.01 if defect.get("early_labels") else 0.0
    exact = exact_columns(run, 1.3089969389957472, 0.0, 1.0, 9.81, shift=shift)
    return write_csv(run, tmp_path / "planted.csv", exact=exact)


@pytest.mark.parametrize(("defect", "kind", "reason"), [
    ({"lag": 2}, "held-too-long", "an input held one step too long"),
    ({"drop": True}, "dropped", "a connection dropped"),
    ({"alternate": True}, "out-of-order", "the FMUs stepped out of order"),
    ({"drift": 2e-5}, "drift", "the macro step drifts"),
    ({"early_labels": True}, "labels", "rows labelled one step early"),
])
def test_fails_each_planted_defect_with_its_reason(tmp_path: Path, defect: dict[str, object], kind: str,
                                                   reason: str) -> None:
    verdict = judge_split(_planted(tmp_path, **defect), start=["theta=75deg", "omega=0"])
    assert not verdict.passed, verdict.lines
    assert verdict.master is None
    assert [f.kind for f in verdict.findings] == [kind], verdict.lines
    assert verdict.lines[-1].startswith("verdict         FAIL  " + reason), verdict.lines


def test_a_master_that_is_not_the_one_it_names_fails(tmp_path: Path) -> None:
    run = simulate("jacobi", "zoh", 0.01, 2.0)
    path = write_csv(run, tmp_path / "jacobi.csv")
    assert main(["judge", str(path), "--system", "split", "--master", "jacobi-zoh"]) == 0
    assert main(["judge", str(path), "--system", "split", "--master", "gauss-seidel-zoh"]) == 1
    assert judge_split(path).passed  # 3.0 times Gauss-Seidel's error, within the default 4


def test_command_line_errors_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write_csv(simulate("gauss-seidel", "zoh", 0.01, 0.5), tmp_path / "gs.csv")
    assert main(["judge", str(path), "--system", "split", "--master", "euler"]) == 2
    assert main(["judge", str(tmp_path / "missing.csv"), "--system", "split"]) == 2
    assert main(["judge", str(path), "--system", "split", "--start", "mass=3"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 3 and all(line.startswith("pendulum-fmu judge: ") for line in err), err
    assert main(["judge", str(path), "--system", "split"]) == 0
    out = capsys.readouterr().out
    assert "behaves as Gauss-Seidel with zero-order hold at H = 0.01" in out and "verdict         PASS" in out
