/* campaign_internal.h: what the campaign layer's files share and nothing above it sees. */
#ifndef FS_CAMPAIGN_INTERNAL_H
#define FS_CAMPAIGN_INTERNAL_H

#include "footsim/campaign/fs_campaign.h"

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

#endif
