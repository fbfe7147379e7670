/* experiment_walk.c: the walking machine: a carriage driven through stance and swing. */
#include "footsim/experiment/fs_walk.h"

#include "footsim/sim/fs_carriage.h"
#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_sim_soil.h"

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

/* The ankle body's tilt from its start orientation, rad. */
static double ankle_tilt(const fs_sim *sim)
{
    double R[9];
    fs_sim_body_pose(sim, fs_sim_geom(sim)->ankle_body, NULL, R);
    return acos(fmax(-1.0, fmin(1.0, R[8])));
}

/* The walking machine while it runs: the carriage it drives and what it measures. */
typedef struct walk_run {
    const fs_scenario_def *d;
    const fs_terrain_def *td;
    fs_walk_result *out;
    fs_carriage *carriage;
    int step;                   /* the step of the gait the last sim step ended in */
    double phase;               /* and where in it, 0..1 */
    double rough_sum, flat_sum, tilt_max;
    int flat_steps, last_step, judged;
    /* on a soil (fs_walk.h): the press past press_m, now and at the last stance's end; the step's
       start (its soil work, its ankle at the stance's start) */
    const fs_soil_grid *soil;
    double weight_N, press_speed_m_per_s, extra_m, extra_end_m, work_at_start_J, stance_ankle[3];
    int in_stance, stance_on_soil;
    /* the sim step being taken: its start, and whether the press goes on down over it (the ground
       carried less than the load at its start); nothing a rejected ODE step changes (fs_carriage.h) */
    double step_start_s;
    int pressing;
} walk_run;

/* The carriage's path elapsed_s into the sim step being taken (fs_carriage_path_fn): the gait's, and
 * on a soil the press (fs_walk.h) at the rate it had at the step's start. */
static void walk_path(void *user, double elapsed_s, double *x, double *z)
{
    walk_run *w = user;
    const fs_scenario_def *d = w->d;
    int step;
    double phase;
    carriage_path(d, w->step_start_s + elapsed_s, x, z, &step, &phase);
    if (!w->soil)
        return;
    if (phase <= d->stance_fraction) { /* press until the soil carries the load (fs_walk.h) */
        *z -= w->pressing ? w->extra_m + w->press_speed_m_per_s * elapsed_s : w->extra_m;
    } else { /* back to the path over the swing, from where the stance just ended (in the swing's first
                step soil_stance has not yet moved the stance's press into extra_end_m: without this the drive
                jumped for one step to the last stance's press, up to 153 mm, and the ground force with it) */
        double swing = (phase - d->stance_fraction) / (1 - d->stance_fraction);
        *z -= (w->in_stance ? w->extra_m : w->extra_end_m) * (1 - swing);
    }
}

/* Before each step: the actuator takes the carriage along the path over it (fs_carriage.h). */
static void drive_carriage(void *user, fs_sim *sim)
{
    walk_run *w = user;
    w->step_start_s = fs_sim_time(sim);
    if (w->soil) {
        double f[3];
        fs_sim_ground_force(sim, f);
        w->pressing = fs_sim_time(sim) > 0 && f[2] < w->weight_N && fs_sim_soil_over(sim, -1); /* off a section: rigid */
    }
    fs_carriage_drive(w->carriage); /* the step's checks count the carriage's work (fs_carriage.h) */
}

/* On a soil: a stance's start and end, and what the soil did in it. */
static void soil_stance(walk_run *w, fs_sim *sim)
{
    int stance = w->phase <= w->d->stance_fraction;
    double a[3];
    fs_sim_ankle(sim, a);
    if (stance && !w->in_stance) {
        memcpy(w->stance_ankle, a, sizeof a);
        w->stance_on_soil = 0;
    }
    if (stance) /* a query of the shapes' boxes: it changes nothing the sim computes */
        w->stance_on_soil |= fs_sim_soil_over(sim, -1);
    if (!stance && w->in_stance && w->step < FS_WALK_MAX_STEPS) {
        fs_walk_step *r = &w->out->step[w->step];
        double f[3];
        fs_sim_ground_force(sim, f);
        r->sinkage_m = fs_sim_soil_sinkage(sim, -1);
        r->slip_m = hypot(a[0] - w->stance_ankle[0], a[1] - w->stance_ankle[1]);
        r->soil_slip_m = fs_sim_soil_slip(sim, -1);
        r->extra_press_m = w->extra_m;
        r->load_N = f[2];
        r->on_soil = w->stance_on_soil;
        w->out->nsteps = w->step + 1;
        w->extra_end_m = w->extra_m;
        w->extra_m = 0;
    }
    w->in_stance = stance;
}

/* After each step: the ground force, the stance tilt, and each step judged at mid-stance. */
static int judge_step(void *user, fs_sim *sim)
{
    walk_run *w = user;
    const fs_scenario_def *d = w->d;
    fs_walk_result *out = w->out;
    double x, z;
    carriage_path(d, fs_sim_time(sim), &x, &z, &w->step, &w->phase); /* where in the gait the step ended */
    if (w->soil && w->pressing && w->phase <= d->stance_fraction) /* the press went on down over the step */
        w->extra_m += w->press_speed_m_per_s * fs_sim_step_taken(sim);
    double f[3];
    fs_sim_ground_force(sim, f);
    out->peak_force_N = fmax(out->peak_force_N, f[2]);
    if (w->step != w->last_step) {
        if (w->soil && w->last_step >= 0 && w->last_step < FS_WALK_MAX_STEPS) /* the step just ended */
            out->step[w->last_step].soil_work_J = w->soil->work_J - w->work_at_start_J;
        if (w->soil)
            w->work_at_start_J = w->soil->work_J;
        w->judged = 0, w->last_step = w->step;
    }
    if (w->soil)
        soil_stance(w, sim);
    if (w->phase <= d->stance_fraction)
        w->tilt_max = fmax(w->tilt_max, ankle_tilt(sim));
    if (!w->judged && w->phase >= 0.5 * d->stance_fraction) {
        w->judged = 1;
        double a[3];
        fs_sim_ankle(sim, a);
        int ok = fs_sim_support(sim) > 0 && ankle_tilt(sim) < d->walk_fall_tilt_deg * DEG; /* contacts or soil */
        ok ? out->steps_completed++ : out->falls++;
        const fs_terrain_def *td = w->td;
        int rough = td->kind == FS_TERRAIN_ROUGH && a[0] >= td->patch_x_min_m && a[0] <= td->patch_x_max_m;
        if (rough) {
            w->rough_sum += fs_sim_contact_count(sim);
            out->rough_steps++;
        } else {
            w->flat_sum += fs_sim_contact_count(sim);
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
    fs_sim *sim;
    fs_status s = fs_sim_new(sc, &opts, &sim, err);
    if (s != FS_OK)
        return s;
    /* the carriage: kinematic, 0.1 m above the body, joined by a vertical slider and the suspension */
    fs_carriage *carriage;
    s = fs_carriage_new(sim, 0.1, d->suspension_k_N_per_m, d->suspension_c_Ns_per_m, &carriage, err);
    if (s != FS_OK) {
        fs_sim_free(sim);
        return s;
    }
    walk_run w = {.d = d, .td = &sc->terrain.def, .out = out, .carriage = carriage, .last_step = -1,
                  .soil = fs_sim_soil_grid(sim)};
    fs_carriage_set_path(carriage, walk_path, &w);
    if (w.soil) { /* the load the soil is to carry: the robot's weight and its foot's */
        w.weight_N = (d->robot.mass_kg + fs_sim_geom(sim)->total_mass_kg) * d->gravity_m_per_s2;
        w.press_speed_m_per_s = 2 * sc->terrain.def.soil.depth_m / (d->walk_period_s * d->stance_fraction);
        out->soil = 1;
    }
    const fs_step_hook hooks[] = {{"judged", judge_step, &w}};
    fs_drive_spec spec = {.max_steps = (long)ceil(d->walk_steps * d->walk_period_s / d->step_s),
                          .before_step = drive_carriage, .before_user = &w, .hooks = hooks, .nhooks = 1, .obs = obs};
    fs_drive_result r;
    s = fs_drive(sim, &spec, &r, err);
    out->rough_contacts_mean = out->rough_steps ? w.rough_sum / out->rough_steps : 0;
    out->flat_contacts_mean = w.flat_steps ? w.flat_sum / w.flat_steps : 0;
    out->peak_tilt_deg = w.tilt_max / DEG;
    out->end_time_s = fs_sim_time(sim);
    if (w.soil && w.last_step >= 0 && w.last_step < FS_WALK_MAX_STEPS) /* the last step's work, to the end */
        out->step[w.last_step].soil_work_J = w.soil->work_J - w.work_at_start_J;
    fs_sim_free(sim);
    fs_carriage_free(carriage); /* after the sim, which stepped it */
    return s;
}
