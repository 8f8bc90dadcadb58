/* test_fmi_conformance.c: two conformance points of the FMI 2.0 library found by independent
 * importers, tested as an importer meets them:
 *  - with loggingOn, every call logs exactly one logCalls message (a layer that checks the
 *    mode twice logs twice);
 *  - fmi2FreeFMUstate frees only a live state of this instance: the state itself passed
 *    instead of its address (as Reference-FMUs' fmusim once did), another instance's state, a
 *    state freed already, and an overwrite target that is none of its states are refused with
 *    fmi2Error and a message naming the pointer, and never freed or written (ASan and valgrind
 *    see a double free or a stray write). States left live are freed with the instance. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fmi2_api.h"
#include "pendulum_vrs.h"

typedef struct {
    int calls;        /* logCalls messages since the last reset */
    char last_call[600];
    char last_error[600];
} Log;

static void logger(fmi2ComponentEnvironment env, fmi2String instance_name, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    Log *log = env;
    char text[600];
    va_list args;
    (void)instance_name;
    va_start(args, message);
    vsnprintf(text, sizeof text, message, args);
    va_end(args);
    if (strcmp(category, "logCalls") == 0) {
        log->calls++;
        snprintf(log->last_call, sizeof log->last_call, "%s", text);
    } else if (status == fmi2Error) {
        snprintf(log->last_error, sizeof log->last_error, "%s", text);
    }
}

static fmi2Component instance(fmi2Type type, const fmi2CallbackFunctions *callbacks, int logging) {
    return fmi2Instantiate("conformance", type, PENDULUM_GUID, NULL, callbacks, fmi2False, logging ? fmi2True : fmi2False);
}

/* The call `status` logged exactly one logCalls message, naming `function`, and returned OK. */
static void once(Log *log, fmi2Status status, const char *function) {
    check(status == fmi2OK, "%s returned %d", function, (int)status);
    check(log->calls == 1 && strcmp(log->last_call, function) == 0, "%s logged %d logCalls messages (last \"%s\")",
          function, log->calls, log->last_call);
    log->calls = 0;
}

static void test_each_call_is_logged_once(void) {
    Log log = {0, "", ""};
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, &log};
    fmi2Component cs = instance(fmi2CoSimulation, &callbacks, 1), me = instance(fmi2ModelExchange, &callbacks, 1);
    const fmi2ValueReference reals[2] = {VR_THETA, VR_OMEGA}, solver = VR_SOLVER, exact = VR_THETA_EXACT;
    const fmi2ValueReference vr_period = VR_PERIOD, vr_theta = VR_THETA;
    fmi2Real values[2] = {1.0, 0.5}, derivative = 0.0, seed = 1.0, x[2] = {0.2, 0.1};
    fmi2Integer integer = 0, order = 1;
    fmi2FMUstate state = NULL, restored = NULL;
    fmi2Byte blob[4096];
    size_t size = 0;
    fmi2Status kind_status;
    fmi2EventInfo info;
    fmi2Boolean enter = fmi2False, terminate = fmi2False;
    check(cs != NULL && me != NULL, "instantiated");
    log.calls = 0;
    once(&log, fmi2SetupExperiment(cs, fmi2True, 1e-8, 0.0, fmi2False, 0.0), "fmi2SetupExperiment");
    once(&log, fmi2EnterInitializationMode(cs), "fmi2EnterInitializationMode");
    once(&log, fmi2SetReal(cs, reals, 2, values), "fmi2SetReal");
    once(&log, fmi2GetReal(cs, reals, 2, values), "fmi2GetReal");
    once(&log, fmi2GetInteger(cs, &solver, 1, &integer), "fmi2GetInteger");
    once(&log, fmi2SetInteger(cs, &solver, 1, &integer), "fmi2SetInteger");
    once(&log, fmi2GetDirectionalDerivative(cs, &vr_period, 1, &vr_theta, 1, &seed, &derivative),
         "fmi2GetDirectionalDerivative");
    once(&log, fmi2ExitInitializationMode(cs), "fmi2ExitInitializationMode");
    once(&log, fmi2DoStep(cs, 0.0, 0.1, fmi2True), "fmi2DoStep");
    once(&log, fmi2GetRealOutputDerivatives(cs, &exact, 1, &order, &derivative), "fmi2GetRealOutputDerivatives");
    once(&log, fmi2GetStatus(cs, fmi2DoStepStatus, &kind_status), "fmi2GetStatus");
    once(&log, fmi2GetFMUstate(cs, &state), "fmi2GetFMUstate");
    once(&log, fmi2SetFMUstate(cs, state), "fmi2SetFMUstate");
    once(&log, fmi2SerializedFMUstateSize(cs, state, &size), "fmi2SerializedFMUstateSize");
    check(size <= sizeof blob, "serialized size %zu fits the test's buffer", size);
    once(&log, fmi2SerializeFMUstate(cs, state, blob, size), "fmi2SerializeFMUstate");
    once(&log, fmi2DeSerializeFMUstate(cs, blob, size, &restored), "fmi2DeSerializeFMUstate");
    once(&log, fmi2FreeFMUstate(cs, &restored), "fmi2FreeFMUstate");
    once(&log, fmi2FreeFMUstate(cs, &state), "fmi2FreeFMUstate");
    once(&log, fmi2Terminate(cs), "fmi2Terminate");
    once(&log, fmi2Reset(cs), "fmi2Reset");

    once(&log, fmi2SetupExperiment(me, fmi2False, 0.0, 0.0, fmi2False, 0.0), "fmi2SetupExperiment");
    once(&log, fmi2EnterInitializationMode(me), "fmi2EnterInitializationMode");
    once(&log, fmi2ExitInitializationMode(me), "fmi2ExitInitializationMode");
    once(&log, fmi2NewDiscreteStates(me, &info), "fmi2NewDiscreteStates");
    once(&log, fmi2EnterContinuousTimeMode(me), "fmi2EnterContinuousTimeMode");
    once(&log, fmi2SetTime(me, 0.1), "fmi2SetTime");
    once(&log, fmi2SetContinuousStates(me, x, 2), "fmi2SetContinuousStates");
    once(&log, fmi2GetDerivatives(me, values, 2), "fmi2GetDerivatives");
    once(&log, fmi2GetContinuousStates(me, values, 2), "fmi2GetContinuousStates");
    once(&log, fmi2GetNominalsOfContinuousStates(me, values, 2), "fmi2GetNominalsOfContinuousStates");
    once(&log, fmi2GetEventIndicators(me, values, 0), "fmi2GetEventIndicators");
    once(&log, fmi2CompletedIntegratorStep(me, fmi2True, &enter, &terminate), "fmi2CompletedIntegratorStep");
    once(&log, fmi2EnterEventMode(me), "fmi2EnterEventMode");
    fmi2FreeInstance(cs);
    fmi2FreeInstance(me);
}

static fmi2Component ready(const fmi2CallbackFunctions *callbacks) {
    fmi2Component c = instance(fmi2CoSimulation, callbacks, 0);
    fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    fmi2ExitInitializationMode(c);
    return c;
}

/* The call was refused with fmi2Error and an error naming `pointer`. */
static void refused(Log *log, fmi2Status status, const void *pointer, const char *what) {
    char name[64];
    snprintf(name, sizeof name, "%p", pointer);
    check(status == fmi2Error, "%s: status %d, not fmi2Error", what, (int)status);
    check(strstr(log->last_error, name) != NULL && strstr(log->last_error, "not an FMU state of this instance"),
          "%s: the error \"%s\" does not name %s", what, log->last_error, name);
    log->last_error[0] = '\0';
}

static void test_free_takes_only_live_states_of_the_instance(void) {
    Log log = {0, "", ""};
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, &log};
    fmi2Component c = ready(&callbacks), other = ready(&callbacks);
    fmi2FMUstate state = NULL, foreign = NULL, stale = NULL, none = NULL, kept = NULL;
    fmi2Real theta = 0.0;
    const fmi2ValueReference vr = VR_THETA;

    /* the state itself where its address belongs: *state is the state's first bytes */
    check(fmi2GetFMUstate(c, &state) == fmi2OK && state != NULL, "get a state");
    refused(&log, fmi2FreeFMUstate(c, (fmi2FMUstate *)state), *(void **)state, "the state instead of its address");
    check(fmi2FreeFMUstate(c, &state) == fmi2OK && state == NULL, "the state itself is still live and freed after");
    fmi2FreeInstance(c);

    /* another instance's state: refused, and still that instance's to use and free */
    c = ready(&callbacks);
    check(fmi2GetFMUstate(other, &foreign) == fmi2OK, "another instance's state");
    refused(&log, fmi2FreeFMUstate(c, &foreign), foreign, "another instance's state");
    check(foreign != NULL, "the refused pointer is left as it was");
    check(fmi2SetFMUstate(other, foreign) == fmi2OK && fmi2GetReal(other, &vr, 1, &theta) == fmi2OK,
          "the other instance still sets its state");
    check(fmi2FreeFMUstate(other, &foreign) == fmi2OK && foreign == NULL, "and frees it");
    fmi2FreeInstance(c);

    /* a state freed already (a copy of the pointer): a double free refused */
    c = ready(&callbacks);
    check(fmi2GetFMUstate(c, &state) == fmi2OK, "get a state");
    stale = state;
    check(fmi2FreeFMUstate(c, &state) == fmi2OK && state == NULL, "free it");
    refused(&log, fmi2FreeFMUstate(c, &stale), stale, "a state freed already");
    fmi2FreeInstance(c);

    /* an overwrite target that is not a live state of this instance: never written */
    c = ready(&callbacks);
    check(fmi2GetFMUstate(other, &foreign) == fmi2OK, "another instance's state");
    refused(&log, fmi2GetFMUstate(c, &foreign), foreign, "GetFMUstate into another instance's state");
    fmi2FreeInstance(c);
    c = ready(&callbacks);
    check(fmi2GetFMUstate(c, &kept) == fmi2OK && fmi2GetFMUstate(c, &kept) == fmi2OK, "overwrite its own state");

    /* NULL is a no-op (FMI 2.0 2.1.8) */
    check(fmi2FreeFMUstate(c, &none) == fmi2OK, "freeing a NULL state is allowed");
    check(fmi2FreeFMUstate(other, &foreign) == fmi2OK, "the other instance frees its state");
    /* kept and a second live state stay: fmi2FreeInstance frees them (the leak checkers see) */
    check(fmi2GetFMUstate(c, &state) == fmi2OK, "one more state, left live");
    fmi2FreeInstance(c);
    fmi2FreeInstance(other);
}

int main(void) {
    test_each_call_is_logged_once();
    test_free_takes_only_live_states_of_the_instance();
    return check_summary("test_fmi_conformance");
}
