/* base_path.c: names taken from paths, and paths checked before use (fs_path.h). */
#include "footsim/base/fs_path.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
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

/* A long path as its first and last characters, for a message that must stay readable. */
static const char *shown(const char *path, char *buf, size_t size)
{
    size_t n = strlen(path);
    if (n <= 100)
        snprintf(buf, size, "%s", path);
    else
        snprintf(buf, size, "%.48s...%s", path, path + n - 48);
    return buf;
}

fs_status fs_path_fits(const char *path, size_t room, size_t name_room, const char *what, fs_error *err)
{
    char b[128];
    size_t n = strlen(path), limit = PATH_MAX - 1 - room;
    if (n == 0)
        return fs_fail(err, FS_BAD_INPUT, "%s%s'': an empty path; give a path", what, *what ? " " : "");
    if (n > limit)
        return fs_fail(err, FS_BAD_INPUT, "%s%s%s: the path is %zu characters long; footsim takes at most %zu (PATH_MAX "
                       "%d, less room for what it writes beside and in it): give a shorter path", what,
                       *what ? " " : "", shown(path, b, sizeof b), n, limit, PATH_MAX);
    /* the last component: the name of what footsim writes (a trailing slash ends a folder's) */
    size_t end = n;
    while (end > 1 && path[end - 1] == '/')
        end--;
    size_t last = end;
    while (last > 0 && path[last - 1] != '/')
        last--;
    for (size_t i = 0; i < n;) {
        size_t len = strcspn(path + i, "/");
        size_t most = i == last ? NAME_MAX - name_room : NAME_MAX;
        if (len > most)
            return fs_fail(err, FS_BAD_INPUT, "%s%s%s: the name '%.24s...' is %zu characters long; a name takes at "
                           "most %d (NAME_MAX)%s%zu%s: give a shorter name", what, *what ? " " : "",
                           shown(path, b, sizeof b), path + i,
                           len, NAME_MAX, i == last ? ", and this one at most " : "", i == last ? most : 0,
                           i == last ? ", with room for what footsim writes beside it" : "");
        i += len + (path[i + len] == '/');
    }
    return FS_OK;
}

fs_status fs_path_format(char *out, size_t size, const char *what, fs_error *err, const char *fmt, ...)
{
    va_list ap, again;
    va_start(ap, fmt);
    va_copy(again, ap);
    int n = vsnprintf(out, size, fmt, ap);
    va_end(ap);
    fs_status s = FS_OK;
    if (n < 0 || (size_t)n >= size) {
        /* the whole path in the message (its end names the file), not the part that fitted */
        char b[128], *whole = n > 0 ? malloc((size_t)n + 1) : NULL;
        if (whole)
            vsnprintf(whole, (size_t)n + 1, fmt, again);
        s = fs_fail(err, FS_BAD_INPUT, "%s%s%s: the path is %d characters long; footsim takes at most %zu here: give "
                    "a shorter path", what, *what ? " " : "", shown(whole ? whole : out, b, sizeof b), n, size - 1);
        free(whole);
    }
    va_end(again);
    return s;
}
