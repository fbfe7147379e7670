/* io_png.c: PNG reading and writing with libpng. */
#include "footsim/fs_png.h"

#include "footsim/fs_output.h"

#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

fs_status fs_png_read_gray(const char *path, const char *where, int *w, int *h, double **values, fs_error *err)
{
    *values = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot open heightmap %s; give an existing PNG file", where, path);
    unsigned char sig[8];
    if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8)) {
        fclose(f);
        return fs_fail(err, FS_BAD_INPUT, "%s: %s is not a PNG image; give an 8- or 16-bit grayscale PNG", where, path);
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    volatile fs_status status = FS_OK;
    double *volatile out = NULL;
    png_bytep *volatile rows = NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        status = fs_fail(err, FS_BAD_INPUT, "%s: %s is a damaged PNG image", where, path);
        goto done;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
    if (type != PNG_COLOR_TYPE_GRAY || (depth != 8 && depth != 16)) {
        status = fs_fail(err, FS_BAD_INPUT, "%s: %s is not an 8- or 16-bit grayscale PNG (colour type %d, %d bits)",
                         where, path, type, depth);
        goto done;
    }
    if (width < 2 || height < 2 || (size_t)width * height > 16u * 1024 * 1024) {
        status = fs_fail(err, FS_BAD_INPUT, "%s: %s is %ux%u pixels; allowed: 2x2 to 16 Mpixels", where, path,
                         (unsigned)width, (unsigned)height);
        goto done;
    }
    if (depth == 16)
        png_set_swap(png); /* host order on little-endian machines */
    png_read_update_info(png, info);
    size_t stride = png_get_rowbytes(png, info);
    rows = calloc(height, sizeof *rows);
    out = malloc((size_t)width * height * sizeof *out);
    unsigned char *pixels = malloc(stride * height);
    if (!rows || !out || !pixels) {
        free(pixels);
        status = fs_fail(err, FS_BAD_INPUT, "%s: %s: out of memory", where, path);
        goto done;
    }
    for (png_uint_32 r = 0; r < height; r++)
        rows[r] = pixels + r * stride;
    png_read_image(png, rows);
    double full = depth == 16 ? 65535.0 : 255.0;
    for (png_uint_32 r = 0; r < height; r++)
        for (png_uint_32 c = 0; c < width; c++) {
            unsigned v = depth == 16 ? ((const unsigned short *)rows[r])[c] : rows[r][c];
            out[(size_t)r * width + c] = v / full;
        }
    free(pixels);
    *w = (int)width;
    *h = (int)height;
    *values = out;
    out = NULL;
done:
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    free(out);
    fclose(f);
    return status;
}

fs_status fs_png_write_rgb(const char *path, int w, int h, const unsigned char *rgb, fs_error *err)
{
    char temp[4200];
    FILE *f = fs_open_temp(path, temp, sizeof temp, err);
    if (!f)
        return FS_IO;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fs_commit_file(f, temp, path, 0, err);
        return fs_fail(err, FS_IO, "%s: PNG could not be written", path);
    }
    png_init_io(png, f);
    png_set_compression_level(png, 3);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int r = 0; r < h; r++)
        png_write_row(png, (png_const_bytep)(rgb + (size_t)r * w * 3));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fs_commit_file(f, temp, path, 1, err);
}
