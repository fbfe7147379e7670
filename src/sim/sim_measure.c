/* sim_measure.c: what a simulation's state measures now (energy, speeds, lean, penetration,
 * ground force, hinge angles, the ankle, the load): read from ODE, never changing it. */
#include "sim_internal.h"
#include "sim_soil.h"

#include "sim_ground.h"

#include <math.h>
#include <string.h>

double fs_sim_load_now_N(const fs_sim *sim)
{
    const fs_scenario_def *s = &sim->sc->def;
    return sim->load_N * (s->ramp_s > 0 && sim->time_s < s->ramp_s ? sim->time_s / s->ramp_s : 1.0);
}

void fs_sim_ankle(const fs_sim *sim, double p[3])
{
    dVector3 w;
    dBodyGetRelPointPos(sim->body[sim->geom->ankle_body], sim->ankle_local[0], sim->ankle_local[1],
                        sim->ankle_local[2], w);
    memcpy(p, w, 3 * sizeof(double));
}

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
    for (int i = 0; i < sim->geom->nhinges; i++) { /* a biped's leg joints' angular springs */
        double k = sim->geom->hinge[i].k_N_m_per_rad, a = k > 0 ? fs_sim_hinge_angle(sim, i) : 0;
        se += 0.5 * k * a * a;
    }
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

_Static_assert(sizeof(dReal) == sizeof(double), "footsim copies ODE's dReal as double: ODE must be built in double precision");

/* Body i, or for i = nbodies the body the robot moves with (its own, or the ankle body it is merged into). */
dBodyID fs_sim_body_id(const fs_sim *sim, int i) { return i == sim->geom->nbodies ? fs_sim_robot_body(sim) : sim->body[i]; }

void fs_sim_body_pose(const fs_sim *sim, int i, double p[3], double R[9])
{
    dBodyID b = fs_sim_body_id(sim, i);
    if (p)
        memcpy(p, dBodyGetPosition(b), 3 * sizeof(double));
    if (R) {
        const dReal *m = dBodyGetRotation(b); /* ODE's rows are 4 wide */
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                R[3 * r + c] = m[4 * r + c];
    }
}

void fs_sim_body_velocity(const fs_sim *sim, int i, double v[3], double w[3])
{
    dBodyID b = fs_sim_body_id(sim, i);
    if (v)
        memcpy(v, dBodyGetLinearVel(b), 3 * sizeof(double));
    if (w)
        memcpy(w, dBodyGetAngularVel(b), 3 * sizeof(double));
}

void fs_sim_robot_com(const fs_sim *sim, double p[3], double v[3])
{
    dBodyID b = fs_sim_robot_body(sim);
    if (!b)
        b = sim->body[sim->geom->ankle_body];
    const double *l = sim->robot_merged && !sim->geom->biped ? sim->robot_local : (const double[3]){0, 0, 0};
    dVector3 w;
    if (p) {
        dBodyGetRelPointPos(b, l[0], l[1], l[2], w);
        memcpy(p, w, 3 * sizeof(double));
    }
    if (v) {
        dBodyGetRelPointVel(b, l[0], l[1], l[2], w);
        memcpy(v, w, 3 * sizeof(double));
    }
}

double fs_sim_body_speed(const fs_sim *sim, int i)
{
    int robot = i == sim->geom->nbodies;
    dBodyID b = fs_sim_body_id(sim, i);
    const dReal *w = dBodyGetAngularVel(b);
    double v[3];
    if (robot) {
        fs_sim_robot_com(sim, NULL, v);
    } else if (sim->robot_merged && i == sim->geom->ankle_body) {
        /* the foot's part of the merged body: at its own COM, with its own reach */
        fs_vec3 l = fs_sub(sim->geom->body[i].com, sim->com[i]);
        dVector3 pv;
        dBodyGetRelPointVel(b, l.x, l.y, l.z, pv);
        memcpy(v, pv, sizeof v);
    } else {
        memcpy(v, dBodyGetLinearVel(b), sizeof v);
    }
    double reach = robot ? sim->sc->def.robot.com_height_m : sim->reach[i];
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + reach * sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

double fs_sim_max_speed(const fs_sim *sim)
{
    double vmax = 0;
    for (int i = 0; i < fs_sim_nbodies(sim); i++)
        vmax = fmax(vmax, fs_sim_body_speed(sim, i));
    return vmax;
}

double fs_sim_robot_tilt(const fs_sim *sim)
{
    dBodyID b = fs_sim_robot_body(sim);
    if (!b)
        return 0;
    const dReal *R = dBodyGetRotation(b);
    return acos(fmax(-1.0, fmin(1.0, R[10])));
}

/* With a soil the terrain is its bedrock: the soil's surface follows the shape it carries, so a shape
 * can sink only into the bedrock (docs/soil.md, What reads the ground). */
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

/* The body a foot's ankle is on (the ankle body of a one-foot sim). */
static dBodyID foot_ankle_body(const fs_sim *sim, int foot)
{
    return sim->body[sim->geom->nfeet > 1 ? sim->geom->foot[foot].ankle_body : sim->geom->ankle_body];
}

void fs_sim_soil_force(const fs_sim *sim, int foot, double force[3])
{
    if (sim->soil)
        memcpy(force, sim->soil->foot_force[1 + foot], 3 * sizeof(double));
    else
        force[0] = force[1] = force[2] = 0;
}

void fs_sim_foot_ankle(const fs_sim *sim, int foot, double p[3])
{
    const double *l = sim->geom->nfeet > 1 ? sim->foot_ankle_local[foot] : sim->ankle_local;
    dVector3 w;
    dBodyGetRelPointPos(foot_ankle_body(sim, foot), l[0], l[1], l[2], w);
    memcpy(p, w, 3 * sizeof(double));
}

/* The foot contact i of the last step is on: its shape's (-1 foot against foot). */
static int contact_foot(const fs_sim *sim, int i)
{
    int shape = sim->scratch->shape[i];
    return shape < 0 ? -1 : sim->shape_foot[shape];
}

void fs_sim_note_touch(fs_sim *sim, double h)
{
    int nfeet = sim->geom->nfeet > 1 ? sim->geom->nfeet : 1;
    for (int f = 0; f < nfeet; f++) {
        fs_touch *t = &sim->touch[f];
        if (t->touched)
            continue;
        int deepest = -1;
        for (int i = 0; i < sim->contacts_now; i++)
            if (contact_foot(sim, i) == f && (deepest < 0 || sim->contact_depth_m[i] > sim->contact_depth_m[deepest]))
                deepest = i;
        if (deepest < 0)
            continue;
        /* how long the deepest point has been sinking at its speed along the normal (at most h) */
        const double *n = sim->scratch->normal[deepest], *p = sim->contact_pos[deepest];
        dBodyID b = dGeomGetBody(sim->shape[sim->scratch->shape[deepest]]);
        dVector3 v;
        dBodyGetPointVel(b, p[0], p[1], p[2], v);
        double sink = v[0] * n[0] + v[1] * n[1] + v[2] * n[2]; /* n points out of the ground */
        double d = sim->contact_depth_m[deepest], back = sink < 0 ? fmin(h, d / -sink) : 0;
        double a[3];
        dVector3 va;
        fs_sim_foot_ankle(sim, f, a);
        dBodyGetPointVel(foot_ankle_body(sim, f), a[0], a[1], a[2], va);
        t->touched = 1;
        t->found_s = sim->time_s;
        t->time_s = sim->time_s - back;
        for (int k = 0; k < 3; k++)
            t->ankle_m[k] = a[k] - back * va[k];
    }
}

const fs_touch *fs_sim_first_touch(const fs_sim *sim, int foot) { return sim->touch[foot].touched ? &sim->touch[foot] : NULL; }

int fs_sim_foot_contacts(const fs_sim *sim, int foot)
{
    int n = 0;
    for (int i = 0; i < sim->contacts_now; i++)
        n += contact_foot(sim, i) == foot;
    return n;
}

/* The force of the last ODE step's contacts on foot (EVERY_CONTACT: all of them), in their order. */
enum { EVERY_CONTACT = -2 };
static void feedback_force(const fs_sim *sim, int foot, double force[3])
{
    force[0] = force[1] = force[2] = 0;
    for (int i = 0; i < sim->contacts_now; i++)
        if (foot == EVERY_CONTACT || contact_foot(sim, i) == foot)
            for (int k = 0; k < 3; k++)
                force[k] += sim->feedback[i].f1[k];
    if (sim->soil) { /* and the soil's, on the same feet */
        double s[3];
        fs_sim_soil_force(sim, foot == EVERY_CONTACT ? -1 : foot, s);
        for (int k = 0; k < 3; k++)
            force[k] += s[k];
    }
}

void fs_sim_add_step_force(fs_sim *sim, int substep, int n)
{
    int nfeet = sim->geom->nfeet > 1 ? sim->geom->nfeet : 1;
    for (int f = -1; f < nfeet; f++) {
        double x[3], *sum = sim->step_force[1 + f];
        feedback_force(sim, f < 0 ? EVERY_CONTACT : f, x);
        for (int k = 0; k < 3; k++)
            sum[k] = (substep ? sum[k] : 0) + x[k] / n;
    }
}

/* The force of the last step on foot: its ODE step's, or the mean over its substeps. */
static void contact_force(const fs_sim *sim, int foot, double force[3])
{
    if (sim->substeps_now > 1)
        memcpy(force, sim->step_force[foot == EVERY_CONTACT ? 0 : 1 + foot], 3 * sizeof(double));
    else
        feedback_force(sim, foot, force);
}

void fs_sim_foot_force(const fs_sim *sim, int foot, double force[3]) { contact_force(sim, foot, force); }

void fs_sim_ground_force(const fs_sim *sim, double force[3]) { contact_force(sim, EVERY_CONTACT, force); }

double fs_sim_hinge_angle(const fs_sim *sim, int i)
{
    /* ODE's hinge angle turns body1 about the axis relative to body2; ours turns body2 (distal). */
    return -dJointGetHingeAngle(sim->hinge[i]);
}

/* Whether a hinge's stop adds its row now: ODE's test (joint.cpp, testRotationalLimit): the angle at
 * or past lo or hi, with a stop set (lo = hi, the leg joints' springs: always). */
static int stop_active(dJointID j)
{
    double lo = dJointGetHingeParam(j, dParamLoStop), hi = dJointGetHingeParam(j, dParamHiStop);
    if (!(lo > -dInfinity) && !(hi < dInfinity))
        return 0;
    double a = dJointGetHingeAngle(j);
    return a <= lo || a >= hi;
}

void fs_sim_constraint_rows(const fs_sim *sim, fs_rows *rows)
{
    memset(rows, 0, sizeof *rows);
    /* every joint on a body, once (each is met from both its bodies): contacts are counted apart */
    enum { MAX_JOINTS = 4 * FS_MAX_BODIES + 16 };
    dJointID seen[MAX_JOINTS];
    int nseen = 0;
    for (int i = 0; i < sim->geom->nbodies + (sim->robot != NULL); i++) {
        dBodyID b = i < sim->geom->nbodies ? sim->body[i] : sim->robot;
        for (int k = 0; k < dBodyGetNumJoints(b); k++) {
            dJointID j = dBodyGetJoint(b, k);
            int known = 0;
            for (int m = 0; m < nseen; m++)
                known |= seen[m] == j;
            if (known || nseen == MAX_JOINTS)
                continue;
            seen[nseen++] = j;
            switch (dJointGetType(j)) {
            case dJointTypeHinge:
                rows->hinge += 5;
                rows->stop += stop_active(j);
                break;
            case dJointTypeFixed: rows->fixed += 6; break;
            case dJointTypeSlider: rows->slider += 5; break;
            case dJointTypeBall: rows->ball += 3; break;
            case dJointTypeDBall: rows->spring += 1; break;
            case dJointTypeContact: break;
            default: rows->other++; break;
            }
        }
    }
    for (int i = 0; i < sim->geom->nsprings; i++) /* a taut cable's one-sided row (a contact joint) */
        rows->spring += sim->spring[i].cable_row;
    rows->contacts = sim->contacts_now;
    rows->contact = sim->contacts_now * (sim->contact_template.surface.mu > 0 ? 3 : 1);
    rows->total = rows->hinge + rows->stop + rows->fixed + rows->slider + rows->ball + rows->spring + rows->contact +
                  rows->other;
}
