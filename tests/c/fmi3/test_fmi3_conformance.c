/* test_fmi3_conformance.c: the conformance points of tests/c/test_fmi_conformance.c for the
 * FMI 3.0 library:
 *  - with loggingOn, every call logs exactly one logCalls message (fmi3GetFloat64,
 *    fmi3SetFloat64, fmi3GetInt32, fmi3GetInt64 and fmi3EnterInitializationMode once logged
 *    two: the layer and the shared instance each checked the mode);
 *  - fmi3FreeFMUState frees only a live state of this instance: the state itself instead of
 *    its address, another instance's state, a state freed already, and an overwrite target
 *    that is none of its states are refused with fmi3Error naming the pointer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../check.h"
#include "fmi3_api.h"
#include "pendulum_vrs.h"

typedef struct {
    int calls;
    char last_call[600];
    char last_error[600];
} Log;

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    Log *log = env;
    if (strcmp(category, "logCalls") == 0) {
        log->calls++;
        snprintf(log->last_call, sizeof log->last_call, "%s", message);
    } else if (status == fmi3Error) {
        snprintf(log->last_error, sizeof log->last_error, "%s", message);
    }
}

static fmi3Instance cs_instance(Log *log, int logging) {
    return fmi3InstantiateCoSimulation("conformance", PENDULUM_GUID, NULL, fmi3False, logging != 0, fmi3False,
                                       fmi3False, NULL, 0, log, logger, NULL);
}

static void once(Log *log, fmi3Status status, const char *function) {
    check(status == fmi3OK, "%s returned %d", function, (int)status);
    check(log->calls == 1 && strcmp(log->last_call, function) == 0, "%s logged %d logCalls messages (last \"%s\")",
          function, log->calls, log->last_call);
    log->calls = 0;
}

static void test_each_call_is_logged_once(void) {
    Log log = {0, "", ""};
    fmi3Instance cs = cs_instance(&log, 1);
    fmi3Instance me = fmi3InstantiateModelExchange("conformance", PENDULUM_GUID, NULL, fmi3False, fmi3True, &log,
                                                   logger);
    const fmi3ValueReference reals[2] = {VR_THETA, VR_OMEGA}, solver = VR_SOLVER, steps = VR_STATS_STEPS;
    const fmi3ValueReference exact = VR_THETA_EXACT, vr_period = VR_PERIOD, vr_theta = VR_THETA;
    fmi3Float64 values[2] = {1.0, 0.5}, derivative = 0.0, seed = 1.0, x[2] = {0.2, 0.1}, last = 0.0;
    fmi3Int64 solver_value = 0;
    fmi3Int32 steps_value = 0, order = 1;
    fmi3FMUState state = NULL, restored = NULL;
    fmi3Byte blob[4096];
    size_t size = 0, count = 0;
    fmi3Boolean a = fmi3False, b = fmi3False, c = fmi3False, d = fmi3False;
    check(cs != NULL && me != NULL, "instantiated");
    log.calls = 0;
    once(&log, fmi3EnterInitializationMode(cs, fmi3True, 1e-8, 0.0, fmi3False, 0.0), "fmi3EnterInitializationMode");
    once(&log, fmi3SetFloat64(cs, reals, 2, values, 2), "fmi3SetFloat64");
    once(&log, fmi3GetFloat64(cs, reals, 2, values, 2), "fmi3GetFloat64");
    once(&log, fmi3GetInt64(cs, &solver, 1, &solver_value, 1), "fmi3GetInt64");
    once(&log, fmi3SetInt64(cs, &solver, 1, &solver_value, 1), "fmi3SetInt64");
    once(&log, fmi3GetDirectionalDerivative(cs, &vr_period, 1, &vr_theta, 1, &seed, 1, &derivative, 1),
         "fmi3GetDirectionalDerivative");
    once(&log, fmi3GetAdjointDerivative(cs, &vr_period, 1, &vr_theta, 1, &seed, 1, &derivative, 1),
         "fmi3GetAdjointDerivative");
    once(&log, fmi3ExitInitializationMode(cs), "fmi3ExitInitializationMode");
    once(&log, fmi3DoStep(cs, 0.0, 0.1, fmi3True, &a, &b, &c, &last), "fmi3DoStep");
    once(&log, fmi3GetInt32(cs, &steps, 1, &steps_value, 1), "fmi3GetInt32");
    once(&log, fmi3GetOutputDerivatives(cs, &exact, 1, &order, &derivative, 1), "fmi3GetOutputDerivatives");
    once(&log, fmi3GetFMUState(cs, &state), "fmi3GetFMUState");
    once(&log, fmi3SetFMUState(cs, state), "fmi3SetFMUState");
    once(&log, fmi3SerializedFMUStateSize(cs, state, &size), "fmi3SerializedFMUStateSize");
    check(size <= sizeof blob, "serialized size %zu fits the test's buffer", size);
    once(&log, fmi3SerializeFMUState(cs, state, blob, size), "fmi3SerializeFMUState");
    once(&log, fmi3DeserializeFMUState(cs, blob, size, &restored), "fmi3DeserializeFMUState");
    once(&log, fmi3FreeFMUState(cs, &restored), "fmi3FreeFMUState");
    once(&log, fmi3FreeFMUState(cs, &state), "fmi3FreeFMUState");
    once(&log, fmi3Terminate(cs), "fmi3Terminate");
    once(&log, fmi3Reset(cs), "fmi3Reset");

    once(&log, fmi3EnterInitializationMode(me, fmi3False, 0.0, 0.0, fmi3False, 0.0), "fmi3EnterInitializationMode");
    once(&log, fmi3ExitInitializationMode(me), "fmi3ExitInitializationMode");
    once(&log, fmi3UpdateDiscreteStates(me, &a, &b, &c, &d, &a, &last), "fmi3UpdateDiscreteStates");
    once(&log, fmi3EnterContinuousTimeMode(me), "fmi3EnterContinuousTimeMode");
    once(&log, fmi3SetTime(me, 0.1), "fmi3SetTime");
    once(&log, fmi3SetContinuousStates(me, x, 2), "fmi3SetContinuousStates");
    once(&log, fmi3GetContinuousStateDerivatives(me, values, 2), "fmi3GetContinuousStateDerivatives");
    once(&log, fmi3GetContinuousStates(me, values, 2), "fmi3GetContinuousStates");
    once(&log, fmi3GetNominalsOfContinuousStates(me, values, 2), "fmi3GetNominalsOfContinuousStates");
    once(&log, fmi3GetEventIndicators(me, values, 0), "fmi3GetEventIndicators");
    once(&log, fmi3GetNumberOfContinuousStates(me, &count), "fmi3GetNumberOfContinuousStates");
    once(&log, fmi3GetNumberOfEventIndicators(me, &count), "fmi3GetNumberOfEventIndicators");
    once(&log, fmi3CompletedIntegratorStep(me, fmi3True, &a, &b), "fmi3CompletedIntegratorStep");
    once(&log, fmi3EnterEventMode(me), "fmi3EnterEventMode");
    fmi3FreeInstance(cs);
    fmi3FreeInstance(me);
}

static fmi3Instance ready(Log *log) {
    fmi3Instance c = cs_instance(log, 0);
    fmi3EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0);
    fmi3ExitInitializationMode(c);
    return c;
}

static void refused(Log *log, fmi3Status status, const void *pointer, const char *what) {
    char name[64];
    snprintf(name, sizeof name, "%p", pointer);
    check(status == fmi3Error, "%s: status %d, not fmi3Error", what, (int)status);
    check(strstr(log->last_error, name) != NULL && strstr(log->last_error, "not an FMU state of this instance"),
          "%s: the error \"%s\" does not name %s", what, log->last_error, name);
    log->last_error[0] = '\0';
}

static void test_free_takes_only_live_states_of_the_instance(void) {
    Log log = {0, "", ""};
    fmi3Instance c = ready(&log), other = ready(&log);
    fmi3FMUState state = NULL, foreign = NULL, stale = NULL, none = NULL;
    fmi3Float64 theta = 0.0;
    const fmi3ValueReference vr = VR_THETA;

    check(fmi3GetFMUState(c, &state) == fmi3OK && state != NULL, "get a state");
    refused(&log, fmi3FreeFMUState(c, (fmi3FMUState *)state), *(void **)state, "the state instead of its address");
    check(fmi3FreeFMUState(c, &state) == fmi3OK && state == NULL, "the state itself is still live and freed after");
    fmi3FreeInstance(c);

    c = ready(&log);
    check(fmi3GetFMUState(other, &foreign) == fmi3OK, "another instance's state");
    refused(&log, fmi3FreeFMUState(c, &foreign), foreign, "another instance's state");
    check(foreign != NULL, "the refused pointer is left as it was");
    check(fmi3SetFMUState(other, foreign) == fmi3OK && fmi3GetFloat64(other, &vr, 1, &theta, 1) == fmi3OK,
          "the other instance still sets its state");
    check(fmi3FreeFMUState(other, &foreign) == fmi3OK && foreign == NULL, "and frees it");
    fmi3FreeInstance(c);

    c = ready(&log);
    check(fmi3GetFMUState(c, &state) == fmi3OK, "get a state");
    stale = state;
    check(fmi3FreeFMUState(c, &state) == fmi3OK && state == NULL, "free it");
    refused(&log, fmi3FreeFMUState(c, &stale), stale, "a state freed already");
    fmi3FreeInstance(c);

    c = ready(&log);
    check(fmi3GetFMUState(other, &foreign) == fmi3OK, "another instance's state");
    refused(&log, fmi3GetFMUState(c, &foreign), foreign, "GetFMUState into another instance's state");
    fmi3FreeInstance(c);

    c = ready(&log);
    check(fmi3FreeFMUState(c, &none) == fmi3OK, "freeing a NULL state is allowed (FMI 3.0 2.2.6.4)");
    check(fmi3FreeFMUState(other, &foreign) == fmi3OK, "the other instance frees its state");
    check(fmi3GetFMUState(c, &state) == fmi3OK, "a state left live: fmi3FreeInstance frees it");
    fmi3FreeInstance(c);
    fmi3FreeInstance(other);
}

int main(void) {
    test_each_call_is_logged_once();
    test_free_takes_only_live_states_of_the_instance();
    return check_summary("test_fmi3_conformance");
}
