"""How close fmpy's CVODE comes to the judge's Model Exchange bound, 0..20 s at 0.01 s:
the worst |error| / bound over theta and omega, per problem and tolerance (< 1 passes).
docs/importers.md quotes this table::

    .venv/bin/python tests/me_bound_table.py [build/Pendulum.fmu]
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from fmpy import simulate_fmu

from pendulum_fmu.judge import judge

PROBLEMS = {"10 deg": (math.radians(10), 0.0), "75 deg": (math.radians(75), 0.0), "90 deg": (math.radians(90), 0.0),
            "150 deg": (math.radians(150), 0.0), "170 deg": (math.radians(170), 0.0),
            "rotation (omega0 = 7)": (0.0, 7.0)}
TOLERANCES = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)


def main(argv: list[str]) -> int:
    fmu = Path(argv[0]) if argv else Path(__file__).resolve().parents[1] / "build/Pendulum.fmu"
    print(f"{'problem':22s}" + "".join(f"{'tol ' + format(t, 'g'):>11s}" for t in TOLERANCES))
    for name, (theta, omega) in PROBLEMS.items():
        cells = []
        for tol in TOLERANCES:
            run = simulate_fmu(str(fmu), fmi_type="ModelExchange", relative_tolerance=tol, stop_time=20.0,
                               output_interval=0.01, start_values={"theta": theta, "omega": omega},
                               output=["theta", "omega"])
            verdict = judge(run, start={"theta": theta, "omega": omega, "tolerance": tol}, interface="ME", fmu=fmu)
            cells.append(verdict.check("bound").figures["worst_ratio"])
        print(f"{name:22s}" + "".join(f"{c:11.3g}" for c in cells))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
