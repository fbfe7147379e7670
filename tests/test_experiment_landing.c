/* A landing's outcome does not hang on a numerical knob (issue 11): on flat ground the same seeds
 * with ODE's contact surface layer at 0.5 mm (shipped) and 1e-9 m (stiff), each at the default step
 * (1e-4 s) and at a tenth of it (1e-5 s, where the landing's reference converges: docs/model.md), are
 * judged alike, for a foot and robot that land and for one that falls.
 *
 * The exception, left out here and stated in docs/landing.md: the flat foot under drop_weight. Its
 * load stands over the ankle, 9.5 mm ahead of the footprint's back edge, so a toe-first touchdown
 * tips it backward to the edge of falling over the heel, and whether it does is decided by the
 * rocking the 0.5 mm layer damps (seed 1 lands with the layer and falls without it). */
#include "fs_test.h"

#include "footsim/base/fs_error.h"
#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_trial.h"

enum { NSEEDS = 2, NCONFIGS = 4 }; /* 2 seeds, not 3: CI's budget (docs/testing.md, CI) */

static const char *const configs[NCONFIGS][2] = {
    {"run.contact_layer_m=5e-4", "run.step_s=1e-4"},
    {"run.contact_layer_m=1e-9", "run.step_s=1e-4"},
    {"run.contact_layer_m=5e-4", "run.step_s=1e-5"},
    {"run.contact_layer_m=1e-9", "run.step_s=1e-5"},
};

/* Every seed of foot under robot judged alike in every configuration, and as expected. */
static void judged_alike(const char *foot, const char *robot, int expected)
{
    char design[128], body[128];
    snprintf(design, sizeof design, "scenario.design=feet/%s.ini", foot);
    snprintf(body, sizeof body, "robot.design=robots/%s.ini", robot);
    for (int seed = 1; seed <= NSEEDS; seed++)
        for (int k = 0; k < NCONFIGS; k++) {
            const char *set[] = {design, body, "scenario.terrain=../terrains/flat.ini", configs[k][0], configs[k][1]};
            fs_trial_result r;
            fs_error err;
            REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 5, seed, NULL, &r, &err) == FS_OK);
            if (r.outcome != expected)
                fprintf(stderr, "  %s under %s, seed %d, %s, %s: %s (%s), expected %s\n", foot, robot, seed,
                        configs[k][0], configs[k][1], fs_outcome_name(r.outcome), fs_rule_name(r.rule),
                        fs_outcome_name(expected));
            CHECK(r.outcome == expected);
        }
}

/* The flat foot lands under the tall robot: at rest with the layer, rocking to a stop without it. */
static void flat_foot_under_single_tall_lands_whatever_the_layer_and_step(void)
{
    judged_alike("flat", "single_tall", FS_LANDED);
}

/* The Table I foot folds under the tall robot (docs/landing.md, the pitch-stiffness law). */
static void biomimetic_foot_under_single_tall_falls_whatever_the_layer_and_step(void)
{
    judged_alike("biomimetic", "single_tall", FS_FELL);
}

/* And carries the same 26 kg over its ankle. */
static void biomimetic_foot_under_drop_weight_lands_whatever_the_layer_and_step(void)
{
    judged_alike("biomimetic", "drop_weight", FS_LANDED);
}

/* A flat sole on rough ground touches at many lattice points, and run.max_contacts keeps some of
 * them: the default keeps enough that the outcome is the one with every contact ODE finds kept
 * (FS_MAX_SHAPE_CONTACTS). With 8, these seeds stopped on the energy check (docs/landing.md). The sole is
 * 76 mm wide against the tall robot's 76.5 N m/rad of toppling, on ground 1 mm RMS: it lands. */
static void flat_foot_on_rough_ground_lands_at_the_default_cap_as_with_every_contact(void)
{
    char all[64];
    snprintf(all, sizeof all, "run.max_contacts=%d", FS_MAX_SHAPE_CONTACTS);
    for (int seed = 1; seed <= 2; seed++)
        for (int k = 0; k < 2; k++) {
            const char *set[] = {"scenario.design=feet/flat.ini", "scenario.terrain=../terrains/rough.ini",
                                 "rough.rms_m=0.001", all};
            fs_trial_result r;
            fs_error err;
            REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 3 + k, seed, NULL, &r, &err) == FS_OK);
            if (r.outcome != FS_LANDED)
                fprintf(stderr, "  flat foot on 1 mm rough ground, seed %d, %s: %s (%s)\n", seed,
                        k ? all : "the default cap", fs_outcome_name(r.outcome), fs_rule_name(r.rule));
            CHECK(r.outcome == FS_LANDED);
        }
}

/* The pitch-stiffness law predicts where landings start to fail: the Table I foot under a 26 kg body
 * over its ankle (drop_weight) lands with the body's centre of mass at 0.8 of the law's critical
 * height K / (m g) and falls at 1.2 of it, on every seed (so the simulated boundary lies within
 * +-20 % of the law's). */
static void the_law_predicts_the_landing_boundary(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", (const char *[]){"robot.design=robots/drop_weight.ini"}, 1,
                             &sc, &err) == FS_OK);
    double g = sc.def.gravity_m_per_s2, m = sc.def.robot.mass_kg, K;
    REQUIRE(fs_pitch_stiffness_model(&sc.geom, m * g, g, &K, &err) == FS_OK);
    fs_scenario_free(&sc);
    double critical = K / (m * g);
    for (int side = 0; side < 2; side++) {
        char height[64];
        snprintf(height, sizeof height, "robot.com_height_m=%.6f", critical * (side ? 1.2 : 0.8));
        const char *set[] = {"robot.design=robots/drop_weight.ini", height};
        for (int seed = 1; seed <= NSEEDS; seed++) {
            fs_trial_result r;
            REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 2, seed, NULL, &r, &err) == FS_OK);
            if (r.outcome != (side ? FS_FELL : FS_LANDED))
                fprintf(stderr, "  %s (critical %.4f m), seed %d: %s (%s)\n", height, critical, seed,
                        fs_outcome_name(r.outcome), fs_rule_name(r.rule));
            CHECK(r.outcome == (side ? FS_FELL : FS_LANDED));
        }
    }
}

FS_TEST_MAIN(TEST(the_law_predicts_the_landing_boundary),
             TEST(flat_foot_under_single_tall_lands_whatever_the_layer_and_step),
             TEST(biomimetic_foot_under_single_tall_falls_whatever_the_layer_and_step),
             TEST(biomimetic_foot_under_drop_weight_lands_whatever_the_layer_and_step),
             TEST(flat_foot_on_rough_ground_lands_at_the_default_cap_as_with_every_contact))
