/* Friction converges with the step (issue 12): on flat ground, halving the step from 2e-5 to 1e-5 s
 * moves the ankle no more than a first-order method allows, and toes that grip do not slide.
 *
 * With dContactApprox1 alone, ODE's direct solver bounded each contact's friction by its normal
 * force in the frictionless problem, not the final one, so toes slid under friction well below
 * mu N: the gripping static load below slid its toes by 0.1 mm at 2e-5 s and 0.36 mm at 1e-5 s
 * (none at 1e-4 s), and its ankle moved by 0.25 mm between the two; the landing's by 0.09 mm
 * (sim_contacts.c, bound_friction; docs/model.md, Contact). */
#include "fs_test.h"

#include "footsim/experiment/fs_trial.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <math.h>
#include <string.h>

/* First order: the frictionless landing's ankle moves 0.034 mm from 4e-5 to 2e-5 s (docs/bench.md,
 * Precision); a first-order method halves that with the step, so from 2e-5 to 1e-5 s the ankle
 * may move 0.017 mm. */
static const double ANKLE_TOL_M = 0.034e-3 / 2;

/* A toe that grips does not slip. What still moves the lowest point of its sphere, where ODE puts
 * the contact on flat ground: the sphere turns about the point that touches the surface, which
 * lies the penetration above it, at most the whole load over the contact stiffness (255 N /
 * 9.09e6 N/m = 2.8e-5 m), by less than 0.1 rad (the phalanx turns a few hundredths under this
 * load), 2.8e-6 m; and the friction rows creep by their CFM (1e-10 m/(N s)) times at most the
 * load, 255 N, for 0.2 s, 5e-9 m. */
static const double GRIP_SLIDE_TOL_M = 2.8e-5 * 0.1 + 5e-9;

typedef struct path {
    int n;
    double ankle[1600][3]; /* every 2e-4 s */
    double toe_slide_m;    /* the most any toe's lowest point slid while touching */
} path;

/* Runs sc for duration_s at step h; a seed >= 0 places a landing trial's pose first. */
static void run(const char *scenario, const char *const *set, int nset, int seed, double h, double duration_s,
                path *out)
{
    static fs_scenario sc;
    static fs_sim sim;
    fs_error err;
    char step[64];
    snprintf(step, sizeof step, "run.step_s=%g", h);
    const char *all[8];
    for (int i = 0; i < nset; i++)
        all[i] = set[i];
    all[nset] = step;
    REQUIRE(fs_scenario_load(scenario, all, nset + 1, &sc, &err) == FS_OK);
    if (seed >= 0)
        REQUIRE(fs_trial_place(&sc, seed, NULL, &err) == FS_OK);
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    const fs_foot_geom *g = sim.geom;
    double slide[FS_MAX_SPHERES] = {0};
    long steps = lround(duration_s / h), every = lround(2e-4 / h);
    memset(out, 0, sizeof *out);
    for (long i = 1; i <= steps; i++) {
        REQUIRE(fs_sim_step(&sim, &err) == FS_OK);
        for (int s = 0; s < g->nspheres; s++) {
            const dReal *c = dGeomGetPosition(sim.shape[s]);
            double r = g->sphere[s].radius_m;
            if (c[2] >= r)
                continue; /* not touching the ground */
            dVector3 v;
            dBodyGetPointVel(sim.body[g->sphere[s].body], c[0], c[1], c[2] - r, v);
            slide[s] += hypot(v[0], v[1]) * h;
        }
        if (i % every == 0 && out->n < 1600)
            fs_sim_ankle(&sim, out->ankle[out->n++]);
    }
    for (int s = 0; s < g->nspheres; s++)
        if (!strncmp(g->sphere[s].name, "toe", 3))
            out->toe_slide_m = fmax(out->toe_slide_m, slide[s]);
    fs_sim_destroy(&sim);
    fs_scenario_free(&sc);
}

static double largest_distance(const path *a, const path *b)
{
    double d = 0;
    for (int i = 0; i < a->n && i < b->n; i++) {
        double e = 0;
        for (int k = 0; k < 3; k++)
            e += (a->ankle[i][k] - b->ankle[i][k]) * (a->ankle[i][k] - b->ankle[i][k]);
        d = fmax(d, sqrt(e));
    }
    return d;
}

static path coarse, fine;

/* 26 kg raised over 20 ms on ground with mu = 10: the toes need about 4 times their normal force
 * sideways (test_analysis_statics), so they grip. */
static void gripping_static_load_converges(void)
{
    const char *set[] = {"material.mu=10", "sole.mu=10"};
    run("scenarios/static_load.ini", set, 2, -1, 2e-5, 0.2, &coarse);
    run("scenarios/static_load.ini", set, 2, -1, 1e-5, 0.2, &fine);
    double moved = largest_distance(&coarse, &fine);
    printf("  gripping static load: ankle moved %.3g m; toe slide %.3g m (2e-5 s), %.3g m (1e-5 s)\n", moved,
           coarse.toe_slide_m, fine.toe_slide_m);
    CHECK(coarse.n == 1000 && fine.n == 1000);
    CHECK(moved < ANKLE_TOL_M);
    CHECK(coarse.toe_slide_m < GRIP_SLIDE_TOL_M);
    CHECK(fine.toe_slide_m < GRIP_SLIDE_TOL_M);
}

/* The landing trial on flat ground (seed 1's pose, sole mu = 1): the toes slide at touchdown and
 * grip after; over the first 0.3 s the ankle's paths at the two steps stay within the bound. */
static void landing_on_flat_ground_converges(void)
{
    run("scenarios/landing_trial.ini", NULL, 0, 1, 2e-5, 0.3, &coarse);
    run("scenarios/landing_trial.ini", NULL, 0, 1, 1e-5, 0.3, &fine);
    double moved = largest_distance(&coarse, &fine);
    printf("  landing on flat ground: ankle paths differ by %.3g m at most\n", moved);
    CHECK(coarse.n == 1500 && fine.n == 1500);
    CHECK(moved < ANKLE_TOL_M);
}

FS_TEST_MAIN(TEST(gripping_static_load_converges), TEST(landing_on_flat_ground_converges))
