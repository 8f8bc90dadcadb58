/* test_certificate.c: every Co-Simulation step that returns OK holds its bound:
 *   |theta - theta_exact| <= 100 tol max(1, |theta_exact|),
 *   |omega - omega_exact| <= 100 tol max(w0, |omega_exact|),
 * recomputed here from the exact port (itself checked against mpmath at 50 digits by
 * tests/exact/test_exact_mpmath.py), independently of instance/certificate.c's own arithmetic.
 *
 * It drives the instance of the model core (the code both FMI layers call) with a logger of
 * its own, and checks
 *   - the separatrix grid: theta0 = 0, omega0 = 2 w0 (1 +- c), c = 1e-4 .. 1e-12, tol 1e-6 ..
 *     1e-10, four solvers, 10 periods at 20 steps a period: no step OK beyond its bound, and
 *     warnings only where certificate_reachable says no double-precision solver can hold it;
 *   - random states (libration, rotation, near the separatrix), four solvers, several tol;
 *   - the hard cases (1 - m = 1.1e-19 with rkn at 1e-12; the scale ladder);
 *   - the certificate changes no number: theta, omega and the solver's counts are bit-identical
 *     with it on and off (Instance.certificate_off);
 *   - one message at the first crossing and one per tenfold growth, naming the solver, its
 *     tolerance, 1 - m and the solvers that can hold the bound;
 *   - an FMU state carries the certificate's field, and a forged value is refused.
 *
 * Arguments: `table` prints the grid's table (docs/certificate.md), `cost` times a step with
 * the certificate on and off, `steps-on N` / `steps-off N` take N steps of 0.01 s (for
 * valgrind's instruction counts). */
#define _POSIX_C_SOURCE 199309L
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "check.h"
#include "instance.h"
#include "core_host.h"
#include "pendulum_vrs.h"

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

static int setup(Instance *inst, const Start *s, int solver, double tol, int certificate_off)
{
    return core_start(inst, "certificate", host_log, certificate_off, s, solver, tol, 0.0);
}

/* Departure from the bound in units of the bound, written out again from the bound's definition. */
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
    instance_release(&inst);
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
                    check(!r.failed, "grid c %g tol %g %s: a step failed", c, tol, integrator_solver_name(solver));
                    check(r.ok_beyond == 0, "grid c %g tol %g %s: %d steps OK beyond the bound", c, tol,
                          integrator_solver_name(solver), r.ok_beyond);
                    check(r.warn_within == 0, "grid c %g tol %g %s: warned within the bound", c, tol, integrator_solver_name(solver));
                    check(!reach || r.warned == 0, "grid c %g tol %g %s: warned (departure %.3g) where "
                          "certificate_reachable says a solver can hold the bound", c, tol, integrator_solver_name(solver), r.worst);
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

/* ---- the certificate changes no number ------------------------------------------------- */
static void test_bit_identical_on_off(void)
{
    const double w0 = sqrt(9.81);
    const Start starts[] = {{0.0, 2.0 * w0 * (1.0 - 1e-12), 1.0, 9.81},   /* warns (rk4, symplectic) */
                            {1.3089969389957472, 0.0, 1.0, 9.81},          /* 75 deg */
                            {3.0849789226170623, 0.034294831419746555, 374.6912982074549, 137.53188593324322},
                            {0.3, 40.0, 1e-3, 1e3}};
    static double on[2 * 120], off[2 * 120];
    int compared = 0, with_warnings = 0;
    for (size_t i = 0; i < sizeof starts / sizeof starts[0]; i++) {
        for (int solver = 1; solver <= 4; solver++) {
            const double tol = solver == 2 ? 1e-10 : 1e-12;
            const double dt = 0.37 / sqrt(starts[i].g / starts[i].L);
            const Run a = run(&starts[i], solver, tol, dt, 120, 0, on);
            const Run b = run(&starts[i], solver, tol, dt, 120, 1, off);
            check(!a.failed && !b.failed, "on/off: a run failed");
            check(memcmp(on, off, sizeof on) == 0 && a.steps == b.steps && a.rhs == b.rhs,
                  "start %zu %s: the numbers differ with the certificate off", i, integrator_solver_name(solver));
            check(b.log.warnings <= 1 && b.warned <= 1, "start %zu %s: the certificate warned while off", i,
                  integrator_solver_name(solver));
            compared++;
            with_warnings += a.warned > 0;
        }
    }
    check(with_warnings >= 2, "on/off: only %d of the compared runs warned", with_warnings);
    printf("certificate on/off: %d runs bit-identical (%d of them with warnings)\n", compared, with_warnings);
}

/* ---- the messages: first crossing, then each tenfold growth --------------------------- */
static void test_messages(void)
{
    /* the hardest case: 1 - m = 1.1e-19, rkn at tol 1e-12, five steps of 16.505 s */
    const Start s = {3.0849789226170623, 0.034294831419746555, 374.6912982074549, 137.53188593324322};
    Instance inst;
    Log log;
    memset(&log, 0, sizeof log);
    current_log = &log;
    check(setup(&inst, &s, SOLVER_RKN, 1e-12, 0) == 0, "1.1e-19 case: set-up");
    int ok_beyond = 0, warned = 0, messages_expected = 0;
    double logged = 0.0;
    for (int i = 0; i < 5; i++) {
        const Status st = instance_do_step(&inst, "DoStep", inst.data.time, 16.505);
        const double dep = departure(&inst);
        ok_beyond += st == STATUS_OK && !(dep <= 1.0);
        warned += st == STATUS_WARNING;
        if (dep > 1.0 && (logged == 0.0 || dep >= 10.0 * logged)) {
            messages_expected++;
            logged = dep;
        }
    }
    double th_e, om_e;
    pendulum_exact_eval(&inst.data.exact, inst.data.time, &th_e, &om_e);
    printf("1 - m = %.2g, rkn at 1e-12, t = %g: theta %.9g, theta_exact %.9g; %d of 5 steps warned, %d messages\n",
           inst.data.exact.m1, inst.data.time, inst.data.theta, th_e, warned, log.warnings);
    check(ok_beyond == 0, "1.1e-19 case: %d steps OK beyond the bound", ok_beyond);
    check(warned >= 1, "1.1e-19 case: theta %g against %g, no warning", inst.data.theta, th_e);
    check(log.warnings == messages_expected + (inst.data.hard_case_reported && messages_expected == 0),
          "1.1e-19 case: %d messages, want %d", log.warnings, messages_expected);
    printf("first message: %s\n", log.first);
    check(strstr(log.first, "times beyond its bound") != NULL && strstr(log.first, "solver rkn") != NULL &&
              strstr(log.first, "tolerance 1e-12") != NULL && strstr(log.first, "1 - m = ") != NULL &&
              strstr(log.first, "No double-precision solver can hold it") != NULL,
          "1.1e-19 case: message \"%s\"", log.first);
    instance_release(&inst);

    /* rk4 beyond its own line: the message names the solvers that can */
    const double w0 = sqrt(9.81);
    const Start near = {0.0, 2.0 * w0 * (1.0 + 1e-11), 1.0, 9.81};
    const Run r = run(&near, SOLVER_RK4, 1e-10, exact_period(&near) / 20.0, 200, 0, NULL);
    check(r.warned > 0 && r.log.warnings >= 1 && r.log.warnings <= 1 + (int)ceil(log10(fmax(r.worst, 10.0))),
          "rk4 near the separatrix: %d warned steps, %d messages, worst %g", r.warned, r.log.warnings, r.worst);
    check(strstr(r.log.first, "rk4 cannot hold it") != NULL && strstr(r.log.first, "rkn, dopri5 or symplectic") != NULL,
          "rk4 message \"%s\"", r.log.first);
    printf("rk4 message: %s\n", r.log.first);
}

/* ---- an FMU state carries the certificate's field -------------------------------------- */
static void test_state_carries_the_certificate(void)
{
    const double w0 = sqrt(9.81);
    const Start s = {0.0, 2.0 * w0 * (1.0 + 1e-12), 1.0, 9.81};
    Instance inst;
    Log log;
    void *state = NULL, *back = NULL;
    memset(&log, 0, sizeof log);
    current_log = &log;
    check(setup(&inst, &s, SOLVER_RK4, 1e-10, 0) == 0, "state: set-up");
    Status st = STATUS_OK;
    for (int i = 0; i < 40 && st == STATUS_OK; i++) {
        st = instance_do_step(&inst, "DoStep", inst.data.time, 0.5);
    }
    check(st == STATUS_WARNING && inst.data.certificate_logged > 1.0, "state: no warning to carry (%g)",
          inst.data.certificate_logged);
    const double logged = inst.data.certificate_logged;
    size_t size = 0;
    check(instance_get_state(&inst, "get", &state) == STATUS_OK, "state: get");
    check(instance_serialized_state_size(&inst, "size", state, &size) == STATUS_OK, "state: size");
    char *bytes = calloc(1, size);
    check(bytes != NULL && instance_serialize_state(&inst, "ser", state, bytes, size) == STATUS_OK, "state: serialize");
    inst.data.certificate_logged = 0.0;
    check(instance_deserialize_state(&inst, "de", bytes, size, &back) == STATUS_OK &&
              instance_set_state(&inst, "set", back) == STATUS_OK && inst.data.certificate_logged == logged,
          "state: the certificate's field did not come back (%g, want %g)", inst.data.certificate_logged, logged);
    /* forged: a value the certificate can never have written */
    const double forged[] = {0.5, -1.0, NAN, INFINITY};
    for (size_t i = 0; i < sizeof forged / sizeof forged[0]; i++) {
        ((ModelData *)state)->certificate_logged = forged[i];
        check(model_check_state((ModelData *)state, INTERFACE_CO_SIMULATION) != NULL,
              "state: a certificate field of %g was accepted", forged[i]);
    }
    ((ModelData *)state)->certificate_logged = logged;
    check(model_check_state((ModelData *)state, INTERFACE_CO_SIMULATION) == NULL, "state: the real one refused");
    instance_free_state(&inst, "free", &state);
    instance_free_state(&inst, "free", &back);
    free(bytes);
    instance_release(&inst);
    current_log = NULL;
}

/* ---- the scale ladder: the same dimensionless problem, the same steps and error --------- */
/* One DoStep over w0 t = 63 from theta0 = 0, omega0 = 2 w0 (1 + 1e-15), rkn at 1e-10. */
static Run ladder_run(double L, double g)
{
    const double w0 = sqrt(g / L);
    const Start s = {0.0, 2.0 * w0 * (1.0 + 1e-15), L, g};
    return run(&s, SOLVER_RKN, 1e-10, 63.0 / w0, 1, 0, NULL);
}

static void test_scale_ladder(void)
{
    /* the scale ladder: (L, g) with g / L from 1e-12 to 1e12; rounding makes 1 - m differ
     * between them (it is ~1e-15 here), so the steps must agree and no step be OK beyond
     * its bound */
    const double Ls[] = {1.0 / 9.81, 1.0, 1e-3, 1e-6, 1e6, 1e3};
    const double gs[] = {1.0, 9.81, 1e3, 1e6, 1e-6, 1e-3};
    const Run base = ladder_run(Ls[0], gs[0]);
    for (int i = 0; i < 6; i++) {
        const Run r = ladder_run(Ls[i], gs[i]);
        const double ratio = (double)r.steps / (double)base.steps;
        printf("scale ladder L = %-8g g = %-8g: %ld steps, departure %.3g of the bound, %s\n", Ls[i], gs[i], r.steps,
               r.worst, r.warned ? "Warning" : "OK");
        check(!r.failed && r.ok_beyond == 0, "scale L %g g %g: failed or OK beyond the bound", Ls[i], gs[i]);
        check(ratio <= 1.5 && ratio >= 1.0 / 1.5, "scale L %g g %g: %ld steps against %ld", Ls[i], gs[i], r.steps,
              base.steps);
    }
    /* the same dimensionless problem exactly (g / L and w0 powers of two, 2^-20 .. 2^20):
     * the same steps and the same departure, to the last bit */
    const Run unit = ladder_run(1.0, 1.0);
    for (int e = -20; e <= 20; e += 10) {
        const Run a = ladder_run(ldexp(1.0, -e), ldexp(1.0, e)), b = ladder_run(ldexp(1.0, e), ldexp(1.0, -e));
        check(a.steps == unit.steps && b.steps == unit.steps, "scale 2^%d: %ld and %ld steps against %ld", e, a.steps,
              b.steps, unit.steps);
        /* every rule dimensionless, every scaling by a power of two exact: the same numbers */
        check(a.worst == unit.worst && b.worst == unit.worst && !a.warned && !b.warned,
              "scale 2^%d: departure %.17g and %.17g against %.17g", e, a.worst, b.worst, unit.worst);
    }
    printf("scale ladder, w0 = 2^-20 .. 2^20: %ld steps each, departure %.3g of the bound\n", unit.steps, unit.worst);
}

/* ---- random states: libration, rotation, near the separatrix ---------------------------- */
static double uniform(unsigned long long *rng)
{
    *rng ^= *rng << 13, *rng ^= *rng >> 7, *rng ^= *rng << 17;
    return (double)(*rng >> 11) * 0x1p-53;
}

static void test_random_states(void)
{
    unsigned long long rng = 0x9e3779b97f4a7c15ull;
    const double tols[] = {1e-6, 1e-8, 1e-10};
    int runs = 0, warned_runs = 0, unreachable_runs = 0;
    for (int k = 0; k < 24; k++) {
        const double L = pow(10.0, -3.0 + 6.0 * uniform(&rng)), g = pow(10.0, -3.0 + 6.0 * uniform(&rng));
        const double w0 = sqrt(g / L);
        const double theta0 = PI * (2.0 * uniform(&rng) - 1.0);
        double omega0;
        switch (k % 3) {
        case 0: omega0 = 2.0 * w0 * cos(0.5 * theta0) * uniform(&rng); break;                 /* libration */
        case 1: omega0 = 2.0 * w0 * (1.0 + 4.0 * uniform(&rng)); break;                        /* rotation */
        default: {                                                                              /* near it */
            const double c = cos(0.5 * theta0), d = pow(10.0, -4.0 - 10.0 * uniform(&rng));
            omega0 = 2.0 * w0 * sqrt(fmax(0.0, c * c + (uniform(&rng) < 0.5 ? -d : d)));
        }
        }
        if (uniform(&rng) < 0.5) {
            omega0 = -omega0;
        }
        const Start s = {theta0, omega0, L, g};
        const double period = exact_period(&s);
        const double dt = isfinite(period) ? period / 20.0 : 0.5 / w0;
        for (int solver = 1; solver <= 4; solver++) {
            const double tol = tols[(k + solver) % 3];
            const Run r = run(&s, solver, tol, dt, 60, 0, NULL);
            const int reach = reachable(&s, solver, tol);
            runs++;
            warned_runs += r.warned > 0;
            unreachable_runs += !reach;
            check(!r.failed && r.ok_beyond == 0, "random %d %s: failed or %d steps OK beyond the bound", k,
                  integrator_solver_name(solver), r.ok_beyond);
            check(!reach || r.warned == 0, "random %d (theta0 %.17g, omega0 %.17g, L %.17g, g %.17g) %s tol %g: "
                  "warned (departure %.3g) within the solver's reach", k, theta0, omega0, L, g, integrator_solver_name(solver), tol,
                  r.worst);
        }
    }
    printf("random states: %d runs, %d warned, %d beyond the solver's reach\n", runs, warned_runs, unreachable_runs);
}

/* ---- what the certificate costs: a DoStep timed with it on and off ---------------------- */
static double seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void print_cost(void)
{
    const Start s = {1.3089969389957472, 0.0, 1.0, 9.81};
    const int n = 100000, reps = 15;
    printf("\ncost of a DoStep (75 deg, default rkn at 1e-8), best of %d alternating runs of %d steps:\n", reps, n);
    printf("%-12s %14s %14s %12s\n", "step", "certificate on", "off", "difference");
    const double dts[] = {1e-3, 1e-2, 0.1};
    for (int j = 0; j < 3; j++) {
        double best[2] = {INFINITY, INFINITY};
        for (int rep = 0; rep < reps; rep++) {
            for (int off = 0; off <= 1; off++) {
                Instance inst;
                current_log = NULL;
                setup(&inst, &s, SOLVER_RKN, 1e-8, off);
                const double t0 = seconds();
                for (int i = 0; i < n; i++) {
                    instance_do_step(&inst, "DoStep", inst.data.time, dts[j]);
                }
                best[off] = fmin(best[off], (seconds() - t0) / n);
                instance_release(&inst);
            }
        }
        printf("%-12g %11.1f ns %11.1f ns %9.1f ns\n", dts[j], 1e9 * best[0], 1e9 * best[1],
               1e9 * (best[0] - best[1]));
    }
    /* the certificate alone: one exact evaluation and certificate_ratio at n times over 100 periods */
    PendulumExact ex;
    pendulum_exact_init_gl(&ex, s.theta0, s.omega0, s.g, s.L, 0.0);
    double best = INFINITY, sink = 0.0;
    for (int rep = 0; rep < reps; rep++) {
        const double t0 = seconds();
        for (int i = 0; i < n; i++) {
            double th, om;
            pendulum_exact_eval(&ex, 2.3e-3 * i, &th, &om);
            sink += certificate_ratio(ex.w0, 1e-8, 0.1, 0.2, th, om);
        }
        best = fmin(best, (seconds() - t0) / n);
    }
    printf("the certificate alone (one exact evaluation and the two ratios): %.1f ns a call%s\n", 1e9 * best,
           sink > 0.0 ? "" : " ");
}

int main(int argc, char **argv)
{
    const int print_table = argc > 1 && strcmp(argv[1], "table") == 0;
    if (argc > 1 && strcmp(argv[1], "cost") == 0) {
        print_cost();
        return 0;
    }
    if (argc > 2 && (strcmp(argv[1], "steps-on") == 0 || strcmp(argv[1], "steps-off") == 0)) {
        /* N DoSteps of 0.01 s (75 deg, rkn at 1e-8), for an instruction count (valgrind) */
        const Start s = {1.3089969389957472, 0.0, 1.0, 9.81};
        Instance inst;
        setup(&inst, &s, SOLVER_RKN, 1e-8, strcmp(argv[1], "steps-off") == 0);
        for (long i = 0, n = atol(argv[2]); i < n; i++) {
            instance_do_step(&inst, "DoStep", inst.data.time, 0.01);
        }
        printf("%.17g\n", inst.data.theta);
        instance_release(&inst);
        return 0;
    }
    test_separatrix_grid(print_table);
    test_bit_identical_on_off();
    test_messages();
    test_state_carries_the_certificate();
    test_scale_ladder();
    test_random_states();
    return check_summary("test_certificate");
}
