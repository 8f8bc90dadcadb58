/* avx512_copy.c: dd.c, elliptic.c and exact.c compiled once more with AVX-512F (and the fma)
 * enabled, their public functions renamed with the suffix _avx512. Of them only
 * pendulum_exact_once_gl_many_avx512 is called: the baseline's pendulum_exact_once_gl_many
 * hands the call to it on a processor with AVX-512F, and there once_avx.h sets up and
 * evaluates eight new states a vector (four in the fma build). Each lane runs the same IEEE
 * operations as the scalar code, so the bits are those of the fma build (exact_fma.h) and of
 * the baseline. Built where the fma build is (GCC or clang on x86-64 Linux), into the numerical core
 * (pendulum_core, which defines PENDULUM_EXACT_AVX512: the exact library, the C tests); not
 * into Pendulum.fmu, whose sources are modelDescription.xml's. */
#include "exact_fma.h"

#ifdef PENDULUM_EXACT_FMA_BUILD
#define EXACT_COPY_TARGET "fma,avx512f"
/* once_avx.h's vectors: eight doubles */
#define PENDULUM_ONCE_LANES 8
#ifndef EXACT_COPY   /* a test's copy names them its own way */
#define EXACT_COPY(name) name##_avx512   /* the public functions named with _avx512 */
#endif
#include "core_copy.h"

#else
typedef int avx512_copy_not_built;   /* ISO C: a translation unit declares something */
#endif
