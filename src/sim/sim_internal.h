/* sim_internal.h: what the sim layer's files share and nothing above it sees.
 *
 * The step (sim_step.c) runs its stages in order: loads, springs, collision and contacts
 * (sim_contacts.c), the ODE step, the state checks (sim_check.c). The checks read the state only
 * through the measures (sim_measure.c), which read ODE and nothing of the step: so the step calls
 * the checks and the checks never call back into the step or the build (no circle). */
#ifndef FS_SIM_INTERNAL_H
#define FS_SIM_INTERNAL_H

#include "footsim/sim/fs_sim.h"
#include "sim_spring.h"

#include <ode/ode.h>

/* The simulation (opaque in fs_sim.h): the ODE world and everything the step keeps. */
typedef struct fs_sim {
    const fs_scenario *sc;
    const fs_foot_geom *geom; /* the model's (fs_model.geom: the scenario's, a biped's or a pinned chain's) */
    fs_foot_geom own_geom; /* unused since the model holds a pinned chain's or a biped's geometry */
    dWorldID world;
    dSpaceID space;        /* the foot's shapes */
    dSpaceID ground;       /* the terrain's shapes (plane, boxes or heightfield); NULL without ground */
    struct fs_ground *heightfield; /* the heightfield tiles' data, or NULL */
    double R0[9], t0[3];   /* the start pose: world = R0 * design + t0 */
    dJointGroupID contact_group;
    dBodyID body[FS_MAX_BODIES];
    dJointID hinge[FS_MAX_HINGES];
    dJointID pin[2];       /* a pinned chain's hinges to the world */
    dGeomID shape[FS_MAX_SHAPES];
    int shape_foot[FS_MAX_SHAPES]; /* which foot each shape is on (a biped's: 0 right, 1 left) */
    int nshapes;
    fs_spring spring[FS_MAX_SPRINGS];
    dBodyID robot;         /* the passive body on the ankle, or NULL (none, or merged) */
    dJointID robot_joint;  /* fixed, or the ankle hinge */
    int robot_merged;      /* 1: a rigid, free robot is part of the ankle body (no body, no joint) */
    dVector3 robot_local;  /* a merged robot's centre of mass on the ankle body */
    fs_vec3 com[FS_MAX_BODIES]; /* each ODE body's centre in the design frame: the geometry's, or
                                   the ankle body's and a merged robot's together */
    fs_spring achilles;    /* with robot.joint = achilles */
    fs_spring *suspension; /* a carriage's (fs_carriage.h), prepared first at each step and substep, or NULL */
    /* a body driven from outside the foot (the walking machine's carriage, fs_carriage.h), or all NULL:
       follow sets it for the ODE step of h about to be taken (at the start of each), exchange saves
       its state into `state` or puts it back (with the rest of the state: fs_sim_save_state) */
    struct {
        void (*follow)(void *user, double h);
        void (*exchange)(void *user, double state[6], int saving);
        void *user;
    } driven;
    int has_achilles;
    double reach[FS_MAX_BODIES]; /* farthest point of each body (joint, anchor, shape) from its COM, m */
    dVector3 ankle_local;  /* the load's point on the ankle body */
    dVector3 foot_ankle_local[FS_MAX_FEET]; /* each foot's ankle on its ankle body (fs_foot_geom.foot) */
    dVector3 down;         /* unit direction of the load and gravity */
    dContact contact_template;  /* every contact joint's surface, soft for step_now_s */
    double contact_k_N_per_m, contact_c_Ns_per_m; /* the sole and terrain in series: what that softness is made of */
    double step_now_s;     /* the step the contacts' and the stops' softness is set for: the scenario's, or
                              a substep's (fs_sim_set_step) */
    int substeps_now;      /* the substeps the last step was taken in (1: whole; run.impact_substeps) */
    double impact_until_s; /* steps are taken in substeps until time_s reaches this */
    unsigned char touched_before[FS_MAX_SHAPES]; /* with substeps: each shape had contact in the step before */
    double step_force[FS_MAX_FEET + 1][3]; /* after a step in substeps: the ground's mean force over them on
                                              every foot (0) and on each (1 + foot), N */
    double torque_again[FS_MAX_BODIES + 1][3]; /* the torques added for the coming step, per body (the
                                                 robot's last): added again in each of its substeps */
    int torque_added;      /* any added since the last step */
    double match_m[FS_MAX_SHAPES]; /* how far a shape's contact may move in a step and still
                                           continue the last step's (its friction bound) */
    int chain_plane_friction;          /* fs_sim_options.chain_plane_friction */
    double grip_dir[FS_MAX_SPHERES][3]; /* with it: each sphere's direction of grip, horizontal, world */
    double time_s;
    double load_N;         /* the load's weight; fs_sim_step ramps it in */
    int contacts_now;      /* contact points in the last step */
    dJointFeedback *feedback; /* FS_MAX_STEP_CONTACTS, filled by the last step */
    double contact_pos[FS_MAX_STEP_CONTACTS][3];
    double contact_depth_m[FS_MAX_STEP_CONTACTS];
    fs_touch touch[FS_MAX_FEET]; /* each foot's first touch of the ground (fs_sim_first_touch) */
    struct fs_ground_grid *ground_grid; /* planes and steps sampled for fs_sim_scene on its first
                                           call (heightfields use theirs), or NULL */
    fs_scene_ground scene_ground;
    long contacts_total, collision_tests;
    /* the last step's contacts before merging and capping (ODE's and the box's lattice vertices),
       how many foot shapes touched, and the most one shape found: what each shape really needs */
    int contacts_found_now, shapes_touching_now, most_found_now;
    fs_check check;        /* the state checks' reference and worst values (fs_check.h) */
    struct fs_contact_scratch *scratch; /* one shape's contacts while a step gathers them */
    unsigned long rand_seed; /* this sim's state of ODE's random generator, which QuickStep draws on */
    char ode_context[FS_PATH_MAX]; /* what ODE's complaints name while this sim steps: its scenario */
    int ode_failed;        /* an ODE error interrupted a step: the sim may only be destroyed (fs_ode.h) */
    struct fs_profile *profile; /* where the step's time goes, or NULL (fs_sim_options.profile) */
    double profile_mark;   /* when the last timed stage ended, s (0: no step yet) */
    /* run.tolerance_m > 0: the error-controlled step (sim_adapt.c) */
    struct fs_sim_saved *saved; /* the state before the step being tried; NULL with fixed steps */
    int level;             /* the next step tried is step_max_s / 2^level */
    int level_held;        /* steps accepted in a row since the level last changed */
    double horizon_s;      /* the next step ends at or before this time, s (fs_sim_set_horizon); 0: none */
    double step_taken_s;   /* the time the last fs_sim_step advanced by, s */
    double step_error_m;   /* the last accepted step's error estimate, m (0 with fixed steps) */
    double damped_step_s;  /* the least c / k of the springs and hinge springs: the ODE step is at most this */
    double damped_contact_s; /* c / k of the contacts: and at most this while a foot touches the ground */
    int cruise_left;       /* steps still to take singly at the dampers' bound before the next doubled one */
    fs_step_stats stats;
    struct fs_sim_soil *soil; /* the terrain's soil layer (fs_sim_soil.h), or NULL: rigid ground only */
    const struct fs_model *model; /* what the sim was made from (fs_model.h) */
    struct fs_model *own_model; /* that model when the sim compiled it itself (fs_sim_build), else NULL */
    long warnings;         /* the warnings (fs_warn) given while this sim was built or stepped */
} fs_sim;

/* The terrain t as the model's ground shapes (planes, blocks, or its lattice: fs_model.h; sim_model.c). */
fs_status fs_model_ground(struct fs_model *m, const fs_terrain *t, fs_error *err);

/* Builds sc's foot in a new ODE world in the caller's sim (fs_sim_new allocates one and calls
 * this; the tests build theirs on the stack). opts may be NULL for a normal run. A failed build
 * leaves nothing behind; destroying it again is harmless. */
fs_status fs_sim_build(fs_sim *sim, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err);
void fs_sim_destroy(fs_sim *sim);

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
 * quaternion and velocities (a driven body's too: fs_sim.driven), and footsim's history (the last step's contacts and their forces,
 * touches, the substep window, the checks' reference, ODE's random state, the time, the counters)
 * (sim_adapt.c; only with sim->saved). */
void fs_sim_save_state(fs_sim *sim);
void fs_sim_restore_state(fs_sim *sim);

/* The error-controlled step's memory, taken at build when run.tolerance_m > 0 (sim_adapt.c); its
 * release. */
fs_status fs_sim_adapt_init(fs_sim *sim, fs_error *err);
void fs_sim_adapt_free(fs_sim *sim);

#endif
