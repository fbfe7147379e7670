/* cli_merge.c: `footsim merge DIR... [--out DIR]`: the shard folders of one campaign (footsim
 * campaign --shard I/N) made into its files by the library (fs_campaign_merge), the chart drawn,
 * the summary printed as the campaign prints it. */
#include "cli.h"

#include "footsim/campaign/fs_campaign_run.h"

#include <stdio.h>
#include <stdlib.h>

/* What merge works on, too large for the stack: on the heap, one per command. */
typedef struct merge_work {
    fs_campaign_merged m;
    cli_campaign_files x;
    fs_campaign_state st;
} merge_work;

int cli_merge(const cli_args *a)
{
    int n = 1 + a->nmore, s = 0;
    const char **dirs = malloc((size_t)n * sizeof *dirs);
    merge_work *w = calloc(1, sizeof *w);
    if (!dirs || !w) {
        free(dirs), free(w);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    dirs[0] = a->input;
    for (int i = 1; i < n; i++)
        dirs[i] = a->more[i - 1];
    fs_error err = {FS_OK, ""};
    fs_campaign_merged *m = &w->m;
    s = fs_campaign_merge(dirs, n, a->force, m, &err);
    if (s == FS_OK && m->other_version)
        fprintf(stderr, "footsim merge: --force: the shards were run by another footsim version (%s); their trials "
                "are merged as they are and summarized by this version\n", m->version_note);
    if (s != FS_OK && m->missing_shard) {
        char run[4 * FS_OUT_PATH], shard[32];
        snprintf(shard, sizeof shard, "%d/%d", m->missing_shard, m->head.nshards);
        cli_args again = {.input = m->head.campaign, .shard = shard, .nset = m->head.nset};
        for (int i = 0; i < m->head.nset; i++)
            again.set[i] = m->head.set[i];
        cli_campaign_command(&again, "DIR", run, sizeof run);
        fprintf(stderr, "footsim merge: %s: %s\n", err.message, run);
    } else if (s != FS_OK) {
        fprintf(stderr, "footsim merge: %s\n", err.message);
    }
    char dir[FS_OUT_PATH];
    if (!s)
        s = cli_results_dir(a, "campaigns", m->c.name, dir, sizeof dir);
    fs_campaign_row *rows = s ? NULL : malloc((size_t)fs_campaign_ncells(&m->c) * sizeof *rows);
    if (!s && !rows)
        s = cli_report(FS_NO_MEMORY, "out of memory");
    if (!s) {
        fs_campaign_run_opts o = {.extra = cli_campaign_files_add, .user = &w->x};
        s = fs_campaign_merge_write(m, dir, a->replace, &o, rows, &w->st, &err);
        if (s == FS_OK)
            s = cli_campaign_report(&m->c, rows, w->st.dir, w->x.drawn);
        else if (s == (int)err.status && err.message[0])
            fprintf(stderr, "footsim merge: %s\n", err.message);
    }
    fs_campaign_merge_free(m);
    free(dirs), free(w), free(rows);
    return s;
}
