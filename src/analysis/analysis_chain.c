/* analysis_chain.c: one toe chain in its plane, from the design and its geometry (never ODE). */
#include "analysis_chain.h"

#include <math.h>
#include <string.h>

#define DEG (M_PI / 180.0)


/* x in the chain's plane; exact for unsplayed chains, a projection for splayed ones. */
static double px(const fs_chain2d *c, fs_vec3 p) { return fs_dot(fs_sub(p, c->origin), c->f) + c->origin_x; }

/* Link frame directions in the plane. */
static void dir(double beta, double e[2]) { e[0] = cos(beta); e[1] = sin(beta); }

/* Joint positions for angles b. */
void fs_chain2d_joints(const fs_chain2d *c, const double b[4], fs_chain_joints *js)
{
    double (*J)[2] = js->p;
    J[0][0] = c->H0x - (c->rolling ? c->r_heel * (b[0] - c->beta0[0]) : 0);
    J[0][1] = c->r_heel;
    for (int k = 0; k < 4; k++) {
        double e[2];
        dir(b[k], e);
        J[k + 1][0] = J[k][0] + c->len[k] * e[0];
        J[k + 1][1] = J[k][1] + c->len[k] * e[1];
    }
}

void fs_chain2d_place(const fs_chain_joints *js, const double b[4], fs_chain_pt p, double out[2])
{
    const double (*J)[2] = js->p;
    double e[2], n[2];
    dir(b[p.link], e);
    dir(b[p.link] - M_PI / 2, n);
    out[0] = J[p.link][0] + p.a * e[0] + p.b * n[0];
    out[1] = J[p.link][1] + p.a * e[1] + p.b * n[1];
}

/* A world point on body `link`, in that link's planar frame at the neutral pose. */
static fs_chain_pt to_local(const fs_chain2d *c, int link, const fs_chain_joints *js, fs_vec3 p)
{
    const double (*J0)[2] = js->p;
    double e[2], n[2];
    dir(c->beta0[link], e);
    dir(c->beta0[link] - M_PI / 2, n);
    double dx = px(c, p) - J0[link][0], dz = p.z - J0[link][1];
    return (fs_chain_pt){link, dx * e[0] + dz * e[1], dx * n[0] + dz * n[1], fs_dot(fs_sub(p, c->origin), c->lat)};
}

void fs_chain2d_setup(fs_chain2d *c, const fs_design_def *d, const fs_foot_geom *g, int i, double load_N,
                      double gravity, double tilt)
{
    memset(c, 0, sizeof *c);
    double psi = fs_design_splay_deg(d, i) * DEG, s = fs_design_chain_scale(d, i);
    c->f = fs_v3(cos(psi), sin(psi), 0);
    c->lat = fs_v3(-sin(psi), cos(psi), 0);
    double beta[4] = {d->heel_deg * DEG, d->talus_deg * DEG, g->chain[i].metatarsal_deg * DEG, d->toe_deg * DEG};
    double len[4] = {d->l1_m, d->l2_m, s * d->l3_m, s * d->l4_m};
    memcpy(c->beta0, beta, sizeof beta);
    memcpy(c->len, len, sizeof len);
    c->r_heel = d->heel_radius_m;
    c->r_toe = s * d->toe_radius_m;
    c->r_ball = s * d->ball_radius_m;
    c->H0x = 0;
    c->rolling = 1;
    fs_chain_joints J0;
    fs_chain2d_joints(c, beta, &J0);
    c->T0x = J0.p[4][0];
    c->origin = g->chain[i].midfoot;
    c->origin_x = J0.p[2][0];
    const fs_spring_geom *sp = g->spring;
    int link_of[FS_MAX_BODIES];
    link_of[FS_BODY_HEEL] = 0;
    link_of[FS_BODY_TALUS] = 1;
    link_of[g->chain[i].metatarsal] = 2;
    link_of[g->chain[i].phalanx] = 3;
    int bodies[4] = {FS_BODY_HEEL, FS_BODY_TALUS, g->chain[i].metatarsal, g->chain[i].phalanx};
    double share[4] = {1.0 / FS_CHAINS, 1.0 / FS_CHAINS, 1, 1};
    for (int k = 0; k < 4; k++) {
        const fs_body_geom *body = &g->body[bodies[k]];
        c->mass[k] = body->mass_kg * share[k];
        fs_vec3 Il = fs_v3(body->inertia[0] * c->lat.x + body->inertia[1] * c->lat.y + body->inertia[2] * c->lat.z,
                           body->inertia[3] * c->lat.x + body->inertia[4] * c->lat.y + body->inertia[5] * c->lat.z,
                           body->inertia[6] * c->lat.x + body->inertia[7] * c->lat.y + body->inertia[8] * c->lat.z);
        c->inertia[k] = fs_dot(c->lat, Il) * share[k];
        c->com[k] = to_local(c, k, &J0, g->body[bodies[k]].com);
    }
    for (int k = 0; k < 3; k++) {
        const fs_spring_geom *q = &sp[g->chain[i].spring[k]];
        c->p1[k] = to_local(c, link_of[q->body1], &J0, q->p1);
        c->p2[k] = to_local(c, link_of[q->body2], &J0, q->p2);
        c->k[k] = q->k_N_per_m;
        c->law[k] = q->law;
        c->c[k] = q->c_Ns_per_m;
        c->rest[k] = q->rest_length_m;
    }
    c->load = load_N / FS_CHAINS;
    c->gx = gravity * sin(tilt);
    c->gz = -gravity * cos(tilt);
    c->down[0] = sin(tilt);
    c->down[1] = -cos(tilt);
}

