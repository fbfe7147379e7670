/* model_spring_law.c: the spring laws' forces, tangents and energies (fs_spring_law.h). */
#include "footsim/model/fs_spring_law.h"

#include <math.h>
#include <string.h>

fs_spring_law fs_spring_law_linear(double k)
{
    fs_spring_law law;
    memset(&law, 0, sizeof law);
    law.kind = FS_LAW_LINEAR;
    law.k_N_per_m = k;
    return law;
}

int fs_spring_law_is_linear(const fs_spring_law *law) { return law->kind == FS_LAW_LINEAR && !law->tension_only; }

/* The curve's segment i (points i and i + 1) that x falls in, the end segments extended. */
static int curve_segment(const fs_spring_law *law, double x)
{
    int i = 0;
    while (i + 2 < law->npoints && x >= law->x_m[i + 1])
        i++;
    return i;
}

static double curve_force(const fs_spring_law *law, double x, double *slope)
{
    int i = curve_segment(law, x);
    double s = (law->f_N[i + 1] - law->f_N[i]) / (law->x_m[i + 1] - law->x_m[i]);
    if (slope)
        *slope = s;
    return law->f_N[i] + s * (x - law->x_m[i]);
}

/* The integral of the curve's force from a to b, a and b within one segment or its extension. */
static double curve_piece(const fs_spring_law *law, double a, double b)
{
    double fa = curve_force(law, a, NULL), fb = curve_force(law, b, NULL);
    return 0.5 * (fa + fb) * (b - a);
}

/* The integral of the curve's force from 0 to x: segment by segment (exact: linear pieces). */
static double curve_energy(const fs_spring_law *law, double x)
{
    double E = 0, at = 0;
    if (x >= 0) {
        for (int i = 0; i < law->npoints; i++)
            if (law->x_m[i] > at && law->x_m[i] < x) {
                E += curve_piece(law, at, law->x_m[i]);
                at = law->x_m[i];
            }
    } else {
        for (int i = law->npoints - 1; i >= 0; i--)
            if (law->x_m[i] < at && law->x_m[i] > x) {
                E += curve_piece(law, at, law->x_m[i]);
                at = law->x_m[i];
            }
    }
    return E + curve_piece(law, at, x);
}

double fs_spring_law_force(const fs_spring_law *law, double x, double *tangent)
{
    double k = law->k_N_per_m, f, t;
    if (law->tension_only && x < 0) {
        if (tangent)
            *tangent = 0;
        return 0;
    }
    switch (law->kind) {
    case FS_LAW_PROGRESSIVE: {
        double r = x / law->x0_m;
        f = k * x * (1 + r * r / 3);
        t = k * (1 + r * r);
        break;
    }
    case FS_LAW_BILINEAR: {
        double a = fabs(x), s = law->stop_m;
        if (a <= s && !(a == s && x > 0)) { /* at the stop on the stretched side: k2's slope */
            f = k * x;
            t = k;
        } else {
            f = copysign(k * s + law->k2_N_per_m * (a - s), x);
            t = law->k2_N_per_m;
        }
        break;
    }
    case FS_LAW_CURVE: f = curve_force(law, x, &t); break;
    default:
        f = k * x;
        t = k;
    }
    if (tangent)
        *tangent = t;
    return f;
}

double fs_spring_law_total(const fs_spring_law *law, double x, double v, double c)
{
    if (law->tension_only && x <= 0)
        return 0;
    double f = fs_spring_law_force(law, x, NULL) + c * v;
    return law->tension_only ? fmax(f, 0) : f;
}

double fs_spring_law_energy(const fs_spring_law *law, double x)
{
    double k = law->k_N_per_m;
    if (law->tension_only && x <= 0)
        return 0;
    switch (law->kind) {
    case FS_LAW_PROGRESSIVE: {
        double r = x / law->x0_m;
        return k * x * x * (0.5 + r * r / 12);
    }
    case FS_LAW_BILINEAR: {
        double a = fabs(x), s = law->stop_m;
        if (a <= s)
            return 0.5 * k * x * x;
        return 0.5 * k * s * s + (a - s) * (k * s + 0.5 * law->k2_N_per_m * (a - s));
    }
    case FS_LAW_CURVE: return curve_energy(law, x);
    default: return 0.5 * k * x * x;
    }
}

void fs_spring_law_scale(fs_spring_law *law, double s)
{
    law->k_N_per_m *= s;
    law->k2_N_per_m *= s;
    for (int i = 0; i < law->npoints; i++)
        law->f_N[i] *= s;
}

const char *fs_spring_law_name(const fs_spring_law *law)
{
    static const char *const names[] = {"linear", "progressive", "bilinear", "curve"};
    return law->kind >= 0 && law->kind <= FS_LAW_CURVE ? names[law->kind] : "?";
}
