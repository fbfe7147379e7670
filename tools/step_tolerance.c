/* step_tolerance.c: the error-controlled step (run.tolerance_m) against the fixed default step and
 * the converged reference (docs/bench.md, "An error-controlled step"; issue 30).
 * `build/step-tolerance [runs] [tolerance ...]`, from the source folder.
 *
 * For each robot, drop_weight and single_tall, the biomimetic foot's landing trial
 * (scenarios/landing_trial.ini) on flat ground, seed 1's pose: the ankle's largest distance from
 * footsim's own run at 1e-5 s over the first 0.5 s (fs_track_run and fs_track_compare, as bench
 * precision's landing_biomimetic scene measures it), with the steps taken, rejected and ODE steps in
 * all; and the trial as `footsim trial --seed 1` runs it (fs_trial_run_scenario: until the judge
 * decides), its outcome, settle time, impulse and wall time, the median of `runs` runs (default 3),
 * every configuration taking turns run by run so that other load hits all alike, and its real-time
 * factor as a ratio to the fixed default step's from the same runs. A tolerance written with a
 * leading 'e' (e3e-6) uses the embedded estimate (run.error_estimate = embedded), else step doubling.
 * Then where each configuration's steps went over the 0.5 s: in flight (before the touchdown), the
 * impact (its first 20 ms), settling (to 0.25 s) and the rest. Markdown on stdout. */
#include "cli.h"

#include "footsim/base/fs_stats.h"
#include "footsim/experiment/fs_outcome.h"
#include "footsim/experiment/fs_track.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/sim/fs_ode.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_RUNS = 15, MAX_CONF = 16 };
static const double REF_STEP_S = 1e-5, DURATION_S = 0.5;
static const char *const ROBOTS[] = {"robots/drop_weight.ini", "robots/single_tall.ini"};

typedef struct conf {
    double tolerance_m;          /* 0: the fixed step (REF_STEP_S for the reference row, else 1e-4) */
    double step_s;
    int estimate;                /* fs_error_estimate */
    long phase_steps[4], phase_rejected[4], phase_ode[4]; /* flight, impact, settling, rest */
    fs_track_error e;
    long steps, rejected, ode_steps;
    fs_trial_result trial;
    double wall[MAX_RUNS], wall_s;
} conf;

static int fail(fs_status s, const fs_error *err)
{
    fprintf(stderr, "step-tolerance: %s\n", err->message);
    return s == FS_BAD_INPUT ? 2 : 3;
}

static void settings(fs_scenario *sc, const conf *c)
{
    sc->def.step_s = c->step_s;
    sc->def.tolerance_m = c->tolerance_m;
    sc->def.error_estimate = c->estimate;
}

enum { PHASES = 4 };
static const char *const PHASE[PHASES] = {"flight", "impact (20 ms)", "settling (to 0.25 s)", "rest (to 0.5 s)"};

/* Steps the scene's sim over DURATION_S, counting the accepted steps, rejections and ODE steps of
 * each phase (a step counted where it ends). */
static fs_status phases(const fs_scenario *sc, conf *c, fs_error *err)
{
    fs_sim *sim = NULL;
    fs_status s = fs_sim_new(sc, NULL, &sim, err);
    double touchdown = -1;
    const fs_step_stats *st = s == FS_OK ? fs_sim_step_stats(sim) : NULL;
    while (s == FS_OK && fs_sim_time(sim) < DURATION_S - 1e-9) {
        long taken = st->taken, rejected = st->rejected, ode = st->ode_steps;
        if ((s = fs_sim_step(sim, err)) != FS_OK)
            break;
        double t = fs_sim_time(sim);
        if (touchdown < 0 && fs_sim_contact_count(sim) > 0)
            touchdown = t;
        int p = touchdown < 0 ? 0 : t < touchdown + 0.02 ? 1 : t < 0.25 ? 2 : 3;
        c->phase_steps[p] += st->taken - taken;
        c->phase_rejected[p] += st->rejected - rejected;
        c->phase_ode[p] += st->ode_steps - ode;
    }
    fs_sim_free(sim);
    return s;
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 3;
    if (runs < 1 || runs > MAX_RUNS) {
        fprintf(stderr, "step-tolerance: runs '%s' is out of range; give 1 to %d\n", argv[1], MAX_RUNS);
        return 2;
    }
    double tols[MAX_CONF] = {1e-4, 3e-5, 1e-5, 3e-6, 1e-6};
    int ntols = 5, embedded[MAX_CONF] = {0};
    if (argc > 2)
        for (ntols = 0; ntols + 2 < argc && ntols < MAX_CONF - 2; ntols++) {
            const char *a = argv[ntols + 2];
            embedded[ntols] = a[0] == 'e';
            tols[ntols] = atof(a + embedded[ntols]);
        }
    fs_ode_init();
    char machine[512];
    cli_machine(machine, sizeof machine);
    printf("`build/step-tolerance %d`: %s, load %.2f at the start\n", runs, machine, cli_load_average());
    for (int rb = 0; rb < 2; rb++) {
        fs_error err;
        static fs_scenario trial, scene, sc;
        fs_status s = cli_flat_landing(ROBOTS[rb], &trial, &scene, &err);
        if (s != FS_OK)
            return fail(s, &err);
        static conf c[MAX_CONF];
        int n = 0;
        c[n++] = (conf){.step_s = trial.def.step_s};
        for (int k = 0; k < ntols; k++)
            c[n++] = (conf){.step_s = trial.def.step_s, .tolerance_m = tols[k], .estimate = embedded[k]};
        fs_sim_options opts = {.with_ground = 1, .record_drift = 1};
        fs_track ref;
        sc = scene;
        settings(&sc, &(conf){.step_s = REF_STEP_S});
        fprintf(stderr, "step-tolerance: %s: the reference at %g s ...\n", ROBOTS[rb], REF_STEP_S);
        if ((s = fs_track_run(&sc, &opts, DURATION_S, &ref, &err)) != FS_OK)
            return fail(s, &err);
        for (int i = 0; i < n; i++) {
            fs_track t;
            sc = scene;
            settings(&sc, &c[i]);
            if ((s = fs_track_run(&sc, &opts, DURATION_S, &t, &err)) != FS_OK ||
                (s = fs_track_compare(&t, &ref, &c[i].e, &err)) != FS_OK)
                return fail(s, &err);
            c[i].steps = t.steps, c[i].rejected = t.rejected, c[i].ode_steps = t.ode_steps;
            fs_track_free(&t);
            if ((s = phases(&sc, &c[i], &err)) != FS_OK)
                return fail(s, &err);
        }
        for (int r = 0; r < runs; r++)
            for (int i = 0; i < n; i++) {
                fprintf(stderr, "\rstep-tolerance: %s: run %d/%d, configuration %d/%d   ", ROBOTS[rb], r + 1, runs, i + 1, n);
                sc = trial;
                settings(&sc, &c[i]);
                double start = fs_clock_s();
                if ((s = fs_trial_run_scenario(&sc, 1, NULL, &c[i].trial, &err)) != FS_OK)
                    return fail(s, &err);
                c[i].wall[r] = fs_clock_s() - start;
            }
        fprintf(stderr, "\n");
        for (int i = 0; i < n; i++) {
            qsort(c[i].wall, (size_t)runs, sizeof c[i].wall[0], fs_compare_doubles);
            c[i].wall_s = c[i].wall[runs / 2];
        }
        printf("\n%s, seed 1, flat ground. Error: the ankle's largest distance from the run at %g s over %g s. "
               "Trial: until the judge decides, median of %d runs.\n\n"
               "| step | error (mm) | steps (rejected) | ODE steps | trial outcome | settle (s) | impulse (N s) | "
               "trial steps (rejected) | median step (s) | real-time factor | ratio to 1e-4 s |\n"
               "|---|--:|--:|--:|---|--:|--:|--:|--:|--:|--:|\n", ROBOTS[rb], REF_STEP_S, DURATION_S, runs);
        for (int i = 0; i < n; i++) {
            const fs_trial_result *t = &c[i].trial;
            double rtf = t->end_time_s / c[i].wall_s, rtf0 = c[0].trial.end_time_s / c[0].wall_s;
            char what[64];
            if (c[i].tolerance_m > 0)
                snprintf(what, sizeof what, "%s %g m", c[i].estimate ? "embedded" : "tolerance", c[i].tolerance_m);
            else
                snprintf(what, sizeof what, "fixed %g s", c[i].step_s);
            printf("| %s | %.4f | %ld (%ld) | %ld | %s (%s) | %.4f | %.3f | %ld (%ld) | %.2e | %.1f | %.2f |\n", what,
                   c[i].e.max_m * 1e3, c[i].steps, c[i].rejected, c[i].ode_steps, fs_outcome_name(t->outcome),
                   fs_rule_name(t->rule), t->settle_time_s, t->impact_impulse_Ns, t->steps, t->rejected_steps,
                   t->step_median_s, rtf, rtf / rtf0);
        }
        printf("\nWhere the steps went over %g s: accepted steps (rejected), ODE steps.\n\n| step |", DURATION_S);
        for (int p = 0; p < PHASES; p++)
            printf(" %s |", PHASE[p]);
        printf("\n|---|");
        for (int p = 0; p < PHASES; p++)
            printf("--:|");
        printf("\n");
        for (int i = 0; i < n; i++) {
            if (c[i].tolerance_m > 0)
                printf("| %s %g m |", c[i].estimate ? "embedded" : "tolerance", c[i].tolerance_m);
            else
                printf("| fixed %g s |", c[i].step_s);
            for (int p = 0; p < PHASES; p++)
                printf(" %ld (%ld), %ld |", c[i].phase_steps[p], c[i].phase_rejected[p], c[i].phase_ode[p]);
            printf("\n");
        }
        fs_track_free(&ref);
    }
    printf("\nload %.2f at the end\n", cli_load_average());
    return 0;
}
