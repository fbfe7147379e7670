/* experiment_log.h: the time series a run keeps (fs_run_result's trajectory), shared with the
 * landing trial; private to src/experiment. A logger is a drive hook (fs_drive.h) that never stops
 * the experiment: it records a row every `every` steps, within the capacity fs_log_open set. */
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
} fs_run_logger;

/* One row of sim's state (when there is room). */
void fs_log_row(fs_run_result *res, const fs_sim *sim);

/* The hook: a row every l->every steps; returns 0 (never stops). */
int fs_log_after_step(void *user, fs_sim *sim);

/* The last row, when the last step was not logged already. */
void fs_log_last(fs_run_result *res, const fs_sim *sim);

#endif
