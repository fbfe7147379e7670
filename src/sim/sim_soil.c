/* sim_soil.c: the feet's shapes for the soil, and the soil's forces put on the ODE bodies.
 *
 * Soil shapes (fs_soil_foot_shapes; docs/soil.md gives their sizes and areas): the flat sole is its
 * plate (a box); on the biomimetic foot every link is a capsule of the radius the design gives it
 * ([soil_shapes], by default its contact spheres' radius, the talus half the links' width;
 * fs_body_geom.soil_radius_m): the heel a capsule between its two heel spheres, each metatarsal from
 * its midfoot joint to its ball sphere, each phalanx from its MTP joint to its toe sphere, the talus
 * between its two joints. The contact spheres stay the shapes the rigid bedrock meets. */
#include "sim_soil.h"

#include "sim_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const fs_soil_grid *fs_sim_soil_grid(const fs_sim *sim) { return sim->soil ? &sim->soil->g : NULL; }

int fs_sim_soil_nodes(const fs_sim *sim, int foot) { return sim->soil ? sim->soil->foot_nodes[1 + foot] : 0; }

double fs_sim_soil_area(const fs_sim *sim, int foot) { return sim->soil ? sim->soil->foot_area_m2[1 + foot] : 0; }

int fs_sim_support(const fs_sim *sim) { return sim->contacts_now + (sim->soil ? sim->soil->foot_nodes[0] : 0); }

/* Over the nodes foot's shapes (-1: every foot's) carried in the last (sub)step: the deepest
 * reach below the undisturbed surface (never past the bedrock), and the slip accumulated on them
 * averaged by area (each node with its stride x stride cells). */
static void under_foot(const fs_sim *sim, int foot, double *deepest_m, double *mean_slip_m)
{
    const fs_soil_grid *g = &sim->soil->g;
    double deepest = 0, slip = 0, cells = 0;
    for (int t = 0; t < g->ntiles; t++) {
        const fs_soil_node *nd = g->pool + (size_t)t * FS_SOIL_TILE * FS_SOIL_TILE;
        int st = g->stride[g->slot_tile[t]], m = (FS_SOIL_TILE / st) * (FS_SOIL_TILE / st);
        for (int k = 0; k < m; k++) {
            const fs_soil_node *n = &nd[k];
            if (n->stamp != g->stamp || (foot >= 0 && g->shape[n->shape].foot != foot))
                continue;
            deepest = fmax(deepest, fmin(n->h0_m - n->zb_m, g->d.depth_m));
            slip += n->slip_m * st * st, cells += st * st;
        }
    }
    *deepest_m = deepest;
    *mean_slip_m = cells > 0 ? slip / cells : 0;
}

double fs_sim_soil_sinkage(const fs_sim *sim, int foot)
{
    double deep = 0, slip;
    if (sim->soil)
        under_foot(sim, foot, &deep, &slip);
    return deep;
}

double fs_sim_soil_slip(const fs_sim *sim, int foot)
{
    double deep, slip = 0;
    if (sim->soil)
        under_foot(sim, foot, &deep, &slip);
    return slip;
}

int fs_sim_soil_over(const fs_sim *sim, int foot)
{
    const fs_soil_grid *g = sim->soil ? &sim->soil->g : NULL;
    for (int s = 0; g && s < g->nshapes; s++) {
        double box[4], zmin;
        if (foot >= 0 && g->shape[s].foot != foot)
            continue;
        fs_soil_shape_box(&g->shape[s], &sim->soil->body[g->shape[s].body], box, &zmin);
        if (fs_soil_depth_over(&g->d, box[0], box[1]) > 0)
            return 1;
    }
    return 0;
}

double fs_sim_ground_surface(const fs_sim *sim, double x, double y)
{
    return sim->soil ? fs_soil_grid_surface(&sim->soil->g, x, y) : fs_terrain_height(&sim->sc->terrain, x, y);
}

static int foot_of(const fs_foot_geom *g, int body)
{
    for (int f = 0; g->nfeet > 1 && f < g->nfeet; f++)
        if (body >= g->foot[f].first_body && body < g->foot[f].first_body + g->foot[f].nbodies)
            return f;
    return g->nfeet > 1 ? -1 : 0;
}

/* The shapes being made: where they go, how many fit, and the bodies' centres (NULL: the design's origin). */
typedef struct shape_list { fs_soil_shape *s; int n, max; const fs_vec3 *com; } shape_list;

static fs_soil_shape *new_shape(shape_list *l, int kind, int body, int foot, const char *name, fs_vec3 at)
{
    if (l->n == l->max)
        return NULL;
    fs_soil_shape *s = &l->s[l->n++];
    memset(s, 0, sizeof *s);
    const fs_vec3 c = l->com ? l->com[body] : fs_v3(0, 0, 0);
    s->kind = kind;
    s->body = body;
    s->foot = foot;
    snprintf(s->name, sizeof s->name, "%s", name);
    s->a[0] = at.x - c.x, s->a[1] = at.y - c.y, s->a[2] = at.z - c.z;
    return s;
}

/* A capsule from design point p to q (radius r) on body i, in its frame (origin at its centre). */
static void add_capsule(shape_list *l, const fs_foot_geom *g, int body, fs_vec3 p, fs_vec3 q, double r, const char *name)
{
    fs_soil_shape *s = new_shape(l, FS_SOIL_CAPSULE, body, foot_of(g, body), name, p);
    if (!s)
        return;
    const fs_vec3 c = l->com ? l->com[body] : fs_v3(0, 0, 0);
    s->b[0] = q.x - c.x, s->b[1] = q.y - c.y, s->b[2] = q.z - c.z;
    s->radius_m = r;
    s->plan_area_m2 = 2 * r * hypot(q.x - p.x, q.y - p.y) + M_PI * r * r;
}

/* The anchors of the hinges joining body to another body of its foot, up to two. */
static int anchors(const fs_foot_geom *g, int body, fs_vec3 out[2], int as_distal_only)
{
    int n = 0;
    for (int h = 0; h < g->nhinges && n < 2; h++) {
        const fs_hinge_geom *j = &g->hinge[h];
        int other = j->body2 == body ? j->body1 : j->body1 == body && !as_distal_only ? j->body2 : -1;
        if (other >= 0 && foot_of(g, other) == foot_of(g, body) && foot_of(g, other) >= 0)
            out[n++] = j->anchor;
    }
    return n;
}

int fs_soil_foot_shapes(const fs_foot_geom *g, const fs_vec3 *com, fs_soil_shape *out, int max)
{
    shape_list l = {out, 0, max, com};
    for (int b = 0; b < g->nboxes; b++) {
        fs_soil_shape *s = new_shape(&l, FS_SOIL_BOX, g->box[b].body, foot_of(g, g->box[b].body), "sole", g->box[b].centre);
        if (!s)
            break;
        s->half[0] = 0.5 * g->box_size.x, s->half[1] = 0.5 * g->box_size.y, s->half[2] = 0.5 * g->box_size.z;
        s->R[0] = s->R[4] = s->R[8] = 1;
        s->plan_area_m2 = g->box_size.x * g->box_size.y;
    }
    for (int body = 0; body < g->nbodies; body++) {
        if (foot_of(g, body) < 0)
            continue;
        int has_box = 0, ns = 0, first = -1, last = -1;
        for (int b = 0; b < g->nboxes; b++)
            has_box |= g->box[b].body == body;
        for (int i = 0; i < g->nspheres; i++)
            if (g->sphere[i].body == body) {
                ns++;
                last = i;
                if (first < 0)
                    first = i;
            }
        if (has_box)
            continue;
        const double r = g->body[body].soil_radius_m; /* [soil_shapes], or the sphere's (fs_body_geom) */
        fs_vec3 a[2];
        if (ns >= 2) { /* the heel: across its spheres */
            add_capsule(&l, g, body, g->sphere[first].centre, g->sphere[last].centre, r, g->body[body].name);
        } else if (ns == 1) { /* a metatarsal or phalanx: from its proximal joint to its sphere */
            if (anchors(g, body, a, 1) >= 1)
                add_capsule(&l, g, body, a[0], g->sphere[first].centre, r, g->body[body].name);
            else
                add_capsule(&l, g, body, g->sphere[first].centre, g->sphere[first].centre, r, g->body[body].name);
        } else if (anchors(g, body, a, 0) == 2) { /* the talus: between its joints */
            add_capsule(&l, g, body, a[0], a[1], r, g->body[body].name);
        }
    }
    return l.n;
}

static void make_shapes(fs_sim *sim)
{
    fs_soil_grid *sg = &sim->soil->g;
    sg->nshapes = fs_soil_foot_shapes(sim->geom, sim->com, sg->shape, FS_SOIL_MAX_SHAPES);
}

static void read_bodies(fs_sim *sim)
{
    for (int i = 0; i < sim->geom->nbodies; i++) {
        fs_soil_body *b = &sim->soil->body[i];
        dBodyID id = sim->body[i];
        const dReal *p = dBodyGetPosition(id), *R = dBodyGetRotation(id), *v = dBodyGetLinearVel(id),
                    *w = dBodyGetAngularVel(id);
        for (int k = 0; k < 3; k++) {
            b->p[k] = p[k], b->v[k] = v[k], b->w[k] = w[k];
            for (int c = 0; c < 3; c++)
                b->R[3 * k + c] = R[4 * k + c];
        }
        dMass m;
        dBodyGetMass(id, &m);
        b->mass_kg = m.mass;
    }
}

fs_status fs_sim_soil_build(fs_sim *sim, fs_error *err)
{
    if (sim->sc->terrain.def.soil.model == FS_SOIL_NONE || !sim->ground)
        return FS_OK;
    sim->soil = calloc(1, sizeof *sim->soil);
    if (!sim->soil)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the soil", sim->sc->path);
    make_shapes(sim);
    /* each shape on the widest spacing that leaves [soil] nodes_across nodes across it (fs_soil_stride) */
    for (int s = 0; s < sim->soil->g.nshapes; s++) {
        fs_soil_shape *sh = &sim->soil->g.shape[s];
        double w = sh->kind == FS_SOIL_BOX ? 2 * fmin(sh->half[0], sh->half[1]) : 2 * sh->radius_m;
        sh->stride = fs_soil_stride(&sim->sc->terrain.def.soil, w);
    }
    read_bodies(sim);
    /* the pool sized for the tiles under the shapes at the start */
    double boxes[FS_SOIL_MAX_SHAPES][4];
    fs_soil_grid *g = &sim->soil->g;
    for (int s = 0; s < g->nshapes; s++) {
        double A[3], B[3], n[3];
        (void)n;
        const fs_soil_body *b = &sim->soil->body[g->shape[s].body];
        for (int r = 0; r < 3; r++) {
            A[r] = b->p[r] + b->R[3 * r] * g->shape[s].a[0] + b->R[3 * r + 1] * g->shape[s].a[1] + b->R[3 * r + 2] * g->shape[s].a[2];
            B[r] = b->p[r] + b->R[3 * r] * g->shape[s].b[0] + b->R[3 * r + 1] * g->shape[s].b[1] + b->R[3 * r + 2] * g->shape[s].b[2];
        }
        double reach = g->shape[s].kind == FS_SOIL_BOX
                           ? hypot(g->shape[s].half[0], g->shape[s].half[1])
                           : g->shape[s].radius_m;
        boxes[s][0] = fmin(A[0], B[0]) - reach, boxes[s][1] = fmax(A[0], B[0]) + reach;
        boxes[s][2] = fmin(A[1], B[1]) - reach, boxes[s][3] = fmax(A[1], B[1]) + reach;
    }
    fs_status st = fs_soil_grid_init(g, &sim->sc->terrain, (const double(*)[4])boxes, g->nshapes, err);
    if (st == FS_OK && sim->saved) /* an error-controlled step puts back what a rejected step did */
        st = fs_soil_grid_keep(g, err);
    return st;
}

/* The last step's per-foot results, into the save or back from it. */
static void exchange_feet(fs_sim_soil *so, int saving)
{
    if (saving) {
        memcpy(so->saved_force, so->foot_force, sizeof so->foot_force);
        memcpy(so->saved_nodes, so->foot_nodes, sizeof so->foot_nodes);
        memcpy(so->saved_area_m2, so->foot_area_m2, sizeof so->foot_area_m2);
    } else {
        memcpy(so->foot_force, so->saved_force, sizeof so->foot_force);
        memcpy(so->foot_nodes, so->saved_nodes, sizeof so->foot_nodes);
        memcpy(so->foot_area_m2, so->saved_area_m2, sizeof so->foot_area_m2);
    }
}

void fs_sim_soil_save(fs_sim *sim)
{
    if (!sim->soil)
        return;
    fs_soil_grid_mark(&sim->soil->g);
    exchange_feet(sim->soil, 1);
}

void fs_sim_soil_restore(fs_sim *sim)
{
    if (!sim->soil)
        return;
    fs_soil_grid_undo(&sim->soil->g);
    exchange_feet(sim->soil, 0);
}

void fs_sim_soil_destroy(fs_sim *sim)
{
    if (!sim->soil)
        return;
    fs_soil_grid_free(&sim->soil->g);
    free(sim->soil);
    sim->soil = NULL;
}

fs_status fs_sim_soil_apply(fs_sim *sim, double h, fs_error *err)
{
    fs_sim_soil *so = sim->soil;
    read_bodies(sim);
    fs_status st = fs_soil_grid_step(&so->g, so->body, h, err);
    if (st != FS_OK)
        return st;
    memset(so->foot_force, 0, sizeof so->foot_force);
    memset(so->foot_nodes, 0, sizeof so->foot_nodes);
    memset(so->foot_area_m2, 0, sizeof so->foot_area_m2);
    for (int s = 0; s < so->g.nshapes; s++) {
        if (!so->g.nodes[s])
            continue;
        const double *F = so->g.force[s], *M = so->g.torque[s];
        dBodyID b = sim->body[so->g.shape[s].body];
        dBodyAddForce(b, F[0], F[1], F[2]);
        dBodyAddTorque(b, M[0], M[1], M[2]);
        int f = so->g.shape[s].foot;
        for (int k = 0; k < 3; k++) {
            so->foot_force[0][k] += F[k];
            so->foot_force[1 + f][k] += F[k];
        }
        so->foot_nodes[0] += so->g.nodes[s];
        so->foot_nodes[1 + f] += so->g.nodes[s];
        so->foot_area_m2[0] += so->g.area_m2[s];
        so->foot_area_m2[1 + f] += so->g.area_m2[s];
    }
    /* a foot's first soil contact is its touchdown, at the start of this (sub)step */
    int nfeet = sim->geom->nfeet > 1 ? sim->geom->nfeet : 1;
    for (int f = 0; f < nfeet; f++) {
        fs_touch *t = &sim->touch[f];
        if (t->touched || !so->foot_nodes[1 + f])
            continue;
        t->touched = 1;
        t->time_s = t->found_s = sim->time_s;
        fs_sim_foot_ankle(sim, f, t->ankle_m);
    }
    return FS_OK;
}
