/* MuJoCo loads footsim's MJCF export (export_mjcf.c): MuJoCo 2.2.2 (Debian 12's libmujoco-dev)
 * compiles it, and its model holds the masses, the tendons (15 springs, and the Achilles tendon
 * of a robot that has one) with their stiffness, damping and rest length, the trace of every
 * inertia (invariant under the principal-axes rotation MuJoCo applies), the loop closure's two
 * connect equalities, and a heightfield whose surface, found by MuJoCo's own ray cast, lies where
 * footsim's does. Built only when CMake finds libmujoco; otherwise it reports itself skipped
 * (exit 77). Tolerances: copied numbers exactly (1e-12 relative); traces 1e-9 relative (MuJoCo's
 * eigen-decomposition); heights 2^-22 of the terrain's height range (its samples are float32). */
#include "fs_test.h"

#ifndef FS_HAVE_MUJOCO
int main(void)
{
    printf("skipped: libmujoco not found when configuring (apt-get install libmujoco-dev)\n");
    return 77;
}
#else

#include "export_fixture.h"

#include "footsim/export/fs_export.h"
#include "footsim/sim/fs_sim.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <cJSON.h>
#include <mujoco/mujoco.h>
#include <stdlib.h>
#include <unistd.h>

#define EXACT(a, e) CHECK_NEAR((a), (e), 1e-12 * fabs(e))

/* sc written to a temporary folder and loaded by MuJoCo; NULL (and a failure) when it refuses. */
static mjModel *load(const fs_scenario *sc, int with_scenario)
{
    char dir[] = "/tmp/fs_mujoco_XXXXXX", path[64], hpath[80], msg[1000] = "";
    if (!mkdtemp(dir))
        return NULL;
    snprintf(path, sizeof path, "%s/foot.xml", dir);
    fs_error err;
    mjModel *m = NULL;
    if (fs_mjcf_write(sc, with_scenario, path, &err) == FS_OK)
        m = mj_loadXML(path, NULL, msg, sizeof msg);
    else
        fprintf(stderr, "export failed: %s\n", err.message);
    if (!m)
        fprintf(stderr, "MuJoCo %s refused %s: %s\n", mj_versionString(), path, msg);
    fs_mjcf_hfield_path(path, hpath, sizeof hpath);
    remove(hpath);
    remove(path);
    rmdir(dir);
    return m;
}

/* The body's mass and inertia's trace, and every tendon, as footsim's sim holds them. */
static void check_model(const mjModel *m, const fs_scenario *sc, int with_scenario)
{
    static fs_sim sim;
    fs_error err;
    fs_sim_options opts = {.with_ground = with_scenario, .keep_robot_body = 1}; /* as the export builds it */
    REQUIRE(fs_sim_build(&sim, sc, &opts, &err) == FS_OK);
    for (int i = 0; i < sim.geom->nbodies + (sim.robot != NULL); i++) {
        dBodyID b = i < sim.geom->nbodies ? sim.body[i] : sim.robot;
        int id = mj_name2id(m, mjOBJ_BODY, i < sim.geom->nbodies ? sim.geom->body[i].name : "robot");
        REQUIRE(id >= 0);
        dMass mass;
        dBodyGetMass(b, &mass);
        EXACT(m->body_mass[id], mass.mass);
        double trace = mass.I[0] + mass.I[5] + mass.I[10];
        CHECK_NEAR(m->body_inertia[3 * id] + m->body_inertia[3 * id + 1] + m->body_inertia[3 * id + 2], trace,
                   1e-9 * trace);
    }
    int n = sim.geom->nsprings + sim.has_achilles;
    CHECK(m->ntendon == n);
    for (int i = 0; i < n && i < m->ntendon; i++) {
        const fs_spring *s = i < sim.geom->nsprings ? &sim.spring[i] : &sim.achilles;
        int id = mj_name2id(m, mjOBJ_TENDON, i < sim.geom->nsprings ? sim.geom->spring[i].name : "achilles");
        REQUIRE(id >= 0);
        EXACT(m->tendon_stiffness[id], s->k);
        EXACT(m->tendon_damping[id], s->c);
        EXACT(m->tendon_lengthspring[id], s->rest);
    }
    int load = mj_name2id(m, mjOBJ_BODY, "load");
    CHECK((load >= 0) == (with_scenario && sc->def.load_kg > 0));
    if (load >= 0)
        EXACT(m->body_mass[load], sc->def.load_kg);
    EXACT(m->opt.timestep, sc->def.step_s);
    fs_sim_destroy(&sim);
}

static void biomimetic_foot(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    mjModel *m = load(&sc, 0);
    REQUIRE(m);
    CHECK(m->ntendon == 15 && m->nbody == 13 && m->njnt == 12 && m->neq == 0);
    check_model(m, &sc, 0);
    mj_deleteModel(m);
    fs_scenario_free(&sc);
}

static void flat_foot_on_static_load(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", (const char *[]){"scenario.design=feet/flat.ini"}, 1, &sc,
                             &err) == FS_OK);
    mjModel *m = load(&sc, 1);
    REQUIRE(m);
    CHECK(m->ntendon == 0);
    check_model(m, &sc, 1);
    mj_deleteModel(m);
    fs_scenario_free(&sc);
}

/* The landing trial's free robot, and the rig on its vertical slide (one degree of freedom). */
static void landing_trial_robots(void)
{
    const char *rig[] = {"robot.design=robots/rig.ini"};
    for (int r = 0; r < 2; r++) {
        static fs_scenario sc;
        fs_error err;
        REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", rig, r, &sc, &err) == FS_OK);
        mjModel *m = load(&sc, 1);
        REQUIRE(m);
        CHECK(m->ntendon == 15);
        int robot = mj_name2id(m, mjOBJ_BODY, "robot");
        REQUIRE(robot >= 0);
        CHECK(m->body_jntnum[robot] == 1 && m->jnt_type[m->body_jntadr[robot]] == (r ? mjJNT_SLIDE : mjJNT_FREE));
        check_model(m, &sc, 1);
        mj_deleteModel(m);
        fs_scenario_free(&sc);
    }
}

/* The walking machine's heightfield: MuJoCo's ray cast down onto the ground (group 0 only) finds
 * fs_terrain_height at points inside the lattice's cells, so both split the cells alike. */
static void walking_heightfield(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking.ini", NULL, 0, &sc, &err) == FS_OK);
    mjModel *m = load(&sc, 1);
    REQUIRE(m);
    CHECK(m->ntendon == 16 && m->nhfield == 1);
    check_model(m, &sc, 1);
    mjData *d = mj_makeData(m);
    REQUIRE(d);
    mj_forward(m, d);
    const fs_terrain *t = &sc.terrain;
    const mjtByte ground_only[mjNGROUP] = {1, 0, 0, 0, 0, 0};
    double range = t->zmax - t->zmin, worst = 0;
    int rays = 0;
    for (int a = 1; a < 20; a++)
        for (int b = 1; b < 20; b++) {
            /* a point a fraction into a cell, on either side of its diagonal */
            double x = t->x0 + (floor(a * (t->nx - 1) / 20.0) + 0.3 + 0.4 * (a % 2)) * t->dx;
            double y = t->y0 + (floor(b * (t->ny - 1) / 20.0) + 0.6 - 0.4 * (b % 2)) * t->dx;
            double top = t->zmax + 1, p[3] = {x, y, top}, down[3] = {0, 0, -1};
            int geom = -1;
            double dist = mj_ray(m, d, p, down, ground_only, 1, -1, &geom);
            if (dist < 0)
                continue;
            worst = fmax(worst, fabs(top - dist - fs_terrain_height(t, x, y)));
            rays++;
        }
    CHECK(rays == 19 * 19);
    CHECK(worst <= range * 0x1p-22);
    printf("  heightfield: %d rays, worst height difference %.3g m (range %.3g m)\n", rays, worst, range);
    mj_deleteData(d);
    mj_deleteModel(m);
    fs_scenario_free(&sc);
}

static void loop_closure(void)
{
    static fs_scenario sc;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_fixture_make_loop(&sc));
    mjModel *m = load(&sc, 0);
    REQUIRE(m);
    CHECK(m->neq == 2 && m->eq_type[0] == mjEQ_CONNECT && m->eq_type[1] == mjEQ_CONNECT);
    mj_deleteModel(m);
    fs_scenario_free(&sc);
}

/* The static-load scenarios run in MuJoCo: 2 s without an instability (MuJoCo's bad-acceleration
 * warning, which resets the state), the ankle (the load's point mass) lower at the end than at
 * the start and by less than the foot is high. The drop is printed beside footsim's (docs/export.md
 * quotes both); it is not compared, the contact and friction models differ. */
static void static_loads_run(void)
{
    const char *files[] = {"scenarios/static_load.ini", "scenarios/tilt10.ini"};
    for (int f = 0; f < 2; f++) {
        static fs_scenario sc;
        fs_error err;
        REQUIRE(fs_scenario_load(files[f], NULL, 0, &sc, &err) == FS_OK);
        mjModel *m = load(&sc, 1);
        REQUIRE(m);
        mjData *d = mj_makeData(m);
        REQUIRE(d);
        int load = mj_name2id(m, mjOBJ_BODY, "load");
        REQUIRE(load >= 0);
        mj_forward(m, d);
        double z0 = d->xpos[3 * load + 2];
        int steps = (int)lround(2.0 / m->opt.timestep);
        for (int i = 0; i < steps && !d->warning[mjWARN_BADQACC].number; i++)
            mj_step(m, d);
        double drop = z0 - d->xpos[3 * load + 2];
        CHECK(d->warning[mjWARN_BADQACC].number == 0);
        CHECK(drop > 0 && drop < sc.geom.ankle.z);
        printf("  %s in MuJoCo %s: ankle drop %.3f mm after %.1f s\n", sc.name, mj_versionString(), drop * 1e3, d->time);
        mj_deleteData(d);
        mj_deleteModel(m);
        fs_scenario_free(&sc);
    }
}

/* A tension-only d3 (a cable) is a limited tendon with no spring of its own, limited to its rest
 * length. MuJoCo holds it so, and the limit is one-sided: each chain's MTP joint turned 0.05 rad
 * either way from the design pose (the rest length), the turn that stretches the tendon makes a
 * tendon-limit row in MuJoCo's constraints pulling (force > 0), the turn that shortens it none. The
 * force against k times the stretch is printed: MuJoCo's soft limit works per unit of the mass it
 * moves (docs/export.md); d1 and d2 stay two-sided springs. Nonlinear laws are refused. */
static void cable_is_a_one_sided_limit(void)
{
    static fs_scenario sc;
    fs_error err;
    const char *set[] = {"springs.d3_tension_only=yes"};
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", set, 1, &sc, &err) == FS_OK);
    mjModel *m = load(&sc, 0);
    REQUIRE(m);
    mjData *d = mj_makeData(m);
    REQUIRE(d);
    for (int i = 0; i < FS_CHAINS; i++) {
        const fs_spring_geom *s = &sc.geom.spring[sc.geom.chain[i].spring[2]];
        const fs_spring_geom *s1 = &sc.geom.spring[sc.geom.chain[i].spring[0]];
        int id = mj_name2id(m, mjOBJ_TENDON, s->name), id1 = mj_name2id(m, mjOBJ_TENDON, s1->name);
        REQUIRE(id >= 0 && id1 >= 0);
        CHECK(m->tendon_limited[id] == 1 && m->tendon_stiffness[id] == 0 && m->tendon_damping[id] == 0);
        CHECK(m->tendon_range[2 * id] == 0);
        EXACT(m->tendon_range[2 * id + 1], s->rest_length_m);
        CHECK(m->tendon_limited[id1] == 0);
        EXACT(m->tendon_stiffness[id1], s1->k_N_per_m);
        char joint[32];
        snprintf(joint, sizeof joint, "%s", sc.geom.hinge[sc.geom.chain[i].mtp_hinge].name);
        int j = mj_name2id(m, mjOBJ_JOINT, joint);
        REQUIRE(j >= 0);
        int stretched = 0, shortened = 0;
        for (int sign = -1; sign <= 1; sign += 2) {
            mju_copy(d->qpos, m->qpos0, m->nq);
            mju_zero(d->qvel, m->nv);
            d->qpos[m->jnt_qposadr[j]] += sign * 0.05;
            mj_forward(m, d);
            double stretch = d->ten_length[id] - s->rest_length_m, force = 0;
            int rows = 0;
            for (int r = 0; r < d->nefc; r++)
                if (d->efc_type[r] == mjCNSTR_LIMIT_TENDON && d->efc_id[r] == id) {
                    rows++;
                    force = d->efc_force[r];
                }
            if (stretch > 0) {
                stretched++;
                CHECK(rows == 1 && force > 0);
                if (i == 0)
                    printf("  cable d3 of chain 1 stretched %.3f mm: MuJoCo's limit pulls %.4g N, k x = %.4g N "
                           "(ratio %.3g)\n", stretch * 1e3, force, s->k_N_per_m * stretch,
                           force / (s->k_N_per_m * stretch));
            } else {
                shortened++;
                CHECK(rows == 0);
            }
        }
        CHECK(stretched == 1 && shortened == 1);
    }
    mj_deleteData(d);
    mj_deleteModel(m);
    fs_scenario_free(&sc);
    /* a law MuJoCo 2.2.2's tendons cannot express: refused, naming the spring and the law */
    const char *prog[] = {"springs.d1_law=progressive"};
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", prog, 1, &sc, &err) == FS_OK);
    fs_mjcf out;
    CHECK(fs_mjcf_build(&sc, 0, NULL, &out, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "d1_chain1's law is progressive") != NULL);
    /* at the law key's place, as every refusal: here its --set (cli_bad_input.sh: a file's line) */
    CHECK(strncmp(err.message, "--set springs.d1_law: ", 22) == 0);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(static_loads_run), TEST(biomimetic_foot), TEST(flat_foot_on_static_load), TEST(landing_trial_robots),
             TEST(walking_heightfield), TEST(loop_closure), TEST(cable_is_a_one_sided_limit))
#endif
