/* fs_analysis.h: what footsim computes about a design besides running it.
 *
 * - fs_model_json: the model as ODE holds it after building (masses, inertias, poses, joints,
 *   springs, shapes), in SI units and world coordinates.
 * - fs_stiffness_*: each chain's joint-space stiffness over (midfoot, MTP), K = G^T Kdd G (paper
 *   eqs. 1-3) from the exact geometry, the same with the paper's eq. 4 lever arms, and K measured
 *   in ODE by torque probes with the rear foot held and gravity off.
 * - fs_planar_*: one chain in its plane with heel and toe rolling on the ground, solved for its
 *   static equilibrium under a load at the ankle: the stiffness model's prediction of how the foot
 *   deflects, shared with no ODE code. */
#ifndef FS_ANALYSIS_H
#define FS_ANALYSIS_H

#include "footsim/fs_scenario.h"

#include <cJSON.h>

cJSON *fs_model_json(const fs_scenario *sc, fs_error *err);

typedef struct fs_chain_stiffness {
    double exact[2][2];     /* N m/rad, from G = dd/dphi at the neutral pose */
    double eq4[2][2];       /* the paper's eq. 4: anchors taken on the link axes */
    double measured[2][2];  /* from ODE */
    double rel_diff;        /* ||measured - exact||_F / ||exact||_F */
    double G[3][2];         /* rows d1, d2, d3; columns midfoot, MTP; m/rad */
} fs_chain_stiffness;

/* The analytic stiffness of every chain at the neutral pose. */
void fs_stiffness_analytic(const fs_foot_geom *g, fs_chain_stiffness out[FS_CHAINS]);

/* Measures K in ODE: for each chain and joint, torques +tau and -tau about the hinge axis, the
 * settled angle changes, K = Q dphi^-1 from the central differences. */
fs_status fs_stiffness_measure(const fs_scenario *sc, fs_chain_stiffness out[FS_CHAINS], fs_error *err);

typedef struct fs_planar_result {
    int converged;        /* Newton converged to an equilibrium */
    int stable;           /* the reduced stiffness there is positive definite */
    double ankle_drop_m;  /* neutral ankle height minus loaded */
    double midfoot_rad, mtp_rad, ankle_joint_rad; /* joint angles from the neutral pose */
    double ball_clearance_m; /* ball sphere's lowest point above the ground */
    double spring_force_N[3];
    double K_reduced[2][2]; /* stiffness in (heel, talus) angles at equilibrium, N m/rad */
} fs_planar_result;

typedef struct fs_planar_load {
    double load_N;            /* at the ankle, shared equally by the five chains */
    double gravity_m_per_s2;
    double tilt_rad;          /* load and gravity turned as in fs_scenario_def.tilt_deg */
    int frictionless;         /* 1: heel and toe slide freely; 0: they roll without slipping */
} fs_planar_load;

/* Chain `chain` of the design in equilibrium under the load, as if all five chains were like it.
 * Exact for a design whose chains are alike and unsplayed; a projection otherwise. */
fs_status fs_planar_equilibrium(const fs_design_def *d, const fs_foot_geom *g, int chain, const fs_planar_load *load,
                                fs_planar_result *out, fs_error *err);

#endif
