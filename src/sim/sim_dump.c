/* sim_dump.c: the model as ODE holds it, as JSON. */

#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_sim.h"

#include <cJSON.h>
#include <string.h>

static cJSON *vec(const double *v, int n) { return cJSON_CreateDoubleArray(v, n); }

/* tree if every put into it succeeded (ok), else NULL (the tree deleted): out of memory */
static cJSON *complete(cJSON *tree, int ok)
{
    if (ok)
        return tree;
    cJSON_Delete(tree);
    return NULL;
}

static const char *body_name(const fs_sim *sim, dBodyID b)
{
    for (int i = 0; i < sim->geom->nbodies; i++)
        if (sim->body[i] == b)
            return sim->geom->body[i].name;
    return "world";
}

static cJSON *bodies_json(const fs_sim *sim)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < sim->geom->nbodies; i++) {
        dBodyID b = sim->body[i];
        dMass m;
        dBodyGetMass(b, &m);
        double I[9], p[3], q[4];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                I[3 * r + c] = m.I[4 * r + c];
        memcpy(p, dBodyGetPosition(b), sizeof p);
        memcpy(q, dBodyGetQuaternion(b), sizeof q);
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", sim->geom->body[i].name) != NULL;
        ok &= cJSON_AddNumberToObject(o, "mass_kg", m.mass) != NULL;
        ok &= fs_json_put(o, "inertia_kgm2", vec(I, 9));
        ok &= fs_json_put(o, "pos_m", vec(p, 3));
        ok &= fs_json_put(o, "quat_wxyz", vec(q, 4));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *joints_json(const fs_sim *sim)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < sim->geom->nhinges; i++) {
        dJointID j = sim->hinge[i];
        dVector3 a, x;
        dJointGetHingeAnchor(j, a);
        dJointGetHingeAxis(j, x);
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", sim->geom->hinge[i].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "type", "hinge") != NULL;
        ok &= cJSON_AddStringToObject(o, "body1", body_name(sim, dJointGetBody(j, 0))) != NULL;
        ok &= cJSON_AddStringToObject(o, "body2", body_name(sim, dJointGetBody(j, 1))) != NULL;
        ok &= fs_json_put(o, "anchor_m", vec(a, 3));
        ok &= fs_json_put(o, "axis", vec(x, 3));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *springs_json(const fs_sim *sim)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < sim->geom->nsprings; i++) {
        const fs_spring *s = &sim->spring[i];
        double p1[3], p2[3];
        fs_spring_anchors(s, p1, p2);
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", sim->geom->spring[i].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "body1", body_name(sim, s->body1)) != NULL;
        ok &= cJSON_AddStringToObject(o, "body2", s->body2 ? body_name(sim, s->body2) : "world") != NULL;
        ok &= fs_json_put(o, "anchor1_m", vec(p1, 3));
        ok &= fs_json_put(o, "anchor2_m", vec(p2, 3));
        ok &= cJSON_AddNumberToObject(o, "k_N_per_m", s->k) != NULL;
        ok &= cJSON_AddNumberToObject(o, "c_Ns_per_m", s->c) != NULL;
        ok &= cJSON_AddNumberToObject(o, "rest_length_m", s->rest) != NULL;
        if (!fs_spring_law_is_linear(&s->law)) { /* k above: the law's stiffness at the rest length */
            ok &= cJSON_AddStringToObject(o, "law", fs_spring_law_name(&s->law)) != NULL;
            ok &= cJSON_AddBoolToObject(o, "tension_only", s->law.tension_only) != NULL;
        }
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *geoms_json(const fs_sim *sim)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < sim->nshapes; i++) {
        dGeomID g = sim->shape[i];
        double size[3], p[3], q[4];
        int n;
        const char *type;
        if (dGeomGetClass(g) == dSphereClass) {
            type = "sphere";
            size[0] = dGeomSphereGetRadius(g);
            n = 1;
        } else {
            dVector3 l;
            dGeomBoxGetLengths(g, l);
            memcpy(size, l, sizeof size);
            type = "box";
            n = 3;
        }
        dQuaternion qq;
        memcpy(p, dGeomGetPosition(g), sizeof p);
        dGeomGetQuaternion(g, qq);
        memcpy(q, qq, sizeof q);
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "body", body_name(sim, dGeomGetBody(g))) != NULL;
        ok &= cJSON_AddStringToObject(o, "type", type) != NULL;
        ok &= fs_json_put(o, "size_m", vec(size, n));
        ok &= fs_json_put(o, "pos_m", vec(p, 3));
        ok &= fs_json_put(o, "quat_wxyz", vec(q, 4));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

cJSON *fs_model_json(const fs_scenario *sc, fs_error *err)
{
    fs_sim sim;
    fs_sim_options opts = {.with_ground = 0, .hold_rear_foot = 0};
    if (fs_sim_build(&sim, sc, &opts, err) != FS_OK)
        return NULL;
    cJSON *root = cJSON_CreateObject();
    int ok = root != NULL;
    ok &= cJSON_AddStringToObject(root, "design", sc->def.design_path) != NULL;
    ok &= cJSON_AddStringToObject(root, "foot", sc->geom.kind == FS_FOOT_FLAT ? "flat" : "biomimetic") != NULL;
    ok &= cJSON_AddStringToObject(root, "frame", "x forward, y left, z up; ground z = 0") != NULL;
    ok &= cJSON_AddNumberToObject(root, "total_mass_kg", sim.geom->total_mass_kg) != NULL;
    double ankle[3] = {sc->geom.ankle.x, sc->geom.ankle.y, sc->geom.ankle.z};
    ok &= fs_json_put(root, "ankle_m", vec(ankle, 3));
    if (sim.robot_merged) /* a rigid, free robot is part of that body: its mass and inertia are in it */
        ok &= cJSON_AddStringToObject(root, "robot_merged_into", sim.geom->body[sim.geom->ankle_body].name) != NULL;
    ok &= fs_json_put(root, "bodies", bodies_json(&sim));
    ok &= fs_json_put(root, "joints", joints_json(&sim));
    ok &= fs_json_put(root, "springs", springs_json(&sim));
    ok &= fs_json_put(root, "geoms", geoms_json(&sim));
    fs_sim_destroy(&sim);
    if (!complete(root, ok))
        fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the model's JSON", sc->path);
    return ok ? root : NULL;
}
