/* libFuzzer target: design and terrain files (the INI reader, the schemas, the checks, the
 * geometry). Any input must be refused or accepted cleanly: no crash, leak or undefined behaviour. */
#include "footsim/model/fs_design.h"
#include "footsim/model/fs_terrain.h"

#include "fuzz_file.h"

#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64];
    if (!fuzz_write_temp(data, size, ".ini", path, sizeof path))
        return 0;
    static fs_design_def def;
    static fs_foot_geom geom;
    static fs_terrain t;
    fs_error err;
    fs_design_load(path, NULL, 0, &def, &geom, &err);
    if (fs_terrain_load(path, NULL, 0, &t, &err) == FS_OK) {
        if (fs_terrain_crop(&t, -0.01, 0.01, -0.01, 0.01, &err) == FS_OK)
            (void)fs_terrain_height(&t, 0.001, 0.002);
        fs_terrain_free(&t);
    }
    unlink(path);
    return 0;
}
