/* Tests of the step (sim_build.c, sim_spring.c): an undamped foot falling freely, its toes
 * set swinging, does not gain energy (gravitational, kinetic and spring energy summed). */
#include "fs_test.h"

#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

/* Runs the undamped foot without ground for 0.5 s; returns the largest energy gain over the start,
 * and the internal (spring + relative kinetic) energy it was given, both J. */
static void fall(const char *springs, const char *step, double *gain, double *internal)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"springs.c_d1_Ns_per_m=0", "springs.c_d2_Ns_per_m=0", "springs.c_d3_Ns_per_m=0",
                         "load.mass_kg=0", springs, step};
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 6, &sc, &err) == FS_OK);
    fs_sim sim;
    fs_sim_options opts = {.with_ground = 0, .hold_rear_foot = 0};
    REQUIRE(fs_sim_build(&sim, &sc, &opts, &err) == FS_OK);
    /* set every toe swinging about its MTP joint at 20 rad/s */
    for (int i = 0; i < FS_CHAINS; i++) {
        const fs_hinge_geom *h = &sc.geom.hinge[sc.geom.chain[i].mtp_hinge];
        dBodyID b = sim.body[h->body2];
        const dReal *p = dBodyGetPosition(b);
        fs_vec3 w = fs_scale(h->axis, 20.0);
        fs_vec3 v = fs_cross(w, fs_sub(fs_v3(p[0], p[1], p[2]), h->anchor));
        dBodySetAngularVel(b, w.x, w.y, w.z);
        dBodySetLinearVel(b, v.x, v.y, v.z);
    }
    double ke, pe, se;
    double e0 = fs_sim_energy(&sim, &ke, &pe, &se);
    *internal = ke + se;
    *gain = 0;
    long steps = lround(0.5 / sc.def.step_s);
    for (long i = 0; i < steps; i++) {
        CHECK(fs_sim_step(&sim, &err) == FS_OK);
        double e = fs_sim_energy(&sim, NULL, NULL, NULL);
        if (e - e0 > *gain)
            *gain = e - e0;
    }
    fs_sim_destroy(&sim);
}

/* Implicit springs are backward Euler: they can only take energy out. What the hinges' own
 * error correction may add is bounded by rounding: 1e-9 of the internal energy. */
static void implicit_springs_do_not_gain_energy(void)
{
    double gain, internal;
    fall("run.springs=implicit", "run.step_s=1e-4", &gain, &internal);
    CHECK(internal > 0);
    CHECK(gain <= 1e-9 * internal);
}

/* Explicit springs are symplectic Euler: the energy wobbles by about h omega / 2 of the internal
 * energy without drifting; the stiffest mode here (a toe about its MTP joint) has omega below
 * 2000 rad/s, so at h = 1e-5 s the wobble stays under 1 %. */
static void explicit_springs_do_not_gain_energy(void)
{
    double gain, internal;
    fall("run.springs=explicit", "run.step_s=1e-5", &gain, &internal);
    CHECK(internal > 0);
    CHECK(gain <= 0.01 * internal);
}

FS_TEST_MAIN(TEST(implicit_springs_do_not_gain_energy), TEST(explicit_springs_do_not_gain_energy))
