/* analysis_chain.h (internal): one toe chain in its own vertical plane, built from the design
 * and its geometry only (never ODE), for the planar statics (analysis_planar.c) and the dynamic
 * reference (analysis_reference.c).
 *
 * Links 0-3 are heel, talus, metatarsal and phalanx; beta[k] is link k's direction above the
 * horizontal; the joints J0..J4 are the heel sphere's centre, the ankle, the midfoot, the MTP and
 * the toe sphere's centre. The heel and talus are shared by the five chains, so a chain carries a
 * fifth of their mass and inertia and a fifth of the load. */
#ifndef FS_ANALYSIS_CHAIN_H
#define FS_ANALYSIS_CHAIN_H

#include "footsim/model/fs_design.h"

/* A point fixed on link `link`, in the link's frame: a along the link, b toward the sole, and dy
 * out of the plane (constant). */
typedef struct fs_chain_pt { int link; double a, b, dy; } fs_chain_pt;

typedef struct fs_chain2d {
    double len[4], beta0[4];     /* link lengths and neutral directions */
    double r_heel, r_toe, r_ball, H0x, T0x;
    int rolling;                 /* 1: the heel sphere rolls on the ground; 0: pinned at its centre */
    double mass[4], inertia[4];  /* the chain's share; inertia about the COM and the plane normal */
    fs_chain_pt com[4];
    fs_chain_pt p1[3], p2[3];    /* spring anchors: d1, d2, d3 */
    double k[3], c[3], rest[3];  /* k: each law's stiffness at its rest length */
    fs_spring_law law[3];
    int frictionless, nfree;     /* the statics' contact model, and how many angles are free */
    double load, gx, gz;         /* per-chain load (N) and gravity vector */
    double down[2];              /* the load's direction */
    fs_vec3 f, lat;              /* the chain plane's heading and its normal */
    fs_vec3 origin;              /* the chain's midfoot joint ... */
    double origin_x;             /* ... and its x in the plane */
} fs_chain2d;

/* Joint positions J0..J4 (x, z). */
typedef struct fs_chain_joints { double p[5][2]; } fs_chain_joints;

/* Chain i of the design, with a total load load_N at the ankle and gravity turned by tilt_rad. */
void fs_chain2d_setup(fs_chain2d *c, const fs_design_def *d, const fs_foot_geom *g, int i, double load_N,
                      double gravity_m_per_s2, double tilt_rad);

/* Joint positions for link directions b. */
void fs_chain2d_joints(const fs_chain2d *c, const double b[4], fs_chain_joints *js);

/* Where point p is for link directions b and their joints js. */
void fs_chain2d_place(const fs_chain_joints *js, const double b[4], fs_chain_pt p, double out[2]);

#endif
