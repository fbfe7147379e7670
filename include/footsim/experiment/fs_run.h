/* fs_run.h: one scenario run from rest to settled, its metrics and its trajectory.
 *
 * fs_run builds the scenario's foot, steps it until it has been at rest for rest_hold_s (after
 * the load has risen) or duration_s has passed, and measures. The trajectory buffer is taken
 * before the first step; nothing is allocated while stepping. fs_run_write puts metrics.json and
 * trajectory.csv in a folder, each written whole or not at all. */
#ifndef FS_RUN_H
#define FS_RUN_H

#include "footsim/sim/fs_observer.h"
#include "footsim/model/fs_scenario.h"

/* trajectory columns: t_s, the ankle's x, y, z (m), contacts, each hinge's angle (NAME_rad), each
 * spring-damper's force (NAME_N, positive in tension) */
enum { FS_TRAJ_MAX_COLS = 5 + FS_MAX_HINGES + FS_MAX_SPRINGS + 1 }; /* time, ankle, contacts, hinges, springs, lean */

/* The most memory a run's trajectory may take (docs/keys.md); a run asking for more is refused
 * (FS_BAD_INPUT) before its first step. */
#define FS_TRAJ_MAX_BYTES (1024.0 * 1024 * 1024)

typedef struct fs_run_result {
    int steps;
    double end_time_s;
    double ankle_start_m[3], ankle_end_m[3];
    double ankle_drop_m;       /* start height minus settled height of the ankle */
    double settle_time_s;      /* the ankle stays within settle_band_m of its final height after this */
    int at_rest;               /* stopped because at rest, not because duration_s ran out */
    double hinge_angle_rad[FS_MAX_HINGES];
    double spring_force_N[FS_MAX_SPRINGS], spring_length_m[FS_MAX_SPRINGS];
    int contacts_end;
    long contacts_total, collision_tests;
    double energy_start_J, energy_end_J;
    /* trajectory: rows of ncols doubles */
    int ncols, nrows, capacity;
    const char *col_name[FS_TRAJ_MAX_COLS]; /* point into the fixed names or hinge_col */
    char hinge_col[FS_MAX_HINGES][48];      /* the hinge columns' names, owned by the result */
    char spring_col[FS_MAX_SPRINGS][48];    /* the spring columns' names, owned by the result */
    double *rows;
    long every;                             /* a row every `every` steps (log_interval_s) */
    int lean_col;                           /* the robot's lean column (lean_deg), 0 when none */
} fs_run_result;

/* obs (fs_observer.h) may be NULL. */
fs_status fs_run(const fs_scenario *sc, const fs_run_observer *obs, fs_run_result *res, fs_error *err);
void fs_run_free(fs_run_result *res);

/* Writes DIR/metrics.json and DIR/trajectory.csv (creating DIR and its parents); metrics.json
 * records prov (fs_provenance.h; may be NULL) as its "provenance". */
fs_status fs_run_write(const fs_scenario *sc, const fs_run_result *res, const fs_provenance *prov, const char *dir,
                       fs_error *err);

/* Writes res's trajectory alone as path (CSV, a header of column names with units); a landing
 * trial's time series (fs_trial_run_logged) is written this way. */
fs_status fs_run_write_trajectory(const fs_run_result *res, const char *path, fs_error *err);

#endif
