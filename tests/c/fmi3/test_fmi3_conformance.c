/* test_fmi3_conformance.c: the FMI conformance cases of tests/c/conformance_cases.h against the
 * FMI 3.0 library: the adapter from the cases' calls to the fmi3 functions. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../check.h"
#include "../conformance_cases.h"
#include "fmi3_api.h"
#include "pendulum_vrs.h"

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    Log *log = env;
    if (strcmp(category, "logCalls") == 0) {
        log->calls++;
        snprintf(log->last_call, sizeof log->last_call, "%s", message);
    } else if (status == fmi3Error) {
        snprintf(log->last_error, sizeof log->last_error, "%s", message);
    }
}

static void *instantiate(Log *log, int co_simulation, int logging_on) {
    if (co_simulation) {
        return fmi3InstantiateCoSimulation("conformance", PENDULUM_GUID, NULL, fmi3False, logging_on != 0, fmi3False,
                                           fmi3False, NULL, 0, log, logger, NULL);
    }
    return fmi3InstantiateModelExchange("conformance", PENDULUM_GUID, NULL, fmi3False, logging_on != 0, log, logger);
}

static void free_instance(void *c) {
    fmi3FreeInstance(c);
}

static const fmi3ValueReference REALS[2] = {VR_THETA, VR_OMEGA}, SOLVER = VR_SOLVER, STEPS = VR_STATS_STEPS;
static const fmi3ValueReference EXACT = VR_THETA_EXACT, PERIOD = VR_PERIOD, THETA = VR_THETA;
static const fmi3Float64 X[2] = {0.2, 0.1};

static int enter_initialization(Fixture *f) {
    return fmi3EnterInitializationMode(f->c, f->tolerance_defined ? fmi3True : fmi3False,
                                       f->tolerance_defined ? 1e-8 : 0.0, 0.0, fmi3False, 0.0);
}

static int exit_initialization(Fixture *f) {
    return fmi3ExitInitializationMode(f->c);
}

static int set_reals(Fixture *f) {
    const fmi3Float64 values[2] = {1.0, 0.5};
    return fmi3SetFloat64(f->c, REALS, 2, values, 2);
}

static int get_reals(Fixture *f) {
    fmi3Float64 values[2];
    return fmi3GetFloat64(f->c, REALS, 2, values, 2);
}

static int get_solver(Fixture *f) {
    fmi3Int64 value = 0;
    const fmi3Status status = fmi3GetInt64(f->c, &SOLVER, 1, &value, 1);
    f->solver = (long)value;
    return status;
}

static int set_solver(Fixture *f) {
    const fmi3Int64 value = f->solver;
    return fmi3SetInt64(f->c, &SOLVER, 1, &value, 1);
}

static int get_statistic(Fixture *f) {
    fmi3Int32 steps = 0;
    return fmi3GetInt32(f->c, &STEPS, 1, &steps, 1);
}

static int directional(Fixture *f) {
    const fmi3Float64 seed = 1.0;
    fmi3Float64 derivative = 0.0;
    return fmi3GetDirectionalDerivative(f->c, &PERIOD, 1, &THETA, 1, &seed, 1, &derivative, 1);
}

static int adjoint(Fixture *f) {
    const fmi3Float64 seed = 1.0;
    fmi3Float64 derivative = 0.0;
    return fmi3GetAdjointDerivative(f->c, &PERIOD, 1, &THETA, 1, &seed, 1, &derivative, 1);
}

static int do_step(Fixture *f) {
    fmi3Boolean event = fmi3False, terminate_simulation = fmi3False, early = fmi3False;
    fmi3Float64 last = 0.0;
    return fmi3DoStep(f->c, 0.0, 0.1, fmi3True, &event, &terminate_simulation, &early, &last);
}

static int output_derivative(Fixture *f) {
    const fmi3Int32 order = 1;
    fmi3Float64 derivative = 0.0;
    return fmi3GetOutputDerivatives(f->c, &EXACT, 1, &order, &derivative, 1);
}

static int get_state(Fixture *f) {
    return fmi3GetFMUState(f->c, &f->state);
}

static int set_state(Fixture *f) {
    return fmi3SetFMUState(f->c, f->state);
}

static int state_size(Fixture *f) {
    return fmi3SerializedFMUStateSize(f->c, f->state, &f->size);
}

static int serialize(Fixture *f) {
    return fmi3SerializeFMUState(f->c, f->state, (fmi3Byte *)f->blob, f->size);
}

static int deserialize(Fixture *f) {
    return fmi3DeserializeFMUState(f->c, (const fmi3Byte *)f->blob, f->size, &f->restored);
}

static int free_restored(Fixture *f) {
    return fmi3FreeFMUState(f->c, &f->restored);
}

static int free_state(Fixture *f) {
    return fmi3FreeFMUState(f->c, &f->state);
}

static int terminate(Fixture *f) {
    return fmi3Terminate(f->c);
}

static int reset(Fixture *f) {
    return fmi3Reset(f->c);
}

static int update_discrete_states(Fixture *f) {
    fmi3Boolean a = fmi3False, b = fmi3False, c = fmi3False, d = fmi3False, e = fmi3False;
    fmi3Float64 next = 0.0;
    return fmi3UpdateDiscreteStates(f->c, &a, &b, &c, &d, &e, &next);
}

static int enter_continuous_time(Fixture *f) {
    return fmi3EnterContinuousTimeMode(f->c);
}

static int set_time(Fixture *f) {
    return fmi3SetTime(f->c, 0.1);
}

static int set_states(Fixture *f) {
    return fmi3SetContinuousStates(f->c, X, 2);
}

static int get_derivatives(Fixture *f) {
    fmi3Float64 dx[2];
    return fmi3GetContinuousStateDerivatives(f->c, dx, 2);
}

static int get_states(Fixture *f) {
    fmi3Float64 x[2];
    return fmi3GetContinuousStates(f->c, x, 2);
}

static int get_nominals(Fixture *f) {
    fmi3Float64 nominals[2];
    return fmi3GetNominalsOfContinuousStates(f->c, nominals, 2);
}

static int get_event_indicators(Fixture *f) {
    fmi3Float64 none[1];
    return fmi3GetEventIndicators(f->c, none, 0);
}

static int number_of_states(Fixture *f) {
    size_t count = 0;
    return fmi3GetNumberOfContinuousStates(f->c, &count);
}

static int number_of_event_indicators(Fixture *f) {
    size_t count = 0;
    return fmi3GetNumberOfEventIndicators(f->c, &count);
}

static int completed_integrator_step(Fixture *f) {
    fmi3Boolean enter = fmi3False, terminate_simulation = fmi3False;
    return fmi3CompletedIntegratorStep(f->c, fmi3True, &enter, &terminate_simulation);
}

static int enter_event_mode(Fixture *f) {
    return fmi3EnterEventMode(f->c);
}

static int get_fmu_state(void *c, void **state) {
    return fmi3GetFMUState(c, state);
}

static int set_fmu_state(void *c, void *state) {
    return fmi3SetFMUState(c, state);
}

static int free_fmu_state(void *c, void **state) {
    return fmi3FreeFMUState(c, state);
}

static int get_theta(void *c, double *theta) {
    return fmi3GetFloat64(c, &THETA, 1, theta, 1);
}

static void start(void *c) {
    fmi3EnterInitializationMode(c, fmi3False, 0.0, 0.0, fmi3False, 0.0);
    fmi3ExitInitializationMode(c);
}

int main(void) {
    const ConformanceApi api = {
        .program = "test_fmi3_conformance",
        .instantiate = instantiate,
        .free_instance = free_instance,
        .setup_experiment = {"fmi3 takes the experiment in fmi3EnterInitializationMode", NULL},
        .enter_initialization = {"fmi3EnterInitializationMode", enter_initialization},
        .set_reals = {"fmi3SetFloat64", set_reals},
        .get_reals = {"fmi3GetFloat64", get_reals},
        .get_solver = {"fmi3GetInt64", get_solver},
        .set_solver = {"fmi3SetInt64", set_solver},
        .directional = {"fmi3GetDirectionalDerivative", directional},
        .adjoint = {"fmi3GetAdjointDerivative", adjoint},
        .exit_initialization = {"fmi3ExitInitializationMode", exit_initialization},
        .do_step = {"fmi3DoStep", do_step},
        .get_statistic = {"fmi3GetInt32", get_statistic},
        .output_derivative = {"fmi3GetOutputDerivatives", output_derivative},
        .get_status = {"fmi3 has no status calls", NULL},
        .get_state = {"fmi3GetFMUState", get_state},
        .set_state = {"fmi3SetFMUState", set_state},
        .state_size = {"fmi3SerializedFMUStateSize", state_size},
        .serialize = {"fmi3SerializeFMUState", serialize},
        .deserialize = {"fmi3DeserializeFMUState", deserialize},
        .free_restored = {"fmi3FreeFMUState", free_restored},
        .free_state = {"fmi3FreeFMUState", free_state},
        .terminate = {"fmi3Terminate", terminate},
        .reset = {"fmi3Reset", reset},
        .update_discrete_states = {"fmi3UpdateDiscreteStates", update_discrete_states},
        .enter_continuous_time = {"fmi3EnterContinuousTimeMode", enter_continuous_time},
        .set_time = {"fmi3SetTime", set_time},
        .set_states = {"fmi3SetContinuousStates", set_states},
        .get_derivatives = {"fmi3GetContinuousStateDerivatives", get_derivatives},
        .get_states = {"fmi3GetContinuousStates", get_states},
        .get_nominals = {"fmi3GetNominalsOfContinuousStates", get_nominals},
        .get_event_indicators = {"fmi3GetEventIndicators", get_event_indicators},
        .number_of_states = {"fmi3GetNumberOfContinuousStates", number_of_states},
        .number_of_event_indicators = {"fmi3GetNumberOfEventIndicators", number_of_event_indicators},
        .completed_integrator_step = {"fmi3CompletedIntegratorStep", completed_integrator_step},
        .enter_event_mode = {"fmi3EnterEventMode", enter_event_mode},
        .get_fmu_state = get_fmu_state,
        .set_fmu_state = set_fmu_state,
        .free_fmu_state = free_fmu_state,
        .get_theta = get_theta,
        .start = start,
    };
    return conformance_run(&api);
}
