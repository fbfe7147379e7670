/* base_path.c: names taken from paths (fs_path.h). */
#include "footsim/base/fs_path.h"

#include <stdio.h>
#include <string.h>

void fs_path_stem(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    const char *dot = strrchr(base, '.');
    size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    snprintf(out, size, "%.*s", (int)(n < size ? n : size - 1), base);
}
