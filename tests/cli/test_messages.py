"""One clear line per message, naming the option the user gave: sizes, certificates, the FMI version."""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest

from pendulum_fmu.cli.arguments import size_field
from pendulum_fmu.cli.main import main
from pendulum_fmu.cli.summary import warning_lines

REMEDY = ("No double-precision solver can hold it this close to the separatrix (tol |1 - m| = 3.7e-41, below "
          "1e-21: the rounding of the state alone moves the period by more); read theta_exact and omega_exact.")


def certificate(t: float, ratio: str) -> str:
    """A certificate message as the FMU logs it."""
    return (f"certificate: at t = {t} the step is {ratio} times beyond its bound (|theta - theta_exact| = 1e-05 "
            f"rad, bound 3e-06 rad; |omega - omega_exact| = 6e-05 rad/s, bound 3e-06 rad/s; solver rkn, "
            f"tolerance 1e-08, 1 - m = 3.75e-33). {REMEDY}")


def test_the_certificate_messages_of_a_run_are_said_once_and_short() -> None:
    lines = warning_lines(tuple(certificate(t, r) for t, r in ((8.9, "19.8"), (9.9, "439"), (11.9, "1.94e+05"))))
    assert lines == ["warning   the step certificate failed from t = 8.9 s on (19.8 times its bound, growing to "
                     "1.94e+05 times): no double-precision solver can hold it this close to the separatrix; "
                     "read theta_exact and omega_exact"]
    assert len(lines[0]) < 250


def test_a_hard_case_and_the_certificate_it_carries_are_said_apart() -> None:
    hard = "hard case: by t = 9.9 the numerical solution reversed the rotation. Use a tighter tolerance."
    lines = warning_lines((certificate(8.9, "19.8"), f"{hard} {certificate(9.9, '439')}"))
    assert lines[0] == f"warning   the FMU: {hard}"
    assert lines[1].startswith("warning   the step certificate failed from t = 8.9 s on (19.8 times its bound, "
                               "growing to 439 times)")


def test_other_warnings_stay_as_the_fmu_logged_them() -> None:
    assert warning_lines(("hard case: near the top",)) == ["warning   the FMU: hard case: near the top"]
    assert warning_lines(()) == []


@pytest.mark.parametrize(("given", "named"), [
    ({"stop_time": 3.0, "periods": None}, "stop_time"),
    ({"stop_time": None, "periods": 100000.0}, "periods"),
    ({"stop_time": None, "periods": None}, "points_per_period"),
])
def test_a_run_too_big_names_the_time_option_given(given: dict[str, float | None], named: str) -> None:
    assert size_field(argparse.Namespace(**given)) == named


def test_simulate_refuses_a_run_too_big_naming_periods_and_the_half(fmu_path: Path,
                                                                     capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["simulate", "-p", "100000", "-n", "10000", "--fmu", str(fmu_path)])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and "stop-time" not in err
    assert "error: argument -p/--periods: this run would record 1 billion output points" in err
    assert "over the limit of half the " in err and "lower -p/--periods or -n/--points-per-period" in err


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_simulate_says_which_fmi_version_it_ran(version: str, fmu_path: Path, fmu3_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    fmu = fmu_path if version == "2.0" else fmu3_path
    assert main(["simulate", "-p", "1", "-n", "10", "--fmu", str(fmu)]) == 0
    assert capsys.readouterr().out.splitlines()[0] == f"fmu       FMI {version}, {fmu}"
