"""The accuracy table of the FMI 3.0 FMU beside the FMI 2.0 one, both run alike.

Part 1, the seed's study: released from rest at 75..90 deg, ten exact periods, 50 points a
period; Co-Simulation at the default tolerance and Model Exchange (CVODE, rtol 1e-10);
max |theta - theta_exact| per FMU, and whether the two FMUs' results are bit-identical.
Part 2, the exact port in every regime: theta_exact from the FMI 3.0 FMU's Co-Simulation run
(3 s, 61 points) against mpmath's closed form at 50 digits.

Both FMUs run through :class:`~pendulum_fmu.fmu.runner.FmuRunner`, the package's one path;
``pendulum-fmu bench fmi-versions`` prints the tables, and after them
:mod:`pendulum_fmu.bench.cvode_jacobian`'s for both FMUs.
"""

from __future__ import annotations

import math

from pendulum_fmu.bench.reference import closed_form, exact_frequency, max_abs_diff
from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

W0 = math.sqrt(9.81)
REGIMES = {
    "10 deg": (math.radians(10.0), 0.0),
    "90 deg": (math.pi / 2, 0.0),
    "pi - 1e-6": (math.pi - 1e-6, 0.0),
    "separatrix - 1e-9": (0.0, 2 * W0 * (1 - 1e-9)),
    "separatrix + 1e-9": (0.0, 2 * W0 * (1 + 1e-9)),
    "rotation backward": (0.3, -3 * W0),
}
SEED_METHODS = (Method(), Method("cvode", 1e-10))
"""Co-Simulation at the FMU's default tolerance; Model Exchange with CVODE at 1e-10."""


def seed_table(fmi2: FmuRunner, fmi3: FmuRunner) -> list[str]:
    """Rows of the seed study for both FMUs."""
    rows = ["| amplitude (deg) | interface | FMI 2.0 max abs(theta - theta_exact) | FMI 3.0 max abs(...) "
            "| bit-identical |", "|---|---|---|---|---|"]
    grid = TimeGrid(10, "periods", 50)
    for amplitude in (75.0, 80.0, 85.0, 90.0):
        problem = InitialValueProblem.from_degrees(amplitude)
        for method in SEED_METHODS:
            two, three = (runner.run(problem, method, grid)
                          for runner in (fmi2, fmi3))
            same = two.result.tobytes() == three.result.tobytes()
            rows.append(f"| {amplitude:.0f} | {method.interface} | {two.max_error:.2e} | {three.max_error:.2e} "
                        f"| {'yes' if same else 'no'} |")
    return rows


def regime_table(runner: FmuRunner) -> list[str]:
    """Rows of the exact port's accuracy in every regime."""
    rows = ["| case | max abs(theta_exact error) (rad) | max abs(omega_exact error) (rad/s) |", "|---|---|---|"]
    grid = TimeGrid(3.0, "s", output_interval=0.05)
    for name, (theta0, omega0) in REGIMES.items():
        problem = InitialValueProblem(theta0, omega0)
        result = runner.run(problem, Method(), grid).result
        theta, omega, _ = closed_form(theta0, omega0, exact_frequency(1.0, 9.81), list(result["time"]))
        rows.append(f"| {name} | {max_abs_diff(result['theta_exact'], theta):.1e} "
                    f"| {max_abs_diff(result['omega_exact'], omega):.1e} |")
    return rows
