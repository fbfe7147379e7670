/* Tests of model_design.c and sim_build.c: the geometry closes each chain's loop on the
 * ground, and the built foot rests on heel and toe tips. */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <string.h>

static const fs_sphere_geom *sphere_named(const fs_foot_geom *g, const char *name)
{
    for (int i = 0; i < g->nspheres; i++)
        if (!strcmp(g->sphere[i].name, name))
            return &g->sphere[i];
    return NULL;
}

/* In the neutral pose every heel and toe sphere touches z = 0 exactly; the balls stay clear. */
static void neutral_pose_closes_every_loop(void)
{
    static fs_scenario sc;
    fs_error err;
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    const fs_foot_geom *g = &sc.geom;
    CHECK(g->nbodies == 12 && g->nhinges == 11 && g->nsprings == 15);
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        double gap = s->centre.z - s->radius_m;
        if (!strncmp(s->name, "ball", 4))
            CHECK(gap > 0);
        else
            CHECK_NEAR(gap, 0, 1e-15);
    }
    /* the links have the design's lengths (scaled for the big toe) */
    for (int i = 0; i < FS_CHAINS; i++) {
        double s = sc.design.scale[i];
        CHECK_NEAR(fs_norm(fs_sub(g->chain[i].mtp, g->chain[i].midfoot)), s * sc.design.l3_m, 1e-15);
        CHECK_NEAR(fs_norm(fs_sub(g->chain[i].toe, g->chain[i].mtp)), s * sc.design.l4_m, 1e-15);
    }
}

/* Under its own weight alone, the built foot rests with heel and every toe tip on the ground:
 * each within its share of the weight over the contact stiffness (microns) of z = 0. */
static void built_foot_rests_on_heel_and_toes(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"load.mass_kg=0"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 1, &sc, &err) == FS_OK);
    fs_sim sim;
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    for (int i = 0; i < 5000; i++)
        CHECK(fs_sim_step(&sim, &err) == FS_OK);
    const fs_foot_geom *g = &sc.geom;
    double k = 1.0 / (1.0 / sc.design.sole_stiffness_N_per_m + 1.0 / sc.terrain.def.stiffness_N_per_m);
    double tol = g->total_mass_kg * sc.def.gravity_m_per_s2 / k + 1e-9;
    const char *touching[] = {"heel_medial", "heel_lateral", "toe1", "toe2", "toe3", "toe4", "toe5"};
    for (int i = 0; i < 7; i++) {
        const fs_sphere_geom *s = sphere_named(g, touching[i]);
        CHECK(s != NULL);
        const dReal *p = dGeomGetPosition(sim.shape[s - g->sphere]);
        CHECK_NEAR(p[2] - s->radius_m, 0, tol);
    }
    CHECK(sim.contacts_now == 7);
    fs_sim_destroy(&sim);
}

/* The flat foot has the biomimetic foot's mass, footprint and ankle. */
static void flat_foot_matches_the_biomimetic_one(void)
{
    static fs_scenario bio, flat;
    fs_error err;
    const char *set[] = {"foot.kind=flat"};
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &bio, &err) == FS_OK);
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", set, 1, &flat, &err) == FS_OK);
    CHECK(flat.geom.nbodies == 1 && flat.geom.nboxes == 1);
    CHECK_NEAR(flat.geom.total_mass_kg, bio.geom.total_mass_kg, 1e-15);
    CHECK_NEAR(flat.geom.ankle.z, bio.geom.ankle.z, 1e-15);
    CHECK_NEAR(flat.geom.box[0].centre.z - 0.5 * flat.geom.box_size.z, 0, 1e-15);
    const fs_sphere_geom *heel = sphere_named(&bio.geom, "heel_medial");
    CHECK_NEAR(flat.geom.box[0].centre.x - 0.5 * flat.geom.box_size.x, heel->centre.x - heel->radius_m, 1e-15);
}

/* The shipped flat.ini stays comparable with the shipped biomimetic.ini. */
static void shipped_feet_match(void)
{
    static fs_scenario bio, flat;
    fs_error err;
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &bio, &err) == FS_OK);
    CHECK(fs_scenario_for_design("scenarios/feet/flat.ini", NULL, 0, &flat, &err) == FS_OK);
    CHECK(flat.geom.kind == FS_FOOT_FLAT);
    CHECK_NEAR(flat.geom.total_mass_kg, bio.geom.total_mass_kg, 1e-15);
    CHECK_NEAR(fs_norm(fs_sub(flat.geom.ankle, bio.geom.ankle)), 0, 1e-15);
}

/* A build that fails half way (a pinned chain asked of the flat foot, refused after the contact
 * buffers are made) leaves nothing behind: the sim is empty, and under the sanitizer build the leak
 * check at exit finds nothing of it. Destroying the empty sim again is harmless. */
static void failed_build_leaves_nothing(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"foot.kind=flat"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 1, &sc, &err) == FS_OK);
    fs_sim sim;
    fs_sim_options opts = {.pinned_chain = 1};
    CHECK(fs_sim_build(&sim, &sc, &opts, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, "", 0, "biomimetic");
    CHECK(sim.world == NULL && sim.feedback == NULL && sim.scratch == NULL && sim.space == NULL);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* Definitions edited in code and compiled (fs_scenario_compile, as a landing trial does with its
 * drawn pose and seed) give the scenario that loading the file with the same edits as --set gives,
 * bit for bit: the definitions, the drawn rocks and the terrain samples cut to the new pose. */
static void typed_edits_compile_like_set(void)
{
    const char *terrains[] = {"scenario.terrain=../terrains/rough.ini", "scenario.terrain=../terrains/complex_uneven.ini"};
    for (int k = 0; k < 2; k++) {
        const char *set[] = {terrains[k], "start.x_m=0.0123", "start.y_m=-0.004", "start.yaw_deg=7",
                             "start.pitch_deg=-0.5", "rough.seed=5"};
        static fs_scenario by_set, typed;
        fs_error err;
        REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 6, &by_set, &err) == FS_OK);
        REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &typed, &err) == FS_OK);
        typed.def.start_x_m = 0.0123;
        typed.def.start_y_m = -0.004;
        typed.def.yaw_deg = 7;
        typed.def.pitch_deg = -0.5;
        typed.terrain.def.seed = 5;
        REQUIRE(fs_scenario_compile(&typed, &err) == FS_OK);
        CHECK(!memcmp(&typed.def, &by_set.def, sizeof typed.def));
        CHECK(!memcmp(&typed.terrain.def, &by_set.terrain.def, sizeof typed.terrain.def));
        CHECK(!memcmp(typed.terrain.rock, by_set.terrain.rock, sizeof typed.terrain.rock));
        CHECK(typed.terrain.nx == by_set.terrain.nx && typed.terrain.ny == by_set.terrain.ny &&
              typed.terrain.i0 == by_set.terrain.i0 && typed.terrain.j0 == by_set.terrain.j0);
        CHECK(typed.terrain.z && by_set.terrain.z &&
              !memcmp(typed.terrain.z, by_set.terrain.z, (size_t)typed.terrain.nx * typed.terrain.ny * sizeof(double)));
        fs_scenario_free(&by_set);
        fs_scenario_free(&typed);
    }
    /* an edit out of the schema's range is refused by the compile, as the same value in a file is */
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    sc.design.k_N_per_m[1] = -5;
    CHECK(fs_scenario_compile(&sc, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, "", 0, "k_d2_N_per_m = -5 is out of range");
    sc.design.k_N_per_m[1] = 12000;
    sc.def.step_s = 0;
    CHECK(fs_scenario_compile(&sc, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, "", 0, "step_s = 0 is out of range");
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(shipped_feet_match), TEST(neutral_pose_closes_every_loop), TEST(built_foot_rests_on_heel_and_toes),
             TEST(flat_foot_matches_the_biomimetic_one), TEST(failed_build_leaves_nothing),
             TEST(typed_edits_compile_like_set))
