/* sim_spring.c: spring-damper joints, implicit (soft DBall, or a one-sided contact row for a cable)
 * and explicit (forces), of any law (fs_spring_law.h). */
#include "sim_spring.h"

#include <math.h>
#include <string.h>

void fs_spring_init(fs_spring *s, dWorldID world, fs_spring_impl impl, dBodyID body1, dBodyID body2,
                    const double p1[3], const double p2[3], double k, double c, double rest)
{
    memset(s, 0, sizeof *s);
    s->impl = impl;
    s->body1 = body1;
    s->body2 = body2;
    s->k = k;
    s->c = c;
    s->rest = rest;
    s->damping_correction = 1;
    s->law = fs_spring_law_linear(k);
    dBodyGetPosRelPoint(body1, p1[0], p1[1], p1[2], s->local1);
    if (body2)
        dBodyGetPosRelPoint(body2, p2[0], p2[1], p2[2], s->local2);
    else
        memcpy(s->local2, p2, 3 * sizeof(double));
    if (impl == FS_SPRING_IMPLICIT) {
        s->joint = dJointCreateDBall(world, 0);
        dJointAttach(s->joint, body1, body2);
        dJointSetDBallAnchor1(s->joint, p1[0], p1[1], p1[2]);
        dJointSetDBallAnchor2(s->joint, p2[0], p2[1], p2[2]);
        dJointSetDBallDistance(s->joint, rest);
    }
}

void fs_spring_anchors(const fs_spring *s, double p1[3], double p2[3])
{
    dVector3 a, b;
    dBodyGetRelPointPos(s->body1, s->local1[0], s->local1[1], s->local1[2], a);
    if (s->body2)
        dBodyGetRelPointPos(s->body2, s->local2[0], s->local2[1], s->local2[2], b);
    else
        memcpy(b, s->local2, sizeof b);
    memcpy(p1, a, 3 * sizeof(double));
    memcpy(p2, b, 3 * sizeof(double));
}

/* Anchor positions, the unit vector from anchor 1 to 2, the length and its rate. */
static double spring_line(const fs_spring *s, double p1[3], double p2[3], double u[3], double *rate)
{
    dVector3 v1, v2 = {0, 0, 0, 0};
    fs_spring_anchors(s, p1, p2);
    dBodyGetRelPointVel(s->body1, s->local1[0], s->local1[1], s->local1[2], v1);
    if (s->body2)
        dBodyGetRelPointVel(s->body2, s->local2[0], s->local2[1], s->local2[2], v2);
    double len = 0;
    for (int i = 0; i < 3; i++) {
        u[i] = p2[i] - p1[i];
        len += u[i] * u[i];
    }
    len = sqrt(len);
    double r = 0;
    for (int i = 0; i < 3; i++) {
        u[i] = len > 0 ? u[i] / len : 0;
        r += u[i] * (v2[i] - v1[i]);
    }
    *rate = r;
    return len;
}

void fs_spring_soft(double h, double k, double c, int correct, double *erp, double *cfm)
{
    double denom = h * k + (correct ? fmax(c - h * k, 0) : c);
    *erp = h * k / denom;
    *cfm = 1.0 / denom;
}

void fs_spring_set_law(fs_spring *s, const fs_spring_law *law)
{
    s->law = *law;
    if (fs_spring_law_is_linear(law)) {
        s->k = law->k_N_per_m;
        return;
    }
    fs_spring_law_force(law, 0, &s->k);
    s->step = 0; /* set afresh at the next step */
    if (s->impl == FS_SPRING_IMPLICIT && law->tension_only && !s->cable) {
        dJointDestroy(s->joint);
        s->joint = NULL;
        s->cable = dJointGroupCreate(0);
    }
}

void fs_spring_free(fs_spring *s)
{
    if (s->cable)
        dJointGroupDestroy(s->cable);
    s->cable = NULL;
}

/* The implicit row of a nonlinear law for the step h about to be taken, linearised at its start:
 * the tangent stiffness k_t (at least a thousandth of the stiffness at rest, so that a law flat
 * beyond a stop keeps a row; the force at the start is exact whatever k_t) with the rest length
 * shifted so that the row's force at the start is the law's, f(x) = k_t (d - (d - f(x) / k_t)). */
static void prepare_law(fs_spring *s, double h)
{
    double p1[3], p2[3], u[3], rate, kt;
    double len = spring_line(s, p1, p2, u, &rate);
    double x = len - s->rest;
    double f = fs_spring_law_force(&s->law, x, &kt);
    double k = fmax(kt, 1e-3 * s->k), erp, cfm;
    fs_spring_soft(h, k, s->c, s->damping_correction, &erp, &cfm);
    s->step = h;
    if (!s->cable) {
        dJointSetDBallDistance(s->joint, len - f / k);
        dJointSetDBallParam(s->joint, dParamERP, erp);
        dJointSetDBallParam(s->joint, dParamCFM, cfm);
        return;
    }
    /* the cable: a one-sided row while it starts the step taut, none while slack. ODE's contact row
       pushes body 1 along its normal, pos the point of action for both bodies: anchor 1 (any point
       on the line between the anchors gives both bodies the same moments), the normal toward
       anchor 2, the depth the shifted stretch f(x) / k plus the world's surface layer, which ODE
       takes off every contact's depth */
    dJointGroupEmpty(s->cable);
    s->cable_row = x > 0;
    if (x <= 0)
        return;
    dContact ct;
    memset(&ct, 0, sizeof ct);
    ct.surface.mode = dContactSoftERP | dContactSoftCFM;
    ct.surface.mu = 0; /* the normal row alone */
    ct.surface.soft_erp = erp;
    ct.surface.soft_cfm = cfm;
    dWorldID world = dBodyGetWorld(s->body1);
    for (int i = 0; i < 3; i++) {
        ct.geom.pos[i] = p1[i];
        ct.geom.normal[i] = u[i];
    }
    ct.geom.depth = f / k + dWorldGetContactSurfaceLayer(world);
    dJointID j = dJointCreateContact(world, s->cable, &ct);
    dJointAttach(j, s->body1, s->body2);
}

void fs_spring_prepare(fs_spring *s, double h)
{
    if (s->impl == FS_SPRING_IMPLICIT && !fs_spring_law_is_linear(&s->law)) {
        prepare_law(s, h);
        return;
    }
    if (s->impl == FS_SPRING_IMPLICIT) {
        if (s->step != h) {
            double erp, cfm;
            fs_spring_soft(h, s->k, s->c, s->damping_correction, &erp, &cfm);
            dJointSetDBallParam(s->joint, dParamERP, erp);
            dJointSetDBallParam(s->joint, dParamCFM, cfm);
            s->step = h;
        }
        return;
    }
    double p1[3], p2[3], u[3], rate;
    double len = spring_line(s, p1, p2, u, &rate);
    double f = fs_spring_law_is_linear(&s->law) ? s->k * (len - s->rest) + s->c * rate
                                                : fs_spring_law_total(&s->law, len - s->rest, rate, s->c);
    dBodyAddForceAtPos(s->body1, f * u[0], f * u[1], f * u[2], p1[0], p1[1], p1[2]);
    if (s->body2)
        dBodyAddForceAtPos(s->body2, -f * u[0], -f * u[1], -f * u[2], p2[0], p2[1], p2[2]);
}

fs_spring_state fs_spring_measure(const fs_spring *s)
{
    double p1[3], p2[3], u[3], rate;
    double len = spring_line(s, p1, p2, u, &rate);
    double stretch = len - s->rest;
    if (!fs_spring_law_is_linear(&s->law))
        return (fs_spring_state){len, rate, fs_spring_law_total(&s->law, stretch, rate, s->c),
                                 fs_spring_law_energy(&s->law, stretch)};
    return (fs_spring_state){len, rate, s->k * stretch + s->c * rate, 0.5 * s->k * stretch * stretch};
}
