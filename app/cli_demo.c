/* cli_demo.c: `footsim demo`: the paper's first experiments (static load, 10 degree tilt), the
 * stiffness check, a small landing campaign, and the finding in one line. */
#include "cli.h"

#include "footsim/analysis/fs_analysis.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int cli_demo(const cli_args *a)
{
    (void)a;
    static const char *const scenarios[] = {"scenarios/static_load.ini", "scenarios/tilt10.ini"};
    for (int i = 0; i < 2; i++) {
        cli_args run = {.command = "run", .input = cli_data_path(scenarios[i])};
        int s = cli_run(&run);
        if (s)
            return s;
    }
    cli_args st = {.command = "stiffness", .input = cli_data_path("scenarios/feet/biomimetic.ini")};
    int s = cli_stiffness(&st);
    if (s)
        return s;
    /* the main job, small: both feet landing on even, simply and complex uneven ground */
    printf("\nlanding comparison (2 seeds each, two robots; 'footsim campaign scenarios/landing.ini' runs 50):\n");
    fflush(stdout);
    cli_args camp = {.command = "campaign", .input = cli_data_path("scenarios/landing_ci.ini"), .nset = 1,
                     .set = {"campaign.seeds=2"}, .out = "results/campaigns/demo", .fresh = 1}; /* always shown */
    s = cli_campaign(&camp);
    /* the finding, in one line: the law for the trial scenario's robot (single_tall) on Table I */
    fs_error err;
    double K;
    fs_scenario *sc = s ? NULL : cli_zalloc(sizeof *sc);
    if (!s && !sc)
        return FS_NO_MEMORY;
    if (sc && fs_scenario_load(cli_data_path("scenarios/landing_trial.ini"), NULL, 0, sc, &err) == FS_OK) {
        fs_pitch_law law;
        double g = sc->def.gravity_m_per_s2;
        if (fs_pitch_stiffness_model(&sc->geom, sc->def.robot.mass_kg * g, g, &K, &err) == FS_OK) {
            fs_pitch_law_apply(K, &sc->def.robot, g, sc->def.landed_tilt_deg * M_PI / 180, &law);
            printf("note: the Table I biomimetic foot toppling under single_tall is the documented finding, not a "
                   "fault: that robot needs %.1f N m/rad of pitch stiffness and the foot has %.1f (docs/landing.md, "
                   "the pitch-stiffness law); under drop_weight it lands\n", law.demand, law.K);
        }
    }
    if (sc)
        fs_scenario_free(sc);
    free(sc);
    return s;
}
