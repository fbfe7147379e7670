/* experiment_trial.c: landing trials: draw a pose, drop the robot on its foot, judge the outcome
 * (fs_outcome.h). */
#include "footsim/experiment/fs_trial.h"

#include "experiment_log.h"

#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_sim_soil.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#define DEG (M_PI / 180.0)

/* Uniform in [-1, 1) from the seed and a stream number: the same on every machine. */
static double symmetric(int seed, int stream)
{
    uint64_t z = ((uint64_t)(uint32_t)seed << 8) + (uint64_t)stream + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return 2.0 * ((double)(z >> 11) * (1.0 / 9007199254740992.0)) - 1.0;
}

void fs_trial_draw_pose(const fs_scenario *sc, int seed, fs_trial_draw *draw)
{
    const fs_scenario_def *d = &sc->def;
    memset(draw, 0, sizeof *draw);
    draw->seed = seed;
    draw->x_m = d->start_x_m + d->land_x_range_m * symmetric(seed, 1);
    draw->y_m = d->start_y_m + d->land_y_range_m * symmetric(seed, 2);
    draw->yaw_deg = d->yaw_deg + d->land_yaw_range_deg * symmetric(seed, 3);
    draw->pitch_deg = d->pitch_deg + d->land_tilt_range_deg * symmetric(seed, 4);
    draw->roll_deg = d->roll_deg + d->land_tilt_range_deg * symmetric(seed, 5);
}

/* What a trial watches while it runs. */
typedef struct watch {
    int touched;
    double mass_kg;     /* of everything that moves */
    double impulse_window_s; /* [landing] impulse_window_s */
    double force_from_s; /* the start of the (sub)step in which the ground first pushed */
    double momentum_Ns; /* the ground's vertical impulse beyond the weight (and load) since then */
    int soil;           /* the ground is a soil: the impact lasts until the fall is stopped */
    double stopped_s;   /* with a soil: when the robot's centre of mass first stopped falling (-1: not yet) */
    double touch_ankle[3];
    double contact_sum;
    double contact_steps; /* the steps watched, each weighing its time over step_s (1 with fixed steps) */
    double rest_since;
    /* a biped's feet, each from its own touchdown */
    int foot_touched[FS_MAX_FEET];
    double foot_touch_ankle[FS_MAX_FEET][3], foot_contact_sum[FS_MAX_FEET];
} watch;

/* Each of a biped's feet: its touchdown, and its contacts while the trial watches. */
static void observe_feet(const fs_sim *sim, watch *w, fs_trial_result *out)
{
    for (int f = 0; f < fs_sim_geom(sim)->nfeet; f++) {
        int n = fs_sim_foot_contacts(sim, f);
        const fs_touch *t = fs_sim_first_touch(sim, f);
        if (!w->foot_touched[f] && t) {
            w->foot_touched[f] = 1;
            out->foot[f].touchdown_s = t->time_s;
            memcpy(w->foot_touch_ankle[f], t->ankle_m, sizeof t->ankle_m);
        }
        if (w->touched)
            w->foot_contact_sum[f] += n * (fs_sim_step_taken(sim) / fs_sim_scenario(sim)->def.step_s);
    }
}

static void observe_step(const fs_sim *sim, watch *w, fs_trial_result *out, double h)
{
    if (fs_sim_geom(sim)->nfeet > 1)
        observe_feet(sim, w, out);
    double f[3];
    fs_sim_ground_force(sim, f);
    double tilt = fs_sim_robot_tilt(sim) / DEG;
    out->peak_tilt_deg = fmax(out->peak_tilt_deg, tilt);
    if (!w->touched && fs_sim_support(sim) > 0) { /* contacts, or the soil holding a foot */
        /* the first touch of any foot, at the instant its lowest point met the surface (fs_touch);
         * a biped's ankle drop and slip are each foot's, from its own touch (finish) */
        const fs_touch *first = NULL;
        for (int f = 0; f < (fs_sim_geom(sim)->nfeet > 1 ? fs_sim_geom(sim)->nfeet : 1); f++) {
            const fs_touch *t = fs_sim_first_touch(sim, f);
            if (t && (!first || t->time_s < first->time_s))
                first = t;
        }
        w->touched = 1;
        out->touchdown_s = first ? first->time_s : fs_sim_time(sim);
        w->force_from_s = first ? first->found_s : fs_sim_time(sim) - h;
        if (first)
            memcpy(w->touch_ankle, first->ankle_m, sizeof first->ankle_m);
        else
            fs_sim_ankle(sim, w->touch_ankle);
    }
    if (!w->touched)
        return;
    out->peak_force_N = fmax(out->peak_force_N, f[2]);
    double weight = h / fs_sim_scenario(sim)->def.step_s; /* exactly 1 with fixed steps: a mean over time */
    w->contact_sum += fs_sim_contact_count(sim) * weight;
    w->contact_steps += weight;
    /* the impact: the ground's vertical impulse beyond the weight (and any load) since it first
     * pushed, which is the momentum it has taken out of the fall, at its largest within the window
     * after touchdown. A landing reads its mass times its speed at the start of the (sub)step whose
     * collision found the contact (and any rebound); a robot that sinks on or topples after its
     * impact loses momentum to gravity again and is read where its impact ended. No threshold
     * decides when to stop counting: the largest value over a fixed time moves as little as the
     * motion does. The count starts with the (sub)step in which the contact force first acts (a
     * whole step after the touchdown's instant, or the substep that found it), so that whole steps
     * and substeps count alike; the speed then is the touchdown's plus g times up to that step, a
     * bias of at most the weight times the step (0.3 % of a landing's impulse at 1e-4 s). The step
     * that ends the window counts up to its end, its force taken as even over its pushing part. */
    double start = fmax(fs_sim_time(sim) - h, w->force_from_s), end = out->touchdown_s + w->impulse_window_s;
    double down[3];
    fs_sim_down(sim, down);
    if (w->soil) {
        /* A soil stops a fall over tens of ms (a foot sinking 19 mm into LETE sand: about 80 ms, its
         * force below the weight for the first half), not the few ms of rigid ground: the window then
         * lasts at least until the robot's centre of mass first stops falling, where the momentum
         * taken is the whole fall's (docs/soil.md, What reads the ground). */
        double v[3];
        fs_sim_robot_com(sim, NULL, v);
        if (w->stopped_s < 0 && v[0] * down[0] + v[1] * down[1] + v[2] * down[2] <= 0)
            w->stopped_s = fs_sim_time(sim);
        end = fmax(end, w->stopped_s < 0 ? fs_sim_time(sim) : w->stopped_s);
    }
    if (start < end && fs_sim_time(sim) > start) {
        double in = fmin(fs_sim_time(sim), end) - start;
        double weight_N = -(w->mass_kg * fs_sim_scenario(sim)->def.gravity_m_per_s2 + fs_sim_load_now_N(sim)) * down[2];
        w->momentum_Ns += (f[2] * h / (fs_sim_time(sim) - start) - weight_N) * in;
        out->impact_impulse_Ns = fmax(out->impact_impulse_Ns, w->momentum_Ns);
    }
}

/* The soil's measures at the end (fs_trial_result), NAN on rigid ground. */
static void soil_end(const fs_sim *sim, fs_trial_result *out)
{
    const fs_soil_grid *g = fs_sim_soil_grid(sim);
    fs_soil_print p = {.volume_m3 = NAN, .deepest_m = NAN, .area_m2 = NAN, .mean_slip_m = NAN};
    if (g)
        fs_soil_grid_print_of(g, &p);
    out->soil_sinkage_m = g ? fs_sim_soil_sinkage(sim, -1) : NAN;
    out->print_depth_m = p.deepest_m, out->print_area_m2 = p.area_m2;
    out->print_volume_m3 = p.volume_m3, out->print_slip_m = p.mean_slip_m;
}

static void finish(const fs_sim *sim, const watch *w, fs_trial_result *out)
{
    double a[3];
    fs_sim_ankle(sim, a);
    out->end_time_s = fs_sim_time(sim);
    out->final_tilt_deg = fs_sim_robot_tilt(sim) / DEG;
    out->final_contacts = fs_sim_contact_count(sim);
    out->mean_contacts = w->contact_steps ? w->contact_sum / w->contact_steps : 0;
    if (w->touched) {
        out->ankle_drop_m = w->touch_ankle[2] - a[2];
        out->slip_m = hypot(a[0] - w->touch_ankle[0], a[1] - w->touch_ankle[1]);
        out->settle_time_s = (w->rest_since >= 0 ? w->rest_since : fs_sim_time(sim)) - out->touchdown_s;
    }
    soil_end(sim, out);
    out->nfeet = fs_sim_geom(sim)->nfeet > 1 ? fs_sim_geom(sim)->nfeet : 1;
    if (out->nfeet == 1) {
        double f[3];
        fs_sim_ground_force(sim, f);
        out->foot[0].touchdown_s = out->touchdown_s;
        out->foot[0].ankle_drop_m = out->ankle_drop_m;
        out->foot[0].slip_m = out->slip_m;
        out->foot[0].mean_contacts = out->mean_contacts;
        out->foot[0].final_contacts = out->final_contacts;
        out->foot[0].final_force_N = f[2];
        return;
    }
    out->ankle_drop_m = out->slip_m = 0;
    for (int i = 0; i < out->nfeet; i++) {
        double p[3], f[3];
        fs_sim_foot_ankle(sim, i, p);
        fs_sim_foot_force(sim, i, f);
        out->foot[i].final_contacts = fs_sim_foot_contacts(sim, i);
        out->foot[i].mean_contacts = w->contact_steps ? w->foot_contact_sum[i] / w->contact_steps : 0;
        out->foot[i].final_force_N = f[2];
        if (w->foot_touched[i]) {
            const double *t = w->foot_touch_ankle[i];
            out->foot[i].ankle_drop_m = t[2] - p[2];
            out->foot[i].slip_m = hypot(p[0] - t[0], p[1] - t[1]);
        }
        out->ankle_drop_m += out->foot[i].ankle_drop_m / out->nfeet;
        out->slip_m = fmax(out->slip_m, out->foot[i].slip_m);
    }
}

/* The rules of fs_outcome.h from the scenario's [landing] and [run] keys and the terrain's bound. */
/* The mass of every body: the foot's, and the robot (a biped's legs are among the geometry's bodies). */
static double moving_mass_kg(const fs_sim *sim, const fs_scenario_def *d)
{
    double mass = 0;
    for (int i = 0; i < fs_sim_geom(sim)->nbodies; i++)
        mass += fs_sim_geom(sim)->body[i].mass_kg;
    return fs_sim_geom(sim)->biped ? mass : mass + d->robot.mass_kg;
}

/* The judge's rules; mass: of everything that moves (moving_mass_kg). */
static void rules_of(const fs_scenario *sc, double mass, fs_outcome_rules *r)
{
    const fs_scenario_def *d = &sc->def;
    *r = (fs_outcome_rules){.fall_lean_rad = d->fall_tilt_deg * DEG,
                            .landed_lean_rad = d->landed_tilt_deg * DEG,
                            .lost_ground_s = d->lost_ground_s,
                            .sink_bound_m = sc->terrain.def.sink_bound_m,
                            .rest_speed_m_per_s = d->rest_speed_m_per_s,
                            .rest_hold_s = d->rest_hold_s,
                            .window_s = d->duration_s,
                            .motion_window_s = d->motion_window_s,
                            .motion_decay = d->motion_decay,
                            /* everything moving at the rest speed */
                            .motion_floor_J = 0.5 * mass * d->rest_speed_m_per_s * d->rest_speed_m_per_s};
}

void fs_trial_rules(const fs_scenario *sc, const fs_sim *sim, fs_outcome_rules *rules)
{
    rules_of(sc, moving_mass_kg(sim, &sc->def), rules);
}

static void sample_of(const fs_sim *sim, fs_outcome_sample *s)
{
    double ke;
    fs_sim_energy(sim, &ke, NULL, NULL);
    *s = (fs_outcome_sample){fs_sim_time(sim), fs_sim_robot_tilt(sim), ke, fs_sim_max_speed(sim), fs_sim_support(sim),
                             fs_sim_step_taken(sim) / fs_sim_scenario(sim)->def.step_s};
}

/* A trial's state while it runs, for its hook. */
typedef struct trial_run {
    const fs_scenario_def *d;
    watch w;
    fs_judge judge;
    fs_outcome_sample last;
    fs_trial_result *out;
} trial_run;

/* Watches and judges each step; stops when the judge says the trial is over. */
static int judge_step(void *user, fs_sim *sim)
{
    trial_run *t = user;
    observe_step(sim, &t->w, t->out, fs_sim_step_taken(sim)); /* step_s, or the error-controlled step's */
    sample_of(sim, &t->last);
    int over = fs_judge_step(&t->judge, &t->last);
    if (t->judge.at_rest && t->w.rest_since < 0)
        t->w.rest_since = t->judge.rest_since_s;
    return over;
}

/* Steps until the judge decides or the window ends; classifies. */
static fs_status run_trial(const fs_scenario *sc, const fs_run_observer *obs, fs_run_result *log,
                           fs_trial_result *out, fs_error *err)
{
    const fs_scenario_def *d = &sc->def;
    if (log) {
        memset(log, 0, sizeof *log);
        fs_status opened = fs_log_open(log, sc, 1, err);
        if (opened != FS_OK)
            return opened;
    }
    fs_sim_options opts = fs_observer_sim_options(obs);
    fs_sim *sim;
    fs_status s = fs_sim_new(sc, &opts, &sim, err);
    if (s != FS_OK)
        return s;
    fs_run_logger logger;
    fs_log_begin(&logger, log, sim);
    trial_run t = {.d = d, .w = {.rest_since = -1, .mass_kg = moving_mass_kg(sim, d),
                                 .impulse_window_s = d->impulse_window_s, .soil = fs_sim_soil_grid(sim) != NULL,
                                 .stopped_s = -1},
                   .out = out};
    fs_outcome_rules rules;
    rules_of(sc, t.w.mass_kg, &rules);
    out->robot_mass_kg = d->robot.mass_kg;
    fs_judge_init(&t.judge, &rules);
    /* the logger last and only when asked: it never stops the trial, so the judge's stop is the same */
    const fs_step_hook hooks[] = {{"judged", judge_step, &t}, {"logged", fs_log_after_step, &logger}};
    fs_drive_spec spec = {.max_steps = (long)ceil(d->duration_s / d->step_s - 1e-9), .hooks = hooks,
                          .nhooks = log ? 2 : 1, .obs = obs};
    fs_drive_result r;
    fs_error step_err;
    s = fs_drive(sim, &spec, &r, &step_err);
    out->steps = r.steps - r.step_failed;
    out->rejected_steps = fs_sim_step_stats(sim)->rejected;
    out->ode_steps = fs_sim_step_stats(sim)->ode_steps;
    out->step_least_s = fs_sim_step_stats(sim)->least_s;
    out->step_median_s = fs_sim_median_step_s(sim);
    out->step_largest_s = fs_sim_step_stats(sim)->largest_s;
    if (r.step_failed) { /* a result of the trial, not a failure of the call */
        out->outcome = FS_FAILED_NUMERICS;
        out->rule = FS_RULE_NUMERICS;
        snprintf(out->failure, sizeof out->failure, "seed %d: %.480s", out->draw.seed, step_err.message);
        s = FS_OK;
    }
    if (s != FS_OK) {
        *err = step_err;
        fs_sim_free(sim);
        return s;
    }
    finish(sim, &t.w, out);
    if (log)
        fs_log_last(log, sim);
    if (out->outcome != FS_FAILED_NUMERICS) {
        sample_of(sim, &t.last);
        fs_judge_finish(&t.judge, &t.last, fs_sim_penetration(sim));
        out->outcome = t.judge.outcome;
        out->rule = t.judge.rule;
    }
    fs_sim_free(sim);
    return FS_OK;
}

/* The drawn pose and seed put into the scenario's definitions: typed edits, then one compile. */
fs_status fs_trial_place(fs_scenario *sc, int seed, fs_trial_draw *draw, fs_error *err)
{
    fs_trial_draw own;
    if (!draw)
        draw = &own;
    fs_trial_draw_pose(sc, seed, draw);
    fs_scenario_def *d = &sc->def;
    d->start_x_m = draw->x_m;
    d->start_y_m = draw->y_m;
    d->yaw_deg = draw->yaw_deg;
    d->pitch_deg = draw->pitch_deg;
    d->roll_deg = draw->roll_deg;
    sc->terrain.def.seed = seed;
    return fs_scenario_compile(sc, err);
}

fs_status fs_trial_placed(const fs_scenario *base, int seed, fs_trial_draw *draw, fs_scenario **out, fs_error *err)
{
    *out = NULL;
    fs_scenario *sc = malloc(sizeof *sc); /* the caller's, not the process's: trials are re-entrant */
    if (!sc)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", base->path);
    fs_status s = fs_scenario_copy(sc, base, err);
    if (s != FS_OK) {
        free(sc);
        return s;
    }
    s = fs_trial_place(sc, seed, draw, err);
    if (s == FS_OK)
        *out = sc;
    else
        fs_trial_placed_free(sc);
    return s;
}

void fs_trial_placed_free(fs_scenario *sc)
{
    if (sc)
        fs_scenario_free(sc);
    free(sc);
}

fs_status fs_trial_run_scenario(const fs_scenario *base, int seed, const fs_run_observer *obs, fs_trial_result *out,
                                fs_error *err)
{
    return fs_trial_run_logged(base, seed, obs, NULL, out, err);
}

fs_status fs_trial_run_logged(const fs_scenario *base, int seed, const fs_run_observer *obs, fs_run_result *log,
                              fs_trial_result *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    fs_scenario *sc;
    fs_status s = fs_trial_placed(base, seed, &out->draw, &sc, err);
    if (s == FS_OK)
        s = run_trial(sc, obs, log, out, err);
    fs_trial_placed_free(sc);
    return s;
}

fs_status fs_trial_run(const char *scenario_path, const char *const *overrides, int noverrides, int seed,
                       const fs_run_observer *obs, fs_trial_result *out, fs_error *err)
{
    memset(out, 0, sizeof *out);
    fs_scenario *sc = malloc(sizeof *sc);
    if (!sc)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", scenario_path);
    /* the file read once; the pose drawn from its ranges, then put into (a copy of) its definitions */
    fs_status s = fs_scenario_load(scenario_path, overrides, noverrides, sc, err);
    if (s == FS_OK)
        s = fs_scenario_require(sc, "trial", err);
    if (s == FS_OK)
        s = fs_trial_run_scenario(sc, seed, obs, out, err);
    fs_scenario_free(sc);
    free(sc);
    return s;
}
