/* The constraint rows of each kind of scene (fs_sim_constraint_rows): a speed guard that cannot
 * flake. A dense direct step's cost grows with the rows, so a change that adds rows to a scene
 * shows here as a count, never as a timing. Every expected count is derived from the design and
 * the robot (5 rows a hinge or slider, 6 a fixed joint, 1 an implicit spring, 3 a contact with
 * friction), not copied from a run. */
#include "fs_test.h"

#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"

/* The rows of the landing trial's sim with overrides, at the start (no contact) and after steps. */
static void rows_of(const char *const *set, int n, long steps, fs_rows *rows, fs_scenario *sc)
{
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, n, sc, &err) == FS_OK);
    fs_sim sim;
    fs_sim_options opts = {.with_ground = 1};
    REQUIRE(fs_sim_build(&sim, sc, &opts, &err) == FS_OK);
    for (long i = 0; i < steps; i++)
        REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
    fs_sim_constraint_rows(&sim, rows);
    fs_sim_destroy(&sim);
}

static void biomimetic_foot_on_a_rigid_robot(void)
{
    static fs_scenario sc;
    fs_rows r;
    rows_of(NULL, 0, 0, &r, &sc);
    const fs_foot_geom *g = &sc.geom;
    CHECK(r.hinge == 5 * g->nhinges && r.spring == g->nsprings && r.fixed == 6 && r.contact == 0);
    CHECK(r.total == 5 * g->nhinges + g->nsprings + 6);
    CHECK(r.total == 5 * 11 + 15 + 6); /* the count: 11 hinges, 15 springs, the robot's fixed joint */
    fs_scenario_free(&sc);
    /* standing: 3 rows a contact point, at most max_contacts a shape */
    rows_of(NULL, 0, 600, &r, &sc); /* 60 ms: touched down at 32 ms */
    CHECK(r.contacts > 0 && r.contact == 3 * r.contacts);
    CHECK(r.contact <= 3 * sc.def.max_contacts * (g->nspheres + g->has_box));
    fs_scenario_free(&sc);
}

static void each_robot_and_spring_kind_adds_its_rows(void)
{
    static fs_scenario sc;
    fs_rows r;
    const char *achilles[] = {"robot.design=robots/single_tall_achilles.ini"};
    rows_of(achilles, 1, 0, &r, &sc);
    CHECK(r.fixed == 0 && r.hinge == 5 * (sc.geom.nhinges + 1) && r.spring == sc.geom.nsprings + 1);
    fs_scenario_free(&sc);
    const char *rig[] = {"robot.design=robots/rig.ini"};
    rows_of(rig, 1, 0, &r, &sc);
    CHECK(r.slider == 5 && r.fixed == 6);
    fs_scenario_free(&sc);
    const char *explicit_springs[] = {"run.springs=explicit"};
    rows_of(explicit_springs, 1, 0, &r, &sc);
    CHECK(r.spring == 0); /* forces, not rows */
    fs_scenario_free(&sc);
    const char *flat[] = {"scenario.design=feet/flat.ini"};
    rows_of(flat, 1, 0, &r, &sc);
    CHECK(r.total == 6);
    fs_scenario_free(&sc);
    /* frictionless contacts: one row each */
    const char *slick[] = {"material.mu=0"};
    rows_of(slick, 1, 600, &r, &sc);
    CHECK(r.contacts > 0 && r.contact == r.contacts && r.total == 5 * 11 + 15 + 6 + r.contacts);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(biomimetic_foot_on_a_rigid_robot), TEST(each_robot_and_spring_kind_adds_its_rows))
