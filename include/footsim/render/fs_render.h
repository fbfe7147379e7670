/* fs_render.h: footsim's headless renderer: a scene snapshot (fs_scene.h) drawn into an image
 * with OSMesa, no display and no GPU needed.
 *
 * The renderer reads plain data and never touches ODE; the simulation core does not depend on
 * it. A renderer (fs_render) owns one OSMesa context and one RGBA frame buffer, both made once
 * by fs_render_open; drawing a frame allocates nothing. Images are addressed top-down: pixel
 * (x, y) is column x from the left, row y from the top, its centre at (x + 0.5, y + 0.5).
 *
 * A view (fs_render_view) is a perspective camera. fs_render_view_fit frames a camera on the
 * extent of scenes (their shapes, links, springs and ankle), never on constants, so a 9 cm foot
 * and a 30 cm one both fill the picture. fs_render_project maps a world point to the pixel the
 * renderer draws it at, with the very matrices it gives GL. */
#ifndef FS_RENDER_H
#define FS_RENDER_H

#include "footsim/base/fs_error.h"
#include "footsim/sim/fs_scene.h"

enum { FS_RENDER_MAX_SIZE = 8192 };

typedef enum fs_render_camera {
    FS_RENDER_SIDE = 0,          /* from the foot's right (-y), x forward to the right of the picture */
    FS_RENDER_FRONT = 1,         /* from ahead (+x), looking back at the toes */
    FS_RENDER_THREE_QUARTER = 2, /* from ahead, right and above */
    FS_RENDER_FOLLOW = 3,        /* closer, from behind-right, its target following the foot each frame */
    FS_RENDER_FOOT = 4,          /* the foot alone (not the robot) filling the picture, from ahead-right and
                                    above, its target following the foot each frame */
    FS_RENDER_NCAMERAS = 5
} fs_render_camera;

/* "side", "front", "three-quarter", "follow", "foot", in fs_render_camera order. */
extern const char *const fs_render_camera_names[FS_RENDER_NCAMERAS];

/* The camera called name, or -1 when there is none. */
int fs_render_camera_find(const char *name);

typedef struct fs_render_view {
    fs_render_camera camera;
    double eye[3], target[3], up[3];
    double fovy_deg;        /* vertical field of view */
    double near_m, far_m;
    double aspect;          /* viewport width / height */
} fs_render_view;

/* Frames camera on the union of n scenes' extents for a viewport of the given aspect: the foot's
 * (shapes, links, springs, ankle) and, except for FS_RENDER_FOOT, the robot's box. */
void fs_render_view_fit(fs_render_view *v, fs_render_camera camera, const fs_scene *const *scenes, int n,
                        double aspect);

/* For FS_RENDER_FOLLOW and FS_RENDER_FOOT: moves eye and target with the centre of scene's
 * extent (same direction and distance); other cameras stay put. */
void fs_render_view_follow(fs_render_view *v, const fs_scene *scene);

/* The pixel (x right, y down from the top, continuous) at which p appears in a w x h viewport;
 * returns 0 (px untouched) when p is behind the camera. */
int fs_render_project(const fs_render_view *v, int w, int h, const double p[3], double px[2]);

/* The view's column-major 4 x 4 projection and model-view matrices, as given to GL. */
void fs_render_view_matrices(const fs_render_view *v, double proj[16], double model[16]);

/* The ground's colour for a height fraction t in [0, 1] (0 lowest, 1 highest; 0.5 for a plane),
 * before lighting: bluish grey when low, sand when high. */
void fs_render_height_colour(double t, float rgb[3]);

typedef struct fs_render fs_render;

/* Makes an OSMesa context and a width x height frame (each 1 to FS_RENDER_MAX_SIZE). FS_BAD_INPUT
 * when OSMesa cannot make one (the message says what to install). */
fs_status fs_render_open(fs_render **r, int width, int height, fs_error *err);
void fs_render_close(fs_render *r);

int fs_render_width(const fs_render *r);
int fs_render_height(const fs_render *r);

/* Fills the whole frame with the background. */
void fs_render_clear(fs_render *r);

/* Draws scene as v sees it into the viewport whose top-left pixel is (x0, y0), w x h (inside the
 * frame), with the overlay (time, scenario, foot, terrain and the note, one line) along its top
 * and a scale bar (a round number of mm at the camera's target) in its bottom-left corner. Shows:
 * the ground as a lit, height-shaded mesh; every shape as it collides (spheres, boxes); a shadow
 * blob on the ground under each shape; links as solid bars with joints; springs coloured by force
 * (red tension, blue compression, grey slack); contact points with ground-force arrows; the load
 * at the ankle; the robot as a translucent box (the foot shows through).
 * Spring colours and arrow lengths are scaled by the largest force r has drawn so far (so that
 * successive frames compare); the overlay scales with the viewport. */
void fs_render_draw(fs_render *r, const fs_render_view *v, const fs_scene *scene, int x0, int y0, int w, int h);

/* A note said on the overlay of every frame drawn after (at most 63 characters; NULL or "" for
 * none): "displacements x20" for an exaggerated view. */
void fs_render_set_note(fs_render *r, const char *note);

/* The colour legend (spring in tension, in compression, contact force, load) as one row of
 * swatches and words, left-aligned and vertically centred in the box at (x0, y0), w x h; the
 * words shrink to fit. Returns the width drawn, pixels. */
int fs_render_legend(fs_render *r, int x0, int y0, int w, int h);

/* The deformation view: out is now with every foot body's displacement from its pose in neutral,
 * taken in the ankle body's frame, multiplied by factor (translation scaled, rotation angle scaled
 * about the same axis), placed back on the ankle body where it is now. Shapes, links, springs (each
 * end with its body) and contacts (with the nearest shape's body) move with their bodies; the
 * ankle body, the robot, forces and the ground stay. factor 1, or scenes without body poses (or
 * with different body counts), give out = now. out may be now. */
void fs_render_exaggerate(const fs_scene *neutral, const fs_scene *now, double factor, fs_scene *out);

/* The RGBA bytes of pixel (x, y) of the last drawn frame. */
const unsigned char *fs_render_pixel(const fs_render *r, int x, int y);

/* Writes the frame to path as an RGB PNG (zlib level 0-9; 1 is fast), whole or not at all. */
fs_status fs_render_write_png(const fs_render *r, const char *path, int level, fs_error *err);

/* Draws text (ASCII; letters shown as capitals) with footsim's 5 x 7 bitmap font, each font pixel
 * scale x scale, its top-left at (x, y), clipped to the frame. Returns the width drawn, pixels. */
int fs_render_text(fs_render *r, int x, int y, int scale, const char *text, const unsigned char rgb[3]);

/* PNG files as top-down RGBA, for tests and tools: fs_render_png_write writes rows of stride
 * bytes (whole or not at all); fs_render_png_read allocates *rgba (free() it). */
fs_status fs_render_png_write(const char *path, const unsigned char *rgba, int w, int h, long stride, int bottom_up,
                              int level, fs_error *err);
fs_status fs_render_png_read(const char *path, unsigned char **rgba, int *w, int *h, fs_error *err);

/* A simulation drawn into the caller's buffer (for embedding, footsim/api/fs_api.h's handles): a
 * renderer, the camera named (fs_render_camera_names) framed on the first frame drawn and
 * following after as the command's frames do, and its scene, all made by fs_render_sim_open;
 * drawing allocates nothing. fs_render_sim_draw fills rgba (width x height x 4 bytes, top-down
 * rows) with sim now. FS_BAD_INPUT for an unknown camera or a size out of range, or when OSMesa is
 * missing (the message says what to install). */
struct fs_sim;
typedef struct fs_render_sim fs_render_sim;
fs_render_sim *fs_render_sim_open(int width, int height, const char *camera, fs_error *err);
void fs_render_sim_close(fs_render_sim *rs);
void fs_render_sim_draw(fs_render_sim *rs, const struct fs_sim *sim, unsigned char *rgba);

#endif
