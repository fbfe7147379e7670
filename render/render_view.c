/* render_view.c: cameras framed on a scene's extent, their matrices and the projection of world
 * points to pixels (the same matrices render_gl.c loads into GL). */
#include "footsim/render/fs_render.h"

#include <math.h>
#include <string.h>

const char *const fs_render_camera_names[FS_RENDER_NCAMERAS] = {"side", "front", "three-quarter", "follow",
                                                                  "foot"};

/* Where each camera looks from (azimuth from +x toward +y, elevation, degrees) and how much room
 * it leaves around the extent (1 = touching the edges). */
static const struct {
    double azimuth_deg, elevation_deg, margin;
} placement[FS_RENDER_NCAMERAS] = {
    {-90, 12, 1.25},
    {0, 12, 1.25},
    {-45, 28, 1.2},
    {-135, 20, 1.05},
    {-60, 24, 1.08},
};

static const double FOVY_DEG = 20; /* narrow: little perspective distortion across the foot */

int fs_render_camera_find(const char *name)
{
    for (int i = 0; i < FS_RENDER_NCAMERAS; i++)
        if (name && !strcmp(name, fs_render_camera_names[i]))
            return i;
    return -1;
}

/* ---- small vector helpers ------------------------------------------------------------------- */

static void sub3(double r[3], const double a[3], const double b[3])
{
    for (int k = 0; k < 3; k++)
        r[k] = a[k] - b[k];
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(double r[3], const double a[3], const double b[3])
{
    double t[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    memcpy(r, t, sizeof t);
}

static void unit3(double a[3])
{
    double n = sqrt(dot3(a, a));
    if (n > 0)
        for (int k = 0; k < 3; k++)
            a[k] /= n;
}

/* ---- extent --------------------------------------------------------------------------------- */

typedef struct box3 {
    double lo[3], hi[3];
} box3;

static void grow(box3 *b, const double p[3], double r)
{
    for (int k = 0; k < 3; k++) {
        b->lo[k] = fmin(b->lo[k], p[k] - r);
        b->hi[k] = fmax(b->hi[k], p[k] + r);
    }
}

/* Half extents along the world axes of a box rotated by quaternion q (w, x, y, z). */
static void box_half_extent(const double q[4], const double size[3], double h[3])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; i++)
        h[i] = 0.5 * (fabs(m[i][0]) * size[0] + fabs(m[i][1]) * size[1] + fabs(m[i][2]) * size[2]);
}

/* Everything of the foot in scene: shapes, links, springs, the ankle. */
static void scene_extent(const fs_scene *s, box3 *b)
{
    grow(b, s->ankle, 0);
    for (int i = 0; i < s->nshapes; i++) {
        const fs_scene_shape *sh = &s->shape[i];
        if (sh->type == FS_SHAPE_SPHERE) {
            grow(b, sh->pos, sh->size[0]);
        } else {
            double h[3], lo[3], hi[3];
            box_half_extent(sh->quat, sh->size, h);
            for (int k = 0; k < 3; k++)
                lo[k] = sh->pos[k] - h[k], hi[k] = sh->pos[k] + h[k];
            grow(b, lo, 0);
            grow(b, hi, 0);
        }
    }
    for (int i = 0; i < s->nlinks; i++)
        grow(b, s->link[i].p1, 0), grow(b, s->link[i].p2, 0);
    for (int i = 0; i < s->nsprings; i++)
        grow(b, s->spring[i].p1, 0), grow(b, s->spring[i].p2, 0);
}

/* The robot's box, for the cameras that show it. */
static void robot_extent(const fs_scene *s, box3 *b)
{
    if (!s->has_robot)
        return;
    double h[3], lo[3], hi[3];
    box_half_extent(s->robot.quat, s->robot.size, h);
    for (int k = 0; k < 3; k++)
        lo[k] = s->robot.pos[k] - h[k], hi[k] = s->robot.pos[k] + h[k];
    grow(b, lo, 0);
    grow(b, hi, 0);
}

static box3 empty_box(void) { return (box3){{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}; }

/* ---- framing -------------------------------------------------------------------------------- */

/* The camera's right and up unit vectors for a viewing direction (eye minus target, unit). */
static void camera_axes(const double dir[3], double right[3], double up[3])
{
    double fwd[3] = {-dir[0], -dir[1], -dir[2]}, zup[3] = {0, 0, 1};
    cross3(right, fwd, zup);
    unit3(right);
    cross3(up, right, fwd);
}

void fs_render_view_fit(fs_render_view *v, fs_render_camera camera, const fs_scene *const *scenes, int n,
                        double aspect)
{
    box3 b = empty_box();
    for (int i = 0; i < n; i++) {
        scene_extent(scenes[i], &b);
        if (camera != FS_RENDER_FOOT)
            robot_extent(scenes[i], &b);
    }
    /* nothing (or a single point) to frame: a 10 cm box around it */
    if (!(b.lo[0] <= b.hi[0]))
        b = (box3){{-0.05, -0.05, 0}, {0.05, 0.05, 0.05}};
    else if (fmax(b.hi[0] - b.lo[0], fmax(b.hi[1] - b.lo[1], b.hi[2] - b.lo[2])) < 1e-6)
        for (int k = 0; k < 3; k++)
            b.lo[k] -= 0.05, b.hi[k] += 0.05;
    double az = placement[camera].azimuth_deg * M_PI / 180, el = placement[camera].elevation_deg * M_PI / 180;
    double dir[3] = {cos(el) * cos(az), cos(el) * sin(az), sin(el)}, right[3], up[3], centre[3];
    camera_axes(dir, right, up);
    for (int k = 0; k < 3; k++)
        centre[k] = 0.5 * (b.lo[k] + b.hi[k]);
    /* the extent's half width, half height and half depth as this camera sees it */
    double hw = 0, hh = 0, hd = 0;
    for (int c = 0; c < 8; c++) {
        double p[3] = {c & 1 ? b.hi[0] : b.lo[0], c & 2 ? b.hi[1] : b.lo[1], c & 4 ? b.hi[2] : b.lo[2]}, d[3];
        sub3(d, p, centre);
        hw = fmax(hw, fabs(dot3(d, right)));
        hh = fmax(hh, fabs(dot3(d, up)));
        hd = fmax(hd, fabs(dot3(d, dir)));
    }
    double ty = tan(FOVY_DEG * M_PI / 360), tx = ty * aspect;
    double dist = placement[camera].margin * fmax(hw / tx, hh / ty) + hd;
    dist = fmax(dist, 1e-3);
    *v = (fs_render_view){.camera = camera, .fovy_deg = FOVY_DEG, .aspect = aspect};
    for (int k = 0; k < 3; k++) {
        v->target[k] = centre[k];
        v->eye[k] = centre[k] + dist * dir[k];
        v->up[k] = up[k];
    }
    v->near_m = 0.05 * dist;
    v->far_m = 20 * dist;
}

void fs_render_view_follow(fs_render_view *v, const fs_scene *scene)
{
    if (v->camera != FS_RENDER_FOLLOW && v->camera != FS_RENDER_FOOT)
        return;
    box3 b = empty_box();
    scene_extent(scene, &b);
    if (!(b.lo[0] <= b.hi[0]))
        return;
    for (int k = 0; k < 3; k++) {
        double move = 0.5 * (b.lo[k] + b.hi[k]) - v->target[k];
        v->target[k] += move;
        v->eye[k] += move;
    }
}

/* ---- matrices and projection ---------------------------------------------------------------- */

void fs_render_view_matrices(const fs_render_view *v, double proj[16], double model[16])
{
    /* perspective, as gluPerspective */
    double f = 1 / tan(v->fovy_deg * M_PI / 360), n = v->near_m, fa = v->far_m;
    memset(proj, 0, 16 * sizeof *proj);
    proj[0] = f / v->aspect;
    proj[5] = f;
    proj[10] = (fa + n) / (n - fa);
    proj[11] = -1;
    proj[14] = 2 * fa * n / (n - fa);
    /* look-at, as gluLookAt */
    double fwd[3], side[3], up[3];
    sub3(fwd, v->target, v->eye);
    unit3(fwd);
    cross3(side, fwd, v->up);
    unit3(side);
    cross3(up, side, fwd);
    memset(model, 0, 16 * sizeof *model);
    for (int k = 0; k < 3; k++) {
        model[4 * k + 0] = side[k];
        model[4 * k + 1] = up[k];
        model[4 * k + 2] = -fwd[k];
    }
    model[12] = -dot3(side, v->eye);
    model[13] = -dot3(up, v->eye);
    model[14] = dot3(fwd, v->eye);
    model[15] = 1;
}

/* r = m p for a column-major 4 x 4 m and a homogeneous p. */
static void mat_apply(const double m[16], const double p[4], double r[4])
{
    for (int i = 0; i < 4; i++)
        r[i] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i] * p[3];
}

int fs_render_project(const fs_render_view *v, int w, int h, const double p[3], double px[2])
{
    double proj[16], model[16], world[4] = {p[0], p[1], p[2], 1}, eye[4], clip[4];
    fs_render_view_matrices(v, proj, model);
    mat_apply(model, world, eye);
    mat_apply(proj, eye, clip);
    if (clip[3] <= 0)
        return 0;
    px[0] = (clip[0] / clip[3] + 1) * 0.5 * w;
    px[1] = (1 - clip[1] / clip[3]) * 0.5 * h;
    return 1;
}

void fs_render_height_colour(double t, float rgb[3])
{
    static const float low[3] = {0.40f, 0.50f, 0.62f}, mid[3] = {0.62f, 0.64f, 0.58f}, high[3] = {0.88f, 0.70f, 0.42f};
    t = fmin(fmax(t, 0), 1);
    const float *a = t < 0.5 ? low : mid, *b = t < 0.5 ? mid : high;
    float u = (float)(t < 0.5 ? 2 * t : 2 * t - 1);
    for (int k = 0; k < 3; k++)
        rgb[k] = a[k] + u * (b[k] - a[k]);
}
