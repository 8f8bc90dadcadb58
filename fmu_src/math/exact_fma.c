/* exact_fma.c: dd.c, elliptic.c and exact.c compiled again for processors with a fused
 * multiply-add, their public functions renamed with the suffix _fma (see exact_fma.h for why
 * the bits are the same and when this build is used). Empty where exact_fma.h builds no
 * second copy. */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
/* the system's headers first, outside the region whose functions take the fma */
#include <float.h>
#include <immintrin.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#ifdef __clang__
#pragma clang attribute push(__attribute__((target("fma"))), apply_to = function)
#else
#pragma GCC target("fma")
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
/* exact.c: this copy does not hand calls on */
#define PENDULUM_EXACT_FMA_PASS 1

/* the public functions named with _fma */
#ifndef EXACT_COPY   /* a test's copy names them its own way */
#define EXACT_COPY(name) name##_fma
#endif
#include "core_copy.h"
#ifdef __clang__
#pragma clang attribute pop
#endif

#else
typedef int exact_fma_not_built;   /* ISO C: a translation unit declares something */
#endif
