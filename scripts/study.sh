#!/usr/bin/env bash
# The main job: build Pendulum.fmu and run the seed's study; everything lands in out/study/.
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
exec pendulum-fmu study "$@"
