/* fs_walk.h: the walking machine of the paper's Fig. 16.
 *
 * A carriage, moved by one actuator along a stance-and-swing trajectory, carries the robot body
 * ([robot]) on a vertical slider with a suspension spring-damper; the body carries the foot at
 * its ankle (rigidly, or through the Achilles joint). The slider blocks side motion and every
 * rotation of the body, so only its up-and-down motion is free. In stance the carriage stands
 * still and presses the foot down by press_m past first contact; in swing it lifts the foot by
 * lift_m and carries it forward by step_length_m. A step succeeds when, at mid-stance, the foot
 * touches the ground and the ankle body has not tilted past fall_tilt_deg; otherwise it is a
 * fall. The terrain (e.g. terrains/partly_rough.ini) decides where the ground is rough. */
#ifndef FS_WALK_H
#define FS_WALK_H

#include "footsim/sim/fs_observer.h"
#include "footsim/model/fs_scenario.h"

typedef struct fs_walk_result {
    int steps_completed, falls;
    double rough_contacts_mean;   /* foot contact points at mid-stance on the rough section */
    int rough_steps;              /* steps whose mid-stance was on the rough section */
    double flat_contacts_mean;    /* the same off it */
    double peak_force_N;          /* peak vertical ground force */
    double peak_tilt_deg;         /* the ankle body's largest tilt in stance */
    double end_time_s;
} fs_walk_result;

/* Runs the walking machine of a walk scenario ([scenario] kind = walk, a [robot] and a [walk]).
 * obs (fs_observer.h) may be NULL. */
fs_status fs_walk_run(const fs_scenario *sc, const fs_run_observer *obs, fs_walk_result *out, fs_error *err);

#endif
