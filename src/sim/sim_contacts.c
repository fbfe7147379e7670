/* sim_contacts.c: a step's contacts: each foot shape against the ground, the box's lattice
 * vertices on a heightfield, near-duplicates merged and the deepest kept, made into contact joints. */
#include "sim_internal.h"

#include "sim_ground.h"

#include <math.h>
#include <string.h>

static void gather(void *data, dGeomID a, dGeomID b)
{
    gathered *g = data;
    g->sim->collision_tests++;
    if (g->n < FS_MAX_CONTACTS)
        g->n += dCollide(a, b, FS_MAX_CONTACTS - g->n, g->c + g->n, sizeof g->c[0]);
}

static double distance2(const dContactGeom *a, const dContactGeom *b)
{
    double d = 0;
    for (int k = 0; k < 3; k++)
        d += (a->pos[k] - b->pos[k]) * (a->pos[k] - b->pos[k]);
    return d;
}

/* distance2(a, b) <= r2, most often decided by x alone (adding squares never makes a sum smaller). */
static int within(const dContactGeom *a, const dContactGeom *b, double r2)
{
    double dx = a->pos[0] - b->pos[0];
    return dx * dx <= r2 && distance2(a, b) <= r2;
}

/* Keeps at most max contacts: the same point found by two heightfield tiles (they share their
 * edges) counts once, then the deepest, then each next the farthest from those kept, so the
 * support the contacts give is spread like the real one. Contacts from index lattice_from on are
 * distinct lattice vertices (box_vertex_contacts), a lattice cell apart: none is another's twin,
 * so they are compared with the others only. */
static int select_contacts(gathered *g, int max, double merge_m, int lattice_from)
{
    int n = 0, others = 0;
    for (int i = 0; i < g->n; i++) {
        int twin = 0;
        if (i == lattice_from)
            others = n;
        for (int k = 0; k < (i < lattice_from ? n : others) && !twin; k++)
            twin = within(&g->c[i], &g->c[k], merge_m * merge_m);
        if (!twin)
            g->c[n++] = g->c[i];
    }
    if (n <= max)
        return n;
    for (int kept = 0; kept < max; kept++) {
        int best = kept;
        double score = -INFINITY;
        for (int i = kept; i < n; i++) {
            double s = g->c[i].depth;
            if (kept > 0) {
                s = INFINITY;
                for (int k = 0; k < kept; k++)
                    s = fmin(s, distance2(&g->c[i], &g->c[k]));
            }
            if (s > score)
                score = s, best = i;
        }
        dContactGeom t = g->c[kept];
        g->c[kept] = g->c[best];
        g->c[best] = t;
    }
    return max;
}

/* Whether every vertex of lattice block (a, b) lies below the box: under its lowest corner zlow,
 * or (the box upright) below the plane of its underside, p[2] < -hz in box_vertex_contacts, by a
 * bound over the block's extent and highest sample with a nanometre to spare. */
static int block_below(const fs_terrain *t, long a, long b, const dReal *R, const dReal *c, double hz, double zlow)
{
    const long B = FS_TERRAIN_BLOCK;
    double top = t->zblock[(size_t)b * t->bx + a];
    if (top < zlow)
        return 1;
    if (R[10] <= 0)
        return 0;
    double xa = t->x0 + a * B * t->dx - c[0], xb = xa + B * t->dx;
    double ya = t->y0 + b * B * t->dx - c[1], yb = ya + B * t->dx;
    double bound = fmax(R[2] * xa, R[2] * xb) + fmax(R[6] * ya, R[6] * yb) + R[10] * (top - c[2]);
    return bound < -hz - 1e-9;
}

/* ODE's box-heightfield test finds box corners below the surface, not the surface's vertices
 * poking up through the box's faces: a flat sole sliding onto a rock would sink into it. This
 * adds one contact per lattice vertex inside the box, pushing out through the nearer of its top
 * and bottom faces. */
static void box_vertex_contacts(const fs_terrain *t, dGeomID box, gathered *g)
{
    dVector3 l;
    dGeomBoxGetLengths(box, l);
    const dReal *R = dGeomGetRotation(box), *c = dGeomGetPosition(box);
    double aabb[6];
    dGeomGetAABB(box, aabb);
    double hx = 0.5 * l[0], hy = 0.5 * l[1], hz = 0.5 * l[2];
    long i0 = (long)floor((aabb[0] - t->x0) / t->dx), i1 = (long)ceil((aabb[1] - t->x0) / t->dx);
    long j0 = (long)floor((aabb[2] - t->y0) / t->dx), j1 = (long)ceil((aabb[3] - t->y0) / t->dx);
    const long B = FS_TERRAIN_BLOCK, nx = t->nx, ilo = i0 > 0 ? i0 : 0;
    const double zlow = aabb[4];
    for (long j = j0 > 0 ? j0 : 0; j <= j1 && j < t->ny; j++) {
        const double *row = t->z + (size_t)j * nx;
        for (long i = ilo; i <= i1 && i < nx; i++) {
            /* a block wholly below the box: on to the next (the same vertices, in the same order) */
            if ((i == ilo || i % B == 0) && block_below(t, i / B, j / B, R, c, hz, zlow)) {
                i = (i / B) * B + B - 1;
                continue;
            }
            double z = row[i];
            if (z < zlow)
                continue;
            double w[3] = {t->x0 + i * t->dx - c[0], t->y0 + j * t->dx - c[1], z - c[2]};
            /* the vertex in the box's frame: R^T w (ODE's R is row-major, 4 columns) */
            double p[3];
            for (int k = 0; k < 3; k++)
                p[k] = R[k] * w[0] + R[4 + k] * w[1] + R[8 + k] * w[2];
            if (g->n == FS_MAX_CONTACTS)
                return;
            if (fabs(p[0]) > hx || fabs(p[1]) > hy || fabs(p[2]) > hz)
                continue;
            int up = p[2] > 0; /* nearer the top face: push the box down over it */
            dContactGeom *ct = &g->c[g->n++];
            memset(ct, 0, sizeof *ct);
            for (int k = 0; k < 3; k++) {
                ct->pos[k] = w[k] + c[k];
                ct->normal[k] = (up ? -1 : 1) * R[4 * k + 2];
            }
            ct->depth = up ? hz - p[2] : p[2] + hz;
            ct->g1 = box;
        }
    }
}

/* Two foot shapes (run.collide = all): bodies joined by a joint are skipped, and whatever touches
 * becomes contact joints between the two bodies. */
static void foot_pair(void *data, dGeomID a, dGeomID b)
{
    fs_sim *sim = data;
    dBodyID b1 = dGeomGetBody(a), b2 = dGeomGetBody(b);
    if (dAreConnectedExcluding(b1, b2, dJointTypeContact))
        return;
    sim->collision_tests++;
    dContactGeom c[8];
    int n = dCollide(a, b, 8, c, sizeof c[0]);
    for (int i = 0; i < n && sim->contacts_now < FS_MAX_STEP_CONTACTS; i++) {
        dContact ct = sim->contact_template;
        ct.geom = c[i];
        dJointID j = dJointCreateContact(sim->world, sim->contact_group, &ct);
        dJointAttach(j, b1, b2);
        dJointSetFeedback(j, &sim->feedback[sim->contacts_now]);
        memcpy(sim->contact_pos[sim->contacts_now++], c[i].pos, 3 * sizeof(double));
    }
}

/* Collision: each foot shape against the terrain, nothing else; its contacts become joints. */
void fs_sim_collide(fs_sim *sim)
{
    const fs_terrain *t = &sim->sc->terrain;
    double merge_m = fs_terrain_is_heightfield(t) ? 1e-3 * t->dx : 1e-9;
    gathered *g = sim->scratch;
    for (int s = 0; s < sim->nshapes; s++) {
        g->sim = sim;
        g->n = 0;
        fs_sim_lap(sim, FS_STAGE_CONTACTS);
        dSpaceCollide2(sim->shape[s], (dGeomID)sim->ground, g, gather);
        fs_sim_lap(sim, FS_STAGE_COLLISION);
        int from_ode = g->n;
        if (t->z && dGeomGetClass(sim->shape[s]) == dBoxClass)
            box_vertex_contacts(t, sim->shape[s], g);
        int n = select_contacts(g, sim->sc->def.max_contacts, merge_m, from_ode);
        dBodyID body = dGeomGetBody(sim->shape[s]);
        for (int i = 0; i < n && sim->contacts_now < FS_MAX_STEP_CONTACTS; i++) {
            dContact ct = sim->contact_template;
            ct.geom = g->c[i];
            dJointID j = dJointCreateContact(sim->world, sim->contact_group, &ct);
            dJointAttach(j, body, 0);
            dJointSetFeedback(j, &sim->feedback[sim->contacts_now]);
            memcpy(sim->contact_pos[sim->contacts_now], g->c[i].pos, 3 * sizeof(double));
            sim->contacts_now++;
        }
    }
    if (sim->sc->def.collide_all) {
        fs_sim_lap(sim, FS_STAGE_CONTACTS);
        dSpaceCollide(sim->space, sim, foot_pair);
        fs_sim_lap(sim, FS_STAGE_COLLISION);
    }
}
