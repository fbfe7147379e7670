/* model_robot.c: the robot file's schema and loading it (fs_robot.h). */
#include "footsim/model/fs_robot.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define F(member) offsetof(fs_robot_def, member)
#define NUM(name, member, lo, hi, flags, unit, dflt, help) \
    {"robot", name, FS_KEY_NUMBER, F(member), lo, hi, flags, 0, NULL, unit, dflt, help}
#define POS FS_KEY_OPEN_MIN

#define DEG (M_PI / 180.0)

/* The single body's keys come first, the biped's from FIRST_BIPED_KEY on (each kind refuses the
 * other's). */
const fs_key fs_robot_keys[] = {
    {"robot", "kind", FS_KEY_CHOICE, F(kind), 0, 0, 0, 0, "single|biped", "", "single",
     "single: one rigid body on one foot (the keys up to mount); biped: a pelvis on two legs, each on its own "
     "copy of the foot (the keys from hip_width_m on; docs/landing.md)"},
    NUM("mass_kg", mass_kg, 0, 1e4, 0, "kg", "26", "the passive body on the ankle; half of the paper's 52 kg person is 26"),
    NUM("com_height_m", com_height_m, 0, 10, POS, "m", "0.3", "its centre of mass above the ankle"),
    NUM("com_forward_m", com_forward_m, -1, 1, 0, "m", "0.03",
        "its centre of mass ahead of the ankle (a biped: its pelvis's and legs' together, ahead of the ankles)"),
    {"robot", "inertia_kgm2", FS_KEY_LIST, F(inertia_kgm2), 0, 1e4, FS_KEY_OPEN_MIN, 3, NULL, "kg m^2", "1.4, 1.4, 0.1",
     "its principal moments of inertia about x, y, z at the centre of mass: a body's, each at most the other two together"},
    {"robot", "joint", FS_KEY_CHOICE, F(joint), 0, 0, 0, 0, "rigid|achilles", "", "rigid",
     "rigid: fixed to the ankle body; achilles: an ankle hinge with a heel-to-leg spring-damper"},
    NUM("achilles_k_N_per_m", achilles_k_N_per_m, 0, 1e9, POS, "N/m", "1e6",
        "Achilles tendon stiffness (2 cm behind the ankle: k (0.02 m)^2 must beat m g com_height)"),
    NUM("achilles_c_Ns_per_m", achilles_c_Ns_per_m, 0, 1e7, 0, "N s/m", "2000", "Achilles tendon damping"),
    NUM("achilles_leg_anchor_m", achilles_leg_anchor_m, 0, 10, POS, "m", "0.1", "where the tendon meets the leg, above the ankle"),
    NUM("inertia_height_m", inertia_height_m, 0, 10, 0, "m", "0",
        "0: inertia_kgm2 as given; else the moments are the body's at this COM height, and at another the body is "
        "stretched along the vertical by f = com_height_m / this: its mass's spread along z, (Ix + Iy - Iz) / 2, "
        "times f^2 in Ix and Iy, Iz kept (a sweep of the height stretches the same body)"),
    {"robot", "mount", FS_KEY_CHOICE, F(mount), 0, 0, 0, 0, "free|vertical", "", "free",
     "free: all six degrees of freedom; vertical: on a vertical slide, only up and down (the walking machine's carriage)"},
#define FIRST_BIPED_KEY "hip_width_m"
    NUM("hip_width_m", hip_width_m, 0, 2, POS, "m", "0.2", "biped: between the two hip joints, and the two ankles under them"),
    NUM("thigh_length_m", thigh_length_m, 0, 2, POS, "m", "0.2", "biped: hip joint to knee joint"),
    NUM("shank_length_m", shank_length_m, 0, 2, POS, "m", "0.2", "biped: knee joint to ankle joint"),
    NUM("knee_bend_deg", knee_bend_deg, 0, 90, POS, "deg", "10",
        "biped: the knee's flexion in the built (neutral) pose, the knee ahead of the hip-ankle line"),
    NUM("leg_width_m", leg_width_m, 0, 1, POS, "m", "0.06", "biped: a thigh's and a shank's square section, for their inertia"),
    NUM("pelvis_mass_kg", pelvis_mass_kg, 0, 1e4, POS, "kg", "36.76", "biped: pelvis and everything above it (head, arms, trunk)"),
    NUM("thigh_mass_kg", thigh_mass_kg, 0, 1e4, POS, "kg", "5.2", "biped: each thigh"),
    NUM("shank_mass_kg", shank_mass_kg, 0, 1e4, POS, "kg", "2.42", "biped: each shank"),
    NUM("pelvis_com_height_m", pelvis_com_height_m, 0, 10, 0, "m", "0.15", "biped: the pelvis's centre of mass above the hip axis"),
    {"robot", "pelvis_inertia_kgm2", FS_KEY_LIST, F(pelvis_inertia_kgm2), 0, 1e4, FS_KEY_OPEN_MIN, 3, NULL, "kg m^2",
     "0.47, 0.35, 0.26", "biped: the pelvis's principal moments about x (roll), y (pitch), z at its centre of mass (a body's, "
     "each at most the other two together)"},
    NUM("hip_k_N_m_per_rad", hip_k_N_m_per_rad, 0, 1e7, 0, "N m/rad", "2000", "biped: each hip's angular stiffness toward the built pose"),
    NUM("hip_c_N_m_s_per_rad", hip_c_N_m_s_per_rad, 0, 1e6, 0, "N m s/rad", "40", "biped: each hip's angular damping"),
    NUM("knee_k_N_m_per_rad", knee_k_N_m_per_rad, 0, 1e7, 0, "N m/rad", "2000", "biped: each knee's angular stiffness"),
    NUM("knee_c_N_m_s_per_rad", knee_c_N_m_s_per_rad, 0, 1e6, 0, "N m s/rad", "40", "biped: each knee's angular damping"),
    NUM("ankle_k_N_m_per_rad", ankle_k_N_m_per_rad, 0, 1e7, 0, "N m/rad", "2000",
        "biped: each ankle's angular stiffness (shank to the foot's ankle body)"),
    NUM("ankle_c_N_m_s_per_rad", ankle_c_N_m_s_per_rad, 0, 1e6, 0, "N m s/rad", "100", "biped: each ankle's angular damping"),
};
const int fs_robot_nkeys = (int)(sizeof fs_robot_keys / sizeof fs_robot_keys[0]);

/* A key of the other kind's refused: a biped's mass follows from its parts, and a single body has
 * no legs. */
static fs_status other_kinds_keys(const fs_config *cfg, const fs_robot_def *def, fs_error *err)
{
    int biped_key = 0;
    for (int i = 1; i < fs_robot_nkeys; i++) { /* after kind */
        const char *name = fs_robot_keys[i].name;
        biped_key |= !strcmp(name, FIRST_BIPED_KEY);
        int both = !strcmp(name, "com_forward_m"); /* a biped's whole body's */
        if (both || biped_key == (def->kind == FS_ROBOT_BIPED) || !fs_config_has(cfg, "robot", name))
            continue;
        char where[FS_PATH_MAX + 80];
        fs_config_where(cfg, "robot", name, where, sizeof where);
        if (biped_key)
            return fs_fail(err, FS_BAD_INPUT, "%s: '%s' is a biped's key and this robot is one body (kind = single): "
                           "give kind = biped or leave it out", where, name);
        return fs_fail(err, FS_BAD_INPUT, "%s: '%s' is a single body's key and this robot is a biped (kind = biped), "
                       "whose mass and centre of mass follow from pelvis_mass_kg, thigh_mass_kg, shank_mass_kg and "
                       "its lengths: leave it out", where, name);
    }
    return FS_OK;
}

/* The relative round-off a body's moments may carry and still count as one on the boundary (a
 * thin plate: A + B = C). */
#define INERTIA_ROUNDOFF 1e-9

int fs_inertia_impossible(const double I[3])
{
    for (int c = 0; c < 3; c++) {
        if (!(I[c] > 0))
            return 1 + c;
        double others = I[(c + 1) % 3] + I[(c + 2) % 3];
        if (others < I[c] - INERTIA_ROUNDOFF * (others + I[c]))
            return 1 + c;
    }
    return 0;
}

/* The robot's given moments (inertia_kgm2, a biped's pelvis_inertia_kgm2) must be a body's: each
 * positive (their range says so) and none above the other two together. */
static fs_status physical_inertia(const fs_config *cfg, const fs_robot_def *def, fs_error *err)
{
    const char *key = def->kind == FS_ROBOT_BIPED ? "pelvis_inertia_kgm2" : "inertia_kgm2";
    const double *I = def->kind == FS_ROBOT_BIPED ? def->pelvis_inertia_kgm2 : def->inertia_kgm2;
    int bad = fs_inertia_impossible(I);
    if (!bad)
        return FS_OK;
    const char axis[3] = {'x', 'y', 'z'};
    int c = bad - 1, a = (c + 1) % 3, b = (c + 2) % 3;
    char where[FS_PATH_MAX + 80];
    if (fs_config_has(cfg, "robot", key))
        fs_config_where(cfg, "robot", key, where, sizeof where);
    else
        snprintf(where, sizeof where, "%s", cfg->path);
    return fs_fail(err, FS_BAD_INPUT, "%s: %s = %g, %g, %g is no rigid body's: the moment about %c (%g kg m^2) is "
                   "more than those about %c and %c together (%g); every body's principal moments A, B, C have "
                   "A + B >= C for each (a thin plate: equal, the mass spread along an axis being (A + B - C) / 2 >= 0): "
                   "give the moment about %c at most %g, or raise the others", where, key, I[0], I[1], I[2], axis[c],
                   I[c], axis[a], axis[b], I[a] + I[b], axis[c], I[a] + I[b]);
}

fs_status fs_robot_load(const char *path, const char *const *overrides, int noverrides, fs_robot_def *def,
                        fs_error *err)
{
    fs_config cfg = {.path = "(no robot)"};
    fs_status s = *path ? fs_config_load(&cfg, path, err) : FS_OK;
    for (int i = 0; s == FS_OK && i < noverrides; i++)
        s = fs_config_override(&cfg, overrides[i], err);
    if (s == FS_OK)
        s = fs_config_bind(&cfg, fs_robot_keys, fs_robot_nkeys, def, err);
    if (s == FS_OK)
        s = other_kinds_keys(&cfg, def, err);
    if (s == FS_OK)
        s = physical_inertia(&cfg, def, err);
    if (s == FS_OK && !*path && !fs_config_has(&cfg, "robot", "mass_kg") && def->kind == FS_ROBOT_SINGLE)
        def->mass_kg = 0; /* no file: no robot, unless --set gives it a mass */
    fs_robot_derive(def);
    fs_config_free(&cfg);
    return s;
}

/* The body stretched along the vertical by f = com_height_m / inertia_height_m: each of its points'
 * heights above the centre of mass times f, the spread across the vertical unchanged. Its mass's
 * spread along z, s = sum m z^2 = (A + B - C) / 2, becomes f^2 s, and it enters the moments about x
 * and y (A = sum m (y^2 + z^2)), not the one about z: a body stays a body at every height. */
void fs_robot_inertia(const fs_robot_def *r, double I[3])
{
    const double *J = r->inertia_kgm2;
    double f = r->inertia_height_m > 0 ? r->com_height_m / r->inertia_height_m : 1;
    double spread_z = 0.5 * (J[0] + J[1] - J[2]), more = (f * f - 1) * spread_z;
    I[0] = J[0] + more;
    I[1] = J[1] + more;
    I[2] = J[2];
}

/* One leg's joint centres in the design frame: its knee and hip above the ankle a, the knee ahead
 * of the hip-ankle line by the bend (thigh and shank each turned half of it from the vertical). */
static void leg_points(const fs_robot_def *r, fs_vec3 a, fs_vec3 *knee, fs_vec3 *hip)
{
    double half = 0.5 * r->knee_bend_deg * DEG;
    *knee = fs_add(a, fs_v3(r->shank_length_m * sin(half), 0, r->shank_length_m * cos(half)));
    *hip = fs_add(*knee, fs_v3(-r->thigh_length_m * sin(half), 0, r->thigh_length_m * cos(half)));
}

/* The pelvis's centre relative to the ankles' point (x forward, z up): above the hips' midpoint by
 * pelvis_com_height_m, and forward so that the pelvis and legs together stand com_forward_m ahead
 * of the ankles. */
static fs_vec3 pelvis_offset(const fs_robot_def *r)
{
    fs_vec3 knee, hip;
    leg_points(r, fs_v3(0, 0, 0), &knee, &hip);
    double legs_x = r->shank_mass_kg * 0.5 * knee.x + r->thigh_mass_kg * 0.5 * (knee.x + hip.x);
    double total = r->pelvis_mass_kg + 2 * (r->thigh_mass_kg + r->shank_mass_kg);
    double x = (total * r->com_forward_m - 2 * legs_x) / r->pelvis_mass_kg;
    return fs_v3(x, 0, hip.z + r->pelvis_com_height_m);
}

void fs_robot_whole_inertia(const fs_robot_def *r, double I[3])
{
    if (r->kind != FS_ROBOT_BIPED) {
        fs_robot_inertia(r, I);
        return;
    }
    /* the pelvis and the legs as fs_robot_biped_geometry builds them, on feet of no body */
    fs_foot_geom none, g;
    memset(&none, 0, sizeof none);
    fs_robot_biped_geometry(r, &none, &g);
    double m = 0;
    fs_vec3 G = fs_v3(0, 0, 0);
    for (int i = g.pelvis_body; i < g.nbodies; i++)
        m += g.body[i].mass_kg, G = fs_add(G, fs_scale(g.body[i].com, g.body[i].mass_kg));
    G = fs_scale(G, 1 / m);
    /* each body's own moment and its mass's about G (parallel axes), the diagonal */
    for (int k = 0; k < 3; k++) {
        I[k] = 0;
        for (int i = g.pelvis_body; i < g.nbodies; i++) {
            fs_vec3 d = fs_sub(g.body[i].com, G);
            double dk = k == 0 ? d.x : k == 1 ? d.y : d.z;
            I[k] += g.body[i].inertia[4 * k] + g.body[i].mass_kg * (fs_dot(d, d) - dk * dk);
        }
    }
}

void fs_robot_derive(fs_robot_def *r)
{
    if (r->kind != FS_ROBOT_BIPED)
        return;
    fs_vec3 knee, hip;
    leg_points(r, fs_v3(0, 0, 0), &knee, &hip);
    r->mass_kg = r->pelvis_mass_kg + 2 * (r->thigh_mass_kg + r->shank_mass_kg);
    double mz = r->pelvis_mass_kg * pelvis_offset(r).z + 2 * r->shank_mass_kg * 0.5 * knee.z +
                2 * r->thigh_mass_kg * 0.5 * (knee.z + hip.z);
    r->com_height_m = mz / r->mass_kg;
}

/* A point of the design foot on side f (0: right, as designed, at y - w/2; 1: left, mirrored, at y + w/2). */
static fs_vec3 side_point(fs_vec3 p, int f, double w)
{
    return f ? fs_v3(p.x, -p.y + 0.5 * w, p.z) : fs_v3(p.x, p.y - 0.5 * w, p.z);
}

/* A hinge's axis mirrored: an axis is a pseudovector (a' = -M a for the mirror M), so the joint's
 * angle keeps its sense (toes up is positive on both feet). */
static fs_vec3 side_axis(fs_vec3 a, int f) { return f ? fs_v3(-a.x, a.y, -a.z) : a; }

static void side_name(char *dst, size_t size, int f, const char *name)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%s_%s", f ? "left" : "right", name);
    snprintf(dst, size, "%.*s", (int)size - 1, buf);
}

static void add_leg_hinge(fs_foot_geom *g, const char *name, int f, int b1, int b2, fs_vec3 at, double k, double c)
{
    fs_hinge_geom *h = &g->hinge[g->nhinges++];
    *h = (fs_hinge_geom){.body1 = b1, .body2 = b2, .anchor = at, .axis = fs_v3(0, -1, 0), .k_N_m_per_rad = k,
                         .c_N_m_s_per_rad = c};
    side_name(h->name, sizeof h->name, f, name);
}

void fs_robot_biped_geometry(const fs_robot_def *r, const fs_foot_geom *foot, fs_foot_geom *g)
{
    memset(g, 0, sizeof *g);
    g->kind = foot->kind;
    const int n = foot->nbodies;
    const double w = r->hip_width_m;
    g->box_size = foot->box_size;
    for (int f = 0; f < 2; f++) {
        const int o = f * n;
        for (int i = 0; i < n; i++) {
            fs_body_geom *b = &g->body[o + i];
            *b = foot->body[i];
            side_name(b->name, sizeof b->name, f, foot->body[i].name);
            b->com = side_point(b->com, f, w);
            if (f) /* M I M: the products with y change sign */
                b->inertia[1] = -b->inertia[1], b->inertia[3] = -b->inertia[3], b->inertia[5] = -b->inertia[5],
                b->inertia[7] = -b->inertia[7];
        }
        for (int i = 0; i < foot->nhinges; i++) {
            fs_hinge_geom *h = &g->hinge[g->nhinges++];
            *h = foot->hinge[i];
            side_name(h->name, sizeof h->name, f, foot->hinge[i].name);
            h->body1 += o, h->body2 += o;
            h->anchor = side_point(h->anchor, f, w);
            h->axis = side_axis(h->axis, f);
        }
        for (int i = 0; i < foot->nsprings; i++) {
            fs_spring_geom *s = &g->spring[g->nsprings++];
            *s = foot->spring[i];
            side_name(s->name, sizeof s->name, f, foot->spring[i].name);
            s->body1 += o, s->body2 += o;
            s->p1 = side_point(s->p1, f, w), s->p2 = side_point(s->p2, f, w);
        }
        for (int i = 0; i < foot->nspheres; i++) {
            fs_sphere_geom *s = &g->sphere[g->nspheres++];
            *s = foot->sphere[i];
            side_name(s->name, sizeof s->name, f, foot->sphere[i].name);
            s->body += o;
            s->centre = side_point(s->centre, f, w);
        }
        for (int i = 0; i < foot->nboxes; i++) {
            g->box[g->nboxes].body = foot->box[i].body + o;
            g->box[g->nboxes++].centre = side_point(foot->box[i].centre, f, w);
        }
        g->foot[f].first_body = o;
        g->foot[f].nbodies = n;
        g->foot[f].ankle_body = foot->ankle_body + o;
        g->foot[f].ankle = side_point(foot->ankle, f, w);
    }
    memcpy(g->chain, foot->chain, sizeof g->chain); /* the right foot's (chain_plane_friction is a foot's probe) */
    g->nfeet = 2;
    g->biped = 1;
    g->ankle_body = g->foot[0].ankle_body;
    g->ankle = g->foot[0].ankle;
    g->total_mass_kg = 2 * foot->total_mass_kg + r->mass_kg;
    /* the legs: the pelvis, then per leg a thigh and a shank, and its hip, knee and ankle */
    const int pelvis = 2 * n;
    fs_vec3 mid = fs_scale(fs_add(g->foot[0].ankle, g->foot[1].ankle), 0.5);
    fs_body_geom *p = &g->body[pelvis];
    snprintf(p->name, sizeof p->name, "pelvis");
    p->mass_kg = r->pelvis_mass_kg;
    p->com = fs_add(mid, pelvis_offset(r));
    for (int k = 0; k < 3; k++)
        p->inertia[4 * k] = r->pelvis_inertia_kgm2[k];
    g->pelvis_body = pelvis;
    g->nbodies = pelvis + 1;
    for (int f = 0; f < 2; f++) {
        fs_vec3 a = g->foot[f].ankle, knee, hip;
        leg_points(r, a, &knee, &hip);
        int thigh = g->nbodies++, shank = g->nbodies++;
        char name[32];
        side_name(name, sizeof name, f, "thigh");
        fs_design_link_body(&g->body[thigh], name, r->thigh_mass_kg, hip, knee, r->leg_width_m, r->leg_width_m);
        side_name(name, sizeof name, f, "shank");
        fs_design_link_body(&g->body[shank], name, r->shank_mass_kg, knee, a, r->leg_width_m, r->leg_width_m);
        add_leg_hinge(g, "hip", f, pelvis, thigh, hip, r->hip_k_N_m_per_rad, r->hip_c_N_m_s_per_rad);
        add_leg_hinge(g, "knee", f, thigh, shank, knee, r->knee_k_N_m_per_rad, r->knee_c_N_m_s_per_rad);
        add_leg_hinge(g, "shank_ankle", f, shank, g->foot[f].ankle_body, a, r->ankle_k_N_m_per_rad,
                      r->ankle_c_N_m_s_per_rad);
    }
}
