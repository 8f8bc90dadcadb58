/* exact_fma.c: dd.c, elliptic.c and exact.c compiled again for processors with a fused
 * multiply-add, their public functions renamed with the suffix _fma (see exact_fma.h for why
 * the bits are the same and when this build is used). Empty where exact_fma.h builds no
 * second copy. */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
#pragma GCC target("fma")
/* No contraction of a*b+c into an fma here either, whatever the build's flags say (a build from
 * the FMU's sources may not pass -ffp-contract=off, and GCC contracts by default in its GNU
 * modes once the target has an fma): only the two-products' explicit fma calls are fused. */
#pragma GCC optimize("fp-contract=off")

/* the two-products of dd.h and the phase's product in exact.c take the fma */
#define PENDULUM_DD_FMA 1
/* exact.c: this copy does not hand calls on */
#define PENDULUM_EXACT_FMA_PASS 1

#define dd_sincos dd_sincos_fma
#define dd_cos_sin dd_cos_sin_fma
#define dd_cos_sin_begin dd_cos_sin_begin_fma
#define dd_cos_sin_end dd_cos_sin_end_fma
#define dd_sin dd_sin_fma
#define elliptic_RF elliptic_RF_fma
#define elliptic_param_init elliptic_param_init_fma
#define elliptic_param_init_root elliptic_param_init_root_fma
#define elliptic_param_begin elliptic_param_begin_fma
#define elliptic_param_finish elliptic_param_finish_fma
#define elliptic_quarter_of elliptic_quarter_of_fma
#define pendulum_exact_init pendulum_exact_init_fma
#define pendulum_exact_init_gl pendulum_exact_init_gl_fma
#define pendulum_exact_same pendulum_exact_same_fma
#define pendulum_exact_resolvable pendulum_exact_resolvable_fma
#define pendulum_exact_eval pendulum_exact_eval_fma
#define pendulum_exact_sin_cos pendulum_exact_sin_cos_fma
#define pendulum_exact_eval_many pendulum_exact_eval_many_fma
#define pendulum_exact_once_gl_many pendulum_exact_once_gl_many_fma
#define pendulum_exact_qualitative_miss pendulum_exact_qualitative_miss_fma
#define pendulum_exact_period pendulum_exact_period_fma

#include "dd.c"
#include "elliptic.c"
#include "exact.c"

#else
typedef int exact_fma_not_built;   /* ISO C: a translation unit declares something */
#endif
