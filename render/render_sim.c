/* render_sim.c: a simulation drawn into the caller's buffer (fs_render.h, fs_render_sim_*). */
#include "footsim/render/fs_render.h"
#include "footsim/sim/fs_sim.h"

#include <stdlib.h>
#include <string.h>

struct fs_render_sim {
    fs_render *r;
    fs_render_view view;
    int camera, frames;
    fs_scene scene; /* the snapshot, reused for each frame */
};

fs_render_sim *fs_render_sim_open(int width, int height, const char *camera, fs_error *err)
{
    int cam = fs_render_camera_find(camera ? camera : "");
    if (cam < 0) {
        fs_fail(err, FS_BAD_INPUT, "camera: '%s' is not a camera; give side, front, three-quarter, follow or foot",
                camera ? camera : "(null)");
        return NULL;
    }
    fs_render_sim *rs = calloc(1, sizeof *rs);
    if (!rs) {
        fs_fail(err, FS_NO_MEMORY, "fs_render_sim_open: no memory for the renderer");
        return NULL;
    }
    if (fs_render_open(&rs->r, width, height, err) != FS_OK) {
        free(rs);
        return NULL;
    }
    rs->camera = cam;
    return rs;
}

void fs_render_sim_close(fs_render_sim *rs)
{
    if (!rs)
        return;
    fs_render_close(rs->r);
    free(rs);
}

void fs_render_sim_draw(fs_render_sim *rs, const struct fs_sim *sim, unsigned char *rgba)
{
    int w = fs_render_width(rs->r), h = fs_render_height(rs->r);
    fs_sim_scene(sim, &rs->scene);
    const fs_scene *first = &rs->scene;
    if (rs->frames++ == 0)
        fs_render_view_fit(&rs->view, (fs_render_camera)rs->camera, &first, 1, (double)w / h);
    else
        fs_render_view_follow(&rs->view, &rs->scene);
    fs_render_clear(rs->r);
    fs_render_draw(rs->r, &rs->view, &rs->scene, 0, 0, w, h);
    for (int y = 0; y < h; y++) /* each row is contiguous in the frame, whichever way GL stores rows */
        memcpy(rgba + (size_t)y * w * 4, fs_render_pixel(rs->r, 0, y), (size_t)w * 4);
}
