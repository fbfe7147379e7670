/* test_sim_lattice.c: footsim's own box-heightfield contacts (src/sim/sim_lattice.c) against an
 * independent test of the same geometry: a box overlaps the ground below a triangulated surface
 * exactly when one of the surface's triangles meets the box (separating-axis test, 13 axes) or the
 * box lies wholly below it. The contacts must be found exactly then, each pointing out of the
 * ground, with a positive depth no deeper than the box's overlap allows, and a few a feature. */
#include "fs_test.h"

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

static gathered *contacts_of(const fs_terrain *t, const pose *p)
{
    static gathered g;
    g.n = 0;
    fs_lattice_box_contacts(t, p->box, &g);
    return &g;
}

/* Over rough ground of short correlation (slopes up to about 60 deg: rocks' steep flanks), 4000
 * random poses: contacts exactly when the box overlaps the ground. */
static void test_contacts_exactly_when_overlapping(void)
{
    fs_terrain t;
    fs_error err;
    const char *set[] = {"rough.rms_m=0.002", "rough.correlation_m=0.002", "rough.resolution_m=0.001",
                         "rough.patch_x_min_m=-1", "rough.patch_x_max_m=1"};
    REQUIRE(fs_terrain_load("terrains/rough.ini", set, 5, &t, &err) == FS_OK);
    REQUIRE(fs_terrain_crop(&t, -0.03, 0.03, -0.03, 0.03, &err) == FS_OK);
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
    fs_error err;
    const char *set[] = {"rough.rms_m=0", "rough.resolution_m=0.001"};
    REQUIRE(fs_terrain_load("terrains/rough.ini", set, 2, &t, &err) == FS_OK);
    REQUIRE(fs_terrain_crop(&t, -0.2, 0.2, -0.1, 0.1, &err) == FS_OK);
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

FS_TEST_MAIN(TEST(test_contacts_exactly_when_overlapping), TEST(test_level_box_on_flat_lattice))
