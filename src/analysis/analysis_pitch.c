/* analysis_pitch.c: the whole biomimetic foot's stiffness against pitching its ankle body, from
 * its geometry in three dimensions (never ODE): the pitch-stiffness law of docs/landing.md.
 *
 * The foot's twelve bodies are placed by three coordinates: the heel's and the talus's angles about
 * the ankle axis, and the foot's sideways shift. The heel rolls on its spheres without slipping
 * along the foot, the talus turns on the heel, and each chain's metatarsal and phalanx turn on
 * their own hinges (about the chain's splayed axis, carried by the talus) until its toe sphere
 * stands on the ground and has rolled, not slid, along its chain's plane; across that plane it
 * slides freely. The potential energy of the springs, of gravity and of the load at the ankle is
 * minimised over the three; K is the energy's second derivative in the talus's angle with the
 * heel's angle and the shift condensed out.
 *
 * The shift: the heel's and the toes' contacts slide freely across the foot and across each
 * chain's plane, but a splayed toe shifted sideways must roll along its plane too, so the shift is
 * not free, and in a foot not symmetric about its long axis pitching excites it. The heel's two
 * spheres, which stay on the ground and grip along the foot, keep the heel (and so the talus, on
 * its hinge) from rolling and from turning about the vertical. */
#include "footsim/analysis/fs_analysis.h"

#include "analysis_diff.h"

#include <math.h>
#include <string.h>

/* The free coordinates: the heel's and the talus's angles about the ankle axis (rad, from the
 * neutral pose) and the foot's sideways shift in units of SHIFT_M (so that one step of the finite
 * differences moves a toe about as far in each). */
enum { NQ = 3 };
_Static_assert((int)NQ == (int)FS_DIFF_MAX, "the Hessian's rows are FS_DIFF_MAX long");
#define SHIFT_M 0.05

typedef struct mat3 { double m[3][3]; } mat3;

/* A body's placement: a point p of the neutral pose goes to c + R (p - c0). */
typedef struct placement { mat3 R; fs_vec3 c0, c; } placement;

typedef struct foot3d {
    const fs_foot_geom *g;
    fs_vec3 axis;              /* the ankle hinge's */
    fs_vec3 heel_centre;       /* the heel spheres' centres lie on a line along the axis, this high */
    double r_heel;
    fs_vec3 f[FS_CHAINS], lat[FS_CHAINS]; /* each chain plane's heading and its normal */
    double r_toe[FS_CHAINS];
    double load_N, gravity;
    double tau;                /* N m about the ankle axis on the talus (the drop law's fold probe; 0 for K) */
    double chain_angles[FS_CHAINS][2]; /* the last solved midfoot and MTP angles (a warm start) */
    int sideways;              /* 0 when no chain is splayed: the shift then costs nothing and couples to
                                  nothing (its rows of the Hessian are zero), so it is held */
} foot3d;

static mat3 rotation(fs_vec3 u, double angle)
{
    double c = cos(angle), s = sin(angle), v = 1 - c;
    mat3 r = {{{c + u.x * u.x * v, u.x * u.y * v - u.z * s, u.x * u.z * v + u.y * s},
               {u.y * u.x * v + u.z * s, c + u.y * u.y * v, u.y * u.z * v - u.x * s},
               {u.z * u.x * v - u.y * s, u.z * u.y * v + u.x * s, c + u.z * u.z * v}}};
    return r;
}

static mat3 mul(const mat3 *a, const mat3 *b)
{
    mat3 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
    return r;
}

static fs_vec3 apply(const mat3 *a, fs_vec3 v)
{
    return fs_v3(a->m[0][0] * v.x + a->m[0][1] * v.y + a->m[0][2] * v.z,
                 a->m[1][0] * v.x + a->m[1][1] * v.y + a->m[1][2] * v.z,
                 a->m[2][0] * v.x + a->m[2][1] * v.y + a->m[2][2] * v.z);
}

/* The rotation vector of R (axis times angle), accurate for small angles. */
static fs_vec3 rotation_vector(const mat3 *a)
{
    fs_vec3 w = fs_v3(0.5 * (a->m[2][1] - a->m[1][2]), 0.5 * (a->m[0][2] - a->m[2][0]), 0.5 * (a->m[1][0] - a->m[0][1]));
    double s = fs_norm(w), c = 0.5 * (a->m[0][0] + a->m[1][1] + a->m[2][2] - 1);
    return s > 0 ? fs_scale(w, atan2(s, c) / s) : w;
}

static fs_vec3 place(const placement *p, fs_vec3 x) { return fs_add(p->c, apply(&p->R, fs_sub(x, p->c0))); }

/* A body turned by `angle` about the hinge (anchor, axis) on its parent, placed. */
static placement on_hinge(const placement *parent, const fs_hinge_geom *h, double angle)
{
    mat3 turn = rotation(h->axis, angle);
    placement p = {mul(&parent->R, &turn), h->anchor, place(parent, h->anchor)};
    return p;
}

/* Chain i's residuals: its toe sphere's centre above its neutral height, and its travel along the
 * chain's plane less what rolling the phalanx's turn about the plane's normal allows. */
static void chain_residual(const foot3d *m, int i, const placement *talus, const double a[2], placement *meta,
                           placement *phal, double r[2])
{
    const fs_foot_geom *g = m->g;
    *meta = on_hinge(talus, &g->hinge[g->chain[i].midfoot_hinge], a[0]);
    *phal = on_hinge(meta, &g->hinge[g->chain[i].mtp_hinge], a[1]);
    fs_vec3 t0 = g->chain[i].toe, t = place(phal, t0), d = fs_sub(t, t0);
    r[0] = d.z;
    r[1] = fs_dot(d, m->f[i]) - m->r_toe[i] * fs_dot(rotation_vector(&phal->R), m->lat[i]);
}

/* Solves chain i's midfoot and MTP angles (Newton, the Jacobian by central differences), from
 * the last solution; 0 when the toe cannot be closed on the ground. */
static int close_chain(foot3d *m, int i, const placement *talus, placement *meta, placement *phal)
{
    double *a = m->chain_angles[i], r[2];
    for (int it = 0; it < 60; it++) {
        chain_residual(m, i, talus, a, meta, phal, r);
        if (fabs(r[0]) + fabs(r[1]) < 1e-16)
            return 1;
        double J[2][2];
        const double h = 1e-7;
        for (int j = 0; j < 2; j++) {
            double ap[2] = {a[0], a[1]}, am[2] = {a[0], a[1]}, rp[2], rm[2];
            placement x, y;
            ap[j] += h;
            am[j] -= h;
            chain_residual(m, i, talus, ap, &x, &y, rp);
            chain_residual(m, i, talus, am, &x, &y, rm);
            J[0][j] = (rp[0] - rm[0]) / (2 * h);
            J[1][j] = (rp[1] - rm[1]) / (2 * h);
        }
        double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (!(fabs(det) > 1e-300))
            break;
        a[0] -= (J[1][1] * r[0] - J[0][1] * r[1]) / det;
        a[1] -= (-J[1][0] * r[0] + J[0][0] * r[1]) / det;
    }
    chain_residual(m, i, talus, a, meta, phal, r);
    if (fabs(r[0]) + fabs(r[1]) < 1e-13)
        return 1;
    a[0] = a[1] = 0; /* the next start from the neutral pose, not from where this one failed */
    return 0;
}

/* The potential energy at q; NAN when a toe cannot reach the ground. */
static double energy(foot3d *m, const double q[NQ])
{
    const fs_foot_geom *g = m->g;
    placement body[FS_MAX_BODIES];
    /* the heel rolls: its spheres' centres travel along the foot by r times its turn */
    placement *heel = &body[FS_BODY_HEEL];
    heel->R = rotation(m->axis, q[0]);
    heel->c0 = m->heel_centre;
    heel->c = fs_add(m->heel_centre,
                     fs_v3(m->r_heel * fs_dot(fs_scale(m->axis, q[0]), fs_v3(0, 1, 0)), SHIFT_M * q[2], 0));
    placement *talus = &body[FS_BODY_TALUS];
    talus->R = rotation(m->axis, q[1]);
    talus->c0 = g->ankle;
    talus->c = place(heel, g->ankle);
    for (int i = 0; i < FS_CHAINS; i++)
        if (!close_chain(m, i, talus, &body[g->chain[i].metatarsal], &body[g->chain[i].phalanx]))
            return NAN;
    double E = m->load_N * (talus->c.z - g->ankle.z);
    if (m->tau != 0)
        E -= m->tau * q[1];
    for (int b = 0; b < g->nbodies; b++)
        E += g->body[b].mass_kg * m->gravity * (place(&body[b], g->body[b].com).z - g->body[b].com.z);
    for (int s = 0; s < g->nsprings; s++) {
        const fs_spring_geom *sp = &g->spring[s];
        double stretch = fs_norm(fs_sub(place(&body[sp->body2], sp->p2), place(&body[sp->body1], sp->p1))) -
                         sp->rest_length_m;
        E += fs_spring_law_energy(&sp->law, stretch);
    }
    return E;
}

static double energy_of(void *m, const double *q) { return energy(m, q); }

/* The energy's gradient and Hessian; the shift's rows zero (its diagonal 1) when it is held. */
static void gradient(foot3d *m, const double q[NQ], double grad[NQ])
{
    fs_diff_gradient(energy_of, m, NQ, q, grad);
    if (!m->sideways)
        grad[2] = 0;
}

static void hessian(foot3d *m, const double q[NQ], double H[NQ][NQ])
{
    fs_diff_hessian(energy_of, m, NQ, q, H);
    if (!m->sideways) {
        H[0][2] = H[2][0] = H[1][2] = H[2][1] = 0;
        H[2][2] = 1;
    }
}

static double det3(const double A[NQ][NQ])
{
    return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

/* The talus's stiffness with the heel's angle and the shift condensed out (the Schur complement);
 * NAN unless H is positive definite. */
static double condensed(const double H[NQ][NQ])
{
    double det_other = H[0][0] * H[2][2] - H[0][2] * H[2][0];
    if (!(H[0][0] > 0 && det_other > 0))
        return NAN;
    double K = H[1][1] - (H[1][0] * H[1][0] * H[2][2] - 2 * H[1][0] * H[1][2] * H[0][2] + H[1][2] * H[1][2] * H[0][0]) /
                             det_other;
    return K > 0 ? K : NAN;
}

/* Sets up the model of foot g under load_N at the ankle; FS_BAD_INPUT (said) for a foot it is not for. */
static fs_status setup(foot3d *m, const fs_foot_geom *g, double load_N, double gravity_m_per_s2, fs_error *err)
{
    if (g->kind != FS_FOOT_BIOMIMETIC || g->nfeet > 1)
        return fs_fail(err, FS_BAD_INPUT, "the pitch-stiffness model is for one biomimetic foot; a flat sole's "
                                          "pitch stiffness is its contacts' (docs/landing.md)");
    memset(m, 0, sizeof *m);
    m->g = g;
    m->axis = g->hinge[0].axis;
    m->load_N = load_N;
    m->gravity = gravity_m_per_s2;
    int nheel = 0;
    for (int s = 0; s < g->nspheres; s++)
        if (g->sphere[s].body == FS_BODY_HEEL) {
            m->heel_centre = fs_add(m->heel_centre, g->sphere[s].centre);
            m->r_heel = g->sphere[s].radius_m;
            nheel++;
        }
    if (nheel == 0)
        return fs_fail(err, FS_BAD_INPUT, "the pitch-stiffness model needs the heel's spheres (a whole foot, not a "
                                          "pinned chain)");
    m->heel_centre = fs_scale(m->heel_centre, 1.0 / nheel);
    for (int i = 0; i < FS_CHAINS; i++) {
        fs_vec3 run = fs_sub(g->chain[i].toe, g->chain[i].midfoot);
        run.z = 0;
        m->f[i] = fs_scale(run, 1 / fs_norm(run));
        m->lat[i] = fs_cross(fs_v3(0, 0, 1), m->f[i]);
        m->sideways |= m->f[i].y != 0;
        for (int s = 0; s < g->nspheres; s++)
            if (g->sphere[s].body == g->chain[i].phalanx)
                m->r_toe[i] = g->sphere[s].radius_m;
    }
    return FS_OK;
}

/* Newton on the energy's gradient (Cramer's rule on the 3 x 3 Hessian) from q; the finite
   differences resolve the angles to about 1e-9 rad. A chain splayed by a small angle psi resists the
   shift only as psi^2 and an unequal foot's load pushes it sideways as psi, so the shift at rest
   grows as 1/psi (0.1 mm at Table I's splay, 11 mm at a tenth of a degree): it is resolved to 1e-6
   of SHIFT_M, 50 nm. Returns the condensed pitch stiffness there, NAN unless Newton converged to a
   stable equilibrium. */
static double solve(foot3d *m, double q[NQ])
{
    double grad[NQ], H[NQ][NQ];
    int converged = 0;
    for (int it = 0; it < 100 && !converged; it++) {
        gradient(m, q, grad);
        hessian(m, q, H);
        double det = det3((const double(*)[NQ])H);
        if (isnan(condensed((const double(*)[NQ])H)) || !(fabs(det) > 0))
            break;
        double dq[NQ], step = 0;
        for (int c = 0; c < NQ; c++) {
            double A[NQ][NQ];
            memcpy(A, H, sizeof A);
            for (int r = 0; r < NQ; r++)
                A[r][c] = grad[r];
            dq[c] = det3((const double(*)[NQ])A) / det;
            step = fmax(step, fabs(dq[c]));
        }
        double scale = step > 0.05 ? 0.05 / step : 1;
        for (int c = 0; c < NQ; c++)
            q[c] -= scale * dq[c];
        converged = fmax(fabs(dq[0]), fabs(dq[1])) < 1e-9 && fabs(dq[2]) < 1e-6;
    }
    hessian(m, q, H);
    return converged ? condensed((const double(*)[NQ])H) : NAN;
}

fs_status fs_pitch_stiffness_model(const fs_foot_geom *g, double load_N, double gravity_m_per_s2, double *K,
                                   fs_error *err)
{
    *K = NAN;
    foot3d m;
    fs_status s = setup(&m, g, load_N, gravity_m_per_s2, err);
    if (s != FS_OK)
        return s;
    double q[NQ] = {0, 0, 0};
    *K = solve(&m, q);
    if (isnan(*K))
        return fs_fail(err, FS_NUMERICAL, "the foot has no stable equilibrium under %.4g N at the ankle: the arch "
                                          "folds (or, its chains splayed by hundredths of a degree, it slides "
                                          "sideways without end), and its pitch stiffness is not positive", load_N);
    return FS_OK;
}

fs_status fs_pitch_fold_moment(const fs_foot_geom *g, double load_N, double gravity_m_per_s2, double cap_N_m,
                               double *fold_N_m, fs_error *err)
{
    *fold_N_m = NAN;
    foot3d m;
    fs_status s = setup(&m, g, load_N, gravity_m_per_s2, err);
    if (s != FS_OK)
        return s;
    /* forward: the ankle body's top turning towards the toes, +x (a turn about the axis a moves the
       point straight above the ankle by a x z, whose x is a.y) */
    double forward = m.axis.y >= 0 ? 1 : -1, q[NQ] = {0, 0, 0};
    if (isnan(solve(&m, q)))
        return fs_fail(err, FS_NUMERICAL, "the foot has no stable equilibrium under %.4g N at the ankle: the arch "
                                          "folds before any moment is put on it", load_N);
    /* continuation in the moment from the last equilibrium, FOLD_STEPS steps up to the cap, then
       bisection between the last moment held and the first not: the fold to cap / FOLD_STEPS / 2^8 */
    enum { FOLD_STEPS = 48, FOLD_HALVINGS = 8 };
    double held = 0, lost = NAN;
    for (int i = 1; i <= FOLD_STEPS + FOLD_HALVINGS; i++) {
        if (i > FOLD_STEPS && isnan(lost)) {
            *fold_N_m = INFINITY; /* the arch holds every moment up to the cap */
            return FS_OK;
        }
        double t = isnan(lost) ? cap_N_m * i / FOLD_STEPS : 0.5 * (held + lost), qt[NQ];
        memcpy(qt, q, sizeof qt);
        m.tau = forward * t;
        if (isnan(solve(&m, qt)))
            lost = t;
        else
            held = t, memcpy(q, qt, sizeof q);
    }
    *fold_N_m = held;
    return FS_OK;
}
