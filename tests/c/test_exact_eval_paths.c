/* test_exact_eval_paths.c: pendulum_exact_eval's inline common case (eval_libration) gives the
 * bits of the general path (eval_any), in the baseline build (Dekker's two-products, the
 * shifted nearest integer); exact_eval_paths.h says what is compared. The fma build:
 * test_exact_eval_paths_fma.c. */
#define PENDULUM_NO_FMA_BUILD 1
#define dd_sincos dd_sincos_paths
#define dd_cos_sin dd_cos_sin_paths
#define dd_cos_sin_begin dd_cos_sin_begin_paths
#define dd_cos_sin_end dd_cos_sin_end_paths
#define dd_sin dd_sin_paths
#define elliptic_RF elliptic_RF_paths
#define elliptic_param_init elliptic_param_init_paths
#define elliptic_param_init_root elliptic_param_init_root_paths
#define elliptic_param_begin elliptic_param_begin_paths
#define elliptic_param_finish elliptic_param_finish_paths
#define elliptic_quarter_of elliptic_quarter_of_paths
#define pendulum_exact_init pendulum_exact_init_paths
#define pendulum_exact_init_gl pendulum_exact_init_gl_paths
#define pendulum_exact_same pendulum_exact_same_paths
#define pendulum_exact_resolvable pendulum_exact_resolvable_paths
#define pendulum_exact_eval pendulum_exact_eval_paths
#define pendulum_exact_sin_cos pendulum_exact_sin_cos_paths
#define pendulum_exact_eval_many pendulum_exact_eval_many_paths
#define pendulum_exact_qualitative_miss pendulum_exact_qualitative_miss_paths
#define pendulum_exact_period pendulum_exact_period_paths
#include "dd.c"
#include "elliptic.c"
#include "exact.c"

#include "exact_eval_paths.h"

int main(void)
{
    return run_paths("test_exact_eval_paths");
}
