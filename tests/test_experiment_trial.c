/* Tests of a landing trial's start (experiment_trial.c): the pose drawn from the seed and the
 * scenario's [landing] ranges, on ranges set in code. */
#include "fs_test.h"

#include "footsim/experiment/fs_trial.h"

enum { NSEEDS = 2000 };

static fs_scenario sc;

static void load(void)
{
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_scenario_def *d = &sc.def;
    d->start_x_m = 0.01, d->start_y_m = -0.02, d->yaw_deg = 30, d->pitch_deg = 1, d->roll_deg = -2;
    d->land_x_range_m = 0.005, d->land_y_range_m = 0.003, d->land_yaw_range_deg = 10, d->land_tilt_range_deg = 0.5;
}

/* Every drawn value lies within its range about the start, and the draws fill the range (over 2000
 * seeds a uniform draw comes within 1 % of each end, or the range would be half used). */
static void draws_lie_within_and_fill_their_ranges(void)
{
    load();
    const fs_scenario_def *d = &sc.def;
    double lo[5] = {1, 1, 1, 1, 1}, hi[5] = {-1, -1, -1, -1, -1};
    for (int seed = 1; seed <= NSEEDS; seed++) {
        fs_trial_draw w;
        fs_trial_draw_pose(&sc, seed, &w);
        double u[5] = {(w.x_m - d->start_x_m) / d->land_x_range_m, (w.y_m - d->start_y_m) / d->land_y_range_m,
                       (w.yaw_deg - d->yaw_deg) / d->land_yaw_range_deg,
                       (w.pitch_deg - d->pitch_deg) / d->land_tilt_range_deg,
                       (w.roll_deg - d->roll_deg) / d->land_tilt_range_deg};
        CHECK(w.seed == seed);
        for (int k = 0; k < 5; k++) {
            CHECK(u[k] >= -1 && u[k] <= 1);
            lo[k] = u[k] < lo[k] ? u[k] : lo[k];
            hi[k] = u[k] > hi[k] ? u[k] : hi[k];
        }
    }
    for (int k = 0; k < 5; k++)
        CHECK(lo[k] < -0.98 && hi[k] > 0.98);
    fs_scenario_free(&sc);
}

/* The same seed draws the same pose whatever was drawn before; neighbouring seeds differ; pitch and
 * roll are drawn apart (not one value twice). */
static void a_seed_draws_the_same_pose_in_any_order(void)
{
    load();
    fs_trial_draw first[50], again[50];
    for (int i = 0; i < 50; i++)
        fs_trial_draw_pose(&sc, i + 1, &first[i]);
    for (int i = 49; i >= 0; i--) /* backwards, with other draws in between */
        fs_trial_draw_pose(&sc, 1000 + i, &again[i]), fs_trial_draw_pose(&sc, i + 1, &again[i]);
    for (int i = 0; i < 50; i++) {
        CHECK(!memcmp(&first[i], &again[i], sizeof first[i]));
        if (i > 0)
            CHECK(first[i].x_m != first[i - 1].x_m && first[i].yaw_deg != first[i - 1].yaw_deg);
        CHECK(first[i].pitch_deg - sc.def.pitch_deg != first[i].roll_deg - sc.def.roll_deg);
    }
    fs_scenario_free(&sc);
}

/* Zero ranges draw exactly the scenario's start; fs_trial_place puts the pose and the seed into the
 * definitions. */
static void zero_ranges_draw_the_start_and_place_sets_it(void)
{
    load();
    fs_scenario_def *d = &sc.def;
    d->land_x_range_m = d->land_y_range_m = d->land_yaw_range_deg = d->land_tilt_range_deg = 0;
    fs_trial_draw w;
    fs_trial_draw_pose(&sc, 77, &w);
    CHECK(w.x_m == d->start_x_m && w.y_m == d->start_y_m && w.yaw_deg == d->yaw_deg && w.pitch_deg == d->pitch_deg &&
          w.roll_deg == d->roll_deg);
    d->land_x_range_m = 0.005;
    fs_error err;
    REQUIRE(fs_trial_place(&sc, 12, &w, &err) == FS_OK);
    CHECK(d->start_x_m == w.x_m && sc.terrain.def.seed == 12 && w.seed == 12);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(draws_lie_within_and_fill_their_ranges), TEST(a_seed_draws_the_same_pose_in_any_order),
             TEST(zero_ranges_draw_the_start_and_place_sets_it))
