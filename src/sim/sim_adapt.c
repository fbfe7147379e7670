/* sim_adapt.c: the error-controlled step (run.tolerance_m > 0), by step doubling or, with
 * run.error_estimate = embedded, by the embedded Euler pair (one ODE step a try: embedded_m below).
 *
 * A step of h = step_max_s / 2^level is tried whole from the saved state, the state put back, and
 * then taken as two half steps; the two ends' difference estimates the half steps' local error
 * (first order: the whole step errs about twice as much as the pair, so the difference is about
 * the pair's own error). Kept when within the tolerance; else the state is put back and the step
 * tried at the next level. Everything a step changes is saved and put back: each body's position,
 * quaternion and velocities (ODE holds no other state between steps for footsim's joints: the
 * contacts are new joints each step, the hinges, stops and springs keep none), and footsim's own
 * history: the contacts of the last step with their forces (the next step's friction bounds), the
 * touches, the substep window, the state checks' reference and work, ODE's random state, the time
 * and counters; and the walking machine's carriage (a kinematic body, set to its path at each ODE
 * step: fs_carriage.h). Nothing is allocated while stepping: the saved state is taken at build. */
#include "sim_internal.h"
#include "sim_soil.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct body_state {
    dReal p[3], q[4], R[12], v[3], w[3];
} body_state;

struct fs_sim_saved {
    body_state body[FS_MAX_BODIES + 1];
    body_state whole[FS_MAX_BODIES + 1]; /* the end of the whole step, against the two halves */
    double time_s, impact_until_s;
    int substeps_now, contacts_now, contacts_found_now, shapes_touching_now, most_found_now;
    unsigned char touched_before[FS_MAX_SHAPES];
    double step_force[FS_MAX_FEET + 1][3];
    fs_touch touch[FS_MAX_FEET];
    long contacts_total, collision_tests;
    fs_check check;
    unsigned long rand_seed;
    double carriage[6]; /* the walking machine's carriage (fs_carriage.h): position, velocity */
    /* the last step's contacts (contacts_now of them): what the next step's friction bounds read */
    dJointFeedback feedback[FS_MAX_STEP_CONTACTS];
    double contact_pos[FS_MAX_STEP_CONTACTS][3], contact_depth_m[FS_MAX_STEP_CONTACTS];
    short shape[FS_MAX_STEP_CONTACTS];
    double normal[FS_MAX_STEP_CONTACTS][3];
    /* the embedded estimate's memory: each body's change of velocity and angular velocity over the
     * last accepted step, and that step (0 before the first) */
    double dv[FS_MAX_BODIES + 1][6], h_before;
};

/* Growth waits for this many accepted steps in a row with the error below a quarter of the
 * tolerance (the local error of a first-order step grows with h^2: a doubled step's is 4 times). */
enum { GROW_AFTER = 4 };

/* The largest ODE step at which an implicit spring-damper of stiffness k and damping c damps by c:
 * c / k. ODE's soft row is implicit Euler, which damps by c + k h; the damping correction hands it
 * c - k h, which it can only while k h <= c (fs_spring_soft): beyond, a contact or spring damps by
 * k h, more the larger the step, and a rocking foot comes to rest sooner. Infinite without a spring
 * or a damper. */
static double damped_step(double k, double c) { return k > 0 && c > 0 ? c / k : INFINITY; }

fs_status fs_sim_adapt_init(fs_sim *sim, fs_error *err)
{
    const fs_scenario_def *d = &sim->sc->def;
    if (!(d->tolerance_m > 0))
        return FS_OK;
    sim->saved = calloc(1, sizeof *sim->saved);
    if (!sim->saved)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", sim->sc->path);
    sim->damped_contact_s = damped_step(sim->contact_k_N_per_m, sim->contact_c_Ns_per_m);
    sim->damped_step_s = INFINITY;
    for (int i = 0; i < sim->geom->nsprings; i++)
        sim->damped_step_s = fmin(sim->damped_step_s, damped_step(sim->spring[i].k, sim->spring[i].c));
    if (sim->has_achilles)
        sim->damped_step_s = fmin(sim->damped_step_s, damped_step(sim->achilles.k, sim->achilles.c));
    for (int i = 0; i < sim->geom->nhinges; i++)
        sim->damped_step_s = fmin(sim->damped_step_s, damped_step(sim->geom->hinge[i].k_N_m_per_rad,
                                                                  sim->geom->hinge[i].c_N_m_s_per_rad));
    /* the first step tried: the fixed step's level, at most step_s */
    sim->level = 0;
    while (d->step_max_s / ldexp(1, sim->level) > d->step_s && sim->level < FS_STEP_LEVELS - 1)
        sim->level++;
    return FS_OK;
}

void fs_sim_adapt_free(fs_sim *sim)
{
    free(sim->saved);
    sim->saved = NULL;
}

void fs_sim_set_horizon(fs_sim *sim, double t_s) { sim->horizon_s = t_s; }

void fs_sim_count_step(fs_sim *sim, double h, int level)
{
    fs_step_stats *s = &sim->stats;
    s->least_s = s->taken ? fmin(s->least_s, h) : h;
    s->largest_s = s->taken ? fmax(s->largest_s, h) : h;
    s->taken++;
    if (level < 0) /* the embedded estimate's step cut to the dampers' bound */
        s->at_bound++, s->bound_s = h;
    else
        s->at_level[level < FS_STEP_LEVELS ? level : FS_STEP_LEVELS - 1]++;
    sim->step_taken_s = h;
}

double fs_sim_median_step_s(const fs_sim *sim)
{
    const fs_step_stats *s = &sim->stats;
    if (!sim->saved)
        return s->taken ? sim->sc->def.step_s : 0;
    long seen = 0;
    int bound_counted = 0;
    for (int k = FS_STEP_LEVELS - 1; k >= 0 && s->taken; k--) { /* from the least step up */
        double h = sim->sc->def.step_max_s / ldexp(1, k);
        if (!bound_counted && s->at_bound && h > s->bound_s) { /* the steps cut to the bound, in their place */
            bound_counted = 1;
            if ((seen += s->at_bound) * 2 >= s->taken)
                return s->bound_s;
        }
        if ((seen += s->at_level[k]) * 2 >= s->taken)
            return h;
    }
    return s->taken ? s->bound_s : 0;
}

/* ---- the state, saved and put back ------------------------------------------------------------ */

static int nbodies_saved(const fs_sim *sim) { return fs_sim_nbodies(sim); }

static void read_bodies(const fs_sim *sim, body_state *b)
{
    for (int i = 0; i < nbodies_saved(sim); i++) {
        dBodyID id = fs_sim_body_id(sim, i);
        memcpy(b[i].p, dBodyGetPosition(id), sizeof b[i].p);
        memcpy(b[i].q, dBodyGetQuaternion(id), sizeof b[i].q);
        memcpy(b[i].R, dBodyGetRotation(id), sizeof b[i].R);
        memcpy(b[i].v, dBodyGetLinearVel(id), sizeof b[i].v);
        memcpy(b[i].w, dBodyGetAngularVel(id), sizeof b[i].w);
    }
}

/* ODE normalises a quaternion it is given (dBodySetQuaternion), and one it normalised itself may
 * come back an ulp away. So the quaternion and the rotation matrix ODE made from it are set, then
 * written back to the saved bits through the pointers ODE's getters return, which the ODE manual
 * documents as its internal data (the setter has marked the body's shapes moved). */
static void set_rotation(dBodyID id, const dReal q[4], const dReal R[12])
{
    dBodySetQuaternion(id, q);
    memcpy((dReal *)dBodyGetQuaternion(id), q, 4 * sizeof(dReal));
    memcpy((dReal *)dBodyGetRotation(id), R, 12 * sizeof(dReal));
}

static void write_bodies(fs_sim *sim, const body_state *b)
{
    for (int i = 0; i < nbodies_saved(sim); i++) {
        dBodyID id = fs_sim_body_id(sim, i);
        dBodySetPosition(id, b[i].p[0], b[i].p[1], b[i].p[2]);
        set_rotation(id, b[i].q, b[i].R);
        dBodySetLinearVel(id, b[i].v[0], b[i].v[1], b[i].v[2]);
        dBodySetAngularVel(id, b[i].w[0], b[i].w[1], b[i].w[2]);
    }
}

/* Copies n bytes between a field of the sim and its saved copy: into the copy when saving. */
static void move(void *field, void *copy, size_t n, int saving) { memcpy(saving ? copy : field, saving ? field : copy, n); }

/* Every field a step changes, each once, saved or put back: the bodies apart (ODE's setters). */
static void exchange(fs_sim *sim, int saving)
{
    struct fs_sim_saved *s = sim->saved;
    gathered *g = sim->scratch;
#define MOVE(field, copy) move(&(field), &(copy), sizeof(copy), saving)
    MOVE(sim->time_s, s->time_s);
    MOVE(sim->impact_until_s, s->impact_until_s);
    MOVE(sim->substeps_now, s->substeps_now);
    MOVE(sim->contacts_now, s->contacts_now);
    MOVE(sim->contacts_found_now, s->contacts_found_now);
    MOVE(sim->shapes_touching_now, s->shapes_touching_now);
    MOVE(sim->most_found_now, s->most_found_now);
    MOVE(sim->touched_before, s->touched_before);
    MOVE(sim->step_force, s->step_force);
    MOVE(sim->touch, s->touch);
    MOVE(sim->contacts_total, s->contacts_total);
    MOVE(sim->collision_tests, s->collision_tests);
    MOVE(sim->check, s->check);
    MOVE(sim->rand_seed, s->rand_seed);
#undef MOVE
    size_t n = (size_t)sim->contacts_now; /* the saved count, once put back */
    move(sim->feedback, s->feedback, n * sizeof s->feedback[0], saving);
    move(sim->contact_pos, s->contact_pos, n * sizeof s->contact_pos[0], saving);
    move(sim->contact_depth_m, s->contact_depth_m, n * sizeof s->contact_depth_m[0], saving);
    move(g->shape, s->shape, n * sizeof s->shape[0], saving);
    move(g->normal, s->normal, n * sizeof s->normal[0], saving);
}

void fs_sim_save_state(fs_sim *sim)
{
    read_bodies(sim, sim->saved->body);
    if (sim->driven.exchange)
        sim->driven.exchange(sim->driven.user, sim->saved->carriage, 1);
    fs_sim_soil_save(sim);
    exchange(sim, 1);
}

void fs_sim_restore_state(fs_sim *sim)
{
    write_bodies(sim, sim->saved->body);
    if (sim->driven.exchange)
        sim->driven.exchange(sim->driven.user, sim->saved->carriage, 0);
    fs_sim_soil_restore(sim);
    exchange(sim, 0);
}

/* ---- the error estimate ----------------------------------------------------------------------- */

/* Body i's reach (its farthest point from its centre): the robot's is its centre's height. */
static double reach_of(const fs_sim *sim, int i)
{
    return i == sim->geom->nbodies ? sim->sc->def.robot.com_height_m : sim->reach[i];
}

static double dist3(const dReal *a, const dReal *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* The angle between two unit quaternions' rotations, rad. */
static double turn(const dReal *a, const dReal *b)
{
    double d = fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
    return 2 * acos(fmin(1, d));
}

/* How far apart the whole step and the two halves end: over every body, its centre's distance plus
 * its rotation's difference times its reach, plus h times the same for the velocities (what the
 * difference in velocity makes of the position over the next step). */
static double difference_m(const fs_sim *sim, const body_state *whole, const body_state *half, double h)
{
    double worst = 0;
    for (int i = 0; i < nbodies_saved(sim); i++) {
        const body_state *a = &whole[i], *b = &half[i];
        double r = reach_of(sim, i);
        double e = dist3(a->p, b->p) + r * turn(a->q, b->q) + h * (dist3(a->v, b->v) + r * dist3(a->w, b->w));
        worst = isfinite(e) ? fmax(worst, e) : INFINITY;
    }
    return worst;
}

/* ---- the step ----------------------------------------------------------------------------------- */

/* Where the dampers' bound, not the error, sets the step (at rest, a foot standing), a doubled step
 * accepted at once at the bound is followed by CRUISE_STEPS single ODE steps of the bound itself, each
 * kept unless the set of foot shapes touching the ground changed (then put back and doubled), before
 * the next doubled step checks the error again. Measured (docs/bench.md): 8 take the landing under
 * drop_weight from 1719 to 1130 ODE steps over 0.5 s at 3e-6 m, its error and its campaign's
 * verdict unchanged; 32 gave 1070. */
enum { CRUISE_STEPS = 8 };

/* The foot shapes in contact now, one bit each. */
static uint64_t touching(const fs_sim *sim)
{
    uint64_t m = 0;
    for (int i = 0; i < sim->contacts_now; i++)
        if (sim->scratch->shape[i] >= 0)
            m |= (uint64_t)1 << (sim->scratch->shape[i] & 63);
    return m;
}

/* One ODE step of h from the state now (the driver's torques again after the first). */
static fs_status one(fs_sim *sim, double h, int again, fs_error *err)
{
    if (again)
        fs_sim_add_torques_again(sim);
    sim->stats.ode_steps++;
    return fs_sim_step_by(sim, h, err);
}

/* A step of h ending past the horizon is cut to end on it (never a sliver short of it). */
static double to_horizon(const fs_sim *sim, double h)
{
    double t0 = sim->time_s;
    if (sim->horizon_s > t0 && t0 + h > sim->horizon_s - 0.5 * sim->sc->def.step_min_s)
        return sim->horizon_s - t0;
    return h;
}

/* A step of h taken in `substeps` ODE steps, kept with error e: counted (at its level, or as the
 * dampers' bound's when cut to it), and the next one a level larger after GROW_AFTER in a row within
 * a quarter of the tolerance (never above top_level). */
static void keep_step(fs_sim *sim, double h, double e, int substeps, int top_level, int at_bound)
{
    double tol = sim->sc->def.tolerance_m;
    sim->substeps_now = substeps;
    sim->step_error_m = e;
    sim->stats.missed += e > tol;
    fs_sim_count_step(sim, h, at_bound ? -1 : sim->level);
    if (e <= tol / 4 && ++sim->level_held >= GROW_AFTER && sim->level > top_level)
        sim->level--, sim->level_held = 0;
}

/* A step beyond the tolerance (error e), or whose checks failed (st) above the least level: the
 * state put back and the next try smaller, by as many levels as the error asks when far beyond
 * (each takes it down about 4 times). */
static void reject_step(fs_sim *sim, fs_status st, double e, int least)
{
    sim->stats.rejected++;
    fs_sim_restore_state(sim);
    sim->level_held = 0;
    sim->level++;
    for (double r = st == FS_OK ? e / sim->sc->def.tolerance_m / 4 : 0; r > 1 && sim->level < least; r /= 4)
        sim->level++;
}

/* The embedded estimate (run.error_estimate = embedded), the two terms step doubling weighs, from
 * one ODE step. Position: how far apart ODE's semi-implicit Euler step (position from the velocity
 * at the step's end) and the explicit Euler step it embeds (from the velocity at its start) put a
 * body's points, halved: h/2 times the centre's change of velocity dv, plus the reach times the
 * change of angular velocity; under an acceleration a this is h^2 |a| / 2, the semi-implicit step's
 * own local error in position. Velocity (times h, as doubling weighs it): h/2 times the change of
 * acceleration, dv less the last accepted step's dv scaled to this step (h^2 |da/dt| h / 2). A force
 * that comes on within the step (a touchdown, a toe that sticks) shows in both. The largest over the
 * bodies; it costs no ODE step beyond the step itself. */
static double embedded_m(const fs_sim *sim, const body_state *before, const body_state *after, double h)
{
    const struct fs_sim_saved *s = sim->saved;
    double worst = 0, q = s->h_before > 0 ? h / s->h_before : 0;
    for (int i = 0; i < nbodies_saved(sim); i++) {
        double r = reach_of(sim, i), dv[6], jerk[2] = {0, 0};
        for (int k = 0; k < 3; k++) {
            dv[k] = after[i].v[k] - before[i].v[k];
            dv[3 + k] = after[i].w[k] - before[i].w[k];
        }
        for (int k = 0; q > 0 && k < 6; k++) /* the change of acceleration: the velocity's own error */
            jerk[k / 3] += (dv[k] - q * s->dv[i][k]) * (dv[k] - q * s->dv[i][k]);
        double e = 0.5 * h * (sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]) + sqrt(jerk[0]) +
                              r * (sqrt(dv[3] * dv[3] + dv[4] * dv[4] + dv[5] * dv[5]) + sqrt(jerk[1])));
        worst = isfinite(e) ? fmax(worst, e) : INFINITY;
    }
    return worst;
}

/* Keeps each body's change of velocity over the step just accepted, for the next estimate. */
static void remember_change(fs_sim *sim, const body_state *before, const body_state *after, double h)
{
    struct fs_sim_saved *s = sim->saved;
    for (int i = 0; i < nbodies_saved(sim); i++)
        for (int k = 0; k < 3; k++) {
            s->dv[i][k] = after[i].v[k] - before[i].v[k];
            s->dv[i][3 + k] = after[i].w[k] - before[i].w[k];
        }
    s->h_before = h;
}

/* One step under the embedded estimate: a single ODE step of h = step_max_s / 2^level, at most the
 * dampers' bound, kept within the tolerance (or at the least level), else put back and tried smaller,
 * as the doubled step is. */
static fs_status embedded_step(fs_sim *sim, double bound, fs_error *err)
{
    const fs_scenario_def *d = &sim->sc->def;
    struct fs_sim_saved *s = sim->saved;
    double tol = d->tolerance_m;
    int least = 0; /* the level of the least ODE step */
    while (d->step_max_s / ldexp(1, least + 1) >= d->step_min_s * (1 - 1e-9) && least < FS_STEP_LEVELS - 1)
        least++;
    int bound_level = 0; /* the largest level step the bound cuts to the bound itself */
    while (d->step_max_s / ldexp(1, bound_level) > 2 * bound && bound_level < least)
        bound_level++;
    sim->level = sim->level > least ? least : sim->level < bound_level ? bound_level : sim->level;
    fs_sim_save_state(sim);
    for (int tries = 0;; tries++) {
        double level_h = d->step_max_s / ldexp(1, sim->level), h = to_horizon(sim, fmin(level_h, bound));
        int at_bound = bound < level_h && h == bound;
        int at_least = sim->level >= least;
        fs_error trial_err;
        fs_status st = one(sim, h, tries > 0, &trial_err);
        double e = INFINITY;
        body_state after[FS_MAX_BODIES + 1];
        if (st == FS_OK) {
            read_bodies(sim, after);
            e = embedded_m(sim, s->body, after, h);
        }
        if (st == FS_OK && (e <= tol || at_least)) {
            remember_change(sim, s->body, after, h);
            keep_step(sim, h, e, 1, bound_level, at_bound);
            return FS_OK;
        }
        if (st != FS_OK && at_least) { /* the checks fail at the least step: a failure of the run */
            *err = trial_err;
            return st;
        }
        reject_step(sim, st, e, least);
    }
}

fs_status fs_sim_adaptive_step(fs_sim *sim, fs_error *err)
{
    const fs_scenario_def *d = &sim->sc->def;
    struct fs_sim_saved *s = sim->saved;
    double tol = d->tolerance_m;
    /* the dampers' limit (damped_step): while a foot touches, the contacts' too */
    double bound = fmin(sim->damped_step_s, sim->contacts_now > 0 ? sim->damped_contact_s : INFINITY);
    if (d->error_estimate == FS_ESTIMATE_EMBEDDED)
        return embedded_step(sim, bound, err);
    int least = 0; /* the level whose half step is the least ODE step */
    while (d->step_max_s / ldexp(1, least + 1) / 2 >= d->step_min_s * (1 - 1e-9) && least < FS_STEP_LEVELS - 1)
        least++;
    if (sim->level > least)
        sim->level = least;
    int bound_level = 0; /* the largest step the dampers allow */
    while (d->step_max_s / ldexp(1, bound_level) > 2 * bound && bound_level < least)
        bound_level++;
    if (sim->level < bound_level)
        sim->level = bound_level;
    int capped = sim->level == bound_level && bound_level > 0; /* the dampers, not the error, set the step */
    fs_sim_save_state(sim);
    int tries = 0;
    if (capped && sim->cruise_left > 0 && sim->contacts_now > 0) {
        /* cruising at the dampers' bound: one ODE step of it, kept unless the contact set changed */
        double h = to_horizon(sim, bound);
        uint64_t before = touching(sim);
        fs_error trial_err;
        fs_status st = one(sim, h, tries++ > 0, &trial_err);
        if (st == FS_OK && touching(sim) == before) {
            sim->substeps_now = 1;
            sim->step_error_m = 0;
            sim->cruise_left--;
            sim->stats.cruised++;
            fs_sim_count_step(sim, h, sim->level);
            return FS_OK;
        }
        fs_sim_restore_state(sim); /* something changed: the step is doubled after all */
        sim->cruise_left = 0;
    }
    for (;;) {
        double t0 = sim->time_s, h = to_horizon(sim, d->step_max_s / ldexp(1, sim->level));
        int at_least = sim->level >= least;
        fs_error trial_err;
        fs_status st = one(sim, h, tries++ > 0, &trial_err);
        double e = INFINITY;
        if (st == FS_OK) {
            read_bodies(sim, s->whole);
            fs_sim_restore_state(sim);
            st = one(sim, h / 2, 1, &trial_err);
            if (st == FS_OK) {
                fs_sim_add_step_force(sim, 0, 2);
                sim->time_s = t0 + h / 2;
                st = one(sim, h / 2, 1, &trial_err);
            }
            if (st == FS_OK) {
                fs_sim_add_step_force(sim, 1, 2);
                body_state half[FS_MAX_BODIES + 1];
                read_bodies(sim, half);
                e = difference_m(sim, s->whole, half, h);
            }
        }
        if (st == FS_OK && (e <= tol || at_least)) {
            sim->time_s = t0 + h; /* as a whole step of h ends */
            keep_step(sim, h, e, 2, 0, 0);
            sim->cruise_left = capped && tries == 1 ? CRUISE_STEPS : 0; /* accepted at once at the bound */
            return FS_OK;
        }
        if (st != FS_OK && at_least) { /* the checks fail at the least step: a failure of the run */
            *err = trial_err;
            return st;
        }
        reject_step(sim, st, e, least); /* beyond the tolerance, or the checks failed at a larger step */
    }
}
