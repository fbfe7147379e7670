/* campaign_metric.c: the metrics a campaign keeps of each trial, their tolerances in a comparison,
 * and a trial's value of each (fs_campaign.h's fs_metric): a table that the campaign file (its
 * [tolerance] keys), the summary, the reports and the comparison read, depending on none of them. */
#include "footsim/campaign/fs_campaign.h"

#include <math.h>

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
    /* a soil's (empty on rigid ground): the feet's sinkage at the end, their prints, the slip on them */
    {.name = "soil_sinkage_m", .tolerance = "0.1, 0.001"},
    {.name = "print_depth_m", .tolerance = "0.1, 0.001"},
    {.name = "print_area_m2", .tolerance = "0.1, 0.0001"},
    {.name = "print_volume_m3", .tolerance = "0.1, 1e-6"},
    {.name = "print_slip_m", .tolerance = "0.1, 0.001"},
};

double fs_metric_value(const fs_trial_result *r, int m)
{
    const double v[FS_CAMPAIGN_NMETRICS] = {r->end_time_s,    r->touchdown_s,       r->peak_tilt_deg,
                                            r->final_tilt_deg, r->peak_force_N,      r->impact_impulse_Ns,
                                            r->settle_time_s,  r->mean_contacts,     r->final_contacts,
                                            r->ankle_drop_m,   r->slip_m,            (double)r->steps,
                                            /* the ankle's drop at rest: a trial that fell never rested */
                                            r->outcome == FS_LANDED ? r->ankle_drop_m : NAN,
                                            r->soil_sinkage_m, r->print_depth_m, r->print_area_m2,
                                            r->print_volume_m3, r->print_slip_m};
    return v[m];
}
