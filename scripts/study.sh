#!/usr/bin/env bash
# The main job: build both FMUs (build/Pendulum.fmu, FMI 2.0; build/fmi3/Pendulum.fmu, FMI 3.0) and run
# the seed's study; everything lands in out/study/. Each step says what it does on stderr: the
# first run creates .venv and builds the FMUs for every platform (minutes), a later one takes seconds.
ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT_DIR/scripts/setup-env.sh"
# The FMU the study runs is the one tested and shipped (seconds when build/ is up to date; after a
# change, every platform is compiled again with zig): CMake's stages as they come, its output on failure.
say "building the FMUs (scripts/build-fmu.sh: FMI 2.0 and 3.0, every platform; seconds when up to date) ..."
run_step "$CMAKE_STAGES" bash scripts/build-fmu.sh
say "running the study (pendulum-fmu study $*) ..."
exec pendulum-fmu study "$@"
