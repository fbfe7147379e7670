/* quickstep_ratio.c: QuickStep against the heavy body's mass ratio (docs/bench.md, "QuickStep and
 * the mass ratio"; issue 12 §3). `build/quickstep-ratio [runs]`, from the source folder.
 *
 * The scene is bench precision's landing_biomimetic: the landing trial (scenarios/landing_trial.ini)
 * of the biomimetic foot under drop_weight on flat ground, seed 1's pose, 0.5 s from release, against
 * footsim's own run at 1e-5 s with dWorldStep (where the landing converges). Each configuration
 * (stepper and iterations, [run] min_inertia_kg_m2, step) is run `runs` times (default 5), the
 * configurations taking turns run by run so that other load hits all alike; it reports the median
 * wall time a step (steps only, not building: fs_track_run), its ratio to dWorldStep without a floor
 * at the same step from the same runs, the largest ankle error of the first run, the state checks'
 * class (drifting: a loop opened by more than 1 mm, or energy from nowhere; blown up), and the
 * landing trial's outcome for seeds 1-10 (fs_trial_run_scenario, as `footsim trial --seed N`), with
 * how many of them match dWorldStep's without a floor at the default step. Writes the table in
 * Markdown to stdout and progress to stderr. */
#include "cli.h"

#include "footsim/base/fs_stats.h"
#include "footsim/experiment/fs_outcome.h"
#include "footsim/experiment/fs_track.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/sim/fs_check.h"
#include "footsim/sim/fs_ode.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { MAX_RUNS = 15, NSEEDS = 10 };

static const double REF_STEP_S = 1e-5, DURATION_S = 0.5;
static const double STEPS[] = {1e-4, 1e-3};
static const int ITERATIONS[] = {0, 10, 20, 50, 100}; /* 0: dWorldStep */
static const double FLOORS[] = {0, 1e-6, 1e-5, 1e-4}; /* kg m^2; a phalanx's smallest moment is 8.5e-8 */
#define COUNT(a) ((int)(sizeof(a) / sizeof(a)[0]))
enum { NCONF = COUNT(STEPS) * COUNT(ITERATIONS) * COUNT(FLOORS) };

typedef struct conf {
    double step_s, floor;
    int iterations;
    int blown;                  /* the track run failed a check beyond drifting */
    int check_class, first_drift;
    double loop_m;              /* the widest a hinge opened, m */
    fs_track_error e;
    double wall[MAX_RUNS];
    double us;                  /* median wall time a step, us */
    double ratio;               /* median of the runs' ratios to dWorldStep without a floor at this step */
    int outcome[NSEEDS];
} conf;

static void settings(fs_scenario *sc, const conf *c)
{
    sc->def.step_s = c->step_s;
    sc->def.stepper = c->iterations ? FS_STEPPER_QUICKSTEP : FS_STEPPER_STEP;
    sc->def.iterations = c->iterations ? c->iterations : 20;
    sc->def.min_inertia_kg_m2 = c->floor;
    sc->def.log_interval_s = fmax(c->step_s, 1e-3);
}

static int fail(fs_status s, const fs_error *err)
{
    fprintf(stderr, "quickstep-ratio: %s\n", err->message);
    return s == FS_BAD_INPUT ? 2 : 3;
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 5;
    if (runs < 1 || runs > MAX_RUNS) {
        fprintf(stderr, "quickstep-ratio: runs '%s' is out of range; give 1 to %d\n", argv[1], MAX_RUNS);
        return 2;
    }
    fs_ode_init();
    fs_error err;
    static fs_scenario trial, scene, sc;
    fs_status s = cli_flat_landing("robots/drop_weight.ini", &trial, &scene, &err);
    if (s != FS_OK)
        return fail(s, &err);
    char machine[512];
    cli_machine(machine, sizeof machine);
    double load0 = cli_load_average();
    fprintf(stderr, "quickstep-ratio: the reference (h = %g s, dWorldStep) ...\n", REF_STEP_S);
    fs_track ref;
    conf rc = {.step_s = REF_STEP_S};
    sc = scene;
    settings(&sc, &rc);
    fs_sim_options opts = {.with_ground = 1, .record_drift = 1};
    if ((s = fs_track_run(&sc, &opts, DURATION_S, &ref, &err)) != FS_OK)
        return fail(s, &err);
    static conf c[NCONF];
    int n = 0;
    for (int h = 0; h < COUNT(STEPS); h++)
        for (int i = 0; i < COUNT(ITERATIONS); i++)
            for (int f = 0; f < COUNT(FLOORS); f++)
                c[n++] = (conf){.step_s = STEPS[h], .iterations = ITERATIONS[i], .floor = FLOORS[f]};
    /* the tracks: configurations take turns, run by run */
    for (int k = 0; k < runs; k++) {
        fprintf(stderr, "quickstep-ratio: tracks, run %d of %d\n", k + 1, runs);
        for (int j = 0; j < n; j++) {
            if (c[j].blown)
                continue;
            sc = scene;
            settings(&sc, &c[j]);
            fs_track t;
            s = fs_track_run(&sc, &opts, DURATION_S, &t, &err);
            if (s == FS_NUMERICAL) {
                c[j].blown = 1;
                c[j].check_class = FS_CHECK_BLOWN_UP;
                continue;
            }
            if (s != FS_OK)
                return fail(s, &err);
            c[j].wall[k] = t.wall_s / (t.n - 1) * 1e6;
            if (k == 0) {
                c[j].check_class = t.check_class;
                c[j].first_drift = t.first_drift;
                c[j].loop_m = t.max_loop_error_m;
                s = fs_track_compare(&t, &ref, &c[j].e, &err);
            }
            fs_track_free(&t);
            if (s != FS_OK)
                return fail(s, &err);
        }
    }
    for (int j = 0; j < n; j++) {
        if (c[j].blown)
            continue;
        const conf *base = &c[j - (j % (COUNT(ITERATIONS) * COUNT(FLOORS)))]; /* dWorldStep, no floor, this step */
        double w[MAX_RUNS], r[MAX_RUNS];
        for (int k = 0; k < runs; k++) {
            w[k] = c[j].wall[k];
            r[k] = c[j].wall[k] / base->wall[k];
        }
        qsort(w, (size_t)runs, sizeof w[0], fs_compare_doubles);
        qsort(r, (size_t)runs, sizeof r[0], fs_compare_doubles);
        c[j].us = w[runs / 2];
        c[j].ratio = r[runs / 2];
    }
    /* the outcomes of seeds 1-10, as `footsim trial --seed N` */
    for (int j = 0; j < n; j++) {
        fprintf(stderr, "quickstep-ratio: trials, configuration %d of %d\n", j + 1, n);
        sc = trial;
        settings(&sc, &c[j]);
        sc.def.log_interval_s = trial.def.log_interval_s;
        for (int seed = 1; seed <= NSEEDS; seed++) {
            fs_trial_result res;
            if ((s = fs_trial_run_scenario(&sc, seed, NULL, &res, &err)) != FS_OK)
                return fail(s, &err);
            c[j].outcome[seed - 1] = res.outcome;
        }
    }
    time_t now = time(NULL);
    char date[32];
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    printf("`build/quickstep-ratio %d` on %s; %s; load average %.2f at the start, %.2f at the end; reference: "
           "h = %g s, dWorldStep, %g s from release; landing_biomimetic (seed 1's pose, flat ground, drop_weight).\n\n",
           runs, date, machine, load0, cli_load_average(), REF_STEP_S, DURATION_S);
    printf("| step h (s) | stepper | min_inertia_kg_m2 | us/step | ratio to dWorldStep | max ankle error (mm) | "
           "widest loop gap (mm) | checks | outcomes seeds 1-10 | same as dWorldStep |\n|--:|---|--:|--:|--:|--:|--:|---|---|--:|\n");
    for (int j = 0; j < n; j++) {
        char who[32], out[NSEEDS * 4 + 1] = "";
        int same = 0;
        if (c[j].iterations)
            snprintf(who, sizeof who, "quickstep %d", c[j].iterations);
        else
            snprintf(who, sizeof who, "dWorldStep");
        for (int k = 0; k < NSEEDS; k++) {
            static const char letter[] = "lfnuh"; /* fs_outcome's order: landed, fell, failed_numerics, ... */
            int o = c[j].outcome[k];
            size_t len = strlen(out);
            snprintf(out + len, sizeof out - len, "%s%c", k ? " " : "", o >= 0 && o < 5 ? letter[o] : '?');
            same += c[j].outcome[k] == c[0].outcome[k];
        }
        if (c[j].blown)
            printf("| %g | %s | %g | | | | | blown up | %s | %d/%d |\n", c[j].step_s, who, c[j].floor, out, same,
                   NSEEDS);
        else
            printf("| %g | %s | %g | %.1f | %.2f | %.3g | %.3g | %s%s%s%s | %s | %d/%d |\n", c[j].step_s, who, c[j].floor,
                   c[j].us, c[j].ratio, c[j].e.max_m * 1e3, c[j].loop_m * 1e3, fs_check_class_name(c[j].check_class),
                   c[j].first_drift ? " (" : "", c[j].first_drift ? fs_check_kind_name(c[j].first_drift) : "",
                   c[j].first_drift ? ")" : "", out, same, NSEEDS);
    }
    printf("\nOutcomes: l landed, f fell, n failed numerically (a state check stopped the trial), u undecided, "
           "h hung; 'same' counts the seeds whose outcome is dWorldStep's without a floor at h = 1e-4 s.\n");
    fs_track_free(&ref);
    fs_scenario_free(&trial);
    fs_scenario_free(&scene);
    return 0;
}
