/* cli_model.c: `footsim model DESIGN`: the built model in SI units and world coordinates (fs_model_json),
 * summarised or, with --json, every number. */
#include "cli.h"

#include "footsim/io/fs_output.h"
#include "footsim/export/fs_export.h"
#include "footsim/sim/fs_sim.h"

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
        printf("'footsim model %s --json' gives every number.\n", a->input);
    }
    cJSON_Delete(root);
    return s;
}

int cli_model(const cli_args *a) { return cli_with_design(a, model_of); }

