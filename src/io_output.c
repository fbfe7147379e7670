/* io_output.c: atomic writes and folder creation. */
#include "footsim/fs_output.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

fs_status fs_make_dirs(const char *dir, fs_error *err)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf)
        return fs_fail(err, FS_BAD_INPUT, "--out %s: path too long", dir);
    for (char *p = buf + 1;; p++) {
        if (*p == '/' || *p == 0) {
            char saved = *p;
            *p = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                return fs_fail(err, FS_BAD_INPUT, "%s: cannot create folder (%s); choose a writable --out", buf,
                               strerror(errno));
            *p = saved;
            if (!saved)
                break;
        }
    }
    struct stat st;
    if (stat(buf, &st) != 0 || !S_ISDIR(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s: not a folder; choose another --out", dir);
    if (access(buf, W_OK) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: folder is not writable; choose another --out", dir);
    return FS_OK;
}

FILE *fs_open_temp(const char *path, char *temp, size_t size, fs_error *err)
{
    if (snprintf(temp, size, "%s.tmp.%ld", path, (long)getpid()) >= (int)size) {
        fs_fail(err, FS_IO, "%s: path too long", path);
        return NULL;
    }
    FILE *f = fopen(temp, "w");
    if (!f)
        fs_fail(err, FS_IO, "%s: cannot write (%s)", temp, strerror(errno));
    return f;
}

fs_status fs_commit_file(FILE *f, const char *temp, const char *path, int ok, fs_error *err)
{
    int failed = ferror(f) || fflush(f) != 0 || fsync(fileno(f)) != 0;
    failed |= fclose(f) != 0;
    if (!ok || failed) {
        remove(temp);
        return ok ? fs_fail(err, FS_IO, "%s: write failed (%s)", path, strerror(errno)) : FS_OK;
    }
    if (rename(temp, path) != 0) {
        int e = errno;
        remove(temp);
        return fs_fail(err, FS_IO, "%s: cannot replace (%s)", path, strerror(e));
    }
    return FS_OK;
}

fs_status fs_write_atomic(const char *path, const char *data, size_t len, fs_error *err)
{
    char temp[4200];
    FILE *f = fs_open_temp(path, temp, sizeof temp, err);
    if (!f)
        return FS_IO;
    fwrite(data, 1, len, f);
    return fs_commit_file(f, temp, path, 1, err);
}
