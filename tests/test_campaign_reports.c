/* Tests of campaign_reports.c (fs_report.h): trial.json, walk.json and the stiffness report, made by
 * the library. A trial's JSON holds its seed, outcome, rule, pose, every campaign metric by name and
 * each foot of a biped; every JSON builder is whole or refused (FS_NO_MEMORY) when cJSON's k-th
 * allocation is refused, for every k (never a tree with a field left out); the stiffness report of
 * the biomimetic foot agrees with the model within 1 %, carries the analytic stiffness
 * fs_stiffness_analytic gives, tells the law for the shipped robots by name, and its JSON and text
 * say the same; a flat sole's report has no chains. */
#include "fs_test.h"
#include "fs_test_refuse.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/campaign/fs_report.h"

#include <stdlib.h>

static fs_trial_result made_up(int nfeet)
{
    fs_trial_result r;
    memset(&r, 0, sizeof r);
    r.draw.seed = 7;
    r.draw.x_m = 0.01, r.draw.yaw_deg = 12;
    r.outcome = FS_LANDED;
    r.rule = FS_RULE_AT_REST;
    r.robot_mass_kg = 26;
    r.peak_force_N = 1234.5;
    r.ankle_drop_m = 0.004;
    r.steps = 1500;
    r.nfeet = nfeet;
    for (int f = 0; f < nfeet; f++)
        r.foot[f].touchdown_s = 0.03 + 0.01 * f;
    return r;
}

static void test_trial_json_holds_the_result(void)
{
    fs_trial_result r = made_up(2);
    fs_error err;
    cJSON *o = fs_trial_json(&r, &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetObjectItem(o, "seed")->valuedouble == 7);
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "outcome")), "landed"));
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "rule")), fs_rule_name(FS_RULE_AT_REST)));
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(o, "pose_x_y_m_yaw_pitch_roll_deg")) == 5);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        CHECK(cJSON_GetObjectItem(o, fs_campaign_metrics[m].name) != NULL);
    CHECK(cJSON_GetObjectItem(o, "peak_force_N")->valuedouble == 1234.5);
    CHECK(cJSON_GetObjectItem(cJSON_GetObjectItem(o, "steps_taken"), "accepted")->valuedouble == 1500);
    cJSON *feet = cJSON_GetObjectItem(o, "feet");
    CHECK(cJSON_GetArraySize(feet) == 2);
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(cJSON_GetArrayItem(feet, 1), "foot")), "left"));
    cJSON_Delete(o);
    r = made_up(1);
    o = fs_trial_json(&r, &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetObjectItem(o, "feet") == NULL); /* one foot: no per-foot list */
    cJSON_Delete(o);
    fs_walk_result w = {.steps_completed = 4, .falls = 1, .peak_force_N = 900};
    o = fs_walk_json(&w, "flat", &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetObjectItem(o, "steps_completed")->valuedouble == 4 &&
          !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(o, "foot")), "flat"));
    cJSON_Delete(o);
    o = fs_walk_json(&w, NULL, &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetObjectItem(o, "foot") == NULL);
    CHECK(cJSON_GetObjectItem(o, "soil_steps") == NULL); /* rigid ground: no step records */
    cJSON_Delete(o);
    /* on a soil each step's record says whether its stance was on the soil (a section's edge) */
    w.soil = 1, w.nsteps = 2;
    w.step[0] = (fs_walk_step){.sinkage_m = 0, .on_soil = 0};
    w.step[1] = (fs_walk_step){.sinkage_m = 0.015, .on_soil = 1};
    o = fs_walk_json(&w, NULL, &err);
    REQUIRE(o != NULL);
    cJSON *steps = cJSON_GetObjectItem(o, "soil_steps");
    CHECK(cJSON_GetArraySize(steps) == 2);
    CHECK(cJSON_IsFalse(cJSON_GetObjectItem(cJSON_GetArrayItem(steps, 0), "on_soil")));
    CHECK(cJSON_IsTrue(cJSON_GetObjectItem(cJSON_GetArrayItem(steps, 1), "on_soil")));
    CHECK(cJSON_GetObjectItem(cJSON_GetArrayItem(steps, 1), "sinkage_m")->valuedouble == 0.015);
    cJSON_Delete(o);
}

/* The builders: a trial's, a walk's and a stiffness report's JSON. */
static cJSON *trial_of(const void *r, fs_error *err) { return fs_trial_json(r, err); }
static cJSON *walk_of(const void *r, fs_error *err) { return fs_walk_json(r, "biomimetic", err); }
static cJSON *report_of(const void *r, fs_error *err) { return fs_stiffness_report_json(r, "feet/x.ini", err); }

static int whole_or_refused(fs_json_builder make, const void *what)
{
    int partial;
    int refusals = fs_json_whole_or_refused(make, what, &partial);
    CHECK(partial == 0);
    return refusals;
}

static fs_stiffness_report report;

static void test_stiffness_report(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *design = FS_SOURCE_DIR "/scenarios/feet/biomimetic.ini";
    REQUIRE(fs_scenario_for_design(design, NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_stiffness_report_make(&sc, design, NULL, &report, &err) == FS_OK);
    CHECK(!report.flat && fs_stiffness_report_agrees(&report) && report.worst <= FS_STIFFNESS_TOLERANCE);
    fs_chain_stiffness k[FS_CHAINS];
    fs_stiffness_analytic(&sc.geom, k);
    for (int i = 0; i < FS_CHAINS; i++)
        CHECK(!memcmp(k[i].exact, report.chain[i].exact, sizeof k[i].exact));
    /* the shipped robots beside scenarios/feet/, sorted by name, each told */
    CHECK(report.nrobots >= 3);
    for (int i = 1; i < report.nrobots; i++)
        CHECK(strcmp(report.robot[i - 1], report.robot[i]) < 0);
    CHECK(report.K_model > 0 && report.K_ode_mu1 > 0 && report.load_kg == sc.design.design_load_kg);
    cJSON *o = fs_stiffness_report_json(&report, "feet/x.ini", &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(o, "chains")) == FS_CHAINS);
    CHECK(cJSON_GetObjectItem(o, "max_rel_diff")->valuedouble == report.worst);
    cJSON *robots = cJSON_GetObjectItem(cJSON_GetObjectItem(o, "pitch_stiffness"), "robots");
    CHECK(cJSON_GetArraySize(robots) == report.nrobots);
    /* Table I's springs are linear: no loaded-pose stiffness (its K is the neutral one; the report
       stays as it was; a nonlinear design's line: cli_paths.sh) */
    CHECK(!report.nonlinear && cJSON_GetObjectItem(cJSON_GetObjectItem(o, "static_check"), "loaded_stiffness") == NULL);
    cJSON_Delete(o);
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    REQUIRE(m != NULL);
    fs_stiffness_report_print(&report, "feet/x.ini", m);
    fclose(m);
    CHECK(strstr(text, "feet/x.ini: joint stiffness per chain") != NULL && strstr(text, "): agree\n") != NULL);
    CHECK(strstr(text, report.robot[0]) != NULL);
    CHECK(strstr(text, "gripping equilibrium (eqs. 1-3") == NULL);
    free(text);
    fs_scenario_free(&sc);
    /* a flat sole: its pitch stiffness only */
    static fs_scenario flat;
    static fs_stiffness_report fr;
    const char *fd = FS_SOURCE_DIR "/scenarios/feet/flat.ini";
    REQUIRE(fs_scenario_for_design(fd, NULL, 0, &flat, &err) == FS_OK);
    REQUIRE(fs_stiffness_report_make(&flat, fd, NULL, &fr, &err) == FS_OK);
    CHECK(fr.flat && fs_stiffness_report_agrees(&fr) && fr.K_model > 0);
    o = fs_stiffness_report_json(&fr, "flat.ini", &err);
    REQUIRE(o != NULL);
    CHECK(cJSON_GetObjectItem(o, "chains") == NULL && cJSON_GetObjectItem(o, "pitch_stiffness") != NULL);
    cJSON_Delete(o);
    fs_scenario_free(&flat);
}

static void test_every_builder_is_whole_or_refused(void)
{
    fs_trial_result r = made_up(2);
    fs_walk_result w = {.steps_completed = 4};
    CHECK(whole_or_refused(trial_of, &r) > 30);
    CHECK(whole_or_refused(walk_of, &w) >= 8);
    if (report.K_model > 0) /* made by test_stiffness_report */
        CHECK(whole_or_refused(report_of, &report) > 100);
}

FS_TEST_MAIN(TEST(test_trial_json_holds_the_result), TEST(test_stiffness_report),
             TEST(test_every_builder_is_whole_or_refused))
