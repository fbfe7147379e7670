/* Determinism: the static-load scenario's whole trajectory hashes to the value committed in
 * tests/determinism_static_load.txt. A change of the physics, the solver settings, the compiler's
 * floating-point contraction or the ODE build shows up here; if the change is meant, rewrite the
 * file with FS_HASH_UPDATE=1 build/tests/test_engine_determinism (from the source folder) and say
 * why in the commit. (That the same inputs give the same bits in one build is tested directly in
 * test_model_terrain and cli_campaign.sh.) */
#include "fs_test.h"

#include "footsim/experiment/fs_run.h"

#include <inttypes.h>
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
    if (getenv("FS_HASH_UPDATE")) {
        FILE *f = fopen(HASH_FILE, "w");
        REQUIRE(f != NULL);
        fprintf(f, "%016" PRIx64 "\n", h);
        fclose(f);
        return;
    }
    FILE *f = fopen(HASH_FILE, "r");
    REQUIRE(f != NULL);
    uint64_t want = 0;
    CHECK(f && fscanf(f, "%" SCNx64, &want) == 1);
    if (f)
        fclose(f);
    if (h != want)
        fprintf(stderr, "  trajectory hash %016" PRIx64 ", committed %016" PRIx64 "\n", h, want);
    CHECK(h == want);
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

FS_TEST_MAIN(TEST(static_load_hashes_to_its_committed_value), TEST(quickstep_does_not_depend_on_earlier_runs))
