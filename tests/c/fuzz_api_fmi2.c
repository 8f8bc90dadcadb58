/* fuzz_api_fmi2.c: the fuzzer's calls in FMI 2.0 (fuzz_api.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi2_api.h"
#include "fuzz_api.h"
#include "pendulum_vrs.h"

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...) {
    char text[600];
    va_list args;
    (void)env, (void)name, (void)status, (void)category;
    va_start(args, message);
    vsnprintf(text, sizeof text, message, args);
    va_end(args);
    fuzz_report(text);
}

static const fmi2CallbackFunctions CALLBACKS = {logger, calloc, free, NULL, NULL};

static void *instantiate(int co_simulation, int logging_on) {
    return fmi2Instantiate("fuzz", co_simulation ? fmi2CoSimulation : fmi2ModelExchange, PENDULUM_GUID, NULL,
                           &CALLBACKS, fmi2False, logging_on ? fmi2True : fmi2False);
}

static int setup_and_enter(void *c, int tolerance_defined, double tolerance) {
    /* a warning (a tolerance below the floor, run at the floor) goes on, as FMI 3.0's one call
     * does; the worse of the two statuses is the pair's */
    int status = fmi2SetupExperiment(c, tolerance_defined, tolerance, 0.0, fmi2False, 0.0);
    int entered;
    if (status != fmi2OK && status != fmi2Warning) {
        return status;
    }
    entered = fmi2EnterInitializationMode(c);
    return entered > status ? entered : status;
}

static int enter_initialization(void *c) { return fmi2EnterInitializationMode(c); }
static int exit_initialization(void *c) { return fmi2ExitInitializationMode(c); }
static int set_real(void *c, unsigned vr, double value) { return fmi2SetReal(c, &vr, 1, &value); }
static int get_real(void *c, unsigned vr, double *value) { return fmi2GetReal(c, &vr, 1, value); }
static int set_integer(void *c, unsigned vr, int value) { return fmi2SetInteger(c, &vr, 1, &value); }
static int get_integer(void *c, unsigned vr, int *value) { return fmi2GetInteger(c, &vr, 1, value); }

static int do_step(void *c, double point, double step, double *reached) {
    int status = fmi2DoStep(c, point, step, fmi2True);
    if (status == fmi2OK || status == fmi2Warning) {
        fmi2GetRealStatus(c, fmi2LastSuccessfulTime, reached);
    }
    return status;
}

static int terminate(void *c) { return fmi2Terminate(c); }
static int reset(void *c) { return fmi2Reset(c); }
static int get_state(void *c, void **state) { return fmi2GetFMUstate(c, state); }
static int set_state(void *c, void *state) { return fmi2SetFMUstate(c, state); }
static int free_state(void *c, void **state) { return fmi2FreeFMUstate(c, state); }
static int state_size(void *c, void *state, size_t *size) { return fmi2SerializedFMUstateSize(c, state, size); }

static int serialize(void *c, void *state, unsigned char *bytes, size_t size) {
    return fmi2SerializeFMUstate(c, state, (fmi2Byte *)bytes, size);
}

static int deserialize(void *c, const unsigned char *bytes, size_t size, void **state) {
    return fmi2DeSerializeFMUstate(c, (const fmi2Byte *)bytes, size, state);
}

static int set_time(void *c, double time) { return fmi2SetTime(c, time); }
static int set_states(void *c, const double *x, size_t n) { return fmi2SetContinuousStates(c, x, n); }
static int get_derivatives(void *c, double *dx, size_t n) { return fmi2GetDerivatives(c, dx, n); }
static int enter_continuous_time(void *c) { return fmi2EnterContinuousTimeMode(c); }

static int update_and_enter_event(void *c) {
    fmi2EventInfo info;
    fmi2NewDiscreteStates(c, &info);
    return fmi2EnterEventMode(c);
}

static int directional(void *c, unsigned unknown, unsigned known, double *value) {
    const double seed = 1.0;
    return fmi2GetDirectionalDerivative(c, &unknown, 1, &known, 1, &seed, value);
}

static int output_derivative(void *c, unsigned vr, int order, double *value) {
    return fmi2GetRealOutputDerivatives(c, &vr, 1, &order, value);
}

const FuzzApi FUZZ_FMI2 = {instantiate, fmi2FreeInstance, setup_and_enter, enter_initialization,
                           exit_initialization, set_real, get_real, set_integer, get_integer, do_step,
                           terminate, reset, get_state, set_state, free_state, state_size, serialize,
                           deserialize, set_time, set_states, get_derivatives, enter_continuous_time,
                           update_and_enter_event, directional, output_derivative};
