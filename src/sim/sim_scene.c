/* sim_scene.c: the simulation as plain data for anything that draws it (fs_scene.h). */
#include "sim_internal.h"

#include <string.h>

static void copy3(double dst[3], const dReal *src)
{
    for (int k = 0; k < 3; k++)
        dst[k] = src[k];
}

/* The plane or steps sampled on the grid scene_ground (sim_build.c) set out, once: the first
 * scene asks for it. A heightfield's grid is its own samples. */
static void sample_ground(const fs_sim *sim)
{
    fs_ground_grid *grid = sim->ground_grid;
    if (!grid || grid->sampled)
        return;
    const fs_scene_ground *g = &sim->scene_ground;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++)
            grid->z[j * g->nx + i] = fs_terrain_height(&sim->sc->terrain, g->x0 + i * g->dx, g->y0 + j * g->dy);
    grid->sampled = 1;
}

void fs_sim_scene(const fs_sim *sim, fs_scene *scene)
{
    const fs_foot_geom *g = sim->geom;
    memset(scene, 0, sizeof *scene);
    scene->time_s = sim->time_s;
    scene->scenario = sim->sc->name;
    scene->foot = g->kind == FS_FOOT_FLAT ? "flat" : "biomimetic";
    scene->terrain = sim->sc->terrain.name;
    sample_ground(sim);
    scene->ground = sim->scene_ground;
    for (int i = 0; i < sim->nshapes && scene->nshapes < FS_SCENE_MAX_SHAPES; i++) {
        dGeomID geom = sim->shape[i];
        fs_scene_shape *s = &scene->shape[scene->nshapes++];
        if (dGeomGetClass(geom) == dSphereClass) {
            s->type = FS_SHAPE_SPHERE;
            s->size[0] = dGeomSphereGetRadius(geom);
        } else {
            dVector3 l;
            dGeomBoxGetLengths(geom, l);
            s->type = FS_SHAPE_BOX;
            copy3(s->size, l);
        }
        copy3(s->pos, dGeomGetPosition(geom));
        dQuaternion q;
        dGeomGetQuaternion(geom, q);
        for (int k = 0; k < 4; k++)
            s->quat[k] = q[k];
        for (int b = 0; b < g->nbodies; b++)
            if (sim->body[b] == dGeomGetBody(geom))
                s->body = b;
    }
    /* links: each hinge to the next along the chain, drawn as the bodies' skeleton */
    for (int i = 0; i < g->nhinges && scene->nlinks < FS_SCENE_MAX_SEGMENTS; i++) {
        dVector3 a;
        dJointGetHingeAnchor(sim->hinge[i], a);
        const dReal *c = dBodyGetPosition(sim->body[g->hinge[i].body2]);
        fs_scene_segment *seg = &scene->link[scene->nlinks++];
        copy3(seg->p1, a);
        copy3(seg->p2, c);
    }
    for (int i = 0; i < g->nsprings && i < FS_SCENE_MAX_SEGMENTS; i++) {
        fs_scene_segment *seg = &scene->spring[scene->nsprings++];
        fs_spring_anchors(&sim->spring[i], seg->p1, seg->p2);
        seg->force_N = fs_spring_measure(&sim->spring[i]).force_N;
    }
    for (int i = 0; i < sim->contacts_now && i < FS_SCENE_MAX_CONTACTS; i++) {
        fs_scene_contact *c = &scene->contact[scene->ncontacts++];
        memcpy(c->pos, sim->contact_pos[i], sizeof c->pos);
        copy3(c->force_N, sim->feedback[i].f1);
    }
    fs_sim_ankle(sim, scene->ankle);
    if ((sim->robot || sim->robot_merged) && scene->nlinks < FS_SCENE_MAX_SEGMENTS) {
        /* the robot as a line from the ankle to its centre of mass */
        fs_scene_segment *seg = &scene->link[scene->nlinks++];
        memcpy(seg->p1, scene->ankle, sizeof seg->p1);
        fs_sim_robot_com(sim, seg->p2, NULL);
    }
    for (int k = 0; k < 3; k++)
        scene->load_N[k] = fs_sim_load_now_N(sim) * sim->down[k];
}
