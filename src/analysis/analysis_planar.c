/* analysis_planar.c: one chain in its plane, heel and toe spheres rolling on the ground, solved
 * for static equilibrium by minimising its potential energy. It reads only the design and its
 * geometry (never ODE), so it is an independent prediction of what the ODE model must do. */
#include "footsim/analysis/fs_analysis.h"

#include "analysis_chain.h"
#include "analysis_diff.h"

#include <math.h>
#include <string.h>

typedef fs_chain2d planar;

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
        fs_chain_joints J;
        fs_chain2d_joints(c, b, &J);
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
    fs_chain_joints J;
    fs_chain2d_joints(c, b, &J);
    return fabs(J.p[4][1] - c->r_toe) < 1e-12;
}

static double spring_length(const planar *c, const fs_chain_joints *J, const double b[4], int i)
{
    double p[2], q[2];
    fs_chain2d_place(J, b, c->p1[i], p);
    fs_chain2d_place(J, b, c->p2[i], q);
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
    fs_chain_joints J;
    double E = 0;
    fs_chain2d_joints(c, b, &J);
    for (int i = 0; i < 3; i++) {
        double s = spring_length(c, &J, b, i) - c->rest[i];
        E += fs_spring_law_energy(&c->law[i], s);
    }
    for (int k = 0; k < 4; k++) {
        double p[2];
        fs_chain2d_place(&J, b, c->com[k], p);
        E -= c->mass[k] * (c->gx * p[0] + c->gz * p[1]);
    }
    return E - c->load * (c->down[0] * J.p[1][0] + c->down[1] * J.p[1][1]);
}

static double energy_of(void *c, const double *q)
{
    double b[4];
    return energy(c, q, b);
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

fs_status fs_planar_equilibrium(const fs_design_def *d, const fs_foot_geom *g, int chain, const fs_planar_load *load,
                                fs_planar_result *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    if (g->kind != FS_FOOT_BIOMIMETIC)
        return fs_fail(err, FS_BAD_INPUT, "the planar model is for the biomimetic foot only");
    if (load->frictionless && load->tilt_rad != 0)
        return fs_fail(err, FS_BAD_INPUT, "a tilted load on frictionless ground has no equilibrium: the foot slides");
    planar c;
    fs_chain2d_setup(&c, d, g, chain, load->load_N, load->gravity_m_per_s2, load->tilt_rad);
    c.frictionless = load->frictionless;
    c.nfree = c.frictionless ? 3 : 2;
    double q[3] = {c.beta0[0], c.beta0[1], c.beta0[2]}, b[4];
    double H[3][3], grad[3], dq[3];
    /* Newton on the energy's gradient; its finite differences resolve angles to about 1e-9 rad */
    const double limit = 0.05, tolerance = 1e-9;
    for (int it = 0; it < 200 && !out->converged; it++) {
        fs_diff_gradient(energy_of, &c, c.nfree, q, grad);
        fs_diff_hessian(energy_of, &c, c.nfree, q, H);
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
    fs_diff_hessian(energy_of, &c, c.nfree, q, H);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++)
            out->K_reduced[i][j] = H[i][j];
    double L[3][3];
    memcpy(L, H, sizeof L);
    out->stable = cholesky(L, c.nfree);
    fs_chain_joints J, J0;
    fs_chain2d_joints(&c, b, &J);
    fs_chain2d_joints(&c, c.beta0, &J0);
    out->ankle_drop_m = J0.p[1][1] - J.p[1][1];
    out->ankle_joint_rad = (b[1] - b[0]) - (c.beta0[1] - c.beta0[0]);
    out->midfoot_rad = (b[2] - b[1]) - (c.beta0[2] - c.beta0[1]);
    out->mtp_rad = (b[3] - b[2]) - (c.beta0[3] - c.beta0[2]);
    out->ball_clearance_m = J.p[3][1] - c.r_ball;
    for (int k = 0; k < 3; k++) {
        out->spring_deflection_m[k] = spring_length(&c, &J, b, k) - c.rest[k];
        out->spring_force_N[k] = fs_spring_law_force(&c.law[k], out->spring_deflection_m[k], NULL);
    }
    return FS_OK;
}
