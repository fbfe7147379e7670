/* fs_analysis.h: what footsim computes about a design besides running it.
 *
 * - fs_stiffness_*: each chain's joint-space stiffness over (midfoot, MTP), K = G^T Kdd G (paper
 *   eqs. 1-3) from the exact geometry, the same with the paper's eq. 4 lever arms, and K measured
 *   in ODE by torque probes with the rear foot held and gravity off.
 * - fs_planar_*: one chain in its plane with heel and toe rolling on the ground, solved for its
 *   static equilibrium under a load at the ankle: the stiffness model's prediction of how the foot
 *   deflects, shared with no ODE code.
 * - fs_pitch_*: the whole foot's stiffness against pitching its ankle body, from its geometry in
 *   three dimensions (the pitch-stiffness law), measured in ODE too, and the law for a robot.
 * - fs_reference_*: the paper's dynamic model (Sec. IV) of one chain in its plane, heel and toe
 *   pinned at their sphere centres, integrated by GSL's rk8pd: the ground truth for the ODE model's
 *   transient (docs/bench.md), also shared with no ODE code. */
#ifndef FS_ANALYSIS_H
#define FS_ANALYSIS_H

#include "footsim/model/fs_scenario.h"

typedef struct fs_chain_stiffness {
    double exact[2][2];     /* N m/rad, from G = dd/dphi at the neutral pose */
    double eq4[2][2];       /* the paper's eq. 4: anchors taken on the link axes */
    double measured[2][2];  /* from ODE */
    double rel_diff;        /* ||measured - exact||_F / ||exact||_F */
    double G[3][2];         /* rows d1, d2, d3; columns midfoot, MTP; m/rad */
} fs_chain_stiffness;

/* The analytic stiffness of every chain at the neutral pose: each spring's stiffness at its rest
 * length (a nonlinear law's tangent there; a cable counted taut). */
void fs_stiffness_analytic(const fs_foot_geom *g, fs_chain_stiffness out[FS_CHAINS]);

/* The same linearised at an operating point (eqs. 1-3 with each law's tangent): spring s of g at
 * deflection x_m[s] (length less rest length) has its law's tangent stiffness there; G is the
 * neutral pose's (the springs' preload's geometric term is left out here; the pitch-stiffness law,
 * an energy's second derivative at the loaded equilibrium, has both). A cable counts only while
 * taut: 0 at x < 0, its taut stiffness at x >= 0 (at exactly its rest length too: the stiffness the
 * load that would stretch it meets). fs_stiffness_analytic is this at x = 0. */
void fs_stiffness_tangent(const fs_foot_geom *g, const double x_m[FS_MAX_SPRINGS], fs_chain_stiffness out[FS_CHAINS]);

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
    double spring_deflection_m[3]; /* d1, d2, d3: length less rest length there */
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

/* The pitch-stiffness law (docs/landing.md; analysis_pitch.c): one biomimetic foot's stiffness
 * against pitching its ankle body (the talus) about the lateral axis, N m/rad, under load_N at the
 * ankle and gravity, from its geometry in three dimensions: heel and toes roll without slipping
 * along the foot and along each chain's plane, slide freely across them, none lifts; the heel
 * turns freely and the foot may shift sideways (both condensed out). Splayed or not, alike or not,
 * ODE given those contacts agrees within 6e-4 (tests/test_analysis_stiffness.c). A robot of
 * mass m whose centre of mass stands h above the ankle stands on the foot when m g h < K.
 * FS_BAD_INPUT for a flat foot (its contacts govern) or a geometry without the heel; FS_NUMERICAL
 * when the foot has no stable equilibrium under the load (the arch folds). */
fs_status fs_pitch_stiffness_model(const fs_foot_geom *g, double load_N, double gravity_m_per_s2, double *K,
                                   fs_error *err);

/* The arch's fold (docs/landing.md, the drop law): the largest moment, up to cap_N_m, that the same
 * model of the foot under load_N at the ankle holds when the moment pitches its ankle body forward
 * (towards the toes), found by continuation in the moment and bisection (to cap_N_m / 12288, as far
 * as Newton from the last equilibrium still converges: a lower bound, about 10 % on Table I): past it
 * the model has no stable equilibrium, the arch folds. INFINITY when it holds the cap. Errors as
 * fs_pitch_stiffness_model's. */
fs_status fs_pitch_fold_moment(const fs_foot_geom *g, double load_N, double gravity_m_per_s2, double cap_N_m,
                               double *fold_N_m, fs_error *err);

/* The pitch stiffness of a scenario's foot on its ground, N m/rad: for the biomimetic foot the
 * model above (the arch governs; the ground is taken as rigid beside it); for a flat sole its
 * contacts govern, on level ground of the scenario's material: the sole's four bottom corners, each
 * a spring of the sole's and the ground's contact stiffness in series (k), pitched about their
 * middle, K = k L^2 for a sole L long (exact while no corner lifts, that is for a pitching moment
 * below load_N L / 2). */
fs_status fs_pitch_stiffness_foot(const fs_scenario *sc, double load_N, double *K, fs_error *err);

/* The same stiffness measured in ODE: the foot on the scenario's ground with friction mu (sole and
 * ground), under load_N at the ankle (the scenario's load and robot replaced), torques +tau and
 * -tau (1e-3 rad times K_guess, and at most a twentieth of the moment that would lift the
 * footprint's heel or toe, load_N times half its length) about the lateral axis on the ankle body,
 * risen with the load and held until still; K = 2 tau / (pitch(+tau) - pitch(-tau)). With mu = 10
 * heel and toes grip (the model's assumption in each chain's plane, but splayed toes are then held
 * across their planes too). in_plane 1 (a biomimetic foot on level ground): the contacts grip with
 * mu along each chain's plane and slide freely across it (fs_sim_options.chain_plane_friction),
 * the contacts the model assumes; docs/landing.md gives all three. */
fs_status fs_pitch_stiffness_measure(const fs_scenario *sc, double load_N, double mu, int in_plane, double K_guess, double *K,
                                     fs_error *err);

/* The law for one robot on a foot of pitch stiffness K_foot: an Achilles tendon acts in series
 * (k times its 2 cm lever squared), a robot on a vertical slide cannot lean. A centre of mass x
 * ahead of the ankle leans the robot by m g x / (K - m g h) at rest (small angles): it stands when
 * m g h < K and that lean is below max_lean_rad (a landing's upright bound). */
typedef struct fs_pitch_law {
    double K_foot, K_series, K;  /* N m/rad: the foot's, the robot's joint's (INFINITY when rigid), in series
                                    (a biped: twice that, two legs side by side, each on its ankle spring) */
    double demand;               /* m g h, N m/rad: what the robot's weight asks of K */
    double critical_height_m;    /* K / (m g): the highest centre of mass that stands */
    double lean_rad;             /* the lean at rest from the forward offset (INFINITY past the height) */
    int held;                    /* pitch held (the rig): it stands whatever K */
    int stands;                  /* held, or demand < K and lean_rad < max_lean_rad */
} fs_pitch_law;
void fs_pitch_law_apply(double K_foot, const fs_robot_def *robot, double gravity_m_per_s2, double max_lean_rad,
                        fs_pitch_law *out);

/* The drop law (docs/landing.md): the pitch-stiffness law with the touchdown in it. The robot meets
 * the ground at v = sqrt(2 g drop) with its centre of mass x ahead of and h above the ankle; over the
 * impact (a few ms, short beside the pitch mode's period) the foot's pitch spring carries no moment,
 * so the impulse passes through the ankle and the robot leaves it turning about it with the angular
 * momentum m x v it had about it: rotational energy E = (m x v)^2 / (2 I_A), I_A = I_pitch + m (h^2 +
 * x^2). The weight's moment about the ankle arrives as a step at touchdown. The foot's restoring
 * moment rises as K theta (K the static law's, any tendon in series) until it saturates at M_s, the
 * smaller of the arch's fold moment and the support's W e (its centre of pressure at the support
 * polygon's edge, e ahead of the ankle in the lean's direction, W = m g): past M_s a fold holds M_s
 * while the robot turns on about the ankle; at the edge the whole foot turns about it, rigidly. The
 * robot lands when the static law's equilibrium lies below M_s (K theta_0 < M_s) and below the lean
 * bound, and E is less than the work B the net restoring moment does from upright to the largest lean
 * it can hold (where it falls to zero: the fold's plateau met by the weight's moment, or the centre of
 * mass over the edge):
 *   B = (K - W h) theta_s^2 / 2 - W x theta_s, theta_s = M_s / K, plus
 *       W h (theta* - theta_s)^2 / 2, theta* = (M_s / W - x) / h, for a fold, or
 *       W (sqrt(b^2 + c^2) - c) about the edge, b = e - x - h theta_s and c = h + the ankle's height
 *       the centre of mass's distances from the edge then (a rigid block about its corner).
 * Small leans as the static law's up to M_s; exact about the edge. Damping left out (it only takes
 * energy away). With M_s infinite it is the static law whatever the drop; a rigid foot (K infinite)
 * on its edge is the rigid block's criterion E < W (R - c). */
typedef struct fs_drop_support {
    double edge_m;             /* e: the support polygon's edge ahead of the ankle along the lean (the
                                  centre of mass's side), horizontal, m; INFINITY: none */
    double ankle_height_m;     /* the ankle above the ground at the edge, m */
    double fold_N_m;           /* the arch's fold moment, N m (INFINITY: it does not fold) */
} fs_drop_support;

typedef struct fs_drop_law {
    double speed_m_per_s;      /* at touchdown */
    double inertia_kgm2;       /* I_A: the robot's pitch inertia about the ankle */
    double energy_J;           /* E */
    double saturation_N_m;     /* M_s */
    int folds;                 /* 1 when M_s is the fold's, 0 the edge's */
    double lean_rad;           /* the static law's equilibrium (INFINITY: none) */
    double barrier_J;          /* B (0 when there is no equilibrium) */
    int stands;                /* held, or an equilibrium below M_s and the lean bound, and E < B */
} fs_drop_law;
void fs_drop_law_apply(const fs_pitch_law *statics, const fs_robot_def *robot, double gravity_m_per_s2, double drop_m,
                       double max_lean_rad, const fs_drop_support *support, fs_drop_law *out);

/* The share of a foot's pitch stiffness K that its n chains (side by side, K / n each) give at a
 * robot's static lean when chain i comes to bear only once the foot has pitched forward by
 * engage_rad[i] (0: it bears at rest; INFINITY: never) and adds K / n (theta - engage_rad[i]) from
 * there (docs/landing.md, The drop law: toes that come to bear). The lean theta is where that
 * piecewise-linear moment meets the weight's, W (x + h theta), found segment by segment in the order
 * the chains engage; the share is the secant M(theta) / (K theta) there (m / n for an upright rest
 * on m chains). NAN when no segment holds an equilibrium (or n is outside 1..FS_MAX_FEET * FS_CHAINS:
 * a biped's two feet are ten chains of 2 K / 10 each under its whole weight). */
double fs_pitch_engaged_share(const double *engage_rad, int n, double K, double W, double x, double h);

/* The rocking onto the rest on uneven ground (docs/landing.md, The drop law): a rigid body of mass m,
 * its principal moments I_G[3] about its centre of mass G along the axes of the points' frame, turns
 * about the axis through `pivot` along `axis` (its first contact; horizontal) with the kinetic energy
 * energy_J, and meets its rest. The impact is plastic and the body goes on turning about the side
 * s1-s2 of its support alone, whose impulses pass through that line, so its angular momentum about
 * the side is kept (Housner's rocking block): with u along the side, r_P = G - pivot, r_S = G - s1,
 *   omega_S = omega u . (I_G a + m r_S x (a x r_P)) / I_S,   I_S = u . I_G u + m d_S^2,
 * omega = sqrt(2 energy_J / I_a), I_a = a . I_G a + m d_a^2 (d the distances of G from the lines).
 * The sense of omega is the one that lowers G. Returns the energy I_S omega_S^2 / 2 left turning about
 * the side in the sense that carries G out over it (the polygon's interior left of s1 -> s2, seen
 * from above); 0 when the kept momentum turns the body back onto its rest. For a rectangular block
 * (half-width b, half-height h) passing from one bottom corner to the other it is energy_J times
 * Housner's (1 - 3/2 sin^2 alpha)^2, tan alpha = b / h: a squat body keeps little, a tall one most. */
double fs_rocking_kept_J(double mass_kg, const double I_G[3], fs_vec3 G, fs_vec3 pivot, fs_vec3 axis, double energy_J,
                         fs_vec3 s1, fs_vec3 s2);

/* The contact in the drop law, per end of a contact band (docs/contact.md, "The band, and how a
 * verdict should carry it"; docs/landing.md, The drop law). Each contact point is a linear
 * spring-damper (k, c) under the mass m it decelerates:
 *   zeta = c / (2 sqrt(k m))                                      fs_contact_damping_ratio
 *   e = exp(-pi zeta / sqrt(1 - zeta^2)) for zeta < 1, else 0     fs_contact_restitution
 * (the half-period of the damped oscillation in contact, the point leaving where the spring is back
 * at its length: the displacement criterion the band's definition uses; overdamped contacts do not
 * rebound). A contact of restitution e at the ankle's touchdown turns the robot about the ankle with
 * (1 + e) times the angular momentum a plastic one leaves, and every rebound (speeds e v, e^2 v, ...)
 * at most adds its own: the drop's energy E grows by at most
 *   G(e) = ((1 + e) / (1 - e))^2                                  fs_contact_rebound_gain
 * (1 at e = 0; 9.0 at e = 0.5). The contacts' compliance acts in series with the arch's pitch
 * stiffness K: a rigid foot on n points of stiffness k each, turned by a small angle about the
 * points' centre along the foot, resists with k S, S = sum (x_i - x_mean)^2 (m^2) over the bearing
 * points' positions x_i along the foot. The law's K is the model's on rigid ground, checked in ODE on
 * the trials' hard contacts (docs/landing.md: within 0.5 % up to 30 times Table I's springs), so it
 * stands for the foot on the band's stiffest contact k_ref; a softer end adds the difference in
 * compliance:
 *   1 / K_end = 1 / K + (1 / k - 1 / k_ref) / S                   fs_pitch_contact_series
 * K itself when k >= k_ref or S <= 0 (to the bit: the stiffest end's law is the law without a band). */
double fs_contact_damping_ratio(double k_N_per_m, double c_Ns_per_m, double mass_kg);
double fs_contact_restitution(double zeta);
double fs_contact_rebound_gain(double e);
double fs_pitch_contact_series(double K_N_m_per_rad, double spread_m2, double k_N_per_m, double k_ref_N_per_m);

/* The reference transient: chain `chain` (0-based, unsplayed) from rest, the load rising linearly
 * over ramp_s. Masses: a fifth of heel and talus, the whole metatarsal and phalanx; a fifth of the
 * load. */
typedef struct fs_reference_def {
    int chain;
    double load_N;             /* on the whole foot, at the ankle */
    double ramp_s;
    double gravity_m_per_s2;
    double tilt_rad;           /* load and gravity turned as in fs_scenario_def.tilt_deg */
    double tolerance;          /* rk8pd's absolute and relative error bound per step */
    double q0_offset_rad[2];   /* a start displaced from the neutral pose (heel, talus directions) */
} fs_reference_def;

typedef struct fs_reference_state {
    double t_s;
    double ankle_m[3];         /* the ankle joint, world coordinates */
    double joint_rad[3];       /* ankle, midfoot, MTP from the neutral pose (positive: distal link up) */
    double energy_J;           /* kinetic + springs + gravity + the load's potential at its current size */
} fs_reference_state;

/* Fills out[i] with the state at t = i * dt_s, i < n. FS_BAD_INPUT for a splayed chain or a
 * non-biomimetic design; FS_NUMERICAL if the loop stops closing (the chain folds through). */
fs_status fs_reference_run(const fs_design_def *d, const fs_foot_geom *g, const fs_reference_def *def, double dt_s,
                           int n, fs_reference_state *out, fs_error *err);

/* The chain linearised about its neutral pose with no load, gravity or damping: its two natural
 * frequencies (rad/s, ascending) and mode shapes (unit vectors in heel and talus direction). */
fs_status fs_reference_modes(const fs_design_def *d, const fs_foot_geom *g, int chain, double omega[2],
                             double shape[2][2], fs_error *err);

#endif
