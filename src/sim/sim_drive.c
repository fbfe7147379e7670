/* sim_drive.c: the one loop that steps a simulation (fs_drive.h) and its observer (fs_observer.h). */
#include "footsim/sim/fs_drive.h"

#include "sim_internal.h"

#include <math.h>

fs_sim_options fs_observer_sim_options(const fs_run_observer *obs)
{
    return (fs_sim_options){.with_ground = 1, .profile = obs ? obs->profile : NULL};
}

static fs_status observe(const fs_run_observer *obs, const fs_sim *sim, fs_error *err)
{
    return obs && obs->fn ? obs->fn(obs->user, sim, err) : FS_OK;
}

fs_status fs_drive(fs_sim *sim, const fs_drive_spec *spec, fs_drive_result *out, fs_error *err)
{
    const fs_run_observer *obs = spec->obs;
    long every = obs ? lround(obs->interval_s / sim->sc->def.step_s) : 0;
    if (every < 1)
        every = 1;
    *out = (fs_drive_result){0, -1, 0};
    /* an error-controlled step (run.tolerance_m): the run ends at the time max_steps fixed steps
     * would reach, its last step cut to end there; the observer is called at the first step that
     * ends at or past each interval (it never moves a step, so it never changes a result) */
    const fs_scenario_def *d = &sim->sc->def;
    int timed = sim->saved != NULL;
    double end_s = timed ? (double)spec->max_steps * d->step_s : 0, sliver = timed ? 0.5 * d->step_min_s : 0;
    double seen_s = 0;
    if (timed)
        fs_sim_set_horizon(sim, end_s);
    fs_status s = observe(obs, sim, err);
    while (s == FS_OK && (timed ? sim->time_s < end_s - sliver : out->steps < spec->max_steps) && out->stopped_by < 0) {
        if (spec->before_step)
            spec->before_step(spec->before_user, sim);
        s = fs_sim_step(sim, err);
        out->steps++;
        if (s != FS_OK) {
            out->step_failed = 1;
            break;
        }
        int due = timed ? obs && sim->time_s >= seen_s + obs->interval_s - sliver : out->steps % every == 0;
        if (due) {
            seen_s = sim->time_s;
            if ((s = observe(obs, sim, err)) != FS_OK)
                break;
        }
        for (int k = 0; k < spec->nhooks; k++) /* every hook sees every step, the last one too */
            if (spec->hooks[k].after_step(spec->hooks[k].user, sim) && out->stopped_by < 0)
                out->stopped_by = k;
    }
    if (s == FS_OK && (timed ? seen_s != sim->time_s : out->steps % every != 0))
        s = observe(obs, sim, err); /* the end, if not just seen */
    return s;
}

const char *fs_drive_reason(const fs_drive_spec *spec, const fs_drive_result *r)
{
    return r->step_failed ? "failed" : r->stopped_by >= 0 ? spec->hooks[r->stopped_by].name : "max_steps";
}
