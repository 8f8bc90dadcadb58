/* bench_solvers.c: the C half of the speed-against-error study (README, "Solvers and the
 * speed-against-error study"). Loads the FMU's shared library with dlopen, resolves the FMI
 * functions with dlsym and drives them directly, so the timings are the model's own cost
 * with no Python in between.
 *
 * Usage: bench_solvers PATH/Pendulum.so [--problems P1,P2,P3] [--solvers dopri5,rk4,rkn,symplectic]
 *                      [--tols 1e-3,1e-4,...] [--repeat N] [--p3-periods N] [--points N]
 *
 * Problems (theta0 from rest, g = 9.81, L = 1):
 *   P1  75, 80, 85 and 90 deg over 10 periods;  P2  179.99 deg over 20 periods;
 *   P3  90 deg over 10,000 periods (--p3-periods).
 * Output grid: `points` communication points a period (default 50), t_i = i T / points.
 *
 * For every problem and amplitude the driver first runs the floor: a Model Exchange
 * instance evaluates the exact solution at the same points (fmi2SetTime, fmi2GetReal of
 * theta_exact). Then, for every solver and tolerance, a Co-Simulation instance steps
 * through the points (fmi2DoStep, fmi2GetReal of theta and omega). Each timing is the best
 * of N repetitions (default 5, 2 for P3) of the loop over the points; instantiation and
 * initialization are timed apart (setup_s). The error is max |theta - theta_exact| over the
 * points, the energy error |H - H0| / H0 with H = omega^2/2 + 2 (g/L) sin^2(theta/2).
 *
 * One line per measurement, key=value separated by spaces:
 *   floor problem=P1 amplitude_deg=75 periods=10 points=501 period_s=... wall_s=...
 *   run problem=P1 amplitude_deg=75 periods=10 points=501 solver=rkn tol=1e-08 status=ok
 *       rhs_evaluations=... steps=... rejected=... max_err=... energy_err_max=...
 *       energy_err_first=... energy_err_last=... max_abs_theta=... wall_s=... setup_s=...
 * (energy_err_first / _last: the largest energy error over the first / last tenth of the
 * points, which shows a drift.) Exit status 0, or 1 if a run failed, 2 on bad usage. */
#define _POSIX_C_SOURCE 200809L

#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmi2_api.h"
#include "pendulum_vrs.h"

#define MAX_LIST 32

/* the FMI functions the driver calls, resolved from the library */
typedef struct {
    fmi2Component (*instantiate)(fmi2String, fmi2Type, fmi2String, fmi2String,
                                 const fmi2CallbackFunctions *, fmi2Boolean, fmi2Boolean);
    void (*free_instance)(fmi2Component);
    fmi2Status (*setup_experiment)(fmi2Component, fmi2Boolean, fmi2Real, fmi2Real, fmi2Boolean,
                                   fmi2Real);
    fmi2Status (*enter_init)(fmi2Component);
    fmi2Status (*exit_init)(fmi2Component);
    fmi2Status (*terminate)(fmi2Component);
    fmi2Status (*get_real)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Real[]);
    fmi2Status (*get_integer)(fmi2Component, const fmi2ValueReference[], size_t, fmi2Integer[]);
    fmi2Status (*set_real)(fmi2Component, const fmi2ValueReference[], size_t, const fmi2Real[]);
    fmi2Status (*set_integer)(fmi2Component, const fmi2ValueReference[], size_t,
                              const fmi2Integer[]);
    fmi2Status (*enter_continuous)(fmi2Component);
    fmi2Status (*set_time)(fmi2Component, fmi2Real);
    fmi2Status (*do_step)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean);
} Fmi;

typedef struct {
    const char *problem;
    double amplitude_deg;
    double periods;
} Case;

typedef struct {
    char problems[MAX_LIST][8];
    int n_problems;
    int solvers[MAX_LIST];
    int n_solvers;
    double tols[MAX_LIST];
    int n_tols;
    int repeat;          /* 0: the default per problem */
    double p3_periods;
    int points;
} Options;

static const char *const SOLVER_NAMES[] = {"", "dopri5", "rk4", "rkn", "symplectic"};
static const double G = 9.81, L = 1.0;

/* monotonic clock: seconds since boot are small, so the double keeps nanoseconds */
static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    va_list ap;
    (void)env;
    fprintf(stderr, "bench_solvers: %s [%s, status %d]: ", name ? name : "?",
            category ? category : "?", (int)status);
    va_start(ap, message);
    vfprintf(stderr, message, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static int resolve(void *lib, const char *name, void **slot)
{
    *slot = dlsym(lib, name);
    if (*slot == NULL) {
        fprintf(stderr, "bench_solvers: %s not found in the library\n", name);
        return -1;
    }
    return 0;
}

/* POSIX: a function pointer is stored through the object pointer dlsym returns */
#define RESOLVE(lib, field, name) resolve(lib, name, (void **)&(field))

static int load(const char *path, Fmi *fmi, void **lib_out)
{
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (lib == NULL) {
        fprintf(stderr, "bench_solvers: cannot load %s: %s\n", path, dlerror());
        return -1;
    }
    *lib_out = lib;
    return RESOLVE(lib, fmi->instantiate, "fmi2Instantiate") |
           RESOLVE(lib, fmi->free_instance, "fmi2FreeInstance") |
           RESOLVE(lib, fmi->setup_experiment, "fmi2SetupExperiment") |
           RESOLVE(lib, fmi->enter_init, "fmi2EnterInitializationMode") |
           RESOLVE(lib, fmi->exit_init, "fmi2ExitInitializationMode") |
           RESOLVE(lib, fmi->terminate, "fmi2Terminate") |
           RESOLVE(lib, fmi->get_real, "fmi2GetReal") |
           RESOLVE(lib, fmi->get_integer, "fmi2GetInteger") |
           RESOLVE(lib, fmi->set_real, "fmi2SetReal") |
           RESOLVE(lib, fmi->set_integer, "fmi2SetInteger") |
           RESOLVE(lib, fmi->enter_continuous, "fmi2EnterContinuousTimeMode") |
           RESOLVE(lib, fmi->set_time, "fmi2SetTime") |
           RESOLVE(lib, fmi->do_step, "fmi2DoStep");
}

/* Instantiates and initializes one instance: theta0 from rest, g, L, the solver (CS) and
 * the tolerance. Returns NULL on failure. */
static fmi2Component start(const Fmi *fmi, fmi2Type type, double theta0, int solver, double tol,
                           const fmi2CallbackFunctions *callbacks)
{
    static const fmi2ValueReference vr_real[] = {VR_L, VR_G, VR_THETA, VR_OMEGA};
    const fmi2Real values[] = {L, G, theta0, 0.0};
    const fmi2ValueReference vr_solver = VR_SOLVER;
    fmi2Component c = fmi->instantiate("bench", type, PENDULUM_GUID, "file:///tmp", callbacks,
                                       fmi2False, fmi2False);
    if (c == NULL)
        return NULL;
    if (fmi->setup_experiment(c, tol > 0.0, tol, 0.0, fmi2False, 0.0) != fmi2OK ||
        fmi->set_real(c, vr_real, 4, values) != fmi2OK ||
        (type == fmi2CoSimulation && fmi->set_integer(c, &vr_solver, 1, &solver) != fmi2OK) ||
        fmi->enter_init(c) != fmi2OK || fmi->exit_init(c) != fmi2OK ||
        (type == fmi2ModelExchange && fmi->enter_continuous(c) != fmi2OK)) {
        fmi->free_instance(c);
        return NULL;
    }
    return c;
}

/* The communication times a master accumulates: t_i = t_{i-1} + (i T / points - t_{i-1}). */
static void make_times(double *times, long n, double period, int points)
{
    double t = 0.0;
    times[0] = 0.0;
    for (long i = 1; i < n; i++) {
        double step = period * (double)i / points - t;
        t = t + step;
        times[i] = t;
    }
}

/* The floor: the exact solution at the points through Model Exchange. Returns the best
 * wall time of the loop or a negative number on failure; fills exact[] (n values). */
static double run_floor(const Fmi *fmi, const fmi2CallbackFunctions *cb, double theta0,
                        const double *times, long n, int repeat, double *exact)
{
    const fmi2ValueReference vr = VR_THETA_EXACT;
    double best = INFINITY;
    for (int r = 0; r < repeat; r++) {
        fmi2Component c = start(fmi, fmi2ModelExchange, theta0, 0, 0.0, cb);
        if (c == NULL)
            return -1.0;
        int ok = 1;
        double t0 = now_seconds();
        for (long i = 0; i < n && ok; i++)
            ok = fmi->set_time(c, times[i]) == fmi2OK && fmi->get_real(c, &vr, 1, &exact[i]) == fmi2OK;
        double wall = now_seconds() - t0;
        fmi->terminate(c);
        fmi->free_instance(c);
        if (!ok)
            return -1.0;
        best = fmin(best, wall);
    }
    return best;
}

typedef struct {
    int ok;
    double wall, setup;
    int stats[3];
} RunResult;

/* One Co-Simulation run through the points, repeated; theta[] and omega[] hold the outputs
 * (n values, theta[0] the start value). */
static RunResult run_solver(const Fmi *fmi, const fmi2CallbackFunctions *cb, double theta0,
                            int solver, double tol, const double *times, long n, int repeat,
                            double *theta, double *omega)
{
    static const fmi2ValueReference vr_out[] = {VR_THETA, VR_OMEGA};
    static const fmi2ValueReference vr_stats[] = {VR_STATS_STEPS, VR_STATS_REJECTED_STEPS,
                                                  VR_STATS_RHS_EVALUATIONS};
    RunResult res = {1, INFINITY, INFINITY, {0, 0, 0}};
    for (int r = 0; r < repeat && res.ok; r++) {
        double t_setup = now_seconds();
        fmi2Component c = start(fmi, fmi2CoSimulation, theta0, solver, tol, cb);
        if (c == NULL) {
            res.ok = 0;
            break;
        }
        double t0 = now_seconds();
        double out[2];
        int ok = fmi->get_real(c, vr_out, 2, out) == fmi2OK;
        theta[0] = out[0];
        omega[0] = out[1];
        for (long i = 1; i < n && ok; i++) {
            /* fmi2Warning: the step certificate says the error is beyond 100 tol; the study
             * measures that error itself, so the run counts (docs/certificate.md) */
            ok = fmi->do_step(c, times[i - 1], times[i] - times[i - 1], fmi2True) <= fmi2Warning &&
                 fmi->get_real(c, vr_out, 2, out) == fmi2OK;
            theta[i] = out[0];
            omega[i] = out[1];
        }
        double t1 = now_seconds();
        ok = ok && fmi->get_integer(c, vr_stats, 3, res.stats) == fmi2OK;
        fmi->terminate(c);
        fmi->free_instance(c);
        res.ok = ok;
        res.wall = fmin(res.wall, t1 - t0);
        res.setup = fmin(res.setup, t0 - t_setup);
    }
    return res;
}

static int parse_list(const char *text, char items[][32], int max)
{
    int n = 0;
    const char *p = text;
    while (*p && n < max) {
        size_t len = strcspn(p, ",");
        if (len == 0 || len >= 32)
            return -1;
        memcpy(items[n], p, len);
        items[n][len] = '\0';
        n++;
        p += len;
        if (*p == ',')
            p++;
    }
    return *p ? -1 : n;
}

static int parse_options(int argc, char **argv, Options *o)
{
    char items[MAX_LIST][32];
    static const double default_tols[] = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10,
                                          1e-11, 1e-12};
    memset(o, 0, sizeof *o);
    strcpy(o->problems[0], "P1");
    strcpy(o->problems[1], "P2");
    strcpy(o->problems[2], "P3");
    o->n_problems = 3;
    for (int k = 1; k <= 4; k++)
        o->solvers[k - 1] = k;
    o->n_solvers = 4;
    o->n_tols = (int)(sizeof default_tols / sizeof default_tols[0]);
    memcpy(o->tols, default_tols, sizeof default_tols);
    o->p3_periods = 10000.0;
    o->points = 50;
    for (int i = 2; i < argc; i++) {
        const char *arg = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        int n;
        if (val == NULL)
            return -1;
        i++;
        if (strcmp(arg, "--problems") == 0) {
            if ((n = parse_list(val, items, MAX_LIST)) <= 0)
                return -1;
            for (int k = 0; k < n; k++) {
                if (strcmp(items[k], "P1") && strcmp(items[k], "P2") && strcmp(items[k], "P3"))
                    return -1;
                strcpy(o->problems[k], items[k]);
            }
            o->n_problems = n;
        } else if (strcmp(arg, "--solvers") == 0) {
            if ((n = parse_list(val, items, MAX_LIST)) <= 0)
                return -1;
            for (int k = 0; k < n; k++) {
                o->solvers[k] = 0;
                for (int s = 1; s <= 4; s++)
                    if (strcmp(items[k], SOLVER_NAMES[s]) == 0)
                        o->solvers[k] = s;
                if (o->solvers[k] == 0)
                    return -1;
            }
            o->n_solvers = n;
        } else if (strcmp(arg, "--tols") == 0) {
            if ((n = parse_list(val, items, MAX_LIST)) <= 0)
                return -1;
            for (int k = 0; k < n; k++) {
                char *end;
                o->tols[k] = strtod(items[k], &end);
                if (*end || !(o->tols[k] > 0.0))
                    return -1;
            }
            o->n_tols = n;
        } else if (strcmp(arg, "--repeat") == 0) {
            o->repeat = atoi(val);
            if (o->repeat <= 0)
                return -1;
        } else if (strcmp(arg, "--p3-periods") == 0) {
            o->p3_periods = strtod(val, NULL);
            if (!(o->p3_periods >= 1.0))
                return -1;
        } else if (strcmp(arg, "--points") == 0) {
            o->points = atoi(val);
            if (o->points <= 0)
                return -1;
        } else {
            return -1;
        }
    }
    return 0;
}

/* the largest |H - H0| / H0 over points [from, to) */
static double energy_error(const double *theta, const double *omega, long from, long to,
                           double h0)
{
    double worst = 0.0;
    for (long i = from; i < to; i++) {
        double s = sin(0.5 * theta[i]);
        worst = fmax(worst, fabs(0.5 * omega[i] * omega[i] + 2.0 * (G / L) * s * s - h0) / h0);
    }
    return worst;
}

static int bench_case(const Fmi *fmi, const fmi2CallbackFunctions *cb, const Options *o,
                      const Case *cs)
{
    const double theta0 = cs->amplitude_deg * (3.14159265358979323846 / 180.0);
    const long n = (long)llround(cs->periods * o->points) + 1;
    const int repeat = o->repeat > 0 ? o->repeat : (strcmp(cs->problem, "P3") == 0 ? 2 : 5);
    const fmi2ValueReference vr_period = VR_PERIOD;
    const double s0 = sin(0.5 * theta0), h0 = 2.0 * (G / L) * s0 * s0;
    int failed = 0, run_failed = 0;
    double period;

    fmi2Component c = start(fmi, fmi2ModelExchange, theta0, 0, 0.0, cb);
    if (c == NULL || fmi->get_real(c, &vr_period, 1, &period) != fmi2OK) {
        fprintf(stderr, "bench_solvers: cannot set up %s at %g deg\n", cs->problem,
                cs->amplitude_deg);
        if (c != NULL)
            fmi->free_instance(c);
        return 1;
    }
    fmi->free_instance(c);

    /* all buffers before any timing: nothing is allocated inside a timed loop */
    double *times = malloc((size_t)n * sizeof *times), *exact = malloc((size_t)n * sizeof *exact);
    double *theta = malloc((size_t)n * sizeof *theta), *omega = malloc((size_t)n * sizeof *omega);
    if (!times || !exact || !theta || !omega) {
        fprintf(stderr, "bench_solvers: out of memory\n");
        free(times), free(exact), free(theta), free(omega);
        return 1;
    }
    make_times(times, n, period, o->points);
    double floor_wall = run_floor(fmi, cb, theta0, times, n, repeat, exact);
    if (floor_wall < 0.0) {
        fprintf(stderr, "bench_solvers: the exact evaluation failed for %s\n", cs->problem);
        failed = 1;
    } else {
        printf("floor problem=%s amplitude_deg=%.10g periods=%.10g points=%ld period_s=%.17g "
               "wall_s=%.6e\n", cs->problem, cs->amplitude_deg, cs->periods, n, period,
               floor_wall);
        fflush(stdout);
    }
    for (int s = 0; s < o->n_solvers && !failed; s++) {
        for (int k = 0; k < o->n_tols; k++) {
            RunResult r = run_solver(fmi, cb, theta0, o->solvers[s], o->tols[k], times, n,
                                     repeat, theta, omega);
            run_failed |= !r.ok;
            printf("run problem=%s amplitude_deg=%.10g periods=%.10g points=%ld solver=%s "
                   "tol=%.3g status=%s", cs->problem, cs->amplitude_deg, cs->periods, n,
                   SOLVER_NAMES[o->solvers[s]], o->tols[k], r.ok ? "ok" : "failed");
            if (r.ok) {
                double err = 0.0, max_abs = 0.0;
                for (long i = 0; i < n; i++) {
                    err = fmax(err, fabs(theta[i] - exact[i]));
                    max_abs = fmax(max_abs, fabs(theta[i]));
                }
                const long tenth = n / 10 > 0 ? n / 10 : 1;
                printf(" rhs_evaluations=%d steps=%d rejected=%d max_err=%.6e "
                       "energy_err_max=%.6e energy_err_first=%.6e energy_err_last=%.6e "
                       "max_abs_theta=%.17g wall_s=%.6e setup_s=%.6e", r.stats[2], r.stats[0],
                       r.stats[1], err,
                       energy_error(theta, omega, 0, n, h0),
                       energy_error(theta, omega, 0, tenth, h0),
                       energy_error(theta, omega, n - tenth, n, h0), max_abs, r.wall, r.setup);
            }
            printf("\n");
            fflush(stdout);
        }
    }
    free(times), free(exact), free(theta), free(omega);
    return failed || run_failed;
}

int main(int argc, char **argv)
{
    Options o;
    if (argc < 2 || parse_options(argc, argv, &o) != 0) {
        fprintf(stderr, "usage: bench_solvers PATH/Pendulum.so [--problems P1,P2,P3] "
                        "[--solvers dopri5,rk4,rkn,symplectic] [--tols 1e-3,...] [--repeat N] "
                        "[--p3-periods N] [--points N]\n");
        return 2;
    }
    Fmi fmi;
    void *lib = NULL;
    if (load(argv[1], &fmi, &lib) != 0) {
        if (lib != NULL)
            dlclose(lib);
        return 2;
    }
    const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    int failed = 0;
    for (int p = 0; p < o.n_problems; p++) {
        if (strcmp(o.problems[p], "P1") == 0) {
            static const double amplitudes[] = {75.0, 80.0, 85.0, 90.0};
            for (int a = 0; a < 4; a++) {
                const Case cs = {"P1", amplitudes[a], 10.0};
                failed |= bench_case(&fmi, &callbacks, &o, &cs);
            }
        } else if (strcmp(o.problems[p], "P2") == 0) {
            const Case cs = {"P2", 179.99, 20.0};
            failed |= bench_case(&fmi, &callbacks, &o, &cs);
        } else {
            const Case cs = {"P3", 90.0, o.p3_periods};
            failed |= bench_case(&fmi, &callbacks, &o, &cs);
        }
    }
    dlclose(lib);
    return failed ? 1 : 0;
}
