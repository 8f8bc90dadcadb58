/* test_split_api.c: the split pendulum's four binaries (PendulumBody and PendulumGravity, FMI 2.0
 * and FMI 3.0), loaded with dlopen as an importer loads them (argv: Body 2.0, Gravity 2.0, Body
 * 3.0, Gravity 3.0). Checks against formulas written here, independently of fmu_src/split/:
 * Body's closed-form step for a held, a linear and a quadratic input (the Taylor polynomial
 * of degree 4 in power form), the input carried along its polynomial, output derivatives;
 * Gravity's alpha and its derivatives against sin and cos; bad input, misuse and the calling
 * sequence, each refused with a logged reason. */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "fmi2_api.h"
#include "fmi3_api.h"
#include "split.h"
#include "split_tokens.h"

/* --- the logger: the last message and the number of errors --------------------------------- */
static char last_message[800];
static int errors_logged;

static void logger2(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                    fmi2String message, ...) {
    va_list args;
    (void)env, (void)name, (void)category;
    va_start(args, message);
    vsnprintf(last_message, sizeof last_message, message, args);
    va_end(args);
    errors_logged += status == fmi2Error;
}

static void logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category, fmi3String message) {
    (void)env, (void)category;
    snprintf(last_message, sizeof last_message, "%s", message);
    errors_logged += status == fmi3Error;
}

/* The call returned an error and logged a reason containing `needle`. */
static void refused(int status, const char *needle, const char *what) {
    check(status == fmi2Error, "%s: status %d, not an error", what, status);
    check(strstr(last_message, needle) != NULL, "%s: log \"%s\" lacks \"%s\"", what, last_message, needle);
}

static void close_to(double got, double want, double tol, const char *what) {
    check(fabs(got - want) <= tol * fmax(1.0, fabs(want)), "%s: %.17g, want %.17g (tol %g)", what, got, want, tol);
}

/* --- the FMI 2.0 functions of one binary --------------------------------------------------- */
/* X(field, function) for each function the tests call: one list gives the struct its fields
 * and the loader its bindings (DEFINE_LOADER below). */
#define API2_FUNCTIONS(X)                                                                                          \
    X(instantiate, fmi2Instantiate) X(free_instance, fmi2FreeInstance) X(setup, fmi2SetupExperiment)               \
    X(enter_init, fmi2EnterInitializationMode) X(exit_init, fmi2ExitInitializationMode) X(get_real, fmi2GetReal)   \
    X(set_real, fmi2SetReal) X(get_integer, fmi2GetInteger) X(do_step, fmi2DoStep)                                 \
    X(set_input_derivatives, fmi2SetRealInputDerivatives) X(get_output_derivatives, fmi2GetRealOutputDerivatives) \
    X(get_state, fmi2GetFMUstate) X(reset, fmi2Reset) X(terminate, fmi2Terminate)
#define FIELD(field, function) __typeof__(&function) field;

typedef struct {
    void *dll;
    API2_FUNCTIONS(FIELD)
} Api2;

static void *need(void *dll, const char *name) {
    void *f = dlsym(dll, name);
    if (f == NULL) {
        printf("FAIL: %s not exported\n", name);
        exit(1);
    }
    return f;
}

static void *open_library(const char *path) {
    void *dll = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (dll == NULL) {
        printf("FAIL: cannot load %s: %s\n", path, dlerror());
        exit(1);
    }
    return dll;
}

#define BIND(field, function) *(void **)(&api.field) = need(api.dll, #function);
/* A loader of an Api struct whose functions the list LIST names. */
#define DEFINE_LOADER(load, Api, LIST)       \
    static Api load(const char *path) {      \
        Api api;                             \
        api.dll = open_library(path);        \
        LIST(BIND)                           \
        return api;                          \
    }

DEFINE_LOADER(load2, Api2, API2_FUNCTIONS)

static const fmi2CallbackFunctions CALLBACKS = {logger2, calloc, free, NULL, NULL};

static fmi2Component instance2(const Api2 *api, const char *token) {
    return api->instantiate("split", fmi2CoSimulation, token, NULL, &CALLBACKS, fmi2False, fmi2False);
}

static void initialize2(const Api2 *api, fmi2Component c) {
    check(api->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) == fmi2OK, "setup");
    check(api->enter_init(c) == fmi2OK, "enter initialization");
    check(api->exit_init(c) == fmi2OK, "exit initialization: %s", last_message);
}

static double get2(const Api2 *api, fmi2Component c, fmi2ValueReference vr) {
    double value = NAN;
    check(api->get_real(c, &vr, 1, &value) == fmi2OK, "get vr %u: %s", vr, last_message);
    return value;
}

static void set2(const Api2 *api, fmi2Component c, fmi2ValueReference vr, double value) {
    check(api->set_real(c, &vr, 1, &value) == fmi2OK, "set vr %u: %s", vr, last_message);
}

static double output_derivative2(const Api2 *api, fmi2Component c, fmi2ValueReference vr, int order) {
    double value = NAN;
    check(api->get_output_derivatives(c, &vr, 1, &order, &value) == fmi2OK, "output derivative vr %u order %d: %s",
          vr, order, last_message);
    return value;
}

/* Taylor polynomial of the body over h with alpha(s) = a + b s + c s^2 / 2, in power form. */
static void body_formula(double theta, double omega, double a, double b, double c, double h, double *theta_h,
                         double *omega_h) {
    *omega_h = omega + a * h + b * pow(h, 2) / 2.0 + c * pow(h, 3) / 6.0;
    *theta_h = theta + omega * h + a * pow(h, 2) / 2.0 + b * pow(h, 3) / 6.0 + c * pow(h, 4) / 24.0;
}

static void test_body_steps(const Api2 *api) {
    const double theta0 = 0.3, omega0 = -0.2;
    double theta, omega, want_theta, want_omega;
    fmi2Component c = instance2(api, PENDULUM_BODY_TOKEN);
    check(c != NULL, "Body instantiates");
    set2(api, c, SPLIT_VR_THETA, theta0);
    set2(api, c, SPLIT_VR_OMEGA, omega0);
    initialize2(api, c);
    check(get2(api, c, SPLIT_VR_ALPHA) == 0.0, "alpha starts at 0");

    /* held input */
    set2(api, c, SPLIT_VR_ALPHA, 1.7);
    check(api->do_step(c, 0.0, 0.1, fmi2True) == fmi2OK, "held step");
    body_formula(theta0, omega0, 1.7, 0.0, 0.0, 0.1, &want_theta, &want_omega);
    close_to(get2(api, c, SPLIT_VR_THETA), want_theta, 1e-15, "held input: theta");
    close_to(get2(api, c, SPLIT_VR_OMEGA), want_omega, 1e-15, "held input: omega");
    check(get2(api, c, SPLIT_VR_ALPHA) == 1.7, "a held input stays what was set");

    /* linear input: alpha(s) = -0.8 + 2.5 s */
    theta = get2(api, c, SPLIT_VR_THETA);
    omega = get2(api, c, SPLIT_VR_OMEGA);
    {
        const fmi2ValueReference vr = SPLIT_VR_ALPHA;
        const int order = 1;
        const double slope = 2.5;
        set2(api, c, SPLIT_VR_ALPHA, -0.8);
        check(api->set_input_derivatives(c, &vr, 1, &order, &slope) == fmi2OK, "set slope: %s", last_message);
    }
    check(api->do_step(c, 0.1, 0.25, fmi2True) == fmi2OK, "linear step");
    body_formula(theta, omega, -0.8, 2.5, 0.0, 0.25, &want_theta, &want_omega);
    close_to(get2(api, c, SPLIT_VR_THETA), want_theta, 2e-15, "linear input: theta");
    close_to(get2(api, c, SPLIT_VR_OMEGA), want_omega, 2e-15, "linear input: omega");
    close_to(get2(api, c, SPLIT_VR_ALPHA), -0.8 + 2.5 * 0.25, 1e-15, "the input moves along its line");

    /* quadratic input: alpha(s) = 0.4 - 1.1 s + 3.0 s^2 / 2, one step of 0.5 against two of 0.25 */
    theta = get2(api, c, SPLIT_VR_THETA);
    omega = get2(api, c, SPLIT_VR_OMEGA);
    {
        const fmi2ValueReference vrs[2] = {SPLIT_VR_ALPHA, SPLIT_VR_ALPHA};
        const int orders[2] = {1, 2};
        const double values[2] = {-1.1, 3.0};
        set2(api, c, SPLIT_VR_ALPHA, 0.4);
        check(api->set_input_derivatives(c, vrs, 2, orders, values) == fmi2OK, "set derivatives: %s", last_message);
    }
    check(api->do_step(c, 0.35, 0.25, fmi2True) == fmi2OK, "quadratic step 1");
    check(api->do_step(c, 0.6, 0.25, fmi2True) == fmi2OK, "quadratic step 2");
    body_formula(theta, omega, 0.4, -1.1, 3.0, 0.5, &want_theta, &want_omega);
    close_to(get2(api, c, SPLIT_VR_THETA), want_theta, 4e-15, "quadratic input, two steps: theta");
    close_to(get2(api, c, SPLIT_VR_OMEGA), want_omega, 4e-15, "quadratic input, two steps: omega");
    close_to(get2(api, c, SPLIT_VR_ALPHA), 0.4 - 1.1 * 0.5 + 1.5 * 0.25, 1e-15, "alpha at the step's end");
    /* output derivatives at t = 0.85: theta' = omega, theta'' = alpha, theta''' = alpha' */
    close_to(output_derivative2(api, c, SPLIT_VR_THETA, 1), want_omega, 4e-15, "d theta / dt");
    close_to(output_derivative2(api, c, SPLIT_VR_THETA, 2), 0.4 - 1.1 * 0.5 + 1.5 * 0.25, 1e-15, "d2 theta / dt2");
    close_to(output_derivative2(api, c, SPLIT_VR_THETA, 3), -1.1 + 3.0 * 0.5, 1e-15, "d3 theta / dt3");
    close_to(output_derivative2(api, c, SPLIT_VR_OMEGA, 3), 3.0, 0.0, "d3 omega / dt3");
    close_to(get2(api, c, SPLIT_VR_DER_OMEGA), get2(api, c, SPLIT_VR_ALPHA), 0.0, "der(omega) = alpha");
    close_to(get2(api, c, SPLIT_VR_DER_THETA), get2(api, c, SPLIT_VR_OMEGA), 0.0, "der(theta) = omega");
    /* the exact pendulum through (0.3, -0.2): its derivatives are its own right-hand side */
    {
        const double theta_e = get2(api, c, SPLIT_VR_THETA_EXACT), omega_e = get2(api, c, SPLIT_VR_OMEGA_EXACT);
        close_to(output_derivative2(api, c, SPLIT_VR_THETA_EXACT, 1), omega_e, 1e-14, "d theta_exact / dt");
        close_to(output_derivative2(api, c, SPLIT_VR_OMEGA_EXACT, 1), -9.81 * sin(theta_e), 1e-13,
                 "d omega_exact / dt = -(g/L) sin theta_exact");
        /* energy of the exact pendulum kept: omega^2 / 2 - (g/L) cos theta */
        close_to(omega_e * omega_e / 2.0 - 9.81 * cos(theta_e), omega0 * omega0 / 2.0 - 9.81 * cos(theta0), 1e-13,
                 "exact solution's energy");
    }
    api->terminate(c);
    api->free_instance(c);
}

static void test_gravity(const Api2 *api) {
    const double theta = 0.7, d1 = 0.3, d2 = -0.4, a = 9.81 / 2.0;
    fmi2Component c = instance2(api, PENDULUM_GRAVITY_TOKEN);
    check(c != NULL, "Gravity instantiates");
    set2(api, c, SPLIT_VR_L, 2.0);
    initialize2(api, c);
    close_to(get2(api, c, SPLIT_VR_THETA), 1.3089969389957472, 0.0, "theta starts at 75 deg");
    close_to(get2(api, c, SPLIT_VR_L), 2.0, 0.0, "L as set");
    set2(api, c, SPLIT_VR_THETA, theta);
    close_to(get2(api, c, SPLIT_VR_ALPHA), -a * sin(theta), 2.3e-16, "alpha = -(g/L) sin theta");
    close_to(output_derivative2(api, c, SPLIT_VR_ALPHA, 1), 0.0, 0.0, "held input: d alpha / dt = 0");
    {
        const fmi2ValueReference vrs[2] = {SPLIT_VR_THETA, SPLIT_VR_THETA};
        const int orders[2] = {1, 2};
        const double values[2] = {d1, d2};
        check(api->set_input_derivatives(c, vrs, 2, orders, values) == fmi2OK, "set derivatives: %s", last_message);
    }
    close_to(output_derivative2(api, c, SPLIT_VR_ALPHA, 1), -a * cos(theta) * d1, 1e-15, "d alpha / dt");
    close_to(output_derivative2(api, c, SPLIT_VR_ALPHA, 2), -a * (cos(theta) * d2 - sin(theta) * d1 * d1), 1e-15,
             "d2 alpha / dt2");
    /* d alpha / dt against a central difference of the extrapolated input, one step each way */
    {
        const double h = 1e-4;
        const double plus = -a * sin(theta + d1 * h + d2 * h * h / 2.0);
        const double minus = -a * sin(theta - d1 * h + d2 * h * h / 2.0);
        close_to(output_derivative2(api, c, SPLIT_VR_ALPHA, 1), (plus - minus) / (2.0 * h), 1e-7,
                 "d alpha / dt against a central difference");
        check(api->do_step(c, 0.0, h, fmi2True) == fmi2OK, "Gravity step");
        close_to(get2(api, c, SPLIT_VR_ALPHA), plus, 1e-15, "alpha at the step's end, of the extrapolated input");
    }
    api->free_instance(c);
}

static void test_misuse2(const Api2 *body, const Api2 *gravity) {
    const fmi2ValueReference alpha_vr = SPLIT_VR_ALPHA, int_vr = 1;
    const double nan_value = NAN, two = 2.0;
    int order = 3, got_int = 0;
    fmi2Component c;
    check(body->instantiate("x", fmi2CoSimulation, PENDULUM_GRAVITY_TOKEN, NULL, &CALLBACKS, 0, 0) == NULL &&
          strstr(last_message, "token") != NULL, "Body refuses Gravity's token: %s", last_message);
    check(body->instantiate("x", fmi2ModelExchange, PENDULUM_BODY_TOKEN, NULL, &CALLBACKS, 0, 0) == NULL &&
          strstr(last_message, "Model Exchange") != NULL, "Body refuses Model Exchange: %s", last_message);
    check(body->instantiate("", fmi2CoSimulation, PENDULUM_BODY_TOKEN, NULL, &CALLBACKS, 0, 0) == NULL,
          "an empty instance name is refused");

    /* no solver runs in the split FMUs: a tolerance below the core's certificate floor is taken,
       one outside (0, 1) refused */
    c = instance2(body, PENDULUM_BODY_TOKEN);
    check(body->setup(c, fmi2True, 1e-16, 0.0, fmi2False, 0.0) == fmi2OK && body->enter_init(c) == fmi2OK &&
          body->exit_init(c) == fmi2OK, "Body takes tolerance 1e-16: %s", last_message);
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    refused(body->setup(c, fmi2True, 2.0, 0.0, fmi2False, 0.0), "(0, 1)", "tolerance 2");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    refused(body->do_step(c, 0.0, 0.1, fmi2True), "not allowed in state Instantiated", "DoStep before initialization");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    refused(body->set_real(c, &alpha_vr, 1, &nan_value), "finite", "alpha = NaN");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    {
        const fmi2ValueReference L = SPLIT_VR_L;
        const double minus = -1.0;
        refused(body->set_real(c, &L, 1, &minus), "greater than 0", "L = -1");
    }
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    {
        const fmi2ValueReference exact = SPLIT_VR_THETA_EXACT;
        refused(body->set_real(c, &exact, 1, &two), "calculated", "theta_exact set");
    }
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    {
        const fmi2ValueReference theta_vr = SPLIT_VR_THETA;
        refused(body->set_real(c, &theta_vr, 1, &two), "fixed after initialization", "theta set after initialization");
    }
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    refused(body->do_step(c, 0.5, 0.1, fmi2True), "is not the current time", "DoStep from the wrong point");
    refused(body->do_step(c, 0.0, 0.1, fmi2True), "not allowed in state Error", "the instance stays in Error");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    refused(body->do_step(c, 0.0, -0.1, fmi2True), "greater than 0", "a negative step");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    refused(body->set_input_derivatives(c, &alpha_vr, 1, &order, &two), "not in 1..2", "input derivative of order 3");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    {
        const fmi2ValueReference theta_vr = SPLIT_VR_THETA;
        order = 1;
        refused(body->set_input_derivatives(c, &theta_vr, 1, &order, &two), "not an input", "derivative of an output");
    }
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    order = 1;
    refused(body->set_input_derivatives(c, &alpha_vr, 1, &order, &nan_value), "finite", "a NaN derivative");
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    {
        const fmi2ValueReference theta_vr = SPLIT_VR_THETA;
        double value;
        order = 4;
        refused(body->get_output_derivatives(c, &theta_vr, 1, &order, &value), "maxOutputDerivativeOrder",
                "output derivative of order 4");
    }
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    refused(body->get_state(c, NULL), "state is NULL", "GetFMUstate into NULL"); /* states: test_split_states.c */
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    refused(body->get_integer(c, &int_vr, 1, &got_int), "no variable of this type", "an Integer read");
    /* Reset: back to the start values, the input too */
    c = (body->free_instance(c), instance2(body, PENDULUM_BODY_TOKEN));
    initialize2(body, c);
    set2(body, c, SPLIT_VR_ALPHA, 3.0);
    check(body->do_step(c, 0.0, 0.1, fmi2True) == fmi2OK, "a step before Reset");
    check(body->reset(c) == fmi2OK, "Reset");
    initialize2(body, c);
    close_to(get2(body, c, SPLIT_VR_ALPHA), 0.0, 0.0, "alpha after Reset");
    close_to(get2(body, c, SPLIT_VR_THETA), 1.3089969389957472, 0.0, "theta after Reset");
    body->free_instance(c);

    c = instance2(gravity, PENDULUM_GRAVITY_TOKEN);
    initialize2(gravity, c);
    {
        double value;
        order = 3;
        refused(gravity->get_output_derivatives(c, &alpha_vr, 1, &order, &value), "not in 1..2",
                "Gravity's output derivative of order 3");
    }
    c = (gravity->free_instance(c), instance2(gravity, PENDULUM_GRAVITY_TOKEN));
    {
        const fmi2ValueReference g_vr = SPLIT_VR_G;
        const double inf = INFINITY;
        refused(gravity->set_real(c, &g_vr, 1, &inf), "finite", "g = inf");
    }
    c = (gravity->free_instance(c), instance2(gravity, PENDULUM_GRAVITY_TOKEN));
    refused(gravity->set_real(c, &alpha_vr, 1, &two), "calculated", "Gravity's alpha set");
    gravity->free_instance(c);
}

/* --- FMI 3.0: the input held over each step, the same step ---------------------------------- */
#define API3_FUNCTIONS(X)                                                                                     \
    X(instantiate, fmi3InstantiateCoSimulation) X(instantiate_me, fmi3InstantiateModelExchange)               \
    X(free_instance, fmi3FreeInstance) X(enter_init, fmi3EnterInitializationMode)                             \
    X(exit_init, fmi3ExitInitializationMode) X(get, fmi3GetFloat64) X(set, fmi3SetFloat64) X(do_step, fmi3DoStep) \
    X(get_output_derivatives, fmi3GetOutputDerivatives) X(set_time, fmi3SetTime)

typedef struct {
    void *dll;
    API3_FUNCTIONS(FIELD)
} Api3;

DEFINE_LOADER(load3, Api3, API3_FUNCTIONS)

static fmi3Instance instance3(const Api3 *api, const char *token) {
    fmi3Instance c = api->instantiate("split", token, NULL, fmi3False, fmi3False, fmi3False, fmi3False, NULL, 0, NULL,
                                      logger3, NULL);
    check(c != NULL, "FMI 3.0 instantiation: %s", last_message);
    check(api->enter_init(c, fmi3False, 0.0, 0.0, fmi3False, 0.0) == fmi3OK, "FMI 3.0 enter initialization");
    check(api->exit_init(c) == fmi3OK, "FMI 3.0 exit initialization: %s", last_message);
    return c;
}

static double get3(const Api3 *api, fmi3Instance c, fmi3ValueReference vr) {
    double value = NAN;
    check(api->get(c, &vr, 1, &value, 1) == fmi3OK, "FMI 3.0 get vr %u: %s", vr, last_message);
    return value;
}

static void test_fmi3(const Api3 *body, const Api3 *gravity) {
    const fmi3ValueReference alpha = SPLIT_VR_ALPHA, theta = SPLIT_VR_THETA;
    const double a = -2.25;
    double want_theta, want_omega, value = 0.0, last_time = 0.0;
    fmi3Boolean event = 1, terminate = 1, early = 1;
    int order = 1;
    fmi3Instance c = instance3(body, PENDULUM_BODY_TOKEN);
    check(body->set(c, &alpha, 1, &a, 1) == fmi3OK, "FMI 3.0 set alpha");
    check(body->do_step(c, 0.0, 0.2, fmi3True, &event, &terminate, &early, &last_time) == fmi3OK, "FMI 3.0 step");
    check(!event && !terminate && !early && last_time == 0.2, "FMI 3.0 step's outputs");
    body_formula(1.3089969389957472, 0.0, a, 0.0, 0.0, 0.2, &want_theta, &want_omega);
    close_to(get3(body, c, SPLIT_VR_THETA), want_theta, 1e-15, "FMI 3.0 held input: theta");
    close_to(get3(body, c, SPLIT_VR_OMEGA), want_omega, 1e-15, "FMI 3.0 held input: omega");
    close_to(get3(body, c, SPLIT_VR_TIME), 0.2, 0.0, "FMI 3.0 time");
    check(body->get_output_derivatives(c, &theta, 1, &order, &value, 1) == fmi3OK && value == want_omega,
          "FMI 3.0 d theta / dt = omega");
    refused(body->set_time(c, 1.0), "Model Exchange", "FMI 3.0 fmi3SetTime on a Co-Simulation instance");
    body->free_instance(c);
    check(body->instantiate_me("x", PENDULUM_BODY_TOKEN, NULL, 0, 0, NULL, logger3) == NULL &&
          strstr(last_message, "Co-Simulation only") != NULL, "FMI 3.0 Model Exchange refused: %s", last_message);

    c = instance3(gravity, PENDULUM_GRAVITY_TOKEN);
    check(gravity->set(c, &theta, 1, &a, 1) == fmi3OK, "FMI 3.0 set theta");
    close_to(get3(gravity, c, SPLIT_VR_ALPHA), -9.81 * sin(a), 2.3e-16, "FMI 3.0 alpha");
    refused(gravity->get_output_derivatives(c, &alpha, 1, &order, &value, 1), "not in 1..0",
            "FMI 3.0 Gravity has no output derivatives");
    gravity->free_instance(c);
}

int main(int argc, char **argv) {
    Api2 body, gravity;
    if (argc != 5) {
        printf("usage: %s Body2.so Gravity2.so Body3.so Gravity3.so\n", argv[0]);
        return 2;
    }
    body = load2(argv[1]);
    gravity = load2(argv[2]);
    test_body_steps(&body);
    test_gravity(&gravity);
    test_misuse2(&body, &gravity);
    {
        Api3 body3 = load3(argv[3]), gravity3 = load3(argv[4]);
        test_fmi3(&body3, &gravity3);
    }
    printf("errors logged: %d\n", errors_logged);
    return check_summary("test_split_api");
}
