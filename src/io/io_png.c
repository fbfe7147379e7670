/* io_png.c: PNG reading and writing with libpng. */
#include "footsim/io/fs_png.h"

#include "footsim/io/fs_output.h"

#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

/* libpng's complaints end the read through setjmp; the caller reports them, libpng stays quiet. */
static void png_quiet_error(png_structp png, png_const_charp message)
{
    (void)message;
    png_longjmp(png, 1);
}

static void png_quiet_warning(png_structp png, png_const_charp message) { (void)png, (void)message; }

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
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, png_quiet_error, png_quiet_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    volatile fs_status status = FS_OK;
    double *volatile out = NULL;
    png_bytep *volatile rows = NULL;
    unsigned char *volatile pixels = NULL; /* freed on every path, the damaged-image jump included */
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
    pixels = malloc(stride * height);
    if (!rows || !out || !pixels) {
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
    *w = (int)width;
    *h = (int)height;
    *values = out;
    out = NULL;
done:
    png_destroy_read_struct(&png, &info, NULL);
    free(pixels);
    free(rows);
    free(out);
    fclose(f);
    return status;
}

/* Encodes h rows of w pixels (3 or 4 bytes each, RGB first; stride bytes apart) to f as RGB. */
static int encode(FILE *f, const unsigned char *pixels, int w, int h, int channels, long stride, int bottom_up,
                  int level)
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
    /* speed over size at low levels: a fast zlib level and the cheapest useful row filter */
    png_set_compression_level(png, level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, level <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    if (channels == 4)
        png_set_filler(png, 0, PNG_FILLER_AFTER);
    for (int y = 0; y < h; y++)
        png_write_row(png, pixels + (size_t)(bottom_up ? h - 1 - y : y) * (size_t)stride);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 1;
}

fs_status fs_png_write(const char *path, const unsigned char *pixels, int w, int h, int channels, long stride,
                       int bottom_up, int level, fs_error *err)
{
    char temp[4200];
    FILE *f = fs_open_temp(path, temp, sizeof temp, err);
    if (!f)
        return FS_IO;
    int ok = encode(f, pixels, w, h, channels, stride, bottom_up, level);
    fs_status s = fs_commit_file(f, temp, path, ok, err);
    return ok ? s : fs_fail(err, FS_IO, "%s: PNG encoding failed", path);
}

fs_status fs_png_write_rgb(const char *path, int w, int h, const unsigned char *rgb, fs_error *err)
{
    return fs_png_write(path, rgb, w, h, 3, (long)w * 3, 0, 6, err);
}
