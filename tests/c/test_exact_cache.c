/* test_exact_cache.c: the exact state at the current time is evaluated once per time.
 * An instance keeps theta_exact and omega_exact of its current time
 * (Instance.exact_now, model.h): the certificate after a DoStep, a GetReal or the output
 * derivatives evaluate it first, the others reuse it. The instance counts its evaluations
 * (exact_now.evaluations), so this test counts them without any timing:
 *   - Co-Simulation, FMI 2.0 and 3.0 instances, certificate on: a DoStep followed by GetReals of
 *     theta_exact and omega_exact (one call each, both in one call, again) and the output
 *     derivatives is ONE evaluation; with the certificate off, the first GetReal makes it;
 *   - Model Exchange: SetTime and the reads, one evaluation per time;
 *   - every value handed out equals pendulum_exact_eval at the instance's time, bit for bit;
 *   - after each call that changes what the exact state depends on (SetTime, SetContinuousStates,
 *     SetFMUstate of a state at the SAME time but other start values, the same through
 *     serialize / deserialize, Reset and a new initialization, a parameter set during
 *     initialization) the next read evaluates afresh and equals a fresh evaluation bit for bit,
 *     where the value before the call would have been wrong (checked too: the test can fail). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "instance.h"
#include "core_host.h"
#include "pendulum_vrs.h"

static void host_log(const Instance *inst, Status status, const char *category, const char *message)
{
    (void)inst;
    (void)status;
    (void)category;
    (void)message;
}

/* An instance of `type` released from theta0 (L = 1, g = 9.81), solver rkn at tol, initialized. */
static int setup(Instance *inst, InterfaceType type, int fmi_version, double theta0, double tol, int certificate_off)
{
    const ValueReference vrs[] = {VR_L, VR_G, VR_THETA, VR_OMEGA};
    const double values[] = {1.0, 9.81, theta0, 0.0};
    memset(inst, 0, sizeof *inst);
    inst->host.log = host_log;
    inst->host.allocate = host_allocate;
    inst->host.release = host_release;
    if (instance_setup(inst, "cache", type, fmi_version, 0) != 0) {
        return -1;
    }
    inst->certificate_off = certificate_off;
    if (instance_setup_experiment(inst, "setup", 1, tol, 0.0, 0, 0.0) != STATUS_OK ||
        instance_enter_initialization(inst, "enter") != STATUS_OK ||
        instance_set_reals(inst, "set", vrs, 4, values) != STATUS_OK ||
        (type == INTERFACE_CO_SIMULATION && instance_set_integer(inst, "set", VR_SOLVER, SOLVER_RKN) != STATUS_OK) ||
        instance_exit_initialization(inst, "exit") != STATUS_OK) {
        instance_release(inst);
        return -1;
    }
    return 0;
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Reads theta_exact and omega_exact (one GetReal each) and checks them against a fresh
 * pendulum_exact_eval of the instance's exact solution at its time. Returns the number of
 * evaluations the reads made. */
static unsigned long read_and_compare(Instance *inst, const char *what, double *theta, double *omega)
{
    const ValueReference vr_theta = VR_THETA_EXACT, vr_omega = VR_OMEGA_EXACT;
    const unsigned long before = inst->exact_now.evaluations;
    double th_fresh, om_fresh;
    check(instance_get_reals(inst, "get", &vr_theta, 1, theta) == STATUS_OK &&
          instance_get_reals(inst, "get", &vr_omega, 1, omega) == STATUS_OK, "%s: GetReal refused", what);
    pendulum_exact_eval(&inst->data.exact, inst->data.time, &th_fresh, &om_fresh);
    check(same_bits(*theta, th_fresh) && same_bits(*omega, om_fresh),
          "%s: theta_exact %.17g, omega_exact %.17g, a fresh evaluation %.17g, %.17g", what, *theta, *omega,
          th_fresh, om_fresh);
    return inst->exact_now.evaluations - before;
}

/* Co-Simulation: one evaluation per DoStep, whatever is read after it. */
static void test_one_per_step(int fmi_version, int certificate_off)
{
    const ValueReference both[] = {VR_THETA_EXACT, VR_OMEGA_EXACT};
    const int orders[] = {1, 1};
    Instance inst;
    int k, steps_with_one = 0;
    if (setup(&inst, INTERFACE_CO_SIMULATION, fmi_version, 75.0 * PI / 180.0, 1e-8, certificate_off) != 0) {
        check(0, "set-up failed");
        return;
    }
    for (k = 0; k < 200; k++) {
        const unsigned long before = inst.exact_now.evaluations;
        double theta, omega, pair[2], der[2];
        unsigned long after_step;
        char what[64];
        const Status status = instance_do_step(&inst, "step", inst.data.time, 0.05);
        check(status == STATUS_OK, "FMI %d, step %d: status %d", fmi_version, k, (int)status);
        after_step = inst.exact_now.evaluations - before;
        snprintf(what, sizeof what, "FMI %d, certificate %s, step %d", fmi_version, certificate_off ? "off" : "on",
                 k);
        read_and_compare(&inst, what, &theta, &omega);
        check(instance_get_reals(&inst, "get", both, 2, pair) == STATUS_OK && same_bits(pair[0], theta) &&
                  same_bits(pair[1], omega), "%s: both in one GetReal differ", what);
        read_and_compare(&inst, what, &theta, &omega);
        check(instance_output_derivatives(&inst, "der", both, 2, orders, der) == STATUS_OK &&
                  same_bits(der[0], omega), "%s: the output derivative of theta_exact is not omega_exact", what);
        steps_with_one += after_step == (certificate_off ? 0u : 1u) && inst.exact_now.evaluations - before == 1;
    }
    check(steps_with_one == 200, "FMI %d, certificate %s: %d of 200 steps made exactly one evaluation "
          "(%lu evaluations in all)", fmi_version, certificate_off ? "off" : "on", steps_with_one,
          inst.exact_now.evaluations);
    printf("Co-Simulation, FMI %d, certificate %s: %lu exact evaluations for 200 DoSteps, each followed by "
           "5 reads of theta_exact/omega_exact and their derivatives\n",
           fmi_version, certificate_off ? "off" : "on", inst.exact_now.evaluations);
    instance_release(&inst);
}

/* Model Exchange: SetTime, then reads; SetContinuousStates. */
static void test_model_exchange(void)
{
    Instance inst;
    double theta, omega, x[2] = {0.3, -0.2};
    int k;
    if (setup(&inst, INTERFACE_MODEL_EXCHANGE, 2, 60.0 * PI / 180.0, 1e-8, 0) != 0 ||
        instance_enter_continuous_time_mode(&inst, "ct") != STATUS_OK) {
        check(0, "Model Exchange set-up failed");
        return;
    }
    for (k = 1; k <= 50; k++) {
        check(instance_set_time(&inst, "time", 0.0173 * k) == STATUS_OK, "SetTime %d refused", k);
        check(read_and_compare(&inst, "ME SetTime", &theta, &omega) == 1, "ME: reads at time %d: not one evaluation", k);
        check(read_and_compare(&inst, "ME again", &theta, &omega) == 0, "ME: a second read at time %d evaluated", k);
    }
    check(instance_set_time(&inst, "time", inst.data.time) == STATUS_OK &&
          read_and_compare(&inst, "ME same time", &theta, &omega) == 1, "ME: SetTime to the same time kept the cache");
    check(instance_set_states(&inst, "states", x, 2) == STATUS_OK &&
          read_and_compare(&inst, "ME SetContinuousStates", &theta, &omega) == 1,
          "ME: SetContinuousStates kept the cache");
    instance_release(&inst);
}

/* The calls that change what the exact state depends on, with the time unchanged. */
static void test_invalidation(void)
{
    Instance a, b;
    void *state_b = NULL, *state_copy = NULL;
    double theta_a, omega_a, theta, omega;
    size_t size = 0;
    char *bytes;
    const ValueReference vr_theta = VR_THETA, vr_l = VR_L;
    const double new_theta = 20.0 * PI / 180.0, new_l = 2.5;
    if (setup(&a, INTERFACE_CO_SIMULATION, 2, 75.0 * PI / 180.0, 1e-8, 0) != 0 ||
        setup(&b, INTERFACE_CO_SIMULATION, 2, 30.0 * PI / 180.0, 1e-8, 0) != 0) {
        check(0, "set-up failed");
        return;
    }
    /* both at t = 0.5 (same steps); a's exact state cached there */
    check(instance_do_step(&a, "step", 0.0, 0.5) == STATUS_OK && instance_do_step(&b, "step", 0.0, 0.5) == STATUS_OK,
          "steps to 0.5 refused");
    read_and_compare(&a, "a at 0.5", &theta_a, &omega_a);
    check(a.exact_now.valid && same_bits(a.exact_now.time, 0.5), "the cache does not hold t = 0.5");

    /* SetFMUstate: b's state, the same time, other start values */
    check(instance_get_state(&b, "get", &state_b) == STATUS_OK, "GetFMUstate refused");
    check(instance_set_state(&a, "set", state_b) == STATUS_OK, "SetFMUstate refused");
    check(read_and_compare(&a, "after SetFMUstate", &theta, &omega) == 1, "SetFMUstate: not evaluated afresh");
    check(!same_bits(theta, theta_a), "SetFMUstate: the state at the same time has the same theta_exact: the test "
          "cannot tell a stale cache");

    /* DeSerializeFMUstate + SetFMUstate: back to a's own start values (a state of a fresh run) */
    {
        Instance c;
        void *state_c = NULL;
        double theta_c, omega_c;
        check(setup(&c, INTERFACE_CO_SIMULATION, 2, 75.0 * PI / 180.0, 1e-8, 0) == 0 &&
              instance_do_step(&c, "step", 0.0, 0.5) == STATUS_OK && instance_get_state(&c, "get", &state_c) == STATUS_OK &&
              instance_serialized_state_size(&c, "size", state_c, &size) == STATUS_OK, "state of c refused");
        bytes = malloc(size);
        check(bytes != NULL && instance_serialize_state(&c, "ser", state_c, bytes, size) == STATUS_OK &&
              instance_deserialize_state(&a, "de", bytes, size, &state_copy) == STATUS_OK, "serialization refused");
        check(read_and_compare(&a, "before restore", &theta, &omega) == 0, "a read between states evaluated");
        check(instance_set_state(&a, "set", state_copy) == STATUS_OK, "SetFMUstate of the deserialized state refused");
        check(read_and_compare(&a, "after DeSerialize + SetFMUstate", &theta_c, &omega_c) == 1,
              "DeSerialize + SetFMUstate: not evaluated afresh");
        check(same_bits(theta_c, theta_a) && same_bits(omega_c, omega_a), "the restored run's exact state is not the "
              "original one's");
        free(bytes);
        instance_release(&c);
    }

    /* Reset, then the same start time with another start value and another parameter */
    check(instance_reset(&a, "reset") == STATUS_OK, "Reset refused");
    check(!a.exact_now.valid, "Reset kept the cache");
    check(instance_setup_experiment(&a, "setup", 1, 1e-8, 0.5, 0, 0.0) == STATUS_OK &&
          instance_enter_initialization(&a, "enter") == STATUS_OK, "initialization refused");
    {
        /* during initialization every read follows the values set so far: nothing is kept */
        const ValueReference vr = VR_THETA_EXACT;
        const unsigned long before = a.exact_now.evaluations;
        double got = 0.0, again = 0.0;
        check(instance_set_reals(&a, "set", &vr_theta, 1, &new_theta) == STATUS_OK, "SetReal theta refused");
        check(instance_get_reals(&a, "get", &vr, 1, &got) == STATUS_OK && same_bits(got, new_theta),
              "theta_exact at the start time during initialization: %.17g, theta0 %.17g", got, new_theta);
        check(instance_set_reals(&a, "set", &vr_l, 1, &new_l) == STATUS_OK &&
              instance_get_reals(&a, "get", &vr, 1, &again) == STATUS_OK && same_bits(again, new_theta),
              "theta_exact after SetReal of L during initialization: %.17g", again);
        check(a.exact_now.evaluations - before == 2 && !a.exact_now.valid,
              "during initialization a read was kept (%lu evaluations for 2 reads)", a.exact_now.evaluations - before);
    }
    check(instance_exit_initialization(&a, "exit") == STATUS_OK, "ExitInitializationMode refused");
    {
        const unsigned long before = a.exact_now.evaluations;
        check(instance_do_step(&a, "step", 0.5, 0.25) == STATUS_OK, "step after the reset refused");
        check(a.exact_now.evaluations - before == 1 && read_and_compare(&a, "after Reset", &theta, &omega) == 0,
              "after Reset: not one evaluation per step");
        check(a.data.exact.L == new_l && a.data.exact.theta0 == new_theta, "the new start values were not taken");
    }
    instance_release(&a);
    instance_release(&b);
}

int main(void)
{
    test_one_per_step(2, 0);
    test_one_per_step(3, 0);
    test_one_per_step(2, 1);
    test_model_exchange();
    test_invalidation();
    return check_summary("test_exact_cache");
}
