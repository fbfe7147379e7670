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
    fs_sim *sim;
    static fs_scene s, empty;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_new(&sc, NULL, &sim, &err) == FS_OK);
    fs_sim_scene(sim, &s);
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
    fs_sim_free(sim);
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
    s.ground = (fs_scene_ground){N, N, -0.15, -0.15, 0.01, 0.01, z, 0, NULL};
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

/* The foot's own extent (shapes, links, springs, the ankle), as the frame commands see it. */
static void foot_box(const fs_scene *s, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = hi[k] = s->ankle[k];
    for (int i = 0; i < s->nshapes; i++)
        for (int k = 0; k < 3; k++) {
            double r = s->shape[i].type == FS_SHAPE_SPHERE ? s->shape[i].size[0] : 0.5 * s->shape[i].size[k];
            lo[k] = fmin(lo[k], s->shape[i].pos[k] - r), hi[k] = fmax(hi[k], s->shape[i].pos[k] + r);
        }
    const fs_scene_segment *seg[2] = {s->link, s->spring};
    int n[2] = {s->nlinks, s->nsprings};
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < n[j]; i++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], fmin(seg[j][i].p1[k], seg[j][i].p2[k]));
                hi[k] = fmax(hi[k], fmax(seg[j][i].p1[k], seg[j][i].p2[k]));
            }
}

/* The fraction of the picture's width and height the box's projected corners span; 0 when a
 * corner falls outside the picture. */
static double box_span(const fs_render_view *v, int w, int h, const double lo[3], const double hi[3])
{
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int c = 0; c < 8; c++) {
        double p[3] = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}, px[2];
        if (!fs_render_project(v, w, h, p, px) || px[0] < 0 || px[0] > w || px[1] < 0 || px[1] > h)
            return 0;
        x0 = fmin(x0, px[0]), x1 = fmax(x1, px[0]), y0 = fmin(y0, px[1]), y1 = fmax(y1, px[1]);
    }
    return fmax((x1 - x0) / w, (y1 - y0) / h);
}

/* The foot camera frames the real foot of a landing trial (a 26 kg robot 0.3 m up on it): every
 * corner of the foot's bounding box inside the picture and the box filling most of its width or
 * height (the camera leaves 8 % room, and perspective a little more: over 70 %), where the side
 * camera, which shows the robot too, leaves the foot under a third of that. */
static void test_foot_camera(void)
{
    static fs_scenario sc;
    fs_sim *sim;
    static fs_scene s;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/landing_trial.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_new(&sc, NULL, &sim, &err) == FS_OK);
    fs_sim_scene(sim, &s);
    CHECK(s.has_robot);
    double lo[3], hi[3];
    foot_box(&s, lo, hi);
    const fs_scene *one = &s;
    fs_render_view foot, side;
    fs_render_view_fit(&foot, FS_RENDER_FOOT, &one, 1, 16.0 / 9);
    fs_render_view_fit(&side, FS_RENDER_SIDE, &one, 1, 16.0 / 9);
    double fspan = box_span(&foot, 640, 360, lo, hi), sspan = box_span(&side, 640, 360, lo, hi);
    printf("  the foot spans %.0f %% of the foot camera's frame, %.0f %% of the side camera's\n", 100 * fspan,
           100 * sspan);
    CHECK(fspan > 0.7 && fspan <= 1);
    CHECK(sspan > 0 && sspan < fspan / 3);
    /* it follows the foot: moved 5 cm, the foot is framed the same */
    fs_scene moved = s;
    for (int i = 0; i < moved.nshapes; i++)
        moved.shape[i].pos[0] += 0.05;
    for (int i = 0; i < moved.nlinks; i++)
        moved.link[i].p1[0] += 0.05, moved.link[i].p2[0] += 0.05;
    for (int i = 0; i < moved.nsprings; i++)
        moved.spring[i].p1[0] += 0.05, moved.spring[i].p2[0] += 0.05;
    moved.ankle[0] += 0.05;
    fs_render_view follow = foot;
    fs_render_view_follow(&follow, &moved);
    CHECK_NEAR(follow.target[0] - foot.target[0], 0.05, 1e-12);
    CHECK_NEAR(follow.eye[0] - foot.eye[0], 0.05, 1e-12);
    fs_sim_free(sim);
}

/* v rotated by the inverse of unit quaternion q (w, x, y, z): into the frame q turns into the world. */
static void unrotate(const double q[4], const double v[3], double r[3])
{
    double w = q[0], x = -q[1], y = -q[2], z = -q[3];
    double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for (int i = 0; i < 3; i++)
        r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

/* Body b's centre in the ankle body's frame. */
static void in_ankle_frame(const fs_scene *s, int b, double d[3])
{
    const fs_scene_pose *a = &s->body[s->ankle_body];
    double v[3] = {s->body[b].pos[0] - a->pos[0], s->body[b].pos[1] - a->pos[1], s->body[b].pos[2] - a->pos[2]};
    unrotate(a->quat, v, d);
}

/* The deformation view on the static load: the neutral pose maps to itself whatever the factor, a
 * factor of 1 changes nothing, and with F = 20 every body's centre is displaced in the ankle
 * body's frame by 20 times its true displacement (to rounding: 1e-12 m), the ankle body stays (to 1e-12 m),
 * and each shape keeps its distance from its body's centre (bodies move rigidly). */
static void test_exaggerate(void)
{
    static fs_scenario sc;
    fs_sim *sim;
    static fs_scene neutral, now, out;
    fs_error err;
    REQUIRE(fs_scenario_load("scenarios/static_load.ini", NULL, 0, &sc, &err) == FS_OK);
    REQUIRE(fs_sim_new(&sc, NULL, &sim, &err) == FS_OK);
    fs_sim_scene(sim, &neutral);
    REQUIRE(neutral.nbodies > 2);
    fs_render_exaggerate(&neutral, &neutral, 20, &out);
    double worst = 0;
    for (int i = 0; i < out.nshapes; i++)
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fabs(out.shape[i].pos[k] - neutral.shape[i].pos[k]));
    for (int i = 0; i < out.nsprings; i++)
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fmax(fabs(out.spring[i].p1[k] - neutral.spring[i].p1[k]),
                                     fabs(out.spring[i].p2[k] - neutral.spring[i].p2[k])));
    CHECK(worst < 1e-12);
    for (int i = 0; i < 1500; i++) /* 0.15 s: the load ramped in, the arch folding */
        REQUIRE(fs_sim_step(sim, &err) == FS_OK);
    fs_sim_scene(sim, &now);
    fs_render_exaggerate(&neutral, &now, 1, &out);
    CHECK(!memcmp(&out, &now, sizeof out));
    const double F = 20;
    fs_render_exaggerate(&neutral, &now, F, &out);
    double largest = 0, err_m = 0;
    for (int b = 0; b < now.nbodies; b++) {
        double d0[3], dn[3], de[3];
        in_ankle_frame(&neutral, b, d0);
        in_ankle_frame(&now, b, dn);
        in_ankle_frame(&out, b, de);
        for (int k = 0; k < 3; k++) {
            largest = fmax(largest, fabs(dn[k] - d0[k]));
            err_m = fmax(err_m, fabs((de[k] - d0[k]) - F * (dn[k] - d0[k])));
        }
    }
    printf("  largest true displacement %.3g m, exaggerated x%g to within %.2g m\n", largest, F, err_m);
    CHECK(largest > 1e-5); /* there is something to exaggerate */
    CHECK(err_m < 1e-12);
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(out.body[now.ankle_body].pos[k], now.body[now.ankle_body].pos[k], 1e-12);
    double rigid = 0;
    for (int i = 0; i < now.nshapes; i++) {
        int b = now.shape[i].body;
        double dn = 0, de = 0;
        for (int k = 0; k < 3; k++) {
            dn += pow(now.shape[i].pos[k] - now.body[b].pos[k], 2);
            de += pow(out.shape[i].pos[k] - out.body[b].pos[k], 2);
        }
        rigid = fmax(rigid, fabs(sqrt(dn) - sqrt(de)));
    }
    CHECK(rigid < 1e-12);
    fs_sim_free(sim);
}

/* The rightmost column of the header's white text (the top 9 rows: 2 px of padding, 7 of text at
 * scale 1), or -1. */
static int header_end(const fs_render *r)
{
    int w = fs_render_width(r), end = -1;
    for (int y = 0; y < 9; y++)
        for (int x = 0; x < w; x++) {
            const unsigned char *p = fs_render_pixel(r, x, y);
            if (p[0] > 230 && p[1] > 230 && p[2] > 230 && x > end)
                end = x;
        }
    return end;
}

/* The header says what is drawn: with a design, a robot and a note (the seed and outcome, as a
 * trial's last frame has) it runs as many characters further as it has more (6 px each at scale
 * 1, within one character for the last glyph's own width), where without them it names the foot's
 * kind alone. */
static void test_header_says_what_is_drawn(void)
{
    int ends[2];
    size_t chars[2];
    for (int k = 0; k < 2; k++) {
        fs_scene s;
        fixture_scene(&s);
        const char *note = k ? "SEED 3  LANDED (RESTED)" : "";
        if (k) {
            snprintf(s.design, sizeof s.design, "biomimetic");
            snprintf(s.robot_file, sizeof s.robot_file, "single_tall");
        }
        char text[256];
        snprintf(text, sizeof text, "T %.3f S  %s%s%s  ON %s%s%s  (%s)", s.time_s, note, note[0] ? "  " : "",
                 k ? s.design : s.foot, s.terrain, k ? "  UNDER " : "", s.robot_file, s.scenario);
        chars[k] = strlen(text);
        fs_render *r = NULL;
        fs_error err;
        REQUIRE(fs_render_open(&r, 640, 360, &err) == FS_OK);
        fs_render_set_note(r, note);
        fs_render_view v;
        const fs_scene *one = &s;
        fs_render_view_fit(&v, FS_RENDER_THREE_QUARTER, &one, 1, 640.0 / 360);
        fs_render_draw(r, &v, &s, 0, 0, 640, 360);
        ends[k] = header_end(r);
        fs_render_close(r);
    }
    CHECK(ends[0] > 0);
    CHECK_NEAR(ends[1] - ends[0], 6.0 * (double)(chars[1] - chars[0]), 6.0);
}

FS_TEST_MAIN(TEST(test_size_and_not_blank), TEST(test_header_says_what_is_drawn), TEST(test_size_refused), TEST(test_projection),
             TEST(test_projection_geometry), TEST(test_terrain_band), TEST(test_foot_camera), TEST(test_exaggerate))
