/* fs_test_refuse.h: cJSON's allocator made to refuse its k-th allocation (cJSON_InitHooks with
 * fs_refusing_malloc), for the tests that check a JSON builder is whole or refused, never partial
 * (test_no_memory, test_campaign_reports). Include it after fs_test.h. */
#ifndef FS_TEST_REFUSE_H
#define FS_TEST_REFUSE_H

#include <cJSON.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

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

/* A JSON builder: a tree made of what, or NULL with err set. */
typedef cJSON *(*fs_json_builder)(const void *what, fs_error *err);

/* Builds with each of cJSON's allocations refused in turn: each build must be whole (the text of a
 * build without any refusal) or refused with FS_NO_MEMORY, never partial (counted in *partial).
 * Returns how many builds were refused. */
static int fs_json_whole_or_refused(fs_json_builder make, const void *what, int *partial)
{
    fs_error err;
    cJSON *full = make(what, &err);
    REQUIRE(full != NULL);
    char *want = cJSON_Print(full);
    cJSON_Delete(full);
    REQUIRE(want != NULL);
    cJSON_Hooks hooks = {refusing_malloc, free};
    cJSON_InitHooks(&hooks);
    int refusals = 0;
    *partial = 0;
    for (long k = 0; k < 100000; k++) {
        refuse_after(k);
        fs_error e = {FS_OK, ""};
        cJSON *root = make(what, &e);
        int was_refused = refused;
        refuse_after(LONG_MAX);
        if (!root) {
            refusals++;
            CHECK(was_refused && e.status == FS_NO_MEMORY);
            continue;
        }
        char *got = cJSON_Print(root);
        cJSON_Delete(root);
        *partial += !got || strcmp(got, want) != 0;
        free(got);
        if (!was_refused)
            break; /* every allocation the build makes has been refused once */
    }
    cJSON_InitHooks(NULL);
    free(want);
    return refusals;
}

#endif
