/* Determinism: the static-load scenario's whole trajectory hashes to the value committed in
 * tests/determinism_static_load.txt, and a landing trial's state after every step to
 * tests/determinism_landing.txt (on a plane: ODE's contacts) and, on rough ground (footsim's own
 * heightfield contacts, both feet), to tests/determinism_landing_rough.txt, and the landing with an
 * error-controlled step to tests/determinism_landing_tolerance.txt, and with it on a soil and the
 * walking machine with it to tests/determinism_variable_soil_walk.txt. A change of the physics, the solver settings, the compiler's
 * floating-point contraction or the ODE build shows up here; if the change is meant, rewrite the
 * files with FS_HASH_UPDATE=1 build/tests/test_engine_determinism (from the source folder) and say
 * why in the commit. (That the same inputs give the same bits in one build is tested directly in
 * test_model_terrain and cli_campaign.sh.) */
#include "fs_test.h"

#include "footsim/experiment/fs_run.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/experiment/fs_walk.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_sim_soil.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static const char *HASH_FILE = "tests/determinism_static_load.txt";

/* FNV-1a over the bytes of every value. */
static uint64_t hash_rows(const fs_run_result *r)
{
    uint64_t h = 1469598103934665603ULL;
    const unsigned char *p = (const unsigned char *)r->rows;
    for (size_t i = 0; i < (size_t)r->nrows * r->ncols * sizeof(double); i++)
        h = (h ^ p[i]) * 1099511628211ULL;
    return h;
}

/* h against the value committed in file (FS_HASH_UPDATE=1: writes it instead). */
static void check_hash(const char *file, const char *what, uint64_t h)
{
    if (getenv("FS_HASH_UPDATE")) {
        FILE *f = fopen(file, "w");
        REQUIRE(f != NULL);
        fprintf(f, "%016" PRIx64 "\n", h);
        fclose(f);
        return;
    }
    FILE *f = fopen(file, "r");
    REQUIRE(f != NULL);
    uint64_t want = 0;
    CHECK(fscanf(f, "%" SCNx64, &want) == 1);
    fclose(f);
    if (h != want)
        fprintf(stderr, "  %s hash %016" PRIx64 ", committed %016" PRIx64 " (%s)\n", what, h, want, file);
    CHECK(h == want);
}

static void static_load_hashes_to_its_committed_value(void)
{
    static fs_scenario sc;
    fs_error err;
    fs_run_result r;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_run(&sc, NULL, &r, &err) == FS_OK);
    uint64_t h = hash_rows(&r);
    fs_run_free(&r);
    fs_scenario_free(&sc);
    check_hash(HASH_FILE, "trajectory", h);
}

/* After every step of a landing trial: every body's position, orientation and velocities, and the
 * contact count (so collision and contact changes show, not only the springs' and hinges'). */
static fs_status hash_state(void *user, const fs_sim *sim, fs_error *err)
{
    (void)err;
    uint64_t *h = user;
    for (int i = 0; i < sim->geom->nbodies + (sim->robot != NULL); i++) {
        dBodyID b = i < sim->geom->nbodies ? sim->body[i] : sim->robot;
        const dReal *v[4] = {dBodyGetPosition(b), dBodyGetQuaternion(b), dBodyGetLinearVel(b), dBodyGetAngularVel(b)};
        for (int k = 0; k < 4; k++) {
            const unsigned char *p = (const unsigned char *)v[k];
            for (size_t j = 0; j < (k == 1 ? 4 : 3) * sizeof(dReal); j++)
                *h = (*h ^ p[j]) * 1099511628211ULL;
        }
    }
    *h = (*h ^ (uint64_t)sim->contacts_now) * 1099511628211ULL;
    return FS_OK;
}

/* The default landing trial (seed 1: the biomimetic foot under single_tall on flat ground, from
 * the drop to the fall) hashes to tests/determinism_landing.txt. */
static void landing_trial_hashes_to_its_committed_value(void)
{
    uint64_t h = 1469598103934665603ULL;
    fs_run_observer obs = {.interval_s = 1e-12, .fn = hash_state, .user = &h};
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", NULL, 0, 1, &obs, &r, &err) == FS_OK);
    CHECK(r.steps > 1000);
    check_hash("tests/determinism_landing.txt", "landing trial", h);
    /* rigid ground: no soil's measures (empty fields in a campaign's files) */
    CHECK(isnan(r.soil_sinkage_m) && isnan(r.print_depth_m) && isnan(r.print_area_m2) && isnan(r.print_volume_m3) &&
          isnan(r.print_slip_m));
}

/* The same on rough ground, for each foot (seed 4: the biomimetic foot under drop_weight lands,
 * the flat foot's box rocks on the roughness), their states hashed one after the other into one
 * value: footsim's own sphere and box contacts with a heightfield (sim_lattice.c). */
static void rough_landings_hash_to_their_committed_value(void)
{
    uint64_t h = 1469598103934665603ULL;
    fs_run_observer obs = {.interval_s = 1e-12, .fn = hash_state, .user = &h};
    const char *feet[] = {"scenario.design=feet/biomimetic.ini", "scenario.design=feet/flat.ini"};
    for (int k = 0; k < 2; k++) {
        const char *set[] = {"scenario.terrain=../terrains/rough.ini", "robot.design=robots/drop_weight.ini", feet[k]};
        fs_trial_result r;
        fs_error err;
        REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 3, 4, &obs, &r, &err) == FS_OK);
        CHECK(r.steps > 1000);
    }
    check_hash("tests/determinism_landing_rough.txt", "rough-ground landings", h);
}

/* The landing trial with an error-controlled step (run.tolerance_m = 1e-5 m; the biomimetic foot
 * under drop_weight, seed 1, from the drop to rest), its state after every accepted step hashed to
 * tests/determinism_landing_tolerance.txt: the steps it takes, rejects and the states it restores
 * are the same bits every run. */
static void variable_step_trial(const char *estimate, const char *file)
{
    uint64_t h = 1469598103934665603ULL;
    fs_run_observer obs = {.interval_s = 1e-12, .fn = hash_state, .user = &h};
    const char *set[] = {"robot.design=robots/drop_weight.ini", "run.tolerance_m=1e-5", estimate};
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 3, 1, &obs, &r, &err) == FS_OK);
    CHECK(r.rejected_steps > 0 && r.steps > 50);
    h = (h ^ (uint64_t)r.steps) * 1099511628211ULL;
    h = (h ^ (uint64_t)r.rejected_steps) * 1099511628211ULL;
    check_hash(file, "variable-step landing trial", h);
}

/* ... and the same trial under the embedded estimate (run.error_estimate = embedded):
 * tests/determinism_landing_embedded.txt. */
static void variable_step_trial_hashes_to_its_committed_value(void)
{
    variable_step_trial("run.error_estimate=doubling", "tests/determinism_landing_tolerance.txt");
    variable_step_trial("run.error_estimate=embedded", "tests/determinism_landing_embedded.txt");
}

/* A landing on soil (issue 29): the biomimetic foot under drop_weight onto dry sand, 0.2 s from the
 * drop through the impact, its states after every step, the soil nodes holding it and its print
 * hashed into one value (tests/determinism_landing_soil.txt). The rigid hashes above do not move
 * with the soil: nothing of its code runs without a [soil] section. */
static fs_status hash_soil(void *user, const fs_sim *sim, fs_error *err)
{
    uint64_t *h = user;
    hash_state(user, sim, err);
    const fs_soil_grid *g = fs_sim_soil_grid(sim);
    double v = fs_soil_grid_print(g, NULL, NULL);
    const unsigned char *p = (const unsigned char *)&v;
    for (size_t j = 0; j < sizeof v; j++)
        *h = (*h ^ p[j]) * 1099511628211ULL;
    *h = (*h ^ (uint64_t)fs_sim_soil_nodes(sim, -1)) * 1099511628211ULL;
    return FS_OK;
}

static void soil_landing_hashes_to_its_committed_value(void)
{
    uint64_t h = 1469598103934665603ULL;
    fs_run_observer obs = {.interval_s = 1e-12, .fn = hash_soil, .user = &h};
    const char *set[] = {"scenario.terrain=../terrains/soils/dry_sand.ini", "robot.design=robots/drop_weight.ini",
                         "run.duration_s=0.2"};
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 3, 1, &obs, &r, &err) == FS_OK);
    CHECK(r.steps > 1000);
    check_hash("tests/determinism_landing_soil.txt", "soil landing", h);
    /* the trial's soil measures (fs_trial_result): 0.2 s is past the impact (touchdown at 32 ms),
     * the foot in the sand and its print made. Every node's plastic sinkage is at most the deepest,
     * so the volume is at most the depth times the area; nothing goes past the 100 mm layer. */
    CHECK(r.soil_sinkage_m > 0 && r.soil_sinkage_m <= 0.1 + 1e-12);
    CHECK(r.print_depth_m > 0 && r.print_depth_m <= 0.1 + 1e-12 && r.print_area_m2 > 0);
    CHECK(r.print_volume_m3 > 0 && r.print_volume_m3 <= r.print_depth_m * r.print_area_m2 * (1 + 1e-12));
    CHECK(r.print_slip_m >= 0 && isfinite(r.print_slip_m));
}

/* Variable steps on a soil and in the walking machine (issue 30: the same inputs give the same bits
 * whatever ran before): the soil landing above at 1e-5 m under the embedded estimate (its rejected
 * steps put the soil back: fs_soil_grid_undo), then one step of the walking machine on LETE sand (2 mm
 * grid) at 1e-5 m by step doubling (the carriage driven at each ODE step, the press), their states
 * after every accepted step, the soil's with them, hashed one after the other into
 * tests/determinism_variable_soil_walk.txt. */
static void variable_steps_on_soil_and_walking_hash_to_their_committed_value(void)
{
    uint64_t h = 1469598103934665603ULL;
    fs_run_observer obs = {.interval_s = 1e-12, .fn = hash_soil, .user = &h};
    const char *set[] = {"scenario.terrain=../terrains/soils/dry_sand.ini", "robot.design=robots/drop_weight.ini",
                         "run.duration_s=0.2", "run.tolerance_m=1e-5", "run.error_estimate=embedded"};
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run("scenarios/landing_trial.ini", set, 5, 1, &obs, &r, &err) == FS_OK);
    CHECK(r.rejected_steps > 0 && r.steps > 50);
    static fs_scenario sc;
    const char *walk[] = {"walk.steps=1", "scenario.terrain=../terrains/soils/lete_sand.ini", "soil.grid_m=0.002",
                          "run.tolerance_m=1e-5"};
    REQUIRE(fs_scenario_load("scenarios/walking.ini", walk, 4, &sc, &err) == FS_OK);
    static fs_walk_result w;
    REQUIRE(fs_walk_run(&sc, &obs, &w, &err) == FS_OK);
    CHECK(w.steps_completed == 1 && w.nsteps == 1);
    fs_scenario_free(&sc);
    check_hash("tests/determinism_variable_soil_walk.txt", "variable steps on soil and walking", h);
}

/* The end of a quickstep run, which draws on ODE's random generator to order its constraints. */
static double quickstep_end(const char *duration)
{
    static fs_scenario sc;
    fs_error err;
    fs_run_result r;
    const char *set[] = {"run.stepper=quickstep", duration};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 2, &sc, &err) == FS_OK);
    REQUIRE(fs_run(&sc, NULL, &r, &err) == FS_OK);
    double z = r.ankle_end_m[2];
    fs_run_free(&r);
    fs_scenario_free(&sc);
    return z;
}

/* A quickstep run gives the same bits whatever ran before it in the process (campaign workers and
 * benchmarks run many). */
static void quickstep_does_not_depend_on_earlier_runs(void)
{
    double first = quickstep_end("run.duration_s=1");
    quickstep_end("run.duration_s=0.05");
    double again = quickstep_end("run.duration_s=1");
    CHECK(memcmp(&first, &again, sizeof first) == 0);
}

/* FNV-1a over every body's position, orientation and velocities now. */
static uint64_t state_hash(const fs_sim *sim, uint64_t h)
{
    for (int i = 0; i <= sim->geom->nbodies; i++) {
        dBodyID b = i < sim->geom->nbodies ? sim->body[i] : sim->robot;
        if (!b)
            continue;
        const dReal *v[4] = {dBodyGetPosition(b), dBodyGetRotation(b), dBodyGetLinearVel(b), dBodyGetAngularVel(b)};
        const int n[4] = {3, 12, 3, 3};
        for (int k = 0; k < 4; k++) {
            const unsigned char *p = (const unsigned char *)v[k];
            for (size_t j = 0; j < n[k] * sizeof(dReal); j++)
                h = (h ^ p[j]) * 1099511628211ULL;
        }
    }
    return h;
}

enum { NSIMS = 5, REENTRANT_STEPS = 1200 };

/* Five different simulations (even ground; the biomimetic foot dropped on rough ground, where
 * the contact scratch works hardest; the flat foot on complex uneven ground; and a pair stepped
 * with QuickStep, which draws on ODE's random generator: each sim keeps its own generator's
 * state), each hashed after every step into one value per sim. interleaved: one step of each in
 * turn; otherwise each alone. */
static void hash_sims(int interleaved, uint64_t out[NSIMS])
{
    static const char *sets[NSIMS][4] = {
        {"run.duration_s=1", NULL, NULL, NULL},
        {"scenario.terrain=../terrains/rough.ini", "start.drop_m=0.01", "start.yaw_deg=5", NULL},
        {"scenario.terrain=../terrains/complex_uneven.ini", "foot.kind=flat", "start.drop_m=0.01", NULL},
        {"run.stepper=quickstep", "run.duration_s=1", NULL, NULL},
        {"run.stepper=quickstep", "scenario.terrain=../terrains/rough.ini", "start.drop_m=0.01", NULL},
    };
    static fs_scenario sc[NSIMS];
    fs_sim sim[NSIMS];
    fs_error err;
    for (int k = 0; k < NSIMS; k++) {
        int n = 0;
        while (n < 4 && sets[k][n])
            n++;
        REQUIRE(fs_scenario_load("scenarios/static_load.ini", sets[k], n, &sc[k], &err) == FS_OK);
        out[k] = 1469598103934665603ULL;
    }
    if (interleaved) {
        for (int k = 0; k < NSIMS; k++)
            REQUIRE(fs_sim_build(&sim[k], &sc[k], NULL, &err) == FS_OK);
        for (int i = 0; i < REENTRANT_STEPS; i++)
            for (int k = 0; k < NSIMS; k++) {
                REQUIRE(fs_sim_step(&sim[k], &err) == FS_OK);
                out[k] = state_hash(&sim[k], out[k]);
            }
        for (int k = 0; k < NSIMS; k++)
            fs_sim_destroy(&sim[k]);
    } else {
        for (int k = 0; k < NSIMS; k++) {
            REQUIRE(fs_sim_build(&sim[k], &sc[k], NULL, &err) == FS_OK);
            for (int i = 0; i < REENTRANT_STEPS; i++) {
                REQUIRE(fs_sim_step(&sim[k], &err) == FS_OK);
                out[k] = state_hash(&sim[k], out[k]);
            }
            fs_sim_destroy(&sim[k]);
        }
    }
    for (int k = 0; k < NSIMS; k++)
        fs_scenario_free(&sc[k]);
}

/* Re-entrancy: simulations built in one process and stepped interleaved give, step by step, the
 * bits each gives alone (everything a step uses lives in its fs_sim; fs_sim.h). */
static void interleaved_sims_give_the_bits_of_each_alone(void)
{
    uint64_t alone[NSIMS], together[NSIMS];
    hash_sims(0, alone);
    hash_sims(1, together);
    for (int k = 0; k < NSIMS; k++) {
        if (alone[k] != together[k])
            fprintf(stderr, "  sim %d: %016" PRIx64 " alone, %016" PRIx64 " interleaved\n", k, alone[k], together[k]);
        CHECK(alone[k] == together[k]);
    }
    for (int a = 0; a < NSIMS; a++) /* different runs, or the test proves nothing */
        for (int b = a + 1; b < NSIMS; b++)
            CHECK(alone[a] != alone[b]);
}

FS_TEST_MAIN(TEST(static_load_hashes_to_its_committed_value), TEST(landing_trial_hashes_to_its_committed_value),
             TEST(rough_landings_hash_to_their_committed_value), TEST(variable_step_trial_hashes_to_its_committed_value),
             TEST(soil_landing_hashes_to_its_committed_value),
             TEST(variable_steps_on_soil_and_walking_hash_to_their_committed_value),
             TEST(quickstep_does_not_depend_on_earlier_runs),
             TEST(interleaved_sims_give_the_bits_of_each_alone))
