/* sim_scene.c: the simulation as plain data for anything that draws it (fs_scene.h). */
#include "sim_internal.h"
#include "sim_soil.h"

#include "footsim/base/fs_path.h"

#include <math.h>
#include <string.h>

_Static_assert((int)FS_SCENE_MAX_SHAPES >= (int)FS_MAX_SHAPES && (int)FS_SCENE_MAX_BODIES >= (int)FS_MAX_BODIES &&
                   (int)FS_SCENE_MAX_SEGMENTS >= (int)FS_MAX_SPRINGS,
               "a scene holds every shape, body and spring of the largest geometry (a biped's; test_robot_biped "
               "checks its links fit too)");

static void copy3(double dst[3], const dReal *src)
{
    for (int k = 0; k < 3; k++)
        dst[k] = src[k];
}

/* A link of body b from hinge from's anchor to hinge to's anchor or to shape's centre. */
static void add_link(fs_scene *scene, dJointID from, int b, dGeomID shape, dJointID to)
{
    if (scene->nlinks >= FS_SCENE_MAX_SEGMENTS)
        return;
    fs_scene_segment *seg = &scene->link[scene->nlinks++];
    dVector3 a;
    dJointGetHingeAnchor(from, a);
    copy3(seg->p1, a);
    if (to) {
        dJointGetHingeAnchor(to, a);
        copy3(seg->p2, a);
    } else {
        copy3(seg->p2, dGeomGetPosition(shape));
    }
    seg->body1 = seg->body2 = b;
}

/* The robot as the uniform box of its mass and principal moments (edges sqrt(6 (Ij + Ik - Ii) / m)),
 * cut off at the ankle's height so that it stands on the foot instead of running through it. */
static void robot_box(const fs_sim *sim, fs_scene_shape *box)
{
    const fs_robot_def *rd = &sim->sc->def.robot;
    double I[3], e[3];
    fs_robot_inertia(rd, I);
    for (int i = 0; i < 3; i++)
        e[i] = sqrt(fmax(6 * (I[(i + 1) % 3] + I[(i + 2) % 3] - I[i]) / rd->mass_kg, 0));
    double lo = fmax(-0.5 * e[2], -rd->com_height_m), hi = 0.5 * e[2];
    /* its own body, or the ankle body it is merged into (the frames are alike), at its centre */
    dBodyID b = fs_sim_robot_body(sim);
    const double *l = sim->robot_merged ? sim->robot_local : (const double[3]){0, 0, 0};
    const dReal *q = dBodyGetQuaternion(b);
    dVector3 centre;
    dBodyGetRelPointPos(b, l[0], l[1], l[2] + 0.5 * (lo + hi), centre);
    *box = (fs_scene_shape){FS_SHAPE_BOX, {e[0], e[1], hi - lo}, {centre[0], centre[1], centre[2]},
                            {q[0], q[1], q[2], q[3]}, -1};
}

/* The plane or steps sampled on the grid scene_ground (sim_build.c) set out, once: the first
 * scene asks for it. A heightfield's grid is its own samples. With a soil, its surface now, at every
 * scene: the prints and the foot pressing them (fs_sim_soil.h), and their sinkage. */
static void sample_ground(const fs_sim *sim)
{
    fs_ground_grid *grid = sim->ground_grid;
    if (!grid || (grid->sampled && !sim->soil))
        return;
    const fs_scene_ground *g = &sim->scene_ground;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            double x = g->x0 + i * g->dx, y = g->y0 + j * g->dy;
            grid->z[j * g->nx + i] = sim->soil ? fs_sim_ground_surface(sim, x, y) : fs_terrain_height(&sim->sc->terrain, x, y);
            if (sim->soil) /* and how deep that is below the undisturbed soil (at most the layer) */
                grid->z[(size_t)g->nx * g->ny + (size_t)(j * g->nx + i)] =
                    fmin(sim->soil->g.d.depth_m, fmax(0, fs_soil_grid_undisturbed(&sim->soil->g, x, y) - grid->z[j * g->nx + i]));
        }
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
    if (g->kind == FS_FOOT_FLAT) /* the flat sole, whatever design file gave the foot */
        snprintf(scene->design, sizeof scene->design, "%s", scene->foot);
    else
        fs_path_stem(sim->sc->def.design_path, scene->design, sizeof scene->design);
    fs_path_stem(sim->sc->def.robot_path, scene->robot_file, sizeof scene->robot_file);
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
    /* links: each body's bars from the hinge it hangs on (its proximal one) to every point it
     * carries on (its distal hinges; its contact spheres when it has none), so each chain's loop
     * reads as a linkage; a body no hinge hangs from (the root) joins its distal hinges to its
     * spheres */
    for (int b = 0; b < g->nbodies; b++) {
        int proximal = -1, ndistal = 0;
        for (int i = 0; i < g->nhinges; i++) {
            proximal = g->hinge[i].body2 == b ? i : proximal;
            ndistal += g->hinge[i].body1 == b;
        }
        for (int i = 0; i < g->nhinges; i++) {
            if (g->hinge[i].body1 == b && proximal >= 0)
                add_link(scene, sim->hinge[proximal], b, NULL, sim->hinge[i]);
            for (int k = 0; k < sim->nshapes && g->hinge[i].body2 == b && ndistal == 0; k++)
                if (dGeomGetBody(sim->shape[k]) == sim->body[b])
                    add_link(scene, sim->hinge[i], b, sim->shape[k], NULL);
            for (int k = 0; k < sim->nshapes && g->hinge[i].body1 == b && proximal < 0; k++)
                if (dGeomGetBody(sim->shape[k]) == sim->body[b] && dGeomGetClass(sim->shape[k]) == dSphereClass)
                    add_link(scene, sim->hinge[i], b, sim->shape[k], NULL);
        }
        /* a root that carries no shape (a biped's pelvis): a bar from its first distal hinge to each other */
        int first = -1, shaped = 0;
        for (int k = 0; k < sim->nshapes; k++)
            shaped |= dGeomGetBody(sim->shape[k]) == sim->body[b];
        for (int i = 0; i < g->nhinges && proximal < 0 && !shaped; i++)
            if (g->hinge[i].body1 == b && first < 0)
                first = i;
            else if (g->hinge[i].body1 == b)
                add_link(scene, sim->hinge[first], b, NULL, sim->hinge[i]);
    }
    for (int i = 0; i < g->nsprings && i < FS_SCENE_MAX_SEGMENTS; i++) {
        fs_scene_segment *seg = &scene->spring[scene->nsprings++];
        seg->body1 = g->spring[i].body1;
        seg->body2 = g->spring[i].body2;
        fs_spring_anchors(&sim->spring[i], seg->p1, seg->p2);
        seg->force_N = fs_spring_measure(&sim->spring[i]).force_N;
    }
    for (int i = 0; i < sim->contacts_now && i < FS_SCENE_MAX_CONTACTS; i++) {
        fs_scene_contact *c = &scene->contact[scene->ncontacts++];
        memcpy(c->pos, sim->contact_pos[i], sizeof c->pos);
        copy3(c->force_N, sim->feedback[i].f1);
    }
    fs_sim_ankle(sim, scene->ankle);
    scene->ankle_body = g->ankle_body;
    for (int b = 0; b < g->nbodies && b < FS_SCENE_MAX_BODIES; b++) {
        copy3(scene->body[b].pos, dBodyGetPosition(sim->body[b]));
        const dReal *q = dBodyGetQuaternion(sim->body[b]);
        for (int k = 0; k < 4; k++)
            scene->body[b].quat[k] = q[k];
        scene->nbodies = b + 1;
    }
    if (sim->robot || sim->robot_merged)
        robot_box(sim, &scene->robot), scene->has_robot = 1;
    for (int k = 0; k < 3; k++)
        scene->load_N[k] = fs_sim_load_now_N(sim) * sim->down[k];
}
