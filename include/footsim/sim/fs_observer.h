/* fs_observer.h: what watches a simulation while fs_drive (fs_drive.h) steps it: a run, a landing
 * trial, the walking machine.
 *
 * fn, when set, is called with the state at t = 0, every interval_s of simulated time (rounded to
 * whole steps, at least one) and at the end; a status other than FS_OK stops the experiment with
 * that status (fn fills err). The renderer draws frames this way. profile, when set, receives the
 * time of every step's stages (fs_sim.h: fs_profile; the caller zeroes it). An observer never
 * changes a result: the same experiment with and without one gives the same bits. */
#ifndef FS_OBSERVER_H
#define FS_OBSERVER_H

#include "footsim/sim/fs_sim.h"

typedef struct fs_run_observer {
    double interval_s;
    fs_status (*fn)(void *user, const fs_sim *sim, fs_error *err);
    void *user;
    fs_profile *profile;
} fs_run_observer;

/* The options an experiment builds its sim with under obs (NULL: none): ground on, obs's profile. */
fs_sim_options fs_observer_sim_options(const fs_run_observer *obs);

#endif
