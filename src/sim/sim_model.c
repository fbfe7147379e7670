/* sim_model.c: a scenario compiled into the model a simulation is made of (fs_model.h): every
 * decision sim_build.c took from the scenario before (masses, poses, shapes, joints, springs, the
 * robot, the contacts, the start pose), with no ODE object made. ODE's mass arithmetic (dMass) is
 * used as arithmetic only, so the numbers are the ones a world built from them holds. */
#include "footsim/sim/fs_model.h"

#include "sim_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define DEG (M_PI / 180.0)

/* Two materials in contact: friction as the geometric mean, stiffness and damping in series. */
static double series(double a, double b) { return a > 0 && b > 0 ? a * b / (a + b) : 0; }

static void contacts(fs_model *m)
{
    const fs_design_def *d = &m->sc->design;
    const fs_terrain_def *t = &m->sc->terrain.def;
    m->mu = sqrt(d->sole_mu * t->mu);
    m->restitution = t->restitution > 0 ? t->restitution : 0;
    m->bounce_speed_m_per_s = 0.01; /* m/s: slower impacts do not bounce */
    m->contact_k_N_per_m = series(d->sole_stiffness_N_per_m, t->stiffness_N_per_m);
    m->contact_c_Ns_per_m = series(d->sole_damping_Ns_per_m, t->damping_Ns_per_m);
    fs_spring_soft(m->sc->def.step_s, m->contact_k_N_per_m, m->contact_c_Ns_per_m, m->sc->def.damping_correction,
                   &m->contact_erp, &m->contact_cfm);
}

/* ---- the ground ------------------------------------------------------------------------------ */

static void plane(fs_model *m, double nx, double ny, double nz, double offset)
{
    fs_model_plane *p = &m->plane[m->nplanes++];
    p->normal[0] = nx, p->normal[1] = ny, p->normal[2] = nz, p->offset_m = offset;
}

/* Steps as blocks (sharp edges) on a plane at the lowest level. */
static fs_status steps(fs_model *m, const fs_terrain *t, fs_error *err)
{
    const fs_terrain_def *d = &t->def;
    const double far = 100.0; /* m: the steps' ends and sides reach beyond any trial */
    int two_ways = d->step_pattern == FS_STEPS_UP_DOWN || d->step_pattern == FS_STEPS_DOWN_UP;
    int k = two_ways ? 2 * d->step_count : d->step_count;
    double base = d->step_pattern == FS_STEPS_DOWN || d->step_pattern == FS_STEPS_DOWN_UP ? -d->step_rise_m * d->step_count : 0;
    plane(m, 0, 0, 1, base);
    m->block = malloc((size_t)(k + 2) * sizeof *m->block);
    if (!m->block)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the terrain's steps");
    for (int i = -1; i <= k; i++) {
        double x0 = i < 0 ? d->step_start_x_m - far : d->step_start_x_m + i * d->step_run_m;
        double x1 = i < 0 ? d->step_start_x_m : i == k ? x0 + far : x0 + d->step_run_m;
        double level = fs_terrain_height(t, 0.5 * (x0 + x1), 0);
        if (level <= base)
            continue;
        double depth = level - base + 0.05;
        fs_model_block *b = &m->block[m->nblocks++];
        b->size_m[0] = x1 - x0, b->size_m[1] = 2 * far, b->size_m[2] = depth;
        b->pos_m[0] = 0.5 * (x0 + x1), b->pos_m[1] = 0, b->pos_m[2] = level - 0.5 * depth;
    }
    return FS_OK;
}

/* The terrain as the ground's shapes: a plane (flat, slope), a plane and blocks (stepped), or the
 * lattice (every other kind). */
fs_status fs_model_ground(fs_model *m, const fs_terrain *t, fs_error *err)
{
    switch (t->def.kind) {
    case FS_TERRAIN_FLAT: plane(m, 0, 0, 1, 0); return FS_OK;
    case FS_TERRAIN_SLOPE: {
        double a = t->def.slope_deg * DEG;
        plane(m, -sin(a), 0, cos(a), 0);
        return FS_OK;
    }
    case FS_TERRAIN_STEPPED: return steps(m, t, err);
    default: m->heightfield = 1; return FS_OK;
    }
}

/* ---- the start pose ------------------------------------------------------------------------ */

static fs_vec3 turn(const fs_model *m, fs_vec3 v)
{
    const double *R = m->R0;
    return fs_v3(R[0] * v.x + R[1] * v.y + R[2] * v.z, R[3] * v.x + R[4] * v.y + R[5] * v.z,
                 R[6] * v.x + R[7] * v.y + R[8] * v.z);
}

static fs_vec3 place(const fs_model *m, fs_vec3 p) { return fs_add(turn(m, p), fs_v3(m->t0[0], m->t0[1], m->t0[2])); }

static void put(double out[3], fs_vec3 v)
{
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

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
static double start_lift(const fs_model *m)
{
    const fs_foot_geom *g = m->geom;
    const fs_terrain *t = &m->sc->terrain;
    double lift = -INFINITY, xlo = INFINITY, xhi = -INFINITY; /* and the foot's extent along x */
    for (int i = 0; i < g->nspheres; i++) {
        fs_vec3 c = place(m, g->sphere[i].centre);
        double r = g->sphere[i].radius_m;
        lift = fmax(lift, terrain_top(t, c.x, c.y, r) - (c.z - r));
        xlo = fmin(xlo, c.x - r), xhi = fmax(xhi, c.x + r);
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
            fs_vec3 pc = place(m, corner);
            lowest = fmin(lowest, pc.z);
            xlo = fmin(xlo, pc.x), xhi = fmax(xhi, pc.x);
        }
        double spacing = fs_terrain_is_heightfield(t) && t->dx > 0 ? 0.5 * t->dx : 0.002;
        int nx = (int)ceil(g->box_size.x / spacing) + 1, ny = (int)ceil(g->box_size.y / spacing) + 1;
        for (int i = 0; i < nx; i++)
            for (int j = 0; j < ny; j++) {
                fs_vec3 p = fs_v3(bc.x + (i / (double)(nx - 1) - 0.5) * g->box_size.x,
                                  bc.y + (j / (double)(ny - 1) - 0.5) * g->box_size.y, 0);
                p = place(m, p);
                top = fmax(top, fs_terrain_height(t, p.x, p.y));
            }
        lift = fmax(lift, top - lowest);
    }
    if (m->sc->terrain.def.soil.model != FS_SOIL_NONE) /* drop_m above the soil's surface, where its section lies */
        lift += fs_soil_depth_over(&m->sc->terrain.def.soil, xlo, xhi);
    return lift + m->sc->def.drop_m;
}

/* ---- bodies ----------------------------------------------------------------------------------- */

/* Whether the robot becomes part of the ankle body (a rigid robot, free, not the walking machine's,
 * whose carriage holds the robot's own body): its fixed joint's 6 rows a step saved, the same
 * rigid assembly. */
static int robot_merges(const fs_model *m)
{
    const fs_scenario_def *s = &m->sc->def;
    return s->robot.mass_kg > 0 && s->robot.kind == FS_ROBOT_SINGLE && s->robot.joint == FS_ROBOT_RIGID && s->robot.mount == FS_ROBOT_FREE &&
           s->kind != FS_SCENARIO_WALK && m->geom->npins == 0;
}

/* The robot's centre of mass in the design frame (its frame is the foot's at the start). */
static fs_vec3 robot_com(const fs_model *m)
{
    const fs_robot_def *r = &m->sc->def.robot;
    return fs_add(m->geom->ankle, fs_v3(r->com_forward_m, 0, r->com_height_m));
}

/* The robot's mass about its centre, in its frame. */
static void robot_mass(const fs_model *m, dMass *mass)
{
    double I[3];
    fs_robot_inertia(&m->sc->def.robot, I);
    dMassSetParameters(mass, m->sc->def.robot.mass_kg, 0, 0, 0, I[0], I[1], I[2], 0, 0, 0);
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

/* A dMass into the model's body (the inverse is fs_model_mass in sim_build.c). */
static void keep_mass(fs_model_body *b, const dMass *mass)
{
    b->mass_kg = mass->mass;
    for (int k = 0; k < 3; k++)
        b->centre_m[k] = mass->c[k];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            b->inertia_kg_m2[3 * r + c] = mass->I[4 * r + c];
}

/* Body i's mass; for the ankle body with a merged robot, the robot's added at its centre (the two
 * frames are alike), and the body's centre moved to the combined one (ODE keeps a body's centre at
 * its origin): com_design_m says where, in the design frame. */
static void body_mass(fs_model *m, int i)
{
    const fs_body_geom *g = &m->geom->body[i];
    const double *I = g->inertia;
    fs_model_body *b = &m->body[i];
    dMass mass;
    dMassSetParameters(&mass, g->mass_kg, 0, 0, 0, I[0], I[4], I[8], I[1], I[2], I[5]);
    fs_vec3 com = g->com;
    if (i == m->geom->ankle_body && m->robot_merged) {
        dMass r;
        robot_mass(m, &r);
        fs_vec3 d = fs_sub(robot_com(m), g->com);
        dMassTranslate(&r, d.x, d.y, d.z);
        dMassAdd(&mass, &r);
        com = fs_add(g->com, fs_v3(mass.c[0], mass.c[1], mass.c[2]));
        dMassTranslate(&mass, -mass.c[0], -mass.c[1], -mass.c[2]);
        put(m->robot_local_m, fs_sub(robot_com(m), com));
    }
    inertia_floor(&mass, m->sc->def.min_inertia_kg_m2);
    keep_mass(b, &mass);
    put(b->com_design_m, com);
    put(b->pos_m, place(m, com));
    b->name = g->name;
}

static fs_vec3 com_of(const fs_model *m, int body)
{
    const double *c = m->body[body].com_design_m;
    return fs_v3(c[0], c[1], c[2]);
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

static void shapes(fs_model *m)
{
    const fs_foot_geom *g = m->geom;
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        fs_model_shape *sh = &m->shape[m->nshapes++];
        sh->kind = FS_MODEL_SPHERE;
        sh->body = s->body;
        sh->foot = foot_of_body(g, s->body);
        sh->radius_m = s->radius_m;
        put(sh->offset_m, fs_sub(s->centre, com_of(m, s->body)));
        sh->match_m = s->radius_m / 4; /* far more than a contact moves in a step */
    }
    for (int b = 0; b < g->nboxes; b++) {
        fs_model_shape *sh = &m->shape[m->nshapes++];
        sh->kind = FS_MODEL_BOX;
        sh->body = g->box[b].body;
        sh->foot = foot_of_body(g, sh->body);
        put(sh->size_m, g->box_size);
        put(sh->offset_m, fs_sub(g->box[b].centre, com_of(m, sh->body)));
        sh->match_m = fmin(g->box_size.x, g->box_size.y) / 4; /* corners lie farther apart */
    }
}

/* With chain_plane_friction: each sphere grips along the horizontal line of its chain's plane
 * (metatarsal and phalanx: midfoot joint to toe), the heel's and talus's along the foot's x. */
static void grip_directions(fs_model *m)
{
    const fs_foot_geom *g = m->geom;
    for (int i = 0; i < g->nspheres; i++) {
        fs_vec3 d = fs_v3(1, 0, 0);
        for (int c = 0; c < FS_CHAINS; c++)
            if (g->sphere[i].body == g->chain[c].metatarsal || g->sphere[i].body == g->chain[c].phalanx)
                d = fs_sub(g->chain[c].toe, g->chain[c].midfoot);
        d = turn(m, d);
        double len = hypot(d.x, d.y);
        m->shape[i].grip_dir[0] = d.x / len, m->shape[i].grip_dir[1] = d.y / len, m->shape[i].grip_dir[2] = 0;
    }
}

static void spring_of(const fs_model *m, fs_model_spring *s, const char *name, int body1, int body2, fs_vec3 p1,
                      fs_vec3 p2, double k, double c, double rest)
{
    s->name = name;
    s->body1 = body1;
    s->body2 = body2;
    put(s->p1_m, p1);
    put(s->p2_m, p2);
    s->k_N_per_m = k;
    s->c_Ns_per_m = c;
    s->rest_length_m = rest;
    s->law = fs_spring_law_linear(k);
    (void)m;
}

static void joints(fs_model *m)
{
    const fs_foot_geom *g = m->geom;
    m->nhinges = g->nhinges;
    for (int i = 0; i < g->nhinges; i++) {
        const fs_hinge_geom *h = &g->hinge[i];
        fs_model_hinge *j = &m->hinge[i];
        j->body1 = h->body1;
        j->body2 = h->body2;
        put(j->anchor_m, place(m, h->anchor));
        put(j->axis, turn(m, h->axis));
        j->spring = fs_hinge_has_spring(h);
        j->k_N_m_per_rad = h->k_N_m_per_rad;
        j->c_N_m_s_per_rad = h->c_N_m_s_per_rad;
    }
    m->npins = g->npins;
    for (int i = 0; i < g->npins; i++) {
        m->pin[i].body1 = g->pin[i].body;
        m->pin[i].body2 = -1;
        put(m->pin[i].anchor_m, place(m, g->pin[i].anchor));
        put(m->pin[i].axis, turn(m, g->pin[i].axis));
    }
    m->nsprings = g->nsprings;
    for (int i = 0; i < g->nsprings; i++) {
        const fs_spring_geom *s = &g->spring[i];
        spring_of(m, &m->spring[i], s->name, s->body1, s->body2, place(m, s->p1), place(m, s->p2), s->k_N_per_m,
                  s->c_Ns_per_m, s->rest_length_m);
        m->spring[i].law = s->law;
    }
}

/* The passive body on the ankle (unless merged into the ankle body, body_mass): rigidly fixed, or
 * hinged at the ankle with an Achilles spring-damper from the ankle body, 2 cm behind the joint, to
 * the leg; free, or on a vertical slide to the world (fs_robot.h). (The tendon ends on the talus, not
 * the heel: here the heel turns about the same ankle axis as the leg would, so a heel-to-leg tendon
 * would let leg and heel fold together about it unresisted.) */
static void robot(fs_model *m)
{
    const fs_scenario_def *s = &m->sc->def;
    const fs_foot_geom *g = m->geom;
    fs_model_body *b = &m->body[m->nbodies];
    m->robot_body = 1;
    dMass mass;
    robot_mass(m, &mass);
    keep_mass(b, &mass);
    put(b->com_design_m, robot_com(m));
    put(b->pos_m, place(m, robot_com(m)));
    b->reach_m = s->robot.com_height_m;
    b->name = "robot";
    m->robot_vertical = s->robot.mount == FS_ROBOT_VERTICAL;
    m->robot_joint = s->robot.joint;
    if (s->robot.joint == FS_ROBOT_RIGID)
        return;
    put(m->robot_hinge_anchor_m, place(m, g->ankle));
    put(m->robot_hinge_axis, turn(m, fs_v3(0, 1, 0)));
    const double behind = FS_ACHILLES_LEVER_M; /* the tendon's line behind the ankle axis */
    fs_vec3 heel = place(m, fs_add(g->ankle, fs_v3(-behind, 0, -0.01)));
    fs_vec3 leg = place(m, fs_add(g->ankle, fs_v3(-behind, 0, s->robot.achilles_leg_anchor_m)));
    spring_of(m, &m->achilles, "achilles", g->ankle_body, m->nbodies, heel, leg, s->robot.achilles_k_N_per_m,
              s->robot.achilles_c_Ns_per_m, fs_norm(fs_sub(leg, heel)));
    m->has_achilles = 1;
}

/* How far each body's points (joints, spring anchors, shapes) lie from its own COM (a merged
 * robot's ankle body too: its speed is taken at the foot's part's COM, fs_sim_body_speed). */
static void body_reach(fs_model *m)
{
    const fs_foot_geom *g = m->geom;
    for (int i = 0; i < g->nhinges; i++) {
        const fs_hinge_geom *h = &g->hinge[i];
        for (int k = 0; k < 2; k++) {
            int b = k ? h->body2 : h->body1;
            m->body[b].reach_m = fmax(m->body[b].reach_m, fs_norm(fs_sub(h->anchor, g->body[b].com)));
        }
    }
    for (int i = 0; i < g->nsprings; i++) {
        const fs_spring_geom *s = &g->spring[i];
        m->body[s->body1].reach_m = fmax(m->body[s->body1].reach_m, fs_norm(fs_sub(s->p1, g->body[s->body1].com)));
        m->body[s->body2].reach_m = fmax(m->body[s->body2].reach_m, fs_norm(fs_sub(s->p2, g->body[s->body2].com)));
    }
    for (int i = 0; i < g->nspheres; i++) {
        const fs_sphere_geom *s = &g->sphere[i];
        double r = fs_norm(fs_sub(s->centre, g->body[s->body].com)) + s->radius_m;
        m->body[s->body].reach_m = fmax(m->body[s->body].reach_m, r);
    }
    for (int k = 0; k < g->nboxes; k++) {
        const int b = g->box[k].body;
        m->body[b].reach_m = fmax(m->body[b].reach_m,
                                  fs_norm(fs_sub(g->box[k].centre, g->body[b].com)) + 0.5 * fs_norm(g->box_size));
    }
    const int a = g->ankle_body;
    m->body[a].reach_m = fmax(m->body[a].reach_m, fs_norm(fs_sub(g->ankle, g->body[a].com)));
}

static fs_status compile(fs_model *m, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err)
{
    m->sc = sc;
    m->opts = *opts;
    m->opts.profile = NULL;
    const fs_scenario_def *s = &sc->def;
    int share = 1;
    if (opts->pinned_chain) {
        fs_status made = fs_design_pinned_chain(&sc->design, &sc->geom, opts->pinned_chain - 1, &m->own_geom, err);
        if (made != FS_OK)
            return made;
        m->geom = &m->own_geom;
        share = FS_CHAINS;
    } else {
        m->geom = fs_scenario_geometry(sc, &m->own_geom); /* a biped's: two feet and the legs */
    }
    const fs_foot_geom *g = m->geom;
    double tilt = s->tilt_deg * DEG;
    m->down[0] = sin(tilt);
    m->down[2] = -cos(tilt);
    m->gravity_m_per_s2[0] = s->gravity_m_per_s2 * m->down[0];
    m->gravity_m_per_s2[2] = s->gravity_m_per_s2 * m->down[2]; /* [1]: 0, as the world has always had it */
    start_rotation(s, m->R0);
    const double *R = m->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dRtoQ(rot, m->q0_wxyz); /* as dBodySetRotation keeps it */
    dNormalize4(m->q0_wxyz);
    m->t0[0] = s->start_x_m;
    m->t0[1] = s->start_y_m;
    m->t0[2] = 0;
    m->with_ground = opts->with_ground && !opts->pinned_chain;
    if (m->with_ground) {
        m->t0[2] = start_lift(m);
        fs_status made = fs_model_ground(m, &sc->terrain, err);
        if (made != FS_OK)
            return made;
    }
    m->nbodies = g->nbodies;
    m->robot_merged = !opts->keep_robot_body && robot_merges(m);
    for (int i = 0; i < g->nbodies; i++)
        body_mass(m, i);
    shapes(m);
    joints(m);
    m->spring_impl = s->springs;
    m->damping_correction = s->damping_correction;
    if (s->robot.mass_kg > 0 && !m->robot_merged && !g->biped)
        robot(m);
    if (opts->hold_rear_foot && g->kind == FS_FOOT_BIOMIMETIC)
        m->body[FS_BODY_HEEL].kinematic = m->body[FS_BODY_TALUS].kinematic = 1;
    put(m->ankle_m, place(m, g->ankle));
    for (int f = 0; f < g->nfeet; f++)
        put(m->foot_ankle_m[f], place(m, g->foot[f].ankle));
    m->load_N = s->load_kg * s->gravity_m_per_s2 / share;
    contacts(m);
    m->chain_plane_friction = opts->chain_plane_friction && g->kind == FS_FOOT_BIOMIMETIC;
    if (m->chain_plane_friction)
        grip_directions(m);
    body_reach(m);
    return FS_OK;
}

fs_status fs_model_compile(const fs_scenario *sc, const fs_sim_options *opts, fs_model **out, fs_error *err)
{
    fs_sim_options normal = {.with_ground = 1, .hold_rear_foot = 0};
    fs_model *m = calloc(1, sizeof *m);
    *out = NULL;
    if (!m)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the model", sc->path);
    fs_status s = compile(m, sc, opts ? opts : &normal, err);
    if (s != FS_OK) {
        fs_model_free(m);
        return s;
    }
    *out = m;
    return FS_OK;
}

void fs_model_free(fs_model *m)
{
    if (!m)
        return;
    free(m->block);
    free(m);
}
