/* core_copy.h: dd.c, elliptic.c and exact.c compiled once more in this translation unit, as a
 * copy beside the core's own functions. The file that includes this defines EXACT_COPY(name),
 * the copy's name of each public function, and, for a copy that a processor with more than
 * the baseline runs (exact_fma.c, avx512_copy.c), EXACT_COPY_TARGET, the instructions it
 * enables ("fma", "fma,avx512f"); a test that compares a build with the core defines its own
 * build's macros instead. */
#ifdef EXACT_COPY_TARGET
/* the system's headers first, outside the region whose functions take EXACT_COPY_TARGET */
#include <float.h>
#include <immintrin.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
/* #pragma with the target's text (C99 6.10.9: _Pragma of a string literal) */
#define CORE_COPY_PRAGMA_TEXT(...) _Pragma(#__VA_ARGS__)
#define CORE_COPY_PRAGMA(...) CORE_COPY_PRAGMA_TEXT(__VA_ARGS__)
#ifdef __clang__
CORE_COPY_PRAGMA(clang attribute push(__attribute__((target(EXACT_COPY_TARGET))), apply_to = function))
#else
CORE_COPY_PRAGMA(GCC target(EXACT_COPY_TARGET))
#endif
/* No contraction of a*b+c into an fma here either, whatever the build's flags say (a build from
 * the FMU's sources may not pass -ffp-contract=off, and GCC contracts by default in its GNU
 * modes once the target has an fma): only the two-products' explicit fma calls are fused. */
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#else
#pragma GCC optimize("fp-contract=off")
#endif
/* the two-products of dd.h and the phase's product in exact.c take the fma */
#define PENDULUM_DD_FMA 1
/* exact.c: a copy does not hand calls on */
#define PENDULUM_EXACT_FMA_PASS 1
#endif

#define dd_sincos EXACT_COPY(dd_sincos)
#define dd_cos_sin EXACT_COPY(dd_cos_sin)
#define dd_cos_sin_begin EXACT_COPY(dd_cos_sin_begin)
#define dd_cos_sin_end EXACT_COPY(dd_cos_sin_end)
#define dd_sin EXACT_COPY(dd_sin)
#define elliptic_RF EXACT_COPY(elliptic_RF)
#define elliptic_param_init EXACT_COPY(elliptic_param_init)
#define elliptic_param_init_root EXACT_COPY(elliptic_param_init_root)
#define elliptic_param_begin EXACT_COPY(elliptic_param_begin)
#define elliptic_param_finish EXACT_COPY(elliptic_param_finish)
#define elliptic_quarter_of EXACT_COPY(elliptic_quarter_of)
#define pendulum_exact_init EXACT_COPY(pendulum_exact_init)
#define pendulum_exact_init_gl EXACT_COPY(pendulum_exact_init_gl)
#define pendulum_exact_same EXACT_COPY(pendulum_exact_same)
#define pendulum_exact_resolvable EXACT_COPY(pendulum_exact_resolvable)
#define pendulum_exact_eval EXACT_COPY(pendulum_exact_eval)
#define pendulum_exact_sin_cos EXACT_COPY(pendulum_exact_sin_cos)
#define pendulum_exact_eval_many EXACT_COPY(pendulum_exact_eval_many)
#define pendulum_exact_once_gl_many EXACT_COPY(pendulum_exact_once_gl_many)
#define pendulum_exact_qualitative_miss EXACT_COPY(pendulum_exact_qualitative_miss)
#define pendulum_exact_period EXACT_COPY(pendulum_exact_period)

#include "dd.c"
#include "elliptic.c"
#include "exact.c"

#if defined(EXACT_COPY_TARGET) && defined(__clang__)
#pragma clang attribute pop
#endif
