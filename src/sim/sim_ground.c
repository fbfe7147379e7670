/* sim_ground.c: a terrain built as ODE geoms: planes, boxes or a heightfield. */
#include "sim_ground.h"

#include "sim_internal.h"

#include <math.h>
#include <stdlib.h>


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

fs_ground *fs_ground_heightfield(dSpaceID space, const fs_terrain *t, int cells, int *ok)
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

fs_ground *fs_ground_build(dSpaceID space, const fs_model *m, const fs_terrain *t, int tile_cells, int *ok)
{
    *ok = 1;
    for (int i = 0; i < m->nplanes; i++) {
        const fs_model_plane *p = &m->plane[i];
        dCreatePlane(space, p->normal[0], p->normal[1], p->normal[2], p->offset_m);
    }
    for (int i = 0; i < m->nblocks; i++) {
        const fs_model_block *b = &m->block[i];
        dGeomID box = dCreateBox(space, b->size_m[0], b->size_m[1], b->size_m[2]);
        dGeomSetPosition(box, b->pos_m[0], b->pos_m[1], b->pos_m[2]);
    }
    return m->heightfield ? fs_ground_heightfield(space, t, tile_cells, ok) : NULL;
}

fs_ground *fs_ground_of_terrain(dSpaceID space, const fs_terrain *t, int tile_cells, int *ok)
{
    fs_model *m = calloc(1, sizeof *m);
    fs_error err;
    if (!m || fs_model_ground(m, t, &err) != FS_OK) {
        fs_model_free(m);
        *ok = 0;
        return NULL;
    }
    fs_ground *g = fs_ground_build(space, m, t, tile_cells, ok);
    fs_model_free(m);
    return g;
}
