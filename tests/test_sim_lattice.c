/* test_sim_lattice.c: footsim's own box- and sphere-heightfield contacts (src/sim/sim_lattice.c)
 * against independent tests of the same geometry. A box overlaps the ground below a triangulated
 * surface exactly when one of the surface's triangles meets the box (separating-axis test, 13 axes)
 * or the box lies wholly below it; a sphere, when its centre lies under the surface or nearer a
 * triangle than its radius (the nearest point found another way: in the triangle's plane, else on
 * its edges). The contacts must be found exactly then, each pointing out of the ground, with a
 * positive depth no deeper than the overlap allows, and a few a feature. */
#include "fs_test.h"

#include "sim/sim_ground.h"
#include "sim/sim_lattice.h"

#include <stdlib.h>

/* a small random number generator of the test's own, so that the poses are the same everywhere */
static unsigned long long state = 88172645463325252ULL;
static double uniform(double a, double b)
{
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return a + (b - a) * (double)(state >> 11) / 9007199254740992.0;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Whether triangle v[3] meets the box (centre c, unit axes ax[3], half lengths h): no separating
 * axis among the box's three, the triangle's normal and the nine crosses of their edges. */
static int triangle_meets_box(double v[3][3], const double c[3], const double ax[3][3], const double h[3])
{
    double w[3][3], e[3][3], axes[13][3];
    int n = 0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            w[i][k] = v[i][k] - c[k];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            e[i][k] = w[(i + 1) % 3][k] - w[i][k];
    for (int i = 0; i < 3; i++)
        memcpy(axes[n++], ax[i], sizeof axes[0]);
    cross3(e[0], e[1], axes[n++]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            cross3(ax[i], e[j], axes[n++]);
    for (int a = 0; a < n; a++) {
        const double *L = axes[a];
        if (dot3(L, L) < 1e-24)
            continue;
        double lo = INFINITY, hi = -INFINITY, r = 0;
        for (int i = 0; i < 3; i++) {
            double p = dot3(w[i], L);
            lo = fmin(lo, p), hi = fmax(hi, p);
            r += h[i] * fabs(dot3(ax[i], L));
        }
        if (lo > r || hi < -r)
            return 0;
    }
    return 1;
}

static double zat(const fs_terrain *t, long i, long j) { return t->z[(size_t)j * t->nx + i]; }

typedef struct pose {
    double c[3], ax[3][3], h[3];
    dGeomID box;
} pose;

/* A box of the flat foot's proportions (scaled to a few cells) at a random place, yaw and tilt
 * just over the surface's height there. */
static void draw_pose(const fs_terrain *t, pose *p)
{
    double h[3] = {uniform(0.004, 0.012), uniform(0.002, 0.006), uniform(0.001, 0.004)};
    double yaw = uniform(-M_PI, M_PI), pitch = uniform(-0.5, 0.5), roll = uniform(-0.5, 0.5);
    dMatrix3 R;
    dRFromEulerAngles(R, roll, pitch, yaw);
    double x = t->x0 + uniform(0.3, 0.7) * (t->nx - 1) * t->dx, y = t->y0 + uniform(0.3, 0.7) * (t->ny - 1) * t->dx;
    double z = fs_terrain_height(t, x, y) + uniform(0, 0.014);
    dGeomSetPosition(p->box, x, y, z);
    dGeomSetRotation(p->box, R);
    dGeomBoxSetLengths(p->box, 2 * h[0], 2 * h[1], 2 * h[2]);
    memcpy(p->h, h, sizeof h);
    p->c[0] = x, p->c[1] = y, p->c[2] = z;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            p->ax[i][k] = R[4 * k + i]; /* column i of R: the box's axis i */
}

/* The truth: whether the box overlaps the ground; 0 with *buried when some lattice vertex under
 * the box rises above the box's highest corner (the box under the surface: not a pose a falling
 * sole can reach, and not what the test is about). */
static int overlaps(const fs_terrain *t, const pose *p, int *buried)
{
    double top = -INFINITY, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    int below = 0;
    for (int k = 0; k < 8; k++) {
        double q[3];
        for (int m = 0; m < 3; m++)
            q[m] = p->c[m] + (k & 1 ? 1 : -1) * p->h[0] * p->ax[0][m] + (k & 2 ? 1 : -1) * p->h[1] * p->ax[1][m] +
                   (k & 4 ? 1 : -1) * p->h[2] * p->ax[2][m];
        top = fmax(top, q[2]);
        for (int m = 0; m < 2; m++)
            lo[m] = fmin(lo[m], q[m]), hi[m] = fmax(hi[m], q[m]);
        below |= q[2] < fs_terrain_height(t, q[0], q[1]);
    }
    long i0 = (long)floor((lo[0] - t->x0) / t->dx), i1 = (long)ceil((hi[0] - t->x0) / t->dx);
    long j0 = (long)floor((lo[1] - t->y0) / t->dx), j1 = (long)ceil((hi[1] - t->y0) / t->dx);
    int meets = 0;
    *buried = 0;
    for (long j = j0; j < j1; j++)
        for (long i = i0; i < i1; i++) {
            double x = t->x0 + i * t->dx, y = t->y0 + j * t->dx, d = t->dx;
            double a[3] = {x, y, zat(t, i, j)}, b[3] = {x + d, y, zat(t, i + 1, j)};
            double cc[3] = {x + d, y + d, zat(t, i + 1, j + 1)}, e[3] = {x, y + d, zat(t, i, j + 1)};
            double lower[3][3], upper[3][3];
            memcpy(lower[0], a, sizeof a), memcpy(lower[1], b, sizeof b), memcpy(lower[2], cc, sizeof cc);
            memcpy(upper[0], a, sizeof a), memcpy(upper[1], cc, sizeof cc), memcpy(upper[2], e, sizeof e);
            meets |= triangle_meets_box(lower, p->c, p->ax, p->h) ||
                     triangle_meets_box(upper, p->c, p->ax, p->h);
            *buried |= a[2] > top;
        }
    return meets || below;
}

/* The contacts footsim's own test finds for shape (a box or a sphere). */
static gathered *contacts_with(const fs_terrain *t, dGeomID shape)
{
    static gathered g;
    g.n = 0;
    if (dGeomGetClass(shape) == dBoxClass)
        fs_lattice_box_contacts(t, shape, &g);
    else
        fs_lattice_sphere_contacts(t, shape, &g);
    return &g;
}

static gathered *contacts_of(const fs_terrain *t, const pose *p) { return contacts_with(t, p->box); }

/* Rough ground of short correlation, 6 cm square: slopes up to about 60 deg, like rocks' flanks. */
static void steep_ground(fs_terrain *t)
{
    fs_error err;
    const char *set[] = {"rough.rms_m=0.002", "rough.correlation_m=0.002", "rough.resolution_m=0.001",
                         "rough.patch_x_min_m=-1", "rough.patch_x_max_m=1"};
    REQUIRE(fs_terrain_load("terrains/rough.ini", set, 5, t, &err) == FS_OK);
    REQUIRE(fs_terrain_crop(t, -0.03, 0.03, -0.03, 0.03, &err) == FS_OK);
}

/* A flat lattice (rough ground of no roughness) of spacing resolution, cropped to x and y within
 * +-half_x and +-half_y. */
static void flat_lattice(fs_terrain *t, const char *resolution, double half_x, double half_y)
{
    fs_error err;
    char res[64];
    snprintf(res, sizeof res, "rough.resolution_m=%s", resolution);
    const char *set[] = {"rough.rms_m=0", res};
    REQUIRE(fs_terrain_load("terrains/rough.ini", set, 2, t, &err) == FS_OK);
    REQUIRE(fs_terrain_crop(t, -half_x, half_x, -half_y, half_y, &err) == FS_OK);
}

/* Over rough ground of short correlation (slopes up to about 60 deg: rocks' steep flanks), 4000
 * random poses: contacts exactly when the box overlaps the ground. */
static void test_contacts_exactly_when_overlapping(void)
{
    fs_terrain t;
    steep_ground(&t);
    pose p;
    p.box = dCreateBox(0, 1, 1, 1);
    int tried = 0, overlapping = 0, missed = 0, spurious = 0, bad = 0, most = 0;
    for (int k = 0; k < 4000; k++) {
        draw_pose(&t, &p);
        int buried, truth = overlaps(&t, &p, &buried);
        if (buried)
            continue;
        tried++;
        overlapping += truth;
        const gathered *g = contacts_of(&t, &p);
        missed += truth && g->n == 0;
        spurious += !truth && g->n > 0;
        most = g->n > most ? g->n : most;
        double diag = 2 * sqrt(dot3(p.h, p.h));
        for (int i = 0; i < g->n; i++) {
            const dContactGeom *c = &g->c[i];
            double len = sqrt(c->normal[0] * c->normal[0] + c->normal[1] * c->normal[1] + c->normal[2] * c->normal[2]);
            bad += !(c->depth > 0 && c->depth <= diag && fabs(len - 1) < 1e-9 && c->g1 == p.box);
        }
    }
    printf("  %d poses (%d overlapping): %d missed, %d spurious, %d bad contacts, at most %d a pose\n", tried,
           overlapping, missed, spurious, bad, most);
    CHECK(tried > 2000 && overlapping > tried / 4 && overlapping < tried * 3 / 4);
    CHECK(missed == 0);
    CHECK(spurious == 0);
    CHECK(bad == 0);
    /* 8 corners, 12 edges in 2 parts, 2 x 4 x 2 face patches and 4 side faces at most */
    CHECK(most <= 8 + 24 + 20);
    dGeomDestroy(p.box);
    fs_terrain_free(&t);
}

/* A box resting level on a flat lattice touches it along its whole underside: its four bottom
 * corners are found at the same depth, straight up, and nothing else (each contact carries the
 * ground's whole stiffness: the vertices under it too would make it stiffer than on a plane). */
static void test_level_box_on_flat_lattice(void)
{
    fs_terrain t;
    flat_lattice(&t, "0.001", 0.2, 0.1);
    dGeomID box = dCreateBox(0, 0.2, 0.08, 0.008);
    double sink = 1e-4;
    dGeomSetPosition(box, 0.0123, -0.0047, 0.004 - sink);
    pose p = {{0}, {{0}}, {0}, box};
    const gathered *g = contacts_of(&t, &p);
    int corners = 0;
    for (int i = 0; i < g->n; i++) {
        CHECK_NEAR(g->c[i].depth, sink, 1e-12);
        CHECK_NEAR(g->c[i].normal[2], 1, 1e-12);
        corners += fabs(fabs(g->c[i].pos[0] - 0.0123) - 0.1) < 1e-12 && fabs(fabs(g->c[i].pos[1] + 0.0047) - 0.04) < 1e-12;
    }
    CHECK(corners == 4);
    CHECK(g->n == 4); /* flush: held by its corners alone, as on a plane */
    /* lifted clear: nothing */
    dGeomSetPosition(box, 0.0123, -0.0047, 0.004 + 1e-6);
    CHECK(contacts_of(&t, &p)->n == 0);
    dGeomDestroy(box);
    fs_terrain_free(&t);
}

/* ---- spheres ---- */

static void sub3(const double *a, const double *b, double *c) { c[0] = a[0] - b[0], c[1] = a[1] - b[1], c[2] = a[2] - b[2]; }

/* The distance from p to segment ab. */
static double to_segment(const double *p, const double *a, const double *b)
{
    double ab[3], ap[3], d[3];
    sub3(b, a, ab), sub3(p, a, ap);
    double s = fmin(1, fmax(0, dot3(ap, ab) / dot3(ab, ab)));
    for (int k = 0; k < 3; k++)
        d[k] = ap[k] - s * ab[k];
    return sqrt(dot3(d, d));
}

/* The distance from p to triangle v: to its plane where p's foot there lies inside it (all three
 * edge tests of the same sign), else to the nearest of its edges. */
static double to_triangle(const double *p, double v[3][3])
{
    double e1[3], e2[3], n[3], w[3];
    sub3(v[1], v[0], e1), sub3(v[2], v[0], e2), cross3(e1, e2, n);
    double len = sqrt(dot3(n, n));
    sub3(p, v[0], w);
    double h = dot3(w, n) / len, foot[3];
    for (int k = 0; k < 3; k++)
        foot[k] = p[k] - h * n[k] / len;
    int inside = 1;
    for (int i = 0; i < 3; i++) {
        double a[3], b[3], c[3];
        sub3(v[(i + 1) % 3], v[i], a), sub3(foot, v[i], b), cross3(a, b, c);
        inside &= dot3(c, n) >= 0;
    }
    if (inside)
        return fabs(h);
    return fmin(to_segment(p, v[0], v[1]), fmin(to_segment(p, v[1], v[2]), to_segment(p, v[2], v[0])));
}

/* The distance from p to the lattice's surface, over every triangle within reach of it. */
static double to_surface(const fs_terrain *t, const double *p, double reach)
{
    double best = INFINITY;
    long i0 = (long)floor((p[0] - reach - t->x0) / t->dx), i1 = (long)ceil((p[0] + reach - t->x0) / t->dx);
    long j0 = (long)floor((p[1] - reach - t->y0) / t->dx), j1 = (long)ceil((p[1] + reach - t->y0) / t->dx);
    for (long j = j0; j < j1; j++)
        for (long i = i0; i < i1; i++) {
            double x = t->x0 + i * t->dx, y = t->y0 + j * t->dx, d = t->dx;
            double lower[3][3] = {{x, y, zat(t, i, j)}, {x + d, y, zat(t, i + 1, j)}, {x + d, y + d, zat(t, i + 1, j + 1)}};
            double upper[3][3] = {{x, y, zat(t, i, j)}, {x + d, y + d, zat(t, i + 1, j + 1)}, {x, y + d, zat(t, i, j + 1)}};
            best = fmin(best, fmin(to_triangle(p, lower), to_triangle(p, upper)));
        }
    return best;
}

/* Whether n is the unit normal of the lattice's triangle above or below p: the cross of two of its
 * edges, up. */
static int normal_above(const fs_terrain *t, const double *p, const double *n)
{
    long i = (long)floor((p[0] - t->x0) / t->dx), j = (long)floor((p[1] - t->y0) / t->dx);
    double fx = (p[0] - t->x0) / t->dx - i, fy = (p[1] - t->y0) / t->dx - j, d = t->dx;
    double a[3] = {0, 0, zat(t, i, j)}, b[3] = {d, 0, zat(t, i + 1, j)};
    double c[3] = {d, d, zat(t, i + 1, j + 1)}, e[3] = {0, d, zat(t, i, j + 1)}, u[3], v[3], m[3];
    if (fx >= fy)
        sub3(b, a, u), sub3(c, b, v);
    else
        sub3(c, e, u), sub3(e, a, v);
    cross3(u, v, m);
    double len = sqrt(dot3(m, m));
    return fabs(m[0] / len - n[0]) < 1e-12 && fabs(m[1] / len - n[1]) < 1e-12 && fabs(m[2] / len - n[2]) < 1e-12;
}

typedef struct ode_found {
    dContactGeom c[64];
    int n;
} ode_found;

static void ode_gather(void *data, dGeomID a, dGeomID b)
{
    ode_found *f = data;
    if (f->n < 64)
        f->n += dCollide(a, b, 64 - f->n, f->c + f->n, sizeof f->c[0]);
}

/* Over the same steep rough ground, 4000 spheres of a toe's and a heel's sizes: contacts exactly
 * when the sphere overlaps the ground; each on the surface, pointing from it to the centre, the
 * deepest as deep as the sphere's overlap with the nearest triangle; a centre under the surface
 * pushed out along the normal there, as deep as the radius. */
static void test_sphere_contacts_exactly_when_overlapping(void)
{
    fs_terrain t;
    steep_ground(&t);
    dGeomID sphere = dCreateSphere(0, 1);
    int tried = 0, overlapping = 0, missed = 0, spurious = 0, bad = 0, wrong_depth = 0, most = 0;
    /* ODE's test of the same spheres, for comparison only (printed, not checked) */
    dSpaceID space = dHashSpaceCreate(0);
    int ok = 1, ode_many = 0, ode_off = 0, ode_touching = 0;
    fs_ground *ground = fs_ground_heightfield(space, &t, 8, &ok);
    REQUIRE(ok);
    for (int k = 0; k < 4000; k++) {
        double r = uniform(0.003, 0.006);
        double c[3] = {t.x0 + uniform(0.3, 0.7) * (t.nx - 1) * t.dx, t.y0 + uniform(0.3, 0.7) * (t.ny - 1) * t.dx, 0};
        c[2] = fs_terrain_height(&t, c[0], c[1]) + uniform(-0.001, r + 0.008);
        dGeomSphereSetRadius(sphere, r);
        dGeomSetPosition(sphere, c[0], c[1], c[2]);
        int under = c[2] < fs_terrain_height(&t, c[0], c[1]);
        double d = to_surface(&t, c, r);
        if (!under && fabs(d - r) < 1e-12)
            continue; /* grazing: either answer is right */
        tried++;
        int truth = under || d < r;
        overlapping += truth;
        const gathered *g = contacts_with(&t, sphere);
        missed += truth && g->n == 0;
        spurious += !truth && g->n > 0;
        most = g->n > most ? g->n : most;
        double deepest = 0;
        for (int i = 0; i < g->n; i++) {
            const dContactGeom *ct = &g->c[i];
            double len = sqrt(dot3(ct->normal, ct->normal)), q[3];
            for (int m = 0; m < 3; m++) /* the surface point: the centre less (r - depth) along the normal */
                q[m] = c[m] - (r - ct->depth) * ct->normal[m];
            /* on the surface; from a centre under it, as deep as the radius, along the normal of
               the surface above the centre */
            int on_surface = under ? ct->depth == r && normal_above(&t, c, ct->normal)
                                   : fabs(q[2] - fs_terrain_height(&t, q[0], q[1])) < 1e-12;
            bad += !(ct->depth > 0 && ct->depth <= 2 * r && fabs(len - 1) < 1e-9 && ct->normal[2] > 0 && on_surface &&
                     ct->g1 == sphere);
            deepest = fmax(deepest, ct->depth);
        }
        wrong_depth += !under && g->n > 0 && fabs(deepest - (r - d)) > 1e-12;
        if (truth && !under) {
            ode_found f = {0};
            dSpaceCollide2(sphere, (dGeomID)space, &f, ode_gather);
            double ode_deepest = 0;
            for (int i = 0; i < f.n; i++)
                ode_deepest = fmax(ode_deepest, f.c[i].depth);
            ode_touching++;
            ode_many += f.n >= 7;
            ode_off += fabs(ode_deepest - (r - d)) > 1e-4;
        }
    }
    printf("  %d spheres (%d overlapping): %d missed, %d spurious, %d bad contacts, %d wrong depths, at most %d a "
           "sphere\n",
           tried, overlapping, missed, spurious, bad, wrong_depth, most);
    printf("  ODE's test of the %d overlapping with the centre over the surface: 7 or more contacts for %d, the "
           "deepest off the overlap by more than 0.1 mm for %d\n",
           ode_touching, ode_many, ode_off);
    CHECK(tried > 3000 && overlapping > tried / 4 && overlapping < tried * 3 / 4);
    CHECK(missed == 0);
    CHECK(spurious == 0);
    CHECK(bad == 0);
    CHECK(wrong_depth == 0);
    dSpaceDestroy(space);
    fs_ground_destroy(ground);
    dGeomDestroy(sphere);
    fs_terrain_free(&t);
}

/* A flat lattice: one contact straight up, as on a plane, wherever the sphere stands (on a
 * triangle's face, its diagonal, a lattice edge or a vertex). Bent into a valley along a lattice
 * line: one on each flank, along its normal. Bent into a ridge: one, on the ridge, pointing at the
 * centre. */
static void test_sphere_on_plane_valley_and_ridge(void)
{
    fs_terrain t;
    flat_lattice(&t, "0.001", 0.05, 0.05);
    dGeomID sphere = dCreateSphere(0, 0.005);
    const double sink = 2e-4, z0 = zat(&t, 0, 0);
    /* a vertex, a lattice edge, the diagonal, the faces either side of it */
    const double at[][2] = {{0, 0}, {0.5, 0}, {0.5, 0.5}, {0.7, 0.2}, {0.2, 0.7}};
    long i = t.nx / 2, j = t.ny / 2;
    for (int k = 0; k < 5; k++) {
        dGeomSetPosition(sphere, t.x0 + (i + at[k][0]) * t.dx, t.y0 + (j + at[k][1]) * t.dx, z0 + 0.005 - sink);
        const gathered *g = contacts_with(&t, sphere);
        CHECK(g->n == 1);
        CHECK_NEAR(g->c[0].depth, sink, 1e-12);
        CHECK_NEAR(g->c[0].normal[2], 1, 1e-12);
    }
    /* a valley along the lattice line x = x0 + i dx, flanks rising at slope s either side */
    const double s = 0.5, xv = t.x0 + i * t.dx;
    for (int pass = 0; pass < 2; pass++) {
        double sign = pass == 0 ? 1 : -1; /* 1: a valley; -1: a ridge */
        for (long b = 0; b < t.ny; b++)
            for (long a = 0; a < t.nx; a++)
                t.z[(size_t)b * t.nx + a] = z0 + sign * s * fabs(t.x0 + a * t.dx - xv);
        t.zmax = z0 + (sign > 0 ? s * 0.05 : 0);
        /* the centre over the crease, sunk so that it is sink nearer each flank than its radius
           (valley), or sink below the ridge line (ridge) */
        double cz = sign > 0 ? z0 + (0.005 - sink) * sqrt(1 + s * s) : z0 + 0.005 - sink;
        dGeomSetPosition(sphere, xv, t.y0 + (j + 0.3) * t.dx, cz);
        const gathered *g = contacts_with(&t, sphere);
        if (sign > 0) {
            CHECK(g->n == 2);
            for (int m = 0; m < g->n && m < 2; m++) {
                CHECK_NEAR(g->c[m].depth, sink, 1e-12);
                CHECK_NEAR(fabs(g->c[m].normal[0]), s / sqrt(1 + s * s), 1e-12);
                CHECK_NEAR(g->c[m].normal[2], 1 / sqrt(1 + s * s), 1e-12);
            }
            if (g->n == 2)
                CHECK(g->c[0].normal[0] * g->c[1].normal[0] < 0);
        } else {
            CHECK(g->n == 1);
            CHECK_NEAR(g->c[0].depth, sink, 1e-12);
            CHECK_NEAR(g->c[0].normal[2], 1, 1e-12);
            CHECK_NEAR(g->c[0].pos[0], xv, 1e-12);
        }
    }
    dGeomDestroy(sphere);
    fs_terrain_free(&t);
}

/* A sphere sunk to near its centre on a lattice far finer than it: thousands of triangles in reach,
 * more than the test keeps (the nearest ones are kept), and still the one contact straight up, as
 * deep as it sank; its centre just on the surface: as deep as its radius. */
static void test_sphere_on_fine_lattice(void)
{
    fs_terrain t;
    flat_lattice(&t, "0.0002", 0.02, 0.02);
    const double r = 0.006, z0 = zat(&t, 0, 0);
    dGeomID sphere = dCreateSphere(0, r);
    const double above[] = {1e-4, 0};
    for (int k = 0; k < 2; k++) {
        dGeomSetPosition(sphere, 0.00123, -0.00047, z0 + above[k]);
        const gathered *g = contacts_with(&t, sphere);
        CHECK(g->n == 1);
        if (g->n == 1) {
            CHECK_NEAR(g->c[0].depth, r - above[k], 1e-12);
            CHECK_NEAR(g->c[0].normal[2], 1, 1e-12);
        }
    }
    dGeomDestroy(sphere);
    fs_terrain_free(&t);
}

FS_TEST_MAIN(TEST(test_contacts_exactly_when_overlapping), TEST(test_level_box_on_flat_lattice),
             TEST(test_sphere_contacts_exactly_when_overlapping), TEST(test_sphere_on_plane_valley_and_ridge),
             TEST(test_sphere_on_fine_lattice))
