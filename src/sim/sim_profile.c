/* sim_profile.c: where a profiled simulation's step time goes, stage by stage (fs_sim.h's
 * fs_profile, sim_internal.h's fs_sim_lap). */
#include "sim_internal.h"

void fs_sim_lap(fs_sim *sim, fs_stage stage)
{
    if (!sim->profile)
        return;
    double t = fs_clock_s();
    if (sim->profile_mark > 0) {
        sim->profile->stage_s[stage] += t - sim->profile_mark;
        sim->profile->laps[stage]++;
    }
    sim->profile_mark = t;
}
