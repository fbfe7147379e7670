/* sim_spring.h (private to the sim layer): footsim's spring-damper between an anchor on each of two bodies.
 *
 * Force along the line between the anchors: f = k (d - rest) + c dd/dt, tension positive,
 * pulling the anchors together; or, with a law set (fs_spring_set_law), the law's force at the
 * deflection x = d - rest plus c dd/dt (fs_spring_law.h). Two implementations behind this one
 * interface:
 * - FS_SPRING_IMPLICIT: an ODE DBall row made soft (fs_spring_soft), stable at any step.
 *   fs_spring_prepare resets its ERP and CFM whenever the step h changes. A nonlinear law is the
 *   same row linearised at each step's start: its tangent stiffness k_t and a rest length shifted
 *   to d - f(x)/k_t, so that the row pulls f(x) at the start and f(x) + k_t (d' - d) at the end.
 *   A cable (tension-only) is one one-sided row instead: an ODE contact joint's normal row
 *   (force >= 0) along the line from anchor 1 to anchor 2, as soft as the two-sided row, made
 *   afresh in the spring's own joint group at each step that starts with the cable taut.
 * - FS_SPRING_EXPLICIT: the force from the current state, added to both bodies each step;
 *   stable only for steps below about 2m/c of the lightest body it acts on.
 * body2 may be NULL: its anchor is then fixed in the world. Nothing here allocates but
 * fs_spring_set_law, once, for a cable's joint group (ODE's group reuses its memory each step);
 * fs_spring_free gives it back. */
#ifndef SIM_SPRING_H
#define SIM_SPRING_H

#include "footsim/sim/fs_sim.h" /* fs_spring_state */

#include "footsim/model/fs_spring_law.h"

#include <ode/ode.h>

typedef struct fs_spring {
    fs_spring_impl impl;
    dBodyID body1, body2;
    dVector3 local1, local2; /* anchors in body frames (local2 is a world point when body2 is NULL) */
    double k, c, rest;
    int damping_correction;  /* implicit only: fs_spring_soft's correct; fs_spring_init sets 1 */
    dJointID joint;          /* implicit only */
    double step;             /* the h its ERP and CFM were set for */
    fs_spring_law law;       /* linear of k unless fs_spring_set_law gave another */
    dJointGroupID cable;     /* implicit cable: the group its one-sided row is made in each step */
    int cable_row;           /* 1 while that row exists (the cable started this step taut) */
} fs_spring;

/* Sets up s between world anchors p1 (on body1) and p2 (on body2, or the world). */
void fs_spring_init(fs_spring *s, dWorldID world, fs_spring_impl impl, dBodyID body1, dBodyID body2,
                    const double p1[3], const double p2[3], double k, double c, double rest);

/* Gives s the law (its k becomes the law's stiffness at the rest length). An implicit cable trades
 * its DBall row for a one-sided row made each step (see the top). */
void fs_spring_set_law(fs_spring *s, const fs_spring_law *law);

/* Frees what fs_spring_set_law made (a cable's joint group); before the world is destroyed. */
void fs_spring_free(fs_spring *s);

/* A spring-damper of stiffness k and damping c over a step h as ODE's soft constraint: ERP = h k /
 * (h k + C), CFM = 1 / (h k + C), which makes the row's force f = k x' + C v' at the step's end
 * (x' its stretch, v' its rate), the implicit-Euler spring-damper of k and C. The spring taken at the
 * step's end is the spring at its start less k h v', so this damps by C + k h: implicit Euler's own
 * damping grows with the step. With correct = 0, C = c (plain implicit Euler). With correct = 1,
 * C = max(c - k h, 0): the damping is c whatever the step as long as k h <= c, and k h beyond, never
 * less than implicit Euler's with no damper, so that a mass on the row is stable at any step
 * (h^2 k < 4 m + 2 h (k h)); at rest the force is k x either way. The implicit springs, the contacts
 * and the biped's angular springs (hinge stops) all take it from here ([run] damping_correction,
 * docs/model.md). */
void fs_spring_soft(double h, double k, double c, int correct, double *erp, double *cfm);

/* Before each step of size h: sets ERP and CFM (implicit, when h changed) or adds the forces
 * (explicit). */
void fs_spring_prepare(fs_spring *s, double h);

/* Length, rate, force and stored energy now; for the implicit spring this is the force the
 * constraint applied over the last step. */
fs_spring_state fs_spring_measure(const fs_spring *s);

/* World positions of the two anchors now. */
void fs_spring_anchors(const fs_spring *s, double p1[3], double p2[3]);

#endif
