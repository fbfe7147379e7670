/* sim_carriage.c: the kinematic carriage on a robot body, its drive and its work (fs_carriage.h). */
#include "footsim/sim/fs_carriage.h"

#include "sim_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct fs_carriage {
    fs_sim *sim;
    dBodyID body;
    dJointID slider;
    dJointFeedback slider_feedback; /* the slider's force and torque on the robot over the last step */
    fs_spring suspension;
    double start[3];                /* where the carriage started, m */
    double before[3];               /* the robot body's position before the step, m */
    double suspension_force_N[3];   /* the suspension's force on the robot over the step, N */
    fs_carriage_path_fn path;       /* where it is to be (fs_carriage_set_path) */
    void *path_user;
    double step_start_s;            /* the time the step being taken started at (fs_carriage_drive) */
} fs_carriage;

static void follow(void *user, double h);
static void exchange(void *user, double state[6], int saving);

/* The suspension's force on the robot (its body 2) for the state it is measured in, N. */
static void suspension_force(const fs_spring *s, double f[3])
{
    double p1[3], p2[3], len = 0;
    fs_spring_anchors(s, p1, p2);
    for (int k = 0; k < 3; k++)
        len += (p2[k] - p1[k]) * (p2[k] - p1[k]);
    len = sqrt(len);
    double t = fs_spring_measure(s).force_N;
    for (int k = 0; k < 3; k++)
        f[k] = len > 0 ? -t * (p2[k] - p1[k]) / len : 0;
}

static int explicit_springs(const fs_sim *sim) { return sim->sc->def.springs == FS_SPRING_EXPLICIT; }

/* The carriage's work on the robot over the step just taken, J (fs_check_work_fn). */
static double carriage_work(void *user, const fs_sim *sim)
{
    fs_carriage *c = user;
    if (!explicit_springs(sim))
        suspension_force(&c->suspension, c->suspension_force_N);
    const dReal *p = dBodyGetPosition(sim->robot), *w = dBodyGetAngularVel(sim->robot);
    const dReal *f = c->slider_feedback.f1, *t = c->slider_feedback.t1;
    double h = sim->step_now_s, work = 0;
    for (int k = 0; k < 3; k++)
        work += (f[k] + c->suspension_force_N[k]) * (p[k] - c->before[k]) + t[k] * w[k] * h;
    /* the next substep's work, if the step is taken in substeps, from here */
    memcpy(c->before, p, sizeof c->before);
    if (explicit_springs(sim))
        suspension_force(&c->suspension, c->suspension_force_N);
    return work;
}

fs_status fs_carriage_new(fs_sim *sim, double height_m, double k_N_per_m, double c_Ns_per_m, fs_carriage **out,
                          fs_error *err)
{
    fs_carriage *c = calloc(1, sizeof *c);
    *out = c;
    if (!c)
        return fs_fail(err, FS_NO_MEMORY, "%s: no memory for the walking machine's carriage", sim->sc->path);
    c->sim = sim;
    const dReal *p = dBodyGetPosition(sim->robot);
    double robot_at[3] = {p[0], p[1], p[2]};
    c->start[0] = p[0];
    c->start[1] = p[1];
    c->start[2] = p[2] + height_m;
    c->body = dBodyCreate(sim->world);
    dBodySetKinematic(c->body);
    dBodySetPosition(c->body, c->start[0], c->start[1], c->start[2]);
    c->slider = dJointCreateSlider(sim->world, 0);
    dJointAttach(c->slider, sim->robot, c->body);
    dJointSetSliderAxis(c->slider, 0, 0, 1);
    dJointSetFeedback(c->slider, &c->slider_feedback);
    fs_sim_spring_init(sim, &c->suspension, c->body, sim->robot, c->start, robot_at, k_N_per_m, c_Ns_per_m, height_m);
    sim->suspension = &c->suspension; /* prepared with the sim's springs, at each step and substep */
    /* under a tolerance: driven at each ODE step, and saved and put back with the rest */
    sim->driven.follow = follow;
    sim->driven.exchange = exchange;
    sim->driven.user = c;
    if (sim->saved) /* its damper bounds the error-controlled step as the foot's do (sim_adapt.c) */
        sim->damped_step_s = fmin(sim->damped_step_s, c_Ns_per_m / k_N_per_m);
    fs_check_set_work(sim, carriage_work, c);
    return FS_OK;
}

void fs_carriage_free(fs_carriage *c) { free(c); }

void fs_carriage_set_path(fs_carriage *c, fs_carriage_path_fn fn, void *user)
{
    c->path = fn;
    c->path_user = user;
}

/* The carriage's velocity to take it from where it is to the path's point elapsed_s into the step,
 * over an ODE step of h; the robot's position (the work's start) and an explicit suspension's force
 * from the state now. */
static void head_for(fs_carriage *c, double elapsed_s, double h)
{
    fs_sim *sim = c->sim;
    double dx = 0, dz = 0;
    if (c->path)
        c->path(c->path_user, elapsed_s, &dx, &dz);
    const dReal *at = dBodyGetPosition(c->body);
    dBodySetLinearVel(c->body, (c->start[0] + dx - at[0]) / h, 0, (c->start[2] + dz - at[2]) / h);
    memcpy(c->before, dBodyGetPosition(sim->robot), sizeof c->before);
    if (explicit_springs(sim))
        suspension_force(&c->suspension, c->suspension_force_N);
}

void fs_carriage_drive(fs_carriage *c)
{
    fs_sim *sim = c->sim;
    c->step_start_s = sim->time_s;
    if (!sim->saved) /* fixed steps: one velocity over the whole step (and its substeps) */
        head_for(c, sim->sc->def.step_s, sim->sc->def.step_s);
}

/* Under a tolerance, at the start of each ODE step of h (fs_sim.driven.follow). */
static void follow(void *user, double h)
{
    fs_carriage *c = user;
    if (c->sim->saved) /* an error-controlled step: each ODE step to the path at its own end */
        head_for(c, c->sim->time_s - c->step_start_s + h, h);
}

/* Its position and velocity into state, or back (fs_sim.driven.exchange). */
static void exchange(void *user, double state[6], int saving)
{
    fs_carriage *c = user;
    if (saving) {
        memcpy(state, dBodyGetPosition(c->body), 3 * sizeof(double));
        memcpy(state + 3, dBodyGetLinearVel(c->body), 3 * sizeof(double));
    } else {
        dBodySetPosition(c->body, state[0], state[1], state[2]);
        dBodySetLinearVel(c->body, state[3], state[4], state[5]);
    }
}
