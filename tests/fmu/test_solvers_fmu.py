"""The FMU's Co-Simulation solvers through fmpy, judged by the FMU's own exact solution.

Convergence order of each method on P1 (75..90 deg, 10 periods), the default solver near the
separatrix (P2: 179.99 deg, 20 periods) at every tolerance, grid independence, and the energy
behaviour over a long horizon (P3, 90 deg, shortened to 2000 periods).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.model_description import ModelDescription

from pendulum_fmu.spec import CS_SOLVERS

P1_AMPLITUDES = (75.0, 80.0, 85.0, 90.0)
W0SQ = 9.81


@pytest.fixture(scope="module")
def unzipped(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return Path(extract(str(fmu_path), unzipdir=str(tmp_path_factory.mktemp("fmu"))))


@pytest.fixture(scope="module")
def md(unzipped: Path) -> ModelDescription:
    return read_model_description(str(unzipped), validate=False)


def _period(unzipped: Path, md: ModelDescription, amplitude: float) -> float:
    result = simulate_fmu(str(unzipped), model_description=md, stop_time=1e-3, output_interval=1e-3,
                          start_values={"theta": math.radians(amplitude)}, output=["period"])
    return float(result["period"][0])


def _run(unzipped: Path, md: ModelDescription, solver: str | None, tol: float, amplitude: float, periods: float,
         points: int, extra: tuple[str, ...] = ()) -> np.ndarray:
    """One Co-Simulation run; solver None keeps the FMU's default."""
    period = _period(unzipped, md, amplitude)
    start: dict[str, float | int] = {"theta": math.radians(amplitude)}
    if solver is not None:
        start["solver"] = CS_SOLVERS.index(solver) + 1
    return simulate_fmu(str(unzipped), model_description=md, stop_time=periods * period,
                        output_interval=period / points, relative_tolerance=tol, start_values=start,
                        output=["theta", "omega", "theta_exact", "stats.steps", "stats.rhs_evaluations", *extra])


def _p1(unzipped: Path, md: ModelDescription, solver: str, tol: float) -> tuple[float, int]:
    """P1 at one tolerance: the largest error over the four amplitudes and the steps taken."""
    error, steps = 0.0, 0
    for amplitude in P1_AMPLITUDES:
        r = _run(unzipped, md, solver, tol, amplitude, 10, 50)
        error = max(error, float(np.max(np.abs(r["theta"] - r["theta_exact"]))))
        steps += int(r["stats.steps"][-1])
    return error, steps


# solver, tolerances whose steps halve one after the other, expected order, allowed band.
# RK4 and the composition take a fixed step h ~ tol^(1/4) and tol^(1/8): tol / 16 and
# tol / 256 halve it exactly (the RK4 range starts where its h^5 term no longer counts; the
# composition's range ends above its rounding floor: its step rule asks 1e-3 tol of the phase
# per unit time).
# The adaptive pairs' steps halve when tol falls by about 2^(q): 32 for DOPRI5, 2048 for
# the 12th-order pair; their order is read from the steps actually taken. DOPRI5 is
# 5th-order; its energy projection adds accuracy (observed 5.6 over the range), never loses it.
ORDER_CASES = [
    ("rk4", (2.44140625e-10, 2.44140625e-10 / 16, 2.44140625e-10 / 256), 4.0, 0.25),
    ("symplectic", (1e-5, 1e-5 / 256, 1e-5 / 65536), 8.0, 0.6),
    ("dopri5", (1e-5, 1e-5 / 32, 1e-5 / 1024), 6.0, 1.2),
    ("rkn", (1e-5, 1e-5 / 2048), 12.0, 1.0),
]


@pytest.mark.parametrize(("solver", "tols", "order", "band"), ORDER_CASES, ids=[c[0] for c in ORDER_CASES])
def test_convergence_order_on_p1(unzipped: Path, md: ModelDescription, solver: str, tols: tuple[float, ...],
                                 order: float, band: float) -> None:
    results = [_p1(unzipped, md, solver, tol) for tol in tols]
    for (_, n1), (_, n2) in zip(results, results[1:], strict=False):
        assert n2 / n1 == pytest.approx(2.0, rel=0.1), f"steps {n1} -> {n2}: the step did not halve"
    # the order over the whole range of steps (DOPRI5's projected errors alternate between the
    # halvings: 7.35 then 3.90 under the certificate's step rules, 5.6 over both)
    (e1, n1), (e2, n2) = results[0], results[-1]
    observed = math.log(e1 / e2) / math.log(n2 / n1)
    assert abs(observed - order) <= band, f"{solver}: errors {e1:.3g} -> {e2:.3g}, observed order {observed:.2f}"


def test_default_solver_is_the_12th_order_nystrom_pair(md: ModelDescription) -> None:
    solver = next(v for v in md.modelVariables if v.name == "solver")
    assert CS_SOLVERS[int(solver.start) - 1] == "rkn"
    assert "12(10)" in next(i for i in md.typeDefinitions[0].items if i.name == "rkn").description
    stats = [v for v in md.modelVariables if v.name.startswith("stats.")]
    assert [v.causality for v in stats] == ["local"] * 3  # readable, but not among a scene's outputs


P2_TOLS = tuple(10.0**-k for k in range(3, 13))


@pytest.fixture(scope="module")
def p2_default(unzipped: Path, md: ModelDescription) -> list[tuple[float, float, float]]:
    """(tol, max error, max |theta|) of the default solver on P2 at every tolerance."""
    rows = []
    for tol in P2_TOLS:
        r = _run(unzipped, md, None, tol, 179.99, 20, 50)
        rows.append((tol, float(np.max(np.abs(r["theta"] - r["theta_exact"]))), float(np.max(np.abs(r["theta"])))))
    return rows


def test_default_never_turns_the_libration_near_the_top_into_a_rotation(
        p2_default: list[tuple[float, float, float]]) -> None:
    for tol, _, max_abs in p2_default:
        assert max_abs < math.pi, f"tol {tol:g}: |theta| reached {max_abs!r}"


def test_default_error_near_the_top_shrinks_with_the_tolerance(p2_default: list[tuple[float, float, float]]) -> None:
    # Down to the rounding floor of double precision near the top (1e-11 to 4e-11):
    # there theta = pi - 1.7e-4 is held to ulp(pi), 2.5e-12 of its distance from the saddle,
    # and each passage's rounding shifts the time spent up there.
    floor = 5e-11
    for (tol1, e1, _), (tol2, e2, _) in zip(p2_default, p2_default[1:], strict=False):
        # within 2 tol: omega's absolute tolerance is tol w0 (the same steps at
        # every L and g), and tol 1e-6 gives 1.8e-6 here (the certificate's bound: 100 tol)
        assert e1 <= max(2 * tol1, floor) and e2 <= max(2 * tol2, floor)
        assert e2 < e1 or e1 < floor, f"tol {tol1:g} -> {tol2:g}: error {e1:.3g} -> {e2:.3g}"
    assert p2_default[-1][1] < 1e-4 * p2_default[0][1]


def test_dopri5_also_keeps_the_libration(unzipped: Path, md: ModelDescription) -> None:
    for tol in (1e-3, 1e-6, 1e-9, 1e-12):
        r = _run(unzipped, md, "dopri5", tol, 179.99, 20, 50)
        assert np.max(np.abs(r["theta"])) < math.pi, tol


@pytest.mark.parametrize("solver", CS_SOLVERS)
def test_coarse_and_fine_grids_agree(unzipped: Path, md: ModelDescription, solver: str) -> None:
    # the solver's steps never depend on the communication points: 3 and 300 points a
    # period give the same values at the common points (the target is 1e-7; by design they
    # differ only by rounding: fmpy's times i T/3 and 100 i T/300 differ in the last bit)
    for amplitude in (75.0, 90.0):
        coarse = _run(unzipped, md, solver, 1e-10, amplitude, 10, 3)
        fine = _run(unzipped, md, solver, 1e-10, amplitude, 10, 300)[::100]
        assert np.allclose(coarse["time"], fine["time"], rtol=1e-15, atol=0.0)
        assert np.max(np.abs(coarse["theta"] - fine["theta"])) <= 1e-12
        assert np.max(np.abs(coarse["omega"] - fine["omega"])) <= 1e-11
        assert np.max(np.abs(coarse["theta"] - coarse["theta_exact"])) <= 1e-6


def _energy_drift(unzipped: Path, md: ModelDescription, solver: str, tol: float) -> tuple[float, float, int]:
    """P3 shortened: 90 deg for 2000 periods, 20 points a period; max |dH/H| over the first
    and the last tenth of the points, and the evaluations."""
    r = _run(unzipped, md, solver, tol, 90.0, 2000, 20)
    h = 0.5 * r["omega"] ** 2 + 2 * W0SQ * np.sin(0.5 * r["theta"]) ** 2
    rel = np.abs(h - W0SQ) / W0SQ  # H0 = 2 w0^2 sin^2(45 deg) = w0^2
    tenth = len(rel) // 10
    return float(np.max(rel[:tenth])), float(np.max(rel[-tenth:])), int(r["stats.rhs_evaluations"][-1])


def test_symplectic_energy_error_stays_bounded_over_a_long_horizon(unzipped: Path, md: ModelDescription) -> None:
    first, last, evals = _energy_drift(unzipped, md, "symplectic", 1e-8)
    assert last < 1e-6
    assert last < 1.5 * first, f"energy error grew from {first:.3g} to {last:.3g}"
    rk_first, rk_last, rk_evals = _energy_drift(unzipped, md, "rk4", 1e-8)
    assert rk_evals > evals  # RK4 spends more and drifts all the same
    assert rk_last > 5 * rk_first, f"RK4 was expected to drift: {rk_first:.3g} then {rk_last:.3g}"


def test_default_keeps_the_energy_to_rounding_over_a_long_horizon(unzipped: Path, md: ModelDescription) -> None:
    first, last, _ = _energy_drift(unzipped, md, "rkn", 1e-10)
    assert max(first, last) < 1e-13
