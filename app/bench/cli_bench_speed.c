/* cli_bench_speed.c: 'footsim bench speed': steps per second and real-time factor of each shipped
 * scenario on one core, where a step's time goes (collision, by ODE's tests or footsim's own on a
 * heightfield; ODE's step; footsim's own code besides: fs_observer.h), and what each thing a run
 * skips saves, each measured with and without.
 *
 * Every time is the wall time of building the world, stepping and measuring (what 'footsim run',
 * 'trial' or 'walk' spends between reading its files and writing its results), the median of
 * repeated runs; each scene's files are read once, before it is timed. A pair (with and without a skip) takes turns run by run, so that other load on the machine
 * hits both alike. Writes DIR/speed.csv, skips.csv (each with its NAME.provenance.json: the machine,
 * the date, the load and what made it), speed.md, speed.gp and speed.png. */
#include "cli.h"

#include "footsim/base/fs_stats.h"
#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/experiment/fs_walk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { MAX_SET = 8, MAX_RUNS = 9, NPRINT = 5 };

typedef enum runner { BY_RUN, BY_TRIAL, BY_WALK } runner;

/* A scenario as the benchmark runs it: which engine, which file, which overrides. */
typedef struct scene {
    const char *name;           /* the row's label */
    runner how;
    const char *path;
    const char *set[MAX_SET];   /* overrides, NULL after the last */
    int flags;                  /* FULL, QUICK, SLOW */
} scene;

/* What one run did: its steps, simulated time, and a fingerprint of its result (bit-compared). */
typedef struct outcome {
    long steps;
    double sim_s, wall_s;
    double print[NPRINT];
} outcome;

/* One scene measured: the median run, and the median stages of its profiled runs. */
typedef struct timing {
    const scene *sc;
    int runs;
    outcome median;
    fs_profile prof;
    double prof_wall_s;
    double clock_read_s;        /* what one clock read cost, taken off each profiled interval */
    int joint_rows;             /* constraint rows of joints and springs */
    double mean_rows;           /* all rows, contacts too, averaged over the steps */
    int max_rows;
    double found_per_shape;     /* contacts a touching foot shape found a step (before merging, capping) */
    double kept_per_shape;      /* and kept */
    int most_found;             /* the most one shape found in a step */
} timing;

/* A skip measured: the scene with it (the cheap way) and without (the costly way). */
typedef struct skip {
    const char *name, *with, *without;
    scene base;
    const char *with_set[MAX_SET], *without_set[MAX_SET];
    int frames;                 /* the costly way draws frames (the renderer) */
} skip;

typedef struct skip_timing {
    const skip *k;
    int runs, same, skipped;
    outcome with, without;
} skip_timing;

/* ---- the shipped scenarios ----------------------------------------------------------------- */

/* Which runs take a scene or a skip (flags): the full one, --quick, or both; SLOW: it takes
 * seconds a run, so the full run repeats it fewer times. */
enum { FULL = 1, QUICK = 2, BOTH = FULL | QUICK, SLOW = 4 };

#define TRIAL(label, design, terrain, flags_)                                                            \
    {label, BY_TRIAL, "scenarios/landing_trial.ini",                                                     \
     {"scenario.design=feet/" design ".ini", "scenario.terrain=../terrains/" terrain ".ini"}, flags_}
#define STATIC_LOAD(label, ...) {label, BY_RUN, "scenarios/static_load.ini", {__VA_ARGS__}, BOTH}

static const scene SCENES[] = {
    STATIC_LOAD("static_load", NULL),
    {"tilt10", BY_RUN, "scenarios/tilt10.ini", {NULL}, BOTH},
    TRIAL("landing biomimetic flat", "biomimetic", "flat", BOTH),
    TRIAL("landing biomimetic simply_uneven", "biomimetic", "simply_uneven", FULL),
    TRIAL("landing biomimetic complex_uneven", "biomimetic", "complex_uneven", BOTH),
    TRIAL("landing biomimetic stepped", "biomimetic", "stepped", FULL),
    TRIAL("landing biomimetic rough", "biomimetic", "rough", FULL | SLOW),
    TRIAL("landing flat flat", "flat", "flat", BOTH),
    TRIAL("landing flat simply_uneven", "flat", "simply_uneven", FULL | SLOW),
    TRIAL("landing flat complex_uneven", "flat", "complex_uneven", BOTH),
    TRIAL("landing flat stepped", "flat", "stepped", FULL),
    TRIAL("landing flat rough", "flat", "rough", FULL | SLOW),
    /* the same landings on a soil (docs/soil.md): their cost per step against the rows on flat ground */
    TRIAL("landing biomimetic soil dry_sand", "biomimetic", "soils/dry_sand", FULL | SLOW),
    TRIAL("landing flat soil dry_sand", "flat", "soils/dry_sand", FULL | SLOW),
    {"walking", BY_WALK, "scenarios/walking.ini", {NULL}, FULL | SLOW},
    {"walking (2 steps)", BY_WALK, "scenarios/walking.ini", {"walk.steps=2"}, QUICK},
};

/* The flat ground as a heightfield: rough ground of no roughness. */
#define FLAT_HEIGHTFIELD "terrain.kind=rough", "rough.rms_m=0"
/* Runs to duration_s: never at rest long enough to stop. */
#define NO_EARLY_STOP "run.rest_hold_s=100"
#define EVERY_PAIR "foot-only collision pairs", "foot shapes against the ground", "every pair (foot-foot too)"
#define LOGGING "trajectory logging off", "a row every 10 s"
/* footsim's own heightfield tests against ODE's */
#define ODE_TESTS "run.heightfield_contacts=ode"
#define SPHERE_TEST "footsim's sphere-heightfield test", "footsim's", "ODE's"
#define BOX_TEST "footsim's box-heightfield test", "footsim's", "ODE's, with the vertices inside added"

static const skip SKIPS[] = {
    {"plane instead of a heightfield", "flat plane", "flat heightfield",
     TRIAL("landing biomimetic", "biomimetic", "flat", BOTH), {NULL}, {FLAT_HEIGHTFIELD}, 0},
    {"plane instead of a heightfield", "flat plane", "flat heightfield",
     TRIAL("landing flat", "flat", "flat", FULL | SLOW), {NULL}, {FLAT_HEIGHTFIELD}, 0},
    {"cropped heightfield", "region margin 0.06 m", "margin 0.5 m (1.1 x 1.1 m)",
     TRIAL("landing biomimetic rough", "biomimetic", "rough", FULL | SLOW), {NULL}, {"start.region_margin_m=0.5"}, 0},
    {"cropped heightfield", "region margin 0.06 m", "margin 0.2 m",
     TRIAL("landing biomimetic simply_uneven", "biomimetic", "simply_uneven", QUICK), {NULL},
     {"start.region_margin_m=0.2"}, 0},
    /* tiles are ODE's heightfield geometry: used only by ODE's tests */
    {"heightfield in tiles (ODE's tests)", "8-cell tiles", "one heightfield",
     TRIAL("landing biomimetic complex_uneven", "biomimetic", "complex_uneven", FULL | SLOW), {ODE_TESTS},
     {ODE_TESTS, "run.tile_cells=4096"}, 0},
    {SPHERE_TEST, TRIAL("landing biomimetic rough", "biomimetic", "rough", FULL | SLOW), {NULL}, {ODE_TESTS}, 0},
    {SPHERE_TEST, TRIAL("landing biomimetic simply_uneven", "biomimetic", "simply_uneven", QUICK), {NULL},
     {ODE_TESTS}, 0},
    {BOX_TEST, TRIAL("landing flat simply_uneven", "flat", "simply_uneven", FULL | SLOW), {NULL}, {ODE_TESTS}, 0},
    {BOX_TEST, TRIAL("landing flat complex_uneven", "flat", "complex_uneven", QUICK), {NULL}, {ODE_TESTS}, 0},
    {EVERY_PAIR, STATIC_LOAD("static_load", NULL), {NULL}, {"run.collide=all"}, 0},
    {EVERY_PAIR, TRIAL("landing biomimetic complex_uneven", "biomimetic", "complex_uneven", FULL), {NULL},
     {"run.collide=all"}, 0},
    {"early stop at rest", "stop at rest", "run to duration_s (1 s)", STATIC_LOAD("static_load", NULL), {NULL},
     {NO_EARLY_STOP}, 0},
    {"ODE auto-disable", "auto_disable_s = 0.05", "off", STATIC_LOAD("static_load to 1 s", NO_EARLY_STOP),
     {"run.auto_disable_s=0.05"}, {NULL}, 0},
    {LOGGING, "a row every 1 ms (default)", STATIC_LOAD("static_load to 1 s", NO_EARLY_STOP),
     {"run.log_interval_s=10"}, {NULL}, 0},
    {LOGGING, "a row every step", STATIC_LOAD("static_load to 1 s", NO_EARLY_STOP), {"run.log_interval_s=10"},
     {"run.log_interval_s=1e-4"}, 0},
    {"rendering off", "no frames", "--frames 320x240 at 60/s", STATIC_LOAD("static_load", NULL), {NULL}, {NULL}, 1},
};
enum { NSCENES = sizeof SCENES / sizeof SCENES[0], NSKIPS = sizeof SKIPS / sizeof SKIPS[0] };

/* ---- one run ------------------------------------------------------------------------------- */

static int count_set(const char *const *set)
{
    int n = 0;
    while (n < MAX_SET && set[n])
        n++;
    return n;
}

/* The scene's overrides followed by extra's. */
static int join_set(const scene *sc, const char *const *extra, const char **out)
{
    int n = count_set(sc->set), m = extra ? count_set(extra) : 0;
    memcpy(out, sc->set, (size_t)n * sizeof *out);
    if (m)
        memcpy(out + n, extra, (size_t)m * sizeof *out);
    return n + m;
}

static fs_status run_engine(const fs_scenario *sc, runner how, const fs_run_observer *obs, outcome *o, fs_error *err)
{
    if (how == BY_WALK) {
        fs_walk_result w;
        fs_status s = fs_walk_run(sc, obs, &w, err);
        *o = (outcome){lround(w.end_time_s / sc->def.step_s), w.end_time_s, 0,
                       {w.peak_force_N, w.rough_contacts_mean, w.peak_tilt_deg, w.steps_completed, w.falls}};
        return s;
    }
    fs_run_result r;
    fs_status s = fs_run(sc, obs, &r, err);
    if (s != FS_OK)
        return s;
    *o = (outcome){r.steps, r.end_time_s, 0, {r.ankle_end_m[0], r.ankle_end_m[1], r.ankle_end_m[2], r.energy_end_J, r.at_rest}};
    fs_run_free(&r);
    return FS_OK;
}

static fs_status run_trial(const fs_scenario *sc, const fs_run_observer *obs, outcome *o, fs_error *err)
{
    fs_trial_result t;
    fs_status s = fs_trial_run_scenario(sc, 1, obs, &t, err);
    if (s == FS_OK && t.outcome == FS_FAILED_NUMERICS)
        s = fs_fail(err, FS_NUMERICAL, "%s", t.failure);
    *o = (outcome){t.steps, t.end_time_s, 0, {t.ankle_drop_m, t.slip_m, t.peak_force_N, t.final_tilt_deg, t.outcome}};
    return s;
}

/* A failure of scene sc, named. */
static fs_status scene_failed(const scene *sc, fs_status s, fs_error *err)
{
    char what[FS_ERROR_MAX];
    snprintf(what, sizeof what, "%s", err->message);
    return fs_fail(err, s, "%s (bench speed, scene '%s')", what, sc->name);
}

/* A scene's scenario read with extra overrides, untimed, its files noted in prov (may be NULL).
 * The caller frees *out (fs_scenario_free, free) also after a failure. */
static fs_status load_scene(const scene *sc, const char *const *extra, fs_provenance *prov, fs_scenario **out,
                            fs_error *err)
{
    const char *set[2 * MAX_SET];
    int n = join_set(sc, extra, set);
    *out = calloc(1, sizeof **out);
    if (!*out)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    fs_status s = fs_scenario_load(cli_data_path(sc->path), set, n, *out, err);
    if (s == FS_OK && sc->how == BY_TRIAL)
        s = fs_scenario_require(*out, "trial", err);
    if (s == FS_OK && prov)
        s = fs_scenario_inputs(*out, prov, err);
    return s == FS_OK ? FS_OK : scene_failed(sc, s, err);
}

static void unload(fs_scenario *sc)
{
    if (sc)
        fs_scenario_free(sc);
    free(sc);
}

/* One timed run of a loaded scene (the trial of seed 1 for a trial scene). */
static fs_status run_once(const scene *sc, const fs_scenario *loaded, const fs_run_observer *obs, outcome *o,
                          fs_error *err)
{
    double t0 = fs_clock_s();
    fs_status s = sc->how == BY_TRIAL ? run_trial(loaded, obs, o, err) : run_engine(loaded, sc->how, obs, o, err);
    o->wall_s = fs_clock_s() - t0;
    return s == FS_OK ? FS_OK : scene_failed(sc, s, err);
}

static int by_wall(const void *a, const void *b)
{
    double x = ((const outcome *)a)->wall_s, y = ((const outcome *)b)->wall_s;
    return (x > y) - (x < y);
}

/* The run of median wall time (the lower middle one for an even count). */
static outcome median_run(outcome *runs, int n)
{
    qsort(runs, (size_t)n, sizeof *runs, by_wall);
    return runs[(n - 1) / 2];
}

/* ---- measuring ----------------------------------------------------------------------------- */

static int repeats(const scene *sc, int quick) { return quick ? 1 : sc->flags & SLOW ? 3 : 5; }

static int taken(const scene *sc, int quick) { return sc->flags & (quick ? QUICK : FULL); }

/* What one interval of the profile costs beyond the code it times: a clock read, s (the
 * median of 9 batches). */
static double clock_read_s(void)
{
    enum { N = 20000 };
    double batch[9];
    for (int b = 0; b < 9; b++) {
        double t0 = fs_clock_s();
        for (int i = 0; i < N; i++)
            fs_clock_s();
        batch[b] = (fs_clock_s() - t0) / (N + 1);
    }
    return fs_median_low(batch, 9);
}

/* The stages without the clock reads that timed them. */
static void take_clock_off(fs_profile *p, double read_s)
{
    for (int k = 0; k < FS_NSTAGES; k++)
        p->stage_s[k] = fmax(0, p->stage_s[k] - p->laps[k] * read_s);
}

/* The constraint rows of a run, seen after every step (fs_sim_constraint_rows). */
typedef struct row_count {
    int joints;                 /* rows of joints and springs (all but contacts) */
    double sum;                 /* of the total, over the steps seen */
    long seen;
    int max;
    long found, kept, touching; /* contacts found and kept, shapes touching, summed over the steps */
    int most_found;
} row_count;

static fs_status count_rows(void *user, const fs_sim *sim, fs_error *err)
{
    (void)err;
    row_count *c = user;
    fs_rows r;
    fs_sim_constraint_rows(sim, &r);
    c->joints = r.total - r.contact;
    c->sum += r.total;
    c->seen++;
    c->max = r.total > c->max ? r.total : c->max;
    int found, touching, most;
    fs_sim_contact_needs(sim, &found, &touching, &most);
    c->found += found;
    c->kept += fs_sim_contact_count(sim);
    c->touching += touching;
    c->most_found = most > c->most_found ? most : c->most_found;
    return FS_OK;
}

/* n profiled runs: each stage's median time (clock reads taken off), and the median wall time; the
 * first also counts the constraint rows after every step (outside the stages it times). */
static fs_status profile_scene(const scene *sc, const fs_scenario *loaded, int n, fs_profile *prof, double *wall_s,
                               double *read_s, row_count *rows, fs_error *err)
{
    *read_s = clock_read_s();
    double stage[FS_NSTAGES][MAX_RUNS], wall[MAX_RUNS];
    fs_status s = FS_OK;
    for (int i = 0; i < n && s == FS_OK; i++) {
        outcome o;
        fs_profile p = {0};
        fs_run_observer obs = {.profile = &p};
        if (i == 0)
            obs.fn = count_rows, obs.user = rows, obs.interval_s = 1e-12; /* every step */
        s = run_once(sc, loaded, &obs, &o, err);
        take_clock_off(&p, *read_s);
        for (int k = 0; k < FS_NSTAGES; k++)
            stage[k][i] = p.stage_s[k];
        wall[i] = o.wall_s;
        prof->steps = p.steps;
    }
    for (int k = 0; k < FS_NSTAGES; k++)
        prof->stage_s[k] = fs_median_low(stage[k], n);
    *wall_s = fs_median_low(wall, n);
    return s;
}

/* `runs` runs (their median), then `profiled` runs with a profile (fs_observer.h). */
static fs_status time_scene(const scene *sc, int runs, int profiled, fs_provenance *prov, timing *t, fs_error *err)
{
    outcome o[MAX_RUNS];
    fs_scenario *loaded;
    fs_status s = load_scene(sc, NULL, prov, &loaded, err);
    for (int i = 0; i < runs && s == FS_OK; i++)
        s = run_once(sc, loaded, NULL, &o[i], err);
    fs_profile prof;
    double wall_s = 0, read_s = 0;
    row_count rows = {0};
    if (s == FS_OK)
        s = profile_scene(sc, loaded, profiled, &prof, &wall_s, &read_s, &rows, err);
    unload(loaded);
    if (s == FS_OK)
        *t = (timing){sc, runs, median_run(o, runs), prof, wall_s, read_s, rows.joints,
                      rows.seen ? rows.sum / rows.seen : 0, rows.max,
                      rows.touching ? (double)rows.found / rows.touching : 0,
                      rows.touching ? (double)rows.kept / rows.touching : 0, rows.most_found};
    return s;
}

/* One run of a loaded scene with the renderer drawing frames (as --frames) into a temporary
 * folder, removed after. FS_BAD_INPUT when this footsim has no renderer. */
static fs_status frames_run(const scene *sc, const fs_scenario *loaded, outcome *o, fs_error *err)
{
    char tmp[] = "/tmp/footsim-bench-XXXXXX";
    if (!mkdtemp(tmp))
        return fs_fail(err, FS_IO, "%s: cannot make a temporary folder for the frames", tmp);
    cli_args a = {.command = "bench", .frames = 1, .size = "320x240"};
    cli_frames *frames = NULL;
    fs_run_observer obs;
    double t0 = fs_clock_s();
    fs_status s = FS_OK;
    if (cli_frames_open(&a, loaded, tmp, &frames, &obs) != 0)
        s = fs_fail(err, FS_BAD_INPUT, "no renderer");
    if (s == FS_OK)
        s = run_engine(loaded, sc->how, &obs, o, err);
    cli_frames_close(frames, 0, tmp);
    o->wall_s = fs_clock_s() - t0;
    fs_remove_tree(tmp);
    return s;
}

/* The two ways of a skip, each read once, then taking turns; same: the fingerprints agree bit for
 * bit. */
static fs_status time_skip(const skip *k, int runs, fs_provenance *prov, skip_timing *t, fs_error *err)
{
    outcome w[MAX_RUNS], wo[MAX_RUNS];
    *t = (skip_timing){k, runs, 1, 0, {0}, {0}};
    fs_scenario *with = NULL, *without = NULL;
    fs_status s = load_scene(&k->base, k->with_set, prov, &with, err);
    if (s == FS_OK)
        s = load_scene(&k->base, k->without_set, prov, &without, err);
    for (int i = 0; i < runs && s == FS_OK; i++) {
        s = run_once(&k->base, with, NULL, &w[i], err);
        if (s == FS_OK)
            s = k->frames ? frames_run(&k->base, without, &wo[i], err)
                          : run_once(&k->base, without, NULL, &wo[i], err);
        t->same = t->same && (s != FS_OK || !memcmp(w[i].print, wo[i].print, sizeof w[i].print));
    }
    unload(with);
    unload(without);
    if (s == FS_OK) {
        t->with = median_run(w, runs);
        t->without = median_run(wo, runs);
    }
    return s;
}

/* ---- reporting ----------------------------------------------------------------------------- */

/* Where and when: the machine, the UTC time, the 1-minute load average. */
typedef struct context {
    char machine[512], date[32], command[64];
    double load_start, load_end;
    const fs_provenance *prov; /* what made the results */
} context;

static double stage_total(const fs_profile *p)
{
    double total = 0;
    for (int i = 0; i < FS_NSTAGES; i++)
        total += p->stage_s[i];
    return total > 0 ? total : 1;
}

static double stage_pct(const fs_profile *p, fs_stage s) { return 100 * p->stage_s[s] / stage_total(p); }

/* A scene's figures as the tables give them. */
typedef struct figures {
    double steps_per_s, rtf, us_per_step;
    double collision_pct, ode_pct, own_pct; /* own: everything but collision and ODE's step */
} figures;

static figures figures_of(const timing *t)
{
    const outcome *m = &t->median;
    double col = stage_pct(&t->prof, FS_STAGE_COLLISION), ode = stage_pct(&t->prof, FS_STAGE_ODE);
    return (figures){m->steps / m->wall_s, m->sim_s / m->wall_s, 1e6 * m->wall_s / m->steps, col, ode, 100 - col - ode};
}

static const char *runner_name(runner r) { return r == BY_RUN ? "run" : r == BY_TRIAL ? "trial" : "walk"; }

static void speed_csv(FILE *f, const timing *t, int n)
{
    fprintf(f, "scene,runner,runs,steps,sim_s,step_s,wall_s,steps_per_s,rtf,us_per_step,profiled_wall_s,collision_pct,"
               "ode_pct,own_pct,own_loads_pct,own_springs_pct,own_contacts_pct,own_check_pct,own_caller_pct,clock_read_ns,"
               "joint_rows,mean_rows,max_rows,found_per_shape,kept_per_shape,most_found\n");
    for (int i = 0; i < n; i++) {
        const outcome *m = &t[i].median;
        figures g = figures_of(&t[i]);
        char q[256];
        fprintf(f, "%s,%s,%d,%ld,%.4f,%.3g,%.4f,%.0f,%.3f,%.2f,%.4f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%.1f,%d,%.1f,"
                   "%d,%.2f,%.2f,%d\n",
                cli_csv_text(q, sizeof q, t[i].sc->name), runner_name(t[i].sc->how), t[i].runs, m->steps, m->sim_s, m->sim_s / m->steps,
                m->wall_s, g.steps_per_s, g.rtf, g.us_per_step, t[i].prof_wall_s, g.collision_pct, g.ode_pct,
                g.own_pct, stage_pct(&t[i].prof, FS_STAGE_LOADS), stage_pct(&t[i].prof, FS_STAGE_SPRINGS),
                stage_pct(&t[i].prof, FS_STAGE_CONTACTS), stage_pct(&t[i].prof, FS_STAGE_CHECK),
                stage_pct(&t[i].prof, FS_STAGE_CALLER), 1e9 * t[i].clock_read_s, t[i].joint_rows, t[i].mean_rows,
                t[i].max_rows, t[i].found_per_shape, t[i].kept_per_shape, t[i].most_found);
    }
}

static double saving_pct(const skip_timing *t) { return 100 * (1 - t->with.wall_s / t->without.wall_s); }

static void skips_csv(FILE *f, const skip_timing *t, int n)
{
    fprintf(f, "skip,scene,with,without,runs,with_steps,without_steps,with_s,without_s,saving_pct,"
               "with_us_per_step,without_us_per_step,same_result\n");
    for (int i = 0; i < n; i++) {
        const skip_timing *s = &t[i];
        if (s->skipped)
            continue;
        char q[4][256]; /* a text with a comma ("ODE's, with the vertices inside added") quoted */
        fprintf(f, "%s,%s,%s,%s,%d,%ld,%ld,%.4f,%.4f,%.1f,%.2f,%.2f,%s\n", cli_csv_text(q[0], sizeof q[0], s->k->name),
                cli_csv_text(q[1], sizeof q[1], s->k->base.name), cli_csv_text(q[2], sizeof q[2], s->k->with),
                cli_csv_text(q[3], sizeof q[3], s->k->without), s->runs, s->with.steps, s->without.steps, s->with.wall_s, s->without.wall_s,
                saving_pct(s), 1e6 * s->with.wall_s / s->with.steps, 1e6 * s->without.wall_s / s->without.steps,
                s->same ? "yes" : "no");
    }
}

static void speed_md_table(FILE *f, const timing *t, int n)
{
    fprintf(f, "| scene | steps | wall s | steps/s | real-time factor | µs/step | collision | ODE step | own code | "
               "rows: joints, mean, max |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (int i = 0; i < n; i++) {
        figures g = figures_of(&t[i]);
        fprintf(f, "| %s | %ld | %.3f | %.0f | %.3f | %.1f | %.1f %% | %.1f %% | %.1f %% | %d, %.0f, %d |\n",
                t[i].sc->name, t[i].median.steps, t[i].median.wall_s, g.steps_per_s, g.rtf, g.us_per_step,
                g.collision_pct, g.ode_pct, g.own_pct, t[i].joint_rows, t[i].mean_rows, t[i].max_rows);
    }
}

static void skips_md_table(FILE *f, const skip_timing *t, int n)
{
    fprintf(f, "| skip | scene | with (cheap) | without | with s | without s | saving | same result |\n"
               "|---|---|---|---|--:|--:|--:|---|\n");
    for (int i = 0; i < n; i++) {
        const skip_timing *s = &t[i];
        if (s->skipped)
            fprintf(f, "| %s | %s | %s | %s | | | | left out: this footsim has no renderer |\n", s->k->name,
                    s->k->base.name, s->k->with, s->k->without);
        else
            fprintf(f, "| %s | %s | %s | %s | %.3f | %.3f | %.1f %% | %s |\n", s->k->name, s->k->base.name,
                    s->k->with, s->k->without, s->with.wall_s, s->without.wall_s, saving_pct(s),
                    s->same ? "bit-identical" : "differs");
    }
}

/* The largest own-code share, %, and its scene. */
static int worst_own(const timing *t, int n, double *own_max)
{
    int worst = 0;
    *own_max = -1;
    for (int i = 0; i < n; i++) {
        double own = figures_of(&t[i]).own_pct;
        if (own > *own_max)
            *own_max = own, worst = i;
    }
    return worst;
}

static void speed_md(FILE *f, const context *c, const timing *t, int n, const skip_timing *k, int nk)
{
    double own;
    int w = worst_own(t, n, &own);
    fprintf(f, "# footsim bench speed\n\n`%s`, %s UTC.\n\nMachine: %s. One core, one run at a time; "
               "1-minute load average %.2f at the start, %.2f at the end.\n\n",
            c->command, c->date, c->machine, c->load_start, c->load_end);
    fprintf(f, "Each time is the median wall time of repeated runs (speed.csv says how many) of building, stepping "
               "and measuring (each scene's files read once, before it is timed); the shares of the step loop come from further runs with a profile (fs_observer.h) (each stage's median, less the cost of the clock reads that timed it, calibrated per scene: speed.csv's clock_read_ns; profiled_wall_s is their median wall time). Rows: the constraint rows ODE's step solves (fs_sim_constraint_rows): those of the joints and implicit springs, and all rows with the contacts', mean and most over the first profiled run's steps.\n\n");
    speed_md_table(f, t, n);
    fprintf(f, "\nfootsim's own code takes at most %.1f %% of a step (%s): %s the 10 %% bound.\n\n", own,
            t[w].sc->name, own < 10 ? "under" : "OVER");
    fprintf(f, "What each skip saves (with: the cheap way; the two ways took turns run by run):\n\n");
    skips_md_table(f, k, nk);
    fputs("\nProvenance: ", f);
    fs_provenance_print(c->prov, f);
    fputs(".\n", f);
}

static void speed_gp(FILE *f)
{
    fprintf(f, "# footsim bench speed: steps per second and where a step's time goes; out is set by footsim\n"
               "set terminal pngcairo size 1100,700 font ',10'\nset output out\n"
               "set datafile separator ','\nset multiplot layout 2,1\n"
               "set style data histograms\nset style fill solid 0.8 border -1\nset boxwidth 0.75\n"
               "set xtics rotate by -30 left noenhanced\nset grid ytics\nset key noenhanced\n"
               "set title 'steps per second on one core (median)'\nset logscale y\nset ylabel 'steps/s'\n"
               "plot 'speed.csv' using 8:xtic(1) skip 1 title 'steps/s' lc rgb '#4477aa'\n"
               "unset logscale y\nset title 'share of a step'\nset ylabel '%%'\nset yrange [0:100]\n"
               "set style histogram rowstacked\nset key outside right\n"
               "plot 'speed.csv' using 12:xtic(1) skip 1 title 'collision' lc rgb '#ddaa33', "
               "'' using 13 skip 1 title 'ODE step' lc rgb '#4477aa', "
               "'' using 14 skip 1 title 'footsim own code' lc rgb '#bb5566'\n"
               "unset multiplot\n");
}

/* Everything the files need, for write_file's fill functions. */
typedef struct report {
    const context *c;
    const timing *t;
    int n;
    const skip_timing *k;
    int nk;
} report;

static int fill_speed_csv(FILE *f, const void *d) { const report *r = d; speed_csv(f, r->t, r->n); return 1; }
static int fill_skips_csv(FILE *f, const void *d) { const report *r = d; skips_csv(f, r->k, r->nk); return 1; }
static int fill_speed_md(FILE *f, const void *d) { const report *r = d; speed_md(f, r->c, r->t, r->n, r->k, r->nk); return 1; }
static int fill_speed_gp(FILE *f, const void *d) { (void)d; speed_gp(f); return 1; }

static fs_status write_report(const char *dir, const report *r, fs_error *err)
{
    /* the CSV files hold their header and rows only; where, when and what made them beside each */
    const context *c = r->c;
    fs_status s = fs_write_in(dir, "speed.csv", fill_speed_csv, r, err);
    if (s == FS_OK)
        s = (fs_status)cli_csv_beside(dir, "speed.csv", c->prov, c->command, c->date, c->machine, c->load_start,
                                      c->load_end, err);
    if (s == FS_OK)
        s = fs_write_in(dir, "skips.csv", fill_skips_csv, r, err);
    if (s == FS_OK)
        s = (fs_status)cli_csv_beside(dir, "skips.csv", c->prov, c->command, c->date, c->machine, c->load_start,
                                      c->load_end, err);
    if (s == FS_OK)
        s = fs_write_in(dir, "speed.gp", fill_speed_gp, r, err);
    if (s == FS_OK)
        cli_gnuplot(dir, "speed.gp", "speed.png", "bench speed");
    if (s == FS_OK)
        s = fs_write_in(dir, "speed.md", fill_speed_md, r, err);
    return s;
}

/* ---- the command --------------------------------------------------------------------------- */

static void start_context(context *c, int quick)
{
    cli_machine(c->machine, sizeof c->machine);
    time_t now = time(NULL);
    strftime(c->date, sizeof c->date, "%Y-%m-%d %H:%M", gmtime(&now));
    snprintf(c->command, sizeof c->command, "footsim bench speed%s", quick ? " --quick" : "");
    c->load_start = cli_load_average();
}

/* What the measuring shares: the record of the files read, and the progress over every scene and
 * skip this run takes. */
typedef struct measuring {
    int quick;
    fs_provenance *prov;
    cli_progress progress;
    int done, total;
} measuring;

/* How many scenes and skips a run takes. */
static int measurements(int quick)
{
    int n = 0;
    for (int i = 0; i < NSCENES; i++)
        n += taken(&SCENES[i], quick) != 0;
    for (int i = 0; i < NSKIPS; i++)
        n += taken(&SKIPS[i].base, quick) != 0;
    return n;
}

/* The scenes this run takes, timed into t; *n: how many. */
static fs_status time_scenes(measuring *m, timing *t, int *n, fs_error *err)
{
    fs_status s = FS_OK;
    *n = 0;
    for (int i = 0; i < NSCENES && s == FS_OK; i++) {
        const scene *sc = &SCENES[i];
        if (!taken(sc, m->quick))
            continue;
        s = time_scene(sc, repeats(sc, m->quick), m->quick || sc->flags & SLOW ? 1 : 3, m->prov, &t[*n], err);
        if (s == FS_OK)
            cli_progress_say(&m->progress, "bench speed: %s: %.0f steps/s", sc->name,
                             t[*n].median.steps / t[*n].median.wall_s);
        ++*n;
        cli_progress_update(&m->progress, ++m->done, m->total, 0);
    }
    return s;
}

/* The skips this run takes, timed into t; *n: how many. */
static fs_status time_skips(measuring *m, skip_timing *t, int *n, fs_error *err)
{
    fs_status s = FS_OK;
    *n = 0;
    for (int i = 0; i < NSKIPS && s == FS_OK; i++) {
        const skip *k = &SKIPS[i];
        if (!taken(&k->base, m->quick))
            continue;
        s = time_skip(k, repeats(&k->base, m->quick), m->prov, &t[*n], err);
        if (s == FS_BAD_INPUT && k->frames) {
            t[*n].skipped = 1; /* no renderer in this build: said on stderr */
            s = FS_OK;
            cli_progress_say(&m->progress, "bench speed: %s on %s: left out (no renderer)", k->name, k->base.name);
        } else if (s == FS_OK) {
            cli_progress_say(&m->progress, "bench speed: %s on %s: saves %.1f %%", k->name, k->base.name,
                             saving_pct(&t[*n]));
        }
        ++*n;
        cli_progress_update(&m->progress, ++m->done, m->total, 0);
    }
    return s;
}

int cli_bench_speed(const cli_args *a, const char *dir)
{
    timing t[NSCENES];
    skip_timing k[NSKIPS];
    memset(t, 0, sizeof t);
    memset(k, 0, sizeof k);
    int n = 0, nk = 0;
    context c;
    start_context(&c, a->quick);
    fs_error err;
    outcome warm;
    fs_provenance prov = {.ninputs = 0};
    fs_scenario *first = NULL;
    fs_status s = fs_make_dirs(dir, &err); /* a folder it cannot write is refused before measuring */
    if (s == FS_OK)
        s = cli_bench_provenance(&prov, NULL, 0, "each row's scene as its files and the overrides in its name give "
                                 "it (step_s column); trials from seed 1's pose", &err);
    prov.first_seed = 1, prov.nseeds = 1;
    if (s == FS_OK)
        s = load_scene(&SCENES[0], NULL, NULL, &first, &err);
    if (s == FS_OK)
        s = run_once(&SCENES[0], first, NULL, &warm, &err); /* untimed: caches and pages */
    unload(first);
    measuring m = {a->quick, &prov, {0}, 0, measurements(a->quick)};
    cli_progress_start(&m.progress, "footsim bench speed", "measurements");
    cli_progress_update(&m.progress, 0, m.total, 0);
    if (s == FS_OK)
        s = time_scenes(&m, t, &n, &err);
    if (s == FS_OK)
        s = time_skips(&m, k, &nk, &err);
    c.load_end = cli_load_average();
    c.prov = &prov;
    report r = {&c, t, n, k, nk};
    if (s == FS_OK)
        s = write_report(dir, &r, &err);
    fs_provenance_free(&prov);
    if (s != FS_OK)
        return cli_report(s, err.message);
    printf("bench speed: %s/speed.md, speed.csv, skips.csv, speed.png\n", dir);
    return 0;
}
