/* Tests of the state checks (sim_check.c): each check fires on a state planted to fail it,
 * naming the body or hinge; a stable run passes with room; a blow-up of the explicit springs is
 * classified as one; recording a drift lets the run go on. */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <string.h>

/* The static load scenario with overrides, built. */
static void build(fs_scenario *sc, fs_sim *sim, const char **set, int nset)
{
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, nset, sc, &err) == FS_OK);
    REQUIRE(fs_sim_build(sim, sc, NULL, &err) == FS_OK);
}

/* Built and stepped once (the checks' reference taken); returns the named body. */
static dBodyID after_one_step(fs_scenario *sc, fs_sim *sim, const char *body)
{
    fs_error err;
    build(sc, sim, NULL, 0);
    CHECK(fs_sim_step(sim, &err) == FS_OK);
    for (int i = 0; i < sc->geom.nbodies; i++)
        if (!strcmp(sc->geom.body[i].name, body))
            return sim->body[i];
    CHECK(!"no such body");
    return sim->body[0];
}

/* The paper's static load with every default: stable at every step. The energy can only fall
 * (dampers, friction; the implicit springs are backward Euler): what it gains beyond the load's
 * work must be rounding, far below the 0.05 J the load puts in (255 N over the 0.2 mm the ankle
 * sinks); the hinges' anchors part only by their compliance, CFM 1e-10 m/N times forces of a few
 * hundred N: well under a micron. */
static void static_load_is_stable(void)
{
    static fs_scenario sc;
    fs_sim sim;
    fs_error err;
    build(&sc, &sim, NULL, 0);
    int ok = 1;
    for (long i = 0; i < lround(0.3 / sc.def.step_s) && ok; i++)
        ok = fs_sim_step(&sim, &err) == FS_OK;
    CHECK(ok);
    CHECK(sim.check.work_J > 0.02 && sim.check.work_J < 0.1);
    CHECK(sim.check.max_energy_excess_J <= 1e-3 * sim.check.work_J);
    CHECK(sim.check.max_loop_error_m < 1e-6);
    CHECK(sim.check.max_speed_m_per_s < 1.0);
    CHECK(fs_check_class_of(sim.check.failure) == FS_CHECK_STABLE);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* Explicit springs at 1 ms, 25 times the 4e-5 s their phalanx dampers allow (2 m / c with both
 * of its 200 N s/m dampers): blown up within a few steps, a body named in the message. */
static void explicit_springs_beyond_their_limit_blow_up(void)
{
    static fs_scenario sc;
    fs_sim sim;
    fs_error err;
    const char *set[] = {"run.springs=explicit", "run.step_s=1e-3"};
    build(&sc, &sim, set, 2);
    CHECK_NEAR(fs_check_explicit_step_limit(&sim), 4.0e-5, 0.05e-5);
    fs_status s = FS_OK;
    int steps = 0;
    while (s == FS_OK && steps < 100)
        s = fs_sim_step(&sim, &err), steps++;
    CHECK(s == FS_NUMERICAL);
    CHECK(steps < 20);
    /* what gives first: a body too fast, or a hinge torn open by the spring forces (with friction
       bounded by the last step's normal forces, the toes' hinges tear a step before any body passes
       100 m/s); either way the cause is named: the explicit springs and their limit */
    CHECK(fs_check_class_of(sim.check.failure) == FS_CHECK_BLOWN_UP || sim.check.failure == FS_CHECK_LOOP);
    CHECK((strstr(err.message, "body '") || strstr(err.message, "hinge '")) && strstr(err.message, "t = ") &&
          strstr(err.message, "run.step_s") && strstr(err.message, "explicit springs are stable below") &&
          strstr(err.message, "run.springs = implicit"));
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* A NaN velocity planted in phalanx3: non-finite, blown up, the body named. */
static void planted_nan_names_the_body(void)
{
    static fs_scenario sc;
    fs_sim sim;
    fs_error err;
    dBodySetLinearVel(after_one_step(&sc, &sim, "phalanx3"), 0, NAN, 0);
    CHECK(fs_check_step(&sim, &err) == FS_NUMERICAL);
    CHECK(sim.check.failure == FS_CHECK_NONFINITE);
    CHECK(fs_check_class_of(sim.check.failure) == FS_CHECK_BLOWN_UP);
    CHECK(!strcmp(sim.check.failure_where, "phalanx3"));
    CHECK(strstr(err.message, "body 'phalanx3'") && strstr(err.message, "non-finite"));
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* A phalanx moved 5 mm off its MTP hinge: the loop has opened beyond the 1 mm bound. */
static void opened_loop_names_the_hinge(void)
{
    static fs_scenario sc;
    fs_sim sim;
    fs_error err;
    dBodyID b = after_one_step(&sc, &sim, "phalanx3");
    const dReal *p = dBodyGetPosition(b);
    dBodySetPosition(b, p[0], p[1], p[2] + 0.005);
    CHECK(fs_check_step(&sim, &err) == FS_NUMERICAL);
    CHECK(sim.check.failure == FS_CHECK_LOOP);
    CHECK(fs_check_class_of(sim.check.failure) == FS_CHECK_DRIFTING);
    CHECK(!strcmp(sim.check.failure_where, "mtp3"));
    CHECK_NEAR(sim.check.max_loop_error_m, 0.005, 1e-6);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* The talus (80 g) given 12 m/s from nowhere: 5.8 J, beyond the 1 J margin, below the speed
 * bound: drifting by energy. Recording instead, the run goes on and remembers when. */
static void energy_from_nowhere_is_caught(void)
{
    for (int record = 0; record < 2; record++) {
        static fs_scenario sc;
        fs_sim sim;
        fs_error err;
        dBodySetLinearVel(after_one_step(&sc, &sim, "talus"), 0, 0, 12);
        sim.check.record_drift = record;
        fs_status s = fs_check_step(&sim, &err);
        if (!record) {
            CHECK(s == FS_NUMERICAL);
            CHECK(sim.check.failure == FS_CHECK_ENERGY);
            CHECK(strstr(err.message, "energy"));
        } else {
            CHECK(s == FS_OK);
            CHECK(sim.check.first_drift == FS_CHECK_ENERGY);
            CHECK_NEAR(sim.check.first_drift_time_s, sc.def.step_s, 1e-12);
            CHECK(sim.check.max_energy_excess_J > 5.0);
        }
        fs_sim_destroy(&sim);
        fs_scenario_free(&sc);
    }
}

FS_TEST_MAIN(TEST(static_load_is_stable), TEST(explicit_springs_beyond_their_limit_blow_up),
             TEST(planted_nan_names_the_body), TEST(opened_loop_names_the_hinge), TEST(energy_from_nowhere_is_caught))
