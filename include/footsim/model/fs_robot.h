/* fs_robot.h: the passive robot a landing trial drops and the walking machine carries, as a file of
 * its own (scenarios/robots/NAME.ini), named from a scenario by `[robot] design = robots/NAME.ini`.
 *
 * A robot is one rigid body standing for torso and leg, its mass, centre of mass and principal
 * inertia stated, joined to the foot's ankle body rigidly or through an ankle hinge with an
 * Achilles spring-damper, and mounted free (all six degrees of freedom) or on a vertical slide (the
 * walking machine's carriage: pitch, roll, yaw and horizontal motion held). docs/landing.md gives
 * every shipped robot's choices and why. fs_robot_load reads and checks a file with the scenario's
 * --set overrides of its keys (`--set robot.mass_kg=30`); an empty path is no robot (mass 0).
 *
 * A biped (kind = biped) is instead a pelvis and two legs, a thigh and a shank each, standing on two
 * copies of the foot design (the design's foot on the right, its mirror image on the left), hips
 * hip_width_m apart, joined by passive hip, knee and ankle hinges about the lateral axis, each an
 * angular spring-damper toward the built pose (knees bent knee_bend_deg). Its mass_kg (pelvis and
 * legs, the feet not counted, as no robot here counts them) and com_height_m (of pelvis and legs,
 * above the ankles) follow from its parts (fs_robot_derive); com_forward_m is where the whole body's
 * centre of mass stands ahead of the ankles, which sets the pelvis's. fs_robot_biped_geometry
 * builds the whole of it as one geometry. */
#ifndef FS_ROBOT_H
#define FS_ROBOT_H

#include "footsim/io/fs_config.h"
#include "footsim/model/fs_design.h"

typedef enum fs_robot_kind { FS_ROBOT_SINGLE = 0, FS_ROBOT_BIPED = 1 } fs_robot_kind;

typedef enum fs_robot_joint { FS_ROBOT_RIGID = 0, FS_ROBOT_ACHILLES = 1 } fs_robot_joint;

/* The Achilles tendon's line lies this far behind the ankle axis, m. */
#define FS_ACHILLES_LEVER_M 0.02
typedef enum fs_robot_mount { FS_ROBOT_FREE = 0, FS_ROBOT_VERTICAL = 1 } fs_robot_mount;

typedef struct fs_robot_def {
    int kind;                  /* fs_robot_kind: one rigid body on the foot, or a biped on two */
    double mass_kg, com_height_m, com_forward_m; /* the body (torso and leg); COM above and ahead of the ankle */
    double inertia_kgm2[3];    /* principal moments about its COM */
    int joint;                 /* fs_robot_joint: rigid, or an ankle hinge with an Achilles spring-damper */
    double achilles_k_N_per_m, achilles_c_Ns_per_m, achilles_leg_anchor_m;
    int mount;                 /* fs_robot_mount: free, or held but for vertical motion */
    double inertia_height_m;   /* > 0: inertia_kgm2 is the body's at this COM height, and at another
                                  the same body is stretched along the vertical (fs_robot_inertia) */
    /* the biped (kind = biped) */
    double hip_width_m, thigh_length_m, shank_length_m, knee_bend_deg, leg_width_m;
    double pelvis_mass_kg, thigh_mass_kg, shank_mass_kg, pelvis_com_height_m;
    double pelvis_inertia_kgm2[3];
    double hip_k_N_m_per_rad, hip_c_N_m_s_per_rad, knee_k_N_m_per_rad, knee_c_N_m_s_per_rad;
    double ankle_k_N_m_per_rad, ankle_c_N_m_s_per_rad;
} fs_robot_def;

/* A biped's mass_kg and com_height_m from its parts; nothing for a single body. */
void fs_robot_derive(fs_robot_def *r);

/* The biped r standing on foot (a checked single foot's geometry) as one geometry: the right foot
 * (the design's bodies 0 .. n - 1, at y = -hip_width_m / 2), the left (its mirror image, bodies n ..
 * 2n - 1, at +hip_width_m / 2), then the pelvis, and per leg (right first) a thigh and a shank; the
 * feet's hinges and springs, then per leg its hip, knee and ankle hinges (ankle: shank to the
 * foot's ankle body, at its ankle). */
void fs_robot_biped_geometry(const fs_robot_def *r, const fs_foot_geom *foot, fs_foot_geom *out);

/* The body's principal moments for its centre-of-mass height: with inertia_height_m > 0, the body
 * stretched along the vertical by f = com_height_m / inertia_height_m, which scales its mass's
 * spread along z, s = (Ix + Iy - Iz) / 2, by f^2: Ix + (f^2 - 1) s, Iy + (f^2 - 1) s, Iz. A body's
 * moments stay a body's at every height (as given at f = 1, bit for bit). */
void fs_robot_inertia(const fs_robot_def *r, double I[3]);

/* The moments about the centre of mass of everything r describes (the foot not counted), along
 * the frame's axes (x forward, y left, z up; the products left out): a single body's
 * fs_robot_inertia; a biped's pelvis and both legs together, as fs_robot_biped_geometry builds them,
 * each body's own moment and its mass's distance from the whole's centre (parallel axes). */
void fs_robot_whole_inertia(const fs_robot_def *r, double I[3]);

/* 0 when the principal moments I can be a rigid body's: each positive, each at most the sum of the
 * other two (A + B >= C, within a relative 1e-9 of round-off: a thin plate is on the boundary);
 * else 1 + the first axis (0 x, 1 y, 2 z) that breaks it. fs_robot_load refuses a robot's. */
int fs_inertia_impossible(const double I[3]);

extern const fs_key fs_robot_keys[];
extern const int fs_robot_nkeys;

/* Reads path (none when empty: the defaults with mass 0) with overrides ("robot.key=value") into
 * def; anything wrong is FS_BAD_INPUT with file:line. */
fs_status fs_robot_load(const char *path, const char *const *overrides, int noverrides, fs_robot_def *def,
                        fs_error *err);

#endif
