/* exact_fma.h: the exact solution built a second time for processors with a fused
 * multiply-add (exact_fma.c), and the run-time choice between the two builds.
 *
 * The set-up of a new state is a chain of double-double operations (dd.h), and each
 * double-double product rests on an exact two-product a b = p + e. x86-64's baseline has no
 * fma instruction, so the baseline build forms e by Dekker's split (17 operations); with an
 * fma, e = fma(a, b, -p) is one. Both give the same e (it is exact either way, within the
 * split's range |a|, |b| < 2^995 and away from underflow, where Dekker's loses bits and the
 * fma's does not), so both builds give the same bits: the fma build is only faster.
 *
 * exact_fma.c compiles dd.c, elliptic.c and exact.c again with the fma enabled (GCC's target
 * pragma, clang's attribute pragma) and PENDULUM_DD_FMA defined, their public functions renamed with the suffix _fma
 * (core_copy.h). The baseline functions pendulum_exact_init, _init_gl, _eval, _eval_many,
 * _once_gl_many and _sin_cos hand the call to the _fma build when the processor has an fma
 * (cpu_level.h: CPUID, with the operating system's support of the AVX state). Only for GCC and
 * clang (zig cc, the cross builds) on x86-64 Linux; every other compiler and platform builds
 * the baseline alone, and exact_fma.c is then empty. */
#ifndef PENDULUM_EXACT_FMA_H
#define PENDULUM_EXACT_FMA_H

#if defined(__GNUC__) && !defined(__INTEL_COMPILER) && defined(__x86_64__) && defined(__linux__) \
    && !defined(PENDULUM_NO_FMA_BUILD)
#define PENDULUM_EXACT_FMA_BUILD 1
#endif

#endif
