/* fs_sim.h: a foot built in ODE from its geometry, over a ground, and stepped.
 *
 * The geometry (fs_foot_geom) and the scenario are the constant model; everything that changes
 * during a run lives in the ODE world that fs_sim_new creates. fs_sim is opaque: no ODE type
 * appears in this header (or any under include/footsim/); its state is read through functions
 * (time, bodies, contacts, springs, energy, checks), which copy nothing the step keeps. All memory is taken at build
 * time: fs_sim_step allocates nothing (ODE's own step works in its preallocated arena).
 *
 * One step is a fixed sequence of stages: external loads, springs, collision (foot against
 * ground only), the ODE step, and the state checks of fs_check.h (finite, speed, loop closure,
 * energy). fs_sim_options.profile times them. With run.impact_substeps N > 1, a step near a
 * touchdown runs the sequence N times at h/N (the contacts', stops' and springs' softness set for
 * h/N, the checks after each); the caller still sees one step of h.
 *
 * Re-entrant: everything a simulation uses lives in its fs_sim (contact scratch, profile, names,
 * its state of ODE's random generator), so simulations may be built and stepped interleaved in one
 * process and give the bits each gives alone, with either stepper. ODE's handlers and its random
 * generator are process-wide: each step points the handlers' context at its own sim (fs_ode.h) and
 * sets the generator to the sim's own state before the ODE step, saving it after. Workers still
 * run as processes (fs_pool.h): ODE ends the process after its error handler, and a generator
 * shared between threads would be raced. test_engine_determinism steps five sims (two with
 * QuickStep) interleaved against each alone. */
#ifndef FS_SIM_H
#define FS_SIM_H

#include "footsim/base/fs_clock.h"
#include "footsim/sim/fs_check.h"
#include "footsim/model/fs_scenario.h"
#include "footsim/sim/fs_ode.h"
#include "footsim/sim/fs_scene.h"

enum { FS_MAX_SHAPES = FS_MAX_SPHERES + FS_MAX_BOXES };
enum { FS_MAX_CONTACTS = FS_MAX_SHAPE_CONTACTS, FS_MAX_STEP_CONTACTS = FS_MAX_SHAPES * 64 };

/* The spring-dampers' implementation ([run] springs): an ODE row made soft, stable at any step, or
 * the force from the state, added each step (src/sim/sim_spring.h). */
typedef enum fs_spring_impl { FS_SPRING_IMPLICIT = 0, FS_SPRING_EXPLICIT = 1 } fs_spring_impl;

typedef struct fs_sim_options {
    int with_ground;        /* 0: no ground (the stiffness probes) */
    int hold_rear_foot;     /* 1: heel and talus kinematic, fixed where they are */
    int pinned_chain;       /* c (1-5): chain c alone, heel and toe pinned to the world, a fifth of the
                               load and no ground (fs_design_pinned_chain); 0: the whole foot */
    int record_drift;       /* 1: a drifting state is recorded, not stopped at (fs_check.h) */
    struct fs_profile *profile; /* where this sim's step time goes (added to), or NULL: not timed */
    int keep_robot_body;    /* 1: a rigid, free robot stays a body of its own on a fixed joint instead
                               of being merged into the ankle body (the export shows it apart) */
    int chain_plane_friction; /* 1 (biomimetic foot): each sphere's contacts grip along its chain's
                               plane (made tangent to the surface) and slide freely across it (mu
                               in-plane, 0 across: ODE's dContactMu2 and fdir1), the heel's along
                               the foot: the contacts the pitch-stiffness model assumes
                               (fs_pitch_stiffness_measure) */
} fs_sim_options;

/* A foot's first touch of the ground, read at the collision that found it (in the substep that
 * found it, when a step is divided): the time and the ankle taken back along their motion by the
 * time the deepest contact's point took to sink that deep at its speed then, at most the step.
 * A step finds a touch between its start and one step later; this finds it at the instant the
 * lowest point met the surface, to first order, so what is read from a touchdown does not move
 * with the step. */
typedef struct fs_touch {
    int touched;
    double time_s;
    double ankle_m[3];
    double found_s; /* the start of the (sub)step whose collision found it: its contact force acts from then */
} fs_touch;

/* The steps a sim has taken: with run.tolerance_m > 0 the error-controlled step's (fs_sim_step), a
 * step being a pair of half steps of ODE's whose size is step_max_s / 2^level (with the embedded
 * estimate one ODE step of that size, or of the dampers' bound when less: counted at its level);
 * else the fixed steps. */
enum { FS_STEP_LEVELS = 48 };
typedef struct fs_step_stats {
    long taken;            /* steps accepted */
    long rejected;         /* steps tried, found beyond the tolerance, and taken again smaller */
    long missed;           /* steps kept at the least step although beyond the tolerance */
    long ode_steps;        /* ODE steps, the rejected ones and the comparisons' included */
    long cruised;          /* steps taken singly at the dampers' bound, not doubled */
    double least_s, largest_s; /* of the steps accepted (a step cut short to end on a horizon included) */
    long at_level[FS_STEP_LEVELS]; /* steps accepted at each level (one cut short: at the level it was cut from) */
    long at_bound;         /* of those, the embedded estimate's steps cut to the dampers' bound ... */
    double bound_s;        /* ... which was this long (the last such step's) */
} fs_step_stats;

/* The simulation: opaque. Its layout (the ODE world, bodies, joints, the step's scratch) is the sim
 * layer's own (src/sim/sim_internal.h), so this header needs no ODE header and a program built on
 * it does not depend on the struct's size. Made by fs_sim_new (or fs_sim_create from a model,
 * fs_model.h) and freed by fs_sim_free; read through the functions below. */
typedef struct fs_sim fs_sim;

/* Builds sc's foot in a new ODE world into a new simulation (*out; NULL on failure, when nothing is
 * left behind). opts may be NULL for a normal run. sc must outlive the simulation. */
fs_status fs_sim_new(const fs_scenario *sc, const fs_sim_options *opts, fs_sim **out, fs_error *err);
/* Frees a simulation (NULL: nothing), the ODE world and everything it made. */
void fs_sim_free(fs_sim *sim);

/* Advances by the scenario's step, whole or, near a touchdown with run.impact_substeps N > 1, in N
 * equal substeps (from a step in which a foot shape without contact could reach the ground within
 * the step and run.impact_window_s, or first touches it, until that window after it); FS_NUMERICAL
 * (with the body or hinge and the time named) if a check of fs_check.h fails, or with ODE's message
 * if an ODE error interrupted the step (then, and for every later call, the sim may only be
 * destroyed: fs_ode.h). */
fs_status fs_sim_step(fs_sim *sim, fs_error *err);

/* With run.tolerance_m > 0, fs_sim_step takes one error-controlled step instead: a step of h
 * (step_max_s / 2^level) tried once whole and once as two half steps from the same state; the two
 * results' difference (each body's centre and its rotation times its reach, and the step times the
 * same for their velocities) estimates the half steps' local error. Within the tolerance the half
 * steps are kept; beyond it the whole state is put back (bodies, contacts and their forces, touches,
 * the state checks' reference, ODE's random state) and the step tried at half the size. A step
 * grows (doubles) after 4 accepted in a row whose error was below a quarter of the tolerance, and
 * never ends past the horizon (fs_sim_set_horizon). A step whose state checks fail is rejected
 * like one beyond the tolerance, and fails only at the least step. An ODE step is at most c / k of
 * every spring and damped hinge, and of the contacts while a foot touches: beyond it ODE's implicit
 * damper damps by k h instead of c, so a rocking foot would come to rest sooner the larger the step
 * (fs_spring_soft; docs/bench.md). Where that bound, not the error, sets the step, a doubled step
 * accepted at once is followed by 8 single ODE steps of the bound, each put back and doubled if the
 * set of shapes touching the ground changed. The time advanced is
 * sim->step_taken_s; the ground force read after it is the mean over its two half steps.
 * With run.error_estimate = embedded, a step is one ODE step of step_max_s / 2^level (cut to the
 * dampers' bound), its error h / 2 times each body's change of velocity over the step and that
 * change's difference from the last step's (its centre's, and its angular velocity's times its
 * reach): rejected and retried smaller, grown, bounded and ended on the horizon as above, without
 * doubling or cruising (sim_adapt.c). */
void fs_sim_set_horizon(fs_sim *sim, double t_s);
/* The median of the accepted steps, s: the level at which half of them had been taken (a step cut
 * short at a horizon counted at its level, one cut to the dampers' bound as the bound's own); the
 * fixed step with fixed steps; 0 before any. */
double fs_sim_median_step_s(const fs_sim *sim);

/* The load's force now (it rises over ramp_s), N; it acts along down. */
double fs_sim_load_now_N(const fs_sim *sim);
/* Where the time of the steps goes. The stages of fs_sim_step, in order, and what their code is:
 * ODE's (collision: dSpaceCollide2 over the ground space with the dCollide calls of footsim's
 * callback; the ODE step: dWorldStep or dWorldQuickStep and emptying the contact group) or
 * footsim's own (the rest, and FS_STAGE_CALLER: the time between one step's end and the next
 * one's start, which is the caller's measurements, logging and rest test). */
typedef enum fs_stage {
    FS_STAGE_LOADS,     /* the load ramped and applied */
    FS_STAGE_SPRINGS,   /* spring-dampers prepared for the step */
    FS_STAGE_COLLISION, /* foot shapes against the ground: ODE's tests, or footsim's own on a heightfield */
    FS_STAGE_CONTACTS,  /* merging and selecting contacts, contact joints made */
    FS_STAGE_ODE,       /* ODE: the step */
    FS_STAGE_CHECK,     /* the state checks (fs_check.h) */
    FS_STAGE_CALLER,    /* between steps: the caller's own work */
    FS_NSTAGES
} fs_stage;

typedef struct fs_profile {
    double stage_s[FS_NSTAGES]; /* wall time in each stage, summed over every profiled step, s */
    long laps[FS_NSTAGES];      /* how many timed intervals each sum has (each holds one clock read;
                                   a step in substeps times each substep's stages) */
    long steps;                 /* calls of fs_sim_step */
} fs_profile;

/* Profiling is per simulation and off by default: a sim built with fs_sim_options.profile set
 * adds the time of each of its steps' stages to that fs_profile (CLOCK_MONOTONIC; the caller
 * zeroes it first). Off, each stage costs one untaken branch. Timing never changes a result. */


/* The load's point (the ankle) in world coordinates now. */
void fs_sim_ankle(const fs_sim *sim, double p[3]);

/* Energy now: kinetic, gravitational (relative to z = 0) and stored in the springs, J. */
double fs_sim_energy(const fs_sim *sim, double *kinetic, double *potential, double *elastic);

/* A bound on the fastest point of any body: COM speed plus angular speed times its reach, m/s. */
double fs_sim_max_speed(const fs_sim *sim);

/* The same for body i (0 .. nbodies - 1; nbodies: the robot, its own body or merged, its reach
 * com_height_m), m/s. */
double fs_sim_body_speed(const fs_sim *sim, int i);

/* The ground's total force on the foot during the last step (the mean over its substeps), N. */
void fs_sim_ground_force(const fs_sim *sim, double force[3]);

/* Fills scene with the state now (shapes, links, springs with their forces, contacts with their
 * forces, the load). */
void fs_sim_scene(const fs_sim *sim, fs_scene *scene);

/* The constraint rows the solver handles in a step, by kind: what a step's cost grows with (a
 * dense direct solver's time grows with the cube of the total). Hinges and sliders 5, a fixed
 * joint 6, a ball 3, an implicit spring's DBall row 1 (a cable's one-sided row 1 while taut), a
 * contact 3 with friction (1 without), for the contacts of the last step; a hinge's stop 1 while it
 * is active (a biped's leg joints' spring-dampers are stops with lo = hi: always active). */
typedef struct fs_rows {
    int hinge, fixed, slider, ball, spring, contact, other; /* other: joints of any other kind, one each */
    int stop;              /* hinge stops (limits) active now */
    int total;
    int contacts;          /* the contact points the contact rows are for */
} fs_rows;
void fs_sim_constraint_rows(const fs_sim *sim, fs_rows *rows);

/* Body i (0 .. nbodies - 1; nbodies: the robot's body, or the ankle body a merged robot is part of) now: its position, m, and rotation R (row-major,
 * R[3 * r + c]: its axes are the columns, world = R * body), either of them NULL if not wanted. */
void fs_sim_body_pose(const fs_sim *sim, int i, double p[3], double R[9]);
/* Body i's linear velocity, m/s, and angular velocity, rad/s (world frame), either NULL if not wanted. */
void fs_sim_body_velocity(const fs_sim *sim, int i, double v[3], double w[3]);
/* Adds a torque (world frame, N m) to body i for the coming step only, each of its substeps too (a
 * driver's before_step). */
void fs_sim_body_add_torque(fs_sim *sim, int i, const double torque_N_m[3]);

/* The robot body's lean from upright (its z axis against world z), rad; 0 without a robot. A
 * merged robot (fs_sim.robot_merged) leans with the ankle body it is part of; a biped's lean is
 * its pelvis's. */
double fs_sim_robot_tilt(const fs_sim *sim);

/* The robot's centre of mass and its velocity now (a merged robot's from the ankle body's
 * motion; a biped's pelvis's); without a robot, the ankle body's. Either may be NULL. */
void fs_sim_robot_com(const fs_sim *sim, double p[3], double v[3]);

/* Per foot (0 .. geom->nfeet - 1; a biped's 0 right, 1 left): its ankle in world coordinates now,
 * its contact points with the ground in the last step, and the ground's force on it then, N. */
void fs_sim_foot_ankle(const fs_sim *sim, int foot, double p[3]);
int fs_sim_foot_contacts(const fs_sim *sim, int foot);
void fs_sim_foot_force(const fs_sim *sim, int foot, double force[3]);

/* The foot's first touch of the ground (fs_touch), or NULL when it has not touched it yet. */
const fs_touch *fs_sim_first_touch(const fs_sim *sim, int foot);

/* How far the foot's contact shapes reach below the terrain surface now, m (negative: above). */
double fs_sim_penetration(const fs_sim *sim);

/* Joint angle of hinge i from the neutral pose, rad (positive: distal link turned up). */
double fs_sim_hinge_angle(const fs_sim *sim, int i);

/* ---- reading the state: functions, not copies; each reads the sim as the last step left it ---- */

/* The scenario the simulation was built from, and the foot's geometry it simulates (the scenario's,
 * a biped's two feet and legs, or a pinned chain's own). */
const fs_scenario *fs_sim_scenario(const fs_sim *sim);
const fs_foot_geom *fs_sim_geom(const fs_sim *sim);
/* Simulated time, s; the scenario's step, s; the time the last fs_sim_step advanced by, s; 1 once
 * an ODE error killed the simulation (it may then only be freed). */
double fs_sim_time(const fs_sim *sim);
double fs_sim_step_size(const fs_sim *sim);
double fs_sim_step_taken(const fs_sim *sim);
int fs_sim_dead(const fs_sim *sim);
/* 1 with the error-controlled step (run.tolerance_m > 0), whose steps vary in length. */
int fs_sim_adaptive(const fs_sim *sim);
/* The unit direction of the load and gravity (world frame). */
void fs_sim_down(const fs_sim *sim, double down[3]);
/* The bodies fs_sim_body_pose and fs_sim_body_velocity take: the foot's, then the robot's when it
 * has a body of its own or is merged into the ankle body. */
int fs_sim_body_count(const fs_sim *sim);
/* The ground's contact points in the last step; the first max of them, each a point, m (pos: max x
 * 3), and the force on the foot from the ground over the last step, N (force: max x 3), either may
 * be NULL; returns how many were written. */
int fs_sim_contact_count(const fs_sim *sim);
int fs_sim_contacts(const fs_sim *sim, double *pos, double *force, int max);
/* The contacts of every step so far, and the collision tests made for them. */
void fs_sim_contact_totals(const fs_sim *sim, long *contacts, long *collision_tests);
/* The last step's contacts before merging and capping, the foot shapes that touched, and the most
 * one shape found (what each shape really needs; bench speed). Any may be NULL. */
void fs_sim_contact_needs(const fs_sim *sim, int *found, int *shapes_touching, int *most_found);
/* Spring-damper i of the foot's geometry (0 .. fs_sim_geom(sim)->nsprings - 1) now: length, rate,
 * force (tension positive) and stored energy. */
typedef struct fs_spring_state {
    double length_m, rate_m_per_s, force_N, energy_J;
} fs_spring_state;
fs_spring_state fs_sim_spring_state(const fs_sim *sim, int i);
/* The state checks' reference and worst values so far (fs_check.h). */
const fs_check *fs_sim_checks(const fs_sim *sim);
/* The steps taken so far (fs_step_stats). */
const fs_step_stats *fs_sim_step_stats(const fs_sim *sim);
/* The warnings (fs_warn, fs_error.h: ODE's messages among them) given while this simulation was
 * built and stepped; the program's handler had their text. */
long fs_sim_warnings(const fs_sim *sim);


#endif
