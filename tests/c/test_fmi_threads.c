/* test_fmi_threads.c: instances in concurrent threads give exactly what they give alone
 * (no global mutable state in the FMU). Run under ThreadSanitizer-free ASan/UBSan builds too. */
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "fmi2_api.h"
#include "pendulum_vrs.h"

#define N_THREADS 4
#define N_STEPS 2000

typedef struct {
    double theta0;      /* initial angle, rad */
    int solver;         /* SolverKind of the instance */
    double theta_end;   /* result: theta after N_STEPS steps */
    double exact_end;   /* result: theta_exact at the same time */
    int status;         /* 0 if every call returned fmi2OK */
} Job;

static void quiet_logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status, fmi2String category,
                         fmi2String message, ...) {
    (void)env, (void)name, (void)status, (void)category, (void)message;
}

static void *run_job(void *argument) {
    Job *job = argument;
    const fmi2CallbackFunctions callbacks = {quiet_logger, calloc, free, NULL, NULL};
    const fmi2ValueReference vr_theta = VR_THETA, vr_solver = VR_SOLVER, vr_out[2] = {VR_THETA, VR_THETA_EXACT};
    double out[2] = {NAN, NAN};
    fmi2Component c = fmi2Instantiate("thread", fmi2CoSimulation, PENDULUM_GUID, NULL, &callbacks, 0, 0);
    int ok = c != NULL && fmi2SetupExperiment(c, fmi2True, 1e-9, 0.0, fmi2False, 0.0) == fmi2OK &&
             fmi2EnterInitializationMode(c) == fmi2OK && fmi2SetReal(c, &vr_theta, 1, &job->theta0) == fmi2OK &&
             fmi2SetInteger(c, &vr_solver, 1, &job->solver) == fmi2OK && fmi2ExitInitializationMode(c) == fmi2OK;
    int i;
    for (i = 0; ok && i < N_STEPS; i++) {
        ok = fmi2DoStep(c, i * 0.01, 0.01, fmi2True) == fmi2OK;
    }
    ok = ok && fmi2GetReal(c, vr_out, 2, out) == fmi2OK;
    job->theta_end = out[0];
    job->exact_end = out[1];
    job->status = ok ? 0 : 1;
    fmi2FreeInstance(c);
    return NULL;
}

int main(void) {
    Job alone[N_THREADS], concurrent[N_THREADS];
    pthread_t threads[N_THREADS];
    int i, failures = 0;
    for (i = 0; i < N_THREADS; i++) {
        Job job = {0.5 + 0.8 * i, 1 + i % 4, NAN, NAN, 1};
        alone[i] = job;
        concurrent[i] = job;
        run_job(&alone[i]);
    }
    for (i = 0; i < N_THREADS; i++) {
        pthread_create(&threads[i], NULL, run_job, &concurrent[i]);
    }
    for (i = 0; i < N_THREADS; i++) {
        pthread_join(threads[i], NULL);
    }
    for (i = 0; i < N_THREADS; i++) {
        int same = alone[i].status == 0 && concurrent[i].status == 0 && isfinite(alone[i].theta_end) &&
                   alone[i].theta_end == concurrent[i].theta_end && alone[i].exact_end == concurrent[i].exact_end;
        if (!same) {
            failures++;
            fprintf(stderr, "FAILED: thread %d: alone %.17g (status %d), concurrent %.17g (status %d)\n", i,
                    alone[i].theta_end, alone[i].status, concurrent[i].theta_end, concurrent[i].status);
        }
    }
    printf("test_fmi_threads: %d instances in threads, %d differ from running alone\n", N_THREADS, failures);
    return failures == 0 ? 0 : 1;
}
