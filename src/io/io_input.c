/* io_input.c: regular files of bounded size opened without blocking, errno-true refusals. */
#include "footsim/io/fs_input.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *fs_file_kind(mode_t m)
{
    return S_ISDIR(m) ? "a folder" : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket" : S_ISCHR(m) ? "a character device"
         : S_ISBLK(m) ? "a block device" : S_ISLNK(m) ? "a symbolic link" : S_ISREG(m) ? "a regular file"
         : "not a regular file";
}

FILE *fs_open_regular(const char *path, long max_bytes, const char *what, fs_error *err)
{
    /* O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused just after */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        fs_fail(err, FS_BAD_INPUT, "%s: cannot open %s (%s); give the path of %s that can be read", path, what,
                strerror(errno), what);
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        fs_fail(err, FS_BAD_INPUT, "%s: cannot read %s (%s)", path, what, strerror(errno));
        close(fd);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        fs_fail(err, FS_BAD_INPUT, "%s: is %s; give %s (a regular file)", path, fs_file_kind(st.st_mode), what);
        close(fd);
        return NULL;
    }
    if (st.st_size > max_bytes) {
        fs_fail(err, FS_BAD_INPUT, "%s: %lld bytes; %s may have at most %ld", path, (long long)st.st_size, what,
                max_bytes);
        close(fd);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        fs_fail(err, FS_BAD_INPUT, "%s: cannot read %s (%s)", path, what, strerror(errno));
        close(fd);
    }
    return f;
}

fs_status fs_read_regular(const char *path, long max_bytes, const char *what, char **data, size_t *len,
                          fs_error *err)
{
    *data = NULL;
    *len = 0;
    FILE *f = fs_open_regular(path, max_bytes, what, err);
    if (!f)
        return FS_BAD_INPUT;
    /* the size may change while reading: read at most max_bytes + 1 to notice */
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap + 1);
    while (buf) {
        if (n == cap) {
            if (cap > (size_t)max_bytes)
                break;
            cap *= 2;
            char *b = realloc(buf, cap + 1);
            if (!b) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = b;
        }
        size_t k = fread(buf + n, 1, cap - n, f);
        n += k;
        if (k == 0)
            break;
    }
    int bad = ferror(f);
    int e = errno;
    fclose(f);
    if (!buf)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory reading %s", path, what);
    if (bad) {
        free(buf);
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot read %s (%s)", path, what, strerror(e));
    }
    if (n > (size_t)max_bytes) {
        free(buf);
        return fs_fail(err, FS_BAD_INPUT, "%s: more than %ld bytes; %s may have at most %ld", path, max_bytes, what,
                       max_bytes);
    }
    buf[n] = 0;
    *data = buf;
    *len = n;
    return FS_OK;
}
