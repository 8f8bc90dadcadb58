/* cpu_level.h: what the processor and its operating system let the exact solution's copies use
 * (exact_fma.h): 0 the x86-64 baseline, 1 the fma with AVX (exact_fma.c), 2 AVX-512F as well
 * (avx512_copy.c). Read from CPUID and XGETBV once, as the library is loaded (before any thread
 * can ask), not from the compiler's __builtin_cpu_supports, which zig's runtime (the cross
 * builds) lacks. Intel SDM vol. 1,
 * 14.3 and 15.2: CPUID.1:ECX.FMA[12], .OSXSAVE[27], .AVX[28]; CPUID.(7,0):EBX.AVX512F[16];
 * XCR0 bits 1-2 (SSE and AVX state) and 5-7 (opmask and ZMM state) saved by the system. */
#ifndef PENDULUM_CPU_LEVEL_H
#define PENDULUM_CPU_LEVEL_H

#include <cpuid.h>

static int cpu_level_read(void)
{
    unsigned eax, ebx, ecx, edx;
    if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) {
        return 0;
    }
    const unsigned fma = 1u << 12, osxsave = 1u << 27, avx = 1u << 28;
    if ((ecx & (fma | osxsave | avx)) != (fma | osxsave | avx)) {
        return 0;
    }
    unsigned xcr0, xcr0_high;
    __asm__("xgetbv" : "=a"(xcr0), "=d"(xcr0_high) : "c"(0));
    (void)xcr0_high;
    if ((xcr0 & 0x6u) != 0x6u) {
        return 0;   /* the system does not save the AVX state */
    }
    if (__get_cpuid_max(0, NULL) < 7) {
        return 1;
    }
    __cpuid_count(7, 0, eax, ebx, ecx, edx);
    const unsigned avx512f = 1u << 16;
    return (ebx & avx512f) != 0 && (xcr0 & 0xE6u) == 0xE6u ? 2 : 1;
}

/* the level, from load time on (0, the baseline, before it) */
static int cpu_level_known;

__attribute__((constructor)) static void cpu_level_at_load(void)
{
    cpu_level_known = cpu_level_read();
}

static inline int cpu_level(void)
{
    return cpu_level_known;
}

#endif
