/* campaign_internal.h: what the campaign layer's files share and nothing above it sees. */
#ifndef FS_CAMPAIGN_INTERNAL_H
#define FS_CAMPAIGN_INTERNAL_H

#include "footsim/campaign/fs_campaign.h"

#include <cjson/cJSON.h>
#include <math.h>

/* The cell of foot on terrain under robot. */
static inline int fs_campaign_cell(const fs_campaign *c, int foot, int terrain, int robot)
{
    return (foot * c->nterrains + terrain) * c->nrobots + robot;
}

/* The summary row of foot on terrain under robot. */
static inline const fs_campaign_row *fs_campaign_row_of(const fs_campaign *c, const fs_campaign_row *rows, int foot,
                                                        int terrain, int robot)
{
    return &rows[fs_campaign_cell(c, foot, terrain, robot)];
}

/* The expectation holds: the success rate within [min_success, max_success]. */
static inline int fs_expectation_met(const fs_expectation *e, const fs_campaign_row *r)
{
    return r->success_rate >= e->min_success && r->success_rate <= e->max_success;
}

/* A summary.json read and parsed (campaign_compare.c): a regular file of at most
 * FS_SUMMARY_MAX_BYTES holding JSON with "rows"; NULL (FS_BAD_INPUT, said in err) otherwise. The
 * caller frees it with cJSON_Delete. */
cJSON *fs_campaign_read_summary(const char *path, fs_error *err);

/* A text field of a summary's object: "?" when missing. */
static inline const char *text_of(const cJSON *row, const char *key)
{
    const char *s = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(row, key));
    return s ? s : "?";
}

/* A number of a summary's object: NAN when it is null or missing. */
static inline double number_of(const cJSON *row, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(row, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

#endif
