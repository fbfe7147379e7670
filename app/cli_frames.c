/* cli_frames.c: `footsim run --frames`: the frame options, a frame drawn at each observation of
 * the run, and the video (the renderer's side of cli.h's cli_frames_open / cli_frames_close). */
#include "cli_frames.h"

#include "footsim/io/fs_config.h"
#include "footsim/io/fs_output.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/sim/fs_sim.h"

#include <errno.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

/* ---- options -------------------------------------------------------------------------------- */

static int parse_size(const char *text, int min_w, int *w, int *h)
{
    char *end;
    long lw = strtol(text, &end, 10), lh = -1;
    if (end != text && (*end == 'x' || *end == 'X')) {
        const char *hs = end + 1;
        lh = strtol(hs, &end, 10);
        if (end == hs || *end)
            lh = -1;
    }
    if (lw < min_w || lw > FS_RENDER_MAX_SIZE || lh < 1 || lh > FS_RENDER_MAX_SIZE) {
        fprintf(stderr, "footsim: --size %s: not a frame size; allowed: WxH with W from %d and H from 1, each to %d\n",
                text, min_w, FS_RENDER_MAX_SIZE);
        return FS_BAD_INPUT;
    }
    *w = (int)lw, *h = (int)lh;
    return 0;
}

static int parse_fps(const char *text, double step_s, double *fps)
{
    double v = 0;
    if (fs_parse_number(text, &v) != FS_NUMBER_OK || v < 1 || v > 10000 || v * step_s > 1 + 1e-9) {
        fprintf(stderr, "footsim: --fps %s: not a frame rate; allowed: frames per simulated second from 1 to %g "
                        "(one frame per step of %g s at most)\n", text, fmin(10000, 1 / step_s), step_s);
        return FS_BAD_INPUT;
    }
    *fps = v;
    return 0;
}

static int parse_exaggerate(const char *text, double *factor)
{
    double v = 0;
    if (fs_parse_number(text, &v) != FS_NUMBER_OK || !(v >= 1) || v > 10000) {
        fprintf(stderr, "footsim: --exaggerate %s: not a factor; allowed: a number from 1 (true size) to 10000\n",
                text);
        return FS_BAD_INPUT;
    }
    *factor = v;
    return 0;
}

int cli_frame_opts_parse(const cli_args *a, double step_s, int min_w, cli_frame_opts *o)
{
    *o = (cli_frame_opts){1280, 720, 60, FS_RENDER_FOOT, a->video, 1};
    if (a->exaggerate && parse_exaggerate(a->exaggerate, &o->exaggerate))
        return FS_BAD_INPUT;
    if (a->size && parse_size(a->size, min_w, &o->width, &o->height))
        return FS_BAD_INPUT;
    if (a->fps && parse_fps(a->fps, step_s, &o->fps))
        return FS_BAD_INPUT;
    if (a->camera) {
        int c = fs_render_camera_find(a->camera);
        if (c < 0) {
            fprintf(stderr, "footsim: --camera %s: unknown camera; allowed: foot, side, front, three-quarter, "
                            "follow\n", a->camera);
            return FS_BAD_INPUT;
        }
        o->camera = (fs_render_camera)c;
    }
    return 0;
}

/* ---- the folder and the files --------------------------------------------------------------- */

int cli_frames_folder(const char *dir, char *frames_dir, size_t size)
{
    fs_error err;
    if (snprintf(frames_dir, size, "%s/frames", dir) >= (int)size)
        return cli_report(FS_BAD_INPUT, "--out: path too long");
    /* dir is a fresh partial folder (fs_outdir_open): no earlier run's frames can mix in */
    if (fs_make_dirs(frames_dir, &err) != FS_OK)
        return cli_report(err.status, err.message);
    return 0;
}

fs_status cli_frames_write(const fs_render *r, const char *frames_dir, int index, fs_error *err)
{
    char path[CLI_FRAMES_PATH + 16];
    snprintf(path, sizeof path, "%s/%06d.png", frames_dir, index);
    return fs_render_write_png(r, path, CLI_PNG_LEVEL, err);
}

int cli_render_open(fs_render **r, int w, int h, double exaggerate)
{
    fs_error err;
    if (fs_render_open(r, w, h, &err) != FS_OK)
        return cli_report(err.status, err.message);
    cli_frame_note(*r, "", exaggerate);
    return 0;
}

void cli_frame_note(fs_render *r, const char *label, double exaggerate)
{
    char note[128];
    if (exaggerate != 1)
        snprintf(note, sizeof note, "%.80s%sDISPLACEMENTS X%g", label, label[0] ? "  " : "", exaggerate);
    else
        snprintf(note, sizeof note, "%.80s", label);
    fs_render_set_note(r, note);
}

void cli_frame_legend(fs_render *r, int x0, int y0, int w, int h)
{
    /* the legend in the bottom-right corner, when the frame is wide enough to keep it off the
     * scale bar (bottom-left) */
    int lh = 12 * (int)fmax(1, fmin(h / 360, w / 640)), lw = 340 * lh / 12;
    if (w >= lw + w / 3)
        fs_render_legend(r, x0 + w - lw, y0 + h - lh - 2, lw, lh);
}

void cli_frame_scene(const cli_frame_opts *o, const fs_scene *neutral, const fs_scene *now, fs_scene *out)
{
    fs_render_exaggerate(neutral, now, o->exaggerate, out);
}

/* ---- video ---------------------------------------------------------------------------------- */

/* Runs argv, waiting for it; its exit status, 127 when it could not be started. */
static int run_program(char *const argv[])
{
    pid_t pid;
    if (posix_spawnp(&pid, argv[0], NULL, NULL, argv, environ) != 0)
        return 127;
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return 126;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 126;
}

int cli_frames_video(const char *dir, const char *frames_dir, double fps, int nframes, const char *shown_dir)
{
    char input[CLI_FRAMES_PATH + 16], path[CLI_FRAMES_PATH + 16], temp[CLI_FRAMES_PATH + 64], rate[32], count[32];
    snprintf(input, sizeof input, "%s/%%06d.png", frames_dir);
    snprintf(path, sizeof path, "%s/video.mp4", dir);
    snprintf(temp, sizeof temp, "%s/video.tmp.%ld.mp4", dir, (long)getpid());
    snprintf(rate, sizeof rate, "%.9g", fps);
    snprintf(count, sizeof count, "%d", nframes);
    /* H.264 wants even sizes: pad by a pixel when odd */
    char *argv[] = {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", rate, "-i", input,
                    "-frames:v", count, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264",
                    "-pix_fmt", "yuv420p", temp, NULL};
    int s = run_program(argv);
    if (s == 127) {
        printf("  video: not made: ffmpeg is not installed (apt-get install ffmpeg); the frames are in %s/frames/\n",
               shown_dir);
        return 0;
    }
    fs_error err;
    if (s != 0) {
        remove(temp);
        fprintf(stderr, "footsim: %s: ffmpeg could not encode the frames (status %d); the frames are in %s/\n", path,
                s, frames_dir);
        return FS_IO;
    }
    /* ffmpeg may end well having written part of it (a full disk): an MP4 starts with its ftyp box */
    char head[8] = {0};
    FILE *f = fopen(temp, "rb");
    int whole = f && fread(head, 1, sizeof head, f) == sizeof head && !memcmp(head + 4, "ftyp", 4);
    if (f)
        fclose(f);
    if (!whole) {
        remove(temp);
        fprintf(stderr, "footsim: %s: ffmpeg's video came out damaged; nothing was installed\n", path);
        return FS_IO;
    }
    if (fs_commit_temp(temp, path, &err) != FS_OK)
        return cli_report(err.status, err.message);
    printf("  video: %s/video.mp4\n", shown_dir);
    return 0;
}

/* ---- run --frames --------------------------------------------------------------------------- */

struct cli_frames {
    fs_render *r;
    cli_frame_opts o;
    fs_render_view view;
    char dir[CLI_FRAMES_PATH], frames_dir[CLI_FRAMES_PATH];
    int n;           /* frames written */
    int flat;        /* 1: the frames straight in dir (cli_frames_open_at) */
    fs_scene scene;  /* the snapshot, reused for each frame */
    fs_scene neutral;/* the first snapshot: the pose --exaggerate measures displacements from */
    fs_scene drawn;  /* the snapshot as drawn (exaggerated) */
    double *heights; /* the drawn ground's heights (and a soil's sinkage), its own copy: the last frame is drawn again
                        (cli_frames_finish) after the sim and scenario that owned them are gone */
    size_t nheights;
    char scenario[256], terrain[256]; /* the drawn names, likewise its own copies */
};

/* The snapshot as drawn, from the view, with the legend, written as frame index. */
static fs_status draw_drawn(cli_frames *f, int index, fs_error *err)
{
    fs_render_draw(f->r, &f->view, &f->drawn, 0, 0, f->o.width, f->o.height);
    cli_frame_legend(f->r, 0, 0, f->o.width, f->o.height);
    return cli_frames_write(f->r, f->frames_dir, index, err);
}

/* The observer: one frame of the state now, framed on the first. */
static fs_status draw_frame(void *user, const fs_sim *sim, fs_error *err)
{
    cli_frames *f = user;
    fs_sim_scene(sim, &f->scene);
    if (f->n == 0)
        f->neutral = f->scene;
    cli_frame_scene(&f->o, &f->neutral, &f->scene, &f->drawn);
    size_t n = (size_t)f->drawn.ground.nx * (size_t)f->drawn.ground.ny, m = f->drawn.ground.sinkage ? 2 * n : n;
    if (f->drawn.ground.heights && n) { /* the heights, and a soil's sinkage after them */
        if (m > f->nheights) {
            double *grown = realloc(f->heights, m * sizeof *grown);
            if (!grown)
                return fs_fail(err, FS_NO_MEMORY, "out of memory for a frame's ground");
            f->heights = grown, f->nheights = m;
        }
        memcpy(f->heights, f->drawn.ground.heights, n * sizeof *f->heights);
        f->drawn.ground.heights = f->heights;
        if (f->drawn.ground.sinkage) {
            memcpy(f->heights + n, f->drawn.ground.sinkage, n * sizeof *f->heights);
            f->drawn.ground.sinkage = f->heights + n;
        }
    }
    snprintf(f->scenario, sizeof f->scenario, "%s", f->drawn.scenario ? f->drawn.scenario : "-");
    snprintf(f->terrain, sizeof f->terrain, "%s", f->drawn.terrain ? f->drawn.terrain : "-");
    f->drawn.scenario = f->scenario, f->drawn.terrain = f->terrain;
    const fs_scene *first = &f->drawn;
    if (f->n == 0)
        fs_render_view_fit(&f->view, f->o.camera, &first, 1, (double)f->o.width / f->o.height);
    else
        fs_render_view_follow(&f->view, &f->drawn);
    return draw_drawn(f, f->n++, err);
}

void cli_frames_label(cli_frames *f, const char *label)
{
    if (f)
        cli_frame_note(f->r, label, f->o.exaggerate);
}

int cli_frames_finish(cli_frames *f, const char *label)
{
    if (!f || f->n == 0)
        return 0;
    cli_frames_label(f, label);
    fs_error err;
    return draw_drawn(f, f->n - 1, &err) == FS_OK ? 0 : cli_report(err.status, err.message);
}

/* The frame options for sc, checked (frames it would draw included). */
static int frames_opts(const cli_args *a, const fs_scenario *sc, cli_frame_opts *o)
{
    int s = cli_frame_opts_parse(a, sc->def.step_s, 1, o);
    double duration_s = sc->def.kind == FS_SCENARIO_WALK ? sc->def.walk_steps * sc->def.walk_period_s : sc->def.duration_s;
    if (!s && floor(duration_s * o->fps) + 2 > CLI_MAX_FRAMES)
        s = cli_report(FS_BAD_INPUT, "--fps: the run's duration x fps asks for more than 999999 frames (six-digit "
                                     "names); lower --fps or shorten the run");
    return s;
}

int cli_frames_check(const cli_args *a, const fs_scenario *sc)
{
    cli_frame_opts o;
    fs_render *r = NULL;
    int s = frames_opts(a, sc, &o);
    if (!s)
        s = cli_render_open(&r, 1, 1, 1); /* OSMesa is there */
    fs_render_close(r);
    return s;
}

int cli_frames_open_at(const cli_args *a, const fs_scenario *sc, const char *frames_dir, cli_frames **frames,
                       fs_run_observer *obs)
{
    *frames = NULL;
    cli_frames *f = calloc(1, sizeof *f);
    if (!f)
        return cli_report(FS_NO_MEMORY, "out of memory");
    int s = frames_opts(a, sc, &f->o);
    if (!s && (snprintf(f->dir, sizeof f->dir, "%s", frames_dir) >= (int)sizeof f->dir ||
               snprintf(f->frames_dir, sizeof f->frames_dir, "%s", frames_dir) >= (int)sizeof f->frames_dir))
        s = cli_report(FS_BAD_INPUT, "--out: path too long");
    if (!s)
        s = cli_render_open(&f->r, f->o.width, f->o.height, f->o.exaggerate);
    if (s) {
        free(f);
        return s;
    }
    f->flat = 1;
    *obs = (fs_run_observer){.interval_s = 1 / f->o.fps, .fn = draw_frame, .user = f};
    *frames = f;
    return 0;
}

int cli_frames_open(const cli_args *a, const fs_scenario *sc, const char *dir, cli_frames **frames,
                    fs_run_observer *obs)
{
    *frames = NULL;
    cli_frame_opts o;
    char frames_dir[CLI_FRAMES_PATH];
    int s = frames_opts(a, sc, &o); /* before the folder is made */
    if (!s)
        s = cli_frames_folder(dir, frames_dir, sizeof frames_dir);
    if (!s)
        s = cli_frames_open_at(a, sc, frames_dir, frames, obs);
    if (!s) {
        (*frames)->flat = 0;
        snprintf((*frames)->dir, sizeof (*frames)->dir, "%s", dir); /* shorter than frames_dir */
    }
    return s;
}

int cli_frames_close(cli_frames *f, int ok, const char *shown_dir)
{
    if (!f)
        return 0;
    int s = 0;
    if (ok) {
        printf("  frames: %s%s/000000.png ... %06d.png (%d at %g per simulated second, %dx%d, camera %s",
               shown_dir, f->flat ? "" : "/frames", f->n - 1, f->n, f->o.fps, f->o.width, f->o.height, fs_render_camera_names[f->o.camera]);
        if (f->o.exaggerate != 1)
            printf(", displacements x%g from the first frame's pose, said on each frame", f->o.exaggerate);
        printf(")\n");
        if (f->o.video)
            s = cli_frames_video(f->dir, f->frames_dir, f->o.fps, f->n, shown_dir);
    }
    fs_render_close(f->r);
    free(f->heights);
    free(f);
    return s;
}
