/* cli_surface.c: a run's final soil surface written out (cli.h: cli_surface_*): the surface the soil
 * keeps at the end of a trial or walk, as a 16-bit heightmap PNG, a CSV in mm, its provenance
 * beside them and a terrain file that loads the PNG back as (rigid) heightmap ground. */
#include "cli.h"

#include "footsim/io/fs_output.h"
#include "footsim/io/fs_png.h"
#include "footsim/io/fs_provenance.h"
#include "footsim/sim/fs_sim_soil.h"

#include <cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Each call of the observer: the caller's own first (frames), then the soil's surface now, kept
 * in the memory of the last copy while the feet stay on the same tiles (the last call is the run's
 * end). */
static fs_status capture(void *user, const fs_sim *sim, fs_error *err)
{
    cli_surface *c = user;
    if (c->inner && c->inner->fn) {
        fs_status s = c->inner->fn(c->inner->user, sim, err);
        if (s != FS_OK)
            return s;
    }
    const fs_soil_grid *g = fs_sim_soil_grid(sim);
    if (!g)
        return FS_OK;
    c->material = fs_sim_scenario(sim)->terrain.def; /* the bedrock's material, for the terrain file */
    return fs_soil_grid_surface_copy(g, &c->s, err);
}

const fs_run_observer *cli_surface_observer(cli_surface *c, const fs_run_observer *inner)
{
    memset(c, 0, sizeof *c);
    c->inner = inner;
    /* with no frames asked for: called at the start and the end only */
    c->obs = (fs_run_observer){.interval_s = inner ? inner->interval_s : 1e9, .fn = capture, .user = c,
                               .profile = inner ? inner->profile : NULL};
    return &c->obs;
}

void cli_surface_free(cli_surface *c) { fs_soil_surface_free(&c->s); }

/* The PNG's heights: black at base (the lowest), white at base + scale. */
static void png_range(const fs_soil_surface *s, double *base, double *scale)
{
    double lo = INFINITY, hi = -INFINITY;
    for (long k = 0; k < (long)s->nx * s->ny; k++)
        lo = fmin(lo, s->z_m[k]), hi = fmax(hi, s->z_m[k]);
    *base = lo;
    *scale = hi - lo > 1e-6 ? hi - lo : 1e-3; /* a surface with no print: any scale reads it back */
}

static int fill_csv(FILE *f, const void *user)
{
    const fs_soil_surface *s = user;
    fputs("x_mm,y_mm,surface_mm,print_mm\r\n", f);
    for (int j = 0; j < s->ny; j++)
        for (int i = 0; i < s->nx; i++) {
            size_t k = (size_t)j * (size_t)s->nx + (size_t)i;
            fprintf(f, "%.6f,%.6f,%.6f,%.6f\r\n", (s->x0 + i * s->dx) * 1e3, (s->y0 + j * s->dx) * 1e3, s->z_m[k] * 1e3,
                    s->sink_m[k] * 1e3);
        }
    return !ferror(f);
}

typedef struct ini_of { const fs_soil_surface *s; const fs_terrain_def *m; double base, scale; } ini_of;

static int fill_ini(FILE *f, const void *user)
{
    const ini_of *o = user;
    fprintf(f, "; The soil's surface at the end of a footsim run (surface.png; surface.csv holds the same in mm,\n"
               "; surface.provenance.json what made it). Loaded back it is RIGID ground, a heightmap: the soil's\n"
               "; state (each node's yield pressure and slip) is not in it, and no soil is laid over it.\n"
               "[terrain]\nkind = heightmap\n\n[heightmap]\nfile = surface.png\nscale_m = %.17g\nbase_m = %.17g\n"
               "pixel_m = %.17g\nx0_m = %.17g\ny0_m = %.17g\n\n[material]\nmu = %.17g\nrestitution = %.17g\n"
               "stiffness_N_per_m = %.17g\ndamping_Ns_per_m = %.17g\n",
            o->scale, o->base, o->s->dx, o->s->x0, o->s->y0, o->m->mu, o->m->restitution, o->m->stiffness_N_per_m,
            o->m->damping_Ns_per_m);
    return !ferror(f);
}

int cli_surface_write(const cli_surface *c, const char *dir, const fs_provenance *prov, fs_error *err)
{
    const fs_soil_surface *s = &c->s;
    if (!s->nx)
        return FS_OK;
    double base, scale;
    png_range(s, &base, &scale);
    size_t n = (size_t)s->nx * (size_t)s->ny;
    unsigned short *v = malloc(n * sizeof *v);
    if (!v)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the surface's image");
    for (int r = 0; r < s->ny; r++) /* row 0 at the largest y */
        for (int i = 0; i < s->nx; i++) {
            double u = (s->z_m[(size_t)(s->ny - 1 - r) * (size_t)s->nx + (size_t)i] - base) / scale;
            v[(size_t)r * (size_t)s->nx + (size_t)i] = (unsigned short)lround(fmin(1, fmax(0, u)) * 65535);
        }
    char path[FS_OUT_PATH + 32];
    snprintf(path, sizeof path, "%s/surface.png", dir);
    fs_status st = fs_png_write_gray16(path, s->nx, s->ny, v, err);
    free(v);
    const ini_of o = {s, &c->material, base, scale};
    if (st == FS_OK)
        st = fs_write_in(dir, "surface.csv", fill_csv, s, err);
    if (st == FS_OK)
        st = fs_write_in(dir, "surface.ini", fill_ini, &o, err);
    if (st != FS_OK)
        return st;
    cJSON *run = cJSON_CreateObject();
    int ok = run && cJSON_AddStringToObject(run, "what",
                                            "the surface the soil keeps at the run's end (undisturbed height less the "
                                            "print), on the grid's nodes over the tiles the feet reached; elsewhere "
                                            "the soil is undisturbed") != NULL;
    ok = ok && cJSON_AddNumberToObject(run, "grid_m", s->dx) && cJSON_AddNumberToObject(run, "x0_m", s->x0) &&
         cJSON_AddNumberToObject(run, "y0_m", s->y0) && cJSON_AddNumberToObject(run, "nx", s->nx) &&
         cJSON_AddNumberToObject(run, "ny", s->ny) && cJSON_AddNumberToObject(run, "png_base_m", base) &&
         cJSON_AddNumberToObject(run, "png_scale_m", scale) &&
         cJSON_AddNumberToObject(run, "png_quantum_m", scale / 65535);
    st = ok ? fs_provenance_write_beside(dir, "surface.csv", prov, run, err)
            : fs_fail(err, FS_NO_MEMORY, "out of memory for the surface's provenance");
    cJSON_Delete(run);
    return st;
}
