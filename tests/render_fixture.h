/* render_fixture.h: scenes built by hand for the renderer's tests (no simulation), and image
 * comparison with a tolerance. */
#ifndef FS_RENDER_FIXTURE_H
#define FS_RENDER_FIXTURE_H

#include "footsim/render/fs_render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double fixture_plane[4]; /* a flat ground as the core gives it: 2 x 2 heights, all 0 */

static inline void fixture_sphere(fs_scene *s, double x, double y, double z, double r, int body)
{
    s->shape[s->nshapes++] = (fs_scene_shape){FS_SHAPE_SPHERE, {r, 0, 0}, {x, y, z}, {1, 0, 0, 0}, body};
}

static inline void fixture_segment(fs_scene_segment *seg, double x1, double y1, double z1, double x2, double y2, double z2,
                            double force_N)
{
    *seg = (fs_scene_segment){{x1, y1, z1}, {x2, y2, z2}, force_N, 0, 0};
}

/* A foot-like scene of every kind of thing a frame shows: a heel sphere, a tilted talus box, three
 * toe spheres (one lifted 1 cm), links, springs in tension and compression, contacts with forces,
 * the load at the ankle; about 9 cm long, like footsim's foot. */
static inline void fixture_scene(fs_scene *s)
{
    memset(s, 0, sizeof *s);
    s->time_s = 0.125;
    s->scenario = "golden";
    s->foot = "fixture";
    s->terrain = "flat";
    s->ground = (fs_scene_ground){2, 2, -0.15, -0.15, 0.3, 0.3, fixture_plane, 1, NULL};
    fixture_sphere(s, 0, 0, 0.008, 0.008, 0);
    double h = 0.2588190451, c = 0.9659258263; /* 30 degrees about y: (cos 15, 0, sin 15, 0) */
    s->shape[s->nshapes++] = (fs_scene_shape){FS_SHAPE_BOX, {0.03, 0.04, 0.01}, {0.025, 0, 0.025}, {c, 0, h, 0}, 1};
    fixture_sphere(s, 0.085, 0.02, 0.006, 0.006, 2);
    fixture_sphere(s, 0.09, 0, 0.006, 0.006, 3);
    fixture_sphere(s, 0.085, -0.02, 0.016, 0.006, 4);
    double toe_y[3] = {0.02, 0, -0.02}, toe_z[3] = {0.005, 0.005, 0.015};
    for (int i = 0; i < 3; i++) {
        fixture_segment(&s->link[s->nlinks++], 0.04, toe_y[i] / 2, 0.02, 0.085 + (i == 1) * 0.005, toe_y[i], toe_z[i], 0);
        fixture_segment(&s->spring[s->nsprings++], 0.004, 0, 0.012, 0.08, toe_y[i], 0.006, i == 2 ? -40 : 80 - 30 * i);
    }
    fixture_segment(&s->link[s->nlinks++], 0.004, 0, 0.026, 0, 0, 0.008, 0);
    double cpos[3][3] = {{0, 0, 0}, {0.085, 0.02, 0}, {0.09, 0, 0}}, cf[3] = {150, 50, 40};
    for (int i = 0; i < 3; i++) {
        fs_scene_contact *ct = &s->contact[s->ncontacts++];
        memcpy(ct->pos, cpos[i], sizeof ct->pos);
        ct->force_N[0] = -0.1 * cf[i];
        ct->force_N[2] = cf[i];
    }
    double ankle[3] = {0.004, 0, 0.026}, load[3] = {0, 0, -240};
    memcpy(s->ankle, ankle, sizeof ankle);
    memcpy(s->load_N, load, sizeof load);
}

/* Pixels of two same-sized RGBA images whose largest channel difference exceeds tol, as a
 * fraction of all pixels. */
static inline double fixture_differ(const unsigned char *a, const unsigned char *b, int w, int h, int tol)
{
    long n = 0;
    for (long i = 0; i < (long)w * h; i++) {
        int worst = 0;
        for (int k = 0; k < 3; k++) {
            int d = abs(a[4 * i + k] - b[4 * i + k]);
            worst = d > worst ? d : worst;
        }
        n += worst > tol;
    }
    return (double)n / ((double)w * h);
}

/* A w x h renderer with s drawn in it, framed by camera on s itself (v gets the view); NULL when
 * no renderer can be opened. */
static inline fs_render *fixture_render(const fs_scene *s, fs_render_camera camera, int w, int h, fs_render_view *v)
{
    fs_render *r = NULL;
    fs_error err;
    if (fs_render_open(&r, w, h, &err) != FS_OK) {
        fprintf(stderr, "%s\n", err.message);
        return NULL;
    }
    const fs_scene *one = s;
    fs_render_view_fit(v, camera, &one, 1, (double)w / h);
    fs_render_draw(r, v, s, 0, 0, w, h);
    return r;
}

/* r's frame as top-down RGBA (into out, w * h * 4 bytes). */
static inline void fixture_copy(const fs_render *r, unsigned char *out)
{
    int w = fs_render_width(r), h = fs_render_height(r);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            memcpy(out + 4 * ((size_t)y * w + x), fs_render_pixel(r, x, y), 4);
}

#endif
