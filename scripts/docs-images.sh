#!/usr/bin/env bash
# The documentation's figures, docs/img/*.png, each drawn by the command the page names beside it:
#   study_*.png        pendulum-fmu study (Figures 3-5, the period ratio, speed against error)
#   judge_cs_rk4.png   pendulum-fmu judge --plot, an rk4 run at tol 1e-6 (simulate) judged against the certificate
#   judge_me_euler.png pendulum-fmu judge --interface ME --plot, fmpy's explicit Euler at h = 0.01 (a FAIL)
#   bench_wp_P1.png    pendulum-fmu bench solvers --problems P1 --quick (the work-precision figure)
#   masters_wp.png     pendulum-fmu bench masters --no-engines --plot (the split pendulum's masters)
# then made small for the repository (256 colours, at most 1400 px wide; each < 150 kB,
# tests/package/test_docs_render.py checks it). About 3 minutes on two cores; run it after a change to
# the figure code and commit docs/img/. Needs .venv and the built FMU (bash scripts/study.sh makes
# both) and build/tests/c/bench_solvers (bash scripts/build-fmu.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BIN="$ROOT/.venv/bin"
FMU="${PENDULUM_FMU:-$ROOT/build/Pendulum.fmu}"
DRIVER="$ROOT/build/tests/c/bench_solvers"
for need in "$BIN/pendulum-fmu" "$FMU" "$DRIVER"; do
    if [ ! -e "$need" ]; then
        echo "docs-images.sh: $need is missing: bash scripts/study.sh (.venv, the FMU) and bash scripts/build-fmu.sh (the driver) make it" >&2
        exit 1
    fi
done
work="$(mktemp -d -t pendulum-docs-images-XXXXXX)"
trap 'rm -rf "$work"' EXIT
say() { echo "docs-images.sh: $*" >&2; }

say "[1/5] the study's figures (pendulum-fmu study, about 30 s) ..."
"$BIN/pendulum-fmu" study --fmu "$FMU" --out "$work/study" > /dev/null
for figure in fig3_numeric fig4_exact fig5_overlay period_ratio speed_vs_error; do
    cp "$work/study/$figure.png" "$work/study_$figure.png"
done

say "[2/5] the judge's plot of a Co-Simulation run (rk4, tol 1e-6, 85 deg, 10 periods) ..."
"$BIN/pendulum-fmu" simulate --fmu "$FMU" -a 85 -p 10 -s rk4 -t 1e-6 -o "$work/rk4.csv" > /dev/null
"$BIN/pendulum-fmu" judge "$work/rk4.csv" --fmu "$FMU" --start theta=85deg --start solver=2 \
    --start tolerance=1e-6 --plot "$work/judge_cs_rk4.png" > /dev/null

say "[3/5] the judge's plot of a Model Exchange run with fmpy's explicit Euler (h = 0.01) ..."
"$BIN/python" - "$FMU" "$work/euler.csv" <<'PY'
import sys

import numpy as np
from fmpy import simulate_fmu

result = simulate_fmu(sys.argv[1], fmi_type="ModelExchange", solver="Euler", step_size=0.01, stop_time=10.0,
                      output_interval=0.01, start_values={"theta": 1.4835},
                      output=["theta", "omega", "theta_exact", "omega_exact"])
np.savetxt(sys.argv[2], np.column_stack([result[name] for name in result.dtype.names]), delimiter=",",
           header=",".join(result.dtype.names), comments="", fmt="%.17g")
PY
# exit status 1: the judge fails the file, as it should
"$BIN/pendulum-fmu" judge "$work/euler.csv" --fmu "$FMU" --interface ME --start theta=1.4835 \
    --plot "$work/judge_me_euler.png" > /dev/null || [ $? -eq 1 ]

say "[4/5] the solvers' work-precision figure (bench solvers --problems P1 --quick, about a minute) ..."
"$BIN/pendulum-fmu" bench solvers --fmu "$FMU" --driver "$DRIVER" --problems P1 --quick \
    --out "$work/bench" > /dev/null
cp "$work/bench/wp_P1.png" "$work/bench_wp_P1.png"

say "[5/5] the masters' work-precision figure (bench masters --no-engines, about a minute and a half) ..."
# (the split FMUs of the package or of build/: bench masters takes no --fmu)
"$BIN/pendulum-fmu" bench masters --no-engines --plot "$work/masters_wp.png" > /dev/null

mkdir -p docs/img
"$BIN/python" - "$work" docs/img <<'PY'
"""Each figure as a 256-colour PNG at most 1400 px wide: the same picture at a tenth of the bytes."""
import sys
from pathlib import Path

from PIL import Image

source, target = Path(sys.argv[1]), Path(sys.argv[2])
for path in sorted(source.glob("*.png")):
    image = Image.open(path).convert("RGB")
    if image.width > 1400:
        image = image.resize((1400, round(image.height * 1400 / image.width)), Image.Resampling.LANCZOS)
    small = image.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    small.save(target / path.name, optimize=True)
    print(f"docs-images.sh: docs/img/{path.name} {(target / path.name).stat().st_size / 1000:.0f} kB", file=sys.stderr)
PY
