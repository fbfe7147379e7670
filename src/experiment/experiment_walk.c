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
    double x, z, t = fs_sim_time(sim) + d->step_s;
    carriage_path(d, t, &x, &z, &w->step, &w->phase);
    fs_carriage_drive(w->carriage, x, z); /* the step's checks count the carriage's work (fs_carriage.h) */
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
    walk_run w = {.d = d, .td = &sc->terrain.def, .out = out, .carriage = carriage, .last_step = -1};
    const fs_step_hook hooks[] = {{"judged", judge_step, &w}};
    fs_drive_spec spec = {.max_steps = (long)ceil(d->walk_steps * d->walk_period_s / d->step_s),
                          .before_step = drive_carriage, .before_user = &w, .hooks = hooks, .nhooks = 1, .obs = obs};
    fs_drive_result r;
    s = fs_drive(sim, &spec, &r, err);
    out->rough_contacts_mean = out->rough_steps ? w.rough_sum / out->rough_steps : 0;
    out->flat_contacts_mean = w.flat_steps ? w.flat_sum / w.flat_steps : 0;
    out->peak_tilt_deg = w.tilt_max / DEG;
    out->end_time_s = fs_sim_time(sim);
    fs_sim_free(sim);
    fs_carriage_free(carriage); /* after the sim, which stepped it */
    return s;
}
