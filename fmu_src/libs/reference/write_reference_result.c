/* write_reference_result.c: writes a reference result of the FMU, the exact solution, as the CSV
 * of the layered standard for reference results (extra/org.fmi-standard.fmi-ls-ref/,
 * cmake/ReferenceResult.cmake and cmake/SuiteReference.cmake).
 *
 * Usage:
 *   write_reference_result OUT.csv START STOP INTERVALS
 *       the default experiment from the FMU's start values: INTERVALS + 1 equally spaced times;
 *   write_reference_result OUT.csv START STOP INTERVAL THETA OMEGA L G MAX_ROWS
 *       a validation experiment with its own start values (theta, omega at START) and
 *       parameters: the times of a run's output grid, START + k INTERVAL and STOP last (a short
 *       last interval when INTERVAL does not divide the duration), every m-th of them with m the
 *       least that keeps the rows at most MAX_ROWS + 1 (so each row is a time the run outputs).
 * Columns: time and the FMU's continuous outputs, each from the exact solution
 * (pendulum_exact_eval, the FMU's own exact port): theta and omega are what a perfect solver
 * would output, theta_exact and omega_exact the same numbers, x = L sin(theta),
 * y = -L cos(theta). Every value with 17 significant digits (a double round-trips). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "exact.h"
#include "model.h"

static void write_row(FILE *out, const PendulumExact *exact, double t, double L) {
    double theta, omega;
    pendulum_exact_eval(exact, t, &theta, &omega);
    fprintf(out, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, theta, omega, theta, omega, L * sin(theta),
            -L * cos(theta));
}

static int parse(const char *text, double *value) {
    char *end;
    *value = strtod(text, &end);
    return *text != '\0' && *end == '\0' && isfinite(*value);
}

int main(int argc, char **argv) {
    PendulumExact exact;
    FILE *out;
    double start, stop, spacing, theta0 = START_THETA, omega0 = START_OMEGA, L = START_L, g = START_G, rows_max = 0;
    long intervals, every = 1, i;
    int validation = argc == 10;
    if ((argc != 5 && !validation) || !parse(argv[2], &start) || !parse(argv[3], &stop) ||
        !parse(argv[4], &spacing) || !(stop > start) || !(spacing > 0) ||
        (validation && (!parse(argv[5], &theta0) || !parse(argv[6], &omega0) || !parse(argv[7], &L) ||
                        !parse(argv[8], &g) || !parse(argv[9], &rows_max) || !(L > 0) || !(g > 0) ||
                        !(rows_max >= 1)))) {
        fprintf(stderr, "usage: write_reference_result OUT.csv START STOP INTERVALS\n"
                        "       write_reference_result OUT.csv START STOP INTERVAL THETA OMEGA L G MAX_ROWS\n"
                        "(STOP > START, INTERVAL(S) > 0, L > 0, g > 0, MAX_ROWS >= 1)\n");
        return 2;
    }
    if (validation) {
        /* output intervals of the run: ceil((stop - start) / interval), the last one short */
        intervals = (long)ceil((stop - start) / spacing - 1e-9);
        every = (long)ceil((double)intervals / rows_max);
    } else {
        intervals = (long)spacing;
        spacing = (stop - start) / (double)intervals;
    }
    if (pendulum_exact_init_gl(&exact, theta0, omega0, g, L, start) != 0) {
        fprintf(stderr, "write_reference_result: the start values set up no exact solution\n");
        return 1;
    }
    out = fopen(argv[1], "w");
    if (out == NULL) {
        perror(argv[1]);
        return 1;
    }
    fprintf(out, "\"time\",\"theta\",\"omega\",\"theta_exact\",\"omega_exact\",\"x\",\"y\"\n");
    for (i = 0; i < intervals; i += every) {
        /* the grid of an importer's output points: start + i * interval */
        write_row(out, &exact, start + (double)i * spacing, L);
    }
    /* the last point: the default's on the same formula, a validation run's at its stop time */
    write_row(out, &exact, validation ? stop : start + (double)intervals * spacing, L);
    return fclose(out) == 0 ? 0 : 1;
}
