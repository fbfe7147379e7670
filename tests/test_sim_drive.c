/* Tests of fs_drive (fs_drive.h): the one loop every experiment steps through. Counts, not
 * physics: how many steps, which hook stopped the run, when the observer is called. */
#include "fs_test.h"

#include "footsim/sim/fs_drive.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

typedef struct counter {
    long seen;       /* steps this hook saw */
    long stop_at;    /* say stop at this step (0: never) */
} counter;

static int count(void *user, fs_sim *sim)
{
    (void)sim;
    counter *c = user;
    return ++c->seen == c->stop_at;
}

typedef struct watcher {
    int calls;
    double last_t;
} watcher;

static fs_status watch(void *user, const fs_sim *sim, fs_error *err)
{
    (void)err;
    watcher *w = user;
    w->calls++;
    w->last_t = sim->time_s;
    return FS_OK;
}

static int befores;
static void before(void *user, fs_sim *sim)
{
    (void)user, (void)sim;
    befores++;
}

/* static_load for a short while: 1e-4 s steps */
static void build(fs_sim *sim, fs_scenario *sc)
{
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, sc, &err) == FS_OK);
    REQUIRE(fs_sim_build(sim, sc, NULL, &err) == FS_OK);
}

/* The first hook to say stop ends the run and is named; every hook sees the last step too. */
static void first_stopping_hook_ends_the_run(void)
{
    static fs_scenario sc;
    fs_sim sim;
    build(&sim, &sc);
    counter a = {0, 0}, b = {0, 7}, c = {0, 5};
    const fs_step_hook hooks[] = {{"a", count, &a}, {"b", count, &b}, {"c", count, &c}};
    fs_drive_spec spec = {.max_steps = 100, .before_step = before, .hooks = hooks, .nhooks = 3};
    fs_drive_result r;
    fs_error err;
    befores = 0;
    CHECK(fs_drive(&sim, &spec, &r, &err) == FS_OK);
    CHECK(r.steps == 5 && r.stopped_by == 2 && !r.step_failed && befores == 5);
    CHECK(a.seen == 5 && b.seen == 5 && c.seen == 5);
    CHECK(!strcmp(fs_drive_reason(&spec, &r), "c"));
    CHECK_NEAR(sim.time_s, 5 * sc.def.step_s, 1e-12);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* Without a stop, max_steps; the observer at t = 0, every interval and at the end (once). */
static void observer_at_start_interval_and_end(void)
{
    static fs_scenario sc;
    fs_sim sim;
    build(&sim, &sc);
    watcher w = {0, -1};
    fs_run_observer obs = {.interval_s = 10 * sc.def.step_s, .fn = watch, .user = &w};
    fs_drive_spec spec = {.max_steps = 35, .obs = &obs};
    fs_drive_result r;
    fs_error err;
    CHECK(fs_drive(&sim, &spec, &r, &err) == FS_OK);
    CHECK(r.steps == 35 && r.stopped_by == -1 && !strcmp(fs_drive_reason(&spec, &r), "max_steps"));
    CHECK(w.calls == 1 + 3 + 1); /* t = 0; steps 10, 20, 30; the end at 35 */
    CHECK_NEAR(w.last_t, 35 * sc.def.step_s, 1e-12);
    /* ending on an interval: no second call at the end */
    w = (watcher){0, -1};
    spec.max_steps = 20;
    CHECK(fs_drive(&sim, &spec, &r, &err) == FS_OK);
    CHECK(w.calls == 1 + 2);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(first_stopping_hook_ends_the_run), TEST(observer_at_start_interval_and_end))
