/* fs_pool.h: tasks run in a pool of worker processes, with a watchdog.
 *
 * Workers are forked processes, not threads: ODE ends the process after its error handler, so a
 * task that breaks ODE takes only its worker with it. Each worker is fed task numbers through a
 * pipe of its own and answers through another, one task at a time (the fast take more); the
 * parent hands every answer to `done` with its task number, so what the caller builds from the
 * answers does not depend on the number of workers or on who ran what.
 *
 * A worker that dies in a task (an exit status, a signal) or that gives no answer for watchdog_s
 * seconds (stopped, hung, looping) is reported to `died` with its task and how it ended, and
 * counted; the watchdog kills it with SIGKILL. A fresh worker takes its place and the pool goes on.
 * `done` may stop the pool by returning a status other than FS_OK: the workers still running are
 * killed and reaped. No worker outlives fs_pool_run, nor its parent: a worker whose parent dies (a
 * kill -9) is killed with it. */
#ifndef FS_POOL_H
#define FS_POOL_H

#include "footsim/base/fs_error.h"

#include <signal.h>
#include <stddef.h>

/* How a worker ended in the middle of a task. */
typedef struct fs_pool_death {
    int exited, status;  /* exited with status */
    int signal;          /* killed by this signal (SIGKILL for the watchdog) */
    int timed_out;       /* killed by the watchdog after watchdog_s without an answer */
    char how[128];       /* in words: "exited with status 3", "made no progress for 600 s ..." */
} fs_pool_death;

typedef struct fs_pool_spec {
    int ntasks;          /* tasks 0 .. ntasks - 1 */
    int jobs;            /* worker processes (at most FS_POOL_MAX_JOBS; fewer when fewer tasks) */
    size_t result_size;  /* bytes of one answer */
    double watchdog_s;   /* a worker with no answer for this long is killed; <= 0: FS_POOL_WATCHDOG_S */
    double tick_s;       /* progress is told again after this long without an answer; <= 0: FS_POOL_TICK_S */
    void *user;
    /* in a worker: runs task, filling result (result_size bytes, zeroed before) */
    void (*run)(int task, void *result, void *user);
    /* in the parent: task's answer; a status other than FS_OK (err filled) stops the pool */
    fs_status (*done)(int task, const void *result, void *user, fs_error *err);
    /* in the parent: the worker running task died or was killed by the watchdog */
    void (*died)(int task, const fs_pool_death *death, void *user);
    /* in the parent, optional: after each task, answered or dead, and at least every
       tick_s while no task ends (done unchanged), so that a reporter's clock moves */
    void (*progress)(int done, int ntasks, void *user);
    /* optional: when *stop becomes nonzero (a signal handler's flag), the pool stops within a
     * fraction of a second: the workers still running are killed and reaped, the tasks they ran
     * neither answered nor reported dead, and fs_pool_run returns FS_OK (the caller knows why) */
    const volatile sig_atomic_t *stop;
} fs_pool_spec;

enum { FS_POOL_MAX_JOBS = 1024 };

/* The watchdog's default, s: far beyond any trial or benchmark run footsim ships (seconds each).
 * FOOTSIM_WATCHDOG_S in the environment replaces it (and any watchdog_s), e.g. for tests. */
#define FS_POOL_WATCHDOG_S 600.0

/* The longest the pool waits for an answer before telling progress again, s. */
#define FS_POOL_TICK_S 5.0

/* What a pool run saw. */
typedef struct fs_pool_stats {
    int answered, died, timed_out; /* timed_out counts among died */
} fs_pool_stats;

/* Runs every task; FS_OK, or done's status, or FS_IO when no worker could be started (the system's
 * reason in err). stats may be NULL. */
fs_status fs_pool_run(const fs_pool_spec *spec, fs_pool_stats *stats, fs_error *err);

/* The workers to run when the user gives no -j: the CPUs this process may use, the least of its
 * affinity mask, its cgroup's CPU quota (cgroup v2 cpu.max, rounded up) and SLURM_CPUS_PER_TASK;
 * at least 1. fs_pool_jobs_from is the same rule on given values (cpu_max: the text of cpu.max,
 * slurm_cpus: the variable's text; either may be NULL or empty). */
int fs_pool_default_jobs(void);
int fs_pool_jobs_from(int affinity_cpus, const char *cpu_max, const char *slurm_cpus);

#endif
