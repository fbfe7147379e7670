/* cli_bench_precision.c: 'footsim bench precision': run time against error.
 *
 * Scenes, each run in ODE at every step size, stepper and spring implementation:
 * - chain: the middle toe chain pinned at heel and toe under the static_load scenario's load (the
 *   paper's Fig. 11 transient), against the planar dynamic reference (analysis_reference.c);
 * - landings that land (a trajectory error is well posed only there; a toppling body's grows with
 *   any perturbation): the flat foot on rough ground (seed 10), the biomimetic foot under
 *   drop_weight on flat ground (seed 1) and on rough ground (seed 4), and (full sweep only) the flat
 *   foot under the rig on each other shipped terrain (seed 1), each against its own run at 1e-5 s
 *   with dWorldStep, where the landing converges (docs/model.md, friction).
 * --scene NAME[,NAME...] runs only the scenes named (SCENES below; a full-sweep-only one with --quick
 * too), checked before anything runs (an unknown name: exit 2, the names listed), and skips the
 * campaign-equivalence stage (said on stderr and in precision.md).
 * Error is the ankle's distance (and the hinge angles' difference) from the reference, largest and
 * RMS over the run; on a soil also the feet's sinkage at the end and the ankle's height against the
 * reference's then (under the rig, whose slide holds the foot's attitude, the sinkage's error);
 * cost is the median wall time of the steps over repeated runs. Last, campaign
 * equivalence (cli_bench_equivalence.c) of scenarios/equivalence_flat.ini on one worker, into
 * DIR/precision_equivalence/ (its folder checked before anything runs). Writes DIR/precision.csv (and
 * precision.provenance.json beside it),
 * precision.md (with the equivalence verdicts) and precision.png (gnuplot). */
#include "cli.h"

#include "footsim/base/fs_stats.h"
#include "footsim/sim/fs_check.h"
#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_track.h"
#include "footsim/experiment/fs_trial.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* the chain and three landings; with the full sweep also the flat foot on each other shipped terrain */
enum { MAX_ROWS = 2048, NSCENES = 13 };

/* Every scene, by the name --scene takes: the chain (no design), the three landings that land (the
 * flat foot under the tall robot with seed 10's pose on rough ground; the biomimetic foot under
 * drop_weight, which the tall robot folds (docs/landing.md), with seed 1's on flat ground and seed 4's
 * on rough ground), and (full sweep only, unless named) the flat foot's landing on each other shipped
 * terrain under the rig, which holds its pitch, so that it lands on every one (seed 1) and its path
 * is well posed: issue 12's "flat foot, any shipped terrain, >= 100x". goal_rtf: the real-time factor
 * wanted within GOAL_ERR_M (0: none, the chain); goal_fine_rtf: within GOAL_FINE_ERR_M (0: none). */
static const struct scene_spec {
    const char *name, *title, *design, *robot, *terrain;
    int seed, full_only;
    double goal_rtf, goal_fine_rtf;
} SCENES[NSCENES] = {
    {"chain", "pinned chain against the planar reference", NULL, NULL, NULL, 0, 0, 0, 0},
    {"landing_flat", "flat foot landing on rough ground", "feet/flat.ini", "robots/single_tall.ini",
     "../terrains/rough.ini", 10, 0, 100, 0},
    {"landing_biomimetic", "biomimetic foot landing on flat ground (drop_weight)", "feet/biomimetic.ini",
     "robots/drop_weight.ini", "../terrains/flat.ini", 1, 0, 100, 10},
    {"landing_biomimetic_rough", "biomimetic foot landing on rough ground (drop_weight)", "feet/biomimetic.ini",
     "robots/drop_weight.ini", "../terrains/rough.ini", 4, 0, 30, 0},
#define FS_RIG(name, title, terrain) {name, title, "feet/flat.ini", "robots/rig.ini", terrain, 1, 1, 100, 0}
    FS_RIG("flat_rig_flat", "flat foot on flat ground (rig)", "../terrains/flat.ini"),
    FS_RIG("flat_rig_simply_uneven", "flat foot on simply uneven ground (rig)", "../terrains/simply_uneven.ini"),
    FS_RIG("flat_rig_complex_uneven", "flat foot on complex uneven ground (rig)", "../terrains/complex_uneven.ini"),
    FS_RIG("flat_rig_stepped", "flat foot on stepped ground (rig)", "../terrains/stepped.ini"),
    FS_RIG("flat_rig_heightmap", "flat foot on the heightmap (rig)", "../terrains/heightmap.ini"),
    FS_RIG("flat_rig_partly_rough", "flat foot on partly rough ground (rig)", "../terrains/partly_rough.ini"),
    FS_RIG("flat_rig_slope", "flat foot on the slope (rig)", "../terrains/slope.ini"),
    FS_RIG("flat_rig_soft", "flat foot on soft ground (rig)", "../terrains/soft.ini"),
    /* a soil (docs/soil.md): its reference also on the fine grid everywhere (the sole's nodes 0.5 mm
     * apart, not coarse_grid_m's 8 mm), so that the error holds the coarse grid's as well as the step's */
    FS_RIG("flat_rig_dry_sand", "flat foot on dry sand (rig; reference at 1e-5 s on the 0.5 mm grid)",
           "../terrains/soils/dry_sand.ini"),
#undef FS_RIG
};

static const double REF_STEP_S = 1e-5;          /* the finest step, and the reference's sample spacing */
static const double REF_TOLERANCE = 1e-10;      /* rk8pd's error bound per step for the reference */
static const double REPEAT_BUDGET_S = 2;        /* wall time after which a configuration is not rerun */
/* issue 12's targets: a landing within 1 mm at a scene's real-time factor (100x on flat ground and
 * for the flat foot, 30x for the biomimetic foot on rough ground), and within 0.1 mm at 10x on flat */
static const double GOAL_ERR_M = 1e-3, GOAL_FINE_ERR_M = 1e-4;

static const double STEPS_FULL[] = {1e-5, 2e-5, 5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2};
static const double STEPS_QUICK[] = {1e-4, 1e-3, 1e-2};
static const int ITERATIONS_FULL[] = {0, 10, 20, 50, 100, 200}; /* 0: dWorldStep */
static const int ITERATIONS_QUICK[] = {0, 20};
/* run.impact_substeps tried on the landings (dWorldStep, implicit springs, the key's window), at the
 * steps where an impact is not resolved whole (docs/bench.md: the error of a large step is at
 * touchdown); 8e-4 s because a sweep of 5e-4..8e-4 s found the even-ground landing within 0.1 mm
 * there with 2 substeps, and fastest */
static const double SUBSTEP_STEPS_FULL[] = {5e-4, 8e-4, 1e-3, 2e-3, 5e-3, 1e-2};
static const double SUBSTEP_STEPS_QUICK[] = {1e-3, 1e-2};
static const int SUBSTEPS_FULL[] = {2, 4, 8};
static const int SUBSTEPS_QUICK[] = {8};
/* The landings with an error-controlled step (run.tolerance_m, its step_max_s and step_min_s at
 * their defaults), each tolerance a row under each error estimate (run.error_estimate: step doubling,
 * then the embedded pair, about half the ODE steps: docs/bench.md, The embedded estimate). */
static const double TOLERANCES_FULL[] = {1e-4, 3e-5, 1e-5, 3e-6, 1e-6};
static const double TOLERANCES_QUICK[] = {1e-5};
static const int ESTIMATE[] = {FS_ESTIMATE_DOUBLING, FS_ESTIMATE_EMBEDDED};
enum { ESTIMATES = sizeof ESTIMATE / sizeof *ESTIMATE };
/* the campaign-equivalence stage: the flat campaign (40 trials) against 1e-5 s, where the landing
 * converges, at each step of the sweep; --quick on 2 seeds (8 trials) against 5e-5 s, two steps,
 * one on each side of the verdict (about 4 s) */
static const char *const EQUIVALENCE_CAMPAIGN = "scenarios/equivalence_flat.ini";
static const char *const EQUIVALENCE_SET_QUICK[] = {"campaign.seeds=2"};
static const char *const EQUIVALENCE_REFERENCE_FULL = "1e-5", *const EQUIVALENCE_REFERENCE_QUICK = "5e-5";
static const char *const EQUIVALENCE_STEPS_FULL = "2e-5,5e-5,1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,1e-2";
static const char *const EQUIVALENCE_STEPS_QUICK = "1e-4,1e-3";

/* A scene: its scenario (loaded and placed once; each row edits only its run settings, as fields),
 * how it is run, and its reference path. */
typedef struct scene {
    const char *name, *title, *path;
    fs_scenario base;
    int pinned_chain;           /* 0, or the chain (1-5) pinned alone */
    double duration_s;
    fs_scenario_def defaults;   /* the scenario's own run settings, to mark the default row */
    fs_track ref;
    double ref_check_m;         /* chain: how much halving the reference's tolerance moves the ankle */
    double ref_wall_s;
    int has_springs;            /* 0: the spring implementation makes no difference (the flat foot) */
    int soil;                   /* on a soil: the sinkage at the end and its error too */
    double goal_rtf;            /* the real-time factor wanted within GOAL_ERR_M (0: none, the chain) */
    double goal_fine_rtf;       /* ... and within GOAL_FINE_ERR_M (0: none) */
} scene;

typedef struct row {
    const scene *sc;
    int stepper, iterations, springs;
    double step_s;
    int substeps;               /* run.impact_substeps (1: off) */
    double tolerance_m;         /* run.tolerance_m (0: fixed steps) */
    int estimate;               /* run.error_estimate (fs_error_estimate), with a tolerance */
    long steps, rejected, ode_steps; /* of the first run: steps accepted, rejected, ODE steps in all */
    int ok;                     /* 0: the run blew up */
    int drifting;               /* a loop opened or energy grew beyond the checks' bounds (fs_check.h) */
    fs_track_error e;
    double wall_s;              /* median over repeats */
    int pareto, is_default;
} row;

static const char *stepper_name(int s) { return s == FS_STEPPER_QUICKSTEP ? "quickstep" : "step"; }
static const char *spring_name(int s) { return s == FS_SPRING_EXPLICIT ? "explicit" : "implicit"; }
static int substeps_of(const struct row *r) { return r->substeps > 1 ? r->substeps : 1; }
/* the error estimate's name, as run.error_estimate takes it; "" for a fixed step */
static const char *estimate_name(const struct row *r)
{
    return r->tolerance_m > 0 ? (r->estimate == FS_ESTIMATE_EMBEDDED ? "embedded" : "doubling") : "";
}

/* The scene's scenario with a row's run settings put into its definition (a shallow copy: the
 * terrain's samples stay the scene's, read only). */
static void with_settings(const scene *s, const row *r, fs_scenario *sc)
{
    *sc = s->base;
    sc->def.step_s = r->step_s;
    sc->def.stepper = r->stepper;
    sc->def.iterations = r->iterations > 0 ? r->iterations : 20;
    sc->def.springs = r->springs;
    sc->def.impact_substeps = r->substeps > 1 ? r->substeps : 1;
    sc->def.tolerance_m = r->tolerance_m;
    sc->def.error_estimate = r->estimate;
    sc->def.log_interval_s = fmax(r->step_s, 1e-3); /* no path is logged here */
}

/* Runs one configuration up to `repeats` times, fewer once REPEAT_BUDGET_S of wall time is spent
 * on it (a long run times itself well): the error of the first run, the median wall time. */
static fs_status measure(row *r, int repeats, fs_error *err)
{
    fs_scenario *sc = malloc(sizeof *sc); /* a shallow copy (with_settings): freed, owns nothing */
    if (!sc)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    with_settings(r->sc, r, sc);
    fs_status s = FS_OK;
    fs_sim_options opts = {.with_ground = 1, .pinned_chain = r->sc->pinned_chain, .record_drift = 1};
    double wall[8], spent = 0;
    int done = 0;
    r->ok = 1;
    for (int k = 0; k < repeats && r->ok && (k == 0 || spent < REPEAT_BUDGET_S); k++) {
        fs_track t;
        fs_error run_err;
        fs_status ran = fs_track_run(sc, &opts, r->sc->duration_s, &t, &run_err);
        if (ran == FS_NUMERICAL) {
            r->ok = 0; /* blown up: a result of the sweep, not a failure of the command */
            break;
        }
        if (ran != FS_OK) {
            *err = run_err;
            s = ran;
            break;
        }
        wall[done++] = t.wall_s;
        r->drifting = t.check_class == FS_CHECK_DRIFTING;
        spent += t.wall_s;
        if (k == 0) {
            s = fs_track_compare(&t, &r->sc->ref, &r->e, err);
            r->steps = t.steps, r->rejected = t.rejected, r->ode_steps = t.ode_steps;
        }
        fs_track_free(&t);
        if (s != FS_OK)
            break;
    }
    if (r->ok) {
        qsort(wall, (size_t)done, sizeof wall[0], fs_compare_doubles);
        r->wall_s = wall[done / 2];
    }
    free(sc);
    return s;
}

/* ---- the scenes and their references ---------------------------------------------------- */

static fs_status chain_scene(scene *s, fs_error *err)
{
    memset(s, 0, sizeof *s);
    s->name = "chain";
    s->title = "pinned chain against the planar reference";
    s->path = cli_data_path("scenarios/static_load.ini");
    s->pinned_chain = 3;
    s->duration_s = 0.2;
    fs_status st = fs_scenario_load(s->path, NULL, 0, &s->base, err);
    if (st != FS_OK)
        return st;
    const fs_scenario *sc = &s->base;
    s->defaults = sc->def;
    s->has_springs = 1;
    const fs_scenario_def *d = &sc->def;
    fs_reference_def def = {s->pinned_chain - 1, d->load_kg * d->gravity_m_per_s2, d->ramp_s, d->gravity_m_per_s2,
                            d->tilt_deg * M_PI / 180, REF_TOLERANCE, {0, 0}};
    int n = (int)lround(s->duration_s / REF_STEP_S) + 1;
    double start = fs_clock_s();
    st = fs_track_reference(&sc->design, &sc->geom, &def, REF_STEP_S, n, &s->ref, err);
    s->ref_wall_s = fs_clock_s() - start;
    /* the reference checked against itself at half the tolerance */
    fs_track half;
    def.tolerance = 0.5 * REF_TOLERANCE;
    if (st == FS_OK)
        st = fs_track_reference(&sc->design, &sc->geom, &def, REF_STEP_S, n, &half, err);
    for (int i = 0; st == FS_OK && i < n; i++)
        for (int k = 0; k < 3; k++)
            s->ref_check_m = fmax(s->ref_check_m, fabs(half.ankle[i][k] - s->ref.ankle[i][k]));
    if (st == FS_OK)
        fs_track_free(&half);
    return st;
}

/* The landing trial of spec's design under its robot on its terrain (files relative to the trial
 * scenario), the pose drawn for its seed (as a campaign would). */
static fs_status landing_scene(scene *s, const struct scene_spec *spec, double duration_s, fs_error *err)
{
    memset(s, 0, sizeof *s);
    s->name = spec->name;
    s->title = spec->title;
    const char *design = spec->design, *robot = spec->robot, *terrain_file = spec->terrain;
    int seed = spec->seed;
    s->path = cli_data_path("scenarios/landing_trial.ini");
    s->duration_s = duration_s;
    char terrain[FS_PATH_MAX + 32], foot[FS_PATH_MAX + 32], body[FS_PATH_MAX + 32];
    snprintf(terrain, sizeof terrain, "scenario.terrain=%s", terrain_file); /* which files: chosen at load */
    snprintf(foot, sizeof foot, "scenario.design=%s", design);
    snprintf(body, sizeof body, "robot.design=%s", robot);
    const char *set[] = {terrain, foot, body};
    fs_status st = fs_scenario_load(s->path, set, 3, &s->base, err);
    if (st == FS_OK)
        st = fs_trial_place(&s->base, seed, NULL, err); /* the pose and ground of seed, as a campaign's */
    if (st != FS_OK)
        return st;
    s->defaults = s->base.def;
    s->has_springs = s->base.geom.nsprings > 0 || s->base.def.robot.joint != FS_ROBOT_RIGID;
    s->soil = s->base.terrain.def.soil.model != FS_SOIL_NONE;
    /* the reference: footsim itself at the finest step with dWorldStep */
    row ref = {.sc = s, .stepper = FS_STEPPER_STEP, .springs = FS_SPRING_IMPLICIT, .step_s = REF_STEP_S};
    fs_scenario *sc = malloc(sizeof *sc); /* a shallow copy (with_settings): freed, owns nothing */
    if (!sc)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    with_settings(s, &ref, sc);
    sc->terrain.def.soil.coarse_grid_m = 0; /* a soil's reference: every shape on the fine grid */
    fs_sim_options opts = {.with_ground = 1};
    st = fs_track_run(sc, &opts, s->duration_s, &s->ref, err);
    free(sc);
    s->ref_wall_s = s->ref.wall_s;
    return st;
}

/* ---- the sweep ---------------------------------------------------------------------------- */

/* Not dominated: no other row is at least as accurate and at least as fast, and better in one. */
static void mark_pareto(row *rows, int n)
{
    for (int i = 0; i < n; i++) {
        rows[i].pareto = rows[i].ok && !rows[i].drifting;
        for (int j = 0; j < n && rows[i].pareto; j++) {
            if (j == i || !rows[j].ok || rows[j].drifting || rows[j].sc != rows[i].sc)
                continue;
            int no_worse = rows[j].e.max_m <= rows[i].e.max_m && rows[j].wall_s <= rows[i].wall_s;
            int better = rows[j].e.max_m < rows[i].e.max_m || rows[j].wall_s < rows[i].wall_s;
            if (no_worse && better)
                rows[i].pareto = 0;
        }
    }
}

static int is_default(const row *r)
{
    const fs_scenario_def *d = &r->sc->defaults;
    return r->step_s == d->step_s && r->springs == d->springs && r->stepper == d->stepper &&
           (r->substeps > 1 ? r->substeps : 1) == d->impact_substeps && r->tolerance_m == d->tolerance_m &&
           (r->tolerance_m == 0 || r->estimate == d->error_estimate) && (r->stepper == FS_STEPPER_STEP || r->iterations == d->iterations);
}

static double rtf(const row *r) { return r->ok && r->wall_s > 0 ? r->sc->duration_s / r->wall_s : 0; }

/* On a soil, the sinkage at the end and its error: the ankle's height against the reference's then.
 * Under the rig the slide holds the foot's attitude and the sole is rigid, so the sole's depth below
 * the undisturbed surface differs from the reference's by exactly that; the row's sinkage is the
 * reference's (its deepest carried node, on the fine grid) less it. Read from the bodies, not from
 * the row's own nodes: at a step of 1e-2 s they may carry none of the sole in its last step. NAN on
 * rigid ground. */
static double sinkage_err(const row *r) { return r->sc->soil ? fabs(r->e.end_dz_m) : NAN; }
static double sinkage(const row *r) { return r->sc->soil ? r->sc->ref.sinkage_end_m - r->e.end_dz_m : NAN; }

static fs_status sweep(scene *scenes, int nscenes, int quick, row *rows, int *nrows, fs_error *err)
{
    const double *steps = quick ? STEPS_QUICK : STEPS_FULL;
    int nsteps = quick ? (int)(sizeof STEPS_QUICK / sizeof *steps) : (int)(sizeof STEPS_FULL / sizeof *steps);
    const int *its = quick ? ITERATIONS_QUICK : ITERATIONS_FULL;
    int nits = quick ? (int)(sizeof ITERATIONS_QUICK / sizeof *its) : (int)(sizeof ITERATIONS_FULL / sizeof *its);
    int repeats = quick ? 1 : 5, total = 0, n = 0;
    const double *sub_steps = quick ? SUBSTEP_STEPS_QUICK : SUBSTEP_STEPS_FULL;
    int nsub_steps = quick ? (int)(sizeof SUBSTEP_STEPS_QUICK / sizeof *sub_steps)
                           : (int)(sizeof SUBSTEP_STEPS_FULL / sizeof *sub_steps);
    const int *subs = quick ? SUBSTEPS_QUICK : SUBSTEPS_FULL;
    int nsubs = quick ? (int)(sizeof SUBSTEPS_QUICK / sizeof *subs) : (int)(sizeof SUBSTEPS_FULL / sizeof *subs);
    const double *tols = quick ? TOLERANCES_QUICK : TOLERANCES_FULL;
    int ntols = quick ? (int)(sizeof TOLERANCES_QUICK / sizeof *tols) : (int)(sizeof TOLERANCES_FULL / sizeof *tols);
    for (int c = 0; c < nscenes; c++)
        total += nsteps * nits * (1 + scenes[c].has_springs) + (scenes[c].pinned_chain ? 0 : nsubs * nsub_steps + ESTIMATES * ntols);
    cli_progress progress;
    cli_progress_start(&progress, "footsim bench precision", "configurations");
    cli_progress_update(&progress, 0, total, 0);
    int blown = 0;
    fs_status s = FS_OK;
    for (int c = 0; c < nscenes && s == FS_OK; c++)
        for (int i = 0; i < nits && s == FS_OK; i++)
            for (int sp = 0; sp < 1 + scenes[c].has_springs && s == FS_OK; sp++)
                for (int h = 0; h < nsteps && s == FS_OK; h++) {
                    row *r = &rows[n++];
                    *r = (row){.sc = &scenes[c], .stepper = its[i] ? FS_STEPPER_QUICKSTEP : FS_STEPPER_STEP,
                               .iterations = its[i], .springs = sp ? FS_SPRING_EXPLICIT : FS_SPRING_IMPLICIT,
                               .step_s = steps[h]};
                    s = measure(r, repeats, err);
                    r->is_default = is_default(r);
                    blown += !r->ok;
                    cli_progress_update(&progress, n, total, blown);
                }
    /* the landings again with their impacts in substeps (the chain has no ground to land on) */
    for (int c = 0; c < nscenes && s == FS_OK; c++)
        for (int k = 0; k < nsubs && !scenes[c].pinned_chain && s == FS_OK; k++)
            for (int h = 0; h < nsub_steps && s == FS_OK; h++) {
                row *r = &rows[n++];
                *r = (row){.sc = &scenes[c], .stepper = FS_STEPPER_STEP, .springs = FS_SPRING_IMPLICIT,
                           .step_s = sub_steps[h], .substeps = subs[k]};
                s = measure(r, repeats, err);
                r->is_default = is_default(r);
                blown += !r->ok;
                cli_progress_update(&progress, n, total, blown);
            }
    /* the landings with an error-controlled step, from the scene's own step, under each estimate */
    for (int c = 0; c < nscenes && s == FS_OK; c++)
        for (int e = 0; e < ESTIMATES && !scenes[c].pinned_chain && s == FS_OK; e++)
            for (int k = 0; k < ntols && s == FS_OK; k++) {
                row *r = &rows[n++];
                *r = (row){.sc = &scenes[c], .stepper = FS_STEPPER_STEP, .springs = FS_SPRING_IMPLICIT,
                           .step_s = scenes[c].defaults.step_s, .tolerance_m = tols[k], .estimate = ESTIMATE[e]};
                s = measure(r, repeats, err);
                r->is_default = is_default(r);
                blown += !r->ok;
                cli_progress_update(&progress, n, total, blown);
            }
    *nrows = n;
    mark_pareto(rows, n);
    return s;
}

/* ---- the outputs -------------------------------------------------------------------------- */

/* What the output files are made of (each written whole or not at all by fs_write_in). */
typedef struct report {
    const row *rows;
    int n;
    const scene *scenes;
    int nscenes;
    const char *machine;
    const char *command;        /* as it ran: with --quick and --scene */
    int quick;
    const fs_provenance *prov;
    const cli_equivalence *eq;  /* the campaign-equivalence stage; NULL: skipped (--scene) */
} report;

static int fill_csv(FILE *f, const void *user)
{
    const report *x = user;
    const row *rows = x->rows;
    int n = x->n;
    fprintf(f, "scene,stepper,iterations,spring,step_s,max_err_m,rms_err_m,max_angle_err_rad,rms_angle_err_rad,"
            "wall_s,wall_per_sim_s,rtf,status,pareto,default,impact_substeps,tolerance_m,steps,rejected,ode_steps,sinkage_m,"
            "sinkage_err_m,error_estimate\n");
    for (int i = 0; i < n; i++) {
        const row *r = &rows[i];
        char b[9][32]; /* a figure a row does not have (not finite): an empty field */
        if (r->ok)
            fprintf(f, "%s,%s,%d,%s,%g,%s,%s,%s,%s,%s,%s,%s,%s,%d,%d,%d,%g,%ld,%ld,%ld,%s,%s,%s\n", r->sc->name,
                stepper_name(r->stepper),
                r->iterations, spring_name(r->springs), r->step_s, cli_csv_num(b[0], sizeof b[0], "%.4e", r->e.max_m),
                cli_csv_num(b[1], sizeof b[1], "%.4e", r->e.rms_m), cli_csv_num(b[2], sizeof b[2], "%.4e", r->e.max_rad),
                cli_csv_num(b[3], sizeof b[3], "%.4e", r->e.rms_rad), cli_csv_num(b[4], sizeof b[4], "%.4e", r->wall_s),
                cli_csv_num(b[5], sizeof b[5], "%.4e", r->wall_s / r->sc->duration_s),
                cli_csv_num(b[6], sizeof b[6], "%.4g", rtf(r)), r->drifting ? "drifting" : "ok", r->pareto,
                r->is_default, substeps_of(r), r->tolerance_m, r->steps, r->rejected, r->ode_steps,
                cli_csv_num(b[7], sizeof b[7], "%.4e", sinkage(r)),
                cli_csv_num(b[8], sizeof b[8], "%.4e", sinkage_err(r)), estimate_name(r));
        else
            /* a blown-up run has no error nor speed: missing, empty fields */
            fprintf(f, "%s,%s,%d,%s,%g,,,,,,,,blown_up,0,%d,%d,%g,,,,,,%s\n", r->sc->name, stepper_name(r->stepper),
                r->iterations, spring_name(r->springs), r->step_s, r->is_default, substeps_of(r), r->tolerance_m,
                estimate_name(r));
    }
    return 1;
}

static void describe(FILE *f, const row *r)
{
    if (r->tolerance_m > 0)
        fprintf(f, "| step, tolerance %g m, %s (%ld steps, %ld rejected, %ld ODE steps) | %s | variable |",
                r->tolerance_m, estimate_name(r), r->steps, r->rejected, r->ode_steps, spring_name(r->springs));
    else if (r->stepper == FS_STEPPER_QUICKSTEP)
        fprintf(f, "| quickstep %d | %s | %g |", r->iterations, spring_name(r->springs), r->step_s);
    else if (substeps_of(r) > 1)
        fprintf(f, "| step, %d substeps at a touchdown | %s | %g |", r->substeps, spring_name(r->springs), r->step_s);
    else
        fprintf(f, "| step | %s | %g |", spring_name(r->springs), r->step_s);
}

/* Scene s's rows on its Pareto front (and its default row, with_default), slowest first. */
static int sorted_front(const row *rows, int n, const scene *s, int with_default, const row **out)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        if (rows[i].sc == s && (rows[i].pareto || (with_default && rows[i].is_default)))
            out[m++] = &rows[i];
    for (int i = 1; i < m; i++)
        for (int j = i; j > 0 && rtf(out[j]) < rtf(out[j - 1]); j--) {
            const row *x = out[j];
            out[j] = out[j - 1];
            out[j - 1] = x;
        }
    return m;
}

/* The table of one scene's Pareto front, fastest last. */
static void front_table(FILE *f, const row *rows, int n, const scene *s)
{
    fprintf(f, "\n### %s: the Pareto front\n\n| stepper | springs | step (s) | max ankle error (m) | RMS (m) | "
           "max angle error (rad) | real-time factor | default |%s\n|---|---|---|---|---|---|---|---|%s\n", s->name,
           s->soil ? " sinkage at the end (m) | its error (m) |" : "", s->soil ? "---|---|" : "");
    const row *sorted[MAX_ROWS];
    int m = sorted_front(rows, n, s, 1, sorted);
    for (int i = 0; i < m; i++) {
        const row *r = sorted[i];
        describe(f, r);
        if (r->ok)
            fprintf(f, " %.2e | %.2e | %.2e | %.3g | %s%s |", r->e.max_m, r->e.rms_m, r->e.max_rad, rtf(r),
                r->is_default ? "yes" : "", r->pareto ? "" : " (not on the front)");
        else
            fprintf(f, " blew up | | | | %s |", r->is_default ? "yes" : "");
        if (s->soil && r->ok)
            fprintf(f, " %.4e | %.2e |", sinkage(r), sinkage_err(r));
        else if (s->soil)
            fprintf(f, " | |");
        fprintf(f, "\n");
    }
}

/* One target of a landing: the fastest configuration within err_m, against the real-time factor
 * wanted. */
static void target(FILE *f, const row *rows, int n, const scene *s, double err_m, double want_rtf)
{
    const row *best = NULL;
    for (int i = 0; i < n; i++) {
        const row *r = &rows[i];
        if (r->sc == s && r->ok && !r->drifting && r->e.max_m <= err_m && (!best || rtf(r) > rtf(best)))
            best = r;
    }
    fprintf(f, "At most %g mm of ankle error at %gx real time or more on one core: ", err_m * 1e3, want_rtf);
    char subs[80] = "";
    if (best && substeps_of(best) > 1)
        snprintf(subs, sizeof subs, " (%d substeps at a touchdown)", best->substeps);
    if (best && best->tolerance_m > 0)
        snprintf(subs, sizeof subs, " (error-controlled, tolerance %g m, %s)", best->tolerance_m, estimate_name(best));
    if (best)
        fprintf(f, "the fastest configuration within %g mm is %s, %s springs, h = %g s%s: %.3g mm at %.3gx, %s. ",
            err_m * 1e3, best->stepper == FS_STEPPER_QUICKSTEP ? "quickstep" : "dWorldStep",
            spring_name(best->springs), best->step_s, subs, best->e.max_m * 1e3, rtf(best),
            rtf(best) >= want_rtf ? "**met**" : "**not met**");
    else
        fprintf(f, "no configuration stays within %g mm: **not met**. ", err_m * 1e3);
}

/* A landing's targets (issue 12), and where the scenario's default stands. */
static void goal(FILE *f, const row *rows, int n, const scene *s)
{
    const row *dflt = NULL;
    for (int i = 0; i < n; i++)
        if (rows[i].sc == s && rows[i].is_default)
            dflt = &rows[i];
    fprintf(f, "\n**Goal** (issue 12), %s: ", s->name);
    target(f, rows, n, s, GOAL_ERR_M, s->goal_rtf);
    if (s->goal_fine_rtf > 0)
        target(f, rows, n, s, GOAL_FINE_ERR_M, s->goal_fine_rtf);
    if (dflt && dflt->ok)
        fprintf(f, "The scenario's default (%s, %s springs, h = %g s): %.3g mm at %.3gx.\n",
            dflt->stepper == FS_STEPPER_QUICKSTEP ? "quickstep" : "dWorldStep", spring_name(dflt->springs),
            dflt->step_s, dflt->e.max_m * 1e3, rtf(dflt));
    else
        fprintf(f, "\n");
}

static int fill_md(FILE *f, const void *user)
{
    const report *x = user;
    const row *rows = x->rows;
    const scene *scenes = x->scenes;
    int n = x->n, nscenes = x->nscenes, quick = x->quick;
    const char *machine = x->machine;
    char date[32];
    time_t now = time(NULL);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    fprintf(f, "# Precision: run time against error\n\n`%s` on %s; %s; load average %.2f at the end. Every row of "
            "`precision.csv` is one configuration; the chart is `precision.png`.\n", x->command, date, machine,
            cli_load_average());
    fprintf(f, "\nReferences: ");
    int landings = 0;
    for (int c = 0; c < nscenes; c++) {
        const scene *s = &scenes[c];
        if (s->pinned_chain) {
            fprintf(f, "**%s**: the planar dynamic model (GSL rk8pd, tolerance %g; halving it moves the ankle by "
                    "%.1e m; %.2f s to compute)%s", s->name, REF_TOLERANCE, s->ref_check_m, s->ref_wall_s,
                    nscenes > 1 ? ". " : ".\n");
            continue;
        }
        if (!landings++)
            fprintf(f, "The landings: footsim's own run of the same trial at h = %g s with dWorldStep, over %g s from "
                    "release; wall time to compute it: ", REF_STEP_S, s->duration_s);
        fprintf(f, "%s**%s** %.1f s", landings > 1 ? ", " : "", s->name, s->ref_wall_s);
        if (s->soil)
            fprintf(f, " (every shape on the soil's %g mm grid; the feet %.3f mm below its undisturbed surface at "
                    "the end)", s->base.terrain.def.soil.grid_m * 1e3, s->ref.sinkage_end_m * 1e3);
    }
    if (landings)
        fprintf(f, ".\n");
    for (int c = 0; c < nscenes; c++)
        if (scenes[c].soil) {
            fprintf(f, "\nOn a soil (**%s**, under the rig) the rows also give the sinkage at the end and its error. "
                    "The rig's slide holds the foot's attitude and the sole is rigid, so at every instant the "
                    "ankle's distance from the reference's is the difference of the sole's depth below the soil's "
                    "undisturbed surface: the largest ankle error is the largest sinkage error, its error at the "
                    "end the ankle's height against the reference's then, and the sinkage at the end the "
                    "reference's (the deepest node its sole carries) less that.\n",
                    scenes[c].name);
            break;
        }
    for (int c = 0; c < nscenes; c++)
        front_table(f, rows, n, &scenes[c]);
    for (int c = 0; c < nscenes; c++)
        if (!scenes[c].pinned_chain)
            goal(f, rows, n, &scenes[c]);
    int blown = 0, drifting = 0;
    for (int i = 0; i < n; i++) {
        blown += !rows[i].ok;
        drifting += rows[i].ok && rows[i].drifting;
    }
    fprintf(f, "\n%d of %d configurations blew up and %d drifted (a hinge opened by more than 1 mm, or energy grew "
            "from nowhere: `status` in the CSV; neither is put on a front); `footsim bench stability` maps where.\n",
        blown, n, drifting);
    fprintf(f, "\n### Campaign equivalence\n\n");
    if (x->eq) {
        fprintf(f, "`%s`%s at each step against its own run at h = %s s with the same seeds, on one worker, as "
                "`footsim bench equivalence` runs it: every cell's success intervals must overlap the reference's "
                "and its medians lie within 5 %% or a floor (docs/bench.md). The header, machine and provenance are "
                "in `precision_equivalence/equivalence.md`, each step's comparison in "
                "`precision_equivalence/h<STEP>.md`, the reference campaign in `precision_equivalence/reference/`."
                "\n\n", EQUIVALENCE_CAMPAIGN, quick ? " on 2 seeds" : "",
                quick ? EQUIVALENCE_REFERENCE_QUICK : EQUIVALENCE_REFERENCE_FULL);
        cli_equivalence_table(f, x->eq);
    } else
        fprintf(f, "Not run: `--scene` named the scenes to run, and this stage runs only with every scene.\n");
    fputs("\nProvenance: ", f);
    fs_provenance_print(x->prov, f);
    fputs(".\n", f);
    return 1;
}

static int fill_chart(FILE *f, const void *user)
{
    const report *x = user;
    const row *rows = x->rows;
    const scene *scenes = x->scenes;
    int n = x->n, nscenes = x->nscenes;
    static const char head[] =
        "# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.\n"
        "if (!exists(\"out\")) out = 'precision.png'\n"
        "set datafile separator ','\n"
        "sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && "
        "$16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN\n"
        "subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN\n"
        "dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN\n";
    static const char axes[] =
        "set terminal pngcairo size 1400,1100 font ',11'\n"
        "set output out\n"
        "set logscale xy\n"
        "set format y '10^{%L}'\n"
        "set format x '10^{%L}'\n"
        "set xlabel 'real-time factor (simulated s per wall s)'\n"
        "set ylabel 'largest ankle error (m)'\n"
        "set grid\n"
        "set key bottom right font ',8' spacing 0.9\n";
    static const char panel[] =
        "set title '%s'\n"
        "plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) "
        "with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \\\n"
        "     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 "
        "lc rgb '#ff7f0e' title 'dWorldStep, explicit', \\\n"
        "     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points "
        "pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \\\n"
        "     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points "
        "pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \\\n"
        "     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' "
        "title 'touchdown in substeps', \\\n"
        "     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' "
        "title 'scenario default', \\\n"
        "     $front%d using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'\n";
    fprintf(f, "%s", head);
    /* each front as a block of its own (real-time factor, error), fastest last: a line through
     * filtered rows of the CSV would break at every row filtered out */
    for (int c = 0; c < nscenes; c++) {
        const row *front[MAX_ROWS];
        int m = sorted_front(rows, n, &scenes[c], 0, front);
        fprintf(f, "$front%d << EOD\n", c);
        for (int i = 0; i < m; i++)
            if (front[i]->e.max_m > 0) /* the reference itself has no place on a log scale */
                fprintf(f, "%.6g,%.6g\n", rtf(front[i]), front[i]->e.max_m);
        fprintf(f, "EOD\n");
    }
    fprintf(f, "%sset multiplot layout %d,2\n", axes, (nscenes + 1) / 2);
    for (int c = 0; c < nscenes; c++) {
        fprintf(f, "s = '%s'\n", scenes[c].name);
        fprintf(f, panel, scenes[c].title, c);
    }
    fprintf(f, "unset multiplot\n");
    return 1;
}

/* --scene's list into chosen (one flag a SCENES entry); 0, or FS_BAD_INPUT (said) for a name not in
 * SCENES or an empty one. Without --scene every scene of the sweep (the full sweep's only without
 * --quick). */
static int choose_scenes(const cli_args *a, int chosen[NSCENES])
{
    const char *names[NSCENES];
    for (int k = 0; k < NSCENES; k++) {
        chosen[k] = !a->scene && !(a->quick && SCENES[k].full_only);
        names[k] = SCENES[k].name;
    }
    return cli_bench_choose("precision", "scene", a->scene, names, NSCENES, chosen);
}

int cli_bench_precision_scenes(const cli_args *a)
{
    int chosen[NSCENES];
    return choose_scenes(a, chosen);
}

int cli_bench_precision(const cli_args *a, const char *dir)
{
    int chosen[NSCENES];
    if (choose_scenes(a, chosen)) /* before anything runs */
        return FS_BAD_INPUT;
    fs_error err;
    scene *scenes = calloc(NSCENES, sizeof *scenes); /* large: on the heap for this command */
    row *rows = calloc(MAX_ROWS, sizeof *rows);
    if (!scenes || !rows) {
        free(scenes);
        free(rows);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    int nrows = 0;
    char machine[512], command[512];
    cli_machine(machine, sizeof machine);
    snprintf(command, sizeof command, "footsim bench precision%s%s%.400s", a->quick ? " --quick" : "",
             a->scene ? " --scene " : "", a->scene ? a->scene : "");
    /* the equivalence stage's folder and campaign checked before anything is measured; none with --scene */
    char eq_dir[FS_OUT_PATH + 32];
    snprintf(eq_dir, sizeof eq_dir, "%s/precision_equivalence", dir);
    cli_equivalence_spec spec = {.campaign = cli_data_path(EQUIVALENCE_CAMPAIGN), .shown = EQUIVALENCE_CAMPAIGN,
                                 .set = a->quick ? EQUIVALENCE_SET_QUICK : NULL, .nset = a->quick,
                                 .reference = a->quick ? EQUIVALENCE_REFERENCE_QUICK : EQUIVALENCE_REFERENCE_FULL,
                                 .steps = a->quick ? EQUIVALENCE_STEPS_QUICK : EQUIVALENCE_STEPS_FULL, .jobs = 1,
                                 .command = command, .who = "footsim bench precision", .option = "--out"};
    cli_equivalence *eq = NULL;
    int eq_status = a->scene ? 0 : cli_equivalence_open(&eq, &spec, eq_dir, a->replace);
    if (eq_status) {
        cli_equivalence_close(eq);
        free(scenes);
        free(rows);
        return eq_status;
    }
    if (a->scene)
        fprintf(stderr, "footsim bench precision: --scene given: only %s, and no campaign-equivalence stage\n",
                a->scene);
    fs_status s = fs_make_dirs(dir, &err);
    /* touchdown at about 35 ms, the impact over by 0.1 s; --quick stops soon after */
    double landing_s = a->quick ? 0.2 : 0.5;
    fprintf(stderr, "footsim bench precision: the references ...\n");
    int nscenes = 0;
    for (int k = 0; k < NSCENES && s == FS_OK; k++) {
        if (!chosen[k])
            continue;
        scene *sc = &scenes[nscenes++];
        s = SCENES[k].design ? landing_scene(sc, &SCENES[k], landing_s, &err) : chain_scene(sc, &err);
        sc->goal_rtf = SCENES[k].goal_rtf, sc->goal_fine_rtf = SCENES[k].goal_fine_rtf;
    }
    fs_provenance prov = {.ninputs = 0};
    const fs_scenario *loaded[NSCENES];
    for (int c = 0; c < nscenes; c++)
        loaded[c] = &scenes[c].base;
    if (s == FS_OK)
        s = cli_bench_provenance(&prov, loaded, nscenes, "each row's stepper, iterations, spring, step_s and impact_substeps; the "
                                 "rest as the inputs give them; landing_flat from seed 10's pose and rough ground "
                                 "under single_tall, landing_biomimetic from seed 1's on flat ground and "
                                 "landing_biomimetic_rough from seed 4's on rough ground, both under drop_weight; "
                                 "flat_rig_* the flat foot under the rig from seed 1's pose on each terrain named",
                                 &err);
    if (s == FS_OK)
        s = sweep(scenes, nscenes, a->quick, rows, &nrows, &err);
    if (s == FS_OK && eq && (eq_status = cli_equivalence_run(eq)) != 0) /* said already */
        s = fs_fail(&err, (fs_status)eq_status, "bench precision: the campaign-equivalence stage failed (above)");
    const report x = {rows, nrows, scenes, nscenes, machine, command, a->quick, &prov, eq};
    if (s == FS_OK)
        s = fs_write_in(dir, "precision.csv", fill_csv, &x, &err);
    if (s == FS_OK) {
        char date[32];
        time_t now = time(NULL);
        strftime(date, sizeof date, "%Y-%m-%d %H:%M", gmtime(&now));
        s = (fs_status)cli_csv_beside(dir, "precision.csv", &prov, command, date, machine, NAN, cli_load_average(),
                                      &err);
    }
    if (s == FS_OK)
        s = fs_write_in(dir, "precision.md", fill_md, &x, &err);
    if (s == FS_OK)
        s = fs_write_in(dir, "precision.gp", fill_chart, &x, &err);
    if (s == FS_OK)
        cli_gnuplot(dir, "precision.gp", "precision.png", "bench precision");
    fs_provenance_free(&prov);
    cli_equivalence_close(eq);
    for (int c = 0; c < NSCENES; c++) { /* calloc'd: the scenes not loaded free nothing */
        fs_track_free(&scenes[c].ref);
        fs_scenario_free(&scenes[c].base);
    }
    free(scenes);
    free(rows);
    if (s != FS_OK)
        return cli_report(s, err.message);
    printf("footsim bench precision: %d configurations; results in %s/precision.{csv,md,png}", nrows, dir);
    if (eq)
        printf("; campaign equivalence in %s/", eq_dir);
    printf("\n");
    return 0;
}
