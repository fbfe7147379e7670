/* sim_soil_grid.c: the soil's nodes, tiles and per-node laws (fs_soil_grid.h); no ODE here. */
#include "footsim/sim/fs_soil_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { T = FS_SOIL_TILE, TT = FS_SOIL_TILE * FS_SOIL_TILE };
_Static_assert(FS_SOIL_TILE == 16, "log2_of covers the strides up to 16");
/* The shift of each stride (a power of two up to a tile's width). */
static const unsigned char log2_of[T + 1] = {0, 0, 1, 0, 2, 0, 0, 0, 3, 0, 0, 0, 0, 0, 0, 0, 4};

/* ---- geometry: a vertical line against a shape ---------------------------------------------- */

static void to_world(const fs_soil_body *b, const double l[3], double w[3])
{
    for (int r = 0; r < 3; r++)
        w[r] = b->p[r] + b->R[3 * r] * l[0] + b->R[3 * r + 1] * l[1] + b->R[3 * r + 2] * l[2];
}

/* Without the library's calls (fmin and fmax are calls in C11 without -ffast-math): the same value for
 * every number that is not NaN, which the step never meets. */
static inline double lo2(double a, double b) { return b < a ? b : a; }
static inline double hi2(double a, double b) { return b > a ? b : a; }

/* A shape where its body is now: world ends (capsule) or centre and axes (box), and what its lowest
 * point on a vertical line needs that does not depend on the line (computed once a step). */
typedef struct placed {
    int kind;
    double A[3], B[3], R[9], r, half[3];
    double cA[3], cB[3]; /* capsule: the part of its segment whose balls reach below a height (clip_below) */
    double D[3], a, aD, r2; /* capsule: B - A, |D_xy|^2, |D|^2 (as a + D_z^2), r^2 */
    int flat[3];            /* box: its axis k is horizontal (the line runs along its faces k) */
    double hull[8][2];      /* box: its plan, the hull of its corners' plans, counter-clockwise (coverage) */
    int nh;
    double hull_m2, ylo, yhi; /* ... its area and its extent in y */
    double corner[8][2];      /* box: its corners in plan (box_corners) */
    double band[4][2];        /* capsule: the band between its clipped ends' disks, in plan (plan_band) */
    int has_band;             /* ... when those ends differ in plan */
} placed;

/* The lowest point of the capsule (segment A-B, radius r) on the vertical line through (x, y): the
 * capsule is the union of balls along the segment, so the lowest point is the lowest of
 * g(t) = A_z + t D_z - sqrt(r^2 - rho(t)^2), rho the horizontal distance to A + t D; g is convex
 * and its stationary point has a closed form. */
static inline double capsule_lowest(const placed *p, double x, double y, double n[3])
{
    const double *A = p->A, *D = p->D, r = p->r, r2 = p->r2, a = p->a;
    double wx = x - A[0], wy = y - A[1];
    double wd = wx * D[0] + wy * D[1], w2 = wx * wx + wy * wy;
    double t;
    if (a < 1e-18) {
        t = D[2] > 0 ? 0 : 1;
    } else {
        double perp2 = hi2(0, w2 - wd * wd / a); /* squared distance to the segment's line, in plan */
        if (perp2 >= r2)
            return INFINITY;
        double u = -D[2] * sqrt(a * (r2 - perp2) / p->aD);
        t = (u + wd) / a;
        t = lo2(1, hi2(0, t));
    }
    double qx = A[0] + t * D[0], qy = A[1] + t * D[1], qz = A[2] + t * D[2];
    double rho2 = (x - qx) * (x - qx) + (y - qy) * (y - qy);
    if (rho2 >= r2)
        return INFINITY;
    double z = qz - sqrt(r2 - rho2);
    if (n)
        n[0] = (x - qx) / r, n[1] = (y - qy) / r, n[2] = (z - qz) / r;
    return z;
}

/* The box (centre A, axes the columns of R, half lengths half) entered by a line going up through (x, y):
 * in the box's frame the line runs from o (its point at z = A_z) along the box's third row of R. */
static inline double box_lowest(const placed *p, double x, double y, double n[3])
{
    const double *R = p->R, *h = p->half;
    double rx = x - p->A[0], ry = y - p->A[1];
    double t0 = -INFINITY, t1 = INFINITY;
    int face = -1;
    for (int k = 0; k < 3; k++) {
        double o = R[k] * rx + R[3 + k] * ry, dir = R[6 + k];
        if (p->flat[k]) {
            if (fabs(o) > h[k])
                return INFINITY;
            continue;
        }
        double ta = (-h[k] - o) / dir, tb = (h[k] - o) / dir;
        if (ta > tb) {
            double s = ta;
            ta = tb, tb = s;
        }
        if (ta > t0)
            t0 = ta, face = k;
        t1 = lo2(t1, tb);
    }
    if (t0 > t1 || face < 0)
        return INFINITY;
    double s = R[6 + face] > 0 ? -1 : 1; /* the face entered looks against the line */
    for (int r = 0; n && r < 3; r++)
        n[r] = s * R[3 * r + face];
    return p->A[2] + t0;
}

/* A box's eight corners in plan. */
static void box_corners(const placed *p, double pt[8][2])
{
    for (int c = 0; c < 8; c++) {
        double sx = c & 1 ? 1 : -1, sy = c & 2 ? 1 : -1, sz = c & 4 ? 1 : -1;
        for (int k = 0; k < 2; k++)
            pt[c][k] = p->A[k] + p->R[3 * k] * sx * p->half[0] + p->R[3 * k + 1] * sy * p->half[1] +
                       p->R[3 * k + 2] * sz * p->half[2];
    }
}

static double cross3(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* A box's plan: the convex hull of its corners (Andrew's monotone chain, counter-clockwise, no
 * repeated or collinear points), its area and its extent in y. */
static void box_hull(placed *p)
{
    double pt[8][2], h[16][2];
    memcpy(pt, p->corner, sizeof pt);
    for (int a = 1; a < 8; a++) /* by x, then y */
        for (int b = a; b > 0 && (pt[b][0] < pt[b - 1][0] || (pt[b][0] == pt[b - 1][0] && pt[b][1] < pt[b - 1][1])); b--) {
            double t0 = pt[b][0], t1 = pt[b][1];
            pt[b][0] = pt[b - 1][0], pt[b][1] = pt[b - 1][1], pt[b - 1][0] = t0, pt[b - 1][1] = t1;
        }
    int n = 0;
    for (int pass = 0; pass < 2; pass++) { /* the lower chain left to right, the upper right to left */
        int base = n;
        for (int k = 0; k < 8; k++) {
            const double *q = pt[pass ? 7 - k : k];
            while (n >= base + 2 && cross3(h[n - 2], h[n - 1], q) <= 0)
                n--;
            h[n][0] = q[0], h[n][1] = q[1], n++;
        }
        n--; /* each chain's last point starts the other */
    }
    p->nh = n < 8 ? n : 8;
    p->hull_m2 = 0, p->ylo = INFINITY, p->yhi = -INFINITY;
    for (int k = 0; k < p->nh; k++) {
        p->hull[k][0] = h[k][0], p->hull[k][1] = h[k][1];
        p->ylo = lo2(p->ylo, h[k][1]), p->yhi = hi2(p->yhi, h[k][1]);
    }
    for (int k = 0; k < p->nh; k++)
        p->hull_m2 += 0.5 * cross3(p->hull[0], p->hull[k], p->hull[(k + 1) % p->nh]);
}

static void place(const fs_soil_shape *s, const fs_soil_body *body, placed *p)
{
    p->kind = s->kind;
    p->r = s->radius_m;
    memcpy(p->half, s->half, sizeof p->half);
    to_world(body, s->a, p->A);
    to_world(body, s->b, p->B);
    memcpy(p->cA, p->A, sizeof p->A);
    memcpy(p->cB, p->B, sizeof p->B);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            p->R[3 * r + c] = body->R[3 * r] * s->R[c] + body->R[3 * r + 1] * s->R[3 + c] + body->R[3 * r + 2] * s->R[6 + c];
    for (int k = 0; k < 3; k++) {
        p->D[k] = p->B[k] - p->A[k];
        p->flat[k] = fabs(p->R[6 + k]) < 1e-12;
    }
    p->a = p->D[0] * p->D[0] + p->D[1] * p->D[1];
    p->aD = p->a + p->D[2] * p->D[2];
    p->r2 = p->r * p->r;
    p->nh = 0;
    p->has_band = 0;
    if (p->kind == FS_SOIL_BOX) {
        box_corners(p, p->corner);
        box_hull(p);
    }
}

/* n NULL: the point alone (only RFT's law reads a node's normal). */
static inline double placed_lowest(const placed *p, double x, double y, double n[3])
{
    return p->kind == FS_SOIL_CAPSULE ? capsule_lowest(p, x, y, n) : box_lowest(p, x, y, n);
}

double fs_soil_shape_lowest(const fs_soil_shape *s, const fs_soil_body *body, double x, double y, double n[3])
{
    placed p;
    place(s, body, &p);
    return placed_lowest(&p, x, y, n);
}

/* A capsule's segment cut to the balls that reach below z_top (cA, cB): nothing above z_top meets
 * the soil, so the plan of what is left holds every node the capsule can press. */
static void clip_below(placed *p, double z_top)
{
    double Dz = p->B[2] - p->A[2], t0 = 0, t1 = 1;
    if (p->kind != FS_SOIL_CAPSULE || fabs(Dz) < 1e-12)
        return;
    double t = (z_top + p->r - p->A[2]) / Dz + (Dz > 0 ? 1e-9 : -1e-9); /* the ball at t touches z_top */
    if (Dz > 0)
        t1 = fmax(0, fmin(1, t));
    else
        t0 = fmax(0, fmin(1, t));
    for (int k = 0; k < 3; k++) {
        double d = p->B[k] - p->A[k];
        p->cA[k] = p->A[k] + t0 * d;
        p->cB[k] = p->A[k] + t1 * d;
    }
}

/* A capsule's band in plan: the quadrilateral between its clipped ends' disks (cA, cB), once a step
 * for row_span's rows. */
static void plan_band(placed *p)
{
    double Dx = p->cB[0] - p->cA[0], Dy = p->cB[1] - p->cA[1], L = p->kind == FS_SOIL_CAPSULE ? hypot(Dx, Dy) : 0;
    p->has_band = L > 0;
    if (!p->has_band)
        return;
    double nx = -Dy / L * p->r, ny = Dx / L * p->r;
    const double pt[4][2] = {{p->cA[0] + nx, p->cA[1] + ny}, {p->cB[0] + nx, p->cB[1] + ny},
                             {p->cB[0] - nx, p->cB[1] - ny}, {p->cA[0] - nx, p->cA[1] - ny}};
    memcpy(p->band, pt, sizeof pt);
}

void fs_soil_shape_box(const fs_soil_shape *s, const fs_soil_body *b, double box[4], double *zmin)
{
    double A[3];
    to_world(b, s->a, A);
    if (s->kind == FS_SOIL_CAPSULE) {
        double B[3], r = s->radius_m;
        to_world(b, s->b, B);
        box[0] = fmin(A[0], B[0]) - r, box[1] = fmax(A[0], B[0]) + r;
        box[2] = fmin(A[1], B[1]) - r, box[3] = fmax(A[1], B[1]) + r;
        *zmin = fmin(A[2], B[2]) - r;
        return;
    }
    double e[3] = {0, 0, 0};
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double Rw = b->R[3 * r] * s->R[c] + b->R[3 * r + 1] * s->R[3 + c] + b->R[3 * r + 2] * s->R[6 + c];
            e[r] += fabs(Rw) * s->half[c];
        }
    box[0] = A[0] - e[0], box[1] = A[0] + e[0], box[2] = A[1] - e[1], box[3] = A[1] + e[1];
    *zmin = A[2] - e[2];
}

/* ---- storage -------------------------------------------------------------------------------- */

double fs_soil_grid_undisturbed(const fs_soil_grid *g, double x, double y)
{
    return fs_terrain_height(g->terrain, x, y) + fs_soil_depth_over(&g->d, x, x);
}

/* Whether column i lies over the soil's section. */
static inline int in_section(const fs_soil_grid *g, int i) { return i >= g->i_lo && i <= g->i_hi; }

static fs_status undo_room(fs_soil_grid *g, long want, fs_error *err);
enum { UNDO_STEPS = 4 }; /* the steps between a mark and an undo the undo log holds without growing */

static fs_status grow(fs_soil_grid *g, fs_error *err)
{
    int cap = g->cap_tiles ? 2 * g->cap_tiles : 16;
    if (cap > g->max_tiles)
        cap = g->max_tiles;
    if (cap <= g->ntiles)
        return fs_fail(err, FS_NO_MEMORY, "the soil's grid is full: %d tiles of %d nodes ([soil] max_nodes %d)",
                       g->ntiles, TT, g->d.max_nodes);
    fs_soil_node *p = realloc(g->pool, (size_t)cap * TT * sizeof *p);
    if (!p)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's grid (%d tiles)", cap);
    g->pool = p;
    if (g->cap_tiles)
        g->grows++;
    g->cap_tiles = cap;
    return g->undo ? undo_room(g, (long)UNDO_STEPS * cap * TT, err) : FS_OK;
}

/* Room for at least want claims (fs_soil_claim): the buffer doubled, as the pool is. */
static fs_status grow_claims(fs_soil_grid *g, long want, fs_error *err)
{
    long cap = g->cap_claims > 0 ? g->cap_claims : TT;
    while (cap < want)
        cap *= 2;
    fs_soil_claim *c = realloc(g->claim, (size_t)cap * sizeof *c);
    if (!c)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's step (%ld nodes claimed)", want);
    g->claim = c;
    if (g->cap_claims)
        g->claim_grows++;
    g->cap_claims = cap;
    return FS_OK;
}

/* ---- the undo log (fs_soil_grid_keep) ------------------------------------------------------- */

/* One change the steps since the mark made: a node as it was (at >= 0: its place in the pool), or a
 * tile's stride as it was (at < 0: tile, stride). */
typedef struct undo_entry {
    long at;
    int tile, stride;
    fs_soil_node node;
} undo_entry;

typedef struct fs_soil_undo {
    undo_entry *e;
    long n, cap;
    /* the grid at the mark */
    long stamp;
    int ntiles;
    double work_J;
    double force[FS_SOIL_MAX_SHAPES][3], torque[FS_SOIL_MAX_SHAPES][3];
    int nodes[FS_SOIL_MAX_SHAPES];
    double area_m2[FS_SOIL_MAX_SHAPES], b_m[FS_SOIL_MAX_SHAPES];
} fs_soil_undo;

/* Room in the log for at least want entries. */
static fs_status undo_room(fs_soil_grid *g, long want, fs_error *err)
{
    fs_soil_undo *u = g->undo;
    if (want <= u->cap)
        return FS_OK;
    long cap = u->cap > 0 ? u->cap : TT;
    while (cap < want)
        cap *= 2;
    undo_entry *e = realloc(u->e, (size_t)cap * sizeof *e);
    if (!e)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's undo log (%ld changes)", want);
    u->e = e;
    u->cap = cap;
    return FS_OK;
}

/* Logs node nd as it is, before this step's first change to it (not one of a tile made since the
 * mark: undo drops those whole). */
static fs_status undo_node(fs_soil_grid *g, const fs_soil_node *nd, fs_error *err)
{
    fs_soil_undo *u = g->undo;
    long at = (long)(nd - g->pool);
    if (at >= (long)u->ntiles * TT)
        return FS_OK;
    fs_status s = undo_room(g, u->n + 1, err);
    if (s == FS_OK)
        u->e[u->n++] = (undo_entry){at, 0, 0, *nd};
    return s;
}

/* Logs tile k (in pool slot `slot`) whole, before it is made finer. */
static fs_status undo_tile(fs_soil_grid *g, int k, int slot, fs_error *err)
{
    fs_soil_undo *u = g->undo;
    if (slot >= u->ntiles)
        return FS_OK;
    fs_status s = undo_room(g, u->n + TT + 1, err);
    if (s != FS_OK)
        return s;
    for (int i = 0; i < TT; i++)
        u->e[u->n++] = (undo_entry){(long)slot * TT + i, 0, 0, g->pool[(size_t)slot * TT + i]};
    u->e[u->n++] = (undo_entry){.at = -1, .tile = k, .stride = g->stride[k]};
    return FS_OK;
}

fs_status fs_soil_grid_keep(fs_soil_grid *g, fs_error *err)
{
    if (!g->undo && !(g->undo = calloc(1, sizeof *g->undo)))
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's undo log");
    fs_status s = undo_room(g, (long)UNDO_STEPS * g->cap_tiles * TT, err);
    if (s == FS_OK)
        fs_soil_grid_mark(g);
    return s;
}

/* The grid's scalars and its shapes' last results, into the mark (saving) or back from it. */
static void exchange(fs_soil_grid *g, fs_soil_undo *u, int saving)
{
    size_t n = (size_t)g->nshapes;
    struct { void *field, *copy; size_t size; } part[] = {
        {&g->stamp, &u->stamp, sizeof g->stamp},          {&g->ntiles, &u->ntiles, sizeof g->ntiles},
        {&g->work_J, &u->work_J, sizeof g->work_J},        {g->force, u->force, n * sizeof g->force[0]},
        {g->torque, u->torque, n * sizeof g->torque[0]},   {g->nodes, u->nodes, n * sizeof g->nodes[0]},
        {g->area_m2, u->area_m2, n * sizeof g->area_m2[0]}, {g->b_m, u->b_m, n * sizeof g->b_m[0]}};
    for (size_t k = 0; k < sizeof part / sizeof part[0]; k++)
        memcpy(saving ? part[k].copy : part[k].field, saving ? part[k].field : part[k].copy, part[k].size);
}

void fs_soil_grid_mark(fs_soil_grid *g)
{
    g->undo->n = 0;
    exchange(g, g->undo, 1);
}

void fs_soil_grid_undo(fs_soil_grid *g)
{
    fs_soil_undo *u = g->undo;
    for (long k = u->n - 1; k >= 0; k--) { /* backwards: each node ends as the mark had it */
        const undo_entry *e = &u->e[k];
        if (e->at >= 0)
            g->pool[e->at] = e->node;
        else
            g->stride[e->tile] = (unsigned char)e->stride;
    }
    for (int slot = g->ntiles - 1; slot >= u->ntiles; slot--) { /* the tiles made since: not made */
        g->tile[g->slot_tile[slot]] = -1;
        g->stride[g->slot_tile[slot]] = 0;
    }
    u->n = 0;
    exchange(g, u, 0);
}

/* Where a tile of stride st keeps its node (li, lj) (both multiples of st): its nodes packed row by
 * row, (T / st)^2 of them, so that a coarse tile's nodes lie together in memory. */
static int packed(int li, int lj, int st) { return st == 1 ? lj * T + li : (lj / st) * (T / st) + li / st; }

/* The stored node (i, j) of a tile (NULL outside the region, in a tile not made, or between a coarse
 * tile's nodes). */
static fs_soil_node *stored_at(const fs_soil_grid *g, int i, int j)
{
    if (i < 0 || j < 0 || i >= g->nx || j >= g->ny)
        return NULL;
    int k = (j / T) * g->tx + i / T, slot = g->tile[k], st = g->stride[k];
    if (slot < 0 || (st > 1 && (i % st || j % st)))
        return NULL;
    return g->pool + (size_t)slot * TT + packed(i % T, j % T, st);
}

/* The node that (i, j) reads: itself, or in a coarse tile of stride st the stored node whose st x st
 * cell, centred on it, holds (i, j) (in the next tile when that one has the same stride; when it has
 * not, NULL: no node stands for (i, j), which no shape has pressed). */
static fs_soil_node *node_at(const fs_soil_grid *g, int i, int j)
{
    if (i < 0 || j < 0 || i >= g->nx || j >= g->ny)
        return NULL;
    int k = (j / T) * g->tx + i / T, slot = g->tile[k], st = g->stride[k];
    if (slot < 0)
        return NULL;
    if (st == 1)
        return g->pool + (size_t)slot * TT + (j % T) * T + i % T;
    int ri = (i + st / 2) / st * st, rj = (j + st / 2) / st * st;
    fs_soil_node *n = stored_at(g, ri, rj);
    return n && g->stride[(rj / T) * g->tx + ri / T] == st ? n : NULL;
}

/* Tile (ti, tj)'s nodes at stride st, packed into nd: the undisturbed surface sampled, and the state
 * of the node each was read from before (from, NULL: none, a new tile). */
static void fill_tile(const fs_soil_grid *g, int ti, int tj, int st, const fs_soil_grid *from, fs_soil_node *nd)
{
    memset(nd, 0, TT * sizeof *nd);
    for (int j = 0; j < T; j += st)
        for (int i = 0; i < T; i += st) {
            fs_soil_node *n = &nd[packed(i, j, st)];
            int gi = ti * T + i, gj = tj * T + j;
            n->h0_m = fs_soil_grid_undisturbed(g, g->x0 + gi * g->dx, g->y0 + gj * g->dx);
            const fs_soil_node *o = from && in_section(g, gi) ? node_at(from, gi, gj) : NULL;
            if (o) {
                n->sp_m = o->sp_m;
                n->yield_Pa = o->yield_Pa;
                n->slip_m = o->slip_m;
            }
        }
}

/* The tile (ti, tj) for a shape of stride st, made when first needed (its nodes' undisturbed surface
 * sampled, at stride st), or made finer when st is finer than its own: each node it gains takes the
 * print, yield and slip of the node it was read from (fs_soil_grid_node). */
static fs_status need_tile(fs_soil_grid *g, int ti, int tj, int st, fs_error *err)
{
    int *slot = &g->tile[tj * g->tx + ti];
    unsigned char *ts = &g->stride[tj * g->tx + ti];
    if (*slot >= 0) {
        if (st < *ts) {
            if (g->undo) {
                fs_status s = undo_tile(g, tj * g->tx + ti, *slot, err);
                if (s != FS_OK)
                    return s;
            }
            fs_soil_node keep[TT];
            fill_tile(g, ti, tj, st, g, keep);
            memcpy(g->pool + (size_t)*slot * TT, keep, sizeof keep);
            *ts = (unsigned char)st;
        }
        return FS_OK;
    }
    if (g->ntiles == g->cap_tiles) {
        fs_status s = grow(g, err);
        if (s != FS_OK)
            return s;
    }
    fill_tile(g, ti, tj, st, NULL, g->pool + (size_t)g->ntiles * TT);
    g->slot_tile[g->ntiles] = tj * g->tx + ti;
    *slot = g->ntiles++;
    *ts = (unsigned char)st;
    return FS_OK;
}

const fs_soil_node *fs_soil_grid_node(const fs_soil_grid *g, int i, int j)
{
    return in_section(g, i) ? node_at(g, i, j) : NULL;
}

double fs_soil_grid_surface(const fs_soil_grid *g, double x, double y)
{
    int i = (int)lround((x - g->x0) / g->dx), j = (int)lround((y - g->y0) / g->dx);
    const fs_soil_node *n = fs_soil_grid_node(g, i, j);
    if (!n)
        return fs_soil_grid_undisturbed(g, x, y);
    double s = n->h0_m - n->sp_m;
    return n->stamp == g->stamp ? fmin(s, n->zb_m) : s;
}

/* The node range [i0, i1] x [j0, j1] over a plan box, clipped to the region; 0 when empty. */
static int node_range(const fs_soil_grid *g, const double box[4], int r[4])
{
    r[0] = (int)fmax(g->i_lo, ceil((box[0] - g->x0) / g->dx));
    r[1] = (int)fmin(g->i_hi, floor((box[1] - g->x0) / g->dx));
    r[2] = (int)fmax(0, ceil((box[2] - g->y0) / g->dx));
    r[3] = (int)fmin(g->ny - 1, floor((box[3] - g->y0) / g->dx));
    return r[0] <= r[1] && r[2] <= r[3];
}

static fs_status need_tiles(fs_soil_grid *g, const int r[4], int st, fs_error *err)
{
    for (int tj = r[2] / T; tj <= r[3] / T; tj++)
        for (int ti = r[0] / T; ti <= r[1] / T; ti++) {
            const int k = tj * g->tx + ti;
            if (g->tile[k] >= 0 && g->stride[k] <= st) /* made, and as fine: need_tile would change nothing */
                continue;
            fs_status s = need_tile(g, ti, tj, st, err);
            if (s != FS_OK)
                return s;
        }
    return FS_OK;
}

int fs_soil_stride(const fs_soil_def *d, double width_m)
{
    int s = 1;
    while (2 * s <= T && 2 * s * d->grid_m <= d->coarse_grid_m * (1 + 1e-9) &&
           d->nodes_across * 2 * s * d->grid_m <= width_m * (1 + 1e-9))
        s *= 2;
    return s;
}

fs_status fs_soil_grid_init(fs_soil_grid *g, const fs_terrain *t, const double (*boxes)[4], int nboxes, fs_error *err)
{
    g->claim = NULL;
    g->cap_claims = 0;
    g->undo = NULL;
    g->terrain = t;
    g->d = t->def.soil;
    g->dx = g->d.grid_m;
    g->tan_phi = tan(g->d.friction_deg * M_PI / 180);
    g->x0 = t->soil_region[0];
    g->y0 = t->soil_region[2];
    g->nx = (int)floor((t->soil_region[1] - t->soil_region[0]) / g->dx) + 2;
    g->ny = (int)floor((t->soil_region[3] - t->soil_region[2]) / g->dx) + 2;
    if ((double)g->nx * g->ny > g->d.max_nodes)
        return fs_fail(err, FS_BAD_INPUT, "%s: the soil's grid has %d x %d nodes, over [soil] max_nodes %d", t->path,
                       g->nx, g->ny, g->d.max_nodes);
    /* the section's columns: those over which the undisturbed surface has the layer's depth
       (fs_soil_depth_over, as fs_soil_grid_undisturbed asks it at the x fill_tile samples a node at) */
    g->i_lo = 0, g->i_hi = g->nx - 1;
    while (g->i_lo < g->nx && !(fs_soil_depth_over(&g->d, g->x0 + g->i_lo * g->dx, g->x0 + g->i_lo * g->dx) > 0))
        g->i_lo++;
    while (g->i_hi >= 0 && !(fs_soil_depth_over(&g->d, g->x0 + g->i_hi * g->dx, g->x0 + g->i_hi * g->dx) > 0))
        g->i_hi--;
    g->tx = (g->nx + T - 1) / T;
    g->ty = (g->ny + T - 1) / T;
    g->max_tiles = g->tx * g->ty;
    g->tile = malloc((size_t)g->max_tiles * sizeof *g->tile);
    g->stride = calloc((size_t)g->max_tiles, 1);
    g->slot_tile = malloc((size_t)g->max_tiles * sizeof *g->slot_tile);
    if (!g->tile || !g->stride || !g->slot_tile)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's grid");
    for (int k = 0; k < g->max_tiles; k++)
        g->tile[k] = -1;
    /* the highest undisturbed surface, from the terrain's samples or its height function */
    g->top_m = (fs_terrain_is_heightfield(t) && t->z ? t->zmax : fs_terrain_height(t, g->x0, g->y0)) + g->d.depth_m;
    if (t->def.kind == FS_TERRAIN_SLOPE || t->def.kind == FS_TERRAIN_STEPPED) /* the region's highest corner or step */
        for (int i = 0; i <= 64; i++)
            for (int j = 0; j <= 1; j++)
                g->top_m = fmax(g->top_m, fs_soil_grid_undisturbed(g, g->x0 + i * (g->nx - 1) * g->dx / 64,
                                                                   g->y0 + j * (g->ny - 1) * g->dx));
    /* the pool: the tiles under the shapes at the start, and room to double */
    int want = 0;
    for (int b = 0; b < nboxes; b++) {
        int r[4];
        if (node_range(g, boxes[b], r))
            want += (r[1] / T - r[0] / T + 1) * (r[3] / T - r[2] / T + 1);
    }
    g->cap_tiles = 0;
    int cap = want > 8 ? 2 * want : 16;
    g->cap_tiles = cap > g->max_tiles ? g->max_tiles : cap;
    g->pool = malloc((size_t)g->cap_tiles * TT * sizeof *g->pool);
    if (!g->pool)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's grid (%d tiles)", g->cap_tiles);
    g->cap_claims = 0;
    return grow_claims(g, (long)g->cap_tiles * TT, err);
}

void fs_soil_grid_free(fs_soil_grid *g)
{
    free(g->tile);
    free(g->stride);
    free(g->slot_tile);
    free(g->pool);
    free(g->claim);
    g->claim = NULL;
    if (g->undo)
        free(g->undo->e);
    free(g->undo);
    g->undo = NULL;
    g->cap_claims = 0;
    g->tile = NULL;
    g->stride = NULL;
    g->slot_tile = NULL;
    g->pool = NULL;
}

void fs_soil_grid_print_of(const fs_soil_grid *g, fs_soil_print *p)
{
    double v = 0, deep = 0, slip = 0;
    long n = 0;
    for (int t = 0; t < g->ntiles; t++) {
        const fs_soil_node *nd = g->pool + (size_t)t * TT;
        int st = g->stride[g->slot_tile[t]];
        for (int k = 0; k < (T / st) * (T / st); k++) {
            double sp = nd[k].sp_m;
            v += st > 1 ? sp * st * st : sp;
            deep = fmax(deep, sp);
            n += sp > 0 ? st * st : 0;
            slip += sp > 0 ? nd[k].slip_m * st * st : 0;
        }
    }
    *p = (fs_soil_print){.volume_m3 = v * g->dx * g->dx, .deepest_m = deep, .area_m2 = (double)n * g->dx * g->dx,
                         .mean_slip_m = n ? slip / (double)n : 0, .nodes = n};
}

double fs_soil_grid_print(const fs_soil_grid *g, double *deepest_m, long *nodes)
{
    fs_soil_print p;
    fs_soil_grid_print_of(g, &p);
    if (deepest_m)
        *deepest_m = p.deepest_m;
    if (nodes)
        *nodes = p.nodes;
    return p.volume_m3;
}

fs_status fs_soil_grid_surface_copy(const fs_soil_grid *g, fs_soil_surface *s, fs_error *err)
{
    int t0 = g->tx, t1 = -1, u0 = g->ty, u1 = -1; /* the tiles reached: their bounding box */
    for (int tj = 0; tj < g->ty; tj++)
        for (int ti = 0; ti < g->tx; ti++)
            if (g->tile[tj * g->tx + ti] >= 0)
                t0 = ti < t0 ? ti : t0, t1 = ti > t1 ? ti : t1, u0 = tj < u0 ? tj : u0, u1 = tj > u1 ? tj : u1;
    if (t1 < 0) {
        fs_soil_surface_free(s);
        return FS_OK;
    }
    /* a node of undisturbed soil around them (where the region allows): a heightmap loaded from this
       draws its edge out beyond it, which is then the undisturbed surface, not a print's */
    int i0 = t0 * T - 1 > 0 ? t0 * T - 1 : 0, j0 = u0 * T - 1 > 0 ? u0 * T - 1 : 0;
    int i1 = (t1 + 1) * T + 1 < g->nx ? (t1 + 1) * T + 1 : g->nx, j1 = (u1 + 1) * T + 1 < g->ny ? (u1 + 1) * T + 1 : g->ny;
    size_t n = (size_t)(i1 - i0) * (size_t)(j1 - j0);
    if (!s->z_m || (size_t)s->nx * (size_t)s->ny != n) { /* a new extent: new memory, else refilled */
        fs_soil_surface_free(s);
        s->z_m = malloc(n * sizeof *s->z_m);
        s->sink_m = malloc(n * sizeof *s->sink_m);
    }
    if (!s->z_m || !s->sink_m) {
        fs_soil_surface_free(s);
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the soil's surface (%zu nodes)", n);
    }
    s->nx = i1 - i0, s->ny = j1 - j0, s->dx = g->dx;
    s->x0 = g->x0 + i0 * g->dx, s->y0 = g->y0 + j0 * g->dx;
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++) {
            const fs_soil_node *nd = fs_soil_grid_node(g, i, j);
            size_t k = (size_t)(j - j0) * (size_t)s->nx + (size_t)(i - i0);
            s->sink_m[k] = nd ? nd->sp_m : 0;
            s->z_m[k] = nd ? nd->h0_m - nd->sp_m : fs_soil_grid_undisturbed(g, g->x0 + i * g->dx, g->y0 + j * g->dx);
        }
    return FS_OK;
}

void fs_soil_surface_free(fs_soil_surface *s)
{
    free(s->z_m);
    free(s->sink_m);
    memset(s, 0, sizeof *s);
}

/* ---- the step ------------------------------------------------------------------------------- */

static void add_force(double f[3], double t[3], const double r[3], const double F[3])
{
    for (int k = 0; k < 3; k++)
        f[k] += F[k];
    t[0] += r[1] * F[2] - r[2] * F[1];
    t[1] += r[2] * F[0] - r[0] * F[2];
    t[2] += r[0] * F[1] - r[1] * F[0];
}

/* A node's place in the order of the claims: row by row, a row W = nx + FS_SOIL_TILE long, so that a
 * neighbour up to a tile's width past either end of a row (i < 0 or i >= nx) has a key no claim has. */
static inline long claim_key(const fs_soil_grid *g, int i, int j) { return (long)j * (g->nx + T) + i; }

/* Whether shape s holds the stored node (i, j) this step, found among its claims [lo, hi) (kept in the
 * order of their rows and, in a row, of i: the claim pass visits them so, and a shape claims a node at
 * most once), by its key (claim_key). *at is a cursor left at the first claim not before (i, j): the perimeter asks for each
 * claim's neighbours in nearly the order of the claims, so a cursor moves a step or two a question.
 * The same answer as looking the node up in its tile (a node is a shape's this step only through its
 * claim), without the tile lookup for each neighbour. */
static inline int claimed(const fs_soil_claim *cl, long lo, long hi, long *at, long key, int s, long now)
{
    long c = *at;
    while (c < hi && cl[c].key < key)
        c++;
    while (c > lo && cl[c - 1].key >= key)
        c--;
    *at = c;
    return c < hi && cl[c].key == key && cl[c].node->stamp == now && cl[c].node->shape == s;
}

/* The x extent of a convex plan polygon's row y, widened into [*lo, *hi]: the row against its edges
 * (pt[e[2k]] to pt[e[2k + 1]], k < ne). */
static void row_edges(const double (*pt)[2], const int *e, int ne, double y, double *lo, double *hi)
{
    for (int k = 0; k < ne; k++) {
        const double *a = pt[e[2 * k]], *b = pt[e[2 * k + 1]];
        if ((y - a[1]) * (y - b[1]) > 0)
            continue;
        double x = a[1] == b[1] ? a[0] : a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
        double x2 = a[1] == b[1] ? b[0] : x;
        *lo = lo2(*lo, lo2(x, x2));
        *hi = hi2(*hi, hi2(x, x2));
    }
}

/* Where a shape's plan meets row y: [*lo, *hi] (lo > hi when it does not). The plan of a capsule is
 * the hull of its ends' disks (the disks and the band between them), a box's the hull of its
 * corners, whose edges are among its twelve edges' plans: the row meets a convex plan in the
 * interval between its crossings of those boundaries. A node outside this interval has no lowest
 * point (placed_lowest), so visiting only the interval changes no result. */
static void row_span(const placed *p, double y, double *lo, double *hi)
{
    *lo = INFINITY, *hi = -INFINITY;
    if (p->kind == FS_SOIL_CAPSULE) {
        const double *ends[2] = {p->cA, p->cB};
        for (int k = 0; k < 2; k++) {
            double dy = y - ends[k][1];
            if (fabs(dy) < p->r) {
                double w = sqrt(p->r * p->r - dy * dy);
                *lo = lo2(*lo, ends[k][0] - w), *hi = hi2(*hi, ends[k][0] + w);
            }
        }
        if (p->has_band) { /* plan_band, once a step */
            static const int e[8] = {0, 1, 1, 2, 2, 3, 3, 0};
            row_edges((const double(*)[2])p->band, e, 4, y, lo, hi);
        }
        return;
    }
    static const int e[24] = {0, 1, 2, 3, 4, 5, 6, 7, 0, 2, 1, 3, 4, 6, 5, 7, 0, 4, 1, 5, 2, 6, 3, 7};
    row_edges((const double(*)[2])p->corner, e, 12, y, lo, hi);
}

/* The nodes [*i0, *i1] of row j that a shape's plan may cover, within its box's range r; 0 when none. */
static inline int row_nodes(const fs_soil_grid *g, const placed *p, const int r[4], int j, int *i0, int *i1)
{
    double lo, hi, pad = 1e-7 + 1e-9 * g->dx * g->nx;
    row_span(p, g->y0 + j * g->dx, &lo, &hi);
    if (!(lo <= hi))
        return 0;
    *i0 = (int)fmax(r[0], ceil((lo - pad - g->x0) / g->dx));
    *i1 = (int)fmin(r[1], floor((hi + pad - g->x0) / g->dx));
    return *i0 <= *i1;
}

/* ---- coverage: a box's nodes carry its plan's exact area ------------------------------------- */

/* Where a box's plan (its hull) meets the line y: [*lo, *hi] (lo > hi when it does not). */
static void hull_span(const placed *p, double y, double *lo, double *hi)
{
    *lo = INFINITY, *hi = -INFINITY;
    for (int k = 0; k < p->nh; k++) {
        const double *a = p->hull[k], *b = p->hull[(k + 1) % p->nh];
        if ((y - a[1]) * (y - b[1]) > 0 || a[1] == b[1])
            continue;
        double x = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
        *lo = lo2(*lo, x), *hi = hi2(*hi, x);
    }
}

/* The area of a box's plan below the line y, m^2 (the hull cut by the half-plane, by the shoelace). */
static double hull_below(const placed *p, double y)
{
    if (y <= p->ylo)
        return 0;
    if (y >= p->yhi)
        return p->hull_m2;
    double q[10][2], a2 = 0;
    int m = 0;
    for (int k = 0; k < p->nh; k++) {
        const double *a = p->hull[k], *b = p->hull[(k + 1) % p->nh];
        if (a[1] <= y)
            q[m][0] = a[0], q[m][1] = a[1], m++;
        if ((a[1] <= y) != (b[1] <= y))
            q[m][0] = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]), q[m][1] = y, m++;
    }
    for (int k = 1; k + 1 < m; k++)
        a2 += cross3(q[0], q[k], q[k + 1]);
    return 0.5 * a2;
}

/* Whether row j holds a node of stride st in the shape's plan. */
static int row_in_plan(const fs_soil_grid *g, const placed *p, const int r[4], int j, int st)
{
    int i0, i1;
    if (j < r[2] || j > r[3] || !row_nodes(g, p, r, j, &i0, &i1))
        return 0;
    for (int i = (i0 + st - 1) / st * st; i <= i1; i += st)
        if (placed_lowest(p, g->x0 + i * g->dx, g->y0 + j * g->dx, NULL) < INFINITY)
            return 1;
    return 0;
}

/* A row of a box's nodes (stride st, row j at y): its plan's span there and the plan's area the row
 * stands for, in cells of its stride. The rows partition the plan: a row stands for the strip of half
 * a cell each side of it, the first row (none of the plan's nodes a cell below) for all of the plan
 * below it, the last for all above; in a row, the nodes inside stand for their cells and the first
 * and last for the span out to the edge (coverage()). So a box's nodes, all pressed, carry its plan's
 * area wherever its edges fall on the grid (docs/soil.md, Grid spacing). */
typedef struct cover_row {
    double lo, hi, cells, span, inv_ds;
    int st, j, exact;
    int i0, i1; /* the row's nodes that the plan may cover (row_nodes) */
} cover_row;

/* Whether the row a cell from row j (at y, where the plan is w wide), towards the plan's end e (ylo
 * or yhi), holds plan nodes. The plan's width is concave in y, so there it is at least
 * w |yn - e| / |y - e|: a cell or more holds a node, and nothing need be asked. */
static int next_row_holds(const fs_soil_grid *g, const placed *p, const int r[4], int j, int dj, double e, double w,
                          int st)
{
    double ds = st * g->dx, y = g->y0 + j * g->dx, yn = g->y0 + (j + dj) * g->dx;
    if ((yn - e) * (y - e) < -1e-6 * ds * ds)
        return 0;
    if (w * fabs(yn - e) >= (1 + 1e-6) * ds * fabs(y - e))
        return 1;
    return row_in_plan(g, p, r, j + dj, st);
}

static void cover_row_at(const fs_soil_grid *g, const placed *p, const int r[4], int j, int st, cover_row *c)
{
    double ds = st * g->dx, y = g->y0 + j * g->dx;
    hull_span(p, y, &c->lo, &c->hi);
    c->inv_ds = 1 / ds;
    c->span = (c->hi - c->lo) * c->inv_ds;
    c->st = st, c->j = j;
    int below = next_row_holds(g, p, r, j, -st, p->ylo, c->hi - c->lo, st);
    int above = next_row_holds(g, p, r, j, st, p->yhi, c->hi - c->lo, st);
    int corner = 0;
    for (int k = 0; k < p->nh; k++)
        corner |= fabs(p->hull[k][1] - y) < 0.5 * ds;
    /* a strip with no corner between rows that hold nodes: its area is its span at y times its height */
    c->exact = below && above && !corner;
    if (c->exact) {
        c->cells = c->span;
        return;
    }
    double lo = below ? hull_below(p, y - 0.5 * ds) : 0, up = above ? hull_below(p, y + 0.5 * ds) : p->hull_m2;
    c->cells = (up - lo) * c->inv_ds * c->inv_ds;
}

/* Whether the node i of row c lies in the shape's plan, asked as the step asks it (the row's nodes from
 * row_nodes, kept in c, then a lowest point), so that the weights and the claims never disagree where
 * an edge falls on a node. */
static int in_row(const fs_soil_grid *g, const placed *p, const cover_row *c, int i)
{
    return i >= c->i0 && i <= c->i1 && placed_lowest(p, g->x0 + i * g->dx, g->y0 + c->j * g->dx, NULL) < INFINITY;
}

/* The share of its cell a box's node i in row c carries: 1 inside; at the row's ends (the next node
 * out not in the plan), its cell's inner half and the span out to the edge; the row's nodes scaled to
 * the strip's area (the span at y is the strip's mean width but where a corner lies in the strip, or
 * at the first and last rows). */
static double coverage(const fs_soil_grid *g, const placed *p, const cover_row *c, int i)
{
    double x = g->x0 + i * g->dx, el = (x - c->lo) * c->inv_ds, eh = (c->hi - x) * c->inv_ds, wx = 1;
    if (el < 1 + 1e-6 && (el < 1 - 1e-6 || !in_row(g, p, c, i - c->st)))
        wx += hi2(el, 0) - 0.5;
    if (eh < 1 + 1e-6 && (eh < 1 - 1e-6 || !in_row(g, p, c, i + c->st)))
        wx += hi2(eh, 0) - 0.5;
    if (c->exact)
        return wx;
    return c->span > 1e-9 ? wx * c->cells / c->span : c->cells;
}

/* A row's stored nodes in one tile: base[(i - off) >> sh] for i = a, a + st, ... b (st = 2^sh). */
typedef struct seg { fs_soil_node *base; int off, a, b, st, sh; } seg;

/* Row j's stored nodes from i0 to i1 in tile column ti; 0 when there are none. */
static int segment(const fs_soil_grid *g, int j, int i0, int i1, int ti, seg *q)
{
    int k = (j / T) * g->tx + ti, slot = g->tile[k];
    if (slot < 0)
        return 0;
    int st = g->stride[k];
    if (j % st)
        return 0;
    q->off = ti * T;
    q->a = i0 > q->off ? i0 : q->off;
    q->b = i1 < q->off + T - 1 ? i1 : q->off + T - 1;
    q->a = (q->a + st - 1) / st * st;
    q->st = st;
    q->sh = log2_of[st];
    q->base = g->pool + (size_t)slot * TT + packed(0, j % T, st);
    return q->a <= q->b;
}

/* Past the yield, the law: the normal stress from the elastic trial se (> the node's yield), the
 * node's yield and print moved. */
static double plastic(fs_soil_node *nd, double s, double se, double law, double Ke)
{
    double sigma = lo2(se, hi2(law, nd->yield_Pa));
    nd->yield_Pa = sigma;
    nd->sp_m = hi2(nd->sp_m, s - sigma / Ke);
    return sigma;
}

/* The force on one node's element (bekker or rft), N, at point q moving at v: its normal part F and
 * its shear part S, whose viscous slope (N s/m) is added to *slope. kb: Bekker's k_c / b + k_phi for
 * its shape's patch (fs_bekker_pressure's factor). */
static void node_force(fs_soil_grid *g, fs_soil_node *nd, double kb, double A, const double v[3], double h,
                       double F[3], double S[3], double *slope)
{
    const fs_soil_def *d = &g->d;
    double reg = d->slip_speed_m_per_s;
    double s = lo2(nd->h0_m - nd->zb_m, d->depth_m); /* sinkage below the undisturbed surface, above the bedrock */
    double vh = sqrt(v[0] * v[0] + v[1] * v[1]);
    F[0] = F[1] = F[2] = S[0] = S[1] = S[2] = 0;
    /* the elastic trial: within the yield (unloading, reloading, at rest) no law need be evaluated */
    double se = d->K_e_Pa_per_m * (s - nd->sp_m);
    if (se <= 0)
        return;
    if (d->model == FS_SOIL_BEKKER) {
        double sigma = se <= nd->yield_Pa ? se : plastic(nd, s, se, kb * pow(hi2(s, 0), d->n), d->K_e_Pa_per_m);
        double total = hi2(0, sigma - d->damping_Pa_s_per_m * v[2]);
        nd->slip_m += vh * h;
        double tau = (d->cohesion_Pa + sigma * g->tan_phi) * (1 - exp(-nd->slip_m / d->shear_K_m));
        double k = tau / hi2(vh, reg);
        S[0] = -k * v[0] * A, S[1] = -k * v[1] * A, F[2] = total * A;
        *slope += k * A;
        nd->sigma_Pa = total;
        return;
    }
    /* rft: beta the element's tilt in the plane of its motion, gamma the motion's angle below horizontal */
    const double *n = nd->n;
    double speed = sqrt(vh * vh + v[2] * v[2]);
    double e[2] = {1, 0}, nh = hypot(n[0], n[1]);
    if (vh > reg)
        e[0] = v[0] / vh, e[1] = v[1] / vh;
    else if (nh > 1e-9)
        e[0] = n[0] / nh, e[1] = n[1] / nh;
    double gamma = speed > reg ? atan2(-v[2], vh) : M_PI / 2;
    double beta = atan2(n[0] * e[0] + n[1] * e[1], fmax(-n[2], 1e-9));
    double az, ax;
    fs_rft_alpha(d, beta, fmax(gamma, 0), &az, &ax);
    double dA = A / fmax(fabs(n[2]), 0.25); /* the element's own area over its plan cell */
    double law = d->zeta_N_per_m3 * fmax(az, 0) * s;
    double sigma = se <= nd->yield_Pa ? se : plastic(nd, s, se, law, d->K_e_Pa_per_m);
    double mob = law > 0 ? fmin(1, sigma / law) : 0; /* the share of the law mobilised, at most all of it */
    double sx = d->zeta_N_per_m3 * ax * s * mob; /* RFT's horizontal stress, in proportion to the vertical mobilised */
    double H[3] = {-sx * e[0], -sx * e[1], 0};
    /* Dissipative by construction (docs/soil.md, RFT): RFT gives stresses on moving elements, so its
     * horizontal stress fades in below the slip speed, like the shear. Of it, the part along the
     * element's velocity may only oppose it: a drag, viscous (its slope in the shape's, so that the
     * cap keeps it from reversing the body's motion within a step); a part that would push along
     * the motion is dropped. The part across the velocity (the thrust on a tilted element pushed
     * down) does no work and stays while the element intrudes; a rising element has none (its
     * angle below horizontal, clamped to 0, would take it for one moving sideways). */
    if (speed > 0) {
        double u[3] = {v[0] / speed, v[1] / speed, v[2] / speed}, hu = H[0] * u[0] + H[1] * u[1] + H[2] * u[2];
        double fade = v[2] < 0 ? fmin(1, speed / reg) : 0;
        for (int k = 0; k < 3; k++)
            H[k] = (H[k] - hu * u[k]) * fade;
        if (hu < 0) {
            double c = -hu / fmax(speed, reg) * dA;
            for (int k = 0; k < 3; k++)
                S[k] -= c * v[k];
            *slope += c;
        }
    } else {
        H[0] = H[1] = 0;
    }
    F[0] = H[0] * dA, F[1] = H[1] * dA, F[2] = (sigma + H[2]) * dA;
    double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    if (vn > 0) { /* intruding: the inertial pressure and its friction, both viscous and capped like the drag */
        double p = d->inertial_lambda * d->density_kg_per_m3 * vn * vn, c = d->inertial_lambda * d->density_kg_per_m3 * vn * dA;
        double vt[3] = {v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]};
        double vtn = sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]), f = d->friction_mu * p / fmax(vtn, reg);
        for (int k = 0; k < 3; k++)
            S[k] -= c * vn * n[k] + f * vt[k] * dA;
        *slope += c + f * dA;
    }
    nd->slip_m += vh * h;
    nd->sigma_Pa = F[2] / A;
}

fs_status fs_soil_grid_step(fs_soil_grid *g, const fs_soil_body *bodies, double h, fs_error *err)
{
    g->stamp++;
    int range[FS_SOIL_MAX_SHAPES][4], near[FS_SOIL_MAX_SHAPES], rows[FS_SOIL_MAX_SHAPES];
    placed pl[FS_SOIL_MAX_SHAPES];
    /* the tiles under every shape, each as fine as the finest shape over it, before any is solved
     * (so that no tile moves while the claims below point into the pool) */
    for (int s = 0; s < g->nshapes; s++) {
        const fs_soil_shape *sh = &g->shape[s];
        double box[4], zmin;
        fs_soil_shape_box(sh, &bodies[sh->body], box, &zmin);
        memset(g->force[s], 0, sizeof g->force[s]);
        memset(g->torque[s], 0, sizeof g->torque[s]);
        g->nodes[s] = 0;
        g->area_m2[s] = 0;
        g->b_m[s] = 0;
        near[s] = zmin < g->top_m && node_range(g, box, range[s]);
        if (!near[s])
            continue;
        fs_status st = need_tiles(g, range[s], sh->stride > 1 ? sh->stride : 1, err);
        if (st != FS_OK)
            return st;
    }
    /* the rows that hold stored nodes under each shape: every rows[s]-th, the finest stride of its tiles */
    for (int s = 0; s < g->nshapes; s++) {
        const int *r = range[s];
        rows[s] = T;
        for (int tj = r[2] / T; near[s] && tj <= r[3] / T; tj++)
            for (int ti = r[0] / T; ti <= r[1] / T; ti++)
                rows[s] = g->stride[tj * g->tx + ti] < rows[s] ? g->stride[tj * g->tx + ti] : rows[s];
    }
    /* each node to the lowest shape over it that reaches below its print; each claim kept, in the
     * order of the shape's rows, for the two passes below */
    long first[FS_SOIL_MAX_SHAPES + 1], nc = 0;
    const int rft = g->d.model == FS_SOIL_RFT; /* only RFT's law reads a node's normal */
    for (int s = 0; s < g->nshapes; s++) {
        first[s] = nc;
        if (!near[s])
            continue;
        placed *p = &pl[s];
        place(&g->shape[s], &bodies[g->shape[s].body], p);
        clip_below(p, g->top_m);
        plan_band(p);
        const int *r = range[s];
        for (int j = (r[2] + rows[s] - 1) / rows[s] * rows[s]; j <= r[3]; j += rows[s]) {
            int i0, i1;
            if (!row_nodes(g, p, r, j, &i0, &i1))
                continue;
            const double y = g->y0 + j * g->dx;
            cover_row cr = {0, 0, 0, 0, 0, 0, 0, 0, i0, i1};
            for (int ti = i0 / T; ti <= i1 / T; ti++) {
                seg q;
                if (!segment(g, j, i0, i1, ti, &q))
                    continue;
                if (p->nh && q.st != cr.st)
                    cover_row_at(g, p, r, j, q.st, &cr);
                if (nc + (q.b - q.a) / q.st + 1 > g->cap_claims) {
                    fs_status st = grow_claims(g, nc + (q.b - q.a) / q.st + 1, err);
                    if (st != FS_OK)
                        return st;
                }
                for (int i = q.a; i <= q.b; i += q.st) {
                    fs_soil_node *nd = q.base + ((i - q.off) >> q.sh);
                    double n[3], z = placed_lowest(p, g->x0 + i * g->dx, y, rft ? n : NULL);
                    if (!(z < nd->h0_m - nd->sp_m) || (nd->stamp == g->stamp && nd->zb_m <= z))
                        continue;
                    if (g->undo && nd->stamp != g->stamp) { /* its first change in this step */
                        fs_status st = undo_node(g, nd, err);
                        if (st != FS_OK)
                            return st;
                    }
                    nd->stamp = g->stamp;
                    nd->shape = s;
                    nd->zb_m = z;
                    if (rft)
                        memcpy(nd->n, n, sizeof n);
                    double w = p->nh ? coverage(g, p, &cr, i) : 1;
                    g->claim[nc++] = (fs_soil_claim){nd, i, j, q.st, w, claim_key(g, i, j)};
                }
            }
        }
    }
    first[g->nshapes] = nc;
    const long now = g->stamp;
#define OURS(n) ((n)->stamp == now && (n)->shape == s)
    for (int s = 0; s < g->nshapes; s++) {
        if (first[s] == first[s + 1])
            continue;
        /* Bekker's b of the shape's loaded patch: twice its area over its perimeter (Chrono's convention),
         * in units of dx^2 and dx (a node of stride st covers st^2 and each of its open sides st); a
         * node claimed here and by a later shape is that shape's */
        long cells = 0, edges = 0, pairs = 0, lo = first[s], hi = first[s + 1], up = lo, down = lo;
        double area = 0;
        for (long c = lo; c < hi; c++) {
            const fs_soil_claim *cl = &g->claim[c];
            const fs_soil_node *nd = cl->node;
            if (!OURS(nd))
                continue;
            /* its neighbours st away: in the same tile (the same stride) read directly, the one above and
             * the one to the right only, each pair found closing both its sides (the node below or to the
             * left, if it is ours, found this one); in another tile, among the shape's claims (along the
             * row next to this claim, across it by a cursor each way) */
            const int st = cl->st, li = cl->i & (T - 1), lj = cl->j & (T - 1), row = T >> log2_of[st];
            const long key = cl->key, across = (long)st * (g->nx + T);
            int open = 4;
            if (li + st < T) {
                if (OURS(nd + 1))
                    open--, pairs += st;
            } else {
                long right = c + 1;
                open -= claimed(g->claim, lo, hi, &right, key + st, s, now);
            }
            if (li < st) {
                long left = c - 1 > lo ? c - 1 : lo;
                open -= claimed(g->claim, lo, hi, &left, key - st, s, now);
            }
            if (lj + st < T) {
                if (OURS(nd + row))
                    open--, pairs += st;
            } else {
                open -= claimed(g->claim, lo, hi, &up, key + across, s, now);
            }
            if (lj < st)
                open -= claimed(g->claim, lo, hi, &down, key - across, s, now);
            cells++;
            area += st * st * cl->w;
            edges += st * open;
        }
        if (!cells)
            continue;
        edges -= pairs; /* the sides each pair in a tile closes on its other node */
        double b = hi2(g->d.b_min_m, 2.0 * area * g->dx / (double)edges);
        g->b_m[s] = b;
        g->nodes[s] = (int)cells;
        g->area_m2[s] = area * g->dx * g->dx;
        const fs_soil_body *bd = &bodies[g->shape[s].body];
        const double kb = g->d.k_c_N_per_m_n1 / b + g->d.k_phi_N_per_m_n2; /* Bekker's modulus for this b */
        /* Bekker's node forces have zeros where add_force multiplies and adds: every sum here starts at
         * +0 and, rounding to nearest, a sum of doubles is -0 only when both terms are, so these sums
         * never hold -0; a product by +0 is a zero, and adding a zero to a sum that is not -0 leaves it
         * as it was. Leaving those terms out gives the same sums to the bit. */
        const int bekker = g->d.model == FS_SOIL_BEKKER;
        double shear[3] = {0, 0, 0}, shear_torque[3] = {0, 0, 0}, slope = 0, work_n = 0, work_s = 0;
        for (long c = first[s]; c < first[s + 1]; c++) {
            const fs_soil_claim *cl = &g->claim[c];
            fs_soil_node *nd = cl->node;
            if (!OURS(nd))
                continue;
            const double ds = cl->st * g->dx, A = ds * ds * cl->w;
            double qp[3] = {g->x0 + cl->i * g->dx, g->y0 + cl->j * g->dx, nd->zb_m};
            double rq[3] = {qp[0] - bd->p[0], qp[1] - bd->p[1], qp[2] - bd->p[2]};
            double v[3] = {bd->v[0] + bd->w[1] * rq[2] - bd->w[2] * rq[1], bd->v[1] + bd->w[2] * rq[0] - bd->w[0] * rq[2],
                           bd->v[2] + bd->w[0] * rq[1] - bd->w[1] * rq[0]};
            double F[3], S[3];
            node_force(g, nd, kb, A, v, h, F, S, &slope);
            if (bekker) { /* F = (0, 0, F_z), S = (S_x, S_y, 0): add_force's terms without its zeros (below) */
                double *f = g->force[s], *t = g->torque[s];
                work_n -= F[2] * v[2] * h;
                work_s -= (S[0] * v[0] + S[1] * v[1]) * h;
                f[2] += F[2];
                t[0] += rq[1] * F[2];
                t[1] -= rq[0] * F[2];
                shear[0] += S[0], shear[1] += S[1];
                shear_torque[0] -= rq[2] * S[1];
                shear_torque[1] += rq[2] * S[0];
                shear_torque[2] += rq[0] * S[1] - rq[1] * S[0];
                continue;
            }
            work_n -= (F[0] * v[0] + F[1] * v[1] + F[2] * v[2]) * h;
            work_s -= (S[0] * v[0] + S[1] * v[1] + S[2] * v[2]) * h;
            add_force(g->force[s], g->torque[s], rq, F);
            add_force(shear, shear_torque, rq, S);
        }
        /* the shear as an explicit damper: its slope kept within half the body's mass over the step */
        double cap = 0.5 * bd->mass_kg / h, k = slope > cap ? cap / slope : 1;
        for (int c = 0; c < 3; c++) {
            g->force[s][c] += k * shear[c];
            g->torque[s][c] += k * shear_torque[c];
        }
        g->work_J += work_n + k * work_s;
    }
#undef OURS
    return FS_OK;
}
