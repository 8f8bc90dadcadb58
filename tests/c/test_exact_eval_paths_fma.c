/* test_exact_eval_paths_fma.c: test_exact_eval_paths.c for the fma build (exact_fma.c: the
 * same sources compiled for processors with a fused multiply-add, the fma's two-product and
 * roundsd's nearest integer), where the processor has an fma; elsewhere it says so and passes
 * without a check (the baseline's own test still runs). */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
#pragma GCC target("fma")
#pragma GCC optimize("fp-contract=off")
#define PENDULUM_DD_FMA 1
#define PENDULUM_EXACT_FMA_PASS 1
#define dd_sincos dd_sincos_paths_fma
#define dd_cos_sin dd_cos_sin_paths_fma
#define dd_cos_sin_begin dd_cos_sin_begin_paths_fma
#define dd_cos_sin_end dd_cos_sin_end_paths_fma
#define dd_sin dd_sin_paths_fma
#define elliptic_RF elliptic_RF_paths_fma
#define elliptic_param_init elliptic_param_init_paths_fma
#define elliptic_param_init_root elliptic_param_init_root_paths_fma
#define elliptic_param_begin elliptic_param_begin_paths_fma
#define elliptic_param_finish elliptic_param_finish_paths_fma
#define elliptic_quarter_of elliptic_quarter_of_paths_fma
#define pendulum_exact_init pendulum_exact_init_paths_fma
#define pendulum_exact_init_gl pendulum_exact_init_gl_paths_fma
#define pendulum_exact_same pendulum_exact_same_paths_fma
#define pendulum_exact_resolvable pendulum_exact_resolvable_paths_fma
#define pendulum_exact_eval pendulum_exact_eval_paths_fma
#define pendulum_exact_sin_cos pendulum_exact_sin_cos_paths_fma
#define pendulum_exact_eval_many pendulum_exact_eval_many_paths_fma
#define pendulum_exact_qualitative_miss pendulum_exact_qualitative_miss_paths_fma
#define pendulum_exact_period pendulum_exact_period_paths_fma
#include "dd.c"
#include "elliptic.c"
#include "exact.c"

#include "exact_eval_paths.h"

int main(void)
{
    if (!__builtin_cpu_supports("fma")) {
        printf("test_exact_eval_paths_fma: this processor lacks an fma: nothing to compare\n");
        return 0;
    }
    return run_paths("test_exact_eval_paths_fma");
}
#else
#include <stdio.h>

int main(void)
{
    printf("test_exact_eval_paths_fma: no fma build here (exact_fma.h): nothing to compare\n");
    return 0;
}
#endif
