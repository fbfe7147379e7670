/* io_png.c: PNG reading and writing with libpng. */
#include "footsim/io/fs_png.h"

#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"

#include <png.h>
#include <sys/statvfs.h>
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
    fs_error why;
    FILE *f = fs_open_regular(path, FS_PNG_MAX_BYTES, "a grayscale PNG heightmap", &why);
    if (!f)
        return fs_fail(err, FS_BAD_INPUT, "%s: heightmap %s", where, why.message);
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
    if (!png || !info) { /* libpng's structures: only memory refuses them */
        status = fs_fail(err, FS_NO_MEMORY, "%s: %s: out of memory", where, path);
        goto done;
    }
    if (setjmp(png_jmpbuf(png))) {
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
        status = fs_fail(err, FS_NO_MEMORY, "%s: %s: out of memory", where, path);
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

/* What to encode: h rows of w pixels (3 or 4 bytes each, RGB first; or one 16-bit gray value, channels
 * 1), stride bytes apart. */
typedef struct image {
    const unsigned char *pixels;
    int w, h, channels, bottom_up, level;
    long stride;
} image;

/* Encodes the image to f as RGB, or 16-bit grayscale (an fs_fill_fn). */
static int encode(FILE *f, const void *user)
{
    const image *im = user;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_quiet_error, png_quiet_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return 0;
    }
    if (setjmp(png_jmpbuf(png))) {
        /* a write error (a full disk): ferror(f) tells fs_write_file, which names it */
        png_destroy_write_struct(&png, &info);
        return ferror(f) ? 1 : 0;
    }
    png_init_io(png, f);
    /* speed over size at low levels: a fast zlib level and the cheapest useful row filter */
    png_set_compression_level(png, im->level);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, im->level <= 3 ? PNG_FILTER_SUB : PNG_ALL_FILTERS);
    int gray = im->channels == 1;
    png_set_IHDR(png, info, (png_uint_32)im->w, (png_uint_32)im->h, gray ? 16 : 8,
                 gray ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    if (gray)
        png_set_swap(png); /* the values in host order (little-endian), PNG's big-endian in the file */
    if (im->channels == 4)
        png_set_filler(png, 0, PNG_FILLER_AFTER);
    for (int y = 0; y < im->h; y++)
        png_write_row(png, im->pixels + (size_t)(im->bottom_up ? im->h - 1 - y : y) * (size_t)im->stride);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 1;
}

fs_status fs_png_write(const char *path, const unsigned char *pixels, int w, int h, int channels, long stride,
                       int bottom_up, int level, fs_error *err)
{
    const image im = {pixels, w, h, channels, bottom_up, level, stride};
    return fs_write_file(path, encode, &im, err);
}

fs_status fs_png_write_rgb(const char *path, int w, int h, const unsigned char *rgb, fs_error *err)
{
    return fs_png_write(path, rgb, w, h, 3, (long)w * 3, 0, 6, err);
}

fs_status fs_png_write_gray16(const char *path, int w, int h, const unsigned short *values, fs_error *err)
{
    return fs_png_write(path, (const unsigned char *)values, w, h, 1, (long)w * 2, 0, 6, err);
}

fs_status fs_png_check(const char *path, const char *shown, fs_error *err)
{
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    unsigned char head[16], tail[12];
    FILE *f = fopen(path, "rb");
    int ok = f && fread(head, 1, sizeof head, f) == sizeof head && !png_sig_cmp(head, 0, 8) &&
             !memcmp(head + 12, "IHDR", 4) && fseek(f, -12, SEEK_END) == 0 && fread(tail, 1, 12, f) == 12 &&
             !memcmp(tail, iend, 12);
    if (f)
        fclose(f);
    if (ok)
        return FS_OK;
    struct statvfs v;
    if (statvfs(path, &v) == 0 && v.f_bavail == 0)
        return fs_fail(err, FS_IO, "%s: cannot write: No space left on device (the chart came out truncated); free "
                       "some space and run again", shown);
    return fs_fail(err, FS_IO, "%s: the chart came out damaged (not a whole PNG: no signature, IHDR or IEND); "
                   "nothing was installed", shown);
}
