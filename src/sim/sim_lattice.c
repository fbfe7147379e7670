/* sim_lattice.c: a box's and a sphere's contacts with a heightfield lattice (sim_lattice.h). */
#include "sim_lattice.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static double zat(const fs_terrain *t, long i, long j) { return t->z[(size_t)j * t->nx + i]; }

static dContactGeom *next_contact(gathered *g, dGeomID shape)
{
    if (g->n == FS_MAX_CONTACTS)
        return NULL;
    dContactGeom *c = &g->c[g->n++];
    memset(c, 0, sizeof *c);
    c->g1 = shape;
    return c;
}

/* The surface at (x, y) (fs_terrain_cell): its height and unit normal (up); 0 outside the lattice. */
static int surface(const fs_terrain *t, double x, double y, double *z, double n[3])
{
    double fi = (x - t->x0) / t->dx, fj = (y - t->y0) / t->dx;
    if (!(fi >= 0 && fj >= 0 && fi <= t->nx - 1 && fj <= t->ny - 1))
        return 0;
    long i = (long)fmin(floor(fi), t->nx - 2), j = (long)fmin(floor(fj), t->ny - 2);
    double g[2]; /* the triangle's rise per cell along x and y */
    *z = fs_terrain_cell(zat(t, i, j), zat(t, i + 1, j), zat(t, i, j + 1), zat(t, i + 1, j + 1), fi - (double)i,
                         fj - (double)j, g);
    double len = sqrt(g[0] * g[0] + g[1] * g[1] + t->dx * t->dx);
    n[0] = -g[0] / len, n[1] = -g[1] / len, n[2] = t->dx / len;
    return 1;
}

/* ---- a box ---------------------------------------------------------------------------------- */

/* A box's contacts are kept a few a feature: the deepest of each patch of a face (PATCHES_X by
 * PATCHES_Y over each of the top and bottom faces) and of each EDGE_PARTS-th of an edge. A rigid
 * sole needs three points to stand on; these spread the support over the face like the surface
 * under it, whatever the lattice's resolution (on a 1 mm lattice a 0.2 m sole covers 18 000
 * vertices). */
enum { PATCHES_X = 4, PATCHES_Y = 2, EDGE_PARTS = 2 };
/* the patches of the top and bottom faces, then one slot for each side face */
enum { SIDE_SLOTS = 2 * PATCHES_X * PATCHES_Y, BOX_SLOTS = SIDE_SLOTS + 4 };
/* A vertex under the underside, or a crossing under one of its edges, is a contact only where it
 * stands deeper than the underside's corners put the surface there (their heights over or under
 * it, interpolated) by more than this: a sole flush on a plane of the lattice is held by its corners
 * alone, as on an ODE plane, not by every vertex under it as well (each contact carries the
 * ground's whole stiffness, so twenty would make it twenty times stiffer). A bump, a ridge or a
 * plateau under the sole stands deeper and is kept. */
static const double FLUSH_M = 1e-6;

typedef struct box_frame {
    const dReal *R, *c; /* ODE's rotation (row-major, 4 columns) and centre */
    double h[3];        /* half lengths */
} box_frame;

static box_frame frame_of(dGeomID box)
{
    dVector3 l;
    dGeomBoxGetLengths(box, l);
    return (box_frame){dGeomGetRotation(box), dGeomGetPosition(box), {0.5 * l[0], 0.5 * l[1], 0.5 * l[2]}};
}

/* w (a point relative to the box's centre) in the box's frame: R^T w */
static void to_box(const box_frame *b, const double w[3], double p[3])
{
    for (int k = 0; k < 3; k++)
        p[k] = b->R[k] * w[0] + b->R[4 + k] * w[1] + b->R[8 + k] * w[2];
}

/* Whether every vertex of lattice block (a, b) lies below the box: under its lowest corner zlow,
 * or (the box upright) below the plane of its underside, by a bound over the block's extent and
 * highest sample with a nanometre to spare. */
static int block_below(const fs_terrain *t, long a, long b, const box_frame *bx, double zlow)
{
    const long B = FS_TERRAIN_BLOCK;
    const dReal *R = bx->R, *c = bx->c;
    double top = t->zblock[(size_t)b * t->bx + a];
    if (top < zlow)
        return 1;
    if (R[10] <= 0)
        return 0;
    double xa = t->x0 + a * B * t->dx - c[0], xb = xa + B * t->dx;
    double ya = t->y0 + b * B * t->dx - c[1], yb = ya + B * t->dx;
    double bound = fmax(R[2] * xa, R[2] * xb) + fmax(R[6] * ya, R[6] * yb) + R[10] * (top - c[2]);
    return bound < -bx->h[2] - 1e-9;
}

/* The lattice vertices inside the box. patch NULL: every one (until g is full), pushed out
 * through the nearer of its top and bottom faces; else through its nearest face, the deepest of
 * each patch (BOX_SLOTS), and with the underside's corner gaps those of the underside only where
 * they stand deeper than the corners (FLUSH_M). */
static void vertices_inside(const fs_terrain *t, dGeomID box, const box_frame *frame, gathered *g,
                            dContactGeom *patch, const double *gap)
{
    const box_frame bx = *frame;
    const dReal *R = bx.R, *c = bx.c;
    double aabb[6];
    dGeomGetAABB(box, aabb);
    long i0 = (long)floor((aabb[0] - t->x0) / t->dx), i1 = (long)ceil((aabb[1] - t->x0) / t->dx);
    long j0 = (long)floor((aabb[2] - t->y0) / t->dx), j1 = (long)ceil((aabb[3] - t->y0) / t->dx);
    const long B = FS_TERRAIN_BLOCK, nx = t->nx, ilo = i0 > 0 ? i0 : 0;
    const double zlow = aabb[4];
    for (long j = j0 > 0 ? j0 : 0; j <= j1 && j < t->ny; j++) {
        const double *row = t->z + (size_t)j * nx;
        for (long i = ilo; i <= i1 && i < nx; i++) {
            /* a block wholly below the box: on to the next (the same vertices, in the same order) */
            if ((i == ilo || i % B == 0) && block_below(t, i / B, j / B, &bx, zlow)) {
                i = (i / B) * B + B - 1;
                continue;
            }
            double z = row[i];
            if (z < zlow)
                continue;
            double w[3] = {t->x0 + i * t->dx - c[0], t->y0 + j * t->dx - c[1], z - c[2]}, p[3];
            to_box(&bx, w, p);
            if (!patch && g->n == FS_MAX_CONTACTS)
                return;
            if (fabs(p[0]) > bx.h[0] || fabs(p[1]) > bx.h[1] || fabs(p[2]) > bx.h[2])
                continue;
            /* out through the nearer of the top and bottom faces (axis 2), or, with patches,
               through the nearest face: a vertex that entered by a side face has not gone deep */
            int axis = 2, up = p[2] > 0;
            double depth = bx.h[2] - fabs(p[2]);
            dContactGeom *ct;
            if (patch) {
                for (int k = 0; k < 2; k++)
                    if (bx.h[k] - fabs(p[k]) < depth)
                        axis = k, up = p[k] > 0, depth = bx.h[k] - fabs(p[k]);
                int slot = SIDE_SLOTS + (axis == 2 ? 0 : 2 * axis + up);
                if (axis == 2) {
                    int a = (int)((p[0] + bx.h[0]) / (2 * bx.h[0]) * PATCHES_X);
                    int b = (int)((p[1] + bx.h[1]) / (2 * bx.h[1]) * PATCHES_Y);
                    slot = (up * PATCHES_Y + (b < PATCHES_Y ? b : PATCHES_Y - 1)) * PATCHES_X +
                           (a < PATCHES_X ? a : PATCHES_X - 1);
                }
                ct = &patch[slot];
                if (ct->depth >= depth)
                    continue;
                /* on the underside, no deeper than the corners' support there: they hold it */
                if (gap && axis == 2 && !up) {
                    double u = (p[0] + bx.h[0]) / (2 * bx.h[0]), v = (p[1] + bx.h[1]) / (2 * bx.h[1]);
                    double under = (1 - u) * (1 - v) * gap[0] + u * (1 - v) * gap[1] + (1 - u) * v * gap[2] + u * v * gap[3];
                    if (depth / R[10] <= under + FLUSH_M)
                        continue;
                }
            } else {
                ct = next_contact(g, box);
            }
            for (int k = 0; k < 3; k++) {
                ct->pos[k] = w[k] + c[k];
                ct->normal[k] = (up ? -1 : 1) * R[4 * k + axis];
            }
            ct->depth = depth;
            ct->g1 = box;
        }
    }
}

void fs_lattice_vertex_contacts(const fs_terrain *t, dGeomID box, gathered *g)
{
    box_frame bx = frame_of(box);
    vertices_inside(t, box, &bx, g, NULL, NULL);
}

/* The box's corner k (bit 0: +x, bit 1: +y, bit 2: +z) in the world. */
static void corner(const box_frame *b, int k, double p[3])
{
    double s[3] = {(k & 1 ? 1 : -1) * b->h[0], (k & 2 ? 1 : -1) * b->h[1], (k & 4 ? 1 : -1) * b->h[2]};
    for (int m = 0; m < 3; m++)
        p[m] = b->c[m] + b->R[4 * m] * s[0] + b->R[4 * m + 1] * s[1] + b->R[4 * m + 2] * s[2];
}

/* Where box edge A->B passes beneath the lattice edges of one family (the lines a u + b v = w of
 * lattice coordinates u, v, each lattice edge from (i, j) to (i, j) + (du, dv)), keeping for each
 * EDGE_PARTS-th of the edge its deepest crossing in part[]. */
static void edge_family(const fs_terrain *t, const double A[3], const double B[3], int a, int b, int du, int dv,
                        const double *gap, dContactGeom *part)
{
    double ua = (A[0] - t->x0) / t->dx, va = (A[1] - t->y0) / t->dx;
    double ub = (B[0] - t->x0) / t->dx, vb = (B[1] - t->y0) / t->dx;
    double wa = a * ua + b * va, wb = a * ub + b * vb;
    if (wa == wb || !isfinite(wa) || !isfinite(wb))
        return; /* the edge runs along the family's lines: it crosses none (or the state is lost) */
    double e[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    for (long w = (long)ceil(fmin(wa, wb)); w <= (long)floor(fmax(wa, wb)); w++) {
        double s = (w - wa) / (wb - wa), u = ua + s * (ub - ua), v = va + s * (vb - va);
        /* the lattice edge crossed: it starts at (i, j), and the crossing is f of the way along */
        double along = du ? u : v;
        long base = (long)floor(along), i = du ? base : w, j = du ? (dv ? base - w : w) : base;
        double f = along - (double)base;
        if (i < 0 || j < 0 || i + du > t->nx - 1 || j + dv > t->ny - 1)
            continue;
        double z0 = zat(t, i, j), z1 = zat(t, i + du, j + dv);
        double zt = z0 + f * (z1 - z0), zb = A[2] + s * e[2];
        if (zb >= zt || (gap && zt - zb <= (1 - s) * gap[0] + s * gap[1] + FLUSH_M))
            continue;
        /* the common normal of the two edges, up: moving the box along it by (zt - zb) n_z parts them */
        double et[3] = {du * t->dx, dv * t->dx, z1 - z0};
        double n[3] = {e[1] * et[2] - e[2] * et[1], e[2] * et[0] - e[0] * et[2], e[0] * et[1] - e[1] * et[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len == 0)
            continue;
        if (n[2] < 0)
            len = -len;
        double depth = (zt - zb) * n[2] / len;
        int k = (int)(s * EDGE_PARTS);
        dContactGeom *ct = &part[k < EDGE_PARTS ? k : EDGE_PARTS - 1];
        if (ct->depth >= depth)
            continue;
        for (int m = 0; m < 3; m++)
            ct->normal[m] = n[m] / len;
        ct->pos[0] = A[0] + s * e[0], ct->pos[1] = A[1] + s * e[1], ct->pos[2] = 0.5 * (zt + zb);
        ct->depth = depth;
    }
}

static void keep_deepest(gathered *g, dGeomID box, const dContactGeom *found, int n)
{
    for (int i = 0; i < n; i++)
        if (found[i].depth > 0) {
            dContactGeom *ct = next_contact(g, box);
            if (!ct)
                return;
            *ct = found[i];
            ct->g1 = box;
        }
}

void fs_lattice_box_contacts(const fs_terrain *t, dGeomID box, gathered *g)
{
    box_frame bx = frame_of(box);
    double p[8][3], gap[4]; /* the underside's corners' heights under the surface (vertical) */
    int flush = bx.R[10] > 0; /* the underside faces down, its corners all over the lattice */
    for (int k = 0; k < 8; k++) {
        corner(&bx, k, p[k]);
        double z, n[3];
        int over = surface(t, p[k][0], p[k][1], &z, n);
        if (k < 4) {
            flush &= over;
            gap[k] = over ? z - p[k][2] : 0;
        }
        if (!over || p[k][2] >= z)
            continue;
        dContactGeom *ct = next_contact(g, box);
        if (!ct)
            return;
        memcpy(ct->pos, p[k], 3 * sizeof p[k][0]);
        memcpy(ct->normal, n, 3 * sizeof n[0]);
        ct->depth = (z - p[k][2]) * n[2];
    }
    /* the twelve edges: corners that differ in one bit */
    for (int k = 0; k < 8; k++)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (k & bit)
                continue;
            const double *A = p[k], *B = p[k | bit];
            if (fmin(A[2], B[2]) > t->zmax)
                continue;
            dContactGeom part[EDGE_PARTS];
            memset(part, 0, sizeof part);
            int underside = (k | bit) < 4; /* both ends on the underside */
            double ends[2] = {underside ? gap[k] : 0, underside ? gap[k | bit] : 0};
            const double *under = flush && underside ? ends : NULL;
            edge_family(t, A, B, 1, 0, 0, 1, under, part);  /* lines u = i: lattice edges along y */
            edge_family(t, A, B, 0, 1, 1, 0, under, part);  /* lines v = j: along x */
            edge_family(t, A, B, 1, -1, 1, 1, under, part); /* lines u - v = k: the rising diagonals */
            keep_deepest(g, box, part, EDGE_PARTS);
        }
    dContactGeom patch[BOX_SLOTS];
    memset(patch, 0, sizeof patch);
    vertices_inside(t, box, &bx, g, patch, flush ? gap : NULL);
    keep_deepest(g, box, patch, BOX_SLOTS);
}

/* ---- a sphere ------------------------------------------------------------------------------- */

/* on ODE's arrays, inlined: this runs for every triangle near every sphere every step, where
 * fs_dot (fs_vec.h) would be a call on fs_vec3 copies into another file */
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The point q of triangle (v[0], v[1], v[2]) nearest p, and which of its corners span the feature q
 * lies on (bit k: v[k]; 7 the face, two bits an edge, one a corner), by the Voronoi regions of its
 * corners, edges and face in turn. */
static int nearest_on_triangle(const double p[3], const double v[3][3], double q[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int k = 0; k < 3; k++) {
        ab[k] = v[1][k] - v[0][k], ac[k] = v[2][k] - v[0][k];
        ap[k] = p[k] - v[0][k], bp[k] = p[k] - v[1][k], cp[k] = p[k] - v[2][k];
    }
    double d1 = dot3(ab, ap), d2 = dot3(ac, ap), d3 = dot3(ab, bp), d4 = dot3(ac, bp);
    double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
    double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    double s = 0, u = 0; /* q = v0 + s ab + u ac */
    int mask;
    if (d1 <= 0 && d2 <= 0)
        mask = 1;
    else if (d3 >= 0 && d4 <= d3)
        mask = 2, s = 1;
    else if (d6 >= 0 && d5 <= d6)
        mask = 4, u = 1;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
        mask = 3, s = d1 / (d1 - d3);
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
        mask = 5, u = d2 / (d2 - d6);
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        mask = 6, u = (d4 - d3) / ((d4 - d3) + (d5 - d6)), s = 1 - u;
    else
        mask = 7, s = vb / (va + vb + vc), u = vc / (va + vb + vc);
    for (int k = 0; k < 3; k++)
        q[k] = v[0][k] + s * ab[k] + u * ac[k];
    return mask;
}

/* A triangle of the lattice near a sphere: the point of it nearest the centre, that point's
 * squared distance, the triangle's corners (lattice indices) and the feature (corner bits) the
 * point lies on. */
typedef struct near_point {
    double q[3], d2;
    long corner[3];
    long i, j; /* its cell: triangles that share a corner lie in cells a cell apart at most */
    int feature;
} near_point;

/* Whether triangle a holds b's nearest point's feature (has every corner that spans it). */
static int holds(const near_point *a, const near_point *b)
{
    for (int k = 0; k < 3; k++) {
        if (!(b->feature & 1 << k))
            continue;
        long id = b->corner[k];
        if (a->corner[0] != id && a->corner[1] != id && a->corner[2] != id)
            return 0;
    }
    return 1;
}

/* The lattice indices of the corners spanning p's feature, ascending; how many. */
static int feature_corners(const near_point *p, long id[3])
{
    int m = 0;
    for (int k = 0; k < 3; k++)
        if (p->feature & 1 << k) {
            int at = m++;
            for (; at > 0 && id[at - 1] > p->corner[k]; at--)
                id[at] = id[at - 1];
            id[at] = p->corner[k];
        }
    return m;
}

/* Whether a and b name the same feature, so the same point. */
static int same_feature(const near_point *a, const near_point *b)
{
    long ia[3], ib[3];
    int m = feature_corners(a, ia);
    if (m != feature_corners(b, ib))
        return 0;
    for (int k = 0; k < m; k++)
        if (ia[k] != ib[k])
            return 0;
    return 1;
}

/* The triangles' nearest points a sphere keeps: past this many (a lattice much finer than the
 * sphere, or a sphere sunk deep), the nearest this many. Every triangle that could pass a kept
 * point over is nearer than it, so kept too: the contacts found are the nearest local minima. */
enum { SPHERE_NEAR_MAX = 256 };

/* A slot for a new nearest point at squared distance d2: the next free one, or when all are taken
 * the farthest, if it is farther than d2; NULL when d2 would be the farthest. */
static near_point *near_slot(near_point *near, int *n, double d2)
{
    if (*n < SPHERE_NEAR_MAX)
        return &near[(*n)++];
    int far = 0;
    for (int k = 1; k < SPHERE_NEAR_MAX; k++)
        if (near[k].d2 > near[far].d2)
            far = k;
    return near[far].d2 > d2 ? &near[far] : NULL;
}

void fs_lattice_sphere_contacts(const fs_terrain *t, dGeomID sphere, gathered *g)
{
    const dReal *c = dGeomGetPosition(sphere);
    const double r = dGeomSphereGetRadius(sphere);
    if (!(c[2] - r <= t->zmax) || !isfinite(c[0]) || !isfinite(c[1]))
        return; /* above every sample (or the state is lost) */
    double zs, ns[3];
    if (surface(t, c[0], c[1], &zs, ns) && c[2] <= zs) {
        /* The centre under the surface (the sphere went through it in a step): out along the normal
         * above it, as deep as with the centre on the surface. Deeper, the contact's spring would
         * hold energy the sphere never gave it (5 mm more: 110 J at the default sole's and
         * ground's stiffnesses in series, 1e7 and 1e8 N/m) and fling the foot. */
        dContactGeom *ct = next_contact(g, sphere);
        if (!ct)
            return;
        for (int k = 0; k < 3; k++)
            ct->normal[k] = ns[k], ct->pos[k] = c[k] - r * ns[k];
        ct->depth = r;
        return;
    }
    /* each triangle within r of the centre: its nearest point */
    near_point near[SPHERE_NEAR_MAX];
    int n = 0;
    /* the cells under the sphere's square, clipped to the lattice before any cast */
    double fi0 = fmax(0, floor((c[0] - r - t->x0) / t->dx)), fi1 = fmin(t->nx - 2, floor((c[0] + r - t->x0) / t->dx));
    double fj0 = fmax(0, floor((c[1] - r - t->y0) / t->dx)), fj1 = fmin(t->ny - 2, floor((c[1] + r - t->y0) / t->dx));
    if (!(fi0 <= fi1 && fj0 <= fj1))
        return;
    const long i0 = (long)fi0, i1 = (long)fi1, j0 = (long)fj0, j1 = (long)fj1;
    for (long j = j0; j <= j1; j++) {
        double y = t->y0 + j * t->dx, Y = y + t->dx;
        double gy = c[1] < y ? y - c[1] : c[1] > Y ? c[1] - Y : 0; /* the row's nearest y to the centre's */
        for (long i = i0; i <= i1; i++) {
            double x = t->x0 + i * t->dx, X = x + t->dx;
            double gx = c[0] < x ? x - c[0] : c[0] > X ? c[0] - X : 0;
            /* r^2 - rho^2: rho the cell's nearest horizontal distance from the centre. The sphere's
               underside there is sqrt(that) below the centre, and lower everywhere else over the
               cell: a cell under it throughout has no point within r (the same triangles are
               tried as without this, in the same order) */
            double reach2 = r * r - gx * gx - gy * gy;
            if (reach2 <= 0)
                continue;
            double z00 = zat(t, i, j), z10 = zat(t, i + 1, j), z01 = zat(t, i, j + 1), z11 = zat(t, i + 1, j + 1);
            double top = z00 > z10 ? z00 : z10;
            top = top > z01 ? top : z01;
            top = top > z11 ? top : z11;
            if (top < c[2] && (c[2] - top) * (c[2] - top) > reach2)
                continue;
            long id00 = j * t->nx + i, id10 = id00 + 1, id01 = id00 + t->nx, id11 = id01 + 1;
            /* the cell's two triangles, as fs_terrain_cell splits it: (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1) */
            const double tri[2][3][3] = {{{x, y, z00}, {X, y, z10}, {X, Y, z11}}, {{x, y, z00}, {X, Y, z11}, {x, Y, z01}}};
            const long ids[2][3] = {{id00, id10, id11}, {id00, id11, id01}};
            for (int h = 0; h < 2; h++) {
                near_point found;
                found.feature = nearest_on_triangle(c, tri[h], found.q);
                double w[3] = {c[0] - found.q[0], c[1] - found.q[1], c[2] - found.q[2]};
                found.d2 = dot3(w, w);
                if (!(found.d2 < r * r))
                    continue;
                memcpy(found.corner, ids[h], sizeof found.corner);
                found.i = i, found.j = j;
                near_point *p = near_slot(near, &n, found.d2);
                if (p)
                    *p = found;
            }
        }
    }
    /* A contact at each point nearest the centre among the points around it: the distance from the
     * centre, over the surface, at a local minimum. A triangle's nearest point is one unless a
     * triangle that holds its feature (the neighbour across its edge, or around its corner) comes
     * nearer; of the triangles that find the same edge or corner, the first stands for all. So a
     * sphere resting on a face, an edge or a corner touches once, and one in a hollow once on each
     * side. The one nearest of all is never passed over. */
    for (int a = 0; a < n; a++) {
        int kept = 1;
        for (int b = 0; b < n && kept; b++)
            if (b != a && labs(near[b].i - near[a].i) <= 1 && labs(near[b].j - near[a].j) <= 1 &&
                holds(&near[b], &near[a]))
                kept = !(near[b].d2 < near[a].d2 * (1 - 1e-12) || (b < a && same_feature(&near[a], &near[b])));
        if (!kept)
            continue;
        double d = sqrt(near[a].d2), u[3];
        for (int k = 0; k < 3; k++)
            u[k] = (c[k] - near[a].q[k]) / d;
        if (!(d > 0) || u[2] <= 0)
            continue; /* touching the centre, or from beneath: no direction out of the ground */
        dContactGeom *ct = next_contact(g, sphere);
        if (!ct)
            return;
        for (int k = 0; k < 3; k++)
            ct->normal[k] = u[k], ct->pos[k] = c[k] - r * u[k];
        ct->depth = r - d;
    }
}
