/* cli_terrain.c: the terrain subcommand: heights, a picture, a summary. */
#include "cli.h"

#include "footsim/io/fs_gnuplot.h"
#include "footsim/io/fs_output.h"
#include "footsim/io/fs_png.h"
#include "footsim/model/fs_scenario.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The region a picture shows when no scenario gives one, m: around a foot at the origin. */
static const double DEFAULT_REGION[4] = {-0.06, 0.16, -0.08, 0.08};
enum { MAP_WIDTH_PX = 880 };
/* --height takes points this far from the origin at most, m: ten times a scenario's start range */
static const double MAX_COORDINATE_M = 1000;

static int parse_coordinate(const char *text, const char *name, double *out)
{
    fs_number n = fs_parse_number(text, out);
    if (n != FS_NUMBER_OK) {
        fprintf(stderr, "footsim: --height %s: '%s' %s; allowed: metres from %g to %g\n", name, text,
                fs_number_problem(n), -MAX_COORDINATE_M, MAX_COORDINATE_M);
        return 0;
    }
    if (fabs(*out) > MAX_COORDINATE_M) {
        fprintf(stderr, "footsim: --height %s: %s m is out of range; allowed: metres from %g to %g\n", name, text,
                -MAX_COORDINATE_M, MAX_COORDINATE_M);
        return 0;
    }
    return 1;
}

static int print_height(fs_terrain *t, const cli_args *a)
{
    double x, y;
    if (!parse_coordinate(a->height_x, "X", &x) || !parse_coordinate(a->height_y, "Y", &y))
        return FS_BAD_INPUT;
    fs_error err;
    double cell = 0.01;
    if (fs_terrain_crop(t, x - cell, x + cell, y - cell, y + cell, &err) != FS_OK)
        return cli_report(err.status, err.message);
    printf("%.9g\n", fs_terrain_height(t, x, y));
    return 0;
}

/* The figure around a map: margins in pixels, so that the map is drawn at its own size. */
enum { FIG_LEFT_PX = 80, FIG_RIGHT_PX = 130, FIG_BOTTOM_PX = 60, FIG_TOP_PX = 50, COLOURBAR_PX = 22 };

typedef struct figure {
    const char *name, *map;     /* the terrain's name; the bare map's file name in the script's folder */
    const double *region, *zrange;
    int w, h, outline;
} figure;

/* The gnuplot script of the figure: the map at one pixel per pixel, axes in mm, a colour bar of
 * the map's colours on level ground in mm. */
static int fill_figure_script(FILE *f, const void *user)
{
    const figure *g = user;
    double W = g->w + FIG_LEFT_PX + FIG_RIGHT_PX, H = g->h + FIG_BOTTOM_PX + FIG_TOP_PX;
    const double *r = g->region;
    double sx = (r[1] - r[0]) / (g->w - 1) * 1e3, sy = (r[3] - r[2]) / (g->h - 1) * 1e3;
    fprintf(f, "# footsim terrain --png: the map with axes and a colour bar ('gnuplot terrain.gp' draws it).\n"
               "if (!exists(\"out\")) out = 'terrain.png'\n"
               "set terminal pngcairo size %.0f,%.0f noenhanced font 'sans,10'\nset output out\n"
               "set lmargin at screen %.6f\nset rmargin at screen %.6f\nset bmargin at screen %.6f\n"
               "set tmargin at screen %.6f\n",
            W, H, FIG_LEFT_PX / W, (FIG_LEFT_PX + g->w) / W, FIG_BOTTOM_PX / H, (FIG_BOTTOM_PX + g->h) / H);
    /* pixel centres at the sampled points: the axes reach half a pixel further */
    fprintf(f, "set xrange [%.9g:%.9g]\nset yrange [%.9g:%.9g]\nset tics out\nset xlabel 'x (mm)'\n"
               "set ylabel 'y (mm)'\nset cblabel 'height (mm)' offset 1.5,0\nset cbrange [%.9g:%.9g]\nset palette defined (",
            r[0] * 1e3 - sx / 2, r[1] * 1e3 + sx / 2, r[2] * 1e3 - sy / 2, r[3] * 1e3 + sy / 2, g->zrange[0] * 1e3,
            /* level ground is drawn in the lowest colour: the bar then spans 1 mm up from it */
            g->zrange[1] - g->zrange[0] > 1e-9 ? g->zrange[1] * 1e3 : g->zrange[0] * 1e3 + 1);
    /* the map's colour ramp is linear between these four */
    for (int k = 0; k <= 3; k++) {
        double c[3];
        fs_terrain_map_colour(k / 3.0, c);
        fprintf(f, "%s%d '#%02x%02x%02x'", k ? ", " : "", k, (int)lround(c[0]), (int)lround(c[1]), (int)lround(c[2]));
    }
    fprintf(f, ")\nset colorbox user origin screen %.6f, screen %.6f size screen %.6f, screen %.6f\n",
            (FIG_LEFT_PX + g->w + 20) / W, FIG_BOTTOM_PX / H, COLOURBAR_PX / W, g->h / H);
    /* the terrain's name and the map's path as data, never code (fs_gnuplot.h) */
    char title[256];
    snprintf(title, sizeof title, "terrain %s from above: height as colour, shaded with light from the north-west%s",
             g->name, g->outline ? "; white: what the foot reaches" : "");
    fputs("map_title = ", f);
    fs_gp_string(f, title);
    fputs("\nmap_file = ", f);
    fs_gp_string(f, g->map);
    fprintf(f, "\nset title map_title\nplot map_file binary filetype=png dx=%.9g dy=%.9g origin=(%.9g,%.9g) with rgbimage notitle, \\\n"
               "     '+' using (NaN):(NaN):(0) with points lc palette notitle\n",
            sx, sy, r[0] * 1e3, r[2] * 1e3);
    return 1;
}

/* The map drawn into a figure by gnuplot: 0 drawn, -1 not (said: the caller writes the bare map),
 * else an exit status. */
static int write_figure(const figure *g, const unsigned char *rgb, const char *png)
{
    const char *tmp = getenv("TMPDIR");
    char dir[FS_OUT_PATH];
    fs_error err;
    if (!cli_have_program("gnuplot")) {
        fprintf(stderr, "footsim terrain: gnuplot is not installed: %s is the bare map, without axes or colour "
                        "bar (apt-get install gnuplot-nox draws them)\n", png);
        return -1;
    }
    if (fs_path_format(dir, sizeof dir, "TMPDIR", &err, "%s/footsim-terrain-XXXXXX", tmp && *tmp ? tmp : "/tmp") !=
        FS_OK) {
        fprintf(stderr, "footsim terrain: no scratch folder for the figure (%s): %s is the bare map\n", err.message,
                png);
        return -1;
    }
    if (!mkdtemp(dir)) {
        fprintf(stderr, "footsim terrain: no scratch folder for the figure (%s: %s): %s is the bare map\n", dir,
                strerror(errno), png);
        return -1;
    }
    char map[FS_OUT_PATH + 16];
    snprintf(map, sizeof map, "%s/map.png", dir);
    if (fs_png_write_rgb(map, g->w, g->h, rgb, &err) != FS_OK ||
        fs_write_in(dir, "terrain.gp", fill_figure_script, g, &err) != FS_OK) {
        fprintf(stderr, "footsim terrain: %s: %s is the bare map\n", err.message, png);
        fs_remove_tree(dir);
        return -1;
    }
    int s = cli_gnuplot_to(dir, "terrain.gp", png, "terrain");
    if (s < 0) /* gnuplot failed: its message names the folder, left for a look */
        fprintf(stderr, "footsim terrain: %s is the bare map\n", png);
    else
        fs_remove_tree(dir);
    return s;
}

/* The region the summary and the picture show: the scenario's (--scenario: what its foot reaches,
 * its footprint at the start or a walk's path, plus its margin, kept in foot[] and *outline set)
 * or DEFAULT_REGION. 0, or an exit status (said). */
static int region_of(const cli_args *a, double region[4], double foot[4], double **outline)
{
    fs_error err;
    for (int k = 0; k < 4; k++)
        region[k] = DEFAULT_REGION[k];
    *outline = NULL;
    if (!a->scenario)
        return 0;
    fs_scenario *sc = cli_zalloc(sizeof *sc);
    if (!sc)
        return FS_NO_MEMORY;
    fs_status ls = fs_scenario_load(a->scenario, NULL, 0, sc, &err);
    if (ls == FS_OK) {
        fs_scenario_reach(sc, foot);
        double m = sc->def.region_margin_m;
        region[0] = foot[0] - m, region[1] = foot[1] + m, region[2] = foot[2] - m, region[3] = foot[3] + m;
        *outline = foot;
    }
    fs_scenario_free(sc);
    free(sc);
    return ls == FS_OK ? 0 : cli_report(err.status, err.message);
}

static int write_map(fs_terrain *t, const cli_args *a)
{
    fs_error err;
    double region[4], foot[4], *outline;
    int rs = region_of(a, region, foot, &outline);
    if (rs)
        return rs;
    if (fs_terrain_crop(t, region[0], region[1], region[2], region[3], &err) != FS_OK)
        return cli_report(err.status, err.message);
    int w = MAP_WIDTH_PX, h = (int)lround(w * (region[3] - region[2]) / (region[1] - region[0]));
    unsigned char *rgb = malloc((size_t)w * h * 3);
    if (!rgb)
        return cli_report(FS_NO_MEMORY, "out of memory");
    double z[2];
    if (fs_terrain_map(t, region, outline, w, h, rgb, z, &err) != FS_OK) {
        free(rgb);
        return cli_report(err.status, err.message);
    }
    const figure g = {t->name, "map.png", region, z, w, h, outline != NULL};
    int s = write_figure(&g, rgb, a->png);
    fs_status ws = s < 0 ? fs_png_write_rgb(a->png, w, h, rgb, &err) : FS_OK;
    free(rgb);
    if (ws != FS_OK)
        return cli_report(err.status, err.message);
    if (s > 0)
        return s;
    printf("%s: %s terrain over x %.3f..%.3f m, y %.3f..%.3f m, heights %.4f..%.4f m%s%s\n", a->png, t->name,
           region[0], region[1], region[2], region[3], z[0], z[1], outline ? "; white: what the foot reaches" : "",
           s < 0 ? " (the bare map: no axes)" : "; axes and colour bar in mm");
    return 0;
}

static int summary(fs_terrain *t, const cli_args *a)
{
    static const char *kinds[] = {"flat", "slope", "stepped", "rough", "simply_uneven", "complex_uneven", "heightmap"};
    fs_error err;
    double r[4], foot[4], *outline;
    int rs = region_of(a, r, foot, &outline);
    if (rs)
        return rs;
    if (fs_terrain_crop(t, r[0], r[1], r[2], r[3], &err) != FS_OK)
        return cli_report(err.status, err.message);
    double lo = INFINITY, hi = -INFINITY, sum = 0, sum2 = 0;
    int n = 0;
    for (double x = r[0]; x <= r[1]; x += 0.001)
        for (double y = r[2]; y <= r[3]; y += 0.001, n++) {
            double z = fs_terrain_height(t, x, y);
            lo = fmin(lo, z), hi = fmax(hi, z), sum += z, sum2 += z * z;
        }
    double mean = sum / n;
    printf("%s: %s terrain; material mu %.2f, restitution %.2f, stiffness %.3g N/m, damping %.3g N s/m\n"
           "  over x %.3f..%.3f m, y %.3f..%.3f m%s: heights %.4f..%.4f m, mean %.4f m, RMS about the mean %.4f m\n",
           t->path, kinds[t->def.kind], t->def.mu, t->def.restitution, t->def.stiffness_N_per_m,
           t->def.damping_Ns_per_m, r[0], r[1], r[2], r[3], outline ? " (what the scenario's foot reaches, and its margin)" : "", lo, hi, mean, sqrt(fmax(0, sum2 / n - mean * mean)));
    const fs_soil_def *d = &t->def.soil;
    if (d->model != FS_SOIL_NONE) /* the heights above are its bedrock's */
        printf("  soil: %s (%s), %.3g m deep over the heights above (its bedrock), grid %.3g mm (shapes met on up to "
               "%.3g mm); docs/soil.md\n", d->model == FS_SOIL_BEKKER ? "bekker" : "rft", t->name, d->depth_m,
               d->grid_m * 1e3, fmax(d->grid_m, d->coarse_grid_m) * 1e3);
    return 0;
}

int cli_terrain(const cli_args *a)
{
    fs_error err;
    /* an existing file there is replaced only when it is a PNG already (its signature), or --replace */
    static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (a->png && fs_check_file_target(a->png, "--png", png_signature, sizeof png_signature, "a PNG", a->replace,
                                       &err) != FS_OK)
        return cli_report(err.status, err.message);
    fs_terrain *t = cli_zalloc(sizeof *t);
    if (!t)
        return FS_NO_MEMORY;
    if (fs_terrain_load(a->input, a->set, a->nset, t, &err) != FS_OK) {
        free(t); /* fs_terrain_load freed what it read */
        return cli_report(err.status, err.message);
    }
    int s = 0;
    if (a->height_x)
        s = print_height(t, a);
    if (!s && a->png)
        s = write_map(t, a);
    if (!a->height_x && !a->png)
        s = summary(t, a);
    fs_terrain_free(t);
    free(t);
    return s;
}
