#!/usr/bin/env bash
# All tests from scratch: the linter and the type checker, C unit tests (ctest) in a normal and a
# sanitizer build, valgrind, then pytest. Each step says what it does; the builds show CMake's
# stages, ctest and pytest their own progress.
#   bash scripts/test.sh [PYTEST ARGS...]          everything (CI, .ci/run: 21 minutes here from a fresh clone)
#   bash scripts/test.sh --fast [PYTEST ARGS...]   while working (about 4 minutes here): ruff, mypy,
#       ctest -LE slow of the Release build (all but the libFuzzer run), and
#       pytest -m "not slow and not engines" (the markers of pyproject.toml)
fast=0
if [ "${1:-}" = "--fast" ]; then
    fast=1
    shift
fi
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
jobs="$(nproc)"
echo "== lint and types: ruff check python tests, mypy (settings in pyproject.toml)"
ruff check python tests
mypy
echo "== C tests (Release; the build also makes the linux64/win64/darwin64 FMU, scripts/build-fmu.sh)"
say "building build/ (seconds when up to date, minutes the first time) ..."
run_step "$CMAKE_STAGES" bash scripts/build-fmu.sh
export PENDULUM_FMU="$ROOT/build/Pendulum.fmu"
if [ "$fast" = 1 ]; then
    echo "== C tests, fast: all but the libFuzzer run (ctest -LE slow)"
    ctest --test-dir build --output-on-failure --parallel "$jobs" -LE slow
    echo "== Python tests, fast: not the slow ones nor the external engines (bash scripts/test.sh runs them)"
    exec python -m pytest -m "not slow and not engines" "$@"
fi
ctest --test-dir build --output-on-failure --parallel "$jobs"
echo "== C tests (AddressSanitizer + UndefinedBehaviorSanitizer)"
say "building build-sanitize/ (Debug, ASan + UBSan; minutes the first time) ..."
run_step "$CMAKE_STAGES" cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DPENDULUM_SANITIZE=ON
run_step "$CMAKE_STAGES" cmake --build build-sanitize --parallel "$jobs"
ctest --test-dir build-sanitize --output-on-failure --parallel "$jobs"
echo "== valgrind memcheck of the FMI harness"
harnesses=(test_fmi_api test_fmi_threads test_fmi3_api test_fmi_conformance test_fmi3_conformance test_split_states)
if ! command -v valgrind > /dev/null; then
    # skipped with its install command, unless PENDULUM_NO_SKIP=1 (CI, whose install script provides it)
    say "skipped: valgrind not found, install it with: apt-get install valgrind"
    [ "${PENDULUM_NO_SKIP:-}" != 1 ] || { say "PENDULUM_NO_SKIP=1 requires every test to run"; exit 1; }
    harnesses=()
fi
for k in "${!harnesses[@]}"; do
    say "valgrind $((k + 1)) of ${#harnesses[@]}: ${harnesses[k]} ..."
    valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=all \
        "build/tests/c/${harnesses[k]}"
done
echo "== Python tests"
exec python -m pytest "$@"
