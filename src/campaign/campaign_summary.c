/* campaign_summary.c: the metrics of a trial and the statistics of a campaign's cells (success
 * rates with Wilson intervals, medians). */
#include "campaign_internal.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/base/fs_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- metrics ------------------------------------------------------------------------------ */

const fs_metric fs_campaign_metrics[FS_CAMPAIGN_NMETRICS] = {
    {.name = "end_time_s", .tolerance = "0.1, 0.005"},
    {.name = "touchdown_s", .tolerance = "0.1, 0.005"},
    {.name = "peak_tilt_deg", .tolerance = "0.1, 1"},
    {.name = "final_tilt_deg", .tolerance = "0.1, 1"},
    {.name = "peak_force_N", .tolerance = "0.1, 10"},
    {.name = "impact_impulse_Ns", .tolerance = "0.1, 0.5"},
    {.name = "settle_time_s", .tolerance = "0.1, 0.005"},
    {.name = "mean_contacts", .tolerance = "0.1, 1"},
    {.name = "final_contacts", .tolerance = "0.1, 1"},
    {.name = "ankle_drop_m", .tolerance = "0.1, 0.001"},
    {.name = "slip_m", .tolerance = "0.1, 0.001"},
    {.name = "steps", .tolerance = "0.1, 100", .reported = 1}, /* follows the step: reported, not judged */
    {.name = "rest_ankle_drop_m", .tolerance = "0.1, 0.001", .over_landed = 1},
};

double fs_metric_value(const fs_trial_result *r, int m)
{
    const double v[FS_CAMPAIGN_NMETRICS] = {r->end_time_s,    r->touchdown_s,       r->peak_tilt_deg,
                                            r->final_tilt_deg, r->peak_force_N,      r->impact_impulse_Ns,
                                            r->settle_time_s,  r->mean_contacts,     r->final_contacts,
                                            r->ankle_drop_m,   r->slip_m,            (double)r->steps,
                                            /* the ankle's drop at rest: a trial that fell never rested */
                                            r->outcome == FS_LANDED ? r->ankle_drop_m : NAN};
    return v[m];
}

/* ---- statistics --------------------------------------------------------------------------- */

void fs_wilson(int k, int n, double *low, double *high)
{
    const double z = 1.959963984540054; /* the 97.5 % quantile of the standard normal */
    double p = (double)k / n, z2n = z * z / n;
    double centre = (p + z2n / 2) / (1 + z2n);
    double half = z / (1 + z2n) * sqrt(p * (1 - p) / n + z2n / (4.0 * n));
    *low = fmax(0, centre - half);
    *high = fmin(1, centre + half);
    /* at k = 0 or k = n the bound is exactly 0 or 1 (centre and half agree but for rounding) */
    if (k == 0)
        *low = 0;
    if (k == n)
        *high = 1;
}

const char *fs_law_name(int law) { return law == FS_LAW_STANDS ? "stands" : law == FS_LAW_TOPPLES ? "topples" : "n/a"; }

/* The law for a cell's foot and robot: the foot's pitch stiffness under the robot's weight (a flat
 * sole's from its contacts, fs_pitch_stiffness_foot); an arch that folds under the weight has none
 * left. */
static void law_of(const fs_scenario *sc, fs_campaign_row *row)
{
    row->law = FS_LAW_NONE;
    row->law_K = row->law_critical_m = NAN;
    const fs_robot_def *r = &sc->def.robot;
    double g = sc->def.gravity_m_per_s2, K;
    fs_error err;
    if (r->mass_kg <= 0)
        return;
    fs_status s = fs_pitch_stiffness_foot(sc, r->mass_kg * g, &K, &err);
    fs_pitch_law law;
    fs_pitch_law_apply(s == FS_OK ? K : 0, r, g, sc->def.landed_tilt_deg * M_PI / 180, &law);
    row->law = law.stands ? FS_LAW_STANDS : FS_LAW_TOPPLES;
    row->law_K = law.held ? INFINITY : law.K;
    row->law_critical_m = law.held ? INFINITY : law.critical_height_m;
}

void fs_campaign_summarize(const fs_campaign *c, const fs_trial_result *results, fs_campaign_row *rows)
{
    double *v = malloc((size_t)c->seeds * sizeof *v);
    for (int cell = 0; cell < fs_campaign_ncells(c); cell++) {
        fs_campaign_row *row = &rows[cell];
        memset(row, 0, sizeof *row);
        fs_campaign_cell_of(c, cell, &row->foot, &row->terrain, &row->robot);
        const fs_trial_result *r = &results[cell * c->seeds];
        for (int s = 0; s < c->seeds; s++) {
            row->trials++;
            row->landed += r[s].outcome == FS_LANDED;
            row->fell += r[s].outcome == FS_FELL;
            row->undecided += r[s].outcome == FS_UNDECIDED;
            row->failed_numerics += r[s].outcome == FS_FAILED_NUMERICS;
            row->hung += r[s].outcome == FS_HUNG;
        }
        row->success_rate = (double)row->landed / row->trials;
        fs_wilson(row->landed, row->trials, &row->ci_low, &row->ci_high);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
            int n = 0;
            for (int s = 0; v && s < c->seeds; s++)
                if (r[s].outcome != FS_FAILED_NUMERICS && r[s].outcome != FS_HUNG) /* no measurements */
                    v[n++] = fs_metric_value(&r[s], m);
            row->nmetric = n;
            /* a metric a trial does not have (NAN: the rest ankle drop of a fall) is left out */
            int k = 0;
            for (int i = 0; i < n; i++)
                if (!isnan(v[i]))
                    v[k++] = v[i];
            row->median[m] = fs_median(v, k);
        }
        if (c->pair)
            law_of(fs_campaign_pair(c, cell), row);
        else
            row->law = FS_LAW_NONE, row->law_K = row->law_critical_m = NAN;
    }
    free(v);
}
