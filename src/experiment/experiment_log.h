/* experiment_log.h: the time series a run keeps (fs_run_result's trajectory), shared with the
 * landing trial; private to src/experiment. A logger is a drive hook (fs_drive.h) that never stops
 * the experiment: it records a row every `every` steps (with an error-controlled step, a row at
 * every log_interval_s, interpolated), within the capacity fs_log_open set. */
#ifndef EXPERIMENT_LOG_H
#define EXPERIMENT_LOG_H

#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"

/* Names res's columns (time, ankle, contacts, each hinge's angle, each spring's force, and the
 * robot's lean when with_lean) and allocates rows for a run of sc's duration_s logged every
 * log_interval_s; FS_BAD_INPUT past the trajectory's bound, FS_NO_MEMORY. */
fs_status fs_log_open(fs_run_result *res, const fs_scenario *sc, int with_lean, fs_error *err);

typedef struct fs_run_logger {
    fs_run_result *res;
    long every, step;
    /* an error-controlled step (run.tolerance_m): rows at every log_interval_s, each interpolated
       linearly between the states of the steps before and after its time (contacts: the nearer's) */
    int timed;
    double interval_s;
    long logged;                      /* rows at k interval_s so far (k = 1, 2, ...) */
    double prev[FS_TRAJ_MAX_COLS];    /* the last step's row */
} fs_run_logger;

/* One row of sim's state (when there is room). */
void fs_log_row(fs_run_result *res, const fs_sim *sim);

/* Logs the row at t = 0 into res (when res is not NULL) and makes *l its logger. */
void fs_log_begin(fs_run_logger *l, fs_run_result *res, const fs_sim *sim);

/* The hook: a row every l->every steps, or at every interval with an error-controlled step;
 * returns 0 (never stops). */
int fs_log_after_step(void *user, fs_sim *sim);

/* The last row, when the last step was not logged already. */
void fs_log_last(fs_run_result *res, const fs_sim *sim);

#endif
