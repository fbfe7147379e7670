/* Tests of ODE's errors and messages routed through footsim (fs_ode.h, fs_error.h): an ODE error
 * inside a guarded call comes back as FS_NUMERICAL and the process goes on; guards nest; a sim an
 * ODE error interrupted refuses further steps; ODE's messages are warnings handed to the program's
 * handler and counted, never printed by the library. */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <string.h>

static int after_failure; /* set by code that runs after fs_ode_fail: must stay 0 */

static fs_status fails(void *arg, fs_error *err)
{
    (void)arg, (void)err;
    fs_ode_fail("planted by test_sim_ode");
    after_failure = 1;
    return FS_OK;
}

static fs_status refuses(void *arg, fs_error *err)
{
    (void)arg;
    return fs_fail(err, FS_BAD_INPUT, "refused on its own");
}

/* An inner guard's failure comes back to it; the outer call goes on and returns its own status. */
static fs_status nests(void *arg, fs_error *err)
{
    int *inner_interrupted = arg;
    fs_error inner;
    CHECK(fs_ode_guard(fails, NULL, inner_interrupted, &inner) == FS_NUMERICAL);
    CHECK(strstr(inner.message, "planted by test_sim_ode") != NULL);
    return fs_fail(err, FS_BAD_INPUT, "outer went on");
}

/* A real ODE error, not a planted one: a body given a negative mass (ODE's own check of the mass). */
static fs_status bad_mass(void *arg, fs_error *err)
{
    (void)err;
    dBodyID b = arg;
    dMass m;
    dMassSetSphereTotal(&m, 1.0, 0.01);
    m.mass = -1.0;
    dBodySetMass(b, &m);
    return FS_OK;
}

static void guard_brings_errors_back(void)
{
    fs_error err = {0};
    int interrupted = 0;
    CHECK(fs_ode_guard(fails, NULL, &interrupted, &err) == FS_NUMERICAL);
    CHECK(interrupted == 1);
    CHECK(after_failure == 0);
    CHECK(err.status == FS_NUMERICAL);
    CHECK(strstr(err.message, "ODE internal check") && strstr(err.message, "planted by test_sim_ode"));
    /* a call that returns on its own keeps its status, and interrupted is left alone */
    interrupted = 0;
    CHECK(fs_ode_guard(refuses, NULL, &interrupted, &err) == FS_BAD_INPUT);
    CHECK(interrupted == 0 && strstr(err.message, "refused on its own"));
    /* nested: the inner guard catches, the outer goes on */
    int inner = 0, outer = 0;
    CHECK(fs_ode_guard(nests, &inner, &outer, &err) == FS_BAD_INPUT);
    CHECK(inner == 1 && outer == 0 && strstr(err.message, "outer went on"));
}

static void a_real_ode_error_is_caught(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = dBodyCreate(w);
    fs_error err = {0};
    int interrupted = 0;
    fs_status s = fs_ode_guard(bad_mass, b, &interrupted, &err);
    /* Debian's ODE checks a body's mass (dMassCheck in dBodySetMass): the error comes back here,
     * naming ODE's check, instead of ending the process */
    CHECK(s == FS_NUMERICAL && interrupted);
    CHECK(strstr(err.message, "ODE internal check") && strstr(err.message, "dMassCheck"));
    dWorldDestroy(w);
}

/* After a caught error, ODE still builds and steps a new simulation; a sim marked as interrupted
 * refuses to step, saying it can only be destroyed. */
static void sims_after_an_error(void)
{
    fs_error err;
    int interrupted = 0;
    CHECK(fs_ode_guard(fails, NULL, &interrupted, &err) == FS_NUMERICAL);
    static fs_scenario sc;
    fs_sim sim;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    for (int i = 0; i < 100; i++)
        REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
    double t = sim.time_s;
    sim.ode_failed = 1;
    CHECK(fs_sim_step(&sim, &err) == FS_NUMERICAL);
    CHECK(strstr(err.message, "can only be destroyed") != NULL);
    CHECK(sim.time_s == t);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

static int handed;
static char last[FS_ERROR_MAX];

static void keep(const char *text, void *user)
{
    handed += user == &handed;
    snprintf(last, sizeof last, "%s", text);
}

static void messages_are_warnings(void)
{
    long before = fs_warning_count();
    fs_warning_handler(keep, &handed);
    dMessage(7, "a message from ODE %d", 42);
    CHECK(fs_warning_count() == before + 1);
    CHECK(handed == 1);
    CHECK(strstr(last, "ODE message 7") && strstr(last, "a message from ODE 42"));
    /* no handler: counted only */
    fs_warning_handler(NULL, NULL);
    dMessage(8, "unheard");
    CHECK(fs_warning_count() == before + 2);
    CHECK(handed == 1);
}

FS_TEST_MAIN(TEST(guard_brings_errors_back), TEST(a_real_ode_error_is_caught), TEST(sims_after_an_error),
             TEST(messages_are_warnings))
