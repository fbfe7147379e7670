/* fs_terrain.h: the ground a foot lands on, described by a file in terrains/ and built exactly
 * where a test can know the answer and cheaply where the scene needs no more.
 *
 * Kinds: flat (an ODE plane), slope (a tilted plane), stepped (boxes: sharp edges), and the
 * heightfield kinds rough, simply_uneven, complex_uneven and heightmap. A heightfield kind is a
 * height function of (x, y) alone, sampled on a fixed world lattice (multiples of resolution_m
 * from the lattice origin), so cutting it to a region never changes it: the same seed gives the
 * same surface wherever it is cut. fs_terrain_crop samples the lattice over the region a scenario
 * can reach; fs_terrain_height then returns the surface ODE collides with: the plane or step
 * height, or the triangulated samples (each lattice cell split along its rising diagonal, as ODE
 * splits it). Outside the cropped region it returns the height function itself. */
#ifndef FS_TERRAIN_H
#define FS_TERRAIN_H

#include "footsim/io/fs_config.h"
#include "footsim/model/fs_soil.h"

typedef enum fs_terrain_kind {
    FS_TERRAIN_FLAT, FS_TERRAIN_SLOPE, FS_TERRAIN_STEPPED, FS_TERRAIN_ROUGH,
    FS_TERRAIN_SIMPLY_UNEVEN, FS_TERRAIN_COMPLEX_UNEVEN, FS_TERRAIN_HEIGHTMAP
} fs_terrain_kind;

typedef enum fs_step_pattern { FS_STEPS_UP = 0, FS_STEPS_DOWN = 1, FS_STEPS_UP_DOWN = 2, FS_STEPS_DOWN_UP = 3 } fs_step_pattern;

enum { FS_MAX_ROCKS = 256 };

typedef struct fs_terrain_def {
    int kind;                       /* fs_terrain_kind */
    double slope_deg;               /* slope: rising toward +x */
    double step_rise_m, step_run_m, step_start_x_m;
    int step_count, step_pattern;   /* stepped */
    double rms_m, correlation_m, resolution_m; /* rough (and the base of complex_uneven) */
    int seed;
    double patch_x_min_m, patch_x_max_m; /* the roughness only between these x, faded in over
                                            one correlation length */
    double bump_height_m, bump_radius_m, bump_x_m, bump_y_m; /* simply_uneven */
    int rock_count;                 /* complex_uneven */
    double rock_height_min_m, rock_height_max_m, rock_radius_min_m, rock_radius_max_m, rock_field_m;
    char heightmap_path[FS_PATH_MAX];
    double heightmap_scale_m, heightmap_base_m, heightmap_pixel_m, heightmap_x0_m, heightmap_y0_m;
    double mu, restitution, stiffness_N_per_m, damping_Ns_per_m; /* the ground's material */
    double sink_bound_m;       /* deepest a landed foot may end in it (fs_outcome.h) */
    fs_soil_def soil;          /* [soil], [bekker], [rft]: a deformable layer over this ground (fs_soil.h) */
} fs_terrain_def;

typedef struct fs_rock { double x, y, height, radius; } fs_rock;

typedef struct fs_terrain {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];
    fs_terrain_def def;
    fs_rock rock[FS_MAX_ROCKS];     /* complex_uneven: drawn from the seed */
    int img_w, img_h;               /* heightmap: the image, heights in m, row 0 at the largest y */
    double *img;
    char placed_at[2 * FS_PATH_MAX + 200]; /* heightmap: where x0_m and y0_m came from, for messages
                                              ("x0_m from FILE:LINE, y0_m from --set heightmap.y0_m") */
    /* the cropped lattice: nx * ny samples, z[j * nx + i] at (x0 + i dx, y0 + j dx) */
    int nx, ny;
    long i0, j0;                    /* lattice index of sample (0, 0) */
    double x0, y0, dx;
    double *z;
    double zmin, zmax;
    /* the highest sample of each block of FS_TERRAIN_BLOCK x FS_TERRAIN_BLOCK samples, bx * by of
     * them, zblock[b * bx + a] over samples [a B, a B + B) x [b B, b B + B): a search for samples
     * above a height skips the blocks below it */
    int bx, by;
    double *zblock;
    /* with a soil: the rectangle its grid covers, [xmin, xmax, ymin, ymax] (fs_soil_region), m */
    double soil_region[4];
    char soil_grid_at[FS_PATH_MAX + 80]; /* with a soil: where [soil] grid_m came from, for the grid's
                                            memory cap ("FILE:LINE", "--set soil.grid_m", ...) */
    char soil_section_at[FS_PATH_MAX + 80]; /* with a soil: where its section ([soil] x_min_m, else x_max_m) came from */
} fs_terrain;

enum { FS_TERRAIN_BLOCK = 8 };

extern const fs_key fs_terrain_keys[];
extern const int fs_terrain_nkeys;

/* Reads and checks a terrain file with overrides; reads its heightmap image. Nothing is sampled
 * until fs_terrain_crop. An empty path gives the defaults: a flat plane of default material. */
fs_status fs_terrain_load(const char *path, const char *const *overrides, int noverrides, fs_terrain *t,
                          fs_error *err);

/* Samples a heightfield kind over [xmin, xmax] x [ymin, ymax] (grown to whole lattice cells);
 * a no-op for planes and steps. Refuses a region of more than FS_TERRAIN_MAX_SAMPLES samples. */
enum { FS_TERRAIN_MAX_SAMPLES = 4000000 };
fs_status fs_terrain_crop(fs_terrain *t, double xmin, double xmax, double ymin, double ymax, fs_error *err);

/* Derives again what t's definition draws (complex_uneven's rocks, from def.seed) after the
 * definition was edited in code, first checking the relations between its keys that loading
 * checks (FS_BAD_INPUT, naming the keys "set in code"); the sampled heights follow at the next
 * fs_terrain_crop. Reads no file (a heightmap's image stays the one loaded). */
fs_status fs_terrain_redraw(fs_terrain *t, fs_error *err);

/* dst becomes a copy of src that owns its own image and samples (FS_NO_MEMORY, dst empty, if they
 * cannot be had). */
fs_status fs_terrain_copy(fs_terrain *dst, const fs_terrain *src, fs_error *err);

/* The surface over one lattice cell whose corners stand at z00 (its origin), z10 (+x), z01 (+y)
 * and z11, at fractions fx and fy (0 to 1) across it: two triangles split along the rising
 * diagonal, as ODE splits a heightfield's cell. slope, unless NULL, gets the triangle's rise per
 * cell along x and y. Every evaluation of the lattice's surface goes through this. */
double fs_terrain_cell(double z00, double z10, double z01, double z11, double fx, double fy, double slope[2]);

/* The surface ODE collides with, at (x, y), m. */
double fs_terrain_height(const fs_terrain *t, double x, double y);

/* The height function the lattice samples (for planes and steps, the same as the surface). */
double fs_terrain_function(const fs_terrain *t, double x, double y);

int fs_terrain_is_heightfield(const fs_terrain *t);

/* For a heightmap, the image's extent (x0, x1, y0, y1, m: the first and last pixel centres) and the
 * part of region [xmin, xmax, ymin, ymax] (by area, 0 to 1) that lies beyond it, where the image's
 * edge heights are drawn out and the ground is not the data; 0 for the generated kinds (their
 * height function covers the plane), with extent left untouched. */
double fs_terrain_outside(const fs_terrain *t, const double region[4], double extent[4]);

void fs_terrain_free(fs_terrain *t);

/* Whether a section belongs to terrain files (for routing --set overrides). */
int fs_terrain_has_section(const char *section, size_t len);

/* The colour fs_terrain_map gives a height a fraction u (0 lowest, 1 highest) of the way up, on
 * level ground (unshaded), 0-255 per channel: for a colour bar. */
void fs_terrain_map_colour(double u, double rgb[3]);

#endif

/* A shaded top-down picture of the surface over region [xmin, xmax, ymin, ymax]: heights as
 * colours (low blue-green to high sand), lit from the north-west; when outline is not NULL, the
 * rectangle [xmin, xmax, ymin, ymax] it gives is drawn in white (a footprint). rgb holds w*h*3
 * bytes, row 0 at the largest y. Returns the lowest and highest height drawn in zrange; FS_NO_MEMORY
 * (rgb not filled) when the heights' memory is refused. */
fs_status fs_terrain_map(const fs_terrain *t, const double region[4], const double *outline, int w, int h,
                         unsigned char *rgb, double zrange[2], fs_error *err);
