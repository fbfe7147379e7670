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

void fs_path_relative(const char *to, const char *from, char *out, size_t size)
{
    /* the longest common prefix of whole components */
    size_t common = 0;
    for (size_t i = 0; to[i] && to[i] == from[i]; i++)
        if (to[i] == '/')
            common = i + 1;
    size_t flen = strlen(from);
    if (!strncmp(to, from, flen) && to[flen] == '/')
        common = flen + 1;
    size_t n = 0;
    out[0] = 0;
    /* a "../" for every component of from past the prefix */
    for (const char *p = from + (common <= flen ? common : flen); *p;) {
        n += (size_t)snprintf(out + (n < size ? n : size - 1), n < size ? size - n : 1, "../");
        const char *slash = strchr(p, '/');
        if (!slash)
            break;
        p = slash + 1;
    }
    snprintf(out + (n < size ? n : size - 1), n < size ? size - n : 1, "%s", to + common);
}
