/* Tests of analysis_stiffness.c: the stiffness model (paper eqs. 1-3) against ODE. */
#include "fs_test.h"

#include "footsim/analysis/fs_analysis.h"

/* K measured by torque probes in ODE agrees with G^T Kdd G within 1 % (Frobenius norm), for the
 * default design and for a stiffer, differently anchored one. */
static void check_design(const char *const *set, int nset)
{
    static fs_scenario sc;
    fs_error err;
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", set, nset, &sc, &err) == FS_OK);
    fs_chain_stiffness k[FS_CHAINS];
    fs_stiffness_analytic(&sc.geom, k);
    CHECK(fs_stiffness_measure(&sc, k, &err) == FS_OK);
    for (int i = 0; i < FS_CHAINS; i++) {
        CHECK(k[i].rel_diff < 0.01);
        /* symmetric and positive definite */
        CHECK_NEAR(k[i].exact[0][1], k[i].exact[1][0], 1e-12);
        CHECK(k[i].exact[0][0] > 0 && k[i].exact[0][0] * k[i].exact[1][1] > k[i].exact[0][1] * k[i].exact[1][0]);
        /* the paper's eq. 4 ignores the anchors' offset from the link axes: it must differ */
        CHECK(k[i].eq4[0][0] < k[i].exact[0][0]);
    }
}

static void default_design_agrees(void) { check_design(NULL, 0); }

static void other_design_agrees(void)
{
    const char *set[] = {"springs.k_d1_N_per_m=30000", "springs.d1_h_m=0.004", "springs.d3_toe_b_m=0.01",
                         "pose.toe_deg=-35"};
    check_design(set, 4);
}

/* d2 does not cross the midfoot: its Jacobian column for the midfoot is exactly zero (eq. 3). */
static void jacobian_has_the_papers_pattern(void)
{
    static fs_scenario sc;
    fs_error err;
    CHECK(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_chain_stiffness k[FS_CHAINS];
    fs_stiffness_analytic(&sc.geom, k);
    for (int i = 0; i < FS_CHAINS; i++) {
        CHECK(fabs(k[i].G[1][0]) < 1e-15); /* d2 against the midfoot */
        CHECK(fabs(k[i].G[0][1]) < 1e-15); /* d1 against the MTP */
        CHECK(k[i].G[2][0] != 0 && k[i].G[2][1] != 0); /* d3 is bi-articular */
    }
}

/* The whole foot's pitch stiffness (the law of docs/landing.md): the model (analysis_pitch.c) is
 * the foot in three dimensions with the definition's contacts, and ODE given those contacts (grip
 * along each chain's plane, free across it) must agree with it. What may separate them: the
 * contacts' compliance (about 9e6 N/m at each of seven points some 0.1 m apart: over 1e4 N m/rad in
 * parallel, against 12: 0.1 %), the probe's 1e-3 rad (second-order terms of that size: 0.1 %) and
 * the hinges' softness (far stiffer still): allow 1 %, the issue's. Splayed 15 degrees, the planar
 * projection footsim used before was 3.8 % off, and on the uneven design below, which pitching
 * also shifts sideways, leaving the shift out was 3.5 % off: the checks can fail. On alike,
 * unsplayed chains a chain's plane is the foot's, so gripping in it alone is gripping. The model
 * must also see the springs: doubling them all must stiffen the foot. */
static double pitch_model_against_ode(const char *const *set, int nset, int in_plane, double *K_model)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", set, nset, &sc, &err) == FS_OK);
    double g = sc.def.gravity_m_per_s2, load = 26 * g, K_ode;
    REQUIRE(fs_pitch_stiffness_model(&sc.geom, load, g, K_model, &err) == FS_OK);
    REQUIRE(fs_pitch_stiffness_measure(&sc, load, 10, in_plane, *K_model, &K_ode, &err) == FS_OK);
    CHECK(*K_model > 0);
    fs_scenario_free(&sc);
    return K_ode / *K_model;
}

static void pitch_stiffness_model_and_ode_agree(void)
{
    double K, K2;
    CHECK_NEAR(pitch_model_against_ode(NULL, 0, 1, &K), 1, 0.01); /* Table I */
    const char *splayed[] = {"chains.splay_deg=15,8,0,-8,-15"};
    CHECK_NEAR(pitch_model_against_ode(splayed, 1, 1, &K2), 1, 0.01);
    CHECK(K2 < K); /* a splayed chain bears less of its stiffness on pitch */
    const char *uneven[] = {"chains.lateral_m=0.03,0.01,0,-0.015,-0.02", "chains.splay_deg=10,3,-2,-5,-9",
                            "chains.scale=1.25,1.1,1,0.9,0.85", "springs.k_d1_N_per_m=30000", "springs.d1_h_m=0.004",
                            "springs.d3_toe_b_m=0.01", "pose.toe_deg=-35"};
    CHECK_NEAR(pitch_model_against_ode(uneven, 7, 1, &K2), 1, 0.01);
    const char *alike[] = {"chains.splay_deg=0,0,0,0,0", "chains.scale=1,1,1,1,1", "springs.d3_heel_spread=1"};
    CHECK_NEAR(pitch_model_against_ode(alike, 3, 0, &K), 1, 0.01);
    CHECK_NEAR(pitch_model_against_ode(alike, 3, 1, &K), 1, 0.01);
    const char *stiffer[] = {"chains.splay_deg=0,0,0,0,0", "chains.scale=1,1,1,1,1", "springs.d3_heel_spread=1",
                             "springs.k_d1_N_per_m=24000", "springs.k_d2_N_per_m=24000", "springs.k_d3_N_per_m=24000"};
    static fs_scenario sc2;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", stiffer, 6, &sc2, &err) == FS_OK);
    double g = sc2.def.gravity_m_per_s2;
    REQUIRE(fs_pitch_stiffness_model(&sc2.geom, 26 * g, g, &K2, &err) == FS_OK);
    CHECK(K2 > 1.5 * K);
    fs_scenario_free(&sc2);
    /* a flat sole has no arch to model: fs_pitch_stiffness_model refuses it */
    static fs_scenario flat;
    REQUIRE(fs_scenario_for_design("scenarios/feet/flat.ini", NULL, 0, &flat, &err) == FS_OK);
    CHECK(fs_pitch_stiffness_model(&flat.geom, 26 * g, g, &K, &err) == FS_BAD_INPUT);
    fs_scenario_free(&flat);
}

/* Splayed chains (Table I): freeing the toes across their planes removes constraints, so the foot
 * can only be softer in pitch than when they grip every way; the model's own contacts (grip in each
 * chain's plane, free across) are the softer of the two. */
static void freeing_toes_across_their_planes_softens_the_foot(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    double g = sc.def.gravity_m_per_s2, load = 26 * g, K, K_grip, K_plane;
    REQUIRE(fs_pitch_stiffness_model(&sc.geom, load, g, &K, &err) == FS_OK);
    REQUIRE(fs_pitch_stiffness_measure(&sc, load, 10, 0, K, &K_grip, &err) == FS_OK);
    REQUIRE(fs_pitch_stiffness_measure(&sc, load, 10, 1, K, &K_plane, &err) == FS_OK);
    CHECK(K_plane > 0 && K_plane < K_grip);
}

/* A flat sole's pitch stiffness is its contacts': its four bottom corners on springs of the sole's
 * and the ground's stiffness in series, K = k L^2. ODE's box on a plane touches at those corners
 * with exactly that soft-contact spring (soft ERP and CFM from k and the damping), so what may
 * separate the two is the probe's second-order terms (a pitch of about 1e-5 rad: 1e-5 relative) and
 * the solver's residuals: allow 1 %. Contacts made twice as stiff must double K, in the model and
 * in ODE alike. */
static void flat_sole_pitch_stiffness_model_and_ode_agree(void)
{
    static fs_scenario flat;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/flat.ini", NULL, 0, &flat, &err) == FS_OK);
    double load = 26 * flat.def.gravity_m_per_s2, K, K_ode;
    REQUIRE(fs_pitch_stiffness_foot(&flat, load, &K, &err) == FS_OK);
    double k = flat.design.sole_stiffness_N_per_m * flat.terrain.def.stiffness_N_per_m /
               (flat.design.sole_stiffness_N_per_m + flat.terrain.def.stiffness_N_per_m);
    CHECK_NEAR(K / (k * flat.geom.box_size.x * flat.geom.box_size.x), 1, 1e-12);
    REQUIRE(fs_pitch_stiffness_measure(&flat, load, 1, 0, K, &K_ode, &err) == FS_OK);
    CHECK_NEAR(K_ode / K, 1, 0.01);
    flat.design.sole_stiffness_N_per_m *= 2;
    flat.terrain.def.stiffness_N_per_m *= 2;
    double K2;
    REQUIRE(fs_pitch_stiffness_foot(&flat, load, &K2, &err) == FS_OK);
    CHECK_NEAR(K2 / K, 2, 1e-12);
    REQUIRE(fs_pitch_stiffness_measure(&flat, load, 1, 0, K2, &K_ode, &err) == FS_OK);
    CHECK_NEAR(K_ode / K2, 1, 0.01);
    fs_scenario_free(&flat);
}

/* The law for each kind of robot: rigid, an Achilles tendon in series, a slide that holds pitch. */
static void pitch_law_for_each_robot(void)
{
    fs_robot_def r = {.mass_kg = 26, .com_height_m = 0.3, .joint = FS_ROBOT_RIGID};
    fs_pitch_law l;
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK_NEAR(l.demand, 26 * 9.81 * 0.3, 1e-9);
    CHECK(!l.stands && l.K == 13 && !l.held);
    CHECK_NEAR(l.critical_height_m, 13 / (26 * 9.81), 1e-12);
    r.com_height_m = 0.05;
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK(l.stands);
    r.joint = FS_ROBOT_ACHILLES, r.achilles_k_N_per_m = 1e6; /* 400 N m/rad in series */
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK_NEAR(l.K, 1 / (1 / 13.0 + 1 / 400.0), 1e-9);
    CHECK(!l.stands); /* 12.6 against 12.75 */
    /* a centre of mass ahead of the ankle leans it by m g x / (K - m g h) */
    r.joint = FS_ROBOT_RIGID, r.com_forward_m = 0.01;
    r.com_height_m = 0.02; /* 2.55 / (13 - 5.10) = 0.32 rad: past 0.26 */
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK_NEAR(l.lean_rad, 26 * 9.81 * 0.01 / (13 - 26 * 9.81 * 0.02), 1e-12);
    CHECK(!l.stands);
    r.com_forward_m = 0.005; /* 0.16 rad */
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK(l.stands);
    r.mount = FS_ROBOT_VERTICAL;
    fs_pitch_law_apply(13, &r, 9.81, 0.26, &l);
    CHECK(l.held && l.stands);
}

FS_TEST_MAIN(TEST(freeing_toes_across_their_planes_softens_the_foot), TEST(default_design_agrees), TEST(other_design_agrees), TEST(jacobian_has_the_papers_pattern),
             TEST(pitch_stiffness_model_and_ode_agree), TEST(flat_sole_pitch_stiffness_model_and_ode_agree),
             TEST(pitch_law_for_each_robot))
