/* test_fmi_edges.c: the FMI-side hard cases, each refused with fmi2Error and a
 * logged reason: functions of the other interface, steps that would move time
 * backwards, forged and corrupted FMU states, steps out of reach of the step budget.
 * Runs under ASan/UBSan and valgrind in the test command. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "fmi2_api.h"
#include "model.h"
#include "pendulum_vrs.h"

typedef struct {
    int errors, warnings;
    char last[600];
} Log;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                   fmi2String message, ...)
{
    Log *log = env;
    va_list args;
    (void)name, (void)category;
    va_start(args, message);
    vsnprintf(log->last, sizeof log->last, message, args);
    va_end(args);
    log->errors += status == fmi2Error;
    log->warnings += status == fmi2Warning;
}

static fmi2CallbackFunctions callbacks_for(Log *log)
{
    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    callbacks.componentEnvironment = log;
    return callbacks;
}

/* An instance of `type` at theta0 = 1, omega0 = 0.5, initialised (ME: in Continuous-Time Mode). */
static fmi2Component ready(fmi2Type type, const fmi2CallbackFunctions *callbacks)
{
    const fmi2ValueReference vrs[2] = {VR_THETA, VR_OMEGA};
    const double values[2] = {1.0, 0.5};
    fmi2EventInfo info;
    fmi2Component c = fmi2Instantiate("edges", type, PENDULUM_GUID, NULL, callbacks, fmi2False, fmi2False);
    if (c == NULL || fmi2SetupExperiment(c, fmi2True, 1e-8, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi2EnterInitializationMode(c) != fmi2OK || fmi2SetReal(c, vrs, 2, values) != fmi2OK ||
        fmi2ExitInitializationMode(c) != fmi2OK) {
        fprintf(stderr, "cannot set up an instance\n");
        exit(1);
    }
    if (type == fmi2ModelExchange &&
        (fmi2NewDiscreteStates(c, &info) != fmi2OK || fmi2EnterContinuousTimeMode(c) != fmi2OK)) {
        fprintf(stderr, "cannot enter Continuous-Time Mode\n");
        exit(1);
    }
    return c;
}

static void expect_refused(fmi2Status status, const Log *log, const char *needle, const char *what)
{
    check(status == fmi2Error, "%s: status %d, not fmi2Error", what, (int)status);
    check(strstr(log->last, needle) != NULL, "%s: log \"%s\" lacks \"%s\"", what, log->last, needle);
}

/* Defect 5: every function of one interface is refused by an instance of the other. */
static void test_interface_type(void)
{
    Log log = {0, 0, ""};
    const fmi2CallbackFunctions callbacks = callbacks_for(&log);
    double x[2] = {0.1, 0.2};
    fmi2Status status;
    fmi2FMUstate cs_state = NULL, me_state = NULL;

    /* a Co-Simulation state in a Model Exchange instance, and the reverse */
    fmi2Component cs = ready(fmi2CoSimulation, &callbacks), me = ready(fmi2ModelExchange, &callbacks);
    check(fmi2GetFMUstate(cs, &cs_state) == fmi2OK && fmi2GetFMUstate(me, &me_state) == fmi2OK, "states");
    expect_refused(fmi2SetFMUstate(me, cs_state), &log, "other interface", "CS state into ME");
    check(fmi2DoStep(me, 0.0, 0.1, fmi2True) == fmi2Error, "fmi2DoStep on ME after a refused CS state");
    expect_refused(fmi2SetFMUstate(cs, me_state), &log, "other interface", "ME state into CS");
    fmi2FreeFMUstate(cs, &cs_state);
    fmi2FreeFMUstate(me, &me_state);
    fmi2FreeInstance(cs);
    fmi2FreeInstance(me);

    /* Model Exchange functions on Co-Simulation instances, in every state */
    cs = ready(fmi2CoSimulation, &callbacks);
    expect_refused(fmi2SetTime(cs, 1.0), &log, "Model Exchange function", "fmi2SetTime on CS");
    fmi2FreeInstance(cs);
    cs = ready(fmi2CoSimulation, &callbacks);
    expect_refused(fmi2SetContinuousStates(cs, x, 2), &log, "Model Exchange function", "fmi2SetContinuousStates on CS");
    fmi2FreeInstance(cs);
    for (int where = 0; where < 3; ++where) {
        cs = fmi2Instantiate("cs", fmi2CoSimulation, PENDULUM_GUID, NULL, &callbacks, fmi2False, fmi2False);
        fmi2SetupExperiment(cs, fmi2False, 0.0, 0.0, fmi2False, 0.0);
        fmi2EnterInitializationMode(cs);                           /* where 0: initialization */
        if (where >= 1) {
            fmi2ExitInitializationMode(cs);
            fmi2Terminate(cs);                                     /* where 1: terminated */
        }
        if (where == 2) {
            fmi2DoStep(cs, 0.0, 0.1, fmi2True);                    /* where 2: error state */
        }
        expect_refused(fmi2GetDerivatives(cs, x, 2), &log, "Model Exchange function", "fmi2GetDerivatives on CS");
        fmi2FreeInstance(cs);
        cs = fmi2Instantiate("cs", fmi2CoSimulation, PENDULUM_GUID, NULL, &callbacks, fmi2False, fmi2False);
        fmi2EnterInitializationMode(cs);
        expect_refused(fmi2GetContinuousStates(cs, x, 2), &log, "Model Exchange function",
                       "fmi2GetContinuousStates on CS");
        fmi2FreeInstance(cs);
    }

    /* Co-Simulation functions on a Model Exchange instance */
    me = ready(fmi2ModelExchange, &callbacks);
    fmi2Status value = fmi2OK;
    expect_refused(fmi2GetStatus(me, fmi2DoStepStatus, &value), &log, "Co-Simulation function", "fmi2GetStatus on ME");
    fmi2FreeInstance(me);
    me = ready(fmi2ModelExchange, &callbacks);
    double real_value = 0.0;
    status = fmi2GetRealStatus(me, fmi2LastSuccessfulTime, &real_value);
    expect_refused(status, &log, "Co-Simulation function", "fmi2GetRealStatus on ME");
    fmi2FreeInstance(me);
}

/* Defect 6: a step never ends before the current time; a few ulps of the point are tolerated. */
static void test_time_never_goes_backwards(void)
{
    Log log = {0, 0, ""};
    const fmi2CallbackFunctions callbacks = callbacks_for(&log);
    fmi2Component cs = ready(fmi2CoSimulation, &callbacks);
    double last = NAN;
    check(fmi2DoStep(cs, 0.0, 1.0, fmi2True) == fmi2OK, "step to t = 1");
    expect_refused(fmi2DoStep(cs, 1.0 - 5e-10, 1e-10, fmi2True), &log, "is not the current time",
                   "fmi2DoStep(1 - 5e-10, 1e-10) at t = 1");
    fmi2GetRealStatus(cs, fmi2LastSuccessfulTime, &last);
    check(last == 1.0, "fmi2LastSuccessfulTime %.17g after the refused step, not 1", last);
    fmi2FreeInstance(cs);

    cs = ready(fmi2CoSimulation, &callbacks);
    check(fmi2DoStep(cs, 0.0, 1.0, fmi2True) == fmi2OK, "step to t = 1");
    /* the master's point two ulps below the time: tolerated, the step ends at point + h >= 1 */
    const double point = nextafter(nextafter(1.0, 0.0), 0.0);
    check(fmi2DoStep(cs, point, 0.25, fmi2True) == fmi2OK, "a point 2 ulps off is tolerated (%s)", log.last);
    fmi2GetRealStatus(cs, fmi2LastSuccessfulTime, &last);
    check(last == point + 0.25 && last >= 1.0, "time after the tolerated step %.17g", last);
    /* a point a few ulps off with a step shorter than that would end before now */
    const double before = nextafter(nextafter(last, 0.0), 0.0);
    expect_refused(fmi2DoStep(cs, before, DBL_EPSILON * 0.25, fmi2True), &log, "before the current time",
                   "a step ending before the current time");
    fmi2FreeInstance(cs);
}

/* Defect 8: a step the budget cannot reach is refused at once. */
static void test_unreachable_step_refused_at_once(void)
{
    Log log = {0, 0, ""};
    const fmi2CallbackFunctions callbacks = callbacks_for(&log);
    fmi2Component cs = ready(fmi2CoSimulation, &callbacks);
    const clock_t start = clock();
    expect_refused(fmi2DoStep(cs, 0.0, 1e300, fmi2True), &log, "internal steps", "fmi2DoStep(0, 1e300)");
    const double seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    check(seconds < 0.05, "the refusal took %.3f s (at once means well below 0.05 s)", seconds);
    fmi2FreeInstance(cs);
}

/* Mirror of instance/state.c's header and checksum, to forge blobs as an attacker would. */
typedef struct {
    char magic[8];
    uint32_t format_version;
    uint32_t payload_size;
    uint64_t checksum;
} Header;

static uint64_t fnv1a64(const unsigned char *bytes, size_t size)
{
    uint64_t hash = 14695981039346656037u;
    for (size_t i = 0; i < size; i++) {
        hash ^= bytes[i];
        hash *= 1099511628211u;
    }
    return hash;
}

static void reseal(fmi2Byte *blob)
{
    Header header;
    memcpy(&header, blob, sizeof header);
    header.checksum = fnv1a64((const unsigned char *)blob + sizeof header, sizeof(ModelData));
    memcpy(blob, &header, sizeof header);
}

/* Every Real and Integer output is finite with fmi2OK (or the call is refused). */
static int outputs_sane(fmi2Component c)
{
    const fmi2ValueReference reals[] = {VR_L, VR_G, VR_THETA, VR_OMEGA, VR_DER_THETA, VR_DER_OMEGA,
                                        VR_THETA_EXACT, VR_OMEGA_EXACT, VR_X, VR_Y};
    double value;
    for (size_t i = 0; i < sizeof reals / sizeof reals[0]; ++i) {
        if (fmi2GetReal(c, &reals[i], 1, &value) == fmi2OK && !isfinite(value)) {
            return 0;
        }
    }
    return 1;
}

/* Defect 7: forged blobs (checksum recomputed) are refused with a reason, never crash. */
static void test_forged_states(fmi2Type type)
{
    Log log = {0, 0, ""};
    const fmi2CallbackFunctions callbacks = callbacks_for(&log);
    fmi2Component c = ready(type, &callbacks);
    fmi2FMUstate state = NULL;
    size_t size = 0;
    if (type == fmi2CoSimulation) {
        fmi2DoStep(c, 0.0, 0.7, fmi2True);
    } else {
        fmi2SetTime(c, 0.7);
    }
    check(fmi2GetFMUstate(c, &state) == fmi2OK && fmi2SerializedFMUstateSize(c, state, &size) == fmi2OK &&
              size == sizeof(Header) + sizeof(ModelData), "state size");
    fmi2Byte *blob = malloc(size), *forged = malloc(size);
    fmi2SerializeFMUstate(c, state, blob, size);

    /* two forged states: Landen level count 2^30, theta = NaN */
    memcpy(forged, blob, size);
    ModelData data;
    memcpy(&data, forged + sizeof(Header), sizeof data);
    data.exact.ell.levels = 1 << 30;
    memcpy(forged + sizeof(Header), &data, sizeof data);
    reseal(forged);
    fmi2FMUstate other = NULL;
    expect_refused(fmi2DeSerializeFMUstate(c, forged, size, &other), &log, "refused", "Landen levels 2^30");
    memcpy(&data, blob + sizeof(Header), sizeof data);
    data.theta = NAN;
    memcpy(forged + sizeof(Header), &data, sizeof data);
    reseal(forged);
    expect_refused(fmi2DeSerializeFMUstate(c, forged, size, &other), &log, "refused", "theta = NaN");
    check(other == NULL, "no state handed out for a refused blob");
    fmi2FreeFMUstate(c, &other);

    /* every 4-byte word of the payload set to hostile values, checksum recomputed: refused, or
     * accepted and every output finite (a word that is padding or an unused stage changes
     * nothing the model reads) */
    static const uint32_t words[] = {0xFFFFFFFFu, 0x7FF80000u, 0x7FF00000u, 0x40000000u, 1u << 30, 0x80000000u};
    int refused = 0, accepted = 0, insane = 0;
    for (size_t offset = 0; offset + 4 <= sizeof(ModelData); offset += 4) {
        for (size_t w = 0; w < sizeof words / sizeof words[0]; ++w) {
            fmi2Component d = ready(type, &callbacks);
            memcpy(forged, blob, size);
            memcpy(forged + sizeof(Header) + offset, &words[w], 4);
            if (memcmp(forged, blob, size) == 0) {
                fmi2FreeInstance(d);
                continue;
            }
            reseal(forged);
            fmi2FMUstate restored = NULL;
            if (fmi2DeSerializeFMUstate(d, forged, size, &restored) == fmi2OK &&
                fmi2SetFMUstate(d, restored) == fmi2OK) {
                ++accepted;
                if (!outputs_sane(d)) {
                    ++insane;
                    printf("offset %zu word %08x: accepted, NaN with fmi2OK\n", offset, words[w]);
                }
                if (type == fmi2CoSimulation) {
                    double h = 0.3;
                    double t = NAN;
                    fmi2GetRealStatus(d, fmi2LastSuccessfulTime, &t);
                    if (fmi2DoStep(d, t, h, fmi2True) == fmi2OK && !outputs_sane(d)) {
                        ++insane;
                        printf("offset %zu word %08x: NaN after a step with fmi2OK\n", offset, words[w]);
                    }
                }
            } else {
                ++refused;
                check(log.last[0] != '\0', "a refusal is logged");
            }
            fmi2FreeFMUstate(d, &restored);
            fmi2FreeInstance(d);
        }
    }
    check(insane == 0, "%d forged blobs accepted with non-finite outputs", insane);
    check(refused > 0, "forged blobs refused: %d (accepted %d)", refused, accepted);
    printf("%s: %d forged blobs refused, %d accepted (padding, unused stages), none gave NaN with OK\n",
           type == fmi2CoSimulation ? "Co-Simulation" : "Model Exchange", refused, accepted);
    free(blob);
    free(forged);
    fmi2FreeFMUstate(c, &state);
    fmi2FreeInstance(c);
}

/* Logger that keeps every warning's category and message. */
typedef struct {
    int warnings;
    char category[64], message[600];
    int hard_cases;   /* messages that start "hard case:" */
} WarningLog;

static void warning_logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                           fmi2String message, ...)
{
    WarningLog *log = env;
    va_list args;
    (void)name;
    if (status != fmi2Warning) {
        return;
    }
    log->warnings++;
    if (strncmp(message, "hard case:", 10) == 0 || log->message[0] == '\0') {
        /* keep the hard case's message (the certificate's may come before and after it) */
        snprintf(log->category, sizeof log->category, "%s", category);
        va_start(args, message);
        vsnprintf(log->message, sizeof log->message, message, args);
        va_end(args);
        log->hard_cases += strncmp(message, "hard case:", 10) == 0;
    }
}

/* Runs a Co-Simulation of theta0 at rest (L = 1, g = 9.81) with `solver` at `tol` by steps of
 * 0.1 s up to `t_end`; returns the number of fmi2Warning steps, fills the log. */
static int run_for_warnings(double theta0, double omega0, int solver, double tol, double t_end, WarningLog *log)
{
    fmi2CallbackFunctions callbacks = {warning_logger, calloc, free, NULL, NULL};
    const fmi2ValueReference vrs[2] = {VR_THETA, VR_OMEGA}, vr_solver = VR_SOLVER;
    const double values[2] = {theta0, omega0};
    int warning_steps = 0;
    callbacks.componentEnvironment = log;
    fmi2Component c = fmi2Instantiate("hard", fmi2CoSimulation, PENDULUM_GUID, NULL, &callbacks, fmi2False, fmi2False);
    fmi2SetupExperiment(c, fmi2True, tol, 0.0, fmi2False, 0.0);
    fmi2EnterInitializationMode(c);
    fmi2SetReal(c, vrs, 2, values);
    fmi2SetInteger(c, &vr_solver, 1, &solver);
    fmi2ExitInitializationMode(c);
    for (int i = 0; i < (int)(t_end / 0.1 + 0.5); ++i) {
        fmi2Status status = fmi2DoStep(c, i * 0.1, 0.1, fmi2True);
        check(status == fmi2OK || status == fmi2Warning, "step %d: status %d", i, (int)status);
        warning_steps += status == fmi2Warning;
    }
    fmi2FreeInstance(c);
    return warning_steps;
}

/* The hard case: released at rest at pi (the double), rkn at 1e-8 goes over the top while the
 * exact solution librates; fmi2DoStep returns fmi2Warning once and logs it once. */
static void test_hard_case_warns_once(void)
{
    WarningLog log = {0, "", "", 0};
    const int steps = run_for_warnings(PI, 0.0, 3, 1e-8, 100.0, &log);
    /* every step beyond the certificate's bound returns fmi2Warning (1 - m = 4e-33 is out of
     * double precision's reach); the messages: the certificate's at its first crossing and
     * at each tenfold growth (at most 9 decades from 1 to 1e8 here), the hard case once */
    check(steps >= 1, "hard case: %d steps returned fmi2Warning", steps);
    check(log.hard_cases <= 1, "hard case: %d hard-case messages (want at most one)", log.hard_cases);
    check(log.warnings >= 1 && log.warnings <= 10, "hard case: %d warnings logged", log.warnings);
    check(strcmp(log.category, "logStatusWarning") == 0, "category \"%s\"", log.category);
    /* the projected solver now keeps it below the top for the 100 s (energy and g/L in
     * double-double): the certificate says so, the hard case's message only if it goes over */
    check(log.hard_cases == 1 ? strstr(log.message, "over the top") != NULL
                              : strncmp(log.message, "certificate:", 12) == 0 &&
                                    strstr(log.message, "No double-precision solver can hold it") != NULL,
          "message \"%s\"", log.message);
    printf("hard case message: %s\n", log.message);
    /* an ordinary run (75 deg, the default) warns never */
    WarningLog quiet = {0, "", "", 0};
    check(run_for_warnings(1.3089969389957472, 0.0, 3, 1e-8, 30.0, &quiet) == 0 && quiet.warnings == 0,
          "an ordinary run warned: %s", quiet.message);
    /* a rotation reversed by a coarse solver: rk4 at 1e-4 just above the separatrix */
    WarningLog reversed = {0, "", "", 0};
    run_for_warnings(0.0, 2.0 * sqrt(9.81) * (1.0 + 1e-9), 2, 1e-4, 30.0, &reversed);
    printf("just above the separatrix, rk4 at 1e-4: %d warnings%s%s\n", reversed.warnings,
           reversed.warnings ? ": " : "", reversed.message);
}

int main(void)
{
    test_hard_case_warns_once();
    test_interface_type();
    test_time_never_goes_backwards();
    test_unreachable_step_refused_at_once();
    test_forged_states(fmi2CoSimulation);
    test_forged_states(fmi2ModelExchange);
    return check_summary("test_fmi_edges");
}
