/* test_render_sim.c: fs_render_sim draws a simulation into the caller's buffer exactly as the
 * renderer's own calls draw its scene (same view, same pixels, rows top-down), framed on the first
 * frame and following after; a bad camera is refused. */
#include "fs_test.h"

#include "footsim/api/fs_api.h"
#include "footsim/render/fs_render.h"
#include "footsim/sim/fs_sim.h"

#include <stdlib.h>

enum { W = 96, H = 64 };

/* The frame rs drew into buf against the same scene drawn by fs_render's calls: every pixel. */
static int differing_pixels(const unsigned char *buf, const fs_sim *sim, fs_render_view *view, int first)
{
    fs_error err;
    fs_render *r;
    static fs_scene scene;
    if (fs_render_open(&r, W, H, &err) != FS_OK)
        return -1;
    fs_sim_scene(sim, &scene);
    const fs_scene *s = &scene;
    if (first)
        fs_render_view_fit(view, FS_RENDER_FOLLOW, &s, 1, (double)W / H);
    else
        fs_render_view_follow(view, &scene);
    fs_render_clear(r);
    fs_render_draw(r, view, &scene, 0, 0, W, H);
    int n = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            n += memcmp(buf + 4 * ((size_t)y * W + x), fs_render_pixel(r, x, y), 4) != 0;
    fs_render_close(r);
    return n;
}

static void draws_what_the_renderer_draws(void)
{
    fs_error err;
    fs_scenario *sc = fs_scenario_open("scenarios/landing_trial.ini", NULL, 0, &err);
    REQUIRE(sc);
    fs_sim *sim = fs_sim_open(sc, &err);
    REQUIRE(sim);
    fs_render_sim *rs = fs_render_sim_open(W, H, "follow", &err);
    if (!rs) { /* no OSMesa at run time: the renderer says so */
        printf("skipped: %s\n", err.message);
        fs_sim_close(sim);
        fs_scenario_close(sc);
        return;
    }
    unsigned char *buf = malloc(4 * W * H), *first = malloc(4 * W * H);
    REQUIRE(buf && first);
    fs_render_view view;
    fs_render_sim_draw(rs, sim, first);
    CHECK(differing_pixels(first, sim, &view, 1) == 0);
    int background = 0; /* something drawn on the background */
    for (int i = 0; i < W * H; i++)
        background += !memcmp(first + 4 * i, first + 4 * (W - 1), 3);
    CHECK(background > W * H / 20 && background < W * H * 19 / 20);
    REQUIRE(fs_sim_advance(sim, 400, &err) == FS_OK); /* fallen and touched down */
    fs_render_sim_draw(rs, sim, buf);
    CHECK(differing_pixels(buf, sim, &view, 0) == 0);
    CHECK(memcmp(buf, first, 4 * W * H) != 0);
    free(buf);
    free(first);
    fs_render_sim_close(rs);
    fs_sim_close(sim);
    fs_scenario_close(sc);
    CHECK(fs_render_sim_open(W, H, "above", &err) == NULL && err.status == FS_BAD_INPUT && strstr(err.message, "above"));
    CHECK(fs_render_sim_open(0, H, "side", &err) == NULL && err.status == FS_BAD_INPUT);
    fs_render_sim_close(NULL);
}

FS_TEST_MAIN(TEST(draws_what_the_renderer_draws))
