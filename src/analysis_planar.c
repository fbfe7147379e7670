/* analysis_planar.c: one chain in its plane, heel and toe spheres rolling on the ground, solved
 * for static equilibrium by minimising its potential energy. It reads only the design and its
 * geometry (never ODE), so it is an independent prediction of what the ODE model must do. */
#include "footsim/fs_analysis.h"

#include <math.h>
#include <string.h>

#define DEG (M_PI / 180.0)

/* A point fixed on link k, in the link's frame: a along the link, b toward the sole. */
typedef struct local_pt { int link; double a, b; double dy; } local_pt;

typedef struct planar {
    double len[4], beta0[4];     /* heel, talus, metatarsal, phalanx */
    double r_heel, r_toe, r_ball, H0x, T0x;
    double mass[4];
    local_pt com[4];
    local_pt p1[3], p2[3];       /* spring anchors */
    double k[3], rest[3];
    int frictionless, nfree;     /* contact model, and how many angles are free */
    double load, gx, gz;         /* per-chain load (N) and gravity vector */
    double down[2];              /* the load's direction */
    fs_vec3 f, lat;              /* the chain plane's heading and its normal */
    fs_vec3 origin;              /* the chain's midfoot joint ... */
    double origin_x;             /* ... and its x in the plane */
} planar;

/* x in the chain's plane; exact for unsplayed chains, a projection for splayed ones. */
static double px(const planar *c, fs_vec3 p) { return fs_dot(fs_sub(p, c->origin), c->f) + c->origin_x; }

/* Link frame directions in the plane. */
static void dir(double beta, double e[2]) { e[0] = cos(beta); e[1] = sin(beta); }

/* Joint positions: H, A, M, B, T (x, z). */
typedef struct joint_set { double p[5][2]; } joint_set;

/* Joint positions for angles b. */
static void joints(const planar *c, const double b[4], joint_set *js)
{
    double (*J)[2] = js->p;
    J[0][0] = c->H0x - c->r_heel * (b[0] - c->beta0[0]);
    J[0][1] = c->r_heel;
    for (int k = 0; k < 4; k++) {
        double e[2];
        dir(b[k], e);
        J[k + 1][0] = J[k][0] + c->len[k] * e[0];
        J[k + 1][1] = J[k][1] + c->len[k] * e[1];
    }
}

static void place(const joint_set *js, const double b[4], local_pt p, double out[2])
{
    const double (*J)[2] = js->p;
    double e[2], n[2];
    dir(b[p.link], e);
    dir(b[p.link] - M_PI / 2, n);
    out[0] = J[p.link][0] + p.a * e[0] + p.b * n[0];
    out[1] = J[p.link][1] + p.a * e[1] + p.b * n[1];
}

/* Closes the loop: the toe sphere's centre at its radius above the ground. Pinned (rolling
 * without slip): the metatarsal and phalanx angles follow from the heel and talus angles.
 * Frictionless: the phalanx angle follows from the other three; the toe slides freely. */
static int close_loop(const planar *c, double b[4])
{
    if (c->frictionless) {
        double z = c->r_heel;
        for (int k = 0; k < 3; k++)
            z += c->len[k] * sin(b[k]);
        double s4 = (c->r_toe - z) / c->len[3];
        if (s4 < -1 || s4 > 1)
            return 0;
        b[3] = asin(s4);
        return 1;
    }
    for (int it = 0; it < 50; it++) {
        joint_set J;
        joints(c, b, &J);
        double r0 = J.p[4][0] - c->T0x + c->r_toe * (b[3] - c->beta0[3]);
        double r1 = J.p[4][1] - c->r_toe;
        if (fabs(r0) + fabs(r1) < 1e-15)
            return 1;
        double a00 = -c->len[2] * sin(b[2]), a01 = -c->len[3] * sin(b[3]) + c->r_toe;
        double a10 = c->len[2] * cos(b[2]), a11 = c->len[3] * cos(b[3]);
        double det = a00 * a11 - a01 * a10;
        if (fabs(det) < 1e-300)
            return 0;
        b[2] -= (a11 * r0 - a01 * r1) / det;
        b[3] -= (-a10 * r0 + a00 * r1) / det;
    }
    joint_set J;
    joints(c, b, &J);
    return fabs(J.p[4][1] - c->r_toe) < 1e-12;
}

static double spring_length(const planar *c, const joint_set *J, const double b[4], int i)
{
    double p[2], q[2];
    place(J, b, c->p1[i], p);
    place(J, b, c->p2[i], q);
    double dx = q[0] - p[0], dz = q[1] - p[1], dy = c->p2[i].dy - c->p1[i].dy;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Potential energy at the free angles q (heel, talus, and the metatarsal when frictionless);
 * fills all four angles in b, closing the loop from the neutral pose. NAN if it cannot close. */
static double energy(const planar *c, const double *q, double b[4])
{
    memcpy(b, c->beta0, 4 * sizeof(double));
    memcpy(b, q, (size_t)c->nfree * sizeof(double));
    if (!close_loop(c, b))
        return NAN;
    joint_set J;
    double E = 0;
    joints(c, b, &J);
    for (int i = 0; i < 3; i++) {
        double s = spring_length(c, &J, b, i) - c->rest[i];
        E += 0.5 * c->k[i] * s * s;
    }
    for (int k = 0; k < 4; k++) {
        double p[2];
        place(&J, b, c->com[k], p);
        E -= c->mass[k] * (c->gx * p[0] + c->gz * p[1]);
    }
    return E - c->load * (c->down[0] * J.p[1][0] + c->down[1] * J.p[1][1]);
}

static void gradient(const planar *c, const double *q, double *grad)
{
    const double h = 1e-7;
    for (int i = 0; i < c->nfree; i++) {
        double qp[3], qm[3], b[4];
        memcpy(qp, q, sizeof qp);
        memcpy(qm, q, sizeof qm);
        qp[i] += h;
        qm[i] -= h;
        grad[i] = (energy(c, qp, b) - energy(c, qm, b)) / (2 * h);
    }
}

static void hessian(const planar *c, const double *q, double H[3][3])
{
    const double h = 1e-5;
    for (int j = 0; j < c->nfree; j++) {
        double qp[3], qm[3], gp[3], gm[3];
        memcpy(qp, q, sizeof qp);
        memcpy(qm, q, sizeof qm);
        qp[j] += h;
        qm[j] -= h;
        gradient(c, qp, gp);
        gradient(c, qm, gm);
        for (int i = 0; i < c->nfree; i++)
            H[i][j] = (gp[i] - gm[i]) / (2 * h);
    }
    for (int i = 0; i < c->nfree; i++)
        for (int j = 0; j < i; j++)
            H[i][j] = H[j][i] = 0.5 * (H[i][j] + H[j][i]);
}

/* Cholesky factorisation in place: 1 if A (n x n) is positive definite. */
static int cholesky(double A[3][3], int n)
{
    for (int j = 0; j < n; j++) {
        double d = A[j][j];
        for (int k = 0; k < j; k++)
            d -= A[j][k] * A[j][k];
        if (!(d > 0))
            return 0;
        A[j][j] = sqrt(d);
        for (int i = j + 1; i < n; i++) {
            double v = A[i][j];
            for (int k = 0; k < j; k++)
                v -= A[i][k] * A[j][k];
            A[i][j] = v / A[j][j];
        }
    }
    return 1;
}

/* Solves A x = r for positive definite A; 0 if it is not. */
static int solve_spd(const double A[3][3], const double *r, double *x, int n)
{
    double L[3][3];
    memcpy(L, A, sizeof L);
    if (!cholesky(L, n))
        return 0;
    double y[3];
    for (int i = 0; i < n; i++) {
        y[i] = r[i];
        for (int k = 0; k < i; k++)
            y[i] -= L[i][k] * y[k];
        y[i] /= L[i][i];
    }
    for (int i = n - 1; i >= 0; i--) {
        x[i] = y[i];
        for (int k = i + 1; k < n; k++)
            x[i] -= L[k][i] * x[k];
        x[i] /= L[i][i];
    }
    return 1;
}

/* A world point on body `link`, in that link's planar frame at the neutral pose. */
static local_pt to_local(const planar *c, int link, const joint_set *js, fs_vec3 p)
{
    const double (*J0)[2] = js->p;
    double e[2], n[2];
    dir(c->beta0[link], e);
    dir(c->beta0[link] - M_PI / 2, n);
    double dx = px(c, p) - J0[link][0], dz = p.z - J0[link][1];
    return (local_pt){link, dx * e[0] + dz * e[1], dx * n[0] + dz * n[1], fs_dot(fs_sub(p, c->origin), c->lat)};
}

static void setup(planar *c, const fs_design_def *d, const fs_foot_geom *g, int i, const fs_planar_load *load)
{
    double gravity = load->gravity_m_per_s2, tilt = load->tilt_rad;
    memset(c, 0, sizeof *c);
    double psi = d->splay_deg[i] * DEG, s = d->scale[i];
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
    joint_set J0;
    joints(c, beta, &J0);
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
        c->mass[k] = g->body[bodies[k]].mass_kg * share[k];
        c->com[k] = to_local(c, k, &J0, g->body[bodies[k]].com);
    }
    for (int k = 0; k < 3; k++) {
        const fs_spring_geom *q = &sp[g->chain[i].spring[k]];
        c->p1[k] = to_local(c, link_of[q->body1], &J0, q->p1);
        c->p2[k] = to_local(c, link_of[q->body2], &J0, q->p2);
        c->k[k] = q->k_N_per_m;
        c->rest[k] = q->rest_length_m;
    }
    c->load = load->load_N / FS_CHAINS;
    c->frictionless = load->frictionless;
    c->nfree = c->frictionless ? 3 : 2;
    c->gx = gravity * sin(tilt);
    c->gz = -gravity * cos(tilt);
    c->down[0] = sin(tilt);
    c->down[1] = -cos(tilt);
}

fs_status fs_planar_equilibrium(const fs_design_def *d, const fs_foot_geom *g, int chain, const fs_planar_load *load,
                                fs_planar_result *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    if (g->kind != FS_FOOT_BIOMIMETIC)
        return fs_fail(err, FS_BAD_INPUT, "the planar model is for the biomimetic foot only");
    if (load->frictionless && load->tilt_rad != 0)
        return fs_fail(err, FS_BAD_INPUT, "a tilted load on frictionless ground has no equilibrium: the foot slides");
    planar c;
    setup(&c, d, g, chain, load);
    double q[3] = {c.beta0[0], c.beta0[1], c.beta0[2]}, b[4];
    double H[3][3], grad[3], dq[3];
    /* Newton on the energy's gradient; its finite differences resolve angles to about 1e-9 rad */
    const double limit = 0.05, tolerance = 1e-9;
    for (int it = 0; it < 200 && !out->converged; it++) {
        gradient(&c, q, grad);
        hessian(&c, q, H);
        if (!solve_spd((const double(*)[3])H, grad, dq, c.nfree)) {
            /* not convex here: go downhill along the gradient instead */
            double norm = 0;
            for (int i = 0; i < c.nfree; i++)
                norm += grad[i] * grad[i];
            norm = sqrt(norm);
            if (!(norm > 0))
                break;
            for (int i = 0; i < c.nfree; i++)
                dq[i] = limit * grad[i] / norm;
        }
        double step = 0;
        for (int i = 0; i < c.nfree; i++)
            step = fmax(step, fabs(dq[i]));
        double scale = step > limit ? limit / step : 1;
        for (int i = 0; i < c.nfree; i++)
            q[i] -= scale * dq[i];
        out->converged = step < tolerance;
    }
    if (!isfinite(energy(&c, q, b)))
        out->converged = 0;
    hessian(&c, q, H);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            out->K_reduced[i][j] = H[i][j];
    double L[3][3];
    memcpy(L, H, sizeof L);
    out->stable = cholesky(L, c.nfree);
    joint_set J, J0;
    joints(&c, b, &J);
    joints(&c, c.beta0, &J0);
    out->ankle_drop_m = J0.p[1][1] - J.p[1][1];
    out->ankle_joint_rad = (b[1] - b[0]) - (c.beta0[1] - c.beta0[0]);
    out->midfoot_rad = (b[2] - b[1]) - (c.beta0[2] - c.beta0[1]);
    out->mtp_rad = (b[3] - b[2]) - (c.beta0[3] - c.beta0[2]);
    out->ball_clearance_m = J.p[3][1] - c.r_ball;
    for (int k = 0; k < 3; k++)
        out->spring_force_N[k] = c.k[k] * (spring_length(&c, &J, b, k) - c.rest[k]);
    return FS_OK;
}
