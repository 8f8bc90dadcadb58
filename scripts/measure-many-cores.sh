#!/usr/bin/env bash
# The sweep's and exact()'s scaling tables, measured where they count: on a machine with many cores.
#   bash scripts/measure-many-cores.sh [--quick] [--max-workers N]
# Builds the wheel of this checkout (pip wheel: CMake builds the FMU and the C libraries),
# installs it with its sweep and bench extras into a fresh virtual environment under
# $MANY_CORES_DIR (default: a new temporary folder), and runs scripts/many_cores.py with that
# environment's interpreter from an empty folder, so the installed package is measured, not the
# checkout. The tables go to stdout (Markdown); progress to stderr.
# Needs python3 (3.11 or newer), CMake and a C compiler; pip needs the package index, or a
# wheelhouse given as PIP_FIND_LINKS with PIP_NO_INDEX=1 on a machine without network.
set -euo pipefail
trap 'echo "measure-many-cores.sh: interrupted" >&2; exit 130' INT
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${MANY_CORES_DIR:-$(mktemp -d -t pendulum-many-cores.XXXXXX)}"
python="${PYTHON:-python3}"
mkdir -p "$work/wheel" "$work/run"
echo "[1/3] building the wheel into $work/wheel" >&2
"$python" -m venv "$work/build-venv"
"$work/build-venv/bin/python" -m pip install --quiet --upgrade pip >&2
"$work/build-venv/bin/python" -m pip wheel --quiet --no-deps "$root" -w "$work/wheel" >&2
wheel="$(ls "$work"/wheel/pendulum_fmu-*.whl | head -n 1)"
echo "[2/3] installing $(basename "$wheel") with its sweep and bench extras into $work/venv" >&2
"$python" -m venv "$work/venv"
"$work/venv/bin/python" -m pip install --quiet "${wheel}[sweep,bench]" >&2
echo "[3/3] measuring (several minutes)" >&2
cd "$work/run"
"$work/venv/bin/python" "$root/scripts/many_cores.py" "$@"
