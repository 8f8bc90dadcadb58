/* conformance_cases.h: the FMI conformance cases, written once and run against both versions.
 * Each version's program (tests/c/test_fmi_conformance.c for FMI 2.0,
 * tests/c/fmi3/test_fmi3_conformance.c for FMI 3.0) fills a ConformanceApi over its own FMI
 * functions, includes check.h and this file, and returns conformance_run(&api). The cases:
 *  - with loggingOn, every call logs exactly one logCalls message, naming the call (a layer
 *    that checks the mode twice logs twice, as FMI 3.0's fmi3GetFloat64 once did);
 *  - FreeFMUState frees only a live state of this instance: the state itself passed instead
 *    of its address (as Reference-FMUs' fmusim once did), another instance's state, a state
 *    freed already, and an overwrite target that is none of its states are refused with the
 *    Error status and a message naming the pointer, and never freed or written (ASan and
 *    valgrind see a double free or a stray write). States left live are freed with the
 *    instance. */
#ifndef PENDULUM_TEST_CONFORMANCE_CASES_H
#define PENDULUM_TEST_CONFORMANCE_CASES_H

#include <stdio.h>
#include <string.h>

/* fmi2Status and fmi3Status share these numbers. */
#define CONFORMANCE_OK 0
#define CONFORMANCE_ERROR 3

/* What the version's logger records (its instance environment). */
typedef struct {
    int calls; /* logCalls messages since the last reset */
    char last_call[600];
    char last_error[600];
} Log;

/* What a call of the logging case works on: the instance, the experiment the case asks for,
 * and the FMU states and the buffer the state calls pass on. */
typedef struct {
    void *c;
    int tolerance_defined; /* 1: tolerance 1e-8; 0: the default */
    long solver; /* the value the solver's Get read, for its Set */
    void *state, *restored;
    unsigned char blob[4096];
    size_t size;
} Fixture;

/* One FMI function as the logging case calls it: its name, which it must log, and the call
 * (NULL: the version has no such function). */
typedef struct {
    const char *name;
    int (*call)(Fixture *f);
} Call;

/* A version's FMI functions behind one table; statuses as ints. */
typedef struct {
    const char *program; /* the name in the summary line */
    void *(*instantiate)(Log *log, int co_simulation, int logging_on);
    void (*free_instance)(void *c);
    /* Co-Simulation then Model Exchange calls, in the order both state machines allow.
     * enter_initialization takes the experiment where setup_experiment is NULL (FMI 3.0). */
    Call setup_experiment, enter_initialization, set_reals, get_reals, get_solver, set_solver, directional,
        adjoint, exit_initialization, do_step, get_statistic, output_derivative, get_status, get_state,
        set_state, state_size, serialize, deserialize, free_restored, free_state, terminate, reset;
    Call update_discrete_states, enter_continuous_time, set_time, set_states, get_derivatives, get_states,
        get_nominals, get_event_indicators, number_of_states, number_of_event_indicators,
        completed_integrator_step, enter_event_mode;
    /* the FMU-state functions on a given state, and theta's value (FreeFMUState's case) */
    int (*get_fmu_state)(void *c, void **state);
    int (*set_fmu_state)(void *c, void *state);
    int (*free_fmu_state)(void *c, void **state);
    int (*get_theta)(void *c, double *theta);
    /* a Co-Simulation instance's default experiment, initialization entered and left */
    void (*start)(void *c);
} ConformanceApi;

/* The call logged exactly one logCalls message, naming it, and returned OK. */
static void once(Log *log, const Call *call, Fixture *f) {
    const int status = call->call(f);
    check(status == CONFORMANCE_OK, "%s returned %d", call->name, status);
    check(log->calls == 1 && strcmp(log->last_call, call->name) == 0,
          "%s logged %d logCalls messages (last \"%s\")", call->name, log->calls, log->last_call);
    log->calls = 0;
}

/* Each call of the list that the version has, once. */
static void each_once(Log *log, const Call *const calls[], size_t n, Fixture *f) {
    size_t i;
    for (i = 0; i < n; i++) {
        if (calls[i]->call != NULL) {
            once(log, calls[i], f);
        }
    }
}

static void test_each_call_is_logged_once(const ConformanceApi *api) {
    Log log = {0, "", ""};
    static Fixture cs, me; /* static: the state buffer stays off the stack */
    const Call *const cs_calls[] = {
        &api->setup_experiment, &api->enter_initialization, &api->set_reals, &api->get_reals, &api->get_solver,
        &api->set_solver, &api->directional, &api->adjoint, &api->exit_initialization, &api->do_step,
        &api->get_statistic, &api->output_derivative, &api->get_status, &api->get_state, &api->set_state,
        &api->state_size};
    const Call *const cs_after_size[] = {&api->serialize, &api->deserialize, &api->free_restored,
                                         &api->free_state, &api->terminate, &api->reset};
    const Call *const me_calls[] = {
        &api->setup_experiment, &api->enter_initialization, &api->exit_initialization,
        &api->update_discrete_states, &api->enter_continuous_time, &api->set_time, &api->set_states,
        &api->get_derivatives, &api->get_states, &api->get_nominals, &api->get_event_indicators,
        &api->number_of_states, &api->number_of_event_indicators, &api->completed_integrator_step,
        &api->enter_event_mode};
    memset(&cs, 0, sizeof cs);
    memset(&me, 0, sizeof me);
    cs.c = api->instantiate(&log, 1, 1);
    me.c = api->instantiate(&log, 0, 1);
    cs.tolerance_defined = 1;
    check(cs.c != NULL && me.c != NULL, "instantiated");
    if (cs.c != NULL && me.c != NULL) {
        log.calls = 0;
        each_once(&log, cs_calls, sizeof cs_calls / sizeof cs_calls[0], &cs);
        check(cs.size <= sizeof cs.blob, "serialized size %zu fits the test's buffer", cs.size);
        if (cs.size <= sizeof cs.blob) {
            each_once(&log, cs_after_size, sizeof cs_after_size / sizeof cs_after_size[0], &cs);
        }
        each_once(&log, me_calls, sizeof me_calls / sizeof me_calls[0], &me);
    }
    api->free_instance(cs.c);
    api->free_instance(me.c);
}

static void *ready(const ConformanceApi *api, Log *log) {
    void *c = api->instantiate(log, 1, 0);
    api->start(c);
    return c;
}

/* The call was refused with the Error status and an error naming `pointer`. */
static void refused(Log *log, int status, const void *pointer, const char *what) {
    char name[64];
    snprintf(name, sizeof name, "%p", pointer);
    check(status == CONFORMANCE_ERROR, "%s: status %d, not Error", what, status);
    check(strstr(log->last_error, name) != NULL && strstr(log->last_error, "not an FMU state of this instance"),
          "%s: the error \"%s\" does not name %s", what, log->last_error, name);
    log->last_error[0] = '\0';
}

static void test_free_takes_only_live_states_of_the_instance(const ConformanceApi *api) {
    Log log = {0, "", ""};
    void *c = ready(api, &log), *other = ready(api, &log);
    void *state = NULL, *foreign = NULL, *stale = NULL, *none = NULL, *kept = NULL;
    double theta = 0.0;

    /* the state itself where its address belongs: *state is the state's first bytes */
    check(api->get_fmu_state(c, &state) == CONFORMANCE_OK && state != NULL, "get a state");
    refused(&log, api->free_fmu_state(c, (void **)state), *(void **)state, "the state instead of its address");
    check(api->free_fmu_state(c, &state) == CONFORMANCE_OK && state == NULL,
          "the state itself is still live and freed after");
    api->free_instance(c);

    /* another instance's state: refused, and still that instance's to use and free */
    c = ready(api, &log);
    check(api->get_fmu_state(other, &foreign) == CONFORMANCE_OK, "another instance's state");
    refused(&log, api->free_fmu_state(c, &foreign), foreign, "another instance's state");
    check(foreign != NULL, "the refused pointer is left as it was");
    check(api->set_fmu_state(other, foreign) == CONFORMANCE_OK && api->get_theta(other, &theta) == CONFORMANCE_OK,
          "the other instance still sets its state");
    check(api->free_fmu_state(other, &foreign) == CONFORMANCE_OK && foreign == NULL, "and frees it");
    api->free_instance(c);

    /* a state freed already (a copy of the pointer): a double free refused */
    c = ready(api, &log);
    check(api->get_fmu_state(c, &state) == CONFORMANCE_OK, "get a state");
    stale = state;
    check(api->free_fmu_state(c, &state) == CONFORMANCE_OK && state == NULL, "free it");
    refused(&log, api->free_fmu_state(c, &stale), stale, "a state freed already");
    api->free_instance(c);

    /* an overwrite target that is not a live state of this instance: never written */
    c = ready(api, &log);
    check(api->get_fmu_state(other, &foreign) == CONFORMANCE_OK, "another instance's state");
    refused(&log, api->get_fmu_state(c, &foreign), foreign, "GetFMUState into another instance's state");
    api->free_instance(c);
    c = ready(api, &log);
    check(api->get_fmu_state(c, &kept) == CONFORMANCE_OK && api->get_fmu_state(c, &kept) == CONFORMANCE_OK,
          "overwrite its own state");

    /* NULL is a no-op (FMI 2.0 2.1.8, FMI 3.0 2.2.6.4) */
    check(api->free_fmu_state(c, &none) == CONFORMANCE_OK, "freeing a NULL state is allowed");
    check(api->free_fmu_state(other, &foreign) == CONFORMANCE_OK, "the other instance frees its state");
    /* kept and a second live state stay: FreeInstance frees them (the leak checkers see) */
    check(api->get_fmu_state(c, &state) == CONFORMANCE_OK, "one more state, left live");
    api->free_instance(c);
    api->free_instance(other);
}

/* Every case against one version; the program's exit status. */
static int conformance_run(const ConformanceApi *api) {
    test_each_call_is_logged_once(api);
    test_free_takes_only_live_states_of_the_instance(api);
    return check_summary(api->program);
}

#endif
