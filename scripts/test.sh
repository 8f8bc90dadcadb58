#!/usr/bin/env bash
# All tests from scratch: C unit tests (ctest) in a normal and a sanitizer build, then pytest.
source "$(dirname "${BASH_SOURCE[0]}")/setup-env.sh"
jobs="$(nproc)"
echo "== C tests (Release; the build also makes the linux64/win64/darwin64 FMU, scripts/build-fmu.sh)"
bash scripts/build-fmu.sh > /dev/null
ctest --test-dir build --output-on-failure
echo "== C tests (AddressSanitizer + UndefinedBehaviorSanitizer)"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DPENDULUM_SANITIZE=ON > /dev/null
cmake --build build-sanitize --parallel "$jobs" > /dev/null
ctest --test-dir build-sanitize --output-on-failure
echo "== valgrind memcheck of the FMI harness"
for harness in test_fmi_api test_fmi_threads test_fmi3_api test_fmi_conformance test_fmi3_conformance; do
    valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=all \
        "build/tests/c/$harness"
done
echo "== Python tests"
export PENDULUM_FMU="$ROOT/build/Pendulum.fmu"
exec python -m pytest "$@"
