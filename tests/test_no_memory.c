/* Out of memory while a result's JSON tree is built. cJSON's adds fail silently (the field is left
 * out), so a builder that did not check them would write a result with a field missing and report
 * success. Here cJSON's allocator (cJSON_InitHooks) refuses its k-th allocation, for every k until
 * a build needs no refusal: the model dump (fs_model_json) and a run's metrics.json (fs_run_write)
 * must each be either whole (the text made without any refusal) or refused with FS_NO_MEMORY and
 * nothing written; never a tree short of a field. */
#include "fs_test.h"

#include "footsim/experiment/fs_run.h"
#include "footsim/io/fs_input.h"
#include "footsim/sim/fs_sim.h"

#include <cJSON.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

static long allocs_left = LONG_MAX; /* allocations cJSON gets before the one refused */
static int refused;                 /* whether one was */

static void *refusing_malloc(size_t n)
{
    if (allocs_left-- == 0) {
        refused = 1;
        return NULL;
    }
    return malloc(n);
}

/* Refuses the k-th allocation cJSON makes from now on, and only that one (k = 0: the first; LONG_MAX:
 * none), so that each allocation, the print included, is refused in turn. */
static void refuse_after(long k)
{
    allocs_left = k;
    refused = 0;
}

static void model_dump_is_whole_or_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    cJSON *whole = fs_model_json(&sc, &err);
    REQUIRE(whole != NULL);
    char *want = cJSON_Print(whole);
    REQUIRE(want != NULL);
    cJSON_Delete(whole);
    cJSON_Hooks hooks = {refusing_malloc, free};
    cJSON_InitHooks(&hooks);
    int refusals = 0, partial = 0;
    for (long k = 0; k < 100000; k++) {
        refuse_after(k);
        fs_error e = {FS_OK, ""};
        cJSON *root = fs_model_json(&sc, &e);
        int was_refused = refused;
        refuse_after(LONG_MAX);
        if (!root) {
            refusals++;
            CHECK(was_refused && e.status == FS_NO_MEMORY);
            continue;
        }
        char *got = cJSON_Print(root);
        cJSON_Delete(root);
        partial += strcmp(got, want) != 0;
        free(got);
        if (!was_refused)
            break; /* every allocation the build makes has been refused once */
    }
    cJSON_InitHooks(NULL);
    printf("  model dump: %d builds refused, %d partial\n", refusals, partial);
    CHECK(refusals > 100); /* the dump makes hundreds of nodes: each refusal was tried */
    CHECK(partial == 0);
    free(want);
    fs_scenario_free(&sc);
}

static char *read_text(const char *path)
{
    char *text = NULL;
    size_t len;
    fs_error err;
    return fs_read_regular(path, 1 << 20, "metrics.json", &text, &len, &err) == FS_OK ? text : NULL;
}

static void run_metrics_are_whole_or_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"run.duration_s=0.01"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 1, &sc, &err) == FS_OK);
    fs_run_result r;
    REQUIRE(fs_run(&sc, NULL, &r, &err) == FS_OK);
    char dir[] = "/tmp/footsim-nomem-XXXXXX", path[64], csv[64];
    REQUIRE(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/metrics.json", dir);
    snprintf(csv, sizeof csv, "%s/trajectory.csv", dir);
    REQUIRE(fs_run_write(&sc, &r, dir, &err) == FS_OK);
    char *want = read_text(path);
    REQUIRE(want != NULL);
    cJSON_Hooks hooks = {refusing_malloc, free};
    cJSON_InitHooks(&hooks);
    int refusals = 0, partial = 0;
    for (long k = 0; k < 10000; k++) {
        unlink(path);
        refuse_after(k);
        fs_error e = {FS_OK, ""};
        fs_status s = fs_run_write(&sc, &r, dir, &e);
        int was_refused = refused;
        refuse_after(LONG_MAX);
        if (s != FS_OK) {
            refusals++;
            CHECK(was_refused && s == FS_NO_MEMORY && access(path, F_OK) != 0);
            continue;
        }
        char *got = read_text(path);
        partial += !got || strcmp(got, want) != 0;
        free(got);
        if (!was_refused)
            break;
    }
    cJSON_InitHooks(NULL);
    printf("  metrics.json: %d writes refused, %d partial\n", refusals, partial);
    CHECK(refusals > 20);
    CHECK(partial == 0);
    free(want);
    unlink(path);
    unlink(csv);
    rmdir(dir);
    fs_run_free(&r);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(model_dump_is_whole_or_refused), TEST(run_metrics_are_whole_or_refused))
