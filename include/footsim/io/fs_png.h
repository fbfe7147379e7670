/* fs_png.h: grayscale PNG input and output (heightmaps) and RGB PNG output (terrain maps), with libpng.
 * Reading refuses a file that is not a PNG or not grayscale; writing is atomic. */
#ifndef FS_PNG_H
#define FS_PNG_H

#include "footsim/base/fs_error.h"

/* The largest heightmap file read, bytes (a regular file; 16 Mpixels of 16 bits uncompressed). */
#define FS_PNG_MAX_BYTES (64L * 1024 * 1024)

/* Reads an 8- or 16-bit grayscale PNG; *values (malloc'd, w*h, row 0 first) are in [0, 1]. */
fs_status fs_png_read_gray(const char *path, const char *where, int *w, int *h, double **values, fs_error *err);

/* Writes h rows of w pixels to path as an RGB PNG, whole or not at all: channels 3 (RGB) or 4
 * (RGBA, alpha dropped), rows stride bytes apart, the last row first when bottom_up (as GL
 * reads them), zlib level 0-9 (1 is fast, 6 small). */
fs_status fs_png_write(const char *path, const unsigned char *pixels, int w, int h, int channels, long stride,
                       int bottom_up, int level, fs_error *err);

/* Writes w*h 16-bit grayscale values (row 0 at the top) to path, whole or not at all: a heightmap
 * fs_png_read_gray reads back exactly (v / 65535). */
fs_status fs_png_write_gray16(const char *path, int w, int h, const unsigned short *values, fs_error *err);

/* Writes w*h RGB pixels (row 0 at the top) to path, whole or not at all. */
fs_status fs_png_write_rgb(const char *path, int w, int h, const unsigned char *rgb, fs_error *err);

/* Checks that path (written by another program) is a whole PNG file: the signature, an IHDR
 * chunk first and an IEND chunk last. `shown` names it in messages. A damaged file is FS_IO, and
 * said to be "No space left on device" when its filesystem has no space left. */
fs_status fs_png_check(const char *path, const char *shown, fs_error *err);

#endif
