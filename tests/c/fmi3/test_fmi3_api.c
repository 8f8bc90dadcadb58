/* test_fmi3_api.c: calls the FMI 3.0 functions of the FMI 3.0 Pendulum library directly, as an
 * importer would: instantiation, the calling sequence, bad input (fmi3Error plus a logged
 * reason), the typed getters and setters, FMU states and their serialization (bit-exact
 * round trips), derivatives, and the refusals of absent features. Runs under ASan/UBSan in the
 * sanitizer build and under valgrind in scripts/test.sh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../check.h"
#include "fmi3_api.h"
#include "pendulum_vrs.h"

/* One check, named by what it checks (check.h counts it and prints the failures). */
#define CHECK(condition, what) check((condition) != 0, "%s", what)

typedef struct {
    int errors;
    char last[600];
} LogCapture;

static void capture_logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    LogCapture *capture = env;
    (void)category;
    snprintf(capture->last, sizeof capture->last, "%s", message);
    if (status == fmi3Error) {
        capture->errors++;
    }
}

/* The call returned fmi3Error and logged a message containing `needle`. */
static void expect_error(fmi3Status status, LogCapture *capture, const char *needle, const char *what) {
    CHECK(status == fmi3Error, what);
    check(strstr(capture->last, needle) != NULL, "%s: log \"%s\" lacks \"%s\"", what, capture->last, needle);
}

static fmi3Instance cs_instance(LogCapture *capture) {
    return fmi3InstantiateCoSimulation("test", PENDULUM_GUID, NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL,
                                       0, capture, capture_logger, NULL);
}

static fmi3Instance me_instance(LogCapture *capture) {
    return fmi3InstantiateModelExchange("test", PENDULUM_GUID, NULL, fmi3False, fmi3False, capture, capture_logger);
}

static void initialize(fmi3Instance c, double theta0) {
    const fmi3ValueReference vr = VR_THETA;
    fmi3EnterInitializationMode(c, fmi3True, 1e-10, 0.0, fmi3False, 0.0);
    fmi3SetFloat64(c, &vr, 1, &theta0, 1);
    fmi3ExitInitializationMode(c);
}

static void test_instantiation(void) {
    LogCapture capture = {0, ""};
    fmi3Instance c;
    CHECK(strcmp(fmi3GetVersion(), "3.0") == 0, "fmi3GetVersion is 3.0");
    c = fmi3InstantiateCoSimulation("test", "{wrong}", NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0,
                                    &capture, capture_logger, NULL);
    CHECK(c == NULL && strstr(capture.last, "does not match") != NULL, "a wrong token is refused with a reason");
    c = fmi3InstantiateModelExchange("", PENDULUM_GUID, NULL, fmi3False, fmi3False, &capture, capture_logger);
    CHECK(c == NULL && strstr(capture.last, "non-empty") != NULL, "an empty name is refused");
    c = fmi3InstantiateCoSimulation("test", PENDULUM_GUID, NULL, fmi3False, fmi3False, fmi3True, fmi3False, NULL, 0,
                                    &capture, capture_logger, NULL);
    CHECK(c == NULL && strstr(capture.last, "hasEventMode") != NULL, "eventModeUsed is refused");
    c = fmi3InstantiateScheduledExecution("test", PENDULUM_GUID, NULL, fmi3False, fmi3False, &capture, capture_logger,
                                          NULL, NULL, NULL);
    CHECK(c == NULL, "no Scheduled Execution");
    fmi3FreeInstance(NULL);
}

static void test_calling_sequence_and_bad_input(void) {
    LogCapture capture = {0, ""};
    fmi3Instance c = cs_instance(&capture);
    fmi3Boolean event = fmi3False, terminate = fmi3False, early = fmi3False;
    fmi3Float64 last = 0.0, value = -1.0, values[2];
    fmi3ValueReference vr = VR_L, vrs[2] = {VR_THETA, 0};
    fmi3Int32 steps = 0;
    fmi3Int64 solver = 0;
    expect_error(fmi3DoStep(c, 0.0, 0.1, fmi3False, &event, &terminate, &early, &last), &capture,
                 "fmi3DoStep: not allowed in state Instantiated", "DoStep before initialization");
    fmi3Reset(c);
    expect_error(fmi3SetFloat64(c, &vr, 1, &value, 1), &capture, "L (value reference 1) = -1: must be greater than 0",
                 "L < 0");
    fmi3Reset(c);
    expect_error(fmi3SetFloat64(c, &vr, 1, values, 2), &capture, "nValues 2 differs", "nValues mismatch");
    fmi3Reset(c);
    vr = VR_SOLVER;
    fmi3EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0);
    expect_error(fmi3GetInt32(c, &vr, 1, &steps, 1), &capture, "solver is Int64", "solver read as Int32");
    fmi3Reset(c);
    solver = 99;
    expect_error(fmi3SetInt64(c, &vr, 1, &solver, 1), &capture, "must be one of the items", "solver = 99");
    fmi3Reset(c);
    solver = 2;
    CHECK(fmi3SetInt64(c, &vr, 1, &solver, 1) == fmi3OK, "solver = rk4 as Int64");
    initialize(c, 1.0);
    CHECK(fmi3DoStep(c, 0.0, 0.5, fmi3False, &event, &terminate, &early, &last) == fmi3OK && last == 0.5 && !event &&
              !terminate && !early, "a step reports its end");
    CHECK(fmi3GetFloat64(c, vrs, 2, values, 2) == fmi3OK && values[1] == 0.5 && isfinite(values[0]),
          "time (value reference 0) is the communication point");
    vr = VR_STATS_STEPS;
    CHECK(fmi3GetInt32(c, &vr, 1, &steps, 1) == fmi3OK && steps > 0, "stats.steps as Int32");
    expect_error(fmi3DoStep(c, 0.25, 0.1, fmi3False, &event, &terminate, &early, &last), &capture,
                 "is not the current time", "a step from the wrong time");
    fmi3Reset(c);
    expect_error(fmi3EnterConfigurationMode(c), &capture, "no structural parameters", "configuration mode");
    fmi3Reset(c);
    expect_error(fmi3EnterEventMode(c), &capture, "is a Model Exchange function", "event mode in CS");
    fmi3FreeInstance(c);
}

/* Get a state, step on, restore it, serialize, deserialize: the same numbers bit for bit. */
static void test_states_round_trip(void) {
    LogCapture capture = {0, ""};
    fmi3Instance c = cs_instance(&capture);
    fmi3FMUState saved = NULL, restored = NULL;
    fmi3Boolean event, terminate, early;
    fmi3Float64 last, first[2], second[2];
    const fmi3ValueReference vrs[2] = {VR_THETA, VR_OMEGA};
    size_t size = 0;
    unsigned char *blob;
    initialize(c, 2.5);
    fmi3DoStep(c, 0.0, 1.0, fmi3False, &event, &terminate, &early, &last);
    CHECK(fmi3GetFMUState(c, &saved) == fmi3OK, "get state");
    fmi3DoStep(c, 1.0, 2.0, fmi3False, &event, &terminate, &early, &last);
    fmi3GetFloat64(c, vrs, 2, first, 2);
    CHECK(fmi3SetFMUState(c, saved) == fmi3OK, "set state");
    CHECK(fmi3SerializedFMUStateSize(c, saved, &size) == fmi3OK && size > 0, "size");
    blob = malloc(size);
    CHECK(fmi3SerializeFMUState(c, saved, blob, size) == fmi3OK, "serialize");
    CHECK(fmi3DeserializeFMUState(c, blob, size, &restored) == fmi3OK, "deserialize");
    CHECK(fmi3SetFMUState(c, restored) == fmi3OK, "set deserialized");
    fmi3DoStep(c, 1.0, 2.0, fmi3False, &event, &terminate, &early, &last);
    fmi3GetFloat64(c, vrs, 2, second, 2);
    CHECK(memcmp(first, second, sizeof first) == 0, "the rollback repeats the step bit for bit");
    blob[size - 1] ^= 1;
    expect_error(fmi3DeserializeFMUState(c, blob, size, &restored), &capture, "corrupted", "a flipped bit");
    fmi3Reset(c);
    expect_error(fmi3DeserializeFMUState(c, blob, size - 1, &restored), &capture, "the blob has", "a truncated blob");
    fmi3FreeFMUState(c, &saved);
    fmi3FreeFMUState(c, &restored);
    CHECK(saved == NULL && restored == NULL, "free clears the pointers");
    free(blob);
    fmi3FreeInstance(c);
}

static void test_model_exchange_and_derivatives(void) {
    LogCapture capture = {0, ""};
    fmi3Instance c = me_instance(&capture);
    const fmi3ValueReference unknowns[2] = {VR_DER_THETA, VR_DER_OMEGA}, knowns[2] = {VR_THETA, VR_OMEGA};
    const fmi3Float64 x[2] = {0.7, -0.2}, seed[2] = {1.0, 0.0};
    fmi3Float64 dx[2], sensitivity[2], adjoint[2];
    size_t n = 0;
    fmi3Boolean enter = fmi3True, terminate = fmi3True;
    CHECK(fmi3GetNumberOfContinuousStates(c, &n) == fmi3OK && n == 2, "two states");
    initialize(c, 0.1);
    CHECK(fmi3EnterContinuousTimeMode(c) == fmi3OK, "continuous time mode");
    CHECK(fmi3SetTime(c, 0.3) == fmi3OK && fmi3SetContinuousStates(c, x, 2) == fmi3OK, "set time and states");
    CHECK(fmi3GetContinuousStateDerivatives(c, dx, 2) == fmi3OK && dx[0] == x[1] &&
              fabs(dx[1] + 9.81 * sin(x[0])) < 1e-15, "derivatives");
    CHECK(fmi3GetDirectionalDerivative(c, unknowns, 2, knowns, 2, seed, 2, sensitivity, 2) == fmi3OK &&
              sensitivity[0] == 0.0 && fabs(sensitivity[1] + 9.81 * cos(x[0])) < 1e-15, "column d/dtheta");
    CHECK(fmi3GetAdjointDerivative(c, unknowns, 2, knowns, 2, seed, 2, adjoint, 2) == fmi3OK && adjoint[0] == 0.0 &&
              adjoint[1] == 1.0, "row of der(theta)");
    CHECK(fmi3CompletedIntegratorStep(c, fmi3True, &enter, &terminate) == fmi3OK && !enter && !terminate,
          "completed step");
    expect_error(fmi3GetDirectionalDerivative(c, unknowns, 2, knowns, 2, seed, 1, sensitivity, 2), &capture,
                 "nSeed 1", "a short seed");
    fmi3FreeInstance(c);
}

/* The certificate (fmu_src/instance/certificate.c) in FMI 3.0: rk4 at tol 1e-10 with 1 - m = -2e-11,
 * beyond rk4's reach, goes beyond the bound within 10 revolutions: fmi3DoStep returns fmi3Warning
 * there and logs "certificate: ..."; rkn holds the same case, every step fmi3OK
 * (docs/certificate.md). */
static int certificate_run(int solver, LogCapture *capture, int *warnings) {
    fmi3Instance c = cs_instance(capture);
    const fmi3ValueReference vrs[2] = {VR_THETA, VR_OMEGA}, vr_solver = VR_SOLVER;
    const fmi3Float64 start[2] = {0.0, 2.0 * sqrt(9.81) * (1.0 + 1e-11)};
    const fmi3Int64 kind = solver;
    fmi3Boolean event, terminate, early;
    fmi3Float64 last, period = 0.0;
    const fmi3ValueReference vr_period = VR_PERIOD;
    int failed = 0;
    *warnings = 0;
    fmi3EnterInitializationMode(c, fmi3True, 1e-10, 0.0, fmi3False, 0.0);
    fmi3SetFloat64(c, vrs, 2, start, 2);
    fmi3SetInt64(c, &vr_solver, 1, &kind, 1);
    fmi3ExitInitializationMode(c);
    fmi3GetFloat64(c, &vr_period, 1, &period, 1);
    for (int i = 0; i < 200; i++) {
        const fmi3Status status = fmi3DoStep(c, i * period / 20.0, period / 20.0, fmi3True, &event, &terminate,
                                             &early, &last);
        *warnings += status == fmi3Warning;
        failed += status != fmi3OK && status != fmi3Warning;
    }
    fmi3FreeInstance(c);
    return failed;
}

static void test_certificate_warns(void) {
    LogCapture capture = {0, ""};
    int warnings = 0;
    CHECK(certificate_run(2, &capture, &warnings) == 0, "rk4 near the separatrix: every step OK or Warning");
    check(warnings > 0, "rk4 near the separatrix: no fmi3Warning (%d)", warnings);
    check(strncmp(capture.last, "certificate: ", 13) == 0 && strstr(capture.last, "solver rk4") != NULL,
          "the certificate's message: \"%s\"", capture.last);
    LogCapture quiet = {0, ""};
    CHECK(certificate_run(3, &quiet, &warnings) == 0 && warnings == 0 && quiet.last[0] == '\0',
          "rkn holds the same case: every step fmi3OK, nothing logged");
}

int main(void) {
    test_instantiation();
    test_calling_sequence_and_bad_input();
    test_states_round_trip();
    test_model_exchange_and_derivatives();
    test_certificate_warns();
    return check_summary("test_fmi3_api");
}
