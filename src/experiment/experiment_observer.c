/* experiment_observer.c: what watches an experiment while it steps (fs_observer.h). */
#include "footsim/experiment/fs_observer.h"

#include <math.h>

fs_sim_options fs_observer_sim_options(const fs_run_observer *obs)
{
    return (fs_sim_options){.with_ground = 1, .profile = obs ? obs->profile : NULL};
}

long fs_observer_every(const fs_run_observer *obs, double step_s)
{
    long every = obs ? lround(obs->interval_s / step_s) : 0;
    return every < 1 ? 1 : every;
}

fs_status fs_observer_call(const fs_run_observer *obs, const fs_sim *sim, fs_error *err)
{
    return obs && obs->fn ? obs->fn(obs->user, sim, err) : FS_OK;
}
