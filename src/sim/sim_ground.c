/* sim_ground.c: a terrain built as ODE geoms: planes, boxes or a heightfield. */
#include "sim_ground.h"

#include <math.h>
#include <stdlib.h>

#define DEG (M_PI / 180.0)


/* One tile: the samples [i0, i0 + nx) x [j0, j0 + ny) of the terrain's lattice, copied in ODE's
 * order into z (ODE reads them as doubles: no callback a sample). */
typedef struct tile {
    int i0, j0, nx, ny;
    double *z;
    dHeightfieldDataID data;
} tile;

struct fs_ground {
    int ntiles;
    double *samples; /* every tile's z, one block */
    tile tiles[];
};

static void build_tile(dSpaceID space, const fs_terrain *t, tile *k)
{
    double w = (k->nx - 1) * t->dx, d = (k->ny - 1) * t->dx, lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < k->ny; j++)
        for (int i = 0; i < k->nx; i++) {
            double z = t->z[(size_t)(k->j0 + j) * t->nx + k->i0 + i];
            lo = fmin(lo, z);
            hi = fmax(hi, z);
            /* ODE's local z runs toward world -y: its row ny - 1 - j is our row j */
            k->z[(size_t)(k->ny - 1 - j) * k->nx + i] = z;
        }
    k->data = dGeomHeightfieldDataCreate();
    /* a thick base below the lowest sample, so nothing passes under the surface */
    double thickness = 0.05 + (t->zmax - t->zmin);
    /* scale 1 and offset 0: ODE's height h * 1 + 0 is the sample itself, as the callback gave it */
    dGeomHeightfieldDataBuildDouble(k->data, k->z, 0, w, d, k->nx, k->ny, 1.0, 0.0, thickness, 0);
    dGeomHeightfieldDataSetBounds(k->data, lo, hi);
    dGeomID hf = dCreateHeightfield(space, k->data, 1);
    /* ODE's heightfield is y-up: turn its y to world z (and its z to world -y) */
    dMatrix3 R = {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0};
    dGeomSetRotation(hf, R);
    dGeomSetPosition(hf, t->x0 + (k->i0 + 0.5 * (k->nx - 1)) * t->dx, t->y0 + (k->j0 + 0.5 * (k->ny - 1)) * t->dx, 0);
}

/* Samples along one side of the tile that starts at sample first, of a lattice of n samples. */
static int tile_side(int first, int cells, int n) { return (first + cells < n - 1 ? cells : n - 1 - first) + 1; }

static fs_ground *build_heightfield(dSpaceID space, const fs_terrain *t, int cells, int *ok)
{
    int tx = (t->nx - 1 + cells - 1) / cells, ty = (t->ny - 1 + cells - 1) / cells;
    fs_ground *g = malloc(sizeof *g + (size_t)tx * ty * sizeof g->tiles[0]);
    /* tiles share their edge samples: at most (cells + 1)^2 each */
    size_t nsamples = 0;
    for (int b = 0; b < ty; b++)
        for (int a = 0; a < tx; a++)
            nsamples += (size_t)tile_side(a * cells, cells, t->nx) * tile_side(b * cells, cells, t->ny);
    double *samples = malloc(nsamples * sizeof *samples);
    if (!g || !samples) {
        free(g);
        free(samples);
        *ok = 0;
        return NULL;
    }
    g->ntiles = 0;
    g->samples = samples;
    for (int b = 0; b < ty; b++)
        for (int a = 0; a < tx; a++) {
            tile *k = &g->tiles[g->ntiles++];
            k->i0 = a * cells;
            k->j0 = b * cells;
            k->nx = tile_side(k->i0, cells, t->nx);
            k->ny = tile_side(k->j0, cells, t->ny);
            k->z = samples;
            samples += (size_t)k->nx * k->ny;
            build_tile(space, t, k);
        }
    return g;
}

void fs_ground_destroy(fs_ground *g)
{
    if (!g)
        return;
    for (int i = 0; i < g->ntiles; i++)
        dGeomHeightfieldDataDestroy(g->tiles[i].data);
    free(g->samples);
    free(g);
}

/* Steps as boxes (sharp edges) on a plane at the lowest level. */
static void build_steps(dSpaceID space, const fs_terrain *t)
{
    const fs_terrain_def *d = &t->def;
    const double far = 100.0; /* m: the steps' ends and sides reach beyond any trial */
    int k = d->step_pattern == FS_STEPS_UP_DOWN ? 2 * d->step_count : d->step_count;
    double base = d->step_pattern == FS_STEPS_DOWN ? -d->step_rise_m * d->step_count : 0;
    dGeomID plane = dCreatePlane(space, 0, 0, 1, base);
    (void)plane;
    for (int i = -1; i <= k; i++) {
        double x0 = i < 0 ? d->step_start_x_m - far : d->step_start_x_m + i * d->step_run_m;
        double x1 = i < 0 ? d->step_start_x_m : i == k ? x0 + far : x0 + d->step_run_m;
        double level = fs_terrain_height(t, 0.5 * (x0 + x1), 0);
        if (level <= base)
            continue;
        double depth = level - base + 0.05;
        dGeomID box = dCreateBox(space, x1 - x0, 2 * far, depth);
        dGeomSetPosition(box, 0.5 * (x0 + x1), 0, level - 0.5 * depth);
    }
}

fs_ground *fs_ground_build(dSpaceID space, const fs_terrain *t, int tile_cells, int *ok)
{
    *ok = 1;
    switch (t->def.kind) {
    case FS_TERRAIN_FLAT: dCreatePlane(space, 0, 0, 1, 0); return NULL;
    case FS_TERRAIN_SLOPE: {
        double a = t->def.slope_deg * DEG;
        dCreatePlane(space, -sin(a), 0, cos(a), 0);
        return NULL;
    }
    case FS_TERRAIN_STEPPED: build_steps(space, t); return NULL;
    default: return build_heightfield(space, t, tile_cells, ok);
    }
}
