/* fs_spring_law.h: a spring's elastic force against its deflection (its law), as data.
 *
 * The deflection x is the spring's length less its rest length (positive: stretched); the force is
 * positive in tension (it pulls the anchors together). Four laws:
 * - linear:      f = k x (Table I; every spring today);
 * - progressive: stiffness k(x) = k0 (1 + (x/x0)^2), so f = k0 (x + x^3 / (3 x0^2)): soft for small
 *                deflections, stiffer the further it is deflected, alike in tension and compression;
 * - bilinear:    k1 while |x| <= the stop, k2 beyond it (a stop that engages at either side);
 * - curve:       a force-deflection table, linear between its points, the end segments extended
 *                beyond them; it passes through (0, 0) (the neutral pose is unstrained) and rises.
 * Any law may be tension-only (a cable): no force while x <= 0; taut, the law's force with the
 * damper's, never a push (f = max(0, f(x) + c v): a cable going slack faster than it unloads lets
 * go). The stiffness model counts a cable at exactly its rest length as taut (the stiffness the
 * load that stretches it meets) and a slack one (x < 0) not at all (docs/model.md).
 * Pure functions of the law: nothing here knows ODE, and nothing allocates. */
#ifndef FS_SPRING_LAW_H
#define FS_SPRING_LAW_H

enum { FS_CURVE_MAX = 16 };

typedef enum fs_law_kind { FS_LAW_LINEAR = 0, FS_LAW_PROGRESSIVE = 1, FS_LAW_BILINEAR = 2, FS_LAW_CURVE = 3 } fs_law_kind;

typedef struct fs_spring_law {
    int kind;                     /* fs_law_kind */
    int tension_only;             /* 1: a cable */
    double k_N_per_m;             /* linear: k; progressive: k0; bilinear: k1 (curve: unused) */
    double x0_m;                  /* progressive: the deflection at which the stiffness has doubled */
    double stop_m, k2_N_per_m;    /* bilinear: where k2 takes over, and k2 */
    int npoints;                  /* curve: its points, deflection strictly rising, force rising */
    double x_m[FS_CURVE_MAX], f_N[FS_CURVE_MAX];
} fs_spring_law;

/* The linear two-sided law of stiffness k (what fs_spring_init gives every spring). */
fs_spring_law fs_spring_law_linear(double k_N_per_m);

/* 1 for a linear two-sided law: the spring of Table I, whose code path is the one before laws. */
int fs_spring_law_is_linear(const fs_spring_law *law);

/* The elastic force at deflection x, N (tension positive), and its slope there (the tangent
 * stiffness, N/m) when tangent is not NULL; at a curve's point or the bilinear stop, the slope on
 * the stretched side. A cable: 0 and 0 for x < 0; at x = 0 its taut stiffness. */
double fs_spring_law_force(const fs_spring_law *law, double x_m, double *tangent_N_per_m);

/* The force with a damper of c at deflection rate v: f(x) + c v, and for a cable 0 while x <= 0 and
 * never below 0. */
double fs_spring_law_total(const fs_spring_law *law, double x_m, double v_m_per_s, double c_Ns_per_m);

/* The elastic energy stored at deflection x, J: the integral of the force from 0 to x. */
double fs_spring_law_energy(const fs_spring_law *law, double x_m);

/* The law with its forces multiplied by s (a design's springs.scale): k, k2 and the curve's forces. */
void fs_spring_law_scale(fs_spring_law *law, double s);

/* The law's name ("linear", "progressive", "bilinear", "curve"), as a design file writes it. */
const char *fs_spring_law_name(const fs_spring_law *law);

#endif
