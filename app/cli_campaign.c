/* cli_campaign.c: `footsim campaign`: a campaign run by the library (fs_campaign_run.h) with the
 * command's progress on stderr, its signals, its chart and frames, and what it prints.
 *
 * The library runs the trials in worker processes, resumes from the journal DIR.journal/, runs one
 * shard, and writes the files whole; the command adds: SIGINT and SIGTERM stop the campaign
 * through the progress callback (its 0), the journal kept and the command that continues printed
 * (exit 128 + the signal); the chart drawn by gnuplot and the --frames-of trials drawn into the
 * results before they are put in place; the summary and the expectations on stdout.
 * Tests: FOOTSIM_TEST_CRASH_SEED=N makes a worker exit with status 3 on seed N,
 * FOOTSIM_TEST_STOP_SEED=N stops it (SIGSTOP) on seed N, FOOTSIM_TEST_KILL_SEED=N kills it
 * (SIGKILL) on seed N; FOOTSIM_TEST_KILL_IN_WRITE kills the campaign with SIGKILL half way through
 * writing its files; FOOTSIM_TEST_SIGNAL_AFTER="N SIG" makes the campaign raise signal SIG on itself
 * once N trials are in its journal (a kill at a chosen point, for the resume tests). */
#include "cli.h"

#include "footsim/campaign/fs_campaign_run.h"
#include "footsim/exec/fs_pool.h"
#include "footsim/io/fs_output.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* SIGINT or SIGTERM received while the campaign runs (0: none). */
static volatile sig_atomic_t interrupted;

static void on_signal(int sig) { interrupted = sig; }

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* The test hooks of the environment (FOOTSIM_TEST_*). */
static fs_campaign_test_hooks test_hooks(void)
{
    const char *crash = getenv("FOOTSIM_TEST_CRASH_SEED"), *stop = getenv("FOOTSIM_TEST_STOP_SEED");
    const char *kill_seed = getenv("FOOTSIM_TEST_KILL_SEED"), *after = getenv("FOOTSIM_TEST_SIGNAL_AFTER");
    fs_campaign_test_hooks t = {crash ? atoi(crash) : -1, stop ? atoi(stop) : -1, kill_seed ? atoi(kill_seed) : -1,
                                0, 0, getenv("FOOTSIM_TEST_KILL_IN_WRITE") != NULL};
    if (!after || sscanf(after, "%d %d", &t.signal_after, &t.signal_sig) != 2)
        t.signal_after = 0;
    return t;
}

/* The command's progress callback: the progress line, the library's messages above it, and a stop
 * once a signal came. */
static int show_progress(const fs_campaign_progress *p, void *user)
{
    cli_progress *progress = user;
    if (p->say)
        cli_progress_say(progress, "%s: %s", progress->who, p->say);
    else
        cli_progress_update(progress, p->done, p->total, p->failed);
    return !interrupted;
}

int cli_campaign_trials(const fs_campaign *c, fs_trial_result *results, int jobs, const char *who, fs_error *err)
{
    cli_progress progress;
    cli_progress_start(&progress, who, "trials");
    fs_campaign_test_hooks t = test_hooks();
    fs_campaign_run_opts o = {.jobs = jobs, .progress = show_progress, .user = &progress, .test = &t};
    return fs_campaign_run_trials(c, results, &o, NULL, err);
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
        if (r->drop_law != FS_LAW_NONE)
            printf(", drop law: %s (stands in %d of %d seeds)", fs_law_name(r->drop_law), r->drop_stands, r->drop_seeds);
        if (r->failed_numerics)
            printf(", failed_numerics %d", r->failed_numerics);
        if (r->hung - r->killed)
            printf(", hung %d", r->hung - r->killed);
        if (r->killed)
            printf(", killed %d", r->killed);
        for (int e = 0; c->band[0] && e < fs_campaign_nends(c); e++) /* the row is the worse end's */
            printf("%s%s %d of %d", e ? ", " : "; band: ", c->end[e].name, r->end_landed[e], r->end_trials[e]);
        putchar('\n');
    }
}

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
void cli_campaign_command(const cli_args *a, const char *dir, char *buf, size_t size)
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

int cli_campaign_files_add(const char *partial, const char *shown, const fs_campaign *c,
                           const fs_trial_result *results, const fs_campaign_row *rows, void *user)
{
    (void)rows;
    cli_campaign_files *x = user;
    cli_frames_of *f = x->frames_of;
    x->frames_of = NULL; /* cli_frames_of_write releases it */
    int s = cli_frames_of_write(f, c, results, partial, shown);
    int g = s ? 0 : cli_gnuplot_shown(partial, shown, "chart.gp", "success.png", "campaign");
    x->drawn = g == 0; /* else not drawn (said), or a damaged chart */
    return s ? s : g < 0 ? 0 : g;
}

/* What a finished campaign says on stdout: its rows, its expectations (exit 1 when one fails). */
int cli_campaign_report(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, int drawn)
{
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
    return failed ? FS_EXPECTATION_FAILED : 0;
}

static const char *signal_name(int sig) { return sig == SIGINT ? "SIGINT" : "SIGTERM"; }

/* What the command says and returns once the library has run the campaign (s its status). */
static int after_run(const cli_args *a, const fs_campaign *c, const fs_journal_head *h, const fs_campaign_row *rows,
                     const fs_campaign_state *st, const cli_campaign_files *x, int s, const fs_error *err,
                     const char *given_dir)
{
    char again[4 * FS_OUT_PATH];
    cli_campaign_command(a, given_dir, again, sizeof again);
    if (s == FS_OK && st->finished_already) {
        printf("footsim campaign: %s already holds this campaign's finished results (the same inputs, overrides and "
               "version); nothing to do (--fresh runs it again)\n", st->dir);
        return h->nshards > 1 ? 0 : finished_expectations(st->dir);
    }
    if (s == FS_OK && st->stopped) {
        int sig = interrupted ? interrupted : SIGINT;
        fprintf(stderr, "footsim campaign: stopped by %s: %d of %d trials done%s%s%s; to continue: %s\n",
                signal_name(sig), st->kept, st->total, st->journal_kept ? ", kept in " : "",
                st->journal_kept ? st->journal : "", st->journal_kept ? "/" : "", again);
        return 128 + sig;
    }
    if (s != FS_OK) {
        if (s == (int)err->status && err->message[0])
            fail(err);
        if (st->journal_kept && st->kept == st->total)
            fprintf(stderr, "footsim campaign: the trials are kept in %s/; once the problem is solved, run again: "
                    "%s\n", st->journal, again);
        else if (st->journal_kept && st->kept)
            fprintf(stderr, "footsim campaign: the %d finished trials are kept in %s/; to run the rest: %s\n", st->kept,
                    st->journal, again);
        return s;
    }
    if (a->shard) {
        printf("campaign %s, shard %d/%d: %d of %d trials\nresults: %s/trials.journal (merge the %d shards with "
               "'footsim merge DIR... --out DIR')\n", c->name, h->shard, h->nshards, st->total, h->ntrials, st->dir,
               h->nshards);
        return 0;
    }
    return cli_campaign_report(c, rows, st->dir, x->drawn);
}

/* What a campaign works on, too large for the stack: on the heap, one per command, freed on every path. */
typedef struct campaign_work {
    fs_campaign c;
    fs_journal_head head;
    cli_campaign_files x;
    fs_campaign_state st;
} campaign_work;

/* The campaign a->input with its journal's head, loaded into w, then run (w's parts freed here). */
static int campaign_work_run(const cli_args *a, int jobs, int shard, int nshards, campaign_work *w)
{
    fs_error err = {FS_OK, ""};
    if (fs_campaign_load(a->input, a->set, a->nset, &w->c, &err) != FS_OK)
        return fail(&err);
    int s = 0;
    if (fs_journal_head_of(&w->c, a->input, a->set, a->nset, shard, nshards, &w->head, &err) != FS_OK) {
        fs_campaign_free(&w->c);
        return fail(&err);
    }
    /* --frames-of (app/cli_frames_of.c): checked before any trial */
    if (a->frames_of && a->shard)
        s = cli_report(FS_BAD_INPUT, "--frames-of with --shard: a shard holds only some trials; draw them from "
                                     "the merged campaign, or run without --shard");
    if (!s)
        s = cli_frames_of_open(a, &w->c, &w->x.frames_of);
    fs_campaign_row *rows = s ? NULL : malloc((size_t)fs_campaign_ncells(&w->c) * sizeof *rows);
    if (!s && !rows)
        s = cli_report(FS_NO_MEMORY, "out of memory");
    char dir[FS_OUT_PATH];
    if (!s)
        s = cli_results_dir(a, "campaigns", w->c.name, dir, sizeof dir);
    if (!s) {
        /* SIGINT and SIGTERM stop the trials and keep the journal (a signal ignored stays ignored) */
        fs_catch_signal(SIGINT, on_signal);
        fs_catch_signal(SIGTERM, on_signal);
        fs_campaign_test_hooks t = test_hooks();
        cli_progress_start(&w->x.progress, "footsim campaign", "trials");
        fs_campaign_run_opts o = {.jobs = jobs, .shard = a->shard ? shard : 0, .nshards = a->shard ? nshards : 0,
                                  .fresh = a->fresh, .replace = a->replace, .progress = show_progress,
                                  .extra = cli_campaign_files_add, .user = &w->x, .test = &t};
        s = fs_campaign_run(&w->c, &w->head, dir, &o, rows, &w->st, &err);
        s = after_run(a, &w->c, &w->head, rows, &w->st, &w->x, s, &err, dir);
    }
    cli_frames_of_free(w->x.frames_of); /* still here when the trials did not all run */
    free(rows);
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
