/* sim_step.c: one step as named stages (fs_stage), each timed when the sim is profiled. */
#include "sim_internal.h"
#include "sim_soil.h"

#include <math.h>
#include <string.h>
#include <time.h>

/* ---- profiling ---------------------------------------------------------------------------- */

double fs_clock_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Adds the time since the last stage ended to stage, when profiling. */
void fs_sim_lap(fs_sim *sim, fs_stage stage)
{
    if (!sim->profile)
        return;
    double t = fs_clock_s();
    if (sim->profile_mark > 0) {
        sim->profile->stage_s[stage] += t - sim->profile_mark;
        sim->profile->laps[stage]++;
    }
    sim->profile_mark = t;
}

double fs_sim_load_now_N(const fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    return sim->load_N * (s->ramp_s > 0 && sim->time_s < s->ramp_s ? sim->time_s / s->ramp_s : 1.0);
}

static void apply_load(fs_sim *sim)
{
    double f = fs_sim_load_now_N(sim);
    double p[3];
    fs_sim_ankle(sim, p);
    dBodyAddForceAtPos(sim->body[sim->geom->ankle_body], f * sim->down[0], f * sim->down[1], f * sim->down[2], p[0],
                       p[1], p[2]);
}

void fs_sim_body_add_torque(fs_sim *sim, int i, const double torque_N_m[3])
{
    dBodyAddTorque(fs_sim_body_id(sim, i), torque_N_m[0], torque_N_m[1], torque_N_m[2]);
    /* ODE clears it after its step: kept, for the step's later substeps */
    for (int k = 0; k < 3; k++)
        sim->torque_again[i][k] += torque_N_m[k];
    sim->torque_added = 1;
}

/* The torques added for this step, again for a later substep of it. */
static void add_torques_again(fs_sim *sim)
{
    for (int i = 0; sim->torque_added && i < fs_sim_nbodies(sim); i++) {
        const double *q = sim->torque_again[i];
        if (q[0] != 0 || q[1] != 0 || q[2] != 0)
            dBodyAddTorque(fs_sim_body_id(sim, i), q[0], q[1], q[2]);
    }
}

/* One ODE step of h, the whole step or one of its substeps, as named stages. */
static fs_status advance(fs_sim *sim, double h, fs_error *err)
{
    const fs_scenario_def *s = &sim->sc->def;
    fs_sim_set_step(sim, h);
    /* external loads */
    apply_load(sim);
    fs_sim_lap(sim, FS_STAGE_LOADS);
    /* spring-dampers: soft rows set for h, or explicit forces (a carriage's suspension first) */
    if (sim->suspension)
        fs_spring_prepare(sim->suspension, h);
    for (int i = 0; i < sim->geom->nsprings; i++)
        fs_spring_prepare(&sim->spring[i], h);
    if (sim->has_achilles)
        fs_spring_prepare(&sim->achilles, h);
    fs_sim_lap(sim, FS_STAGE_SPRINGS);
    /* collision: the foot's shapes against the ground, nothing else */
    fs_sim_remember_contacts(sim);
    sim->contacts_now = 0;
    if (sim->ground)
        fs_sim_collide(sim);
    sim->contacts_total += sim->contacts_now;
    if (sim->contacts_now > 0)
        fs_sim_note_touch(sim, h);
    if (sim->soil) { /* the soil's forces, explicit, for this (sub)step (fs_sim_soil.h) */
        fs_status st = fs_sim_soil_apply(sim, h, err);
        if (st != FS_OK)
            return st;
    }
    fs_sim_lap(sim, FS_STAGE_CONTACTS);
    /* the ODE step, with this sim's own state of ODE's one random generator (QuickStep draws on
     * it to order its constraints), so that other sims stepped between leave it alone */
    dRandSetSeed(sim->rand_seed);
    if (s->stepper == FS_STEPPER_QUICKSTEP)
        dWorldQuickStep(sim->world, h);
    else
        dWorldStep(sim->world, h);
    sim->rand_seed = dRandGetSeed();
    dJointGroupEmpty(sim->contact_group);
    sim->time_s += h;
    fs_sim_lap(sim, FS_STAGE_ODE);
    /* a sound state (finite, physical speeds, closed loops, no energy from nowhere), or a clear stop */
    fs_status st = fs_check_step(sim, err);
    fs_sim_lap(sim, FS_STAGE_CHECK);
    return st;
}

/* Whether foot shape i, which has no contact, could reach the ground within `ahead` s (the coming
 * step h and the window after it): its lowest point's height over the highest of five terrain
 * samples (under it, and its reach away along x and y), against how far it comes down in that time:
 * at the speed it has (its centre's descent, its turn at its reach), plus gravity from rest, over
 * `ahead` while nothing touches the ground (the whole foot falls) and over h otherwise (gravity over
 * the window would foresee a landing for every toe the foot holds a few mm above the ground). */
static int could_land(const fs_sim *sim, int i, double h, double ahead)
{
    dGeomID g = sim->shape[i];
    const dReal *p = dGeomGetPosition(g), *w = dBodyGetAngularVel(dGeomGetBody(g));
    double reach, low;
    if (dGeomGetClass(g) == dSphereClass) {
        reach = dGeomSphereGetRadius(g);
        low = p[2] - reach;
    } else {
        dVector3 l;
        dGeomBoxGetLengths(g, l);
        const dReal *R = dGeomGetRotation(g); /* 4 x 3, row-major: world z of each box axis in row 2 */
        reach = 0.5 * sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        low = p[2] - 0.5 * (fabs(R[8]) * l[0] + fabs(R[9]) * l[1] + fabs(R[10]) * l[2]);
    }
    const fs_terrain *t = &sim->sc->terrain;
    double top = fs_terrain_height(t, p[0], p[1]);
    for (int k = 0; k < 4; k++)
        top = fmax(top, fs_terrain_height(t, p[0] + (k == 0 ? reach : k == 1 ? -reach : 0),
                                          p[1] + (k == 2 ? reach : k == 3 ? -reach : 0)));
    if (sim->soil) /* the soil's undisturbed surface (a print only lowers it) */
        top += t->def.soil.depth_m;
    dVector3 v;
    dBodyGetPointVel(dGeomGetBody(g), p[0], p[1], p[2], v);
    double spin = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    double fall_s = sim->contacts_now ? h : ahead; /* under gravity alone: over the window when nothing holds the foot */
    double fall = (fmax(0, -v[2]) + spin * reach) * ahead + 0.5 * sim->sc->def.gravity_m_per_s2 * fall_s * fall_s;
    return low - top <= fall;
}

/* How many substeps the coming step is taken in: run.impact_substeps from a step in which a shape
 * without contact could land, or one touched for the first time, until impact_window_s after it;
 * else 1. */
static int substeps(fs_sim *sim, double h)
{
    const fs_scenario_def *s = &sim->sc->def;
    if (s->impact_substeps <= 1 || !sim->ground)
        return 1;
    int touching[FS_MAX_SHAPES] = {0};
    for (int i = 0; i < sim->contacts_now; i++)
        if (sim->scratch->shape[i] >= 0)
            touching[sim->scratch->shape[i]] = 1;
    for (int i = 0; i < sim->nshapes; i++) {
        /* a shape that touched in the last step and not in the one before: a touchdown seen late */
        int landed = touching[i] && !sim->touched_before[i];
        sim->touched_before[i] = (unsigned char)touching[i];
        if (landed || (!touching[i] && could_land(sim, i, h, h + s->impact_window_s)))
            sim->impact_until_s = fmax(sim->impact_until_s, sim->time_s + h + s->impact_window_s);
    }
    return sim->time_s < sim->impact_until_s ? s->impact_substeps : 1;
}

fs_status fs_sim_step(fs_sim *sim, fs_error *err)
{
    double h = sim->sc->def.step_s;
    fs_sim_lap(sim, FS_STAGE_CALLER);
    fs_ode_context(sim->ode_context); /* this sim is the one ODE may complain about now */
    int n = substeps(sim, h);
    sim->substeps_now = n;
    fs_status st = FS_OK;
    if (n == 1) {
        st = advance(sim, h, err);
    } else {
        double t0 = sim->time_s;
        for (int i = 0; i < n && st == FS_OK; i++) {
            sim->time_s = t0 + i * (h / n);
            if (i > 0)
                add_torques_again(sim);
            st = advance(sim, h / n, err);
            fs_sim_add_step_force(sim, i, n);
        }
        if (st == FS_OK)
            sim->time_s = t0 + h; /* as a whole step ends */
    }
    if (sim->torque_added) {
        memset(sim->torque_again, 0, sizeof sim->torque_again);
        sim->torque_added = 0;
    }
    if (sim->profile)
        sim->profile->steps++;
    return st;
}
