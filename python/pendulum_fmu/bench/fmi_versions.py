"""The accuracy table of the FMI 3.0 FMU beside the FMI 2.0 one, both run by fmpy's
``simulate_fmu`` alike.

Part 1, the seed's study: released from rest at 75..90 deg, ten exact periods, 50 points a
period; Co-Simulation at the default tolerance and Model Exchange (CVODE, rtol 1e-10);
max |theta - theta_exact| per FMU, and whether the two FMUs' results are bit-identical.
Part 2, the exact port in every regime: theta_exact from the FMI 3.0 FMU's Co-Simulation run
(3 s, 61 points) against mpmath's closed form at 50 digits.

Usage: ``python -m pendulum_fmu.bench.fmi_versions FMI2_FMU FMI3_FMU``.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
from fmpy import simulate_fmu

from pendulum_fmu.bench.reference import closed_form, exact_frequency, max_abs_diff
from pendulum_fmu.fmu.simulate import Scenario, simulate

W0 = math.sqrt(9.81)
REGIMES = {
    "10 deg": (math.radians(10.0), 0.0),
    "90 deg": (math.pi / 2, 0.0),
    "pi - 1e-6": (math.pi - 1e-6, 0.0),
    "separatrix - 1e-9": (0.0, 2 * W0 * (1 - 1e-9)),
    "separatrix + 1e-9": (0.0, 2 * W0 * (1 + 1e-9)),
    "rotation backward": (0.3, -3 * W0),
}


def seed_table(fmi2: Path, fmi3: Path) -> list[str]:
    """Rows of the seed study for both FMUs."""
    rows = ["| amplitude (deg) | interface | FMI 2.0 max abs(theta - theta_exact) | FMI 3.0 max abs(...) "
            "| bit-identical |", "|---|---|---|---|---|"]
    for amplitude in (75.0, 80.0, 85.0, 90.0):
        scenario = Scenario(amplitude_deg=amplitude, periods=10)
        for interface, tolerance in (("CS", None), ("ME", 1e-10)):
            runs = [simulate(fmu, scenario, interface, tolerance) for fmu in (fmi2, fmi3)]
            same = all(np.array_equal(runs[0].result[n], runs[1].result[n]) for n in runs[0].result.dtype.names)
            rows.append(f"| {amplitude:.0f} | {interface} | {runs[0].max_error:.2e} | {runs[1].max_error:.2e} "
                        f"| {'yes' if same else 'no'} |")
    return rows


def regime_table(fmu: Path) -> list[str]:
    """Rows of the exact port's accuracy in every regime."""
    rows = ["| case | max abs(theta_exact error) (rad) | max abs(omega_exact error) (rad/s) |", "|---|---|---|"]
    for name, (theta0, omega0) in REGIMES.items():
        result = simulate_fmu(str(fmu), start_time=0.0, stop_time=3.0, output_interval=0.05,
                              start_values={"theta": theta0, "omega": omega0},
                              output=["theta_exact", "omega_exact"], validate=False)
        theta, omega, _ = closed_form(theta0, omega0, exact_frequency(1.0, 9.81), list(result["time"]))
        rows.append(f"| {name} | {max_abs_diff(result['theta_exact'], theta):.1e} "
                    f"| {max_abs_diff(result['omega_exact'], omega):.1e} |")
    return rows


def main(argv: list[str]) -> int:
    """Prints both tables."""
    if len(argv) != 2:
        print("usage: python -m pendulum_fmu.bench.fmi_versions FMI2_FMU FMI3_FMU", file=sys.stderr)
        return 2
    fmi2, fmi3 = Path(argv[0]), Path(argv[1])
    print("\n".join(seed_table(fmi2, fmi3)))
    print()
    print("\n".join(regime_table(fmi3)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
