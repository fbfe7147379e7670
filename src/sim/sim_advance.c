/* sim_advance.c: one ODE step of h as named stages (fs_stage), each timed when the sim is profiled:
 * the load, the springs, collision and contacts, ODE's step, the state checks; and the torques a
 * caller adds, kept for a step's later substeps. The whole step, its substeps and the
 * error-controlled step (sim_step.c, sim_adapt.c) all take their ODE steps here. */
#include "sim_internal.h"
#include "sim_soil.h"

#include <math.h>
#include <string.h>

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
void fs_sim_add_torques_again(fs_sim *sim)
{
    for (int i = 0; sim->torque_added && i < fs_sim_nbodies(sim); i++) {
        const double *q = sim->torque_again[i];
        if (q[0] != 0 || q[1] != 0 || q[2] != 0)
            dBodyAddTorque(fs_sim_body_id(sim, i), q[0], q[1], q[2]);
    }
}

/* One ODE step of h, the whole step or one of its substeps, as named stages. */
fs_status fs_sim_step_by(fs_sim *sim, double h, fs_error *err)
{
    const fs_scenario_def *s = &sim->sc->def;
    fs_sim_set_step(sim, h);
    if (sim->driven.follow) /* the carriage: under a tolerance, to its path at this ODE step's end (fs_carriage.h) */
        sim->driven.follow(sim->driven.user, h);
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
