/* Tests of experiment_walk.c: the walking machine steps as its trajectory says. */
#include "fs_test.h"

#include "footsim/experiment/fs_walk.h"

#include <math.h>
#include <stdio.h>

/* Every step is judged once, as completed or a fall; on flat ground the flat foot completes all,
 * and the ground carries the body's weight at least (26 kg: 255 N) at some moment. */
static void machine_takes_its_steps(void)
{
    const char *set[] = {"walk.steps=3", "scenario.terrain=../terrains/flat.ini", "foot.kind=flat"};
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking.ini", set, 3, &sc, &err) == FS_OK);
    fs_walk_result r;
    REQUIRE(fs_walk_run(&sc, NULL, &r, &err) == FS_OK);
    CHECK(r.steps_completed + r.falls == 3);
    CHECK(r.steps_completed == 3);
    CHECK(r.rough_steps == 0);
    CHECK(r.peak_force_N > sc.def.robot.mass_kg * sc.def.gravity_m_per_s2);
    CHECK_NEAR(r.end_time_s, 3 * sc.def.walk_period_s, sc.def.step_s);
    /* at mid-stance the sole lies flat on flat ground: ODE's box-plane contact, its four corners */
    CHECK(r.flat_contacts_mean == 4);
    /* and the ankle body stays level but for the contacts' compression: even the peak force on one
     * end of the sole, against the sole's and the ground's stiffness in series, tilts it at most
     * atan(F / k / length) */
    double k = 1 / (1 / sc.design.sole_stiffness_N_per_m + 1 / sc.terrain.def.stiffness_N_per_m);
    double bound_deg = atan(r.peak_force_N / k / sc.geom.box_size.x) * 180 / M_PI;
    CHECK(r.peak_tilt_deg >= 0 && r.peak_tilt_deg < bound_deg);
    fs_scenario_free(&sc);
}

/* The biomimetic foot at mid-stance on flat ground stands on its two heel spheres and five toe
 * tips, the metatarsal heads clear of the ground (the design's neutral pose; test_model_design
 * finds the same seven standing still). */
static void biomimetic_foot_stands_on_heel_and_toes(void)
{
    const char *set[] = {"walk.steps=2", "scenario.terrain=../terrains/flat.ini"};
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking.ini", set, 2, &sc, &err) == FS_OK);
    fs_walk_result r;
    REQUIRE(fs_walk_run(&sc, NULL, &r, &err) == FS_OK);
    CHECK(r.steps_completed == 2 && r.falls == 0);
    CHECK(r.flat_contacts_mean == 2 + FS_CHAINS);
    fs_scenario_free(&sc);
}

/* Over a soil (fs_walk.h) the machine presses until the ground carries the load: on LETE sand (2 mm
 * grid) the biomimetic foot under 26 kg sinks some 19 mm and the soil carries it, so each stance
 * ends with the foot in the layer, above the bedrock, and the ground's force at least the robot's
 * and foot's weight W less what the press's last step of the suspension leaves open (the carriage
 * stops going down once the force reaches W; it may dip after, by the suspension's force over one
 * step of the drive, k v h, and the body's sway: a tenth of W is allowed). The soil takes energy in
 * every step; on rigid ground no step is recorded. */
static void machine_presses_until_the_soil_carries_it(void)
{
    const char *set[] = {"walk.steps=2", "scenario.terrain=../terrains/soils/lete_sand.ini", "soil.grid_m=0.002"};
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking.ini", set, 3, &sc, &err) == FS_OK);
    static fs_walk_result r;
    REQUIRE(fs_walk_run(&sc, NULL, &r, &err) == FS_OK);
    double mass = sc.def.robot.mass_kg;
    for (int i = 0; i < sc.geom.nbodies; i++)
        mass += sc.geom.body[i].mass_kg;
    double W = mass * sc.def.gravity_m_per_s2;
    CHECK(r.soil == 1 && r.nsteps == 2 && r.steps_completed == 2);
    for (int i = 0; i < r.nsteps; i++) {
        const fs_walk_step *w = &r.step[i];
        printf("  step %d: sinkage %.2f mm, force %.0f N (W %.0f N), pressed %.2f mm more, the soil took %.3f J, slip on "
               "the soil under the foot %.2f mm\n", i + 1, w->sinkage_m * 1e3, w->load_N, W, w->extra_press_m * 1e3,
               w->soil_work_J, w->soil_slip_m * 1e3);
        CHECK(w->sinkage_m > 0 && w->sinkage_m < sc.terrain.def.soil.depth_m);
        CHECK(w->load_N >= 0.9 * W);
        CHECK(w->extra_press_m > 0);
        CHECK(w->soil_work_J > 0);
        /* the slider holds the ankle in x and y, but the toes and links flex and turn as they load: the
           soil under them is sheared, so the slip its nodes keep is there (and finite) */
        CHECK(w->soil_slip_m > 0 && isfinite(w->soil_slip_m));
    }
    fs_scenario_free(&sc);
    const char *rigid[] = {"walk.steps=1", "scenario.terrain=../terrains/flat.ini"};
    REQUIRE(fs_scenario_load("scenarios/walking.ini", rigid, 2, &sc, &err) == FS_OK);
    REQUIRE(fs_walk_run(&sc, NULL, &r, &err) == FS_OK);
    CHECK(r.soil == 0 && r.nsteps == 0);
    fs_scenario_free(&sc);
}

/* A scenario that is not a walk is refused. */
static void only_walk_scenarios_walk(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_walk_result r;
    CHECK(fs_walk_run(&sc, NULL, &r, &err) == FS_BAD_INPUT);
    fs_scenario_free(&sc);
}

/* The carriage's work goes into the energy balance of the state checks (fs_check.h): over a step,
 * whose swing lifts the 26 kg body 2 cm (5 J) and lowers it again, the balance closes to 0.05 J
 * (the check's margin set that tight), with either spring implementation of the suspension (the
 * explicit one below its 4e-5 s limit). */
static void carriage_work_closes_the_energy_balance(void)
{
    for (int explicit_springs = 0; explicit_springs < 2; explicit_springs++) {
        const char *set[] = {"walk.steps=1", "check.energy_margin_J=0.05", "check.energy_margin_rel=0",
                             explicit_springs ? "run.springs=explicit" : "run.springs=implicit",
                             explicit_springs ? "run.step_s=2e-5" : "run.step_s=1e-4"};
        static fs_scenario sc;
        fs_error err = {FS_OK, ""};
        REQUIRE(fs_scenario_load("scenarios/walking.ini", set, 5, &sc, &err) == FS_OK);
        fs_walk_result r;
        REQUIRE(fs_walk_run(&sc, NULL, &r, &err) == FS_OK);
        if (err.status != FS_OK)
            fprintf(stderr, "  %s\n", err.message);
        fs_scenario_free(&sc);
    }
}

FS_TEST_MAIN(TEST(machine_takes_its_steps), TEST(machine_presses_until_the_soil_carries_it), TEST(biomimetic_foot_stands_on_heel_and_toes), TEST(only_walk_scenarios_walk), TEST(carriage_work_closes_the_energy_balance))
