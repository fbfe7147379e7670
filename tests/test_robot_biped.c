/* The biped (robots/biped.ini, fs_robot_biped_geometry): two copies of the foot and its legs in one
 * world, its stated mass, left-right symmetric at the start, its leg joints' rows, and standing on
 * flat ground with each foot carrying half its weight. Every expected value is derived from the
 * files' numbers and statics, not copied from a run. */
#include "fs_test.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <math.h>

#define DEG (M_PI / 180.0)

/* The landing trial with the biped on foot (a design file), standing still: no drop, no drawn pose. */
static void load_biped(const char *foot, fs_scenario *sc)
{
    char design[128];
    snprintf(design, sizeof design, "scenario.design=%s", foot);
    const char *set[] = {"robot.design=robots/biped.ini", design, "start.drop_m=0"};
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", set, 3, sc, &err) == FS_OK);
}

static double body_mass(fs_sim *sim, int i)
{
    dMass m;
    dBodyGetMass(sim->body[i], &m);
    return m.mass;
}

static void builds_two_feet_and_its_legs(void)
{
    const char *feet[] = {"feet/biomimetic.ini", "feet/flat.ini"};
    for (int k = 0; k < 2; k++) {
        static fs_scenario sc;
        load_biped(feet[k], &sc);
        fs_sim sim;
        fs_error err;
        REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
        const fs_foot_geom *g = sim.geom, *foot = &sc.geom;
        const int n = foot->nbodies;
        CHECK(g->biped && g->nfeet == 2);
        CHECK(g->nbodies == 2 * n + 5); /* two feet, a pelvis, two thighs, two shanks */
        CHECK(g->nhinges == 2 * foot->nhinges + 6 && g->nsprings == 2 * foot->nsprings);
        CHECK(g->nspheres == 2 * foot->nspheres && g->nboxes == 2 * foot->nboxes);
        CHECK(sim.robot == NULL && !sim.robot_merged);
        /* 52 kg above the ankles, as the file states (36.76 + 2 (5.2 + 2.42)), and the feet on top */
        CHECK_NEAR(sc.def.robot.mass_kg, 52, 1e-9);
        double legs = 0, feet_kg = 0;
        for (int i = 0; i < g->nbodies; i++)
            *(i < 2 * n ? &feet_kg : &legs) += body_mass(&sim, i);
        CHECK_NEAR(legs, 52, 1e-9);
        CHECK_NEAR(feet_kg, 2 * foot->total_mass_kg, 1e-12);
        CHECK_NEAR(g->total_mass_kg, 52 + 2 * foot->total_mass_kg, 1e-9);
        /* left-right symmetric: each left body the mirror of its right one about y = start y */
        const double y0 = sc.def.start_y_m;
        for (int i = 0; i < g->nbodies; i++) {
            int mirror = i < n ? i + n : i < 2 * n ? i - n : i == 2 * n ? i : i <= 2 * n + 2 ? i + 2 : i - 2;
            const dReal *p = dBodyGetPosition(sim.body[i]), *q = dBodyGetPosition(sim.body[mirror]);
            CHECK_NEAR(p[0], q[0], 1e-12);
            CHECK_NEAR(p[1] - y0, -(q[1] - y0), 1e-12);
            CHECK_NEAR(p[2], q[2], 1e-12);
            CHECK_NEAR(body_mass(&sim, i), body_mass(&sim, mirror), 0);
        }
        /* the ankles hip_width_m apart, the right one at -y */
        double r[3], l[3];
        fs_sim_foot_ankle(&sim, 0, r);
        fs_sim_foot_ankle(&sim, 1, l);
        CHECK_NEAR(l[1] - r[1], sc.def.robot.hip_width_m, 1e-12);
        /* the rows: 5 a hinge, a stop row for each of the 6 sprung leg joints, one an implicit spring */
        fs_rows rows;
        fs_sim_constraint_rows(&sim, &rows);
        CHECK(rows.hinge == 5 * g->nhinges && rows.stop == 6 && rows.spring == g->nsprings && rows.fixed == 0);
        CHECK(rows.total == 5 * g->nhinges + 6 + g->nsprings);
        /* a drawing holds all of it: every shape, body and spring, and the links with room to spare */
        static fs_scene scene;
        fs_sim_scene(&sim, &scene);
        CHECK(scene.nshapes == g->nspheres + g->nboxes && scene.nbodies == g->nbodies);
        CHECK(scene.nsprings == g->nsprings && scene.nlinks < FS_SCENE_MAX_SEGMENTS);
        fs_sim_destroy(&sim);
        fs_scenario_free(&sc);
    }
}

/* A single robot keeps its old geometry: one foot, no biped's parts. */
static void single_robots_are_unchanged(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_sim sim;
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    CHECK(sim.geom == &sc.geom && !sim.geom->biped && sim.geom->nfeet == 1);
    fs_rows rows;
    fs_sim_constraint_rows(&sim, &rows);
    CHECK(rows.stop == 0);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* On flat ground on the flat foot, at rest: the two feet carry the weight equally and the pelvis
 * stands upright. Vertical: the feet's forces, averaged over a window T, sum to M g within the
 * momentum the bodies may change in it, M 2 v_rest / T. Lateral: moments about the feet's midline,
 * (F_left - F_right) w / 2 = M g y_c, and the centre of mass lies at most h sin(lean) off it. The
 * lean: the ankles alone give M g x / (2 k_ankle - M g h) = 0.23 deg for the 3 cm forward offset x
 * (on a rigid sole); hips and knees, stiffer against their loads, at most as much again each: 1 deg. */
static void stands_on_both_feet(void)
{
    static fs_scenario sc;
    load_biped("feet/flat.ini", &sc);
    fs_sim sim;
    fs_error err;
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    const double g = sc.def.gravity_m_per_s2, T = 0.2, v_rest = sc.def.rest_speed_m_per_s;
    double M = 0;
    for (int i = 0; i < sim.geom->nbodies; i++)
        M += body_mass(&sim, i);
    const long steps = (long)(1.5 / sc.def.step_s), window = (long)(T / sc.def.step_s);
    double F[2] = {0, 0};
    for (long s = 0; s < steps; s++) {
        REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
        if (s >= steps - window)
            for (int f = 0; f < 2; f++) {
                double force[3];
                fs_sim_foot_force(&sim, f, force);
                F[f] += force[2] / window;
            }
    }
    double lean = fs_sim_robot_tilt(&sim);
    CHECK(lean < 1 * DEG);
    CHECK(fs_sim_max_speed(&sim) < 10 * v_rest);
    CHECK(fs_sim_foot_contacts(&sim, 0) > 0 && fs_sim_foot_contacts(&sim, 1) > 0);
    double momentum_N = M * 2 * v_rest / T;
    CHECK(fabs(F[0] + F[1] - M * g) <= momentum_N);
    const double h = sc.def.robot.com_height_m, w = sc.def.robot.hip_width_m;
    double split_N = M * g * h * sin(lean) / (0.5 * w) + momentum_N;
    printf("feet %.2f N and %.2f N against M g / 2 = %.2f N (bound %.2f N); lean %.3f deg\n", F[0], F[1],
           0.5 * M * g, 0.5 * split_N, lean / DEG);
    for (int f = 0; f < 2; f++)
        CHECK(fabs(F[f] - 0.5 * M * g) <= 0.5 * split_N);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

/* A trial's time series has a column for each hinge and spring of the built biped (its two feet and
 * legs), not of one foot: a row holds what the sim logs. */
static void trajectory_has_the_bipeds_columns(void)
{
    static fs_scenario sc;
    load_biped("feet/biomimetic.ini", &sc);
    sc.def.duration_s = 0.01;
    fs_foot_geom biped;
    const fs_foot_geom *g = fs_scenario_geometry(&sc, &biped);
    CHECK(g->nhinges == 2 * sc.geom.nhinges + 6);
    fs_run_result log;
    fs_trial_result r;
    fs_error err;
    REQUIRE(fs_trial_run_logged(&sc, 1, NULL, &log, &r, &err) == FS_OK);
    CHECK(log.ncols == 5 + g->nhinges + g->nsprings + 1);
    CHECK(r.nfeet == 2);
    fs_run_free(&log);
    fs_scenario_free(&sc);
}

/* The pitch-stiffness law for the biped: two legs side by side, each its foot and ankle in series. */
static void law_counts_two_legs(void)
{
    fs_robot_def r = {.kind = FS_ROBOT_BIPED, .mass_kg = 52, .com_height_m = 0.457, .ankle_k_N_m_per_rad = 2000};
    fs_pitch_law law;
    fs_pitch_law_apply(13, &r, 9.81, 15 * DEG, &law);
    CHECK_NEAR(law.K, 2 / (1 / 13.0 + 1 / 2000.0), 1e-12);
    CHECK(!law.stands);
}

FS_TEST_MAIN(TEST(builds_two_feet_and_its_legs), TEST(single_robots_are_unchanged), TEST(stands_on_both_feet),
             TEST(trajectory_has_the_bipeds_columns), TEST(law_counts_two_legs))
