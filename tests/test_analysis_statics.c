/* Tests of analysis_planar.c against the ODE model: the foot's static deflection under the
 * paper's 26 kg load agrees with the stiffness model's prediction. */
#include "fs_test.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_run.h"

/* A design whose five chains are alike and unsplayed, so that one planar chain is exact; stiff
 * contacts and a strict rest criterion, so that the comparison measures the models, not those;
 * a slow load, since on gripping ground a sudden one makes the toes slip for a moment and the
 * foot then settles elsewhere (friction keeps the history). The contact layer (run.contact_layer_m)
 * matters here: without it these stiff contacts chatter on and off while the load is small and the
 * toes creep by 3 microns, which moves the ankle by 5e-7 m. */
static const char *planar_overrides[] = {
    "chains.splay_deg=0,0,0,0,0", "chains.scale=1,1,1,1,1", "springs.d3_heel_spread=1",
    "material.stiffness_N_per_m=1e12", "sole.stiffness_N_per_m=1e12", "run.rest_speed_m_per_s=1e-7",
    "run.rest_hold_s=0.05", "run.duration_s=5", "load.ramp_s=0.5", NULL, NULL, /* the friction of ground and sole */
};
enum { NOVERRIDES = sizeof planar_overrides / sizeof planar_overrides[0] };

/* Bounds on what separates the two models at rest (26 kg, five chains):
 * - contact penetration: 255 N / (1e12 / 2 N/m) = 5e-10 m, plus ODE's contact layer, 1e-9 m;
 * - the toes' one free step before first contact: about 1e-8 m of slip, moving the ankle by
 *   0.16 m/m of slip (the planar model's sensitivity), 2e-9 m;
 * - hinge compliance: a soft row behaves as a spring of ERP/(h CFM) = 2e13 N/m, 300 N gives 2e-11 m;
 * - motion left at the stop: 1e-7 m/s times the slowest time constant, c/k = 0.017 s, = 2e-9 m;
 * - the planar solver: 1e-9 rad times levers under 0.1 m = 1e-10 m.
 * About 5e-9 m in all: allow 1e-8 m; angles then agree to 1e-8 m over the shortest lever
 * (6 mm), 2e-6 rad. */
static const double DROP_TOL_M = 1e-8, ANGLE_TOL_RAD = 2e-6;

static void compare(const char *ground_mu, const char *sole_mu, int frictionless)
{
    const char *set[NOVERRIDES];
    for (int i = 0; i < NOVERRIDES - 2; i++)
        set[i] = planar_overrides[i];
    set[NOVERRIDES - 2] = ground_mu;
    set[NOVERRIDES - 1] = sole_mu;
    static fs_scenario sc;
    fs_error err;
    fs_status loaded = fs_scenario_load("scenarios/static_load.ini", set, NOVERRIDES, &sc, &err);
    if (loaded != FS_OK)
        fprintf(stderr, "  %s\n", err.message);
    CHECK(loaded == FS_OK);
    if (loaded != FS_OK)
        return;
    fs_run_result res;
    REQUIRE(fs_run(&sc, NULL, &res, &err) == FS_OK);
    CHECK(res.at_rest);
    fs_planar_load load = {sc.def.load_kg * sc.def.gravity_m_per_s2, sc.def.gravity_m_per_s2, 0, frictionless};
    fs_planar_result eq;
    CHECK(fs_planar_equilibrium(&sc.design, &sc.geom, 2, &load, &eq, &err) == FS_OK);
    CHECK(eq.converged && eq.stable);
    /* the load does deflect the arch: the comparison is not between two zeros */
    CHECK(eq.ankle_drop_m > 1e-5);
    CHECK_NEAR(res.ankle_drop_m, eq.ankle_drop_m, DROP_TOL_M);
    CHECK_NEAR(res.hinge_angle_rad[0], eq.ankle_joint_rad, ANGLE_TOL_RAD);
    for (int i = 0; i < FS_CHAINS; i++) {
        CHECK_NEAR(res.hinge_angle_rad[sc.geom.chain[i].midfoot_hinge], eq.midfoot_rad, ANGLE_TOL_RAD);
        CHECK_NEAR(res.hinge_angle_rad[sc.geom.chain[i].mtp_hinge], eq.mtp_rad, ANGLE_TOL_RAD);
    }
    fs_run_free(&res);
}

/* The paper ignores ground friction: heel and toes slide. */
static void deflection_on_frictionless_ground(void) { compare("material.mu=0", "sole.mu=1", 1); }

/* Friction high enough that nothing slips (the toes need about 4 times their normal force
 * sideways): heel and toes roll. */
static void deflection_on_gripping_ground(void) { compare("material.mu=10", "sole.mu=10", 0); }

/* The default design neither collapses nor inverts under its design load. */
static void default_arch_holds_its_load(void)
{
    static fs_scenario sc;
    fs_error err;
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    for (int i = 0; i < FS_CHAINS; i++) {
        fs_planar_load load = {sc.design.design_load_kg * 9.81, 9.81, 0, 1};
        fs_planar_result eq;
        CHECK(fs_planar_equilibrium(&sc.design, &sc.geom, i, &load, &eq, &err) == FS_OK);
        CHECK(eq.converged && eq.stable);
        /* not collapsed: the ball stays off the ground; not inverted: joints turn less than 30 deg */
        CHECK(eq.ball_clearance_m > 0);
        CHECK(fabs(eq.midfoot_rad) < 30 * M_PI / 180 && fabs(eq.mtp_rad) < 30 * M_PI / 180);
    }
}

FS_TEST_MAIN(TEST(deflection_on_frictionless_ground), TEST(deflection_on_gripping_ground),
             TEST(default_arch_holds_its_load))
