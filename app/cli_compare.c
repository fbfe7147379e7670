/* cli_compare.c: `footsim compare RESULT BASELINE`: a campaign's summary.json against its baseline
 * (fs_campaign_compare_with), as Markdown or, with --json, one JSON object. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_output.h"

#include <cjson/cJSON.h>
#include <stdio.h>

int cli_compare(const cli_args *a)
{
    if (!a->input2)
        return cli_report(FS_BAD_INPUT, "compare: give two summary.json files: RESULT BASELINE");
    fs_error err;
    const fs_compare_opts o = {.force = a->force, .all = a->all, .equivalence = a->equivalence};
    cJSON *json = NULL;
    /* --json: the JSON alone on stdout, whatever the outcome (the Markdown not printed) */
    fs_status s = fs_campaign_compare_with(a->input, a->input2, &o, a->json ? NULL : stdout, a->json ? &json : NULL,
                                           NULL, &err);
    int printed = fs_json_print(stdout, json);
    cJSON_Delete(json);
    if (a->json && !printed && s != FS_NO_MEMORY)
        return cli_report(FS_NO_MEMORY, "compare: out of memory for the JSON");
    return s == FS_OK || s == FS_EXPECTATION_FAILED ? (int)s : cli_report(err.status, err.message);
}
