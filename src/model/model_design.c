/* model_design.c: the design schema, its checks, and the geometry built from a design. */
#include "footsim/model/fs_design.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define DEG (M_PI / 180.0)
#define F(member) offsetof(fs_design_def, member)
#define NUM(sec, name, member, lo, hi, flags, unit, dflt, help) \
    {sec, name, FS_KEY_NUMBER, F(member), lo, hi, flags, 0, NULL, unit, dflt, help}
#define LIST(sec, name, member, lo, hi, unit, dflt, help) \
    {sec, name, FS_KEY_LIST, F(member), lo, hi, 0, FS_CHAINS, NULL, unit, dflt, help}
#define POS FS_KEY_OPEN_MIN
#define LAW_KEYS(d, i)                                                                                              \
    {"springs", "d" #d "_law", FS_KEY_CHOICE, F(law[i]), 0, 0, 0, 0, "linear|progressive|bilinear|curve", "", "linear", \
     "d" #d "'s force against its deflection x: linear f = k x (Table I); progressive, stiffness k (1 + (x/x0)^2); "  \
     "bilinear, k up to the stop and k2 beyond; curve, the points d" #d "_curve_m and _N (docs/model.md)"},          \
    {"springs", "d" #d "_tension_only", FS_KEY_CHOICE, F(tension_only[i]), 0, 0, 0, 0, "no|yes", "", "no",          \
     "yes: d" #d " is a cable: no force while shorter than its rest length, and never a push"},                     \
    NUM("springs", "d" #d "_x0_m", x0_m[i], 0, 1, POS, "m", "0.001",                                               \
        "progressive d" #d ": the deflection at which its stiffness has doubled"),                                   \
    NUM("springs", "d" #d "_stop_m", stop_m[i], 0, 1, POS, "m", "0.001",                                           \
        "bilinear d" #d ": the deflection, either way, beyond which k2 acts"),                                       \
    NUM("springs", "d" #d "_k2_N_per_m", k2_N_per_m[i], 0, 1e9, 0, "N/m", "12000",                                 \
        "bilinear d" #d ": the stiffness beyond the stop (times springs.scale)"),                                   \
    {"springs", "d" #d "_curve_m", FS_KEY_SERIES, F(curve_m[i]), -1, 1, 0, FS_CURVE_MAX, NULL, "m", "",            \
     "curve d" #d ": deflections (length less rest length), strictly rising, one of them 0"},                       \
    {"springs", "d" #d "_curve_N", FS_KEY_SERIES, F(curve_N[i]), -1e7, 1e7, 0, FS_CURVE_MAX, NULL, "N", "",        \
     "curve d" #d ": the tension at each deflection, rising, 0 at 0 (times springs.scale)"}

/* Every key a design file may hold. Defaults: Table I where the paper gives a value, and the
 * choices argued in docs/model.md where it does not. */
const fs_key fs_design_keys[] = {
    {"foot", "kind", FS_KEY_CHOICE, F(kind), 0, 0, 0, 0, "biomimetic|flat", "", "biomimetic",
     "biomimetic: heel, talus and five toe chains; flat: one rigid sole of the same mass, footprint and ankle height"},
    NUM("foot", "design_load_kg", design_load_kg, 0, 1e4, POS, "kg", "26", "load the arch is checked under (Table I)"),
    NUM("links", "l1_m", l1_m, 0, 1, POS, "m", "0.02", "heel link: heel sphere centre to ankle joint (Table I)"),
    NUM("links", "l2_m", l2_m, 0, 1, 0, "m", "0.02", "talus link: ankle joint to midfoot joints (Table I; 0 gives the 4-bar)"),
    NUM("links", "l3_m", l3_m, 0, 1, POS, "m", "0.04", "metatarsal: midfoot joint to MTP joint (Table I)"),
    NUM("links", "l4_m", l4_m, 0, 1, POS, "m", "0.015", "phalanx: MTP joint to toe sphere centre (Table I)"),
    NUM("pose", "heel_deg", heel_deg, 0, 90, POS, "deg", "80", "heel link above the horizontal, heel to ankle"),
    NUM("pose", "talus_deg", talus_deg, -90, 90, 0, "deg", "-20", "talus link above the horizontal, ankle to midfoot"),
    NUM("pose", "toe_deg", toe_deg, -90, 0, 0, "deg", "-25", "phalanx above the horizontal, MTP to toe; the metatarsal angle follows"),
    NUM("springs", "k_d1_N_per_m", k_N_per_m[0], 0, 1e9, POS, "N/m", "12000", "midfoot spring stiffness (Table I)"),
    NUM("springs", "k_d2_N_per_m", k_N_per_m[1], 0, 1e9, POS, "N/m", "12000", "MTP spring stiffness (Table I)"),
    NUM("springs", "k_d3_N_per_m", k_N_per_m[2], 0, 1e9, POS, "N/m", "12000", "heel-to-toe spring stiffness (Table I)"),
    NUM("springs", "scale", spring_scale, 0, 1e6, POS, "", "1",
        "multiplies the three stiffnesses above and every force of their laws (not the damping): one key for a sweep or a search"),
    NUM("springs", "c_d1_Ns_per_m", c_Ns_per_m[0], 0, 1e7, 0, "N s/m", "200", "midfoot damping (Table I)"),
    NUM("springs", "c_d2_Ns_per_m", c_Ns_per_m[1], 0, 1e7, 0, "N s/m", "200", "MTP damping (Table I)"),
    NUM("springs", "c_d3_Ns_per_m", c_Ns_per_m[2], 0, 1e7, 0, "N s/m", "200", "heel-to-toe damping (Table I)"),
    NUM("springs", "d1_b_m", d1_b_m, 0, 1, POS, "m", "0.008", "d1 anchors: distance from the midfoot joint along talus and metatarsal"),
    NUM("springs", "d1_h_m", d1_h_m, 0, 1, 0, "m", "0.012", "d1 anchors: offset toward the sole"),
    NUM("springs", "d2_b_m", d2_b_m, 0, 1, POS, "m", "0.006", "d2 anchors: distance from the MTP joint along metatarsal and phalanx"),
    NUM("springs", "d2_h_m", d2_h_m, 0, 1, 0, "m", "0.008", "d2 anchors: offset toward the sole"),
    NUM("springs", "d3_heel_b_m", d3_heel_b_m, 0, 1, 0, "m", "0.004", "d3 heel anchor: distance from the heel centre along the heel link"),
    NUM("springs", "d3_heel_h_m", d3_heel_h_m, 0, 1, 0, "m", "0.004", "d3 heel anchor: offset toward the sole"),
    NUM("springs", "d3_toe_b_m", d3_toe_b_m, 0, 1, POS, "m", "0.006", "d3 toe anchor: distance from the MTP joint along the phalanx"),
    NUM("springs", "d3_toe_h_m", d3_toe_h_m, 0, 1, 0, "m", "0.003", "d3 toe anchor: offset toward the sole"),
    NUM("springs", "d3_heel_spread", d3_heel_spread, 0, 1, 0, "", "0.5", "d3 heel anchor's lateral offset as a fraction of its chain's"),
    LAW_KEYS(1, 0),
    LAW_KEYS(2, 1),
    LAW_KEYS(3, 2),
    LIST("chains", "lateral_m", lateral_m, -1, 1, "m", "0.024, 0.012, 0, -0.012, -0.024", "y of each midfoot joint, big toe first"),
    LIST("chains", "splay_deg", splay_deg, -45, 45, "deg", "8, 4, 0, -4, -8", "each chain's plane turned about z"),
    LIST("chains", "scale", scale, 0.2, 5, "", "1.25, 1, 1, 1, 1", "forefoot size factor per chain (the big toe is larger)"),
    NUM("chains", "splay_factor", splay_factor, 0, 5, 0, "", "1",
        "multiplies every chain's splay_deg (the splay as one number; each product within [-45, 45] deg)"),
    NUM("chains", "scale_factor", scale_factor, 0, 5, POS, "",  "1",
        "multiplies every chain's scale (the toes' size as one number; each product within [0.2, 5])"),
    NUM("mass", "heel_kg", heel_kg, 0, 100, POS, "kg", "0.05", "heel body mass"),
    NUM("mass", "talus_kg", talus_kg, 0, 100, POS, "kg", "0.08", "talus (ankle) body mass"),
    NUM("mass", "metatarsal_kg", metatarsal_kg, 0, 100, POS, "kg", "0.02", "each metatarsal (times the chain's scale)"),
    NUM("mass", "phalanx_kg", phalanx_kg, 0, 100, POS, "kg", "0.008", "each phalanx (times the chain's scale)"),
    NUM("mass", "link_width_m", link_width_m, 0, 1, POS, "m", "0.008", "square cross-section of every link, for inertia"),
    NUM("contact", "heel_radius_m", heel_radius_m, 0, 1, POS, "m", "0.006", "heel contact spheres"),
    NUM("contact", "heel_width_m", heel_width_m, 0, 1, 0, "m", "0.024", "lateral distance between the two heel spheres (0: one sphere)"),
    NUM("contact", "ball_radius_m", ball_radius_m, 0, 1, POS, "m", "0.004", "metatarsal head contact sphere (times scale)"),
    NUM("contact", "toe_radius_m", toe_radius_m, 0, 1, POS, "m", "0.003", "toe tip contact sphere (times scale)"),
    NUM("soil_shapes", "heel_radius_m", soil_heel_radius_m, 0, 0.05, 0, "m", "0",
        "on a soil the heel is a capsule of this radius across its two spheres (0: contact.heel_radius_m; docs/soil.md, "
        "The feet's shapes)"),
    NUM("soil_shapes", "talus_radius_m", soil_talus_radius_m, 0, 0.05, 0, "m", "0",
        "the talus's capsule, between its joints (0: half of mass.link_width_m)"),
    NUM("soil_shapes", "metatarsal_radius_m", soil_metatarsal_radius_m, 0, 0.05, 0, "m", "0",
        "each metatarsal's capsule, midfoot joint to ball sphere, times the chain's scale (0: the ball sphere's)"),
    NUM("soil_shapes", "phalanx_radius_m", soil_phalanx_radius_m, 0, 0.05, 0, "m", "0",
        "each phalanx's capsule, MTP joint to toe sphere, times the chain's scale (0: the toe sphere's)"),
    NUM("sole", "mu", sole_mu, 0, 10, 0, "", "1.0", "friction coefficient of the sole material"),
    NUM("sole", "stiffness_N_per_m", sole_stiffness_N_per_m, 0, 1e12, POS, "N/m", "1e7", "contact stiffness of the sole material"),
    NUM("sole", "damping_Ns_per_m", sole_damping_Ns_per_m, 0, 1e9, 0, "N s/m", "2e4", "contact damping of the sole material"),
    NUM("flat", "thickness_m", flat_thickness_m, 0, 1, POS, "m", "0.008", "the flat foot's sole plate thickness"),
};
const int fs_design_nkeys = (int)(sizeof fs_design_keys / sizeof fs_design_keys[0]);

void fs_design_defaults(fs_design_def *def)
{
    fs_config empty = {.path = "(defaults)"};
    fs_error err;
    memset(def, 0, sizeof *def);
    fs_config_bind(&empty, fs_design_keys, fs_design_nkeys, def, &err);
}

/* ---- geometry --------------------------------------------------------------------------- */

/* Inertia about the COM of a box with edges a, b, c along the orthonormal axes u, v, w. */
static void box_inertia(double m, double a, double b, double c, fs_vec3 u, fs_vec3 v, fs_vec3 w, double I[9])
{
    double Iu = m * (b * b + c * c) / 12.0, Iv = m * (a * a + c * c) / 12.0, Iw = m * (a * a + b * b) / 12.0;
    double U[3] = {u.x, u.y, u.z}, V[3] = {v.x, v.y, v.z}, W[3] = {w.x, w.y, w.z};
    for (int r = 0; r < 3; r++)
        for (int s = 0; s < 3; s++)
            I[3 * r + s] = Iu * U[r] * U[s] + Iv * V[r] * V[s] + Iw * W[r] * W[s];
}

/* A link of square section w between two points: its body geometry. */
void fs_design_link_body(fs_body_geom *b, const char *name, double m, fs_vec3 from, fs_vec3 to, double width,
                         double depth)
{
    snprintf(b->name, sizeof b->name, "%s", name);
    b->mass_kg = m;
    b->com = fs_scale(fs_add(from, to), 0.5);
    fs_vec3 d = fs_sub(to, from);
    double len = fs_norm(d);
    fs_vec3 u = len > 0 ? fs_scale(d, 1.0 / len) : fs_v3(1, 0, 0);
    fs_vec3 lat = fs_v3(0, 1, 0);
    fs_vec3 v = fs_sub(lat, fs_scale(u, fs_dot(u, lat)));
    v = fs_scale(v, 1.0 / fs_norm(v));
    box_inertia(m, len, depth, width, u, v, fs_cross(u, v), b->inertia);
}

/* Direction at angle (rad) above the horizontal within the vertical plane heading f. */
static fs_vec3 in_plane(fs_vec3 f, double angle) { return fs_add(fs_scale(f, cos(angle)), fs_v3(0, 0, sin(angle))); }

/* The sole side of a link with direction e in plane heading f: e turned 90 degrees down. */
static fs_vec3 sole_side(fs_vec3 f, double angle) { return in_plane(f, angle - M_PI / 2); }

/* Spring kind `which`'s law as the def gives it, its forces not yet scaled. */
static fs_spring_law design_law(const fs_design_def *d, int which)
{
    fs_spring_law law = fs_spring_law_linear(d->k_N_per_m[which]);
    law.kind = d->law[which];
    law.tension_only = d->tension_only[which];
    law.x0_m = d->x0_m[which];
    law.stop_m = d->stop_m[which];
    law.k2_N_per_m = d->k2_N_per_m[which];
    if (law.kind == FS_LAW_CURVE) {
        law.npoints = d->curve_m[which].n;
        for (int i = 0; i < law.npoints; i++) {
            law.x_m[i] = d->curve_m[which].v[i];
            law.f_N[i] = d->curve_N[which].v[i];
        }
    }
    return law;
}

/* Each spring kind's law whole: a key of another law than the one chosen refused (it would be
 * ignored), and a curve of at least two points, as many forces as deflections, both rising, through
 * (0, 0). */
static fs_status check_laws(const fs_design_def *d, const fs_config *cfg, fs_error *err)
{
    static const char *const own[][2] = {{"x0_m", "progressive"}, {"stop_m", "bilinear"}, {"k2_N_per_m", "bilinear"},
                                         {"curve_m", "curve"}, {"curve_N", "curve"}};
    static const int own_law[] = {FS_LAW_PROGRESSIVE, FS_LAW_BILINEAR, FS_LAW_BILINEAR, FS_LAW_CURVE, FS_LAW_CURVE};
    char key[32], lawkey[32], where[FS_PATH_MAX + 80], where_law[FS_PATH_MAX + 80];
    for (int w = 0; w < 3; w++) {
        fs_spring_law law = design_law(d, w);
        snprintf(lawkey, sizeof lawkey, "d%d_law", w + 1);
        fs_config_where(cfg, "springs", lawkey, where_law, sizeof where_law);
        for (size_t j = 0; cfg && j < sizeof own_law / sizeof *own_law; j++) {
            snprintf(key, sizeof key, "d%d_%s", w + 1, own[j][0]);
            if (law.kind != own_law[j] && fs_config_has(cfg, "springs", key)) {
                fs_config_where(cfg, "springs", key, where, sizeof where);
                return fs_fail(err, FS_BAD_INPUT,
                               "%s: %s is a key of the %s law, but d%d_law is %s (%s): set d%d_law = %s, or leave %s "
                               "out",
                               where, key, own[j][1], w + 1, fs_spring_law_name(&law), where_law, w + 1, own[j][1], key);
            }
        }
        if (law.kind != FS_LAW_CURVE)
            continue;
        snprintf(key, sizeof key, "d%d_curve_m", w + 1);
        fs_config_where(cfg, "springs", key, where, sizeof where);
        const fs_series *xs = &d->curve_m[w], *fs = &d->curve_N[w];
        if (xs->n < 2)
            return fs_fail(err, FS_BAD_INPUT,
                           "%s: d%d_law = curve needs its points: give d%d_curve_m (at least 2 deflections, m) and "
                           "d%d_curve_N (as many forces, N)",
                           xs->n ? where : where_law, w + 1, w + 1, w + 1);
        if (fs->n != xs->n) {
            snprintf(key, sizeof key, "d%d_curve_N", w + 1);
            fs_config_where(cfg, "springs", key, where, sizeof where);
            return fs_fail(err, FS_BAD_INPUT, "%s: d%d_curve_N has %d forces for d%d_curve_m's %d deflections; give one "
                           "force for each", where, w + 1, fs->n, w + 1, xs->n);
        }
        int zero = -1;
        for (int i = 0; i < xs->n; i++) {
            if (i > 0 && !(xs->v[i] > xs->v[i - 1]))
                return fs_fail(err, FS_BAD_INPUT,
                               "%s: d%d_curve_m is not increasing (value %d, %g m, after %g m): give the deflections "
                               "in strictly rising order",
                               where, w + 1, i + 1, xs->v[i], xs->v[i - 1]);
            if (xs->v[i] == 0)
                zero = i;
        }
        if (zero < 0 || fs->v[zero] != 0)
            return fs_fail(err, FS_BAD_INPUT,
                           "%s: d%d's curve must pass through 0 N at 0 m (the neutral pose is unstrained): put a 0 in "
                           "d%d_curve_m and 0 at the same place in d%d_curve_N",
                           where, w + 1, w + 1, w + 1);
        snprintf(key, sizeof key, "d%d_curve_N", w + 1);
        fs_config_where(cfg, "springs", key, where, sizeof where);
        for (int i = 1; i < fs->n; i++)
            if (!(fs->v[i] > fs->v[i - 1]))
                return fs_fail(err, FS_BAD_INPUT,
                               "%s: d%d_curve_N is not increasing (value %d, %g N, after %g N): a spring's tension must "
                               "rise with its deflection (a positive stiffness everywhere)",
                               where, w + 1, i + 1, fs->v[i], fs->v[i - 1]);
    }
    return FS_OK;
}

static void add_spring(fs_foot_geom *g, const fs_design_def *d, int which, int chain, int b1, int b2, fs_vec3 p1,
                       fs_vec3 p2)
{
    fs_spring_geom *s = &g->spring[g->nsprings];
    g->chain[chain].spring[which] = g->nsprings++;
    snprintf(s->name, sizeof s->name, "d%d_chain%d", which + 1, chain + 1);
    s->body1 = b1;
    s->body2 = b2;
    s->p1 = p1;
    s->p2 = p2;
    s->law = design_law(d, which);
    fs_spring_law_scale(&s->law, d->spring_scale); /* a linear law's k: k_dN times the scale, as always */
    if (fs_spring_law_is_linear(&s->law))
        s->k_N_per_m = s->law.k_N_per_m;
    else
        fs_spring_law_force(&s->law, 0, &s->k_N_per_m);
    s->c_Ns_per_m = d->c_Ns_per_m[which];
    s->rest_length_m = fs_norm(fs_sub(p2, p1)); /* the neutral pose is unstrained */
}

static void add_sphere(fs_foot_geom *g, const char *name, int body, fs_vec3 c, double r)
{
    fs_sphere_geom *s = &g->sphere[g->nspheres++];
    snprintf(s->name, sizeof s->name, "%s", name);
    s->body = body;
    s->centre = c;
    s->radius_m = r;
}

/* Where a message about two keys that meet begins: the other key's --set when it was given by --set
 * (a value from the command line is not blamed on a line of the file), else the file line of the
 * first. */
static const char *lead_where(const char *first, const char *other)
{
    return strncmp(other, "--set ", 6) ? first : other;
}

static fs_status chain_geometry(const fs_design_def *d, const fs_config *cfg, int i, fs_vec3 H, fs_vec3 A,
                                fs_foot_geom *g, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    double s = fs_design_chain_scale(d, i), psi = fs_design_splay_deg(d, i) * DEG;
    double a2 = d->talus_deg * DEG, a4 = d->toe_deg * DEG;
    fs_vec3 f = fs_v3(cos(psi), sin(psi), 0);
    fs_vec3 axis = fs_v3(sin(psi), -cos(psi), 0); /* positive rotation turns the link up */
    fs_vec3 M = fs_add(A, fs_v3(d->l2_m * cos(a2), d->lateral_m[i], d->l2_m * sin(a2)));
    /* The metatarsal angle that puts the toe sphere on the ground. */
    double l3 = s * d->l3_m, l4 = s * d->l4_m, rt = s * d->toe_radius_m, rb = s * d->ball_radius_m;
    double sin3 = (rt - M.z - l4 * sin(a4)) / l3;
    if (sin3 < -1 || sin3 > 0) {
        /* several keys meet here: name where l3_m came from too (a --set is not a line of the file) */
        char where_l3[FS_PATH_MAX + 80];
        fs_config_where(cfg, "pose", "toe_deg", where, sizeof where);
        fs_config_where(cfg, "links", "l3_m", where_l3, sizeof where_l3);
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: chain %d's toe cannot rest on the ground (its metatarsal would need sin = %.3g; l3_m = %.3g "
                       "m from %s); change l3_m, toe_deg or the heel and talus angles",
                       lead_where(where, where_l3), i + 1, sin3, d->l3_m, where_l3);
    }
    double a3 = asin(sin3);
    fs_vec3 B = fs_add(M, fs_scale(in_plane(f, a3), l3));
    fs_vec3 T = fs_add(B, fs_scale(in_plane(f, a4), l4));
    if (B.z < rb) {
        char where_rb[FS_PATH_MAX + 80];
        fs_config_where(cfg, "pose", "toe_deg", where, sizeof where);
        fs_config_where(cfg, "contact", "ball_radius_m", where_rb, sizeof where_rb);
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: chain %d's ball sphere would start %.3g mm into the ground (ball_radius_m = %.3g m from "
                       "%s); use a steeper toe_deg or a smaller ball_radius_m",
                       lead_where(where, where_rb), i + 1, (rb - B.z) * 1e3, d->ball_radius_m, where_rb);
    }
    int meta = g->nbodies++, phal = g->nbodies++;
    char name[32];
    snprintf(name, sizeof name, "metatarsal%d", i + 1);
    fs_design_link_body(&g->body[meta], name, s * d->metatarsal_kg, M, B, d->link_width_m, d->link_width_m);
    snprintf(name, sizeof name, "phalanx%d", i + 1);
    fs_design_link_body(&g->body[phal], name, s * d->phalanx_kg, B, T, d->link_width_m, d->link_width_m);
    g->body[meta].soil_radius_m = d->soil_metatarsal_radius_m > 0 ? s * d->soil_metatarsal_radius_m : rb;
    g->body[phal].soil_radius_m = d->soil_phalanx_radius_m > 0 ? s * d->soil_phalanx_radius_m : rt;
    g->chain[i].metatarsal = meta;
    g->chain[i].phalanx = phal;
    g->chain[i].midfoot = M;
    g->chain[i].mtp = B;
    g->chain[i].toe = T;
    g->chain[i].metatarsal_deg = a3 / DEG;
    /* Hinges: midfoot (talus to metatarsal) and MTP (metatarsal to phalanx). */
    fs_hinge_geom *h = &g->hinge[g->nhinges];
    g->chain[i].midfoot_hinge = g->nhinges++;
    snprintf(h->name, sizeof h->name, "midfoot%d", i + 1);
    *h = (fs_hinge_geom){.body1 = FS_BODY_TALUS, .body2 = meta, .anchor = M, .axis = axis};
    snprintf(h->name, sizeof h->name, "midfoot%d", i + 1);
    h = &g->hinge[g->nhinges];
    g->chain[i].mtp_hinge = g->nhinges++;
    *h = (fs_hinge_geom){.body1 = meta, .body2 = phal, .anchor = B, .axis = axis};
    snprintf(h->name, sizeof h->name, "mtp%d", i + 1);
    /* Springs: d1 across the midfoot, d2 across the MTP, d3 from the heel to the phalanx. */
    fs_vec3 e2 = in_plane(f, a2), e3 = in_plane(f, a3), e4 = in_plane(f, a4);
    fs_vec3 n2 = sole_side(f, a2), n3 = sole_side(f, a3), n4 = sole_side(f, a4);
    add_spring(g, d, 0, i, FS_BODY_TALUS, meta, fs_add(M, fs_add(fs_scale(e2, -s * d->d1_b_m), fs_scale(n2, s * d->d1_h_m))),
               fs_add(M, fs_add(fs_scale(e3, s * d->d1_b_m), fs_scale(n3, s * d->d1_h_m))));
    add_spring(g, d, 1, i, meta, phal, fs_add(B, fs_add(fs_scale(e3, -s * d->d2_b_m), fs_scale(n3, s * d->d2_h_m))),
               fs_add(B, fs_add(fs_scale(e4, s * d->d2_b_m), fs_scale(n4, s * d->d2_h_m))));
    double a1 = d->heel_deg * DEG;
    fs_vec3 heel_anchor = fs_add(H, fs_add(fs_scale(in_plane(fs_v3(1, 0, 0), a1), d->d3_heel_b_m),
                                           fs_scale(sole_side(fs_v3(1, 0, 0), a1), d->d3_heel_h_m)));
    heel_anchor.y = d->d3_heel_spread * d->lateral_m[i];
    add_spring(g, d, 2, i, FS_BODY_HEEL, phal, heel_anchor,
               fs_add(B, fs_add(fs_scale(e4, s * d->d3_toe_b_m), fs_scale(n4, s * d->d3_toe_h_m))));
    snprintf(name, sizeof name, "ball%d", i + 1);
    add_sphere(g, name, meta, B, rb);
    snprintf(name, sizeof name, "toe%d", i + 1);
    add_sphere(g, name, phal, T, rt);
    return FS_OK;
}

/* The flat foot: one box under the same footprint, the same mass, the ankle at the same point. */
static void flat_geometry(const fs_design_def *d, const fs_foot_geom *bio, fs_foot_geom *g)
{
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    for (int i = 0; i < bio->nspheres; i++) {
        const fs_sphere_geom *s = &bio->sphere[i];
        xmin = fmin(xmin, s->centre.x - s->radius_m);
        xmax = fmax(xmax, s->centre.x + s->radius_m);
        ymin = fmin(ymin, s->centre.y - s->radius_m);
        ymax = fmax(ymax, s->centre.y + s->radius_m);
    }
    memset(g, 0, sizeof *g);
    g->kind = FS_FOOT_FLAT;
    g->nbodies = 1;
    g->nboxes = 1;
    g->box_size = fs_v3(xmax - xmin, ymax - ymin, d->flat_thickness_m);
    g->box[0].body = 0;
    g->box[0].centre = fs_v3(0.5 * (xmin + xmax), 0.5 * (ymin + ymax), 0.5 * d->flat_thickness_m);
    fs_body_geom *b = &g->body[0];
    snprintf(b->name, sizeof b->name, "sole");
    b->mass_kg = bio->total_mass_kg;
    b->com = g->box[0].centre;
    box_inertia(b->mass_kg, g->box_size.x, g->box_size.y, g->box_size.z, fs_v3(1, 0, 0), fs_v3(0, 1, 0),
                fs_v3(0, 0, 1), b->inertia);
    g->ankle_body = 0;
    g->ankle = bio->ankle;
    g->total_mass_kg = bio->total_mass_kg;
}

double fs_design_splay_deg(const fs_design_def *d, int i) { return d->splay_deg[i] * d->splay_factor; }
double fs_design_chain_scale(const fs_design_def *d, int i) { return d->scale[i] * d->scale_factor; }

/* Each chain's splay and scale times its factor stays within the list's own range. */
static fs_status check_factors(const fs_design_def *d, const fs_config *cfg, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    for (int i = 0; i < FS_CHAINS; i++) {
        double psi = fs_design_splay_deg(d, i), s = fs_design_chain_scale(d, i);
        if (fabs(psi) > 45)
            return fs_fail(err, FS_BAD_INPUT, "%s: splay_factor = %g turns chain %d by %g deg (splay_deg %g); each "
                           "chain's splay times the factor must lie in [-45, 45] deg: give a factor of at most %g",
                           fs_config_where(cfg, "chains", "splay_factor", where, sizeof where), d->splay_factor, i + 1,
                           psi, d->splay_deg[i], 45 / fabs(d->splay_deg[i]));
        if (s < 0.2 || s > 5)
            return fs_fail(err, FS_BAD_INPUT, "%s: scale_factor = %g makes chain %d's scale %g (scale %g); each "
                           "chain's scale times the factor must lie in [0.2, 5]",
                           fs_config_where(cfg, "chains", "scale_factor", where, sizeof where), d->scale_factor, i + 1,
                           s, d->scale[i]);
    }
    return FS_OK;
}

fs_status fs_design_geometry(const fs_design_def *d, const fs_config *cfg, fs_foot_geom *geom, fs_error *err)
{
    fs_status law_status = check_laws(d, cfg, err);
    if (law_status == FS_OK)
        law_status = check_factors(d, cfg, err);
    if (law_status != FS_OK)
        return law_status;
    fs_foot_geom g;
    memset(&g, 0, sizeof g);
    g.kind = FS_FOOT_BIOMIMETIC;
    double a1 = d->heel_deg * DEG;
    fs_vec3 H = fs_v3(0, 0, d->heel_radius_m);
    fs_vec3 A = fs_add(H, fs_scale(in_plane(fs_v3(1, 0, 0), a1), d->l1_m));
    double ymin = 1e9, ymax = -1e9;
    for (int i = 0; i < FS_CHAINS; i++) {
        ymin = fmin(ymin, d->lateral_m[i]);
        ymax = fmax(ymax, d->lateral_m[i]);
    }
    /* Rear foot: the heel (heel centre to ankle) and the talus (ankle to the midfoot joints). */
    g.nbodies = 2;
    fs_design_link_body(&g.body[FS_BODY_HEEL], "heel", d->heel_kg, H, A, d->link_width_m, d->link_width_m);
    double a2 = d->talus_deg * DEG;
    fs_vec3 Mc = fs_add(A, fs_v3(d->l2_m * cos(a2), 0.5 * (ymin + ymax), d->l2_m * sin(a2)));
    fs_vec3 Ac = fs_v3(A.x, Mc.y, A.z);
    fs_design_link_body(&g.body[FS_BODY_TALUS], "talus", d->talus_kg, Ac, Mc, ymax - ymin + d->link_width_m, d->link_width_m);
    g.body[FS_BODY_HEEL].soil_radius_m = d->soil_heel_radius_m > 0 ? d->soil_heel_radius_m : d->heel_radius_m;
    g.body[FS_BODY_TALUS].soil_radius_m = d->soil_talus_radius_m > 0 ? d->soil_talus_radius_m : 0.5 * d->link_width_m;
    if (d->l2_m == 0) /* the 4-bar: a talus of no length still has its width and thickness */
        g.body[FS_BODY_TALUS].com = Ac;
    g.hinge[0] = (fs_hinge_geom){.body1 = FS_BODY_HEEL, .body2 = FS_BODY_TALUS, .anchor = A, .axis = fs_v3(0, -1, 0)};
    snprintf(g.hinge[0].name, sizeof g.hinge[0].name, "ankle");
    g.nhinges = 1;
    /* Two heel spheres side by side (calcaneal tubercles): a single point would let the rear
     * foot roll over under load. */
    if (d->heel_width_m > 0) {
        add_sphere(&g, "heel_medial", FS_BODY_HEEL, fs_add(H, fs_v3(0, 0.5 * d->heel_width_m, 0)), d->heel_radius_m);
        add_sphere(&g, "heel_lateral", FS_BODY_HEEL, fs_add(H, fs_v3(0, -0.5 * d->heel_width_m, 0)), d->heel_radius_m);
    } else {
        add_sphere(&g, "heel", FS_BODY_HEEL, H, d->heel_radius_m);
    }
    g.ankle_body = FS_BODY_TALUS;
    g.ankle = A;
    for (int i = 0; i < FS_CHAINS; i++) {
        fs_status s = chain_geometry(d, cfg, i, H, A, &g, err);
        if (s != FS_OK)
            return s;
    }
    for (int i = 0; i < g.nbodies; i++)
        g.total_mass_kg += g.body[i].mass_kg;
    if (d->kind == FS_FOOT_FLAT)
        flat_geometry(d, &g, geom);
    else
        *geom = g;
    geom->nfeet = 1;
    geom->foot[0].nbodies = geom->nbodies;
    geom->foot[0].ankle_body = geom->ankle_body;
    geom->foot[0].ankle = geom->ankle;
    return FS_OK;
}

fs_status fs_design_load(const char *path, const char *const *overrides, int noverrides, fs_design_def *def,
                         fs_foot_geom *geom, fs_error *err)
{
    return fs_design_load_located(path, overrides, noverrides, def, geom, NULL, err);
}

fs_status fs_design_load_located(const char *path, const char *const *overrides, int noverrides, fs_design_def *def,
                                 fs_foot_geom *geom, char law_where[3][FS_DESIGN_WHERE_MAX], fs_error *err)
{
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    for (int i = 0; s == FS_OK && i < noverrides; i++)
        s = fs_config_override(&cfg, overrides[i], err);
    if (s == FS_OK) {
        memset(def, 0, sizeof *def);
        s = fs_config_bind(&cfg, fs_design_keys, fs_design_nkeys, def, err);
    }
    if (s == FS_OK)
        s = fs_design_geometry(def, &cfg, geom, err);
    for (int w = 0; s == FS_OK && law_where && w < 3; w++) {
        char key[16];
        snprintf(key, sizeof key, "d%d_law", w + 1);
        fs_config_where(&cfg, "springs", key, law_where[w], FS_DESIGN_WHERE_MAX);
    }
    fs_config_free(&cfg);
    return s;
}

fs_status fs_design_pinned_chain(const fs_design_def *d, const fs_foot_geom *foot, int chain, fs_foot_geom *out,
                                 fs_error *err)
{
    if (foot->kind != FS_FOOT_BIOMIMETIC)
        return fs_fail(err, FS_BAD_INPUT, "a pinned chain needs the biomimetic foot (foot.kind = biomimetic)");
    if (chain < 0 || chain >= FS_CHAINS || fs_design_splay_deg(d, chain) != 0)
        return fs_fail(err, FS_BAD_INPUT, "chain %d: give an unsplayed chain (1 to %d with chains.splay_deg = 0)",
                       chain + 1, FS_CHAINS);
    memset(out, 0, sizeof *out);
    out->kind = FS_FOOT_BIOMIMETIC;
    const int body_of[4] = {FS_BODY_HEEL, FS_BODY_TALUS, foot->chain[chain].metatarsal, foot->chain[chain].phalanx};
    const double share[4] = {1.0 / FS_CHAINS, 1.0 / FS_CHAINS, 1, 1};
    int index[FS_MAX_BODIES];
    for (int i = 0; i < FS_MAX_BODIES; i++)
        index[i] = -1;
    /* bodies, with the shared ones' share */
    for (int k = 0; k < 4; k++) {
        out->body[k] = foot->body[body_of[k]];
        out->body[k].mass_kg *= share[k];
        for (int r = 0; r < 9; r++)
            out->body[k].inertia[r] *= share[k];
        out->total_mass_kg += out->body[k].mass_kg;
        index[body_of[k]] = k;
    }
    out->nbodies = 4;
    /* the ankle, midfoot and MTP hinges */
    const int hinge_of[3] = {0, foot->chain[chain].midfoot_hinge, foot->chain[chain].mtp_hinge};
    for (int k = 0; k < 3; k++) {
        out->hinge[k] = foot->hinge[hinge_of[k]];
        out->hinge[k].body1 = index[out->hinge[k].body1];
        out->hinge[k].body2 = index[out->hinge[k].body2];
    }
    out->nhinges = 3;
    for (int k = 0; k < 3; k++) {
        out->spring[k] = foot->spring[foot->chain[chain].spring[k]];
        out->spring[k].body1 = index[out->spring[k].body1];
        out->spring[k].body2 = index[out->spring[k].body2];
        out->chain[0].spring[k] = k;
    }
    out->nsprings = 3;
    /* pins: the heel sphere's centre in the chain's plane, and the toe sphere's centre */
    fs_vec3 axis = foot->hinge[hinge_of[1]].axis;
    double heel = d->heel_deg * DEG;
    fs_vec3 H = fs_sub(foot->ankle, fs_v3(d->l1_m * cos(heel), 0, d->l1_m * sin(heel)));
    H.y = foot->chain[chain].midfoot.y;
    out->pin[0].body = 0;
    out->pin[0].anchor = H;
    out->pin[1].body = 3;
    out->pin[1].anchor = foot->chain[chain].toe;
    out->pin[0].axis = out->pin[1].axis = axis;
    out->npins = 2;
    out->ankle_body = index[foot->ankle_body];
    out->ankle = foot->ankle;
    out->chain[0].metatarsal = 2;
    out->chain[0].phalanx = 3;
    out->chain[0].midfoot_hinge = 1;
    out->chain[0].mtp_hinge = 2;
    out->chain[0].midfoot = foot->chain[chain].midfoot;
    out->chain[0].mtp = foot->chain[chain].mtp;
    out->chain[0].toe = foot->chain[chain].toe;
    out->chain[0].metatarsal_deg = foot->chain[chain].metatarsal_deg;
    return FS_OK;
}
