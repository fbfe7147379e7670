/* libFuzzer target: heightmap images. Any input must be refused or read cleanly. */
#include "footsim/fs_png.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/footsim-fuzz-%ld.png", (long)getpid());
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    int w, h;
    double *v = NULL;
    fs_error err;
    if (fs_png_read_gray(path, "fuzz", &w, &h, &v, &err) == FS_OK)
        free(v);
    unlink(path);
    return 0;
}
