/* fs_drive.h: the one loop that steps a simulation, for every experiment.
 *
 * fs_drive steps a built sim at most max_steps times. Before each step it calls `before` (a
 * driver's own forces and motions: the stiffness probes' torques, the walking machine's carriage);
 * after each step it calls the observer when due (fs_observer.h: at t = 0, every interval and at the
 * end), then every hook in order. A hook measures, records or judges (a hook's user data is its
 * own state: a history, a rest clock, a window of samples) and says whether the run stops there;
 * every hook sees every step, the last one too, and the first that said stop is the one the
 * result names. A step whose state checks fail
 * (fs_check.h) ends the run with FS_NUMERICAL; an observer that fails ends it with its status.
 * With an error-controlled step (run.tolerance_m > 0, fs_sim.h) the run ends instead at the time
 * max_steps steps of step_s reach, its last step cut short to end there, and the observer is called
 * at the first step ending at or past each interval.
 * The loop allocates nothing and adds a few indirect calls to a step (docs/bench.md). */
#ifndef FS_DRIVE_H
#define FS_DRIVE_H

#include "footsim/sim/fs_observer.h"

typedef struct fs_step_hook {
    const char *name;                      /* why the run stopped, when this hook stops it ("at rest") */
    int (*after_step)(void *user, fs_sim *sim); /* nonzero: stop after this step */
    void *user;
} fs_step_hook;

typedef struct fs_drive_spec {
    long max_steps;                        /* the run ends after this many steps at the latest */
    void (*before_step)(void *user, fs_sim *sim); /* or NULL */
    void *before_user;
    const fs_step_hook *hooks;             /* nhooks of them, called in order after each step */
    int nhooks;
    const fs_run_observer *obs;            /* or NULL */
} fs_drive_spec;

typedef struct fs_drive_result {
    long steps;            /* steps taken (the failed one included) */
    int stopped_by;        /* the hook that stopped the run (its index), or -1 */
    int step_failed;       /* a step's checks failed: the status is FS_NUMERICAL, err says where */
} fs_drive_result;

/* Steps sim as spec says. FS_OK when a hook stopped the run or max_steps were taken. */
fs_status fs_drive(fs_sim *sim, const fs_drive_spec *spec, fs_drive_result *out, fs_error *err);

/* The name of what ended a run: the stopping hook's, "failed" or "max_steps". */
const char *fs_drive_reason(const fs_drive_spec *spec, const fs_drive_result *r);

#endif
