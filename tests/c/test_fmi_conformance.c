/* test_fmi_conformance.c: the FMI conformance cases of conformance_cases.h against the FMI 2.0
 * library: the adapter from the cases' calls to the fmi2 functions. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "conformance_cases.h"
#include "fmi2_api.h"
#include "pendulum_vrs.h"

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

static void *instantiate(Log *log, int co_simulation, int logging_on) {
    /* the instance keeps a copy of the callbacks (FMI 2.0 2.1.5) */
    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    callbacks.componentEnvironment = log;
    return fmi2Instantiate("conformance", co_simulation ? fmi2CoSimulation : fmi2ModelExchange, PENDULUM_GUID, NULL,
                           &callbacks, fmi2False, logging_on ? fmi2True : fmi2False);
}

static void free_instance(void *c) {
    fmi2FreeInstance(c);
}

static const fmi2ValueReference REALS[2] = {VR_THETA, VR_OMEGA}, SOLVER = VR_SOLVER, STEPS = VR_STATS_STEPS;
static const fmi2ValueReference EXACT = VR_THETA_EXACT, PERIOD = VR_PERIOD, THETA = VR_THETA;
static const fmi2Real X[2] = {0.2, 0.1};

static int setup_experiment(Fixture *f) {
    return fmi2SetupExperiment(f->c, f->tolerance_defined ? fmi2True : fmi2False, f->tolerance_defined ? 1e-8 : 0.0,
                               0.0, fmi2False, 0.0);
}

static int enter_initialization(Fixture *f) {
    return fmi2EnterInitializationMode(f->c);
}

static int exit_initialization(Fixture *f) {
    return fmi2ExitInitializationMode(f->c);
}

static int set_reals(Fixture *f) {
    const fmi2Real values[2] = {1.0, 0.5};
    return fmi2SetReal(f->c, REALS, 2, values);
}

static int get_reals(Fixture *f) {
    fmi2Real values[2];
    return fmi2GetReal(f->c, REALS, 2, values);
}

static int get_solver(Fixture *f) {
    fmi2Integer value = 0;
    const fmi2Status status = fmi2GetInteger(f->c, &SOLVER, 1, &value);
    f->solver = value;
    return status;
}

static int set_solver(Fixture *f) {
    const fmi2Integer value = (fmi2Integer)f->solver;
    return fmi2SetInteger(f->c, &SOLVER, 1, &value);
}

static int get_statistic(Fixture *f) {
    fmi2Integer steps = 0;
    return fmi2GetInteger(f->c, &STEPS, 1, &steps);
}

static int directional(Fixture *f) {
    const fmi2Real seed = 1.0;
    fmi2Real derivative = 0.0;
    return fmi2GetDirectionalDerivative(f->c, &PERIOD, 1, &THETA, 1, &seed, &derivative);
}

static int do_step(Fixture *f) {
    return fmi2DoStep(f->c, 0.0, 0.1, fmi2True);
}

static int output_derivative(Fixture *f) {
    const fmi2Integer order = 1;
    fmi2Real derivative = 0.0;
    return fmi2GetRealOutputDerivatives(f->c, &EXACT, 1, &order, &derivative);
}

static int get_status(Fixture *f) {
    fmi2Status value;
    return fmi2GetStatus(f->c, fmi2DoStepStatus, &value);
}

static int get_state(Fixture *f) {
    return fmi2GetFMUstate(f->c, &f->state);
}

static int set_state(Fixture *f) {
    return fmi2SetFMUstate(f->c, f->state);
}

static int state_size(Fixture *f) {
    return fmi2SerializedFMUstateSize(f->c, f->state, &f->size);
}

static int serialize(Fixture *f) {
    return fmi2SerializeFMUstate(f->c, f->state, (fmi2Byte *)f->blob, f->size);
}

static int deserialize(Fixture *f) {
    return fmi2DeSerializeFMUstate(f->c, (const fmi2Byte *)f->blob, f->size, &f->restored);
}

static int free_restored(Fixture *f) {
    return fmi2FreeFMUstate(f->c, &f->restored);
}

static int free_state(Fixture *f) {
    return fmi2FreeFMUstate(f->c, &f->state);
}

static int terminate(Fixture *f) {
    return fmi2Terminate(f->c);
}

static int reset(Fixture *f) {
    return fmi2Reset(f->c);
}

static int new_discrete_states(Fixture *f) {
    fmi2EventInfo info;
    return fmi2NewDiscreteStates(f->c, &info);
}

static int enter_continuous_time(Fixture *f) {
    return fmi2EnterContinuousTimeMode(f->c);
}

static int set_time(Fixture *f) {
    return fmi2SetTime(f->c, 0.1);
}

static int set_states(Fixture *f) {
    return fmi2SetContinuousStates(f->c, X, 2);
}

static int get_derivatives(Fixture *f) {
    fmi2Real dx[2];
    return fmi2GetDerivatives(f->c, dx, 2);
}

static int get_states(Fixture *f) {
    fmi2Real x[2];
    return fmi2GetContinuousStates(f->c, x, 2);
}

static int get_nominals(Fixture *f) {
    fmi2Real nominals[2];
    return fmi2GetNominalsOfContinuousStates(f->c, nominals, 2);
}

static int get_event_indicators(Fixture *f) {
    fmi2Real none[1];
    return fmi2GetEventIndicators(f->c, none, 0);
}

static int completed_integrator_step(Fixture *f) {
    fmi2Boolean enter = fmi2False, terminate_simulation = fmi2False;
    return fmi2CompletedIntegratorStep(f->c, fmi2True, &enter, &terminate_simulation);
}

static int enter_event_mode(Fixture *f) {
    return fmi2EnterEventMode(f->c);
}

static int get_fmu_state(void *c, void **state) {
    return fmi2GetFMUstate(c, state);
}

static int set_fmu_state(void *c, void *state) {
    return fmi2SetFMUstate(c, state);
}

static int free_fmu_state(void *c, void **state) {
    return fmi2FreeFMUstate(c, state);
}

static int get_theta(void *c, double *theta) {
    return fmi2GetReal(c, &THETA, 1, theta);
}

static void start(void *c) {
    fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    fmi2ExitInitializationMode(c);
}

int main(void) {
    const ConformanceApi api = {
        .program = "test_fmi_conformance",
        .instantiate = instantiate,
        .free_instance = free_instance,
        .setup_experiment = {"fmi2SetupExperiment", setup_experiment},
        .enter_initialization = {"fmi2EnterInitializationMode", enter_initialization},
        .set_reals = {"fmi2SetReal", set_reals},
        .get_reals = {"fmi2GetReal", get_reals},
        .get_solver = {"fmi2GetInteger", get_solver},
        .set_solver = {"fmi2SetInteger", set_solver},
        .directional = {"fmi2GetDirectionalDerivative", directional},
        .adjoint = {"fmi2 has no adjoint derivatives", NULL},
        .exit_initialization = {"fmi2ExitInitializationMode", exit_initialization},
        .do_step = {"fmi2DoStep", do_step},
        .get_statistic = {"fmi2GetInteger", get_statistic},
        .output_derivative = {"fmi2GetRealOutputDerivatives", output_derivative},
        .get_status = {"fmi2GetStatus", get_status},
        .get_state = {"fmi2GetFMUstate", get_state},
        .set_state = {"fmi2SetFMUstate", set_state},
        .state_size = {"fmi2SerializedFMUstateSize", state_size},
        .serialize = {"fmi2SerializeFMUstate", serialize},
        .deserialize = {"fmi2DeSerializeFMUstate", deserialize},
        .free_restored = {"fmi2FreeFMUstate", free_restored},
        .free_state = {"fmi2FreeFMUstate", free_state},
        .terminate = {"fmi2Terminate", terminate},
        .reset = {"fmi2Reset", reset},
        .update_discrete_states = {"fmi2NewDiscreteStates", new_discrete_states},
        .enter_continuous_time = {"fmi2EnterContinuousTimeMode", enter_continuous_time},
        .set_time = {"fmi2SetTime", set_time},
        .set_states = {"fmi2SetContinuousStates", set_states},
        .get_derivatives = {"fmi2GetDerivatives", get_derivatives},
        .get_states = {"fmi2GetContinuousStates", get_states},
        .get_nominals = {"fmi2GetNominalsOfContinuousStates", get_nominals},
        .get_event_indicators = {"fmi2GetEventIndicators", get_event_indicators},
        .number_of_states = {"fmi2 has no fmi3GetNumberOfContinuousStates", NULL},
        .number_of_event_indicators = {"fmi2 has no fmi3GetNumberOfEventIndicators", NULL},
        .completed_integrator_step = {"fmi2CompletedIntegratorStep", completed_integrator_step},
        .enter_event_mode = {"fmi2EnterEventMode", enter_event_mode},
        .get_fmu_state = get_fmu_state,
        .set_fmu_state = set_fmu_state,
        .free_fmu_state = free_fmu_state,
        .get_theta = get_theta,
        .start = start,
    };
    return conformance_run(&api);
}
