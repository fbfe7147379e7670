/* law_rewrite.c: a committed campaign's summaries written again from its trials.csv, with this
 * version's laws (docs/landing.md, The drop law): no trial is run. `build/law-rewrite CAMPAIGN
 * RESULTS_DIR OUT_DIR [section.key=value ...]`, from the source folder: reads RESULTS_DIR/trials.csv
 * (every trial of CAMPAIGN with its overrides, matched by foot, terrain, robot and seed), summarizes
 * them and writes OUT_DIR's trials.csv, summary.csv, summary.md, schema.sql, summary.json and the
 * chart's data, as `footsim campaign` would have (the provenance this version's, as `footsim merge
 * --force` writes it). OUT_DIR/trials.csv must come out byte for byte as RESULTS_DIR's (cmp them):
 * that checks the reading; a trials.csv from before footsim measured a soil's print gains those five
 * columns, empty, as footsim writes them on rigid ground. A campaign with a contact band reads each trial's band_end too. Exit 2 on bad input, 4 when it cannot write. */
#include "footsim/campaign/fs_campaign.h"
#include "footsim/experiment/fs_outcome.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { MAX_FIELDS = 64, MAX_LINE = 8192 };

/* Splits an RFC 4180 line in place (quoted fields, "" inside them); the number of fields. */
static int split(char *line, char **field)
{
    int n = 0;
    char *p = line;
    while (n < MAX_FIELDS) {
        char *out = p;
        field[n++] = p;
        if (*p == '"') {
            char *q = p + 1;
            for (;;) {
                if (*q == '"' && q[1] == '"')
                    *out++ = '"', q += 2;
                else if (*q == '"' || *q == '\0') {
                    if (*q == '"')
                        q++;
                    break;
                } else
                    *out++ = *q++;
            }
            p = q;
        } else {
            while (*p && *p != ',' && *p != '\n' && *p != '\r')
                *out++ = *p++;
        }
        char end = *p;
        *out = '\0';
        if (end != ',')
            break;
        p++;
    }
    return n;
}

static int column(char **head, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(head[i], name))
            return i;
    return -1;
}

static int code_of(const char *text, const char *(*name)(int), int last)
{
    for (int k = 0; k <= last; k++)
        if (!strcmp(name(k), text))
            return k;
    return -1;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: law-rewrite CAMPAIGN RESULTS_DIR OUT_DIR [section.key=value ...]\n");
        return 2;
    }
    static fs_campaign c;
    fs_error err;
    if (fs_campaign_load(argv[1], (const char *const *)argv + 4, argc - 4, &c, &err) != FS_OK) {
        fprintf(stderr, "law-rewrite: %s\n", err.message);
        return err.status;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/trials.csv", argv[2]);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "law-rewrite: %s: %s\n", path, strerror(errno));
        return 2;
    }
    int ntrials = fs_campaign_ntrials(&c), ncells = fs_campaign_ncells(&c);
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    fs_campaign_row *rows = calloc((size_t)ncells, sizeof *rows);
    char *seen = calloc((size_t)ntrials, 1);
    static char headline[MAX_LINE], line[MAX_LINE];
    char *head[MAX_FIELDS], *field[MAX_FIELDS];
    if (!results || !rows || !seen || !fgets(headline, sizeof headline, f)) {
        fprintf(stderr, "law-rewrite: %s: empty, or out of memory\n", path);
        return 2;
    }
    int nhead = split(headline, head);
    const char *names[] = {"foot", "terrain", "robot", "seed", "x_m", "y_m", "yaw_deg", "pitch_deg", "roll_deg",
                           "outcome", "rule", "end_time_s", "touchdown_s", "peak_tilt_deg", "final_tilt_deg",
                           "peak_force_N", "impact_impulse_Ns", "settle_time_s", "mean_contacts",
                           "final_contacts", "ankle_drop_m", "slip_m", "steps", "failure"};
    enum { NNAMES = sizeof names / sizeof *names };
    int col[NNAMES];
    for (int i = 0; i < NNAMES; i++)
        if ((col[i] = column(head, nhead, names[i])) < 0) {
            fprintf(stderr, "law-rewrite: %s: no column %s\n", path, names[i]);
            return 2;
        }
    /* a soil's print: columns since footsim measured one (absent from an older trials.csv, and empty on
       rigid ground, as footsim writes them) */
    const char *soil_names[] = {"soil_sinkage_m", "print_depth_m", "print_area_m2", "print_volume_m3", "print_slip_m"};
    enum { NSOIL = sizeof soil_names / sizeof *soil_names };
    int soil_col[NSOIL];
    for (int i = 0; i < NSOIL; i++)
        soil_col[i] = column(head, nhead, soil_names[i]);
    int band_col = c.band[0] ? column(head, nhead, "band_end") : -1, nends = fs_campaign_nends(&c);
    if (c.band[0] && band_col < 0) {
        fprintf(stderr, "law-rewrite: %s: no column band_end, and the campaign has a band\n", path);
        return 2;
    }
    int lineno = 1, read = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (split(line, field) != nhead) {
            fprintf(stderr, "law-rewrite: %s:%d: %d columns expected\n", path, lineno, nhead);
            return 2;
        }
        int cell = -1, seed = atoi(field[col[3]]);
        for (int k = 0; k < ncells && cell < 0; k++) {
            int fo, te, ro;
            fs_campaign_cell_of(&c, k, &fo, &te, &ro);
            if (!strcmp(c.foot[fo].name, field[col[0]]) && !strcmp(c.terrain[te].name, field[col[1]]) &&
                !strcmp(c.robot[ro].name, field[col[2]]))
                cell = k;
        }
        int end = 0;
        while (band_col >= 0 && end < nends && strcmp(c.end[end].name, field[band_col]))
            end++;
        int index = (cell * nends + end) * c.seeds + seed - c.first_seed;
        if (cell < 0 || end >= nends || seed < c.first_seed || seed >= c.first_seed + c.seeds || seen[index]) {
            fprintf(stderr, "law-rewrite: %s:%d: a trial the campaign does not have, or one seen already\n", path,
                    lineno);
            return 2;
        }
        seen[index] = 1, read++;
        fs_trial_result *r = &results[index];
        double *num[] = {&r->draw.x_m, &r->draw.y_m, &r->draw.yaw_deg, &r->draw.pitch_deg, &r->draw.roll_deg};
        for (int i = 0; i < 5; i++)
            *num[i] = strtod(field[col[4 + i]], NULL);
        r->outcome = code_of(field[col[9]], fs_outcome_name, FS_KILLED);
        r->rule = code_of(field[col[10]], fs_rule_name, FS_RULE_KILLED);
        double *m[] = {&r->end_time_s, &r->touchdown_s, &r->peak_tilt_deg, &r->final_tilt_deg, &r->peak_force_N,
                       &r->impact_impulse_Ns, &r->settle_time_s, &r->mean_contacts, &r->final_contacts,
                       &r->ankle_drop_m, &r->slip_m};
        for (int i = 0; i < 11; i++)
            *m[i] = field[col[11 + i]][0] ? strtod(field[col[11 + i]], NULL) : NAN;
        double *soil[NSOIL] = {&r->soil_sinkage_m, &r->print_depth_m, &r->print_area_m2, &r->print_volume_m3,
                               &r->print_slip_m};
        for (int i = 0; i < NSOIL; i++)
            *soil[i] = soil_col[i] >= 0 && field[soil_col[i]][0] ? strtod(field[soil_col[i]], NULL) : NAN;
        r->steps = atol(field[col[22]]);
        snprintf(r->failure, sizeof r->failure, "%s", field[col[23]]);
        if (r->outcome < 0 || r->rule < 0) {
            fprintf(stderr, "law-rewrite: %s:%d: an outcome or rule footsim does not name\n", path, lineno);
            return 2;
        }
    }
    fclose(f);
    if (read != ntrials) {
        fprintf(stderr, "law-rewrite: %s: %d trials of the campaign's %d\n", path, read, ntrials);
        return 2;
    }
    fs_campaign_summarize(&c, results, rows);
    mkdir(argv[3], 0777);
    if (fs_campaign_write(&c, results, rows, argv[3], &err) != FS_OK ||
        fs_campaign_write_chart(&c, rows, argv[3], &err) != FS_OK ||
        fs_campaign_write_summary(&c, rows, argv[3], &err) != FS_OK) {
        fprintf(stderr, "law-rewrite: %s\n", err.message);
        return 4;
    }
    free(results), free(rows), free(seen);
    fs_campaign_free(&c);
    return 0;
}
