/* fuzz_fmi_api.c: drives random call sequences with random values into the FMI API.
 *
 * LLVMFuzzerTestOneInput reads the input as a program: each byte picks an FMI call, the
 * following bytes its arguments. Invariants: no crash or sanitizer report, no hang (steps
 * are bounded), and a call that returns fmi2OK never hands out NaN.
 * With clang, link with -fsanitize=fuzzer for coverage-guided libFuzzer; without it (gcc),
 * main() below feeds it pseudo-random inputs for a bounded time and prints the counts. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmi2_api.h"
#include "pendulum_vrs.h"

typedef struct {
    const uint8_t *data;
    size_t size, pos;
} Input;

static uint8_t next_byte(Input *in) {
    return in->pos < in->size ? in->data[in->pos++] : 0;
}

/* Interesting values, or any double made of 8 input bytes. */
static double next_double(Input *in) {
    static const double special[] = {0.0, -0.0, 1.0, -1.0, 3.141592653589793, 3.1415926535897, 1e-300, 1e300,
                                     NAN, INFINITY, -INFINITY, 5e-324, 9.81, 0.1, 1e-12, 2.0};
    uint8_t selector = next_byte(in);
    double value;
    uint8_t bytes[8];
    size_t i;
    if (selector < 200) {
        return special[selector % (sizeof special / sizeof special[0])];
    }
    for (i = 0; i < 8; i++) {
        bytes[i] = next_byte(in);
    }
    memcpy(&value, bytes, sizeof value);
    return value;
}

static void silent_logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                          fmi2String message, ...) {
    (void)env, (void)name, (void)status, (void)category, (void)message;
}

static void require_numbers(fmi2Status status, const double *values, size_t n, const char *what) {
    size_t i;
    for (i = 0; status == fmi2OK && i < n; i++) {
        if (isnan(values[i])) {
            fprintf(stderr, "invariant broken: %s returned fmi2OK with NaN at index %zu\n", what, i);
            abort();
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const fmi2CallbackFunctions callbacks = {silent_logger, calloc, free, NULL, NULL};
    Input in = {data, size, 0};
    fmi2Component c = NULL;
    fmi2FMUstate state = NULL;
    fmi2EventInfo info;
    double time = 0.0, values[4], total_step = 0.0;
    fmi2Byte blob[4096];
    size_t blob_size = 0;
    while (in.pos < in.size) {
        uint8_t op = next_byte(&in);
        fmi2ValueReference vr = next_byte(&in) % 18; /* 0 and 16, 17 are unknown references */
        if (c == NULL) {
            c = fmi2Instantiate("fuzz", (op & 1) ? fmi2CoSimulation : fmi2ModelExchange, PENDULUM_GUID, NULL,
                                &callbacks, fmi2False, (op & 2) ? fmi2True : fmi2False);
            time = 0.0;
            continue;
        }
        switch (op % 20) {
        case 0: fmi2SetupExperiment(c, next_byte(&in) & 1, next_double(&in), 0.0, fmi2False, 0.0); break;
        case 1: fmi2EnterInitializationMode(c); break;
        case 2: fmi2ExitInitializationMode(c); break;
        case 3: values[0] = next_double(&in); fmi2SetReal(c, &vr, 1, values); break;
        case 4: {
            char what[64];
            snprintf(what, sizeof what, "fmi2GetReal(value reference %u)", vr);
            require_numbers(fmi2GetReal(c, &vr, 1, values), values, 1, what);
            break;
        }
        case 5: {
            fmi2Integer value = (fmi2Integer)(next_byte(&in)) - 8;
            fmi2SetInteger(c, &vr, 1, &value);
            break;
        }
        case 6: {
            /* bounded: at most 50 s per step and 400 s per input, so no input runs for long */
            double h = fmod(fabs(next_double(&in)), 50.0);
            if (total_step + h <= 400.0 && fmi2DoStep(c, time, h, fmi2True) == fmi2OK) {
                time += h;
                total_step += h;
            }
            break;
        }
        case 7: fmi2DoStep(c, next_double(&in), next_double(&in), fmi2True); break;
        case 8: fmi2Terminate(c); break;
        case 9: fmi2Reset(c); time = 0.0; break;
        case 10: fmi2GetFMUstate(c, &state); break;
        case 11: if (state != NULL) fmi2SetFMUstate(c, state); break;
        case 12:
            if (state != NULL && fmi2SerializedFMUstateSize(c, state, &blob_size) == fmi2OK &&
                blob_size <= sizeof blob) {
                fmi2SerializeFMUstate(c, state, blob, blob_size);
                blob[next_byte(&in) % blob_size] ^= (fmi2Byte)next_byte(&in); /* maybe corrupt */
                fmi2DeSerializeFMUstate(c, blob, blob_size - (next_byte(&in) & 1), &state);
            }
            break;
        case 13: fmi2SetTime(c, next_double(&in)); break;
        case 14:
            values[0] = next_double(&in);
            values[1] = next_double(&in);
            fmi2SetContinuousStates(c, values, 2 + (next_byte(&in) & 1));
            break;
        case 15:
            require_numbers(fmi2GetDerivatives(c, values, 2), values, 2, "fmi2GetDerivatives");
            break;
        case 16: fmi2EnterContinuousTimeMode(c); break;
        case 17: fmi2NewDiscreteStates(c, &info); fmi2EnterEventMode(c); break;
        case 18: fmi2FreeFMUstate(c, &state); break;
        default:
            fmi2FreeFMUstate(c, &state);
            fmi2FreeInstance(c);
            c = NULL;
            break;
        }
    }
    if (c != NULL) {
        fmi2FreeFMUstate(c, &state);
        fmi2FreeInstance(c);
    }
    return 0;
}

#ifndef PENDULUM_LIBFUZZER
/* Without libFuzzer: random inputs (xorshift64, fixed seed) for a bounded time. */
int main(int argc, char **argv) {
    double seconds = argc > 1 ? atof(argv[1]) : 20.0;
    uint64_t rng = 0x9E3779B97F4A7C15u;
    uint8_t input[512];
    long executions = 0;
    clock_t start = clock();
    while ((double)(clock() - start) / CLOCKS_PER_SEC < seconds) {
        size_t size = 16 + (size_t)(rng % (sizeof input - 16)), i;
        for (i = 0; i < size; i++) {
            rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
            input[i] = (uint8_t)(rng >> 24);
        }
        LLVMFuzzerTestOneInput(input, size);
        executions++;
    }
    printf("fuzz_fmi_api: %ld executions in %.0f s, 0 findings\n", executions, seconds);
    return 0;
}
#endif
