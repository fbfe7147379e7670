/* test_render_draw.c: frames have the asked size and content; the foot appears where the camera's
 * projection puts it; the ground's height colours show a raised band. */
#include "fs_test.h"
#include "render_fixture.h"

#include "footsim/sim/fs_sim.h"

#include <stdio.h>
#include <unistd.h>

/* Largest channel difference between two RGBA pixels. */
static int pixel_diff(const unsigned char *a, const unsigned char *b)
{
    int worst = 0;
    for (int k = 0; k < 3; k++)
        worst = abs(a[k] - b[k]) > worst ? abs(a[k] - b[k]) : worst;
    return worst;
}

/* The index of the shape whose centre is nearest eye. */
static int nearest_shape(const fs_scene *s, const double eye[3])
{
    int best = 0;
    double best_d = INFINITY;
    for (int i = 0; i < s->nshapes; i++) {
        double d = 0;
        for (int k = 0; k < 3; k++)
            d += (s->shape[i].pos[k] - eye[k]) * (s->shape[i].pos[k] - eye[k]);
        if (d < best_d)
            best_d = d, best = i;
    }
    return best;
}

/* A frame of an odd size, written and read back: that size, and far from a single colour. */
static void test_size_and_not_blank(void)
{
    fs_scene s;
    fixture_scene(&s);
    fs_render_view v;
    fs_render *r = fixture_render(&s, FS_RENDER_THREE_QUARTER, 97, 61, &v);
    CHECK(r != NULL);
    if (!r)
        return;
    fs_error err;
    char path[64];
    snprintf(path, sizeof path, "/tmp/footsim_test_render_%ld.png", (long)getpid());
    CHECK(fs_render_write_png(r, path, 1, &err) == FS_OK);
    unsigned char *img;
    int w = 0, h = 0;
    REQUIRE(fs_render_png_read(path, &img, &w, &h, &err) == FS_OK);
    remove(path);
    CHECK(w == 97 && h == 61);
    /* not blank: many pixels far from the top-left (background) one */
    long far = 0;
    for (long i = 0; img && i < (long)w * h; i++)
        far += pixel_diff(img + 4 * i, img) > 40;
    CHECK(far > w * h / 4);
    free(img);
    fs_render_close(r);
}

/* Sizes outside 1 to 8192 are refused. */
static void test_size_refused(void)
{
    fs_render *r = NULL;
    fs_error err;
    CHECK(fs_render_open(&r, 0, 10, &err) == FS_BAD_INPUT && !r);
    CHECK(fs_render_open(&r, 10, FS_RENDER_MAX_SIZE + 1, &err) == FS_BAD_INPUT && !r);
    CHECK(strstr(err.message, "allowed: WxH") != NULL);
}

/* The ankle (drawn as a marker, always on top) and the nearest shape are where fs_render_project
 * says, on the real foot at t = 0, in every view; the same frame without the foot differs at the
 * ankle and not 12 mm above it. */
static void test_projection(void)
{
    static fs_scenario sc;
    static fs_sim sim;
    static fs_scene s, empty;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_build(&sim, &sc, NULL, &err) == FS_OK);
    fs_sim_scene(&sim, &s);
    empty = s;
    empty.nshapes = empty.nlinks = empty.nsprings = empty.ncontacts = 0;
    empty.ankle[2] = -1; /* the marker under the ground, out of sight */
    const int w = 320, h = 240;
    fs_render *r;
    CHECK(fs_render_open(&r, w, h, &err) == FS_OK);
    if (!r)
        return;
    static unsigned char with[320 * 240 * 4], without[320 * 240 * 4];
    for (int cam = 0; cam < FS_RENDER_NCAMERAS; cam++) {
        fs_render_view v;
        const fs_scene *one = &s;
        fs_render_view_fit(&v, (fs_render_camera)cam, &one, 1, (double)w / h);
        fs_render_draw(r, &v, &s, 0, 0, w, h);
        fixture_copy(r, with);
        fs_render_draw(r, &v, &empty, 0, 0, w, h);
        fixture_copy(r, without);
        double px[2], above[3] = {s.ankle[0], s.ankle[1], s.ankle[2] + 0.012}, qx[2];
        CHECK(fs_render_project(&v, w, h, s.ankle, px));
        CHECK(fs_render_project(&v, w, h, above, qx));
        int x = (int)px[0], y = (int)px[1], ax = (int)qx[0], ay = (int)qx[1];
        CHECK(x >= 0 && x < w && y >= 0 && y < h && ax >= 0 && ax < w && ay >= 0 && ay < h);
        if (x < 0 || x >= w || y < 0 || y >= h || ax < 0 || ax >= w || ay < 0 || ay >= h)
            continue;
        /* the ankle marker's magenta at the projected pixel */
        const unsigned char *p = with + 4 * ((size_t)y * w + x);
        CHECK(p[0] > 150 && p[1] < 80 && p[2] > 130);
        CHECK(pixel_diff(p, without + 4 * ((size_t)y * w + x)) > 60);
        /* 12 mm above the ankle (the top of the foot) nothing is drawn */
        CHECK(pixel_diff(with + 4 * ((size_t)ay * w + ax), without + 4 * ((size_t)ay * w + ax)) <= 2);
        /* the shape nearest the camera shows a body's warm colour around its projected centre */
        CHECK(fs_render_project(&v, w, h, s.shape[nearest_shape(&s, v.eye)].pos, px));
        int warm = 0;
        for (int j = -2; j <= 2; j++)
            for (int i = -2; i <= 2; i++) {
                const unsigned char *q = with + 4 * ((size_t)((int)px[1] + j) * w + (int)px[0] + i);
                warm += q[0] > q[2] + 30;
            }
        CHECK(warm >= 13);
    }
    fs_render_close(r);
    fs_sim_destroy(&sim);
}

/* The projection puts the view's target in the middle of the picture and x forward to the right
 * in the side view. */
static void test_projection_geometry(void)
{
    fs_scene s;
    fixture_scene(&s);
    fs_render_view v;
    const fs_scene *one = &s;
    fs_render_view_fit(&v, FS_RENDER_SIDE, &one, 1, 4.0 / 3);
    double px[2], ahead[3] = {v.target[0] + 0.01, v.target[1], v.target[2]}, qx[2];
    CHECK(fs_render_project(&v, 400, 300, v.target, px));
    CHECK_NEAR(px[0], 200, 1e-9);
    CHECK_NEAR(px[1], 150, 1e-9);
    CHECK(fs_render_project(&v, 400, 300, ahead, qx) && qx[0] > px[0] + 1);
    double behind[3];
    for (int k = 0; k < 3; k++)
        behind[k] = 2 * v.eye[k] - v.target[k];
    CHECK(!fs_render_project(&v, 400, 300, behind, qx));
}

/* A ground 5 mm higher on a band x in [0.03, 0.06] m: sand-coloured there, bluish grey elsewhere. */
static void test_terrain_band(void)
{
    enum { N = 31 };
    static double z[N * N];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double x = -0.15 + 0.01 * i;
            z[j * N + i] = x > 0.025 && x < 0.065 ? 0.005 : 0;
        }
    fs_scene s;
    memset(&s, 0, sizeof s);
    s.ground = (fs_scene_ground){N, N, -0.15, -0.15, 0.01, 0.01, z, 0};
    /* two small spheres at opposite corners frame a 15 cm x 10 cm patch across the band */
    fixture_sphere(&s, -0.03, 0.05, 0.005, 0.005, 0);
    fixture_sphere(&s, 0.12, -0.05, 0.005, 0.005, 0);
    s.ankle[0] = 0.045, s.ankle[2] = -1;
    fs_render_view v;
    fs_render *r = fixture_render(&s, FS_RENDER_THREE_QUARTER, 320, 240, &v);
    CHECK(r != NULL);
    if (!r)
        return;
    double on[3] = {0.045, 0, 0.005}, off[3] = {-0.01, 0, 0}, px[2], qx[2];
    CHECK(fs_render_project(&v, 320, 240, on, px) && fs_render_project(&v, 320, 240, off, qx));
    int inside = px[0] >= 0 && px[0] < 320 && px[1] >= 0 && px[1] < 240 && qx[0] >= 0 && qx[0] < 320 && qx[1] >= 0 &&
                 qx[1] < 240;
    CHECK(inside);
    if (!inside)
        px[0] = px[1] = qx[0] = qx[1] = 0;
    const unsigned char *p = fs_render_pixel(r, (int)px[0], (int)px[1]), *q = fs_render_pixel(r, (int)qx[0], (int)qx[1]);
    CHECK(p[0] > p[2] + 40);
    CHECK(q[2] > q[0] + 20);
    fs_render_close(r);
}

FS_TEST_MAIN(TEST(test_size_and_not_blank), TEST(test_size_refused), TEST(test_projection),
             TEST(test_projection_geometry), TEST(test_terrain_band))
