/* [run] min_inertia_kg_m2 (docs/bench.md, "QuickStep and the mass ratio"): at its default (0) it
 * changes nothing, bit for bit, and a floor raises every foot body's smallest principal moment of
 * inertia to at least the floor, by at most the floor, while masses and centres stay. Every body is
 * a body: a robot's impossible moments (A + B < C) are refused, a stretched robot stays physical at
 * every height, and every body built from the shipped feet and robots has moments a body can have. */
#include "fs_test.h"

#include "footsim/model/fs_robot.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

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

/* Principal moments no body has (one above the other two together) are refused with where they were
 * given and what would do; a thin plate (A + B = C, to round-off) is a body. */
static void impossible_moments_are_refused(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *needle[] = {"robot.inertia_kgm2=0.01,0.01,1", "robot.inertia_kgm2=1,0.1,0.1",
                            "robot.inertia_kgm2=0.1,1,0.5"};
    const char *axis[] = {"about z (1 kg m^2)", "about x (1 kg m^2)", "about y (1 kg m^2)"};
    for (int i = 0; i < 3; i++) {
        const char *set[] = {needle[i]};
        CHECK(fs_scenario_load("scenarios/landing_trial.ini", set, 1, &sc, &err) == FS_BAD_INPUT);
        CHECK(strstr(err.message, "--set robot.inertia_kgm2") && strstr(err.message, "no rigid body's") &&
              strstr(err.message, axis[i]) && strstr(err.message, "A + B >= C"));
    }
    const char *pelvis[] = {"robot.design=robots/biped.ini", "robot.pelvis_inertia_kgm2=0.1,0.1,0.3"};
    CHECK(fs_scenario_load("scenarios/landing_trial.ini", pelvis, 2, &sc, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "pelvis_inertia_kgm2 = 0.1, 0.1, 0.3 is no rigid body's") != NULL);
    /* on the boundary: a thin plate, with its sum's round-off either way, and a sphere */
    const double plate[][3] = {{0.1, 0.2, 0.1 + 0.2}, {0.1, 0.2, 0.3 * (1 + 1e-12)}, {0.5, 0.5, 1}, {1, 1, 1}};
    for (int i = 0; i < 4; i++)
        CHECK(fs_inertia_impossible(plate[i]) == 0);
    const double bad[][3] = {{0.1, 0.2, 0.3 * (1 + 1e-6)}, {0, 1, 1}, {1, -1, 1}, {2.1, 1, 1}, {1, 1, NAN}};
    for (int i = 0; i < 5; i++)
        CHECK(fs_inertia_impossible(bad[i]) != 0);
    const char *ok[] = {"robot.inertia_kgm2=0.1,0.2,0.3"};
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", ok, 1, &sc, &err) == FS_OK);
    fs_scenario_free(&sc);
}

/* single_tall moved to another height is the same body stretched along the vertical: its spread
 * across (the moment about z) kept, its spread along z, (Ix + Iy - Iz) / 2, scaled with the height
 * squared, and at every height a body's moments; at its own height, as given, bit for bit. */
static void stretched_robot_stays_a_body(void)
{
    fs_robot_def r;
    fs_error err;
    REQUIRE(fs_robot_load("scenarios/robots/single_tall.ini", NULL, 0, &r, &err) == FS_OK);
    const double *J = r.inertia_kgm2, along = 0.5 * (J[0] + J[1] - J[2]);
    const double heights[] = {0.005, 0.02, 0.035, 0.05, 0.0567, 0.1, 0.2, 0.3, 0.6, 2};
    for (int i = 0; i < 10; i++) {
        r.com_height_m = heights[i];
        double I[3], f = heights[i] / r.inertia_height_m;
        fs_robot_inertia(&r, I);
        CHECK(fs_inertia_impossible(I) == 0);
        CHECK(I[2] == J[2]);
        CHECK_NEAR(0.5 * (I[0] + I[1] - I[2]), f * f * along, 1e-12);
        CHECK_NEAR(0.5 * (I[1] + I[2] - I[0]), 0.5 * (J[1] + J[2] - J[0]), 1e-12); /* spread along x, y kept */
    }
    r.com_height_m = r.inertia_height_m;
    double I[3];
    fs_robot_inertia(&r, I);
    CHECK(!memcmp(I, J, sizeof I));
}

/* Whether the moments of a body's tensor I (ODE's rows 4 apart) are a body's: its largest principal
 * moment at most half the trace (A + B >= C), i.e. (trace / 2) 1 - I positive semidefinite,
 * checked as -I - l 1 positive definite for l just below -trace / 2. */
static int physical(const dReal *I)
{
    dReal minus[12];
    for (int k = 0; k < 12; k++)
        minus[k] = -I[k];
    double half = 0.5 * (I[0] + I[5] + I[10]);
    return half > 0 && above(minus, -half * (1 + 1e-9));
}

/* Every body built from the shipped feet under every shipped robot (and single_tall at the
 * envelope's lowest height) has moments a body can have: the design's links, the merged ankle body,
 * a robot's own body, a biped's pelvis and legs. */
static void every_built_body_is_a_body(void)
{
    const char *robots[] = {"robot.design=robots/single_tall.ini", "robot.design=robots/single_tall_achilles.ini",
                            "robot.design=robots/drop_weight.ini", "robot.design=robots/rig.ini",
                            "robot.design=robots/biped.ini"};
    const char *feet[] = {"scenario.design=feet/biomimetic.ini", "scenario.design=feet/flat.ini"};
    const char *heights[] = {"robot.com_height_m=0.3", "robot.com_height_m=0.02"};
    int bodies = 0;
    for (int r = 0; r < 5; r++)
        for (int f = 0; f < 2; f++)
            for (int h = 0; h < (r < 2 ? 2 : 1); h++) {
                static fs_scenario sc;
                const char *set[] = {robots[r], feet[f], heights[h]};
                fs_error err;
                REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, r < 2 ? 3 : 2, &sc, &err) == FS_OK);
                fs_sim sim;
                fs_sim_options apart = {.keep_robot_body = 1}; /* the robot's own tensor, not merged */
                REQUIRE(fs_sim_build(&sim, &sc, &apart, &err) == FS_OK);
                for (int i = 0; i < sc.geom.nbodies; i++, bodies++) {
                    dMass m;
                    dBodyGetMass(sim.body[i], &m);
                    if (!physical(m.I))
                        printf("  %s %s %s: body %d has moments no body has\n", robots[r], feet[f], heights[h], i);
                    CHECK(physical(m.I));
                }
                if (sim.robot) {
                    dMass m;
                    dBodyGetMass(sim.robot, &m);
                    if (!physical(m.I))
                        printf("  %s %s %s: the robot has moments no body has\n", robots[r], feet[f], heights[h]);
                    CHECK(physical(m.I));
                    bodies++;
                }
                fs_sim_destroy(&sim);
                fs_scenario_free(&sc);
            }
    CHECK(bodies > 90); /* 12 bodies a biomimetic foot, 1 a flat one, 5 a biped's legs, the robots */
}

FS_TEST_MAIN(TEST(off_by_default_changes_no_bit), TEST(floor_raises_light_links_and_keeps_masses),
             TEST(out_of_range_is_refused), TEST(impossible_moments_are_refused), TEST(stretched_robot_stays_a_body),
             TEST(every_built_body_is_a_body))
