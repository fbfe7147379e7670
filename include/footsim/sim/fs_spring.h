/* fs_spring.h: footsim's linear spring-damper between an anchor on each of two bodies.
 *
 * Force along the line between the anchors: f = k (d - rest) + c dd/dt, tension positive,
 * pulling the anchors together. Two implementations behind this one interface:
 * - FS_SPRING_IMPLICIT: an ODE DBall row made soft, ERP = hk/(hk + c), CFM = 1/(hk + c), which is
 *   the implicit-Euler spring-damper; stable at any step. fs_spring_prepare resets ERP and CFM
 *   whenever the step h changes.
 * - FS_SPRING_EXPLICIT: the force from the current state, added to both bodies each step;
 *   stable only for steps below about 2m/c of the lightest body it acts on.
 * body2 may be NULL: its anchor is then fixed in the world. Nothing here allocates. */
#ifndef FS_SPRING_H
#define FS_SPRING_H

#include <ode/ode.h>

typedef enum fs_spring_impl { FS_SPRING_IMPLICIT = 0, FS_SPRING_EXPLICIT = 1 } fs_spring_impl;

typedef struct fs_spring {
    fs_spring_impl impl;
    dBodyID body1, body2;
    dVector3 local1, local2; /* anchors in body frames (local2 is a world point when body2 is NULL) */
    double k, c, rest;
    dJointID joint;          /* implicit only */
    double step;             /* the h its ERP and CFM were set for */
} fs_spring;

typedef struct fs_spring_state {
    double length_m, rate_m_per_s, force_N, energy_J;
} fs_spring_state;

/* Sets up s between world anchors p1 (on body1) and p2 (on body2, or the world). */
void fs_spring_init(fs_spring *s, dWorldID world, fs_spring_impl impl, dBodyID body1, dBodyID body2,
                    const double p1[3], const double p2[3], double k, double c, double rest);

/* The implicit-Euler spring-damper of stiffness k and damping c over a step h as ODE's soft
 * constraint: ERP = h k / (h k + c), CFM = 1 / (h k + c). The implicit springs, the contacts and the
 * biped's angular springs (hinge stops) all take it from here. */
void fs_spring_soft(double h, double k, double c, double *erp, double *cfm);

/* Before each step of size h: sets ERP and CFM (implicit, when h changed) or adds the forces
 * (explicit). */
void fs_spring_prepare(fs_spring *s, double h);

/* Length, rate, force and stored energy now; for the implicit spring this is the force the
 * constraint applied over the last step. */
fs_spring_state fs_spring_measure(const fs_spring *s);

/* World positions of the two anchors now. */
void fs_spring_anchors(const fs_spring *s, double p1[3], double p2[3]);

#endif
