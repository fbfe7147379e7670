/* render_gl.c: the OSMesa context and the drawing of a scene with fixed-function GL. */
#include "render_internal.h"

#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Checker squares on the ground, m: a scale the eye can read off. */
static const double CHECKER_M = 0.01;
static const float BACKGROUND[3] = {0.86f, 0.88f, 0.91f};
static const float LINK_RGB[3] = {0.30f, 0.32f, 0.38f};
static const float JOINT_RGB[3] = {0.95f, 0.95f, 0.95f};
static const float ANKLE_RGB[3] = {0.85f, 0.10f, 0.75f};
static const float CONTACT_RGB[3] = {1.0f, 0.78f, 0.0f};
static const float FORCE_RGB[3] = {0.05f, 0.62f, 0.18f};
static const float ROBOT_RGBA[4] = {0.30f, 0.42f, 0.62f, 0.16f};
static const float TENSION_RGB[3] = {0.90f, 0.10f, 0.08f}, COMPRESSION_RGB[3] = {0.10f, 0.30f, 0.95f};
/* Links are drawn as round bars of this radius, m (the foot's links are a few mm wide). */
static const double LINK_RADIUS_M = 0.0009;
/* The bodies' colours, by body index. */
static const float BODY_RGB[][3] = {{0.80f, 0.62f, 0.45f}, {0.72f, 0.52f, 0.38f}, {0.86f, 0.70f, 0.52f},
                                    {0.76f, 0.58f, 0.42f}, {0.90f, 0.76f, 0.58f}};

/* ---- context and meshes --------------------------------------------------------------------- */

/* A unit sphere as quad strips between latitudes, normals equal to positions. */
static void emit_sphere(int slices, int stacks)
{
    for (int i = 0; i < stacks; i++) {
        double a0 = M_PI * ((double)i / stacks - 0.5), a1 = M_PI * ((double)(i + 1) / stacks - 0.5);
        gl.Begin(GL_QUAD_STRIP);
        for (int j = 0; j <= slices; j++) {
            double b = 2 * M_PI * j / slices;
            for (int k = 1; k >= 0; k--) {
                double a = k ? a1 : a0, p[3] = {cos(a) * cos(b), cos(a) * sin(b), sin(a)};
                gl.Normal3dv(p);
                gl.Vertex3dv(p);
            }
        }
        gl.End();
    }
}

/* A unit cylinder about z (radius 1, z from 0 to 1), its side only. */
static void emit_cylinder(int slices)
{
    gl.Begin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; j++) {
        double b = 2 * M_PI * j / slices, c = cos(b), s = sin(b);
        gl.Normal3d(c, s, 0);
        gl.Vertex3d(c, s, 1);
        gl.Vertex3d(c, s, 0);
    }
    gl.End();
}

/* A unit cube centred on the origin, one normal per face. */
static void emit_cube(void)
{
    static const int face[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    static const double normal[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    gl.Begin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        gl.Normal3dv(normal[f]);
        for (int v = 0; v < 4; v++) {
            int c = face[f][v];
            gl.Vertex3d(c & 1 ? 0.5 : -0.5, c & 2 ? 0.5 : -0.5, c & 4 ? 0.5 : -0.5);
        }
    }
    gl.End();
}

fs_status fs_render_open(fs_render **out, int width, int height, fs_error *err)
{
    *out = NULL;
    if (width < 1 || height < 1 || width > FS_RENDER_MAX_SIZE || height > FS_RENDER_MAX_SIZE)
        return fs_fail(err, FS_BAD_INPUT, "frame size %dx%d; allowed: WxH with each from 1 to %d", width, height,
                       FS_RENDER_MAX_SIZE);
    if (fs_render_gl_load(err) != FS_OK)
        return FS_BAD_INPUT;
    fs_render *r = calloc(1, sizeof *r);
    if (r)
        r->rgba = malloc((size_t)width * (size_t)height * 4);
    if (!r || !r->rgba) {
        free(r);
        return fs_fail(err, FS_NO_MEMORY, "frame size %dx%d: out of memory for the frame", width, height);
    }
    r->w = width, r->h = height;
    /* RGBA, 24-bit depth, 8-bit stencil (for shadows), no accumulation buffer */
    r->ctx = gl.CreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!r->ctx || !gl.MakeCurrent(r->ctx, r->rgba, GL_UNSIGNED_BYTE, width, height)) {
        fs_render_close(r);
        return fs_fail(err, FS_BAD_INPUT, "OSMesa could not make a %dx%d drawing context; install libosmesa6 "
                       "(apt-get install libosmesa6) or run without --frames", width, height);
    }
    r->sphere = gl.GenLists(3);
    r->cube = r->sphere + 1;
    r->cylinder = r->sphere + 2;
    gl.NewList(r->sphere, GL_COMPILE);
    emit_sphere(24, 14);
    gl.EndList();
    gl.NewList(r->cube, GL_COMPILE);
    emit_cube();
    gl.EndList();
    gl.NewList(r->cylinder, GL_COMPILE);
    emit_cylinder(12);
    gl.EndList();
    *out = r;
    return FS_OK;
}

void fs_render_close(fs_render *r)
{
    if (!r)
        return;
    /* released first, so that Mesa frees the frame's buffers with the context */
    if (r->ctx && gl.GetCurrentContext() == r->ctx)
        gl.MakeCurrent(NULL, NULL, 0, 0, 0);
    if (r->ctx)
        gl.DestroyContext(r->ctx);
    free(r->rgba);
    free(r);
}

int fs_render_width(const fs_render *r) { return r->w; }
int fs_render_height(const fs_render *r) { return r->h; }

const unsigned char *fs_render_pixel(const fs_render *r, int x, int y)
{
    return r->rgba + ((size_t)(r->h - 1 - y) * r->w + x) * 4;
}

void fs_render_clear(fs_render *r)
{
    render_make_current(r);
    gl.Disable(GL_SCISSOR_TEST);
    gl.Viewport(0, 0, r->w, r->h);
    gl.ClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* ---- the ground ----------------------------------------------------------------------------- */

/* A value of the grid's samples val (its heights, or a soil's sinkage) at (x, y), bilinear, clamped to
 * the grid; 0 when there is no grid. */
static double grid_value(const fs_scene_ground *g, const double *val, double x, double y)
{
    if (!val || g->nx < 1 || g->ny < 1)
        return 0;
    double u = g->dx > 0 ? (x - g->x0) / g->dx : 0, v = g->dy > 0 ? (y - g->y0) / g->dy : 0;
    u = fmin(fmax(u, 0), g->nx - 1);
    v = fmin(fmax(v, 0), g->ny - 1);
    int i = (int)fmin(floor(u), g->nx - 2 < 0 ? 0 : g->nx - 2), j = (int)fmin(floor(v), g->ny - 2 < 0 ? 0 : g->ny - 2);
    int i1 = i + 1 < g->nx ? i + 1 : i, j1 = j + 1 < g->ny ? j + 1 : j;
    double fu = u - i, fv = v - j;
    const double *z = val;
    return (1 - fv) * ((1 - fu) * z[j * g->nx + i] + fu * z[j * g->nx + i1]) +
           fv * ((1 - fu) * z[j1 * g->nx + i] + fu * z[j1 * g->nx + i1]);
}

static double ground_height(const fs_scene_ground *g, double x, double y) { return grid_value(g, g->heights, x, y); }

/* A soil's sinkage scale, m: the deepest sinkage drawn rounded up to 1, 2 or 5 times a power of
 * ten, at least 1 mm; 0 on rigid ground. */
static double sinkage_scale(const fs_scene_ground *g)
{
    if (!g->sinkage)
        return 0;
    double deepest = 0;
    for (long k = 0; k < (long)g->nx * g->ny; k++)
        deepest = fmax(deepest, g->sinkage[k]);
    double p = pow(10, floor(log10(fmax(deepest, 1e-3)))), scale = 10 * p;
    for (int k = 2; k >= 0; k--) {
        const double m[3] = {1, 2, 5};
        if (m[k] * p >= deepest)
            scale = m[k] * p;
    }
    return scale;
}

/* The colour of a sinkage a fraction t (0 to 1) of the scale: pale sand through orange to a deep
 * red-violet. */
static void sinkage_colour(double t, float rgb[3])
{
    static const float ramp[3][3] = {{0.98f, 0.90f, 0.55f}, {0.93f, 0.50f, 0.16f}, {0.42f, 0.08f, 0.32f}};
    t = fmin(fmax(t, 0), 1);
    int a = t < 0.5 ? 0 : 1;
    float u = (float)(t < 0.5 ? 2 * t : 2 * t - 1);
    for (int k = 0; k < 3; k++)
        rgb[k] = ramp[a][k] + u * (ramp[a + 1][k] - ramp[a][k]);
}

/* One vertex of the ground mesh: normal from the local slope, colour from the height, or on a soil
 * from the sinkage where there is any (scale smax, sinkage_scale). */
static void ground_vertex(const fs_scene_ground *g, double x, double y, double zlo, double zspan, double shade,
                          double smax)
{
    double e = 0.25 * fmin(g->dx, g->dy), z = ground_height(g, x, y);
    double sx = (ground_height(g, x + e, y) - ground_height(g, x - e, y)) / (2 * e);
    double sy = (ground_height(g, x, y + e) - ground_height(g, x, y - e)) / (2 * e);
    float rgb[3];
    fs_render_height_colour(zspan > 1e-12 ? (z - zlo) / zspan : 0.5, rgb);
    if (smax > 0) { /* blended in over the first 1/20 of the scale: the print's edge stays soft */
        double t = grid_value(g, g->sinkage, x, y) / smax, w = fmin(1, 20 * t);
        float c[3];
        sinkage_colour(t, c);
        for (int k = 0; k < 3 && w > 0; k++)
            rgb[k] = (float)((1 - w) * rgb[k] + w * c[k]);
    }
    gl.Color3f((float)(rgb[0] * shade), (float)(rgb[1] * shade), (float)(rgb[2] * shade));
    gl.Normal3d(-sx, -sy, 1);
    gl.Vertex3d(x, y, z);
}

/* The height grid as lit quads, subdivided to checker squares (bilinear inside each cell). */
static void draw_ground(const fs_scene_ground *g)
{
    if (!g->heights || g->nx < 2 || g->ny < 2 || !(g->dx > 0) || !(g->dy > 0))
        return;
    double zlo = INFINITY, zhi = -INFINITY;
    for (int k = 0; k < g->nx * g->ny; k++)
        zlo = fmin(zlo, g->heights[k]), zhi = fmax(zhi, g->heights[k]);
    double w = g->dx * (g->nx - 1), d = g->dy * (g->ny - 1);
    int nu = (int)fmin(ceil(w / CHECKER_M), 1024), nv = (int)fmin(ceil(d / CHECKER_M), 1024);
    nu = nu > g->nx - 1 ? nu : g->nx - 1;
    nv = nv > g->ny - 1 ? nv : g->ny - 1;
    double su = w / nu, sv = d / nv, smax = sinkage_scale(g);
    gl.Begin(GL_QUADS);
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            double x = g->x0 + i * su, y = g->y0 + j * sv;
            long cx = lround(floor((x + 0.5 * su) / CHECKER_M)), cy = lround(floor((y + 0.5 * sv) / CHECKER_M));
            double shade = (cx + cy) % 2 ? 0.9 : 1.0;
            ground_vertex(g, x, y, zlo, zhi - zlo, shade, smax);
            ground_vertex(g, x + su, y, zlo, zhi - zlo, shade, smax);
            ground_vertex(g, x + su, y + sv, zlo, zhi - zlo, shade, smax);
            ground_vertex(g, x, y + sv, zlo, zhi - zlo, shade, smax);
        }
    gl.End();
}

/* ---- the foot's shapes and their shadows ---------------------------------------------------- */

/* Moves GL's current matrix to shape's pose (box: rotated, scaled to its edges; sphere: scaled). */
static void shape_transform(const fs_scene_shape *s)
{
    double w = s->quat[0], x = s->quat[1], y = s->quat[2], z = s->quat[3];
    double m[16] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 0,
                    2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 0,
                    2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y), 0,
                    s->pos[0], s->pos[1], s->pos[2], 1};
    gl.MultMatrixd(m);
    if (s->type == FS_SHAPE_SPHERE)
        gl.Scaled(s->size[0], s->size[0], s->size[0]);
    else
        gl.Scaled(s->size[0], s->size[1], s->size[2]);
}

static void draw_shape_mesh(const fs_render *r, const fs_scene_shape *s)
{
    gl.PushMatrix();
    shape_transform(s);
    gl.CallList(s->type == FS_SHAPE_SPHERE ? r->sphere : r->cube);
    gl.PopMatrix();
}

static void draw_shapes(const fs_render *r, const fs_scene *scene)
{
    int ncol = (int)(sizeof BODY_RGB / sizeof BODY_RGB[0]);
    for (int i = 0; i < scene->nshapes; i++) {
        const fs_scene_shape *s = &scene->shape[i];
        const float *c = BODY_RGB[(s->body % ncol + ncol) % ncol];
        gl.Color3fv(c);
        draw_shape_mesh(r, s);
    }
}

/* Each shape flattened straight down onto the ground under it, darker the closer it is: the
 * stencil keeps overlapping shadows from darkening twice. */
static void draw_shadows(const fs_render *r, const fs_scene *scene)
{
    gl.Disable(GL_LIGHTING);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(-2, -4);
    gl.Enable(GL_STENCIL_TEST);
    gl.StencilFunc(GL_EQUAL, 0, 0xff);
    gl.StencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    for (int i = 0; i < scene->nshapes; i++) {
        const fs_scene_shape *s = &scene->shape[i];
        double zg = ground_height(&scene->ground, s->pos[0], s->pos[1]);
        double size = s->type == FS_SHAPE_SPHERE ? s->size[0] : 0.5 * fmin(s->size[0], fmin(s->size[1], s->size[2]));
        double above = fmax(s->pos[2] - size - zg, 0);
        gl.Color4f(0.05f, 0.05f, 0.08f, (float)(0.55 * exp(-above / (3 * size + 1e-9))));
        gl.PushMatrix();
        gl.Translated(0, 0, zg);
        gl.Scaled(1, 1, 0);
        draw_shape_mesh(r, s);
        gl.PopMatrix();
    }
    gl.Disable(GL_STENCIL_TEST);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.DepthMask(GL_TRUE);
    gl.Disable(GL_BLEND);
}

/* ---- lines: links, springs, forces ---------------------------------------------------------- */

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

static void line(const double a[3], const double b[3])
{
    gl.Vertex3dv(a);
    gl.Vertex3dv(b);
}

/* An arrow from tail to tip with a head in the plane that faces the camera. */
static void arrow(const fs_render_view *v, const double tail[3], const double tip[3])
{
    double d[3], view[3], side[3], len = 0;
    for (int k = 0; k < 3; k++)
        d[k] = tip[k] - tail[k], view[k] = v->eye[k] - tip[k], len += d[k] * d[k];
    len = sqrt(len);
    if (len <= 0)
        return;
    side[0] = d[1] * view[2] - d[2] * view[1];
    side[1] = d[2] * view[0] - d[0] * view[2];
    side[2] = d[0] * view[1] - d[1] * view[0];
    double sn = sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
    line(tail, tip);
    if (sn <= 0)
        return;
    for (int s = -1; s <= 1; s += 2) {
        double h[3];
        for (int k = 0; k < 3; k++)
            h[k] = tip[k] - 0.25 * d[k] + s * 0.12 * len * side[k] / sn;
        line(tip, h);
    }
}

/* Spring colour: grey when slack, toward red in tension and blue in compression. */
static void spring_colour(double force_N, double ref_N)
{
    static const float slack[3] = {0.55f, 0.55f, 0.55f};
    const float *tension = TENSION_RGB, *compression = COMPRESSION_RGB;
    float t = (float)fmin(fabs(force_N) / (ref_N > 0 ? ref_N : 1), 1);
    const float *to = force_N >= 0 ? tension : compression;
    gl.Color3f(slack[0] + t * (to[0] - slack[0]), slack[1] + t * (to[1] - slack[1]), slack[2] + t * (to[2] - slack[2]));
}

/* A round bar of radius rad from a to b (lit). */
static void draw_bar(const fs_render *r, const double a[3], const double b[3], double rad)
{
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, len = norm3(d);
    if (!(len > 0))
        return;
    double z[3] = {d[0] / len, d[1] / len, d[2] / len}, x[3], y[3];
    /* any unit x across z, y = z x x */
    double pick[3] = {fabs(z[0]) < 0.9 ? 1 : 0, fabs(z[0]) < 0.9 ? 0 : 1, 0};
    x[0] = pick[1] * z[2] - pick[2] * z[1], x[1] = pick[2] * z[0] - pick[0] * z[2], x[2] = pick[0] * z[1] - pick[1] * z[0];
    double xn = norm3(x);
    for (int k = 0; k < 3; k++)
        x[k] /= xn;
    y[0] = z[1] * x[2] - z[2] * x[1], y[1] = z[2] * x[0] - z[0] * x[2], y[2] = z[0] * x[1] - z[1] * x[0];
    double m[16] = {rad * x[0], rad * x[1], rad * x[2], 0, rad * y[0], rad * y[1], rad * y[2], 0,
                    d[0], d[1], d[2], 0, a[0], a[1], a[2], 1};
    gl.PushMatrix();
    gl.MultMatrixd(m);
    gl.CallList(r->cylinder);
    gl.PopMatrix();
}

/* The links as solid bars, lit. */
static void draw_links(const fs_render *r, const fs_scene *scene)
{
    gl.Enable(GL_LIGHTING);
    gl.Color3fv(LINK_RGB);
    for (int i = 0; i < scene->nlinks; i++)
        draw_bar(r, scene->link[i].p1, scene->link[i].p2, LINK_RADIUS_M);
}

/* The robot's box, translucent, over everything else: the foot shows through. */
static void draw_robot(const fs_render *r, const fs_scene *scene)
{
    if (!scene->has_robot)
        return;
    gl.Enable(GL_LIGHTING);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.DepthMask(GL_FALSE);
    gl.Color4f(ROBOT_RGBA[0], ROBOT_RGBA[1], ROBOT_RGBA[2], ROBOT_RGBA[3]);
    draw_shape_mesh(r, &scene->robot);
    gl.DepthMask(GL_TRUE);
    gl.Disable(GL_BLEND);
}

/* Joints, springs, contacts with their ground-force arrows, and the load at the ankle. */
static void draw_lines(fs_render *r, const fs_render_view *v, const fs_scene *scene, double view_h_m, float lw)
{
    gl.Disable(GL_LIGHTING);
    gl.LineWidth(2.5f * lw);
    for (int i = 0; i < scene->nsprings; i++)
        r->spring_ref_N = fmax(r->spring_ref_N, fabs(scene->spring[i].force_N));
    gl.Begin(GL_LINES);
    for (int i = 0; i < scene->nsprings; i++) {
        spring_colour(scene->spring[i].force_N, r->spring_ref_N);
        line(scene->spring[i].p1, scene->spring[i].p2);
    }
    gl.End();
    /* forces: the largest contact force seen is drawn a sixth of the viewport's height long */
    for (int i = 0; i < scene->ncontacts; i++)
        r->contact_ref_N = fmax(r->contact_ref_N, norm3(scene->contact[i].force_N));
    double per_N = r->contact_ref_N > 0 ? view_h_m / 6 / r->contact_ref_N : 0;
    gl.LineWidth(lw);
    gl.Color3fv(FORCE_RGB);
    gl.Begin(GL_LINES);
    for (int i = 0; i < scene->ncontacts; i++) {
        const fs_scene_contact *c = &scene->contact[i];
        double tip[3] = {c->pos[0] + per_N * c->force_N[0], c->pos[1] + per_N * c->force_N[1],
                         c->pos[2] + per_N * c->force_N[2]};
        arrow(v, c->pos, tip);
    }
    /* the load: an arrow a twelfth of the viewport's height long, ending at the ankle */
    double load = norm3(scene->load_N);
    gl.Color3fv(ANKLE_RGB);
    if (load > 0) {
        double tail[3];
        for (int k = 0; k < 3; k++)
            tail[k] = scene->ankle[k] - view_h_m / 12 * scene->load_N[k] / load;
        arrow(v, tail, scene->ankle);
    }
    gl.End();
    /* points: joints, contacts, the ankle */
    gl.PointSize(2.5f * lw);
    gl.Begin(GL_POINTS);
    gl.Color3fv(JOINT_RGB);
    for (int i = 0; i < scene->nlinks; i++)
        gl.Vertex3dv(scene->link[i].p1);
    gl.Color3fv(CONTACT_RGB);
    for (int i = 0; i < scene->ncontacts; i++)
        gl.Vertex3dv(scene->contact[i].pos);
    gl.End();
    /* the ankle, where the load acts, on top of everything */
    gl.Disable(GL_DEPTH_TEST);
    gl.PointSize(3.5f * lw);
    gl.Begin(GL_POINTS);
    gl.Color3fv(ANKLE_RGB);
    gl.Vertex3dv(scene->ankle);
    gl.End();
    gl.Enable(GL_DEPTH_TEST);
}

/* ---- a frame -------------------------------------------------------------------------------- */

/* Light from above, ahead and to the right (the side the cameras see), fixed in the world; a soft
 * ambient. */
static void set_lighting(void)
{
    static const float dir[4] = {0.35f, -0.45f, 0.82f, 0}, diffuse[4] = {0.75f, 0.75f, 0.72f, 1},
                       ambient[4] = {0.38f, 0.38f, 0.42f, 1};
    gl.Lightfv(GL_LIGHT0, GL_POSITION, dir);
    gl.Lightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    gl.LightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    gl.Enable(GL_LIGHT0);
    gl.Enable(GL_LIGHTING);
    gl.Enable(GL_COLOR_MATERIAL);
    gl.ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    gl.Enable(GL_NORMALIZE);
    gl.ShadeModel(GL_SMOOTH);
}

/* Text scale for a viewport: 1 up to 720 px tall (or 1280 wide), then a step per 360 px. */
static int text_scale(int w, int h) { return (int)fmax(1, fmin(h / 360, w / 640)); }

/* Time, the note, then what is drawn: the design file, the terrain, the robot (when there is one)
 * and the scenario, one line along the viewport's top on a thin strip. */
static void draw_overlay(fs_render *r, const fs_scene *scene, int x0, int y0, int w, int h)
{
    static const unsigned char white[3] = {255, 255, 255};
    int scale = text_scale(w, h);
    char text[512];
    /* the note (the seed, the outcome, an exaggeration) before the names: cut off last on a narrow tile */
    snprintf(text, sizeof text, "T %.3f S  %s%s%s  ON %s%s%s  (%s)", scene->time_s, r->note, r->note[0] ? "  " : "",
             scene->design[0] ? scene->design : scene->foot ? scene->foot : "-", scene->terrain ? scene->terrain : "-",
             scene->robot_file[0] ? "  UNDER " : "", scene->robot_file, scene->scenario ? scene->scenario : "-");
    int pad = 2 * scale, fit = (w - 2 * pad) / (6 * scale);
    if (fit >= 0 && (size_t)fit < strlen(text))
        text[fit] = 0; /* cut at the tile's edge, not into its neighbour */
    int bw = (int)strlen(text) * 6 * scale + 2 * pad - scale, bh = 7 * scale + 2 * pad;
    fs_render_shade_box(r, x0, y0, bw < w ? bw : w, bh < h ? bh : h, 0.45);
    fs_render_text_gl(r, x0 + pad, y0 + pad, scale, text, white);
}

/* On a soil: the sinkage colour scale, in mm, at the right under the top strip. */
static void draw_sinkage_legend(fs_render *r, const fs_scene_ground *g, int x0, int y0, int w, int h)
{
    static const unsigned char ink[3] = {20, 20, 24};
    double smax = sinkage_scale(g);
    if (!(smax > 0))
        return;
    int scale = text_scale(w, h), cells = 20, cw = 4 * scale, bh = 6 * scale, pad = 2 * scale;
    char lo[32] = "SINKAGE 0", hi[32];
    snprintf(hi, sizeof hi, "%g MM", smax * 1e3);
    int tw = (int)(strlen(lo) + strlen(hi) + 2) * 6 * scale, bw = cells * cw + tw + 2 * pad;
    int bx = x0 + w - bw - 4 * scale, by = y0 + 7 * scale + 2 * pad + 4 * scale;
    if (bx < x0 || by + bh + 2 * pad > y0 + h)
        return;
    fs_render_shade_box(r, bx, by, bw, bh + 2 * pad, 0.85);
    int x = bx + pad + fs_render_text_gl(r, bx + pad, by + pad, scale, lo, ink) + 3 * scale;
    for (int k = 0; k < cells; k++) {
        float c[3];
        sinkage_colour((k + 0.5) / cells, c);
        fs_render_fill_box(r, x + k * cw, by + pad, cw, bh, c);
    }
    fs_render_text_gl(r, x + cells * cw + 3 * scale, by + pad, scale, hi, ink);
}

/* A bar of a round length (1, 2 or 5 times a power of ten, mm) about a fifth of the viewport wide
 * at the camera's target, labelled, in the bottom-left corner. */
static void draw_scale_bar(fs_render *r, int x0, int y0, int w, int h, double view_h_m)
{
    static const unsigned char ink[3] = {20, 20, 24};
    static const float bar[3] = {0.08f, 0.08f, 0.10f};
    if (!(view_h_m > 0))
        return;
    double px_per_m = h / view_h_m, want_m = 0.2 * w / px_per_m, p = pow(10, floor(log10(want_m))), len_m = p;
    for (int k = 0; k < 3; k++) {
        double m[3] = {1, 2, 5};
        if (m[k] * p <= want_m)
            len_m = m[k] * p;
    }
    int scale = text_scale(w, h), len = (int)lround(len_m * px_per_m), th = 2 * scale;
    int bx = x0 + 4 * scale, by = y0 + h - 6 * scale - th;
    if (len < 2 || len > w)
        return;
    char label[32];
    snprintf(label, sizeof label, "%g MM", len_m * 1e3);
    fs_render_fill_box(r, bx, by, len, th, bar);
    fs_render_fill_box(r, bx, by - 3 * scale, scale, 3 * scale, bar);
    fs_render_fill_box(r, bx + len - scale, by - 3 * scale, scale, 3 * scale, bar);
    fs_render_text_gl(r, bx + len + 3 * scale, by - 5 * scale, scale, label, ink);
}

int fs_render_legend(fs_render *r, int x0, int y0, int w, int h)
{
    static const unsigned char ink[3] = {20, 20, 24};
    static const char *const words[4] = {"SPRING TENSION", "COMPRESSION", "CONTACT FORCE", "LOAD"};
    const float *colour[4] = {TENSION_RGB, COMPRESSION_RGB, FORCE_RGB, ANKLE_RGB};
    int scale = (int)fmax(1, fmin(h / 12, w / 340)), x = x0 + 3 * scale, cy = y0 + h / 2;
    for (int i = 0; i < 4; i++) {
        int sw = 8 * scale;
        fs_render_fill_box(r, x, cy - 2 * scale, sw, 4 * scale, colour[i]);
        x += sw + 3 * scale;
        x += fs_render_text_gl(r, x, cy - 3 * scale - scale / 2, scale, words[i], ink) + 5 * scale;
    }
    gl.Finish();
    return x - x0;
}

void fs_render_set_note(fs_render *r, const char *note)
{
    snprintf(r->note, sizeof r->note, "%s", note ? note : "");
}

void fs_render_draw(fs_render *r, const fs_render_view *v, const fs_scene *scene, int x0, int y0, int w, int h)
{
    render_make_current(r);
    int gy = r->h - y0 - h;
    gl.Viewport(x0, gy, w, h);
    gl.Scissor(x0, gy, w, h);
    gl.Enable(GL_SCISSOR_TEST);
    gl.ClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    double proj[16], model[16];
    fs_render_view_matrices(v, proj, model);
    gl.MatrixMode(GL_PROJECTION);
    gl.LoadMatrixd(proj);
    gl.MatrixMode(GL_MODELVIEW);
    gl.LoadMatrixd(model);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    set_lighting();
    draw_ground(&scene->ground);
    draw_shadows(r, scene);
    gl.Enable(GL_LIGHTING);
    draw_shapes(r, scene);
    draw_links(r, scene);
    /* the viewport's height in metres at the target, for sizes given as a part of the picture */
    double dx = v->eye[0] - v->target[0], dy = v->eye[1] - v->target[1], dz = v->eye[2] - v->target[2];
    double view_h_m = 2 * sqrt(dx * dx + dy * dy + dz * dz) * tan(v->fovy_deg * M_PI / 360);
    draw_lines(r, v, scene, view_h_m, (float)fmax(1, h / 360.0));
    draw_robot(r, scene);
    gl.Disable(GL_SCISSOR_TEST);
    draw_overlay(r, scene, x0, y0, w, h);
    draw_sinkage_legend(r, &scene->ground, x0, y0, w, h);
    draw_scale_bar(r, x0, y0, w, h, view_h_m);
    gl.Finish();
}
