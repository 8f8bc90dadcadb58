/* fma_check.c: prints a, b, c and the C library's fma(a, b, c) for pseudo-random cases, as
 * IEEE 754 bit patterns, so tests/helpers/platform_runs.py can check each result against the exactly
 * rounded a*b + c (Python fractions). The FMU relies on a correctly rounded fma (C11 7.12.13.1:
 * "computes (x*y)+z, rounded as one ternary operation"): integrator.c forms the exact residual
 * g - (g/L) L with it, and dd.h and exact.c form exact products with it where the platform has
 * a fast fma (FP_FAST_FMA). Half the cases nearly cancel (c close to -a*b), where a wrong fma
 * shows most. Usage: fma_check [cases] (default 20000). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t state = 0x9E3779B97F4A7C15u;

/* xorshift64: the same sequence on every platform */
static uint64_t next(void) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}

/* A double in [1, 2) times 2^e, e in [-8, 7], with a random sign. */
static double random_double(void) {
    const uint64_t bits = next();
    uint64_t mantissa = (bits >> 12) | 0x3FF0000000000000u;
    double x;
    memcpy(&x, &mantissa, sizeof x);
    x = ldexp(x, (int)(bits & 15u) - 8);
    return (bits & 16u) ? -x : x;
}

static void print_bits(double x) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    printf(" %08lx%08lx", (unsigned long)(bits >> 32), (unsigned long)(bits & 0xffffffffu));
}

int main(int argc, char **argv) {
    const long cases = argc > 1 ? strtol(argv[1], NULL, 10) : 20000;
    long i;
    for (i = 0; i < cases; i++) {
        const double a = random_double(), b = random_double();
        volatile double product = a * b; /* rounded: c = -fl(a b) (1 + tiny) nearly cancels */
        const double c = (i % 2 == 0) ? -product * (1.0 + ldexp(random_double(), -40)) : random_double();
        print_bits(a);
        print_bits(b);
        print_bits(c);
        print_bits(fma(a, b, c));
        putchar('\n');
    }
    return 0;
}
