/* A landing's outcome does not hang on a numerical knob (issue 11): on flat ground the same seeds
 * with ODE's contact surface layer at 0.5 mm (shipped) and 1e-9 m (stiff), each at the default step
 * and at half of it, are judged alike, for a foot and robot that land and for one that falls.
 *
 * The exception, left out here and stated in docs/landing.md: the flat foot under drop_weight. Its
 * load stands over the ankle, 9.5 mm ahead of the footprint's back edge, so a toe-first touchdown
 * tips it backward to the edge of falling over the heel, and whether it does is decided by the
 * rocking the 0.5 mm layer damps (seed 1 lands with the layer and falls without it). */
#include "fs_test.h"

#include "footsim/base/fs_error.h"
#include "footsim/experiment/fs_trial.h"

enum { NSEEDS = 3, NCONFIGS = 4 };

static const char *const configs[NCONFIGS][2] = {
    {"run.contact_layer_m=5e-4", "run.step_s=1e-4"},
    {"run.contact_layer_m=1e-9", "run.step_s=1e-4"},
    {"run.contact_layer_m=5e-4", "run.step_s=5e-5"},
    {"run.contact_layer_m=1e-9", "run.step_s=5e-5"},
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

FS_TEST_MAIN(TEST(flat_foot_under_single_tall_lands_whatever_the_layer_and_step),
             TEST(biomimetic_foot_under_single_tall_falls_whatever_the_layer_and_step),
             TEST(biomimetic_foot_under_drop_weight_lands_whatever_the_layer_and_step))
