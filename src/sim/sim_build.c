/* sim_build.c: a simulation made in ODE from its model (fs_model.h, compiled in sim_model.c): the
 * world, bodies, shapes, joints, springs, the robot and the ground, and taken down again. Nothing
 * here decides a number of the model; it only makes ODE's objects of them, in a fixed order. The
 * step is sim_step.c. */
#include "footsim/sim/fs_model.h"

#include "sim_internal.h"
#include "sim_soil.h"

#include "sim_ground.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put(double out[3], const double in[3]) { memcpy(out, in, 3 * sizeof(double)); }

/* The contact joints' surface from the model's materials, soft for the scenario's step. */
static void contact_template(fs_sim *sim)
{
    const fs_model *m = sim->model;
    dContact *ct = &sim->contact_template;
    memset(ct, 0, sizeof *ct);
    ct->surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
    ct->surface.mu = m->mu;
    if (m->restitution > 0) {
        ct->surface.mode |= dContactBounce;
        ct->surface.bounce = m->restitution;
        ct->surface.bounce_vel = m->bounce_speed_m_per_s;
    }
    sim->contact_k_N_per_m = m->contact_k_N_per_m;
    sim->contact_c_Ns_per_m = m->contact_c_Ns_per_m;
    fs_sim_soften_contacts(sim, sim->sc->def.step_s);
    sim->step_now_s = sim->sc->def.step_s;
}

/* A model body's mass as ODE's dMass, bit for bit what the model kept of it (sim_model.c). */
static void model_mass(const fs_model_body *b, dMass *mass)
{
    dMassSetZero(mass);
    mass->mass = b->mass_kg;
    for (int k = 0; k < 3; k++)
        mass->c[k] = b->centre_m[k];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            mass->I[4 * r + c] = b->inertia_kg_m2[3 * r + c];
}

/* A body at its start pose (rotation R0) with its mass. */
static dBodyID make_body(const fs_sim *sim, const fs_model_body *b)
{
    dBodyID id = dBodyCreate(sim->world);
    dMass m;
    model_mass(b, &m);
    dBodySetMass(id, &m);
    dBodySetPosition(id, b->pos_m[0], b->pos_m[1], b->pos_m[2]);
    const double *R = sim->R0;
    dMatrix3 rot = {R[0], R[1], R[2], 0, R[3], R[4], R[5], 0, R[6], R[7], R[8], 0};
    dBodySetRotation(id, rot);
    return id;
}

static void build_body(fs_sim *sim, int i)
{
    const fs_model_body *b = &sim->model->body[i];
    sim->com[i] = fs_v3(b->com_design_m[0], b->com_design_m[1], b->com_design_m[2]);
    sim->body[i] = make_body(sim, b);
}

static void build_shapes(fs_sim *sim)
{
    const fs_model *m = sim->model;
    for (int i = 0; i < m->nshapes; i++) {
        const fs_model_shape *s = &m->shape[i];
        dGeomID geom = s->kind == FS_MODEL_SPHERE ? dCreateSphere(sim->space, s->radius_m)
                                                  : dCreateBox(sim->space, s->size_m[0], s->size_m[1], s->size_m[2]);
        dGeomSetBody(geom, sim->body[s->body]);
        dGeomSetOffsetPosition(geom, s->offset_m[0], s->offset_m[1], s->offset_m[2]);
        sim->shape_foot[i] = s->foot;
        sim->match_m[i] = s->match_m;
        if (m->chain_plane_friction && s->kind == FS_MODEL_SPHERE)
            put(sim->grip_dir[i], s->grip_dir);
        sim->shape[i] = geom;
    }
    sim->nshapes = m->nshapes;
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

static dJointID hinge_of(const fs_sim *sim, const fs_model_hinge *h)
{
    dJointID j = dJointCreateHinge(sim->world, 0);
    dJointAttach(j, sim->body[h->body1], h->body2 < 0 ? 0 : sim->body[h->body2]);
    dJointSetHingeAnchor(j, h->anchor_m[0], h->anchor_m[1], h->anchor_m[2]);
    dJointSetHingeAxis(j, h->axis[0], h->axis[1], h->axis[2]);
    return j;
}

/* A model's spring-damper between ODE bodies b1 and b2. */
static void spring_of(const fs_sim *sim, fs_spring *s, const fs_model_spring *ms, dBodyID b1, dBodyID b2)
{
    fs_sim_spring_init(sim, s, b1, b2, ms->p1_m, ms->p2_m, ms->k_N_per_m, ms->c_Ns_per_m, ms->rest_length_m);
    if (!fs_spring_law_is_linear(&ms->law)) /* Table I's linear springs: as they always were */
        fs_spring_set_law(s, &ms->law);
}

static void build_joints(fs_sim *sim)
{
    const fs_model *m = sim->model;
    for (int i = 0; i < m->nhinges; i++) {
        const fs_model_hinge *h = &m->hinge[i];
        dJointID j = hinge_of(sim, h);
        if (h->spring)
            angular_spring(sim, j, h->k_N_m_per_rad, h->c_N_m_s_per_rad, sim->sc->def.step_s);
        sim->hinge[i] = j;
    }
    for (int i = 0; i < m->npins; i++)
        sim->pin[i] = hinge_of(sim, &m->pin[i]);
    for (int i = 0; i < m->nsprings; i++) {
        const fs_model_spring *s = &m->spring[i];
        spring_of(sim, &sim->spring[i], s, sim->body[s->body1], sim->body[s->body2]);
    }
}

/* ---- the robot ---------------------------------------------------------------------------- */

/* The robot's own body on the ankle body (fs_model.h; sim_model.c says how it is decided). */
static void build_robot(fs_sim *sim)
{
    const fs_model *m = sim->model;
    dBodyID ankle_body = sim->body[sim->geom->ankle_body];
    sim->robot = make_body(sim, &m->body[m->nbodies]);
    if (m->robot_vertical) { /* the carriage's slide: up and down only */
        dJointID slide = dJointCreateSlider(sim->world, 0);
        dJointAttach(slide, sim->robot, 0);
        dJointSetSliderAxis(slide, 0, 0, 1);
    }
    if (m->robot_joint == FS_ROBOT_RIGID) {
        sim->robot_joint = dJointCreateFixed(sim->world, 0);
        dJointAttach(sim->robot_joint, sim->robot, ankle_body);
        dJointSetFixed(sim->robot_joint);
        return;
    }
    const double *a = m->robot_hinge_anchor_m, *axis = m->robot_hinge_axis;
    sim->robot_joint = dJointCreateHinge(sim->world, 0);
    dJointAttach(sim->robot_joint, sim->robot, ankle_body);
    dJointSetHingeAnchor(sim->robot_joint, a[0], a[1], a[2]);
    dJointSetHingeAxis(sim->robot_joint, axis[0], axis[1], axis[2]);
    spring_of(sim, &sim->achilles, &m->achilles, ankle_body, sim->robot);
    sim->has_achilles = m->has_achilles;
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

static fs_status build(fs_sim *sim, const fs_model *m, fs_error *err)
{
    const fs_scenario *sc = m->sc;
    snprintf(sim->ode_context, sizeof sim->ode_context, "%s", sc->path);
    fs_ode_context(sim->ode_context); /* ODE's complaints name the scenario */
    sim->feedback = calloc(FS_MAX_STEP_CONTACTS, sizeof *sim->feedback);
    sim->scratch = malloc(sizeof *sim->scratch);
    if (!sim->feedback || !sim->scratch)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", sc->path);
    sim->model = m;
    sim->sc = sc;
    sim->geom = m->geom;
    sim->check.record_drift = m->opts.record_drift;
    const fs_scenario_def *s = &sc->def;
    put(sim->down, m->down);
    sim->world = dWorldCreate();
    /* quickstep reorders its constraints with ODE's one global random generator: each sim starts
     * its own sequence (fs_sim_step sets and saves it), so a run depends on nothing else in the process */
    sim->rand_seed = 0;
    dWorldSetGravity(sim->world, m->gravity_m_per_s2[0], m->gravity_m_per_s2[1], m->gravity_m_per_s2[2]);
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
    memcpy(sim->R0, m->R0, sizeof sim->R0);
    put(sim->t0, m->t0);
    if (m->with_ground) {
        /* a hash space: a heightfield comes as many tiles */
        sim->ground = dHashSpaceCreate(0);
        int ok = 1;
        /* a heightfield is ODE geometry only when ODE tests the shapes against it
           (run.heightfield_contacts = ode; footsim's own tests: sim_lattice.h) */
        if (!fs_terrain_is_heightfield(&sc->terrain) || s->heightfield_ode)
            sim->heightfield = fs_ground_build(sim->ground, m, &sc->terrain, s->tile_cells, &ok);
        if (!ok)
            return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the terrain", sc->path);
    }
    sim->robot_merged = m->robot_merged;
    put(sim->robot_local, m->robot_local_m);
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
    if (m->robot_body)
        build_robot(sim);
    for (int i = 0; i < sim->geom->nbodies; i++)
        if (m->body[i].kinematic)
            dBodySetKinematic(sim->body[i]);
    const double *a = m->ankle_m;
    dBodyGetPosRelPoint(sim->body[sim->geom->ankle_body], a[0], a[1], a[2], sim->ankle_local);
    for (int f = 0; f < sim->geom->nfeet; f++) {
        const double *fa = m->foot_ankle_m[f];
        dBodyGetPosRelPoint(sim->body[sim->geom->foot[f].ankle_body], fa[0], fa[1], fa[2], sim->foot_ankle_local[f]);
    }
    sim->load_N = m->load_N;
    contact_template(sim);
    sim->chain_plane_friction = m->chain_plane_friction;
    for (int i = 0; i < sim->geom->nbodies; i++)
        sim->reach[i] = m->body[i].reach_m;
    sim->profile = m->opts.profile;
    fs_status made = fs_sim_adapt_init(sim, err);
    if (made == FS_OK)
        made = fs_sim_soil_build(sim, err);
    return made == FS_OK ? scene_ground(sim, err) : made;
}

typedef struct build_call {
    fs_sim *sim;
    const fs_model *m;
} build_call;

static fs_status build_guarded(void *arg, fs_error *err)
{
    build_call *c = arg;
    return build(c->sim, c->m, err);
}

/* Builds m into sim, which owns own (m, or NULL) from then on, on failure too. */
static fs_status build_from(fs_sim *sim, const fs_model *m, fs_model *own, struct fs_profile *profile, fs_error *err)
{
    memset(sim, 0, sizeof *sim);
    sim->own_model = own;
    build_call call = {sim, m};
    long warned = fs_warning_count();
    fs_status s = fs_ode_guard(build_guarded, &call, NULL, err); /* an ODE error: FS_NUMERICAL, not an exit */
    sim->warnings = fs_warning_count() - warned;
    if (profile)
        sim->profile = profile;
    if (s != FS_OK)
        fs_sim_destroy(sim); /* whatever was made so far: a failed build leaves nothing behind */
    return s;
}

fs_status fs_sim_build(fs_sim *sim, const fs_scenario *sc, const fs_sim_options *opts, fs_error *err)
{
    fs_model *m;
    fs_status s = fs_model_compile(sc, opts, &m, err);
    if (s != FS_OK) {
        memset(sim, 0, sizeof *sim);
        return s;
    }
    return build_from(sim, m, m, opts ? opts->profile : NULL, err);
}

/* A new sim made from m, owning own (m, or NULL; freed on failure too). */
static fs_status new_sim(const fs_model *m, fs_model *own, struct fs_profile *profile, fs_sim **out, fs_error *err)
{
    fs_sim *sim = malloc(sizeof *sim);
    *out = NULL;
    if (!sim) {
        fs_model_free(own);
        return fs_fail(err, FS_NO_MEMORY, "%s: no memory for the simulation", m->sc->path);
    }
    fs_status s = build_from(sim, m, own, profile, err);
    if (s != FS_OK) {
        free(sim);
        return s;
    }
    *out = sim;
    return FS_OK;
}

fs_status fs_sim_create(const fs_model *m, struct fs_profile *profile, fs_sim **out, fs_error *err)
{
    return new_sim(m, NULL, profile, out, err);
}

const fs_model *fs_sim_model(const fs_sim *sim) { return sim->model; }

fs_status fs_sim_new(const fs_scenario *sc, const fs_sim_options *opts, fs_sim **out, fs_error *err)
{
    fs_model *m;
    *out = NULL;
    fs_status s = fs_model_compile(sc, opts, &m, err);
    return s == FS_OK ? new_sim(m, m, opts ? opts->profile : NULL, out, err) : s;
}

void fs_sim_free(fs_sim *sim)
{
    if (!sim)
        return;
    fs_sim_destroy(sim);
    free(sim);
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
    for (int i = 0; sim->geom && i < sim->geom->nsprings; i++)
        fs_spring_free(&sim->spring[i]); /* a cable's joint group */
    if (sim->world)
        dWorldDestroy(sim->world);
    free(sim->feedback);
    free(sim->scratch);
    fs_sim_adapt_free(sim);
    free(sim->ground_grid);
    fs_sim_soil_destroy(sim);
    fs_ode_context_leave(sim->ode_context);
    fs_model_free(sim->own_model);
    memset(sim, 0, sizeof *sim);
}
