/* render_internal.h: what the renderer's own files share (not part of its interface). */
#ifndef FS_RENDER_INTERNAL_H
#define FS_RENDER_INTERNAL_H

#include "footsim/render/fs_render.h"

#include "render_glapi.h"

struct fs_render {
    OSMesaContext ctx;
    int w, h;
    unsigned char *rgba;     /* w x h RGBA, rows bottom-up as GL writes them */
    GLuint sphere, cube;     /* display lists: unit sphere (radius 1), unit cube (edges 1) */
    GLuint cylinder;         /* display list: radius 1 about z, from z = 0 to 1, open ends */
    char note[128];          /* said on every frame's overlay (fs_render_set_note), or "" */
    double spring_ref_N;     /* the largest spring force seen: full colour */
    double contact_ref_N;    /* the largest contact force seen: the longest arrow */
};

/* Makes r's context current on its frame. Inline here, so the text (render_font.c) needs nothing
 * of the scene's drawing (render_gl.c), which uses the text: the files depend one way. */
static inline void render_make_current(fs_render *r)
{
    if (gl.GetCurrentContext() != r->ctx)
        gl.MakeCurrent(r->ctx, r->rgba, GL_UNSIGNED_BYTE, r->w, r->h);
}

/* Darkens the rectangle at (x0, y0), w x h, keeping the fraction keep of each colour (GL). */
void fs_render_shade_box(fs_render *r, int x0, int y0, int w, int h, double keep);

/* Fills the rectangle at (x0, y0), w x h, with rgb (GL). */
void fs_render_fill_box(fs_render *r, int x0, int y0, int w, int h, const float rgb[3]);

/* fs_render_text without waiting for GL to finish. */
int fs_render_text_gl(fs_render *r, int x, int y, int scale, const char *text, const unsigned char rgb[3]);

#endif
