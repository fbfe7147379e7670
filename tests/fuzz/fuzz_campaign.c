/* libFuzzer target: campaign files, parsed with the files they name resolved in a folder laid out as
 * the shipped data (or refused when missing): feet, terrains, robots, sweeps, expectations, and
 * each cell's trial scenario loaded and compiled once. No trial is run. Any input must be refused
 * or accepted cleanly: no crash, leak or undefined behaviour. The ground is sampled coarsely
 * (fuzz_coarse). */
#include "footsim/campaign/fs_campaign.h"

#include "fuzz_file.h"

#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[128];
    if (!fuzz_write_in_data(data, size, path, sizeof path))
        return 0;
    fs_campaign *c = calloc(1, sizeof *c);
    if (!c)
        return 0;
    fs_error err;
    fs_status s = fs_campaign_load(path, fuzz_coarse, FUZZ_NCOARSE, c, &err); /* to every cell's trial */
    fuzz_said(s, &err);
    if (s == FS_OK)
        fs_campaign_free(c);
    free(c);
    return 0;
}
