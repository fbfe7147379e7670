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

/* On a soil ([soil] in the terrain) the machine's stance does more: having lowered the carriage
 * press_m past its start, it goes on down while the ground's vertical force on the foot is below
 * the robot's weight (body and foot), so that the soil (or, through it, the bedrock) carries the
 * load; it holds where that is reached and comes back up to its path over the swing. It goes down
 * at twice the layer's depth over the stance's time, fast enough to reach the bedrock by
 * mid-stance, where the step is judged. Each step then records what the soil did
 * (fs_walk_step). It presses past press_m only while the foot lies over the soil (fs_sim_soil_over: a
 * soil laid over a section of the path, [soil] x_min_m..x_max_m, leaves the steps beyond it the rigid
 * ground's), and records every step. Without a soil nothing changes. */
enum { FS_WALK_MAX_STEPS = 1000 }; /* [walk] steps' largest */

typedef struct fs_walk_step {
    double sinkage_m;     /* at the stance's end: the foot's lowest point below the undisturbed soil */
    double slip_m;        /* the ankle's horizontal travel over the stance */
    double soil_slip_m;   /* at the stance's end: the slip (shear displacement) accumulated on the soil's nodes
                             under the foot, their mean by area (fs_sim_soil_slip; earlier steps' too) */
    double soil_work_J;   /* the energy the soil took over the step (fs_soil_grid.work_J's rise) */
    double extra_press_m; /* how far past press_m the drive pressed until the soil carried the load */
    double load_N;        /* the ground's vertical force at the stance's end */
    int on_soil;          /* 1: one of the foot's soil shapes lay over the soil at some time in the stance
                             (fs_sim_soil_over); 0: the stance was the rigid ground's (beyond a section) */
} fs_walk_step;

typedef struct fs_walk_result {
    int steps_completed, falls;
    int soil;                     /* 1: on a soil: step[] holds each step's record */
    int nsteps;                   /* steps recorded in step[] */
    fs_walk_step step[FS_WALK_MAX_STEPS];
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
