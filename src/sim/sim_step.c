/* sim_step.c: one step as named stages (fs_stage), each timed when the sim is profiled. */
#include "sim_internal.h"

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
}

fs_status fs_sim_step(fs_sim *sim, fs_error *err)
{
    const fs_scenario_def *s = &sim->sc->def;
    double h = s->step_s;
    fs_sim_lap(sim, FS_STAGE_CALLER);
    fs_ode_context(sim->ode_context); /* this sim is the one ODE may complain about now */
    /* external loads */
    apply_load(sim);
    fs_sim_lap(sim, FS_STAGE_LOADS);
    /* spring-dampers: soft rows set for h, or explicit forces */
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
    if (sim->profile)
        sim->profile->steps++;
    return st;
}
