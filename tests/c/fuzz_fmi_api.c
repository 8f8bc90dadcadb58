/* fuzz_fmi_api.c: drives random call sequences with random values into the FMI API.
 *
 * LLVMFuzzerTestOneInput reads the input as a program: each byte picks an FMI call, the
 * following bytes its arguments. The program runs on two instances in lockstep. Invariants
 * (a broken one aborts, which libFuzzer and the test report):
 *  - no crash or sanitizer report, no hang (steps are bounded);
 *  - a call that returns fmi2OK hands out finite numbers only, and after every call each
 *    output read with fmi2OK is finite;
 *  - the two instances fed the same calls return the same statuses and bit-identical outputs;
 *  - a rollback (fmi2GetFMUstate, more calls, fmi2SetFMUstate) and a serialization round trip
 *    (serialize, deserialize, set) give back bit-identical outputs and the same bytes.
 * With clang it is linked with -fsanitize=fuzzer (coverage-guided libFuzzer, run for a fixed
 * number of runs); with gcc, main() below feeds it a fixed number of pseudo-random inputs. */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* Silent, unless FUZZ_VERBOSE is set (to see the FMU's reasons while studying a finding). */
static void silent_logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                          fmi2String message, ...) {
    (void)env, (void)name, (void)status, (void)category;
    if (getenv("FUZZ_VERBOSE") != NULL) {
        va_list args;
        va_start(args, message);
        vfprintf(stderr, message, args);
        va_end(args);
        fputc('\n', stderr);
    }
}

static void broken(const char *what, unsigned detail) {
    fprintf(stderr, "invariant broken: %s (%u)\n", what, detail);
    abort();
}

#define N_OUTPUTS 12
static const fmi2ValueReference OUTPUTS[N_OUTPUTS] = {VR_L, VR_G, VR_THETA, VR_OMEGA, VR_DER_THETA, VR_DER_OMEGA,
                                                      VR_THETA_EXACT, VR_OMEGA_EXACT, VR_PERIOD, VR_X, VR_Y, VR_SOLVER};

/* Reads every output one by one: its status and bits (NaN where refused). A Real read with
 * fmi2OK must be finite (the period may be +inf on the separatrix). Reading may move an
 * instance into the error state, so both instances of a pair read the same way. */
typedef struct {
    fmi2Status status[N_OUTPUTS];
    double value[N_OUTPUTS];
} Snapshot;

static void snapshot(fmi2Component c, Snapshot *shot) {
    size_t i;
    memset(shot, 0, sizeof *shot);
    for (i = 0; i < N_OUTPUTS; i++) {
        if (OUTPUTS[i] == VR_SOLVER) {
            fmi2Integer solver = 0;
            shot->status[i] = fmi2GetInteger(c, &OUTPUTS[i], 1, &solver);
            shot->value[i] = solver;
            continue;
        }
        shot->value[i] = NAN;
        shot->status[i] = fmi2GetReal(c, &OUTPUTS[i], 1, &shot->value[i]);
        if (shot->status[i] == fmi2OK && !isfinite(shot->value[i]) &&
            !(OUTPUTS[i] == VR_PERIOD && shot->value[i] == INFINITY)) {
            broken("fmi2GetReal returned fmi2OK with a value that is not finite, value reference", OUTPUTS[i]);
        }
        if (shot->status[i] != fmi2OK) {
            shot->value[i] = 0.0;
        }
    }
}

static void same_snapshots(const Snapshot *a, const Snapshot *b, const char *what) {
    if (memcmp(a, b, sizeof *a) != 0) {
        broken(what, 0);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* One call of the program, decoded once and applied to both instances. */
typedef struct {
    uint8_t op, byte[4];
    fmi2ValueReference vr;
    double value[3];
} Call;

static void decode(Input *in, Call *call) {
    size_t i;
    call->op = next_byte(in);
    call->vr = next_byte(in) % 18; /* 0 and 16, 17 are unknown references */
    for (i = 0; i < 4; i++) {
        call->byte[i] = next_byte(in);
    }
    for (i = 0; i < 3; i++) {
        call->value[i] = next_double(in);
    }
}

/* One instance of the pair and what the program keeps for it. */
typedef struct {
    fmi2Component c;
    fmi2FMUstate state;
    double time, total_step;
} Slot;

static const fmi2CallbackFunctions CALLBACKS = {silent_logger, calloc, free, NULL, NULL};

/* A rollback: the state now, a step or a new time, back to the state: the outputs are the
 * ones before, bit for bit. Then a serialization round trip: the same outputs and bytes. */
static int round_trips(Slot *slot, const Call *call) {
    fmi2FMUstate saved = NULL, restored = NULL;
    Snapshot before, after;
    fmi2Byte blob[4096], again[4096];
    size_t size = 0;
    int status = fmi2GetFMUstate(slot->c, &saved);
    if (status != fmi2OK) {
        return status;
    }
    snapshot(slot->c, &before);
    if (fmod(fabs(call->value[0]), 5.0) > 0.0) {
        fmi2DoStep(slot->c, slot->time, fmod(fabs(call->value[0]), 5.0), fmi2False);
    }
    fmi2SetTime(slot->c, call->value[1]);
    if (fmi2SetFMUstate(slot->c, saved) != fmi2OK) {
        broken("fmi2SetFMUstate refused a state of the same instance", 0);
    }
    snapshot(slot->c, &after);
    same_snapshots(&before, &after, "rollback is not bit-exact");
    if (fmi2SetFMUstate(slot->c, saved) != fmi2OK ||
        fmi2SerializedFMUstateSize(slot->c, saved, &size) != fmi2OK || size > sizeof blob ||
        fmi2SerializeFMUstate(slot->c, saved, blob, size) != fmi2OK) {
        broken("a state of the instance does not serialize", 0);
    }
    if (fmi2DeSerializeFMUstate(slot->c, blob, size, &restored) != fmi2OK ||
        fmi2SetFMUstate(slot->c, restored) != fmi2OK) {
        broken("a serialized state of the instance is refused", 0);
    }
    snapshot(slot->c, &after);
    same_snapshots(&before, &after, "serialization round trip is not bit-exact");
    if (fmi2SerializeFMUstate(slot->c, restored, again, size) != fmi2OK || memcmp(blob, again, size) != 0) {
        broken("re-serialized bytes differ", 0);
    }
    fmi2SetFMUstate(slot->c, saved);
    fmi2FreeFMUstate(slot->c, &saved);
    fmi2FreeFMUstate(slot->c, &restored);
    return fmi2OK;
}

/* Applies one call; returns its status (or -1 where no FMI status applies). */
static int apply(Slot *slot, const Call *call) {
    fmi2EventInfo info;
    double values[4];
    fmi2Component c = slot->c;
    int status = -1;
    if (c == NULL) {
        slot->c = fmi2Instantiate("fuzz", (call->op & 1) ? fmi2CoSimulation : fmi2ModelExchange, PENDULUM_GUID,
                                  NULL, &CALLBACKS, fmi2False, (call->op & 2) ? fmi2True : fmi2False);
        slot->time = slot->total_step = 0.0;
        return slot->c == NULL;
    }
    switch (call->op % 22) {
    case 0: status = fmi2SetupExperiment(c, call->byte[0] & 1, call->value[0], 0.0, fmi2False, 0.0); break;
    case 1: status = fmi2EnterInitializationMode(c); break;
    case 2: status = fmi2ExitInitializationMode(c); break;
    case 3: status = fmi2SetReal(c, &call->vr, 1, call->value); break;
    case 4:
        status = fmi2GetReal(c, &call->vr, 1, values);
        if (status == fmi2OK && !isfinite(values[0]) && !(call->vr == VR_PERIOD && values[0] == INFINITY)) {
            broken("fmi2GetReal returned fmi2OK with a value that is not finite, value reference", call->vr);
        }
        break;
    case 5: {
        fmi2Integer value = (fmi2Integer)(call->byte[0]) - 8;
        status = fmi2SetInteger(c, &call->vr, 1, &value);
        break;
    }
    case 6: {
        /* bounded: at most 50 s per step and 400 s per input, so no input runs for long */
        double h = fmod(fabs(call->value[0]), 50.0);
        if (slot->total_step + h <= 400.0) {
            status = fmi2DoStep(c, slot->time, h, fmi2True);
            if (status == fmi2OK || status == fmi2Warning) {
                fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &slot->time);
                slot->total_step += h;
            }
        }
        break;
    }
    case 7: status = fmi2DoStep(c, call->value[0], call->value[1], fmi2True); break;
    case 8: status = fmi2Terminate(c); break;
    case 9: status = fmi2Reset(c); slot->time = 0.0; break;
    case 10: status = fmi2GetFMUstate(c, &slot->state); break;
    case 11: if (slot->state != NULL) status = fmi2SetFMUstate(c, slot->state); break;
    case 12: {
        fmi2Byte blob[4096];
        size_t blob_size = 0;
        if (slot->state != NULL && fmi2SerializedFMUstateSize(c, slot->state, &blob_size) == fmi2OK &&
            blob_size <= sizeof blob) {
            fmi2SerializeFMUstate(c, slot->state, blob, blob_size);
            blob[call->byte[0] % blob_size] ^= call->byte[1]; /* maybe corrupt */
            status = fmi2DeSerializeFMUstate(c, blob, blob_size - (call->byte[2] & 1), &slot->state);
        }
        break;
    }
    case 13: status = fmi2SetTime(c, call->value[0]); break;
    case 14: status = fmi2SetContinuousStates(c, call->value, 2 + (call->byte[0] & 1)); break;
    case 15:
        status = fmi2GetDerivatives(c, values, 2);
        if (status == fmi2OK && !(isfinite(values[0]) && isfinite(values[1]))) {
            broken("fmi2GetDerivatives returned fmi2OK with a value that is not finite", 0);
        }
        break;
    case 16: status = fmi2EnterContinuousTimeMode(c); break;
    case 17: fmi2NewDiscreteStates(c, &info); status = fmi2EnterEventMode(c); break;
    case 18: status = fmi2FreeFMUstate(c, &slot->state); break;
    case 19: status = round_trips(slot, call); break;
    case 20: {
        fmi2Status step_status = fmi2OK;
        status = fmi2GetStatus(c, fmi2DoStepStatus, &step_status);
        break;
    }
    default:
        fmi2FreeFMUstate(c, &slot->state);
        fmi2FreeInstance(c);
        slot->c = NULL;
        break;
    }
    return status;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    Input in = {data, size, 0};
    Slot pair[2] = {{NULL, NULL, 0.0, 0.0}, {NULL, NULL, 0.0, 0.0}};
    Call call;
    Snapshot first, second;
    int i;
    while (in.pos < in.size) {
        decode(&in, &call);
        if (apply(&pair[0], &call) != apply(&pair[1], &call)) {
            broken("two instances fed the same calls returned different statuses, op", call.op);
        }
        if (pair[0].c != NULL && (call.op % 22 == 4 || call.op % 22 == 19)) {
            /* both instances answer alike, output by output (reading may fail alike) */
            snapshot(pair[0].c, &first);
            snapshot(pair[1].c, &second);
            same_snapshots(&first, &second, "two instances fed the same calls disagree");
        }
    }
    for (i = 0; i < 2; i++) {
        if (pair[i].c != NULL) {
            fmi2FreeFMUstate(pair[i].c, &pair[i].state);
            fmi2FreeInstance(pair[i].c);
        }
    }
    return 0;
}

#ifndef PENDULUM_LIBFUZZER
/* Without libFuzzer: a fixed number of pseudo-random inputs (xorshift64, fixed seed), so the
 * run's length does not depend on the machine's speed. */
int main(int argc, char **argv) {
    long runs = argc > 1 ? atol(argv[1]) : 20000;
    uint64_t rng = 0x9E3779B97F4A7C15u;
    uint8_t input[512];
    long executions;
    for (executions = 0; executions < runs; executions++) {
        size_t size = 16 + (size_t)(rng % (sizeof input - 16)), i;
        for (i = 0; i < size; i++) {
            rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
            input[i] = (uint8_t)(rng >> 24);
        }
        LLVMFuzzerTestOneInput(input, size);
    }
    printf("fuzz_fmi_api: %ld executions, 0 findings (invariants: finite outputs with fmi2OK, "
           "identical twin instances, bit-exact rollback and serialization)\n", executions);
    return 0;
}
#endif
