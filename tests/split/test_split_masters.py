"""The reference masters of pendulum_fmu.split.masters (docs/masters.md).

They drive the real PendulumBody and PendulumGravity FMUs through fmpy; here they are held
against the same masters written without the FMUs (tests/helpers/split_closed_form.py), against the
exact pendulum (Body's theta_exact and pendulum_fmu.exact), and their orders are measured:
halving H halves the error of a zero-order-hold master (order 1 within 0.2), extrapolation
from output derivatives gives order 2, input interpolation order 3, and strong coupling (each
macro step iterated with rollback through the FMU states) order 3 with a third of
Gauss-Seidel's error, converged to round-off in a few passes.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pendulum_fmu import exact
from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.masters import (
    ITERATION_CAP,
    MASTERS,
    Master,
    master_named,
    masters_for,
    observed_orders,
    run_master,
)
from pendulum_fmu.split.pair import DEFAULT_PROBLEM
from split_closed_form import simulate

STOP = 2.0


@pytest.mark.parametrize("master", MASTERS, ids=lambda m: m.name)
def test_masters_equal_the_closed_form(master: Master) -> None:
    """Through the FMUs, each master's theta and omega equal the closed form's to 1e-13
    (75 deg and a rotation with L = 2)."""
    for problem in (DEFAULT_PROBLEM, InitialValueProblem(L=2.0, g=9.81, theta0=0.3, omega0=4.5)):
        fmus = run_master(master, 0.05, STOP, problem)
        again = simulate(master.scheme, master.coupling, 0.05, STOP, problem.theta0, problem.omega0, problem.L,
                         problem.g)
        assert np.max(np.abs(fmus.theta - np.array(again.theta))) < 1e-13
        assert np.max(np.abs(fmus.omega - np.array(again.omega))) < 1e-13
        assert np.allclose(fmus.time, again.time, rtol=0, atol=1e-15)


def test_theta_exact_is_the_exact_pendulum() -> None:
    """Body's theta_exact (the error's reference) against pendulum_fmu.exact at the same times."""
    problem = InitialValueProblem(L=1.5, g=9.81, theta0=2.8, omega0=0.0)
    run = run_master(master_named("gauss-seidel-zoh"), 0.01, STOP, problem)
    theta, omega = exact(problem.theta0, problem.omega0, problem.L, problem.g, run.time)
    assert np.max(np.abs(run.theta_exact - theta)) < 1e-12
    assert np.max(np.abs(run.omega_exact - omega)) < 1e-12


@pytest.mark.parametrize(("coupling", "order", "steps"), [
    ("zoh", 1.0, (0.01, 0.005, 0.0025)),
    ("extrapolation", 2.0, (0.01, 0.005, 0.0025)),
    ("interpolation", 3.0, (0.02, 0.01, 0.005)),
])
@pytest.mark.parametrize("scheme", ["jacobi", "gauss-seidel"])
def test_orders(scheme: str, coupling: str, order: float, steps: tuple[float, ...]) -> None:
    """Halving H divides the error by 2^order (within 0.2)."""
    errors = [run_master(Master(scheme, coupling), h, STOP).error for h in steps]
    for measured in observed_orders(list(steps), errors):
        assert abs(measured - order) < 0.2, (errors, measured)


def test_strong_coupling_has_order_three() -> None:
    errors = [run_master(master_named("iterated-interpolation"), h, STOP).error for h in (0.02, 0.01, 0.005)]
    for measured in observed_orders([0.02, 0.01, 0.005], errors):
        assert abs(measured - 3.0) < 0.2, (errors, measured)


def test_strong_coupling_converges_in_a_few_passes_and_reports_them() -> None:
    """Each pass shrinks the change of alpha at the step's end by (g/L) |cos theta| H^2 / 12: at
    H = 0.1 (0.08) the passes number more than at H = 0.01 (8e-5), all below the cap; the
    converged step is its own fixed point: one more pass changes alpha(t + H) by round-off only.
    Beyond H = sqrt(12 L / g) the iteration cannot converge, and the run says so."""
    master = master_named("iterated-interpolation")
    coarse, fine = run_master(master, 0.1, STOP), run_master(master, 0.01, STOP)
    assert coarse.converged and fine.converged and coarse.iterations is not None and fine.iterations is not None
    assert 2 <= fine.iterations.max() <= 5 < coarse.iterations.max() < 15, (coarse.iterations, fine.iterations)
    assert coarse.iterations.shape == (20,) and fine.iterations.shape == (200,)
    one_pass = run_master(master_named("gauss-seidel-zoh"), 0.1, STOP).iterations
    assert one_pass is not None and np.all(one_pass == 1)
    # the fixed point: each step is Body's closed form for the quadratic input through alpha_k,
    # alpha'_k = -(g/L) cos(theta_k) omega_k and alpha_(k+1) = -(g/L) sin(theta_(k+1)) of the step's own end
    H, k = 0.01, 9.81
    theta, omega, alpha = fine.theta, fine.omega, -k * np.sin(fine.theta)
    slope = -k * np.cos(theta[:-1]) * omega[:-1]
    c = 2 * (alpha[1:] - alpha[:-1] - slope * H) / H ** 2
    assert np.max(np.abs(omega[:-1] + alpha[:-1] * H + slope * H ** 2 / 2 + c * H ** 3 / 6 - omega[1:])) < 1e-13
    assert np.max(np.abs(theta[:-1] + omega[:-1] * H + alpha[:-1] * H ** 2 / 2 + slope * H ** 3 / 6
                         + c * H ** 4 / 24 - theta[1:])) < 1e-13
    diverging = run_master(master, 1.5, 3.0)
    assert not diverging.converged and diverging.iterations is not None
    assert diverging.iterations.max() == ITERATION_CAP


def test_gauss_seidel_beats_jacobi_and_interpolation_beats_hold() -> None:
    """At H = 0.01 over 2 s from 75 deg: Jacobi's hold lags one step and costs about 3 times
    Gauss-Seidel's error; interpolation is 1,000 times better than hold."""
    errors = {m.name: run_master(m, 0.01, STOP).error for m in MASTERS}
    assert 2.5 < errors["jacobi-zoh"] / errors["gauss-seidel-zoh"] < 3.5, errors
    assert errors["gauss-seidel-interpolation"] < errors["gauss-seidel-zoh"] / 1000, errors
    assert errors["gauss-seidel-extrapolation"] < errors["gauss-seidel-zoh"] / 50, errors
    # strong coupling: about a third of the best explicit master's error (0.33 at 10 s)
    assert 0.2 < errors["iterated-interpolation"] / errors["gauss-seidel-interpolation"] < 0.45, errors


def test_fmi3_has_zero_order_hold_only_with_the_same_numbers() -> None:
    """FMI 3.0 Co-Simulation has no input derivatives: hold only, bit for bit FMI 2.0's."""
    assert [m.coupling for m in masters_for(3)] == ["zoh", "zoh"]
    for master in masters_for(3):
        two, three = run_master(master, 0.02, STOP), run_master(master, 0.02, STOP, fmi_version=3)
        assert np.array_equal(two.theta, three.theta)
    with pytest.raises(ValueError, match="input and output derivatives"):
        run_master(master_named("gauss-seidel-interpolation"), 0.02, STOP, fmi_version=3)


def test_master_names() -> None:
    assert [m.name for m in MASTERS][:2] == ["jacobi-zoh", "gauss-seidel-zoh"]
    assert master_named("jacobi-extrapolation").describe() == "Jacobi with first-order extrapolation"
    assert master_named("iterated-interpolation").describe() == "strong coupling with input interpolation"
    assert [m.name for m in MASTERS][-1] == "iterated-interpolation" and len(MASTERS) == 7
    with pytest.raises(ValueError, match="one of jacobi-zoh"):
        master_named("euler")


def test_split_path_finds_both_packages() -> None:
    import zipfile

    import pendulum_fmu

    for version in (2, 3):
        path = pendulum_fmu.split_path(fmi_version=version)
        assert path.name == "PendulumSplit.ssp" and path.is_file()
        with zipfile.ZipFile(path) as archive:
            assert {"SystemStructure.ssd", "resources/PendulumBody.fmu"} <= set(archive.namelist())
    assert math.isfinite(float(pendulum_fmu.split_path().stat().st_size))
