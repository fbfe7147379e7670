/* campaign_compare.c: a campaign's summary compared with a baseline, cell by cell, within the
 * baseline's tolerances; or judged equivalent to a reference campaign run at another setting. */
#include "campaign_internal.h"

#include "footsim/io/fs_input.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- comparison --------------------------------------------------------------------------- */

cJSON *fs_campaign_read_summary(const char *path, fs_error *err)
{
    char *text;
    size_t len;
    /* a regular file of bounded size: a FIFO or /dev/zero is refused, not waited on or read forever */
    if (fs_read_regular(path, FS_SUMMARY_MAX_BYTES, "a summary.json written by footsim campaign", &text, &len, err) !=
        FS_OK)
        return NULL;
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    free(text);
    if (!root || !cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(root, "rows"))) {
        cJSON_Delete(root);
        fs_fail(err, FS_BAD_INPUT, "%s: not a campaign summary (JSON with \"rows\"); give a summary.json written by "
                                   "footsim campaign", path);
        return NULL;
    }
    return root;
}

fs_status fs_campaign_summary_expectations(const char *path, FILE *out, int *failed, int *total, fs_error *err)
{
    *failed = *total = 0;
    cJSON *root = fs_campaign_read_summary(path, err);
    if (!root)
        return FS_BAD_INPUT;
    const cJSON *e;
    cJSON_ArrayForEach(e, cJSON_GetObjectItemCaseSensitive(root, "expectations")) {
        int met = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(e, "met"));
        ++*total;
        *failed += !met;
        fprintf(out, "  %-6s %s: %s on %s under %s: success %.2f; wanted %.2f to %.2f\n", met ? "ok" : "FAILED",
                text_of(e, "name"), text_of(e, "foot"), text_of(e, "terrain"), text_of(e, "robot"),
                number_of(e, "success_rate"), number_of(e, "min_success"), number_of(e, "max_success"));
    }
    cJSON_Delete(root);
    return FS_OK;
}

/* The row of the same cell: foot, terrain and robot (a summary from before robots has none: "?"). */
static const cJSON *find_row(const cJSON *rows, const cJSON *like)
{
    const cJSON *r;
    cJSON_ArrayForEach(r, rows)
        if (!strcmp(text_of(r, "foot"), text_of(like, "foot")) && !strcmp(text_of(r, "terrain"), text_of(like, "terrain")) &&
            !strcmp(text_of(r, "robot"), text_of(like, "robot")))
            return r;
    return NULL;
}

/* The tolerance of metric m: the baseline's, else footsim's default. */
static void tolerance_of(const cJSON *baseline, int m, double tol[2])
{
    sscanf(fs_campaign_metrics[m].tolerance, "%lf, %lf", &tol[0], &tol[1]);
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(baseline, "tolerances"),
                                                      fs_campaign_metrics[m].name);
    if (cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(t, "relative")))
        tol[0] = number_of(t, "relative");
    if (cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(t, "absolute")))
        tol[1] = number_of(t, "absolute");
}

static int same_number(double a, double b) { return (isnan(a) && isnan(b)) || a == b; }

/* A table row's first cells: the cell it is about. */
static void put_cell(FILE *out, const cJSON *row)
{
    fprintf(out, "| %s | %s | %s | ", text_of(row, "foot"), text_of(row, "terrain"), text_of(row, "robot"));
}

/* A median over the landed trials that one of two cells has and the other does not (no trial of
 * it landed) is said, not judged: the success rates judge that change, and it would count twice.
 * Returns 1 then. */
static int landed_in_one(FILE *out, const cJSON *r, const char *key, int over_landed, double base, double now)
{
    if (!over_landed || isnan(base) == isnan(now))
        return 0;
    put_cell(out, r);
    fprintf(out, "%s | %.6g | %.6g | | not judged: no trial landed in one of the two (the success rate judges that) "
                 "|\n", key, base, now);
    return 1;
}

/* A median the older of two summaries lacks (written before footsim had the metric: a baseline's
 * or reference's rest_ankle_drop_m from before 2026-11-25) is said, not judged. Returns 1 then. */
static int not_in(FILE *out, const cJSON *older, const cJSON *r, const char *key, const char *which)
{
    if (cJSON_GetObjectItemCaseSensitive(older, key))
        return 0;
    put_cell(out, r);
    fprintf(out, "%s | (not in the %s) | %.6g | | not compared: the %s was written before footsim had it |\n", key,
            which, number_of(r, key), which);
    return 1;
}

/* Prints one changed quantity; returns 1 when it is outside what is allowed. */
static int report_change(FILE *out, const cJSON *row, const char *what, double base, double now, double lo, double hi)
{
    int bad = !(now >= lo && now <= hi) && !(isnan(base) && isnan(now));
    put_cell(out, row);
    fprintf(out, "%s | %.6g | %.6g | [%.6g, %.6g] | %s |\n", what, base, now, lo, hi, bad ? "**outside**" : "within");
    return bad;
}

/* A count that may only fall (undecided, hung trials): never more than the baseline's. A summary
 * without it (written before footsim counted it) had none: 0. Returns 1 when it rose. */
static int compare_count(FILE *out, const cJSON *b, const cJSON *r, const char *key, int *changed)
{
    double now = number_of(r, key), base = number_of(b, key);
    now = isnan(now) ? 0 : now, base = isnan(base) ? 0 : base;
    if (now == base)
        return 0;
    (*changed)++;
    return report_change(out, r, key, base, now, 0, base);
}

/* Compares one row of each; returns how many quantities left their allowance; counts changes. */
static int compare_row(FILE *out, const cJSON *baseline, const cJSON *b, const cJSON *r, int *changed)
{
    int bad = 0;
    double rate = number_of(r, "success_rate"), base_rate = number_of(b, "success_rate");
    if (!same_number(rate, base_rate) || number_of(r, "trials") != number_of(b, "trials")) {
        (*changed)++;
        bad += report_change(out, r, "success_rate", base_rate, rate, number_of(b, "ci_low"), number_of(b, "ci_high"));
    }
    /* trials the window left undecided (a baseline without the count had none: its rules decided
       every trial), and trials whose worker hung (a baseline has none) */
    bad += compare_count(out, b, r, "undecided", changed);
    bad += compare_count(out, b, r, "hung", changed);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
        double base = number_of(b, key), now = number_of(r, key), tol[2];
        if (same_number(base, now) || not_in(out, b, r, key, "baseline"))
            continue;
        if (landed_in_one(out, r, key, fs_campaign_metrics[m].over_landed, base, now)) {
            (*changed)++;
            continue;
        }
        (*changed)++;
        tolerance_of(baseline, m, tol);
        double allow = tol[0] * fabs(base) + tol[1];
        bad += report_change(out, r, key, base, now, base - allow, base + allow);
    }
    return bad;
}

/* A provenance field as text (arrays and objects printed whole), or NULL when missing. */
static char *field_text(const cJSON *prov, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(prov, key);
    return v ? cJSON_PrintUnformatted(v) : NULL;
}

/* Compares the two summaries' provenance: prints every difference; returns the names of those that
 * make the comparison meaningless (seeds, overrides, inputs) in `refused`, "" when none. */
static void compare_provenance(const cJSON *result, const cJSON *baseline, int equivalence, FILE *out, char *refused,
                               size_t size)
{
    refused[0] = 0;
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(result, "provenance");
    const cJSON *b = cJSON_GetObjectItemCaseSensitive(baseline, "provenance");
    if (!r || !b) {
        fprintf(out, "provenance: not checked (%s has none)\n\n", !r ? "the result" : "the baseline");
        return;
    }
    static const char *const keys[] = {"footsim", "seeds", "first_seed", "overrides", "inputs", "settings"};
    int differ = 0;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        char *x = field_text(r, keys[i]), *y = field_text(b, keys[i]);
        if (!(x && y && !strcmp(x, y))) {
            fprintf(out, "provenance: %s differs: result %s, baseline %s\n", keys[i], x ? x : "(none)", y ? y : "(none)");
            differ = 1;
            /* another version, or other settings, is what a comparison is for; the rest is not (an
               equivalence compares settings, which may come as overrides: run.step_s) */
            if (strcmp(keys[i], "footsim") && strcmp(keys[i], "settings") &&
                !(equivalence && !strcmp(keys[i], "overrides"))) {
                size_t n = strlen(refused);
                snprintf(refused + n, size - n, "%s%s", n ? ", " : "", keys[i]);
            }
        }
        free(x);
        free(y);
    }
    fprintf(out, differ ? "\n" : "provenance: the same seeds, overrides and inputs\n\n");
}

static fs_status compare_mode(const char *result_path, const char *result_name, const char *baseline_path,
                              int force, int equivalence, FILE *out, int *nbad, fs_error *err);

/* ---- equivalence ------------------------------------------------------------------------- */

/* The metrics equivalence judges, each with its absolute floor (issue 12, docs/bench.md): a median
 * may differ from the reference's by 5 % or by the floor, whichever is larger. Peak force is
 * reported, not judged: an impact's peak depends on the step by nature. The ankle drop judged is
 * at rest, over the trials that landed: where a fall leaves the ankle is not well posed. */
static const struct {
    const char *metric;
    double floor;
} equivalence_metrics[] = {
    {"impact_impulse_Ns", 0}, {"final_tilt_deg", 0.5}, {"rest_ankle_drop_m", 1e-4},
    {"settle_time_s", 0.005}, {"mean_contacts", 1},    {"final_contacts", 1},
};
enum { N_EQUIVALENCE = sizeof equivalence_metrics / sizeof equivalence_metrics[0] };
static const double EQUIVALENCE_RELATIVE = 0.05;

static int over_landed(const char *metric)
{
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        if (!strcmp(fs_campaign_metrics[m].name, metric))
            return fs_campaign_metrics[m].over_landed;
    return 0;
}

/* One judged (or reported) quantity of a cell; returns 1 when it is not equivalent. */
static int report_equivalence(FILE *out, const cJSON *row, const char *what, double ref, double now, double lo,
                              double hi, int judged)
{
    int bad = judged && !(now >= lo && now <= hi) && !(isnan(ref) && isnan(now));
    put_cell(out, row);
    fprintf(out, "%s | %.6g | %.6g | ", what, ref, now);
    if (judged)
        fprintf(out, "[%.6g, %.6g] | %s |\n", lo, hi, bad ? "**differs**" : "equivalent");
    else
        fprintf(out, "%+.1f %% | reported (step-dependent) |\n", 100 * (now / ref - 1));
    return bad;
}

/* Judges one cell against its reference; returns how many quantities differ. */
static int equivalence_row(FILE *out, const cJSON *ref, const cJSON *r)
{
    /* the success rates: their 95 % Wilson intervals overlap */
    double lo = number_of(ref, "ci_low"), hi = number_of(ref, "ci_high");
    double rlo = number_of(r, "ci_low"), rhi = number_of(r, "ci_high");
    int overlap = rlo <= hi && lo <= rhi;
    put_cell(out, r);
    fprintf(out, "success_rate | %.6g [%.3g, %.3g] | %.6g [%.3g, %.3g] | intervals overlap | %s |\n",
            number_of(ref, "success_rate"), lo, hi, number_of(r, "success_rate"), rlo, rhi,
            overlap ? "equivalent" : "**differs**");
    int bad = !overlap;
    for (int i = 0; i < N_EQUIVALENCE; i++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", equivalence_metrics[i].metric);
        double base = number_of(ref, key), now = number_of(r, key);
        if (not_in(out, ref, r, key, "reference") ||
            landed_in_one(out, r, key, over_landed(equivalence_metrics[i].metric), base, now))
            continue;
        double allow = fmax(EQUIVALENCE_RELATIVE * fabs(base), equivalence_metrics[i].floor);
        bad += report_equivalence(out, r, key, base, now, base - allow, base + allow, 1);
    }
    /* trials the window left undecided or whose worker hung: never more than the reference's (a
       step that leaves trials undecided answers a different question) */
    static const char *const counts[] = {"undecided", "hung"};
    for (int i = 0; i < 2; i++) {
        double base = number_of(ref, counts[i]), now = number_of(r, counts[i]);
        base = isnan(base) ? 0 : base, now = isnan(now) ? 0 : now;
        if (now != base)
            bad += report_equivalence(out, r, counts[i], base, now, 0, base, 1);
    }
    bad += report_equivalence(out, r, "median_peak_force_N", number_of(ref, "median_peak_force_N"),
                              number_of(r, "median_peak_force_N"), 0, 0, 0);
    return bad;
}

fs_status fs_campaign_equivalence(const char *result_path, const char *result_name, const char *reference_path,
                                  int force, FILE *out, int *ndiffer, fs_error *err)
{
    return compare_mode(result_path, result_name, reference_path, force, 1, out, ndiffer, err);
}

fs_status fs_campaign_compare(const char *result_path, const char *baseline_path, int force, FILE *out, fs_error *err)
{
    return compare_mode(result_path, NULL, baseline_path, force, 0, out, NULL, err);
}

/* The two comparisons share reading, provenance and the pairing of rows; `equivalence` picks the
 * rule a pair of rows is judged by. */
static fs_status compare_mode(const char *result_path, const char *result_name, const char *baseline_path,
                              int force, int equivalence, FILE *out, int *nbad, fs_error *err)
{
    if (nbad)
        *nbad = 0;
    cJSON *result = fs_campaign_read_summary(result_path, err);
    cJSON *baseline = result ? fs_campaign_read_summary(baseline_path, err) : NULL;
    if (!baseline) {
        cJSON_Delete(result);
        return err ? err->status : FS_BAD_INPUT; /* as read_summary found it: bad input, unreadable, out of memory */
    }
    char refused[128];
    compare_provenance(result, baseline, equivalence, out, refused, sizeof refused);
    if (refused[0] && !force) {
        cJSON_Delete(result);
        cJSON_Delete(baseline);
        return fs_fail(err, FS_BAD_INPUT, "%s and %s were made with different %s (above): their numbers do not "
                       "compare; rerun one like the other, or give --force to compare them anyway", result_path,
                       baseline_path, refused);
    }
    const cJSON *rrows = cJSON_GetObjectItemCaseSensitive(result, "rows");
    const cJSON *brows = cJSON_GetObjectItemCaseSensitive(baseline, "rows");
    fprintf(out, "%s against the %s %s\n\n| foot | terrain | robot | quantity | %s | result | allowed | "
                 "verdict |\n|---|---|---|---|--:|--:|---|---|\n", result_name ? result_name : result_path,
            equivalence ? "reference" : "baseline", baseline_path, equivalence ? "reference" : "baseline");
    int bad = 0, changed = 0;
    const cJSON *b, *r;
    cJSON_ArrayForEach(b, brows) {
        r = find_row(rrows, b);
        if (!r) {
            put_cell(out, b);
            fputs("(row) | present | **missing** | | **outside** |\n", out);
            bad++, changed++;
        } else if (equivalence) {
            bad += equivalence_row(out, b, r);
        } else {
            bad += compare_row(out, baseline, b, r, &changed);
        }
    }
    cJSON_ArrayForEach(r, rrows)
        if (!find_row(brows, r)) {
            put_cell(out, r);
            fputs("(row) | **missing** | present | | **outside** |\n", out);
            bad++, changed++;
        }
    if (equivalence)
        fprintf(out, "\n%d rows in the reference; %d quantities differ: %s\n", cJSON_GetArraySize(brows), bad,
                bad ? "NOT EQUIVALENT" : "equivalent");
    else
        fprintf(out, "\n%d rows in the baseline; %d quantities changed, %d outside what the baseline allows: %s\n",
                cJSON_GetArraySize(brows), changed, bad, bad ? "CHANGED" : changed ? "within tolerance" : "identical");
    cJSON_Delete(result);
    cJSON_Delete(baseline);
    if (nbad)
        *nbad = bad;
    return bad ? FS_EXPECTATION_FAILED : FS_OK;
}
