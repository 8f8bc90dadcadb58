"""The seed's study through fmpy: CS and ME against the exact port, periods, rebuild; the accuracy
targets hold for the FMI 2.0 and the FMI 3.0 FMU alike (fixture fmu_any)."""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
from fmpy import simulate_fmu
from scipy.special import ellipk

from fmpy_runs import Scenario, simulate
from fmu_rebuild import rebuild_from_sources
from pendulum_fmu.fmu.period import measured_period
from reference_cache import cached

SEED_AMPLITUDES = (75.0, 80.0, 85.0, 90.0)


@pytest.mark.parametrize("amplitude", SEED_AMPLITUDES)
def test_cosimulation_at_default_tolerance_within_1e6(fmu_any: Path, amplitude: float) -> None:
    run = simulate(fmu_any, Scenario(amplitude_deg=amplitude, periods=10), "CS")
    assert run.result["time"][-1] == pytest.approx(10 * run.scenario.period)
    assert run.max_error <= 1e-6


@pytest.mark.parametrize("amplitude", SEED_AMPLITUDES)
def test_model_exchange_with_cvode_at_1e10_within_1e6(fmu_any: Path, amplitude: float) -> None:
    run = simulate(fmu_any, Scenario(amplitude_deg=amplitude, periods=10), "ME", tolerance=1e-10)
    assert run.max_error <= 1e-6


def _mpmath_pendulum(theta0: float, w0: float, times: list[float]) -> list[float]:
    """theta(t) by mpmath's Taylor-series ODE solver at 35 digits (independent of elliptic functions)."""
    def compute() -> list[list[str]]:
        with mpmath.workdps(35):
            w0sq = mpmath.mpf(w0) ** 2
            solution = mpmath.odefun(lambda t, y: [y[1], -w0sq * mpmath.sin(y[0])], 0, [mpmath.mpf(theta0), 0])
            return [[repr(float(solution(mpmath.mpf(t))[0])) for t in times]]

    # seconds per case: computed once, then read from build/test-cache/ (reference_cache.py)
    return [float(v) for v in cached("odefun35", (theta0, w0, tuple(times)), compute)[0]]


@pytest.mark.slow
@pytest.mark.parametrize("amplitude", (75.0, 90.0))
def test_theta_exact_against_mpmath_ode_solution(fmu_any: Path, amplitude: float) -> None:
    scenario = Scenario(amplitude_deg=amplitude, periods=1.0, points_per_period=8)
    run = simulate(fmu_any, scenario, "CS")
    reference = _mpmath_pendulum(math.radians(amplitude), scenario.w0, list(run.result["time"]))
    assert np.max(np.abs(run.result["theta_exact"] - reference)) <= 1e-12


@pytest.mark.parametrize("amplitude", SEED_AMPLITUDES)
def test_period_is_4K_over_w0_and_matches_scipy_ratio(fmu_path: Path, amplitude: float) -> None:
    theta0 = math.radians(amplitude)
    result = simulate_fmu(str(fmu_path), stop_time=0.1, output_interval=0.1, output=["period"],
                          start_values={"theta": theta0, "L": 2.0, "g": 9.81})
    w0 = math.sqrt(9.81 / 2.0)
    period = float(result["period"][0])
    m = math.sin(theta0 / 2.0) ** 2
    assert period == pytest.approx(4.0 * ellipk(m) / w0, rel=1e-14)
    # T / T0 = 2 K(m) / pi with T0 = 2 pi / w0; the note's table: 1.11896, 1.13749, 1.15789, 1.18034
    assert period * w0 / (2 * math.pi) == pytest.approx(2 * ellipk(m) / math.pi, rel=1e-14)
    expected_ratio = {75.0: 1.11896, 80.0: 1.13749, 85.0: 1.15789, 90.0: 1.18034}[amplitude]
    assert period * w0 / (2 * math.pi) == pytest.approx(expected_ratio, abs=5e-6)


def test_measured_period_agrees_with_exact(fmu_path: Path) -> None:
    run = simulate(fmu_path, Scenario(amplitude_deg=85.0, periods=10), "CS")
    assert measured_period(run.result["time"], run.result["theta"]) == pytest.approx(run.scenario.period, rel=1e-6)


def test_coarse_and_fine_communication_grids_agree(fmu_any: Path) -> None:
    coarse = simulate(fmu_any, Scenario(amplitude_deg=80.0, periods=5, points_per_period=3), "CS", 1e-10)
    fine = simulate(fmu_any, Scenario(amplitude_deg=80.0, periods=5, points_per_period=300), "CS", 1e-10)
    common = fine.result[::100]
    assert np.allclose(common["time"], coarse.result["time"], rtol=0, atol=1e-12)
    assert np.max(np.abs(common["theta"] - coarse.result["theta"])) <= 1e-9


@pytest.mark.slow
def test_fmu_rebuilt_from_its_sources_gives_the_same_results(fmu_path: Path, tmp_path: Path) -> None:
    unzipped = rebuild_from_sources(fmu_path, tmp_path)
    assert (unzipped / "binaries/linux64/Pendulum.so").exists()
    scenario = Scenario(amplitude_deg=80.0, periods=2)
    original = simulate(fmu_path, scenario, "CS").result
    rebuilt = simulate(unzipped, scenario, "CS").result
    for name in ("theta", "omega", "theta_exact", "omega_exact"):  # bit for bit: contraction is off in both
        assert np.array_equal(rebuilt[name], original[name]), (name, np.max(np.abs(rebuilt[name] - original[name])))
