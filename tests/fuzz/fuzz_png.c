/* libFuzzer target: heightmap images. Any input must be refused or read cleanly. */
#include "footsim/io/fs_png.h"

#include "fuzz_file.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64];
    if (!fuzz_write_temp(data, size, ".png", path, sizeof path))
        return 0;
    int w, h;
    double *v = NULL;
    fs_error err;
    if (fs_png_read_gray(path, "fuzz", &w, &h, &v, &err) == FS_OK)
        free(v);
    unlink(path);
    return 0;
}
