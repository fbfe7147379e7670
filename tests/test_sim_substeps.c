/* [run] impact_substeps (fs_sim_step; docs/bench.md, "A step that shrinks at a touchdown"): off by
 * default and then said nowhere; a step taken in N substeps is N steps of h/N (contacts, springs,
 * the hinge stops' softness and the ground's force all at the substep); and the step is divided only
 * around a touchdown, from one it foresees to impact_window_s after it. */
#include "fs_test.h"

#include "footsim/experiment/fs_walk.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <math.h>
#include <string.h>

static void load(const char *const *set, int n, fs_scenario *sc)
{
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, n, sc, &err) == FS_OK);
}

/* The settings line that results carry says nothing of the key while it is off. */
static void off_is_said_nowhere(void)
{
    static fs_scenario a, b;
    const char *on[] = {"run.impact_substeps=4"};
    load(NULL, 0, &a);
    load(on, 1, &b);
    CHECK(a.def.impact_substeps == 1);
    char sa[256], sb[256];
    fs_scenario_settings(&a, sa, sizeof sa);
    fs_scenario_settings(&b, sb, sizeof sb);
    CHECK(!strstr(sa, "substeps"));
    CHECK(strstr(sb, "impact_substeps 4, impact_window_s 0.03") != NULL);
    fs_scenario_free(&a);
    fs_scenario_free(&b);
}

/* A landing at h = 1e-3 s in 4 substeps throughout (a window longer than the run) against the same
 * landing at h = 2.5e-4 s: the same steps, so the ankles agree at every coarse step to within what
 * the substeps' clock (t0 + i h/4 where the fine run adds h/4 each step: the load's ramp a few ulp
 * apart) can move them, far below the 0.1 mm the two step sizes differ by; and the mean ground force
 * over a coarse step is the mean of the fine run's over the same four. With the biped, whose leg
 * joints are hinge stops made soft for the step, so that their softness follows the substep too;
 * with a driver's torque on the ankle body each step (fs_sim_body_add_torque), which ODE clears after
 * each of its steps, so that it acts in every substep. */
static void substeps_are_steps_of_the_fraction(const char *robot, double torque_N_m)
{
    static fs_scenario coarse, fine;
    const char *c[] = {robot, "run.step_s=1e-3", "run.impact_substeps=4", "run.impact_window_s=10"};
    const char *f[] = {robot, "run.step_s=2.5e-4"};
    load(c, 4, &coarse);
    load(f, 2, &fine);
    fs_error err;
    fs_sim x, y;
    REQUIRE(fs_sim_build(&x, &coarse, NULL, &err) == FS_OK);
    REQUIRE(fs_sim_build(&y, &fine, NULL, &err) == FS_OK);
    double worst_m = 0, worst_N = 0, most_N = 0;
    int substepped = 0, touched = 0;
    const double torque[3] = {0, torque_N_m, 0};
    for (int k = 0; k < 150; k++) {
        if (torque_N_m != 0)
            fs_sim_body_add_torque(&x, x.geom->ankle_body, torque);
        REQUIRE(fs_sim_step(&x, &err) == FS_OK);
        substepped += x.substeps_now == 4;
        double mean[3] = {0, 0, 0};
        for (int i = 0; i < 4; i++) {
            if (torque_N_m != 0)
                fs_sim_body_add_torque(&y, y.geom->ankle_body, torque);
            REQUIRE(fs_sim_step(&y, &err) == FS_OK);
            double g[3];
            fs_sim_ground_force(&y, g);
            for (int d = 0; d < 3; d++)
                mean[d] += g[d] / 4;
        }
        double ax[3], ay[3], g[3];
        fs_sim_ankle(&x, ax);
        fs_sim_ankle(&y, ay);
        fs_sim_ground_force(&x, g);
        worst_m = fmax(worst_m, sqrt(pow(ax[0] - ay[0], 2) + pow(ax[1] - ay[1], 2) + pow(ax[2] - ay[2], 2)));
        worst_N = fmax(worst_N, fabs(g[2] - mean[2]));
        most_N = fmax(most_N, fabs(mean[2]));
        touched |= x.contacts_now > 0;
        CHECK(x.time_s == (k + 1) * 1e-3 || fabs(x.time_s - (k + 1) * 1e-3) < 1e-15);
    }
    CHECK(substepped == 150);
    CHECK(touched);
    CHECK(most_N > 100); /* the landing's force was there to compare */
    printf("  %s: ankles at most %.3g m apart, mean ground forces %.3g N of %.3g N\n", robot, worst_m, worst_N, most_N);
    CHECK(worst_m < 1e-7);
    CHECK(worst_N < 1e-3 * most_N);
    fs_sim_destroy(&x);
    fs_sim_destroy(&y);
    fs_scenario_free(&coarse);
    fs_scenario_free(&fine);
}

static void substeps_single_foot(void) { substeps_are_steps_of_the_fraction("robot.design=robots/drop_weight.ini", 0); }
static void substeps_biped(void) { substeps_are_steps_of_the_fraction("robot.design=robots/biped.ini", 0); }
/* 2 N m about the lateral axis: the 26 kg ankle body turns by degrees over the run, far more than
 * the bound, were it applied in the first substep only */
static void substeps_with_a_torque(void) { substeps_are_steps_of_the_fraction("robot.design=robots/drop_weight.ini", 2); }

/* The flat foot dropped 5 cm onto a plane (touchdown near 0.1 s) at h = 1e-3 s, 4 substeps, a
 * 10 ms window: the falling sole is foreseen within the step and window before it lands (the
 * prediction's horizon, h + window, at the fall's speed and under gravity), so the substeps start
 * at most that and a step early, and not from release; every step from there to the window's end
 * after the touchdown is in substeps; and once the sole is at rest (it bounces once, about 1 mm,
 * and lands again: substeps again) the steps are whole. */
static void divided_only_around_a_touchdown(void)
{
    static fs_scenario sc;
    const char *set[] = {"scenario.design=feet/flat.ini", "robot.design=robots/drop_weight.ini", "start.drop_m=0.05",
                         "run.step_s=1e-3", "run.impact_substeps=4", "run.impact_window_s=0.01"};
    load(set, 6, &sc);
    const double h = 1e-3, w = 0.01;
    fs_error err;
    fs_sim x;
    REQUIRE(fs_sim_build(&x, &sc, NULL, &err) == FS_OK);
    double first = -1, last = -1, touchdown = -1;
    int whole_in_window = 0;
    for (int k = 0; k < 300; k++) {
        double t = x.time_s;
        REQUIRE(fs_sim_step(&x, &err) == FS_OK);
        if (x.substeps_now > 1) {
            if (first < 0)
                first = t;
            last = t;
        }
        if (touchdown < 0 && x.contacts_now > 0)
            touchdown = t;
        whole_in_window += first >= 0 && x.substeps_now == 1 && touchdown >= 0 && t <= touchdown + w - h;
    }
    printf("  substeps from %.3f s to %.3f s; touchdown in the step from %.3f s\n", first, last, touchdown);
    REQUIRE(touchdown > 0.08 && first >= 0);
    CHECK(first <= touchdown - w);           /* foreseen, not seen late */
    CHECK(first >= touchdown - 2 * (h + w)); /* and not from release */
    CHECK(whole_in_window == 0);             /* none whole between */
    CHECK(last >= touchdown + w - h);
    CHECK(last < 0.25);                      /* whole again at rest */
    fs_sim_destroy(&x);
    fs_scenario_free(&sc);
}

/* The walking machine in substeps: its carriage's suspension is prepared at each substep and its
 * work counted over each, so the energy check, which fails a run whose energy grows beyond the work
 * put in, passes; every step's touchdown is in substeps. */
static void walking_machine_in_substeps(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"walk.steps=2", "run.step_s=1e-3", "run.impact_substeps=4"};
    REQUIRE(fs_scenario_load("scenarios/walking.ini", set, 3, &sc, &err) == FS_OK);
    fs_walk_result out;
    fs_status s = fs_walk_run(&sc, NULL, &out, &err);
    if (s != FS_OK)
        fprintf(stderr, "%s\n", err.message);
    CHECK(s == FS_OK);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(off_is_said_nowhere), TEST(substeps_single_foot), TEST(substeps_biped), TEST(substeps_with_a_torque),
             TEST(divided_only_around_a_touchdown), TEST(walking_machine_in_substeps))
