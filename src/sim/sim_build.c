/* sim_build.c: the foot built in ODE from its geometry (bodies, shapes, joints, springs, the
 * robot, the ground), and taken down again. The step is sim_step.c. */
#include "sim_internal.h"
#include "sim_soil.h"

#include "sim_ground.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEG (M_PI / 180.0)

/* Two materials in contact: friction as the geometric mean, stiffness and damping in series. */
static double series(double a, double b) { return a > 0 && b > 0 ? a * b / (a + b) : 0; }

static void contact_template(fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    const fs_design_def *d = &sim->sc->design;
    const fs_terrain_def *m = &sim->sc->terrain.def;
    dContact *ct = &sim->contact_template;
    memset(ct, 0, sizeof *ct);
    ct->surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
    ct->surface.mu = sqrt(d->sole_mu * m->mu);
    if (m->restitution > 0) {
        ct->surface.mode |= dContactBounce;
        ct->surface.bounce = m->restitution;
        ct->surface.bounce_vel = 0.01; /* m/s: slower impacts do not bounce */
    }
    sim->contact_k_N_per_m = series(d->sole_stiffness_N_per_m, m->stiffness_N_per_m);
    sim->contact_c_Ns_per_m = series(d->sole_damping_Ns_per_m, m->damping_Ns_per_m);
    fs_sim_soften_contacts(sim, s->step_s);
    sim->step_now_s = s->step_s;
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
    for (int b = 0; b < g->nboxes; b++) {
        /* the plate's corners, and the terrain under it finer than its lattice (the highest point of
         * triangulated samples is a sample or on the edge) */
        const fs_vec3 bc = g->box[b].centre;
        double lowest = INFINITY, top = -INFINITY;
        for (int k = 0; k < 8; k++) {
            fs_vec3 corner = fs_v3(bc.x + ((k & 1) ? 0.5 : -0.5) * g->box_size.x,
                                   bc.y + ((k & 2) ? 0.5 : -0.5) * g->box_size.y,
                                   bc.z + ((k & 4) ? 0.5 : -0.5) * g->box_size.z);
            lowest = fmin(lowest, place(sim, corner).z);
        }
        double spacing = fs_terrain_is_heightfield(t) && t->dx > 0 ? 0.5 * t->dx : 0.002;
        int nx = (int)ceil(g->box_size.x / spacing) + 1, ny = (int)ceil(g->box_size.y / spacing) + 1;
        for (int i = 0; i < nx; i++)
            for (int j = 0; j < ny; j++) {
                fs_vec3 p = fs_v3(bc.x + (i / (double)(nx - 1) - 0.5) * g->box_size.x,
                                  bc.y + (j / (double)(ny - 1) - 0.5) * g->box_size.y, 0);
                p = place(sim, p);
                top = fmax(top, fs_terrain_height(t, p.x, p.y));
            }
        lift = fmax(lift, top - lowest);
    }
    if (sim->sc->terrain.def.soil.model != FS_SOIL_NONE) /* drop_m above the soil's surface */
        lift += sim->sc->terrain.def.soil.depth_m;
    return lift + sim->sc->def.drop_m;
}

/* Whether the robot becomes part of the ankle body (a rigid robot, free, not the walking machine's,
 * whose carriage holds the robot's own body): its fixed joint's 6 rows a step saved, the same
 * rigid assembly. */
static int robot_merges(const fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    return s->robot.mass_kg > 0 && s->robot.kind == FS_ROBOT_SINGLE && s->robot.joint == FS_ROBOT_RIGID && s->robot.mount == FS_ROBOT_FREE &&
           s->kind != FS_SCENARIO_WALK && sim->geom->npins == 0;
}

/* The robot's centre of mass in the design frame (its frame is the foot's at the start). */
static fs_vec3 robot_com(const fs_sim *sim)
{
    const fs_robot_def *r = &sim->sc->def.robot;
    return fs_add(sim->geom->ankle, fs_v3(r->com_forward_m, 0, r->com_height_m));
}

/* The robot's mass about its centre, in its frame. */
static void robot_mass(const fs_sim *sim, dMass *m)
{
    double I[3];
    fs_robot_inertia(&sim->sc->def.robot, I);
    dMassSetParameters(m, sim->sc->def.robot.mass_kg, 0, 0, 0, I[0], I[1], I[2], 0, 0, 0);
}

/* The smallest eigenvalue of the symmetric 3x3 matrix ODE keeps in a dMass (rows 4 apart):
 * the smallest principal moment of inertia (closed form, trigonometric; Smith 1961). */
static double smallest_moment(const dReal *I)
{
    double a = I[0], b = I[5], c = I[10], d = I[1], e = I[6], f = I[2];
    double off = d * d + e * e + f * f;
    if (off == 0)
        return fmin(a, fmin(b, c));
    double q = (a + b + c) / 3;
    double p = sqrt(((a - q) * (a - q) + (b - q) * (b - q) + (c - q) * (c - q) + 2 * off) / 6);
    /* det((A - q 1) / p) / 2, in [-1, 1] but for rounding */
    double A = (a - q) / p, B = (b - q) / p, C = (c - q) / p, D = d / p, E = e / p, F = f / p;
    double r = 0.5 * (A * (B * C - E * E) - D * (D * C - E * F) + F * (D * E - B * F));
    double phi = acos(fmax(-1.0, fmin(1.0, r))) / 3;
    return q + 2 * p * cos(phi + 2 * M_PI / 3);
}

/* [run] min_inertia_kg_m2 (for QuickStep: docs/bench.md, "QuickStep and the mass ratio"): I becomes
 * I + d 1 with d = max(0, floor - smallest principal moment), so that no principal moment is below
 * the floor and none is raised by more than it; the principal axes stay, the moments' triangle
 * inequality holds (each grows by d), and the mass and centre are untouched. Off (0), nothing is done:
 * the bits are those of a build without the key. */
static void inertia_floor(dMass *m, double floor_kg_m2)
{
    if (!(floor_kg_m2 > 0))
        return;
    double d = floor_kg_m2 - smallest_moment(m->I);
    if (d <= 0)
        return;
    m->I[0] += d;
    m->I[5] += d;
    m->I[10] += d;
}

/* Body i's mass; for the ankle body with a merged robot, the robot's added at its centre (the two
 * frames are alike), and the body's centre moved to the combined one (ODE keeps a body's centre at
 * its origin): sim->com[i] says where, in the design frame. */
static void body_mass(fs_sim *sim, int i, dMass *m)
{
    const fs_body_geom *g = &sim->geom->body[i];
    const double *I = g->inertia;
    dMassSetParameters(m, g->mass_kg, 0, 0, 0, I[0], I[4], I[8], I[1], I[2], I[5]);
    sim->com[i] = g->com;
    if (i != sim->geom->ankle_body || !sim->robot_merged)
        return;
    dMass r;
    robot_mass(sim, &r);
    fs_vec3 d = fs_sub(robot_com(sim), g->com);
    dMassTranslate(&r, d.x, d.y, d.z);
    dMassAdd(m, &r);
    sim->com[i] = fs_add(g->com, fs_v3(m->c[0], m->c[1], m->c[2]));
    dMassTranslate(m, -m->c[0], -m->c[1], -m->c[2]);
    fs_vec3 local = fs_sub(robot_com(sim), sim->com[i]);
    sim->robot_local[0] = local.x;
    sim->robot_local[1] = local.y;
    sim->robot_local[2] = local.z;
}

static void build_body(fs_sim *sim, int i)
{
    dBodyID b = dBodyCreate(sim->world);
    dMass m;
    body_mass(sim, i, &m);
    inertia_floor(&m, sim->sc->def.min_inertia_kg_m2);
    dBodySetMass(b, &m);
    fs_vec3 p = place(sim, sim->com[i]);
    dBodySetPosition(b, p.x, p.y, p.z);
    const double *R = sim->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dBodySetRotation(b, rot);
    sim->body[i] = b;
}

/* Which foot body b belongs to (a biped's legs: -1). */
static int foot_of_body(const fs_foot_geom *g, int b)
{
    if (g->nfeet <= 1)
        return 0;
    for (int f = 0; f < g->nfeet; f++)
        if (b >= g->foot[f].first_body && b < g->foot[f].first_body + g->foot[f].nbodies)
            return f;
    return -1;
}

static void build_shapes(fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        sim->shape_foot[sim->nshapes] = foot_of_body(g, s->body);
        dGeomID geom = dCreateSphere(sim->space, s->radius_m);
        dGeomSetBody(geom, sim->body[s->body]);
        const fs_vec3 c = sim->com[s->body];
        dGeomSetOffsetPosition(geom, s->centre.x - c.x, s->centre.y - c.y, s->centre.z - c.z);
        sim->match_m[sim->nshapes] = s->radius_m / 4; /* far more than a contact moves in a step */
        sim->shape[sim->nshapes++] = geom;
    }
    for (int b = 0; b < g->nboxes; b++) {
        dGeomID box = dCreateBox(sim->space, g->box_size.x, g->box_size.y, g->box_size.z);
        const int body = g->box[b].body;
        dGeomSetBody(box, sim->body[body]);
        const fs_vec3 c = sim->com[body], bc = g->box[b].centre;
        dGeomSetOffsetPosition(box, bc.x - c.x, bc.y - c.y, bc.z - c.z);
        sim->shape_foot[sim->nshapes] = foot_of_body(g, body);
        sim->match_m[sim->nshapes] = fmin(g->box_size.x, g->box_size.y) / 4; /* corners lie farther apart */
        sim->shape[sim->nshapes++] = box;
    }
}

/* With chain_plane_friction: each sphere grips along the horizontal line of its chain's plane
 * (metatarsal and phalanx: midfoot joint to toe), the heel's and talus's along the foot's x. */
static void grip_directions(fs_sim *sim)
{
    const fs_foot_geom *g = sim->geom;
    for (int i = 0; i < g->nspheres; i++) {
        fs_vec3 d = fs_v3(1, 0, 0);
        for (int c = 0; c < FS_CHAINS; c++)
            if (g->sphere[i].body == g->chain[c].metatarsal || g->sphere[i].body == g->chain[c].phalanx)
                d = fs_sub(g->chain[c].toe, g->chain[c].midfoot);
        d = turn(sim, d);
        double len = hypot(d.x, d.y);
        sim->grip_dir[i][0] = d.x / len, sim->grip_dir[i][1] = d.y / len, sim->grip_dir[i][2] = 0;
    }
}

/* A passive angular spring-damper toward the hinge's angle now (0: its built pose), implicit: a stop
 * with lo = hi, which ODE makes one two-sided row whenever it is met, as it always is (joint.cpp,
 * dxJointLimitMotor::testRotationalLimit and addLimot: angle <= lo or >= hi sets the limit, and
 * lo == hi gives the row -inf .. inf bounds), with the stop's ERP and CFM from k and c by the same
 * mapping as the contacts and the springs (fs_spring_soft). */
static void angular_spring(const fs_sim *sim, dJointID j, double k, double c, double h)
{
    dJointSetHingeParam(j, dParamLoStop, 0);
    dJointSetHingeParam(j, dParamHiStop, 0);
    fs_sim_soften_stop(sim, j, k, c, h);
    dJointSetHingeParam(j, dParamBounce, 0);
}

void fs_sim_spring_init(const fs_sim *sim, fs_spring *s, dBodyID body1, dBodyID body2, const double p1[3],
                        const double p2[3], double k, double c, double rest)
{
    fs_spring_init(s, sim->world, (fs_spring_impl)sim->sc->def.springs, body1, body2, p1, p2, k, c, rest);
    s->damping_correction = sim->sc->def.damping_correction;
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
        if (fs_hinge_has_spring(h))
            angular_spring(sim, j, h->k_N_m_per_rad, h->c_N_m_s_per_rad, sim->sc->def.step_s);
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
        fs_sim_spring_init(sim, &sim->spring[i], sim->body[s->body1], sim->body[s->body2], p1, p2, s->k_N_per_m,
                           s->c_Ns_per_m, s->rest_length_m);
    }
}

/* ---- the robot ---------------------------------------------------------------------------- */

/* The passive body on the ankle (unless merged into the ankle body, body_mass): rigidly fixed, or hinged at the ankle with an Achilles
 * spring-damper from the ankle body, 2 cm behind the joint, to the leg; free, or on a vertical
 * slide to the world (fs_robot.h). (The tendon ends on the
 * talus, not the heel: here the heel turns about the same ankle axis as the leg would, so a
 * heel-to-leg tendon would let leg and heel fold together about it unresisted.) */
static void build_robot(fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    const fs_foot_geom *g = sim->geom;
    dBodyID ankle_body = sim->body[g->ankle_body];
    sim->robot = dBodyCreate(sim->world);
    dMass m;
    robot_mass(sim, &m);
    dBodySetMass(sim->robot, &m);
    fs_vec3 com = place(sim, robot_com(sim));
    dBodySetPosition(sim->robot, com.x, com.y, com.z);
    const double *R = sim->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dBodySetRotation(sim->robot, rot);
    if (s->robot.mount == FS_ROBOT_VERTICAL) { /* the carriage's slide: up and down only */
        dJointID slide = dJointCreateSlider(sim->world, 0);
        dJointAttach(slide, sim->robot, 0);
        dJointSetSliderAxis(slide, 0, 0, 1);
    }
    if (s->robot.joint == FS_ROBOT_RIGID) {
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
    const double behind = FS_ACHILLES_LEVER_M; /* the tendon's line behind the ankle axis */
    fs_vec3 heel = place(sim, fs_add(g->ankle, fs_v3(-behind, 0, -0.01)));
    fs_vec3 leg = place(sim, fs_add(g->ankle, fs_v3(-behind, 0, s->robot.achilles_leg_anchor_m)));
    double p1[3] = {heel.x, heel.y, heel.z}, p2[3] = {leg.x, leg.y, leg.z};
    fs_sim_spring_init(sim, &sim->achilles, ankle_body, sim->robot, p1, p2, s->robot.achilles_k_N_per_m,
                       s->robot.achilles_c_Ns_per_m, fs_norm(fs_sub(leg, heel)));
    sim->has_achilles = 1;
}

/* How far each body's points (joints, spring anchors, shapes) lie from its own COM (a merged
 * robot's ankle body too: its speed is taken at the foot's part's COM, fs_sim_body_speed). */
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
    for (int k = 0; k < g->nboxes; k++) {
        const int b = g->box[k].body;
        sim->reach[b] = fmax(sim->reach[b], fs_norm(fs_sub(g->box[k].centre, g->body[b].com)) + 0.5 * fs_norm(g->box_size));
    }
    sim->reach[g->ankle_body] = fmax(sim->reach[g->ankle_body], fs_norm(fs_sub(g->ankle, g->body[g->ankle_body].com)));
}

/* The ground as a grid for fs_sim_scene: a heightfield's own samples, or the plane or steps
 * sampled over the region around the foot. Only the grid's size and memory are settled here; the
 * plane or steps are sampled on the scene's first call (sim_scene.c), so a run that draws no frame
 * never samples them. */
static fs_status scene_ground(fs_sim *sim, fs_error *err)
{
    const fs_terrain *t = &sim->sc->terrain;
    if (fs_terrain_is_heightfield(t) && t->z) {
        sim->scene_ground = (fs_scene_ground){t->nx, t->ny, t->x0, t->y0, t->dx, t->dx, t->z, 0, NULL};
        return FS_OK;
    }
    double box[4], m = sim->sc->def.region_margin_m + 0.05;
    fs_scenario_reach(sim->sc, box);
    int steps = t->def.kind == FS_TERRAIN_STEPPED;
    /* steps need their edges sampled; a soil its prints, every 1 mm both ways */
    int soil = t->def.soil.model != FS_SOIL_NONE;
    double dx = steps || soil ? 0.001 : (box[1] - box[0] + 2 * m);
    int nx = (int)ceil((box[1] - box[0] + 2 * m) / dx) + 1, ny = soil ? (int)ceil((box[3] - box[2] + 2 * m) / dx) + 1 : 2;
    double dy = soil ? dx : box[3] - box[2] + 2 * m;
    /* with a soil, the sinkage at each sample after the heights */
    sim->ground_grid = malloc(sizeof *sim->ground_grid + (size_t)(soil ? 2 : 1) * nx * ny * sizeof sim->ground_grid->z[0]);
    if (!sim->ground_grid)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", sim->sc->path);
    sim->ground_grid->sampled = 0;
    sim->scene_ground = (fs_scene_ground){nx, ny, box[0] - m, box[2] - m, dx, dy, sim->ground_grid->z, !steps && !soil,
                                          soil ? sim->ground_grid->z + (size_t)nx * ny : NULL};
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
    } else {
        sim->geom = fs_scenario_geometry(sc, &sim->own_geom); /* a biped's: two feet and the legs */
    }
    double tilt = s->tilt_deg * DEG;
    sim->down[0] = sin(tilt);
    sim->down[2] = -cos(tilt);
    sim->world = dWorldCreate();
    /* quickstep reorders its constraints with ODE's one global random generator: each sim starts
     * its own sequence (fs_sim_step sets and saves it), so a run depends on nothing else in the process */
    sim->rand_seed = 0;
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
        int ok = 1;
        /* a heightfield is ODE geometry only when ODE tests the shapes against it
           (run.heightfield_contacts = ode; footsim's own tests: sim_lattice.h) */
        if (!fs_terrain_is_heightfield(&sc->terrain) || s->heightfield_ode)
            sim->heightfield = fs_ground_build(sim->ground, &sc->terrain, s->tile_cells, &ok);
        if (!ok)
            return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the terrain", sc->path);
    }
    sim->robot_merged = !opts->keep_robot_body && robot_merges(sim);
    /* a merged robot's ankle body is made last, as the robot's own body was: the order bodies are
     * made in sets the order of the rows ODE's direct solver pivots through (made in index order,
     * the contact steps of a landing took 16 % more instructions than with the fixed joint; made
     * last, 13 % fewer: docs/bench.md, Leaner step) */
    for (int i = 0; i < sim->geom->nbodies; i++)
        if (!sim->robot_merged || i != sim->geom->ankle_body)
            build_body(sim, i);
    if (sim->robot_merged)
        build_body(sim, sim->geom->ankle_body);
    build_shapes(sim);
    build_joints(sim);
    if (s->robot.mass_kg > 0 && !sim->robot_merged && !sim->geom->biped)
        build_robot(sim);
    if (opts->hold_rear_foot && sim->geom->kind == FS_FOOT_BIOMIMETIC) {
        dBodySetKinematic(sim->body[FS_BODY_HEEL]);
        dBodySetKinematic(sim->body[FS_BODY_TALUS]);
    }
    const fs_vec3 a = place(sim, sim->geom->ankle);
    dBodyGetPosRelPoint(sim->body[sim->geom->ankle_body], a.x, a.y, a.z, sim->ankle_local);
    for (int f = 0; f < sim->geom->nfeet; f++) {
        const fs_vec3 fa = place(sim, sim->geom->foot[f].ankle);
        dBodyGetPosRelPoint(sim->body[sim->geom->foot[f].ankle_body], fa.x, fa.y, fa.z, sim->foot_ankle_local[f]);
    }
    sim->load_N = s->load_kg * s->gravity_m_per_s2 / share;
    contact_template(sim);
    sim->chain_plane_friction = opts->chain_plane_friction && sim->geom->kind == FS_FOOT_BIOMIMETIC;
    if (sim->chain_plane_friction)
        grip_directions(sim);
    body_reach(sim);
    sim->profile = opts->profile;
    fs_status made = fs_sim_adapt_init(sim, err);
    if (made == FS_OK)
        made = fs_sim_soil_build(sim, err);
    return made == FS_OK ? scene_ground(sim, err) : made;
}

typedef struct build_call {
    fs_sim *sim;
    const fs_scenario *sc;
    const fs_sim_options *opts;
} build_call;

static fs_status build_guarded(void *arg, fs_error *err)
{
    build_call *c = arg;
    return build(c->sim, c->sc, c->opts, err);
}

fs_status fs_sim_build(fs_sim *sim, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err)
{
    fs_sim_options normal = {.with_ground = 1, .hold_rear_foot = 0};
    memset(sim, 0, sizeof *sim);
    build_call call = {sim, sc, opts ? opts : &normal};
    fs_status s = fs_ode_guard(build_guarded, &call, NULL, err); /* an ODE error: FS_NUMERICAL, not an exit */
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
    fs_sim_adapt_free(sim);
    free(sim->ground_grid);
    fs_sim_soil_destroy(sim);
    fs_ode_context_leave(sim->ode_context);
    memset(sim, 0, sizeof *sim);
}
