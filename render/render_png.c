/* render_png.c: frames to PNG files (libpng), whole or not at all, and PNG files back to pixels. */
#include "render_internal.h"

#include "footsim/io/fs_png.h"

#include <png.h>
#include <stdlib.h>

fs_status fs_render_png_write(const char *path, const unsigned char *rgba, int w, int h, long stride, int bottom_up,
                              int level, fs_error *err)
{
    return fs_png_write(path, rgba, w, h, 4, stride, bottom_up, level, err);
}

fs_status fs_render_write_png(const fs_render *r, const char *path, int level, fs_error *err)
{
    return fs_render_png_write(path, r->rgba, r->w, r->h, (long)r->w * 4, 1, level, err);
}

fs_status fs_render_png_read(const char *path, unsigned char **rgba, int *w, int *h, fs_error *err)
{
    png_image img = {.version = PNG_IMAGE_VERSION};
    *rgba = NULL;
    if (!png_image_begin_read_from_file(&img, path))
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot read as PNG (%s)", path, img.message);
    img.format = PNG_FORMAT_RGBA;
    *rgba = malloc(PNG_IMAGE_SIZE(img));
    if (!*rgba) {
        png_image_free(&img);
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for a %ux%u image", path, img.width, img.height);
    }
    if (!png_image_finish_read(&img, NULL, *rgba, 0, NULL)) {
        free(*rgba);
        *rgba = NULL;
        png_image_free(&img);
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot decode PNG", path);
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return FS_OK;
}
