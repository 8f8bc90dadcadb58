/* pendulum_driver: steps a Co-Simulation FMU over an output grid and reads its outputs, in C.
 *
 * The Python package (pendulum_fmu.fmu.driver) loads and instantiates the FMU with fmpy and
 * hands this library the instance and the addresses of the FMU's own DoStep and GetReal
 * (FMI 2.0) or DoStep and GetFloat64 (FMI 3.0). One call then runs a stretch of the grid:
 * for each point k, DoStep from times[k-1] to times[k] and one GetReal of every recorded
 * output straight into row k of the caller's array. Every status is checked; fmi2Warning /
 * fmi3Warning goes on (the FMU's logger has the message), anything worse stops the stretch
 * and says which call failed where. The library loads nothing itself and allocates nothing.
 */
#ifndef PENDULUM_DRIVER_H
#define PENDULUM_DRIVER_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define PENDULUM_DRIVER_API __declspec(dllexport)
#else
#define PENDULUM_DRIVER_API __attribute__((visibility("default")))
#endif

/* The interface version; pendulum_fmu.fmu.driver refuses a library that reports another. */
#define PENDULUM_DRIVER_ABI 1

/* Which call stopped a stretch (pendulum_drive_outcome.call). */
enum pendulum_drive_call {
    PENDULUM_DRIVE_NONE = 0,       /* every point of the stretch done */
    PENDULUM_DRIVE_DO_STEP = 1,    /* DoStep returned worse than Warning */
    PENDULUM_DRIVE_GET = 2,        /* GetReal / GetFloat64 returned worse than Warning */
    PENDULUM_DRIVE_TERMINATE = 3,  /* fmi3DoStep asked to terminate the simulation */
    PENDULUM_DRIVE_EARLY = 4,      /* fmi3DoStep returned early (not allowed at instantiation) */
    PENDULUM_DRIVE_BAD_ARGS = 5    /* a null pointer, an unknown FMI version, or first > last */
};

/* One FMU instance and what to record: filled once per run by the caller. */
typedef struct pendulum_drive_fmu {
    int fmi_version;          /* 2 or 3 */
    void *instance;           /* fmi2Component / fmi3Instance */
    void *do_step;            /* address of fmi2DoStep / fmi3DoStep */
    void *get_values;         /* address of fmi2GetReal / fmi3GetFloat64 */
    const uint32_t *vrs;      /* value references of the recorded outputs (fmi2/fmi3ValueReference) */
    size_t nvr;               /* how many */
} pendulum_drive_fmu;

/* How a stretch ended. */
typedef struct pendulum_drive_outcome {
    size_t done;              /* rows [0, done) are filled */
    int call;                 /* enum pendulum_drive_call */
    int status;               /* the failing call's status (0 when call is NONE) */
    double time;              /* the communication point of the failing call (3.0: lastSuccessfulTime) */
} pendulum_drive_outcome;

PENDULUM_DRIVER_API int pendulum_driver_abi(void);

/* Run points first .. last-1 of the grid ``times``: point 0 is read without a step (the FMU
 * stands at times[0]), every later point k steps from times[k-1] by times[k] - times[k-1].
 * Row k is ``rows + k * row_stride`` (in doubles); the nvr outputs land there contiguously.
 * Returns outcome->call (0: all done). */
PENDULUM_DRIVER_API int pendulum_drive(const pendulum_drive_fmu *fmu, const double *times, size_t first,
                                       size_t last, double *rows, size_t row_stride,
                                       pendulum_drive_outcome *outcome);

#endif
