/* cli_render.c: frames of a run and render-compare when footsim is built without the renderer
 * (FS_RENDER=OFF): both refuse with exit 2. */
#include "cli.h"

#include "footsim/base/fs_error.h"

#include <stdio.h>

static const char *const WITHOUT = "this footsim was built without the renderer (FS_RENDER=OFF); "
                                   "install libosmesa6-dev and libpng-dev and rebuild with -DFS_RENDER=ON";

int cli_frames_open(const cli_args *a, const fs_scenario *sc, const char *dir, cli_frames **frames,
                    fs_run_observer *obs)
{
    (void)a, (void)sc, (void)dir, (void)obs;
    *frames = 0;
    fprintf(stderr, "footsim: --frames: %s\n", WITHOUT);
    return FS_BAD_INPUT;
}

int cli_render_compare(const cli_args *a)
{
    (void)a;
    fprintf(stderr, "footsim: render-compare: %s\n", WITHOUT);
    return FS_BAD_INPUT;
}

int cli_frames_close(cli_frames *frames, int ok, const char *shown_dir)
{
    (void)frames, (void)ok, (void)shown_dir;
    return 0;
}

int cli_frames_open_at(const cli_args *a, const fs_scenario *sc, const char *frames_dir, cli_frames **frames,
                       fs_run_observer *obs)
{
    return cli_frames_open(a, sc, frames_dir, frames, obs);
}

void cli_frames_label(cli_frames *frames, const char *label) { (void)frames, (void)label; }

int cli_frames_finish(cli_frames *frames, const char *label)
{
    (void)frames, (void)label;
    return 0;
}

int cli_frames_check(const cli_args *a, const fs_scenario *sc)
{
    cli_frames *f;
    return cli_frames_open(a, sc, NULL, &f, NULL);
}
