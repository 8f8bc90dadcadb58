/* core_copy.h: dd.c, elliptic.c and exact.c compiled once more in this translation unit, as a
 * copy beside the core's own functions: for a processor with more than the baseline
 * (exact_fma.c, avx512_copy.c, which enable its instructions and define PENDULUM_DD_FMA and
 * PENDULUM_EXACT_FMA_PASS first), or in a test that compares a build with the core. The file
 * that includes this defines EXACT_COPY(name), the copy's name of each public function. */
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
