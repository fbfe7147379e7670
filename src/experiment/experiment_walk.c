/* experiment_walk.c: the walking machine: a carriage driven through stance and swing. */
#include "footsim/experiment/fs_walk.h"

#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <string.h>

#define DEG (M_PI / 180.0)

/* Where the carriage is at time t, relative to where it started: forward x and lift z. */
static void carriage_path(const fs_scenario_def *d, double t, double *x, double *z, int *step, double *phase)
{
    double u = t / d->walk_period_s;
    int n = (int)floor(u);
    double f = u - n; /* phase within the step, 0..1 */
    double swing = f <= d->stance_fraction ? 0 : (f - d->stance_fraction) / (1 - d->stance_fraction);
    /* stance: still, pressed down; swing: a smooth lift and a smooth advance */
    *x = d->step_length_m * (n + 0.5 * (1 - cos(M_PI * swing)));
    *z = swing > 0 ? d->lift_m * sin(M_PI * swing) - d->press_m * (1 - sin(M_PI * swing)) : -d->press_m;
    *step = n;
    *phase = f;
}

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

/* What the carriage's work over a step needs: the slider's feedback, the suspension, the robot's
 * position before the step and, for explicit springs, the suspension's force as applied. */
typedef struct carriage_drive {
    dBodyID robot;
    const dJointFeedback *slider;
    const fs_spring *suspension;
    int explicit_springs;
    double h, before[3], susp[3];
} carriage_drive;

/* The carriage's work on the robot over the step just taken, J (fs_check_work_fn): the slider's
 * force and torque and the suspension's force (explicit: from the state before the step, as
 * applied; implicit: after, as backward Euler applies it) times the robot's displacement and turn. */
static double carriage_work(void *user, const fs_sim *sim)
{
    carriage_drive *c = user;
    (void)sim;
    if (!c->explicit_springs)
        suspension_force(c->suspension, c->susp);
    const dReal *p = dBodyGetPosition(c->robot), *w = dBodyGetAngularVel(c->robot);
    double work = 0;
    for (int k = 0; k < 3; k++)
        work += (c->slider->f1[k] + c->susp[k]) * (p[k] - c->before[k]) + c->slider->t1[k] * w[k] * c->h;
    return work;
}

/* The ankle body's tilt from its start orientation, rad. */
static double ankle_tilt(const fs_sim *sim)
{
    const dReal *R = dBodyGetRotation(sim->body[sim->geom->ankle_body]);
    return acos(fmax(-1.0, fmin(1.0, R[10])));
}

/* The walking machine while it runs: the carriage it drives and what it measures. */
typedef struct walk_run {
    const fs_scenario_def *d;
    const fs_terrain_def *td;
    fs_walk_result *out;
    dBodyID carriage;
    const dReal *body_pos;      /* the robot body's position, as ODE keeps it */
    double start[3];            /* the carriage's start */
    fs_spring *suspension;
    carriage_drive *drive;
    int step;                   /* the step of the gait the coming (then last) sim step belongs to */
    double phase;               /* and where in it, 0..1 */
    double rough_sum, flat_sum, tilt_max;
    int flat_steps, last_step, judged;
} walk_run;

/* Before each step: the actuator sets the carriage's velocity to take it to the path. */
static void drive_carriage(void *user, fs_sim *sim)
{
    walk_run *w = user;
    const fs_scenario_def *d = w->d;
    double x, z, t = sim->time_s + d->step_s;
    carriage_path(d, t, &x, &z, &w->step, &w->phase);
    const dReal *c = dBodyGetPosition(w->carriage);
    dBodySetLinearVel(w->carriage, (w->start[0] + x - c[0]) / d->step_s, 0, (w->start[2] + z - c[2]) / d->step_s);
    fs_spring_prepare(w->suspension, d->step_s);
    memcpy(w->drive->before, w->body_pos, sizeof w->drive->before);
    if (d->springs == FS_SPRING_EXPLICIT)
        suspension_force(w->suspension, w->drive->susp);
    /* the step's checks take the carriage's work into their energy balance (carriage_work) */
}

/* After each step: the ground force, the stance tilt, and each step judged at mid-stance. */
static int judge_step(void *user, fs_sim *sim)
{
    walk_run *w = user;
    const fs_scenario_def *d = w->d;
    fs_walk_result *out = w->out;
    double f[3];
    fs_sim_ground_force(sim, f);
    out->peak_force_N = fmax(out->peak_force_N, f[2]);
    if (w->step != w->last_step)
        w->judged = 0, w->last_step = w->step;
    if (w->phase <= d->stance_fraction)
        w->tilt_max = fmax(w->tilt_max, ankle_tilt(sim));
    if (!w->judged && w->phase >= 0.5 * d->stance_fraction) {
        w->judged = 1;
        double a[3];
        fs_sim_ankle(sim, a);
        int ok = sim->contacts_now > 0 && ankle_tilt(sim) < d->walk_fall_tilt_deg * DEG;
        ok ? out->steps_completed++ : out->falls++;
        const fs_terrain_def *td = w->td;
        int rough = td->kind == FS_TERRAIN_ROUGH && a[0] >= td->patch_x_min_m && a[0] <= td->patch_x_max_m;
        if (rough) {
            w->rough_sum += sim->contacts_now;
            out->rough_steps++;
        } else {
            w->flat_sum += sim->contacts_now;
            w->flat_steps++;
        }
    }
    return 0;
}

fs_status fs_walk_run(const fs_scenario *sc, const fs_run_observer *obs, fs_walk_result *out, fs_error *err)
{
    const fs_scenario_def *d = &sc->def;
    memset(out, 0, sizeof *out);
    if (d->kind != FS_SCENARIO_WALK || d->robot.mass_kg <= 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: a walking machine needs [scenario] kind = walk and a [robot] mass_kg > 0",
                       sc->path);
    fs_sim_options opts = fs_observer_sim_options(obs);
    fs_sim sim;
    fs_status s = fs_sim_build(&sim, sc, &opts, err);
    if (s != FS_OK)
        return s;
    /* the carriage: kinematic, above the body, joined by a vertical slider and the suspension */
    const dReal *p = dBodyGetPosition(sim.robot);
    double start[3] = {p[0], p[1], p[2] + 0.1};
    dBodyID carriage = dBodyCreate(sim.world);
    dBodySetKinematic(carriage);
    dBodySetPosition(carriage, start[0], start[1], start[2]);
    dJointID slider = dJointCreateSlider(sim.world, 0);
    dJointAttach(slider, sim.robot, carriage);
    dJointSetSliderAxis(slider, 0, 0, 1);
    dJointFeedback feedback;
    dJointSetFeedback(slider, &feedback);
    fs_spring suspension;
    double a1[3] = {start[0], start[1], start[2]}, a2[3] = {p[0], p[1], p[2]};
    fs_spring_init(&suspension, sim.world, (fs_spring_impl)d->springs, carriage, sim.robot, a1, a2,
                   d->suspension_k_N_per_m, d->suspension_c_Ns_per_m, 0.1);
    carriage_drive drive = {sim.robot, &feedback, &suspension, d->springs == FS_SPRING_EXPLICIT, d->step_s,
                            {0, 0, 0}, {0, 0, 0}};
    fs_check_set_work(&sim, carriage_work, &drive);
    walk_run w = {.d = d, .td = &sc->terrain.def, .out = out, .carriage = carriage, .body_pos = p,
                  .start = {start[0], start[1], start[2]}, .suspension = &suspension, .drive = &drive,
                  .last_step = -1};
    const fs_step_hook hooks[] = {{"judged", judge_step, &w}};
    fs_drive_spec spec = {.max_steps = (long)ceil(d->walk_steps * d->walk_period_s / d->step_s),
                          .before_step = drive_carriage, .before_user = &w, .hooks = hooks, .nhooks = 1, .obs = obs};
    fs_drive_result r;
    s = fs_drive(&sim, &spec, &r, err);
    out->rough_contacts_mean = out->rough_steps ? w.rough_sum / out->rough_steps : 0;
    out->flat_contacts_mean = w.flat_steps ? w.flat_sum / w.flat_steps : 0;
    out->peak_tilt_deg = w.tilt_max / DEG;
    out->end_time_s = sim.time_s;
    fs_sim_destroy(&sim);
    return s;
}
