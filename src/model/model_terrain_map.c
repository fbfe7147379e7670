/* model_terrain_map.c: a shaded top-down picture of a terrain. */
#include "footsim/model/fs_terrain.h"

#include <math.h>
#include <stdlib.h>

/* Low to high: deep green, olive, sand, near white. */
static void colour(double u, double rgb[3])
{
    static const double stops[4][3] = {{40, 90, 80}, {110, 130, 60}, {200, 170, 110}, {245, 240, 225}};
    u = fmin(fmax(u, 0), 1) * 3;
    int k = (int)fmin(floor(u), 2);
    double f = u - k;
    for (int c = 0; c < 3; c++)
        rgb[c] = stops[k][c] + f * (stops[k + 1][c] - stops[k][c]);
}

static int on_outline(const double *o, double x, double y, double px)
{
    if (!o || x < o[0] - px || x > o[1] + px || y < o[2] - px || y > o[3] + px)
        return 0;
    return fabs(x - o[0]) <= px || fabs(x - o[1]) <= px || fabs(y - o[2]) <= px || fabs(y - o[3]) <= px;
}

fs_status fs_terrain_map(const fs_terrain *t, const double region[4], const double *outline, int w, int h,
                         unsigned char *rgb, double zrange[2], fs_error *err)
{
    double sx = (region[1] - region[0]) / (w - 1), sy = (region[3] - region[2]) / (h - 1);
    double *z = malloc((size_t)w * h * sizeof *z);
    if (!z)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for a %dx%d map", t->name, w, h);
    double lo = INFINITY, hi = -INFINITY;
    for (int r = 0; r < h; r++)
        for (int c = 0; c < w; c++) {
            double v = fs_terrain_height(t, region[0] + c * sx, region[3] - r * sy);
            z[(size_t)r * w + c] = v;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
    double span = hi - lo > 1e-9 ? hi - lo : 1e-9;
    /* light from the north-west, 45 degrees up */
    const double L[3] = {-0.5, 0.5, 0.7071};
    for (int r = 0; r < h; r++)
        for (int c = 0; c < w; c++) {
            int cl = c > 0 ? c - 1 : c, cr = c < w - 1 ? c + 1 : c, ru = r > 0 ? r - 1 : r, rd = r < h - 1 ? r + 1 : r;
            double gx = (z[(size_t)r * w + cr] - z[(size_t)r * w + cl]) / ((cr - cl) * sx);
            double gy = (z[(size_t)ru * w + c] - z[(size_t)rd * w + c]) / ((rd - ru) * sy);
            double n = sqrt(gx * gx + gy * gy + 1);
            double light = fmax(0, (-gx * L[0] - gy * L[1] + L[2]) / n);
            double col[3];
            colour((z[(size_t)r * w + c] - lo) / span, col);
            unsigned char *p = rgb + ((size_t)r * w + c) * 3;
            int edge = on_outline(outline, region[0] + c * sx, region[3] - r * sy, 0.75 * sx);
            for (int k = 0; k < 3; k++)
                p[k] = edge ? 255 : (unsigned char)fmin(255, col[k] * (0.35 + 0.65 * light / L[2]));
        }
    free(z);
    zrange[0] = lo;
    zrange[1] = hi;
    return FS_OK;
}

void fs_terrain_map_colour(double u, double rgb[3]) { colour(u, rgb); }
