/* law_cells.c: the static and the drop law's verdicts for every cell of a campaign file, without a
 * trial run (docs/landing.md, The drop law): for judging a committed campaign's measurement with a
 * law newer than its summary. `build/law-cells CAMPAIGN [section.key=value ...]`, from the source
 * folder; JSON on stdout: {"seeds", "rows": [{foot, terrain, robot, law_prediction,
 * drop_law_prediction, drop_law_seeds, drop_law_stands, drop_law_energy_J, drop_law_barrier_J,
 * drop_law_saturation_N_m, drop_law_critical_com_height_m; with a band each end's laws too, NAME_END:
 * law_prediction_, drop_law_prediction_, drop_law_stands_, law_K_N_m_per_rad_, contact_restitution_,
 * drop_law_energy_J_, drop_law_barrier_J_}]}, which tools/law-agreement.py --laws
 * reads beside the campaign's summary.json. */
#include "footsim/campaign/fs_campaign.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void number(const char *key, double v, const char *end)
{
    if (isfinite(v))
        printf("\"%s\": %.17g%s", key, v, end);
    else
        printf("\"%s\": null%s", key, end);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: law-cells CAMPAIGN [section.key=value ...]\n");
        return 2;
    }
    static fs_campaign c;
    fs_error err;
    if (fs_campaign_load(argv[1], (const char *const *)argv + 2, argc - 2, &c, &err) != FS_OK) {
        fprintf(stderr, "law-cells: %s\n", err.message);
        return err.status;
    }
    fs_trial_result *results = calloc((size_t)fs_campaign_ntrials(&c), sizeof *results);
    fs_campaign_row *rows = calloc((size_t)fs_campaign_ncells(&c), sizeof *rows);
    if (!results || !rows) {
        fprintf(stderr, "law-cells: out of memory\n");
        return 5;
    }
    fs_campaign_summarize(&c, results, rows);
    printf("{\"campaign\": \"%s\", \"seeds\": %d, \"rows\": [\n", c.name, c.seeds);
    for (int i = 0; i < fs_campaign_ncells(&c); i++) {
        const fs_campaign_row *r = &rows[i];
        printf("  {\"foot\": \"%s\", \"terrain\": \"%s\", \"robot\": \"%s\", ", c.foot[r->foot].name,
               c.terrain[r->terrain].name, c.robot[r->robot].name);
        printf(r->law == FS_LAW_NONE ? "\"law_prediction\": null, " : "\"law_prediction\": \"%s\", ", fs_law_name(r->law));
        printf(r->drop_law == FS_LAW_NONE ? "\"drop_law_prediction\": null, " : "\"drop_law_prediction\": \"%s\", ",
               fs_law_name(r->drop_law));
        printf("\"drop_law_seeds\": %d, \"drop_law_stands\": %d, ", r->drop_seeds, r->drop_stands);
        number("drop_law_energy_J", r->drop_energy_J, ", ");
        number("drop_law_barrier_J", r->drop_barrier_J, ", ");
        number("drop_law_saturation_N_m", r->drop_saturation_N_m, ", ");
        number("drop_law_critical_com_height_m", r->drop_critical_m, "");
        for (int e = 0; c.band[0] && r->law_end >= 0 && e < fs_campaign_nends(&c); e++) { /* a band: each end's laws */
            const char *n = c.end[e].name;
            printf(", \"law_prediction_%s\": \"%s\", \"drop_law_prediction_%s\": \"%s\", \"drop_law_stands_%s\": %d, ", n,
                   fs_law_name(r->end_law[e]), n, fs_law_name(r->end_drop_law[e]), n, r->end_drop_stands[e]);
            char key[64];
            snprintf(key, sizeof key, "law_K_N_m_per_rad_%s", n);
            number(key, r->end_law_K[e], ", ");
            snprintf(key, sizeof key, "contact_restitution_%s", n);
            number(key, r->end_restitution[e], ", ");
            snprintf(key, sizeof key, "drop_law_energy_J_%s", n);
            number(key, r->end_drop_energy_J[e], ", ");
            snprintf(key, sizeof key, "drop_law_barrier_J_%s", n);
            number(key, r->end_drop_barrier_J[e], "");
        }
        printf("}");
        printf("%s\n", i + 1 < fs_campaign_ncells(&c) ? "," : "");
    }
    printf("]}\n");
    free(results), free(rows);
    fs_campaign_free(&c);
    return 0;
}
