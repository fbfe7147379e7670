/* fs_model.h: a simulation's model, apart from its state (MuJoCo's split of mjModel and mjData).
 *
 * fs_model_compile decides, from a compiled scenario and the simulation's options, everything a
 * simulation is built of and nothing that changes as it runs: the bodies (mass, inertia about the
 * centre of mass in the body frame, the centre's place in the design frame and at the start pose),
 * the contact shapes (spheres and sole boxes on their bodies), the hinges and a pinned chain's
 * pins, the spring-dampers with their laws, the robot (its own body, merged into the ankle body, or
 * a biped's pelvis; its joint, mount and Achilles spring), the contact parameters (friction,
 * restitution, the sole's and terrain's stiffness and damping in series), the start pose (rotation
 * R0 and lift t0 over the terrain), gravity and the world's solver settings. The model holds no ODE
 * type: fs_sim_create makes the ODE world from it alone, so what the dump (`footsim model`), the
 * MJCF export and a program read of a model is what is simulated, bit for bit (the masses are
 * ODE's own arithmetic: dMassAdd and dMassTranslate for a robot merged into the ankle body).
 *
 * Immutable once compiled; many simulations may be created from one model (each its own state).
 * The model keeps a pointer to the scenario it was compiled from (its terrain is the ground), which
 * must outlive it; a simulation keeps one to its model, which must outlive the simulation. */
#ifndef FS_MODEL_H
#define FS_MODEL_H

#include "footsim/model/fs_scenario.h"
#include "footsim/sim/fs_sim.h"

/* The foot's bodies, then the robot's own body when it has one. */
enum { FS_MODEL_MAX_BODIES = FS_MAX_BODIES + 1 };

typedef struct fs_model_body {
    const char *name;           /* the geometry's, or "robot" */
    double mass_kg;
    double centre_m[3];         /* the mass's centre from the body's origin, body frame: 0 (ODE keeps it there) */
    double inertia_kg_m2[9];    /* about the centre, body frame (whose axes are the design's), row-major; with
                                   run.min_inertia_kg_m2's floor applied */
    double com_design_m[3];     /* the centre in the design frame (a merged robot's and the ankle body's together) */
    double pos_m[3];            /* the centre at the start pose, world; every body starts at rotation R0 */
    double reach_m;             /* the farthest point of the body (joint, anchor, shape) from its centre */
    int kinematic;              /* 1: held where it is (fs_sim_options.hold_rear_foot) */
} fs_model_body;

typedef enum fs_model_shape_kind { FS_MODEL_SPHERE = 0, FS_MODEL_BOX = 1 } fs_model_shape_kind;

typedef struct fs_model_shape {
    fs_model_shape_kind kind;
    int body;                   /* the foot body it is on */
    int foot;                   /* which foot (a biped's 0 right, 1 left; -1 a leg's) */
    double radius_m;            /* a sphere's */
    double size_m[3];           /* a box's edges */
    double offset_m[3];         /* its centre from its body's centre, body frame */
    double match_m;             /* how far its contacts may move in a step and still continue the last step's */
    double grip_dir[3];         /* with chain_plane_friction, a sphere's direction of grip (world, horizontal) */
} fs_model_shape;

typedef struct fs_model_hinge {
    int body1, body2;           /* body2 -1: the world (a pin) */
    double anchor_m[3], axis[3];/* at the start pose, world */
    int spring;                 /* 1: an angular spring-damper toward the built pose (a stop with lo = hi) */
    double k_N_m_per_rad, c_N_m_s_per_rad;
} fs_model_hinge;

typedef struct fs_model_spring {
    const char *name;
    int body1, body2;           /* body indices (the robot's own body: nbodies) */
    double p1_m[3], p2_m[3];    /* the anchors at the start pose, world */
    double k_N_per_m, c_Ns_per_m, rest_length_m;
    fs_spring_law law;          /* its law (fs_spring_law.h); k_N_per_m is its stiffness at rest */
} fs_model_spring;

/* The ground's shapes (with_ground): a plane n . p = offset_m (n a unit normal, pointing out of the
 * ground), and blocks (a stepped terrain's steps, axis-aligned boxes). A heightfield terrain's
 * surface is its lattice (sc->terrain: fs_terrain_height, z). */
typedef struct fs_model_plane {
    double normal[3], offset_m;
} fs_model_plane;

typedef struct fs_model_block {
    double size_m[3], pos_m[3]; /* edges, centre (world) */
} fs_model_block;

typedef struct fs_model {
    const fs_scenario *sc;      /* compiled from, with its terrain (the ground) */
    fs_sim_options opts;        /* compiled for (profile left out: a run's, not the model's) */
    const fs_foot_geom *geom;   /* the scenario's, a biped's (own_geom), or a pinned chain's (own_geom) */
    fs_foot_geom own_geom;
    double R0[9], t0[3];        /* the start pose: world = R0 * design + t0 */
    double q0_wxyz[4];          /* R0 as the quaternion ODE keeps of it (every body's at the start) */
    double down[3];             /* unit direction of the load and gravity */
    double gravity_m_per_s2[3];
    int with_ground;            /* the terrain is the ground (not with a pinned chain or without ground) */
    int nplanes, nblocks;       /* the ground's shapes (0 without ground) */
    fs_model_plane plane[1];
    fs_model_block *block;      /* nblocks of them, the model's own */
    int heightfield;            /* the ground is the terrain's lattice (sc->terrain.z) */
    int nbodies;                /* the foot's bodies (geom->nbodies) */
    fs_model_body body[FS_MODEL_MAX_BODIES]; /* the foot's, then [nbodies] the robot's own (robot_body) */
    int nshapes;                /* spheres, then boxes */
    fs_model_shape shape[FS_MAX_SHAPES];
    int nhinges, npins;
    fs_model_hinge hinge[FS_MAX_HINGES], pin[2];
    int nsprings;
    fs_model_spring spring[FS_MAX_SPRINGS];
    int spring_impl;            /* the scenario's [run] springs: 0 implicit, 1 explicit */
    int damping_correction;
    /* the robot */
    int robot_body;             /* 1: a body of its own (body[nbodies]) on a joint to the ankle body */
    int robot_merged;           /* 1: a rigid, free robot is part of the ankle body */
    double robot_local_m[3];    /* a merged robot's centre of mass on the ankle body, from its centre */
    int robot_joint;            /* fs_robot_joint: FS_ROBOT_RIGID (fixed) or a hinge at the ankle */
    int robot_vertical;         /* 1: on a vertical slide to the world (the carriage's) */
    double robot_hinge_anchor_m[3], robot_hinge_axis[3];
    int has_achilles;
    fs_model_spring achilles;   /* the ankle body to the robot */
    /* the load at the ankle */
    double ankle_m[3];          /* at the start pose, world */
    double foot_ankle_m[FS_MAX_FEET][3];
    double load_N;              /* its weight (a pinned chain's fifth) */
    /* the contacts: the sole's and the terrain's materials together */
    double mu;                  /* sqrt(sole mu * terrain mu) */
    double restitution, bounce_speed_m_per_s; /* restitution 0: no bounce */
    double contact_k_N_per_m, contact_c_Ns_per_m; /* in series */
    double contact_erp, contact_cfm; /* ODE's softness of that spring-damper at the scenario's step */
    int chain_plane_friction;
} fs_model;

/* Compiles sc into a new model (*out; NULL on failure, FS_BAD_INPUT or FS_NO_MEMORY) for a
 * simulation with opts (NULL: a normal run with the ground). Reads no file and builds no ODE world. */
fs_status fs_model_compile(const fs_scenario *sc, const fs_sim_options *opts, fs_model **out, fs_error *err);
void fs_model_free(fs_model *m);

/* A new simulation made from m alone (*out; NULL on failure, when nothing is left behind): the ODE
 * world, bodies, shapes, joints, springs and ground. profile, when not NULL, is where its steps'
 * time goes (fs_sim_options.profile). m must outlive the simulation; free it with fs_sim_free. */
fs_status fs_sim_create(const fs_model *m, struct fs_profile *profile, fs_sim **out, fs_error *err);

/* The model a simulation was made from. */
const fs_model *fs_sim_model(const fs_sim *sim);

#endif
