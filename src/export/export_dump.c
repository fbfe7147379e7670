/* export_dump.c: a scenario's model (fs_model.h) as JSON, `footsim model --json`: read from the
 * model, not from an ODE world, in SI units and world coordinates at the design pose. */

#include "footsim/export/fs_export.h"

#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_model.h"

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

static const char *body_name(const fs_model *m, int b) { return b >= 0 && b <= m->nbodies ? m->body[b].name : "world"; }

static cJSON *bodies_json(const fs_model *m)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < m->nbodies; i++) {
        const fs_model_body *b = &m->body[i];
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", b->name) != NULL;
        ok &= cJSON_AddNumberToObject(o, "mass_kg", b->mass_kg) != NULL;
        ok &= fs_json_put(o, "inertia_kgm2", vec(b->inertia_kg_m2, 9));
        ok &= fs_json_put(o, "pos_m", vec(b->pos_m, 3));
        ok &= fs_json_put(o, "quat_wxyz", vec(m->q0_wxyz, 4));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *joints_json(const fs_model *m)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < m->nhinges; i++) {
        const fs_model_hinge *h = &m->hinge[i];
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", m->geom->hinge[i].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "type", "hinge") != NULL;
        ok &= cJSON_AddStringToObject(o, "body1", body_name(m, h->body1)) != NULL;
        ok &= cJSON_AddStringToObject(o, "body2", body_name(m, h->body2)) != NULL;
        ok &= fs_json_put(o, "anchor_m", vec(h->anchor_m, 3));
        ok &= fs_json_put(o, "axis", vec(h->axis, 3));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *springs_json(const fs_model *m)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < m->nsprings; i++) {
        const fs_model_spring *s = &m->spring[i];
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", s->name) != NULL;
        ok &= cJSON_AddStringToObject(o, "body1", body_name(m, s->body1)) != NULL;
        ok &= cJSON_AddStringToObject(o, "body2", body_name(m, s->body2)) != NULL;
        ok &= fs_json_put(o, "anchor1_m", vec(s->p1_m, 3));
        ok &= fs_json_put(o, "anchor2_m", vec(s->p2_m, 3));
        ok &= cJSON_AddNumberToObject(o, "k_N_per_m", s->k_N_per_m) != NULL;
        ok &= cJSON_AddNumberToObject(o, "c_Ns_per_m", s->c_Ns_per_m) != NULL;
        ok &= cJSON_AddNumberToObject(o, "rest_length_m", s->rest_length_m) != NULL;
        if (!fs_spring_law_is_linear(&s->law)) { /* k above: the law's stiffness at the rest length */
            ok &= cJSON_AddStringToObject(o, "law", fs_spring_law_name(&s->law)) != NULL;
            ok &= cJSON_AddBoolToObject(o, "tension_only", s->law.tension_only) != NULL;
        }
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

static cJSON *geoms_json(const fs_model *m)
{
    cJSON *arr = cJSON_CreateArray();
    int ok = arr != NULL;
    for (int i = 0; i < m->nshapes; i++) {
        const fs_model_shape *s = &m->shape[i];
        const double *R = m->R0, *c = m->body[s->body].pos_m, *d = s->offset_m;
        double p[3];
        for (int r = 0; r < 3; r++) /* the shape's centre: its body's, and its offset turned with the body */
            p[r] = c[r] + (R[3 * r] * d[0] + R[3 * r + 1] * d[1] + R[3 * r + 2] * d[2]);
        int sphere = s->kind == FS_MODEL_SPHERE;
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "body", body_name(m, s->body)) != NULL;
        ok &= cJSON_AddStringToObject(o, "type", sphere ? "sphere" : "box") != NULL;
        ok &= fs_json_put(o, "size_m", sphere ? vec(&s->radius_m, 1) : vec(s->size_m, 3));
        ok &= fs_json_put(o, "pos_m", vec(p, 3));
        ok &= fs_json_put(o, "quat_wxyz", vec(m->q0_wxyz, 4));
        ok &= fs_json_put(arr, NULL, o);
    }
    return complete(arr, ok);
}

cJSON *fs_model_json(const fs_scenario *sc, fs_error *err)
{
    fs_model *m;
    fs_sim_options opts = {.with_ground = 0, .hold_rear_foot = 0};
    if (fs_model_compile(sc, &opts, &m, err) != FS_OK)
        return NULL;
    cJSON *root = cJSON_CreateObject();
    int ok = root != NULL;
    ok &= cJSON_AddStringToObject(root, "design", sc->def.design_path) != NULL;
    ok &= cJSON_AddStringToObject(root, "foot", sc->geom.kind == FS_FOOT_FLAT ? "flat" : "biomimetic") != NULL;
    ok &= cJSON_AddStringToObject(root, "frame", "x forward, y left, z up; ground z = 0") != NULL;
    ok &= cJSON_AddNumberToObject(root, "total_mass_kg", m->geom->total_mass_kg) != NULL;
    double ankle[3] = {sc->geom.ankle.x, sc->geom.ankle.y, sc->geom.ankle.z};
    ok &= fs_json_put(root, "ankle_m", vec(ankle, 3));
    if (m->robot_merged) /* a rigid, free robot is part of that body: its mass and inertia are in it */
        ok &= cJSON_AddStringToObject(root, "robot_merged_into", m->geom->body[m->geom->ankle_body].name) != NULL;
    ok &= fs_json_put(root, "bodies", bodies_json(m));
    ok &= fs_json_put(root, "joints", joints_json(m));
    ok &= fs_json_put(root, "springs", springs_json(m));
    ok &= fs_json_put(root, "geoms", geoms_json(m));
    fs_model_free(m);
    if (!complete(root, ok))
        fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the model's JSON", sc->path);
    return ok ? root : NULL;
}
