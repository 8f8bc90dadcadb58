/* test_exact_eval_paths.c: pendulum_exact_eval's inline common case (eval_libration) gives the
 * bits of the general path (eval_any), in the baseline build (Dekker's two-products, the
 * shifted nearest integer); exact_eval_paths.h says what is compared. The fma build:
 * test_exact_eval_paths_fma.c. */
#define PENDULUM_NO_FMA_BUILD 1
#define EXACT_COPY(name) name##_paths
#include "core_copy.h"

#include "exact_eval_paths.h"

int main(void)
{
    return run_paths("test_exact_eval_paths");
}
