#!/usr/bin/env bash
# The main job: build both FMUs (build/Pendulum.fmu, FMI 2.0; build/fmi3/Pendulum.fmu, FMI 3.0) and run
# the seed's study; everything lands in out/study/.
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
bash scripts/build-fmu.sh > /dev/null   # the FMU the study runs is the one tested and shipped
exec pendulum-fmu study "$@"
