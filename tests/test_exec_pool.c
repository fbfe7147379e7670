/* Tests of exec_pool.c: answers reach the parent by task number whatever the number of workers; a
 * worker that exits, is killed or stops is reported with its task and replaced; the watchdog
 * kills a stopped worker; `done` can stop the pool. Workers are real forked processes. */
#include "fs_test.h"

#include "footsim/exec/fs_pool.h"

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

enum { NTASKS = 40 };

/* A task's answer: mixed types, so a misaligned result would show under UBSan. */
typedef struct answer {
    char tag;
    double square;
    long pid;
} answer;

typedef struct state {
    double got[NTASKS];
    int seen[NTASKS], died[NTASKS], timed_out[NTASKS];
    int exit_on, stop_on, kill_on, refuse_on; /* the task that misbehaves so, or -1 */
} state;

static void run_task(int task, void *result, void *user)
{
    const state *s = user;
    if (task == s->exit_on)
        _exit(3); /* what ODE's error handler does */
    if (task == s->kill_on)
        raise(SIGKILL); /* a crash */
    if (task == s->stop_on)
        raise(SIGSTOP); /* hangs: only the watchdog ends it */
    answer *a = result;
    a->tag = 'a';
    a->square = (double)task * task + 0.25;
    a->pid = (long)getpid();
}

static fs_status take(int task, const void *result, void *user, fs_error *err)
{
    state *s = user;
    const answer *a = result;
    s->got[task] = a->square;
    s->seen[task]++;
    if (task == s->refuse_on)
        return fs_fail(err, FS_BAD_INPUT, "task %d refused", task);
    return FS_OK;
}

static void died(int task, const fs_pool_death *d, void *user)
{
    state *s = user;
    s->died[task]++;
    s->timed_out[task] += d->timed_out;
}

static fs_status run_pool(state *s, int jobs, double watchdog_s, fs_pool_stats *st, fs_error *err)
{
    fs_pool_spec spec = {.ntasks = NTASKS, .jobs = jobs, .result_size = sizeof(answer), .watchdog_s = watchdog_s,
                         .user = s, .run = run_task, .done = take, .died = died};
    return fs_pool_run(&spec, st, err);
}

static void fresh(state *s) { *s = (state){.exit_on = -1, .stop_on = -1, .kill_on = -1, .refuse_on = -1}; }

static void answers_do_not_depend_on_jobs(void)
{
    static state one, four;
    fs_error err;
    fs_pool_stats st;
    fresh(&one), fresh(&four);
    CHECK(run_pool(&one, 1, 0, &st, &err) == FS_OK && st.answered == NTASKS && st.died == 0);
    CHECK(run_pool(&four, 4, 0, &st, &err) == FS_OK && st.answered == NTASKS);
    for (int i = 0; i < NTASKS; i++) {
        CHECK(one.seen[i] == 1 && four.seen[i] == 1);
        CHECK(one.got[i] == (double)i * i + 0.25 && !memcmp(&one.got[i], &four.got[i], sizeof one.got[i]));
    }
}

static void dead_workers_are_reported_and_replaced(void)
{
    static state s;
    fs_error err;
    fs_pool_stats st;
    fresh(&s);
    s.exit_on = 7, s.kill_on = 20;
    CHECK(run_pool(&s, 3, 0, &st, &err) == FS_OK);
    CHECK(st.died == 2 && st.answered == NTASKS - 2 && st.timed_out == 0);
    CHECK(s.died[7] == 1 && s.died[20] == 1 && !s.seen[7] && !s.seen[20]);
    for (int i = 0; i < NTASKS; i++)
        if (i != 7 && i != 20)
            CHECK(s.seen[i] == 1 && !s.died[i]);
}

static void the_watchdog_kills_a_stopped_worker(void)
{
    static state s;
    fs_error err;
    fs_pool_stats st;
    fresh(&s);
    s.stop_on = 5;
    CHECK(run_pool(&s, 2, 3, &st, &err) == FS_OK); /* 3 s: the other tasks take microseconds */
    CHECK(st.timed_out == 1 && st.died == 1 && s.timed_out[5] == 1 && st.answered == NTASKS - 1);
}

/* Progress is told again while no task ends (the tick), not only after each task: a log's
 * once-a-minute line needs it. A stopped worker holds its task until the watchdog (1 s); the pool
 * wakes every 0.1 s meanwhile, so progress comes with the count unchanged before the task is
 * reported dead (without the tick it would come only after each task). */
typedef struct ticks {
    state s;
    int last, repeats, died_at_repeats;
} ticks;

static void count_progress(int done, int ntasks, void *user)
{
    (void)ntasks;
    ticks *t = user;
    t->repeats += done == t->last && done > 0;
    t->last = done;
}

static void died_counting(int task, const fs_pool_death *d, void *user)
{
    ticks *t = user;
    died(task, d, &t->s);
    t->died_at_repeats = t->repeats;
}

static void run_task_ticks(int task, void *result, void *user) { run_task(task, result, &((ticks *)user)->s); }

static fs_status take_ticks(int task, const void *result, void *user, fs_error *err)
{
    return take(task, result, &((ticks *)user)->s, err);
}

static void progress_ticks_while_no_task_ends(void)
{
    static ticks t;
    fresh(&t.s);
    t.s.stop_on = NTASKS - 1; /* the last: every other is answered before the wait */
    t.last = -1;
    fs_error err;
    fs_pool_stats st;
    fs_pool_spec spec = {.ntasks = NTASKS, .jobs = 2, .result_size = sizeof(answer), .watchdog_s = 1,
                         .tick_s = 0.1, .user = &t, .run = run_task_ticks, .done = take_ticks,
                         .died = died_counting, .progress = count_progress};
    CHECK(fs_pool_run(&spec, &st, &err) == FS_OK);
    CHECK(st.timed_out == 1 && t.s.timed_out[NTASKS - 1] == 1);
    CHECK(t.died_at_repeats >= 1);
}

/* A refusal in done stops the pool: no task is handed out after it. With one worker the tasks go
 * strictly in order, so exactly tasks 0..3 are answered (with more workers a slow one may answer
 * its task after every other, so the count would say nothing). */
static void done_can_stop_the_pool(void)
{
    static state s;
    fs_error err = {0};
    fresh(&s);
    s.refuse_on = 3;
    CHECK(run_pool(&s, 1, 0, NULL, &err) == FS_BAD_INPUT && strstr(err.message, "task 3 refused"));
    int seen = 0;
    for (int i = 0; i < NTASKS; i++)
        seen += s.seen[i];
    CHECK(seen == 4 && s.seen[3] == 1);
}

/* The default -j: the least of the affinity, the cgroup quota (rounded up) and Slurm's CPUs. */
static void default_jobs_follow_the_cpus_given(void)
{
    CHECK(fs_pool_jobs_from(8, NULL, NULL) == 8);
    CHECK(fs_pool_jobs_from(8, "max 100000\n", "") == 8);      /* no quota */
    CHECK(fs_pool_jobs_from(8, "150000 100000\n", NULL) == 2); /* 1.5 CPUs: 2 workers */
    CHECK(fs_pool_jobs_from(8, "400000 100000\n", "3") == 3);  /* Slurm's 3 under a quota of 4 */
    CHECK(fs_pool_jobs_from(2, "800000 100000\n", "16") == 2); /* never more than the affinity */
    CHECK(fs_pool_jobs_from(0, NULL, "x") == 1);                /* nothing known, a bad variable: 1 */
    CHECK(fs_pool_default_jobs() >= 1);
}

FS_TEST_MAIN(TEST(answers_do_not_depend_on_jobs), TEST(dead_workers_are_reported_and_replaced),
             TEST(the_watchdog_kills_a_stopped_worker), TEST(progress_ticks_while_no_task_ends), TEST(done_can_stop_the_pool),
             TEST(default_jobs_follow_the_cpus_given))
