/* cli_frames.h: what footsim's frame-writing commands share (run --frames, render-compare):
 * the frame options, the frames folder, one frame written, the video. Each returns 0 or the
 * exit status, having printed why. */
#ifndef FS_CLI_FRAMES_H
#define FS_CLI_FRAMES_H

#include "cli.h"
#include "footsim/render/fs_render.h"

#include <stddef.h>

enum { CLI_FRAMES_PATH = 4200, CLI_PNG_LEVEL = 1 /* zlib level of frames: speed over size */,
       CLI_MAX_FRAMES = 999999 /* frames are named with six digits */ };

typedef struct cli_frame_opts {
    int width, height;
    double fps;
    fs_render_camera camera;
    int video;
    double exaggerate;  /* 1: true size */
} cli_frame_opts;

/* Checks --fps (1 to 10000 and no faster than one frame per step_s), --size (each from min_w x 1
 * to 8192), --camera and --exaggerate (1 to 10000); fills the defaults (60, 1280x720, foot, 1). */
int cli_frame_opts_parse(const cli_args *a, double step_s, int min_w, cli_frame_opts *o);

/* Makes DIR/frames (DIR a fresh partial results folder); frames_dir gets the folder's path. */
int cli_frames_folder(const char *dir, char *frames_dir, size_t size);

/* Writes r's frame as frames_dir/NNNNNN.png (index, six digits), whole or not at all. */
fs_status cli_frames_write(const fs_render *r, const char *frames_dir, int index, fs_error *err);

/* For --video: DIR/video.mp4 from the frames with ffmpeg when it is installed (when it is not,
 * says so and returns 0); 4 when ffmpeg fails. */
int cli_frames_video(const char *dir, const char *frames_dir, double fps, int nframes, const char *shown_dir);

/* Opens a renderer, printing why not; with exaggerate other than 1 its frames say so. */
int cli_render_open(fs_render **r, int w, int h, double exaggerate);

/* The note every frame of r says after its time: label (a side, a seed, an outcome; "" for none),
 * then the exaggeration when it is not 1. */
void cli_frame_note(fs_render *r, const char *label, double exaggerate);

/* The colour legend in the bottom-right corner of the viewport, when it is wide enough. */
void cli_frame_legend(fs_render *r, int x0, int y0, int w, int h);

/* The scene as o draws it: now with displacements from neutral exaggerated (o->exaggerate). */
void cli_frame_scene(const cli_frame_opts *o, const fs_scene *neutral, const fs_scene *now, fs_scene *out);

#endif
