/* The constraint rows of each kind of scene (fs_sim_constraint_rows): a speed guard that cannot
 * flake. A dense direct step's cost grows with the rows, so a change that adds rows to a scene
 * shows here as a count, never as a timing. Every expected count is derived from the design and
 * the robot (5 rows a hinge or slider, 6 a fixed joint, 1 an implicit spring, 3 a contact with
 * friction; a rigid, free robot merged into the ankle body adds none), not copied from a run. */
#include "fs_test.h"

#include "footsim/sim/fs_drive.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <math.h>

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
    /* the rigid, free robot is merged into the ankle body: no fixed joint, 6 rows fewer */
    CHECK(r.hinge == 5 * g->nhinges && r.spring == g->nsprings && r.fixed == 0 && r.contact == 0);
    CHECK(r.total == 5 * g->nhinges + g->nsprings);
    CHECK(r.total == 5 * 11 + 15); /* the count, 11 hinges and 15 springs, less the fixed joint's 6 */
    fs_scenario_free(&sc);
    /* standing: 3 rows a contact point, at most max_contacts a shape */
    rows_of(NULL, 0, 600, &r, &sc); /* 60 ms: touched down at 32 ms */
    CHECK(r.contacts > 0 && r.contact == 3 * r.contacts);
    CHECK(r.contact <= 3 * sc.def.max_contacts * (g->nspheres + g->nboxes));
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
    rows_of(rig, 1, 0, &r, &sc); /* on its slide: a body of its own, fixed to the ankle */
    CHECK(r.slider == 5 && r.fixed == 6);
    fs_scenario_free(&sc);
    const char *explicit_springs[] = {"run.springs=explicit"};
    rows_of(explicit_springs, 1, 0, &r, &sc);
    CHECK(r.spring == 0); /* forces, not rows */
    fs_scenario_free(&sc);
    const char *flat[] = {"scenario.design=feet/flat.ini"};
    rows_of(flat, 1, 0, &r, &sc);
    CHECK(r.total == 0); /* one body: the plate with the robot merged into it */
    fs_scenario_free(&sc);
    /* frictionless contacts: one row each */
    const char *slick[] = {"material.mu=0"};
    rows_of(slick, 1, 600, &r, &sc);
    CHECK(r.contacts > 0 && r.contact == r.contacts && r.total == 5 * 11 + 15 + r.contacts);
    fs_scenario_free(&sc);
}

/* A merged robot is the same rigid assembly: the bodies' masses sum to the foot's and the robot's,
 * and its centre of mass and lean, measured from the ankle body's pose, are where the fixed robot's
 * were: at the start, R0 (ankle offset) from the ankle, leaning as R0 turns z. Rounding: 1e-12. */
static void merged_robot_keeps_its_mass_and_measures(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"robot.design=robots/drop_weight.ini"};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &sc, &err) == FS_OK);
    fs_sim sim;
    fs_sim_options opts = {.with_ground = 1};
    REQUIRE(fs_sim_build(&sim, &sc, &opts, &err) == FS_OK);
    CHECK(sim.robot_merged && sim.robot == NULL);
    double mass = 0, design = sc.def.robot.mass_kg;
    for (int i = 0; i < sc.geom.nbodies; i++) {
        dMass m;
        dBodyGetMass(sim.body[i], &m);
        mass += m.mass;
        design += sc.geom.body[i].mass_kg;
    }
    CHECK(fabs(mass - design) <= 1e-12 * design);
    double a[3], p[3], off[3] = {sc.def.robot.com_forward_m, 0, sc.def.robot.com_height_m};
    fs_sim_ankle(&sim, a);
    fs_sim_robot_com(&sim, p, NULL);
    for (int k = 0; k < 3; k++)
        CHECK(fabs(p[k] - (a[k] + sim.R0[3 * k] * off[0] + sim.R0[3 * k + 2] * off[2])) <= 1e-12);
    CHECK(fabs(fs_sim_robot_tilt(&sim) - acos(sim.R0[8])) <= 1e-12);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(biomimetic_foot_on_a_rigid_robot), TEST(each_robot_and_spring_kind_adds_its_rows),
             TEST(merged_robot_keeps_its_mass_and_measures))
