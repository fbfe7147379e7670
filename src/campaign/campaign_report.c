/* campaign_report.c: a campaign's result files (trials.csv, summary.csv, summary.md,
 * summary.json, schema.sql), its chart, and its expectations checked. The CSV files are RFC 4180:
 * one header row, then the rows, a missing value an empty field (null in summary.json, – in
 * summary.md); what made them is in summary.json and schema.sql. */
#include "campaign_internal.h"

#include "footsim/base/fs_path.h"
#include "footsim/io/fs_gnuplot.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- result files ------------------------------------------------------------------------- */

typedef struct out_ctx {
    const fs_campaign *c;
    const fs_trial_result *results;
    const fs_campaign_row *rows;
} out_ctx;

/* A fill function of out_ctx for fs_write_file. */
typedef struct out_fill {
    int (*fill)(FILE *, const out_ctx *);
    const out_ctx *ctx;
} out_fill;

static int fill_adapter(FILE *f, const void *user)
{
    const out_fill *x = user;
    return x->fill(f, x->ctx);
}

/* Writes dir/name through fill, whole or not at all. */
static fs_status write_file(const char *dir, const char *name, int (*fill)(FILE *, const out_ctx *),
                            const out_ctx *ctx, fs_error *err)
{
    const out_fill x = {fill, ctx};
    return fs_write_in(dir, name, fill_adapter, &x, err);
}

/* A number for CSV: exact (%.17g), or empty when there is none. */
static void csv_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, ",%.17g", v);
    else
        fputs(",", f);
}

/* s quoted for CSV: quotes doubled, line breaks as spaces. */
static void csv_quoted(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++)
        if (*s == '"')
            fputs("\"\"", f);
        else
            fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
    fputc('"', f);
}

/* Free text for CSV: always quoted. */
static void csv_text(FILE *f, const char *s)
{
    fputc(',', f);
    csv_quoted(f, s);
}

/* A name for CSV: as it is, or quoted when it holds a comma, a quote or a line break (a point of a
 * two-key sweep is named "BASE@v1,v2"). */
static void csv_name(FILE *f, const char *s)
{
    if (strpbrk(s, ",\"\r\n"))
        csv_quoted(f, s);
    else
        fputs(s, f);
}

static void csv_row_key(FILE *f, const fs_campaign *c, int foot, int terrain, int robot)
{
    csv_name(f, c->foot[foot].name);
    fputc(',', f);
    csv_name(f, c->terrain[terrain].name);
    fputc(',', f);
    csv_name(f, c->robot[robot].name);
    for (int w = 0; w < c->nsweep; w++)
        csv_number(f, c->terrain[terrain].sweep_value[w]);
}

/* What made the results: the campaign's record with its seeds as they are now (a design search
 * reruns its best on fresh seeds); a read-only view of c's record, not to be freed. */
static fs_provenance provenance_of(const fs_campaign *c)
{
    fs_provenance p = c->provenance;
    p.first_seed = c->first_seed;
    p.nseeds = c->seeds;
    if (!c->pair) /* a campaign built in code, not loaded */
        snprintf(p.settings, sizeof p.settings, "settings unknown");
    return p;
}

/* The provenance line a journal keeps (the CSV files hold none: summary.json and schema.sql do). */
static void csv_provenance(FILE *f, const fs_campaign *c)
{
    fs_provenance p = provenance_of(c);
    fs_provenance_line(&p, f);
}

char *fs_campaign_provenance(const fs_campaign *c)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return NULL;
    csv_provenance(f, c);
    if (fclose(f) != 0) {
        free(text);
        return NULL;
    }
    if (len && text[len - 1] == '\n')
        text[len - 1] = 0;
    return text;
}

/* The header's key columns: foot, terrain, robot and the swept keys. */
static void csv_key_header(FILE *f, const fs_campaign *c)
{
    fputs("foot,terrain,robot", f);
    for (int w = 0; w < c->nsweep; w++)
        fprintf(f, ",%s", c->sweep[w]);
}

static int fill_trials(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    csv_key_header(f, c);
    if (c->band[0])
        fputs(",band_end", f);
    fputs(",seed,x_m,y_m,yaw_deg,pitch_deg,roll_deg,outcome,rule", f);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, ",%s", fs_campaign_metrics[m].name);
    fputs(",failure\n", f);
    for (int i = 0; i < fs_campaign_ntrials(c); i++) {
        const fs_trial_result *r = &x->results[i];
        int cell, foot, terrain, robot, seed;
        fs_campaign_trial_of(c, i, &cell, &seed);
        fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
        csv_row_key(f, c, foot, terrain, robot);
        if (c->band[0])
            fprintf(f, ",%s", c->end[fs_campaign_trial_end(c, i)].name);
        fprintf(f, ",%d", seed);
        const double pose[5] = {r->draw.x_m, r->draw.y_m, r->draw.yaw_deg, r->draw.pitch_deg, r->draw.roll_deg};
        for (int k = 0; k < 5; k++)
            csv_number(f, pose[k]);
        fprintf(f, ",%s,%s", fs_outcome_name(r->outcome), fs_rule_name(r->rule));
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            csv_number(f, fs_metric_value(r, m));
        csv_text(f, fs_trial_measured(r) ? "" : r->failure);
        fputc('\n', f);
    }
    return 1;
}

static int fill_summary_csv(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    csv_key_header(f, c);
    fputs(",trials,landed,fell,undecided,failed_numerics,hung,success_rate,ci_low,ci_high", f);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, ",median_%s", fs_campaign_metrics[m].name);
    fputs(",law_prediction,law_K_N_m_per_rad,law_critical_com_height_m,drop_law_prediction,drop_law_seeds,"
          "drop_law_stands,drop_law_energy_J,drop_law_barrier_J,drop_law_saturation_N_m,drop_law_critical_com_height_m", f);
    if (c->band[0]) { /* the band's columns, last: a file without a band is as before */
        fputs(",band_end", f);
        for (int e = 0; e < fs_campaign_nends(c); e++)
            fprintf(f, ",landed_%s,success_rate_%s", c->end[e].name, c->end[e].name);
        fputs(",law_end", f);
        for (int e = 0; e < fs_campaign_nends(c); e++)
            fprintf(f, ",law_prediction_%s,drop_law_prediction_%s,drop_law_stands_%s", c->end[e].name, c->end[e].name,
                    c->end[e].name);
    }
    fputc('\n', f);
    for (int i = 0; i < fs_campaign_ncells(c); i++) {
        const fs_campaign_row *r = &x->rows[i];
        csv_row_key(f, c, r->foot, r->terrain, r->robot);
        fprintf(f, ",%d,%d,%d,%d,%d,%d", r->trials, r->landed, r->fell, r->undecided, r->failed_numerics, r->hung);
        csv_number(f, r->success_rate);
        csv_number(f, r->ci_low);
        csv_number(f, r->ci_high);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            csv_number(f, r->median[m]);
        fprintf(f, ",%s", r->law == FS_LAW_NONE ? "" : fs_law_name(r->law)); /* none: empty, as every missing value */
        csv_number(f, r->law_K);
        csv_number(f, r->law_critical_m);
        fprintf(f, ",%s", r->drop_law == FS_LAW_NONE ? "" : fs_law_name(r->drop_law));
        if (r->drop_law == FS_LAW_NONE)
            fputs(",,", f);
        else
            fprintf(f, ",%d,%d", r->drop_seeds, r->drop_stands);
        csv_number(f, r->drop_energy_J);
        csv_number(f, r->drop_barrier_J);
        csv_number(f, r->drop_saturation_N_m);
        csv_number(f, r->drop_critical_m);
        if (c->band[0]) {
            fprintf(f, ",%s", c->end[r->band_end].name);
            for (int e = 0; e < fs_campaign_nends(c); e++) {
                fprintf(f, ",%d", r->end_landed[e]);
                csv_number(f, r->end_rate[e]);
            }
            fprintf(f, ",%s", r->law_end >= 0 ? c->end[r->law_end].name : "");
            for (int e = 0; e < fs_campaign_nends(c); e++) {
                int none = r->law_end < 0 || r->end_drop_law[e] == FS_LAW_NONE;
                fprintf(f, ",%s,%s", r->law_end < 0 || r->end_law[e] == FS_LAW_NONE ? "" : fs_law_name(r->end_law[e]),
                        none ? "" : fs_law_name(r->end_drop_law[e]));
                if (none)
                    fputc(',', f);
                else
                    fprintf(f, ",%d", r->end_drop_stands[e]);
            }
        }
        fputc('\n', f);
    }
    return 1;
}

/* How often the laws' verdicts agree with a rate where it decides (>= 0.7 lands, <= 0.3 falls; in
 * between nothing is counted): the band's (end -1: the cell's, its worse end's) or one end's. */
static void md_law_agreement(FILE *f, const out_ctx *x, int end)
{
    const fs_campaign *c = x->c;
    int decided = 0, law_n = 0, law_ok = 0, drop_n = 0, drop_ok = 0;
    for (int i = 0; i < fs_campaign_ncells(c); i++) {
        const fs_campaign_row *r = &x->rows[i];
        double rate = end < 0 ? r->success_rate : r->end_rate[end];
        if (rate > FS_RATE_FALLS && rate < FS_RATE_LANDS)
            continue;
        int lands = rate >= FS_RATE_LANDS;
        decided++;
        /* an end's rate against the law at that end (with its contact), the band's against the cell's */
        int by_end = end >= 0 && r->law_end >= 0;
        int law = by_end ? r->end_law[end] : r->law, drop = by_end ? r->end_drop_law[end] : r->drop_law;
        if (law != FS_LAW_NONE)
            law_n++, law_ok += (law == FS_LAW_STANDS) == lands;
        if (drop != FS_LAW_NONE)
            drop_n++, drop_ok += (drop == FS_LAW_STANDS) == lands;
    }
    if (end < 0)
        fputs("| the band's (the smaller) |", f);
    else
        fprintf(f, "| the %s end's |", c->end[end].name);
    fprintf(f, " %d | %d of %d | %d of %d |\n", decided, law_ok, law_n, drop_ok, drop_n);
}

/* A band's part of summary.md: what it is (intro 1), or the laws against its rates (intro 0). */
static void md_band(FILE *f, const out_ctx *x, int intro)
{
    const fs_campaign *c = x->c;
    if (intro) {
        fprintf(f, "Contact band `%s`: every trial runs at each of its ends on the same seed", c->band);
        for (int e = 0; e < fs_campaign_nends(c); e++)
            fprintf(f, "%s%s (%s%s%s)", e ? " and " : ", ", c->end[e].name, c->end[e].nsets ? "`" : "",
                    c->end[e].nsets ? c->end[e].text : "the trials' own values", c->end[e].nsets ? "`" : "");
        fputs("; a cell's row is its worse end's (its counts, rate, interval, medians and law; the first end on a tie), "
              "so a cell lands only as often as it lands across the band; `band` gives each end's landings.\n\n", f);
        return;
    }
    fprintf(f, "\n## The laws against the band\n\nThe static and the drop law's verdicts (the band's: the law's worse "
               "end's; an end's: the law at that end, with its contact) against the rates where they decide (at least %.1f: lands; at most %.1f: falls; between: not counted).\n\n"
               "| rate | cells decided | static law agrees | drop law agrees |\n|---|--:|--:|--:|\n",
            FS_RATE_LANDS, FS_RATE_FALLS);
    md_law_agreement(f, x, -1);
    for (int e = 0; e < fs_campaign_nends(c); e++)
        md_law_agreement(f, x, e);
}

/* The drop law's verdict: "drop: stands, stands in N of S seeds (E ... J, B ... J)", the energies the
 * medians over the seeds whose support holds the centre of mass (none: said so, no NaN printed; a
 * robot on a slide stands without them: pitch held). */
static void md_drop(FILE *f, int law, int stands, int seeds, double E, double B)
{
    fprintf(f, "drop: %s, stands in %d of %d seeds", fs_law_name(law), stands, seeds);
    if (isnan(E) || isnan(B)) /* a verdict that stands without energies: a robot on a slide */
        fputs(law == FS_LAW_STANDS ? " (pitch held)" : " (the centre of mass over no seed's support)", f);
    else
        fprintf(f, " (E %.3g J, B %.3g J)", E, B);
}

/* With a band: the laws at each end (each with its contact: fs_pitch_contact_series, the rebound
 * gain of its restitution e), after the cell's, which is the law's worse end's. */
static void md_law_ends(FILE *f, const fs_campaign *c, const fs_campaign_row *r)
{
    if (!c->band[0] || r->law_end < 0)
        return;
    fprintf(f, "; the %s end's; by end:", c->end[r->law_end].name);
    for (int e = 0; e < fs_campaign_nends(c); e++) {
        fprintf(f, "%s %s %s", e ? "," : "", c->end[e].name, fs_law_name(r->end_law[e]));
        if (isfinite(r->end_law_K[e]))
            fprintf(f, " (K %.3g, e %.2f)", r->end_law_K[e], r->end_restitution[e]);
        if (r->end_drop_law[e] != FS_LAW_NONE) {
            fputs(", ", f);
            md_drop(f, r->end_drop_law[e], r->end_drop_stands[e], r->drop_seeds, r->end_drop_energy_J[e],
                    r->end_drop_barrier_J[e]);
        }
    }
}

static int fill_summary_md(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    char trial[FS_NAME_MAX];
    fs_path_stem(c->trial_path, trial, sizeof trial);
    int killed = 0; /* said only when there are: the file of a campaign without is as before */
    for (int i = 0; i < fs_campaign_ncells(c); i++)
        killed += x->rows[i].killed;
    fprintf(f, "# Campaign %s\n\nTrial scenario `%s`, seeds %d to %d (%d per foot, terrain and robot)%s%s. Success: the "
               "trial landed; undecided trials (the window ended first) count as not landed and are shown apart; "
               "interval: 95 %% Wilson score. Rules: docs/landing.md. Medians over the trials that did not fail numerically or hang (hung: the worker killed by the watchdog%s); the ankle drop at rest's over the trials that landed.\n\n",
            c->name, trial, c->first_seed, c->first_seed + c->seeds - 1, c->seeds,
            c->nsweep ? "; each terrain swept over " : "", c->sweep[0],
            killed ? ", or killed from outside: trials.csv says which" : "");
    if (c->nsweep == 2)
        fprintf(f, "Swept over %s and %s: a terrain named NAME@v1,v2 is the point (%s = v1, %s = v2).\n\n", c->sweep[0],
                c->sweep[1], c->sweep[0], c->sweep[1]);
    if (c->band[0])
        md_band(f, x, 1);
    fprintf(f, "| foot | terrain | robot | trials | landed | fell | undecided | failed_numerics | hung | success | 95 %% CI |%s law |",
            c->band[0] ? " band |" : "");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, " %s |", fs_campaign_metrics[m].name);
    fprintf(f, "\n|---|---|---|--:|--:|--:|--:|--:|--:|--:|---|%s---|", c->band[0] ? "---|" : "");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fputs("--:|", f);
    fputc('\n', f);
    for (int i = 0; i < fs_campaign_ncells(c); i++) {
        const fs_campaign_row *r = &x->rows[i];
        fprintf(f, "| %s | %s | %s | %d | %d | %d | %d | %d | %d | %.2f | [%.2f, %.2f] |", c->foot[r->foot].name,
                c->terrain[r->terrain].name, c->robot[r->robot].name, r->trials, r->landed, r->fell, r->undecided,
                r->failed_numerics, r->hung, r->success_rate, r->ci_low, r->ci_high);
        for (int e = 0; c->band[0] && e < fs_campaign_nends(c); e++)
            fprintf(f, "%s%s %d/%d%s", e ? ", " : " ", c->end[e].name, r->end_landed[e], r->end_trials[e],
                    e + 1 == fs_campaign_nends(c) ? " |" : "");
        if (isfinite(r->law_K)) {
            fprintf(f, " %s (K %.3g N m/rad, critical height %.3f m)", fs_law_name(r->law), r->law_K,
                    r->law_critical_m);
            if (r->drop_law != FS_LAW_NONE) {
                fputs("; ", f);
                md_drop(f, r->drop_law, r->drop_stands, r->drop_seeds, r->drop_energy_J, r->drop_barrier_J);
            }
        }
        else
            fprintf(f, " %s", r->law == FS_LAW_STANDS ? "stands (pitch held)" : r->law == FS_LAW_NONE ? "–" : fs_law_name(r->law));
        md_law_ends(f, c, r);
        fputs(" |", f);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            fprintf(f, isfinite(r->median[m]) ? " %.4g |" : " – |", r->median[m]);
        fputc('\n', f);
    }
    if (c->band[0])
        md_band(f, x, 0);
    fs_provenance p = provenance_of(c);
    fputs("\nProvenance: ", f);
    fs_provenance_print(&p, f);
    fputs(".\n", f);
    if (c->nexpect)
        fputs("\n## Expectations\n\n| expectation | foot | terrain | robot | success | wanted | met |\n"
              "|---|---|---|---|--:|---|---|\n", f);
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        const fs_campaign_row *r = fs_campaign_row_of(c, x->rows, e->foot, e->terrain, e->robot);
        fprintf(f, "| %s | %s | %s | %s | %.2f | [%.2f, %.2f] | %s |\n", e->name, c->foot[e->foot].name,
                c->terrain[e->terrain].name, c->robot[e->robot].name, r->success_rate, e->min_success, e->max_success,
                fs_expectation_met(e, r) ? "yes" : "**no**");
    }
    return 1;
}

static cJSON *summary_json(const out_ctx *x)
{
    const fs_campaign *c = x->c;
    cJSON *root = cJSON_CreateObject();
    int ok = root != NULL;
    char trial[FS_NAME_MAX];
    fs_path_stem(c->trial_path, trial, sizeof trial);
    ok &= cJSON_AddStringToObject(root, "campaign", c->name) != NULL;
    ok &= cJSON_AddStringToObject(root, "trial", trial) != NULL;
    ok &= cJSON_AddNumberToObject(root, "seeds", c->seeds) != NULL;
    ok &= cJSON_AddNumberToObject(root, "first_seed", c->first_seed) != NULL;
    for (int w = 0; w < 2; w++)
        if (w < c->nsweep)
            ok &= cJSON_AddStringToObject(root, w ? "sweep2" : "sweep", c->sweep[w]) != NULL;
        else
            ok &= cJSON_AddNullToObject(root, w ? "sweep2" : "sweep") != NULL;
    if (c->band[0]) { /* only with a band: a summary without is as before */
        cJSON *band = cJSON_AddObjectToObject(root, "band");
        ok &= band && cJSON_AddStringToObject(band, "name", c->band) != NULL;
        cJSON *ends = band ? cJSON_AddArrayToObject(band, "ends") : NULL;
        ok &= ends != NULL;
        for (int e = 0; ok && e < fs_campaign_nends(c); e++) {
            cJSON *o = cJSON_CreateObject(), *sets = o ? cJSON_AddArrayToObject(o, "overrides") : NULL;
            ok &= sets && cJSON_AddStringToObject(o, "name", c->end[e].name) != NULL;
            for (int i = 0; ok && i < c->end[e].nsets; i++) {
                char text[3 * FS_NAME_MAX];
                snprintf(text, sizeof text, "%s=%.17g", c->end[e].key[i], c->end[e].value[i]);
                ok &= fs_json_put(sets, NULL, cJSON_CreateString(text));
            }
            ok &= fs_json_put(ends, NULL, o);
        }
    }
    fs_provenance p = provenance_of(c);
    ok &= fs_json_put(root, "provenance", fs_provenance_json(&p));
    cJSON *tol = cJSON_AddObjectToObject(root, "tolerances");
    ok &= tol != NULL;
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        cJSON *t = cJSON_AddObjectToObject(tol, fs_campaign_metrics[m].name);
        ok &= t != NULL;
        ok &= cJSON_AddNumberToObject(t, "relative", c->tolerance[m][0]) != NULL;
        ok &= cJSON_AddNumberToObject(t, "absolute", c->tolerance[m][1]) != NULL;
    }
    cJSON *rows = cJSON_AddArrayToObject(root, "rows");
    ok &= rows != NULL;
    for (int i = 0; i < fs_campaign_ncells(c); i++) {
        const fs_campaign_row *r = &x->rows[i];
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "foot", c->foot[r->foot].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "terrain", c->terrain[r->terrain].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "robot", c->robot[r->robot].name) != NULL;
        for (int w = 0; w < c->nsweep; w++)
            ok &= cJSON_AddNumberToObject(o, w ? "sweep_value2" : "sweep_value", c->terrain[r->terrain].sweep_value[w]) != NULL;
        ok &= cJSON_AddNumberToObject(o, "trials", r->trials) != NULL;
        ok &= cJSON_AddNumberToObject(o, "landed", r->landed) != NULL;
        ok &= cJSON_AddNumberToObject(o, "fell", r->fell) != NULL;
        ok &= cJSON_AddNumberToObject(o, "undecided", r->undecided) != NULL;
        ok &= cJSON_AddNumberToObject(o, "failed_numerics", r->failed_numerics) != NULL;
        ok &= cJSON_AddNumberToObject(o, "hung", r->hung) != NULL;
        ok &= cJSON_AddNumberToObject(o, "success_rate", r->success_rate) != NULL;
        ok &= cJSON_AddNumberToObject(o, "ci_low", r->ci_low) != NULL;
        ok &= cJSON_AddNumberToObject(o, "ci_high", r->ci_high) != NULL;
        ok &= (r->law == FS_LAW_NONE ? cJSON_AddNullToObject(o, "law_prediction") /* none: null, as every missing value */
                                     : cJSON_AddStringToObject(o, "law_prediction", fs_law_name(r->law))) != NULL;
        ok &= cJSON_AddNumberToObject(o, "law_K_N_m_per_rad", r->law_K) != NULL; /* NAN, INFINITY: null */
        ok &= cJSON_AddNumberToObject(o, "law_critical_com_height_m", r->law_critical_m) != NULL;
        ok &= (r->drop_law == FS_LAW_NONE ? cJSON_AddNullToObject(o, "drop_law_prediction")
                                          : cJSON_AddStringToObject(o, "drop_law_prediction", fs_law_name(r->drop_law))) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_seeds", r->drop_seeds) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_stands", r->drop_stands) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_energy_J", r->drop_energy_J) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_barrier_J", r->drop_barrier_J) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_saturation_N_m", r->drop_saturation_N_m) != NULL;
        ok &= cJSON_AddNumberToObject(o, "drop_law_critical_com_height_m", r->drop_critical_m) != NULL;
        if (c->band[0]) {
            ok &= cJSON_AddStringToObject(o, "band_end", c->end[r->band_end].name) != NULL;
            for (int e = 0; e < fs_campaign_nends(c); e++) {
                char key[32];
                snprintf(key, sizeof key, "landed_%s", c->end[e].name);
                ok &= cJSON_AddNumberToObject(o, key, r->end_landed[e]) != NULL;
                snprintf(key, sizeof key, "success_rate_%s", c->end[e].name);
                ok &= cJSON_AddNumberToObject(o, key, r->end_rate[e]) != NULL;
            }
            ok &= (r->law_end < 0 ? cJSON_AddNullToObject(o, "law_end")
                                  : cJSON_AddStringToObject(o, "law_end", c->end[r->law_end].name)) != NULL;
            for (int e = 0; e < fs_campaign_nends(c); e++) {
                char key[48];
                snprintf(key, sizeof key, "law_prediction_%s", c->end[e].name);
                ok &= (r->law_end < 0 || r->end_law[e] == FS_LAW_NONE
                           ? cJSON_AddNullToObject(o, key)
                           : cJSON_AddStringToObject(o, key, fs_law_name(r->end_law[e]))) != NULL;
                snprintf(key, sizeof key, "drop_law_prediction_%s", c->end[e].name);
                int none = r->law_end < 0 || r->end_drop_law[e] == FS_LAW_NONE;
                ok &= (none ? cJSON_AddNullToObject(o, key) : cJSON_AddStringToObject(o, key, fs_law_name(r->end_drop_law[e]))) != NULL;
                snprintf(key, sizeof key, "drop_law_stands_%s", c->end[e].name);
                ok &= (none ? cJSON_AddNullToObject(o, key) : cJSON_AddNumberToObject(o, key, r->end_drop_stands[e])) != NULL;
            }
        }
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
            char key[FS_NAME_MAX + 8];
            snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
            ok &= cJSON_AddNumberToObject(o, key, r->median[m]) != NULL; /* NAN is written as null */
        }
        ok &= fs_json_put(rows, NULL, o);
    }
    cJSON *ex = cJSON_AddArrayToObject(root, "expectations");
    ok &= ex != NULL;
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        cJSON *o = cJSON_CreateObject();
        ok &= cJSON_AddStringToObject(o, "name", e->name) != NULL;
        ok &= cJSON_AddStringToObject(o, "foot", c->foot[e->foot].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "terrain", c->terrain[e->terrain].name) != NULL;
        ok &= cJSON_AddStringToObject(o, "robot", c->robot[e->robot].name) != NULL;
        ok &= cJSON_AddNumberToObject(o, "min_success", e->min_success) != NULL;
        ok &= cJSON_AddNumberToObject(o, "max_success", e->max_success) != NULL;
        const fs_campaign_row *r = fs_campaign_row_of(c, x->rows, e->foot, e->terrain, e->robot);
        ok &= cJSON_AddNumberToObject(o, "success_rate", r->success_rate) != NULL;
        ok &= cJSON_AddBoolToObject(o, "met", fs_expectation_met(e, r)) != NULL;
        ok &= fs_json_put(ex, NULL, o);
    }
    if (ok)
        return root;
    cJSON_Delete(root); /* a field could not be added (out of memory): no result rather than one short of it */
    return NULL;
}

static int fill_summary_json(FILE *f, const out_ctx *x)
{
    cJSON *root = summary_json(x);
    int ok = fs_json_print(f, root);
    cJSON_Delete(root);
    return ok;
}

/* ---- schema.sql: the CSV files as SQLite tables ------------------------------------------- */

/* A column of a table schema.sql makes, as its declaration (`"name" TYPE`) or, with set, as the
 * assignment that turns its empty text into NULL (`"name" = NULLIF("name", '')`). */
typedef struct sql_list {
    FILE *f;
    int n, set;
} sql_list;

static void sql_column(sql_list *l, const char *name, const char *type)
{
    fputs(l->n++ ? (l->set ? ", " : ",\n") : "", l->f);
    if (l->set)
        fprintf(l->f, "\"%s\" = NULLIF(\"%s\", '')", name, name);
    else
        fprintf(l->f, "  \"%s\" %s", name, type);
}

/* SQL text: single quotes doubled. */
static void sql_text(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', f);
        fputc(*s, f);
    }
    fputc('\'', f);
}

/* For each band end, n columns NAME_END of the given types (name and type pairs in nt). */
static void sql_end_columns(sql_list *l, const fs_campaign *c, const char *const *nt, int n)
{
    for (int e = 0; e < fs_campaign_nends(c); e++)
        for (int i = 0; i < n; i++) {
            char key[48];
            snprintf(key, sizeof key, "%s_%s", nt[2 * i], c->end[e].name);
            sql_column(l, key, nt[2 * i + 1]);
        }
}

/* The columns of trials.csv (summary 0) or summary.csv (1), in the files' order, each with its type:
 * the names and the order are those the CSV writers above write. */
static void sql_columns(sql_list *l, const fs_campaign *c, int summary)
{
    sql_column(l, "foot", "TEXT NOT NULL");
    sql_column(l, "terrain", "TEXT NOT NULL");
    sql_column(l, "robot", "TEXT NOT NULL");
    for (int w = 0; w < c->nsweep; w++)
        sql_column(l, c->sweep[w], "REAL");
    if (!summary) {
        static const char *const pose[] = {"x_m", "y_m", "yaw_deg", "pitch_deg", "roll_deg"};
        if (c->band[0])
            sql_column(l, "band_end", "TEXT NOT NULL");
        sql_column(l, "seed", "INTEGER NOT NULL");
        for (int k = 0; k < 5; k++)
            sql_column(l, pose[k], "REAL");
        sql_column(l, "outcome", "TEXT NOT NULL");
        sql_column(l, "rule", "TEXT NOT NULL");
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            sql_column(l, fs_campaign_metrics[m].name, strcmp(fs_campaign_metrics[m].name, "steps") ? "REAL" : "INTEGER");
        sql_column(l, "failure", "TEXT");
        return;
    }
    static const char *const counts[] = {"trials", "landed", "fell", "undecided", "failed_numerics", "hung"};
    for (int k = 0; k < 6; k++)
        sql_column(l, counts[k], "INTEGER NOT NULL");
    sql_column(l, "success_rate", "REAL");
    sql_column(l, "ci_low", "REAL");
    sql_column(l, "ci_high", "REAL");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
        sql_column(l, key, "REAL");
    }
    sql_column(l, "law_prediction", "TEXT");
    sql_column(l, "law_K_N_m_per_rad", "REAL");
    sql_column(l, "law_critical_com_height_m", "REAL");
    sql_column(l, "drop_law_prediction", "TEXT");
    sql_column(l, "drop_law_seeds", "INTEGER");
    sql_column(l, "drop_law_stands", "INTEGER");
    sql_column(l, "drop_law_energy_J", "REAL");
    sql_column(l, "drop_law_barrier_J", "REAL");
    sql_column(l, "drop_law_saturation_N_m", "REAL");
    sql_column(l, "drop_law_critical_com_height_m", "REAL");
    if (!c->band[0])
        return;
    static const char *const rates[] = {"landed", "INTEGER NOT NULL", "success_rate", "REAL"};
    static const char *const laws[] = {"law_prediction", "TEXT", "drop_law_prediction", "TEXT", "drop_law_stands", "INTEGER"};
    sql_column(l, "band_end", "TEXT NOT NULL");
    sql_end_columns(l, c, rates, 2);
    sql_column(l, "law_end", "TEXT");
    sql_end_columns(l, c, laws, 3);
}

/* One table filled from its CSV file: made, imported (the header row skipped), and every empty
 * field (a missing value) turned into NULL, which .import would keep as empty text. */
static void sql_table(FILE *f, const fs_campaign *c, const char *table, const char *csv, int summary)
{
    fprintf(f, "DROP TABLE IF EXISTS %s;\nCREATE TABLE %s (\n", table, table);
    sql_columns(&(sql_list){f, 0, 0}, c, summary);
    fprintf(f, "\n);\n.import --csv --skip 1 %s %s\nUPDATE %s SET ", csv, table, table);
    sql_columns(&(sql_list){f, 0, 1}, c, summary);
    fputs(";\n", f);
}

/* schema.sql: a sqlite3 script that makes the campaign's tables from its CSV files, with typed
 * columns and NULL for a missing value, and its provenance as tables. */
static int fill_schema(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    fprintf(f, "-- Campaign %s as SQLite tables: in this folder, `sqlite3 %s.sqlite < schema.sql` (sqlite3 3.32 or\n"
               "-- later) makes tables trials (trials.csv) and summary (summary.csv), their columns typed, an empty\n"
               "-- field NULL, and provenance, provenance_inputs and provenance_overrides (summary.json's).\n"
               "BEGIN;\n",
            c->name, c->name);
    sql_table(f, c, "trials", "trials.csv", 0);
    sql_table(f, c, "summary", "summary.csv", 1);
    fs_provenance p = provenance_of(c);
    fputs("DROP TABLE IF EXISTS provenance;\nCREATE TABLE provenance (footsim TEXT NOT NULL, seeds INTEGER NOT NULL, "
          "first_seed INTEGER NOT NULL, settings TEXT NOT NULL);\nINSERT INTO provenance VALUES (", f);
    sql_text(f, p.version ? p.version : "");
    fprintf(f, ", %d, %d, ", p.nseeds, p.first_seed);
    sql_text(f, p.settings);
    fputs(");\nDROP TABLE IF EXISTS provenance_inputs;\nCREATE TABLE provenance_inputs (path TEXT NOT NULL, hash TEXT "
          "NOT NULL);\n", f);
    for (int i = 0; i < p.ninputs; i++) {
        fputs("INSERT INTO provenance_inputs VALUES (", f);
        sql_text(f, p.inputs[i].path);
        fprintf(f, ", '%016llx');\n", p.inputs[i].hash);
    }
    fputs("DROP TABLE IF EXISTS provenance_overrides;\nCREATE TABLE provenance_overrides (position INTEGER NOT NULL, "
          "override TEXT NOT NULL);\n", f);
    for (int i = 0; i < p.noverrides; i++) {
        fprintf(f, "INSERT INTO provenance_overrides VALUES (%d, ", i + 1);
        sql_text(f, p.overrides[i]);
        fputs(");\n", f);
    }
    fputs("COMMIT;\n", f);
    return 1;
}

fs_status fs_campaign_write(const fs_campaign *c, const fs_trial_result *results, const fs_campaign_row *rows,
                            const char *dir, fs_error *err)
{
    const out_ctx x = {c, results, rows};
    fs_status s = write_file(dir, "trials.csv", fill_trials, &x, err);
    if (s == FS_OK)
        s = write_file(dir, "summary.csv", fill_summary_csv, &x, err);
    if (s == FS_OK)
        s = write_file(dir, "summary.md", fill_summary_md, &x, err);
    if (s == FS_OK)
        s = write_file(dir, "schema.sql", fill_schema, &x, err);
    return s;
}

fs_status fs_campaign_write_summary(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err)
{
    const out_ctx x = {c, NULL, rows};
    return write_file(dir, "summary.json", fill_summary_json, &x, err);
}

/* ---- the chart ---------------------------------------------------------------------------- */

/* The chart's series are the (foot, robot) pairs, foot-major, and for a sweep each of its terrains
 * too; a series' title names the robot only when the campaign has several, the terrain only when a
 * sweep has several. */
static int nseries(const fs_campaign *c) { return c->nfeet * c->nrobots * (c->nsweep ? c->nbase : 1); }

static void series_of(const fs_campaign *c, int k, int *foot, int *robot, int *base)
{
    int nbase = c->nsweep ? c->nbase : 1;
    *base = k % nbase;
    *robot = k / nbase % c->nrobots;
    *foot = k / nbase / c->nrobots;
}

static void series_title(const fs_campaign *c, int k, char *buf, size_t size)
{
    int foot, robot, base;
    series_of(c, k, &foot, &robot, &base);
    const char *terrain = c->nsweep && c->nbase > 1 ? c->terrain[base * c->nvalues[0] * c->nvalues[1]].name : "";
    int cut = (int)strcspn(terrain, "@");
    snprintf(buf, size, "%s%s%s%s%.*s", c->foot[foot].name, c->nrobots > 1 ? ", " : "",
             c->nrobots > 1 ? c->robot[robot].name : "", *terrain ? ", " : "", cut, terrain);
}

/* A sweep's row of series k at point (i, j) of its values. */
static const fs_campaign_row *point_row(const out_ctx *x, int k, int i, int j)
{
    const fs_campaign *c = x->c;
    int foot, robot, base;
    series_of(c, k, &foot, &robot, &base);
    return fs_campaign_row_of(c, x->rows, foot, (base * c->nvalues[0] + i) * c->nvalues[1] + j, robot);
}

/* The swept values of key w, in the file's order. */
static double value_of(const fs_campaign *c, int w, int i)
{
    return c->terrain[w ? i : i * c->nvalues[1]].sweep_value[w];
}

/* Log scale for an axis whose values are all positive and span a factor of 20 or more. */
static int log_axis(const fs_campaign *c, int w)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < c->nvalues[w]; i++)
        lo = fmin(lo, value_of(c, w, i)), hi = fmax(hi, value_of(c, w, i));
    return lo > 0 && hi >= 20 * lo;
}

/* The edges of value i's cell of a heat map: half-way (geometrically on a log axis) to its neighbours. */
static void cell_edges(const fs_campaign *c, int w, int i, double edge[2])
{
    int n = c->nvalues[w], lg = log_axis(c, w);
    double v = value_of(c, w, i);
    for (int side = 0; side < 2; side++) {
        int nb = side ? i + 1 : i - 1;
        double other = nb >= 0 && nb < n ? value_of(c, w, nb) : NAN;
        if (isnan(other)) /* the outer edge: as far out as the inner one */
            other = n > 1 ? (lg ? v * v / value_of(c, w, side ? i - 1 : i + 1) : 2 * v - value_of(c, w, side ? i - 1 : i + 1))
                          : (lg ? v * (side ? 2 : 0.5) : v + (side ? 0.5 : -0.5) * (v ? fabs(v) : 1));
        edge[side] = lg ? sqrt(v * other) : (v + other) / 2;
    }
}

/* Bars: a line per terrain with each series' rate, low and high. One key swept: a block per series
 * of (value, rate, low, high). Two: a block per series of heat-map cells (v1, v2, their cell's
 * edges, rate, the law's prediction 1 stands, 0 topples, -1 none, and its critical height). */
static int fill_chart_data(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    char title[4 * FS_NAME_MAX];
    if (!c->nsweep) {
        fputs("# terrain", f);
        for (int k = 0; k < nseries(c); k++) {
            series_title(c, k, title, sizeof title);
            fputs(" \"", f);
            fs_gp_data_text(f, title);
            fputs("\": rate low high law (1 stands, 0 topples, -1 none)", f);
        }
        fputc('\n', f);
        for (int t = 0; t < c->nterrains; t++) {
            fputc('"', f);
            fs_gp_data_text(f, c->terrain[t].name);
            fputc('"', f);
            for (int k = 0; k < nseries(c); k++) {
                int foot, robot, base;
                series_of(c, k, &foot, &robot, &base);
                const fs_campaign_row *r = fs_campaign_row_of(c, x->rows, foot, t, robot);
                fprintf(f, " %.17g %.17g %.17g %d", r->success_rate, r->ci_low, r->ci_high, r->law);
            }
            fputc('\n', f);
        }
        return 1;
    }
    for (int k = 0; k < nseries(c); k++) {
        series_title(c, k, title, sizeof title);
        fprintf(f, "%s# ", k ? "\n\n" : "");
        fs_gp_data_text(f, title);
        fputs(": ", f);
        fs_gp_data_text(f, c->sweep[0]);
        if (c->nsweep == 1) {
            fputs(" rate low high", f);
            for (int e = 0; c->band[0] && e < fs_campaign_nends(c); e++) /* a band: each end's rate too */
                fprintf(f, " rate_%s", c->end[e].name);
            fputc('\n', f);
            for (int i = 0; i < c->nvalues[0]; i++) {
                const fs_campaign_row *r = point_row(x, k, i, 0);
                fprintf(f, "%.17g %.17g %.17g %.17g", value_of(c, 0, i), r->success_rate, r->ci_low, r->ci_high);
                for (int e = 0; c->band[0] && e < fs_campaign_nends(c); e++)
                    fprintf(f, " %.17g", r->end_rate[e]);
                fputc('\n', f);
            }
            continue;
        }
        fputc(' ', f);
        fs_gp_data_text(f, c->sweep[1]);
        fputs(" x_low x_high y_low y_high rate law critical_height_m drop_law drop_critical_height_m\n", f);
        for (int i = 0; i < c->nvalues[0]; i++)
            for (int j = 0; j < c->nvalues[1]; j++) {
                const fs_campaign_row *r = point_row(x, k, i, j);
                double ex[2], ey[2];
                cell_edges(c, 0, i, ex);
                cell_edges(c, 1, j, ey);
                fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %.17g %d %.17g\n", value_of(c, 0, i),
                        value_of(c, 1, j), ex[0], ex[1], ey[0], ey[1], r->success_rate, r->law,
                        isfinite(r->law_critical_m) ? r->law_critical_m : NAN, r->drop_law,
                        isfinite(r->drop_critical_m) ? r->drop_critical_m : NAN);
            }
    }
    return 1;
}

/* Which swept key is a robot's centre-of-mass height: the law's critical height is then a line on
 * the heat map; -1 when neither. */
static int height_key(const fs_campaign *c)
{
    for (int w = 0; w < c->nsweep; w++)
        if (!strcmp(c->sweep[w], "robot.com_height_m"))
            return w;
    return -1;
}

static void heat_map_script(FILE *f, const fs_campaign *c)
{
    int n = nseries(c), cols = n < 3 ? n : 3, rows = (n + cols - 1) / cols, hk = height_key(c);
    double ex[2], ey[2], xr[2], yr[2];
    cell_edges(c, 0, 0, ex), cell_edges(c, 0, c->nvalues[0] - 1, xr);
    cell_edges(c, 1, 0, ey), cell_edges(c, 1, c->nvalues[1] - 1, yr);
    /* each panel 560 by 480 px: the heat map, and under its axis label a legend of the laws' marks
     * and lines (three rows at 9 pt, held by a bottom margin of 7 character heights) */
    fprintf(f, "set terminal pngcairo size %d,%d noenhanced font 'sans,10'\nset output out\n"
               "set multiplot layout %d,%d title 'Campaign ' . campaign . ': success rate (%d seeds per point) and "
               "the laws'\n"
               "set palette defined (0 '#b2182b', 0.5 '#f7f7f7', 1 '#2166ac')\nset cbrange [0:1]\n"
               "set cblabel 'success rate'\nset xlabel key1\nset ylabel key2\n%s%s"
               "set xrange [%.17g:%.17g]\nset yrange [%.17g:%.17g]\n"
               "set bmargin 7\nset key at graph 0.5, graph -0.19 center top horizontal maxrows 3 reverse Left "
               "samplen 2 width 1 font 'sans,9'\nset style fill solid 1.0 noborder\n",
            560 * cols, 480 * rows, rows, cols, c->seeds, log_axis(c, 0) ? "set logscale x\n" : "",
            log_axis(c, 1) ? "set logscale y\n" : "", fmin(ex[0], xr[1]), fmax(ex[0], xr[1]), fmin(ey[0], yr[1]),
            fmax(ey[0], yr[1]));
    for (int k = 0; k < n; k++) {
        fprintf(f, "set title series%d\nplot 'chart.dat' index %d using 1:2:3:4:5:6:7 with boxxyerror lc palette "
                   "notitle, \\\n"
                   "     '' index %d using 1:($8 == 1 ? $2 : 1/0) with points pt 6 ps 1.2 lc rgb 'black' notitle, \\\n"
                   "     '' index %d using 1:($8 == 0 ? $2 : 1/0) with points pt 2 ps 1.2 lc rgb 'black' notitle, \\\n"
                   "     '' index %d using 1:($10 == 1 ? $2 : 1/0) with points pt 7 ps 0.5 lc rgb 'black' notitle",
                k + 1, k, k, k, k);
        /* the critical height against the other key: one point per value of it (a row of the block
         * each, picked with every, so that the line is not broken by skipped rows), clipped by the
         * axes' ranges, which the data set */
        if (hk == 1)
            fprintf(f, ", \\\n     '' index %d every %d using 1:9 with lines lw 2 lc rgb 'black' notitle, \\\n"
                       "     '' index %d every %d using 1:11 with lines lw 2 dt 2 lc rgb 'black' notitle", k,
                    c->nvalues[1], k, c->nvalues[1]);
        else if (hk == 0)
            fprintf(f, ", \\\n     '' index %d every ::0::%d using 9:2 with lines lw 2 lc rgb 'black' notitle, \\\n"
                       "     '' index %d every ::0::%d using 11:2 with lines lw 2 dt 2 lc rgb 'black' notitle", k,
                    c->nvalues[1] - 1, k, c->nvalues[1] - 1);
        /* the legend: the static law's marks and line, then the drop law's (the lines only where a
         * key is the height) */
        fprintf(f, ", \\\n     keyentry with points pt 6 ps 1.2 lc rgb 'black' title 'static law: stands', \\\n"
                   "     keyentry with points pt 2 ps 1.2 lc rgb 'black' title 'static law: topples'%s, \\\n"
                   "     keyentry with points pt 7 ps 0.5 lc rgb 'black' title 'drop law: stands'%s\n",
                hk >= 0 ? ", \\\n     keyentry with lines lw 2 lc rgb 'black' title 'its critical height K/(m g)'" : "",
                hk >= 0 ? ", \\\n     keyentry with lines lw 2 dt 2 lc rgb 'black' title 'its highest centre of mass'"
                        : "");
    }
    fputs("unset multiplot\n", f);
}

/* name = NAME as a gnuplot string (fs_gp_string): the script uses the variable, never the text. */
static void name_variable(FILE *f, const char *name, int number, const char *text)
{
    fprintf(f, number ? "%s%d = " : "%s = ", name, number);
    fs_gp_string(f, text);
    fputc('\n', f);
}

/* The names the chart shows, each a variable: campaign, series1 .., terrain1 .. (bars) or key1,
 * key2 (the swept keys). A received summary.json's names are anyone's text. */
static void chart_names(FILE *f, const fs_campaign *c)
{
    char title[4 * FS_NAME_MAX];
    fputs("# the names shown, as gnuplot strings: data, never code\n", f);
    name_variable(f, "campaign", 0, c->name);
    for (int k = 0; k < nseries(c); k++) {
        series_title(c, k, title, sizeof title);
        name_variable(f, "series", k + 1, title);
    }
    for (int t = 0; !c->nsweep && t < c->nterrains; t++)
        name_variable(f, "terrain", t + 1, c->terrain[t].name);
    for (int w = 0; w < c->nsweep; w++)
        name_variable(f, "key", w + 1, c->sweep[w]);
    for (int e = 0; c->band[0] && c->nsweep == 1 && e < fs_campaign_nends(c); e++)
        name_variable(f, "end", e + 1, c->end[e].name);
}

static int fill_chart_script(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    fputs("# A campaign's chart: 'gnuplot chart.gp' in this folder draws success.png.\n"
          "if (!exists(\"out\")) out = 'success.png'\n",
          f);
    chart_names(f, c);
    if (c->nsweep == 2) {
        heat_map_script(f, c);
        return 1;
    }
    int n = nseries(c), nt = c->nterrains, longest = 1;
    for (int t = 0; t < nt; t++)
        if ((int)strlen(c->terrain[t].name) > longest)
            longest = (int)strlen(c->terrain[t].name);
    /* wide enough for every bar (a bar at least 16 px); the legend takes about 300 px */
    int width = c->nsweep ? 960 : (int)fmax(960, 400 + 16.0 * nt * (n + 1));
    fprintf(f, "set terminal pngcairo size %d,540 noenhanced font 'sans,11'\n"
               "set output out\n"
               "set title 'Campaign ' . campaign . ': success rate with 95 %% Wilson interval (%d seeds each)'\n"
               "set ylabel 'success rate (landed / trials)'\n"
               "set yrange [-0.05:1.05]\nset ytics 0,0.2,1\nset grid ytics\nset key outside right top noenhanced\n"
               "set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'\n",
            width, c->seeds);
    if (!c->nsweep) {
        /* bars drawn as boxes at known places (not gnuplot's histogram), so that a rate of zero gets
         * a thin bar under the zero line in its colour, with its interval (a vector from low to high:
         * error bars would leave a hole at the rate); within a terrain the bars stand robot by robot
         * (half a bar apart), each foot in its own colour, each robot in its own shade, and above
         * each bar the law's verdict for its foot and robot (o stands, x topples); terrain names
         * turned when they are wider than their group of bars (about 7.5 px a character at 11 pt) */
        double group_px = (width - 400.0) / nt, bar = 0.8 / (n + 0.5 * (c->nrobots - 1));
        fprintf(f, "set yrange [-0.05:1.12]\nset xrange [-0.6:%d.4]\nset xtics scale 0 noenhanced%s (", nt - 1,
                7.5 * longest > 0.9 * group_px ? " rotate by 30 right" : "");
        for (int t = 0; t < nt; t++) /* each terrain's name under its group of bars */
            fprintf(f, "%sterrain%d %d", t ? ", " : "", t + 1, t);
        fprintf(f, ")\nset boxwidth %.6g absolute\n"
                   "set style fill solid 0.6 border -1\nset xlabel 'terrain'\n"
                   "set label \"a thin bar under the zero line:\\nno trial landed\" at graph 1.03, graph 0.05 "
                   "font 'sans,9' tc rgb 'gray30'\nplot ",
                bar);
        for (int k = 0; k < n; k++) {
            int foot, robot, base;
            series_of(c, k, &foot, &robot, &base);
            double off = -0.4 + (robot * c->nfeet + foot + 0.5 * robot + 0.5) * bar;
            double shade = 0.75 - 0.5 * robot / (c->nrobots > 1 ? c->nrobots - 1 : 1);
            int rate = 2 + 4 * k;
            fprintf(f, "%s'chart.dat' using ($0%+.6g):%d with boxes fs solid %.3g lc %d title series%d, \\\n"
                       "     '' using ($0%+.6g):(column(%d) == 0 ? -0.025 : 1/0) with boxes fs solid %.3g lc %d notitle, \\\n"
                       "     '' using ($0%+.6g):%d:(0):(column(%d) - column(%d)) with vectors heads size screen 0.004,90 "
                       "lw 1 lc rgb 'black' notitle, \\\n"
                       "     '' using ($0%+.6g):(column(%d) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc %d notitle, \\\n"
                       "     '' using ($0%+.6g):(column(%d) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc %d notitle",
                    k ? ", \\\n     " : "", off, rate, shade, foot + 1, k + 1, off, rate, shade, foot + 1, off,
                    rate + 1, rate + 2, rate + 1, off, rate + 3, foot + 1, off, rate + 3, foot + 1);
        }
        fputs(", \\\n     keyentry with points pt 6 lc rgb 'black' title 'law: stands', \\\n"
              "     keyentry with points pt 2 lc rgb 'black' title 'law: topples'\n",
              f);
        return 1;
    }
    /* a line per series, each foot in its own colour and each robot in its own dash */
    fputs("set xlabel key1\nplot ", f);
    for (int k = 0; k < nseries(c); k++) {
        int foot, robot, base;
        series_of(c, k, &foot, &robot, &base);
        fprintf(f, "%s'chart.dat' index %d using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc %d "
                   "notitle, \\\n     '' index %d using 1:2 with linespoints lw 2 dt %d pt %d lc %d title series%d",
                k ? ", \\\n     " : "", k, foot + 1, k, robot + 1, 7 + 2 * base, foot + 1, k + 1);
        for (int e = 0; c->band[0] && e < fs_campaign_nends(c); e++) /* each end's rate, thin, under the band's */
            fprintf(f, ", \\\n     '' index %d using 1:%d with linespoints lw 1 dt %d pt %d ps 0.8 lc %d title series%d . "
                       "', ' . end%d . ' end'", k, 5 + e, 2 + e, 6 + 2 * e, foot + 1, k + 1, e + 1);
    }
    fputc('\n', f);
    return 1;
}

fs_status fs_campaign_write_chart(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err)
{
    const out_ctx x = {c, NULL, rows};
    fs_status s = write_file(dir, "chart.dat", fill_chart_data, &x, err);
    return s == FS_OK ? write_file(dir, "chart.gp", fill_chart_script, &x, err) : s;
}

/* ---- expectations ------------------------------------------------------------------------- */

int fs_campaign_check(const fs_campaign *c, const fs_campaign_row *rows, FILE *out)
{
    int failed = 0;
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        const fs_campaign_row *r = fs_campaign_row_of(c, rows, e->foot, e->terrain, e->robot);
        int ok = fs_expectation_met(e, r);
        failed += !ok;
        fprintf(out, "  %-6s %s: %s on %s under %s landed %d of %d (%.2f, 95 %% CI [%.2f, %.2f]", ok ? "ok" : "FAILED",
                e->name, c->foot[e->foot].name, c->terrain[e->terrain].name, c->robot[e->robot].name, r->landed,
                r->trials, r->success_rate, r->ci_low, r->ci_high);
        for (int k = 0; c->band[0] && k < fs_campaign_nends(c); k++) /* with a band: the worse end's, and each end */
            fprintf(out, "%s%s %d of %d", k ? ", " : "; band: ", c->end[k].name, r->end_landed[k], r->end_trials[k]);
        fprintf(out, "); wanted %.2f to %.2f\n", e->min_success, e->max_success);
    }
    return failed;
}
