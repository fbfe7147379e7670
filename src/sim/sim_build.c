/* sim_build.c: the foot built in ODE from its geometry, and the step as named stages. */
#include "footsim/sim/fs_sim.h"

#include "footsim/sim/fs_ground.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define DEG (M_PI / 180.0)

/* Two materials in contact: friction as the geometric mean, stiffness and damping in series. */
static double series(double a, double b) { return a > 0 && b > 0 ? a * b / (a + b) : 0; }

static void contact_template(fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    const fs_design_def *d = &sim->sc->design;
    const fs_terrain_def *m = &sim->sc->terrain.def;
    double k = series(d->sole_stiffness_N_per_m, m->stiffness_N_per_m);
    double c = series(d->sole_damping_Ns_per_m, m->damping_Ns_per_m);
    double h = s->step_s;
    dContact *ct = &sim->contact_template;
    memset(ct, 0, sizeof *ct);
    ct->surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
    ct->surface.mu = sqrt(d->sole_mu * m->mu);
    if (m->restitution > 0) {
        ct->surface.mode |= dContactBounce;
        ct->surface.bounce = m->restitution;
        ct->surface.bounce_vel = 0.01; /* m/s: slower impacts do not bounce */
    }
    ct->surface.soft_erp = h * k / (h * k + c);
    ct->surface.soft_cfm = 1.0 / (h * k + c);
}

/* ---- the start pose ------------------------------------------------------------------------ */

static fs_vec3 turn(const fs_sim *sim, fs_vec3 v)
{
    const double *R = sim->R0;
    return fs_v3(R[0] * v.x + R[1] * v.y + R[2] * v.z, R[3] * v.x + R[4] * v.y + R[5] * v.z,
                 R[6] * v.x + R[7] * v.y + R[8] * v.z);
}

static fs_vec3 place(const fs_sim *sim, fs_vec3 p) { return fs_add(turn(sim, p), fs_v3(sim->t0[0], sim->t0[1], sim->t0[2])); }

/* R0 = Rz(yaw) Ry(pitch) Rx(roll): toe down for positive pitch, left side up for positive roll. */
static void start_rotation(const fs_scenario_def *s, double R[9])
{
    double y = s->yaw_deg * DEG, p = s->pitch_deg * DEG, r = s->roll_deg * DEG;
    double cy = cos(y), sy = sin(y), cp = cos(p), sp = sin(p), cr = cos(r), sr = sin(r);
    double M[9] = {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,
                   sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,
                   -sp,     cp * sr,                cp * cr};
    memcpy(R, M, sizeof M);
}

/* Highest terrain within the disc of radius r around (x, y), from nine samples. */
static double terrain_top(const fs_terrain *t, double x, double y, double r)
{
    double top = fs_terrain_height(t, x, y);
    for (int k = 0; k < 8; k++)
        top = fmax(top, fs_terrain_height(t, x + r * cos(k * M_PI / 4), y + r * sin(k * M_PI / 4)));
    return top;
}

/* The lift that puts the foot's lowest point drop_m above the terrain under it. */
static double start_lift(const fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    const fs_terrain *t = &sim->sc->terrain;
    double lift = -INFINITY;
    for (int i = 0; i < g->nspheres; i++) {
        fs_vec3 c = place(sim, g->sphere[i].centre);
        double r = g->sphere[i].radius_m;
        lift = fmax(lift, terrain_top(t, c.x, c.y, r) - (c.z - r));
    }
    if (g->has_box) {
        /* the plate's corners, and the terrain under it finer than its lattice (the highest point of
         * triangulated samples is a sample or on the edge) */
        double lowest = INFINITY, top = -INFINITY;
        for (int k = 0; k < 8; k++) {
            fs_vec3 corner = fs_v3(g->box_centre.x + ((k & 1) ? 0.5 : -0.5) * g->box_size.x,
                                   g->box_centre.y + ((k & 2) ? 0.5 : -0.5) * g->box_size.y,
                                   g->box_centre.z + ((k & 4) ? 0.5 : -0.5) * g->box_size.z);
            lowest = fmin(lowest, place(sim, corner).z);
        }
        double spacing = fs_terrain_is_heightfield(t) && t->dx > 0 ? 0.5 * t->dx : 0.002;
        int nx = (int)ceil(g->box_size.x / spacing) + 1, ny = (int)ceil(g->box_size.y / spacing) + 1;
        for (int i = 0; i < nx; i++)
            for (int j = 0; j < ny; j++) {
                fs_vec3 p = fs_v3(g->box_centre.x + (i / (double)(nx - 1) - 0.5) * g->box_size.x,
                                  g->box_centre.y + (j / (double)(ny - 1) - 0.5) * g->box_size.y, 0);
                p = place(sim, p);
                top = fmax(top, fs_terrain_height(t, p.x, p.y));
            }
        lift = fmax(lift, top - lowest);
    }
    return lift + sim->sc->def.drop_m;
}

static void build_body(fs_sim *sim, int i)
{
    const fs_body_geom *g = &sim->geom->body[i];
    dBodyID b = dBodyCreate(sim->world);
    dMass m;
    const double *I = g->inertia;
    dMassSetParameters(&m, g->mass_kg, 0, 0, 0, I[0], I[4], I[8], I[1], I[2], I[5]);
    dBodySetMass(b, &m);
    fs_vec3 p = place(sim, g->com);
    dBodySetPosition(b, p.x, p.y, p.z);
    const double *R = sim->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dBodySetRotation(b, rot);
    sim->body[i] = b;
}

static void build_shapes(fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        dGeomID geom = dCreateSphere(sim->space, s->radius_m);
        dGeomSetBody(geom, sim->body[s->body]);
        const fs_vec3 c = g->body[s->body].com;
        dGeomSetOffsetPosition(geom, s->centre.x - c.x, s->centre.y - c.y, s->centre.z - c.z);
        sim->shape[sim->nshapes++] = geom;
    }
    if (g->has_box) {
        dGeomID box = dCreateBox(sim->space, g->box_size.x, g->box_size.y, g->box_size.z);
        dGeomSetBody(box, sim->body[0]);
        const fs_vec3 c = g->body[0].com;
        dGeomSetOffsetPosition(box, g->box_centre.x - c.x, g->box_centre.y - c.y, g->box_centre.z - c.z);
        sim->shape[sim->nshapes++] = box;
    }
}

static void build_joints(fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    for (int i = 0; i < g->nhinges; i++) {
        const fs_hinge_geom *h = &g->hinge[i];
        dJointID j = dJointCreateHinge(sim->world, 0);
        dJointAttach(j, sim->body[h->body1], sim->body[h->body2]);
        fs_vec3 a = place(sim, h->anchor), x = turn(sim, h->axis);
        dJointSetHingeAnchor(j, a.x, a.y, a.z);
        dJointSetHingeAxis(j, x.x, x.y, x.z);
        sim->hinge[i] = j;
    }
    for (int i = 0; i < g->npins; i++) {
        dJointID j = dJointCreateHinge(sim->world, 0);
        dJointAttach(j, sim->body[g->pin[i].body], 0);
        fs_vec3 a = place(sim, g->pin[i].anchor), x = turn(sim, g->pin[i].axis);
        dJointSetHingeAnchor(j, a.x, a.y, a.z);
        dJointSetHingeAxis(j, x.x, x.y, x.z);
        sim->pin[i] = j;
    }
    for (int i = 0; i < g->nsprings; i++) {
        const fs_spring_geom *s = &g->spring[i];
        fs_vec3 a = place(sim, s->p1), b = place(sim, s->p2);
        double p1[3] = {a.x, a.y, a.z}, p2[3] = {b.x, b.y, b.z};
        fs_spring_init(&sim->spring[i], sim->world, (fs_spring_impl)sim->sc->def.springs, sim->body[s->body1],
                       sim->body[s->body2], p1, p2, s->k_N_per_m, s->c_Ns_per_m, s->rest_length_m);
    }
}

/* ---- the robot ---------------------------------------------------------------------------- */

/* The passive body on the ankle: rigidly fixed, or hinged at the ankle with an Achilles
 * spring-damper from the ankle body, 2 cm behind the joint, to the leg. (The tendon ends on the
 * talus, not the heel: here the heel turns about the same ankle axis as the leg would, so a
 * heel-to-leg tendon would let leg and heel fold together about it unresisted.) */
static void build_robot(fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    const fs_foot_geom *g = sim->geom;
    dBodyID ankle_body = sim->body[g->ankle_body];
    sim->robot = dBodyCreate(sim->world);
    dMass m;
    const double *I = s->robot_inertia_kgm2;
    dMassSetParameters(&m, s->robot_kg, 0, 0, 0, I[0], I[1], I[2], 0, 0, 0);
    dBodySetMass(sim->robot, &m);
    fs_vec3 com = place(sim, fs_add(g->ankle, fs_v3(s->robot_com_forward_m, 0, s->robot_com_height_m)));
    dBodySetPosition(sim->robot, com.x, com.y, com.z);
    const double *R = sim->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dBodySetRotation(sim->robot, rot);
    if (s->robot_joint == 0) {
        sim->robot_joint = dJointCreateFixed(sim->world, 0);
        dJointAttach(sim->robot_joint, sim->robot, ankle_body);
        dJointSetFixed(sim->robot_joint);
        return;
    }
    fs_vec3 a = place(sim, g->ankle), axis = turn(sim, fs_v3(0, 1, 0));
    sim->robot_joint = dJointCreateHinge(sim->world, 0);
    dJointAttach(sim->robot_joint, sim->robot, ankle_body);
    dJointSetHingeAnchor(sim->robot_joint, a.x, a.y, a.z);
    dJointSetHingeAxis(sim->robot_joint, axis.x, axis.y, axis.z);
    const double behind = 0.02; /* m: the tendon's line behind the ankle axis */
    fs_vec3 heel = place(sim, fs_add(g->ankle, fs_v3(-behind, 0, -0.01)));
    fs_vec3 leg = place(sim, fs_add(g->ankle, fs_v3(-behind, 0, s->achilles_leg_anchor_m)));
    double p1[3] = {heel.x, heel.y, heel.z}, p2[3] = {leg.x, leg.y, leg.z};
    fs_spring_init(&sim->achilles, sim->world, (fs_spring_impl)s->springs, ankle_body, sim->robot, p1, p2,
                   s->achilles_k_N_per_m, s->achilles_c_Ns_per_m, fs_norm(fs_sub(leg, heel)));
    sim->has_achilles = 1;
}

/* How far each body's points (joints, spring anchors, shapes) lie from its COM. */
static void body_reach(fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    for (int i = 0; i < g->nhinges; i++) {
        const fs_hinge_geom *h = &g->hinge[i];
        for (int k = 0; k < 2; k++) {
            int b = k ? h->body2 : h->body1;
            sim->reach[b] = fmax(sim->reach[b], fs_norm(fs_sub(h->anchor, g->body[b].com)));
        }
    }
    for (int i = 0; i < g->nsprings; i++) {
        const fs_spring_geom *s = &g->spring[i];
        sim->reach[s->body1] = fmax(sim->reach[s->body1], fs_norm(fs_sub(s->p1, g->body[s->body1].com)));
        sim->reach[s->body2] = fmax(sim->reach[s->body2], fs_norm(fs_sub(s->p2, g->body[s->body2].com)));
    }
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        double r = fs_norm(fs_sub(s->centre, g->body[s->body].com)) + s->radius_m;
        sim->reach[s->body] = fmax(sim->reach[s->body], r);
    }
    if (g->has_box)
        sim->reach[0] = fmax(sim->reach[0], fs_norm(fs_sub(g->box_centre, g->body[0].com)) + 0.5 * fs_norm(g->box_size));
    sim->reach[g->ankle_body] = fmax(sim->reach[g->ankle_body], fs_norm(fs_sub(g->ankle, g->body[g->ankle_body].com)));
}

/* The ground as a grid for fs_sim_scene: a heightfield's own samples, or the plane or steps
 * sampled over the region around the foot. */
static fs_status scene_ground(fs_sim *sim, fs_error *err)
{
    const fs_terrain *t = &sim->sc->terrain;
    if (fs_terrain_is_heightfield(t) && t->z) {
        sim->scene_ground = (fs_scene_ground){t->nx, t->ny, t->x0, t->y0, t->dx, t->dx, t->z, 0};
        return FS_OK;
    }
    double box[4], m = sim->sc->def.region_margin_m + 0.05;
    fs_scenario_footprint(sim->sc, box);
    int steps = t->def.kind == FS_TERRAIN_STEPPED;
    double dx = steps ? 0.001 : (box[1] - box[0] + 2 * m); /* steps need their edges sampled */
    int nx = (int)ceil((box[1] - box[0] + 2 * m) / dx) + 1, ny = steps ? 2 : 2;
    double dy = box[3] - box[2] + 2 * m;
    sim->ground_grid = malloc((size_t)nx * ny * sizeof *sim->ground_grid);
    if (!sim->ground_grid)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", sim->sc->path);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            sim->ground_grid[j * nx + i] = fs_terrain_height(t, box[0] - m + i * dx, box[2] - m + j * dy);
    sim->scene_ground = (fs_scene_ground){nx, ny, box[0] - m, box[2] - m, dx, dy, sim->ground_grid, !steps};
    return FS_OK;
}

/* ODE's auto-disable: a body that has moved slower than rest_speed_m_per_s (and turned slower than
 * that over 1 cm) for auto_disable_s stops being stepped until something enabled touches it. */
static void auto_disable(dWorldID world, const fs_scenario_def *s)
{
    dWorldSetAutoDisableFlag(world, 1);
    dWorldSetAutoDisableLinearThreshold(world, s->rest_speed_m_per_s);
    dWorldSetAutoDisableAngularThreshold(world, s->rest_speed_m_per_s / 0.01);
    dWorldSetAutoDisableSteps(world, 0);
    dWorldSetAutoDisableTime(world, s->auto_disable_s);
}

/* Contacts of one foot shape with all terrain geoms in one step: the sim's own scratch, so two
 * simulations can step in one process. */
typedef struct fs_contact_scratch {
    fs_sim *sim;
    int n;
    dContactGeom c[FS_MAX_CONTACTS];
} gathered;

/* ---- profiling ---------------------------------------------------------------------------- */

double fs_clock_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Adds the time since the last stage ended to stage, when profiling. */
static void lap(fs_sim *sim, fs_stage stage)
{
    if (!sim->profile)
        return;
    double t = fs_clock_s();
    if (sim->profile_mark > 0) {
        sim->profile->stage_s[stage] += t - sim->profile_mark;
        sim->profile->laps[stage]++;
    }
    sim->profile_mark = t;
}

static fs_status build(fs_sim *sim, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err)
{
    snprintf(sim->ode_context, sizeof sim->ode_context, "%s", sc->path);
    fs_ode_context(sim->ode_context); /* ODE's complaints name the scenario */
    sim->feedback = calloc(FS_MAX_STEP_CONTACTS, sizeof *sim->feedback);
    sim->scratch = malloc(sizeof *sim->scratch);
    if (!sim->feedback || !sim->scratch)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", sc->path);
    sim->sc = sc;
    sim->geom = &sc->geom;
    sim->check.record_drift = opts->record_drift;
    const fs_scenario_def *s = &sc->def;
    int share = 1;
    if (opts->pinned_chain) {
        fs_status made = fs_design_pinned_chain(&sc->design, &sc->geom, opts->pinned_chain - 1, &sim->own_geom, err);
        if (made != FS_OK)
            return made;
        sim->geom = &sim->own_geom;
        share = FS_CHAINS;
    }
    double tilt = s->tilt_deg * DEG;
    sim->down[0] = sin(tilt);
    sim->down[2] = -cos(tilt);
    sim->world = dWorldCreate();
    /* quickstep reorders its constraints with ODE's one global random generator: restart it, so a
     * run does not depend on what ran before it in the process */
    dRandSetSeed(0);
    dWorldSetGravity(sim->world, s->gravity_m_per_s2 * sim->down[0], 0, s->gravity_m_per_s2 * sim->down[2]);
    dWorldSetQuickStepNumIterations(sim->world, s->iterations);
    /* ODE's global ERP/CFM only touch hinges and contacts' defaults: keep joints stiff. */
    dWorldSetERP(sim->world, s->joint_erp);
    dWorldSetCFM(sim->world, s->joint_cfm);
    /* Without a surface layer, a very stiff contact pushes a resting sphere out in one step and it
     * loses contact (and friction) every few steps: the toes then creep. */
    dWorldSetContactSurfaceLayer(sim->world, s->contact_layer_m);
    if (s->auto_disable_s > 0)
        auto_disable(sim->world, s);
    sim->space = dSimpleSpaceCreate(0);
    sim->contact_group = dJointGroupCreate(0);
    start_rotation(s, sim->R0);
    sim->t0[0] = s->start_x_m;
    sim->t0[1] = s->start_y_m;
    sim->t0[2] = 0;
    if (opts->with_ground && !opts->pinned_chain) {
        sim->t0[2] = start_lift(sim);
        /* a hash space: a heightfield comes as many tiles */
        sim->ground = dHashSpaceCreate(0);
        int ok;
        sim->heightfield = fs_ground_build(sim->ground, &sc->terrain, s->tile_cells, &ok);
        if (!ok)
            return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the terrain", sc->path);
    }
    for (int i = 0; i < sim->geom->nbodies; i++)
        build_body(sim, i);
    build_shapes(sim);
    build_joints(sim);
    if (s->robot_kg > 0)
        build_robot(sim);
    if (opts->hold_rear_foot && sim->geom->kind == FS_FOOT_BIOMIMETIC) {
        dBodySetKinematic(sim->body[FS_BODY_HEEL]);
        dBodySetKinematic(sim->body[FS_BODY_TALUS]);
    }
    const fs_vec3 a = place(sim, sim->geom->ankle);
    dBodyGetPosRelPoint(sim->body[sim->geom->ankle_body], a.x, a.y, a.z, sim->ankle_local);
    sim->load_N = s->load_kg * s->gravity_m_per_s2 / share;
    contact_template(sim);
    body_reach(sim);
    sim->profile = opts->profile;
    return scene_ground(sim, err);
}

fs_status fs_sim_build(fs_sim *sim, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err)
{
    fs_sim_options normal = {.with_ground = 1, .hold_rear_foot = 0};
    memset(sim, 0, sizeof *sim);
    fs_status s = build(sim, sc, opts ? opts : &normal, err);
    if (s != FS_OK)
        fs_sim_destroy(sim); /* whatever was made so far: a failed build leaves nothing behind */
    return s;
}

void fs_sim_destroy(fs_sim *sim)
{
    if (sim->ground)
        dSpaceDestroy(sim->ground);
    fs_ground_destroy(sim->heightfield);
    if (sim->space)
        dSpaceDestroy(sim->space); /* destroys the shapes it holds */
    if (sim->contact_group)
        dJointGroupDestroy(sim->contact_group);
    if (sim->world)
        dWorldDestroy(sim->world);
    free(sim->feedback);
    free(sim->scratch);
    free(sim->ground_grid);
    fs_ode_context_leave(sim->ode_context);
    memset(sim, 0, sizeof *sim);
}

void fs_sim_ankle(const fs_sim *sim, double p[3])
{
    dVector3 w;
    dBodyGetRelPointPos(sim->body[sim->geom->ankle_body], sim->ankle_local[0], sim->ankle_local[1],
                        sim->ankle_local[2], w);
    memcpy(p, w, 3 * sizeof(double));
}

/* ---- the step ----------------------------------------------------------------------------- */


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
static void collide(fs_sim *sim)
{
    const fs_terrain *t = &sim->sc->terrain;
    double merge_m = fs_terrain_is_heightfield(t) ? 1e-3 * t->dx : 1e-9;
    gathered *g = sim->scratch;
    for (int s = 0; s < sim->nshapes; s++) {
        g->sim = sim;
        g->n = 0;
        lap(sim, FS_STAGE_CONTACTS);
        dSpaceCollide2(sim->shape[s], (dGeomID)sim->ground, g, gather);
        lap(sim, FS_STAGE_COLLISION);
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
        lap(sim, FS_STAGE_CONTACTS);
        dSpaceCollide(sim->space, sim, foot_pair);
        lap(sim, FS_STAGE_COLLISION);
    }
}

double fs_sim_load_now_N(const fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    return sim->load_N * (s->ramp_s > 0 && sim->time_s < s->ramp_s ? sim->time_s / s->ramp_s : 1.0);
}

static void apply_load(fs_sim *sim)
{
    double f = fs_sim_load_now_N(sim);
    double p[3];
    fs_sim_ankle(sim, p);
    dBodyAddForceAtPos(sim->body[sim->geom->ankle_body], f * sim->down[0], f * sim->down[1], f * sim->down[2], p[0],
                       p[1], p[2]);
}

fs_status fs_sim_step(fs_sim *sim, fs_error *err)
{
    const fs_scenario_def *s = &sim->sc->def;
    double h = s->step_s;
    lap(sim, FS_STAGE_CALLER);
    fs_ode_context(sim->ode_context); /* this sim is the one ODE may complain about now */
    /* external loads */
    apply_load(sim);
    lap(sim, FS_STAGE_LOADS);
    /* spring-dampers: soft rows set for h, or explicit forces */
    for (int i = 0; i < sim->geom->nsprings; i++)
        fs_spring_prepare(&sim->spring[i], h);
    if (sim->has_achilles)
        fs_spring_prepare(&sim->achilles, h);
    lap(sim, FS_STAGE_SPRINGS);
    /* collision: the foot's shapes against the ground, nothing else */
    sim->contacts_now = 0;
    if (sim->ground)
        collide(sim);
    sim->contacts_total += sim->contacts_now;
    lap(sim, FS_STAGE_CONTACTS);
    /* the ODE step */
    if (s->stepper == FS_STEPPER_QUICKSTEP)
        dWorldQuickStep(sim->world, h);
    else
        dWorldStep(sim->world, h);
    dJointGroupEmpty(sim->contact_group);
    sim->time_s += h;
    lap(sim, FS_STAGE_ODE);
    /* a sound state (finite, physical speeds, closed loops, no energy from nowhere), or a clear stop */
    fs_status st = fs_check_step(sim, err);
    lap(sim, FS_STAGE_CHECK);
    if (sim->profile)
        sim->profile->steps++;
    return st;
}

/* ---- measurements ------------------------------------------------------------------------- */

/* Kinetic and gravitational energy of one body (relative to z = 0), J. */
static void body_energy(const fs_sim *sim, dBodyID b, double *ke, double *pe)
{
    if (dBodyIsKinematic(b))
        return;
    double g = sim->sc->def.gravity_m_per_s2;
    dMass m;
    dBodyGetMass(b, &m);
    const dReal *v = dBodyGetLinearVel(b), *w = dBodyGetAngularVel(b), *p = dBodyGetPosition(b);
    const dReal *R = dBodyGetRotation(b);
    /* the angular velocity in the body frame, where ODE keeps the inertia */
    double wb[3] = {0, 0, 0};
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            wb[r] += R[4 * c + r] * w[c];
    double rot = 0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            rot += wb[r] * m.I[4 * r + c] * wb[c];
    *ke += 0.5 * m.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * rot;
    *pe -= m.mass * g * (p[0] * sim->down[0] + p[1] * sim->down[1] + p[2] * sim->down[2]);
}

double fs_sim_energy(const fs_sim *sim, double *kinetic, double *potential, double *elastic)
{
    double ke = 0, pe = 0, se = 0;
    for (int i = 0; i < sim->geom->nbodies; i++)
        body_energy(sim, sim->body[i], &ke, &pe);
    if (sim->robot)
        body_energy(sim, sim->robot, &ke, &pe);
    for (int i = 0; i < sim->geom->nsprings; i++)
        se += fs_spring_measure(&sim->spring[i]).energy_J;
    if (sim->has_achilles)
        se += fs_spring_measure(&sim->achilles).energy_J;
    if (kinetic)
        *kinetic = ke;
    if (potential)
        *potential = pe;
    if (elastic)
        *elastic = se;
    return ke + pe + se;
}

double fs_sim_body_speed(const fs_sim *sim, int i)
{
    int robot = i == sim->geom->nbodies;
    dBodyID b = robot ? sim->robot : sim->body[i];
    const dReal *v = dBodyGetLinearVel(b), *w = dBodyGetAngularVel(b);
    double reach = robot ? sim->sc->def.robot_com_height_m : sim->reach[i];
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + reach * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

double fs_sim_max_speed(const fs_sim *sim)
{
    double vmax = 0;
    for (int i = 0; i < sim->geom->nbodies + (sim->robot != NULL); i++)
        vmax = fmax(vmax, fs_sim_body_speed(sim, i));
    return vmax;
}

double fs_sim_robot_tilt(const fs_sim *sim)
{
    if (!sim->robot)
        return 0;
    const dReal *R = dBodyGetRotation(sim->robot);
    return acos(fmax(-1.0, fmin(1.0, R[10])));
}

double fs_sim_penetration(const fs_sim *sim)
{
    const fs_terrain *t = &sim->sc->terrain;
    double worst = -INFINITY;
    for (int i = 0; i < sim->nshapes; i++) {
        dGeomID g = sim->shape[i];
        const dReal *p = dGeomGetPosition(g);
        if (dGeomGetClass(g) == dSphereClass) {
            worst = fmax(worst, fs_terrain_height(t, p[0], p[1]) - (p[2] - dGeomSphereGetRadius(g)));
            continue;
        }
        /* a box: its underside on a 21 x 11 grid */
        dVector3 l, q;
        dGeomBoxGetLengths(g, l);
        for (int a = 0; a <= 20; a++)
            for (int b = 0; b <= 10; b++) {
                dGeomGetRelPointPos(g, (a / 20.0 - 0.5) * l[0], (b / 10.0 - 0.5) * l[1], -0.5 * l[2], q);
                worst = fmax(worst, fs_terrain_height(t, q[0], q[1]) - q[2]);
            }
    }
    return worst;
}

void fs_sim_ground_force(const fs_sim *sim, double force[3])
{
    force[0] = force[1] = force[2] = 0;
    for (int i = 0; i < sim->contacts_now; i++)
        for (int k = 0; k < 3; k++)
            force[k] += sim->feedback[i].f1[k];
}

static void copy3(double dst[3], const dReal *src)
{
    for (int k = 0; k < 3; k++)
        dst[k] = src[k];
}

void fs_sim_scene(const fs_sim *sim, fs_scene *scene)
{
    const fs_foot_geom *g = sim->geom;
    memset(scene, 0, sizeof *scene);
    scene->time_s = sim->time_s;
    scene->scenario = sim->sc->name;
    scene->foot = g->kind == FS_FOOT_FLAT ? "flat" : "biomimetic";
    scene->terrain = sim->sc->terrain.name;
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
    if (sim->robot && scene->nlinks < FS_SCENE_MAX_SEGMENTS) {
        /* the robot as a line from the ankle to its centre of mass */
        fs_scene_segment *seg = &scene->link[scene->nlinks++];
        memcpy(seg->p1, scene->ankle, sizeof seg->p1);
        copy3(seg->p2, dBodyGetPosition(sim->robot));
    }
    for (int k = 0; k < 3; k++)
        scene->load_N[k] = fs_sim_load_now_N(sim) * sim->down[k];
}

double fs_sim_hinge_angle(const fs_sim *sim, int i)
{
    /* ODE's hinge angle turns body1 about the axis relative to body2; ours turns body2 (distal). */
    return -dJointGetHingeAngle(sim->hinge[i]);
}
