/* io_output.c: atomic writes, atomic folders and folder creation. */
#define _GNU_SOURCE /* renameat2: swapping two folders in one step (Linux) */
#include "footsim/io/fs_output.h"

#include <fcntl.h>
#include <ftw.h>
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

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

void fs_remove_tree(const char *dir) { nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS); }

fs_status fs_commit_dir(const char *partial, const char *final, fs_error *err)
{
    /* swap the two folders in one step, then remove the old one; or move the new one in */
    if (renameat2(AT_FDCWD, partial, AT_FDCWD, final, RENAME_EXCHANGE) == 0) {
        fs_remove_tree(partial);
        return FS_OK;
    }
    if (errno == ENOENT && rename(partial, final) == 0)
        return FS_OK;
    int e = errno;
    fs_remove_tree(partial);
    return fs_fail(err, FS_IO, "%s: cannot put the results in place (%s)", final, strerror(e));
}
