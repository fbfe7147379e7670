/* cli_campaign.c: `footsim campaign` (the trials in worker processes, the result files, the chart,
 * the expectations) and `footsim compare` (a summary against its baseline).
 *
 * Workers are forked processes, each fed trial indices through a pipe and answering with whole
 * results through another of its own, one trial at a time, so the fast take more. A worker
 * that dies (an ODE error exits with status 3) marks its trial failed_numerics, saying which
 * trial, which seed and how it ended; a fresh worker takes its place and the campaign goes on.
 * FOOTSIM_TEST_CRASH_SEED=N (for tests) makes a worker exit with status 3 on seed N;
 * FOOTSIM_TEST_KILL_IN_WRITE kills the campaign with SIGKILL half way through writing its files. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_output.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

enum { MAX_JOBS = 1024 };

/* A worker's answer to one trial, read in full (each worker has its own pipe: nothing interleaves). */
typedef struct message {
    int index;      /* the trial */
    int status;     /* fs_trial_run's */
    fs_trial_result result;
    char error[FS_ERROR_MAX];
} message;

typedef struct worker {
    pid_t pid;
    int task_fd, result_fd; /* the parent's ends, -1 when closed */
    int index;              /* the trial it runs, or -1 when idle */
} worker;

typedef struct pool {
    const fs_campaign *c;
    fs_trial_result *results;
    worker w[MAX_JOBS];
    int nworkers, next, done, ntrials, crash_seed;
    int progress;           /* draw a progress bar (stderr is a terminal) */
} pool;

static int fail(const fs_error *err) { return cli_report(err->status, err->message); }

/* ---- workers ------------------------------------------------------------------------------ */

static int io_full(int fd, void *buf, size_t n, int writing)
{
    size_t done = 0;
    while (done < n) {
        ssize_t k = writing ? write(fd, (char *)buf + done, n - done) : read(fd, (char *)buf + done, n - done);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0)
            return 0;
        done += (size_t)k;
    }
    return 1;
}

static void run_one(const fs_campaign *c, int index, int crash_seed, message *m)
{
    int foot, terrain, seed;
    fs_campaign_trial_of(c, index, &foot, &terrain, &seed);
    if (seed == crash_seed)
        _exit(FS_NUMERICAL); /* FOOTSIM_TEST_CRASH_SEED: what an ODE error does */
    char buf[3][FS_PATH_MAX + 32];
    const char *ov[FS_CAMPAIGN_MAX_SET + 3];
    int n = fs_campaign_overrides(c, foot, terrain, buf, ov);
    fs_error err = {FS_OK, ""};
    memset(m, 0, sizeof *m);
    m->index = index;
    m->status = fs_trial_run(c->trial_path, ov, n, seed, &m->result, &err);
    snprintf(m->error, sizeof m->error, "%s", err.message);
}

/* A worker: runs the trials it is given until its task pipe closes. */
static void worker_main(const pool *p, int task_fd, int result_fd)
{
    int index;
    static message m;
    while (io_full(task_fd, &index, sizeof index, 0)) {
        run_one(p->c, index, p->crash_seed, &m);
        if (!io_full(result_fd, &m, sizeof m, 1))
            _exit(FS_IO);
    }
    _exit(0);
}

static void close_fd(int *fd)
{
    if (*fd >= 0)
        close(*fd);
    *fd = -1;
}

static int spawn(pool *p, worker *w)
{
    int task[2], result[2];
    if (pipe(task) != 0)
        return 0;
    if (pipe(result) != 0) {
        close(task[0]);
        close(task[1]);
        return 0;
    }
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        /* the child keeps only its own ends: a sibling's pipes must close when the parent's do */
        for (int i = 0; i < p->nworkers; i++) {
            close_fd(&p->w[i].task_fd);
            close_fd(&p->w[i].result_fd);
        }
        close(task[1]);
        close(result[0]);
        worker_main(p, task[0], result[1]);
    }
    close(task[0]);
    close(result[1]);
    if (pid < 0) {
        close(task[1]);
        close(result[0]);
        return 0;
    }
    *w = (worker){pid, task[1], result[0], -1};
    return 1;
}

/* Gives w the next trial, or closes its task pipe when there is none (it then exits). */
static void assign(pool *p, worker *w)
{
    if (p->next >= p->ntrials) {
        close_fd(&w->task_fd);
        w->index = -1;
        return;
    }
    w->index = p->next++;
    if (!io_full(w->task_fd, &w->index, sizeof w->index, 1))
        close_fd(&w->task_fd); /* it died: its result pipe says so */
}

/* The record of a trial whose worker died: the pose it drew, and how the worker ended. */
static void record_death(pool *p, int index, int status)
{
    const fs_campaign *c = p->c;
    int foot, terrain, seed;
    fs_campaign_trial_of(c, index, &foot, &terrain, &seed);
    fs_trial_result *r = &p->results[index];
    memset(r, 0, sizeof *r);
    double nan = NAN;
    r->end_time_s = r->touchdown_s = r->peak_tilt_deg = r->final_tilt_deg = r->peak_force_N = nan;
    r->impact_impulse_Ns = r->settle_time_s = r->mean_contacts = r->final_contacts = nan;
    r->ankle_drop_m = r->slip_m = nan;
    r->outcome = FS_FAILED_NUMERICS;
    static fs_scenario sc;
    char buf[3][FS_PATH_MAX + 32];
    const char *ov[FS_CAMPAIGN_MAX_SET + 3];
    int n = fs_campaign_overrides(c, foot, terrain, buf, ov);
    fs_error err;
    if (fs_scenario_load(c->trial_path, ov, n, &sc, &err) == FS_OK)
        fs_trial_draw_pose(&sc, seed, &r->draw);
    fs_scenario_free(&sc);
    r->draw.seed = seed;
    char how[96];
    if (WIFEXITED(status))
        snprintf(how, sizeof how, "exited with status %d", WEXITSTATUS(status));
    else
        snprintf(how, sizeof how, "was killed by signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
    snprintf(r->failure, sizeof r->failure, "the worker running foot %s on terrain %s, seed %d, %s",
             c->foot[foot].name, c->terrain[terrain].name, seed, how);
    if (p->progress)
        fputc('\n', stderr);
    fprintf(stderr, "footsim campaign: %s; counted as failed_numerics\n", r->failure);
}

static void draw_progress(const pool *p)
{
    if (!p->progress)
        return;
    enum { WIDTH = 40 };
    int filled = (int)((long)WIDTH * p->done / p->ntrials);
    fprintf(stderr, "\r[%.*s%*s] %d/%d trials", filled, "########################################", WIDTH - filled, "",
            p->done, p->ntrials);
    if (p->done == p->ntrials)
        fputc('\n', stderr);
    fflush(stderr);
}

/* Reads what worker w has to say. Returns FS_OK, or the status of a trial that was refused. */
static fs_status collect(pool *p, worker *w, fs_error *err)
{
    static message m;
    if (io_full(w->result_fd, &m, sizeof m, 0)) {
        if (m.status != FS_OK)
            return fs_fail(err, (fs_status)m.status, "%s", m.error);
        p->results[m.index] = m.result;
        p->done++;
        assign(p, w);
        return FS_OK;
    }
    /* end of its pipe: it exited, on purpose when idle, or died in the middle of a trial */
    int status = 0, index = w->index;
    close_fd(&w->result_fd);
    close_fd(&w->task_fd);
    waitpid(w->pid, &status, 0);
    w->pid = 0;
    if (index < 0)
        return FS_OK;
    record_death(p, index, status);
    p->done++;
    if (p->next < p->ntrials) {
        if (!spawn(p, w))
            return fs_fail(err, FS_IO, "cannot start a worker process (%s)", strerror(errno));
        assign(p, w);
    }
    return FS_OK;
}

/* Ends every worker still running (after a refused trial) and reaps them all. */
static void stop_workers(pool *p)
{
    for (int i = 0; i < p->nworkers; i++) {
        worker *w = &p->w[i];
        close_fd(&w->task_fd);
        close_fd(&w->result_fd);
        if (w->pid > 0) {
            if (w->index >= 0)
                kill(w->pid, SIGTERM);
            waitpid(w->pid, NULL, 0);
        }
        w->pid = 0;
    }
}

static fs_status run_trials(pool *p, int jobs, fs_error *err)
{
    signal(SIGPIPE, SIG_IGN);
    p->nworkers = jobs < p->ntrials ? jobs : p->ntrials;
    fs_status s = FS_OK;
    for (int i = 0; i < p->nworkers; i++)
        p->w[i] = (worker){0, -1, -1, -1};
    for (int i = 0; i < p->nworkers && s == FS_OK; i++) {
        if (!spawn(p, &p->w[i]))
            s = fs_fail(err, FS_IO, "cannot start a worker process (%s)", strerror(errno));
        else
            assign(p, &p->w[i]);
    }
    draw_progress(p);
    while (s == FS_OK && p->done < p->ntrials) {
        struct pollfd fds[MAX_JOBS];
        int who[MAX_JOBS], n = 0;
        for (int i = 0; i < p->nworkers; i++)
            if (p->w[i].result_fd >= 0 && p->w[i].index >= 0) {
                fds[n] = (struct pollfd){p->w[i].result_fd, POLLIN, 0};
                who[n++] = i;
            }
        if (poll(fds, (nfds_t)n, -1) < 0 && errno != EINTR)
            s = fs_fail(err, FS_IO, "poll: %s", strerror(errno));
        for (int k = 0; k < n && s == FS_OK; k++)
            if (fds[k].revents) {
                s = collect(p, &p->w[who[k]], err);
                draw_progress(p);
            }
    }
    stop_workers(p);
    return s;
}

/* ---- campaign ----------------------------------------------------------------------------- */

int cli_parse_jobs(const cli_args *a, int *jobs)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    *jobs = n > 0 ? (int)(n < MAX_JOBS ? n : MAX_JOBS) : 1;
    if (!a->jobs)
        return 0;
    char *end;
    n = strtol(a->jobs, &end, 10);
    if (*end || end == a->jobs || n < 1 || n > MAX_JOBS) {
        fprintf(stderr, "footsim %s: -j %s: not a number of workers; allowed: a whole number from 1 to %d\n",
                a->command, a->jobs, MAX_JOBS);
        return FS_BAD_INPUT;
    }
    *jobs = (int)n;
    return 0;
}

static void print_rows(const fs_campaign *c, const fs_campaign_row *rows)
{
    for (int i = 0; i < c->nfeet * c->nterrains; i++) {
        const fs_campaign_row *r = &rows[i];
        printf("  %-12s on %-20s landed %3d of %3d (%.2f, 95 %% CI [%.2f, %.2f])", c->foot[r->foot].name,
               c->terrain[r->terrain].name, r->landed, r->trials, r->success_rate, r->ci_low, r->ci_high);
        printf(r->failed_numerics ? ", %d failed_numerics\n" : "\n", r->failed_numerics);
    }
}

/* Summarizes, writes every file (summary.json last), checks the expectations. */
static int finish(const fs_campaign *c, const fs_trial_result *results, fs_outdir *out)
{
    int nrows = c->nfeet * c->nterrains;
    fs_campaign_row *rows = malloc((size_t)nrows * sizeof *rows);
    if (!rows)
        return cli_report(FS_IO, "out of memory");
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
    if (fs_outdir_open(&out, dir, cli_campaign_files, a->replace, "--out", &err) != FS_OK)
        return fail(&err);
    pool *p = calloc(1, sizeof *p);
    int ntrials = fs_campaign_ntrials(&c);
    fs_trial_result *results = p ? calloc((size_t)ntrials, sizeof *results) : NULL;
    if (!results) {
        free(p);
        fs_outdir_abort(&out);
        return cli_report(FS_IO, "out of memory");
    }
    const char *crash = getenv("FOOTSIM_TEST_CRASH_SEED");
    *p = (pool){.c = &c, .results = results, .ntrials = ntrials, .crash_seed = crash ? atoi(crash) : -1,
                .progress = isatty(STDERR_FILENO)};
    if (run_trials(p, jobs, &err) != FS_OK)
        s = fail(&err);
    else
        s = finish(&c, results, &out);
    fs_outdir_abort(&out); /* when it was not committed */
    free(results);
    free(p);
    return s;
}

/* ---- compare ------------------------------------------------------------------------------ */

int cli_compare(const cli_args *a)
{
    if (!a->input2)
        return cli_report(FS_BAD_INPUT, "compare: give two summary.json files: RESULT BASELINE");
    fs_error err;
    fs_status s = fs_campaign_compare(a->input, a->input2, stdout, &err);
    return s == FS_BAD_INPUT ? fail(&err) : (int)s;
}
