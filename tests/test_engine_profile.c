/* Tests of fs_sim_profile and of what a run may skip (the speed benchmark's switches): the stages
 * account for every profiled step, and neither profiling, nor trajectory logging off, nor testing
 * foot-foot pairs changes a result. No timings are compared: only that they add up. */
#include "fs_test.h"

#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/experiment/fs_trial.h"

#include <string.h>

/* static_load with overrides; the result's rows stay with the caller (fs_run_free). */
static void run_static(const char **set, int n, fs_run_result *r)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, n, &sc, &err) == FS_OK);
    REQUIRE(fs_run(&sc, NULL, r, &err) == FS_OK);
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

static double total_s(const fs_profile *p)
{
    double t = 0;
    for (int i = 0; i < FS_NSTAGES; i++)
        t += p->stage_s[i];
    return t;
}

static void stages_account_for_every_step(void)
{
    fs_run_result r;
    fs_sim_profile(1);
    run_static(NULL, 0, &r);
    fs_sim_profile(0);
    fs_profile p;
    fs_sim_profile_read(&p);
    CHECK(p.steps == r.steps);
    for (int i = 0; i < FS_NSTAGES; i++)
        CHECK(p.stage_s[i] >= 0);
    CHECK(p.stage_s[FS_STAGE_ODE] > 0 && p.stage_s[FS_STAGE_COLLISION] > 0);
    /* the shares (collision, ODE, own = the rest) add up to 1 */
    double t = total_s(&p), col = p.stage_s[FS_STAGE_COLLISION] / t, ode = p.stage_s[FS_STAGE_ODE] / t;
    double own = 0;
    for (int i = 0; i < FS_NSTAGES; i++)
        own += i == FS_STAGE_COLLISION || i == FS_STAGE_ODE ? 0 : p.stage_s[i] / t;
    CHECK_NEAR(col + ode + own, 1, 1e-12);
    fs_run_free(&r);
    /* off: a sim built afterwards adds nothing */
    run_static(NULL, 0, &r);
    fs_profile after;
    fs_sim_profile_read(&after);
    CHECK(after.steps == p.steps && total_s(&after) == t);
    fs_run_free(&r);
}

static void profiling_changes_no_result(void)
{
    fs_run_result off, on;
    run_static(NULL, 0, &off);
    fs_sim_profile(1);
    run_static(NULL, 0, &on);
    fs_sim_profile(0);
    CHECK(same_end(&off, &on));
    CHECK(off.nrows == on.nrows && !memcmp(off.rows, on.rows, (size_t)off.nrows * off.ncols * sizeof *off.rows));
    fs_run_free(&off);
    fs_run_free(&on);
}

static void logging_off_keeps_the_final_state(void)
{
    const char *off[] = {"run.log_interval_s=10"}, *every[] = {"run.log_interval_s=1e-4"};
    fs_run_result a, b, c;
    run_static(NULL, 0, &a);
    run_static(off, 1, &b);
    run_static(every, 1, &c);
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
    run_static(NULL, 0, &a);
    run_static(all, 1, &b);
    CHECK(same_end(&a, &b));
    fs_run_free(&a);
    fs_run_free(&b);
    const char *trial[] = {"scenario.terrain=../terrains/complex_uneven.ini", "run.collide=all"};
    fs_trial_result ta, tb;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", trial, 1, 1, &ta, &err) == FS_OK);
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", trial, 2, 1, &tb, &err) == FS_OK);
    CHECK(ta.steps == tb.steps && !memcmp(&ta.ankle_drop_m, &tb.ankle_drop_m, sizeof ta.ankle_drop_m) &&
          !memcmp(&ta.peak_force_N, &tb.peak_force_N, sizeof ta.peak_force_N));
}

/* ODE's auto-disable freezes the foot once at rest: it ends where the run stopped at rest ends. */
static void auto_disable_freezes_the_foot_at_rest(void)
{
    const char *frozen[] = {"run.rest_hold_s=100", "run.auto_disable_s=0.05"};
    fs_run_result a, b;
    run_static(NULL, 0, &a);
    run_static(frozen, 2, &b);
    CHECK(a.at_rest && !b.at_rest && b.end_time_s > 0.99);
    CHECK_NEAR(b.ankle_drop_m, a.ankle_drop_m, 1e-6);
    fs_run_free(&a);
    fs_run_free(&b);
}

FS_TEST_MAIN(TEST(stages_account_for_every_step), TEST(profiling_changes_no_result),
             TEST(logging_off_keeps_the_final_state), TEST(foot_pairs_change_no_result),
             TEST(auto_disable_freezes_the_foot_at_rest))
