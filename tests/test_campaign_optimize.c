/* Tests of the design search (fs_optimize.h): its file checked, a candidate put into every cell's
 * definitions, the penalty, and the search itself against trials whose outcome is known by
 * construction (no simulation: a stand-in decides each trial from the candidate). */
#include "fs_test.h"

#include "footsim/base/fs_error.h"
#include "footsim/campaign/fs_optimize.h"

#include <stdlib.h>

static const char *small[] = {"campaign.seeds=2"};

/* The file: three parameters, their keys and bounds; the start is in every cell's definitions. */
static void loads_and_applies(void)
{
    static fs_optimize o;
    fs_error err;
    REQUIRE(fs_optimize_load("scenarios/optimize_single_tall.ini", small, 1, &o, &err) == FS_OK);
    CHECK(o.nparams == 3 && !strcmp(o.param[2].key, "springs.k_d3_N_per_m") && o.param[0].log);
    CHECK(o.campaign.nexpect == 1 && o.campaign.seeds == 2 && fs_campaign_ncells(&o.campaign) == 1);
    const double x[3] = {2e5, 3e5, 4e5};
    REQUIRE(fs_optimize_apply(&o, x, &err) == FS_OK);
    for (int cell = 0; cell < 1; cell++) {
        const fs_scenario *sc = fs_campaign_pair(&o.campaign, cell);
        CHECK(sc->design.k_N_per_m[1] == 3e5);
        CHECK(sc->geom.spring[sc->geom.chain[0].spring[2]].k_N_per_m == 4e5); /* compiled into the geometry */
    }
    CHECK_NEAR(fs_optimize_objective(&o, x), (2e5 + 3e5 + 4e5) / 12000, 1e-9);
    fs_optimize_free(&o);
}

/* Bounds out of order, a start outside them, a log parameter through zero: refused with file:line. */
static void refuses_bad_parameters(void)
{
    static fs_optimize o;
    fs_error err;
    const char *bad[][2] = {{"optimize.max_evaluations=0", "max_evaluations"}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *set[] = {small[0], bad[i][0]};
        CHECK(fs_optimize_load("scenarios/optimize_single_tall.ini", set, 2, &o, &err) == FS_BAD_INPUT);
        CHECK(strstr(err.message, bad[i][1]) != NULL);
    }
    char path[] = "/tmp/fs_optimize_XXXXXX";
    int fd = mkstemp(path);
    REQUIRE(fd >= 0);
    FILE *f = fdopen(fd, "w");
    fprintf(f, "[optimize]\ncampaign = %s/scenarios/search_single_tall.ini\nobjective = least_stiff\n[param.a]\nkey = springs.k_d1_N_per_m\n"
               "min = 2e5\nmax = 1e5\nstart = 1e5\n", FS_SOURCE_DIR);
    fclose(f);
    CHECK(fs_optimize_load(path, small, 1, &o, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, 8, "give min < max and the start between them");
    f = fopen(path, "w");
    fprintf(f, "[optimize]\ncampaign = %s/scenarios/search_single_tall.ini\nobjective = least_stiff\n[param.a]\nkey = springs.k_d1_N_per_m\n"
               "min = 0\nmax = 1e5\nstart = 1e4\nlog = yes\n", FS_SOURCE_DIR);
    fclose(f);
    CHECK(fs_optimize_load(path, small, 1, &o, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, 9, "log = yes needs min > 0");
    /* the objective must be named */
    f = fopen(path, "w");
    fprintf(f, "[optimize]\ncampaign = %s/scenarios/search_single_tall.ini\n[param.a]\nkey = springs.k_d1_N_per_m\n"
               "min = 1e4\nmax = 1e5\nstart = 2e4\n", FS_SOURCE_DIR);
    fclose(f);
    CHECK(fs_optimize_load(path, small, 1, &o, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "objective is missing") && strstr(err.message, "objective = least_stiff"));
    /* lightest: the foot's mass as the candidate compiles it, moving with a mass parameter alone */
    f = fopen(path, "w");
    fprintf(f, "[optimize]\ncampaign = %s/scenarios/search_single_tall.ini\nobjective = lightest\n[param.m]\n"
               "key = mass.phalanx_kg\nmin = 0.004\nmax = 0.016\nstart = 0.008\n", FS_SOURCE_DIR);
    fclose(f);
    REQUIRE(fs_optimize_load(path, small, 1, &o, &err) == FS_OK);
    double light[1] = {0.004}, heavy[1] = {0.016};
    REQUIRE(fs_optimize_apply(&o, light, &err) == FS_OK);
    double m_light = fs_optimize_objective(&o, light);
    REQUIRE(fs_optimize_apply(&o, heavy, &err) == FS_OK);
    double m_heavy = fs_optimize_objective(&o, heavy);
    /* five phalanges, each scaled by its chain's scale (Table I: the big toe larger) */
    double scales = 0;
    for (int i = 0; i < FS_CHAINS; i++)
        scales += fs_campaign_pair(&o.campaign, 0)->design.scale[i];
    CHECK_NEAR(m_heavy - m_light, 0.012 * scales, 1e-12);
    fs_optimize_free(&o);
    remove(path);
}

/* Stand-in trials: every trial lands exactly when k_d1 >= 3e5 and k_d3 >= 5e4 (k_d2 does not
 * matter), so the least stiff design meeting the targets is (3e5, 12000, 5e4); one that misses
 * stays up the longer the nearer it comes, as a toppling robot does on stiffer springs. */
static fs_status known_boundary(void *user, const fs_campaign *c, fs_trial_result *results, fs_error *err)
{
    (void)user, (void)err;
    const fs_scenario *sc = fs_campaign_pair(c, 0);
    double a = sc->design.k_N_per_m[0] / 3e5, b = sc->design.k_N_per_m[2] / 5e4;
    int lands = a >= 1 && b >= 1;
    for (int i = 0; i < fs_campaign_ntrials(c); i++) {
        results[i].outcome = lands ? FS_LANDED : FS_FELL;
        results[i].end_time_s = sc->def.duration_s * 0.9 * fmin(1, a) * fmin(1, b);
    }
    return FS_OK;
}

/* The search finds that design: each parameter within 10 % of the boundary (Subplex narrows a step to
 * its tolerance within the budget), and never settles on a design that misses a target. */
static void search_finds_a_known_boundary(void)
{
    static fs_optimize o;
    fs_error err;
    const char *set[] = {small[0], "optimize.max_evaluations=200"};
    REQUIRE(fs_optimize_load("scenarios/optimize_single_tall.ini", set, 2, &o, &err) == FS_OK);
    int n = fs_campaign_ntrials(&o.campaign);
    fs_trial_result *results = calloc((size_t)n, sizeof *results);
    fs_campaign_row *rows = calloc((size_t)fs_campaign_ncells(&o.campaign), sizeof *rows);
    double best[3], value;
    REQUIRE(fs_optimize_run(&o, known_boundary, NULL, NULL, results, rows, best, &value, &err) == FS_OK);
    CHECK(best[0] >= 3e5 && best[0] <= 3.3e5);
    CHECK(best[2] >= 5e4 && best[2] <= 5.5e4);
    CHECK(best[1] <= 1.1 * 12000);
    CHECK_NEAR(value, fs_optimize_objective(&o, best), 1e-9); /* no penalty left */
    free(results);
    free(rows);
    fs_optimize_free(&o);
}

FS_TEST_MAIN(TEST(loads_and_applies), TEST(refuses_bad_parameters), TEST(search_finds_a_known_boundary))
