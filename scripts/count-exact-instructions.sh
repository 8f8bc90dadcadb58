#!/usr/bin/env bash
# Instructions per point of the exact port (docs/speed-exact.md), counted with valgrind as the
# difference of two runs of build/tests/c/bench_exact --count (N and 2N points), which cancels
# the start-up: for each amplitude, eval (scalar loop), batch (lock-step), gsl
# (gsl_sf_elljac_e + atan2), init (new state + one evaluation), gsl_init (GSL's new state:
# gsl_sf_ellint_Kcomp_e + gsl_sf_elljac_e + atan2) and once (new states set up and evaluated
# in blocks by pendulum_exact_once_gl_many, as exact() does).
# Usage: bash scripts/count-exact-instructions.sh [N]   (default N = 4000)
set -euo pipefail
n="${1:-4000}"
bench="$(dirname "${BASH_SOURCE[0]}")/../build/tests/c/bench_exact"
count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bench" --count "$1" "$2" "$3" 2>&1 \
        | sed -n 's/.*I *refs: *\([0-9,]*\).*/\1/p' | tr -d ,
}
printf '%-12s %10s %10s %10s %10s %10s %10s\n' amplitude eval batch gsl init gsl_init once
for amplitude in 10 90 170 179.9999; do
    row=()
    for kind in eval batch gsl init gsl_init once; do
        one=$(count "$kind" "$n" "$amplitude")
        two=$(count "$kind" "$((2 * n))" "$amplitude")
        row+=("$(( (two - one) / n ))")
    done
    printf '%-12s %10s %10s %10s %10s %10s %10s\n' "$amplitude" "${row[@]}"
done
