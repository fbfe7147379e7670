/* analysis_stiffness.c: each chain's joint stiffness, from the geometry and measured in ODE. */
#include "footsim/analysis/fs_analysis.h"

#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"

#include <limits.h>
#include <math.h>
#include <string.h>

/* How a point on `body` moves per unit rotation of joint j (0 midfoot, 1 MTP) of chain i. */
static fs_vec3 point_rate(const fs_foot_geom *g, int i, int j, int body, fs_vec3 p)
{
    int distal = j == 0 ? (body == g->chain[i].metatarsal || body == g->chain[i].phalanx) : body == g->chain[i].phalanx;
    if (!distal)
        return fs_v3(0, 0, 0);
    const fs_hinge_geom *h = &g->hinge[j == 0 ? g->chain[i].midfoot_hinge : g->chain[i].mtp_hinge];
    return fs_cross(h->axis, fs_sub(p, h->anchor));
}

/* An anchor moved onto its link's axis (the paper's eq. 4 attaches springs on the axes). */
static fs_vec3 on_axis(const fs_foot_geom *g, int i, int body, fs_vec3 p)
{
    fs_vec3 from, to;
    if (body == g->chain[i].metatarsal) {
        from = g->chain[i].midfoot;
        to = g->chain[i].mtp;
    } else if (body == g->chain[i].phalanx) {
        from = g->chain[i].mtp;
        to = g->chain[i].toe;
    } else {
        return p; /* the rear foot does not move with the chain's joints */
    }
    fs_vec3 e = fs_sub(to, from);
    e = fs_scale(e, 1.0 / fs_norm(e));
    return fs_add(from, fs_scale(e, fs_dot(fs_sub(p, from), e)));
}

/* K = G^T Kdd G, each spring's stiffness its law's tangent at x_m[spring] (NULL: at its rest length,
 * k_N_per_m). */
static void stiffness_from_G(const fs_foot_geom *g, int i, const double G[3][2], const double *x_m, double K[2][2])
{
    memset(K, 0, 4 * sizeof(double));
    for (int k = 0; k < 3; k++) {
        const fs_spring_geom *s = &g->spring[g->chain[i].spring[k]];
        double kk = s->k_N_per_m;
        if (x_m)
            fs_spring_law_force(&s->law, x_m[g->chain[i].spring[k]], &kk);
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++)
                K[r][c] += kk * G[k][r] * G[k][c];
    }
}

static void chain_G(const fs_foot_geom *g, int i, int paper, double G[3][2])
{
    for (int k = 0; k < 3; k++) {
        const fs_spring_geom *s = &g->spring[g->chain[i].spring[k]];
        fs_vec3 u = fs_sub(s->p2, s->p1);
        u = fs_scale(u, 1.0 / fs_norm(u));
        fs_vec3 p1 = paper ? on_axis(g, i, s->body1, s->p1) : s->p1;
        fs_vec3 p2 = paper ? on_axis(g, i, s->body2, s->p2) : s->p2;
        for (int j = 0; j < 2; j++)
            G[k][j] = fs_dot(u, fs_sub(point_rate(g, i, j, s->body2, p2), point_rate(g, i, j, s->body1, p1)));
    }
}

static void stiffness_at(const fs_foot_geom *g, const double *x_m, fs_chain_stiffness out[FS_CHAINS])
{
    for (int i = 0; i < FS_CHAINS; i++) {
        double Gp[3][2];
        chain_G(g, i, 0, out[i].G);
        chain_G(g, i, 1, Gp);
        stiffness_from_G(g, i, (const double(*)[2])out[i].G, x_m, out[i].exact);
        stiffness_from_G(g, i, (const double(*)[2])Gp, x_m, out[i].eq4);
    }
}

void fs_stiffness_analytic(const fs_foot_geom *g, fs_chain_stiffness out[FS_CHAINS]) { stiffness_at(g, NULL, out); }

void fs_stiffness_tangent(const fs_foot_geom *g, const double x_m[FS_MAX_SPRINGS], fs_chain_stiffness out[FS_CHAINS])
{
    stiffness_at(g, x_m, out);
}

/* ---- measured in ODE ------------------------------------------------------------------------ */

/* A probe: torque tau about joint j (0 midfoot, 1 MTP) of every chain. */
typedef struct probe_load {
    int j;
    double tau;
} probe_load;

static const double SETTLE_S = 2.0, STILL_M_PER_S = 1e-12;

static void apply_torques(void *user, fs_sim *sim)
{
    const probe_load *p = user;
    const fs_foot_geom *g = fs_sim_geom(sim);
    double tau = p->tau;
    for (int i = 0; i < FS_CHAINS; i++) {
        const fs_hinge_geom *h = &g->hinge[p->j == 0 ? g->chain[i].midfoot_hinge : g->chain[i].mtp_hinge];
        const double on2[3] = {tau * h->axis.x, tau * h->axis.y, tau * h->axis.z};
        const double on1[3] = {-tau * h->axis.x, -tau * h->axis.y, -tau * h->axis.z};
        fs_sim_body_add_torque(sim, h->body2, on2);
        fs_sim_body_add_torque(sim, h->body1, on1);
    }
}

/* Still: after 0.1 s, every body slower than STILL_M_PER_S. */
static int still(void *user, fs_sim *sim)
{
    (void)user;
    return fs_sim_time(sim) > 0.1 && fs_sim_max_speed(sim) < STILL_M_PER_S;
}

/* Out of time: SETTLE_S simulated. */
static int out_of_time(void *user, fs_sim *sim)
{
    (void)user;
    return fs_sim_time(sim) >= SETTLE_S;
}

/* Torque tau about joint j of every chain, held until still; the joint angles that result. */
static fs_status probe(const fs_scenario *sc, int j, double tau, double angles[FS_CHAINS][2], fs_error *err)
{
    fs_sim *sim;
    fs_sim_options opts = {.with_ground = 0, .hold_rear_foot = 1};
    fs_status s = fs_sim_new(sc, &opts, &sim, err);
    if (s != FS_OK)
        return s;
    const fs_foot_geom *g = fs_sim_geom(sim);
    probe_load load = {j, tau};
    const fs_step_hook hooks[] = {{"still", still, NULL}, {"out of time", out_of_time, NULL}};
    fs_drive_spec spec = {.max_steps = LONG_MAX, .before_step = apply_torques, .before_user = &load, .hooks = hooks,
                          .nhooks = 2};
    fs_drive_result r;
    if (s == FS_OK && fs_sim_time(sim) < SETTLE_S)
        s = fs_drive(sim, &spec, &r, err);
    for (int i = 0; s == FS_OK && i < FS_CHAINS; i++) {
        angles[i][0] = fs_sim_hinge_angle(sim, g->chain[i].midfoot_hinge);
        angles[i][1] = fs_sim_hinge_angle(sim, g->chain[i].mtp_hinge);
    }
    fs_sim_free(sim);
    return s;
}

fs_status fs_stiffness_measure(const fs_scenario *sc_in, fs_chain_stiffness out[FS_CHAINS], fs_error *err)
{
    fs_scenario sc = *sc_in;
    sc.def.gravity_m_per_s2 = 0;
    sc.def.load_kg = 0;
    sc.geom = sc_in->geom;
    /* a probe about 1e-3 rad deep: linear, yet far above the solver's residuals */
    double scale = 0;
    for (int i = 0; i < FS_CHAINS; i++)
        scale = fmax(scale, out[i].exact[0][0] + out[i].exact[1][1]);
    double tau = 1e-3 * scale / 2;
    double plus[2][FS_CHAINS][2], minus[2][FS_CHAINS][2];
    for (int j = 0; j < 2; j++) {
        fs_status s = probe(&sc, j, tau, plus[j], err);
        if (s == FS_OK)
            s = probe(&sc, j, -tau, minus[j], err);
        if (s != FS_OK)
            return s;
    }
    for (int i = 0; i < FS_CHAINS; i++) {
        /* columns of D: angle changes per probe; K D = tau I */
        double D[2][2];
        for (int j = 0; j < 2; j++)
            for (int r = 0; r < 2; r++)
                D[r][j] = (plus[j][i][r] - minus[j][i][r]) / 2;
        double det = D[0][0] * D[1][1] - D[0][1] * D[1][0];
        double (*K)[2] = out[i].measured;
        K[0][0] = tau * D[1][1] / det;
        K[0][1] = -tau * D[0][1] / det;
        K[1][0] = -tau * D[1][0] / det;
        K[1][1] = tau * D[0][0] / det;
        double num = 0, den = 0;
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++) {
                double e = K[r][c] - out[i].exact[r][c];
                num += e * e;
                den += out[i].exact[r][c] * out[i].exact[r][c];
            }
        out[i].rel_diff = sqrt(num / den);
    }
    return FS_OK;
}

/* ---- the whole foot's pitch stiffness, measured --------------------------------------------- */

/* A pitch probe: torque tau about the world's lateral axis on the ankle body, rising with the load. */
typedef struct pitch_load {
    double tau, ramp_s;
} pitch_load;

static void apply_pitch(void *user, fs_sim *sim)
{
    const pitch_load *p = user;
    double rise = p->ramp_s > 0 ? fmin(1, fs_sim_time(sim) / p->ramp_s) : 1;
    const double torque[3] = {0, p->tau * rise, 0};
    fs_sim_body_add_torque(sim, fs_sim_geom(sim)->ankle_body, torque);
}

/* Still, once the load and torque have risen: every body slower than 1e-7 m/s. */
static int still_after_ramp(void *user, fs_sim *sim)
{
    const pitch_load *p = user;
    return fs_sim_time(sim) > p->ramp_s + 0.1 && fs_sim_max_speed(sim) < 1e-7;
}

/* The ankle body's pitch at rest under torque tau: the turn of its x axis about the world's y. */
static fs_status pitch_probe(const fs_scenario *sc, double tau, int in_plane, double *pitch, fs_error *err)
{
    fs_sim *sim;
    fs_sim_options opts = {.with_ground = 1, .chain_plane_friction = in_plane};
    fs_status s = fs_sim_new(sc, &opts, &sim, err);
    if (s != FS_OK)
        return s;
    pitch_load load = {tau, sc->def.ramp_s};
    const fs_step_hook hooks[] = {{"still", still_after_ramp, &load}, {"out of time", out_of_time, NULL}};
    fs_drive_spec spec = {.max_steps = LONG_MAX, .before_step = apply_pitch, .before_user = &load, .hooks = hooks,
                          .nhooks = 2};
    fs_drive_result r;
    if (s == FS_OK)
        s = fs_drive(sim, &spec, &r, err);
    if (s == FS_OK && r.stopped_by != 0)
        s = fs_fail(err, FS_NUMERICAL, "%s: the foot did not come to rest within %g s under a pitch torque of %.3g N m",
                    sc->path, SETTLE_S, tau);
    if (s == FS_OK) {
        double R[9];
        fs_sim_body_pose(sim, fs_sim_geom(sim)->ankle_body, NULL, R);
        *pitch = atan2(-R[6], R[0]);
    }
    fs_sim_free(sim);
    return s;
}

/* The footprint's length along the foot (x): the flat sole's box, or the spheres' extent. */
static double footprint_length_m(const fs_foot_geom *g)
{
    if (g->nboxes)
        return g->box_size.x;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < g->nspheres; i++) {
        lo = fmin(lo, g->sphere[i].centre.x - g->sphere[i].radius_m);
        hi = fmax(hi, g->sphere[i].centre.x + g->sphere[i].radius_m);
    }
    return hi > lo ? hi - lo : 0;
}

/* Two materials in contact: stiffness in series, as the sim's contacts take it. */
static double in_series(double a, double b) { return a > 0 && b > 0 ? a * b / (a + b) : 0; }

fs_status fs_pitch_stiffness_foot(const fs_scenario *sc, double load_N, double *K, fs_error *err)
{
    double g = sc->def.gravity_m_per_s2;
    if (sc->geom.kind == FS_FOOT_BIOMIMETIC)
        return fs_pitch_stiffness_model(&sc->geom, load_N, g, K, err);
    (void)err;
    double k = in_series(sc->design.sole_stiffness_N_per_m, sc->terrain.def.stiffness_N_per_m);
    double L = sc->geom.box_size.x;
    *K = k * L * L;
    return FS_OK;
}

fs_status fs_pitch_stiffness_measure(const fs_scenario *sc_in, double load_N, double mu, int in_plane, double K_guess, double *K,
                                     fs_error *err)
{
    fs_scenario sc = *sc_in;
    sc.def.load_kg = load_N / sc.def.gravity_m_per_s2;
    sc.def.robot.mass_kg = 0;
    sc.design.sole_mu = sc.terrain.def.mu = mu;
    /* a probe about 1e-3 rad deep: linear, yet far above the solver's residuals; and far from
       lifting the footprint's heel or toe (a flat sole is linear only while all four corners bear) */
    double tau = fmin(1e-3 * K_guess, 0.05 * load_N * 0.5 * footprint_length_m(&sc.geom)), plus, minus;
    fs_status s = pitch_probe(&sc, tau, in_plane, &plus, err);
    if (s == FS_OK)
        s = pitch_probe(&sc, -tau, in_plane, &minus, err);
    *K = s == FS_OK ? 2 * tau / (plus - minus) : NAN;
    return s;
}

void fs_pitch_law_apply(double K_foot, const fs_robot_def *r, double gravity_m_per_s2, double max_lean_rad,
                        fs_pitch_law *out)
{
    memset(out, 0, sizeof *out);
    out->K_foot = K_foot;
    out->held = r->mount == FS_ROBOT_VERTICAL;
    out->K_series = r->joint == FS_ROBOT_ACHILLES ? r->achilles_k_N_per_m * FS_ACHILLES_LEVER_M * FS_ACHILLES_LEVER_M
                                                  : INFINITY;
    out->K = isfinite(out->K_series) ? 1 / (1 / K_foot + 1 / out->K_series) : K_foot;
    if (r->kind == FS_ROBOT_BIPED) { /* two legs side by side, each its foot and ankle spring in series */
        out->K_series = r->ankle_k_N_m_per_rad;
        out->K = 2 / (1 / K_foot + 1 / out->K_series);
    }
    out->demand = r->mass_kg * gravity_m_per_s2 * r->com_height_m;
    out->critical_height_m = r->mass_kg > 0 ? out->K / (r->mass_kg * gravity_m_per_s2) : INFINITY;
    double margin = out->K - out->demand;
    out->lean_rad = out->held ? 0 : margin > 0 ? r->mass_kg * gravity_m_per_s2 * fabs(r->com_forward_m) / margin
                                               : INFINITY;
    out->stands = out->held || (margin > 0 && out->lean_rad < max_lean_rad);
}
