/* test_certificate_edges.c: the step certificate at its edges.
 *
 *   - the start time: the same problem takes the same internal steps (accepted, rejected,
 *     right-hand sides) from every start time, for every solver, and the two steps that
 *     were refused with "step size underflow" (L = 1e-6, g = 1e6 from startTime 1e7; L = 1,
 *     g = 9.81 from startTime 2^41) return OK;
 *   - the tolerance floor: a Co-Simulation experiment below INTEGRATOR_TOLERANCE_FLOOR (1e-14),
 *     subnormal (5e-324) included, runs at the floor with a warning naming the tolerance asked
 *     for and the one used, its steps certified at the floor; 0 or negative is refused with an
 *     error naming the tolerance; the floor itself is accepted; Model Exchange, which integrates nothing, accepts any tolerance
 *     in (0, 1); an FMU state that carries a tolerance below the floor is refused;
 *   - the bound leaves room for the exact port's own error: OK only where the distance to the
 *     exact port is within (100 tol - 5e-14) of the scale, so that the true error is within
 *     100 tol (the true error against mpmath: tests/fmu/test_certificate_edges.py).
 *
 * Drives the instance of the model core (what both FMI layers call). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "core_host.h"
#include "instance.h"
#include "pendulum_vrs.h"

static char last_error[1024];
static char last_warning[1024];

static void host_log(const Instance *inst, Status status, const char *category, const char *message)
{
    (void)inst;
    (void)category;
    if (status == STATUS_ERROR) {
        snprintf(last_error, sizeof last_error, "%s", message);
    } else if (status == STATUS_WARNING) {
        snprintf(last_warning, sizeof last_warning, "%s", message);
    }
}

static void instantiate(Instance *inst, InterfaceType type)
{
    check(core_instance(inst, "edges", host_log, type) == 0, "instance_setup");
}

/* A Co-Simulation instance at startTime t0; 0 or -1 (the call that failed is in last_error). */
static int setup(Instance *inst, const Start *s, int solver, double tol, double t0)
{
    last_error[0] = '\0';
    return core_start(inst, "edges", host_log, 0, s, solver, tol, t0);
}

typedef struct {
    Status worst;          /* the worst status of the steps */
    SolverStats stats;     /* the solver's counts at the end */
    double theta, omega;   /* the state at the end */
    double departure;      /* its distance to the exact port in units of 100 tol (scales as the
                              certificate's) */
} Run;

static Run run(const Start *s, int solver, double tol, double t0, const double *ends, int n)
{
    Run r;
    Instance inst;
    memset(&r, 0, sizeof r);
    if (setup(&inst, s, solver, tol, t0) != 0) {
        r.worst = STATUS_FATAL;
        return r;
    }
    for (int i = 0; i < n; i++) {
        const Status st = instance_do_step(&inst, "DoStep", inst.data.time, ends[i] - inst.data.time);
        r.worst = st > r.worst ? st : r.worst;
        if (st != STATUS_OK && st != STATUS_WARNING) {
            break;
        }
    }
    double th_e, om_e;
    const ModelData *d = &inst.data;
    pendulum_exact_eval(&d->exact, d->time, &th_e, &om_e);
    const double w0 = sqrt(d->g / d->L);
    r.departure = fmax(fabs(d->theta - th_e) / (100.0 * tol * fmax(1.0, fabs(th_e))),
                       fabs(d->omega - om_e) / (100.0 * tol * fmax(w0, fabs(om_e))));
    r.stats = d->integrator.stats;
    r.theta = d->theta;
    r.omega = d->omega;
    instance_release(&inst);
    return r;
}

static int same_stats(SolverStats a, SolverStats b)
{
    return a.steps == b.steps && a.rejected == b.rejected && a.rhs_evals == b.rhs_evals;
}

/* ---- the start time ------------------------------------------------------------------- */

/* n DoSteps of length h from t0 and from 0: the step ends are t0 + i h rounded, and the run
 * from 0 takes the same lengths (each end minus t0, exact by Sterbenz's lemma where t0 + i h
 * lies within a factor 2 of t0, and exactly representable anyway: t0 is a multiple of the
 * ends' ulp). */
static void compare_start_times(const char *name, const Start *s, double tol, double t0, double h, int n)
{
    double far[64], near[64];
    for (int i = 0; i < n; i++) {
        far[i] = t0 + (i + 1) * h;
        near[i] = far[i] - t0;
    }
    for (int solver = 1; solver <= 4; solver++) {
        const Run a = run(s, solver, tol, t0, far, n);
        const Run b = run(s, solver, tol, 0.0, near, n);
        check(a.worst == STATUS_OK, "%s, %s from t0 = %.17g: status %d (%s)", name, integrator_solver_name(solver), t0, (int)a.worst,
              last_error);
        check(b.worst == STATUS_OK, "%s, %s from 0: status %d", name, integrator_solver_name(solver), (int)b.worst);
        check(same_stats(a.stats, b.stats), "%s, %s: from t0 = %.17g %ld steps, %ld rejected, %ld rhs; from 0 %ld, "
              "%ld, %ld", name, integrator_solver_name(solver), t0, a.stats.steps, a.stats.rejected, a.stats.rhs_evals, b.stats.steps,
              b.stats.rejected, b.stats.rhs_evals);
        check(a.departure <= 1.0 && b.departure <= 1.0, "%s, %s: departures %.3g and %.3g of 100 tol", name,
              integrator_solver_name(solver), a.departure, b.departure);
        /* the same steps, interpolated at the same elapsed time up to the rounding of the
         * clock's low part: equal to far below the bound */
        const double w0 = sqrt(s->g / s->L);
        check(fabs(a.theta - b.theta) <= 1e-3 * 100.0 * tol * fmax(1.0, fabs(b.theta)) &&
              fabs(a.omega - b.omega) <= 1e-3 * 100.0 * tol * fmax(w0, fabs(b.omega)),
              "%s, %s: theta %.17g against %.17g from 0", name, integrator_solver_name(solver), a.theta, b.theta);
        printf("%-28s %-10s t0 = %-22.17g %6ld steps %4ld rejected %7ld rhs (same from 0), departure %.3g / %.3g\n",
               name, integrator_solver_name(solver), t0, a.stats.steps, a.stats.rejected, a.stats.rhs_evals, a.departure, b.departure);
    }
}

static void test_start_times(void)
{
    const double deg75 = 75.0 * PI / 180.0;
    const Start tiny = {deg75, 0.0, 1e-6, 1e6};
    const Start earth = {deg75, 0.0, 1.0, 9.81};
    /* the two steps once refused */
    compare_start_times("L 1e-6, g 1e6, one step", &tiny, 1e-8, 1e7, 6.283185307179586e-07, 1);
    compare_start_times("L 1, g 9.81, one step", &earth, 1e-8, 0x1p41, 0.224, 1);
    /* several steps, other start times and tolerances */
    compare_start_times("L 1e-6, g 1e6, 20 steps", &tiny, 1e-10, 1e7, 3.1e-7, 20);
    compare_start_times("L 1, g 9.81, 20 steps", &earth, 1e-6, 0x1p41, 0.5, 20);
    compare_start_times("L 1, g 9.81, 20 steps at 1e-12", &earth, 1e-12, 0x1p41, 0.25, 20);
    const Start rotation = {0.3, 9.0, 2.0, 9.81};
    compare_start_times("rotation, 20 steps", &rotation, 1e-9, 1e9, 0.1, 20);
}

/* ---- the tolerance floor -------------------------------------------------------------- */

static void test_tolerance_floor(void)
{
    const Start s = {1.3089969389957472, 0.0, 1.0, 9.81};
    const double below[] = {5e-324, 1e-320, 1e-20, 1e-16, 1e-15, 0.99e-14};
    const ValueReference vrs[] = {VR_L, VR_G, VR_THETA, VR_OMEGA};
    const double values[] = {s.L, s.g, s.theta0, s.omega0};
    const double floor_tol = INTEGRATOR_TOLERANCE_FLOOR;
    Instance inst;
    /* below the floor: the run takes the floor, with a warning that names the tolerance asked
     * for and the one used, and every step is certified at the floor */
    for (size_t i = 0; i < sizeof below / sizeof below[0]; i++) {
        for (int solver = 1; solver <= 4; solver++) {
            char want[96];
            instantiate(&inst, INTERFACE_CO_SIMULATION);
            last_warning[0] = last_error[0] = '\0';
            check(instance_setup_experiment(&inst, "setup", 1, below[i], 0.0, 0, 0.0) == STATUS_WARNING,
                  "tolerance %g with %s: not a warning (%s)", below[i], integrator_solver_name(solver), last_error);
            check(inst.data.tolerance == floor_tol, "tolerance %g with %s: runs at %g", below[i], integrator_solver_name(solver),
                  inst.data.tolerance);
            snprintf(want, sizeof want, "tolerance %g is below %g", below[i], floor_tol);
            check(strstr(last_warning, want) != NULL && strstr(last_warning, "the run uses tolerance 1e-14") != NULL,
                  "tolerance %g with %s: message \"%s\"", below[i], integrator_solver_name(solver), last_warning);
            check(instance_enter_initialization(&inst, "enter") == STATUS_OK &&
                  instance_set_reals(&inst, "set", vrs, 4, values) == STATUS_OK &&
                  instance_set_integer(&inst, "set", VR_SOLVER, solver) == STATUS_OK &&
                  instance_exit_initialization(&inst, "exit") == STATUS_OK,
                  "tolerance %g with %s: initialization failed (%s)", below[i], integrator_solver_name(solver), last_error);
            Status worst = STATUS_OK;
            for (int k = 1; k <= 4; k++) {
                const Status st = instance_do_step(&inst, "DoStep", inst.data.time, 0.1 * k - inst.data.time);
                worst = st > worst ? st : worst;
            }
            double th_e, om_e;
            pendulum_exact_eval(&inst.data.exact, inst.data.time, &th_e, &om_e);
            const double w0 = sqrt(s.g / s.L);
            const double departure = fmax(fabs(inst.data.theta - th_e) / (100.0 * floor_tol * fmax(1.0, fabs(th_e))),
                                          fabs(inst.data.omega - om_e) / (100.0 * floor_tol * fmax(w0, fabs(om_e))));
            check(worst == STATUS_WARNING || (worst == STATUS_OK && departure <= 1.0),
                  "tolerance %g with %s: status %d, departure %g of the bound at the floor", below[i],
                  integrator_solver_name(solver), (int)worst, departure);
            instance_release(&inst);
        }
    }
    printf("below the floor: \"%s\"\n", last_warning);
    const double invalid[] = {0.0, -0.0, -1e-8, 1.0};
    for (size_t i = 0; i < sizeof invalid / sizeof invalid[0]; i++) {
        check(setup(&inst, &s, SOLVER_SYMPLECTIC, invalid[i], 0.0) != 0 && strstr(last_error, "tolerance") != NULL,
              "tolerance %g: message \"%s\"", invalid[i], last_error);
    }
    for (int solver = 1; solver <= 4; solver++) {
        const double end = 0.37;
        const Run r = run(&s, solver, INTEGRATOR_TOLERANCE_FLOOR, 0.0, &end, 1);
        check(r.worst == STATUS_OK || r.worst == STATUS_WARNING, "the floor itself with %s: status %d (%s)",
              integrator_solver_name(solver), (int)r.worst, last_error);
    }
    /* Model Exchange integrates nothing: the experiment's tolerance is only recorded */
    instantiate(&inst, INTERFACE_MODEL_EXCHANGE);
    check(instance_setup_experiment(&inst, "setup", 1, 1e-16, 0.0, 0, 0.0) == STATUS_OK,
          "Model Exchange refused tolerance 1e-16: %s", last_error);
    instance_release(&inst);
    /* a state that carries a tolerance below the floor */
    check(setup(&inst, &s, SOLVER_RKN, 1e-8, 0.0) == 0, "state: set-up");
    ModelData forged = inst.data;
    check(model_check_state(&forged, INTERFACE_CO_SIMULATION) == NULL, "state: the honest one refused");
    forged.tolerance = 1e-15;
    const char *why = model_check_state(&forged, INTERFACE_CO_SIMULATION);
    check(why != NULL && strstr(why, "tolerance") != NULL, "state with tolerance 1e-15: %s", why ? why : "accepted");
    instance_release(&inst);
}

/* ---- room for the exact port's own error ----------------------------------------------- */

static void test_margin(void)
{
    const double tol = 1e-12, w0 = 3.0, th_e = 2.5, om_e = 0.5;
    const double room = 100.0 * tol - CERTIFICATE_EXACT_ERROR;
    check(CERTIFICATE_EXACT_ERROR == 5e-14, "the port's bound is %g", CERTIFICATE_EXACT_ERROR);
    check(certificate_factor(tol) == room, "certificate_factor(1e-12) = %.17g", certificate_factor(tol));
    /* theta: at 100 tol (the true bound) a distance to the port is not certified, within the
     * room it is; omega the same with its scale max(w0, |omega_exact|) = w0 */
    check(certificate_ratio(w0, tol, th_e + 100.0 * tol * th_e, om_e, th_e, om_e) > 1.0,
          "a distance of 100 tol to the port certified");
    check(certificate_ratio(w0, tol, th_e + 0.9999 * room * th_e, om_e, th_e, om_e) <= 1.0,
          "a distance within the room refused");
    check(certificate_ratio(w0, tol, th_e, om_e + 0.99999 * 100.0 * tol * w0, th_e, om_e) > 1.0,
          "omega: a distance of 0.99999 of 100 tol to the port certified (the port may be 5e-14 off)");
    check(certificate_ratio(w0, tol, th_e, om_e + 0.9999 * room * w0, th_e, om_e) <= 1.0,
          "omega: a distance within the room refused");
    /* at the floor the room is 95 % of the bound */
    check(fabs(certificate_factor(INTEGRATOR_TOLERANCE_FLOOR) / (100.0 * INTEGRATOR_TOLERANCE_FLOOR) - 0.95) < 1e-12,
          "at the floor the room is %.17g of the bound",
          certificate_factor(INTEGRATOR_TOLERANCE_FLOOR) / (100.0 * INTEGRATOR_TOLERANCE_FLOOR));
}

int main(void)
{
    test_start_times();
    test_tolerance_floor();
    test_margin();
    return check_summary("test_certificate_edges");
}
