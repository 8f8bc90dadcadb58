#!/usr/bin/env bash
# The benchmarks that time the repository's C test programs. The package carries no test
# program and looks for none; this script builds the one a benchmark needs, with the FMU, and
# hands it over:
#   bash scripts/bench.sh solvers [options of bench solvers]  # tests/c/bench_solvers: the FMU's solvers and the floor
#                                                             # in C, the study judged against the solvers' targets
#                                                             # (tests/lab/solver_targets.py)
#   bash scripts/bench.sh exact [options of bench exact]      # tests/c/bench_exact: the C columns (eval, batch, GSL, init)
# $PENDULUM_FMU_BUILD_DIR chooses the CMake build folder (default: build/, configured here if new).
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
usage="usage: bash scripts/bench.sh solvers|exact [options of tests/lab/solver_targets.py|pendulum-fmu bench exact]"
if [ $# -lt 1 ]; then
    echo "$usage" >&2
    exit 2
fi
benchmark="$1"
shift
build="${PENDULUM_FMU_BUILD_DIR:-build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPENDULUM_PYTHON="$VENV/bin/python" >&2
fi
case "$benchmark" in
    solvers)
        cmake --build "$build" --target fmu bench_solvers --parallel "$(nproc)" >&2
        exec "$VENV/bin/python" tests/lab/solver_targets.py --fmu "$build/Pendulum.fmu" \
            --driver "$build/tests/c/bench_solvers" "$@"
        ;;
    exact)
        # the Python columns from this build's pendulum_exact too, not from another build's
        cmake --build "$build" --target pendulum_exact bench_exact --parallel "$(nproc)" >&2
        export PENDULUM_EXACT_LIB="${PENDULUM_EXACT_LIB:-$build/libpendulum_exact.so}"
        exec pendulum-fmu bench exact --exe "$build/tests/c/bench_exact" "$@"
        ;;
    *)
        echo "$usage" >&2
        exit 2
        ;;
esac
