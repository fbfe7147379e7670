/* test_analysis_campaign: Wilson intervals, medians, summaries, expectations, the campaign file
 * and the comparison of two summaries (no trials run here; tests/cli_campaign.sh runs them). */
#include "fs_test.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>

#include <stdlib.h>
#include <unistd.h>

/* The 95 % Wilson score interval of k in n, z = 1.959964 (z^2 = 3.841459):
 *   centre = (p + z^2/2n) / (1 + z^2/n),  half = z / (1 + z^2/n) * sqrt(p(1-p)/n + z^2/4n^2).
 * 0/10:  z^2/n = 0.3841459; centre = 0.1920729 / 1.3841459 = 0.1387664; half = 1.4160006 *
 *        sqrt(0 + 0.0096036) = 0.1387664: [0, 0.2775328].
 * 5/10:  centre 0.5; half = 1.4160006 * sqrt(0.025 + 0.0096036) = 0.2634069: [0.2365931, 0.7634069].
 * 10/10: the mirror of 0/10: [0.7224672, 1].
 * 45/50: p = 0.9, z^2/n = 0.0768292; centre = (0.9 + 0.0384146) / 1.0768292 = 0.8714610;
 *        half = 1.8201194 * sqrt(0.0018 + 0.0003841) = 0.0850633: [0.7863977, 0.9565242].
 * (The textbook values, e.g. Newcombe 1998, agree to the 4 digits they give.) */
static void test_wilson(void)
{
    double lo, hi;
    fs_wilson(0, 10, &lo, &hi);
    CHECK(lo == 0);
    CHECK_NEAR(hi, 0.2775328, 1e-7);
    fs_wilson(5, 10, &lo, &hi);
    CHECK_NEAR(lo, 0.2365931, 1e-7);
    CHECK_NEAR(hi, 0.7634069, 1e-7);
    fs_wilson(10, 10, &lo, &hi);
    CHECK_NEAR(lo, 0.7224672, 1e-7);
    CHECK(hi == 1);
    fs_wilson(45, 50, &lo, &hi);
    CHECK_NEAR(lo, 0.7863977, 1e-7);
    CHECK_NEAR(hi, 0.9565242, 1e-7);
}

static void test_median(void)
{
    double odd[] = {5, 1, 3}, even[] = {4, 1, 3, 2}, one[] = {7};
    CHECK(fs_median(odd, 3) == 3);
    CHECK(fs_median(even, 4) == 2.5);
    CHECK(fs_median(one, 1) == 7);
    CHECK(isnan(fs_median(NULL, 0)));
}

/* A campaign of two feet on one terrain, 4 seeds, built by hand. */
static void small_campaign(fs_campaign *c)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "small");
    snprintf(c->trial_path, sizeof c->trial_path, "/x/trial.ini");
    c->seeds = 4;
    c->first_seed = 1;
    c->nfeet = 2;
    c->nterrains = 1;
    c->nrobots = 1;
    snprintf(c->foot[0].name, FS_NAME_MAX, "bio");
    snprintf(c->foot[1].name, FS_NAME_MAX, "flat");
    snprintf(c->terrain[0].name, FS_NAME_MAX, "rocks");
    snprintf(c->robot[0].name, FS_NAME_MAX, "tall");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        c->tolerance[m][0] = 0.1;
        c->tolerance[m][1] = 1;
    }
}

/* bio: 3 landed, 1 failed numerically; flat: 1 landed, 3 fell; peak force 100, 200, ... */
static void small_results(fs_trial_result r[8])
{
    memset(r, 0, 8 * sizeof *r);
    for (int i = 0; i < 8; i++) {
        r[i].outcome = i < 4 ? FS_LANDED : FS_FELL;
        r[i].peak_force_N = 100.0 * (i + 1);
        r[i].steps = 10 * (i + 1);
        r[i].impact_impulse_Ns = 10.0 + i; /* bio's medians: 11 N s */
        r[i].ankle_drop_m = 1e-3 * (i + 1);
    }
    r[3].outcome = FS_FAILED_NUMERICS;
    r[3].peak_force_N = NAN; /* left out of the medians */
    r[5].outcome = FS_LANDED;
}

/* The small campaign and its summary rows. */
static void summarized(fs_campaign *c, fs_campaign_row rows[2])
{
    fs_trial_result r[8];
    small_campaign(c);
    small_results(r);
    fs_campaign_summarize(c, r, rows);
}

static void test_summarize(void)
{
    static fs_campaign c;
    fs_campaign_row rows[2];
    summarized(&c, rows);
    CHECK(rows[0].trials == 4 && rows[0].landed == 3 && rows[0].failed_numerics == 1 && rows[0].fell == 0);
    CHECK(rows[0].success_rate == 0.75);
    CHECK(rows[0].nmetric == 3);
    CHECK(rows[0].median[4] == 200); /* peak_force_N of 100, 200, 300 */
    CHECK(rows[0].median[11] == 20); /* steps 10, 20, 30 */
    CHECK(rows[1].landed == 1 && rows[1].fell == 3);
    CHECK(rows[1].median[4] == 650); /* 500, 600, 700, 800 */
    /* the ankle drop over every trial measured; at rest, over those that landed (flat: seed 2) */
    CHECK_NEAR(rows[1].median[9], 6.5e-3, 1e-15);
    CHECK_NEAR(rows[1].median[12], 6e-3, 1e-15);
    CHECK_NEAR(rows[0].median[9], 2e-3, 1e-15);
    CHECK_NEAR(rows[0].median[12], 2e-3, 1e-15);
    int cell, foot, terrain, robot, seed;
    fs_campaign_trial_of(&c, 5, &cell, &seed);
    fs_campaign_cell_of(&c, cell, &foot, &terrain, &robot);
    CHECK(cell == 1 && foot == 1 && terrain == 0 && robot == 0 && seed == 2);
    CHECK(rows[1].foot == 1 && rows[1].terrain == 0 && rows[1].robot == 0);
    /* a trial whose worker the watchdog killed is hung: its own count, never failed_numerics, and
       no measurement for the medians */
    fs_trial_result r[8];
    small_results(r);
    r[2].outcome = FS_HUNG;
    r[2].peak_force_N = NAN;
    fs_campaign_summarize(&c, r, rows);
    CHECK(rows[0].hung == 1 && rows[0].failed_numerics == 1 && rows[0].landed == 2 && rows[0].nmetric == 2);
    CHECK(rows[0].median[4] == 150); /* peak_force_N of 100, 200 */
    CHECK(rows[1].hung == 0);
    r[5].outcome = FS_FELL; /* no trial of flat's landed: no ankle drop at rest */
    fs_campaign_summarize(&c, r, rows);
    CHECK(isnan(rows[1].median[12]));
    CHECK_NEAR(rows[1].median[9], 6.5e-3, 1e-15);
    CHECK(!strcmp(fs_outcome_name(FS_HUNG), "hung") && !strcmp(fs_rule_name(FS_RULE_WATCHDOG), "watchdog"));
}

static void test_expectations(void)
{
    static fs_campaign c;
    fs_campaign_row rows[2];
    summarized(&c, rows);
    c.nexpect = 2;
    c.expect[0] = (fs_expectation){"bio_lands", 0, 0, 0, 0.7, 1};
    c.expect[1] = (fs_expectation){"flat_fails", 1, 0, 0, 0, 0.5};
    FILE *null = fopen("/dev/null", "w");
    CHECK(fs_campaign_check(&c, rows, null) == 0);
    c.expect[0].min_success = 0.8; /* 0.75 is below it */
    c.expect[1].max_success = 0.2; /* 0.25 is above it */
    CHECK(fs_campaign_check(&c, rows, null) == 2);
    fclose(null);
}

/* Writes the small campaign's summary.json into dir, after change() edits its rows. */
static void write_summary(const char *dir, void (*change)(fs_campaign_row *))
{
    static fs_campaign c;
    fs_campaign_row rows[2];
    fs_error err;
    summarized(&c, rows);
    if (change)
        change(rows);
    REQUIRE(fs_make_dirs(dir, &err) == FS_OK);
    CHECK(fs_campaign_write_summary(&c, rows, dir, &err) == FS_OK);
}

static void rate_out(fs_campaign_row *rows) { rows[1].success_rate = 0.9; } /* baseline CI of 1/4 ends at 0.70 */
static void rate_in(fs_campaign_row *rows) { rows[1].success_rate = 0.5; }
static void force_near(fs_campaign_row *rows) { rows[0].median[4] += 20; } /* 0.1 * 200 + 1 = 21 allowed */
static void force_far(fs_campaign_row *rows) { rows[0].median[4] += 22; }
static void no_median(fs_campaign_row *rows) { rows[0].median[4] = NAN; }
static void one_hung(fs_campaign_row *rows) { rows[0].hung = 1; }
static void one_undecided(fs_campaign_row *rows) { rows[0].undecided = 1; }

/* tmp/no_rest/summary.json: tmp/base's without the ankle drop at rest, as footsim wrote it before
 * it had that metric. */
static void without_rest_drop(const char *tmp)
{
    char path[600], *text;
    size_t len;
    fs_error err;
    snprintf(path, sizeof path, "%s/base/summary.json", tmp);
    REQUIRE(fs_read_regular(path, 1 << 20, "a summary", &text, &len, &err) == FS_OK);
    cJSON *root = cJSON_Parse(text);
    free(text);
    REQUIRE(root != NULL);
    const cJSON *row;
    cJSON_ArrayForEach(row, cJSON_GetObjectItemCaseSensitive(root, "rows"))
        cJSON_DeleteItemFromObjectCaseSensitive((cJSON *)row, "median_rest_ankle_drop_m");
    char *out = cJSON_Print(root);
    cJSON_Delete(root);
    snprintf(path, sizeof path, "%s/no_rest", tmp);
    REQUIRE(out && fs_make_dirs(path, &err) == FS_OK);
    snprintf(path, sizeof path, "%s/no_rest/summary.json", tmp);
    CHECK(fs_write_atomic(path, out, strlen(out), &err) == FS_OK);
    free(out);
}

/* Compares the summary change() makes with the baseline in tmp/base (or tmp/BASE_NAME). */
static fs_status compare_against(const char *tmp, const char *base_name, const char *name,
                                 void (*change)(fs_campaign_row *))
{
    char dir[512], result[600], baseline[600];
    snprintf(dir, sizeof dir, "%s/%s", tmp, name);
    write_summary(dir, change);
    snprintf(result, sizeof result, "%s/summary.json", dir);
    snprintf(baseline, sizeof baseline, "%s/%s/summary.json", tmp, base_name);
    FILE *null = fopen("/dev/null", "w");
    fs_error err;
    fs_status s = fs_campaign_compare(result, baseline, 0, null, &err);
    fclose(null);
    return s;
}

static fs_status compare_with(const char *tmp, const char *name, void (*change)(fs_campaign_row *))
{
    return compare_against(tmp, "base", name, change);
}

static void test_compare(void)
{
    char tmp[] = "/tmp/fs_campaign_XXXXXX";
    CHECK(mkdtemp(tmp) != NULL);
    char dir[512];
    snprintf(dir, sizeof dir, "%s/base", tmp);
    write_summary(dir, NULL);
    CHECK(compare_with(tmp, "same", NULL) == FS_OK);
    CHECK(compare_with(tmp, "rate_out", rate_out) == FS_EXPECTATION_FAILED);
    CHECK(compare_with(tmp, "rate_in", rate_in) == FS_OK);
    CHECK(compare_with(tmp, "force_near", force_near) == FS_OK);
    CHECK(compare_with(tmp, "force_far", force_far) == FS_EXPECTATION_FAILED);
    CHECK(compare_with(tmp, "no_median", no_median) == FS_EXPECTATION_FAILED);
    /* hung trials: never more than the baseline's; a summary from before the count reads as 0 */
    CHECK(compare_with(tmp, "hung", one_hung) == FS_EXPECTATION_FAILED);
    char cmd_old[1400];
    snprintf(cmd_old, sizeof cmd_old, "mkdir '%s/old' && grep -v '\"hung\"' '%s/base/summary.json' >'%s/old/summary.json'",
             tmp, tmp, tmp);
    REQUIRE(system(cmd_old) == 0);
    CHECK(compare_against(tmp, "old", "same_as_old", NULL) == FS_OK);
    CHECK(compare_against(tmp, "old", "hung_vs_old", one_hung) == FS_EXPECTATION_FAILED);
    /* a summary from before the ankle drop at rest: that median is said, not compared or judged */
    without_rest_drop(tmp);
    CHECK(compare_against(tmp, "no_rest", "same_as_no_rest", NULL) == FS_OK);
    char now_path[600], no_rest[600];
    snprintf(now_path, sizeof now_path, "%s/same_as_no_rest/summary.json", tmp);
    snprintf(no_rest, sizeof no_rest, "%s/no_rest/summary.json", tmp);
    FILE *null = fopen("/dev/null", "w");
    int differ = -1;
    CHECK(fs_campaign_equivalence(now_path, NULL, no_rest, 0, null, &differ, NULL) == FS_OK && differ == 0);
    fclose(null);
    /* a file that is no summary is bad input */
    fs_error err;
    char path[600];
    snprintf(path, sizeof path, "%s/base/summary.json", tmp);
    CHECK(fs_campaign_compare("scenarios/landing_ci.ini", path, 0, stdout, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "not a campaign summary") != NULL);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0);
}

/* Equivalence (issue 12): intervals that overlap, medians within 5 % or the metric's floor. */
static void apart(fs_campaign_row *rows) { rows[1].ci_low = 0.71, rows[1].ci_high = 1; } /* reference's ends at 0.70 */
static void touching(fs_campaign_row *rows) { rows[1].ci_low = 0.69, rows[1].ci_high = 1; }
static void lean_in_floor(fs_campaign_row *rows) { rows[0].median[3] += 0.49; } /* final_tilt_deg: floor 0.5 */
static void lean_past_floor(fs_campaign_row *rows) { rows[0].median[3] += 0.51; }
static void impulse_in(fs_campaign_row *rows) { rows[0].median[5] = 11 * 1.049; } /* 5 % of 11 N s */
static void impulse_out(fs_campaign_row *rows) { rows[0].median[5] = 11 * 1.051; }
/* rest_ankle_drop_m (2 mm): its floor 0.1 mm; a fall's ankle drop (ankle_drop_m) is not judged */
static void drop_in_floor(fs_campaign_row *rows) { rows[0].median[12] += 0.99e-4; }
static void drop_past_floor(fs_campaign_row *rows) { rows[0].median[12] += 1.01e-4; }
static void fall_drop_moved(fs_campaign_row *rows) { rows[1].median[9] *= 2; }
/* flat's one landed trial gone: no ankle drop at rest; said, not judged (the success rate is) */
static void none_landed(fs_campaign_row *rows) { rows[1].median[12] = NAN; }
static void force_doubled(fs_campaign_row *rows) { rows[0].median[4] *= 2; } /* reported, not judged */
static void no_contacts(fs_campaign_row *rows) { rows[0].median[7] = NAN; }

static fs_status equivalent_to(const char *tmp, const char *name, void (*change)(fs_campaign_row *))
{
    char dir[512], result[600], reference[600];
    snprintf(dir, sizeof dir, "%s/%s", tmp, name);
    write_summary(dir, change);
    snprintf(result, sizeof result, "%s/summary.json", dir);
    snprintf(reference, sizeof reference, "%s/base/summary.json", tmp);
    FILE *null = fopen("/dev/null", "w");
    fs_error err;
    int differ = -1;
    fs_status s = fs_campaign_equivalence(result, NULL, reference, 0, null, &differ, &err);
    CHECK(differ >= 0 && (differ > 0) == (s == FS_EXPECTATION_FAILED));
    fclose(null);
    return s;
}

static void test_equivalence(void)
{
    char tmp[] = "/tmp/fs_campaign_XXXXXX";
    CHECK(mkdtemp(tmp) != NULL);
    char dir[512];
    snprintf(dir, sizeof dir, "%s/base", tmp);
    write_summary(dir, NULL);
    CHECK(equivalent_to(tmp, "same", NULL) == FS_OK);
    CHECK(equivalent_to(tmp, "apart", apart) == FS_EXPECTATION_FAILED);
    CHECK(equivalent_to(tmp, "touching", touching) == FS_OK);
    CHECK(equivalent_to(tmp, "lean_in", lean_in_floor) == FS_OK);
    CHECK(equivalent_to(tmp, "lean_out", lean_past_floor) == FS_EXPECTATION_FAILED);
    CHECK(equivalent_to(tmp, "impulse_in", impulse_in) == FS_OK);
    CHECK(equivalent_to(tmp, "impulse_out", impulse_out) == FS_EXPECTATION_FAILED);
    CHECK(equivalent_to(tmp, "drop_in", drop_in_floor) == FS_OK);
    CHECK(equivalent_to(tmp, "drop_out", drop_past_floor) == FS_EXPECTATION_FAILED);
    CHECK(equivalent_to(tmp, "fall_drop", fall_drop_moved) == FS_OK);
    CHECK(equivalent_to(tmp, "none_landed", none_landed) == FS_OK);
    CHECK(compare_with(tmp, "none_landed_vs_base", none_landed) == FS_OK);
    CHECK(equivalent_to(tmp, "force", force_doubled) == FS_OK);
    CHECK(equivalent_to(tmp, "no_contacts", no_contacts) == FS_EXPECTATION_FAILED);
    /* a trial more left undecided, or hung, is not equivalent */
    CHECK(equivalent_to(tmp, "hung", one_hung) == FS_EXPECTATION_FAILED);
    CHECK(equivalent_to(tmp, "undecided", one_undecided) == FS_EXPECTATION_FAILED);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0);
}

static void test_load(void)
{
    static fs_campaign c;
    fs_error err;
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", NULL, 0, &c, &err) == FS_OK);
    CHECK(c.nfeet == 2 && c.nterrains == 3 && c.seeds == 5 && c.first_seed == 1 && !c.nsweep && !c.sweep[0][0]);
    CHECK(!strcmp(c.foot[1].name, "flat") && !strcmp(c.terrain[2].name, "complex_uneven"));
    CHECK(c.foot[0].path[0] == '/');
    CHECK(fs_campaign_ntrials(&c) == 60);
    /* each (foot, terrain) loaded once, with its foot and terrain */
    /* each cell (foot, terrain, robot; robot fastest) loaded once, with its foot, terrain and robot */
    CHECK(c.nrobots == 2 && !strcmp(c.robot[1].name, "drop_weight") && fs_campaign_ncells(&c) == 12);
    CHECK(fs_campaign_pair(&c, 10)->geom.kind == FS_FOOT_FLAT && fs_campaign_pair(&c, 4)->geom.kind == FS_FOOT_BIOMIMETIC);
    CHECK(fs_campaign_pair(&c, 10)->terrain.def.kind == FS_TERRAIN_COMPLEX_UNEVEN);
    CHECK(fs_campaign_pair(&c, 10)->def.robot.com_height_m == 0.3 && fs_campaign_pair(&c, 11)->def.robot.com_height_m == 0.02);
    fs_campaign_free(&c);
    const char *sets[] = {"campaign.seeds=2", "run.step_s=2e-4", "expect.e.foot=flat", "expect.e.terrain=flat",
                          "tolerance.peak_force_N=0.2, 3", "expect.e.robot=drop_weight"};
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", sets, 6, &c, &err) == FS_OK);
    CHECK(c.seeds == 2 && c.nset == 1 && !strcmp(c.set[0], "run.step_s=2e-4"));
    CHECK(c.nexpect == 1 && c.expect[0].foot == 1 && c.expect[0].terrain == 0 && c.expect[0].robot == 1 &&
          c.expect[0].min_success == 0);
    CHECK(c.tolerance[4][0] == 0.2 && c.tolerance[4][1] == 3);
    char buf[FS_CAMPAIGN_CELL_SETS][FS_PATH_MAX + 32];
    const char *ov[FS_CAMPAIGN_MAX_SET + FS_CAMPAIGN_CELL_SETS];
    CHECK(fs_campaign_overrides(&c, 10, buf, ov) == 4);
    CHECK(!strncmp(ov[0], "scenario.design=/", 17) && strstr(ov[0], "/scenarios/feet/flat.ini"));
    CHECK(strstr(ov[1], "/terrains/complex_uneven.ini") && strstr(ov[2], "robots/single_tall.ini") &&
          !strcmp(ov[3], "run.step_s=2e-4"));
    CHECK(fs_campaign_pair(&c, 3)->def.step_s == 2e-4); /* the trials' --set reached every cell */
    fs_campaign_free(&c);
    /* robots added by --set: a cell per foot, terrain and robot, robot fastest */
    const char *robots[] = {"robot.tall.file=robots/single_tall.ini", "robot.low.file=robots/drop_weight.ini",
                            "expect.e.foot=flat", "expect.e.terrain=flat", "expect.e.robot=low"};
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", robots, 5, &c, &err) == FS_OK);
    CHECK(c.nrobots == 4 && !strcmp(c.robot[3].name, "low") && fs_campaign_ntrials(&c) == 120);
    int foot, terrain, robot;
    fs_campaign_cell_of(&c, 15, &foot, &terrain, &robot);
    CHECK(foot == 1 && terrain == 0 && robot == 3 && c.expect[0].robot == 3);
    CHECK(fs_campaign_pair(&c, 15)->def.robot.com_height_m == 0.02 && fs_campaign_pair(&c, 14)->def.robot.com_height_m == 0.3);
    CHECK(fs_campaign_overrides(&c, 15, buf, ov) == 3 && strstr(ov[2], "robot.design=/") && strstr(ov[2], "drop_weight.ini"));
    fs_campaign_free(&c);
    /* a robot's own step: its cells only, said in the settings; a --set run.step_s still wins */
    const char *stepped[] = {"robot.tall.file=robots/single_tall.ini", "robot.low.file=robots/drop_weight.ini",
                             "robot.low.step_s=5e-4", "expect.e.foot=flat", "expect.e.terrain=flat",
                             "expect.e.robot=low", "run.step_s=2e-4"};
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", stepped, 6, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 15)->def.step_s == 5e-4 && fs_campaign_pair(&c, 14)->def.step_s == 1e-4);
    CHECK(fs_campaign_overrides(&c, 15, buf, ov) == 4 && !strcmp(ov[3], "run.step_s=0.00050000000000000001"));
    CHECK(strstr(c.provenance.settings, "; robot low: step_s 0.0005") != NULL &&
          strstr(c.provenance.settings, "robot tall") == NULL);
    fs_campaign_free(&c);
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", stepped, 7, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 15)->def.step_s == 2e-4 && fs_campaign_pair(&c, 14)->def.step_s == 2e-4);
    CHECK(strstr(c.provenance.settings, "; robot") == NULL);
    fs_campaign_free(&c);
    stepped[2] = "robot.low.step_s=1e-9"; /* below run.step_s's least; 0 would be the trial's step */
    CHECK(fs_campaign_load("scenarios/landing_ci.ini", stepped, 6, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "step_s = 1e-09 is below") && strstr(err.message, "give 0 for the trial's own step"));
    /* a robot's own error-controlled step: its cells only, said in the settings; a --set still wins */
    const char *tolerant[] = {"robot.tall.file=robots/single_tall.ini", "robot.low.file=robots/drop_weight.ini",
                              "robot.low.tolerance_m=1e-6", "robot.low.error_estimate=embedded",
                              "expect.e.foot=flat", "expect.e.terrain=flat", "expect.e.robot=low",
                              "run.tolerance_m=3e-6"};
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", tolerant, 7, &c, &err) == FS_OK);
    const fs_scenario_def *low = &fs_campaign_pair(&c, 15)->def, *tall = &fs_campaign_pair(&c, 14)->def;
    CHECK(low->tolerance_m == 1e-6 && low->error_estimate == FS_ESTIMATE_EMBEDDED);
    CHECK(tall->tolerance_m == 0 && tall->error_estimate == FS_ESTIMATE_DOUBLING);
    CHECK(fs_campaign_overrides(&c, 15, buf, ov) == 5 && !strcmp(ov[3], "run.tolerance_m=9.9999999999999995e-07") &&
          !strcmp(ov[4], "run.error_estimate=embedded"));
    CHECK(fs_campaign_overrides(&c, 14, buf, ov) == 3);
    const char *part = strstr(c.provenance.settings, "; robot");
    CHECK(part && !strcmp(part, "; robot low: tolerance_m 1e-06, error_estimate embedded"));
    fs_campaign_free(&c);
    /* its own step and tolerance, doubling: one part of the settings line */
    const char *both[] = {"robot.tall.file=robots/single_tall.ini", "robot.low.file=robots/drop_weight.ini",
                          "robot.low.tolerance_m=1e-6", "robot.low.error_estimate=doubling", "robot.low.step_s=5e-4",
                          "expect.e.foot=flat", "expect.e.terrain=flat", "expect.e.robot=low"};
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", both, 8, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 15)->def.error_estimate == FS_ESTIMATE_DOUBLING &&
          fs_campaign_pair(&c, 15)->def.tolerance_m == 1e-6 && fs_campaign_pair(&c, 15)->def.step_s == 5e-4);
    CHECK(fs_campaign_overrides(&c, 15, buf, ov) == 6 && !strcmp(ov[5], "run.error_estimate=doubling"));
    part = strstr(c.provenance.settings, "; robot");
    CHECK(part && !strcmp(part, "; robot low: step_s 0.0005, tolerance_m 1e-06, error_estimate doubling"));
    fs_campaign_free(&c);
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", tolerant, 8, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 15)->def.tolerance_m == 3e-6 && fs_campaign_pair(&c, 14)->def.tolerance_m == 3e-6);
    CHECK(fs_campaign_pair(&c, 15)->def.error_estimate == FS_ESTIMATE_EMBEDDED); /* the --set named no estimate */
    fs_campaign_free(&c);
    tolerant[2] = "robot.low.tolerance_m=0"; /* an estimate for no error-controlled step */
    CHECK(fs_campaign_load("scenarios/landing_ci.ini", tolerant, 7, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "error_estimate") && strstr(err.message, "give tolerance_m too"));
    tolerant[2] = "robot.low.tolerance_m=2"; /* past run.tolerance_m's range */
    CHECK(fs_campaign_load("scenarios/landing_ci.ini", tolerant, 7, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "tolerance_m = '2' is out of range") != NULL);
    /* with several robots an expectation must name its robot */
    const char *unnamed[] = {"robot.tall.file=robots/single_tall.ini", "robot.low.file=robots/drop_weight.ini",
                             "expect.e.foot=flat", "expect.e.terrain=flat"};
    CHECK(fs_campaign_load("scenarios/landing_ci.ini", unnamed, 4, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "robot = (a [robot.NAME])") != NULL);
}

static void test_sweep(void)
{
    static fs_campaign c;
    fs_error err;
    REQUIRE(fs_campaign_load("scenarios/roughness.ini", NULL, 0, &c, &err) == FS_OK);
    CHECK(!strcmp(c.sweep[0], "rough.rms_m") && c.nsweep == 1 && c.nterrains == 11 && c.nbase == 1);
    CHECK(!strcmp(c.terrain[3].name, "rough@0.003") && c.terrain[3].sweep_value[0] == 0.003);
    CHECK(c.terrain[10].sweep_value[0] == 0.02 && c.terrain[10].sweep_value[1] == 0);
    CHECK(c.nrobots == 2 && !strcmp(c.robot[1].name, "drop_weight"));
    /* the swept value in its cells: foot 0, terrain 3, each robot (cell = (foot * 11 + 3) * 2 + robot) */
    CHECK(fs_campaign_pair(&c, 6)->terrain.def.rms_m == 0.003 && fs_campaign_pair(&c, 7)->terrain.def.rms_m == 0.003);
    CHECK(fs_campaign_pair(&c, 7)->def.robot.com_height_m < fs_campaign_pair(&c, 6)->def.robot.com_height_m);
    fs_campaign_free(&c);
    /* no [robot.NAME]: the trial scenario's own robot, named after its file */
    char tmp[] = "/tmp/fs_campaign_XXXXXX", cwd[512], path[600];
    REQUIRE(mkdtemp(tmp) != NULL && getcwd(cwd, sizeof cwd) != NULL);
    snprintf(path, sizeof path, "%s/own_robot.ini", tmp);
    FILE *f = fopen(path, "w");
    REQUIRE(f != NULL);
    fprintf(f, "[campaign]\ntrial = %s/scenarios/landing_trial.ini\nseeds = 1\n\n[foot.flat]\nfile = "
               "%s/scenarios/feet/flat.ini\n\n[terrain.flat]\nfile = %s/terrains/flat.ini\n", cwd, cwd, cwd);
    fclose(f);
    REQUIRE(fs_campaign_load(path, NULL, 0, &c, &err) == FS_OK);
    CHECK(c.nrobots == 1 && !strcmp(c.robot[0].name, "single_tall") && fs_campaign_pair(&c, 0)->def.robot.mass_kg == 26);
    fs_campaign_free(&c);
    remove(path);
    rmdir(tmp);
    const char *bad[] = {"campaign.sweep_values=0, -0.001"};
    CHECK(fs_campaign_load("scenarios/roughness.ini", bad, 1, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "rms_m = '-0.001' is out of range") && strstr(err.message, "sweep_values"));
}

/* Two keys of the design and the robot swept over every pair of values, on each of two terrains. */
static void test_sweep_two_keys(void)
{
    static fs_campaign c;
    fs_error err;
    const char *set[] = {"campaign.sweep_values=1, 10", "campaign.sweep2_values=0.02, 0.1, 0.3", "campaign.seeds=1"};
    REQUIRE(fs_campaign_load("scenarios/envelope.ini", set, 3, &c, &err) == FS_OK);
    CHECK(c.nsweep == 2 && !strcmp(c.sweep[0], "springs.scale") && !strcmp(c.sweep[1], "robot.com_height_m"));
    CHECK(c.nbase == 2 && c.nvalues[0] == 2 && c.nvalues[1] == 3 && c.nterrains == 12 && fs_campaign_ntrials(&c) == 12);
    /* terrain-major, then the first key, then the second */
    const fs_campaign_item *p = &c.terrain[6 + 1 * 3 + 2];
    CHECK(!strcmp(p->name, "complex_uneven@10,0.3") && p->base == 1 && p->point[0] == 1 && p->point[1] == 2);
    CHECK(p->sweep_value[0] == 10 && p->sweep_value[1] == 0.3);
    const fs_scenario *sc = fs_campaign_pair(&c, 6 + 1 * 3 + 2);
    CHECK(sc->design.spring_scale == 10 && sc->geom.spring[0].k_N_per_m == 10 * sc->design.k_N_per_m[0]);
    CHECK(sc->def.robot.com_height_m == 0.3 && sc->terrain.def.kind == FS_TERRAIN_COMPLEX_UNEVEN);
    /* the stretched body: its mass's spread along z, (1.4 + 1.4 - 0.1) / 2, scales with the height
     * squared, the spread across (0.05 each way) stays */
    double I[3];
    fs_robot_inertia(&fs_campaign_pair(&c, 0)->def.robot, I);
    CHECK_NEAR(I[0], 0.05 + 1.35 * (0.02 / 0.3) * (0.02 / 0.3), 1e-12);
    CHECK(I[2] == 0.1);
    /* a point's name holds a comma: written quoted, every CSV row has the header's fields */
    char tmp[] = "/tmp/fs_sweep_csv_XXXXXX";
    REQUIRE(mkdtemp(tmp) != NULL);
    fs_trial_result *results = calloc((size_t)fs_campaign_ntrials(&c), sizeof *results);
    fs_campaign_row *rows = calloc((size_t)fs_campaign_ncells(&c), sizeof *rows);
    REQUIRE(results && rows);
    fs_campaign_summarize(&c, results, rows);
    CHECK(fs_campaign_write(&c, results, rows, tmp, &err) == FS_OK);
    const char *files[] = {"trials.csv", "summary.csv"};
    for (int k = 0; k < 2; k++) {
        char path[600], line[8192];
        snprintf(path, sizeof path, "%s/%s", tmp, files[k]);
        FILE *f = fopen(path, "r");
        REQUIRE(f != NULL);
        int header = -1, nrows = 0, last_quoted = 0;
        while (fgets(line, sizeof line, f)) {
            if (line[0] == '#')
                continue;
            int fields = 1, quoted = 0;
            for (const char *q = line; *q; q++)
                if (*q == '"')
                    quoted = !quoted;
                else if (*q == ',' && !quoted)
                    fields++;
            if (header < 0)
                header = fields;
            else {
                CHECK(fields == header);
                nrows++;
                last_quoted = strstr(line, ",\"complex_uneven@10,0.3\",") != NULL;
            }
        }
        fclose(f);
        CHECK(nrows == (k == 0 ? fs_campaign_ntrials(&c) : fs_campaign_ncells(&c)));
        CHECK(last_quoted);
    }
    free(results);
    free(rows);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    CHECK(system(cmd) == 0);
    fs_campaign_free(&c);
    /* the same key twice, and sweep2 alone, are refused */
    const char *twice[] = {"campaign.sweep2=springs.scale"};
    CHECK(fs_campaign_load("scenarios/envelope.ini", twice, 1, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "sweep two different keys") != NULL);
    const char *alone[] = {"campaign.sweep=none", "campaign.sweep_values=", "campaign.sweep2_values=0.1"};
    CHECK(fs_campaign_load("scenarios/envelope.ini", alone, 3, &c, &err) == FS_BAD_INPUT);
}

/* A sweep's points are typed edits of the loaded definitions, compiled: the same scenario, bit for
 * bit, as loading the trial with the swept value as --set; an integer key takes whole numbers only;
 * the relations the values enter are checked; --set of the swept key is refused. */
static void test_sweep_typed(void)
{
    static fs_campaign c;
    static fs_scenario loaded;
    fs_error err;
    const char *set[] = {"campaign.sweep_values=0.001, 0.004", "campaign.seeds=1"};
    REQUIRE(fs_campaign_load("scenarios/roughness.ini", set, 2, &c, &err) == FS_OK);
    for (int cell = 0; cell < fs_campaign_ncells(&c); cell++) {
        int f, t, r;
        fs_campaign_cell_of(&c, cell, &f, &t, &r);
        char buf[FS_CAMPAIGN_CELL_SETS][FS_PATH_MAX + 32];
        const char *ov[FS_CAMPAIGN_MAX_SET + FS_CAMPAIGN_CELL_SETS];
        int n = fs_campaign_overrides(&c, cell, buf, ov); /* the point's value among them, as --set */
        CHECK(!strcmp(ov[n - 1], t ? "rough.rms_m=0.0040000000000000001" : "rough.rms_m=0.001"));
        REQUIRE(fs_scenario_load(c.trial_path, ov, n, &loaded, &err) == FS_OK);
        const fs_scenario *sc = fs_campaign_pair(&c, cell);
        CHECK(sc->terrain.def.rms_m == (t ? 0.004 : 0.001) && sc->terrain.nx == loaded.terrain.nx &&
              sc->terrain.ny == loaded.terrain.ny && sc->terrain.x0 == loaded.terrain.x0 &&
              sc->terrain.y0 == loaded.terrain.y0);
        CHECK(sc->terrain.nx == loaded.terrain.nx && sc->terrain.ny == loaded.terrain.ny &&
              !memcmp(sc->terrain.z, loaded.terrain.z, sizeof(double) * (size_t)loaded.terrain.nx * (size_t)loaded.terrain.ny));
        CHECK(sc->def.robot.com_height_m == loaded.def.robot.com_height_m && sc->def.step_s == loaded.def.step_s &&
              sc->geom.total_mass_kg == loaded.geom.total_mass_kg);
        fs_scenario_free(&loaded);
    }
    fs_campaign_free(&c);
    /* an integer key: whole numbers only, each point its own value */
    const char *seeds[] = {"campaign.sweep=rough.seed", "campaign.sweep_values=3, 4"};
    REQUIRE(fs_campaign_load("scenarios/roughness.ini", seeds, 2, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 0)->terrain.def.seed == 3 && fs_campaign_pair(&c, 2)->terrain.def.seed == 4);
    fs_campaign_free(&c);
    const char *half[] = {"campaign.sweep=rough.seed", "campaign.sweep_values=3, 4.5"};
    CHECK(fs_campaign_load("scenarios/roughness.ini", half, 2, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "seed = '4.5' is not a whole number") && strstr(err.message, "sweep_values"));
    /* an unset log interval follows a swept step; a step too short for the window is refused */
    const char *steps[] = {"campaign.sweep=run.step_s", "campaign.sweep_values=0.002, 0.0001"};
    REQUIRE(fs_campaign_load("scenarios/roughness.ini", steps, 2, &c, &err) == FS_OK);
    CHECK(fs_campaign_pair(&c, 0)->def.log_interval_s == 0.002 && fs_campaign_pair(&c, 2)->def.log_interval_s == 1e-3);
    fs_campaign_free(&c);
    const char *tiny[] = {"campaign.sweep=run.step_s", "campaign.sweep_values=0.001, 1e-7", "run.duration_s=1000"};
    CHECK(fs_campaign_load("scenarios/roughness.ini", tiny, 3, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "a run may take at most") && strstr(err.message, "set in code"));
    /* a swept log interval stays each point's own, also where a later point repeats the first's */
    const char *logs[] = {"campaign.sweep_values=0, 0.004", "campaign.sweep2=run.log_interval_s",
                          "campaign.sweep2_values=0.002, 0.005"};
    REQUIRE(fs_campaign_load("scenarios/roughness.ini", logs, 3, &c, &err) == FS_OK);
    for (int cell = 0; cell < fs_campaign_ncells(&c); cell++) {
        int f, t, r;
        fs_campaign_cell_of(&c, cell, &f, &t, &r);
        CHECK(fs_campaign_pair(&c, cell)->def.log_interval_s == c.terrain[t].sweep_value[1]);
    }
    fs_campaign_free(&c);
    /* the file's relations are judged on each point's values, not on the file's own value of the
       swept key: height_max_m swept from 0.05 with height_min_m set to 0.045 is valid everywhere */
    const char *rocks[] = {"campaign.sweep=rocks.height_max_m", "campaign.sweep_values=0.05, 0.08",
                           "campaign.sweep2=none", "campaign.sweep2_values=", "rocks.height_min_m=0.045"};
    CHECK(fs_campaign_load("scenarios/envelope.ini", rocks, 5, &c, &err) == FS_OK);
    fs_campaign_free(&c);
    /* a point that leaves the trial without a robot is refused, as --set robot.mass_kg=0 is */
    const char *massless[] = {"campaign.sweep=robot.mass_kg", "campaign.sweep_values=26, 0"};
    CHECK(fs_campaign_load("scenarios/roughness.ini", massless, 2, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "has none (mass 0)") != NULL);
    /* one --set of the swept key would be overwritten by the sweep */
    const char *both[] = {"rough.rms_m=0.002"};
    CHECK(fs_campaign_load("scenarios/roughness.ini", both, 1, &c, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "is the key the campaign sweeps") != NULL);
}

FS_TEST_MAIN(TEST(test_wilson), TEST(test_median), TEST(test_summarize), TEST(test_expectations), TEST(test_compare), TEST(test_equivalence),
             TEST(test_load), TEST(test_sweep), TEST(test_sweep_two_keys),
             TEST(test_sweep_typed))
