/* Out of memory while a result's JSON tree is built. cJSON's adds fail silently (the field is left
 * out), so a builder that did not check them would write a result with a field missing and report
 * success. Here cJSON's allocator (cJSON_InitHooks) refuses its k-th allocation, for every k until
 * a build needs no refusal: the model dump (fs_model_json), a run's metrics.json (fs_run_write) and a
 * campaign's summary.json (fs_campaign_write_summary) must each be either whole (the text made
 * without any refusal) or refused with FS_NO_MEMORY and nothing written; never one short of a field. */
#include "fs_test.h"
#include "fs_test_refuse.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/io/fs_input.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/export/fs_export.h"

#include <cJSON.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

static cJSON *model_of(const void *sc, fs_error *err) { return fs_model_json(sc, err); }

static void model_dump_is_whole_or_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    int partial;
    int refusals = fs_json_whole_or_refused(model_of, &sc, &partial);
    printf("  model dump: %d builds refused, %d partial\n", refusals, partial);
    CHECK(refusals > 100); /* the dump makes hundreds of nodes: each refusal was tried */
    CHECK(partial == 0);
    fs_scenario_free(&sc);
}

static char *read_text(const char *path)
{
    char *text = NULL;
    size_t len;
    fs_error err;
    return fs_read_regular(path, 1 << 22, "a result", &text, &len, &err) == FS_OK ? text : NULL;
}

/* A writer of one result file name into a folder. */
typedef fs_status (*writer)(const void *ctx, const char *dir, fs_error *err);

/* write(ctx) with each of cJSON's allocations refused in turn: dir/name is then the file written
 * without a refusal, or the write fails with FS_NO_MEMORY and leaves no file. Returns how many
 * writes were refused, and counts the partial files written into *partial. */
static int whole_or_refused(writer write, const void *ctx, const char *name, int *partial)
{
    /* in memory where there is a tmpfs: each write fsyncs, a thousand times over */
    char dir[64], path[128];
    snprintf(dir, sizeof dir, "%s/footsim-nomem-XXXXXX", access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp");
    REQUIRE(mkdtemp(dir) != NULL);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    fs_error err;
    REQUIRE(write(ctx, dir, &err) == FS_OK);
    char *want = read_text(path);
    REQUIRE(want != NULL);
    cJSON_Hooks hooks = {refusing_malloc, free};
    cJSON_InitHooks(&hooks);
    int refusals = 0;
    *partial = 0;
    for (long k = 0; k < 100000; k++) {
        unlink(path);
        refuse_after(k);
        fs_error e = {FS_OK, ""};
        fs_status s = write(ctx, dir, &e);
        int was_refused = refused;
        refuse_after(LONG_MAX);
        if (s != FS_OK) {
            refusals++;
            CHECK(was_refused && s == FS_NO_MEMORY && access(path, F_OK) != 0);
            continue;
        }
        char *got = read_text(path);
        *partial += !got || strcmp(got, want) != 0;
        free(got);
        if (!was_refused)
            break; /* every allocation the write makes has been refused once */
    }
    cJSON_InitHooks(NULL);
    free(want);
    char rm[160];
    snprintf(rm, sizeof rm, "rm -rf '%s'", dir);
    CHECK(system(rm) == 0);
    return refusals;
}

typedef struct run_ctx {
    const fs_scenario *sc;
    const fs_run_result *r;
    const fs_provenance *prov;
} run_ctx;

static fs_status write_run(const void *ctx, const char *dir, fs_error *err)
{
    const run_ctx *x = ctx;
    return fs_run_write(x->sc, x->r, x->prov, dir, err);
}

static void run_metrics_are_whole_or_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"run.duration_s=0.01"};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 1, &sc, &err) == FS_OK);
    fs_run_result r;
    REQUIRE(fs_run(&sc, NULL, &r, &err) == FS_OK);
    fs_provenance prov = {.ninputs = 0};
    REQUIRE(fs_scenario_provenance(&sc, set, 1, &prov, &err) == FS_OK);
    run_ctx x = {&sc, &r, &prov};
    int partial, refusals = whole_or_refused(write_run, &x, "metrics.json", &partial);
    printf("  metrics.json: %d writes refused, %d partial\n", refusals, partial);
    CHECK(refusals > 20); /* about as many allocations as fields: each was refused */
    CHECK(partial == 0);
    fs_provenance_free(&prov);
    fs_run_free(&r);
    fs_scenario_free(&sc);
}

typedef struct summary_ctx {
    const fs_campaign *c;
    const fs_campaign_row *rows;
} summary_ctx;

static fs_status write_summary(const void *ctx, const char *dir, fs_error *err)
{
    const summary_ctx *x = ctx;
    return fs_campaign_write_summary(x->c, x->rows, dir, err);
}

static void campaign_summary_is_whole_or_refused(void)
{
    static fs_campaign c;
    fs_error err;
    REQUIRE(fs_campaign_load("scenarios/landing_ci.ini", NULL, 0, &c, &err) == FS_OK);
    int n = fs_campaign_ncells(&c);
    fs_campaign_row *rows = calloc((size_t)n, sizeof *rows);
    REQUIRE(rows != NULL);
    for (int i = 0; i < n; i++) /* rows as a summary gives them, numbers made up */
        fs_campaign_cell_of(&c, i, &rows[i].foot, &rows[i].terrain, &rows[i].robot), rows[i].trials = 5,
            rows[i].landed = i % 6, rows[i].success_rate = rows[i].landed / 5.0;
    summary_ctx x = {&c, rows};
    int partial, refusals = whole_or_refused(write_summary, &x, "summary.json", &partial);
    printf("  summary.json: %d writes refused, %d partial\n", refusals, partial);
    CHECK(refusals > 100); /* a dozen rows of twenty fields */
    CHECK(partial == 0);
    free(rows);
    fs_campaign_free(&c);
}

FS_TEST_MAIN(TEST(model_dump_is_whole_or_refused), TEST(run_metrics_are_whole_or_refused),
             TEST(campaign_summary_is_whole_or_refused))
