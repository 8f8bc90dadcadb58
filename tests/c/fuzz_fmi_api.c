/* fuzz_fmi_api.c: drives random call sequences with random values into the FMI API.
 *
 * LLVMFuzzerTestOneInput reads the input as a program: each byte picks an FMI call, the
 * following bytes its arguments. The program runs on two instances in lockstep: an FMI 2.0 and
 * an FMI 3.0 one when both layers are built in (PENDULUM_FUZZ_FMI3; the calls of each version
 * in fuzz_api_fmi2.c and fuzz_api_fmi3.c), otherwise two FMI 2.0 ones. Invariants (a broken
 * one aborts, which libFuzzer and the test report):
 *  - no crash or sanitizer report, no hang (steps are bounded);
 *  - a call that returns fmi2OK hands out finite numbers only, and after every call each
 *    output read with fmi2OK is finite;
 *  - the two instances fed the same calls return the same statuses and bit-identical outputs
 *    (so FMI 2.0 and FMI 3.0 behave alike on any sequence of calls);
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

#include "fuzz_api.h"
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
void fuzz_report(const char *message) {
    if (getenv("FUZZ_VERBOSE") != NULL) {
        fprintf(stderr, "%s\n", message);
    }
}

static void broken(const char *what, unsigned detail) {
    fprintf(stderr, "invariant broken: %s (%u)\n", what, detail);
    abort();
}

#define N_OUTPUTS 12
static const unsigned OUTPUTS[N_OUTPUTS] = {VR_L, VR_G, VR_THETA, VR_OMEGA, VR_DER_THETA, VR_DER_OMEGA,
                                                      VR_THETA_EXACT, VR_OMEGA_EXACT, VR_PERIOD, VR_X, VR_Y, VR_SOLVER};

/* Reads every output one by one: its status and bits (NaN where refused). A Real read with
 * status OK must be finite (the period may be +inf on the separatrix). Reading may move an
 * instance into the error state, so both instances of a pair read the same way. */
typedef struct {
    int status[N_OUTPUTS];
    double value[N_OUTPUTS];
} Snapshot;

#define OK 0      /* fmi2OK, fmi3OK */
#define WARNING 1 /* fmi2Warning, fmi3Warning */

static void snapshot(const FuzzApi *api, void *c, Snapshot *shot) {
    size_t i;
    memset(shot, 0, sizeof *shot);
    for (i = 0; i < N_OUTPUTS; i++) {
        if (OUTPUTS[i] == VR_SOLVER) {
            int solver = 0;
            shot->status[i] = api->get_integer(c, OUTPUTS[i], &solver);
            shot->value[i] = solver;
            continue;
        }
        shot->value[i] = NAN;
        shot->status[i] = api->get_real(c, OUTPUTS[i], &shot->value[i]);
        if (shot->status[i] == OK && !isfinite(shot->value[i]) &&
            !(OUTPUTS[i] == VR_PERIOD && shot->value[i] == INFINITY)) {
            broken("GetReal returned OK with a value that is not finite, value reference", OUTPUTS[i]);
        }
        if (shot->status[i] != OK) {
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
    unsigned vr;
    double value[3];
} Call;

static void decode(Input *in, Call *call) {
    size_t i;
    call->op = next_byte(in);
    call->vr = 1 + next_byte(in) % 17; /* 16, 17 are unknown references (0 is FMI 3.0's time) */
    for (i = 0; i < 4; i++) {
        call->byte[i] = next_byte(in);
    }
    for (i = 0; i < 3; i++) {
        call->value[i] = next_double(in);
    }
}

/* One instance of the pair and what the program keeps for it. */
typedef struct {
    const FuzzApi *api;
    void *c;
    void *state;
    double time, total_step;
} Slot;

/* A rollback: the state now, a step or a new time, back to the state: the outputs are the
 * ones before, bit for bit. Then a serialization round trip: the same outputs and bytes. */
static int round_trips(Slot *slot, const Call *call) {
    const FuzzApi *api = slot->api;
    void *saved = NULL, *restored = NULL;
    Snapshot before, after;
    unsigned char blob[4096], again[4096];
    size_t size = 0;
    double reached = slot->time;
    int status = api->get_state(slot->c, &saved);
    if (status != OK) {
        return status;
    }
    snapshot(api, slot->c, &before);
    if (fmod(fabs(call->value[0]), 5.0) > 0.0) {
        api->do_step(slot->c, slot->time, fmod(fabs(call->value[0]), 5.0), &reached);
    }
    api->set_time(slot->c, call->value[1]);
    if (api->set_state(slot->c, saved) != OK) {
        broken("SetFMUstate refused a state of the same instance", 0);
    }
    snapshot(api, slot->c, &after);
    same_snapshots(&before, &after, "rollback is not bit-exact");
    if (api->set_state(slot->c, saved) != OK || api->state_size(slot->c, saved, &size) != OK ||
        size > sizeof blob || api->serialize(slot->c, saved, blob, size) != OK) {
        broken("a state of the instance does not serialize", 0);
    }
    if (api->deserialize(slot->c, blob, size, &restored) != OK || api->set_state(slot->c, restored) != OK) {
        broken("a serialized state of the instance is refused", 0);
    }
    snapshot(api, slot->c, &after);
    same_snapshots(&before, &after, "serialization round trip is not bit-exact");
    if (api->serialize(slot->c, restored, again, size) != OK || memcmp(blob, again, size) != 0) {
        broken("re-serialized bytes differ", 0);
    }
    api->set_state(slot->c, saved);
    api->free_state(slot->c, &saved);
    api->free_state(slot->c, &restored);
    return OK;
}

#define N_OPS 23

/* Applies one call; returns its status (or -1 where no FMI status applies). */
static int apply(Slot *slot, const Call *call) {
    const FuzzApi *api = slot->api;
    double values[4];
    void *c = slot->c;
    int status = -1;
    if (c == NULL) {
        slot->c = api->instantiate(call->op & 1, (call->op & 2) != 0);
        slot->time = slot->total_step = 0.0;
        return slot->c == NULL;
    }
    switch (call->op % N_OPS) {
    case 0: status = api->setup_and_enter(c, call->byte[0] & 1, call->value[0]); break;
    case 1: status = api->enter_initialization(c); break;
    case 2: status = api->exit_initialization(c); break;
    case 3: status = api->set_real(c, call->vr, call->value[0]); break;
    case 4:
        status = api->get_real(c, call->vr, values);
        if (status == OK && !isfinite(values[0]) && !(call->vr == VR_PERIOD && values[0] == INFINITY)) {
            broken("GetReal returned OK with a value that is not finite, value reference", call->vr);
        }
        break;
    case 5: status = api->set_integer(c, call->vr, (int)(call->byte[0]) - 8); break;
    case 6: {
        /* bounded: at most 50 s per step and 400 s per input, so no input runs for long */
        double h = fmod(fabs(call->value[0]), 50.0);
        if (slot->total_step + h <= 400.0) {
            status = api->do_step(c, slot->time, h, &slot->time);
            if (status == OK || status == WARNING) {
                slot->total_step += h;
            }
        }
        break;
    }
    case 7: {
        double ignored = 0.0;
        status = api->do_step(c, call->value[0], call->value[1], &ignored);
        break;
    }
    case 8: status = api->terminate(c); break;
    case 9: status = api->reset(c); slot->time = 0.0; break;
    case 10: status = api->get_state(c, &slot->state); break;
    case 11: if (slot->state != NULL) status = api->set_state(c, slot->state); break;
    case 12: {
        unsigned char blob[4096];
        size_t blob_size = 0;
        if (slot->state != NULL && api->state_size(c, slot->state, &blob_size) == OK && blob_size <= sizeof blob) {
            api->serialize(c, slot->state, blob, blob_size);
            blob[call->byte[0] % blob_size] ^= call->byte[1]; /* maybe corrupt */
            status = api->deserialize(c, blob, blob_size - (call->byte[2] & 1), &slot->state);
        }
        break;
    }
    case 13: status = api->set_time(c, call->value[0]); break;
    case 14: status = api->set_states(c, call->value, 2 + (call->byte[0] & 1)); break;
    case 15:
        status = api->get_derivatives(c, values, 2);
        if (status == OK && !(isfinite(values[0]) && isfinite(values[1]))) {
            broken("GetDerivatives returned OK with a value that is not finite", 0);
        }
        break;
    case 16: status = api->enter_continuous_time(c); break;
    case 17: status = api->update_and_enter_event(c); break;
    case 18: status = api->free_state(c, &slot->state); break;
    case 19: status = round_trips(slot, call); break;
    case 20:
        /* a partial derivative: unknown call->vr by one of L, g, theta, omega or another reference */
        status = api->directional(c, call->vr, (unsigned)(call->byte[1] % 7), values);
        if (status == OK && !isfinite(values[0]) && call->vr != VR_PERIOD) {
            broken("a directional derivative returned OK and is not finite, unknown", call->vr);
        }
        if (status != OK) {
            values[0] = 0.0;
        }
        status = status * 2 + (values[0] < 0.0); /* the twins must agree on the value's sign too */
        break;
    case 21:
        status = api->output_derivative(c, call->vr, (int)(call->byte[1] % 5), values);
        if (status == OK && !isfinite(values[0])) {
            broken("an output derivative returned OK and is not finite, value reference", call->vr);
        }
        break;
    default:
        api->free_state(c, &slot->state);
        api->free_instance(c);
        slot->c = NULL;
        break;
    }
    return status;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    Input in = {data, size, 0};
#ifdef PENDULUM_FUZZ_FMI3
    Slot pair[2] = {{&FUZZ_FMI2, NULL, NULL, 0.0, 0.0}, {&FUZZ_FMI3, NULL, NULL, 0.0, 0.0}};
#else
    Slot pair[2] = {{&FUZZ_FMI2, NULL, NULL, 0.0, 0.0}, {&FUZZ_FMI2, NULL, NULL, 0.0, 0.0}};
#endif
    Call call;
    Snapshot first, second;
    int i;
    while (in.pos < in.size) {
        decode(&in, &call);
        if (apply(&pair[0], &call) != apply(&pair[1], &call)) {
            broken("two instances fed the same calls returned different statuses, op", call.op);
        }
        if (pair[0].c != NULL && (call.op % N_OPS == 4 || call.op % N_OPS == 19)) {
            /* both instances answer alike, output by output (reading may fail alike) */
            snapshot(pair[0].api, pair[0].c, &first);
            snapshot(pair[1].api, pair[1].c, &second);
            same_snapshots(&first, &second, "two instances fed the same calls disagree");
        }
    }
    for (i = 0; i < 2; i++) {
        if (pair[i].c != NULL) {
            pair[i].api->free_state(pair[i].c, &pair[i].state);
            pair[i].api->free_instance(pair[i].c);
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
    printf("fuzz_fmi_api: %ld executions, 0 findings (invariants: finite outputs with status OK, "
#ifdef PENDULUM_FUZZ_FMI3
           "an FMI 2.0 and an FMI 3.0 twin identical, "
#else
           "identical twin instances, "
#endif
           "bit-exact rollback and serialization)\n", executions);
    return 0;
}
#endif
