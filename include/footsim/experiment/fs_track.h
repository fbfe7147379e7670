/* fs_track.h: a run's path sampled at every step, and how far one path is from another.
 *
 * The precision benchmark (footsim bench precision) measures ODE's error this way: a scenario, or
 * one chain of it pinned to the world, run at some step size, stepper and spring implementation,
 * against a reference path (the planar dynamic model, or the same scenario at the finest step). */
#ifndef FS_TRACK_H
#define FS_TRACK_H

#include "footsim/analysis/fs_analysis.h"
#include "footsim/sim/fs_sim.h"

enum { FS_TRACK_ANGLES = 3 };


/* Sample i is the state at t = i * dt_s: the ankle (world, m) and the first FS_TRACK_ANGLES hinge
 * angles (rad; for a pinned chain: ankle, midfoot, MTP). */
typedef struct fs_track {
    double dt_s;
    int n;
    int nangles;               /* hinge angles sampled: up to FS_TRACK_ANGLES (0 for the flat foot) */
    double (*ankle)[3];
    double (*angle)[FS_TRACK_ANGLES];
    double wall_s;             /* fs_track_run: wall-clock time of the steps (not of building), s */
    int check_class;           /* fs_track_run: fs_check_class of the run (drifting only with record_drift) */
    int first_drift;           /* fs_track_run: the fs_check_kind of the first drift (FS_CHECK_OK: none) */
    double max_loop_error_m;   /* fs_track_run: the widest a hinge's two anchors stood apart, m */
    double *t_s;               /* with an error-controlled step (run.tolerance_m): sample i's time (the
                                  end of step i); NULL: i * dt_s */
    long steps, rejected, ode_steps; /* fs_track_run: steps accepted, rejected, and ODE steps in all */
    double sinkage_end_m;      /* fs_track_run on a soil: how deep the feet reach below its undisturbed
                                  surface at the end (fs_sim_soil_sinkage: the deepest node carried), m;
                                  NAN without a soil */
} fs_track;

/* Runs sc built with opts (NULL: the whole foot on its ground) for duration_s at sc's step (or its
 * error-controlled step) and samples every step. All memory is taken before the first step. FS_NUMERICAL when a state
 * check fails (fs_check.h; with opts->record_drift only when it blows up; err says when); out is
 * then freed. */
fs_status fs_track_run(const fs_scenario *sc, const fs_sim_options *opts, double duration_s, fs_track *out,
                       fs_error *err);

/* The reference model's path as a track: n samples dt_s apart. */
fs_status fs_track_reference(const fs_design_def *d, const fs_foot_geom *g, const fs_reference_def *def, double dt_s,
                             int n, fs_track *out, fs_error *err);

typedef struct fs_track_error {
    double max_m, rms_m;       /* ankle position: largest and RMS distance */
    double max_rad, rms_rad;   /* hinge angles: largest and RMS difference over all angles; NAN without */
    int compared;              /* samples compared */
    double end_dz_m;           /* the ankle's height less the reference's at the last sample compared, m */
} fs_track_error;

/* Compares run with ref at run's sample times, which must fall on ref's (run.dt_s a whole
 * multiple of ref.dt_s), up to the shorter of the two; a run with sample times (t_s) at those
 * times, ref interpolated linearly between its samples. */
fs_status fs_track_compare(const fs_track *run, const fs_track *ref, fs_track_error *out, fs_error *err);

void fs_track_free(fs_track *t);

#endif
