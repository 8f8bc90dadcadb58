/* fuzz_api_fmi3.c: the fuzzer's calls in FMI 3.0 (fuzz_api.h). The solver (an Enumeration) is
 * an Int64, the statistics Int32, as the FMI 3.0 model description declares them. */
#include "fmi3_api.h"
#include "fuzz_api.h"
#include "pendulum_vrs.h"

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    (void)env, (void)status, (void)category;
    fuzz_report(message);
}

static void *instantiate(int co_simulation, int logging_on) {
    if (co_simulation) {
        return fmi3InstantiateCoSimulation("fuzz", PENDULUM_GUID, NULL, fmi3False, logging_on != 0, fmi3False,
                                           fmi3False, NULL, 0, NULL, logger, NULL);
    }
    return fmi3InstantiateModelExchange("fuzz", PENDULUM_GUID, NULL, fmi3False, logging_on != 0, NULL, logger);
}

static int setup_and_enter(void *c, int tolerance_defined, double tolerance) {
    return fmi3EnterInitializationMode(c, tolerance_defined != 0, tolerance, 0.0, fmi3False, 0.0);
}

static int enter_initialization(void *c) { return fmi3EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0); }
static int exit_initialization(void *c) { return fmi3ExitInitializationMode(c); }
static int set_real(void *c, unsigned vr, double value) { return fmi3SetFloat64(c, &vr, 1, &value, 1); }
static int get_real(void *c, unsigned vr, double *value) { return fmi3GetFloat64(c, &vr, 1, value, 1); }

static int set_integer(void *c, unsigned vr, int value) {
    const fmi3Int64 wide = value;
    const fmi3Int32 narrow = value;
    return vr == VR_SOLVER ? fmi3SetInt64(c, &vr, 1, &wide, 1) : fmi3SetInt32(c, &vr, 1, &narrow, 1);
}

static int get_integer(void *c, unsigned vr, int *value) {
    fmi3Int64 wide = 0;
    fmi3Int32 narrow = 0;
    int status = vr == VR_SOLVER ? fmi3GetInt64(c, &vr, 1, &wide, 1) : fmi3GetInt32(c, &vr, 1, &narrow, 1);
    *value = vr == VR_SOLVER ? (int)wide : narrow;
    return status;
}

static int do_step(void *c, double point, double step, double *reached) {
    fmi3Boolean event = fmi3False, terminate_now = fmi3False, early = fmi3False;
    double last = *reached;
    int status = fmi3DoStep(c, point, step, fmi3True, &event, &terminate_now, &early, &last);
    if (status == fmi3OK || status == fmi3Warning) {
        *reached = last;
    }
    return status;
}

static int terminate(void *c) { return fmi3Terminate(c); }
static int reset(void *c) { return fmi3Reset(c); }
static int get_state(void *c, void **state) { return fmi3GetFMUState(c, state); }
static int set_state(void *c, void *state) { return fmi3SetFMUState(c, state); }
static int free_state(void *c, void **state) { return fmi3FreeFMUState(c, state); }
static int state_size(void *c, void *state, size_t *size) { return fmi3SerializedFMUStateSize(c, state, size); }

static int serialize(void *c, void *state, unsigned char *bytes, size_t size) {
    return fmi3SerializeFMUState(c, state, bytes, size);
}

static int deserialize(void *c, const unsigned char *bytes, size_t size, void **state) {
    return fmi3DeserializeFMUState(c, bytes, size, state);
}

static int set_time(void *c, double time) { return fmi3SetTime(c, time); }
static int set_states(void *c, const double *x, size_t n) { return fmi3SetContinuousStates(c, x, n); }
static int get_derivatives(void *c, double *dx, size_t n) { return fmi3GetContinuousStateDerivatives(c, dx, n); }
static int enter_continuous_time(void *c) { return fmi3EnterContinuousTimeMode(c); }

static int update_and_enter_event(void *c) {
    fmi3Boolean update, terminate_now, nominals, values, defined;
    double next;
    fmi3UpdateDiscreteStates(c, &update, &terminate_now, &nominals, &values, &defined, &next);
    return fmi3EnterEventMode(c);
}

static int directional(void *c, unsigned unknown, unsigned known, double *value) {
    const double seed = 1.0;
    return fmi3GetDirectionalDerivative(c, &unknown, 1, &known, 1, &seed, 1, value, 1);
}

static int output_derivative(void *c, unsigned vr, int order, double *value) {
    return fmi3GetOutputDerivatives(c, &vr, 1, &order, value, 1);
}

const FuzzApi FUZZ_FMI3 = {instantiate, fmi3FreeInstance, setup_and_enter, enter_initialization,
                           exit_initialization, set_real, get_real, set_integer, get_integer, do_step,
                           terminate, reset, get_state, set_state, free_state, state_size, serialize,
                           deserialize, set_time, set_states, get_derivatives, enter_continuous_time,
                           update_and_enter_event, directional, output_derivative};
