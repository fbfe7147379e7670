/* cli_render_compare.c: `footsim render-compare SCENARIO_A SCENARIO_B`: both runs side by side in one
 * image sequence, and a filmstrip of key frames from touch-down to rest.
 *
 * Both scenarios run first, each keeping a snapshot per frame (taken once, before the first
 * step); the frames are drawn after, so the two sides show the same simulated time. A run that
 * ends first keeps showing its last state. Both rows of the filmstrip are taken at the same
 * simulated times (from the earlier touch-down to the later end), under a band with the colour
 * legend. */
#include "cli_frames.h"

#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { FILMSTRIP_FRAMES = 5 };

/* The snapshots of one run, and its ground (static during a run) copied once. */
typedef struct scene_store {
    fs_scene *scene;
    int n, cap;
    double *heights;
    const char *side; /* "A" or "B": said on each of its frames' halves and the filmstrip's rows */
} scene_store;

/* The observer: keeps a snapshot of the state now. */
static fs_status store_scene(void *user, const fs_sim *sim, fs_error *err)
{
    scene_store *st = user;
    if (st->n == st->cap)
        return FS_OK;
    fs_scene *s = &st->scene[st->n++];
    fs_sim_scene(sim, s);
    size_t nh = (size_t)s->ground.nx * (size_t)s->ground.ny;
    if (s->ground.sinkage && nh) { /* a soil's ground changes: each snapshot's own heights and sinkage */
        double *own = malloc(2 * nh * sizeof *own);
        if (!own)
            return fs_fail(err, FS_NO_MEMORY, "render-compare: out of memory for the soil's ground");
        memcpy(own, s->ground.heights, nh * sizeof *own);
        memcpy(own + nh, s->ground.sinkage, nh * sizeof *own);
        s->ground.heights = own, s->ground.sinkage = own + nh;
        return FS_OK;
    }
    if (!st->heights && nh) {
        st->heights = malloc(nh * sizeof *st->heights);
        if (!st->heights)
            return fs_fail(err, FS_NO_MEMORY, "render-compare: out of memory for the ground");
        memcpy(st->heights, s->ground.heights, nh * sizeof *st->heights);
    }
    s->ground.heights = st->heights;
    return FS_OK;
}

/* Takes room for both runs' snapshots (one every 1/fps simulated seconds), before either runs:
 * frames are bounded by memory, at most half of the machine's. */
static int reserve(const fs_scenario sc[2], double fps, scene_store st[2])
{
    double bytes = 0, frames[2];
    for (int k = 0; k < 2; k++) {
        const fs_scenario_def *d = &sc[k].def;
        double steps = ceil(d->duration_s / d->step_s), every = fmax(1, round(1 / (fps * d->step_s)));
        frames[k] = floor(steps / every) + 3;
        bytes += frames[k] * sizeof *st[k].scene;
    }
    double memory = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
    if (frames[0] > CLI_MAX_FRAMES || frames[1] > CLI_MAX_FRAMES || bytes > memory / 2)
        return cli_report(FS_BAD_INPUT, "render-compare: duration_s x --fps asks for too many frames to keep "
                                        "(over 999999, or over half of this machine's memory); lower --fps");
    for (int k = 0; k < 2; k++) {
        st[k].cap = (int)frames[k];
        st[k].scene = malloc((size_t)st[k].cap * sizeof *st[k].scene);
        if (!st[k].scene)
            return cli_report(FS_NO_MEMORY, "render-compare: out of memory for the frames; lower --fps");
    }
    return 0;
}

/* Runs sc, keeping a snapshot every 1/fps simulated seconds, in st (reserved). */
static int run_stored(const fs_scenario *sc, double fps, scene_store *st)
{
    fs_run_observer obs = {.interval_s = 1 / fps, .fn = store_scene, .user = st};
    fs_run_result res;
    fs_error err;
    fs_status s = fs_run(sc, &obs, &res, &err);
    fs_run_free(&res);
    return s == FS_OK ? 0 : cli_report(s, err.message);
}

static void store_free(scene_store *st)
{
    for (int i = 0; i < st->n; i++) /* a soil's snapshots own their ground */
        if (st->scene[i].ground.sinkage)
            free((double *)st->scene[i].ground.heights);
    free(st->scene);
    free(st->heights);
}

/* ---- drawing -------------------------------------------------------------------------------- */

/* The i-th snapshot, or the last when the run ended before. */
static const fs_scene *scene_at(const scene_store *st, int i) { return &st->scene[i < st->n ? i : st->n - 1]; }

/* Side k at snapshot i as drawn (--exaggerate), at (x0, y0), w x h, its view following its foot
 * for the cameras that follow; drawn: the caller's room for the scene (large: on the heap). */
static void draw_one(fs_render *r, const cli_frame_opts *o, fs_render_view *view, const scene_store *run, int i,
                     int x0, int y0, int w, int h, fs_scene *drawn)
{
    cli_frame_scene(o, &run->scene[0], scene_at(run, i), drawn);
    fs_render_view_follow(view, drawn);
    cli_frame_note(r, run->side, o->exaggerate); /* which row or half: A or B */
    fs_render_draw(r, view, drawn, x0, y0, w, h);
}

/* The same camera for both sides, framed on both first states. */
static void fit_pair(fs_render_view view[2], fs_render_camera camera, const scene_store run[2], int cw, int ch)
{
    const fs_scene *first[2] = {&run[0].scene[0], &run[1].scene[0]};
    fs_render_view_fit(&view[0], camera, first, 2, (double)cw / ch);
    view[1] = view[0];
}

static int write_frames(fs_render *r, const cli_frame_opts *o, const scene_store run[2], const char *frames_dir,
                        fs_scene *drawn)
{
    int cw = o->width / 2, n = run[0].n > run[1].n ? run[0].n : run[1].n;
    fs_render_view view[2];
    fit_pair(view, o->camera, run, cw, o->height);
    fs_render_clear(r);
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 2; k++)
            draw_one(r, o, &view[k], &run[k], i, k * cw, 0, cw, o->height, drawn);
        cli_frame_legend(r, 0, 0, o->width, o->height);
        fs_error err;
        if (cli_frames_write(r, frames_dir, i, &err) != FS_OK)
            return cli_report(err.status, err.message);
    }
    return 0;
}

/* The first snapshot with the foot on the ground (touch-down), or the first. */
static int touch_down(const scene_store *st)
{
    for (int i = 0; i < st->n; i++)
        if (st->scene[i].ncontacts > 0)
            return i;
    return 0;
}

/* The filmstrip's legend band under the two rows, pixels. */
static int legend_band(int ch) { return ch >= 96 ? 16 * (int)fmax(1, ch / 480) : 0; }

/* FILMSTRIP_FRAMES columns at the same simulated times in both rows, from the earlier touch-down
 * to the later end; A above, B below, the legend under them. */
static int write_filmstrip(fs_render *r, const cli_frame_opts *o, const scene_store run[2], const char *dir, int ch,
                           fs_scene *drawn)
{
    int cw = fs_render_width(r) / FILMSTRIP_FRAMES;
    fs_render_view view[2];
    fit_pair(view, o->camera, run, cw, ch);
    fs_render_clear(r);
    int d0 = touch_down(&run[0]), d1 = touch_down(&run[1]);
    int t0 = d0 < d1 ? d0 : d1, t1 = (run[0].n > run[1].n ? run[0].n : run[1].n) - 1;
    for (int c = 0; c < FILMSTRIP_FRAMES; c++) {
        int i = t0 + (int)lround((double)c * (t1 - t0) / (FILMSTRIP_FRAMES - 1));
        for (int k = 0; k < 2; k++)
            draw_one(r, o, &view[k], &run[k], i, c * cw, k * ch, cw, ch, drawn);
    }
    int band = fs_render_height(r) - 2 * ch;
    if (band > 0)
        fs_render_legend(r, 0, 2 * ch, fs_render_width(r), band);
    char path[CLI_FRAMES_PATH + 16];
    snprintf(path, sizeof path, "%s/filmstrip.png", dir);
    fs_error err;
    if (fs_render_write_png(r, path, 6, &err) != FS_OK)
        return cli_report(err.status, err.message);
    return 0;
}

/* ---- the command ---------------------------------------------------------------------------- */

/* --set a:KEY=V goes to A only, b:KEY=V to B only, KEY=V to both. */
static void split_sets(const cli_args *a, const char *sets[2][CLI_MAX_SET], int nsets[2])
{
    nsets[0] = nsets[1] = 0;
    for (int i = 0; i < a->nset; i++) {
        const char *s = a->set[i];
        int only = (s[0] == 'a' || s[0] == 'b') && s[1] == ':' ? s[0] - 'a' : -1;
        for (int k = 0; k < 2; k++)
            if (only < 0 || only == k)
                sets[k][nsets[k]++] = only < 0 ? s : s + 2;
    }
}

static const char *foot_name(const fs_scenario *sc) { return sc->geom.kind == FS_FOOT_FLAT ? "flat" : "biomimetic"; }

/* Loads both scenarios and works out DIR (default results/compare/A-foot_vs_B-foot). */
static int load_pair(const cli_args *a, fs_scenario sc[2], char *dir, size_t size)
{
    const char *sets[2][CLI_MAX_SET]; /* 4 KiB of pointers into a->set */
    int nsets[2];
    split_sets(a, sets, nsets);
    const char *input[2] = {a->input, a->input2};
    for (int k = 0; k < 2; k++) {
        fs_error err;
        if (fs_scenario_load(input[k], sets[k], nsets[k], &sc[k], &err) != FS_OK ||
            fs_scenario_require(&sc[k], "run", &err) != FS_OK)
            return cli_report(err.status, err.message);
    }
    int n = a->out ? snprintf(dir, size, "%s", a->out)
                   : snprintf(dir, size, "results/compare/%s-%s_vs_%s-%s", sc[0].name, foot_name(&sc[0]), sc[1].name,
                              foot_name(&sc[1]));
    if (n >= (int)size)
        return cli_report(FS_BAD_INPUT, "--out: path too long");
    return 0;
}

/* Checks the frame options against both runs and opens the frame and filmstrip renderers. */
static int prepare(const cli_args *a, const fs_scenario sc[2], const char *dir, cli_frame_opts *o, char *frames_dir,
                   fs_render *r[2])
{
    int s = cli_frame_opts_parse(a, fmax(sc[0].def.step_s, sc[1].def.step_s), 2, o);
    if (!s)
        s = cli_frames_folder(dir, frames_dir, CLI_FRAMES_PATH);
    if (!s)
        s = cli_render_open(&r[0], o->width, o->height, o->exaggerate);
    /* the filmstrip's cells are a quarter of a frame's width and half its height: a side's shape */
    int cw = o->width / 4 > 0 ? o->width / 4 : 1, ch = o->height / 2 > 0 ? o->height / 2 : 1;
    if (!s)
        s = cli_render_open(&r[1], FILMSTRIP_FRAMES * cw, 2 * ch + legend_band(ch), o->exaggerate);
    return s;
}

/* What render-compare works on, too large for the stack: on the heap, one per command. */
typedef struct compare_work {
    fs_scenario sc[2];
    char dir[CLI_FRAMES_PATH], frames_dir[CLI_FRAMES_PATH];
    fs_outdir out;
    fs_scene drawn; /* the frame being drawn */
} compare_work;

int cli_render_compare(const cli_args *a)
{
    if (!a->input2)
        return cli_report(FS_BAD_INPUT, "render-compare: give two scenario files, SCENARIO_A SCENARIO_B "
                                        "(the same file twice with --set b:foot.kind=flat compares the feet)");
    compare_work *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    fs_scenario *sc = w->sc;
    char *dir = w->dir, *frames_dir = w->frames_dir;
    fs_outdir *out = &w->out;
    fs_error err;
    cli_frame_opts o;
    fs_render *r[2] = {NULL, NULL};
    scene_store run[2] = {{.side = "A"}, {.side = "B"}};
    int s = load_pair(a, sc, dir, sizeof w->dir);
    /* the folder must be one footsim may replace before anything is simulated; everything goes to
     * a partial folder beside it, swapped in whole at the end: a failure leaves the old one */
    if (!s && fs_outdir_open(out, dir, a->replace, "--out", &err) != FS_OK)
        s = cli_report(err.status, err.message);
    if (!s)
        s = prepare(a, sc, out->partial, &o, frames_dir, r);
    if (!s)
        s = reserve(sc, o.fps, run);
    for (int k = 0; k < 2 && !s; k++)
        s = run_stored(&sc[k], o.fps, &run[k]);
    if (!s)
        s = write_frames(r[0], &o, run, frames_dir, &w->drawn);
    if (!s)
        s = write_filmstrip(r[1], &o, run, out->partial, o.height / 2 > 0 ? o.height / 2 : 1, &w->drawn);
    if (!s && o.video)
        s = cli_frames_video(out->partial, frames_dir, o.fps, run[0].n > run[1].n ? run[0].n : run[1].n, dir);
    if (!s && fs_outdir_commit(out, &err) != FS_OK)
        s = cli_report(err.status, err.message);
    if (!s) {
        int n = run[0].n > run[1].n ? run[0].n : run[1].n;
        printf("render-compare: %s (%s foot, left) beside %s (%s foot, right)\n  frames: %s/frames/000000.png ... %06d.png "
               "(%d at %g per simulated second, %dx%d, camera %s)\n  filmstrip: %s/filmstrip.png\n",
               sc[0].name, foot_name(&sc[0]), sc[1].name, foot_name(&sc[1]), out->path, n - 1, n, o.fps, o.width,
               o.height, fs_render_camera_names[o.camera], out->path);
    }
    fs_outdir_abort(out); /* when it was not committed */
    for (int k = 0; k < 2; k++) {
        fs_render_close(r[k]);
        store_free(&run[k]);
        fs_scenario_free(&sc[k]);
    }
    free(w);
    return s;
}
