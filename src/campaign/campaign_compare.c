/* campaign_compare.c: a campaign's summary compared with a baseline, cell by cell, within the
 * baseline's tolerances; or judged equivalent to a reference campaign run at another setting. */
#include "campaign_internal.h"

#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
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

/* A comparison under way: every quantity goes into the JSON; the Markdown lists a quantity when it
 * is outside what is allowed (or differs), or when every quantity was asked for (all). */
typedef struct cmp {
    FILE *out;        /* the Markdown, or NULL */
    int all;
    int header;       /* the table's header printed */
    int equivalence;
    cJSON *items;     /* every quantity compared (NULL: out of memory, said at the end) */
    int compared, changed, bad, reported;
} cmp;

/* A number for JSON: null when not finite. */
static cJSON *json_number(double v) { return isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull(); }

/* Adds one quantity of a cell to the JSON; counts it. */
static void add_item(cmp *x, const cJSON *row, const char *what, double base, double now, double lo, double hi,
                     const char *verdict, int changed, int bad, const char *note)
{
    x->compared++;
    x->changed += changed;
    x->bad += bad;
    x->reported += !strcmp(verdict, "reported");
    if (!x->items)
        return;
    cJSON *o = cJSON_CreateObject();
    int ok = o && cJSON_AddStringToObject(o, "foot", text_of(row, "foot")) &&
             cJSON_AddStringToObject(o, "terrain", text_of(row, "terrain")) &&
             cJSON_AddStringToObject(o, "robot", text_of(row, "robot")) && cJSON_AddStringToObject(o, "quantity", what);
    ok = ok && fs_json_put(o, x->equivalence ? "reference" : "baseline", json_number(base)) &&
         fs_json_put(o, "result", json_number(now)) && fs_json_put(o, "low", json_number(lo)) &&
         fs_json_put(o, "high", json_number(hi)) && cJSON_AddStringToObject(o, "verdict", verdict) &&
         cJSON_AddBoolToObject(o, "changed", changed) && cJSON_AddBoolToObject(o, "outside", bad) &&
         (!note || cJSON_AddStringToObject(o, "note", note));
    if (!ok || !fs_json_put(x->items, NULL, o)) {
        if (!ok)
            cJSON_Delete(o);
        cJSON_Delete(x->items);
        x->items = NULL;
    }
}

/* Prints a table row when it is to be listed: the cell it is about, then fmt. */
static void put_row(cmp *x, int listed, const cJSON *row, const char *fmt, ...)
{
    if (!x->out || !listed)
        return;
    if (!x->header++)
        fprintf(x->out, "| foot | terrain | robot | quantity | %s | result | allowed | verdict |\n|---|---|---|---|--:|--:|---|---|\n",
                x->equivalence ? "reference" : "baseline");
    fprintf(x->out, "| %s | %s | %s | ", text_of(row, "foot"), text_of(row, "terrain"), text_of(row, "robot"));
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    /* a missing number (printf's "nan", signed or not) as Markdown's one spelling of it: – */
    for (const char *c = text; *c; c++) {
        int sign = (*c == '-' || *c == '+') && !strncmp(c + 1, "nan", 3);
        int word = (c == text || !isalnum((unsigned char)c[-1])) && !strncmp(c + sign, "nan", 3) &&
                   !isalnum((unsigned char)c[sign + 3]);
        if (word) {
            fputs("–", x->out);
            c += sign + 2;
        } else {
            fputc(*c, x->out);
        }
    }
}

/* A median over the landed trials that one of two cells has and the other does not (no trial of
 * it landed) is said, not judged: the success rates judge that change, and it would count twice.
 * Returns 1 then. */
static int landed_in_one(cmp *x, const cJSON *r, const char *key, int over_landed, double base, double now)
{
    if (!over_landed || isnan(base) == isnan(now))
        return 0;
    static const char note[] = "no trial landed in one of the two (the success rate judges that)";
    add_item(x, r, key, base, now, NAN, NAN, "not judged", 1, 0, note);
    put_row(x, x->all, r, "%s | %.6g | %.6g | | not judged: %s |\n", key, base, now, note);
    return 1;
}

/* A median the older of two summaries lacks (written before footsim had the metric: a baseline's
 * or reference's rest_ankle_drop_m from before 2026-11-25) is said, not judged. Returns 1 then. */
static int not_in(cmp *x, const cJSON *older, const cJSON *r, const char *key, const char *which)
{
    if (cJSON_GetObjectItemCaseSensitive(older, key))
        return 0;
    char note[96];
    snprintf(note, sizeof note, "the %s was written before footsim had it", which);
    add_item(x, r, key, NAN, number_of(r, key), NAN, NAN, "not compared", 0, 0, note);
    put_row(x, x->all, r, "%s | (not in the %s) | %.6g | | not compared: %s |\n", key, which, number_of(r, key), note);
    return 1;
}

/* One quantity judged against [lo, hi] (identical when same); returns 1 when outside. */
static int judge(cmp *x, const cJSON *row, const char *what, double base, double now, double lo, double hi, int same)
{
    int bad = !same && !(now >= lo && now <= hi) && !(isnan(base) && isnan(now));
    const char *verdict = same ? "identical" : bad ? "outside" : "within";
    add_item(x, row, what, base, now, lo, hi, verdict, !same, bad, NULL);
    put_row(x, bad || x->all, row, "%s | %.6g | %.6g | [%.6g, %.6g] | %s |\n", what, base, now, lo, hi,
            bad ? "**outside**" : verdict);
    return bad;
}

static int report_change(cmp *x, const cJSON *row, const char *what, double base, double now, double lo, double hi)
{
    return judge(x, row, what, base, now, lo, hi, same_number(base, now));
}

/* A quantity reported, never judged (a step count follows the step). */
static void report_only(cmp *x, const cJSON *row, const char *what, double base, double now)
{
    int same = same_number(base, now);
    add_item(x, row, what, base, now, NAN, NAN, "reported", !same, 0, "reported, not judged");
    put_row(x, x->all, row, "%s | %.6g | %.6g | | reported, not judged |\n", what, base, now);
}

/* A count that may only fall (undecided, hung trials): never more than the baseline's. A summary
 * without it (written before footsim counted it) had none: 0. Returns 1 when it rose. */
static int compare_count(cmp *x, const cJSON *b, const cJSON *r, const char *key)
{
    double now = number_of(r, key), base = number_of(b, key);
    now = isnan(now) ? 0 : now, base = isnan(base) ? 0 : base;
    return report_change(x, r, key, base, now, 0, base);
}

/* Compares one row of each; returns how many quantities left their allowance. */
static int compare_row(cmp *x, const cJSON *baseline, const cJSON *b, const cJSON *r)
{
    int bad = 0;
    double rate = number_of(r, "success_rate"), base_rate = number_of(b, "success_rate");
    /* the same rate of another number of trials is a change, judged by the baseline's interval */
    bad += judge(x, r, "success_rate", base_rate, rate, number_of(b, "ci_low"), number_of(b, "ci_high"),
                 same_number(rate, base_rate) && number_of(r, "trials") == number_of(b, "trials"));
    /* trials the window left undecided (a baseline without the count had none: its rules decided
       every trial), and trials whose worker hung (a baseline has none) */
    bad += compare_count(x, b, r, "undecided");
    bad += compare_count(x, b, r, "hung");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
        double base = number_of(b, key), now = number_of(r, key), tol[2];
        if (not_in(x, b, r, key, "baseline"))
            continue;
        if (fs_campaign_metrics[m].reported) {
            report_only(x, r, key, base, now);
            continue;
        }
        if (!same_number(base, now) && landed_in_one(x, r, key, fs_campaign_metrics[m].over_landed, base, now))
            continue;
        tolerance_of(baseline, m, tol);
        double allow = tol[0] * fabs(base) + tol[1];
        bad += report_change(x, r, key, base, now, base - allow, base + allow);
    }
    return bad;
}

/* A provenance field as text (arrays and objects printed whole), or NULL when missing. */
static char *field_text(const cJSON *prov, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(prov, key);
    return v ? cJSON_PrintUnformatted(v) : NULL;
}

/* The hash an input list gives path, or NULL. */
static const char *input_hash(const cJSON *inputs, const char *path)
{
    const cJSON *in;
    cJSON_ArrayForEach(in, inputs)
        if (!strcmp(text_of(in, "path"), path))
            return text_of(in, "hash");
    return NULL;
}

/* One difference of the provenance, into the JSON: {"field", "path" (inputs only), "result", "baseline"}. */
static void add_difference(cJSON *diffs, const char *field, const char *path, cJSON *result, cJSON *baseline)
{
    cJSON *o = diffs ? cJSON_CreateObject() : NULL;
    int ok = o && cJSON_AddStringToObject(o, "field", field) && (!path || cJSON_AddStringToObject(o, "path", path));
    ok = fs_json_put(o, "result", result ? result : cJSON_CreateNull()) && ok;
    ok = fs_json_put(o, "baseline", baseline ? baseline : cJSON_CreateNull()) && ok;
    if (!ok || !fs_json_put(diffs, NULL, o))
        if (!ok)
            cJSON_Delete(o);
}

/* The inputs of the two records, compared by path: each changed input named, and each one only
 * one side read. Returns how many differ. */
static int compare_inputs(const cJSON *r, const cJSON *b, FILE *out, cJSON *diffs)
{
    const cJSON *ri = cJSON_GetObjectItemCaseSensitive(r, "inputs"), *bi = cJSON_GetObjectItemCaseSensitive(b, "inputs");
    int n = 0;
    const cJSON *in;
    cJSON_ArrayForEach(in, ri) {
        const char *path = text_of(in, "path"), *h = text_of(in, "hash"), *bh = input_hash(bi, path);
        if (bh && !strcmp(h, bh))
            continue;
        n++;
        if (out && bh)
            fprintf(out, "provenance: input %s differs: result %s, baseline %s\n", path, h, bh);
        else if (out)
            fprintf(out, "provenance: input %s read by the result only (%s)\n", path, h);
        add_difference(diffs, "inputs", path, cJSON_CreateString(h), bh ? cJSON_CreateString(bh) : NULL);
    }
    cJSON_ArrayForEach(in, bi) {
        const char *path = text_of(in, "path");
        if (input_hash(ri, path))
            continue;
        n++;
        if (out)
            fprintf(out, "provenance: input %s read by the baseline only (%s)\n", path, text_of(in, "hash"));
        add_difference(diffs, "inputs", path, NULL, cJSON_CreateString(text_of(in, "hash")));
    }
    if (!n && cJSON_GetArraySize(ri) == cJSON_GetArraySize(bi)) {
        /* the same files with the same hashes but in another order: the same inputs */
        char *x = field_text(r, "inputs"), *y = field_text(b, "inputs");
        if (out && !(x && y && !strcmp(x, y)))
            fprintf(out, "provenance: the same inputs, read in another order\n");
        free(x), free(y);
    }
    return n;
}

/* Compares the two summaries' provenance: prints every difference, each changed input by its path;
 * returns the names of those that make the comparison meaningless (seeds, overrides, inputs) in
 * `refused`, "" when none. Into prov (when given): "same", "differences", "refused". */
static void compare_provenance(const cJSON *result, const cJSON *baseline, int equivalence, FILE *out, char *refused,
                               size_t size, cJSON *prov)
{
    refused[0] = 0;
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(result, "provenance");
    const cJSON *b = cJSON_GetObjectItemCaseSensitive(baseline, "provenance");
    cJSON *diffs = prov ? cJSON_AddArrayToObject(prov, "differences") : NULL;
    if (!r || !b) {
        if (out)
            fprintf(out, "provenance: not checked (%s has none)\n\n", !r ? "the result" : "the baseline");
        if (prov)
            cJSON_AddNullToObject(prov, "same");
        return;
    }
    static const char *const keys[] = {"footsim", "seeds", "first_seed", "overrides", "inputs", "settings"};
    int differ = 0;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        int d;
        if (!strcmp(keys[i], "inputs")) {
            d = compare_inputs(r, b, out, diffs) > 0;
        } else {
            char *x = field_text(r, keys[i]), *y = field_text(b, keys[i]);
            d = !(x && y && !strcmp(x, y));
            if (d && out)
                fprintf(out, "provenance: %s differs: result %s, baseline %s\n", keys[i], x ? x : "(none)", y ? y : "(none)");
            if (d)
                add_difference(diffs, keys[i], NULL, cJSON_Duplicate(cJSON_GetObjectItemCaseSensitive(r, keys[i]), 1),
                               cJSON_Duplicate(cJSON_GetObjectItemCaseSensitive(b, keys[i]), 1));
            free(x);
            free(y);
        }
        differ |= d;
        /* another version, or other settings, is what a comparison is for; the rest is not (an
           equivalence compares settings, which may come as overrides: run.step_s) */
        if (d && strcmp(keys[i], "footsim") && strcmp(keys[i], "settings") &&
            !(equivalence && !strcmp(keys[i], "overrides"))) {
            size_t n = strlen(refused);
            snprintf(refused + n, size - n, "%s%s", n ? ", " : "", keys[i]);
        }
    }
    if (out)
        fprintf(out, differ ? "\n" : "provenance: the same seeds, overrides and inputs\n\n");
    if (prov)
        cJSON_AddBoolToObject(prov, "same", !differ);
}

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
static int report_equivalence(cmp *x, const cJSON *row, const char *what, double ref, double now, double lo,
                              double hi, int judged)
{
    int bad = judged && !(now >= lo && now <= hi) && !(isnan(ref) && isnan(now));
    add_item(x, row, what, ref, now, judged ? lo : NAN, judged ? hi : NAN,
             !judged ? "reported" : bad ? "differs" : "equivalent", !same_number(ref, now), bad,
             judged ? NULL : "step-dependent");
    if (judged)
        put_row(x, bad || x->all, row, "%s | %.6g | %.6g | [%.6g, %.6g] | %s |\n", what, ref, now, lo, hi,
                bad ? "**differs**" : "equivalent");
    else
        put_row(x, x->all, row, "%s | %.6g | %.6g | %+.1f %% | reported (step-dependent) |\n", what, ref, now,
                100 * (now / ref - 1));
    return bad;
}

/* Judges one cell against its reference; returns how many quantities differ. */
static int equivalence_row(cmp *x, const cJSON *ref, const cJSON *r)
{
    /* the success rates: their 95 % Wilson intervals overlap */
    double lo = number_of(ref, "ci_low"), hi = number_of(ref, "ci_high");
    double rlo = number_of(r, "ci_low"), rhi = number_of(r, "ci_high");
    double rate = number_of(r, "success_rate"), ref_rate = number_of(ref, "success_rate");
    int overlap = rlo <= hi && lo <= rhi;
    add_item(x, r, "success_rate", ref_rate, rate, lo, hi, overlap ? "equivalent" : "differs",
             !same_number(rate, ref_rate), !overlap, "the two 95 % intervals overlap (low, high: the reference's)");
    put_row(x, !overlap || x->all, r, "success_rate | %.6g [%.3g, %.3g] | %.6g [%.3g, %.3g] | intervals overlap | %s |\n",
            ref_rate, lo, hi, rate, rlo, rhi, overlap ? "equivalent" : "**differs**");
    int bad = !overlap;
    for (int i = 0; i < N_EQUIVALENCE; i++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", equivalence_metrics[i].metric);
        double base = number_of(ref, key), now = number_of(r, key);
        if (not_in(x, ref, r, key, "reference") ||
            landed_in_one(x, r, key, over_landed(equivalence_metrics[i].metric), base, now))
            continue;
        double allow = fmax(EQUIVALENCE_RELATIVE * fabs(base), equivalence_metrics[i].floor);
        bad += report_equivalence(x, r, key, base, now, base - allow, base + allow, 1);
    }
    /* trials the window left undecided or whose worker hung: never more than the reference's (a
       step that leaves trials undecided answers a different question) */
    static const char *const counts[] = {"undecided", "hung"};
    for (int i = 0; i < 2; i++) {
        double base = number_of(ref, counts[i]), now = number_of(r, counts[i]);
        base = isnan(base) ? 0 : base, now = isnan(now) ? 0 : now;
        if (now != base)
            bad += report_equivalence(x, r, counts[i], base, now, 0, base, 1);
    }
    bad += report_equivalence(x, r, "median_peak_force_N", number_of(ref, "median_peak_force_N"),
                              number_of(r, "median_peak_force_N"), 0, 0, 0);
    return bad;
}

fs_status fs_campaign_equivalence(const char *result_path, const char *result_name, const char *reference_path,
                                  int force, FILE *out, int *ndiffer, fs_error *err)
{
    const fs_compare_opts o = {.force = force, .all = 1, .equivalence = 1, .result_name = result_name};
    return fs_campaign_compare_with(result_path, reference_path, &o, out, NULL, ndiffer, err);
}

fs_status fs_campaign_compare(const char *result_path, const char *baseline_path, int force, FILE *out, fs_error *err)
{
    const fs_compare_opts o = {.force = force};
    return fs_campaign_compare_with(result_path, baseline_path, &o, out, NULL, NULL, err);
}

/* The verdict's word for the JSON. */
static const char *verdict_of(fs_status s, int equivalence, int changed)
{
    switch (s) {
    case FS_OK:
        return equivalence ? "equivalent" : changed ? "within tolerance" : "identical";
    case FS_EXPECTATION_FAILED:
        return equivalence ? "not equivalent" : "changed";
    case FS_INPUTS_DIFFER:
        return "inputs differ";
    default:
        return "cannot read";
    }
}

/* The two comparisons share reading, provenance and the pairing of rows; `equivalence` picks the
 * rule a pair of rows is judged by. */
fs_status fs_campaign_compare_with(const char *result_path, const char *baseline_path, const fs_compare_opts *o,
                                   FILE *out, cJSON **json, int *nbad, fs_error *err)
{
    if (nbad)
        *nbad = 0;
    fs_error local;
    if (!err)
        err = &local;
    cmp x = {.out = out, .all = o->all, .equivalence = o->equivalence, .items = json ? cJSON_CreateArray() : NULL};
    cJSON *root = json ? cJSON_CreateObject() : NULL, *prov = root ? cJSON_CreateObject() : NULL;
    if (root) {
        cJSON_AddStringToObject(root, "result", result_path);
        cJSON_AddStringToObject(root, o->equivalence ? "reference" : "baseline", baseline_path);
        cJSON_AddStringToObject(root, "mode", o->equivalence ? "equivalence" : "compare");
    }
    fs_status s = FS_OK;
    cJSON *result = fs_campaign_read_summary(result_path, err);
    cJSON *baseline = result ? fs_campaign_read_summary(baseline_path, err) : NULL;
    if (!baseline)
        s = err->status; /* as read_summary found it: bad input, unreadable, out of memory */
    char refused[128] = "";
    if (s == FS_OK)
        compare_provenance(result, baseline, o->equivalence, out, refused, sizeof refused, prov);
    if (s == FS_OK && refused[0] && !o->force)
        s = fs_fail(err, FS_INPUTS_DIFFER, "%s and %s were made with different %s (above): their numbers do not "
                    "compare; rerun one like the other, or give --force to compare them anyway", result_path,
                    baseline_path, refused);
    int nrows = 0;
    if (s == FS_OK) {
        const cJSON *rrows = cJSON_GetObjectItemCaseSensitive(result, "rows");
        const cJSON *brows = cJSON_GetObjectItemCaseSensitive(baseline, "rows");
        nrows = cJSON_GetArraySize(brows);
        if (out)
            fprintf(out, "%s against the %s %s\n\n", o->result_name ? o->result_name : result_path,
                    o->equivalence ? "reference" : "baseline", baseline_path);
        const cJSON *b, *r;
        cJSON_ArrayForEach(b, brows) {
            r = find_row(rrows, b);
            if (!r) {
                add_item(&x, b, "(row)", NAN, NAN, NAN, NAN, "missing in the result", 1, 1, NULL);
                put_row(&x, 1, b, "(row) | present | **missing** | | **outside** |\n");
            } else if (o->equivalence) {
                equivalence_row(&x, b, r); /* each quantity counted as it is added */
            } else {
                compare_row(&x, baseline, b, r);
            }
        }
        cJSON_ArrayForEach(r, rrows)
            if (!find_row(brows, r)) {
                add_item(&x, r, "(row)", NAN, NAN, NAN, NAN, "missing in the baseline", 1, 1, NULL);
                put_row(&x, 1, r, "(row) | **missing** | present | | **outside** |\n");
            }
        if (out && !x.header)
            fprintf(out, "%s\n", o->equivalence ? "Nothing differs." : x.changed ? "Nothing outside what the baseline allows."
                                                                                  : "Nothing changed.");
        int unlisted = o->all ? 0 : x.changed - x.bad;
        if (out && o->equivalence)
            fprintf(out, "\n%d rows in the reference; %d quantities differ: %s\n", nrows, x.bad,
                    x.bad ? "NOT EQUIVALENT" : "equivalent");
        else if (out)
            fprintf(out, "\n%d rows in the baseline; %d quantities changed, %d outside what the baseline allows: %s%s\n",
                    nrows, x.changed, x.bad, x.bad ? "CHANGED" : x.changed ? "within tolerance" : "identical",
                    unlisted > 0 ? " (those within are not listed: --all lists every quantity)" : "");
        s = x.bad ? FS_EXPECTATION_FAILED : FS_OK;
    }
    if (root) {
        int ok = fs_json_put(root, "provenance", prov);
        cJSON *counts = cJSON_AddObjectToObject(root, "counts");
        ok = ok && counts && cJSON_AddNumberToObject(counts, "rows", nrows) &&
             cJSON_AddNumberToObject(counts, "quantities", x.compared) &&
             cJSON_AddNumberToObject(counts, "changed", x.changed) && cJSON_AddNumberToObject(counts, "outside", x.bad) &&
             cJSON_AddNumberToObject(counts, "reported", x.reported);
        ok = ok && (refused[0] ? cJSON_AddStringToObject(root, "refused_for", refused)
                               : cJSON_AddNullToObject(root, "refused_for"));
        ok = ok && cJSON_AddStringToObject(root, "verdict", verdict_of(s, o->equivalence, x.changed)) &&
             cJSON_AddNumberToObject(root, "exit_status", s == FS_NO_MEMORY ? FS_NO_MEMORY : (int)s);
        ok = ok && (s == FS_OK || s == FS_EXPECTATION_FAILED ? cJSON_AddNullToObject(root, "error")
                                                             : cJSON_AddStringToObject(root, "error", err->message));
        ok = fs_json_put(root, "quantities", x.items) && ok;
        x.items = NULL;
        if (!ok) {
            cJSON_Delete(root);
            root = NULL;
            s = fs_fail(err, FS_NO_MEMORY, "out of memory for the comparison's JSON");
        }
        *json = root;
    } else {
        cJSON_Delete(prov);
        if (json)
            *json = NULL;
    }
    cJSON_Delete(x.items);
    cJSON_Delete(result);
    cJSON_Delete(baseline);
    if (nbad)
        *nbad = x.bad;
    return s;
}
