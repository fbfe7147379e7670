/* analysis_reference.c: the paper's dynamic model (Sec. IV) of one chain in its plane, heel and
 * toe pinned at their sphere centres: the ground truth the ODE model is measured against.
 *
 * Coordinates: the four link directions beta (analysis_chain.h); the heel and talus angles are
 * the independent pair q, the metatarsal and phalanx angles follow in closed form from the loop
 * (the phalanx's end on the toe pin). With G = d(beta)/dq and beta'' = G q'' + gamma, the open
 * chain's equations M beta'' + c = Q projected by virtual work give
 *     (G^T M G) q'' = G^T (Q - c - M gamma),
 * integrated by GSL's rk8pd. It reads only the design and its geometry; it shares nothing with ODE. */
#include "footsim/analysis/fs_analysis.h"

#include "analysis_chain.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <string.h>

#define DEG (M_PI / 180.0)

typedef struct chain_dyn {
    fs_chain2d c;
    double H[2], T[2];  /* the heel and toe pins */
    double branch;      /* +1 or -1: which of the loop's two closures the neutral pose is */
    double ramp_s;
} chain_dyn;

/* One pose with its velocities and everything derived from them. */
typedef struct pose {
    double b[4], bd[4];  /* link directions and their rates */
    double G[4][2];      /* d(beta)/dq */
    double gamma[4];     /* beta'' = G q'' + gamma */
    fs_chain_joints J;
} pose;

static void e_of(double beta, double e[2]) { e[0] = cos(beta); e[1] = sin(beta); }

/* The metatarsal and phalanx directions that put the phalanx's end on the toe pin. */
static int close_loop(const chain_dyn *m, double b[4], double branch)
{
    const fs_chain2d *c = &m->c;
    double e0[2], e1[2];
    e_of(b[0], e0);
    e_of(b[1], e1);
    double P[2] = {m->H[0] + c->len[0] * e0[0] + c->len[1] * e1[0], m->H[1] + c->len[0] * e0[1] + c->len[1] * e1[1]};
    double d[2] = {m->T[0] - P[0], m->T[1] - P[1]};
    double D = hypot(d[0], d[1]);
    double cosA = (c->len[2] * c->len[2] + D * D - c->len[3] * c->len[3]) / (2 * c->len[2] * D);
    if (!(D > 0) || !(fabs(cosA) <= 1))
        return 0;
    b[2] = atan2(d[1], d[0]) + branch * acos(cosA);
    double e2[2];
    e_of(b[2], e2);
    b[3] = atan2(m->T[1] - P[1] - c->len[2] * e2[1], m->T[0] - P[0] - c->len[2] * e2[0]);
    return 1;
}

/* Angles near enough: the same direction modulo a turn. */
static double angle_diff(double a, double b) { return remainder(a - b, 2 * M_PI); }

/* Fills the pose for independent angles q and rates qd: the loop, G, gamma, the joints. */
static int make_pose(const chain_dyn *m, const double q[2], const double qd[2], pose *p)
{
    const fs_chain2d *c = &m->c;
    p->b[0] = q[0];
    p->b[1] = q[1];
    if (!close_loop(m, p->b, m->branch))
        return 0;
    /* the loop's velocity equations: A (b2', b3') = -B (b0', b1'), columns l_k e'(b_k) */
    double ep[4][2];
    for (int k = 0; k < 4; k++) {
        ep[k][0] = -c->len[k] * sin(p->b[k]);
        ep[k][1] = c->len[k] * cos(p->b[k]);
    }
    double det = ep[2][0] * ep[3][1] - ep[3][0] * ep[2][1];
    if (fabs(det) < 1e-18)
        return 0;
    double Ainv[2][2] = {{ep[3][1] / det, -ep[3][0] / det}, {-ep[2][1] / det, ep[2][0] / det}};
    memset(p->G, 0, sizeof p->G);
    p->G[0][0] = p->G[1][1] = 1;
    for (int j = 0; j < 2; j++)
        for (int r = 0; r < 2; r++)
            p->G[2 + r][j] = -(Ainv[r][0] * ep[j][0] + Ainv[r][1] * ep[j][1]);
    for (int k = 0; k < 4; k++)
        p->bd[k] = p->G[k][0] * qd[0] + p->G[k][1] * qd[1];
    /* accelerations: A (b2'', b3'') = sum_k l_k e(b_k) b_k'^2 - B (b0'', b1'') */
    double s[2] = {0, 0};
    for (int k = 0; k < 4; k++) {
        s[0] += c->len[k] * cos(p->b[k]) * p->bd[k] * p->bd[k];
        s[1] += c->len[k] * sin(p->b[k]) * p->bd[k] * p->bd[k];
    }
    p->gamma[0] = p->gamma[1] = 0;
    for (int r = 0; r < 2; r++)
        p->gamma[2 + r] = Ainv[r][0] * s[0] + Ainv[r][1] * s[1];
    fs_chain2d_joints(c, p->b, &p->J);
    return 1;
}

/* The segments from the heel pin to point pt: r[j] for the links j <= pt.link. */
static void segments(const chain_dyn *m, const pose *p, fs_chain_pt pt, double r[4][2])
{
    const fs_chain2d *c = &m->c;
    for (int j = 0; j < pt.link; j++) {
        r[j][0] = c->len[j] * cos(p->b[j]);
        r[j][1] = c->len[j] * sin(p->b[j]);
    }
    double e[2], n[2];
    e_of(p->b[pt.link], e);
    e_of(p->b[pt.link] - M_PI / 2, n);
    r[pt.link][0] = pt.a * e[0] + pt.b * n[0];
    r[pt.link][1] = pt.a * e[1] + pt.b * n[1];
}

/* Adds a force F at point pt to the generalised forces Q (virtual work: F . dp/dbeta_j). */
static void add_force(double r[4][2], int link, const double F[2], double Q[4])
{
    for (int j = 0; j <= link; j++)
        Q[j] += F[0] * -r[j][1] + F[1] * r[j][0];
}

/* A point's position and velocity. */
static void point_motion(const chain_dyn *m, const pose *p, double r[4][2], int link, double x[2], double v[2])
{
    x[0] = m->H[0];
    x[1] = m->H[1];
    v[0] = v[1] = 0;
    for (int j = 0; j <= link; j++) {
        x[0] += r[j][0];
        x[1] += r[j][1];
        v[0] += -r[j][1] * p->bd[j];
        v[1] += r[j][0] * p->bd[j];
    }
}

/* Spring i: its length and rate, the anchors' segments. */
typedef struct spring_state { double L, Ld, u[2], rp[4][2], rq[4][2]; } spring_state;

static void spring(const chain_dyn *m, const pose *p, int i, spring_state *s)
{
    const fs_chain2d *c = &m->c;
    double xp[2], vp[2], xq[2], vq[2];
    segments(m, p, c->p1[i], s->rp);
    segments(m, p, c->p2[i], s->rq);
    point_motion(m, p, s->rp, c->p1[i].link, xp, vp);
    point_motion(m, p, s->rq, c->p2[i].link, xq, vq);
    double d[2] = {xq[0] - xp[0], xq[1] - xp[1]}, dy = c->p2[i].dy - c->p1[i].dy;
    s->L = sqrt(d[0] * d[0] + d[1] * d[1] + dy * dy);
    s->u[0] = d[0] / s->L;
    s->u[1] = d[1] / s->L;
    s->Ld = s->u[0] * (vq[0] - vp[0]) + s->u[1] * (vq[1] - vp[1]);
}

static double load_now(const chain_dyn *m, double t)
{
    return m->c.load * (m->ramp_s > 0 && t < m->ramp_s ? t / m->ramp_s : 1.0);
}

/* The open chain's mass matrix M, velocity terms c and generalised forces Q at time t. */
static void open_chain(const chain_dyn *m, const pose *p, double t, double M[4][4], double cv[4], double Q[4])
{
    const fs_chain2d *c = &m->c;
    memset(M, 0, 16 * sizeof(double));
    memset(cv, 0, 4 * sizeof(double));
    memset(Q, 0, 4 * sizeof(double));
    /* inertia, velocity terms and gravity of each link */
    for (int k = 0; k < 4; k++) {
        double r[4][2];
        segments(m, p, c->com[k], r);
        double acc[2] = {0, 0}; /* the COM's acceleration from the rates alone: -sum r_j bd_j^2 */
        for (int j = 0; j <= k; j++) {
            acc[0] -= r[j][0] * p->bd[j] * p->bd[j];
            acc[1] -= r[j][1] * p->bd[j] * p->bd[j];
        }
        for (int i = 0; i <= k; i++) {
            for (int j = 0; j <= k; j++)
                M[i][j] += c->mass[k] * (r[i][0] * r[j][0] + r[i][1] * r[j][1]);
            cv[i] += c->mass[k] * (-r[i][1] * acc[0] + r[i][0] * acc[1]);
        }
        M[k][k] += c->inertia[k];
        double F[2] = {c->mass[k] * c->gx, c->mass[k] * c->gz};
        add_force(r, k, F, Q);
    }
    /* the load at the ankle, the end of the heel link */
    double r[4][2];
    segments(m, p, (fs_chain_pt){0, c->len[0], 0, 0}, r);
    double f = load_now(m, t), F[2] = {f * c->down[0], f * c->down[1]};
    add_force(r, 0, F, Q);
    /* spring-dampers, tension positive */
    for (int i = 0; i < 3; i++) {
        spring_state s;
        spring(m, p, i, &s);
        double T = fs_spring_law_total(&c->law[i], s.L - c->rest[i], s.Ld, c->c[i]);
        double Fp[2] = {T * s.u[0], T * s.u[1]}, Fq[2] = {-Fp[0], -Fp[1]};
        add_force(s.rp, c->p1[i].link, Fp, Q);
        add_force(s.rq, c->p2[i].link, Fq, Q);
    }
}

/* The reduced mass matrix G^T M G and right-hand side G^T (Q - c - M gamma). */
static void reduced(const pose *p, double M[4][4], const double cv[4], const double Q[4], double Mr[2][2],
                    double rhs[2])
{
    double f[4];
    for (int i = 0; i < 4; i++) {
        f[i] = Q[i] - cv[i];
        for (int j = 0; j < 4; j++)
            f[i] -= M[i][j] * p->gamma[j];
    }
    for (int a = 0; a < 2; a++) {
        rhs[a] = 0;
        for (int i = 0; i < 4; i++)
            rhs[a] += p->G[i][a] * f[i];
        for (int b = 0; b < 2; b++) {
            Mr[a][b] = 0;
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                    Mr[a][b] += p->G[i][a] * M[i][j] * p->G[j][b];
        }
    }
}

/* GSL's right-hand side: y = (q0, q1, q0', q1'). */
static int derivs(double t, const double y[], double dydt[], void *params)
{
    const chain_dyn *m = params;
    pose p;
    if (!make_pose(m, y, y + 2, &p))
        return GSL_EBADFUNC;
    double M[4][4], cv[4], Q[4], Mr[2][2], rhs[2];
    open_chain(m, &p, t, M, cv, Q);
    reduced(&p, M, cv, Q, Mr, rhs);
    double det = Mr[0][0] * Mr[1][1] - Mr[0][1] * Mr[1][0];
    dydt[0] = y[2];
    dydt[1] = y[3];
    dydt[2] = (Mr[1][1] * rhs[0] - Mr[0][1] * rhs[1]) / det;
    dydt[3] = (-Mr[1][0] * rhs[0] + Mr[0][0] * rhs[1]) / det;
    return GSL_SUCCESS;
}

/* Chain `chain` with its pins where the neutral pose puts them. */
static fs_status setup(chain_dyn *m, const fs_design_def *d, const fs_foot_geom *g, int chain, double load_N,
                       double gravity, double tilt, fs_error *err)
{
    memset(m, 0, sizeof *m);
    if (g->kind != FS_FOOT_BIOMIMETIC)
        return fs_fail(err, FS_BAD_INPUT, "the reference model is for the biomimetic foot only");
    if (chain < 0 || chain >= FS_CHAINS)
        return fs_fail(err, FS_BAD_INPUT, "chain %d does not exist; give 1 to %d", chain + 1, FS_CHAINS);
    if (fs_design_splay_deg(d, chain) != 0)
        return fs_fail(err, FS_BAD_INPUT,
                       "chain %d is splayed by %g deg: the planar reference needs a chain in the heel's plane "
                       "(chains.splay_deg = 0 for it)", chain + 1, fs_design_splay_deg(d, chain));
    fs_chain2d_setup(&m->c, d, g, chain, load_N, gravity, tilt);
    m->c.rolling = 0;
    fs_chain_joints J0;
    fs_chain2d_joints(&m->c, m->c.beta0, &J0);
    memcpy(m->H, J0.p[0], sizeof m->H);
    memcpy(m->T, J0.p[4], sizeof m->T);
    /* which closure the design's neutral pose is */
    double b[4] = {m->c.beta0[0], m->c.beta0[1], 0, 0};
    m->branch = 1;
    if (!close_loop(m, b, 1) || fabs(angle_diff(b[2], m->c.beta0[2])) > 1e-9)
        m->branch = -1;
    return FS_OK;
}

/* What a pose is worth to the caller: the ankle in world coordinates, joint angles, energy. */
static void observe(const chain_dyn *m, const pose *p, double t, fs_reference_state *out)
{
    const fs_chain2d *c = &m->c;
    out->t_s = t;
    double xp = p->J.p[1][0] - c->origin_x;
    out->ankle_m[0] = c->origin.x + xp * c->f.x;
    out->ankle_m[1] = c->origin.y + xp * c->f.y;
    out->ankle_m[2] = p->J.p[1][1];
    for (int k = 0; k < 3; k++)
        out->joint_rad[k] = angle_diff(p->b[k + 1] - p->b[k], c->beta0[k + 1] - c->beta0[k]);
    double M[4][4], cv[4], Q[4];
    open_chain(m, p, t, M, cv, Q);
    double E = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            E += 0.5 * p->bd[i] * M[i][j] * p->bd[j];
    for (int k = 0; k < 4; k++) {
        double r[4][2], x[2], v[2];
        segments(m, p, c->com[k], r);
        point_motion(m, p, r, k, x, v);
        E -= c->mass[k] * (c->gx * x[0] + c->gz * x[1]);
    }
    for (int i = 0; i < 3; i++) {
        spring_state s;
        spring(m, p, i, &s);
        E += fs_spring_law_energy(&c->law[i], s.L - c->rest[i]);
    }
    double f = load_now(m, t);
    out->energy_J = E - f * (c->down[0] * p->J.p[1][0] + c->down[1] * p->J.p[1][1]);
}

fs_status fs_reference_run(const fs_design_def *d, const fs_foot_geom *g, const fs_reference_def *def, double dt_s,
                           int n, fs_reference_state *out, fs_error *err)
{
    chain_dyn m;
    fs_status s = setup(&m, d, g, def->chain, def->load_N, def->gravity_m_per_s2, def->tilt_rad, err);
    if (s != FS_OK)
        return s;
    if (!(def->tolerance > 0) || !(dt_s > 0) || n < 1)
        return fs_fail(err, FS_BAD_INPUT, "the reference needs a tolerance > 0, a sample interval > 0 and samples");
    m.ramp_s = def->ramp_s;
    gsl_set_error_handler_off();
    double y[4] = {m.c.beta0[0] + def->q0_offset_rad[0], m.c.beta0[1] + def->q0_offset_rad[1], 0, 0};
    gsl_odeiv2_system sys = {derivs, NULL, 4, &m};
    gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-7, def->tolerance,
                                                           def->tolerance);
    if (!drv)
        return fs_fail(err, FS_NO_MEMORY, "the reference integrator could not be set up (out of memory)");
    double t = 0;
    for (int i = 0; i < n && s == FS_OK; i++) {
        double t1 = i * dt_s;
        /* the load's ramp has a kink: land on it so that no step straddles it */
        int status = GSL_SUCCESS;
        if (t < m.ramp_s && t1 > m.ramp_s)
            status = gsl_odeiv2_driver_apply(drv, &t, m.ramp_s, y);
        if (status == GSL_SUCCESS && t1 > t)
            status = gsl_odeiv2_driver_apply(drv, &t, t1, y);
        pose p;
        if (status != GSL_SUCCESS || !make_pose(&m, y, y + 2, &p))
            s = fs_fail(err, FS_NUMERICAL, "the reference chain cannot move on at t = %.6f s (GSL status %d): the "
                        "load folds the loop past where it closes", t, status);
        else
            observe(&m, &p, t, &out[i]);
    }
    gsl_odeiv2_driver_free(drv);
    return s;
}

/* dL/dq of every spring at pose p (rates zero). */
static void spring_gradients(const chain_dyn *m, const pose *p, double w[3][2])
{
    const fs_chain2d *c = &m->c;
    for (int i = 0; i < 3; i++) {
        spring_state s;
        spring(m, p, i, &s);
        double dLdb[4] = {0, 0, 0, 0};
        for (int j = 0; j <= c->p2[i].link; j++)
            dLdb[j] += s.u[0] * -s.rq[j][1] + s.u[1] * s.rq[j][0];
        for (int j = 0; j <= c->p1[i].link; j++)
            dLdb[j] -= s.u[0] * -s.rp[j][1] + s.u[1] * s.rp[j][0];
        for (int a = 0; a < 2; a++) {
            w[i][a] = 0;
            for (int j = 0; j < 4; j++)
                w[i][a] += dLdb[j] * p->G[j][a];
        }
    }
}

fs_status fs_reference_modes(const fs_design_def *d, const fs_foot_geom *g, int chain, double omega[2],
                             double shape[2][2], fs_error *err)
{
    chain_dyn m;
    fs_status s = setup(&m, d, g, chain, 0, 0, 0, err);
    if (s != FS_OK)
        return s;
    pose p;
    const double zero[2] = {0, 0};
    make_pose(&m, m.c.beta0, zero, &p);
    double M[4][4], cv[4], Q[4], Mr[2][2], rhs[2], K[2][2] = {{0, 0}, {0, 0}}, w[3][2];
    open_chain(&m, &p, 0, M, cv, Q);
    reduced(&p, M, cv, Q, Mr, rhs);
    /* at the neutral pose every spring is at its rest length: K = sum k w w^T exactly */
    spring_gradients(&m, &p, w);
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 2; a++)
            for (int b = 0; b < 2; b++)
                K[a][b] += m.c.k[i] * w[i][a] * w[i][b];
    /* det(K - w^2 M) = 0: A w^4 - B w^2 + C = 0 */
    double A = Mr[0][0] * Mr[1][1] - Mr[0][1] * Mr[1][0];
    double B = K[0][0] * Mr[1][1] + K[1][1] * Mr[0][0] - 2 * K[0][1] * Mr[0][1];
    double C = K[0][0] * K[1][1] - K[0][1] * K[1][0];
    double disc = sqrt(fmax(B * B - 4 * A * C, 0));
    double w2[2] = {(B - disc) / (2 * A), (B + disc) / (2 * A)};
    for (int k = 0; k < 2; k++) {
        omega[k] = sqrt(w2[k]);
        /* the row of (K - w^2 M) with more in it gives the better-conditioned shape */
        double r0[2] = {K[0][0] - w2[k] * Mr[0][0], K[0][1] - w2[k] * Mr[0][1]};
        double r1[2] = {K[1][0] - w2[k] * Mr[1][0], K[1][1] - w2[k] * Mr[1][1]};
        const double *r = hypot(r0[0], r0[1]) > hypot(r1[0], r1[1]) ? r0 : r1;
        double v[2] = {-r[1], r[0]}, nv = hypot(v[0], v[1]);
        shape[k][0] = v[0] / nv;
        shape[k][1] = v[1] / nv;
    }
    return FS_OK;
}
