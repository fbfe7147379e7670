/* [run] min_inertia_kg_m2 (docs/bench.md, "QuickStep and the mass ratio"): at its default (0) it
 * changes nothing, bit for bit, and a floor raises every foot body's smallest principal moment of
 * inertia to at least the floor, by at most the floor, while masses and centres stay. */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <string.h>

static const char *const ROBOT = "robot.design=robots/drop_weight.ini";

static void load(const char *extra, fs_scenario *sc)
{
    fs_error err;
    const char *set[] = {ROBOT, extra};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, extra ? 2 : 1, sc, &err) == FS_OK);
}

/* The key absent and the key at 0: the same masses and, over 700 steps (touchdown at about 35 ms),
 * the same bodies' poses and velocities, bit for bit; the results' settings line says nothing of it. */
static void off_by_default_changes_no_bit(void)
{
    static fs_scenario a, b;
    load(NULL, &a);
    load("run.min_inertia_kg_m2=0", &b);
    CHECK(a.def.min_inertia_kg_m2 == 0);
    char sa[256], sb[256];
    fs_scenario_settings(&a, sa, sizeof sa);
    fs_scenario_settings(&b, sb, sizeof sb);
    CHECK(!strcmp(sa, sb) && !strstr(sa, "inertia"));
    fs_error err;
    fs_sim x, y;
    REQUIRE(fs_sim_build(&x, &a, NULL, &err) == FS_OK);
    REQUIRE(fs_sim_build(&y, &b, NULL, &err) == FS_OK);
    for (int i = 0; i < a.geom.nbodies; i++) {
        dMass mx, my;
        dBodyGetMass(x.body[i], &mx);
        dBodyGetMass(y.body[i], &my);
        CHECK(!memcmp(&mx, &my, sizeof mx));
    }
    for (int k = 0; k < 700; k++) {
        REQUIRE(fs_sim_step(&x, &err) == FS_OK);
        REQUIRE(fs_sim_step(&y, &err) == FS_OK);
    }
    CHECK(x.contacts_now > 0);
    for (int i = 0; i < a.geom.nbodies; i++) {
        double px[3], py[3], Rx[9], Ry[9], vx[3], vy[3], wx[3], wy[3];
        fs_sim_body_pose(&x, i, px, Rx);
        fs_sim_body_pose(&y, i, py, Ry);
        fs_sim_body_velocity(&x, i, vx, wx);
        fs_sim_body_velocity(&y, i, vy, wy);
        CHECK(!memcmp(px, py, sizeof px) && !memcmp(Rx, Ry, sizeof Rx));
        CHECK(!memcmp(vx, vy, sizeof vx) && !memcmp(wx, wy, sizeof wx));
    }
    fs_sim_destroy(&x);
    fs_sim_destroy(&y);
    fs_scenario_free(&a);
    fs_scenario_free(&b);
}

/* Whether I - l 1 is positive definite (Sylvester: its leading minors are positive; ODE's dMass
 * rows are 4 apart). */
static int above(const dReal *I, double l)
{
    double a = I[0] - l, b = I[5] - l, c = I[10] - l, d = I[1], e = I[6], f = I[2];
    double m2 = a * b - d * d;
    double m3 = a * (b * c - e * e) - d * (d * c - e * f) + f * (d * e - b * f);
    return a > 0 && m2 > 0 && m3 > 0;
}

/* The smallest principal moment by bisection on that test: found without the code under test's
 * closed form, to 1e-12 of the trace. */
static double smallest_moment(const dReal *I)
{
    double lo = 0, hi = I[0] + I[5] + I[10];
    for (int k = 0; k < 200 && hi - lo > 1e-12 * (I[0] + I[5] + I[10]); k++) {
        double mid = 0.5 * (lo + hi);
        if (above(I, mid))
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void floor_raises_light_links_and_keeps_masses(void)
{
    static fs_scenario a, b;
    const double floor = 1e-6; /* kg m^2: twelve times a phalanx's smallest moment, below the heel's */
    load(NULL, &a);
    load("run.min_inertia_kg_m2=1e-6", &b);
    CHECK(b.def.min_inertia_kg_m2 == floor);
    char sb[256];
    fs_scenario_settings(&b, sb, sizeof sb);
    CHECK(strstr(sb, "min_inertia_kg_m2 1e-06") != NULL);
    fs_error err;
    fs_sim x, y;
    REQUIRE(fs_sim_build(&x, &a, NULL, &err) == FS_OK);
    REQUIRE(fs_sim_build(&y, &b, NULL, &err) == FS_OK);
    int raised = 0, kept = 0;
    for (int i = 0; i < a.geom.nbodies; i++) {
        dMass mx, my;
        dBodyGetMass(x.body[i], &mx);
        dBodyGetMass(y.body[i], &my);
        CHECK(mx.mass == my.mass); /* masses and centres untouched */
        CHECK(!memcmp(mx.c, my.c, sizeof mx.c));
        CHECK(!memcmp(dBodyGetPosition(x.body[i]), dBodyGetPosition(y.body[i]), 3 * sizeof(dReal)));
        double before = smallest_moment(mx.I), after = smallest_moment(my.I);
        CHECK(after >= floor * (1 - 1e-6)); /* no direction below the floor */
        /* raised by d 1, 0 <= d <= floor: the same off-diagonal terms, the diagonal up alike */
        double d = my.I[0] - mx.I[0];
        CHECK(d >= 0 && d <= floor);
        CHECK(fabs(my.I[5] - mx.I[5] - d) <= 1e-15 && fabs(my.I[10] - mx.I[10] - d) <= 1e-15);
        CHECK(my.I[1] == mx.I[1] && my.I[2] == mx.I[2] && my.I[6] == mx.I[6]);
        if (before < floor) {
            raised++;
            CHECK(after <= floor * (1 + 1e-6)); /* raised to the floor, not beyond */
        } else {
            kept++;
            CHECK(!memcmp(mx.I, my.I, sizeof mx.I)); /* a body already above it is left alone */
        }
    }
    CHECK(raised >= 10); /* the five metatarsals and five phalanges at least */
    CHECK(kept >= 1);    /* the ankle body with the 26 kg robot merged into it */
    fs_sim_destroy(&x);
    fs_sim_destroy(&y);
    fs_scenario_free(&a);
    fs_scenario_free(&b);
}

/* Out of its range: refused with the file and line that say so. */
static void out_of_range_is_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"run.min_inertia_kg_m2=-1e-6"};
    CHECK(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &sc, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "min_inertia_kg_m2") != NULL);
}

FS_TEST_MAIN(TEST(off_by_default_changes_no_bit), TEST(floor_raises_light_links_and_keeps_masses),
             TEST(out_of_range_is_refused))
