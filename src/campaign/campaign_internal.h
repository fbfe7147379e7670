/* campaign_internal.h: what the campaign layer's files share and nothing above it sees. */
#ifndef FS_CAMPAIGN_INTERNAL_H
#define FS_CAMPAIGN_INTERNAL_H

#include "footsim/campaign/fs_campaign.h"

/* The summary row of foot on terrain. */
static inline const fs_campaign_row *fs_campaign_row_of(const fs_campaign *c, const fs_campaign_row *rows, int foot,
                                                        int terrain)
{
    return &rows[foot * c->nterrains + terrain];
}

/* The expectation holds: the success rate within [min_success, max_success]. */
static inline int fs_expectation_met(const fs_expectation *e, const fs_campaign_row *r)
{
    return r->success_rate >= e->min_success && r->success_rate <= e->max_success;
}

#endif
