/* libFuzzer target: scenario files, parsed and compiled (the design, terrain and robot files they
 * name, the foot's geometry, the terrain cut to the foot's region), never simulated. The input is
 * written beside copies (links) of the shipped files, so it may name them as the shipped scenarios
 * do. Any input must be refused or accepted cleanly: no crash, leak or undefined behaviour. The
 * ground is sampled coarsely (fuzz_coarse). */
#include "footsim/model/fs_scenario.h"

#include "fuzz_file.h"

#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[128];
    if (!fuzz_write_in_data(data, size, path, sizeof path))
        return 0;
    fs_scenario *sc = calloc(1, sizeof *sc);
    if (!sc)
        return 0;
    fs_error err;
    fs_status s = fs_scenario_load(path, fuzz_coarse, FUZZ_NCOARSE, sc, &err);
    fuzz_said(s, &err);
    if (s == FS_OK) {
        double box[4];
        fs_scenario_footprint(sc, box);
        (void)fs_scenario_require(sc, "run", &err);
    }
    fs_scenario_free(sc);
    free(sc);
    return 0;
}
