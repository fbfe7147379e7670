/* cli_model.c: `footsim model DESIGN`: the built model in SI units and world coordinates (fs_model_json),
 * summarised or, with --json, every number. */
#include "cli.h"

#include "footsim/base/fs_vec.h"
#include "footsim/io/fs_output.h"
#include "footsim/export/fs_export.h"
#include "footsim/sim/fs_sim.h"
#include "footsim/sim/fs_sim_soil.h"

#include <cjson/cJSON.h>
#include <stdio.h>

static int model_of(const cli_args *a, const fs_scenario *sc)
{
    fs_error err;
    cJSON *root = fs_model_json(sc, &err);
    if (!root)
        return cli_report(err.status, err.message);
    int s = 0;
    if (a->json) {
        s = cli_print_json(root);
    } else {
        const fs_foot_geom *g = &sc->geom;
        printf("%s: %s foot, %d bodies, %d hinges, %d springs, %d contact shapes, %.3f kg\n", a->input,
               g->kind == FS_FOOT_FLAT ? "flat" : "biomimetic", g->nbodies, g->nhinges, g->nsprings,
               g->nspheres + g->nboxes, g->total_mass_kg);
        printf("ankle at (%.4f, %.4f, %.4f) m\n", g->ankle.x, g->ankle.y, g->ankle.z);
        for (int i = 0; i < g->nbodies; i++)
            printf("  body %-12s %.4f kg at (%.4f, %.4f, %.4f) m\n", g->body[i].name, g->body[i].mass_kg,
                   g->body[i].com.x, g->body[i].com.y, g->body[i].com.z);
        /* the shapes a soil meets (docs/soil.md, The feet's shapes), the [soil_shapes] radii */
        static fs_soil_shape shape[FS_SOIL_MAX_SHAPES];
        int n = fs_soil_foot_shapes(g, NULL, shape, FS_SOIL_MAX_SHAPES);
        double total = 0;
        for (int i = 0; i < n; i++) {
            const fs_soil_shape *s = &shape[i];
            total += s->plan_area_m2;
            if (s->kind == FS_SOIL_BOX)
                printf("  soil shape %-12s box %.1f x %.1f x %.1f mm, %.2f cm^2 from below\n", s->name, 2e3 * s->half[0],
                       2e3 * s->half[1], 2e3 * s->half[2], s->plan_area_m2 * 1e4);
            else
                printf("  soil shape %-12s capsule radius %.2f mm, %.1f mm long, %.2f cm^2 from below\n", s->name,
                       s->radius_m * 1e3,
                       1e3 * fs_norm(fs_v3(s->b[0] - s->a[0], s->b[1] - s->a[1], s->b[2] - s->a[2])),
                       s->plan_area_m2 * 1e4);
        }
        printf("  soil shapes: %d, %.1f cm^2 from below at rest\n", n, total * 1e4);
        printf("'footsim model %s --json' gives every number.\n", a->input);
    }
    cJSON_Delete(root);
    return s;
}

int cli_model(const cli_args *a) { return cli_with_design(a, model_of); }

