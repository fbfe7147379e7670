/* render_png.c: frames to PNG files (libpng), whole or not at all, and PNG files back to pixels. */
#include "render_internal.h"

#include "footsim/fs_output.h"

#include <png.h>
#include <stdlib.h>

/* Encodes w x h RGBA rows to f as RGB; 0 when libpng fails. */
static int encode(FILE *f, const unsigned char *rgba, int w, int h, long stride, int bottom_up, int level)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return 0;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return 0;
    }
    png_init_io(png, f);
    /* speed over size: a fast zlib level and the cheapest useful row filter */
    png_set_compression_level(png, level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, level <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    png_set_filler(png, 0, PNG_FILLER_AFTER);
    for (int y = 0; y < h; y++)
        png_write_row(png, rgba + (size_t)(bottom_up ? h - 1 - y : y) * (size_t)stride);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 1;
}

fs_status fs_render_png_write(const char *path, const unsigned char *rgba, int w, int h, long stride, int bottom_up,
                              int level, fs_error *err)
{
    char temp[4200];
    FILE *f = fs_open_temp(path, temp, sizeof temp, err);
    if (!f)
        return FS_IO;
    int ok = encode(f, rgba, w, h, stride, bottom_up, level);
    fs_status s = fs_commit_file(f, temp, path, ok, err);
    return ok ? s : fs_fail(err, FS_IO, "%s: PNG encoding failed", path);
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
    if (!*rgba || !png_image_finish_read(&img, NULL, *rgba, 0, NULL)) {
        free(*rgba);
        *rgba = NULL;
        png_image_free(&img);
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot decode PNG", path);
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return FS_OK;
}
