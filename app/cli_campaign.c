/* cli_campaign.c: `footsim campaign` (the trials in worker processes, the result files, the chart,
 * the expectations) and `footsim compare` (a summary against its baseline).
 *
 * The trials run in footsim's pool of worker processes (fs_pool.h). A worker that dies (an ODE
 * error exits with status 3) marks its trial failed_numerics, one that the watchdog kills (no
 * answer for FS_POOL_WATCHDOG_S) marks it hung, never a numerical failure; each is said with its
 * trial, seed and how it ended; a fresh worker takes its place and the campaign goes on. Tests: FOOTSIM_TEST_CRASH_SEED=N makes a worker exit with
 * status 3 on seed N, FOOTSIM_TEST_STOP_SEED=N stops it (SIGSTOP) on seed N;
 * FOOTSIM_TEST_KILL_IN_WRITE kills the campaign with SIGKILL half way through writing its files. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/exec/fs_pool.h"
#include "footsim/io/fs_output.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
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
    int crash_seed, stop_seed;
    cli_progress progress;
    int failed;             /* trials so far that failed numerically or whose worker died */
} campaign_run;

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* ---- the pool's callbacks ----------------------------------------------------------------- */

/* In a worker: one trial. */
static void run_one(int index, void *result, void *user)
{
    const campaign_run *p = user;
    message *m = result;
    const fs_campaign *c = p->c;
    int cell, seed;
    fs_campaign_trial_of(c, index, &cell, &seed);
    if (seed == p->crash_seed)
        _exit(FS_NUMERICAL); /* FOOTSIM_TEST_CRASH_SEED: what an ODE error does */
    if (seed == p->stop_seed)
        raise(SIGSTOP); /* FOOTSIM_TEST_STOP_SEED: a worker that hangs, for the watchdog */
    fs_error err = {FS_OK, ""};
    m->status = fs_trial_run_scenario(fs_campaign_pair(c, cell), seed, NULL, &m->result, &err);
    snprintf(m->error, sizeof m->error, "%s", err.message);
}

/* In the parent: a trial's answer, or the refusal that stops the campaign. */
static fs_status take_one(int index, const void *result, void *user, fs_error *err)
{
    campaign_run *p = user;
    const message *m = result;
    if (m->status != FS_OK)
        return fs_fail(err, (fs_status)m->status, "%s", m->error);
    p->results[index] = m->result;
    p->failed += m->result.outcome == FS_FAILED_NUMERICS;
    return FS_OK;
}

/* In the parent: the record of a trial whose worker died: the pose it drew, and how it ended. */
static void record_death(int index, const fs_pool_death *d, void *user)
{
    campaign_run *p = user;
    const fs_campaign *c = p->c;
    int cell, seed;
    fs_campaign_trial_of(c, index, &cell, &seed);
    fs_trial_result *r = &p->results[index];
    memset(r, 0, sizeof *r);
    double nan = NAN;
    r->end_time_s = r->touchdown_s = r->peak_tilt_deg = r->final_tilt_deg = r->peak_force_N = nan;
    r->impact_impulse_Ns = r->settle_time_s = r->mean_contacts = r->final_contacts = nan;
    r->ankle_drop_m = r->slip_m = nan;
    r->outcome = d->timed_out ? FS_HUNG : FS_FAILED_NUMERICS; /* a hang says nothing of the physics */
    fs_trial_draw_pose(fs_campaign_pair(c, cell), seed, &r->draw);
    int foot, terrain, robot;
    fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
    r->rule = d->timed_out ? FS_RULE_WATCHDOG : FS_RULE_NUMERICS;
    snprintf(r->failure, sizeof r->failure, "the worker running foot %s on terrain %s under robot %s, seed %d, %s",
             c->foot[foot].name, c->terrain[terrain].name, c->robot[robot].name, seed, d->how);
    p->failed++;
    if (p->progress.tty)
        fputc('\n', stderr);
    fprintf(stderr, "footsim campaign: %s; counted as %s\n", r->failure, fs_outcome_name(r->outcome));
}

static void draw_progress(int done, int ntrials, void *user)
{
    campaign_run *p = user;
    cli_progress_update(&p->progress, done, ntrials, p->failed);
}

/* ---- campaign ----------------------------------------------------------------------------- */

int cli_campaign_trials(const fs_campaign *c, fs_trial_result *results, int jobs, const char *who, fs_error *err)
{
    const char *crash = getenv("FOOTSIM_TEST_CRASH_SEED"), *stop = getenv("FOOTSIM_TEST_STOP_SEED");
    campaign_run run = {.c = c, .results = results, .crash_seed = crash ? atoi(crash) : -1,
                        .stop_seed = stop ? atoi(stop) : -1};
    cli_progress_start(&run.progress, who, "trials");
    fs_pool_spec spec = {.ntasks = fs_campaign_ntrials(c), .jobs = jobs, .result_size = sizeof(message), .user = &run,
                         .run = run_one, .done = take_one, .died = record_death, .progress = draw_progress};
    fs_pool_stats stats;
    fs_status s = fs_pool_run(&spec, &stats, err);
    if (s == FS_OK && stats.timed_out)
        fprintf(stderr, "%s: %d worker%s made no progress for the watchdog's time and %s killed; their trials are "
                        "counted as hung, not as numerical failures\n",
                who, stats.timed_out, stats.timed_out > 1 ? "s" : "", stats.timed_out > 1 ? "were" : "was");
    return s;
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
        if (r->hung)
            printf(", hung %d", r->hung);
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
    int g = s == FS_OK ? cli_gnuplot(out->partial, "chart.gp", "success.png", "campaign") : 0;
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
    printf("results: %s/summary.md, summary.csv, summary.json, trials.csv, success.png\n", dir);
    free(rows);
    return failed ? FS_EXPECTATION_FAILED : 0;
}

int cli_campaign(const cli_args *a)
{
    int jobs;
    int s = cli_parse_jobs(a, &jobs);
    if (s)
        return s;
    static fs_campaign c;
    fs_error err;
    if (fs_campaign_load(a->input, a->set, a->nset, &c, &err) != FS_OK)
        return fail(&err);
    char dir[FS_PATH_MAX + 64];
    snprintf(dir, sizeof dir, a->out ? "%s" : "results/campaigns/%s", a->out ? a->out : c.name);
    static fs_outdir out;
    if (fs_outdir_open(&out, dir, cli_campaign_files, a->replace, "--out", &err) != FS_OK) {
        fs_campaign_free(&c);
        return fail(&err);
    }
    int ntrials = fs_campaign_ntrials(&c);
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    if (!results) {
        fs_outdir_abort(&out);
        fs_campaign_free(&c);
        return cli_report(FS_NO_MEMORY, "out of memory");
    }
    if (cli_campaign_trials(&c, results, jobs, "footsim campaign", &err) != FS_OK)
        s = fail(&err);
    else
        s = finish(&c, results, &out);
    fs_outdir_abort(&out); /* when it was not committed */
    free(results);
    fs_campaign_free(&c);
    return s;
}

/* ---- compare ------------------------------------------------------------------------------ */

int cli_compare(const cli_args *a)
{
    if (!a->input2)
        return cli_report(FS_BAD_INPUT, "compare: give two summary.json files: RESULT BASELINE");
    fs_error err;
    fs_status s = fs_campaign_compare(a->input, a->input2, a->force, stdout, &err);
    return s == FS_BAD_INPUT ? fail(&err) : (int)s;
}
