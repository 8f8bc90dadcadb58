/* test_fmi_api.c: calls the FMI 2.0 functions of Pendulum directly, as an importer would:
 * the calling sequence, bad input (fmi2Error plus a logged reason), FMU states and their
 * serialization, reset, and independent instances. Runs under ASan/UBSan in the test command. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2_api.h"
#include "pendulum_vrs.h"

static int checks, failures;

#define CHECK(condition, what)                                                        \
    do {                                                                              \
        checks++;                                                                     \
        if (!(condition)) {                                                           \
            failures++;                                                               \
            fprintf(stderr, "%s:%d: FAILED: %s\n", __FILE__, __LINE__, what);         \
        }                                                                             \
    } while (0)

/* What the logger saw: the componentEnvironment of each instance. */
typedef struct {
    int errors;
    char last[600];
} LogCapture;

static void capture_logger(fmi2ComponentEnvironment env, fmi2String instance_name, fmi2Status status,
                           fmi2String category, fmi2String message, ...) {
    LogCapture *capture = env;
    va_list args;
    (void)instance_name, (void)category;
    va_start(args, message);
    vsnprintf(capture->last, sizeof capture->last, message, args);
    va_end(args);
    if (status == fmi2Error) {
        capture->errors++;
    }
}

static fmi2CallbackFunctions callbacks_for(LogCapture *capture) {
    fmi2CallbackFunctions callbacks = {capture_logger, calloc, free, NULL, NULL};
    callbacks.componentEnvironment = capture;
    return callbacks;
}

/* The call returned fmi2Error and logged a message containing `needle`. */
static void expect_error(fmi2Status status, LogCapture *capture, const char *needle, const char *what) {
    CHECK(status == fmi2Error, what);
    if (strstr(capture->last, needle) == NULL) {
        failures++;
        fprintf(stderr, "FAILED: %s: log \"%s\" lacks \"%s\"\n", what, capture->last, needle);
    }
    checks++;
}

static fmi2Component instantiate(fmi2Type type, const fmi2CallbackFunctions *callbacks) {
    return fmi2Instantiate("test", type, PENDULUM_GUID, NULL, callbacks, fmi2False, fmi2False);
}

/* A Co-Simulation instance initialized at theta0 (rad), at rest, tolerance 1e-10. */
static fmi2Component ready_cs(double theta0, const fmi2CallbackFunctions *callbacks) {
    const fmi2ValueReference vr = VR_THETA;
    fmi2Component c = fmi2Instantiate("cs", fmi2CoSimulation, PENDULUM_GUID, NULL, callbacks, fmi2False, fmi2False);
    if (c == NULL || fmi2SetupExperiment(c, fmi2True, 1e-10, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK || fmi2SetReal(c, &vr, 1, &theta0) != fmi2OK ||
        fmi2ExitInitializationMode(c) != fmi2OK) {
        fprintf(stderr, "cannot set up a Co-Simulation instance\n");
        exit(1);
    }
    return c;
}

/* Steps n times by h and returns theta at the end. */
static double run_steps(fmi2Component c, double t0, double h, int n) {
    const fmi2ValueReference vr = VR_THETA;
    double theta = NAN;
    int i;
    for (i = 0; i < n; i++) {
        if (fmi2DoStep(c, t0 + i * h, h, fmi2True) != fmi2OK) {
            return NAN;
        }
    }
    fmi2GetReal(c, &vr, 1, &theta);
    return theta;
}

static void test_instantiate_refuses_bad_arguments(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2CallbackFunctions no_allocator = callbacks;
    no_allocator.allocateMemory = NULL;
    CHECK(fmi2Instantiate("x", fmi2CoSimulation, "{wrong}", NULL, &callbacks, 0, 0) == NULL, "wrong GUID");
    CHECK(strstr(capture.last, "GUID") != NULL, "wrong GUID is logged");
    CHECK(fmi2Instantiate("x", fmi2CoSimulation, NULL, NULL, &callbacks, 0, 0) == NULL, "NULL GUID");
    CHECK(fmi2Instantiate("x", (fmi2Type)7, PENDULUM_GUID, NULL, &callbacks, 0, 0) == NULL, "wrong type");
    CHECK(fmi2Instantiate("x", fmi2CoSimulation, PENDULUM_GUID, NULL, NULL, 0, 0) == NULL, "NULL callbacks");
    CHECK(fmi2Instantiate("x", fmi2CoSimulation, PENDULUM_GUID, NULL, &no_allocator, 0, 0) == NULL,
          "NULL allocateMemory");
    CHECK(fmi2Instantiate(NULL, fmi2CoSimulation, PENDULUM_GUID, NULL, &callbacks, 0, 0) == NULL, "NULL name");
    CHECK(strcmp(fmi2GetVersion(), "2.0") == 0 && strcmp(fmi2GetTypesPlatform(), "default") == 0, "version");
}

static void test_bad_values_are_refused(void) {
    const fmi2ValueReference vr_L = VR_L, vr_theta = VR_THETA, vr_exact = VR_THETA_EXACT;
    const fmi2ValueReference vr_unknown = 999;
    double value = 0.0;
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    struct {
        fmi2ValueReference vr;
        double value;
        const char *needle;
    } cases[] = {{VR_L, -1.0, "greater than 0"}, {VR_L, 0.0, "greater than 0"}, {VR_G, -9.81, "greater than 0"},
                 {VR_L, NAN, "finite"},          {VR_THETA, INFINITY, "finite"}, {VR_OMEGA, -INFINITY, "finite"},
                 {VR_THETA_EXACT, 1.0, "calculated"}, {VR_PERIOD, 1.0, "calculated"}, {999, 1.0, "unknown"}};
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fmi2Component c = instantiate(fmi2CoSimulation, &callbacks);
        expect_error(fmi2SetReal(c, &cases[i].vr, 1, &cases[i].value), &capture, cases[i].needle, "bad fmi2SetReal");
        /* the instance is now in the error state: stepping is refused */
        expect_error(fmi2EnterInitializationMode(c), &capture, "not allowed in state Error", "after an error");
        CHECK(fmi2Reset(c) == fmi2OK, "fmi2Reset leaves the error state");
        CHECK(fmi2EnterInitializationMode(c) == fmi2OK, "usable again after fmi2Reset");
        fmi2FreeInstance(c);
    }
    {
        fmi2Component c = ready_cs(1.0, &callbacks);
        expect_error(fmi2SetReal(c, &vr_L, 1, &value), &capture, "fixed after initialization", "L after init");
        fmi2FreeInstance(c);
        c = ready_cs(1.0, &callbacks);
        expect_error(fmi2GetReal(c, &vr_unknown, 1, &value), &capture, "unknown value reference", "unknown vr");
        fmi2FreeInstance(c);
        c = ready_cs(1.0, &callbacks);
        expect_error(fmi2GetReal(c, NULL, 1, &value), &capture, "NULL", "NULL vr");
        fmi2FreeInstance(c);
        c = ready_cs(1.0, &callbacks);
        CHECK(fmi2GetReal(c, &vr_exact, 0, NULL) == fmi2OK, "nvr = 0 with NULL arrays is fine");
        CHECK(fmi2GetReal(c, &vr_theta, 1, &value) == fmi2OK && value == 1.0, "theta reads back");
        fmi2FreeInstance(c);
    }
}

static void test_calling_sequence_is_enforced(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2Component c = instantiate(fmi2CoSimulation, &callbacks);
    const fmi2ValueReference vr = VR_THETA;
    double theta;
    expect_error(fmi2DoStep(c, 0.0, 0.1, fmi2True), &capture, "fmi2DoStep: not allowed in state Instantiated",
                 "step before init");
    fmi2FreeInstance(c);

    c = ready_cs(1.0, &callbacks);
    expect_error(fmi2DoStep(c, 0.0, 0.0, fmi2True), &capture, "greater than 0", "zero step");
    fmi2Reset(c);
    fmi2FreeInstance(c);
    c = ready_cs(1.0, &callbacks);
    expect_error(fmi2DoStep(c, 0.0, NAN, fmi2True), &capture, "greater than 0", "NaN step");
    fmi2FreeInstance(c);
    c = ready_cs(1.0, &callbacks);
    CHECK(fmi2DoStep(c, 0.0, 0.1, fmi2True) == fmi2OK, "first step");
    expect_error(fmi2DoStep(c, 0.5, 0.1, fmi2True), &capture, "not the current time", "wrong communication point");
    fmi2FreeInstance(c);

    c = ready_cs(1.0, &callbacks);
    CHECK(fmi2DoStep(c, 0.0, 0.1, fmi2True) == fmi2OK, "step");
    CHECK(fmi2Terminate(c) == fmi2OK, "terminate");
    CHECK(fmi2GetReal(c, &vr, 1, &theta) == fmi2OK, "get after terminate is allowed");
    expect_error(fmi2DoStep(c, 0.1, 0.1, fmi2True), &capture, "not allowed in state Terminated", "step after terminate");
    CHECK(fmi2Reset(c) == fmi2OK, "reset after terminate");
    fmi2FreeInstance(c);

    c = instantiate(fmi2ModelExchange, &callbacks);
    expect_error(fmi2SetTime(c, 1.0), &capture, "not allowed in state Instantiated", "ME set time before init");
    fmi2FreeInstance(c);
}

static void test_reset_gives_a_fresh_instance(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2Component fresh = ready_cs(1.0, &callbacks);
    fmi2Component reused = ready_cs(2.5, &callbacks);
    const fmi2ValueReference vr = VR_THETA;
    const double theta0 = 1.0;
    run_steps(reused, 0.0, 0.3, 5);
    CHECK(fmi2Reset(reused) == fmi2OK, "reset");
    fmi2SetupExperiment(reused, fmi2True, 1e-10, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(reused);
    fmi2SetReal(reused, &vr, 1, &theta0);
    CHECK(fmi2ExitInitializationMode(reused) == fmi2OK, "re-initialize after reset");
    CHECK(run_steps(reused, 0.0, 0.25, 8) == run_steps(fresh, 0.0, 0.25, 8), "reset instance equals a fresh one");
    fmi2FreeInstance(fresh);
    fmi2FreeInstance(reused);
}

static void test_fmu_state_roll_back_and_serialization(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2Component c = ready_cs(2.0, &callbacks);
    fmi2Component other = ready_cs(0.3, &callbacks);
    fmi2FMUstate saved = NULL, restored = NULL;
    size_t size = 0;
    fmi2Byte *blob;
    double first, again, elsewhere;
    run_steps(c, 0.0, 0.2, 3);
    CHECK(fmi2GetFMUstate(c, &saved) == fmi2OK && saved != NULL, "get state");
    first = run_steps(c, 0.6, 0.2, 10);
    CHECK(fmi2SetFMUstate(c, saved) == fmi2OK, "set state");
    again = run_steps(c, 0.6, 0.2, 10);
    CHECK(first == again && isfinite(first), "roll back reproduces the steps bit for bit");

    CHECK(fmi2SerializedFMUstateSize(c, saved, &size) == fmi2OK && size > 0, "serialized size");
    blob = malloc(size);
    CHECK(fmi2SerializeFMUstate(c, saved, blob, size) == fmi2OK, "serialize");
    CHECK(fmi2DeSerializeFMUstate(other, blob, size, &restored) == fmi2OK, "deserialize in another instance");
    CHECK(fmi2SetFMUstate(other, restored) == fmi2OK, "set the deserialized state");
    elsewhere = run_steps(other, 0.6, 0.2, 10);
    CHECK(elsewhere == first, "another instance continues bit for bit");

    expect_error(fmi2DeSerializeFMUstate(other, blob, size - 1, &restored), &capture, "bytes", "truncated blob");
    fmi2Reset(other);
    blob[size / 2] ^= 0x5a;
    expect_error(fmi2DeSerializeFMUstate(other, blob, size, &restored), &capture, "corrupted", "corrupted blob");
    fmi2Reset(other);
    blob[size / 2] ^= 0x5a;
    blob[0] = 'X';
    expect_error(fmi2DeSerializeFMUstate(other, blob, size, &restored), &capture, "not a state", "wrong magic");
    fmi2Reset(other);
    CHECK(fmi2FreeFMUstate(other, &restored) == fmi2OK && restored == NULL, "free deserialized state");
    CHECK(fmi2FreeFMUstate(c, &saved) == fmi2OK && saved == NULL, "free state");
    free(blob);
    fmi2FreeInstance(c);
    fmi2FreeInstance(other);
}

static void test_instances_do_not_disturb_each_other(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2Component alone = ready_cs(1.2, &callbacks);
    fmi2Component a = ready_cs(1.2, &callbacks);
    fmi2Component b = ready_cs(3.0, &callbacks);
    const fmi2ValueReference vr = VR_THETA;
    double theta_alone = run_steps(alone, 0.0, 0.1, 40), theta_a = NAN;
    int i;
    for (i = 0; i < 40; i++) { /* interleaved with another instance at another amplitude */
        fmi2DoStep(a, i * 0.1, 0.1, fmi2True);
        fmi2DoStep(b, i * 0.1, 0.1, fmi2True);
    }
    fmi2GetReal(a, &vr, 1, &theta_a);
    CHECK(theta_a == theta_alone, "interleaved instance equals the lone one bit for bit");
    fmi2FreeInstance(alone);
    fmi2FreeInstance(a);
    fmi2FreeInstance(b);
}

static void test_model_exchange_interface(void) {
    LogCapture capture = {0, ""};
    fmi2CallbackFunctions callbacks = callbacks_for(&capture);
    fmi2Component c = instantiate(fmi2ModelExchange, &callbacks);
    fmi2EventInfo info;
    double x[2] = {0.5, -0.25}, dx[2], nominal[2], bad[2] = {NAN, 0.0};
    fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "ME exit init");
    CHECK(fmi2NewDiscreteStates(c, &info) == fmi2OK && !info.newDiscreteStatesNeeded, "no discrete states");
    CHECK(fmi2EnterContinuousTimeMode(c) == fmi2OK, "continuous time mode");
    CHECK(fmi2SetContinuousStates(c, x, 2) == fmi2OK, "set states");
    CHECK(fmi2GetDerivatives(c, dx, 2) == fmi2OK && dx[0] == -0.25 && dx[1] == -9.81 * sin(0.5),
          "derivatives of the full nonlinear model");
    CHECK(fmi2GetNominalsOfContinuousStates(c, nominal, 2) == fmi2OK && nominal[0] == 1.0, "nominals");
    expect_error(fmi2GetDerivatives(c, dx, 3), &capture, "array length", "nx mismatch");
    fmi2FreeInstance(c);
    c = instantiate(fmi2ModelExchange, &callbacks);
    fmi2EnterInitializationMode(c);
    fmi2ExitInitializationMode(c);
    fmi2EnterContinuousTimeMode(c);
    expect_error(fmi2SetContinuousStates(c, bad, 2), &capture, "finite", "NaN state");
    fmi2FreeInstance(c);
}

int main(void) {
    test_instantiate_refuses_bad_arguments();
    test_bad_values_are_refused();
    test_calling_sequence_is_enforced();
    test_reset_gives_a_fresh_instance();
    test_fmu_state_roll_back_and_serialization();
    test_instances_do_not_disturb_each_other();
    test_model_exchange_interface();
    printf("test_fmi_api: %d checks, %d failed\n", checks, failures);
    return failures == 0 ? 0 : 1;
}
