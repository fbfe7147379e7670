/* Tests of export_mjcf.c (footsim export --mjcf): the MJCF is parsed back with libxml2 and every
 * mass, inertia, pose, joint, anchor, stiffness, damping, rest length and contact shape is
 * compared with the model dump (fs_model_json, what `footsim model --json` prints) or, for a
 * scenario, with the ODE world footsim builds for it.
 *
 * Tolerances: numbers are written with %.17g, so a number copied reads back exactly (masses,
 * inertias, stiffness, damping, rest lengths, sizes: compared to 1e-12 relative, which fails on
 * any rounding to fewer digits). Positions are written in each body's parent frame and composed
 * back here, which costs a few roundings of the world coordinates: 1e-9 relative to the larger of
 * the value and the foot's extent (0.1 m), i.e. 0.1 nm. */
#include "fs_test.h"

#include "export_fixture.h"

#include "footsim/export/fs_export.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_model.h"
#include "sim/sim_internal.h" /* the sim's fields, which tests may read */

#include <cJSON.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define EXACT(a, e) CHECK_NEAR((a), (e), 1e-12 * fabs(e))
#define SAME_POS(a, e) CHECK_NEAR((a), (e), 1e-9 * fmax(fabs(e), 0.1))

/* ---- the document, read back ----------------------------------------------------------------- */

enum { MAXB = 32, MAXS = 64, MAXG = 64, MAXJ = 32, MAXT = 32, MAXE = 8 };

typedef struct xbody { char name[64]; int parent; double p[3], R[9], q[4], mass, I[9]; int free, slide; } xbody;
typedef struct xsite { char name[64]; int body; double p[3]; } xsite;
typedef struct xgeom { char name[64], type[16], cls[16]; int body; double size[4], p[3]; } xgeom;
typedef struct xjoint { char name[64]; int body; double p[3], axis[3]; } xjoint;
typedef struct xtendon { char name[64], site[2][64]; double k, c, rest; } xtendon;
typedef struct xeq { char kind[16], body1[64], body2[64]; double anchor[3]; } xeq;

typedef struct xmodel {
    xbody body[MAXB];
    xsite site[MAXS];
    xgeom geom[MAXG];
    xjoint joint[MAXJ];
    xtendon tendon[MAXT];
    xeq eq[MAXE];
    int nbody, nsite, ngeom, njoint, ntendon, neq;
    double timestep, gravity[3];
    char hfield_file[256];
    double hfield_size[4];
} xmodel;

/* Reads up to n numbers of attribute name; returns how many there were (0: absent). */
static int nums(xmlNodePtr e, const char *name, double *v, int n)
{
    xmlChar *s = xmlGetProp(e, BAD_CAST name);
    if (!s)
        return 0;
    int k = 0;
    char *p = (char *)s, *end;
    while (k < n) {
        double x = strtod(p, &end);
        if (end == p)
            break;
        v[k++] = x;
        p = end;
    }
    xmlFree(s);
    return k;
}

static void text(xmlNodePtr e, const char *name, char *out, size_t size)
{
    xmlChar *s = xmlGetProp(e, BAD_CAST name);
    snprintf(out, size, "%s", s ? (const char *)s : "");
    xmlFree(s);
}

static int is(xmlNodePtr e, const char *name) { return e->type == XML_ELEMENT_NODE && !strcmp((const char *)e->name, name); }

static void quat_matrix(const double q[4], double R[9])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double M[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                   2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    memcpy(R, M, sizeof M);
}

static void quat_mul(const double a[4], const double b[4], double q[4])
{
    q[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    q[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    q[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    q[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* World coordinates of a point (or direction) given in body b's frame. */
static void to_world(const xbody *b, const double v[3], int point, double w[3])
{
    for (int r = 0; r < 3; r++)
        w[r] = (point ? b->p[r] : 0) + b->R[3 * r] * v[0] + b->R[3 * r + 1] * v[1] + b->R[3 * r + 2] * v[2];
}

static void read_body(xmodel *m, xmlNodePtr e, int parent)
{
    REQUIRE(m->nbody < MAXB);
    int i = m->nbody++;
    xbody *b = &m->body[i];
    text(e, "name", b->name, sizeof b->name);
    b->parent = parent;
    double p[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
    nums(e, "pos", p, 3);
    nums(e, "quat", q, 4);
    if (parent < 0) {
        memcpy(b->p, p, sizeof p);
        memcpy(b->q, q, sizeof q);
    } else {
        to_world(&m->body[parent], p, 1, b->p);
        quat_mul(m->body[parent].q, q, b->q);
    }
    quat_matrix(b->q, b->R);
    for (xmlNodePtr c = e->children; c; c = c->next) {
        if (is(c, "freejoint"))
            b->free = 1;
        else if (is(c, "joint")) {
            char type[16];
            text(c, "type", type, sizeof type);
            if (!strcmp(type, "slide")) {
                b->slide = 1;
                continue;
            }
            REQUIRE(m->njoint < MAXJ && !strcmp(type, "hinge"));
            xjoint *j = &m->joint[m->njoint++];
            text(c, "name", j->name, sizeof j->name);
            j->body = i;
            double lp[3], la[3];
            CHECK(nums(c, "pos", lp, 3) == 3 && nums(c, "axis", la, 3) == 3);
            to_world(b, lp, 1, j->p);
            to_world(b, la, 0, j->axis);
        } else if (is(c, "inertial")) {
            double f[6];
            CHECK(nums(c, "mass", &b->mass, 1) == 1);
            double pos[3];
            CHECK(nums(c, "pos", pos, 3) == 3 && pos[0] == 0 && pos[1] == 0 && pos[2] == 0);
            int n = nums(c, "fullinertia", f, 6);
            if (n == 6) {
                double I[9] = {f[0], f[3], f[4], f[3], f[1], f[5], f[4], f[5], f[2]};
                memcpy(b->I, I, sizeof I);
            } else {
                CHECK(nums(c, "diaginertia", f, 3) == 3);
                double I[9] = {f[0], 0, 0, 0, f[1], 0, 0, 0, f[2]};
                memcpy(b->I, I, sizeof I);
            }
        } else if (is(c, "site")) {
            REQUIRE(m->nsite < MAXS);
            xsite *s = &m->site[m->nsite++];
            text(c, "name", s->name, sizeof s->name);
            s->body = i;
            double lp[3];
            CHECK(nums(c, "pos", lp, 3) == 3);
            to_world(b, lp, 1, s->p);
        } else if (is(c, "geom")) {
            REQUIRE(m->ngeom < MAXG);
            xgeom *g = &m->geom[m->ngeom++];
            text(c, "name", g->name, sizeof g->name);
            text(c, "type", g->type, sizeof g->type);
            text(c, "class", g->cls, sizeof g->cls);
            g->body = i;
            double lp[3];
            CHECK(nums(c, "size", g->size, 4) > 0 && nums(c, "pos", lp, 3) == 3);
            to_world(b, lp, 1, g->p);
        } else if (is(c, "body"))
            read_body(m, c, i);
    }
}

static void read_model(xmodel *m, const char *xml, size_t len)
{
    memset(m, 0, sizeof *m);
    xmlDocPtr doc = xmlReadMemory(xml, (int)len, "export.xml", NULL, XML_PARSE_NONET);
    REQUIRE(doc);
    xmlNodePtr root = xmlDocGetRootElement(doc);
    CHECK(root && is(root, "mujoco"));
    for (xmlNodePtr e = root ? root->children : NULL; e; e = e->next) {
        if (is(e, "option")) {
            CHECK(nums(e, "timestep", &m->timestep, 1) == 1);
            CHECK(nums(e, "gravity", m->gravity, 3) == 3);
        } else if (is(e, "asset")) {
            for (xmlNodePtr c = e->children; c; c = c->next)
                if (is(c, "hfield")) {
                    text(c, "file", m->hfield_file, sizeof m->hfield_file);
                    CHECK(nums(c, "size", m->hfield_size, 4) == 4);
                }
        } else if (is(e, "worldbody")) {
            for (xmlNodePtr c = e->children; c; c = c->next) {
                if (is(c, "body"))
                    read_body(m, c, -1);
                else if (is(c, "geom")) { /* the ground, in world coordinates */
                    REQUIRE(m->ngeom < MAXG);
                    xgeom *g = &m->geom[m->ngeom++];
                    text(c, "name", g->name, sizeof g->name);
                    text(c, "type", g->type, sizeof g->type);
                    text(c, "class", g->cls, sizeof g->cls);
                    g->body = -1;
                    nums(c, "size", g->size, 4);
                    nums(c, "pos", g->p, 3);
                }
            }
        } else if (is(e, "tendon")) {
            for (xmlNodePtr c = e->children; c; c = c->next) {
                if (!is(c, "spatial"))
                    continue;
                REQUIRE(m->ntendon < MAXT);
                xtendon *t = &m->tendon[m->ntendon++];
                text(c, "name", t->name, sizeof t->name);
                CHECK(nums(c, "stiffness", &t->k, 1) == 1 && nums(c, "damping", &t->c, 1) == 1 &&
                      nums(c, "springlength", &t->rest, 1) == 1);
                int k = 0;
                for (xmlNodePtr s = c->children; s; s = s->next)
                    if (is(s, "site") && k < 2)
                        text(s, "site", t->site[k++], sizeof t->site[0]);
                CHECK(k == 2);
            }
        } else if (is(e, "equality")) {
            for (xmlNodePtr c = e->children; c; c = c->next) {
                if (c->type != XML_ELEMENT_NODE)
                    continue;
                REQUIRE(m->neq < MAXE);
                xeq *q = &m->eq[m->neq++];
                snprintf(q->kind, sizeof q->kind, "%s", (const char *)c->name);
                text(c, "body1", q->body1, sizeof q->body1);
                text(c, "body2", q->body2, sizeof q->body2);
                nums(c, "anchor", q->anchor, 3);
            }
        }
    }
    xmlFreeDoc(doc);
}

static int body_named(const xmodel *m, const char *name)
{
    for (int i = 0; i < m->nbody; i++)
        if (!strcmp(m->body[i].name, name))
            return i;
    return -1;
}

static const xsite *site_named(const xmodel *m, const char *name)
{
    for (int i = 0; i < m->nsite; i++)
        if (!strcmp(m->site[i].name, name))
            return &m->site[i];
    return NULL;
}

static const xjoint *joint_named(const xmodel *m, const char *name)
{
    for (int i = 0; i < m->njoint; i++)
        if (!strcmp(m->joint[i].name, name))
            return &m->joint[i];
    return NULL;
}

static double num(const cJSON *o, const char *key) { return cJSON_GetObjectItem(o, key)->valuedouble; }
static double at(const cJSON *o, const char *key, int i) { return cJSON_GetArrayItem(cJSON_GetObjectItem(o, key), i)->valuedouble; }
static const char *str(const cJSON *o, const char *key) { return cJSON_GetObjectItem(o, key)->valuestring; }

static void export_scenario(const fs_scenario *sc, int with_scenario, fs_mjcf *out, xmodel *m)
{
    fs_error err;
    REQUIRE(fs_mjcf_build(sc, with_scenario, "x.hfield.bin", out, &err) == FS_OK);
    read_model(m, out->xml, out->xml_len);
}

/* ---- the foot against the model dump ----------------------------------------------------------- */

static void check_against_dump(const char *design, int nbodies, int ntendons)
{
    static fs_scenario sc;
    static xmodel m;
    fs_error err;
    REQUIRE(fs_scenario_for_design(design, NULL, 0, &sc, &err) == FS_OK);
    fs_mjcf out;
    export_scenario(&sc, 0, &out, &m);
    cJSON *dump = fs_model_json(&sc, &err);
    REQUIRE(dump);
    const cJSON *bodies = cJSON_GetObjectItem(dump, "bodies"), *joints = cJSON_GetObjectItem(dump, "joints");
    const cJSON *springs = cJSON_GetObjectItem(dump, "springs"), *geoms = cJSON_GetObjectItem(dump, "geoms");
    CHECK(m.nbody == nbodies && cJSON_GetArraySize(bodies) == nbodies);
    CHECK(m.ntendon == ntendons && cJSON_GetArraySize(springs) == ntendons);
    CHECK(m.njoint == cJSON_GetArraySize(joints));
    CHECK(m.ngeom == cJSON_GetArraySize(geoms));
    CHECK(m.neq == 0); /* every shipped foot is a tree: its loops close through the ground */
    CHECK(m.timestep == sc.def.step_s && m.gravity[2] == -sc.def.gravity_m_per_s2);
    const cJSON *o;
    cJSON_ArrayForEach(o, bodies) {
        int b = body_named(&m, str(o, "name"));
        REQUIRE(b >= 0);
        EXACT(m.body[b].mass, num(o, "mass_kg"));
        for (int k = 0; k < 9; k++)
            EXACT(m.body[b].I[k], at(o, "inertia_kgm2", k));
        for (int k = 0; k < 3; k++)
            SAME_POS(m.body[b].p[k], at(o, "pos_m", k));
        for (int k = 0; k < 4; k++)
            CHECK_NEAR(m.body[b].q[k], at(o, "quat_wxyz", k), 1e-12);
        CHECK(m.body[b].free == (m.body[b].parent < 0)); /* the root is free, as the foot in footsim */
    }
    cJSON_ArrayForEach(o, joints) {
        const xjoint *j = joint_named(&m, str(o, "name"));
        REQUIRE(j);
        /* the hinge joins the same two bodies: one is the other's parent in the tree */
        int b1 = body_named(&m, str(o, "body1")), b2 = body_named(&m, str(o, "body2"));
        CHECK((j->body == b2 && m.body[b2].parent == b1) || (j->body == b1 && m.body[b1].parent == b2));
        for (int k = 0; k < 3; k++) {
            SAME_POS(j->p[k], at(o, "anchor_m", k));
            CHECK_NEAR(j->axis[k], at(o, "axis", k), 1e-12);
        }
    }
    int i = 0;
    cJSON_ArrayForEach(o, springs) {
        const xtendon *t = &m.tendon[i++];
        CHECK(!strcmp(t->name, str(o, "name")));
        EXACT(t->k, num(o, "k_N_per_m"));
        EXACT(t->c, num(o, "c_Ns_per_m"));
        EXACT(t->rest, num(o, "rest_length_m"));
        for (int e = 0; e < 2; e++) {
            const xsite *s = site_named(&m, t->site[e]);
            REQUIRE(s);
            CHECK(!strcmp(m.body[s->body].name, str(o, e ? "body2" : "body1")));
            for (int k = 0; k < 3; k++)
                SAME_POS(s->p[k], at(o, e ? "anchor2_m" : "anchor1_m", k));
        }
    }
    cJSON_ArrayForEach(o, geoms) { /* the dump's k-th shape of a body is the XML's k-th geom of it */
        int before = 0, found = -1;
        const cJSON *p;
        cJSON_ArrayForEach(p, geoms) {
            if (p == o)
                break;
            before += !strcmp(str(p, "body"), str(o, "body"));
        }
        for (int h = 0; h < m.ngeom && found < 0; h++)
            if (!strcmp(m.body[m.geom[h].body].name, str(o, "body")) && before-- == 0)
                found = h;
        REQUIRE(found >= 0);
        const xgeom *g = &m.geom[found];
        CHECK(!strcmp(g->type, str(o, "type")) && !strcmp(g->cls, "foot"));
        int n = !strcmp(g->type, "box") ? 3 : 1;
        for (int k = 0; k < n; k++) /* MuJoCo's box size is half the lengths */
            EXACT((n == 3 ? 2 : 1) * g->size[k], at(o, "size_m", k));
        for (int k = 0; k < 3; k++)
            SAME_POS(g->p[k], at(o, "pos_m", k));
    }
    cJSON_Delete(dump);
    fs_mjcf_free(&out);
    fs_scenario_free(&sc);
}

static void biomimetic_matches_the_dump(void) { check_against_dump("scenarios/feet/biomimetic.ini", 12, 15); }
static void flat_matches_the_dump(void) { check_against_dump("scenarios/feet/flat.ini", 1, 0); }

/* ---- a scenario against the ODE world built for it --------------------------------------------- */

/* Masses and poses as ODE holds them at the start; tendons at their anchors. */
static void check_against_sim(const fs_scenario *sc, const xmodel *m)
{
    static fs_sim sim;
    fs_error err;
    fs_sim_options opts = {.with_ground = 1, .keep_robot_body = 1}; /* as the export builds it */
    REQUIRE(fs_sim_build(&sim, sc, &opts, &err) == FS_OK);
    for (int i = 0; i < sim.geom->nbodies; i++) {
        int b = body_named(m, sim.geom->body[i].name);
        REQUIRE(b >= 0);
        dMass mass;
        dBodyGetMass(sim.body[i], &mass);
        EXACT(m->body[b].mass, mass.mass);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                EXACT(m->body[b].I[3 * r + c], mass.I[4 * r + c]);
        for (int k = 0; k < 3; k++)
            SAME_POS(m->body[b].p[k], dBodyGetPosition(sim.body[i])[k]);
    }
    for (int i = 0; i < sim.geom->nsprings + sim.has_achilles; i++) {
        const fs_spring *s = i < sim.geom->nsprings ? &sim.spring[i] : &sim.achilles;
        const xtendon *t = &m->tendon[i];
        CHECK(!strcmp(t->name, i < sim.geom->nsprings ? sim.geom->spring[i].name : "achilles"));
        EXACT(t->k, s->k);
        EXACT(t->c, s->c);
        EXACT(t->rest, s->rest);
        double p[2][3];
        fs_spring_anchors(s, p[0], p[1]);
        for (int e = 0; e < 2; e++) {
            const xsite *x = site_named(m, t->site[e]);
            REQUIRE(x);
            for (int k = 0; k < 3; k++)
                SAME_POS(x->p[k], p[e][k]);
        }
    }
    CHECK(m->ntendon == sim.geom->nsprings + sim.has_achilles);
    const double g = sc->def.gravity_m_per_s2;
    for (int k = 0; k < 3; k++)
        EXACT(m->gravity[k], g * sim.down[k]);
    EXACT(m->timestep, sc->def.step_s);
    int robot = body_named(m, "robot");
    CHECK((robot >= 0) == (sim.robot != NULL));
    if (sim.robot) {
        EXACT(m->body[robot].mass, sc->def.robot.mass_kg);
        for (int k = 0; k < 3; k++)
            SAME_POS(m->body[robot].p[k], dBodyGetPosition(sim.robot)[k]);
        /* the robot is the root: free, or on the carriage's vertical slide */
        CHECK(m->body[robot].parent < 0);
        CHECK(sc->def.robot.mount == FS_ROBOT_VERTICAL ? m->body[robot].slide && !m->body[robot].free
                                                       : m->body[robot].free);
        /* the ankle: a hinge to the robot, or welded to it */
        const xjoint *j = joint_named(m, "robot_ankle");
        CHECK((j != NULL) == (sc->def.robot.joint == FS_ROBOT_ACHILLES));
    }
    int load = body_named(m, "load");
    CHECK((load >= 0) == (sc->def.load_kg > 0));
    if (load >= 0) {
        EXACT(m->body[load].mass, sc->def.load_kg);
        CHECK(!strcmp(m->body[m->body[load].parent].name, sim.geom->body[sim.geom->ankle_body].name));
        double a[3];
        fs_sim_ankle(&sim, a);
        for (int k = 0; k < 3; k++)
            SAME_POS(m->body[load].p[k], a[k]);
    }
    fs_sim_destroy(&sim);
}

static void static_load_scenario(void)
{
    static fs_scenario sc;
    static xmodel m;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_mjcf out;
    export_scenario(&sc, 1, &out, &m);
    check_against_sim(&sc, &m);
    /* the flat terrain: one plane through z = 0, facing up */
    int planes = 0;
    for (int i = 0; i < m.ngeom; i++)
        if (m.geom[i].body < 0) {
            CHECK(!strcmp(m.geom[i].type, "plane") && !strcmp(m.geom[i].cls, "ground"));
            CHECK(m.geom[i].p[0] == 0 && m.geom[i].p[1] == 0 && m.geom[i].p[2] == 0);
            planes++;
        }
    CHECK(planes == 1 && !out.hfield && !m.hfield_file[0]);
    fs_mjcf_free(&out);
    fs_scenario_free(&sc);
}

/* A free robot welded to the talus, tilted gravity, and the rig: a robot on the vertical slide. */
static void robot_scenarios(void)
{
    const char *files[] = {"scenarios/landing_trial.ini", "scenarios/tilt10.ini", "scenarios/landing_trial.ini"};
    const char *rig[] = {"robot.design=robots/rig.ini"};
    for (int f = 0; f < 3; f++) {
        static fs_scenario sc;
        static xmodel m;
        fs_error err;
        REQUIRE(fs_scenario_load(files[f], rig, f == 2, &sc, &err) == FS_OK);
        REQUIRE(f < 2 || sc.def.robot.mount == FS_ROBOT_VERTICAL);
        fs_mjcf out;
        export_scenario(&sc, 1, &out, &m);
        check_against_sim(&sc, &m);
        fs_mjcf_free(&out);
        fs_scenario_free(&sc);
    }
}

/* The walking machine: robot on a vertical slide, ankle hinge and Achilles tendon, a heightfield
 * whose file holds the lattice scaled to [0, 1] of its height range, row 0 at the smallest y. */
static void walking_heightfield(void)
{
    static fs_scenario sc;
    static xmodel m;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/walking.ini", NULL, 0, &sc, &err) == FS_OK);
    fs_mjcf out;
    export_scenario(&sc, 1, &out, &m);
    check_against_sim(&sc, &m);
    const fs_terrain *t = &sc.terrain;
    REQUIRE(fs_terrain_is_heightfield(t) && out.hfield);
    CHECK(!strcmp(m.hfield_file, "x.hfield.bin"));
    int32_t dims[2];
    memcpy(dims, out.hfield, sizeof dims);
    CHECK(dims[0] == t->ny && dims[1] == t->nx);
    REQUIRE(out.hfield_len == 8 + 4 * (size_t)t->nx * t->ny);
    double range = t->zmax - t->zmin;
    EXACT(m.hfield_size[2], range);
    int found = 0;
    for (int i = 0; i < m.ngeom; i++) {
        const xgeom *g = &m.geom[i];
        if (g->body >= 0 || strcmp(g->type, "hfield"))
            continue;
        found++;
        /* the lattice's corners and lowest sample where the geom puts them */
        SAME_POS(g->p[0] - m.hfield_size[0], t->x0);
        SAME_POS(g->p[1] - m.hfield_size[1], t->y0);
        SAME_POS(g->p[0] + m.hfield_size[0], t->x0 + (t->nx - 1) * t->dx);
        SAME_POS(g->p[1] + m.hfield_size[1], t->y0 + (t->ny - 1) * t->dx);
        EXACT(g->p[2], t->zmin);
    }
    CHECK(found == 1);
    /* every sample within float32 rounding (2^-24 of the range) */
    double worst = 0;
    for (size_t k = 0; k < (size_t)t->nx * t->ny; k++) {
        float v;
        memcpy(&v, out.hfield + 8 + 4 * k, 4);
        worst = fmax(worst, fabs(t->zmin + v * range - t->z[k]));
    }
    CHECK(worst <= range * 0x1p-24);
    fs_mjcf_free(&out);
    fs_scenario_free(&sc);
}

/* A hinge that closes a loop through the joints (export_fixture.h) becomes two connect equalities
 * on its axis, and the body it no longer holds (phalanx5) is a free root of its own. */
static void loop_through_a_joint(void)
{
    static fs_scenario sc;
    static xmodel m;
    fs_error err;
    REQUIRE(fs_scenario_for_design("scenarios/feet/biomimetic.ini", NULL, 0, &sc, &err) == FS_OK);
    const fs_hinge_geom *h = fs_fixture_make_loop(&sc);
    REQUIRE(h);
    fs_mjcf out;
    export_scenario(&sc, 0, &out, &m);
    CHECK(m.neq == 2);
    for (int i = 0; i < m.neq && i < 2; i++) {
        const xeq *q = &m.eq[i];
        CHECK(!strcmp(q->kind, "connect") && !strcmp(q->body1, "talus") && !strcmp(q->body2, "metatarsal4"));
        /* anchor in body1's frame: 5 mm either side of the hinge's anchor along its axis */
        int b = body_named(&m, "talus");
        REQUIRE(b >= 0);
        double w[3];
        to_world(&m.body[b], q->anchor, 1, w);
        double s = i == 0 ? -0.005 : 0.005;
        fs_vec3 e = fs_add(h->anchor, fs_scale(h->axis, s));
        SAME_POS(w[0], e.x);
        SAME_POS(w[1], e.y);
        SAME_POS(w[2], e.z);
    }
    int ph5 = body_named(&m, "phalanx5");
    REQUIRE(ph5 >= 0);
    CHECK(m.body[ph5].parent < 0 && m.body[ph5].free);
    CHECK(joint_named(&m, "loop") == NULL); /* not a tree joint */
    fs_mjcf_free(&out);
    fs_scenario_free(&sc);
}

/* Names with XML's special characters are escaped, and the file is written whole. */
static void writes_the_files(void)
{
    static fs_scenario sc;
    fs_error err;
    char dir[] = "/tmp/fs_export_XXXXXX";
    REQUIRE(mkdtemp(dir));
    char path[256], hpath[256];
    snprintf(path, sizeof path, "%s/a&b.xml", dir);
    REQUIRE(fs_scenario_load("scenarios/walking.ini", NULL, 0, &sc, &err) == FS_OK);
    CHECK(fs_mjcf_write(&sc, 1, path, &err) == FS_OK);
    fs_mjcf_hfield_path(path, hpath, sizeof hpath);
    FILE *f = fopen(path, "rb");
    REQUIRE(f);
    static char buf[1 << 20];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    static xmodel m;
    read_model(&m, buf, n);
    CHECK(!strcmp(m.hfield_file, "a&b.hfield.bin")); /* read back through the escaping */
    CHECK(strstr(buf, "a&amp;b.hfield.bin") != NULL);
    f = fopen(hpath, "rb");
    CHECK(f != NULL);
    if (f)
        fclose(f);
    remove(hpath);
    remove(path);
    rmdir(dir);
    fs_scenario_free(&sc);
}

FS_TEST_MAIN(TEST(biomimetic_matches_the_dump), TEST(flat_matches_the_dump), TEST(static_load_scenario),
             TEST(robot_scenarios), TEST(walking_heightfield), TEST(loop_through_a_joint), TEST(writes_the_files))
