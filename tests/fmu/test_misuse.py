"""Bad input and wrong call sequences through fmpy, on the FMI 2.0 and the FMI 3.0 FMU: an error
status and a logged reason, no crash.

Each case runs in its own process, so a crash is a failing exit code, not a dead test run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from misuse_cases import CASES

RUNNER = Path(__file__).resolve().parents[1] / "helpers" / "misuse_cases.py"

# case -> a phrase the FMU's error log must contain
EXPECTED_LOG = {
    "L_negative": "L (value reference 1) = -1: must be greater than 0",
    "L_zero": "L (value reference 1) = 0: must be greater than 0",
    "g_negative": "g (value reference 2) = -9.81: must be greater than 0",
    "L_nan": "must be a finite number",
    "theta_nan": "theta (value reference 3) = nan: must be a finite number",
    "omega_inf": "omega (value reference 5) = inf: must be a finite number",
    "theta_exact_set": "theta_exact (value reference 7) = 1: is calculated by the FMU and cannot be set",
    "period_set": "period (value reference 9) = 1: is calculated",
    "g_over_L_underflow": "fmi2ExitInitializationMode: g / L must be a finite number greater than 0",
    "parameter_after_init": "is fixed after initialization",
    "step_zero": "communicationStepSize 0 must be a finite number greater than 0",
    "step_negative": "communicationStepSize -0.1 must be",
    "step_wrong_time": "currentCommunicationPoint 1 is not the current time 0",
    "step_after_terminate": "fmi2DoStep: not allowed in state Terminated",
    "step_before_init": "fmi2DoStep: not allowed in state Instantiated",
    "unknown_reference": "(unknown) (value reference 4242): unknown value reference",
    "bad_solver": "solver (value reference 12) = 99: must be one of the items",
    "bad_tolerance": "tolerance -1 must be in (0, 1)",
    "wrong_guid": "does not match this FMU's",
    "me_nan_state": "fmi2SetContinuousStates: states (nan, 0) must be finite",
    "free_state_itself": "is not an FMU state of this instance that is still live",
}


def test_every_case_has_an_expectation() -> None:
    assert set(EXPECTED_LOG) == set(CASES)


@pytest.mark.parametrize("case", sorted(CASES))
def test_misuse_gives_an_error_and_a_clear_log(case: str, fmu_any: Path) -> None:
    version = "fmi3" if fmu_any.parent.name == "fmi3" else "fmi2"
    completed = subprocess.run([sys.executable, str(RUNNER), case, str(fmu_any)],
                               capture_output=True, text=True, timeout=60, check=False)
    assert completed.returncode == 0, f"crashed: {completed.returncode}\n{completed.stderr}"
    result = completed.stdout.strip().splitlines()[-1]
    if case == "wrong_guid":
        assert result in ("RESULT Failed to instantiate model", "RESULT Failed to instantiate FMU")
    else:
        assert "failed with status 3 (error)" in result, result
    assert "[ERROR] " in completed.stdout
    assert EXPECTED_LOG[case].replace("fmi2", version) in completed.stdout, completed.stdout
