/* fmu_results.c: the seed's runs through the FMI functions of one Pendulum binary, printed
 * bit for bit, so that the same program built for another platform (win64 under wine,
 * aarch64 under qemu) can be compared with the linux64 binary (tests/helpers/platform_runs.py).
 *
 * Released from rest at 75, 80, 85 and 90 deg, L = 1 m, g = 9.81 m/s2, the default solver,
 * 10 periods with 50 communication steps a period. One line per step:
 *   <amplitude deg> <step> <theta> <omega> <theta_exact> <omega_exact>
 * each value as the 16 hex digits of its IEEE 754 bit pattern (no printf rounding, and no
 * dependence on the C runtime's printf of doubles). Exit code 0 if every call returned fmi2OK. */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2_api.h"
#include "pendulum_vrs.h"

enum { PERIODS = 10, STEPS_PER_PERIOD = 50 };

static void print_logger(fmi2ComponentEnvironment env, fmi2String instance_name, fmi2Status status,
                         fmi2String category, fmi2String message, ...) {
    va_list args;
    (void)env, (void)status, (void)category;
    va_start(args, message);
    fprintf(stderr, "%s: ", instance_name);
    vfprintf(stderr, message, args);
    fputc('\n', stderr);
    va_end(args);
}

/* The 64 bits of x as 16 hex digits, printed as two 32-bit halves (portable printf). */
static void print_bits(double x) {
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    printf(" %08lx%08lx", (unsigned long)(bits >> 32), (unsigned long)(bits & 0xffffffffu));
}

/* One run from rest at amplitude_deg; 0 on success. */
static int run(int amplitude_deg, const fmi2CallbackFunctions *callbacks) {
    const fmi2ValueReference parameters[3] = {VR_L, VR_G, VR_THETA};
    const fmi2ValueReference period_vr = VR_PERIOD;
    const fmi2ValueReference outputs[4] = {VR_THETA, VR_OMEGA, VR_THETA_EXACT, VR_OMEGA_EXACT};
    const double pi = 3.14159265358979323846;
    double values[3], period = 0.0, y[4], h;
    int step, i;
    fmi2Component c = fmi2Instantiate("fmu_results", fmi2CoSimulation, PENDULUM_GUID, NULL, callbacks,
                                      fmi2False, fmi2False);
    values[0] = 1.0;
    values[1] = 9.81;
    values[2] = amplitude_deg / 180.0 * pi;
    if (c == NULL || fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK || fmi2SetReal(c, parameters, 3, values) != fmi2OK ||
        fmi2ExitInitializationMode(c) != fmi2OK || fmi2GetReal(c, &period_vr, 1, &period) != fmi2OK) {
        fprintf(stderr, "fmu_results: cannot initialize the run at %d deg\n", amplitude_deg);
        return 1;
    }
    h = period / STEPS_PER_PERIOD;
    for (step = 1; step <= PERIODS * STEPS_PER_PERIOD; step++) {
        if (fmi2DoStep(c, (step - 1) * h, h, fmi2True) != fmi2OK || fmi2GetReal(c, outputs, 4, y) != fmi2OK) {
            fprintf(stderr, "fmu_results: step %d at %d deg failed\n", step, amplitude_deg);
            fmi2FreeInstance(c);
            return 1;
        }
        printf("%d %d", amplitude_deg, step);
        for (i = 0; i < 4; i++) {
            print_bits(y[i]);
        }
        putchar('\n');
    }
    fmi2FreeInstance(c);
    return 0;
}

int main(void) {
    const int amplitudes[4] = {75, 80, 85, 90};
    const fmi2CallbackFunctions callbacks = {print_logger, calloc, free, NULL, NULL};
    int i, failed = 0;
    for (i = 0; i < 4; i++) {
        failed |= run(amplitudes[i], &callbacks);
    }
    return failed;
}
