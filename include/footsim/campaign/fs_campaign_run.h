/* fs_campaign_run.h: running a campaign, for the command and for any program (Python through
 * footsim/api/fs_api.h): its trials in the pool of worker processes (fs_pool.h), resumed from its
 * journal, one shard of it, shards merged, and its result files written.
 *
 * Contract:
 * - Trials run in forked workers that run only C code and leave with _exit; a worker that exits
 *   with status 3 (an ODE error) makes its trial failed_numerics, one the watchdog kills makes it
 *   hung, one killed any other way (the OOM killer) makes it killed, and a killed trial runs once
 *   more (at the end of the run, or on resume). A fresh worker takes each lost one's place.
 * - Resume: every finished trial is appended to the journal DIR.journal/journal as it ends; a run
 *   whose journal exists (made by the same campaign, inputs, overrides, version and shard, else
 *   FS_BAD_INPUT naming the difference) runs only the trials it lacks, and the journal is removed
 *   once DIR holds the results. A torn or damaged end is cut off (said) and its trials run again.
 *   The files are those of an uninterrupted run, whatever the number of workers or stops.
 * - Progress: the caller's callback is told the trials done (the journal's included), the total and
 *   the failures after every trial and at least every 0.2 s while trials run, and is handed each
 *   line worth saying (a lost worker, a resume, a damaged journal) in `say`; the library prints
 *   nothing. The callback's 0 stops the campaign cleanly: the workers are killed, the finished
 *   trials stay in the journal, nothing else is written, and the same call later goes on from
 *   there (fs_campaign_state.stopped). A program that wants Ctrl-C to stop a campaign makes its
 *   callback return 0 after its signal (the command; Python through its own callback).
 * - The library installs no signal handler and reads no environment: test hooks come in the options.
 * - A shard (1-based `shard` of `nshards` > 1) runs the trials whose index % nshards == shard - 1
 *   and writes DIR/trials.journal; fs_campaign_merge makes the campaign's files of the shard folders,
 *   the same bytes as the campaign run whole. */
#ifndef FS_CAMPAIGN_RUN_H
#define FS_CAMPAIGN_RUN_H

#include "footsim/campaign/fs_campaign.h"

/* What a progress callback is told. */
typedef struct fs_campaign_progress {
    int done, total;  /* trials of this run's share finished (the journal's included), of total */
    int failed;       /* of those run now, failed numerically or lost their worker */
    const char *say;  /* NULL, or one line worth saying (no newline, no prefix) */
} fs_campaign_progress;

/* Returns nonzero to go on, 0 to stop (cleanly and resumably). */
typedef int (*fs_campaign_progress_fn)(const fs_campaign_progress *p, void *user);

/* Failures on purpose, for tests (the command takes them from FOOTSIM_TEST_* variables): a worker
 * that reaches crash_seed exits with status 3 (what an ODE error does), one that reaches stop_seed
 * stops itself (SIGSTOP: the watchdog's case), one that reaches kill_seed is killed (SIGKILL);
 * once signal_after trials are journaled the caller's process raises signal_sig; kill_in_write
 * kills it (SIGKILL) in the middle of writing the files. Seeds below 0 and counts of 0: none. */
typedef struct fs_campaign_test_hooks {
    int crash_seed, stop_seed, kill_seed;
    int signal_after, signal_sig;
    int kill_in_write;
} fs_campaign_test_hooks;

/* Called once the trials have run and the result files but summary.json are in `partial` (the
 * folder swapped in whole at the end; `shown` is what it will be called): the caller adds its own
 * (the chart's PNG, frames of chosen trials). Its nonzero return (an fs_status or an exit status,
 * said by the caller) gives up the results: nothing is put in place, the journal stays. */
typedef int (*fs_campaign_extra_fn)(const char *partial, const char *shown, const fs_campaign *c,
                                    const fs_trial_result *results, const fs_campaign_row *rows, void *user);

typedef struct fs_campaign_run_opts {
    int jobs;                          /* worker processes; <= 0: fs_pool_default_jobs() */
    int shard, nshards;                /* 0/0 or 1/1: the whole campaign */
    int fresh;                         /* start over: the journal removed first */
    int replace;                       /* replace a non-empty folder footsim did not make (--replace) */
    fs_campaign_progress_fn progress;  /* may be NULL */
    fs_campaign_extra_fn extra;        /* may be NULL */
    void *user;                        /* for both */
    const fs_campaign_test_hooks *test;/* NULL: none */
} fs_campaign_run_opts;

/* How a run ended, beside its status. */
typedef struct fs_campaign_state {
    int finished_already; /* DIR held this campaign's (or shard's) finished results: nothing ran */
    int stopped;          /* the callback stopped it: `kept` trials are in the journal (0: none kept) */
    int kept, total;      /* final trials in the journal at the end, of the share's */
    int journal_kept;     /* the journal folder is still there (to resume or retry) */
    int committed;        /* DIR holds the results */
    char journal[FS_OUT_PATH + 16]; /* DIR.journal */
    char dir[FS_OUT_PATH];          /* DIR, normalised */
} fs_campaign_state;

/* Runs the campaign c (fs_campaign_load) with its journal head h (fs_journal_head_of with the same
 * shard) into the results folder dir (fs_outdir_open: checked before any trial runs): the trials
 * the journal lacks, then the files (fs_campaign_write, the chart's data, o->extra, summary.json
 * last; a shard: DIR/trials.journal), put in place whole. rows (fs_campaign_ncells(c), may be
 * NULL) get the summary. An fs_status (or extra's nonzero); `state` says how it ended. */
int fs_campaign_run(const fs_campaign *c, const fs_journal_head *h, const char *dir, const fs_campaign_run_opts *o,
                    fs_campaign_row *rows, fs_campaign_state *state, fs_error *err);

/* Runs every trial of c in o->jobs workers into results (by trial index), no journal, no files:
 * for a program that judges the results itself (the design search, the equivalence bench); of o
 * only jobs, progress, user and test count. A stop (the callback's 0) is FS_OK with *stopped set
 * (stopped may be NULL), the results then incomplete. */
fs_status fs_campaign_run_trials(const fs_campaign *c, fs_trial_result *results, const fs_campaign_run_opts *o,
                                 int *stopped, fs_error *err);

/* Shards merged: fs_campaign_merge reads the shard folders dirs[n] (each holding DIR/trials.journal,
 * or a journal folder) of one campaign into m: the campaign, loaded as the shards loaded it, the
 * first shard's head (its campaign file and overrides, for messages) and every trial's result.
 * FS_BAD_INPUT, said, when the shards come from other campaigns, inputs, overrides or versions,
 * when the campaign's files changed since, when a trial is in two shards, or when one is missing
 * (m->missing_shard: the first missing trial's shard, 1-based, of m->head.nshards). With force,
 * shards whose only difference from the campaign now is footsim's version are merged as they are
 * (m->other_version set, m->version_note saying which): the summaries are this version's.
 * fs_campaign_merge_write writes the campaign's files into dir as fs_campaign_run does (the same
 * bytes as the campaign run whole; o's extra and progress as there), refusing a dir that is one of
 * the shard folders. fs_campaign_merge_free releases m (also after a failure). */
typedef struct fs_campaign_merged {
    fs_campaign c;
    int loaded;                 /* c is loaded (fs_campaign_free'd by fs_campaign_merge_free) */
    fs_journal_head head;
    fs_trial_result *results;   /* by trial index */
    int missing_shard;
    const char *const *dirs;
    int n;
    int other_version;          /* force merged shards of another footsim version */
    char version_note[512];     /* which versions, said */
} fs_campaign_merged;
fs_status fs_campaign_merge(const char *const *dirs, int n, int force, fs_campaign_merged *m, fs_error *err);
int fs_campaign_merge_write(const fs_campaign_merged *m, const char *dir, int replace, const fs_campaign_run_opts *o,
                            fs_campaign_row *rows, fs_campaign_state *state, fs_error *err);
void fs_campaign_merge_free(fs_campaign_merged *m);

#endif
