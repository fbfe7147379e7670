/* Tests of the embeddable interface (footsim/api/fs_api.h): opaque handles, errors as status and
 * message, accessors into caller arrays, each checked against the physics or against the layer it
 * wraps. */
#include "fs_test.h"

#include "footsim/api/fs_api.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_sim.h"

#include <stdlib.h>
#include <unistd.h>

static fs_scenario *open_sc(const char *path, const char *const *sets, int n)
{
    fs_error err;
    fs_scenario *sc = fs_scenario_open(path, sets, n, &err);
    if (!sc)
        fprintf(stderr, "%s\n", err.message);
    return sc;
}

/* Overrides reach the scenario; bad input comes back as FS_BAD_INPUT with footsim's message. */
static void scenario_opens_with_overrides_and_refuses_bad_input(void)
{
    const char *sets[] = {"run.step_s=2e-4", "robot.mass_kg=30"};
    fs_scenario *sc = open_sc("scenarios/landing_trial.ini", sets, 2);
    REQUIRE(sc);
    double v = 0;
    fs_error err;
    CHECK(fs_scenario_get(sc, "run.step_s", &v, &err) == FS_OK && v == 2e-4);
    CHECK(fs_scenario_get(sc, "robot.mass_kg", &v, &err) == FS_OK && v == 30);
    CHECK(fs_scenario_get(sc, "run.no_such_key", &v, &err) == FS_BAD_INPUT && strstr(err.message, "no_such_key"));
    CHECK(!strcmp(fs_scenario_title(sc), "landing_trial") && fs_scenario_trial(sc) == 1);
    fs_scenario_close(sc);

    const char *bad[] = {"run.step_s=5"};
    err.status = FS_OK;
    CHECK(fs_scenario_open("scenarios/landing_trial.ini", bad, 1, &err) == NULL);
    CHECK(err.status == FS_BAD_INPUT && strstr(err.message, "step_s"));
    CHECK(fs_scenario_open("scenarios/no_such.ini", NULL, 0, &err) == NULL && err.status == FS_BAD_INPUT &&
          strstr(err.message, "no_such.ini"));
    /* the file's own line is named */
    char dir[] = "/tmp/fs_api_XXXXXX", path[64];
    REQUIRE(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/bad.ini", dir);
    FILE *f = fopen(path, "w");
    REQUIRE(f);
    fprintf(f, "[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nstep_s = -1\n", FS_SOURCE_DIR);
    fclose(f);
    CHECK(fs_scenario_open(path, NULL, 0, &err) == NULL && err.status == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, 4, "step_s");
    remove(path);
    rmdir(dir);
    fs_scenario_close(NULL); /* harmless */
}

/* The static load settled: the ground carries the load and the foot (the contacts' forces sum to
 * their weight), the springs' stored energy is the sum of k (L - rest)^2 / 2 over the lengths the
 * accessor gives, and the time is the steps taken times the step. */
static void sim_settles_and_its_accessors_agree(void)
{
    fs_scenario *sc = open_sc("scenarios/static_load.ini", NULL, 0);
    REQUIRE(sc);
    fs_error err;
    fs_sim *sim = fs_sim_open(sc, &err);
    fs_scenario_close(sc); /* the sim keeps its own copy */
    REQUIRE(sim);
    const fs_foot_geom *g = fs_sim_geom(sim);
    int n = fs_sim_body_count(sim);
    CHECK(n == g->nbodies && n == 12); /* heel, talus and five chains of two; no robot */
    CHECK(fs_sim_body_index(sim, "talus") >= 0 && !strcmp(fs_sim_body_name(sim, fs_sim_body_index(sim, "talus")), "talus"));
    CHECK(fs_sim_body_index(sim, "robot") == -1 && fs_sim_body_name(sim, n) == NULL);
    REQUIRE(fs_sim_advance(sim, 3000, &err) == FS_OK);
    CHECK_NEAR(fs_sim_time(sim), 3000 * 1e-4, 1e-12);
    CHECK(fs_sim_step_size(sim) == 1e-4 && !fs_sim_dead(sim));

    double mass = 26, masses[64];
    REQUIRE(n <= 64);
    fs_sim_body_masses(sim, masses);
    for (int b = 0; b < n; b++)
        mass += masses[b];
    CHECK(mass > 26 && masses[0] == g->body[0].mass_kg);
    int nc = fs_sim_contact_count(sim);
    CHECK(nc > 0);
    double *pos = malloc(sizeof(double) * 3 * (size_t)(nc > 0 ? nc : 1)), *force = malloc(sizeof(double) * 3 * (size_t)(nc > 0 ? nc : 1));
    REQUIRE(pos && force);
    CHECK(fs_sim_contacts(sim, pos, force, nc) == nc);
    double fz = 0, zmax = -1;
    for (int i = 0; i < nc; i++) {
        fz += force[3 * i + 2];
        zmax = fmax(zmax, fabs(pos[3 * i + 2]));
    }
    CHECK_NEAR(fz, mass * 9.81, 0.01 * mass * 9.81); /* at rest: 1 % (the motion left at 0.3 s) */
    CHECK(zmax < 2e-3);                               /* on the flat ground at z = 0, within the layer */
    CHECK(fs_sim_contacts(sim, pos, NULL, 1) == (nc > 0 ? 1 : 0));
    free(pos);
    free(force);

    int ns = fs_sim_spring_count(sim);
    CHECK(ns == 15 && fs_sim_spring_name(sim, 0) && fs_sim_spring_name(sim, ns) == NULL);
    double F[64], L[64], e_springs = 0;
    REQUIRE(ns <= 64);
    fs_sim_spring_forces(sim, F, L);
    for (int i = 0; i < ns; i++) {
        double x = L[i] - g->spring[i].rest_length_m;
        e_springs += 0.5 * g->spring[i].k_N_per_m * x * x;
    }
    double ek, ep, ee, e = fs_sim_energies(sim, &ek, &ep, &ee);
    CHECK_NEAR(ee, e_springs, 1e-9 + 1e-6 * e_springs);
    CHECK_NEAR(e, ek + ep + ee, 1e-12);
    CHECK(ek < 1e-3); /* settled */

    double p[64 * 3], R[64 * 9], v[64 * 3], w[64 * 3];
    fs_sim_poses(sim, p, R);
    fs_sim_velocities(sim, v, w);
    for (int b = 0; b < n; b++) {
        double d = 0; /* R is a rotation: its rows are unit vectors */
        for (int k = 0; k < 3; k++)
            d += R[9 * b + k] * R[9 * b + k];
        CHECK_NEAR(d, 1, 1e-9);
        CHECK(fabs(v[3 * b + 2]) < 0.02 && p[3 * b + 2] > 0 && p[3 * b + 2] < 0.1);
    }
    double a[3];
    fs_sim_ankle_position(sim, a);
    CHECK(a[2] > 0.01 && a[2] < 0.1);
    double speed, loop, excess;
    fs_sim_check_worst(sim, &speed, &loop, &excess);
    CHECK(speed > 0 && speed < fs_sim_scenario(sim)->def.check_max_speed_m_per_s && loop >= 0 &&
          loop < fs_sim_scenario(sim)->def.check_max_loop_error_m);
    fs_sim_close(sim);
    fs_sim_close(NULL);
}

/* A torque about z on the ankle body, in the air (no contact, gravity along z exerts none about
 * it), turns the foot one way, its opposite the other way; a bad body or torque is refused. */
static void torque_turns_the_foot_and_bad_ones_are_refused(void)
{
    fs_scenario *sc = open_sc("scenarios/landing_trial.ini", NULL, 0);
    REQUIRE(sc);
    fs_error err;
    fs_sim *s[3] = {fs_sim_open(sc, &err), fs_sim_open(sc, &err), fs_sim_open(sc, &err)};
    REQUIRE(s[0] && s[1] && s[2]);
    int n = fs_sim_body_count(s[0]);
    CHECK(n == fs_sim_geom(s[0])->nbodies + 1 && !strcmp(fs_sim_body_name(s[0], n - 1), "robot"));
    double masses[64];
    fs_sim_body_masses(s[0], masses);
    CHECK(masses[n - 1] == 26); /* single_tall */
    int talus = fs_sim_body_index(s[0], "talus");
    REQUIRE(talus >= 0);
    const double tz[3] = {0, 5, -5};
    for (int k = 0; k < 3; k++) {
        REQUIRE(fs_sim_apply_torque(s[k], talus, (double[3]){0, 0, tz[k]}, &err) == FS_OK);
        REQUIRE(fs_sim_advance(s[k], 10, &err) == FS_OK);
        CHECK(fs_sim_contact_count(s[k]) == 0);
    }
    double w[3][64 * 3];
    for (int k = 0; k < 3; k++)
        fs_sim_velocities(s[k], NULL, w[k]);
    CHECK(fabs(w[0][3 * talus + 2]) < 1e-9);
    CHECK(w[1][3 * talus + 2] > 1e-3 && w[2][3 * talus + 2] < -1e-3);
    CHECK(fs_sim_apply_torque(s[0], n, (double[3]){0, 0, 1}, &err) == FS_BAD_INPUT && strstr(err.message, "body"));
    CHECK(fs_sim_apply_torque(s[0], 0, (double[3]){0, NAN, 1}, &err) == FS_BAD_INPUT);
    for (int k = 0; k < 3; k++)
        fs_sim_close(s[k]);
    fs_scenario_close(sc);
}

/* A trial through the handle is fs_trial_run's, bit for bit; it touches down after the free fall
 * from its drop (sqrt(2 drop / g)); its metrics are named; a scenario that is no trial is refused. */
static void trial_is_the_library_s_and_named(void)
{
    fs_scenario *sc = open_sc("scenarios/landing_trial.ini", NULL, 0);
    REQUIRE(sc);
    fs_error err;
    fs_trial_result *r = fs_trial_open(sc, 3, &err);
    REQUIRE(r);
    fs_trial_result direct;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", NULL, 0, 3, NULL, &direct, &err) == FS_OK);
    CHECK(!strcmp(fs_trial_outcome(r), fs_outcome_name(direct.outcome)));
    CHECK(!strcmp(fs_trial_rule(r), fs_rule_name(direct.rule)) && fs_trial_seed(r) == 3);
    CHECK(!strcmp(fs_trial_failure(r), ""));
    int m = fs_trial_metric_find("touchdown_s"), steps = fs_trial_metric_find("steps");
    REQUIRE(m >= 0 && steps >= 0 && fs_trial_metric_count() == 18);
    CHECK(!strcmp(fs_trial_metric_name(m), "touchdown_s") && fs_trial_metric_name(18) == NULL);
    CHECK(fs_trial_metric_find("nothing") == -1 && isnan(fs_trial_metric(r, -1)));
    CHECK_NEAR(fs_trial_metric(r, m), sqrt(2 * 0.005 / 9.81), 0.003); /* the pose's tilt moves it a little */
    CHECK(fs_trial_metric(r, m) == direct.touchdown_s && fs_trial_metric(r, steps) == (double)direct.steps);
    CHECK_NEAR(fs_trial_metric(r, fs_trial_metric_find("end_time_s")), direct.steps * 1e-4, 1e-9);
    fs_trial_close(r);
    fs_scenario_close(sc);

    sc = open_sc("scenarios/static_load.ini", NULL, 0);
    REQUIRE(sc);
    CHECK(fs_trial_open(sc, 1, &err) == NULL && err.status == FS_BAD_INPUT && strstr(err.message, "footsim run"));
    fs_scenario_close(sc);
}

/* The stiffness model is symmetric and positive definite; the law's demand is m g h and its
 * critical height K / (m g); a stiff enough foot stands the robot and the Table I foot does not
 * (docs/landing.md's finding); a flat foot has no chains; a scenario without robot has no law. */
static void stiffness_and_law(void)
{
    fs_scenario *sc = open_sc("scenarios/landing_trial.ini", NULL, 0);
    REQUIRE(sc);
    fs_error err;
    double K[4], K4[4];
    REQUIRE(fs_scenario_chain_stiffness(sc, 2, K, K4, &err) == FS_OK);
    CHECK_NEAR(K[1], K[2], 1e-9 * fabs(K[0]));
    CHECK(K[0] > 0 && K[0] * K[3] - K[1] * K[2] > 0 && K4[0] > 0);
    CHECK(fs_scenario_chain_stiffness(sc, 5, K, NULL, &err) == FS_BAD_INPUT);
    fs_scenario *design = fs_scenario_open_design("scenarios/feet/biomimetic.ini", NULL, 0, &err);
    REQUIRE(design);
    double Kd[4];
    REQUIRE(fs_scenario_chain_stiffness(design, 2, Kd, NULL, &err) == FS_OK);
    CHECK(!memcmp(K, Kd, sizeof K)); /* the scenario's foot is that design */
    fs_scenario_close(design);
    const char *soft[] = {"springs.k_d1_N_per_m=1000"};
    design = fs_scenario_open_design("scenarios/feet/biomimetic.ini", soft, 1, &err);
    REQUIRE(design);
    REQUIRE(fs_scenario_chain_stiffness(design, 2, Kd, NULL, &err) == FS_OK);
    CHECK(Kd[0] < K[0]); /* a softer d1 spring, a softer chain */
    fs_scenario_close(design);
    CHECK(fs_scenario_open_design("scenarios/feet/none.ini", NULL, 0, &err) == NULL && err.status == FS_BAD_INPUT);
    double Kp;
    REQUIRE(fs_scenario_pitch_stiffness(sc, 26 * 9.81, &Kp, &err) == FS_OK);
    CHECK(Kp > 0);
    double m = 26, h = 0.3, gg = 9.81, Kl, demand, hc, lean;
    int stands = -1;
    REQUIRE(fs_scenario_pitch_law(sc, NAN, &Kl, &demand, &hc, &lean, &stands, &err) == FS_OK);
    CHECK_NEAR(demand, m * gg * h, 1e-9);
    CHECK_NEAR(hc, Kl / (m * gg), 1e-12);
    CHECK(stands == 0 && Kl < demand);
    REQUIRE(fs_scenario_pitch_law(sc, 1e6, &Kl, NULL, NULL, &lean, &stands, &err) == FS_OK);
    CHECK(stands == 1 && Kl == 1e6);
    CHECK_NEAR(lean, m * gg * 0.03 / (1e6 - m * gg * h), 1e-12); /* m g x / (K - m g h) */
    CHECK(fs_scenario_pitch_law(sc, -1, &Kl, NULL, NULL, NULL, NULL, &err) == FS_BAD_INPUT);
    fs_scenario_close(sc);

    const char *flat[] = {"scenario.design=feet/flat.ini"};
    sc = open_sc("scenarios/static_load.ini", flat, 1);
    REQUIRE(sc);
    CHECK(fs_scenario_chain_stiffness(sc, 0, K, NULL, &err) == FS_BAD_INPUT && strstr(err.message, "flat"));
    CHECK(fs_scenario_pitch_law(sc, NAN, &Kl, NULL, NULL, NULL, NULL, &err) == FS_BAD_INPUT);
    fs_scenario_close(sc);
}

/* What the campaign's scalar callback saw. */
typedef struct campaign_seen {
    int calls, last_done, total, stop_at;
} campaign_seen;

static int campaign_progress(int done, int total, int failed, const char *say, void *user)
{
    campaign_seen *s = user;
    (void)failed;
    if (say)
        return 1;
    s->calls++, s->last_done = done, s->total = total;
    return !(s->stop_at && done >= s->stop_at);
}

/* A campaign behind its handle: counted, refused with file:line, stopped by its callback's 0 (the
 * journal kept, no folder), then finished by the same call; run again, nothing to do. */
static void campaign_runs_stops_and_resumes(void)
{
    char dir[64], ini[128], out[128];
    snprintf(dir, sizeof dir, "/tmp/fs_api_campaign_XXXXXX");
    REQUIRE(mkdtemp(dir) != NULL);
    snprintf(ini, sizeof ini, "%s/two.ini", dir);
    snprintf(out, sizeof out, "%s/out", dir);
    FILE *f = fopen(ini, "w");
    REQUIRE(f != NULL);
    fprintf(f, "[campaign]\ntrial = %s/scenarios/campaign_test_trial.ini\nseeds = 2\n[foot.bio]\nfile = %s/scenarios/feet/"
            "biomimetic.ini\n[foot.flat]\nfile = %s/scenarios/feet/flat.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n",
            FS_SOURCE_DIR, FS_SOURCE_DIR, FS_SOURCE_DIR, FS_SOURCE_DIR);
    fclose(f);
    fs_error err;
    const char *bad[] = {"campaign.seeds=0"};
    CHECK(fs_campaign_open(ini, bad, 1, &err) == NULL && err.status == FS_BAD_INPUT && strstr(err.message, "seeds"));
    const char *sets[] = {"run.duration_s=0.1"};
    fs_campaign_handle *c = fs_campaign_open(ini, sets, 1, &err);
    REQUIRE(c != NULL);
    CHECK(!strcmp(fs_campaign_title(c), "two") && fs_campaign_trial_count(c) == 4 && fs_campaign_cell_count(c) == 2);
    int how = -5;
    CHECK(fs_campaign_execute(c, out, 2, 3, 2, 0, campaign_progress, NULL, &how, &err) == FS_BAD_INPUT &&
          how == FS_CAMPAIGN_FAILED);
    campaign_seen stop = {.stop_at = 1};
    CHECK(fs_campaign_execute(c, out, 2, 0, 0, 0, campaign_progress, &stop, &how, &err) == FS_OK);
    CHECK(how == FS_CAMPAIGN_STOPPED && stop.total == 4 && access(out, F_OK) != 0);
    char journal[160];
    snprintf(journal, sizeof journal, "%s.journal/journal", out);
    CHECK(access(journal, F_OK) == 0);
    campaign_seen go = {0};
    CHECK(fs_campaign_execute(c, out, 2, 0, 0, 0, campaign_progress, &go, &how, &err) == FS_OK);
    CHECK(how == FS_CAMPAIGN_DONE && go.last_done == 4 && access(journal, F_OK) != 0);
    char summary[160];
    snprintf(summary, sizeof summary, "%s/summary.json", out);
    CHECK(access(summary, F_OK) == 0);
    CHECK(fs_campaign_execute(c, out, 1, 0, 0, 0, NULL, NULL, &how, &err) == FS_OK && how == FS_CAMPAIGN_ALREADY);
    fs_campaign_close(c);
    fs_remove_tree(dir);
}

FS_TEST_MAIN(TEST(scenario_opens_with_overrides_and_refuses_bad_input), TEST(sim_settles_and_its_accessors_agree),
             TEST(torque_turns_the_foot_and_bad_ones_are_refused), TEST(trial_is_the_library_s_and_named),
             TEST(stiffness_and_law), TEST(campaign_runs_stops_and_resumes))
