/* sim_internal.h: what the sim layer's files share and nothing above it sees.
 *
 * The step (sim_step.c) runs its stages in order: loads, springs, collision and contacts
 * (sim_contacts.c), the ODE step, the state checks (sim_check.c). The checks read the state only
 * through the measures (sim_measure.c), which read ODE and nothing of the step: so the step calls
 * the checks and the checks never call back into the step or the build (no circle). */
#ifndef FS_SIM_INTERNAL_H
#define FS_SIM_INTERNAL_H

#include "footsim/sim/fs_sim.h"

/* Contacts of one foot shape with all terrain geoms in one step: the sim's own scratch, so two
 * simulations can step in one process. */
typedef struct fs_contact_scratch {
    fs_sim *sim;
    int n;
    dContactGeom c[FS_MAX_CONTACTS];
    /* each contact joint of the step: its shape (-1 foot against foot) and normal, and, kept for
       the next step's friction bounds, the last step's contacts with their normal forces */
    short shape[FS_MAX_STEP_CONTACTS];
    double normal[FS_MAX_STEP_CONTACTS][3];
    int prev_n;
    short prev_shape[FS_MAX_STEP_CONTACTS];
    double prev_pos[FS_MAX_STEP_CONTACTS][3], prev_N[FS_MAX_STEP_CONTACTS];
    int share[FS_MAX_STEP_CONTACTS];   /* how many of this step's contacts took each one's force */
    int match[FS_MAX_CONTACTS];        /* this shape's contacts: the last step's contact each continues, or -1 */
} gathered;

/* A plane's or steps' heights for fs_sim_scene: memory taken at build, sampled when a scene is
 * first asked for (sim_scene.c), so a run that draws nothing never samples them. */
typedef struct fs_ground_grid {
    int sampled;
    double z[];
} fs_ground_grid;

/* The foot's bodies and the robot (its own body or merged into the ankle body): what the checks
 * and speeds go over, the robot last. */
static inline int fs_sim_nbodies(const fs_sim *sim) { return sim->geom->nbodies + (sim->robot || sim->robot_merged); }

/* The body the robot moves with: its own, or the ankle body it is merged into; NULL without one. */
static inline dBodyID fs_sim_robot_body(const fs_sim *sim)
{
    if (sim->geom->biped)
        return sim->body[sim->geom->pelvis_body];
    return sim->robot_merged ? sim->body[sim->geom->ankle_body] : sim->robot;
}

/* Keeps the last step's contacts and the normal force ODE gave each (its feedback), for the next
 * step's friction bounds; call before the contacts of a step are made (sim_contacts.c). */
void fs_sim_remember_contacts(fs_sim *sim);

/* A spring-damper of sim's (fs_spring_init) as its scenario's [run] springs and damping_correction
 * make it. */
void fs_sim_spring_init(const fs_sim *sim, fs_spring *s, dBodyID body1, dBodyID body2, const double p1[3],
                        const double p2[3], double k, double c, double rest);

/* After a step's (or substep's) collision at the state before it moves, with h the step it takes:
 * each foot's first contact, if this is it, recorded in sim->touch (fs_touch). */
void fs_sim_note_touch(fs_sim *sim, double h);

/* Sets the contacts' and the hinge stops' softness (ERP, CFM from their k and c) for a step of h
 * (sim_soften.c); nothing when they are set for h already. The springs set theirs as they are
 * prepared (fs_spring_prepare). */
void fs_sim_set_step(fs_sim *sim, double h);
/* The contact template's softness for a step of h (the sole's and terrain's k and c in series), and a
 * hinge stop's; whether a hinge has an angular spring-damper (sim_soften.c). */
void fs_sim_soften_contacts(fs_sim *sim, double h);
void fs_sim_soften_stop(const fs_sim *sim, dJointID j, double k, double c, double h);
int fs_hinge_has_spring(const fs_hinge_geom *h);

/* After one substep of n: adds its ground forces, over n, to step_force (sim_measure.c). */
void fs_sim_add_step_force(fs_sim *sim, int substep, int n);

/* Adds the time since the last timed stage ended to stage, when sim is profiled (sim_profile.c). */
void fs_sim_lap(fs_sim *sim, fs_stage stage);

/* Body i's ODE body: 0 .. nbodies - 1 the foot's, nbodies the robot (sim_measure.c). */
dBodyID fs_sim_body_id(const fs_sim *sim, int i);

/* Collision: each foot shape against the terrain (and, with run.collide = all, foot against
 * foot); every contact becomes a contact joint of this step (sim_contacts.c). */
void fs_sim_collide(fs_sim *sim);

/* One ODE step of h as the step's stages (loads, springs, collision and contacts, ODE, checks):
 * a whole step, a substep or a half step (sim_step.c). */
fs_status fs_sim_step_by(fs_sim *sim, double h, fs_error *err);

/* The driver's torques for this step added again, for a later ODE step within it (sim_step.c). */
void fs_sim_add_torques_again(fs_sim *sim);

/* The error-controlled step (run.tolerance_m > 0; sim_adapt.c): one accepted step, its time in
 * sim->step_taken_s. */
fs_status fs_sim_adaptive_step(fs_sim *sim, fs_error *err);

/* Records an accepted step of h taken at level (-1: the embedded estimate's step cut to the dampers'
 * bound) (sim->stats; sim_adapt.c), and sets step_taken_s. */
void fs_sim_count_step(fs_sim *sim, double h, int level);

/* The state a step changes, saved (into sim->saved) and put back bit for bit: every body's position,
 * quaternion and velocities, and footsim's history (the last step's contacts and their forces,
 * touches, the substep window, the checks' reference, ODE's random state, the time, the counters)
 * (sim_adapt.c; only with sim->saved). */
void fs_sim_save_state(fs_sim *sim);
void fs_sim_restore_state(fs_sim *sim);

/* The error-controlled step's memory, taken at build when run.tolerance_m > 0 (sim_adapt.c); its
 * release. */
fs_status fs_sim_adapt_init(fs_sim *sim, fs_error *err);
void fs_sim_adapt_free(fs_sim *sim);

#endif
