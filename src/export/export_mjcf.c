/* export_mjcf.c: a scenario's model (fs_model.h) written as MuJoCo MJCF (fs_export.h,
 * docs/export.md): read from the model a simulation is made of, not from an ODE world. */
#include "footsim/export/fs_export.h"

#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_model.h"

#include <libxml/xmlwriter.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NODES = FS_MODEL_MAX_BODIES, EDGES = FS_MAX_HINGES + 1 };

/* A body of the tree: a foot body, or the robot (index nbodies): the model's body of its index. */
typedef struct node {
    const char *name;
    double p[3], q[4], R[9]; /* world pose: position of the COM, quaternion (w x y z), rotation */
    int parent, edge;        /* parent node and the joint to it (-1: the root, or welded) */
} node;

/* A joint between two nodes: a hinge, or the robot's fixed joint. */
typedef struct edge {
    int a, b, hinge;
    const char *name;
    double anchor[3], axis[3]; /* world */
    int in_tree;
} edge;

typedef struct exporter {
    const fs_model *m;
    const fs_scenario *sc;
    int with_scenario;
    const char *hfield_file;
    xmlTextWriterPtr w;
    int ok;
    node node[NODES];
    int nnodes;
    edge edge[EDGES];
    int nedges;
    double solref[2], mu;
} exporter;

/* ---- writing ------------------------------------------------------------------------------- */

static void start(exporter *x, const char *element)
{
    if (xmlTextWriterStartElement(x->w, BAD_CAST element) < 0)
        x->ok = 0;
}

static void end(exporter *x)
{
    if (xmlTextWriterEndElement(x->w) < 0)
        x->ok = 0;
}

static void attr(exporter *x, const char *name, const char *value)
{
    if (xmlTextWriterWriteAttribute(x->w, BAD_CAST name, BAD_CAST value) < 0)
        x->ok = 0;
}

/* n numbers, each %.17g (exact when read back), separated by spaces. */
static void attr_num(exporter *x, const char *name, const double *v, int n)
{
    char buf[32 * 8] = "";
    size_t len = 0;
    for (int i = 0; i < n; i++)
        len += (size_t)snprintf(buf + len, sizeof buf - len, "%s%.17g", i ? " " : "", v[i] == 0 ? 0.0 : v[i]);
    attr(x, name, buf);
}

static void attr1(exporter *x, const char *name, double v) { attr_num(x, name, &v, 1); }

static void attrf(exporter *x, const char *name, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    attr(x, name, buf);
}

/* XML forbids "--" inside a comment (and a comment ending in "-"): a path may hold them. */
static void comment(exporter *x, const char *text)
{
    char safe[2 * (2 * FS_PATH_MAX + 256)];
    size_t n = 0;
    for (const char *c = text; *c && n + 3 < sizeof safe; c++) {
        safe[n++] = *c;
        if (*c == '-' && (c[1] == '-' || c[1] == 0))
            safe[n++] = ' ';
    }
    safe[n] = 0;
    if (xmlTextWriterWriteComment(x->w, BAD_CAST safe) < 0)
        x->ok = 0;
}

/* ---- frames -------------------------------------------------------------------------------- */

/* v in the frame of node n: R^T (w - p) for a point, R^T w for a direction. */
static void to_local(const node *n, const double w[3], int point, double v[3])
{
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = w[k] - (point ? n->p[k] : 0);
    for (int k = 0; k < 3; k++)
        v[k] = n->R[k] * d[0] + n->R[3 + k] * d[1] + n->R[6 + k] * d[2];
}

/* conj(a) * b: b's rotation in a's frame. */
static void quat_rel(const double a[4], const double b[4], double q[4])
{
    double w = a[0], x = -a[1], y = -a[2], z = -a[3];
    q[0] = w * b[0] - x * b[1] - y * b[2] - z * b[3];
    q[1] = w * b[1] + x * b[0] + y * b[3] - z * b[2];
    q[2] = w * b[2] - x * b[3] + y * b[0] + z * b[1];
    q[3] = w * b[3] + x * b[2] - y * b[1] + z * b[0];
}

/* The bodies, the joints between them, and a spanning tree by breadth-first search from the root
 * (the robot when there is one, else the first body): edges outside it close loops. */
static void gather(exporter *x)
{
    const fs_model *m = x->m;
    for (int i = 0; i < m->nbodies + m->robot_body; i++) {
        node *n = &x->node[x->nnodes++];
        n->name = m->body[i].name;
        memcpy(n->p, m->body[i].pos_m, sizeof n->p);
        memcpy(n->q, m->q0_wxyz, sizeof n->q);
        memcpy(n->R, m->R0, sizeof n->R);
    }
    for (int i = 0; i < m->nhinges; i++) {
        edge *e = &x->edge[x->nedges++];
        const fs_model_hinge *h = &m->hinge[i];
        e->a = h->body1;
        e->b = h->body2;
        e->hinge = 1;
        e->name = m->geom->hinge[i].name;
        memcpy(e->anchor, h->anchor_m, sizeof e->anchor);
        memcpy(e->axis, h->axis, sizeof e->axis);
    }
    if (m->robot_body) {
        edge *e = &x->edge[x->nedges++];
        e->a = x->nnodes - 1;
        e->b = m->geom->ankle_body;
        e->hinge = m->robot_joint != FS_ROBOT_RIGID;
        e->name = "robot_ankle";
        if (e->hinge) {
            memcpy(e->anchor, m->robot_hinge_anchor_m, sizeof e->anchor);
            memcpy(e->axis, m->robot_hinge_axis, sizeof e->axis);
        }
    }
    int queue[NODES], head = 0, tail = 0, seen[NODES] = {0};
    int root = m->robot_body ? x->nnodes - 1 : 0;
    for (int i = 0; i < x->nnodes; i++)
        x->node[i].parent = x->node[i].edge = -1;
    queue[tail++] = root;
    seen[root] = 1;
    while (head < tail) {
        int n = queue[head++];
        for (int k = 0; k < x->nedges; k++) {
            edge *e = &x->edge[k];
            int other = e->a == n ? e->b : e->b == n ? e->a : -1;
            if (other < 0 || seen[other])
                continue;
            seen[other] = 1;
            e->in_tree = 1;
            x->node[other].parent = n;
            x->node[other].edge = k;
            queue[tail++] = other;
        }
    }
}

/* ---- contact parameters -------------------------------------------------------------------- */

/* ODE's soft contact (ERP, CFM at step h) is a spring-damper of stiffness k = ERP / (h CFM) and
 * damping c = (1 - ERP) / CFM per contact point. MuJoCo's direct solref (-stiffness, -damping) with
 * a constant impedance d gives the contact's violation r the dynamics r'' + damping r' +
 * stiffness r = (1 - d) a0: per unit of the mass the contact carries. That mass is taken as the
 * weight borne (foot, load, robot) shared by the contact points of a flat landing (each sphere
 * one, the box four). */
static void contact_parameters(exporter *x)
{
    const fs_model *mo = x->m;
    const fs_foot_geom *g = mo->geom;
    double h = x->sc->def.step_s, erp = mo->contact_erp, cfm = mo->contact_cfm;
    double k = erp / (h * cfm), c = (1 - erp) / cfm;
    double mass = g->total_mass_kg;
    if (x->with_scenario)
        mass += x->sc->def.load_kg + (mo->robot_body ? x->sc->def.robot.mass_kg : 0);
    int points = g->nspheres + 4 * g->nboxes;
    double m = mass / (points > 0 ? points : 1);
    x->solref[0] = -k / m;
    x->solref[1] = -c / m;
    x->mu = mo->mu;
}

static void contact_attrs(exporter *x)
{
    const double imp[3] = {FS_MJCF_IMPEDANCE, FS_MJCF_IMPEDANCE, 0.001};
    const double friction[3] = {x->mu, 0, 0};
    attr(x, "condim", "3");
    attr_num(x, "friction", friction, 3);
    attr_num(x, "solref", x->solref, 2);
    attr_num(x, "solimp", imp, 3);
}

/* ---- the foot ------------------------------------------------------------------------------ */

static void inertial(exporter *x, int i)
{
    const fs_model_body *b = &x->m->body[i];
    start(x, "inertial");
    const double zero[3] = {0, 0, 0};
    attr_num(x, "pos", zero, 3);
    attr1(x, "mass", b->mass_kg);
    const double *I = b->inertia_kg_m2; /* 3 x 3, row-major, about the COM in the body frame */
    if (I[1] == 0 && I[2] == 0 && I[5] == 0) {
        const double d[3] = {I[0], I[4], I[8]};
        attr_num(x, "diaginertia", d, 3);
    } else {
        const double f[6] = {I[0], I[4], I[8], I[1], I[2], I[5]};
        attr_num(x, "fullinertia", f, 6);
    }
    end(x);
}

static void site(exporter *x, const node *n, const char *name, const double world[3])
{
    double v[3];
    to_local(n, world, 1, v);
    start(x, "site");
    attr(x, "name", name);
    attr_num(x, "pos", v, 3);
    end(x);
}

/* The sites of the springs (and the Achilles tendon) that end on node i. */
static void sites(exporter *x, int i)
{
    const fs_model *m = x->m;
    const node *n = &x->node[i];
    char name[96];
    for (int k = 0; k < m->nsprings; k++) {
        const fs_model_spring *s = &m->spring[k];
        if (s->body1 == i) {
            snprintf(name, sizeof name, "%s_1", s->name);
            site(x, n, name, s->p1_m);
        }
        if (s->body2 == i) {
            snprintf(name, sizeof name, "%s_2", s->name);
            site(x, n, name, s->p2_m);
        }
    }
    if (m->has_achilles) {
        if (m->achilles.body1 == i)
            site(x, n, "achilles_1", m->achilles.p1_m);
        if (m->achilles.body2 == i)
            site(x, n, "achilles_2", m->achilles.p2_m);
    }
}

/* A geom's box size (MuJoCo's is half lengths), from its edges. */
static void half_size(exporter *x, const double edges[3])
{
    const double half[3] = {0.5 * edges[0], 0.5 * edges[1], 0.5 * edges[2]};
    attr_num(x, "size", half, 3);
}

/* A geom's place and class, and its end. */
static void geom_placed(exporter *x, const double pos[3], const double q[4], const char *cls)
{
    attr_num(x, "pos", pos, 3);
    attr_num(x, "quat", q, 4);
    attr(x, "class", cls);
    end(x);
}

/* The contact shapes on node i: spheres and the sole box (MuJoCo's box size is half lengths). */
static void shapes(exporter *x, int i)
{
    const fs_model *m = x->m;
    const node *n = &x->node[i];
    int count = 0;
    for (int k = 0; k < m->nshapes; k++) {
        const fs_model_shape *g = &m->shape[k];
        if (g->body != i || i >= m->nbodies)
            continue;
        /* in the body's frame: the model's offset, turned as the body is */
        const double *p = g->offset_m, q[4] = {1, 0, 0, 0};
        start(x, "geom");
        if (g->kind == FS_MODEL_SPHERE) {
            attrf(x, "name", "%s_sphere%d", n->name, ++count);
            attr(x, "type", "sphere");
            attr1(x, "size", g->radius_m);
        } else {
            attrf(x, "name", "%s_box", n->name);
            attr(x, "type", "box");
            half_size(x, g->size_m);
        }
        geom_placed(x, p, q, "foot");
    }
}

/* The static load: a point mass welded at the ankle (its weight is the load; it is not ramped). */
static void load_body(exporter *x, int i)
{
    const fs_model *m = x->m;
    if (!x->with_scenario || x->sc->def.load_kg <= 0 || i != m->geom->ankle_body)
        return;
    double p[3];
    to_local(&x->node[i], m->ankle_m, 1, p);
    comment(x, " the scenario's static load as a point mass at the ankle (footsim ramps its weight in over "
               "ramp_s) ");
    start(x, "body");
    attr(x, "name", "load");
    attr_num(x, "pos", p, 3);
    start(x, "inertial");
    const double zero[3] = {0, 0, 0};
    attr_num(x, "pos", zero, 3);
    attr1(x, "mass", x->sc->def.load_kg);
    /* a point mass: MuJoCo wants some inertia; a 1 mm sphere of that mass */
    double I = 0.4 * x->sc->def.load_kg * 1e-6;
    const double d[3] = {I, I, I};
    attr_num(x, "diaginertia", d, 3);
    end(x);
    end(x);
}

static void joint_to_parent(exporter *x, int i)
{
    node *n = &x->node[i];
    if (n->parent < 0) { /* the root: free, or the walking machine's vertical slide */
        if (x->m->robot_body && i == x->m->nbodies && x->m->robot_vertical) {
            const double up[3] = {0, 0, 1};
            double v[3];
            to_local(n, up, 0, v);
            start(x, "joint");
            attr(x, "name", "carriage");
            attr(x, "type", "slide");
            attr_num(x, "axis", v, 3);
            end(x);
        } else {
            start(x, "freejoint"); /* "root"; a body no joint holds (a cut loop's) is free on its own */
            if (i == (x->m->robot_body ? x->nnodes - 1 : 0))
                attr(x, "name", "root");
            else
                attrf(x, "name", "%s_free", n->name);
            end(x);
        }
        return;
    }
    const edge *e = &x->edge[n->edge];
    if (!e->hinge)
        return; /* welded to its parent */
    double p[3], a[3];
    to_local(n, e->anchor, 1, p);
    to_local(n, e->axis, 0, a);
    start(x, "joint");
    attr(x, "name", e->name);
    attr(x, "type", "hinge");
    attr_num(x, "pos", p, 3);
    attr_num(x, "axis", a, 3);
    end(x);
}

static void body(exporter *x, int i)
{
    node *n = &x->node[i];
    double p[3], q[4];
    const double identity[4] = {1, 0, 0, 0};
    if (n->parent >= 0) {
        to_local(&x->node[n->parent], n->p, 1, p);
        quat_rel(x->node[n->parent].q, n->q, q);
    } else {
        memcpy(p, n->p, sizeof p);
        quat_rel(identity, n->q, q);
    }
    start(x, "body");
    attr(x, "name", n->name);
    attr_num(x, "pos", p, 3);
    attr_num(x, "quat", q, 4);
    joint_to_parent(x, i);
    inertial(x, i);
    shapes(x, i);
    sites(x, i);
    load_body(x, i);
    for (int k = 0; k < x->nnodes; k++)
        if (x->node[k].parent == i)
            body(x, k);
    end(x);
}

/* ---- the ground ---------------------------------------------------------------------------- */

/* The terrain's lattice as one heightfield; MuJoCo scales samples to [0, 1] of its height. */
/* MuJoCo's hfield size: half extents in x and y, the height of the highest sample above the lowest,
 * and a base below the lowest as thick as ODE's (sim_ground.c). */
static void hfield_size(const fs_terrain *t, double size[4])
{
    double range = t->zmax - t->zmin;
    size[0] = 0.5 * (t->nx - 1) * t->dx;
    size[1] = 0.5 * (t->ny - 1) * t->dx;
    size[2] = range > 0 ? range : 1e-9;
    size[3] = 0.05 + range;
}

static void hfield_geom(exporter *x)
{
    const fs_terrain *t = &x->sc->terrain;
    double size[4];
    hfield_size(t, size);
    double pos[3] = {t->x0 + size[0], t->y0 + size[1], t->zmin};
    start(x, "geom");
    attr(x, "name", "terrain");
    attr(x, "type", "hfield");
    attr(x, "hfield", "terrain");
    attr_num(x, "pos", pos, 3);
    attr(x, "class", "ground");
    end(x);
}

static int has_hfield(const exporter *x)
{
    return x->with_scenario && x->m->with_ground && fs_terrain_is_heightfield(&x->sc->terrain) && x->sc->terrain.z;
}

static void ground(exporter *x)
{
    const fs_model *m = x->m;
    if (!m->with_ground)
        return;
    if (has_hfield(x)) /* the lattice, whether or not ODE has it as tiles */
        hfield_geom(x);
    for (int i = 0; i < m->nplanes; i++) {
        const double *r = m->plane[i].normal, d = m->plane[i].offset_m;
        double pos[3] = {d * r[0], d * r[1], d * r[2]};
        /* the rotation taking z to the normal: (1 + n_z, -n_y, n_x, 0), normalised */
        double q[4] = {1 + r[2], -r[1], r[0], 0}, s = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        for (int k = 0; k < 4; k++)
            q[k] /= s;
        const double size[3] = {0, 0, 0.05};
        start(x, "geom");
        attrf(x, "name", "plane%d", i + 1);
        attr(x, "type", "plane");
        attr_num(x, "size", size, 3);
        geom_placed(x, pos, q, "ground");
    }
    for (int i = 0; i < m->nblocks; i++) {
        const double q[4] = {1, 0, 0, 0};
        start(x, "geom");
        attrf(x, "name", "step%d", i + 1);
        attr(x, "type", "box");
        half_size(x, m->block[i].size_m);
        geom_placed(x, m->block[i].pos_m, q, "ground");
    }
}

/* MuJoCo's binary hfield file: int32 rows, int32 columns, then rows x columns float32 samples,
 * row 0 at the smallest y (as footsim's lattice), scaled here to [0, 1] of the height range. */
static unsigned char *hfield_data(const fs_terrain *t, size_t *len)
{
    size_t n = (size_t)t->nx * t->ny;
    *len = 8 + 4 * n;
    unsigned char *buf = malloc(*len);
    if (!buf)
        return NULL;
    int32_t dims[2] = {t->ny, t->nx};
    memcpy(buf, dims, sizeof dims);
    double range = t->zmax - t->zmin;
    for (size_t k = 0; k < n; k++) {
        float v = range > 0 ? (float)((t->z[k] - t->zmin) / range) : 0.0f;
        memcpy(buf + 8 + 4 * k, &v, 4);
    }
    return buf;
}

/* ---- the document -------------------------------------------------------------------------- */

static void defaults(exporter *x)
{
    start(x, "default");
    start(x, "default");
    attr(x, "class", "foot");
    start(x, "geom");
    /* foot shapes touch the ground only, as in footsim (contype & conaffinity decide pairs) */
    attr(x, "contype", "1");
    attr(x, "conaffinity", "0");
    attr(x, "group", "1"); /* the ground is group 0: a ray or a viewer can tell them apart */
    contact_attrs(x);
    attr(x, "rgba", "0.8 0.6 0.4 1");
    end(x);
    end(x);
    start(x, "default");
    attr(x, "class", "ground");
    start(x, "geom");
    attr(x, "contype", "0");
    attr(x, "conaffinity", "1");
    contact_attrs(x);
    attr(x, "rgba", "0.5 0.55 0.5 1");
    end(x);
    end(x);
    start(x, "site");
    attr(x, "size", "0.001");
    end(x);
    end(x);
}

/* The mass a spring's line moves, as if its two bodies were free: 1/m = the sum over both of
 * 1/m_b + (r_b x u)^T I_b^-1 (r_b x u), r_b its anchor from the body's centre, u the line (the
 * world's anchor adds nothing), from the model at the start pose (every body at rotation R0, its
 * inertia in the body's frame). */
static double line_mass(const fs_model *m, const fs_model_spring *s)
{
    const double *p[2] = {s->p1_m, s->p2_m};
    const int body[2] = {s->body1, s->body2};
    double u[3], len = 0, inv = 0;
    for (int i = 0; i < 3; i++) {
        u[i] = p[1][i] - p[0][i];
        len += u[i] * u[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++)
        u[i] /= len;
    for (int e = 0; e < 2; e++) {
        if (body[e] < 0)
            continue;
        const fs_model_body *b = &m->body[body[e]];
        double r[3], w[3], wl[3];
        for (int i = 0; i < 3; i++)
            r[i] = p[e][i] - b->pos_m[i];
        w[0] = r[1] * u[2] - r[2] * u[1];
        w[1] = r[2] * u[0] - r[0] * u[2];
        w[2] = r[0] * u[1] - r[1] * u[0];
        for (int i = 0; i < 3; i++) /* into the body's frame: R0 transposed */
            wl[i] = m->R0[i] * w[0] + m->R0[3 + i] * w[1] + m->R0[6 + i] * w[2];
        /* I^-1 wl by the adjugate (I symmetric, positive definite) */
        const double *I = b->inertia_kg_m2;
        double a[9] = {I[4] * I[8] - I[5] * I[7], I[2] * I[7] - I[1] * I[8], I[1] * I[5] - I[2] * I[4],
                       I[5] * I[6] - I[3] * I[8], I[0] * I[8] - I[2] * I[6], I[2] * I[3] - I[0] * I[5],
                       I[3] * I[7] - I[4] * I[6], I[1] * I[6] - I[0] * I[7], I[0] * I[4] - I[1] * I[3]};
        double det = I[0] * a[0] + I[1] * a[3] + I[2] * a[6], q = 0;
        for (int i = 0; i < 3; i++)
            q += wl[i] * (a[3 * i] * wl[0] + a[3 * i + 1] * wl[1] + a[3 * i + 2] * wl[2]) / det;
        inv += 1 / b->mass_kg + q;
    }
    return 1 / inv;
}

static void tendon(exporter *x, const char *name, const fs_model_spring *s)
{
    char a[96], b[96];
    snprintf(a, sizeof a, "%s_1", name);
    snprintf(b, sizeof b, "%s_2", name);
    start(x, "spatial");
    attr(x, "name", name);
    if (s->law.tension_only) {
        /* a cable: no spring of its own, a limit at its rest length instead (one-sided: it acts only
           while the tendon is longer), as soft as the spring for the mass its line moves, in the
           direct form (docs/export.md) */
        const double range[2] = {0, s->rest_length_m}, imp[3] = {FS_MJCF_IMPEDANCE, FS_MJCF_IMPEDANCE, 0.001};
        double ml = line_mass(x->m, s), ref[2] = {-s->k_N_per_m / ml, -s->c_Ns_per_m / ml};
        attr(x, "limited", "true");
        attr_num(x, "range", range, 2);
        attr_num(x, "solreflimit", ref, 2);
        attr_num(x, "solimplimit", imp, 3);
    } else {
        attr1(x, "stiffness", s->k_N_per_m);
        attr1(x, "damping", s->c_Ns_per_m);
        attr1(x, "springlength", s->rest_length_m);
    }
    attr(x, "width", "0.0005");
    start(x, "site");
    attr(x, "site", a);
    end(x);
    start(x, "site");
    attr(x, "site", b);
    end(x);
    end(x);
}

/* A hinge closing a loop: two points on its axis held together (a ball joint each; together a hinge). */
static void loop_closures(exporter *x)
{
    int any = 0;
    for (int k = 0; k < x->nedges; k++) {
        const edge *e = &x->edge[k];
        if (e->in_tree)
            continue;
        if (!any++)
            start(x, "equality");
        for (int s = -1; s <= 1; s += 2) {
            const double half = 0.005; /* m along the axis either side of the anchor */
            double w[3], v[3];
            for (int c = 0; c < 3; c++)
                w[c] = e->anchor[c] + s * half * e->axis[c];
            to_local(&x->node[e->a], w, 1, v);
            start(x, e->hinge ? "connect" : "weld");
            attrf(x, "name", "%s_%s", e->name, s < 0 ? "a" : "b");
            attr(x, "body1", x->node[e->a].name);
            attr(x, "body2", x->node[e->b].name);
            if (e->hinge)
                attr_num(x, "anchor", v, 3);
            end(x);
            if (!e->hinge)
                break;
        }
    }
    if (any)
        end(x);
}

static void document(exporter *x)
{
    const fs_model *m = x->m;
    const fs_scenario *sc = x->sc;
    if (xmlTextWriterStartDocument(x->w, NULL, "UTF-8", NULL) < 0)
        x->ok = 0;
    if (xmlTextWriterSetIndent(x->w, 1) < 0 || xmlTextWriterSetIndentString(x->w, BAD_CAST "  ") < 0)
        x->ok = 0;
    char text[2 * FS_PATH_MAX + 256];
    snprintf(text, sizeof text,
             " footsim export (MJCF) of %s%s%s. SI units, x forward, y left, z up. docs/export.md says what maps "
             "one to one and what does not. ",
             sc->def.design_path, x->with_scenario ? ", scenario " : "", x->with_scenario ? sc->path : "");
    comment(x, text);
    start(x, "mujoco");
    attr(x, "model", x->with_scenario ? sc->name : "foot");
    start(x, "compiler");
    attr(x, "angle", "radian");
    attr(x, "inertiafromgeom", "false");
    end(x);
    start(x, "option");
    attr1(x, "timestep", sc->def.step_s);
    double gvec[3] = {sc->def.gravity_m_per_s2 * m->down[0], sc->def.gravity_m_per_s2 * m->down[1],
                      sc->def.gravity_m_per_s2 * m->down[2]};
    attr_num(x, "gravity", gvec, 3);
    /* damping implicit, as footsim's implicit springs are (their stiffness stays explicit) */
    attr(x, "integrator", "implicit");
    /* friction as stiff as ODE's (no creep under the static load; docs/export.md measures it) */
    attr(x, "impratio", "100");
    end(x);
    defaults(x);
    if (has_hfield(x)) {
        double size[4];
        hfield_size(&sc->terrain, size);
        start(x, "asset");
        start(x, "hfield");
        attr(x, "name", "terrain");
        attr(x, "file", x->hfield_file);
        attr_num(x, "size", size, 4);
        end(x);
        end(x);
    }
    start(x, "worldbody");
    if (x->with_scenario)
        ground(x);
    for (int i = 0; i < x->nnodes; i++)
        if (x->node[i].parent < 0)
            body(x, i);
    end(x);
    start(x, "tendon");
    for (int k = 0; k < m->nsprings; k++)
        tendon(x, m->spring[k].name, &m->spring[k]);
    if (m->has_achilles)
        tendon(x, "achilles", &m->achilles);
    end(x);
    loop_closures(x);
    end(x); /* mujoco */
    if (xmlTextWriterEndDocument(x->w) < 0)
        x->ok = 0;
}

fs_status fs_mjcf_build(const fs_scenario *sc, int with_scenario, const char *hfield_file, fs_mjcf *out,
                        fs_error *err)
{
    memset(out, 0, sizeof *out);
    if (with_scenario && sc->def.robot.kind == FS_ROBOT_BIPED && sc->def.robot.mass_kg > 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: kind = biped: the biped is not exported (its leg joints' angular "
                       "spring-dampers, ODE hinge stops, have no counterpart in this export yet): export the foot "
                       "with a single robot (robots/single_tall.ini), or without --scenario", sc->def.robot_path);
    for (int i = 0; i < sc->geom.nsprings; i++) {
        const fs_spring_law *law = &sc->geom.spring[i].law;
        if (law->kind == FS_LAW_LINEAR)
            continue;
        /* the line of its kind's law key (springs.dN_law) */
        const char *where = sc->def.design_path;
        for (int c = 0; c < FS_CHAINS; c++)
            for (int w = 0; w < FS_SPRINGS_PER_CHAIN; w++)
                if (sc->geom.chain[c].spring[w] == i && sc->law_where[w][0])
                    where = sc->law_where[w];
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: spring %s's law is %s, which MuJoCo 2.2.2's tendons cannot express (one linear spring "
                       "and one rest length each): export a design whose springs are linear (tension-only ones "
                       "map, as limited tendons; docs/export.md)",
                       where, sc->geom.spring[i].name, fs_spring_law_name(law));
    }
    fs_model *model;
    /* the robot as its own body, welded to the ankle body as footsim's fixed joint welds it: a reader
       sees the robot apart (footsim's merge of the two is a speed cut, docs/bench.md) */
    fs_sim_options opts = {.with_ground = with_scenario, .keep_robot_body = 1};
    fs_status s = fs_model_compile(sc, &opts, &model, err);
    if (s != FS_OK)
        return s;
    exporter *x = calloc(1, sizeof *x);
    xmlBufferPtr buf = xmlBufferCreate();
    if (x && buf)
        x->w = xmlNewTextWriterMemory(buf, 0);
    if (!x || !buf || !x->w) {
        free(x);
        xmlBufferFree(buf);
        fs_model_free(model);
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the MJCF document", sc->path);
    }
    x->m = model;
    x->sc = sc;
    x->with_scenario = with_scenario;
    x->hfield_file = hfield_file ? hfield_file : "terrain.hfield.bin";
    x->ok = 1;
    gather(x);
    contact_parameters(x);
    document(x);
    xmlFreeTextWriter(x->w); /* flushes into buf */
    int ok = x->ok;
    if (ok && has_hfield(x)) {
        out->hfield = hfield_data(&sc->terrain, &out->hfield_len);
        ok = out->hfield != NULL;
    }
    free(x);
    fs_model_free(model);
    if (ok) {
        size_t len = (size_t)xmlBufferLength(buf);
        out->xml = malloc(len + 1);
        if (out->xml) {
            memcpy(out->xml, xmlBufferContent(buf), len);
            out->xml[len] = 0;
            out->xml_len = len;
        }
    }
    xmlBufferFree(buf);
    if (!ok || !out->xml) {
        fs_mjcf_free(out);
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the MJCF document", sc->path);
    }
    return FS_OK;
}

void fs_mjcf_free(fs_mjcf *m)
{
    free(m->xml);
    free(m->hfield);
    memset(m, 0, sizeof *m);
}

void fs_mjcf_hfield_path(const char *path, char *out, size_t size)
{
    size_t n = strlen(path);
    if (n >= 4 && !strcmp(path + n - 4, ".xml"))
        n -= 4;
    snprintf(out, size, "%.*s.hfield.bin", (int)n, path);
}

fs_status fs_mjcf_write(const fs_scenario *sc, int with_scenario, const char *path, fs_error *err)
{
    char hpath[FS_OUT_PATH];
    fs_mjcf_hfield_path(path, hpath, sizeof hpath);
    const char *slash = strrchr(hpath, '/');
    /* the structural checks only (replace = 1): export has no --replace, and writes over a file at
     * --out as it did before the kind check came in for terrain --png */
    fs_status s = fs_check_file_target(path, "--out", NULL, 0, "an MJCF file", 1, err);
    if (s != FS_OK)
        return s;
    fs_mjcf m;
    if ((s = fs_mjcf_build(sc, with_scenario, slash ? slash + 1 : hpath, &m, err)) != FS_OK)
        return s;
    if (m.hfield)
        s = fs_write_atomic(hpath, (const char *)m.hfield, m.hfield_len, err);
    if (s == FS_OK)
        s = fs_write_atomic(path, m.xml, m.xml_len, err);
    fs_mjcf_free(&m);
    return s;
}
