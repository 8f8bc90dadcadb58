/* test_split_states.c: FMU states of the split pendulum's four binaries (PendulumBody and
 * PendulumGravity, FMI 2.0 and 3.0), loaded with dlopen as an importer loads them (argv, or the
 * paths CMake compiled in, so valgrind runs it without arguments).
 *
 * A rollback as an iterating master does it: GetFMUstate, steps with changing inputs (and
 * input derivatives in FMI 2.0), SetFMUstate, the same steps again: every output, the input
 * and the output derivatives equal bit for bit. The state serialized and deserialized into
 * another instance (with other start values) continues bit for bit too. Blobs that are not a
 * state of this FMU are refused with an error and a logged reason: a wrong size, another
 * model's blob of the same size (Body's in Gravity, Pendulum.fmu's marker), a flipped bit, a
 * wrong format version, and forged blobs whose checksum is recomputed (FNV-1a written here
 * from its definition) but whose contents no instance can have; and 3000 blobs with random
 * bits flipped, each refused or taken whole, never read out of bounds. */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fmi2_api.h"
#include "fmi3_api.h"
#include "split.h"
#include "split_tokens.h"

static char last_message[800];

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                    fmi2String message, ...) {
    va_list args;
    (void)env, (void)name, (void)category, (void)status;
    va_start(args, message);
    vsnprintf(last_message, sizeof last_message, message, args);
    va_end(args);
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    (void)env, (void)category, (void)status;
    snprintf(last_message, sizeof last_message, "%s", message);
}

static const fmi2CallbackFunctions CALLBACKS = {logger2, calloc, free, NULL, NULL};

/* One binary, FMI 2.0 or 3.0, behind one set of calls. */
typedef struct {
    int version, body;
    const char *token;
    void *dll;
    void *f[16];
} Binary;

enum { INSTANTIATE, SETUP, ENTER, EXIT, GET, SET, STEP, INPUT_DER, OUTPUT_DER, GET_STATE, SET_STATE, FREE_STATE,
       SIZE, SERIALIZE, DESERIALIZE, FREE_INSTANCE };

static const char *const NAMES2[16] = {
    "fmi2Instantiate", "fmi2SetupExperiment", "fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
    "fmi2GetReal", "fmi2SetReal", "fmi2DoStep", "fmi2SetRealInputDerivatives", "fmi2GetRealOutputDerivatives",
    "fmi2GetFMUstate", "fmi2SetFMUstate", "fmi2FreeFMUstate", "fmi2SerializedFMUstateSize", "fmi2SerializeFMUstate",
    "fmi2DeSerializeFMUstate", "fmi2FreeInstance"};
static const char *const NAMES3[16] = {
    "fmi3InstantiateCoSimulation", "fmi3EnterInitializationMode", "fmi3EnterInitializationMode",
    "fmi3ExitInitializationMode", "fmi3GetFloat64", "fmi3SetFloat64", "fmi3DoStep", "fmi3GetFloat64",
    "fmi3GetOutputDerivatives", "fmi3GetFMUState", "fmi3SetFMUState", "fmi3FreeFMUState",
    "fmi3SerializedFMUStateSize", "fmi3SerializeFMUState", "fmi3DeserializeFMUState", "fmi3FreeInstance"};

static Binary load(const char *path, int version, int body) {
    Binary b;
    int i;
    b.version = version;
    b.body = body;
    b.token = body ? PENDULUM_BODY_TOKEN : PENDULUM_GRAVITY_TOKEN;
    b.dll = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (b.dll == NULL) {
        printf("FAIL: cannot load %s: %s\n", path, dlerror());
        exit(1);
    }
    for (i = 0; i < 16; i++) {
        b.f[i] = dlsym(b.dll, (version == 2 ? NAMES2 : NAMES3)[i]);
        if (b.f[i] == NULL) {
            printf("FAIL: %s not exported by %s\n", (version == 2 ? NAMES2 : NAMES3)[i], path);
            exit(1);
        }
    }
    return b;
}

/* The k-th function as the FMI function `type` (the stored pointer read as that type, as
 * dlsym's result must be). */
#define CALL2(b, k, type) (*(__typeof__(&type) const *)&(b)->f[k])
#define CALL3 CALL2

/* A fresh instance, initialized with L = 1.5 and (Body) the start values theta0, omega0. */
static void *instance(const Binary *b, double theta0, double omega0) {
    void *c;
    const unsigned vr[3] = {SPLIT_VR_L, SPLIT_VR_THETA, SPLIT_VR_OMEGA};
    const double values[3] = {1.5, theta0, omega0};
    const size_t n = b->body ? 3 : 2; /* Gravity: L and its input theta */
    int ok;
    if (b->version == 2) {
        c = CALL2(b, INSTANTIATE, fmi2Instantiate)("s", fmi2CoSimulation, b->token, NULL, &CALLBACKS, 0, 0);
        ok = c != NULL && CALL2(b, SETUP, fmi2SetupExperiment)(c, 0, 0.0, 0.25, 0, 0.0) == fmi2OK &&
             CALL2(b, ENTER, fmi2EnterInitializationMode)(c) == fmi2OK &&
             CALL2(b, SET, fmi2SetReal)(c, vr, n, values) == fmi2OK &&
             CALL2(b, EXIT, fmi2ExitInitializationMode)(c) == fmi2OK;
    } else {
        c = CALL3(b, INSTANTIATE, fmi3InstantiateCoSimulation)("s", b->token, NULL, 0, 0, 0, 0, NULL, 0, NULL, logger3,
                                                               NULL);
        ok = c != NULL && CALL3(b, ENTER, fmi3EnterInitializationMode)(c, 0, 0.0, 0.25, 0, 0.0) == fmi3OK &&
             CALL3(b, SET, fmi3SetFloat64)(c, vr, n, values, n) == fmi3OK &&
             CALL3(b, EXIT, fmi3ExitInitializationMode)(c) == fmi3OK;
    }
    check(ok, "FMI %d %s: instantiation and initialization: %s", b->version, b->body ? "Body" : "Gravity",
          last_message);
    return c;
}

static void free_instance(const Binary *b, void *c) {
    if (b->version == 2) {
        CALL2(b, FREE_INSTANCE, fmi2FreeInstance)(c);
    } else {
        CALL3(b, FREE_INSTANCE, fmi3FreeInstance)(c);
    }
}

static int set_input(const Binary *b, void *c, double value, double d1, double d2) {
    const unsigned vr = b->body ? SPLIT_VR_ALPHA : SPLIT_VR_THETA;
    if (b->version == 2) {
        const unsigned vrs[2] = {vr, vr};
        const int orders[2] = {1, 2};
        const double ders[2] = {d1, d2};
        return CALL2(b, SET, fmi2SetReal)(c, &vr, 1, &value) == fmi2OK &&
               CALL2(b, INPUT_DER, fmi2SetRealInputDerivatives)(c, vrs, 2, orders, ders) == fmi2OK;
    }
    return CALL3(b, SET, fmi3SetFloat64)(c, &vr, 1, &value, 1) == fmi3OK;
}

static int step(const Binary *b, void *c, double t, double h) {
    if (b->version == 2) {
        return CALL2(b, STEP, fmi2DoStep)(c, t, h, fmi2False);
    } else {
        fmi3Boolean event, terminate, early;
        fmi3Float64 last;
        return CALL3(b, STEP, fmi3DoStep)(c, t, h, fmi3False, &event, &terminate, &early, &last);
    }
}

/* Every output, the input and the output derivatives the FMU has, in `out`; their number. */
static size_t outputs(const Binary *b, void *c, double out[16]) {
    static const unsigned body_vrs[8] = {SPLIT_VR_THETA, SPLIT_VR_OMEGA, SPLIT_VR_THETA_EXACT, SPLIT_VR_OMEGA_EXACT,
                                         SPLIT_VR_DER_THETA, SPLIT_VR_DER_OMEGA, SPLIT_VR_ALPHA, SPLIT_VR_L};
    static const unsigned gravity_vrs[3] = {SPLIT_VR_ALPHA, SPLIT_VR_THETA, SPLIT_VR_L};
    const unsigned *vrs = b->body ? body_vrs : gravity_vrs;
    const size_t n = b->body ? 8 : 3;
    unsigned der_vrs[6];
    int orders[6];
    size_t n_der = 0, k;
    int ok;
    if (b->body) { /* theta, omega to order 3 */
        for (k = 0; k < 6; k++) {
            der_vrs[k] = k < 3 ? SPLIT_VR_THETA : SPLIT_VR_OMEGA;
            orders[k] = (int)(k % 3) + 1;
        }
        n_der = 6;
    } else if (b->version == 2) { /* alpha to order 2 */
        der_vrs[0] = der_vrs[1] = SPLIT_VR_ALPHA;
        orders[0] = 1, orders[1] = 2;
        n_der = 2;
    }
    if (b->version == 2) {
        ok = CALL2(b, GET, fmi2GetReal)(c, vrs, n, out) == fmi2OK &&
             CALL2(b, OUTPUT_DER, fmi2GetRealOutputDerivatives)(c, der_vrs, n_der, orders, out + n) == fmi2OK;
    } else {
        const unsigned time_vr = SPLIT_VR_TIME;
        ok = CALL3(b, GET, fmi3GetFloat64)(c, vrs, n, out, n) == fmi3OK &&
             CALL3(b, OUTPUT_DER, fmi3GetOutputDerivatives)(c, der_vrs, n_der, orders, out + n, n_der) == fmi3OK &&
             CALL3(b, GET, fmi3GetFloat64)(c, &time_vr, 1, out + n + n_der, 1) == fmi3OK;
        n_der++;
    }
    check(ok, "FMI %d: outputs read: %s", b->version, last_message);
    return n + n_der;
}

static int get_state(const Binary *b, void *c, void **state) {
    return b->version == 2 ? CALL2(b, GET_STATE, fmi2GetFMUstate)(c, state)
                           : CALL3(b, GET_STATE, fmi3GetFMUState)(c, state);
}

static int set_state(const Binary *b, void *c, void *state) {
    return b->version == 2 ? CALL2(b, SET_STATE, fmi2SetFMUstate)(c, state)
                           : CALL3(b, SET_STATE, fmi3SetFMUState)(c, state);
}

static int free_state(const Binary *b, void *c, void **state) {
    return b->version == 2 ? CALL2(b, FREE_STATE, fmi2FreeFMUstate)(c, state)
                           : CALL3(b, FREE_STATE, fmi3FreeFMUState)(c, state);
}

static int state_size(const Binary *b, void *c, void *state, size_t *size) {
    return b->version == 2 ? CALL2(b, SIZE, fmi2SerializedFMUstateSize)(c, state, size)
                           : CALL3(b, SIZE, fmi3SerializedFMUStateSize)(c, state, size);
}

static int serialize(const Binary *b, void *c, void *state, unsigned char *bytes, size_t size) {
    return b->version == 2 ? CALL2(b, SERIALIZE, fmi2SerializeFMUstate)(c, state, (fmi2Byte *)bytes, size)
                           : CALL3(b, SERIALIZE, fmi3SerializeFMUState)(c, state, bytes, size);
}

static int deserialize(const Binary *b, void *c, const unsigned char *bytes, size_t size, void **state) {
    return b->version == 2 ? CALL2(b, DESERIALIZE, fmi2DeSerializeFMUstate)(c, (const fmi2Byte *)bytes, size, state)
                           : CALL3(b, DESERIALIZE, fmi3DeserializeFMUState)(c, bytes, size, state);
}

/* Five steps from t, the first with the input the instance holds (as its last step carried it
 * along its polynomial), then with inputs that change at each (FMI 2.0: with derivatives); the
 * outputs after each appended to out; the number of values written. */
static size_t steps(const Binary *b, void *c, double t, double *out) {
    static const double H[4] = {0.05, 0.125, 0.01, 0.3};
    size_t n = 0;
    int k;
    check(step(b, c, t, 0.02) == 0, "FMI %d: step with the held input: %s", b->version, last_message);
    t += 0.02;
    n += outputs(b, c, out + n);
    for (k = 0; k < 4; k++) {
        check(set_input(b, c, 0.8 - 0.7 * k, 1.25 * k - 1.0, 0.5 - 0.3 * k), "FMI %d: input set: %s", b->version,
              last_message);
        check(step(b, c, t, H[k]) == 0, "FMI %d: step at %g: %s", b->version, t, last_message);
        t += H[k];
        n += outputs(b, c, out + n);
    }
    return n;
}

static int same_bits(const double *a, const double *b, size_t n) {
    return memcmp(a, b, n * sizeof *a) == 0;
}

static const char *model(const Binary *b) {
    return b->body ? "Body" : "Gravity";
}

/* Rollback in one instance and a serialized state continued in another, bit for bit. */
static void test_rollback(const Binary *b) {
    double first[128], again[128], other[128], at_state[16], now[16];
    size_t n, size = 0;
    unsigned char *bytes;
    void *state = NULL, *restored = NULL, *c = instance(b, 0.9, 0.4), *d = instance(b, -2.0, 1.0);
    check(set_input(b, c, 0.3, -0.2, 0.1) && step(b, c, 0.25, 0.1) == 0, "FMI %d %s: a first step", b->version,
          model(b));
    check(get_state(b, c, &state) == 0 && state != NULL, "FMI %d %s: GetFMUstate: %s", b->version, model(b),
          last_message);
    n = outputs(b, c, at_state);
    check(steps(b, c, 0.35, first) > 0, "FMI %d %s: steps", b->version, model(b));
    check(set_state(b, c, state) == 0, "FMI %d %s: SetFMUstate: %s", b->version, model(b), last_message);
    /* the outputs, the input and its derivatives (Body's theta'' and theta''') as at the state */
    check(outputs(b, c, now) == n && same_bits(at_state, now, n), "FMI %d %s: after SetFMUstate every output is "
          "the state's, bit for bit", b->version, model(b));
    n = steps(b, c, 0.35, first);
    check(set_state(b, c, state) == 0, "FMI %d %s: SetFMUstate: %s", b->version, model(b), last_message);
    check(steps(b, c, 0.35, again) == n && same_bits(first, again, n), "FMI %d %s: the rollback repeats every output "
          "bit for bit", b->version, model(b));

    check(state_size(b, c, state, &size) == 0 && size > sizeof(ModelData), "FMI %d %s: SerializedFMUstateSize: %zu",
          b->version, model(b), size);
    bytes = malloc(size);
    check(bytes != NULL && serialize(b, c, state, bytes, size) == 0, "FMI %d %s: SerializeFMUstate: %s", b->version,
          model(b), last_message);
    check(deserialize(b, d, bytes, size, &restored) == 0 && restored != NULL, "FMI %d %s: DeSerializeFMUstate in "
          "another instance: %s", b->version, model(b), last_message);
    check(set_state(b, d, restored) == 0, "FMI %d %s: SetFMUstate of the deserialized state: %s", b->version,
          model(b), last_message);
    check(steps(b, d, 0.35, other) == n && same_bits(first, other, n), "FMI %d %s: the other instance continues bit "
          "for bit", b->version, model(b));
    /* SetFMUstate takes an instance out of Error: a master rolls back after a refused step */
    check(step(b, d, 99.0, 0.1) == 3, "FMI %d %s: a step from the wrong time is refused", b->version, model(b));
    check(set_state(b, d, restored) == 0 && steps(b, d, 0.35, other) == n && same_bits(first, other, n),
          "FMI %d %s: after an error, SetFMUstate and the same steps: bit for bit", b->version, model(b));
    check(free_state(b, c, &state) == 0 && state == NULL && free_state(b, d, &restored) == 0, "FMI %d %s: "
          "FreeFMUstate", b->version, model(b));
    free(bytes);
    free_instance(b, c);
    free_instance(b, d);
}

/* FNV-1a, 64 bit (offset basis 14695981039346656037, prime 1099511628211), from its definition. */
static uint64_t fnv1a(const unsigned char *bytes, size_t n) {
    uint64_t hash = 14695981039346656037u;
    size_t i;
    for (i = 0; i < n; i++) {
        hash = (hash ^ bytes[i]) * 1099511628211u;
    }
    return hash;
}

/* The serialized form: 8 characters of magic, format version and payload size (uint32), the
 * payload's checksum (uint64), then the payload (ModelData, then the input polynomial). */
#define HEADER 24u

static void reseal(unsigned char *blob, size_t size) {
    const uint64_t sum = fnv1a(blob + HEADER, size - HEADER);
    memcpy(blob + 16, &sum, sizeof sum);
}

/* `blob` deserialized by a fresh instance: refused with an error whose log holds `needle`. */
static void refused(const Binary *b, const unsigned char *blob, size_t size, const char *needle, const char *what) {
    void *c = instance(b, 0.5, 0.0), *state = NULL;
    int status = deserialize(b, c, blob, size, &state);
    check(status == 3 && state == NULL, "FMI %d %s: %s: status %d, not an error", b->version, model(b), what, status);
    check(strstr(last_message, needle) != NULL, "FMI %d %s: %s: log \"%s\" lacks \"%s\"", b->version, model(b), what,
          last_message, needle);
    free_instance(b, c);
}

static void test_bad_blobs(const Binary *b, const Binary *other) {
    unsigned char blob[4096], bad[4096], foreign[4096];
    size_t size = 0, other_size = 0;
    void *state = NULL, *c = instance(b, 0.7, 0.1), *o = instance(other, 0.7, 0.1);
    const size_t input_at = HEADER + sizeof(ModelData);
    double value;
    check(set_input(b, c, 0.5, 0.0, 0.0) && step(b, c, 0.25, 0.5) == 0 && get_state(b, c, &state) == 0 &&
          state_size(b, c, state, &size) == 0 && size == HEADER + sizeof(ModelData) + sizeof(InputPolynomial) &&
          serialize(b, c, state, blob, size) == 0, "FMI %d %s: a blob of %zu bytes", b->version, model(b), size);
    check(memcmp(blob, b->body ? "PNDLBODY" : "PNDLGRAV", 8) == 0, "FMI %d %s: the blob names its model", b->version,
          model(b));
    check(serialize(b, c, state, bad, size - 1) == 3, "FMI %d %s: SerializeFMUstate into too few bytes is refused",
          b->version, model(b));
    free_state(b, c, &state);
    free_instance(b, c);

    refused(b, blob, size - 1, "a state of this FMU has", "one byte short");
    refused(b, blob, size + 1, "a state of this FMU has", "one byte more");
    refused(b, blob, 0, "a state of this FMU has", "no bytes");
    /* another model's blob, of the same size */
    check(get_state(other, o, &state) == 0 && state_size(other, o, state, &other_size) == 0 && other_size == size &&
          serialize(other, o, state, foreign, other_size) == 0, "FMI %d: the other model's blob", b->version);
    free_state(other, o, &state);
    free_instance(other, o);
    refused(b, foreign, size, "not a state of this FMU", "the other model's blob");
    memcpy(bad, blob, size);
    memcpy(bad, "PNDLSTAT", 8);
    refused(b, bad, size, "marked \"PNDLSTAT\"", "Pendulum.fmu's marker");
    memcpy(bad, "\n\0\x7f" "ABCDE", 8);
    refused(b, bad, size, "marked \"???ABCDE\"", "a marker that is not text, printed as text");
    memcpy(bad, blob, size);
    bad[8] ^= 1u;
    refused(b, bad, size, "format version", "another format version");
    memcpy(bad, blob, size);
    bad[HEADER + offsetof(ModelData, theta) + 3] ^= 0x10u;
    refused(b, bad, size, "corrupted", "a flipped bit in theta");
    memcpy(bad, blob, size);
    bad[size - 1] ^= 0x80u;
    refused(b, bad, size, "corrupted", "a flipped bit in the input");

    /* forged: the checksum recomputed, the contents impossible */
    memcpy(bad, blob, size);
    value = NAN;
    memcpy(bad + HEADER + offsetof(ModelData, time), &value, sizeof value);
    reseal(bad, size);
    refused(b, bad, size, "not finite", "a NaN time");
    memcpy(bad, blob, size);
    value = INFINITY;
    memcpy(bad + input_at + offsetof(InputPolynomial, value), &value, sizeof value);
    reseal(bad, size);
    refused(b, bad, size, "input", "an infinite input");
    memcpy(bad, blob, size);
    {
        const Mode mode = MODE_ERROR;
        memcpy(bad + HEADER + offsetof(ModelData, mode), &mode, sizeof mode);
    }
    reseal(bad, size);
    refused(b, bad, size, "mode", "a state in Error");
    memcpy(bad, blob, size);
    value = -1.0;
    memcpy(bad + HEADER + offsetof(ModelData, g), &value, sizeof value);
    reseal(bad, size);
    refused(b, bad, size, "L or g", "g = -1");
    if (b->body) {
        memcpy(bad, blob, size);
        value = 2.5;
        memcpy(bad + HEADER + offsetof(ModelData, L), &value, sizeof value);
        reseal(bad, size);
        refused(b, bad, size, "exact solution", "L other than the exact solution's");
    }
    memcpy(bad, blob, size);
    value = 0.75;
    memcpy(bad + input_at + offsetof(InputPolynomial, d1), &value, sizeof value);
    reseal(bad, size);
    if (b->version == 3) {
        refused(b, bad, size, "FMI 3.0", "an input derivative in FMI 3.0");
    }
    if (!b->body) {
        memcpy(bad, blob, size);
        value = 3.0;
        memcpy(bad + HEADER + offsetof(ModelData, omega), &value, sizeof value);
        reseal(bad, size);
        refused(b, bad, size, "omega", "Gravity with an omega");
    }
}

/* A blob with random bits flipped (every other one with its checksum recomputed, so that the
 * contents are parsed): each is refused with an error or taken; a state taken is set and read
 * without complaint (SetFMUstate checks what DeSerializeFMUstate checked). Run under ASan,
 * UBSan and valgrind, so that no flip reads or writes out of bounds. */
static void test_random_blobs(const Binary *b) {
    unsigned char blob[4096], bad[4096];
    size_t size = 0, n_values, i;
    uint64_t seed = 0x9E3779B97F4A7C15u;
    int k, taken = 0, refused_count = 0;
    double values[16];
    void *state = NULL, *c = instance(b, 1.1, -0.3);
    check(set_input(b, c, -0.5, 0.25, 0.125) && step(b, c, 0.25, 0.2) == 0 && get_state(b, c, &state) == 0 &&
          state_size(b, c, state, &size) == 0 && size <= sizeof blob && serialize(b, c, state, blob, size) == 0,
          "FMI %d %s: a blob", b->version, model(b));
    free_state(b, c, &state);
    for (k = 0; k < 3000; k++) {
        int flips = 1 + k % 3, f, status;
        memcpy(bad, blob, size);
        for (f = 0; f < flips; f++) {
            seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17; /* xorshift64 */
            bad[(size_t)(seed >> 8) % size] ^= (unsigned char)(1u << (seed & 7u));
        }
        if (k % 2 == 1) {
            reseal(bad, size);
        }
        state = NULL;
        status = deserialize(b, c, bad, size, &state);
        check(status == 0 || (status == 3 && state == NULL), "FMI %d %s: random blob %d: status %d", b->version,
              model(b), k, status);
        if (status != 0) {
            refused_count++;
            continue;
        }
        taken++;
        check(set_state(b, c, state) == 0, "FMI %d %s: random blob %d taken, but SetFMUstate refuses it: %s",
              b->version, model(b), k, last_message);
        n_values = outputs(b, c, values);
        for (i = 0; i < n_values; i++) {
            check(isfinite(values[i]), "FMI %d %s: random blob %d: output %zu is not finite", b->version, model(b), k,
                  i);
        }
        free_state(b, c, &state);
    }
    check(taken > 10 && refused_count > 1000, "FMI %d %s: of 3000 random blobs %d taken, %d refused", b->version,
          model(b), taken, refused_count);
    free_instance(b, c);
}

int main(int argc, char **argv) {
    const char *paths[4] = {SPLIT_BODY2, SPLIT_GRAVITY2, SPLIT_BODY3, SPLIT_GRAVITY3};
    Binary binaries[4];
    int k;
    if (argc == 5) {
        for (k = 0; k < 4; k++) {
            paths[k] = argv[k + 1];
        }
    } else if (argc != 1) {
        printf("usage: %s [Body2.so Gravity2.so Body3.so Gravity3.so]\n", argv[0]);
        return 2;
    }
    for (k = 0; k < 4; k++) {
        binaries[k] = load(paths[k], k < 2 ? 2 : 3, k % 2 == 0);
    }
    for (k = 0; k < 4; k++) {
        test_rollback(&binaries[k]);
        test_bad_blobs(&binaries[k], &binaries[k ^ 1]);
        test_random_blobs(&binaries[k]);
    }
    for (k = 0; k < 4; k++) {
        dlclose(binaries[k].dll);
    }
    return check_summary("test_split_states");
}
