/* model_terrain.c: terrain files, their height functions, and the lattice cut to a region. */
#include "footsim/model/fs_terrain.h"

#include "footsim/io/fs_png.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEG (M_PI / 180.0)
#define F(member) offsetof(fs_terrain_def, member)
#define NUM(sec, name, member, lo, hi, flags, unit, dflt, help) \
    {sec, name, FS_KEY_NUMBER, F(member), lo, hi, flags, 0, NULL, unit, dflt, help}
#define INT(sec, name, member, lo, hi, dflt, help) \
    {sec, name, FS_KEY_INTEGER, F(member), lo, hi, 0, 0, NULL, "", dflt, help}
#define POS FS_KEY_OPEN_MIN

const fs_key fs_terrain_keys[] = {
    {"terrain", "kind", FS_KEY_CHOICE, F(kind), 0, 0, 0, 0,
     "flat|slope|stepped|rough|simply_uneven|complex_uneven|heightmap", "", "flat", "what the ground is"},
    NUM("slope", "angle_deg", slope_deg, -60, 60, 0, "deg", "10", "slope: the plane rises toward +x at this angle"),
    NUM("stepped", "rise_m", step_rise_m, 0, 0.5, POS, "m", "0.01", "height of each step"),
    NUM("stepped", "run_m", step_run_m, 0, 10, POS, "m", "0.05", "length of each step along x"),
    NUM("stepped", "start_x_m", step_start_x_m, -10, 10, 0, "m", "0.03", "where the first step's edge is"),
    INT("stepped", "count", step_count, 1, 1000, "3", "number of steps (each way for up_down)"),
    {"stepped", "pattern", FS_KEY_CHOICE, F(step_pattern), 0, 0, 0, 0, "up|down|up_down|down_up", "", "up",
     "steps rising along +x, falling, rising then falling, or falling then rising (a pit: with [soil] over it, "
     "a soil section flush with the ground around it)"},
    NUM("rough", "rms_m", rms_m, 0, 1, 0, "m", "0.003", "RMS height of the Gaussian-correlated roughness"),
    NUM("rough", "correlation_m", correlation_m, 0, 10, POS, "m", "0.015", "distance at which the height correlation falls to 1/e"),
    NUM("rough", "resolution_m", resolution_m, 1e-4, 1, 0, "m", "0.001", "lattice spacing of the heightfield"),
    INT("rough", "seed", seed, 0, 2147483647, "1", "random seed of the roughness and the rocks"),
    NUM("rough", "patch_x_min_m", patch_x_min_m, -1e3, 1e3, 0, "m", "-1000", "the roughness starts here along x (a rough section)"),
    NUM("rough", "patch_x_max_m", patch_x_max_m, -1e3, 1e3, 0, "m", "1000", "and ends here"),
    NUM("bump", "height_m", bump_height_m, 0, 1, POS, "m", "0.008", "simply_uneven: height of the one rock"),
    NUM("bump", "radius_m", bump_radius_m, 0, 1, POS, "m", "0.015", "simply_uneven: its radius (a cosine-squared cap)"),
    NUM("bump", "x_m", bump_x_m, -10, 10, 0, "m", "0.06", "simply_uneven: its centre"),
    NUM("bump", "y_m", bump_y_m, -10, 10, 0, "m", "-0.015", "simply_uneven: its centre"),
    INT("rocks", "count", rock_count, 0, FS_MAX_ROCKS, "40", "complex_uneven: rocks on the rough base"),
    NUM("rocks", "height_min_m", rock_height_min_m, 0, 1, 0, "m", "0.003", "lowest rock"),
    NUM("rocks", "height_max_m", rock_height_max_m, 0, 1, 0, "m", "0.012", "highest rock"),
    NUM("rocks", "radius_min_m", rock_radius_min_m, 0, 1, POS, "m", "0.005", "smallest rock radius"),
    NUM("rocks", "radius_max_m", rock_radius_max_m, 0, 1, POS, "m", "0.012", "largest rock radius"),
    NUM("rocks", "field_m", rock_field_m, 0, 100, POS, "m", "0.12", "rocks lie within +-field_m of the origin in x and y"),
    {"heightmap", "file", FS_KEY_PATH, F(heightmap_path), 0, 0, 0, 0, NULL, "", "",
     "8- or 16-bit grayscale PNG, relative to the terrain file; row 0 is the largest y"},
    NUM("heightmap", "scale_m", heightmap_scale_m, 0, 10, POS, "m", "0.02", "height of a white pixel above a black one"),
    NUM("heightmap", "base_m", heightmap_base_m, -10, 10, 0, "m", "0", "height of a black pixel"),
    NUM("heightmap", "pixel_m", heightmap_pixel_m, 1e-4, 10, 0, "m", "0.002", "distance between pixel centres"),
    NUM("heightmap", "x0_m", heightmap_x0_m, -100, 100, 0, "m", "-0.1", "x of the left column"),
    NUM("heightmap", "y0_m", heightmap_y0_m, -100, 100, 0, "m", "-0.1", "y of the bottom row"),
    NUM("material", "mu", mu, 0, 10, 0, "", "1.0", "friction coefficient (combined with the sole's as sqrt(mu_sole mu_ground))"),
    NUM("material", "restitution", restitution, 0, 1, 0, "", "0", "bounce: the share of normal speed kept after impact"),
    NUM("material", "stiffness_N_per_m", stiffness_N_per_m, 0, 1e12, POS, "N/m", "1e8", "contact stiffness (in series with the sole's)"),
    NUM("material", "damping_Ns_per_m", damping_Ns_per_m, 0, 1e9, 0, "N s/m", "2e4", "contact damping (in series with the sole's)"),
    NUM("material", "sink_bound_m", sink_bound_m, 0, 1, POS, "m", "1e-3",
        "a landing fell when a foot shape ends deeper than this in the ground (soft ground states its own)"),
    /* a soil laid over this ground (fs_soil.h, docs/soil.md) */
    {"soil", "model", FS_KEY_CHOICE, F(soil.model), 0, 0, 0, 0, "none|bekker|rft", "", "none",
     "none: the ground is rigid; bekker: Bekker-Wong/Janosi terramechanics (as Chrono's SCM); rft: resistive force "
     "theory for granular media (Li, Zhang & Goldman 2013)"},
    NUM("soil", "depth_m", soil.depth_m, 0, 10, POS, "m", "0.1", "thickness of the soil over the terrain, which is its rigid bedrock"),
    NUM("soil", "grid_m", soil.grid_m, 1e-4, 0.05, 0, "m", "5e-4",
        "the finest spacing of the soil's nodes: each shape is met on it or on a power-of-two multiple of it "
        "(nodes_across, coarse_grid_m; docs/soil.md, Grid spacing)"),
    NUM("soil", "coarse_grid_m", soil.coarse_grid_m, 0, 0.05, 0, "m", "0.008",
        "the widest spacing a shape's nodes may have (the flat sole's; a power-of-two multiple of grid_m, at most "
        "16 times it; 0: every shape on grid_m; docs/soil.md, Grid spacing)"),
    INT("soil", "nodes_across", soil.nodes_across, 1, 256, "6",
        "each shape is met on the widest power-of-two multiple of grid_m (up to coarse_grid_m) that leaves at least "
        "this many nodes across its narrowest side (docs/soil.md, Grid spacing)"),
    NUM("soil", "margin_m", soil.margin_m, 0, 1, 0, "m", "0.03", "the grid covers the region the feet can reach plus this"),
    NUM("soil", "x_min_m", soil.x_min_m, -1e3, 1e3, 0, "m", "-1000",
        "the layer starts here along x (a soil section of the path: beyond x_min_m..x_max_m the ground is the bedrock, "
        "rigid; docs/soil.md, A soil section)"),
    NUM("soil", "x_max_m", soil.x_max_m, -1e3, 1e3, 0, "m", "1000", "and ends here"),
    NUM("soil", "b_min_m", soil.b_min_m, 0, 1, POS, "m", "0.002",
        "Bekker's b (twice a patch's area over its perimeter) is taken at least this (a patch as it first forms)"),
    NUM("soil", "slip_speed_m_per_s", soil.slip_speed_m_per_s, 0, 10, POS, "m/s", "1e-3",
        "shear and drag act fully above this slip speed and in proportion below it (a regularisation, a choice)"),
    INT("soil", "max_nodes", soil.max_nodes, 1000, 50000000, "4000000",
        "the most nodes the grid may cover (its index: 4 bytes a tile of 256 nodes; a tile a foot has reached: 88 bytes a node)"),
    NUM("bekker", "n", soil.n, 0, 5, POS, "", "1.1", "sinkage exponent n"),
    NUM("bekker", "k_c_N_per_m_n1", soil.k_c_N_per_m_n1, 0, 1e12, 0, "N/m^(n+1)", "0", "cohesive modulus k_c"),
    NUM("bekker", "k_phi_N_per_m_n2", soil.k_phi_N_per_m_n2, 0, 1e12, 0, "N/m^(n+2)", "2e6", "frictional modulus k_phi"),
    NUM("bekker", "cohesion_Pa", soil.cohesion_Pa, 0, 1e9, 0, "Pa", "50", "cohesion c"),
    NUM("bekker", "friction_deg", soil.friction_deg, 0, 90, FS_KEY_OPEN_MAX, "deg", "20", "internal friction angle phi"),
    NUM("bekker", "shear_K_m", soil.shear_K_m, 0, 1, POS, "m", "0.01", "Janosi's shear deformation modulus K"),
    NUM("bekker", "K_e_Pa_per_m", soil.K_e_Pa_per_m, 0, 1e13, POS, "Pa/m", "5e7", "elastic unloading and reloading slope K_e"),
    NUM("bekker", "damping_Pa_s_per_m", soil.damping_Pa_s_per_m, 0, 1e9, 0, "Pa s/m", "0",
        "pressure added per sinking speed (Chrono's R)"),
    NUM("rft", "A00", soil.rft_coeff[0], -10, 10, 0, "", "0.206", "generic alpha_z coefficient (Li et al. 2013)"),
    NUM("rft", "A10", soil.rft_coeff[1], -10, 10, 0, "", "0.169", "generic alpha_z coefficient"),
    NUM("rft", "B11", soil.rft_coeff[2], -10, 10, 0, "", "0.212", "generic alpha_z coefficient"),
    NUM("rft", "B01", soil.rft_coeff[3], -10, 10, 0, "", "0.358", "generic alpha_z coefficient"),
    NUM("rft", "Bm11", soil.rft_coeff[4], -10, 10, 0, "", "0.055", "generic alpha_z coefficient B-11"),
    NUM("rft", "C11", soil.rft_coeff[5], -10, 10, 0, "", "-0.124", "generic alpha_x coefficient"),
    NUM("rft", "C01", soil.rft_coeff[6], -10, 10, 0, "", "0.253", "generic alpha_x coefficient"),
    NUM("rft", "Cm11", soil.rft_coeff[7], -10, 10, 0, "", "0.007", "generic alpha_x coefficient C-11"),
    NUM("rft", "D10", soil.rft_coeff[8], -10, 10, 0, "", "0.088", "generic alpha_x coefficient"),
    NUM("rft", "zeta_N_per_m3", soil.zeta_N_per_m3, 0, 1e10, 0, "N/m^3", "0",
        "the medium's scale: alpha = zeta times the generic fit (one plate test); an rft soil must give it"),
    NUM("rft", "density_kg_per_m3", soil.density_kg_per_m3, 0, 1e5, 0, "kg/m^3", "0",
        "bulk density of the medium, for the inertial term; an rft soil must give it"),
    NUM("rft", "inertial_lambda", soil.inertial_lambda, 0, 100, 0, "", "1",
        "the inertial pressure is lambda rho (v.n)^2 on an element moving into the medium (a choice, docs/soil.md)"),
    NUM("rft", "friction_mu", soil.friction_mu, 0, 10, 0, "", "0.4", "intruder-grain friction on the inertial pressure"),
};
const int fs_terrain_nkeys = (int)(sizeof fs_terrain_keys / sizeof fs_terrain_keys[0]);

int fs_terrain_has_section(const char *section, size_t len)
{
    for (int i = 0; i < fs_terrain_nkeys; i++)
        if (strlen(fs_terrain_keys[i].section) == len && !strncmp(fs_terrain_keys[i].section, section, len))
            return 1;
    return 0;
}

int fs_terrain_is_heightfield(const fs_terrain *t) { return t->def.kind >= FS_TERRAIN_ROUGH; }

/* ---- deterministic noise ------------------------------------------------------------------ */

/* A 64-bit mix (splitmix64's finaliser): the same on every machine. */
static uint64_t mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1) from a 64-bit key. */
static double unit(uint64_t key) { return (double)(mix(key) >> 11) * (1.0 / 9007199254740992.0); }

/* Unit-variance white noise at lattice node (i, j). */
static double white(int seed, long i, long j)
{
    uint64_t key = ((uint64_t)(uint32_t)seed << 40) ^ ((uint64_t)(uint32_t)i << 20) ^ (uint64_t)(uint32_t)j;
    key = mix(key ^ 0x9e3779b97f4a7c15ULL) ^ (uint64_t)(uint32_t)j * 0x632be59bd9b4e019ULL;
    return (2.0 * unit(key) - 1.0) * sqrt(3.0);
}

/* Gaussian kernel of the roughness: weights w[-r..r] (unnormalised exp(-k^2 dx^2 / (2 s^2))) with
 * s = correlation / 2, whose correlation exp(-d^2 / (4 s^2)) falls to 1/e at d = correlation. */
typedef struct kernel { int r; double w[1024]; double gain; } kernel;

static void make_kernel(const fs_terrain_def *d, kernel *k)
{
    double s = 0.5 * d->correlation_m / d->resolution_m;
    k->r = (int)ceil(3 * s);
    if (k->r > 511)
        k->r = 511;
    double sum2 = 0;
    for (int i = -k->r; i <= k->r; i++) {
        k->w[i + k->r] = exp(-0.5 * i * i / (s * s));
        sum2 += k->w[i + k->r] * k->w[i + k->r];
    }
    /* separable: the 2-D weights are products, so the output variance is (sum w^2)^2 */
    k->gain = d->rms_m / sum2;
}

/* 1 inside the rough section, 0 outside, linear over one correlation length at its ends. */
static double patch_window(const fs_terrain_def *d, double x)
{
    double ramp = d->correlation_m;
    double a = (x - d->patch_x_min_m) / ramp, b = (d->patch_x_max_m - x) / ramp;
    return fmin(1.0, fmax(0.0, fmin(a, b)));
}

/* Roughness on lattice rows j0..j0+ny-1, columns i0..i0+nx-1 into out (row-major). Each value
 * depends only on the noise around its own node, summed in a fixed order: any crop agrees. */
static fs_status rough_patch(const fs_terrain_def *d, long i0, long j0, int nx, int ny, double *out, fs_error *err)
{
    kernel k;
    make_kernel(d, &k);
    int r = k.r, wx = nx + 2 * r;
    double *rows = malloc((size_t)wx * ny * sizeof *rows);
    if (!rows)
        return fs_fail(err, FS_NO_MEMORY, "rough terrain: out of memory");
    /* filter along y first, for every column the x pass will need */
    for (int j = 0; j < ny; j++)
        for (int c = 0; c < wx; c++) {
            double s = 0;
            for (int q = -r; q <= r; q++)
                s += k.w[q + r] * white(d->seed, i0 - r + c, j0 + j + q);
            rows[(size_t)j * wx + c] = s;
        }
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            double s = 0;
            for (int p = -r; p <= r; p++)
                s += k.w[p + r] * rows[(size_t)j * wx + i + r + p];
            out[(size_t)j * nx + i] = k.gain * s * patch_window(d, (double)(i0 + i) * d->resolution_m);
        }
    free(rows);
    return FS_OK;
}

/* ---- height functions ---------------------------------------------------------------------- */

static double cap(double height, double radius, double dx, double dy)
{
    double r = sqrt(dx * dx + dy * dy);
    if (r >= radius)
        return 0;
    double c = cos(0.5 * M_PI * r / radius);
    return height * c * c;
}

static double rocks_height(const fs_terrain *t, double x, double y)
{
    double h = 0;
    for (int i = 0; i < t->def.rock_count; i++) {
        const fs_rock *k = &t->rock[i];
        h = fmax(h, cap(k->height, k->radius, x - k->x, y - k->y));
    }
    return h;
}

static double step_level(const fs_terrain_def *d, double x)
{
    double n = floor((x - d->step_start_x_m) / d->step_run_m) + 1;
    if (n < 0)
        n = 0;
    if (d->step_pattern == FS_STEPS_UP_DOWN || d->step_pattern == FS_STEPS_DOWN_UP)
        n = n <= d->step_count ? n : fmax(0, 2.0 * d->step_count - n);
    else if (n > d->step_count)
        n = d->step_count;
    return (d->step_pattern == FS_STEPS_DOWN || d->step_pattern == FS_STEPS_DOWN_UP ? -1 : 1) * d->step_rise_m * n;
}

static double image_height(const fs_terrain *t, double x, double y)
{
    const fs_terrain_def *d = &t->def;
    double u = (x - d->heightmap_x0_m) / d->heightmap_pixel_m;
    double v = (t->img_h - 1) - (y - d->heightmap_y0_m) / d->heightmap_pixel_m; /* row, from the top */
    u = fmin(fmax(u, 0), t->img_w - 1);
    v = fmin(fmax(v, 0), t->img_h - 1);
    int c = (int)fmin(floor(u), t->img_w - 2), r = (int)fmin(floor(v), t->img_h - 2);
    double fu = u - c, fv = v - r;
    const double *p = t->img + (size_t)r * t->img_w + c;
    double top = p[0] + fu * (p[1] - p[0]), bottom = p[t->img_w] + fu * (p[t->img_w + 1] - p[t->img_w]);
    return d->heightmap_base_m + d->heightmap_scale_m * (top + fv * (bottom - top));
}

/* Everything but the roughness, which needs its lattice (rough_patch). */
static double smooth_part(const fs_terrain *t, double x, double y)
{
    const fs_terrain_def *d = &t->def;
    switch (d->kind) {
    case FS_TERRAIN_SLOPE: return x * tan(d->slope_deg * DEG);
    case FS_TERRAIN_STEPPED: return step_level(d, x);
    case FS_TERRAIN_SIMPLY_UNEVEN: return cap(d->bump_height_m, d->bump_radius_m, x - d->bump_x_m, y - d->bump_y_m);
    case FS_TERRAIN_COMPLEX_UNEVEN: return rocks_height(t, x, y);
    case FS_TERRAIN_HEIGHTMAP: return image_height(t, x, y);
    default: return 0;
    }
}

static int has_roughness(const fs_terrain *t)
{
    return (t->def.kind == FS_TERRAIN_ROUGH || t->def.kind == FS_TERRAIN_COMPLEX_UNEVEN) && t->def.rms_m > 0;
}

/* The lattice origin: 0 for generated terrains, the image's first pixel for a heightmap. */
static void lattice(const fs_terrain *t, double *ox, double *oy, double *dx)
{
    int img = t->def.kind == FS_TERRAIN_HEIGHTMAP;
    *ox = img ? t->def.heightmap_x0_m : 0;
    *oy = img ? t->def.heightmap_y0_m : 0;
    *dx = img ? t->def.heightmap_pixel_m : t->def.resolution_m;
}

double fs_terrain_cell(double z00, double z10, double z01, double z11, double fx, double fy, double slope[2])
{
    /* the lower triangle (0,0), (1,0), (1,1) or the upper one (0,0), (1,1), (0,1) */
    double sx = fx >= fy ? z10 - z00 : z11 - z01, sy = fx >= fy ? z11 - z10 : z01 - z00;
    if (slope)
        slope[0] = sx, slope[1] = sy;
    return fx >= fy ? z00 + sx * fx + sy * fy : z00 + sy * fy + sx * fx;
}

double fs_terrain_function(const fs_terrain *t, double x, double y)
{
    double h = smooth_part(t, x, y);
    if (!has_roughness(t))
        return h;
    /* roughness between lattice nodes: the same triangles as the surface */
    double ox, oy, dx;
    lattice(t, &ox, &oy, &dx);
    long i = (long)floor((x - ox) / dx), j = (long)floor((y - oy) / dx);
    double z[4];
    fs_error err;
    if (rough_patch(&t->def, i, j, 2, 2, z, &err) != FS_OK)
        return NAN;
    double fx = (x - ox) / dx - i, fy = (y - oy) / dx - j;
    return h + fs_terrain_cell(z[0], z[1], z[2], z[3], fx, fy, NULL);
}

double fs_terrain_height(const fs_terrain *t, double x, double y)
{
    if (!fs_terrain_is_heightfield(t) || !t->z)
        return fs_terrain_function(t, x, y);
    /* position on the world lattice first, so that every crop gives the same bits */
    double ox, oy, dx;
    lattice(t, &ox, &oy, &dx);
    double gi = (x - ox) / dx, gj = (y - oy) / dx;
    double fi = gi - t->i0, fj = gj - t->j0;
    if (fi < 0 || fj < 0 || fi > t->nx - 1 || fj > t->ny - 1)
        return fs_terrain_function(t, x, y);
    int i = (int)fmin(floor(fi), t->nx - 2), j = (int)fmin(floor(fj), t->ny - 2);
    double fx = gi - (double)(t->i0 + i), fy = gj - (double)(t->j0 + j);
    const double *z = t->z + (size_t)j * t->nx + i;
    return fs_terrain_cell(z[0], z[1], z[t->nx], z[t->nx + 1], fx, fy, NULL);
}

/* The highest sample of each block (fs_terrain.h). */
static fs_status block_tops(fs_terrain *t, fs_error *err)
{
    const int B = FS_TERRAIN_BLOCK;
    t->bx = (t->nx + B - 1) / B;
    t->by = (t->ny + B - 1) / B;
    t->zblock = malloc((size_t)t->bx * t->by * sizeof *t->zblock);
    if (!t->zblock)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for %d x %d samples", t->path, t->nx, t->ny);
    for (int k = 0; k < t->bx * t->by; k++)
        t->zblock[k] = -INFINITY;
    for (int j = 0; j < t->ny; j++)
        for (int i = 0; i < t->nx; i++) {
            double *top = &t->zblock[(size_t)(j / B) * t->bx + i / B];
            *top = fmax(*top, t->z[(size_t)j * t->nx + i]);
        }
    return FS_OK;
}

fs_status fs_terrain_crop(fs_terrain *t, double xmin, double xmax, double ymin, double ymax, fs_error *err)
{
    if (!fs_terrain_is_heightfield(t))
        return FS_OK;
    double ox, oy, dx;
    lattice(t, &ox, &oy, &dx);
    /* lattice indices must fit a long (and the hash of a rough terrain's cells): refuse far regions */
    const double far = 1e9;
    if (!(fabs((xmin - ox) / dx) < far && fabs((xmax - ox) / dx) < far && fabs((ymin - oy) / dx) < far &&
          fabs((ymax - oy) / dx) < far))
        return fs_fail(err, FS_BAD_INPUT, "%s: the region x %.3g..%.3g m, y %.3g..%.3g m is too far from the terrain's "
                       "origin (over %.0e cells of %.3g m); use points nearer the origin", t->path, xmin, xmax, ymin,
                       ymax, far, dx);
    long i0 = (long)floor((xmin - ox) / dx), i1 = (long)ceil((xmax - ox) / dx);
    long j0 = (long)floor((ymin - oy) / dx), j1 = (long)ceil((ymax - oy) / dx);
    if (i1 - i0 < 1)
        i1 = i0 + 1;
    if (j1 - j0 < 1)
        j1 = j0 + 1;
    double n = (double)(i1 - i0 + 1) * (double)(j1 - j0 + 1);
    if (n > FS_TERRAIN_MAX_SAMPLES)
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: the region %.3g x %.3g m at resolution %.3g m needs %.3g samples (at most %d); use a "
                       "coarser resolution_m or a smaller region",
                       t->path, xmax - xmin, ymax - ymin, dx, n, FS_TERRAIN_MAX_SAMPLES);
    free(t->z);
    free(t->zblock);
    t->zblock = NULL;
    t->nx = (int)(i1 - i0 + 1);
    t->ny = (int)(j1 - j0 + 1);
    t->i0 = i0;
    t->j0 = j0;
    t->x0 = ox + i0 * dx;
    t->y0 = oy + j0 * dx;
    t->dx = dx;
    t->z = calloc((size_t)t->nx * t->ny, sizeof *t->z);
    if (!t->z)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for %d x %d samples", t->path, t->nx, t->ny);
    if (has_roughness(t)) {
        fs_status s = rough_patch(&t->def, i0, j0, t->nx, t->ny, t->z, err);
        if (s != FS_OK)
            return s;
    }
    t->zmin = INFINITY;
    t->zmax = -INFINITY;
    for (int j = 0; j < t->ny; j++)
        for (int i = 0; i < t->nx; i++) {
            double *z = &t->z[(size_t)j * t->nx + i];
            *z += smooth_part(t, ox + (double)(i0 + i) * dx, oy + (double)(j0 + j) * dx);
            t->zmin = fmin(t->zmin, *z);
            t->zmax = fmax(t->zmax, *z);
        }
    return block_tops(t, err);
}

/* ---- loading ------------------------------------------------------------------------------- */

static void draw_rocks(fs_terrain *t)
{
    const fs_terrain_def *d = &t->def;
    for (int i = 0; i < d->rock_count; i++) {
        uint64_t base = ((uint64_t)(uint32_t)d->seed << 32) ^ ((uint64_t)i << 3) ^ 0x5bd1e995ULL;
        fs_rock *k = &t->rock[i];
        k->x = (2 * unit(base + 1) - 1) * d->rock_field_m;
        k->y = (2 * unit(base + 2) - 1) * d->rock_field_m;
        k->height = d->rock_height_min_m + unit(base + 3) * (d->rock_height_max_m - d->rock_height_min_m);
        k->radius = d->rock_radius_min_m + unit(base + 4) * (d->rock_radius_max_m - d->rock_radius_min_m);
    }
}

static fs_status check_terrain(const fs_terrain *t, const fs_config *cfg, fs_error *err)
{
    const fs_terrain_def *d = &t->def;
    char where[FS_PATH_MAX + 80];
    if (d->kind == FS_TERRAIN_COMPLEX_UNEVEN && d->rock_height_max_m < d->rock_height_min_m)
        return fs_fail(err, FS_BAD_INPUT, "%s: height_max_m is below height_min_m; make it at least that",
                       fs_config_where(cfg, "rocks", "height_max_m", where, sizeof where));
    if (d->kind == FS_TERRAIN_COMPLEX_UNEVEN && d->rock_radius_max_m < d->rock_radius_min_m)
        return fs_fail(err, FS_BAD_INPUT, "%s: radius_max_m is below radius_min_m; make it at least that",
                       fs_config_where(cfg, "rocks", "radius_max_m", where, sizeof where));
    if (d->kind == FS_TERRAIN_HEIGHTMAP && !d->heightmap_path[0])
        return fs_fail(err, FS_BAD_INPUT, "%s: a heightmap terrain needs [heightmap] file = a grayscale PNG", t->path);
    if (d->patch_x_max_m <= d->patch_x_min_m)
        return fs_fail(err, FS_BAD_INPUT, "%s: patch_x_max_m is not above patch_x_min_m; make the section longer",
                       fs_config_where(cfg, "rough", "patch_x_max_m", where, sizeof where));
    if (has_roughness(t) && d->correlation_m / d->resolution_m > 300)
        return fs_fail(err, FS_BAD_INPUT,
                       "%s: correlation_m is %.3g lattice cells; at most 300: use a coarser resolution_m",
                       fs_config_where(cfg, "rough", "correlation_m", where, sizeof where),
                       d->correlation_m / d->resolution_m);
    return fs_soil_check(&d->soil, cfg, t->path, err);
}

fs_status fs_terrain_load(const char *path, const char *const *overrides, int noverrides, fs_terrain *t,
                          fs_error *err)
{
    memset(t, 0, sizeof *t);
    snprintf(t->path, sizeof t->path, "%s", path);
    const char *slash = strrchr(path, '/');
    snprintf(t->name, sizeof t->name, "%s", slash ? slash + 1 : path);
    char *dot = strrchr(t->name, '.');
    if (dot && dot != t->name)
        *dot = 0;
    fs_config cfg = {.path = "(default flat terrain)"};
    fs_status s = FS_OK;
    if (*path)
        s = fs_config_load(&cfg, path, err);
    else
        snprintf(t->name, sizeof t->name, "flat");
    for (int i = 0; s == FS_OK && i < noverrides; i++)
        s = fs_config_override(&cfg, overrides[i], err);
    if (s == FS_OK)
        s = fs_config_bind(&cfg, fs_terrain_keys, fs_terrain_nkeys, &t->def, err);
    if (s == FS_OK)
        s = check_terrain(t, &cfg, err);
    if (s == FS_OK && t->def.kind == FS_TERRAIN_HEIGHTMAP) {
        char where[FS_PATH_MAX + 80];
        fs_config_where(&cfg, "heightmap", "file", where, sizeof where);
        s = fs_png_read_gray(t->def.heightmap_path, where, &t->img_w, &t->img_h, &t->img, err);
        char where_y[FS_PATH_MAX + 80];
        snprintf(t->placed_at, sizeof t->placed_at, "x0_m from %s, y0_m from %s",
                 fs_config_where(&cfg, "heightmap", "x0_m", where, sizeof where),
                 fs_config_where(&cfg, "heightmap", "y0_m", where_y, sizeof where_y));
    }
    if (s == FS_OK && t->def.soil.model != FS_SOIL_NONE) {
        fs_config_where(&cfg, "soil", "grid_m", t->soil_grid_at, sizeof t->soil_grid_at);
        fs_config_where(&cfg, "soil", fs_config_has(&cfg, "soil", "x_max_m") && !fs_config_has(&cfg, "soil", "x_min_m")
                                          ? "x_max_m" : "x_min_m", t->soil_section_at, sizeof t->soil_section_at);
    }
    fs_config_free(&cfg);
    if (s == FS_OK)
        draw_rocks(t);
    else
        fs_terrain_free(t);
    return s;
}

fs_status fs_terrain_redraw(fs_terrain *t, fs_error *err)
{
    fs_status s = check_terrain(t, NULL, err);
    if (s == FS_OK)
        draw_rocks(t);
    return s;
}

double fs_terrain_outside(const fs_terrain *t, const double region[4], double extent[4])
{
    if (t->def.kind != FS_TERRAIN_HEIGHTMAP || !t->img)
        return 0;
    const fs_terrain_def *d = &t->def;
    extent[0] = d->heightmap_x0_m, extent[1] = d->heightmap_x0_m + (t->img_w - 1) * d->heightmap_pixel_m;
    extent[2] = d->heightmap_y0_m, extent[3] = d->heightmap_y0_m + (t->img_h - 1) * d->heightmap_pixel_m;
    double w = region[1] - region[0], h = region[3] - region[2];
    double in_x = fmax(0, fmin(region[1], extent[1]) - fmax(region[0], extent[0]));
    double in_y = fmax(0, fmin(region[3], extent[3]) - fmax(region[2], extent[2]));
    return w > 0 && h > 0 ? 1 - in_x * in_y / (w * h) : 0;
}

/* A copy of n doubles, or NULL (for src NULL too). */
static double *dup_doubles(const double *src, size_t n)
{
    double *d = src && n ? malloc(n * sizeof *d) : NULL;
    if (d)
        memcpy(d, src, n * sizeof *d);
    return d;
}

fs_status fs_terrain_copy(fs_terrain *dst, const fs_terrain *src, fs_error *err)
{
    *dst = *src;
    dst->img = dup_doubles(src->img, (size_t)src->img_w * src->img_h);
    dst->z = dup_doubles(src->z, (size_t)src->nx * src->ny);
    dst->zblock = dup_doubles(src->zblock, (size_t)src->bx * src->by);
    if ((src->img && !dst->img) || (src->z && !dst->z) || (src->zblock && !dst->zblock)) {
        fs_terrain_free(dst);
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for a copy of the terrain", src->path);
    }
    return FS_OK;
}

void fs_terrain_free(fs_terrain *t)
{
    free(t->img);
    free(t->z);
    free(t->zblock);
    t->img = NULL;
    t->z = NULL;
    t->zblock = NULL;
}
