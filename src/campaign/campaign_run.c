/* campaign_run.c: a campaign's trials in the worker pool, resumed from its journal, a shard of
 * it, the shards merged, and its files put in place whole (fs_campaign_run.h). Moved out of the
 * command (app/cli_campaign.c) so that any program runs campaigns as the command does. */
#include "footsim/campaign/fs_campaign_run.h"

#include "footsim/exec/fs_pool.h"
#include "footsim/io/fs_output.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A worker's answer to one trial. */
typedef struct message {
    int status; /* fs_trial_run's */
    fs_trial_result result;
    char error[FS_ERROR_MAX];
} message;

/* The caller's side of a run: its callback and hooks, and whether it asked to stop. */
typedef struct caller {
    fs_campaign_progress_fn progress;
    void *user;
    fs_campaign_test_hooks test;
    volatile sig_atomic_t stop; /* the callback returned 0 (the pool polls it) */
    int done, total, failed;    /* the last state told */
} caller;

static const fs_campaign_test_hooks no_hooks = {-1, -1, -1, 0, 0, 0};

static void caller_init(caller *k, const fs_campaign_run_opts *o)
{
    memset(k, 0, sizeof *k);
    k->progress = o ? o->progress : NULL;
    k->user = o ? o->user : NULL;
    k->test = o && o->test ? *o->test : no_hooks;
}

/* Tells the caller the state (and a line, when say is not NULL); its 0 sets stop. */
static void tell(caller *k, const char *say)
{
    fs_campaign_progress p = {k->done, k->total, k->failed, say};
    if (k->progress && !k->progress(&p, k->user))
        k->stop = 1;
}

static void say(caller *k, const char *format, ...)
{
    char line[2 * FS_OUT_PATH];
    va_list ap;
    va_start(ap, format);
    vsnprintf(line, sizeof line, format, ap);
    va_end(ap);
    tell(k, line);
}

/* What the pool's callbacks share. */
typedef struct trials_run {
    const fs_campaign *c;
    fs_trial_result *results;
    const int *index;       /* the trial index of each pool task, or NULL: the task number */
    int already;            /* trials done before this run (the journal's) */
    fs_journal *journal;    /* where each finished trial goes, or NULL */
    const unsigned char *killed_before; /* per trial index: its worker was killed once already, or NULL */
    int records, final_records; /* records journaled; those that are final (not a first kill) */
    fs_status journal_status; /* a journal write that failed in record_death, for the next take_one */
    fs_error journal_err;
    caller *k;
} trials_run;

static int trial_index(const trials_run *p, int task) { return p->index ? p->index[task] : task; }

/* Whether trial index's result is the first kill of its worker: the trial runs once more. */
static int first_kill(const trials_run *p, int index)
{
    return p->results[index].outcome == FS_KILLED && !(p->killed_before && p->killed_before[index]);
}

/* Appends a finished trial to the journal (when there is one). */
static fs_status journal_trial(trials_run *p, int index, fs_error *err)
{
    if (!p->journal)
        return FS_OK;
    fs_status s = fs_journal_append(p->journal, index, &p->results[index], err);
    if (s == FS_OK)
        p->final_records += !first_kill(p, index);
    if (s == FS_OK && ++p->records == p->k->test.signal_after)
        raise(p->k->test.signal_sig);
    return s;
}

/* In a worker: one trial. */
static void run_one(int task, void *result, void *user)
{
    const trials_run *p = user;
    int index = trial_index(p, task);
    message *m = result;
    int cell, seed;
    fs_campaign_trial_of(p->c, index, &cell, &seed);
    if (seed == p->k->test.crash_seed)
        _exit(FS_NUMERICAL); /* what an ODE error does */
    if (seed == p->k->test.stop_seed)
        raise(SIGSTOP); /* a worker that hangs, for the watchdog */
    if (seed == p->k->test.kill_seed)
        raise(SIGKILL); /* what the OOM killer does */
    fs_error err = {FS_OK, ""};
    m->status = fs_trial_run_scenario(fs_campaign_pair_of(p->c, cell, fs_campaign_trial_end(p->c, index)), seed, NULL,
                                      &m->result, &err);
    snprintf(m->error, sizeof m->error, "%s", err.message);
}

/* In the parent: a trial's answer, or the refusal that stops the campaign. */
static fs_status take_one(int task, const void *result, void *user, fs_error *err)
{
    trials_run *p = user;
    const message *m = result;
    int index = trial_index(p, task);
    if (p->journal_status != FS_OK) {
        *err = p->journal_err;
        return p->journal_status;
    }
    if (m->status != FS_OK)
        return fs_fail(err, (fs_status)m->status, "%s", m->error);
    p->results[index] = m->result;
    p->k->failed += m->result.outcome == FS_FAILED_NUMERICS;
    return journal_trial(p, index, err);
}

/* In the parent: the record of a trial whose worker died: the pose it drew, and how it ended. */
static void record_death(int task, const fs_pool_death *d, void *user)
{
    trials_run *p = user;
    if (p->k->stop)
        return; /* stopped by the caller: the trial was not finished, and runs again on resume */
    int index = trial_index(p, task);
    const fs_campaign *c = p->c;
    int cell, seed;
    fs_campaign_trial_of(c, index, &cell, &seed);
    fs_trial_result *r = &p->results[index];
    memset(r, 0, sizeof *r);
    double nan = NAN;
    r->end_time_s = r->touchdown_s = r->peak_tilt_deg = r->final_tilt_deg = r->peak_force_N = nan;
    r->impact_impulse_Ns = r->settle_time_s = r->mean_contacts = r->final_contacts = nan;
    r->ankle_drop_m = r->slip_m = nan;
    r->soil_sinkage_m = r->print_depth_m = r->print_area_m2 = r->print_volume_m3 = r->print_slip_m = nan;
    /* only a numerical failure (ODE's error handler exits with status 3) is one; a hang or a kill
       from outside says nothing of the physics */
    int numerics = d->exited && d->status == FS_NUMERICAL;
    r->outcome = d->timed_out ? FS_HUNG : numerics ? FS_FAILED_NUMERICS : FS_KILLED;
    int end = fs_campaign_trial_end(c, index);
    fs_trial_draw_pose(fs_campaign_pair_of(c, cell, end), seed, &r->draw);
    int foot, terrain, robot;
    fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
    r->rule = d->timed_out ? FS_RULE_WATCHDOG : numerics ? FS_RULE_NUMERICS : FS_RULE_KILLED;
    snprintf(r->failure, sizeof r->failure, "the worker running foot %s on terrain %s under robot %s%s%s, seed %d, %s",
             c->foot[foot].name, c->terrain[terrain].name, c->robot[robot].name, c->band[0] ? " at band end " : "",
             c->end[end].name, seed, d->how);
    p->k->failed++;
    say(p->k, "%s; counted as %s%s", r->failure, fs_outcome_name(r->outcome),
        first_kill(p, index) ? " for now: it runs once more" : r->outcome == FS_KILLED ? " (its second try)" : "");
    if (p->journal_status == FS_OK)
        p->journal_status = journal_trial(p, index, &p->journal_err);
}

static void draw_progress(int done, int ntrials, void *user)
{
    trials_run *p = user;
    (void)ntrials;
    p->k->done = p->already + done;
    tell(p->k, NULL);
}

/* How a run of trials is journaled: where, the trials killed once before (or NULL), and, in and out,
 * the records written so far (all; the final ones). */
typedef struct journal_run {
    fs_journal *journal;
    const unsigned char *killed_before;
    int records, final_records;
} journal_run;

/* Runs the trials index[0 .. n - 1] (every trial when index is NULL) into results, each appended
 * to the journal when one is given (j NULL: none); `already` trials of k->total were done before.
 * Stops early, FS_OK, when the caller asks. */
static fs_status run_trials(const fs_campaign *c, fs_trial_result *results, const int *index, int n, int already,
                            journal_run *j, int jobs, caller *k, fs_error *err)
{
    trials_run run = {.c = c, .results = results, .index = index, .already = already,
                      .journal = j ? j->journal : NULL, .killed_before = j ? j->killed_before : NULL,
                      .records = j ? j->records : 0, .final_records = j ? j->final_records : 0, .k = k};
    fs_pool_spec spec = {.ntasks = n, .jobs = jobs > 0 ? jobs : fs_pool_default_jobs(), .result_size = sizeof(message),
                         .user = &run, .run = run_one, .done = take_one, .died = record_death,
                         .progress = draw_progress, .stop = &k->stop};
    fs_pool_stats stats;
    fs_status s = fs_pool_run(&spec, &stats, err);
    if (j)
        j->records = run.records, j->final_records = run.final_records;
    if (s == FS_OK && run.journal_status != FS_OK) {
        *err = run.journal_err;
        s = run.journal_status;
    }
    if (s == FS_OK && stats.timed_out)
        say(k, "%d worker%s made no progress for the watchdog's time and %s killed; their trials are counted as "
            "hung, not as numerical failures", stats.timed_out, stats.timed_out > 1 ? "s" : "",
            stats.timed_out > 1 ? "were" : "was");
    return s;
}

fs_status fs_campaign_run_trials(const fs_campaign *c, fs_trial_result *results, const fs_campaign_run_opts *o,
                                 int *stopped, fs_error *err)
{
    caller k;
    caller_init(&k, o);
    k.total = fs_campaign_ntrials(c);
    fs_status s = run_trials(c, results, NULL, k.total, 0, NULL, o ? o->jobs : 0, &k, err);
    if (stopped)
        *stopped = k.stop != 0;
    return s;
}

/* ---- the files ---------------------------------------------------------------------------- */

/* Tells the caller once more after a long step; whether it asked to stop. */
static int stopping(caller *k)
{
    tell(k, NULL);
    return k->stop != 0;
}

/* Summarizes into rows, writes every file into out's partial folder (summary.json last, after the
 * caller's extra), and puts it in place. */
static int finish(const fs_campaign *c, const fs_trial_result *results, fs_outdir *out, caller *k,
                  const fs_campaign_run_opts *o, fs_campaign_row *rows, fs_campaign_state *st, fs_error *err)
{
    fs_campaign_summarize(c, results, rows);
    /* everything goes into the partial folder, swapped in whole at the end */
    fs_status s = fs_campaign_write(c, results, rows, out->partial, err);
    if (k->test.kill_in_write)
        raise(SIGKILL); /* tests: a kill in the middle of writing the results */
    if (s == FS_OK)
        s = fs_campaign_write_chart(c, rows, out->partial, err);
    int g = s == FS_OK && o && o->extra ? o->extra(out->partial, out->path, c, results, rows, o->user) : 0;
    if (s != FS_OK || g)
        return g ? g : (int)s;
    if (stopping(k)) { /* stopped while writing: the old folder stays, whole */
        st->stopped = 1;
        return FS_OK;
    }
    s = fs_campaign_write_summary(c, rows, out->partial, err);
    if (s == FS_OK)
        s = fs_outdir_commit(out, err);
    st->committed = s == FS_OK;
    return (int)s;
}

/* A shard's results: DIR/trials.journal, its trials sorted by index. */
static int finish_shard(const fs_journal_head *h, const fs_trial_result *results, fs_outdir *out, caller *k,
                        fs_campaign_state *st, fs_error *err)
{
    unsigned char *in = malloc((size_t)h->ntrials);
    char path[sizeof out->partial + 32];
    if (!in)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    for (int i = 0; i < h->ntrials; i++)
        in[i] = (unsigned char)fs_campaign_in_shard(i, h->shard, h->nshards);
    snprintf(path, sizeof path, "%s/trials.journal", out->partial);
    fs_status s = fs_journal_write(path, h, results, in, err);
    free(in);
    if (s == FS_OK && stopping(k)) { /* stopped while writing: the old folder stays, whole */
        st->stopped = 1;
        return FS_OK;
    }
    if (s == FS_OK)
        s = fs_outdir_commit(out, err);
    st->committed = s == FS_OK;
    return (int)s;
}

/* ---- resume ------------------------------------------------------------------------------- */

/* Whether the folder `journal` is absent (0), footsim's journal folder (1: only "journal" and its
 * temporary files in it), or something else (-1). */
static int journal_folder(const char *journal)
{
    struct stat st;
    if (lstat(journal, &st) != 0)
        return 0;
    if (!S_ISDIR(st.st_mode))
        return -1;
    DIR *d = opendir(journal);
    if (!d)
        return -1;
    int ours = 1;
    for (struct dirent *e; ours && (e = readdir(d)) != NULL;)
        ours = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") || !strcmp(e->d_name, "journal") ||
               !strncmp(e->d_name, "journal.tmp.", 12);
    closedir(d);
    return ours ? 1 : -1;
}

/* Whether dir already holds this campaign's finished results: a summary.json whose provenance is
 * h's (the whole campaign), or a trials.journal with h's head (a shard). */
static int finished_already(const char *dir, const fs_journal_head *h, int sharded)
{
    char path[FS_OUT_PATH + 32];
    if (sharded) {
        snprintf(path, sizeof path, "%s/trials.journal", dir);
        fs_journal_head old;
        fs_trial_result *results;
        unsigned char *done;
        int ndone;
        fs_error err;
        if (access(path, R_OK) != 0 || fs_journal_read(path, &old, &results, &done, &ndone, NULL, &err) != FS_OK)
            return 0;
        char why[8];
        int same = !fs_journal_differs(h, &old, "", "", why, sizeof why) && old.shard == h->shard &&
                   old.nshards == h->nshards;
        fs_journal_head_free(&old);
        free(results), free(done);
        return same;
    }
    snprintf(path, sizeof path, "%s/summary.json", dir);
    if (access(path, R_OK) != 0)
        return 0;
    char *line = fs_campaign_summary_provenance(path);
    int same = line && !strcmp(line, h->provenance);
    free(line);
    return same;
}

/* The journal's records checked against the campaign: each in the share, with its trial's seed.
 * `what` says what to do about a record that is not (resume: move the journal away or --fresh;
 * merge: run the shard again). */
static fs_status check_records(const fs_campaign *c, const fs_journal_head *h, const fs_trial_result *results,
                               const unsigned char *done, const char *path, const char *what, fs_error *err)
{
    for (int i = 0; i < h->ntrials; i++) {
        int cell, seed;
        fs_campaign_trial_of(c, i, &cell, &seed);
        if (!done[i])
            continue;
        if (!fs_campaign_in_shard(i, h->shard, h->nshards))
            return fs_fail(err, FS_BAD_INPUT, "%s: holds trial %d, which belongs to shard %d/%d, not to shard %d/%d "
                           "as its header says: records of another shard were put in it; %s", path, i,
                           i % h->nshards + 1, h->nshards, h->shard, h->nshards, what);
        if (results[i].draw.seed != seed)
            return fs_fail(err, FS_BAD_INPUT, "%s: holds trial %d with seed %d, but this campaign's trial %d has seed "
                           "%d: records of another campaign were put in it; %s", path, i, results[i].draw.seed, i,
                           seed, what);
    }
    return FS_OK;
}

/* What a resume found in the journal. */
typedef struct resumed {
    unsigned char *done;          /* per trial: a final record is there (the results hold it) */
    unsigned char *killed_once;   /* per trial: its one record says its worker was killed: it runs once more */
    int ndone;
    long long keep_bytes;         /* >= 0: the journal is cut to this length before appending */
} resumed;

/* Reads the journal of an interrupted run into results and *out, refusing one that another
 * campaign, other inputs, overrides, version or shard made. A torn or damaged end is said and cut
 * off (its trials run again); a journal of format 1 is rewritten in today's format. */
static fs_status resume(const fs_campaign *c, const fs_journal_head *h, const char *path, fs_trial_result *results,
                        resumed *out, caller *k, fs_error *err)
{
    fs_journal_head old;
    fs_trial_result *r;
    unsigned char *d;
    fs_journal_tail tail;
    int nrecords;
    fs_status s = fs_journal_read(path, &old, &r, &d, &nrecords, &tail, err);
    if (s != FS_OK)
        return s;
    char why[512];
    if (fs_journal_differs(h, &old, "this run", "the journal", why, sizeof why) ||
        (old.shard != h->shard || old.nshards != h->nshards
             ? snprintf(why, sizeof why, "shard: %d/%d in this run, %d/%d in the journal", h->shard, h->nshards,
                        old.shard, old.nshards)
             : 0))
        s = fs_fail(err, FS_BAD_INPUT, "%s holds the trials of another run of this campaign (%s); they are not "
                    "mixed with this run's: run it as it was run to finish it, or add --fresh to start over (the "
                    "journal is removed)", path, why);
    if (s == FS_OK)
        s = check_records(c, h, r, d, path, "move the journal away, or start over with --fresh (it is removed)", err);
    out->keep_bytes = tail.torn || tail.line ? tail.good_bytes : -1;
    for (int i = 0; s == FS_OK && i < h->ntrials; i++) {
        if (!d[i])
            continue;
        results[i] = r[i];
        if (d[i] == 1 && r[i].outcome == FS_KILLED)
            out->killed_once[i] = 1;
        else
            out->done[i] = 1, out->ndone++;
    }
    if (s == FS_OK && tail.line)
        say(k, "%s:%d: %s; the records before that line are kept, it and every line after it are cut off, and their "
            "trials run again", path, tail.line, tail.why);
    else if (s == FS_OK && tail.torn)
        say(k, "%s ends in a record cut short (a kill, a full disk or a file-size limit in the middle of its write); "
            "it is cut off and its trial runs again", path);
    if (s == FS_OK && tail.format != FS_JOURNAL_FORMAT) { /* read cleanly: rewritten whole before anything follows */
        say(k, "%s is of an earlier footsim's journal format (%d); its %d records read cleanly and are kept, "
            "rewritten in format %d", path, tail.format, nrecords, FS_JOURNAL_FORMAT);
        s = fs_journal_write(path, h, r, d, err);
        out->keep_bytes = -1;
    }
    fs_journal_head_free(&old);
    free(r), free(d);
    return s;
}

/* Runs the trials of c's share that the journal lacks, then writes the results. A trial whose
 * worker was killed runs once more, after the others. */
static int run_share(const fs_campaign *c, const fs_journal_head *h, fs_outdir *out, int jobs, caller *k,
                     const fs_campaign_run_opts *o, fs_campaign_row *rows, fs_campaign_state *st, fs_error *err)
{
    char jpath[sizeof st->journal + 16];
    snprintf(jpath, sizeof jpath, "%s/journal", st->journal);
    int kind = journal_folder(st->journal);
    if (kind < 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: is not footsim's journal folder (it holds other files); move it away, "
                       "or choose another --out", st->journal);
    if (o->fresh && kind > 0) {
        fs_remove_tree(st->journal);
        kind = 0;
    }
    if (!o->fresh && kind == 0 && finished_already(out->path, h, h->nshards > 1 || o->nshards > 0)) {
        st->finished_already = 1;
        return FS_OK;
    }
    int ntrials = h->ntrials, npending = 0;
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    resumed from = {.done = calloc((size_t)ntrials, 1), .killed_once = calloc((size_t)ntrials, 1), .keep_bytes = -1};
    int *pending = malloc((size_t)ntrials * sizeof *pending);
    fs_journal journal;
    int s = FS_OK;
    if (!results || !from.done || !from.killed_once || !pending)
        s = fs_fail(err, FS_NO_MEMORY, "out of memory");
    struct stat sb;
    if (!s && kind > 0 && lstat(jpath, &sb) == 0)
        s = resume(c, h, jpath, results, &from, k, err);
    if (!s && kind == 0 && mkdir(st->journal, 0777) != 0)
        s = fs_fail(err, FS_IO, "%s: cannot make the journal folder (%s)", st->journal, strerror(errno));
    if (!s)
        s = fs_journal_open(&journal, jpath, h, from.keep_bytes, err);
    for (int i = 0; !s && i < ntrials; i++)
        if (fs_campaign_in_shard(i, h->shard, h->nshards)) {
            st->total++;
            if (!from.done[i])
                pending[npending++] = i;
        }
    k->total = st->total;
    k->done = from.ndone;
    if (!s && from.ndone)
        say(k, "resuming from %s: %d of %d trials done, %d to run", jpath, from.ndone, st->total, npending);
    int ran = !s;
    fs_status r = FS_OK;
    if (ran) {
        journal_run j = {.journal = &journal, .killed_before = from.killed_once};
        r = run_trials(c, results, pending, npending, from.ndone, &j, jobs, k, err);
        /* the trials whose worker was killed for the first time: once more, after the others */
        int nretry = 0;
        for (int i = 0; r == FS_OK && !k->stop && i < npending; i++)
            if (results[pending[i]].outcome == FS_KILLED && !from.killed_once[pending[i]])
                from.killed_once[pending[i]] = 1, pending[nretry++] = pending[i];
        if (nretry) {
            say(k, "%d trial%s whose worker was killed run%s once more", nretry, nretry > 1 ? "s" : "",
                nretry > 1 ? "" : "s");
            r = run_trials(c, results, pending, nretry, st->total - nretry, &j, jobs, k, err);
        }
        fs_journal_close(&journal);
        st->kept = from.ndone + j.final_records;
        if (k->stop)
            st->stopped = 1;
        else if (r != FS_OK)
            s = (int)r;
        else
            s = h->nshards > 1 || o->nshards > 0 ? finish_shard(h, results, out, k, st, err)
                                                 : finish(c, results, out, k, o, rows, st, err);
    }
    if (ran && (st->committed || (st->kept == 0 && (st->stopped || r != FS_OK))))
        fs_remove_tree(st->journal); /* served, or nothing to keep */
    st->journal_kept = journal_folder(st->journal) > 0;
    free(results), free(from.done), free(from.killed_once), free(pending);
    return s;
}

int fs_campaign_run(const fs_campaign *c, const fs_journal_head *h, const char *dir, const fs_campaign_run_opts *o,
                    fs_campaign_row *rows, fs_campaign_state *state, fs_error *err)
{
    fs_campaign_run_opts none = {0};
    if (err)
        *err = (fs_error){FS_OK, ""};
    fs_campaign_state st_local;
    fs_campaign_state *st = state ? state : &st_local;
    memset(st, 0, sizeof *st);
    o = o ? o : &none;
    caller k;
    caller_init(&k, o);
    fs_campaign_row *own = NULL;
    if (!rows && !(rows = own = malloc((size_t)fs_campaign_ncells(c) * sizeof *rows)))
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    fs_outdir *out = calloc(1, sizeof *out);
    int s = out ? (int)fs_outdir_open(out, dir, o->replace, "--out", err) : (int)fs_fail(err, FS_NO_MEMORY, "out of memory");
    if (s == FS_OK) {
        snprintf(st->dir, sizeof st->dir, "%s", out->path);
        snprintf(st->journal, sizeof st->journal, "%s.journal", out->path);
        s = run_share(c, h, out, o->jobs, &k, o, rows, st, err);
    }
    if (out)
        fs_outdir_abort(out); /* when it was not committed */
    free(out), free(own);
    return s;
}

/* ---- merge -------------------------------------------------------------------------------- */

/* The journal file of a shard folder (DIR/trials.journal) or of a journal folder (DIR/journal). */
static fs_status journal_in(const char *dir, char *path, size_t size, fs_error *err)
{
    fs_status s = fs_path_format(path, size, "merge", err, "%s/trials.journal", dir);
    if (s != FS_OK || access(path, F_OK) == 0)
        return s;
    snprintf(path, size, "%s/journal", dir); /* shorter */
    if (access(path, F_OK) == 0)
        return FS_OK;
    return fs_fail(err, FS_BAD_INPUT, "%s: holds no trials.journal; give the folders 'footsim campaign --shard I/N "
                   "--out DIR' wrote", dir);
}

/* The index of the folder among dirs[n] that dir is (the same device and inode, whatever either is
 * called: "s1", "./s1/", a link to it), or -1. */
static int same_folder(const char *dir, const char *const *dirs, int n)
{
    struct stat out, in;
    if (stat(dir, &out) != 0)
        return -1; /* not there yet: none of the inputs */
    for (int k = 0; k < n; k++)
        if (stat(dirs[k], &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
            return k;
    return -1;
}

/* Reads shard k's journal into results (from[i]: the shard trial i came from, -1 for none),
 * loading the campaign from the first. */
static fs_status merge_one(const char *const *dirs, int k, int force, fs_campaign_merged *m, fs_journal_head *heads,
                           int **from, fs_error *err)
{
    char path[FS_OUT_PATH + 32];
    fs_trial_result *r;
    unsigned char *d;
    int nd;
    fs_status s = journal_in(dirs[k], path, sizeof path, err);
    if (s != FS_OK)
        return s;
    if ((s = fs_journal_read(path, &heads[k], &r, &d, &nd, NULL, err)) != FS_OK) {
        /* a shard's trials.journal is written whole: damage is the disk's or an edit */
        if (s == FS_BAD_INPUT) {
            size_t n = strlen(err->message);
            snprintf(err->message + n, sizeof err->message - n, "; run that shard again (or give its folder as it "
                     "was written)");
        }
        return s;
    }
    char why[512];
    if (k == 0) {
        /* the campaign the shards ran, loaded as they loaded it: its files must not have changed */
        fs_journal_head now;
        const char *const *set = (const char *const *)heads[0].set;
        if ((s = fs_campaign_load(heads[0].campaign, set, heads[0].nset, &m->c, err)) == FS_OK &&
            (m->loaded = 1, s = fs_journal_head_of(&m->c, heads[0].campaign, set, heads[0].nset, 1, 1, &now, err)) == FS_OK) {
            if (fs_journal_differs(&now, &heads[0], "the campaign now", dirs[0], why, sizeof why)) {
                if (force && fs_journal_version_only(&now, &heads[0])) {
                    m->other_version = 1;
                    snprintf(m->version_note, sizeof m->version_note, "%s", why);
                } else {
                    s = fs_fail(err, FS_BAD_INPUT, "the campaign %s has changed since its shards ran (%s); run the "
                                "shards again", heads[0].campaign, why);
                }
            }
            fs_journal_head_free(&now);
        }
        m->results = calloc((size_t)heads[0].ntrials, sizeof *m->results);
        *from = malloc((size_t)heads[0].ntrials * sizeof **from);
        if (s == FS_OK && (!m->results || !*from))
            s = fs_fail(err, FS_NO_MEMORY, "out of memory");
        for (int i = 0; s == FS_OK && i < heads[0].ntrials; i++)
            (*from)[i] = -1;
    } else if (fs_journal_differs(&heads[k], &heads[0], dirs[k], dirs[0], why, sizeof why)) {
        s = fs_fail(err, FS_BAD_INPUT, "%s and %s are shards of different campaigns or inputs (%s); merge only the "
                    "shards of one campaign run with the same inputs, overrides and version", dirs[k], dirs[0], why);
    }
    if (s == FS_OK)
        s = check_records(&m->c, &heads[k], r, d, path, "run that shard again", err);
    for (int i = 0; s == FS_OK && i < heads[0].ntrials; i++) {
        if (!d[i])
            continue;
        if ((*from)[i] >= 0) {
            int cell, seed, foot, terrain, robot;
            fs_campaign_trial_of(&m->c, i, &cell, &seed);
            fs_campaign_cell_of(&m->c, cell, &foot, &terrain, &robot);
            s = fs_fail(err, FS_BAD_INPUT, "trial %d (foot %s on terrain %s under robot %s, seed %d) is in both %s and "
                        "%s; give each shard once, all of one --shard I/N split", i, m->c.foot[foot].name,
                        m->c.terrain[terrain].name, m->c.robot[robot].name, seed, dirs[(*from)[i]], dirs[k]);
        } else {
            m->results[i] = r[i];
            (*from)[i] = k;
        }
    }
    free(r), free(d);
    return s;
}

fs_status fs_campaign_merge(const char *const *dirs, int n, int force, fs_campaign_merged *m, fs_error *err)
{
    memset(m, 0, sizeof *m);
    m->dirs = dirs;
    m->n = n;
    if (n < 1)
        return fs_fail(err, FS_BAD_INPUT, "merge: give the shard folders");
    fs_journal_head *heads = calloc((size_t)n, sizeof *heads);
    if (!heads)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    int *from = NULL; /* the shard each trial came from, -1 for none */
    fs_status s = FS_OK;
    int read = 0;
    for (; read < n && s == FS_OK; read++)
        s = merge_one(dirs, read, force, m, heads, &from, err);
    int missing = 0;
    for (int i = 0; s == FS_OK && i < heads[0].ntrials; i++)
        missing += from[i] < 0;
    if (s == FS_OK && missing) {
        int first = 0;
        while (from[first] >= 0)
            first++;
        m->missing_shard = first % heads[0].nshards + 1;
        s = fs_fail(err, FS_BAD_INPUT, "%d of %d trials missing (the first: trial %d, of shard %d/%d); give every "
                    "shard's folder, or run the missing shard", missing, heads[0].ntrials, first, m->missing_shard,
                    heads[0].nshards);
    }
    /* the first shard's head, for the caller's messages (the campaign, its overrides) */
    m->head = heads[0];
    for (int k = 1; k < read; k++)
        fs_journal_head_free(&heads[k]);
    free(heads), free(from);
    return s;
}

int fs_campaign_merge_write(const fs_campaign_merged *m, const char *dir, int replace, const fs_campaign_run_opts *o,
                            fs_campaign_row *rows, fs_campaign_state *state, fs_error *err)
{
    fs_campaign_run_opts none = {0};
    fs_campaign_state st_local;
    fs_campaign_state *st = state ? state : &st_local;
    memset(st, 0, sizeof *st);
    o = o ? o : &none;
    int input = same_folder(dir, m->dirs, m->n);
    if (input >= 0)
        return fs_fail(err, FS_BAD_INPUT, "--out %s: is the shard folder %s given to merge (the same folder); "
                       "replacing it would destroy its journal: give another --out", dir, m->dirs[input]);
    fs_outdir *out = calloc(1, sizeof *out);
    fs_campaign_row *own = NULL;
    caller k;
    caller_init(&k, o);
    int s = out && (rows || (rows = own = malloc((size_t)fs_campaign_ncells(&m->c) * sizeof *rows)))
                ? FS_OK : fs_fail(err, FS_NO_MEMORY, "out of memory");
    if (s == FS_OK && (s = fs_outdir_open(out, dir, replace, "--out", err)) == FS_OK) {
        snprintf(st->dir, sizeof st->dir, "%s", out->path);
        k.done = k.total = st->kept = st->total = fs_campaign_ntrials(&m->c);
        s = finish(&m->c, m->results, out, &k, o, rows, st, err);
    }
    if (out)
        fs_outdir_abort(out);
    free(out), free(own);
    return s;
}

void fs_campaign_merge_free(fs_campaign_merged *m)
{
    fs_journal_head_free(&m->head);
    if (m->loaded)
        fs_campaign_free(&m->c);
    free(m->results);
    memset(m, 0, sizeof *m);
}
