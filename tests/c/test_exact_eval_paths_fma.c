/* test_exact_eval_paths_fma.c: test_exact_eval_paths.c for the fma build (exact_fma.c: the
 * same sources compiled for processors with a fused multiply-add, the fma's two-product and
 * roundsd's nearest integer), where the processor has an fma; elsewhere it says so and passes
 * without a check (the baseline's own test still runs). */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
#define EXACT_COPY(name) name##_paths_fma
#include "exact_fma.c"

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
