/* fs_design.h: a foot design: its def (what the user's file says) and its geometry (what
 * follows from the def, in world coordinates, before anything is built in ODE).
 *
 * The def is plain data with defaults: fs_design_load reads it from an INI file (plus --set
 * overrides) through the schema fs_design_keys and checks it whole. fs_design_geometry turns a
 * checked def into bodies, hinges, springs and contact shapes; the ODE builder, the stiffness
 * model, the planar reference and the model dump all read that one geometry.
 *
 * Frame: x forward, y left, z up; the ground is z = 0 and the heel sphere touches it at x = 0.
 * Each toe chain lies in its own vertical plane through its midfoot joint, turned by its splay
 * angle about z. A joint angle is the distal body's rotation about the hinge axis, positive when
 * the distal link turns up (toe dorsiflexion); it is 0 in the neutral pose. */
#ifndef FS_DESIGN_H
#define FS_DESIGN_H

#include "footsim/io/fs_config.h"
#include "footsim/base/fs_vec.h"
#include "footsim/model/fs_spring_law.h"

enum { FS_CHAINS = 5, FS_SPRINGS_PER_CHAIN = 3 };
/* One foot's parts, and the most a geometry holds: two feet and a biped's legs (fs_robot.h:
 * a pelvis, and a thigh and a shank per leg, joined by a hip, a knee and an ankle hinge each). */
enum { FS_FOOT_BODIES = 2 + 2 * FS_CHAINS, FS_FOOT_HINGES = 1 + 2 * FS_CHAINS,
       FS_FOOT_SPRINGS = FS_SPRINGS_PER_CHAIN * FS_CHAINS, FS_FOOT_SPHERES = 2 + 2 * FS_CHAINS };
enum { FS_MAX_FEET = 2, FS_LEG_BODIES = 1 + 2 * FS_MAX_FEET, FS_LEG_HINGES = 3 * FS_MAX_FEET };
enum { FS_MAX_BODIES = FS_MAX_FEET * FS_FOOT_BODIES + FS_LEG_BODIES,
       FS_MAX_HINGES = FS_MAX_FEET * FS_FOOT_HINGES + FS_LEG_HINGES,
       FS_MAX_SPRINGS = FS_MAX_FEET * FS_FOOT_SPRINGS, FS_MAX_SPHERES = FS_MAX_FEET * FS_FOOT_SPHERES,
       FS_MAX_BOXES = FS_MAX_FEET };

typedef enum fs_foot_kind { FS_FOOT_BIOMIMETIC = 0, FS_FOOT_FLAT = 1 } fs_foot_kind;

/* What a design file says. Units are SI; angles in the file are degrees. */
typedef struct fs_design_def {
    int kind;                          /* fs_foot_kind */
    double design_load_kg;             /* the load the arch is checked under (Table I: 26 kg) */
    double l1_m, l2_m, l3_m, l4_m;     /* heel, talus, metatarsal, phalanx (Table I) */
    double heel_deg, talus_deg, toe_deg; /* neutral link directions above the horizontal */
    double k_N_per_m[3];               /* d1 midfoot, d2 MTP, d3 heel to toe */
    double spring_scale;               /* multiplies the three (the geometry's springs carry the product) */
    double c_Ns_per_m[3];
    double d1_b_m, d1_h_m;             /* d1 anchors: distance along the links from the midfoot
                                          joint, and offset toward the sole */
    double d2_b_m, d2_h_m;             /* d2 anchors about the MTP joint */
    double d3_heel_b_m, d3_heel_h_m;   /* d3 on the heel: along the heel link from the heel centre */
    double d3_toe_b_m, d3_toe_h_m;     /* d3 on the phalanx: along it from the MTP joint */
    double d3_heel_spread;             /* d3's heel anchor sits at this fraction of its chain's
                                          lateral offset (the aponeurosis fans out from the heel) */
    /* Each spring kind's law (d1, d2, d3; fs_spring_law.h), linear and two-sided unless the file
       says: k_N_per_m above is k, k0 or k1; springs.scale multiplies every force of the law. */
    int law[3];                        /* fs_law_kind */
    int tension_only[3];               /* 1: a cable (no force while shorter than its rest length) */
    double x0_m[3];                    /* progressive: where the stiffness has doubled */
    double stop_m[3], k2_N_per_m[3];   /* bilinear: the stop's deflection, and the stiffness beyond */
    fs_series curve_m[3], curve_N[3];  /* curve: deflections (m) and forces (N), point by point */
    double lateral_m[FS_CHAINS];       /* y of each midfoot joint, chain 1 (big toe) first */
    double splay_deg[FS_CHAINS];       /* chain plane turned about z */
    double scale[FS_CHAINS];           /* forefoot size factor (lengths, anchors, radii, mass) */
    double splay_factor;               /* multiplies every splay_deg (one number for a search) */
    double scale_factor;               /* multiplies every scale */
    double heel_kg, talus_kg, metatarsal_kg, phalanx_kg;
    double link_width_m;               /* square cross-section of the links, for their inertia */
    double heel_radius_m, ball_radius_m, toe_radius_m; /* contact spheres */
    double heel_width_m;               /* between the two heel spheres; 0 for one */
    /* [soil_shapes]: each link's capsule for a soil (docs/soil.md, The feet's shapes), m; 0: the contact
       sphere's radius (heel, metatarsals, phalanges; the last two times the chain's scale, as given ones
       are), half link_width_m (talus) */
    double soil_heel_radius_m, soil_talus_radius_m, soil_metatarsal_radius_m, soil_phalanx_radius_m;
    double sole_mu;                    /* friction coefficient of the sole material */
    double sole_stiffness_N_per_m;     /* contact stiffness of the sole material, per contact */
    double sole_damping_Ns_per_m;
    double flat_thickness_m;           /* the flat foot's sole plate */
} fs_design_def;

typedef struct fs_body_geom {
    char name[32];
    double mass_kg;
    fs_vec3 com;         /* the body's origin, at its centre of mass */
    double soil_radius_m; /* its capsule's radius for a soil ([soil_shapes]); 0: none given (the sole's box) */
    double inertia[9];   /* about the COM, world axes, kg m^2 (row-major) */
} fs_body_geom;

typedef struct fs_hinge_geom {
    char name[32];
    int body1, body2;    /* proximal, distal */
    fs_vec3 anchor, axis;
    /* a passive angular spring-damper about the axis toward the built pose (0, 0: a free hinge;
       the biped's leg joints), N m/rad and N m s/rad */
    double k_N_m_per_rad, c_N_m_s_per_rad;
} fs_hinge_geom;

typedef struct fs_spring_geom {
    char name[32];
    int body1, body2;
    fs_vec3 p1, p2;      /* anchors in the neutral pose */
    double k_N_per_m, c_Ns_per_m, rest_length_m; /* k: the law's stiffness at its rest length */
    fs_spring_law law;   /* its forces scaled by the design's springs.scale */
} fs_spring_geom;

typedef struct fs_sphere_geom {
    char name[32];
    int body;
    fs_vec3 centre;
    double radius_m;
} fs_sphere_geom;

/* Everything built from a def; a flat foot has one body, a box and no hinges or springs. A biped
 * (fs_robot_biped_geometry) is two copies of a foot (the second mirrored: a right and a left foot)
 * and its legs in one geometry: foot[] says which bodies are whose. */
typedef struct fs_foot_geom {
    int kind;
    int nbodies, nhinges, nsprings, nspheres;
    fs_body_geom body[FS_MAX_BODIES];
    fs_hinge_geom hinge[FS_MAX_HINGES];
    fs_spring_geom spring[FS_MAX_SPRINGS];
    fs_sphere_geom sphere[FS_MAX_SPHERES];
    int nboxes;          /* the flat sole: one per foot, all of one size */
    fs_vec3 box_size;
    struct { int body; fs_vec3 centre; } box[FS_MAX_BOXES];
    int npins;           /* hinges to the world (a pinned chain, fs_design_pinned_chain) */
    struct { int body; fs_vec3 anchor, axis; } pin[2];
    int ankle_body;      /* the body the load acts on (a biped: its right foot's) */
    fs_vec3 ankle;       /* the load's point: the ankle joint centre */
    double total_mass_kg; /* the foot's (a biped: both feet and the legs) */
    /* nfeet 1: the foot's bodies are 0 .. nbodies - 1. A biped: 2, foot f's bodies first_body ..
       first_body + nbodies - 1, its ankle (the leg's ankle hinge) on ankle_body at ankle; then the
       legs, pelvis_body whose lean is the robot's */
    int nfeet;
    struct { int first_body, nbodies, ankle_body; fs_vec3 ankle; } foot[FS_MAX_FEET];
    int biped, pelvis_body;
    /* Biomimetic chains: body and hinge indices, and the neutral joint centres. */
    struct {
        int metatarsal, phalanx, midfoot_hinge, mtp_hinge, spring[3];
        fs_vec3 midfoot, mtp, toe;
        double metatarsal_deg; /* solved so the toe sphere rests on the ground */
    } chain[FS_CHAINS];
} fs_foot_geom;

/* A link of width x depth section (width across, along y where it can) between two points: its
 * body geometry (mass centred between them, inertia of a solid box). */
void fs_design_link_body(fs_body_geom *b, const char *name, double m, fs_vec3 from, fs_vec3 to, double width,
                         double depth);

/* Body and hinge indices of the biomimetic foot. */
enum { FS_BODY_HEEL = 0, FS_BODY_TALUS = 1 };

extern const fs_key fs_design_keys[];
extern const int fs_design_nkeys;

/* Reads and checks a design file with overrides ("section.key=value", n of them). On success
 * def and geom are filled; on failure err says where and why, and nothing else is done. */
fs_status fs_design_load(const char *path, const char *const *overrides, int noverrides, fs_design_def *def,
                         fs_foot_geom *geom, fs_error *err);

/* Where a key of a design is given, for a later check's message: "file:line", "--set section.key",
 * or "file ([section] key, default)" (fs_config_where). */
enum { FS_DESIGN_WHERE_MAX = FS_PATH_MAX + 80 };

/* fs_design_load, and where each spring kind's law (springs.d1_law, d2_law, d3_law) is given, into
 * law_where[0 .. 2] (may be NULL): for a check that comes after loading, such as the MJCF export's
 * refusal of a law MuJoCo cannot express. */
fs_status fs_design_load_located(const char *path, const char *const *overrides, int noverrides, fs_design_def *def,
                                 fs_foot_geom *geom, char law_where[3][FS_DESIGN_WHERE_MAX], fs_error *err);

/* The defaults, as fs_design_load would give for an empty file. */
void fs_design_defaults(fs_design_def *def);

/* Chain i's splay angle (deg) and forefoot size factor as the geometry, the stiffness model and the
 * planar statics use them: chains.splay_deg[i] times chains.splay_factor, chains.scale[i] times
 * chains.scale_factor (fs_design_geometry refuses a product outside the list's range). */
double fs_design_splay_deg(const fs_design_def *d, int i);
double fs_design_chain_scale(const fs_design_def *d, int i);

/* Builds the geometry of a def; cfg (may be NULL) only locates keys in messages. Refuses a
 * def whose toe cannot reach the ground or whose ball would sit below it. */
fs_status fs_design_geometry(const fs_design_def *def, const fs_config *cfg, fs_foot_geom *geom, fs_error *err);

/* One chain of a biomimetic foot alone, for comparison with the planar dynamic reference
 * (fs_reference_run): heel, talus, metatarsal and phalanx (0-3), with a fifth of the heel's and
 * talus's mass and inertia (they are shared by five chains), the chain's three hinges and three
 * springs, no contact shapes, and the heel and the toe pinned to the world at their sphere centres
 * by hinges about the chain's axis. The chain must be unsplayed. */
fs_status fs_design_pinned_chain(const fs_design_def *d, const fs_foot_geom *foot, int chain, fs_foot_geom *out,
                                 fs_error *err);

#endif
