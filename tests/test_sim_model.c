/* Tests of the model apart from its state (footsim/sim/fs_model.h): what a scenario compiles into
 * follows from its parts (masses add up, a merged robot's centre is the two centres weighted by
 * mass, shapes sit where the geometry puts them), a simulation made from a model is bit for bit the
 * one fs_sim_new builds, several simulations share one model, and stepping them leaves the model
 * unchanged (it is immutable). */
#include "fs_test.h"

#include "footsim/sim/fs_model.h"
#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static fs_scenario *load(const char *path, const char *const *sets, int n)
{
    static fs_scenario sc[4];
    static int used;
    fs_error err;
    fs_scenario *s = &sc[used++ % 4];
    if (fs_scenario_load(path, sets, n, s, &err) != FS_OK) {
        fprintf(stderr, "%s\n", err.message);
        return NULL;
    }
    return s;
}

/* The foot's and the robot's masses: the model's bodies carry every kilogram of the geometry and
 * the robot, once (merged into the ankle body or a body of its own), and a merged body's centre is
 * the mass-weighted mean of the two centres. */
static void masses_add_up(void)
{
    const char *own[] = {"robot.design=robots/single_tall_achilles.ini"};
    for (int variant = 0; variant < 2; variant++) {
        fs_scenario *sc = load("scenarios/landing_trial.ini", own, variant);
        REQUIRE(sc);
        fs_model *m;
        fs_error err;
        REQUIRE(fs_model_compile(sc, NULL, &m, &err) == FS_OK);
        double robot_kg = sc->def.robot.mass_kg, total = 0;
        REQUIRE(robot_kg > 0);
        for (int i = 0; i < m->nbodies + m->robot_body; i++)
            total += m->body[i].mass_kg;
        CHECK_NEAR(total, m->geom->total_mass_kg + robot_kg, 1e-12 * total);
        CHECK(m->robot_merged == (variant == 0) && m->robot_body == (variant == 1));
        CHECK(m->has_achilles == (variant == 1)); /* the achilles robot is hinged at the ankle */
        const int a = m->geom->ankle_body;
        const fs_body_geom *g = &m->geom->body[a];
        if (m->robot_merged) {
            const double robot_at[3] = {m->geom->ankle.x + sc->def.robot.com_forward_m, m->geom->ankle.y,
                                        m->geom->ankle.z + sc->def.robot.com_height_m};
            const double foot_at[3] = {g->com.x, g->com.y, g->com.z};
            for (int k = 0; k < 3; k++) {
                double mean = (g->mass_kg * foot_at[k] + robot_kg * robot_at[k]) / (g->mass_kg + robot_kg);
                CHECK_NEAR(m->body[a].com_design_m[k], mean, 1e-12);
                CHECK_NEAR(m->robot_local_m[k], robot_at[k] - mean, 1e-12);
            }
        } else {
            CHECK(m->body[a].mass_kg == g->mass_kg);
            CHECK(!strcmp(m->body[m->nbodies].name, "robot") && m->body[m->nbodies].mass_kg == robot_kg);
            CHECK(m->achilles.body1 == a && m->achilles.body2 == m->nbodies && m->achilles.rest_length_m > 0);
        }
        /* the ODE convention: each body's centre of mass at its origin */
        for (int i = 0; i < m->nbodies + m->robot_body; i++)
            CHECK(m->body[i].centre_m[0] == 0 && m->body[i].centre_m[1] == 0 && m->body[i].centre_m[2] == 0);
        fs_model_free(m);
        fs_scenario_free(sc);
    }
}

/* Shapes where the geometry puts them: a sphere's offset from its body's centre is the design's
 * centre less the body's; a body starts at R0 com + t0; the foot starts lifted drop_m above the
 * flat ground (its lowest sphere's bottom at drop_m). */
static void shapes_and_pose(void)
{
    fs_scenario *sc = load("scenarios/landing_trial.ini", NULL, 0); /* flat ground */
    REQUIRE(sc);
    fs_model *m;
    fs_error err;
    REQUIRE(fs_model_compile(sc, NULL, &m, &err) == FS_OK);
    REQUIRE(m->nshapes == m->geom->nspheres + m->geom->nboxes && m->nshapes > 0);
    double lowest = INFINITY;
    for (int i = 0; i < m->geom->nspheres; i++) {
        const fs_model_shape *s = &m->shape[i];
        const fs_sphere_geom *g = &m->geom->sphere[i];
        CHECK(s->kind == FS_MODEL_SPHERE && s->body == g->body && s->radius_m == g->radius_m);
        const double *c = m->body[s->body].com_design_m;
        CHECK(s->offset_m[0] == g->centre.x - c[0] && s->offset_m[1] == g->centre.y - c[1] &&
              s->offset_m[2] == g->centre.z - c[2]);
        /* the sphere's centre at the start: its body's place plus R0 times the offset */
        const double *R = m->R0, *p = m->body[s->body].pos_m;
        double z = p[2] + R[6] * s->offset_m[0] + R[7] * s->offset_m[1] + R[8] * s->offset_m[2];
        lowest = fmin(lowest, z - s->radius_m);
    }
    CHECK_NEAR(lowest, sc->def.drop_m, 1e-12);
    double n = 0;
    for (int k = 0; k < 4; k++)
        n += m->q0_wxyz[k] * m->q0_wxyz[k];
    CHECK_NEAR(n, 1, 1e-15);
    CHECK_NEAR(m->load_N, sc->def.load_kg * sc->def.gravity_m_per_s2, 1e-12);
    fs_model_free(m);
    fs_scenario_free(sc);
}

static int same_state(const fs_sim *a, const fs_sim *b)
{
    int n = fs_sim_body_count(a), same = n == fs_sim_body_count(b) && fs_sim_time(a) == fs_sim_time(b);
    for (int i = 0; same && i < n; i++) {
        double p[2][3], R[2][9], v[2][3], w[2][3];
        fs_sim_body_pose(a, i, p[0], R[0]);
        fs_sim_body_pose(b, i, p[1], R[1]);
        fs_sim_body_velocity(a, i, v[0], w[0]);
        fs_sim_body_velocity(b, i, v[1], w[1]);
        same = !memcmp(p[0], p[1], sizeof p[0]) && !memcmp(R[0], R[1], sizeof R[0]) && !memcmp(v[0], v[1], sizeof v[0]) &&
               !memcmp(w[0], w[1], sizeof w[0]);
    }
    return same;
}

/* Two simulations from one model and one from fs_sim_new step to the same bits through a
 * landing's touchdown; the model's bytes are the same after as before (nothing writes it), and
 * each sim names its model. */
static void sims_from_one_model(void)
{
    const char *sets[] = {"start.drop_m=0.002"};
    fs_scenario *sc = load("scenarios/landing_trial.ini", sets, 1);
    REQUIRE(sc);
    fs_model *m;
    fs_error err;
    REQUIRE(fs_model_compile(sc, NULL, &m, &err) == FS_OK);
    fs_model *before = malloc(sizeof *before);
    REQUIRE(before);
    memcpy(before, m, sizeof *m);
    fs_sim *a, *b, *c;
    REQUIRE(fs_sim_create(m, NULL, &a, &err) == FS_OK);
    REQUIRE(fs_sim_create(m, NULL, &b, &err) == FS_OK);
    REQUIRE(fs_sim_new(sc, NULL, &c, &err) == FS_OK);
    CHECK(fs_sim_model(a) == m && fs_sim_model(b) == m && fs_sim_model(c) != m);
    CHECK(same_state(a, c) && same_state(b, c));
    int touched = 0;
    for (int i = 0; i < 600; i++) {
        REQUIRE(fs_sim_step(a, &err) == FS_OK);
        REQUIRE(fs_sim_step(b, &err) == FS_OK);
        REQUIRE(fs_sim_step(c, &err) == FS_OK);
        touched |= fs_sim_contact_count(a) > 0;
    }
    CHECK(touched); /* the steps compared include contacts */
    CHECK(same_state(a, c) && same_state(b, c));
    CHECK(fs_sim_energy(a, NULL, NULL, NULL) == fs_sim_energy(c, NULL, NULL, NULL));
    CHECK(fs_sim_warnings(a) == 0 && fs_sim_warnings(c) == 0);
    CHECK(!memcmp(before, m, sizeof *m));
    fs_sim_free(a);
    fs_sim_free(b);
    fs_sim_free(c);
    CHECK(!memcmp(before, m, sizeof *m));
    free(before);
    fs_model_free(m);
    fs_model_free(NULL); /* harmless */
    fs_sim_free(NULL);
    fs_scenario_free(sc);
}

/* The options that shape a model: a pinned chain is its own geometry of one chain, without ground
 * and with a fifth of the load; without ground nothing is lifted. */
static void options_shape_the_model(void)
{
    fs_scenario *sc = load("scenarios/static_load.ini", NULL, 0);
    REQUIRE(sc);
    fs_model *m;
    fs_error err;
    fs_sim_options pinned = {.pinned_chain = 3}; /* the middle chain, unsplayed */
    REQUIRE(fs_model_compile(sc, &pinned, &m, &err) == FS_OK);
    CHECK(m->geom == &m->own_geom && m->npins == 2 && !m->with_ground && m->t0[2] == 0);
    CHECK_NEAR(m->load_N, sc->def.load_kg * sc->def.gravity_m_per_s2 / FS_CHAINS, 1e-12);
    fs_model_free(m);
    fs_sim_options none = {.with_ground = 0};
    REQUIRE(fs_model_compile(sc, &none, &m, &err) == FS_OK);
    CHECK(m->geom == &sc->geom && !m->with_ground && m->t0[2] == 0 && m->npins == 0);
    fs_model_free(m);
    fs_scenario_free(sc);
}

/* A warning given while a sim steps (here by a driver's work function, which runs inside the step)
 * is counted in that sim and in no other. */
static double warn_once(void *user, const struct fs_sim *sim)
{
    int *left = user;
    (void)sim;
    if ((*left)-- > 0)
        fs_warn("a driver's warning");
    return 0;
}

static void warnings_are_counted_per_sim(void)
{
    fs_scenario *sc = load("scenarios/static_load.ini", NULL, 0);
    REQUIRE(sc);
    fs_error err;
    fs_sim *a, *b;
    REQUIRE(fs_sim_new(sc, NULL, &a, &err) == FS_OK);
    REQUIRE(fs_sim_new(sc, NULL, &b, &err) == FS_OK);
    int left = 1;
    fs_check_set_work(a, warn_once, &left);
    long before = fs_warning_count();
    for (int i = 0; i < 5; i++) {
        REQUIRE(fs_sim_step(a, &err) == FS_OK);
        REQUIRE(fs_sim_step(b, &err) == FS_OK);
    }
    CHECK(left < 0); /* the work function ran */
    CHECK(fs_warning_count() == before + 1 && fs_sim_warnings(a) == 1 && fs_sim_warnings(b) == 0);
    fs_sim_free(a);
    fs_sim_free(b);
    fs_scenario_free(sc);
}

FS_TEST_MAIN(TEST(masses_add_up), TEST(shapes_and_pose), TEST(sims_from_one_model), TEST(options_shape_the_model),
             TEST(warnings_are_counted_per_sim))
