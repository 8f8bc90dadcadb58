/* exact_fma.c: dd.c, elliptic.c and exact.c compiled again for processors with a fused
 * multiply-add, their public functions renamed with the suffix _fma (see exact_fma.h for why
 * the bits are the same and when this build is used). Empty where exact_fma.h builds no
 * second copy. */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
#define EXACT_COPY_TARGET "fma"
#ifndef EXACT_COPY   /* a test's copy names them its own way */
#define EXACT_COPY(name) name##_fma   /* the public functions named with _fma */
#endif
#include "core_copy.h"

#else
typedef int exact_fma_not_built;   /* ISO C: a translation unit declares something */
#endif
