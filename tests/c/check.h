/* check.h: the counting check of the C unit tests (one test program includes it once). */
#ifndef PENDULUM_TEST_CHECK_H
#define PENDULUM_TEST_CHECK_H

#include <stdarg.h>
#include <stdio.h>

static const double PI = 3.141592653589793238462643383;

static int n_checks, n_failed;

/* Counts one check; prints "FAIL: <message>" when ok is 0. */
static void check(int ok, const char *fmt, ...)
{
    n_checks++;
    if (ok) {
        return;
    }
    n_failed++;
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL: ");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
}

/* Prints the program's summary line; returns its exit status (0 iff every check passed). */
static int check_summary(const char *program)
{
    if (n_failed) {
        printf("%s: %d of %d checks FAILED\n", program, n_failed, n_checks);
        return 1;
    }
    printf("%s: %d checks passed\n", program, n_checks);
    return 0;
}

#endif
