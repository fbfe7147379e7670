/* Tests of model_terrain.c and sim_ground.c: every terrain lies where its height function says,
 * nothing tunnels through it, the same seed gives the same ground, and bad files are refused. */
#include "fs_test.h"

#include "sim/sim_ground.h" /* private to the sim layer: the test reaches in */
#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *terrains[] = {"flat", "slope", "stepped", "rough", "simply_uneven", "complex_uneven", "heightmap",
                                 "soft"};
enum { NTERRAINS = sizeof terrains / sizeof terrains[0] };

static void terrain_path(char *buf, size_t n, const char *name) { snprintf(buf, n, "terrains/%s.ini", name); }

/* Where a sphere of radius r centred above (x, y) comes to rest on the surface: the lowest centre
 * height that touches it, max over the disc of h(p) + sqrt(r^2 - |p - c|^2), sampled every r/40. */
static double support_height(const fs_terrain *t, double x, double y, double r)
{
    double best = -INFINITY, step = r / 40;
    for (double dx = -r; dx <= r; dx += step)
        for (double dy = -r; dy <= r; dy += step) {
            double d2 = dx * dx + dy * dy;
            if (d2 <= r * r)
                best = fmax(best, fs_terrain_height(t, x + dx, y + dy) + sqrt(r * r - d2));
        }
    return best;
}

typedef struct found_set { dContactGeom c[8]; int n; } found_set;

static void on_near(void *data, dGeomID a, dGeomID b)
{
    found_set *f = data;
    if (f->n < 8)
        f->n += dCollide(a, b, 8 - f->n, f->c + f->n, sizeof f->c[0]);
}

/* A 5 mm sphere that cannot turn (so it stays where friction holds it) let go 2 mm above the
 * surface at (x, y); returns where it settles and its speed there. ODE corrects a contact's depth
 * at up to MAX_CORRECTING_M_PER_S: without that cap a sphere sliding down a rock's flank onto a
 * steeper triangle found itself 39 um deep in one step, was pushed out at 0.35 m/s and was in the
 * air, 6 mm up, when the test read it (complex_uneven at (-0.0423, 0.0371), docs/terrain.md). */
static const double MAX_CORRECTING_M_PER_S = 0.01;
static void drop_sphere(const fs_terrain *t, double x, double y, double out[3], double *speed)
{
    const double r = 0.005, h = 1e-4;
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetContactSurfaceLayer(world, 1e-9);
    dWorldSetContactMaxCorrectingVel(world, MAX_CORRECTING_M_PER_S);
    dSpaceID ground = dHashSpaceCreate(0), space = dSimpleSpaceCreate(0);
    int ok;
    fs_ground *hf = fs_ground_of_terrain(ground, t, 8, &ok);
    CHECK(ok);
    dBodyID b = dBodyCreate(world);
    dMass m;
    dMassSetSphereTotal(&m, 0.01, r);
    dBodySetMass(b, &m);
    dBodySetMaxAngularSpeed(b, 0);
    dBodySetPosition(b, x, y, support_height(t, x, y, r) + 0.002);
    dGeomID g = dCreateSphere(space, r);
    dGeomSetBody(g, b);
    dJointGroupID contacts = dJointGroupCreate(0);
    for (int step = 0; step < 8000; step++) {
        found_set f = {.n = 0};
        dSpaceCollide2(g, (dGeomID)ground, &f, on_near);
        dContactGeom *found = f.c;
        for (int k = 0; k < f.n; k++) {
            dContact ct;
            memset(&ct, 0, sizeof ct);
            ct.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
            ct.surface.mu = 1.0;
            ct.surface.soft_erp = h * 1e8 / (h * 1e8 + 1e3);
            ct.surface.soft_cfm = 1 / (h * 1e8 + 1e3);
            ct.geom = found[k];
            dJointAttach(dJointCreateContact(world, contacts, &ct), b, 0);
        }
        dWorldStep(world, h);
        dJointGroupEmpty(contacts);
    }
    memcpy(out, dBodyGetPosition(b), 3 * sizeof(double));
    const dReal *v = dBodyGetLinearVel(b);
    *speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
    dSpaceDestroy(ground);
    fs_ground_destroy(hf);
    dWorldDestroy(world);
}

/* The steepest slope of a cut heightfield's triangles (0 for planes and steps, whose faces are
 * flat), from its samples. */
static double steepest_slope(const fs_terrain *t)
{
    double g = 0;
    for (int j = 0; t->z && j + 1 < t->ny; j++)
        for (int i = 0; i + 1 < t->nx; i++) {
            const double *z = t->z + (size_t)j * t->nx + i;
            g = fmax(g, fmax(fabs(z[1] - z[0]), fabs(z[t->nx] - z[0])) / t->dx);
            g = fmax(g, fmax(fabs(z[t->nx + 1] - z[1]), fabs(z[t->nx + 1] - z[t->nx])) / t->dx);
        }
    return g;
}

/* On every terrain, at lattice nodes, cell edges and diagonals, on step edges: the sphere settles
 * (slower than the capped correction could throw it: it may creep down a slope, it is not in the
 * air) where the height function says. fs_terrain_height is the surface ODE collides with (the same
 * triangles), so what separates the two is, per terrain: the weight's compression of the contact
 * (0.098 N / 1e8 N/m = 1e-9 m); a hop of at most v^2 / 2g from the capped depth correction (5 um);
 * and support_height's sampling of the disc every r/40, which can miss the highest touching point
 * by the support's gradient there times half a sample's diagonal (r/40 * 0.71). That gradient is
 * the surface's slope plus tan of the contact normal's angle from vertical, which friction (mu = 1)
 * keeps at most 1 for a sphere that stays put: (steepest slope + 1) * r/40 * 0.71, from 88 um on
 * planes and steps (a sphere resting on a step's edge) up with the terrain's steepest triangle. */
static void spheres_rest_on_the_surface(void)
{
    const double pts[][2] = {{0, 0},          {0.01, 0.02},   {0.0305, -0.01}, {0.0335, 0.004}, {0.06, -0.015},
                             {0.0705, 0.0105}, {0.0295, 0.01}, {0.07, 0.0},     {0.1105, 0.01},  {-0.0423, 0.0371}};
    for (int i = 0; i < NTERRAINS; i++) {
        char path[64];
        terrain_path(path, sizeof path, terrains[i]);
        static fs_terrain t;
        fs_error err;
        REQUIRE(fs_terrain_load(path, NULL, 0, &t, &err) == FS_OK);
        CHECK(fs_terrain_crop(&t, -0.1, 0.2, -0.1, 0.1, &err) == FS_OK);
        const double r = 0.005, hop = MAX_CORRECTING_M_PER_S * MAX_CORRECTING_M_PER_S / (2 * 9.81);
        double bound = 1e-9 + hop + (steepest_slope(&t) + 1) * r / 40 * M_SQRT1_2;
        for (size_t p = 0; p < sizeof pts / sizeof pts[0]; p++) {
            double c[3], speed;
            drop_sphere(&t, pts[p][0], pts[p][1], c, &speed);
            double expect = support_height(&t, c[0], c[1], r);
            if (fabs(c[2] - expect) > bound || speed > MAX_CORRECTING_M_PER_S)
                fprintf(stderr, "  %s at (%g, %g): rests at %.6f m at %.2g m/s, surface says %.6f m (bound %.2g m)\n",
                        terrains[i], pts[p][0], pts[p][1], c[2], speed, expect, bound);
            CHECK(speed < MAX_CORRECTING_M_PER_S);
            CHECK_NEAR(c[2], expect, bound);
        }
        fs_terrain_free(&t);
    }
}

/* Both feet dropped from 0.5 m onto every terrain end with no shape more than 1 mm below it
 * (soft ground gives way more than that during the impact, by design). */
static void nothing_tunnels(void)
{
    for (int f = 0; f < 2; f++)
        for (int i = 0; i < NTERRAINS; i++) {
            char terrain[96], design[64];
            snprintf(terrain, sizeof terrain, "scenario.terrain=../terrains/%s.ini", terrains[i]);
            snprintf(design, sizeof design, "foot.kind=%s", f ? "flat" : "biomimetic");
            const char *set[] = {terrain, design, "load.mass_kg=0", "start.drop_m=0.5", "start.x_m=-0.02",
                                 "start.yaw_deg=7"};
            static fs_scenario sc;
            fs_error err;
            REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 6, &sc, &err) == FS_OK);
            fs_sim sim;
            REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
            for (int step = 0; step < 7000; step++)
                CHECK(fs_sim_step(&sim, &err) == FS_OK);
            double worst = fs_sim_penetration(&sim);
            if (worst > 1e-3)
                fprintf(stderr, "  %s foot on %s: %.2f mm below the surface\n", f ? "flat" : "biomimetic", terrains[i],
                        worst * 1e3);
            CHECK(worst <= 1e-3);
            /* and it did fall and land */
            double a[3];
            fs_sim_ankle(&sim, a);
            CHECK(a[2] < 0.1 && sim.contacts_now > 0);
            fs_sim_destroy(&sim);
            fs_scenario_free(&sc);
        }
}

/* The same seed gives the same samples wherever the heightfield is cut; another seed does not;
 * a run on it repeats bit for bit. */
static void same_seed_same_ground(void)
{
    static fs_terrain a, b, c;
    fs_error err;
    const char *seed2[] = {"rough.seed=2"};
    REQUIRE(fs_terrain_load("terrains/complex_uneven.ini", NULL, 0, &a, &err) == FS_OK);
    REQUIRE(fs_terrain_load("terrains/complex_uneven.ini", NULL, 0, &b, &err) == FS_OK);
    REQUIRE(fs_terrain_load("terrains/complex_uneven.ini", seed2, 1, &c, &err) == FS_OK);
    CHECK(fs_terrain_crop(&a, -0.05, 0.10, -0.04, 0.04, &err) == FS_OK);
    CHECK(fs_terrain_crop(&b, 0.00, 0.15, -0.02, 0.06, &err) == FS_OK);
    CHECK(fs_terrain_crop(&c, -0.05, 0.10, -0.04, 0.04, &err) == FS_OK);
    int same = 1, differ = 0;
    for (double x = 0.0; x <= 0.1; x += 0.0037)
        for (double y = -0.02; y <= 0.04; y += 0.0041) {
            double za = fs_terrain_height(&a, x, y), zb = fs_terrain_height(&b, x, y);
            same &= memcmp(&za, &zb, sizeof za) == 0;
            differ |= fs_terrain_height(&c, x, y) != za;
        }
    CHECK(same);
    CHECK(differ);
    fs_terrain_free(&a), fs_terrain_free(&b), fs_terrain_free(&c);
    /* a run twice: the same trajectory to the last bit (the 26 kg load folds the foot on the
     * rocks) */
    const char *set[] = {"scenario.terrain=../terrains/complex_uneven.ini", "start.drop_m=0.01"};
    fs_run_result r[2];
    for (int k = 0; k < 2; k++) {
        static fs_scenario sc;
        REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 2, &sc, &err) == FS_OK);
        REQUIRE(fs_run(&sc, NULL, &r[k], &err) == FS_OK);
        fs_scenario_free(&sc);
    }
    CHECK(r[0].nrows == r[1].nrows && r[0].nrows > 10);
    CHECK(memcmp(r[0].rows, r[1].rows, (size_t)r[0].nrows * r[0].ncols * sizeof(double)) == 0);
    fs_run_free(&r[0]), fs_run_free(&r[1]);
}

/* The default cap on contacts per foot shape (run.max_contacts) is enough: both feet come to rest
 * on the rocks where they would with every contact ODE finds kept (FS_MAX_SHAPE_CONTACTS), to a micron. */
static void contact_cap_is_enough(void)
{
    char all[64];
    snprintf(all, sizeof all, "run.max_contacts=%d", FS_MAX_SHAPE_CONTACTS);
    for (int f = 0; f < 2; f++) {
        double end[2][3];
        for (int k = 0; k < 2; k++) {
            const char *set[] = {"scenario.terrain=../terrains/complex_uneven.ini", f ? "foot.kind=flat" : "foot.kind=biomimetic",
                                 "load.mass_kg=0", "start.drop_m=0.005", k ? all : "run.rest_hold_s=0.05"};
            static fs_scenario sc;
            fs_error err;
            fs_run_result r;
            REQUIRE(fs_scenario_load("scenarios/static_load.ini", set, 5, &sc, &err) == FS_OK);
            CHECK(k ? sc.def.max_contacts == FS_MAX_SHAPE_CONTACTS : sc.def.max_contacts < FS_MAX_SHAPE_CONTACTS);
            REQUIRE(fs_run(&sc, NULL, &r, &err) == FS_OK);
            CHECK(r.at_rest);
            memcpy(end[k], r.ankle_end_m, sizeof end[k]);
            fs_run_free(&r);
            fs_scenario_free(&sc);
        }
        for (int i = 0; i < 3; i++)
            CHECK_NEAR(end[0][i], end[1][i], 1e-6);
    }
}

static char dir[64];

static void refused(const char *text, int line, const char *words)
{
    char path[128];
    snprintf(path, sizeof path, "%s/terrain.ini", dir);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
    static fs_terrain t;
    fs_error err = {0};
    CHECK(fs_terrain_load(path, NULL, 0, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, line, words);
}

static void bad_terrain_files_are_refused(void)
{
    snprintf(dir, sizeof dir, "/tmp/footsim-terrain-XXXXXX");
    CHECK(mkdtemp(dir) != NULL);
    char notpng[128];
    snprintf(notpng, sizeof notpng, "%s/notpng.png", dir);
    FILE *f = fopen(notpng, "w");
    fputs("this is text\n", f);
    fclose(f);
    refused("[terrain]\nkind = rough\n[rough]\nresolution_m = -0.001\n", 4, "out of range");
    refused("[terrain]\nkind = rough\n[rough]\nrms_m = nan\n", 4, "not a finite number");
    refused("[terrain]\nkind = heightmap\n[heightmap]\nfile = missing.png\n", 4, "no such file");
    refused("[terrain]\nkind = heightmap\n[heightmap]\nfile = notpng.png\n", 4, "is not a PNG image");
    refused("[terrain]\nkind = heightmap\n", 0, "needs [heightmap] file");
    refused("[terrain]\nkind = lava\n", 2, "allowed: flat|slope|stepped");
    refused("[terrain]\nkind = complex_uneven\n[rocks]\nheight_min_m = 0.02\nheight_max_m = 0.01\n", 5,
            "below height_min_m");
    char cmd[96];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    CHECK(system(cmd) == 0);
}

FS_TEST_MAIN(TEST(spheres_rest_on_the_surface), TEST(nothing_tunnels), TEST(same_seed_same_ground), TEST(contact_cap_is_enough),
             TEST(bad_terrain_files_are_refused))
