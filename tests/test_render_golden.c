/* test_render_golden.c: one fixed scene (built here, not simulated) seen by each camera matches
 * the picture committed in tests/golden/, within a tolerance that absorbs llvmpipe's rounding but
 * not a missing body. FS_GOLDEN_UPDATE=1 rewrites the pictures (look at them before committing).
 *
 * Tolerance: a pixel differs when a channel is off by more than 24 of 255 (rounding of lighting and
 * edge coverage moves a pixel by a few units; a missing or moved body changes it by far more);
 * the picture matches when at most 0.1 % of its pixels differ (77 pixels: a Mesa version may move a
 * few edge pixels; taking away any one body of the scene changes over 0.24 % in every view). */
#include "fs_test.h"
#include "render_fixture.h"

#include <stdio.h>

enum { W = 320, H = 240, PIXEL_TOL = 24 };
static const double MAX_DIFFERING = 0.001;

static unsigned char frame[W * H * 4];

/* The fixture as camera sees it, into frame. */
static void draw(fs_render *r, fs_render_camera camera, const fs_scene *s)
{
    fs_scene framed;
    fixture_scene(&framed); /* the view is framed on the whole fixture, whatever s lacks */
    const fs_scene *one = &framed;
    fs_render_view v;
    fs_render_view_fit(&v, camera, &one, 1, (double)W / H);
    fs_render_draw(r, &v, s, 0, 0, W, H);
    fixture_copy(r, frame);
}

static void golden_path(char *path, size_t size, int camera)
{
    snprintf(path, size, "%s/tests/golden/%s.png", FS_SOURCE_DIR, fs_render_camera_names[camera]);
}

/* Fraction of pixels that differ from the golden picture of camera (1 when it cannot be read). */
static double against_golden(int camera)
{
    char path[4096];
    golden_path(path, sizeof path, camera);
    unsigned char *gold;
    int w, h;
    fs_error err;
    if (fs_render_png_read(path, &gold, &w, &h, &err) != FS_OK || w != W || h != H) {
        fprintf(stderr, "%s\n", err.message);
        free(gold);
        return 1;
    }
    double d = fixture_differ(frame, gold, W, H, PIXEL_TOL);
    free(gold);
    return d;
}

static fs_render *open_renderer(void)
{
    fs_render *r = NULL;
    fs_error err;
    CHECK(fs_render_open(&r, W, H, &err) == FS_OK);
    return r;
}

/* Each camera's picture of the fixture matches its golden picture. */
static void test_golden_per_camera(void)
{
    fs_render *r = open_renderer();
    if (!r)
        return;
    fs_scene s;
    fixture_scene(&s);
    int update = getenv("FS_GOLDEN_UPDATE") != NULL;
    for (int c = 0; c < FS_RENDER_NCAMERAS; c++) {
        draw(r, (fs_render_camera)c, &s);
        if (update) {
            char path[4096];
            fs_error err;
            golden_path(path, sizeof path, c);
            CHECK(fs_render_png_write(path, frame, W, H, W * 4, 0, 9, &err) == FS_OK);
        }
        double d = against_golden(c);
        printf("  %-13s %.4f %% of pixels differ (allowed %.2f %%)\n", fs_render_camera_names[c], 100 * d,
               100 * MAX_DIFFERING);
        CHECK(d <= MAX_DIFFERING);
    }
    fs_render_close(r);
}

/* Without any one of its bodies (each shape in turn) the picture no longer matches, in every view. */
static void test_missing_body_fails(void)
{
    fs_render *r = open_renderer();
    if (!r)
        return;
    fs_scene full;
    fixture_scene(&full);
    for (int c = 0; c < FS_RENDER_NCAMERAS; c++) {
        double least = 1;
        for (int i = 0; i < full.nshapes; i++) {
            fs_scene s = full;
            s.shape[i] = s.shape[--s.nshapes];
            draw(r, (fs_render_camera)c, &s);
            double d = against_golden(c);
            least = d < least ? d : least;
            CHECK(d > MAX_DIFFERING);
        }
        printf("  %-13s without a body: at least %.3f %% of pixels differ\n", fs_render_camera_names[c], 100 * least);
    }
    fs_render_close(r);
}

FS_TEST_MAIN(TEST(test_golden_per_camera), TEST(test_missing_body_fails))
