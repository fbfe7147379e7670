/* cli_campaign.c: `footsim campaign` (the trials in worker processes, the result files, the chart,
 * the expectations) and `footsim compare` (a summary against its baseline).
 *
 * The trials run in footsim's pool of worker processes (fs_pool.h). A worker that exits with
 * status 3 (an ODE error) marks its trial failed_numerics; one that the watchdog kills (no answer
 * for FS_POOL_WATCHDOG_S) marks it hung; one that dies any other way (a signal from outside, as the
 * OOM killer's SIGKILL, a crash, another status) marks it killed, and a killed trial runs once more
 * (at the end of the run, or on resume when the run stopped first): neither hung nor killed says
 * anything of the physics. Each is said with its trial, seed and how it ended; a fresh worker takes
 * its place and the campaign goes on. Tests: FOOTSIM_TEST_CRASH_SEED=N makes a worker exit with
 * status 3 on seed N, FOOTSIM_TEST_STOP_SEED=N stops it (SIGSTOP) on seed N,
 * FOOTSIM_TEST_KILL_SEED=N kills it (SIGKILL) on seed N;
 * FOOTSIM_TEST_KILL_IN_WRITE kills the campaign with SIGKILL half way through writing its files;
 * FOOTSIM_TEST_SIGNAL_AFTER="N SIG" makes the campaign raise signal SIG on itself once N trials
 * are in its journal (a kill at a chosen point, for the resume tests).
 *
 * Resume: every finished trial is appended to the journal DIR.journal/journal as it ends
 * (fs_campaign.h); a run whose journal exists runs only the trials it lacks, after checking that
 * the journal was made by the same campaign (provenance), and removes it once DIR holds the
 * results. A torn last record, or a record that fails its checksum and all after it, is cut off
 * (said, with the line) and its trials run again. SIGINT and SIGTERM stop the pool (fs_pool_spec.stop), keep the journal and say how to
 * continue. --shard I/N runs one share of the trials and writes it as DIR/trials.journal;
 * `footsim merge` makes the campaign's files of the shards. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/exec/fs_pool.h"
#include "footsim/io/fs_output.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A worker's answer to one trial. */
typedef struct message {
    int status;     /* fs_trial_run's */
    fs_trial_result result;
    char error[FS_ERROR_MAX];
} message;

/* What the pool's callbacks share. */
typedef struct campaign_run {
    const fs_campaign *c;
    fs_trial_result *results;
    const int *index;       /* the trial index of each pool task, or NULL: the task number */
    int already;            /* trials done before this run (the journal's) */
    int total;              /* trials of this run's share, the journal's included */
    fs_journal *journal;    /* where each finished trial goes, or NULL */
    const unsigned char *killed_before; /* per trial index: its worker was killed once already, or NULL */
    int final_records;      /* records journaled that are final (not a first kill, which runs again) */
    fs_status journal_status; /* a journal write that failed in record_death, for the next take_one */
    fs_error journal_err;
    int signal_after, signal_sig, journaled; /* FOOTSIM_TEST_SIGNAL_AFTER */
    int crash_seed, stop_seed, kill_seed;
    cli_progress progress;
    int failed;             /* trials so far that failed numerically or whose worker died */
} campaign_run;

/* SIGINT or SIGTERM received while trials run (0: none). */
static volatile sig_atomic_t interrupted;

static void on_signal(int sig) { interrupted = sig; }

static int trial_index(const campaign_run *p, int task) { return p->index ? p->index[task] : task; }

/* Whether trial index's result is the first kill of its worker: the trial runs once more. */
static int first_kill(const campaign_run *p, int index)
{
    return p->results[index].outcome == FS_KILLED && !(p->killed_before && p->killed_before[index]);
}

/* Appends a finished trial to the journal (when there is one). */
static fs_status journal_trial(campaign_run *p, int index, fs_error *err)
{
    if (!p->journal)
        return FS_OK;
    fs_status s = fs_journal_append(p->journal, index, &p->results[index], err);
    if (s == FS_OK)
        p->final_records += !first_kill(p, index);
    if (s == FS_OK && ++p->journaled == p->signal_after)
        raise(p->signal_sig);
    return s;
}

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* ---- the pool's callbacks ----------------------------------------------------------------- */

/* In a worker: one trial. */
static void run_one(int task, void *result, void *user)
{
    const campaign_run *p = user;
    int index = trial_index(p, task);
    message *m = result;
    const fs_campaign *c = p->c;
    int cell, seed;
    fs_campaign_trial_of(c, index, &cell, &seed);
    if (seed == p->crash_seed)
        _exit(FS_NUMERICAL); /* FOOTSIM_TEST_CRASH_SEED: what an ODE error does */
    if (seed == p->stop_seed)
        raise(SIGSTOP); /* FOOTSIM_TEST_STOP_SEED: a worker that hangs, for the watchdog */
    if (seed == p->kill_seed)
        raise(SIGKILL); /* FOOTSIM_TEST_KILL_SEED: what the OOM killer does */
    fs_error err = {FS_OK, ""};
    m->status = fs_trial_run_scenario(fs_campaign_pair(c, cell), seed, NULL, &m->result, &err);
    snprintf(m->error, sizeof m->error, "%s", err.message);
}

/* In the parent: a trial's answer, or the refusal that stops the campaign. */
static fs_status take_one(int task, const void *result, void *user, fs_error *err)
{
    campaign_run *p = user;
    const message *m = result;
    int index = trial_index(p, task);
    if (p->journal_status != FS_OK) {
        *err = p->journal_err;
        return p->journal_status;
    }
    if (m->status != FS_OK)
        return fs_fail(err, (fs_status)m->status, "%s", m->error);
    p->results[index] = m->result;
    p->failed += m->result.outcome == FS_FAILED_NUMERICS;
    return journal_trial(p, index, err);
}

/* In the parent: the record of a trial whose worker died: the pose it drew, and how it ended. */
static void record_death(int task, const fs_pool_death *d, void *user)
{
    campaign_run *p = user;
    if (interrupted)
        return; /* stopped by the user: the trial was not finished, and runs again on resume */
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
    /* only a numerical failure (ODE's error handler exits with status 3) is one; a hang or a kill
       from outside says nothing of the physics */
    int numerics = d->exited && d->status == FS_NUMERICAL;
    r->outcome = d->timed_out ? FS_HUNG : numerics ? FS_FAILED_NUMERICS : FS_KILLED;
    fs_trial_draw_pose(fs_campaign_pair(c, cell), seed, &r->draw);
    int foot, terrain, robot;
    fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
    r->rule = d->timed_out ? FS_RULE_WATCHDOG : numerics ? FS_RULE_NUMERICS : FS_RULE_KILLED;
    snprintf(r->failure, sizeof r->failure, "the worker running foot %s on terrain %s under robot %s, seed %d, %s",
             c->foot[foot].name, c->terrain[terrain].name, c->robot[robot].name, seed, d->how);
    p->failed++;
    if (p->progress.tty)
        fputc('\n', stderr);
    fprintf(stderr, "footsim campaign: %s; counted as %s%s\n", r->failure, fs_outcome_name(r->outcome),
            first_kill(p, index) ? " for now: it runs once more" : r->outcome == FS_KILLED ? " (its second try)" : "");
    if (p->journal_status == FS_OK)
        p->journal_status = journal_trial(p, index, &p->journal_err);
}

static void draw_progress(int done, int ntrials, void *user)
{
    campaign_run *p = user;
    (void)ntrials;
    cli_progress_update(&p->progress, p->already + done, p->total, p->failed);
}

/* ---- campaign ----------------------------------------------------------------------------- */

/* How a run of trials is journaled: where, the trials killed once before (or NULL), and, in and out,
 * the records written so far (all; the final ones). */
typedef struct journal_run {
    fs_journal *journal;
    const unsigned char *killed_before;
    int records, final_records;
} journal_run;

/* Runs the trials index[0 .. n - 1] (every trial when index is NULL) into results, each appended
 * to the journal when one is given (j NULL: none); `already` trials of `total` were done before.
 * Stops early, FS_OK, when `interrupted` is set. */
static fs_status run_trials(const fs_campaign *c, fs_trial_result *results, const int *index, int n, int already,
                            int total, journal_run *j, int jobs, const char *who, fs_error *err)
{
    const char *crash = getenv("FOOTSIM_TEST_CRASH_SEED"), *stop = getenv("FOOTSIM_TEST_STOP_SEED");
    const char *kill_seed = getenv("FOOTSIM_TEST_KILL_SEED"), *after = getenv("FOOTSIM_TEST_SIGNAL_AFTER");
    fs_journal *journal = j ? j->journal : NULL;
    campaign_run run = {.c = c, .results = results, .index = index, .already = already, .total = total,
                        .journal = journal, .killed_before = j ? j->killed_before : NULL,
                        .journaled = j ? j->records : 0, .final_records = j ? j->final_records : 0,
                        .crash_seed = crash ? atoi(crash) : -1, .stop_seed = stop ? atoi(stop) : -1,
                        .kill_seed = kill_seed ? atoi(kill_seed) : -1};
    if (!after || sscanf(after, "%d %d", &run.signal_after, &run.signal_sig) != 2)
        run.signal_after = -1;
    cli_progress_start(&run.progress, who, "trials");
    fs_pool_spec spec = {.ntasks = n, .jobs = jobs, .result_size = sizeof(message), .user = &run,
                         .run = run_one, .done = take_one, .died = record_death, .progress = draw_progress,
                         .stop = journal ? &interrupted : NULL};
    fs_pool_stats stats;
    fs_status s = fs_pool_run(&spec, &stats, err);
    if (j)
        j->records = run.journaled, j->final_records = run.final_records;
    if (s == FS_OK && run.journal_status != FS_OK) {
        *err = run.journal_err;
        s = run.journal_status;
    }
    if (s == FS_OK && stats.timed_out)
        fprintf(stderr, "%s: %d worker%s made no progress for the watchdog's time and %s killed; their trials are "
                        "counted as hung, not as numerical failures\n",
                who, stats.timed_out, stats.timed_out > 1 ? "s" : "", stats.timed_out > 1 ? "were" : "was");
    return s;
}

int cli_campaign_trials(const fs_campaign *c, fs_trial_result *results, int jobs, const char *who, fs_error *err)
{
    int n = fs_campaign_ntrials(c);
    return run_trials(c, results, NULL, n, 0, n, NULL, jobs, who, err);
}

int cli_parse_jobs(const cli_args *a, int *jobs)
{
    *jobs = fs_pool_default_jobs(); /* the CPUs this process may use */
    if (!a->jobs)
        return 0;
    char *end;
    long n = strtol(a->jobs, &end, 10);
    if (*end || end == a->jobs || n < 1 || n > FS_POOL_MAX_JOBS) {
        fprintf(stderr, "footsim %s: -j %s: not a number of workers; allowed: a whole number from 1 to %d\n",
                a->command, a->jobs, FS_POOL_MAX_JOBS);
        return FS_BAD_INPUT;
    }
    *jobs = (int)n;
    return 0;
}

static void print_rows(const fs_campaign *c, const fs_campaign_row *rows)
{
    for (int i = 0; i < fs_campaign_ncells(c); i++) {
        const fs_campaign_row *r = &rows[i];
        printf("  %-12s on %-18s under %-14s landed %3d of %3d (%.2f, 95 %% CI [%.2f, %.2f])", c->foot[r->foot].name,
               c->terrain[r->terrain].name, c->robot[r->robot].name, r->landed, r->trials, r->success_rate, r->ci_low, r->ci_high);
        printf(", fell %3d, undecided %d; law: %s", r->fell, r->undecided, fs_law_name(r->law));
        if (r->failed_numerics)
            printf(", failed_numerics %d", r->failed_numerics);
        if (r->hung - r->killed)
            printf(", hung %d", r->hung - r->killed);
        if (r->killed)
            printf(", killed %d", r->killed);
        putchar('\n');
    }
}

/* Summarizes, writes every file (summary.json last), checks the expectations. */
static int finish(const fs_campaign *c, const fs_trial_result *results, fs_outdir *out)
{
    int nrows = fs_campaign_ncells(c);
    fs_campaign_row *rows = malloc((size_t)nrows * sizeof *rows);
    if (!rows)
        return cli_report(FS_NO_MEMORY, "out of memory");
    fs_campaign_summarize(c, results, rows);
    fs_error err;
    /* everything goes into the partial folder, swapped in whole at the end */
    fs_status s = fs_campaign_write(c, results, rows, out->partial, &err);
    if (getenv("FOOTSIM_TEST_KILL_IN_WRITE"))
        raise(SIGKILL); /* tests: a kill in the middle of writing the results */
    if (s == FS_OK)
        s = fs_campaign_write_chart(c, rows, out->partial, &err);
    int g = s == FS_OK ? cli_gnuplot_shown(out->partial, out->path, "chart.gp", "success.png", "campaign") : 0;
    int drawn = g == 0; /* else not drawn (said), or a damaged chart */
    g = g < 0 ? 0 : g;
    if (s == FS_OK && !g && interrupted) { /* stopped while writing: the old folder stays, whole */
        free(rows);
        return 128 + interrupted;
    }
    if (s == FS_OK && !g)
        s = fs_campaign_write_summary(c, rows, out->partial, &err);
    if (s == FS_OK && !g)
        s = fs_outdir_commit(out, &err);
    if (s != FS_OK || g) {
        free(rows);
        return g ? g : fail(&err);
    }
    const char *dir = out->path;
    printf("campaign %s: %d trials\n", c->name, fs_campaign_ntrials(c));
    print_rows(c, rows);
    int failed = 0;
    if (c->nexpect) {
        printf("expectations:\n");
        failed = fs_campaign_check(c, rows, stdout);
        printf(failed ? "%d of %d expectations FAILED\n" : "all %d expectations met\n", failed ? failed : c->nexpect,
               c->nexpect);
    }
    printf("results: %s/summary.md, summary.csv, summary.json, trials.csv, schema.sql, %s\n", dir,
           drawn ? "success.png" : "chart.dat and chart.gp (no success.png: see above)");
    free(rows);
    return failed ? FS_EXPECTATION_FAILED : 0;
}

/* ---- resume, shards ----------------------------------------------------------------------- */

/* --shard I/N into shard and nshards (1/1 without it); 0 or exit 2. */
static int parse_shard(const cli_args *a, int *shard, int *nshards)
{
    *shard = *nshards = 1;
    if (!a->shard)
        return 0;
    int used = 0;
    if (sscanf(a->shard, "%d/%d%n", shard, nshards, &used) != 2 || a->shard[used] || *nshards < 1 ||
        *nshards > FS_CAMPAIGN_MAX_TRIALS || *shard < 1 || *shard > *nshards) {
        fprintf(stderr, "footsim campaign: --shard %s: give I/N, the I-th of N shares (1 <= I <= N), e.g. --shard 2/8\n",
                a->shard);
        return FS_BAD_INPUT;
    }
    return 0;
}

/* Appends s to buf, quoted for a POSIX shell when it needs it. */
static void shell_word(char *buf, size_t size, const char *s)
{
    size_t n = strlen(buf);
    int plain = *s && strspn(s, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./=:,@%+-") == strlen(s);
    if (plain) {
        snprintf(buf + n, size - n, " %s", s);
        return;
    }
    snprintf(buf + n, size - n, " '");
    for (; *s; s++) {
        n = strlen(buf);
        snprintf(buf + n, size - n, *s == '\'' ? "'\\''" : "%c", *s);
    }
    n = strlen(buf);
    snprintf(buf + n, size - n, "'");
}

/* The command that runs this campaign again into the same folder. */
static void command_of(const cli_args *a, const char *dir, char *buf, size_t size)
{
    snprintf(buf, size, "footsim campaign");
    shell_word(buf, size, a->input);
    shell_word(buf, size, "--out");
    shell_word(buf, size, dir);
    if (a->jobs) {
        shell_word(buf, size, "-j");
        shell_word(buf, size, a->jobs);
    }
    if (a->shard) {
        shell_word(buf, size, "--shard");
        shell_word(buf, size, a->shard);
    }
    for (int i = 0; i < a->nset; i++) {
        shell_word(buf, size, "--set");
        shell_word(buf, size, a->set[i]);
    }
    if (a->data) {
        shell_word(buf, size, "--data");
        shell_word(buf, size, a->data);
    }
}

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
        int same = !fs_journal_differs(h, &old, "", "", why, sizeof why) && old.shard == h->shard && old.nshards == h->nshards;
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

/* A shard's results: DIR/trials.journal, its trials sorted by index. */
static int finish_shard(const fs_campaign *c, const fs_journal_head *h, const fs_trial_result *results, fs_outdir *out)
{
    unsigned char *in = malloc((size_t)h->ntrials);
    char path[sizeof out->partial + 32];
    if (!in)
        return cli_report(FS_NO_MEMORY, "out of memory");
    int n = 0;
    for (int i = 0; i < h->ntrials; i++)
        n += in[i] = (unsigned char)fs_campaign_in_shard(i, h->shard, h->nshards);
    snprintf(path, sizeof path, "%s/trials.journal", out->partial);
    fs_error err;
    fs_status s = fs_journal_write(path, h, results, in, &err);
    free(in);
    if (s == FS_OK && interrupted) /* stopped while writing: the old folder stays, whole */
        return 128 + interrupted;
    if (s == FS_OK)
        s = fs_outdir_commit(out, &err);
    if (s != FS_OK)
        return fail(&err);
    printf("campaign %s, shard %d/%d: %d of %d trials\nresults: %s/trials.journal (merge the %d shards with "
           "'footsim merge DIR... --out DIR')\n", c->name, h->shard, h->nshards, n, h->ntrials, out->path, h->nshards);
    return 0;
}

/* The journal's records checked against the campaign: each in the share, with its trial's seed.
 * `what` says what to do about a record that is not (resume: move the journal away or --fresh;
 * merge: run the shard again). */
static int check_records(const fs_campaign *c, const fs_journal_head *h, const fs_trial_result *results,
                         const unsigned char *done, const char *path, const char *what)
{
    for (int i = 0; i < h->ntrials; i++) {
        int cell, seed;
        fs_campaign_trial_of(c, i, &cell, &seed);
        if (!done[i])
            continue;
        if (!fs_campaign_in_shard(i, h->shard, h->nshards)) {
            fprintf(stderr, "footsim: %s: holds trial %d, which belongs to shard %d/%d, not to shard %d/%d as its "
                    "header says: records of another shard were put in it; %s\n", path, i, i % h->nshards + 1,
                    h->nshards, h->shard, h->nshards, what);
            return FS_BAD_INPUT;
        }
        if (results[i].draw.seed != seed) {
            fprintf(stderr, "footsim: %s: holds trial %d with seed %d, but this campaign's trial %d has seed %d: records "
                    "of another campaign were put in it; %s\n", path, i, results[i].draw.seed, i, seed, what);
            return FS_BAD_INPUT;
        }
    }
    return 0;
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
static int resume(const fs_campaign *c, const fs_journal_head *h, const char *path, fs_trial_result *results,
                  resumed *out)
{
    fs_journal_head old;
    fs_trial_result *r;
    unsigned char *d;
    fs_journal_tail tail;
    fs_error err;
    int nrecords;
    if (fs_journal_read(path, &old, &r, &d, &nrecords, &tail, &err) != FS_OK)
        return fail(&err);
    char why[512];
    int s = 0;
    if (fs_journal_differs(h, &old, "this run", "the journal", why, sizeof why) ||
        (old.shard != h->shard || old.nshards != h->nshards
             ? snprintf(why, sizeof why, "shard: %d/%d in this run, %d/%d in the journal", h->shard, h->nshards,
                        old.shard, old.nshards)
             : 0)) {
        fprintf(stderr, "footsim campaign: %s holds the trials of another run of this campaign (%s); they are not "
                "mixed with this run's: run it as it was run to finish it, or add --fresh to start over (the journal "
                "is removed)\n", path, why);
        s = FS_BAD_INPUT;
    }
    if (!s)
        s = check_records(c, h, r, d, path, "move the journal away, or start over with --fresh (it is removed)");
    out->keep_bytes = tail.torn || tail.line ? tail.good_bytes : -1;
    for (int i = 0; !s && i < h->ntrials; i++) {
        if (!d[i])
            continue;
        results[i] = r[i];
        if (d[i] == 1 && r[i].outcome == FS_KILLED)
            out->killed_once[i] = 1;
        else
            out->done[i] = 1, out->ndone++;
    }
    if (!s && tail.line)
        fprintf(stderr, "footsim campaign: %s:%d: %s; the records before that line are kept, it and every line "
                "after it are cut off, and their trials run again\n", path, tail.line, tail.why);
    else if (!s && tail.torn)
        fprintf(stderr, "footsim campaign: %s ends in a record cut short (a kill, a full disk or a file-size limit "
                "in the middle of its write); it is cut off and its trial runs again\n", path);
    if (!s && tail.format != FS_JOURNAL_FORMAT) { /* read cleanly: rewritten whole before anything follows */
        fprintf(stderr, "footsim campaign: %s is of an earlier footsim's journal format (%d); its %d records read "
                "cleanly and are kept, rewritten in format %d\n", path, tail.format, nrecords, FS_JOURNAL_FORMAT);
        if (fs_journal_write(path, h, r, d, &err) != FS_OK)
            s = fail(&err);
        out->keep_bytes = -1;
    }
    fs_journal_head_free(&old);
    free(r), free(d);
    return s;
}

/* Whether a finished folder's expectations (its summary.json's) all held: 0, or FS_EXPECTATION_FAILED
 * with each printed, as the run that wrote it exited. */
static int finished_expectations(const char *dir)
{
    char path[FS_OUT_PATH + 32];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    int failed = 0, total = 0;
    fs_error err;
    if (m && fs_campaign_summary_expectations(path, m, &failed, &total, &err) == FS_OK && failed)
        printf("expectations (as the run that wrote it checked them):\n");
    if (m)
        fclose(m);
    if (failed)
        printf("%s%d of %d expectations FAILED\n", text ? text : "", failed, total);
    free(text);
    return failed ? FS_EXPECTATION_FAILED : 0;
}

/* Runs the trials of c's share that the journal lacks, then draws the --frames-of trials (handing
 * *frames_of on, NULL after) and writes the results. A trial whose worker was killed runs once
 * more, after the others. */
static int run_campaign_trials(const cli_args *a, const fs_campaign *c, const fs_journal_head *h,
                               const char *given_dir, fs_outdir *out, fs_journal *journal, int jobs,
                               cli_frames_of **frames_of)
{
    char jdir[FS_OUT_PATH + 16], jpath[FS_OUT_PATH + 32], again[4 * FS_OUT_PATH];
    snprintf(jdir, sizeof jdir, "%s.journal", out->path);
    snprintf(jpath, sizeof jpath, "%s/journal", jdir);
    command_of(a, given_dir, again, sizeof again);
    int kind = journal_folder(jdir);
    if (kind < 0) {
        fprintf(stderr, "footsim campaign: %s: is not footsim's journal folder (it holds other files); move it away, "
                "or choose another --out\n", jdir);
        return FS_BAD_INPUT;
    }
    if (a->fresh && kind > 0) {
        fs_remove_tree(jdir);
        kind = 0;
    }
    if (!a->fresh && kind == 0 && finished_already(out->path, h, a->shard != NULL)) {
        printf("footsim campaign: %s already holds this campaign's finished results (the same inputs, overrides and "
               "version); nothing to do (--fresh runs it again)\n", out->path);
        return h->nshards > 1 ? 0 : finished_expectations(out->path);
    }
    int ntrials = h->ntrials, npending = 0, total = 0;
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    resumed from = {.done = calloc((size_t)ntrials, 1), .killed_once = calloc((size_t)ntrials, 1), .keep_bytes = -1};
    int *pending = malloc((size_t)ntrials * sizeof *pending);
    if (!results || !from.done || !from.killed_once || !pending) {
        free(results), free(from.done), free(from.killed_once), free(pending);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    int s = 0;
    struct stat st;
    if (kind > 0 && lstat(jpath, &st) == 0)
        s = resume(c, h, jpath, results, &from);
    fs_error err;
    if (!s && kind == 0 && mkdir(jdir, 0777) != 0)
        s = cli_report(FS_IO, "cannot make the journal folder");
    if (!s && fs_journal_open(journal, jpath, h, from.keep_bytes, &err) != FS_OK)
        s = fail(&err);
    for (int i = 0; !s && i < ntrials; i++)
        if (fs_campaign_in_shard(i, h->shard, h->nshards)) {
            total++;
            if (!from.done[i])
                pending[npending++] = i;
        }
    int ndone = from.ndone;
    if (!s && ndone)
        fprintf(stderr, "footsim campaign: resuming from %s: %d of %d trials done, %d to run\n", jpath, ndone, total,
                npending);
    if (!s) {
        journal_run j = {.journal = journal, .killed_before = from.killed_once};
        fs_status r = run_trials(c, results, pending, npending, ndone, total, &j, jobs, "footsim campaign", &err);
        /* the trials whose worker was killed for the first time: once more, after the others */
        int nretry = 0;
        for (int k = 0; r == FS_OK && !interrupted && k < npending; k++)
            if (results[pending[k]].outcome == FS_KILLED && !from.killed_once[pending[k]])
                from.killed_once[pending[k]] = 1, pending[nretry++] = pending[k];
        if (nretry) {
            fprintf(stderr, "footsim campaign: %d trial%s whose worker was killed run%s once more\n", nretry,
                    nretry > 1 ? "s" : "", nretry > 1 ? "" : "s");
            r = run_trials(c, results, pending, nretry, total - nretry, total, &j, jobs, "footsim campaign", &err);
        }
        fs_journal_close(journal);
        int kept = ndone + j.final_records;
        if (kept == 0 && (interrupted || r != FS_OK)) { /* nothing to keep */
            fs_remove_tree(jdir);
        }
        if (interrupted) {
            fprintf(stderr, "footsim campaign: stopped by %s: %d of %d trials done%s%s%s; to continue: %s\n",
                    interrupted == SIGINT ? "SIGINT" : "SIGTERM", kept, total, kept ? ", kept in " : "",
                    kept ? jdir : "", kept ? "/" : "", again);
            s = 128 + interrupted;
        } else if (r != FS_OK) {
            s = fail(&err);
            if (kept)
                fprintf(stderr, "footsim campaign: the %d finished trials are kept in %s/; to run the rest: %s\n", kept,
                        jdir, again);
        } else {
            cli_frames_of *f = *frames_of;
            *frames_of = NULL; /* cli_frames_of_write releases it */
            s = cli_frames_of_write(f, c, results, out->partial, out->path);
            if (!s)
                s = a->shard ? finish_shard(c, h, results, out) : finish(c, results, out); /* 1/1 too: a shard */
            if (!out->open) /* the results are in place: the journal has served */
                fs_remove_tree(jdir);
            else if (interrupted) /* while the results were written (--frames-of, the chart) */
                fprintf(stderr, "footsim campaign: stopped by %s: %d of %d trials done, kept in %s/; to continue: "
                        "%s\n", interrupted == SIGINT ? "SIGINT" : "SIGTERM", kept, total, jdir, again);
            else
                fprintf(stderr, "footsim campaign: the trials are kept in %s/; once the problem is solved, run again: "
                        "%s\n", jdir, again);
        }
    }
    free(results), free(from.done), free(from.killed_once), free(pending);
    return s;
}

/* What a campaign works on, too large for the stack (the campaign, its journal's head and file, the
 * results folder's paths): on the heap, one per command, freed on every path. */
typedef struct campaign_work {
    fs_campaign c;
    fs_journal_head head;
    fs_journal journal;
    fs_outdir out;
} campaign_work;

static int run_campaign(const cli_args *a, campaign_work *w, const char *given_dir, int jobs,
                        cli_frames_of *frames_of)
{
    int s = run_campaign_trials(a, &w->c, &w->head, given_dir, &w->out, &w->journal, jobs, &frames_of);
    cli_frames_of_free(frames_of); /* still here when the trials did not all run */
    return s;
}

/* The campaign a->input with its journal's head, loaded into w, then run (w's parts freed here). */
static int campaign_work_run(const cli_args *a, int jobs, int shard, int nshards, campaign_work *w)
{
    fs_error err;
    if (fs_campaign_load(a->input, a->set, a->nset, &w->c, &err) != FS_OK)
        return fail(&err);
    int s = 0;
    if (fs_journal_head_of(&w->c, a->input, a->set, a->nset, shard, nshards, &w->head, &err) != FS_OK) {
        fs_campaign_free(&w->c);
        return fail(&err);
    }
    cli_frames_of *frames_of = NULL; /* --frames-of (app/cli_frames_of.c): checked before any trial */
    if (a->frames_of && a->shard)
        s = cli_report(FS_BAD_INPUT, "--frames-of with --shard: a shard holds only some trials; draw them from "
                                     "the merged campaign, or run without --shard");
    if (!s)
        s = cli_frames_of_open(a, &w->c, &frames_of);
    if (!s) {
        char dir[FS_OUT_PATH];
        s = cli_results_dir(a, "campaigns", w->c.name, dir, sizeof dir);
        /* SIGINT and SIGTERM stop the trials and keep the journal (a signal ignored stays ignored) */
        fs_catch_signal(SIGINT, on_signal);
        fs_catch_signal(SIGTERM, on_signal);
        if (s) {
            cli_frames_of_free(frames_of);
        } else if (fs_outdir_open(&w->out, dir, a->replace, "--out", &err) != FS_OK) {
            cli_frames_of_free(frames_of);
            s = fail(&err);
        } else {
            s = run_campaign(a, w, dir, jobs, frames_of);
        }
        fs_outdir_abort(&w->out); /* when it was not committed */
    }
    fs_journal_head_free(&w->head);
    fs_campaign_free(&w->c);
    return s;
}

int cli_campaign(const cli_args *a)
{
    int jobs, shard, nshards;
    int s = cli_parse_jobs(a, &jobs);
    if (s || (s = parse_shard(a, &shard, &nshards)))
        return s;
    campaign_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    s = campaign_work_run(a, jobs, shard, nshards, w);
    free(w);
    return s;
}

/* ---- merge -------------------------------------------------------------------------------- */

/* The journal file of a shard folder (DIR/trials.journal) or of a journal folder (DIR/journal). */
static int journal_in(const char *dir, char *path, size_t size)
{
    fs_error err;
    if (fs_path_format(path, size, "merge", &err, "%s/trials.journal", dir) != FS_OK) {
        cli_report(err.status, err.message);
        return 0;
    }
    if (access(path, F_OK) == 0)
        return 1;
    snprintf(path, size, "%s/journal", dir); /* shorter */
    if (access(path, F_OK) == 0)
        return 1;
    fprintf(stderr, "footsim merge: %s: holds no trials.journal; give the folders 'footsim campaign --shard I/N "
            "--out DIR' wrote\n", dir);
    return 0;
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

/* What merge works on, too large for the stack: on the heap, one per command. */
typedef struct merge_work {
    fs_campaign c;
    fs_outdir out;
} merge_work;

int cli_merge(const cli_args *a)
{
    int n = 1 + a->nmore, s = 0;
    const char **dirs = malloc((size_t)n * sizeof *dirs);
    fs_journal_head *heads = calloc((size_t)n, sizeof *heads);
    merge_work *w = calloc(1, sizeof *w);
    if (!dirs || !heads || !w) {
        free(dirs), free(heads), free(w);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    fs_campaign *const c = &w->c;
    dirs[0] = a->input;
    for (int i = 1; i < n; i++)
        dirs[i] = a->more[i - 1];
    fs_trial_result *results = NULL;
    int *from = NULL; /* the shard each trial came from, -1 for none */
    fs_error err;
    int loaded = 0;
    for (int k = 0; k < n && !s; k++) {
        char path[FS_OUT_PATH + 32];
        fs_trial_result *r;
        unsigned char *d;
        int nd;
        if (!journal_in(dirs[k], path, sizeof path)) {
            s = FS_BAD_INPUT;
            break;
        }
        if (fs_journal_read(path, &heads[k], &r, &d, &nd, NULL, &err) != FS_OK) {
            /* a shard's trials.journal is written whole: damage is the disk's or an edit */
            fprintf(stderr, "footsim merge: %s%s\n", err.message,
                    err.status == FS_BAD_INPUT ? "; run that shard again (or give its folder as it was written)" : "");
            s = err.status;
            break;
        }
        char why[512];
        if (k == 0) {
            /* the campaign the shards ran, loaded as they loaded it: its files must not have changed */
            fs_journal_head now;
            if (fs_campaign_load(heads[0].campaign, (const char *const *)heads[0].set, heads[0].nset, c, &err) != FS_OK)
                s = fail(&err);
            else if ((loaded = 1, fs_journal_head_of(c, heads[0].campaign, (const char *const *)heads[0].set,
                                                     heads[0].nset, 1, 1, &now, &err)) != FS_OK)
                s = fail(&err);
            else {
                if (fs_journal_differs(&now, &heads[0], "the campaign now", dirs[0], why, sizeof why) && a->force &&
                    fs_journal_version_only(&now, &heads[0]))
                    fprintf(stderr, "footsim merge: --force: the shards were run by another footsim version (%s); "
                            "their trials are merged as they are and summarized by this version\n", why);
                else if (fs_journal_differs(&now, &heads[0], "the campaign now", dirs[0], why, sizeof why)) {
                    fprintf(stderr, "footsim merge: the campaign %s has changed since its shards ran (%s); run the "
                            "shards again\n", heads[0].campaign, why);
                    s = FS_BAD_INPUT;
                }
                fs_journal_head_free(&now);
            }
            results = calloc((size_t)heads[0].ntrials, sizeof *results);
            from = malloc((size_t)heads[0].ntrials * sizeof *from);
            if (!s && (!results || !from))
                s = cli_report(FS_NO_MEMORY, "out of memory");
            for (int i = 0; !s && i < heads[0].ntrials; i++)
                from[i] = -1;
        } else if (fs_journal_differs(&heads[k], &heads[0], dirs[k], dirs[0], why, sizeof why)) {
            fprintf(stderr, "footsim merge: %s and %s are shards of different campaigns or inputs (%s); merge only "
                    "the shards of one campaign run with the same inputs, overrides and version\n", dirs[k], dirs[0],
                    why);
            s = FS_BAD_INPUT;
        }
        if (!s)
            s = check_records(c, &heads[k], r, d, path, "run that shard again");
        for (int i = 0; !s && i < heads[0].ntrials; i++) {
            if (!d[i])
                continue;
            if (from[i] >= 0) {
                int cell, seed, foot, terrain, robot;
                fs_campaign_trial_of(c, i, &cell, &seed);
                fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
                fprintf(stderr, "footsim merge: trial %d (foot %s on terrain %s under robot %s, seed %d) is in both "
                        "%s and %s; give each shard once, all of one --shard I/N split\n", i, c->foot[foot].name,
                        c->terrain[terrain].name, c->robot[robot].name, seed, dirs[from[i]], dirs[k]);
                s = FS_BAD_INPUT;
            } else {
                results[i] = r[i];
                from[i] = k;
            }
        }
        free(r), free(d);
    }
    int missing = 0;
    for (int i = 0; !s && i < heads[0].ntrials; i++)
        missing += from[i] < 0;
    if (!s && missing) {
        int first = 0;
        while (from[first] >= 0)
            first++;
        int nshards = heads[0].nshards;
        char run[4 * FS_OUT_PATH], shard[32];
        snprintf(shard, sizeof shard, "%d/%d", first % nshards + 1, nshards);
        cli_args again = {.input = heads[0].campaign, .shard = shard, .nset = heads[0].nset};
        for (int i = 0; i < heads[0].nset; i++)
            again.set[i] = heads[0].set[i];
        command_of(&again, "DIR", run, sizeof run);
        fprintf(stderr, "footsim merge: %d of %d trials missing (the first: trial %d, of shard %s); give every "
                "shard's folder, or run the missing shard: %s\n", missing, heads[0].ntrials, first, shard, run);
        s = FS_BAD_INPUT;
    }
    if (!s) {
        char dir[FS_OUT_PATH];
        int input = -1;
        s = cli_results_dir(a, "campaigns", c->name, dir, sizeof dir);
        if (!s && (input = same_folder(dir, dirs, n)) >= 0) {
            fprintf(stderr, "footsim merge: --out %s: is the shard folder %s given to merge (the same folder); "
                    "replacing it would destroy its journal: give another --out\n", dir, dirs[input]);
            s = FS_BAD_INPUT;
        }
        if (s)
            ; /* said */
        else if (fs_outdir_open(&w->out, dir, a->replace, "--out", &err) != FS_OK)
            s = fail(&err);
        else
            s = finish(c, results, &w->out);
        fs_outdir_abort(&w->out);
    }
    for (int k = 0; k < n; k++)
        fs_journal_head_free(&heads[k]);
    if (loaded)
        fs_campaign_free(c);
    free(dirs), free(heads), free(results), free(from), free(w);
    return s;
}

/* ---- compare ------------------------------------------------------------------------------ */

int cli_compare(const cli_args *a)
{
    if (!a->input2)
        return cli_report(FS_BAD_INPUT, "compare: give two summary.json files: RESULT BASELINE");
    fs_error err;
    const fs_compare_opts o = {.force = a->force, .all = a->all, .equivalence = a->equivalence};
    cJSON *json = NULL;
    /* --json: the JSON alone on stdout, whatever the outcome (the Markdown not printed) */
    fs_status s = fs_campaign_compare_with(a->input, a->input2, &o, a->json ? NULL : stdout, a->json ? &json : NULL,
                                           NULL, &err);
    int printed = fs_json_print(stdout, json);
    cJSON_Delete(json);
    if (a->json && !printed && s != FS_NO_MEMORY)
        return cli_report(FS_NO_MEMORY, "compare: out of memory for the JSON");
    return s == FS_OK || s == FS_EXPECTATION_FAILED ? (int)s : fail(&err);
}
