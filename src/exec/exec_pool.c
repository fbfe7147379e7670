/* exec_pool.c: worker processes fed through pipes, answers collected with poll, a watchdog on
 * each task's wall time. */
#include "footsim/exec/fs_pool.h"

#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* An answer on the wire: the task number in a header as wide as the strictest alignment, then the
 * result, so the result in the buffer is aligned for any type. */
#define HEAD ((size_t)_Alignof(max_align_t))

typedef struct worker {
    pid_t pid;
    int task_fd, result_fd; /* the parent's ends, -1 when closed */
    int task;               /* the task it runs, or -1 when idle */
    double since_s;         /* when it was given that task */
} worker;

typedef struct pool {
    const fs_pool_spec *spec;
    worker *w;
    int nworkers, next, finished;
    double watchdog_s;
    unsigned char *buf;     /* one answer: HEAD bytes holding the task number, then result_size bytes */
    fs_pool_stats stats;
} pool;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

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

static void close_fd(int *fd)
{
    if (*fd >= 0)
        close(*fd);
    *fd = -1;
}

/* A worker: runs the tasks it is given until its task pipe closes. */
static void worker_main(const fs_pool_spec *spec, unsigned char *buf, int task_fd, int result_fd)
{
    int task;
    while (io_full(task_fd, &task, sizeof task, 0)) {
        memset(buf, 0, HEAD + spec->result_size);
        memcpy(buf, &task, sizeof task);
        spec->run(task, buf + HEAD, spec->user);
        if (!io_full(result_fd, buf, HEAD + spec->result_size, 1))
            _exit(4);
    }
    _exit(0);
}

static int spawn(pool *p, worker *w)
{
    int task[2], result[2];
    if (pipe(task) != 0)
        return 0;
    if (pipe(result) != 0) {
        int e = errno;
        close(task[0]);
        close(task[1]);
        errno = e;
        return 0;
    }
    fflush(stdout);
    fflush(stderr);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid == 0) {
        /* a worker dies with its parent (a kill -9 of the campaign leaves no worker running on) */
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent)
            _exit(FS_IO);
        /* the child keeps only its own ends: a sibling's pipes must close when the parent's do */
        for (int i = 0; i < p->nworkers; i++) {
            close_fd(&p->w[i].task_fd);
            close_fd(&p->w[i].result_fd);
        }
        close(task[1]);
        close(result[0]);
        signal(SIGPIPE, SIG_DFL);
        worker_main(p->spec, p->buf, task[0], result[1]);
    }
    int e = errno;
    close(task[0]);
    close(result[1]);
    if (pid < 0) {
        close(task[1]);
        close(result[0]);
        errno = e;
        return 0;
    }
    *w = (worker){pid, task[1], result[0], -1, 0};
    return 1;
}

/* Gives w the next task, or closes its task pipe when there is none (it then exits). */
static void assign(pool *p, worker *w)
{
    if (p->next >= p->spec->ntasks) {
        close_fd(&w->task_fd);
        w->task = -1;
        return;
    }
    w->task = p->next++;
    w->since_s = now_s();
    if (!io_full(w->task_fd, &w->task, sizeof w->task, 1))
        close_fd(&w->task_fd); /* it died: its result pipe says so */
}

static void progress(pool *p)
{
    if (p->spec->progress)
        p->spec->progress(p->finished, p->spec->ntasks, p->spec->user);
}

/* Reaps w (killing it first when kill_it), reports its task as dead, and starts a fresh worker
 * when tasks remain. */
static fs_status bury(pool *p, worker *w, int timed_out, fs_error *err)
{
    int status = 0, task = w->task;
    if (timed_out)
        kill(w->pid, SIGKILL);
    close_fd(&w->result_fd);
    close_fd(&w->task_fd);
    while (waitpid(w->pid, &status, 0) < 0 && errno == EINTR) {
    }
    w->pid = 0;
    w->task = -1;
    if (task < 0)
        return FS_OK;
    fs_pool_death d = {0};
    if (timed_out) {
        d.timed_out = 1, d.signal = SIGKILL;
        snprintf(d.how, sizeof d.how, "made no progress for %g s and was killed by the watchdog", p->watchdog_s);
        p->stats.timed_out++;
    } else if (WIFEXITED(status)) {
        d.exited = 1, d.status = WEXITSTATUS(status);
        snprintf(d.how, sizeof d.how, "exited with status %d", d.status);
    } else {
        d.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
        snprintf(d.how, sizeof d.how, "was killed by signal %d (%s)", d.signal, strsignal(d.signal));
    }
    p->stats.died++;
    p->finished++;
    if (p->spec->died)
        p->spec->died(task, &d, p->spec->user);
    progress(p);
    if (p->next < p->spec->ntasks) {
        if (!spawn(p, w))
            return fs_fail(err, FS_IO, "cannot start a worker process (%s)", strerror(errno));
        assign(p, w);
    }
    return FS_OK;
}

/* Reads what worker w has to say. */
static fs_status collect(pool *p, worker *w, fs_error *err)
{
    size_t n = HEAD + p->spec->result_size;
    if (!io_full(w->result_fd, p->buf, n, 0))
        return bury(p, w, 0, err); /* end of its pipe: it died in the middle of its task */
    int task;
    memcpy(&task, p->buf, sizeof task);
    if (task != w->task)
        return fs_fail(err, FS_IO, "a worker answered task %d when given %d", task, w->task);
    p->stats.answered++;
    p->finished++;
    fs_status s = p->spec->done(task, p->buf + HEAD, p->spec->user, err);
    progress(p);
    if (s == FS_OK)
        assign(p, w);
    return s;
}

/* Ends every worker still running and reaps them all. */
static void stop_workers(pool *p)
{
    for (int i = 0; i < p->nworkers; i++) {
        worker *w = &p->w[i];
        close_fd(&w->task_fd);
        close_fd(&w->result_fd);
        if (w->pid > 0) {
            if (w->task >= 0)
                kill(w->pid, SIGKILL);
            while (waitpid(w->pid, NULL, 0) < 0 && errno == EINTR) {
            }
        }
        w->pid = 0;
    }
}

fs_status fs_pool_run(const fs_pool_spec *spec, fs_pool_stats *stats, fs_error *err)
{
    pool p = {.spec = spec};
    const char *env = getenv("FOOTSIM_WATCHDOG_S");
    p.watchdog_s = env && atof(env) > 0 ? atof(env) : spec->watchdog_s > 0 ? spec->watchdog_s : FS_POOL_WATCHDOG_S;
    int jobs = spec->jobs < 1 ? 1 : spec->jobs > FS_POOL_MAX_JOBS ? FS_POOL_MAX_JOBS : spec->jobs;
    p.nworkers = jobs < spec->ntasks ? jobs : spec->ntasks;
    p.w = calloc((size_t)(p.nworkers > 0 ? p.nworkers : 1), sizeof *p.w);
    p.buf = malloc(HEAD + spec->result_size);
    struct pollfd *fds = calloc((size_t)(p.nworkers > 0 ? p.nworkers : 1), sizeof *fds);
    int *who = calloc((size_t)(p.nworkers > 0 ? p.nworkers : 1), sizeof *who);
    if (!p.w || !p.buf || !fds || !who) {
        free(p.w), free(p.buf), free(fds), free(who);
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the worker pool");
    }
    void (*old_pipe)(int) = signal(SIGPIPE, SIG_IGN);
    for (int i = 0; i < p.nworkers; i++)
        p.w[i] = (worker){0, -1, -1, -1, 0};
    fs_status s = FS_OK;
    for (int i = 0; i < p.nworkers && s == FS_OK; i++) {
        if (!spawn(&p, &p.w[i]))
            s = fs_fail(err, FS_IO, "cannot start a worker process (%s)", strerror(errno));
        else
            assign(&p, &p.w[i]);
    }
    progress(&p);
    while (s == FS_OK && p.finished < spec->ntasks && !(spec->stop && *spec->stop)) {
        int n = 0;
        double t = now_s(), wait_s = p.watchdog_s;
        for (int i = 0; i < p.nworkers; i++)
            if (p.w[i].result_fd >= 0 && p.w[i].task >= 0) {
                fds[n] = (struct pollfd){p.w[i].result_fd, POLLIN, 0};
                who[n++] = i;
                double left = p.w[i].since_s + p.watchdog_s - t;
                wait_s = left < wait_s ? left : wait_s;
            }
        if (n == 0) {
            s = fs_fail(err, FS_IO, "the worker pool has tasks left and no worker running them");
            break;
        }
        /* wake at least every tick: progress is told while no task ends */
        double tick_s = spec->tick_s > 0 ? spec->tick_s : FS_POOL_TICK_S;
        wait_s = wait_s < tick_s ? wait_s : tick_s;
        int ms = wait_s <= 0 ? 0 : (int)(wait_s * 1000) + 1;
        if (spec->stop && ms > 200)
            ms = 200; /* a signal between the test of *stop and poll is seen this soon */
        int ready = poll(fds, (nfds_t)n, ms);
        if (ready < 0 && errno != EINTR) {
            s = fs_fail(err, FS_IO, "poll: %s", strerror(errno));
            break;
        }
        if (ready == 0)
            progress(&p);
        for (int k = 0; k < n && s == FS_OK && !(spec->stop && *spec->stop); k++)
            if (fds[k].revents)
                s = collect(&p, &p.w[who[k]], err);
        /* the watchdog: a worker without an answer for watchdog_s is killed, its task counted */
        t = now_s();
        for (int i = 0; i < p.nworkers && s == FS_OK; i++)
            if (p.w[i].pid > 0 && p.w[i].task >= 0 && t - p.w[i].since_s >= p.watchdog_s)
                s = bury(&p, &p.w[i], 1, err);
    }
    stop_workers(&p);
    signal(SIGPIPE, old_pipe);
    if (stats)
        *stats = p.stats;
    free(p.w), free(p.buf), free(fds), free(who);
    return s;
}
