/* Tests of the per-sim profile (fs_sim_options.profile, through fs_run_observer) and of what a run may skip (the speed benchmark's switches): the stages
 * account for every profiled step, and neither profiling, nor trajectory logging off, nor testing
 * foot-foot pairs changes a result. No timings are compared: only counts of timed intervals. */
#include "fs_test.h"

#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/experiment/fs_trial.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <string.h>

/* static_load with overrides, timed into prof when it is not NULL; the result's rows stay with the
 * caller (fs_run_free). */
static void run_static(const char **set, int n, fs_profile *prof, fs_run_result *r)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, n, &sc, &err) == FS_OK);
    REQUIRE(fs_run(&sc, prof ? &(fs_run_observer){.profile = prof} : NULL, r, &err) == FS_OK);
    fs_scenario_free(&sc);
}

/* The final state, bit for bit. */
static int same_end(const fs_run_result *a, const fs_run_result *b)
{
    return a->steps == b->steps && !memcmp(a->ankle_end_m, b->ankle_end_m, sizeof a->ankle_end_m) &&
           !memcmp(a->hinge_angle_rad, b->hinge_angle_rad, sizeof a->hinge_angle_rad) &&
           !memcmp(a->spring_force_N, b->spring_force_N, sizeof a->spring_force_N) &&
           !memcmp(&a->energy_end_J, &b->energy_end_J, sizeof a->energy_end_J);
}

/* The foot shapes of static_load's foot: collision is timed once per shape and step. */
static int static_load_shapes(void)
{
    static fs_scenario sc;
    fs_error err;
    fs_sim sim;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    int n = sim.nshapes;
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
    return n;
}

/* Every step passes through every stage the pipeline has, once (collision once per foot shape; the
 * caller's stage from the second step on, as it is the time between two steps), and each lap holds
 * a time that is not negative. Counts, not timings: these hold on any machine under any load. */
static void stages_account_for_every_step(void)
{
    fs_run_result r;
    fs_profile p = {0};
    run_static(NULL, 0, &p, &r);
    long steps = r.steps;
    CHECK(p.steps == steps);
    CHECK(p.laps[FS_STAGE_LOADS] == steps && p.laps[FS_STAGE_SPRINGS] == steps && p.laps[FS_STAGE_ODE] == steps &&
          p.laps[FS_STAGE_CHECK] == steps);
    CHECK(p.laps[FS_STAGE_CALLER] == steps - 1);
    CHECK(p.laps[FS_STAGE_COLLISION] == steps * static_load_shapes());
    for (int i = 0; i < FS_NSTAGES; i++)
        CHECK(p.stage_s[i] >= 0 && (p.laps[i] == 0) == (p.stage_s[i] == 0));
    fs_run_free(&r);
    /* a run without a profile adds nothing to one that another run filled */
    fs_profile before = p;
    run_static(NULL, 0, NULL, &r);
    CHECK(!memcmp(&before, &p, sizeof p));
    fs_run_free(&r);
}

static void profiling_changes_no_result(void)
{
    fs_run_result off, on;
    fs_profile p = {0};
    run_static(NULL, 0, NULL, &off);
    run_static(NULL, 0, &p, &on);
    CHECK(same_end(&off, &on));
    CHECK(off.nrows == on.nrows && !memcmp(off.rows, on.rows, (size_t)off.nrows * off.ncols * sizeof *off.rows));
    fs_run_free(&off);
    fs_run_free(&on);
}

static void logging_off_keeps_the_final_state(void)
{
    const char *off[] = {"run.log_interval_s=10"}, *every[] = {"run.log_interval_s=1e-4"};
    fs_run_result a, b, c;
    run_static(NULL, 0, NULL, &a);
    run_static(off, 1, NULL, &b);
    run_static(every, 1, NULL, &c);
    CHECK(same_end(&a, &b) && same_end(&a, &c));
    CHECK(b.nrows == 2 && c.nrows == a.steps + 1);
    fs_run_free(&a);
    fs_run_free(&b);
    fs_run_free(&c);
}

/* The foot's shapes never touch each other: testing their pairs too finds nothing. */
static void foot_pairs_change_no_result(void)
{
    const char *all[] = {"run.collide=all"};
    fs_run_result a, b;
    run_static(NULL, 0, NULL, &a);
    run_static(all, 1, NULL, &b);
    CHECK(same_end(&a, &b));
    fs_run_free(&a);
    fs_run_free(&b);
    const char *trial[] = {"scenario.terrain=../terrains/complex_uneven.ini", "run.collide=all"};
    fs_trial_result ta, tb;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", trial, 1, 1, NULL, &ta, &err) == FS_OK);
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", trial, 2, 1, NULL, &tb, &err) == FS_OK);
    CHECK(ta.steps == tb.steps && !memcmp(&ta.ankle_drop_m, &tb.ankle_drop_m, sizeof ta.ankle_drop_m) &&
          !memcmp(&ta.peak_force_N, &tb.peak_force_N, sizeof ta.peak_force_N));
}

/* ODE's auto-disable freezes the foot once at rest: it ends where the run stopped at rest ends. */
static void auto_disable_freezes_the_foot_at_rest(void)
{
    const char *frozen[] = {"run.rest_hold_s=100", "run.auto_disable_s=0.05"};
    fs_run_result a, b;
    run_static(NULL, 0, NULL, &a);
    run_static(frozen, 2, NULL, &b);
    CHECK(a.at_rest && !b.at_rest && b.end_time_s > 0.99);
    CHECK_NEAR(b.ankle_drop_m, a.ankle_drop_m, 1e-6);
    fs_run_free(&a);
    fs_run_free(&b);
}

FS_TEST_MAIN(TEST(stages_account_for_every_step), TEST(profiling_changes_no_result),
             TEST(logging_off_keeps_the_final_state), TEST(foot_pairs_change_no_result),
             TEST(auto_disable_freezes_the_foot_at_rest))
