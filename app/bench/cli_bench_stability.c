/* cli_bench_stability.c: 'footsim bench stability': where the numerics hold, over step size,
 * spring stiffness, load, link masses and drop height, for both spring implementations and both
 * ODE steppers.
 *
 * Four slices, each a grid of step size against one quantity, each for 2 springs x 2 steppers:
 * stiffness (all fifteen springs, static_load.ini), load (static_load.ini), mass (every link mass
 * scaled, static_load.ini), drop (the landing robot let fall, landing_trial.ini at its mean
 * pose) and law (the landing robot dropped 2 cm on a foot whose three spring kinds all follow one
 * law: 0 linear, 1 progressive, 2 bilinear, 3 curve, 4 linear tension-only; the parameters in
 * set_law). A run steps its scenario for a fixed time with the run-time checks of fs_check.h, which
 * record a drift and stop at a blow-up: the classifier and the run-time checks are one piece of
 * code. The runs go to footsim's pool of worker processes (fs_pool.h): an ODE error (which exits
 * the process), a crash or a hang (killed by the pool's watchdog) is a blown-up run and the sweep
 * goes on; results do not depend on -j. Files: DIR/stability.csv, stability_<slice>.gp and .png, stability.md, each whole or not at
 * all. */
#include "cli.h"

#include "footsim/exec/fs_pool.h"
#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

enum { NSLICES = 7, NCOMBOS = 4, MAX_VALUES = 12, MAX_WORKERS = 64, MAX_SET = 4, LAW_SLICE = 5 };

/* A swept quantity and its values (full sweep, then --quick). */
typedef struct slice {
    const char *name, *scenario, *label, *unit;
    int log_axis;
    double full[MAX_VALUES], quick[MAX_VALUES];
    int nfull, nquick;
    const char *set[MAX_SET];   /* overrides of its scenario, NULL after the last */
} slice;

static const slice SLICES[NSLICES] = {
    {"stiffness", "scenarios/static_load.ini", "spring stiffness k, all 15 springs", "N/m", 1,
     {1e3, 1e4, 1e5, 1e6, 1e7}, {1e3, 1e5, 1e7}, 5, 3, {NULL}},
    {"load", "scenarios/static_load.ini", "load at the ankle", "kg", 1, {1, 5, 26, 100, 500}, {1, 26, 500}, 5, 3, {NULL}},
    {"mass", "scenarios/static_load.ini", "link mass scale (every link)", "", 1, {0.01, 0.1, 1, 10}, {0.01, 1}, 4, 2, {NULL}},
    {"drop", "scenarios/landing_trial.ini", "drop height of the 26 kg robot", "m", 0, {0, 0.005, 0.02, 0.05},
     {0, 0.02}, 4, 2, {NULL}},
    /* the soil's explicit forces (docs/soil.md, Stability): the stiff elastic (unloading and reloading)
     * branch K_e against the step, the flat foot under the drop weight landing on dry sand */
    {"soil", "scenarios/landing_trial.ini", "elastic slope K_e of dry sand (flat foot, drop weight)", "Pa/m", 1,
     {2e7, 2e8, 2e9}, {2e8}, 3, 1,
     {"scenario.design=feet/flat.ini", "scenario.terrain=../terrains/soils/dry_sand.ini",
      "robot.design=robots/drop_weight.ini"}},
    {"law", "scenarios/landing_trial.ini", "spring law (0 linear, 1 progressive, 2 bilinear, 3 curve, 4 cable)", "", 0,
     {0, 1, 2, 3, 4}, {1, 4}, 5, 2, {NULL}},
    /* the same soil under the biomimetic foot, whose light links (8-25 g) each meet the soil through
     * their own capsule, under the trial's own robot, single_tall: an audit found its toe hinges
     * drifting at steps the flat sole's slice passes (the cause, as far as it was traced: docs/soil.md,
     * Explicit forces) */
    {"soil_biomimetic", "scenarios/landing_trial.ini", "elastic slope K_e of dry sand (biomimetic foot, single_tall)",
     "Pa/m", 1, {2e7, 2e8, 2e9}, {2e8}, 3, 1, {"scenario.terrain=../terrains/soils/dry_sand.ini"}},
};

/* a slice on a soil: its quantity is the soil's K_e */
static int on_soil(const slice *s) { return !strncmp(s->name, "soil", 4); }

/* The law slice's value v for every spring kind: progressive doubling its stiffness at 0.5 mm;
 * bilinear 4 k beyond a 0.3 mm stop; a curve of slope k to 0.2 mm and 4 k beyond (points at 0,
 * +-0.2 and +-0.6 mm, extended past them); and linear tension-only (a cable). Drop 2 cm. */
static void set_law(fs_design_def *d, int v)
{
    static const double x[] = {-0.0006, -0.0002, 0, 0.0002, 0.0006};
    for (int k = 0; k < 3; k++) {
        double kk = d->k_N_per_m[k];
        d->law[k] = v == 4 ? FS_LAW_LINEAR : v;
        d->tension_only[k] = v == 4;
        d->x0_m[k] = 5e-4;
        d->stop_m[k] = 3e-4;
        d->k2_N_per_m[k] = 4 * kk;
        d->curve_m[k].n = d->curve_N[k].n = 5;
        for (int i = 0; i < 5; i++) {
            d->curve_m[k].v[i] = x[i];
            d->curve_N[k].v[i] = kk * (fabs(x[i]) <= 2e-4 ? x[i] : copysign(2e-4 + 4 * (fabs(x[i]) - 2e-4), x[i]));
        }
    }
}
/* finer around the explicit springs' limit (4e-5 to 8e-5 s for the default foot) */
static const double STEPS_FULL[] = {1e-5, 2e-5, 3e-5, 4e-5, 5e-5, 6e-5, 8e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2};
static const double STEPS_QUICK[] = {2e-5, 1e-4, 5e-4, 2e-3, 1e-2};
static const char *const STEPPERS[2] = {"step", "quickstep"}, *const SPRINGS[2] = {"implicit", "explicit"};

/* Simulated time of each run, s: the static load rises over 20 ms and settles by 0.2 s; the robot
 * dropped 5 cm lands at 0.1 s. */
static const double DURATION_FULL_S = 0.3, DURATION_QUICK_S = 0.1;

typedef struct config {
    int slice, stepper, springs;
    double step_s, value; /* value: the slice's quantity */
} config;

/* What a run found; a child sends it whole through its pipe. */
typedef struct outcome {
    int status;                 /* FS_OK, or FS_BAD_INPUT when the scenario was refused (a bug here) */
    int cls, kind, drift;       /* fs_check_class, the failure's and the first drift's fs_check_kind */
    char reason[32];            /* the kind's name, or how the child died */
    double time_s, drift_time_s, sim_time_s;
    long steps;
    double loop_m, excess_J, bound_J, speed_m_per_s, limit_s;
    int iterations;
    char where[48], drift_where[48];
    char error[512];
} outcome;

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* ---- one run ---------------------------------------------------------------------------------- */

/* A configuration put into a loaded scenario's definitions (typed edits, then one compile, which
 * checks them against the schema); base masses from the design. */
static fs_status configure(const config *c, const fs_design_def *base, double duration, fs_scenario *sc,
                           fs_error *err)
{
    const slice *s = &SLICES[c->slice];
    fs_scenario_def *d = &sc->def;
    d->step_s = c->step_s;
    d->stepper = c->stepper;
    d->springs = c->springs;
    d->duration_s = duration;
    d->log_interval_s = fmax(c->step_s, 1e-3);
    if (!strcmp(s->name, "stiffness"))
        for (int k = 0; k < 3; k++)
            sc->design.k_N_per_m[k] = c->value;
    if (!strcmp(s->name, "load"))
        d->load_kg = c->value;
    if (!strcmp(s->name, "mass")) {
        sc->design.heel_kg = base->heel_kg * c->value;
        sc->design.talus_kg = base->talus_kg * c->value;
        sc->design.metatarsal_kg = base->metatarsal_kg * c->value;
        sc->design.phalanx_kg = base->phalanx_kg * c->value;
    }
    if (!strcmp(s->name, "drop"))
        d->drop_m = c->value;
    if (on_soil(s))
        sc->terrain.def.soil.K_e_Pa_per_m = c->value;
    if (!strcmp(s->name, "law")) {
        d->drop_m = 0.02;
        set_law(&sc->design, (int)c->value);
    }
    return fs_scenario_compile(sc, err);
}

/* Steps the configuration for the duration, the checks recording drifts, until it blows up: on a
 * copy of its slice's scenario, loaded once (loaded), its definitions edited. */
static void run_config(const config *c, const fs_scenario *loaded, double duration, outcome *o)
{
    fs_scenario *sc = calloc(1, sizeof *sc); /* large: on the heap, freed on every path */
    fs_error err = {FS_OK, ""};
    memset(o, 0, sizeof *o);
    o->status = sc ? fs_scenario_copy(sc, loaded, &err) : fs_fail(&err, FS_NO_MEMORY, "out of memory");
    if (o->status == FS_OK)
        o->status = configure(c, &loaded->design, duration, sc, &err);
    fs_sim *sim = NULL;
    if (o->status == FS_OK)
        o->status = fs_sim_new(sc, &(fs_sim_options){.with_ground = 1, .record_drift = 1}, &sim, &err);
    if (o->status != FS_OK) {
        snprintf(o->error, sizeof o->error, "%.500s", err.message);
        if (sc)
            fs_scenario_free(sc);
        free(sc);
        return;
    }
    fs_drive_spec spec = {.max_steps = (long)ceil(duration / c->step_s - 1e-9)};
    fs_drive_result r;
    fs_status s = fs_drive(sim, &spec, &r, &err);
    const fs_check *k = fs_sim_checks(sim);
    o->kind = s == FS_OK ? FS_CHECK_OK : k->failure;
    o->drift = k->first_drift;
    o->cls = fs_check_class_of(o->kind != FS_CHECK_OK ? (fs_check_kind)o->kind : k->first_drift);
    snprintf(o->reason, sizeof o->reason, "%s", fs_check_kind_name(o->kind != FS_CHECK_OK ? o->kind : o->drift));
    snprintf(o->where, sizeof o->where, "%s", o->kind != FS_CHECK_OK ? k->failure_where : k->drift_where);
    snprintf(o->drift_where, sizeof o->drift_where, "%s", k->drift_where);
    if (fs_sim_dead(sim)) { /* ODE's own check stopped the step (fs_ode.h): blown up */
        o->cls = FS_CHECK_BLOWN_UP;
        snprintf(o->reason, sizeof o->reason, "ode_error");
        snprintf(o->where, sizeof o->where, "ODE");
    }
    o->time_s = o->kind != FS_CHECK_OK ? k->failure_time_s : o->drift ? k->first_drift_time_s : NAN;
    o->drift_time_s = o->drift ? k->first_drift_time_s : NAN;
    o->sim_time_s = fs_sim_time(sim);
    o->steps = k->steps;
    o->loop_m = k->max_loop_error_m;
    o->excess_J = k->max_energy_excess_J;
    o->bound_J = k->energy_bound_J;
    o->speed_m_per_s = k->max_speed_m_per_s;
    o->limit_s = fs_check_explicit_step_limit(sim);
    o->iterations = sc->def.iterations;
    fs_sim_free(sim);
    fs_scenario_free(sc);
    free(sc);
}

/* ---- the runs, in footsim's pool of worker processes -------------------------------------------- */

typedef struct sweep {
    const config *cfg;
    outcome *out;
    fs_scenario *const *loaded; /* each slice's scenario, read once */
    double duration;
    cli_progress progress;
    int died;             /* runs whose worker died (counted as blown up) */
} sweep;

/* In a worker: one configuration. */
static void run_task(int index, void *result, void *user)
{
    const sweep *w = user;
    run_config(&w->cfg[index], w->loaded[w->cfg[index].slice], w->duration, result);
}

/* In the parent: a run's outcome, or the refused scenario that stops the sweep (a bug here). */
static fs_status take_task(int index, const void *result, void *user, fs_error *err)
{
    const sweep *w = user;
    const outcome *o = result;
    if (o->status != FS_OK)
        return fs_fail(err, (fs_status)o->status, "%s", o->error);
    w->out[index] = *o;
    return FS_OK;
}

/* In the parent: a run whose worker died (an ODE error, a crash) or hung: a blown-up run. */
static void task_died(int index, const fs_pool_death *d, void *user)
{
    sweep *w = user;
    w->died++;
    const config *c = &w->cfg[index];
    outcome *o = &w->out[index];
    memset(o, 0, sizeof *o);
    o->cls = FS_CHECK_BLOWN_UP;
    o->time_s = o->drift_time_s = o->sim_time_s = o->loop_m = o->excess_J = o->bound_J = NAN;
    o->speed_m_per_s = o->limit_s = NAN;
    if (d->timed_out)
        snprintf(o->reason, sizeof o->reason, "timed_out");
    else if (d->exited)
        snprintf(o->reason, sizeof o->reason, d->status == FS_NUMERICAL ? "ode_error" : "exit_%d", d->status);
    else
        snprintf(o->reason, sizeof o->reason, "signal_%d", d->signal);
    fprintf(stderr, "footsim bench stability: the run %s (%s), %s, %s springs, h = %g s, %s = %g %s\n", o->reason,
            d->how, STEPPERS[c->stepper], SPRINGS[c->springs], c->step_s, SLICES[c->slice].name, c->value,
            "(counted as blown_up)");
}

static void progress(int done, int n, void *user)
{
    sweep *w = user;
    cli_progress_update(&w->progress, done, n, w->died);
}

/* Runs every configuration in up to jobs workers. */
static fs_status run_all(const config *cfg, outcome *out, int n, int jobs, fs_scenario *const *loaded,
                         double duration, fs_error *err)
{
    sweep w = {cfg, out, loaded, duration, {0}, 0};
    cli_progress_start(&w.progress, "footsim bench stability", "runs");
    fs_pool_spec spec = {.ntasks = n, .jobs = jobs, .result_size = sizeof(outcome), .user = &w, .run = run_task,
                         .done = take_task, .died = task_died, .progress = progress};
    return fs_pool_run(&spec, NULL, err);
}

/* ---- the grid --------------------------------------------------------------------------------- */

static int grid(int quick, const int *chosen, config *cfg)
{
    const double *steps = quick ? STEPS_QUICK : STEPS_FULL;
    int nsteps = quick ? (int)(sizeof STEPS_QUICK / sizeof *STEPS_QUICK) : (int)(sizeof STEPS_FULL / sizeof *STEPS_FULL);
    int n = 0;
    for (int s = 0; s < NSLICES; s++) {
        const slice *sl = &SLICES[s];
        if (!chosen[s])
            continue;
        for (int combo = 0; combo < NCOMBOS; combo++)
            for (int v = 0; v < (quick ? sl->nquick : sl->nfull); v++)
                for (int h = 0; h < nsteps; h++)
                    cfg[n++] = (config){s, combo / 2, combo % 2, steps[h], quick ? sl->quick[v] : sl->full[v]};
    }
    return n;
}

/* ---- files ------------------------------------------------------------------------------------ */

/* What the files are made of (each written whole or not at all by fs_write_in). */
typedef struct report {
    const config *cfg;
    const outcome *out;
    int n, quick, jobs;
    double wall_s;
    const fs_provenance *prov;
    const int *chosen;          /* the slices run (--scene), NSLICES flags */
    const char *command;        /* as the results name it: "footsim bench stability --quick --scene soil" */
} report;

static int fill_csv(FILE *f, const void *user)
{
    const report *x = user;
    const config *cfg = x->cfg;
    const outcome *out = x->out;
    int n = x->n;
    fprintf(f, "slice,stepper,iterations,springs,step_s,k_N_per_m,load_kg,mass_scale,drop_m,K_e_Pa_per_m,class,"
               "class_code,reason,"
               "where,time_s,drift_reason,drift_time_s,steps,max_loop_err_m,max_energy_excess_J,energy_bound_J,"
               "max_speed_m_per_s,explicit_limit_s,law\n");
    for (int i = 0; i < n; i++) {
        const config *c = &cfg[i];
        const outcome *o = &out[i];
        const char *sl = SLICES[c->slice].name;
        double k = !strcmp(sl, "stiffness") ? c->value : 12000, load = !strcmp(sl, "load") ? c->value : 26;
        double scale = !strcmp(sl, "mass") ? c->value : 1, drop = !strcmp(sl, "drop") ? c->value : 0;
        char ke[32] = ""; /* the soil's K_e; empty for a rigid slice */
        if (on_soil(&SLICES[c->slice]))
            snprintf(ke, sizeof ke, "%g", c->value);
        double law = !strcmp(sl, "law") ? c->value : 0;
        if (!strcmp(sl, "law"))
            drop = 0.02;
        /* a quantity the run did not have (no failure: its time; a blow-up's non-finite figures): empty */
        char b[7][32], q[2][128];
        fprintf(f, "%s,%s,%d,%s,%g,%g,%g,%g,%g,%s,%s,%d,%s,%s,%s,%s,%s,%ld,%s,%s,%s,%s,%s,%g\n", sl,
                STEPPERS[c->stepper], o->iterations, SPRINGS[c->springs], c->step_s, k, load, scale, drop, ke,
                fs_check_class_name((fs_check_class)o->cls), o->cls, cli_csv_text(q[0], sizeof q[0], o->reason),
                cli_csv_text(q[1], sizeof q[1], o->where),
                cli_csv_num(b[0], sizeof b[0], "%.6g", o->time_s), fs_check_kind_name((fs_check_kind)o->drift),
                cli_csv_num(b[1], sizeof b[1], "%.6g", o->drift_time_s), o->steps,
                cli_csv_num(b[2], sizeof b[2], "%.4g", o->loop_m), cli_csv_num(b[3], sizeof b[3], "%.4g", o->excess_J),
                cli_csv_num(b[4], sizeof b[4], "%.4g", o->bound_J),
                cli_csv_num(b[5], sizeof b[5], "%.4g", o->speed_m_per_s), cli_csv_num(b[6], sizeof b[6], "%.4g", o->limit_s),
                law);
    }
    return 1;
}

/* The column of a slice's quantity in stability.csv (1-based, for gnuplot): the law's is the last, both
 * soil slices' K_e's the tenth. */
static int value_column(int s) { return s == LAW_SLICE ? 24 : on_soil(&SLICES[s]) ? 10 : 6 + s; }

/* One chart per slice: step size against the quantity, a panel per spring x stepper, each run a
 * square coloured by its class, the explicit springs' predicted limit as crosses. */
static fs_status write_script(const char *dir, int s, fs_error *err)
{
    const slice *sl = &SLICES[s];
    char path[FS_OUT_PATH], text[6000];
    int n = snprintf(text, sizeof text,
                     "# footsim bench stability: %s against step size (run from this folder: gnuplot -e \"out='x.png'\" "
                     "stability_%s.gp)\n"
                     "set terminal pngcairo size 1200,900 noenhanced font 'sans,10'\nset output out\n"
                     "set datafile separator ','\nset multiplot layout 2,2 title 'footsim bench stability: %s'\n"
                     "set logscale x\nset xrange [5e-6:2e-2]\nset format x '%%.0e'\nset xlabel 'step h, s'\nset ylabel '%s%s%s%s'\n%s"
                     "set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08\nset key outside bottom center horizontal\n"
                     "set linetype 11 lc rgb '#2ca02c'\nset linetype 12 lc rgb '#ff9f1c'\nset linetype 13 lc rgb '#d62728'\n",
                     sl->name, sl->name, sl->name, sl->label, *sl->unit ? ", " : "", sl->unit, "",
                     sl->log_axis ? "set logscale y\n" : "");
    for (int combo = 0; combo < NCOMBOS && n < (int)sizeof text; combo++) {
        const char *st = STEPPERS[combo / 2], *sp = SPRINGS[combo % 2];
        n += snprintf(text + n, sizeof text - (size_t)n,
                      "set title '%s springs, %s'\n"
                      "ok(p) = strcol(1) eq '%s' && strcol(2) eq '%s' && strcol(4) eq '%s' && column(12) == p\n"
                      "plot for [p=0:2] 'stability.csv' every ::1 using (ok(p) ? $5 : NaN):%d:(11 + p) with points "
                      "pt 5 ps 1.8 lc variable title word('stable drifting blown_up', p + 1), \\\n"
                      "     'stability.csv' every ::1 using (ok(0) + ok(1) + ok(2) && '%s' eq 'explicit' ? $23 : NaN):%d "
                      "with points pt 2 ps 1.5 lc rgb 'black' title 'predicted explicit limit'\n",
                      sp, st, sl->name, st, sp, value_column(s), sp, value_column(s));
    }
    n += snprintf(text + n, sizeof text - (size_t)n, "unset multiplot\n");
    if (fs_path_format(path, sizeof path, "--out", err, "%s/stability_%s.gp", dir, sl->name) != FS_OK)
        return FS_BAD_INPUT;
    return fs_write_atomic(path, text, strlen(text), err);
}

/* Rows over several slices: every run, or every run with the design's link masses. */
enum { ALL_RUNS = -1, DESIGN_MASSES = -2, MASS_SLICE = 2 /* SLICES[2] */ };

/* Whether run c belongs to a row: its spring x stepper, and its slice and value (or ALL_RUNS, or
 * DESIGN_MASSES). */
static int in_row(const config *c, int s, int combo, double value)
{
    if (c->stepper != combo / 2 || c->springs != combo % 2)
        return 0;
    if (s == ALL_RUNS)
        return 1;
    if (s == DESIGN_MASSES)
        return c->slice != MASS_SLICE || c->value == 1;
    return c->slice == s && c->value == value;
}

/* The largest step of a row below which every run was stable, and the smallest that drifted and
 * that blew up; 0 / INFINITY when none. */
static void boundary(const config *cfg, const outcome *out, int n, int s, int combo, double value, double *stable,
                     double *blown, double *drift)
{
    *stable = 0, *blown = *drift = INFINITY;
    double first_bad = INFINITY;
    for (int i = 0; i < n; i++) {
        if (!in_row(&cfg[i], s, combo, value))
            continue;
        if (out[i].cls != FS_CHECK_STABLE)
            first_bad = fmin(first_bad, cfg[i].step_s);
        if (out[i].cls == FS_CHECK_BLOWN_UP)
            *blown = fmin(*blown, cfg[i].step_s);
        if (out[i].cls == FS_CHECK_DRIFTING)
            *drift = fmin(*drift, cfg[i].step_s);
    }
    for (int i = 0; i < n; i++)
        if (in_row(&cfg[i], s, combo, value) && cfg[i].step_s < first_bad)
            *stable = fmax(*stable, cfg[i].step_s);
}

static void cell(char *buf, size_t size, double stable, double drift, double blown)
{
    int k = snprintf(buf, size, "%s", "");
    if (stable > 0)
        k += snprintf(buf + k, size - (size_t)k, "≤ %g", stable);
    else
        k += snprintf(buf + k, size - (size_t)k, "none");
    if (isfinite(drift))
        k += snprintf(buf + k, size - (size_t)k, "; drifts %g", drift);
    if (isfinite(blown))
        snprintf(buf + k, size - (size_t)k, "; blows up %g", blown);
}

/* The limit the explicit springs' stability predicts for one row (the first run of it). */
static double predicted(const config *cfg, const outcome *out, int n, int s, double value)
{
    for (int i = 0; i < n; i++)
        if (cfg[i].slice == s && cfg[i].value == value && isfinite(out[i].limit_s) && out[i].limit_s > 0)
            return out[i].limit_s;
    return NAN;
}

static void slice_table(FILE *f, const config *cfg, const outcome *out, int n, int s, int quick)
{
    const slice *sl = &SLICES[s];
    fprintf(f, "\n### %s: step size against %s (`%s`)\n\n![%s](stability_%s.png)\n\n", sl->name, sl->label,
            sl->scenario, sl->name, sl->name);
    fprintf(f, "| %s%s%s%s | explicit limit predicted, s | step, implicit | step, explicit | quickstep, implicit | "
               "quickstep, explicit |\n|--:|--:|---|---|---|---|\n",
            sl->name, *sl->unit ? " (" : "", sl->unit, *sl->unit ? ")" : "");
    for (int v = 0; v < (quick ? sl->nquick : sl->nfull); v++) {
        double value = quick ? sl->quick[v] : sl->full[v];
        double limit = predicted(cfg, out, n, s, value); /* NaN: no spring to predict it from (the flat foot) */
        if (isnan(limit))
            fprintf(f, "| %g | — |", value);
        else
            fprintf(f, "| %g | %.2g |", value, limit);
        for (int combo = 0; combo < NCOMBOS; combo++) { /* combo = stepper * 2 + springs */
            double st, bl, dr;
            char text[160];
            boundary(cfg, out, n, s, combo, value, &st, &bl, &dr);
            cell(text, sizeof text, st, dr, bl);
            fprintf(f, " %s |", text);
        }
        fputc('\n', f);
    }
}

static void count_classes(const outcome *out, int n, int counts[3])
{
    counts[0] = counts[1] = counts[2] = 0;
    for (int i = 0; i < n; i++)
        counts[out[i].cls]++;
}

static int fill_summary(FILE *f, const void *user)
{
    const report *x = user;
    const config *cfg = x->cfg;
    const outcome *out = x->out;
    int n = x->n, quick = x->quick, jobs = x->jobs;
    double wall_s = x->wall_s;
    char machine[512];
    cli_machine(machine, sizeof machine);
    int counts[3];
    count_classes(out, n, counts);
    fprintf(f, "# Numerical stability (`%s`)\n\n", x->command);
    fprintf(f, "%d runs of %.2f s simulated each: %d stable, %d drifting, %d blown up; %.0f s with -j %d on %s.\n",
            n, quick ? DURATION_QUICK_S : DURATION_FULL_S, counts[0], counts[1], counts[2], wall_s, jobs, machine);
    fprintf(f, "\nClasses (the run-time checks of `include/footsim/sim/fs_check.h`, default bounds): **stable**; "
               "**drifting**: a hinge's anchors over 1 mm apart, or the energy above its start plus the work put "
               "in by more than 1 J + 10 %% of that work; **blown up**: a non-finite state, a point faster than "
               "100 m/s, or an ODE error that ended the run's process.\n");
    fprintf(f, "\nEach cell: the largest step h (s) at which that row was stable at every step up to it, then the "
               "smallest h that drifted and that blew up. The predicted limit is the explicit springs' (the "
               "lightest body as a mass on its springs and dampers, `fs_check_explicit_step_limit`: "
               "k h² + 2 c h < 4 m); the paper's default foot gives 4.0e-5 s (phalanx, 8 g, two dampers of "
               "200 N·s/m), or 8e-5 s with one damper (2 m / c).\n");
    int all = 1;
    for (int s = 0; s < NSLICES; s++)
        all &= x->chosen[s];
    fprintf(f, "\n## Safe envelope\n\nThe largest step at which every swept case (every %s) was "
               "stable, then the smallest that drifted and that blew up; and the same with the design's link "
               "masses (the mass slice's other scales left out):\n\n| springs, stepper | every case | design's "
               "link masses |\n|---|---|---|\n", all ? "slice and value" : "value of the slices run here");
    for (int combo = 0; combo < NCOMBOS; combo++) {
        char text[2][160];
        for (int k = 0; k < 2; k++) {
            double st, bl, dr;
            boundary(cfg, out, n, k ? DESIGN_MASSES : ALL_RUNS, combo, 0, &st, &bl, &dr);
            cell(text[k], sizeof text[k], st, dr, bl);
        }
        fprintf(f, "| %s, %s | %s | %s |\n", SPRINGS[combo % 2], STEPPERS[combo / 2], text[0], text[1]);
    }
    for (int s = 0; s < NSLICES; s++)
        if (x->chosen[s])
            slice_table(f, cfg, out, n, s, quick);
    fprintf(f, "\n`stability.csv` has every run (class, the check that failed, where and when, the worst loop "
               "error, energy excess and speed); `stability_<slice>.gp` draws each chart.\n");
    fputs("\nProvenance: ", f);
    fs_provenance_print(x->prov, f);
    fputs(".\n", f);
    return 1;
}

/* ---- the command ------------------------------------------------------------------------------ */

/* Which slices run: every one, or those --scene names. */
static int choose_slices(const cli_args *a, int chosen[NSLICES])
{
    const char *names[NSLICES];
    for (int k = 0; k < NSLICES; k++) {
        chosen[k] = !a->scene;
        names[k] = SLICES[k].name;
    }
    return cli_bench_choose("stability", "slice", a->scene, names, NSLICES, chosen);
}

int cli_bench_stability_slices(const cli_args *a)
{
    int chosen[NSLICES];
    return choose_slices(a, chosen);
}

int cli_bench_stability(const cli_args *a, const char *dir)
{
    int jobs, chosen[NSLICES];
    int st = cli_parse_jobs(a, &jobs);
    if (!st)
        st = choose_slices(a, chosen);
    if (st)
        return st;
    char command[512];
    snprintf(command, sizeof command, "footsim bench stability%s%s%.400s", a->quick ? " --quick" : "",
             a->scene ? " --scene " : "", a->scene ? a->scene : "");
    jobs = jobs < MAX_WORKERS ? jobs : MAX_WORKERS;
    fs_error err;
    /* each slice's scenario read once (the workers copy it), before anything runs */
    fs_scenario *loaded[NSLICES] = {NULL};
    fs_provenance prov = {.ninputs = 0};
    fs_status s = FS_OK;
    const fs_scenario *inputs[NSLICES]; /* the slices run, for the provenance */
    int ninputs = 0;
    for (int i = 0; i < NSLICES && s == FS_OK; i++) {
        if (!chosen[i])
            continue; /* a slice not run is not read */
        for (int j = 0; j < i && !loaded[i] && !SLICES[i].set[0]; j++)
            if (loaded[j] && !strcmp(SLICES[j].scenario, SLICES[i].scenario) && !SLICES[j].set[0])
                loaded[i] = loaded[j];
        if (loaded[i])
            continue;
        if (!(loaded[i] = calloc(1, sizeof *loaded[i])))
            s = fs_fail(&err, FS_NO_MEMORY, "out of memory");
        else {
            int nset = 0;
            while (nset < MAX_SET && SLICES[i].set[nset])
                nset++;
            s = fs_scenario_load(cli_data_path(SLICES[i].scenario), SLICES[i].set, nset, loaded[i], &err);
        }
    }
    if (s == FS_OK)
        for (int i = 0; i < NSLICES; i++)
            if (chosen[i])
                inputs[ninputs++] = loaded[i];
    if (s == FS_OK)
        s = cli_bench_provenance(&prov, inputs, ninputs, "each row's stepper, springs "
                                 "and step_s, and its slice's quantity; the rest as the inputs give them", &err);
    if (s == FS_OK)
        s = fs_make_dirs(dir, &err);
    /* the grid of configurations: large, so on the heap for this command */
    config *cfg = calloc(NSLICES * NCOMBOS * MAX_VALUES * 16, sizeof *cfg);
    if (s == FS_OK && !cfg)
        s = fs_fail(&err, FS_NO_MEMORY, "out of memory");
    int n = cfg ? grid(a->quick, chosen, cfg) : 0;
    outcome *out = s == FS_OK ? calloc((size_t)n, sizeof *out) : NULL;
    if (s == FS_OK && !out)
        s = fs_fail(&err, FS_NO_MEMORY, "out of memory");
    double duration = a->quick ? DURATION_QUICK_S : DURATION_FULL_S, t0 = fs_clock_s();
    if (s == FS_OK) {
        fprintf(stderr, "footsim bench stability: %d runs of %g s simulated, -j %d\n", n, duration, jobs);
        s = run_all(cfg, out, n, jobs, loaded, duration, &err);
    }
    report x = {cfg, out, n, a->quick, jobs, 0, &prov, chosen, command};
    if (s == FS_OK)
        s = fs_write_in(dir, "stability.csv", fill_csv, &x, &err);
    if (s == FS_OK) {
        char date[32], machine[512];
        time_t now = time(NULL);
        strftime(date, sizeof date, "%Y-%m-%d %H:%M", gmtime(&now));
        cli_machine(machine, sizeof machine);
        s = (fs_status)cli_csv_beside(dir, "stability.csv", &prov, command, date, machine, NAN, cli_load_average(),
                                      &err);
    }
    for (int i = 0; s == FS_OK && i < NSLICES; i++) {
        if (!chosen[i])
            continue;
        char gp[64], png[64];
        snprintf(gp, sizeof gp, "stability_%s.gp", SLICES[i].name);
        snprintf(png, sizeof png, "stability_%s.png", SLICES[i].name);
        if ((s = write_script(dir, i, &err)) == FS_OK)
            cli_gnuplot(dir, gp, png, "bench stability");
    }
    x.wall_s = fs_clock_s() - t0;
    if (s == FS_OK)
        s = fs_write_in(dir, "stability.md", fill_summary, &x, &err);
    free(out);
    free(cfg);
    fs_provenance_free(&prov);
    for (int i = 0; i < NSLICES; i++) {
        int shared = 0;
        for (int j = 0; j < i; j++)
            shared |= loaded[j] == loaded[i];
        if (loaded[i] && !shared) {
            fs_scenario_free(loaded[i]);
            free(loaded[i]);
        }
    }
    if (s != FS_OK)
        return fail(&err);
    printf("bench stability: %d runs; results: %s/stability.md, stability.csv, stability_*.png\n", n, dir);
    return 0;
}
