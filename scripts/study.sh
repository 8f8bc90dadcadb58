#!/usr/bin/env bash
# The main job: build both FMUs (build/Pendulum.fmu, FMI 2.0; build/fmi3/Pendulum.fmu, FMI 3.0) and run
# the seed's study; everything lands in out/study/.
ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ -x "$ROOT_DIR/.venv/bin/python" ] || echo "study.sh: creating the Python environment .venv (about a minute, once) ..." >&2
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
# The FMU the study runs is the one tested and shipped. The first build compiles the FMUs for
# every platform with zig and takes a few minutes: say so, and show CMake's output when it fails.
[ -f build/Pendulum.fmu ] || echo "study.sh: building the FMUs (FMI 2.0 and 3.0, every platform; a few minutes the first time) ..." >&2
build_log="$(mktemp -t pendulum-build-XXXXXX.log)"
if ! bash scripts/build-fmu.sh > "$build_log" 2>&1; then
    tail -n 30 "$build_log" >&2
    echo "study.sh: building the FMUs failed (the last lines of its output are above)" >&2
    rm -f "$build_log"
    exit 1
fi
rm -f "$build_log"
exec pendulum-fmu study "$@"
