/* write_reference_result.c: writes the reference result of the FMU's default experiment, the
 * exact solution from the start values, as the CSV of the layered standard for reference
 * results (extra/org.fmi-standard.fmi-ls-ref/, cmake/ReferenceResult.cmake).
 *
 * Usage: write_reference_result OUT.csv START STOP INTERVALS
 * Columns: time and the FMU's continuous outputs, each from the exact solution
 * (pendulum_exact_eval, the FMU's own exact port): theta and omega are what a perfect solver
 * would output, theta_exact and omega_exact the same numbers, x = L sin(theta),
 * y = -L cos(theta). Every value with 17 significant digits (a double round-trips). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "exact.h"
#include "model.h"

int main(int argc, char **argv) {
    PendulumExact exact;
    FILE *out;
    double start, stop;
    long intervals, i;
    if (argc != 5 || (start = atof(argv[2]), stop = atof(argv[3]), intervals = atol(argv[4])) <= 0 ||
        !(stop > start)) {
        fprintf(stderr, "usage: write_reference_result OUT.csv START STOP INTERVALS (STOP > START, INTERVALS > 0)\n");
        return 2;
    }
    if (pendulum_exact_init_gl(&exact, START_THETA, START_OMEGA, START_G, START_L, start) != 0) {
        fprintf(stderr, "write_reference_result: the start values set up no exact solution\n");
        return 1;
    }
    out = fopen(argv[1], "w");
    if (out == NULL) {
        perror(argv[1]);
        return 1;
    }
    fprintf(out, "\"time\",\"theta\",\"omega\",\"theta_exact\",\"omega_exact\",\"x\",\"y\"\n");
    for (i = 0; i <= intervals; i++) {
        /* the grid of an importer's output points: start + i * (stop - start) / intervals */
        double t = start + (double)i * ((stop - start) / (double)intervals), theta, omega;
        pendulum_exact_eval(&exact, t, &theta, &omega);
        fprintf(out, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, theta, omega, theta, omega,
                START_L * sin(theta), -START_L * cos(theta));
    }
    return fclose(out) == 0 ? 0 : 1;
}
