/* cli_stiffness.c: `footsim stiffness DESIGN`: the library's stiffness report (fs_report.h) printed,
 * or as JSON; exit 1 when the chains' analytic and measured stiffness differ by more than 1 %. */
#include "cli.h"

#include "footsim/base/fs_path.h"
#include "footsim/campaign/fs_report.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

static int stiffness_of(const cli_args *a, const fs_scenario *sc)
{
    fs_stiffness_report *r = cli_zalloc(sizeof *r);
    if (!r)
        return FS_NO_MEMORY;
    fs_error err;
    char robots[FS_PATH_MAX]; /* the shipped robots, for a design away from scenarios/feet/ */
    int s = fs_stiffness_report_make(sc, a->input, cli_data_robots(robots, sizeof robots), r, &err);
    if (s != FS_OK) {
        s = cli_report(err.status, err.message);
    } else if (a->json) {
        cJSON *root = fs_stiffness_report_json(r, a->input, &err);
        s = root ? cli_print_json(root) : cli_report(err.status, err.message);
        cJSON_Delete(root);
    } else {
        fs_stiffness_report_print(r, a->input, stdout);
    }
    if (!s && !fs_stiffness_report_agrees(r))
        s = FS_EXPECTATION_FAILED;
    free(r);
    return s;
}

int cli_stiffness(const cli_args *a) { return cli_with_design(a, stiffness_of); }
