/* walk_tolerance.c: the walking machine under an error-controlled step (run.tolerance_m) against the
 * fixed default step and a fine fixed reference (docs/bench.md, "The walking machine and the soil
 * under a tolerance"; issue 30). `build/walk-tolerance RUNS SCENE [tolerance ...]`, from the source
 * folder. SCENE: `rigid` (scenarios/walking.ini as it is: the biomimetic foot, 8 steps over
 * partly rough ground), `flat` (2 steps on flat ground, as test_engine_walk walks) or `soil` (2 steps
 * on terrains/soils/lete_sand.ini on a 2 mm grid, the press of fs_walk.h). A tolerance written with a leading 'e' (e1e-6) uses the embedded estimate.
 *
 * Each configuration (the reference at 1e-5 s, the fixed default 1e-4 s, then the tolerances) walks
 * once with an observer that keeps the robot's centre at the first observation at or past each
 * stance's end (the carriage has stood still through the stance), and the steps taken, rejected and
 * ODE steps; then, for the wall time, every configuration but the reference walks RUNS times more,
 * taking turns run by run so that other load hits all alike (median). Markdown on stdout: the walk's
 * own result (steps, falls, contacts at mid-stance, peak force and tilt; on the soil each step's
 * record) and the robot's largest distance from the reference's at the stances' ends. */
#include "cli.h"

#include "footsim/base/fs_clock.h"
#include "footsim/base/fs_stats.h"
#include "footsim/experiment/fs_walk.h"
#include "footsim/sim/fs_ode.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_RUNS = 15, MAX_CONF = 12, MAX_ENDS = 16 };
static const double REF_STEP_S = 1e-5;

typedef struct conf {
    double step_s, tolerance_m;
    int estimate;
    fs_walk_result r;
    long steps, rejected, ode_steps;
    int nends;
    double ends[MAX_ENDS][3];
    double wall[MAX_RUNS], wall_s, dist_m;
} conf;

typedef struct seen {
    const fs_scenario_def *d;
    conf *c;
} seen;

static fs_status observe(void *user, const fs_sim *sim, fs_error *err)
{
    (void)err;
    seen *s = user;
    conf *c = s->c;
    double t = fs_sim_time(sim), end = (c->nends + s->d->stance_fraction) * s->d->walk_period_s, v[3];
    if (c->nends < MAX_ENDS && t >= end - 1e-9)
        fs_sim_robot_com(sim, c->ends[c->nends++], v);
    const fs_step_stats *st = fs_sim_step_stats(sim);
    c->steps = st->taken, c->rejected = st->rejected, c->ode_steps = st->ode_steps;
    return FS_OK;
}

static int fail(fs_status s, const fs_error *err)
{
    fprintf(stderr, "walk-tolerance: %s\n", err->message);
    return s == FS_BAD_INPUT ? 2 : 3;
}

static void settings(fs_scenario *sc, const conf *c)
{
    sc->def.step_s = c->step_s;
    sc->def.tolerance_m = c->tolerance_m;
    sc->def.error_estimate = c->estimate;
}

static void name(const conf *c, char *buf, size_t n)
{
    if (c->tolerance_m > 0)
        snprintf(buf, n, "%s %g m", c->estimate ? "embedded" : "doubling", c->tolerance_m);
    else
        snprintf(buf, n, "fixed %g s%s", c->step_s, c->step_s == REF_STEP_S ? " (reference)" : "");
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 1;
    const char *scene = argc > 2 ? argv[2] : "rigid";
    int soil = !strcmp(scene, "soil"), flat = !strcmp(scene, "flat");
    if (runs < 1 || runs > MAX_RUNS || (!soil && !flat && strcmp(scene, "rigid"))) {
        fprintf(stderr, "usage: walk-tolerance RUNS (1 to %d) rigid|flat|soil [tolerance ...]\n", MAX_RUNS);
        return 2;
    }
    static conf c[MAX_CONF];
    int n = 0;
    c[n++] = (conf){.step_s = REF_STEP_S};
    c[n++] = (conf){.step_s = 1e-4};
    for (int k = 3; k < argc && n < MAX_CONF; k++) {
        int e = argv[k][0] == 'e';
        c[n++] = (conf){.step_s = 1e-4, .tolerance_m = atof(argv[k] + e), .estimate = e};
    }
    fs_ode_init();
    char machine[512];
    cli_machine(machine, sizeof machine);
    printf("`build/walk-tolerance %d %s`: %s, load %.2f at the start\n", runs, scene, machine, cli_load_average());
    const char *set_soil[] = {"walk.steps=2", "scenario.terrain=../terrains/soils/lete_sand.ini", "soil.grid_m=0.002"};
    const char *set_flat[] = {"walk.steps=2", "scenario.terrain=../terrains/flat.ini"};
    static fs_scenario base, sc;
    fs_error err;
    fs_status s = fs_scenario_load("scenarios/walking.ini", soil ? set_soil : flat ? set_flat : NULL, soil ? 3 : flat ? 2 : 0,
                                   &base, &err);
    if (s != FS_OK)
        return fail(s, &err);
    for (int i = 0; i < n; i++) {
        sc = base;
        settings(&sc, &c[i]);
        seen w = {&sc.def, &c[i]};
        fs_run_observer obs = {.interval_s = 1e-3, .fn = observe, .user = &w};
        fprintf(stderr, "walk-tolerance: configuration %d/%d ...\n", i + 1, n);
        double start = fs_clock_s();
        if ((s = fs_walk_run(&sc, &obs, &c[i].r, &err)) != FS_OK)
            return fail(s, &err);
        c[i].wall[0] = fs_clock_s() - start;
    }
    for (int r = 1; r < runs; r++)
        for (int i = 1; i < n; i++) {
            fprintf(stderr, "\rwalk-tolerance: run %d/%d, configuration %d/%d   ", r + 1, runs, i + 1, n);
            sc = base;
            settings(&sc, &c[i]);
            static fs_walk_result again;
            double start = fs_clock_s();
            if ((s = fs_walk_run(&sc, NULL, &again, &err)) != FS_OK)
                return fail(s, &err);
            c[i].wall[r] = fs_clock_s() - start;
        }
    fprintf(stderr, "\n");
    for (int i = 0; i < n; i++) {
        int m = i ? runs : 1;
        qsort(c[i].wall, (size_t)m, sizeof c[i].wall[0], fs_compare_doubles);
        c[i].wall_s = c[i].wall[m / 2];
        for (int k = 0; k < c[i].nends && k < c[0].nends; k++) {
            double d = 0;
            for (int a = 0; a < 3; a++)
                d += (c[i].ends[k][a] - c[0].ends[k][a]) * (c[i].ends[k][a] - c[0].ends[k][a]);
            c[i].dist_m = fmax(c[i].dist_m, sqrt(d));
        }
    }
    printf("\n%s, %d steps of %g s. Robot: its centre's largest distance from the reference's at the stances' "
           "ends. Wall: the median of %d walks taking turns (the reference once); ratio: the fixed default's wall "
           "time over this one's.\n\n| step | steps (rejected), ODE steps | completed, falls | contacts at "
           "mid-stance, rough / flat | peak force (N) | peak tilt (deg) | robot (mm) | wall (s) | real-time "
           "factor | ratio to 1e-4 s |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
           soil   ? "The biomimetic foot on LETE sand (2 mm grid)"
           : flat ? "The biomimetic foot on flat ground"
                  : "scenarios/walking.ini (biomimetic foot, partly rough)",
           base.def.walk_steps, base.def.walk_period_s, runs);
    for (int i = 0; i < n; i++) {
        const fs_walk_result *r = &c[i].r;
        char what[64];
        name(&c[i], what, sizeof what);
        printf("| %s | %ld (%ld), %ld | %d, %d | %.2f / %.2f | %.0f | %.3f | %.4f | %.2f | %.2f | %.2f |\n", what,
               c[i].steps, c[i].rejected, c[i].ode_steps, r->steps_completed, r->falls, r->rough_contacts_mean,
               r->flat_contacts_mean, r->peak_force_N, r->peak_tilt_deg, c[i].dist_m * 1e3, c[i].wall_s,
               r->end_time_s / c[i].wall_s, c[1].wall_s / c[i].wall_s);
    }
    if (soil) {
        printf("\nEach step's record (fs_walk_step): sinkage, ankle slip, the soil's slip under the foot (mm), the "
               "soil's work (J), the press past press_m (mm), the load at the stance's end (N).\n\n| step | gait "
               "step | sinkage | slip | soil slip | soil work | press | load |\n|---|--:|--:|--:|--:|--:|--:|--:|\n");
        for (int i = 0; i < n; i++)
            for (int k = 0; k < c[i].r.nsteps; k++) {
                const fs_walk_step *w = &c[i].r.step[k];
                char what[64];
                name(&c[i], what, sizeof what);
                printf("| %s | %d | %.3f | %.3f | %.3f | %.4f | %.3f | %.1f |\n", what, k + 1, w->sinkage_m * 1e3,
                       w->slip_m * 1e3, w->soil_slip_m * 1e3, w->soil_work_J, w->extra_press_m * 1e3, w->load_N);
            }
    }
    printf("\nload %.2f at the end\n", cli_load_average());
    fs_scenario_free(&base);
    return 0;
}
