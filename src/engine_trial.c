/* engine_trial.c: landing trials. (A stand-in until the robot lands: outcomes drawn from the
 * seed, so that the campaign machinery can be built against the interface.) */
#include "footsim/fs_trial.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

const char *fs_outcome_name(int outcome)
{
    static const char *names[] = {"landed", "fell", "failed_numerics"};
    return outcome >= 0 && outcome <= 2 ? names[outcome] : "unknown";
}

static double unit(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

void fs_trial_draw_pose(const fs_scenario *sc, int seed, fs_trial_draw *draw)
{
    (void)sc;
    memset(draw, 0, sizeof *draw);
    draw->seed = seed;
    draw->x_m = 0.01 * (2 * unit((uint64_t)seed * 5 + 1) - 1);
    draw->y_m = 0.01 * (2 * unit((uint64_t)seed * 5 + 2) - 1);
}

fs_status fs_trial_run(const char *scenario_path, const char *const *overrides, int noverrides, int seed,
                       fs_trial_result *out, fs_error *err)
{
    static fs_scenario sc;
    fs_status s = fs_scenario_load(scenario_path, overrides, noverrides, &sc, err);
    if (s != FS_OK)
        return s;
    memset(out, 0, sizeof *out);
    fs_trial_draw_pose(&sc, seed, &out->draw);
    double u = unit((uint64_t)seed * 7 + (uint64_t)sc.geom.kind);
    out->outcome = u < (sc.geom.kind == FS_FOOT_FLAT ? 0.5 : 0.95) ? FS_LANDED : FS_FELL;
    out->peak_force_N = 500 + 100 * u;
    out->final_tilt_deg = 30 * u;
    out->peak_tilt_deg = 35 * u;
    fs_scenario_free(&sc);
    return FS_OK;
}
