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

FS_TEST_MAIN(TEST(default_design_agrees), TEST(other_design_agrees), TEST(jacobian_has_the_papers_pattern))
