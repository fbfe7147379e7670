/* sim_contacts.c: a step's contacts: each foot shape against the ground (on a heightfield by
 * footsim's own tests, sim_lattice.h; on a plane or steps by ODE's), near-duplicates merged and the
 * deepest kept, made into contact joints. */
#include "sim_internal.h"

#include "sim_lattice.h"

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

/* A sphere's contacts whose normals lie within SPHERE_MERGE_DEG of each other are one contact: each
 * pushes along its normal through the sphere's centre, so the two push the same way to within that
 * angle, which the kept one's friction covers for mu >= tan(10 deg) = 0.18 (a force along one
 * normal is, on the other, a normal part and a tangential part at most tan(angle) of it). ODE's
 * heightfield test returns such near-twins from neighbouring triangles under one sphere; footsim's
 * (sim_lattice.h), one on each flank of a shallow hollow. */
static const double SPHERE_MERGE_DEG = 10.0;
static int alike_normals(const dContactGeom *a, const dContactGeom *b)
{
    double d = a->normal[0] * b->normal[0] + a->normal[1] * b->normal[1] + a->normal[2] * b->normal[2];
    return d >= cos(SPHERE_MERGE_DEG * M_PI / 180.0);
}

/* Keeps at most max contacts: the same point found by two heightfield tiles (they share their
 * edges) counts once, then the deepest, then each next the farthest from those kept, so the
 * support the contacts give is spread like the real one. Contacts from index lattice_from on are
 * distinct lattice vertices (fs_lattice_vertex_contacts), a lattice cell apart: none is another's twin,
 * so they are compared with the others only. A sphere's contacts with alike normals merge into the
 * deepest (sphere: 1). */
static int select_contacts(gathered *g, int max, double merge_m, int lattice_from, int sphere)
{
    int n = 0, others = 0;
    for (int i = 0; i < g->n; i++) {
        int twin = 0;
        if (i == lattice_from)
            others = n;
        for (int k = 0; k < (i < lattice_from ? n : others) && !twin; k++) {
            twin = within(&g->c[i], &g->c[k], merge_m * merge_m);
            if (!twin && sphere && alike_normals(&g->c[i], &g->c[k])) {
                twin = 1;
                if (g->c[i].depth > g->c[k].depth)
                    g->c[k] = g->c[i]; /* the deeper of the two stands for both */
            }
        }
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

/* ---- friction bounds ------------------------------------------------------------------------ */

void fs_sim_remember_contacts(fs_sim *sim)
{
    gathered *g = sim->scratch;
    g->prev_n = sim->contacts_now;
    for (int i = 0; i < sim->contacts_now; i++) {
        const dReal *f = sim->feedback[i].f1; /* on the shape's body, along the normal when it pushes */
        double N = f[0] * g->normal[i][0] + f[1] * g->normal[i][1] + f[2] * g->normal[i][2];
        g->prev_N[i] = isfinite(N) ? fmax(0, N) : -1; /* -1: no force to go by */
        g->prev_shape[i] = g->shape[i];
        memcpy(g->prev_pos[i], sim->contact_pos[i], sizeof g->prev_pos[i]);
        g->share[i] = 0;
    }
}

/* For each of shape s's n contacts, the last step's contact of the same shape it continues: the
 * nearest within match_m (a contact moves by its speed times a step), each shared out among the
 * contacts that continue it. */
static void match_contacts(gathered *g, int s, int n, double match_m)
{
    for (int i = 0; i < n; i++) {
        double best = match_m * match_m;
        g->match[i] = -1;
        for (int j = 0; j < g->prev_n; j++) {
            if (g->prev_shape[j] != s || g->prev_N[j] < 0)
                continue;
            double d2 = 0;
            for (int k = 0; k < 3; k++)
                d2 += (g->c[i].pos[k] - g->prev_pos[j][k]) * (g->c[i].pos[k] - g->prev_pos[j][k]);
            if (d2 < best)
                best = d2, g->match[i] = j;
        }
        if (g->match[i] >= 0)
            g->share[g->match[i]]++;
    }
}

/* The friction bound of a contact that continues one of the last step's (docs/model.md, Contact):
 * dContactApprox1 bounds friction by mu times the normal force of the same solve, but ODE's direct
 * solver (Dantzig) fixes each friction row's bound from the normal forces it has when it reaches
 * the friction rows, which it takes last: those of the frictionless problem. Once friction enters,
 * the normal forces change and the bounds do not, so at small steps a toe can slide under friction
 * well below mu N (or grip beyond it). A continuing contact gets a fixed bound instead: mu times the
 * normal force ODE gave it in the last step (its share, when several continue one), one step late,
 * an error of order h. A new contact keeps dContactApprox1: it has no force yet. */
static void bound_friction(dContact *ct, double N)
{
    ct->surface.mode &= ~dContactApprox1;
    ct->surface.mu *= N;
}

/* fs_sim_options.chain_plane_friction: the contact grips along dir (its chain's plane, made
 * tangent to the surface) and slides freely across it. */
static void grip_in_plane(dContact *ct, const double dir[3])
{
    const double *n = ct->geom.normal;
    double along = dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2], t[3], len = 0;
    for (int k = 0; k < 3; k++) {
        t[k] = dir[k] - along * n[k];
        len += t[k] * t[k];
    }
    if (len < 1e-12) /* the chain's line along the normal: no direction in the surface to grip in */
        return;
    ct->surface.mode |= dContactMu2 | dContactFDir1;
    ct->surface.mu2 = 0;
    for (int k = 0; k < 3; k++)
        ct->fdir1[k] = t[k] / sqrt(len);
}

/* Whether the contact point leaves the surface faster than SEPARATING_M_PER_S: the last step's
 * force says nothing of a contact that is coming apart (a foot bounced off a rock), and a bound
 * from it could hold the point to the surface; such a contact keeps dContactApprox1. */
static const double SEPARATING_M_PER_S = 0.01;
static int separating(dBodyID body, const dContactGeom *c)
{
    dVector3 v;
    dBodyGetPointVel(body, c->pos[0], c->pos[1], c->pos[2], v);
    return v[0] * c->normal[0] + v[1] * c->normal[1] + v[2] * c->normal[2] > SEPARATING_M_PER_S;
}

/* One contact joint of this step between b1 and b2 (b2 0: the terrain), from shape (-1: foot
 * against foot); its force is recorded after the step. */
static void add_contact(fs_sim *sim, const dContact *ct, dBodyID b1, dBodyID b2, int shape)
{
    gathered *g = sim->scratch;
    dJointID j = dJointCreateContact(sim->world, sim->contact_group, ct);
    dJointAttach(j, b1, b2);
    dJointSetFeedback(j, &sim->feedback[sim->contacts_now]);
    g->shape[sim->contacts_now] = (short)shape;
    memcpy(g->normal[sim->contacts_now], ct->geom.normal, 3 * sizeof(double));
    sim->contact_depth_m[sim->contacts_now] = ct->geom.depth;
    memcpy(sim->contact_pos[sim->contacts_now++], ct->geom.pos, 3 * sizeof(double));
}

/* Two foot shapes (run.collide = all): bodies joined by a joint are skipped, and whatever touches
 * becomes contact joints between the two bodies (dContactApprox1: no history is kept for them). */
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
        add_contact(sim, &ct, b1, b2, -1);
    }
}

/* Collision: each foot shape against the terrain, nothing else; its contacts become joints. */
void fs_sim_collide(fs_sim *sim)
{
    const fs_terrain *t = &sim->sc->terrain;
    double merge_m = fs_terrain_is_heightfield(t) ? 1e-3 * t->dx : 1e-9;
    gathered *g = sim->scratch;
    sim->contacts_found_now = sim->shapes_touching_now = sim->most_found_now = 0;
    for (int s = 0; s < sim->nshapes; s++) {
        g->sim = sim;
        g->n = 0;
        fs_sim_lap(sim, FS_STAGE_CONTACTS);
        int box = dGeomGetClass(sim->shape[s]) == dBoxClass, from_ode;
        if (t->z && !sim->sc->def.heightfield_ode) {
            if (box)
                fs_lattice_box_contacts(t, sim->shape[s], g);
            else
                fs_lattice_sphere_contacts(t, sim->shape[s], g);
            fs_sim_lap(sim, FS_STAGE_COLLISION); /* footsim's own test, but collision all the same */
            from_ode = g->n;
        } else {
            dSpaceCollide2(sim->shape[s], (dGeomID)sim->ground, g, gather);
            fs_sim_lap(sim, FS_STAGE_COLLISION);
            from_ode = g->n;
            if (t->z && box)
                fs_lattice_vertex_contacts(t, sim->shape[s], g);
        }
        sim->contacts_found_now += g->n;
        sim->shapes_touching_now += g->n > 0;
        sim->most_found_now = g->n > sim->most_found_now ? g->n : sim->most_found_now;
        int n = select_contacts(g, sim->sc->def.max_contacts, merge_m, from_ode, !box);
        dBodyID body = dGeomGetBody(sim->shape[s]);
        match_contacts(g, s, n, sim->match_m[s]);
        for (int i = 0; i < n && sim->contacts_now < FS_MAX_STEP_CONTACTS; i++) {
            dContact ct = sim->contact_template;
            ct.geom = g->c[i];
            if (sim->chain_plane_friction && s < sim->geom->nspheres)
                grip_in_plane(&ct, sim->grip_dir[s]);
            if (g->match[i] >= 0 && sim->contact_template.surface.mu > 0 && !separating(body, &g->c[i]))
                bound_friction(&ct, g->prev_N[g->match[i]] / g->share[g->match[i]]);
            add_contact(sim, &ct, body, 0, s);
        }
    }
    if (sim->sc->def.collide_all) {
        fs_sim_lap(sim, FS_STAGE_CONTACTS);
        dSpaceCollide(sim->space, sim, foot_pair);
        fs_sim_lap(sim, FS_STAGE_COLLISION);
    }
}
