/* api_campaign.c: campaigns behind a handle of footsim/api/fs_api.h: loaded with overrides, run
 * by the library's campaign runner (fs_campaign_run.h) with a callback of plain scalars. */
#include "footsim/api/fs_api.h"
#include "footsim/campaign/fs_campaign_run.h"

#include <stdlib.h>
#include <string.h>

struct fs_campaign_handle {
    fs_campaign c;
    char path[FS_PATH_MAX];
    char **set; /* the overrides, owned (c keeps pointers to them) */
    int nset;
};

static void free_sets(char **set, int n)
{
    for (int i = 0; set && i < n; i++)
        free(set[i]);
    free(set);
}

fs_campaign_handle *fs_campaign_open(const char *path, const char *const *overrides, int noverrides, fs_error *err)
{
    if (!path || noverrides < 0 || noverrides > FS_CAMPAIGN_MAX_SET || (noverrides && !overrides)) {
        fs_fail(err, FS_BAD_INPUT, "campaign: give a campaign file and at most %d overrides", FS_CAMPAIGN_MAX_SET);
        return NULL;
    }
    fs_campaign_handle *h = calloc(1, sizeof *h);
    char **set = calloc((size_t)(noverrides > 0 ? noverrides : 1), sizeof *set);
    int ok = h && set;
    for (int i = 0; ok && i < noverrides; i++)
        ok = (set[i] = strdup(overrides[i] ? overrides[i] : "")) != NULL;
    if (!ok) {
        free_sets(set, noverrides);
        free(h);
        fs_fail(err, FS_NO_MEMORY, "%s: no memory for the campaign", path);
        return NULL;
    }
    h->set = set;
    h->nset = noverrides;
    snprintf(h->path, sizeof h->path, "%s", path);
    if (fs_campaign_load(path, (const char *const *)set, noverrides, &h->c, err) != FS_OK) {
        free_sets(set, noverrides);
        free(h);
        return NULL;
    }
    return h;
}

void fs_campaign_close(fs_campaign_handle *h)
{
    if (!h)
        return;
    fs_campaign_free(&h->c);
    free_sets(h->set, h->nset);
    free(h);
}

const char *fs_campaign_title(const fs_campaign_handle *h) { return h->c.name; }
int fs_campaign_trial_count(const fs_campaign_handle *h) { return fs_campaign_ntrials(&h->c); }
int fs_campaign_cell_count(const fs_campaign_handle *h) { return fs_campaign_ncells(&h->c); }

/* The caller's scalar callback behind the library's. */
typedef struct relay {
    fs_campaign_progress_cb cb;
    void *user;
} relay;

static int relay_progress(const fs_campaign_progress *p, void *user)
{
    const relay *r = user;
    return r->cb(p->done, p->total, p->failed, p->say, r->user);
}

fs_status fs_campaign_execute(fs_campaign_handle *h, const char *dir, int jobs, int shard, int nshards, int flags,
                              fs_campaign_progress_cb progress, void *user, int *how, fs_error *err)
{
    if (how)
        *how = FS_CAMPAIGN_FAILED;
    if (!dir || !*dir)
        return fs_fail(err, FS_BAD_INPUT, "campaign %s: give the results folder", h->c.name);
    int sharded = shard != 0 || nshards != 0;
    if (sharded && (nshards < 1 || nshards > FS_CAMPAIGN_MAX_TRIALS || shard < 1 || shard > nshards))
        return fs_fail(err, FS_BAD_INPUT, "shard %d/%d: give the I-th of N shares, 1 <= I <= N (or 0/0: the whole "
                       "campaign)", shard, nshards);
    fs_journal_head head;
    fs_status s = fs_journal_head_of(&h->c, h->path, (const char *const *)h->set, h->nset, sharded ? shard : 1,
                                     sharded ? nshards : 1, &head, err);
    if (s != FS_OK)
        return s;
    relay r = {progress, user};
    fs_campaign_run_opts o = {.jobs = jobs, .shard = shard, .nshards = nshards, .fresh = (flags & FS_CAMPAIGN_FRESH) != 0,
                              .replace = (flags & FS_CAMPAIGN_REPLACE) != 0, .progress = progress ? relay_progress : NULL,
                              .user = &r};
    fs_campaign_state st;
    int rs = fs_campaign_run(&h->c, &head, dir, &o, NULL, &st, err);
    fs_journal_head_free(&head);
    if (how && rs == FS_OK)
        *how = st.finished_already ? FS_CAMPAIGN_ALREADY : st.stopped ? FS_CAMPAIGN_STOPPED : FS_CAMPAIGN_DONE;
    return (fs_status)rs;
}
