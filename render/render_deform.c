/* render_deform.c: the deformation view (fs_render_exaggerate): each foot body's displacement from
 * its neutral pose, in the ankle body's frame, multiplied by a factor.
 *
 * A pose is a rigid transform x -> R x + t (R from the unit quaternion q). For body b, its pose
 * relative to the ankle body a is A^-1 B, now and in neutral; the exaggerated relative pose has
 * translation t0 + F (t - t0) and rotation exp(F log(R R0^T)) R0; placed on the ankle body as it
 * is now, it gives E_b. Every point fixed to b moves by M_b = E_b B^-1 (the identity when F = 1 or
 * when b is where it was). */
#include "footsim/render/fs_render.h"

#include <math.h>
#include <string.h>

typedef struct pose {
    double q[4]; /* w, x, y, z */
    double t[3];
} pose;

static void qmul(const double a[4], const double b[4], double r[4])
{
    double t[4] = {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
                   a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                   a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
                   a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
    memcpy(r, t, sizeof t);
}

static void qconj(const double a[4], double r[4]) { r[0] = a[0], r[1] = -a[1], r[2] = -a[2], r[3] = -a[3]; }

/* r = q v q* (v a 3-vector). */
static void qrot(const double q[4], const double v[3], double r[3])
{
    double p[4] = {0, v[0], v[1], v[2]}, c[4], t[4];
    qconj(q, c);
    qmul(q, p, t);
    qmul(t, c, t);
    r[0] = t[1], r[1] = t[2], r[2] = t[3];
}

/* a then b: (a b)(x) = a(b(x)). */
static pose compose(const pose *a, const pose *b)
{
    pose r;
    qmul(a->q, b->q, r.q);
    qrot(a->q, b->t, r.t);
    for (int k = 0; k < 3; k++)
        r.t[k] += a->t[k];
    return r;
}

static pose inverse(const pose *a)
{
    pose r;
    qconj(a->q, r.q);
    qrot(r.q, a->t, r.t);
    for (int k = 0; k < 3; k++)
        r.t[k] = -r.t[k];
    return r;
}

static pose pose_of(const fs_scene_pose *p)
{
    pose r;
    double n = sqrt(p->quat[0] * p->quat[0] + p->quat[1] * p->quat[1] + p->quat[2] * p->quat[2] + p->quat[3] * p->quat[3]);
    for (int k = 0; k < 4; k++)
        r.q[k] = n > 0 ? p->quat[k] / n : (k == 0);
    memcpy(r.t, p->pos, sizeof r.t);
    return r;
}

/* The rotation q's angle multiplied by f about its own axis (q taken with w >= 0: the short way). */
static void qpow(const double q[4], double f, double r[4])
{
    double s = q[0] < 0 ? -1 : 1, v = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double half = atan2(v, s * q[0]);
    if (v < 1e-300) {
        r[0] = 1, r[1] = r[2] = r[3] = 0;
        return;
    }
    double sh = sin(f * half) / v;
    r[0] = cos(f * half);
    for (int k = 1; k < 4; k++)
        r[k] = s * q[k] * sh;
}

/* The body's neutral and present poses relative to the ankle body, exaggerated, as the motion
 * M = E B^-1 of its points. */
static pose body_motion(const fs_scene *neutral, const fs_scene *now, int b, double f)
{
    pose a0 = pose_of(&neutral->body[neutral->ankle_body]), a = pose_of(&now->body[now->ankle_body]);
    pose b0 = pose_of(&neutral->body[b]), bn = pose_of(&now->body[b]);
    pose ia0 = inverse(&a0), ia = inverse(&a);
    pose rel0 = compose(&ia0, &b0), rel = compose(&ia, &bn), ex;
    for (int k = 0; k < 3; k++)
        ex.t[k] = rel0.t[k] + f * (rel.t[k] - rel0.t[k]);
    double c[4], d[4], dp[4];
    qconj(rel0.q, c);
    qmul(rel.q, c, d); /* R R0^T */
    qpow(d, f, dp);
    qmul(dp, rel0.q, ex.q);
    pose e = compose(&a, &ex), ib = inverse(&bn);
    return compose(&e, &ib);
}

static void move_point(const pose *m, double p[3])
{
    double r[3];
    qrot(m->q, p, r);
    for (int k = 0; k < 3; k++)
        p[k] = r[k] + m->t[k];
}

static int valid_body(const fs_scene *s, int b) { return b >= 0 && b < s->nbodies; }

/* The body of the shape nearest p (its surface), or -1. */
static int nearest_body(const fs_scene *s, const double p[3])
{
    double best = INFINITY;
    int body = -1;
    for (int i = 0; i < s->nshapes; i++) {
        const fs_scene_shape *sh = &s->shape[i];
        double d = 0;
        for (int k = 0; k < 3; k++)
            d += (p[k] - sh->pos[k]) * (p[k] - sh->pos[k]);
        d = sqrt(d) - (sh->type == FS_SHAPE_SPHERE ? sh->size[0] : 0);
        if (d < best)
            best = d, body = sh->body;
    }
    return body;
}

void fs_render_exaggerate(const fs_scene *neutral, const fs_scene *now, double factor, fs_scene *out)
{
    if (out != now)
        *out = *now;
    if (factor == 1 || now->nbodies < 1 || neutral->nbodies != now->nbodies || !valid_body(now, now->ankle_body) ||
        now->ankle_body != neutral->ankle_body)
        return;
    pose m[FS_SCENE_MAX_BODIES];
    for (int b = 0; b < now->nbodies; b++)
        m[b] = body_motion(neutral, now, b, factor);
    for (int i = 0; i < out->ncontacts; i++) {
        int b = nearest_body(now, out->contact[i].pos);
        if (valid_body(out, b))
            move_point(&m[b], out->contact[i].pos);
    }
    for (int i = 0; i < out->nshapes; i++) {
        fs_scene_shape *sh = &out->shape[i];
        if (!valid_body(out, sh->body))
            continue;
        move_point(&m[sh->body], sh->pos);
        double q[4];
        qmul(m[sh->body].q, sh->quat, q);
        memcpy(sh->quat, q, sizeof q);
    }
    fs_scene_segment *seg[2] = {out->link, out->spring};
    int nseg[2] = {out->nlinks, out->nsprings};
    for (int kind = 0; kind < 2; kind++)
        for (int i = 0; i < nseg[kind]; i++) {
            if (valid_body(out, seg[kind][i].body1))
                move_point(&m[seg[kind][i].body1], seg[kind][i].p1);
            if (valid_body(out, seg[kind][i].body2))
                move_point(&m[seg[kind][i].body2], seg[kind][i].p2);
        }
    for (int b = 0; b < out->nbodies; b++) {
        move_point(&m[b], out->body[b].pos);
        double q[4];
        qmul(m[b].q, out->body[b].quat, q);
        memcpy(out->body[b].quat, q, sizeof q);
    }
}
