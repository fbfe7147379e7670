/* sim_step.c: the step a caller takes (fs_sim_step): whole, in substeps near a touchdown, or
 * error-controlled (sim_adapt.c), each ODE step taken by sim_advance.c, within ODE's guard. */
#include "sim_internal.h"

#include <math.h>
#include <string.h>

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
    if (sim->soil) /* the soil's undisturbed surface (a print only lowers it), where its section lies */
        top += fs_soil_depth_over(&t->def.soil, p[0] - reach, p[0] + reach);
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

/* The step, within fs_ode_guard (ODE's errors come back as FS_NUMERICAL). */
static fs_status step(void *arg, fs_error *err)
{
    fs_sim *sim = arg;
    double h = sim->sc->def.step_s;
    fs_status st = FS_OK;
    int n = sim->saved ? 0 : substeps(sim, h);
    if (sim->saved) {
        st = fs_sim_adaptive_step(sim, err); /* run.tolerance_m (sim_adapt.c) */
    } else if ((sim->substeps_now = n) == 1) {
        st = fs_sim_step_by(sim, h, err);
    } else {
        double t0 = sim->time_s;
        for (int i = 0; i < n && st == FS_OK; i++) {
            sim->time_s = t0 + i * (h / n);
            if (i > 0)
                fs_sim_add_torques_again(sim);
            st = fs_sim_step_by(sim, h / n, err);
            fs_sim_add_step_force(sim, i, n);
        }
        if (st == FS_OK)
            sim->time_s = t0 + h; /* as a whole step ends */
    }
    if (n) {
        fs_sim_count_step(sim, h, 0);
        sim->stats.ode_steps += n;
    }
    if (sim->torque_added) {
        memset(sim->torque_again, 0, sizeof sim->torque_again);
        sim->torque_added = 0;
    }
    if (sim->profile)
        sim->profile->steps++;
    return st;
}

fs_status fs_sim_step(fs_sim *sim, fs_error *err)
{
    if (sim->ode_failed)
        return fs_fail(err, FS_NUMERICAL, "%s: an ODE error stopped this simulation at %.6g s; it can only be "
                       "destroyed (build a new one to run again)", sim->ode_context, sim->time_s);
    fs_sim_lap(sim, FS_STAGE_CALLER);
    fs_ode_context(sim->ode_context); /* this sim is the one ODE may complain about now */
    long warned = fs_warning_count();
    fs_status s = fs_ode_guard(step, sim, &sim->ode_failed, err);
    sim->warnings += fs_warning_count() - warned; /* ODE's messages while it stepped this sim */
    return s;
}
