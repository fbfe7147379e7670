/* cli_keys.c: `footsim keys`: every key of design, scenario, terrain, robot, campaign and design
 * search files (Markdown, the source of docs/keys.md), and the limits footsim refuses past. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/campaign/fs_optimize.h"
#include "footsim/experiment/fs_run.h"
#include "footsim/io/fs_config.h"
#include "footsim/model/fs_design.h"
#include "footsim/model/fs_robot.h"
#include "footsim/model/fs_terrain.h"
#include "footsim/sim/fs_sim.h"

#include <stdio.h>

int cli_keys(const cli_args *a)
{
    (void)a;
    fs_config_print_keys(fs_design_keys, fs_design_nkeys, "Design files (scenarios/feet/*.ini)", stdout);
    fs_config_print_keys(fs_scenario_keys, fs_scenario_nkeys, "Scenario files (scenarios/*.ini)", stdout);
    fs_config_print_keys(fs_terrain_keys, fs_terrain_nkeys, "Terrain files (terrains/*.ini)", stdout);
    fs_config_print_keys(fs_robot_keys, fs_robot_nkeys, "Robot files (scenarios/robots/*.ini)", stdout);
    fs_campaign_print_keys(stdout);
    printf("A campaign's `sweep_values` and `sweep2_values` (the swept keys' values, comma-separated) and its\n"
           "`[band.NAME]` sections (`low` and `high`, each a comma-separated list of overrides key=value):\n"
           "[campaign.md](campaign.md).\n\n");
    fs_optimize_print_keys(stdout);
    printf("### Limits\n\nWhat footsim refuses up front (exit 2, before anything is simulated or written), so that no\n"
           "count overflows and no buffer outgrows memory:\n\n| what | at most |\n|---|---|\n"
           "| an input file (design, scenario, terrain, campaign) | %d bytes, %d keys; regular files only |\n"
           "| a line of an input file | %d characters |\n"
           "| steps of one run, trial or walk (duration_s / step_s; steps x period_s / step_s) | %.0e |\n"
           "| a run's trajectory in memory (rows x columns x 8 bytes) | %.0f MiB |\n"
           "| trials of a campaign (feet x terrains x robots x seeds, x 2 with a band) | %d |\n"
           "| a campaign's `[band.NAME]` sections; overrides per band end | %d; %d |\n"
           "| frames of `run --frames` or `render-compare` (six-digit names) | %d |\n"
           "| frames `render-compare` keeps in memory | half of the machine's memory |\n"
           "| a number | decimal; 0 or a normal double, 2.2e-308 to 1.8e308 in magnitude (hexadecimal and subnormals refused) |\n"
           "| `terrain --height X Y` | metres from -1000 to 1000 |\n\n",
           FS_CONFIG_MAX_BYTES, FS_CONFIG_MAX_KEYS, fs_config_max_line(), (double)FS_MAX_STEPS, FS_TRAJ_MAX_BYTES / (1024.0 * 1024),
           FS_CAMPAIGN_MAX_TRIALS, FS_CAMPAIGN_MAX_BANDS, FS_BAND_MAX_SETS, 999999);
    return 0;
}

