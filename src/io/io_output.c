/* io_output.c: files written whole through one writer, results folders replaced whole, and the
 * temporary files and folders of both removed on every exit path footsim controls. */
#define _GNU_SOURCE /* renameat2: swapping two folders in one step (Linux) */
#include "footsim/io/fs_output.h"

#include "footsim/io/fs_input.h"

#include <cJSON.h>
#include <dirent.h>
#include <signal.h>
#include <sys/syscall.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- what to remove at exit --------------------------------------------------------------------- */

/* Temporary files and partial folders of this process, removed (unless they were committed) by
 * fs_output_cleanup, which the command calls at exit (ODE's error handler ends the process with
 * exit()) and on SIGINT, SIGTERM and SIGHUP through fs_output_install_cleanup; the library itself
 * installs no handler. A forked worker inherits the list but never removes its parent's entries
 * (owner). */
enum { PENDING_MAX = 32 };
typedef struct pending {
    char path[FS_OUT_PATH + 64];
    int tree;
    pid_t owner;
} pending;
/* Static on purpose: the atexit and signal handlers that remove these take no argument, so the list
 * they read must be the process's own (filled and read with no allocation: safe in a handler). */
static pending pend[PENDING_MAX];
static int npend;

static void cleanup_at_exit(void)
{
    for (int i = 0; i < npend; i++) {
        if (!pend[i].path[0] || pend[i].owner != getpid())
            continue;
        if (pend[i].tree)
            fs_remove_tree(pend[i].path);
        else
            unlink(pend[i].path);
        pend[i].path[0] = 0;
    }
}

/* Removes a folder and everything in it with system calls only (no malloc, no stdio): safe in a
 * signal handler. Folders nest at most `depth` deep (a results folder: frames/ in it). */
static void remove_tree_raw(int parent, const char *name, int depth)
{
    int fd = openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
        char buf[4096];
        for (;;) {
            long n = syscall(SYS_getdents64, fd, buf, sizeof buf);
            if (n <= 0)
                break;
            for (long off = 0; off < n;) {
                struct dirent64 *e = (struct dirent64 *)(buf + off);
                off += e->d_reclen;
                if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                    continue;
                if (unlinkat(fd, e->d_name, 0) != 0 && depth > 0)
                    remove_tree_raw(fd, e->d_name, depth - 1);
            }
        }
        close(fd);
    }
    unlinkat(parent, name, AT_REMOVEDIR);
}

void fs_output_cleanup(void)
{
    for (int i = 0; i < npend; i++) {
        if (!pend[i].path[0] || pend[i].owner != getpid())
            continue;
        if (pend[i].tree)
            remove_tree_raw(AT_FDCWD, pend[i].path, 4);
        else
            unlink(pend[i].path);
    }
}

/* SIGINT, SIGTERM, SIGHUP: what this process left half done is removed, then the signal ends it
 * as it would have. */
static void cleanup_on_signal(int sig)
{
    fs_output_cleanup();
    signal(sig, SIG_DFL);
    raise(sig);
}

void fs_catch_signal(int sig, void (*handler)(int))
{
    struct sigaction old, sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    /* a signal the user's shell ignores (nohup) stays ignored */
    if (sigaction(sig, NULL, &old) == 0 && old.sa_handler != SIG_IGN)
        sigaction(sig, &sa, NULL);
}

int fs_output_install_cleanup(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++)
        fs_catch_signal(sigs[i], cleanup_on_signal);
    return atexit(cleanup_at_exit) == 0 ? 0 : -1;
}

static void remember(const char *path, int tree)
{
    int slot = -1;
    for (int i = 0; i < npend && slot < 0; i++)
        if (!pend[i].path[0])
            slot = i;
    if (slot < 0 && npend < PENDING_MAX)
        slot = npend++;
    if (slot >= 0) {
        pend[slot].owner = 0; /* a signal arriving now skips the entry until it is whole */
        pend[slot].tree = tree;
        snprintf(pend[slot].path, sizeof pend[slot].path, "%s", path);
        pend[slot].owner = getpid();
    }
}

static void forget(const char *path)
{
    for (int i = 0; i < npend; i++)
        if (pend[i].owner == getpid() && !strcmp(pend[i].path, path))
            pend[i].path[0] = 0;
}

/* ---- folders ------------------------------------------------------------------------------------ */

fs_status fs_make_dirs(const char *dir, fs_error *err)
{
    char buf[FS_OUT_PATH];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf)
        return fs_fail(err, FS_BAD_INPUT, "%.64s...: path too long", dir);
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
    if (stat(buf, &st) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot create folder (%s); choose a writable --out", dir, strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s: is %s, not a folder; choose another --out", dir, fs_file_kind(st.st_mode));
    if (access(buf, W_OK | X_OK) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: folder cannot be written (%s); choose another --out", dir,
                       strerror(errno));
    return FS_OK;
}

static int fsync_path(const char *path);
static int sync_failed; /* static on purpose: nftw's callback takes no user pointer to report through */

static int sync_folder(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)ftw;
    if ((flag == FTW_D || flag == FTW_DP) && fsync_path(path) != 0)
        sync_failed = errno ? errno : EIO;
    return 0;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

void fs_remove_tree(const char *dir) { nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS); }

/* The folder part of path ("." when there is none). */
static void parent_of(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(out, size, ".");
    else if (slash == path)
        snprintf(out, size, "/");
    else
        snprintf(out, size, "%.*s", (int)(slash - path), path);
}

static int fsync_path(const char *path)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    int r = fsync(fd);
    /* some filesystems cannot fsync a folder; that is not a failure of the write */
    if (r != 0 && (errno == EINVAL || errno == EROFS || errno == EBADF))
        r = 0;
    close(fd);
    return r;
}

const char *fs_output_shown(const char *path, char *buf, size_t size)
{
    for (int i = 0; i < npend; i++) {
        const char *p = pend[i].path, *mark = strstr(p, ".partial.");
        size_t n = strlen(p);
        if (pend[i].tree && pend[i].owner == getpid() && mark && n && !strncmp(path, p, n) &&
            (path[n] == '/' || !path[n])) {
            snprintf(buf, size, "%.*s%s", (int)(mark - p), p, path + n);
            return buf;
        }
    }
    return path;
}

static fs_status write_error(fs_error *err, const char *path, int e)
{
    char b[FS_OUT_PATH + 64];
    path = fs_output_shown(path, b, sizeof b);
    if (e == ENOSPC)
        return fs_fail(err, FS_IO, "%s: cannot write: No space left on device; free some space and run again", path);
    if (e == EFBIG)
        return fs_fail(err, FS_IO, "%s: cannot write: File too large (a file-size limit, ulimit -f, is reached); raise "
                       "the limit or write less, and run again", path);
    return fs_fail(err, FS_IO, "%s: cannot write (%s)", path, strerror(e ? e : EIO));
}

/* ---- files -------------------------------------------------------------------------------------- */

/* Whether the regular file at path begins with the n bytes of sig (read without following a link). */
static int begins_with(const char *path, const unsigned char *sig, size_t n)
{
    unsigned char buf[64];
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0 || n > sizeof buf) {
        if (fd >= 0)
            close(fd);
        return 0;
    }
    ssize_t got = read(fd, buf, n);
    close(fd);
    return got == (ssize_t)n && !memcmp(buf, sig, n);
}

fs_status fs_check_file_target(const char *path, const char *what, const unsigned char *signature, size_t nsig,
                               const char *kind, int replace, fs_error *err)
{
    fs_status fits = fs_path_fits(path, FS_FILE_ROOM, FS_FILE_ROOM, what, err);
    if (fits != FS_OK)
        return fits;
    struct stat st;
    int exists = lstat(path, &st) == 0;
    if (exists && !S_ISREG(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s %s: is %s; footsim writes only regular files: give a file's path", what,
                       path, fs_file_kind(st.st_mode));
    /* a user's file (notes, data) is not replaced by accident: only what footsim would write there */
    if (exists && !replace && st.st_size > 0 && !begins_with(path, signature, nsig))
        return fs_fail(err, FS_BAD_INPUT, "%s %s: the file exists and is not %s; footsim replaces only its own kind of "
                       "file: give another name, remove it, or add --replace to overwrite it", what, path, kind);
    char dir[FS_OUT_PATH];
    parent_of(path, dir, sizeof dir);
    if (stat(dir, &st) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s %s: folder %s: %s; give a path in an existing folder", what, path, dir,
                       strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s %s: %s is %s, not a folder", what, path, dir, fs_file_kind(st.st_mode));
    if (access(dir, W_OK | X_OK) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s %s: folder %s cannot be written (%s); give a writable place", what, path,
                       dir, strerror(errno));
    return FS_OK;
}

fs_status fs_check_own_file(const char *path, const char *what, const char *fix, fs_error *err)
{
    struct stat st;
    if (lstat(path, &st) != 0 || S_ISREG(st.st_mode))
        return FS_OK;
    if (S_ISLNK(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s: is a symbolic link; footsim does not follow links for %s (it reads back "
                       "and appends to only the file it wrote there itself): %s", path, what, fix);
    return fs_fail(err, FS_BAD_INPUT, "%s: is %s, not %s (a regular file footsim writes): %s", path,
                   fs_file_kind(st.st_mode), what, fix);
}

fs_status fs_temp_name(const char *path, char *temp, size_t size, fs_error *err)
{
    if (snprintf(temp, size, "%s.tmp.%ld", path, (long)getpid()) >= (int)size)
        return fs_fail(err, FS_IO, "%.64s...: path too long", path);
    remember(temp, 0);
    return FS_OK;
}

/* Whether path lies in a partial results folder of this process: its folder is fsync'd once, when
 * the partial folder is put in place (fs_outdir_commit), not after each file. */
static int in_partial(const char *path)
{
    for (int i = 0; i < npend; i++) {
        size_t n = strlen(pend[i].path);
        if (pend[i].tree && pend[i].owner == getpid() && n && !strncmp(path, pend[i].path, n) && path[n] == '/')
            return 1;
    }
    return 0;
}

/* Renames temp (fsync'd first unless synced) over path, then fsyncs path's folder. */
static fs_status commit(const char *temp, const char *path, int synced, fs_error *err)
{
    struct stat st;
    fs_status s = FS_OK;
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode))
        s = fs_fail(err, FS_IO, "%s: is %s; footsim replaces only regular files", path, fs_file_kind(st.st_mode));
    else if (!synced && fsync_path(temp) != 0)
        s = write_error(err, path, errno);
    else if (rename(temp, path) != 0) {
        char b[FS_OUT_PATH + 64];
        s = fs_fail(err, FS_IO, "%s: cannot replace (%s)", fs_output_shown(path, b, sizeof b), strerror(errno));
    }
    if (s != FS_OK) {
        unlink(temp);
        forget(temp);
        return s;
    }
    forget(temp);
    char dir[FS_OUT_PATH];
    parent_of(path, dir, sizeof dir);
    if (!in_partial(path) && fsync_path(dir) != 0)
        return write_error(err, dir, errno);
    return FS_OK;
}

fs_status fs_commit_temp(const char *temp, const char *path, fs_error *err) { return commit(temp, path, 0, err); }

fs_status fs_write_file(const char *path, fs_fill_fn fill, const void *user, fs_error *err)
{
    char temp[FS_OUT_PATH + 64];
    struct stat st;
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return fs_fail(err, FS_IO, "%s: is %s; footsim replaces only regular files", path, fs_file_kind(st.st_mode));
    if (fs_temp_name(path, temp, sizeof temp, err) != FS_OK)
        return FS_IO;
    unlink(temp); /* one a killed run of the same pid left */
    int fd = open(temp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        int e = errno;
        if (fd >= 0)
            close(fd);
        forget(temp);
        unlink(temp);
        return write_error(err, path, e);
    }
    errno = 0;
    int ok = fill(f, user);
    int e = errno;
    int failed = ferror(f) || fflush(f) != 0;
    if (failed)
        e = errno ? errno : e;
    if (!failed && fsync(fileno(f)) != 0)
        failed = 1, e = errno;
    if (fclose(f) != 0 && !failed)
        failed = 1, e = errno;
    if (!ok || failed) {
        unlink(temp);
        forget(temp);
        if (failed)
            return write_error(err, path, e);
        return fs_fail(err, FS_NO_MEMORY, "%s: its content could not be made (out of memory)", path);
    }
    return commit(temp, path, 1, err);
}

fs_status fs_write_in(const char *dir, const char *name, fs_fill_fn fill, const void *user, fs_error *err)
{
    char path[FS_OUT_PATH];
    if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path)
        return fs_fail(err, FS_IO, "%.64s.../%s: path too long", dir, name);
    return fs_write_file(path, fill, user, err);
}

typedef struct bytes {
    const char *data;
    size_t len;
} bytes;

static int fill_bytes(FILE *f, const void *user)
{
    const bytes *b = user;
    return fwrite(b->data, 1, b->len, f) == b->len;
}

fs_status fs_write_atomic(const char *path, const char *data, size_t len, fs_error *err)
{
    bytes b = {data, len};
    return fs_write_file(path, fill_bytes, &b, err);
}

/* ---- results folders ---------------------------------------------------------------------------- */

fs_status fs_normalise_dir(const char *dir, char *out, size_t size, const char *option, fs_error *err)
{
    size_t n = strlen(dir);
    if (n == 0)
        return fs_fail(err, FS_BAD_INPUT, "%s '': give a folder's path", option);
    fs_status fits = fs_path_fits(dir, FS_DIR_ROOM, 0, option, err);
    if (fits != FS_OK)
        return fits;
    /* drop repeated slashes and "." components */
    char buf[FS_OUT_PATH];
    size_t k = 0;
    int absolute = dir[0] == '/';
    if (absolute)
        buf[k++] = '/';
    for (const char *p = dir; *p;) {
        while (*p == '/')
            p++;
        size_t len = strcspn(p, "/");
        if (len == 0)
            break;
        if (!(len == 1 && p[0] == '.')) {
            if (k > 0 && buf[k - 1] != '/')
                buf[k++] = '/';
            memcpy(buf + k, p, len);
            k += len;
        }
        p += len;
    }
    buf[k] = 0;
    if (k == 0)
        snprintf(buf, sizeof buf, ".");
    const char *last = strrchr(buf, '/');
    last = last ? last + 1 : buf;
    if (!strcmp(last, "..") || !strcmp(buf, ".")) {
        /* the folder a final ".." (or ".") names: resolve it, as it must exist */
        char *real = realpath(buf, NULL);
        if (!real)
            return fs_fail(err, FS_BAD_INPUT, "%s %s: %s; give the folder's own path", option, dir, strerror(errno));
        snprintf(buf, sizeof buf, "%s", real);
        free(real);
    }
    if (!strcmp(buf, "/"))
        return fs_fail(err, FS_BAD_INPUT, "%s %s: the root folder cannot be a results folder; give a folder of its own",
                       option, dir);
    if ((fits = fs_path_fits(buf, FS_DIR_ROOM, FS_NAME_ROOM, option, err)) != FS_OK)
        return fits;
    return fs_path_format(out, size, option, err, "%s", buf);
}

/* Whether folder path holds nothing; -1 when it cannot be read. */
static int is_empty(const char *path)
{
    DIR *d = opendir(path);
    if (!d)
        return -1;
    int empty = 1;
    for (struct dirent *e; empty && (e = readdir(d));)
        empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..");
    closedir(d);
    return empty;
}

/* Whether the folder at path, and everything in it, can be removed: no entry immutable or
 * append-only (what even root cannot remove), and every folder writable. Fills why with the first
 * that cannot be. */
static int removable(const char *path, int depth, char *why, size_t size)
{
    struct statx sx;
    if (statx(AT_FDCWD, path, AT_SYMLINK_NOFOLLOW, STATX_TYPE, &sx) != 0)
        return 1; /* gone: nothing to remove */
    unsigned long long fixed = sx.stx_attributes & sx.stx_attributes_mask & (STATX_ATTR_IMMUTABLE | STATX_ATTR_APPEND);
    if (fixed) {
        snprintf(why, size, "%.3900s is %s", path, fixed & STATX_ATTR_IMMUTABLE ? "immutable (chattr +i)"
                                                                             : "append-only (chattr +a)");
        return 0;
    }
    if (!S_ISDIR(sx.stx_mode) || depth == 0)
        return 1;
    if (access(path, W_OK | X_OK) != 0) {
        snprintf(why, size, "%.3900s cannot be written (%s)", path, strerror(errno));
        return 0;
    }
    DIR *d = opendir(path);
    if (!d) {
        snprintf(why, size, "%.3900s cannot be read (%s)", path, strerror(errno));
        return 0;
    }
    int ok = 1;
    char child[FS_OUT_PATH];
    for (struct dirent *e; ok && (e = readdir(d));) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        if (fs_path_format(child, sizeof child, "", NULL, "%s/%s", path, e->d_name) != FS_OK) {
            snprintf(why, size, "%.3000s/%.255s: the path is too long to remove", path, e->d_name);
            ok = 0;
        } else {
            ok = removable(child, depth - 1, why, size);
        }
    }
    closedir(d);
    return ok;
}

static int has_marker(const char *path)
{
    char m[FS_OUT_PATH + 32];
    snprintf(m, sizeof m, "%s/%s", path, FS_MARKER);
    FILE *f = fopen(m, "r");
    if (!f)
        return 0;
    char line[128] = "";
    int format = 0;
    int ok = fgets(line, sizeof line, f) && sscanf(line, "footsim results folder, format %d", &format) == 1 &&
             format >= 1;
    fclose(f);
    return ok;
}

/* The partial and old folders a killed run left beside path (path.partial.<pid>, path.old.<pid>,
 * each marked or empty): removed, as the lock is ours. An old folder whose swap was cut short is
 * put back when path is missing. */
static void sweep_leftovers(const char *path)
{
    char dir[FS_OUT_PATH], prefix[FS_OUT_PATH + 256];
    parent_of(path, dir, sizeof dir);
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct stat st;
    int missing = lstat(path, &st) != 0;
    for (struct dirent *e; (e = readdir(d));) {
        const char *kind = NULL;
        size_t n = strlen(base);
        if (strncmp(e->d_name, base, n))
            continue;
        if (!strncmp(e->d_name + n, ".partial.", 9))
            kind = "partial";
        else if (!strncmp(e->d_name + n, ".old.", 5))
            kind = "old";
        else
            continue;
        const char *pid = e->d_name + n + (kind[0] == 'p' ? 9 : 5);
        if (!*pid || strspn(pid, "0123456789") != strlen(pid))
            continue;
        snprintf(prefix, sizeof prefix, "%s/%s", dir, e->d_name);
        struct stat ps;
        /* only a folder footsim made: its marker, or nothing in it (a user's "data.old.2024" stays) */
        if (lstat(prefix, &ps) != 0 || !S_ISDIR(ps.st_mode) || (!has_marker(prefix) && is_empty(prefix) != 1))
            continue;
        if (kind[0] == 'o' && missing && rename(prefix, path) == 0) {
            missing = 0;
            continue;
        }
        fs_remove_tree(prefix);
    }
    closedir(d);
}

/* Takes the lock .<name>.footsim-lock beside the folder (kept open): refuses when another footsim
 * holds it, or when a file there is not a footsim lock. */
/* Whether path is absent or looks like footsim's lock file: a small regular file holding a pid. */
static int lock_is_ours(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return errno == ENOENT;
    if (!S_ISREG(st.st_mode) || st.st_size > 32)
        return 0;
    char text[40] = "";
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : -1;
    if (fd >= 0)
        close(fd);
    text[n > 0 ? n : 0] = 0;
    return n >= 0 && strspn(text, "0123456789\n") == strlen(text);
}

static fs_status take_lock(fs_outdir *o, const char *option, fs_error *err)
{
    if (!lock_is_ours(o->lock))
        return fs_fail(err, FS_BAD_INPUT, "%s %s: %s exists and is not footsim's lock file; move it away, or choose "
                       "another %s", option, o->path, o->lock, option);
    int waited = 0;
    for (int tries = 0; tries < 8; tries++) {
        int fd = open(o->lock, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
        if (fd < 0)
            return fs_fail(err, FS_BAD_INPUT, "%s %s: cannot make the lock file %s (%s); choose a writable place",
                           option, o->path, o->lock, strerror(errno));
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            char pid[32] = "";
            ssize_t n = read(fd, pid, sizeof pid - 1);
            pid[n > 0 ? n : 0] = 0;
            pid[strcspn(pid, "\n")] = 0;
            close(fd);
            /* its footsim is gone, and the lock is held by its worker processes (which inherit it),
             * dying with it (fs_pool.h) after a kill -9: wait for them, up to 5 s */
            long holder = atol(pid);
            if (holder > 0 && kill((pid_t)holder, 0) != 0 && errno == ESRCH && waited++ < 100) {
                usleep(50000);
                tries--;
                continue;
            }
            return fs_fail(err, FS_BAD_INPUT,
                           "%s %s: another footsim (process %s) is writing this folder; wait for it to end, or "
                           "choose another %s", option, o->path, *pid ? pid : "?", option);
        }
        /* the lock file may have been removed by the holder just before we locked it: then retry */
        struct stat a, b;
        if (fstat(fd, &a) == 0 && stat(o->lock, &b) == 0 && a.st_ino == b.st_ino && a.st_dev == b.st_dev) {
            char pid[32];
            int n = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
            if (ftruncate(fd, 0) != 0 || pwrite(fd, pid, (size_t)n, 0) != n) { /* only for messages */
            }
            o->lock_fd = fd;
            return FS_OK;
        }
        close(fd);
    }
    return fs_fail(err, FS_BAD_INPUT, "%s %s: cannot take the lock %s; try again", option, o->path, o->lock);
}

static void release_lock(fs_outdir *o)
{
    if (o->lock_fd >= 0) {
        unlink(o->lock);
        close(o->lock_fd);
    }
    o->lock_fd = -1;
}

static int fill_marker(FILE *f, const void *user)
{
    (void)user;
    fprintf(f, "footsim results folder, format %d\n"
               "footsim replaces this folder whole (a folder several commands share, such as a bench's: only\n"
               "the files it writes) when asked to write here again; a folder without this file is never\n"
               "written into unless --replace is given.\n", FS_MARKER_FORMAT);
    return 1;
}

/* Refuses a target footsim must not replace or write into: a symbolic link, not a folder, a
 * non-empty folder without the marker (unless replace); one it would replace (not shared) that
 * cannot be removed whole. Makes its parent. `path` is normalised, `dir` as given. */
static fs_status check_target(const char *path, const char *dir, int replace, const char *option, int shared,
                              fs_error *err)
{
    char parent[FS_OUT_PATH];
    parent_of(path, parent, sizeof parent);
    fs_status s = fs_make_dirs(parent, err);
    if (s != FS_OK)
        return s;
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (S_ISLNK(st.st_mode))
            return fs_fail(err, FS_BAD_INPUT, "%s %s: is a symbolic link; footsim replaces only folders it made: give "
                           "the folder's own path", option, dir);
        if (!S_ISDIR(st.st_mode))
            return fs_fail(err, FS_BAD_INPUT, "%s %s: is %s, not a results folder; choose another %s", option, dir,
                           fs_file_kind(st.st_mode), option);
        int empty = is_empty(path);
        if (empty < 0)
            return fs_fail(err, FS_BAD_INPUT, "%s %s: cannot read the folder (%s); choose another %s", option, dir,
                           strerror(errno), option);
        /* footsim's by its marker only: files that merely carry footsim's names are the user's */
        if (!empty && !has_marker(path) && !replace)
            return fs_fail(err, FS_BAD_INPUT,
                           "%s %s: a folder footsim did not make (it has no %s marker, whatever its files are "
                           "called); footsim %s only its own results folders: choose another %s, or add --replace to %s",
                           option, dir, FS_MARKER, shared ? "writes into" : "replaces, whole,", option,
                           shared ? "write its files into it anyway" : "replace it and everything in it");
        char why[FS_OUT_PATH + 64];
        if (!shared && !removable(path, 16, why, sizeof why))
            return fs_fail(err, FS_IO, "%s %s: cannot be replaced: %s; make it writable (chattr -i, chmod -R u+w) "
                           "or choose another %s (nothing was written)", option, dir, why, option);
    }
    return FS_OK;
}

/* o->lock for the results folder o->path: .<name>.footsim-lock beside it; refused when it would
 * not fit. */
static fs_status lock_path(fs_outdir *o, const char *option, fs_error *err)
{
    char parent[FS_OUT_PATH];
    parent_of(o->path, parent, sizeof parent);
    const char *base = strrchr(o->path, '/');
    return fs_path_format(o->lock, sizeof o->lock, option, err, "%s/.%s.footsim-lock", parent, base ? base + 1 : o->path);
}

fs_status fs_outdir_open(fs_outdir *o, const char *dir, int replace, const char *option, fs_error *err)
{
    memset(o, 0, sizeof *o);
    o->lock_fd = -1;
    fs_status s = fs_normalise_dir(dir, o->path, sizeof o->path, option, err);
    if (s != FS_OK)
        return s;
    if ((s = check_target(o->path, dir, replace, option, 0, err)) != FS_OK)
        return s;
    if ((s = lock_path(o, option, err)) != FS_OK)
        return s;
    if ((s = take_lock(o, option, err)) != FS_OK)
        return s;
    sweep_leftovers(o->path);
    if (fs_path_format(o->partial, sizeof o->partial, option, err, "%s.partial.%ld", o->path, (long)getpid()) != FS_OK) {
        release_lock(o);
        return FS_BAD_INPUT;
    }
    if (mkdir(o->partial, 0777) != 0) {
        s = fs_fail(err, FS_BAD_INPUT, "%s %s: cannot create %s (%s); choose a writable %s", option, dir, o->partial,
                    strerror(errno), option);
        release_lock(o);
        return s;
    }
    remember(o->partial, 1);
    remember(o->lock, 0);
    o->open = 1;
    char marker[FS_OUT_PATH + 80];
    snprintf(marker, sizeof marker, "%s/%s", o->partial, FS_MARKER);
    if ((s = fs_write_file(marker, fill_marker, NULL, err)) != FS_OK)
        fs_outdir_abort(o);
    return s;
}

fs_status fs_outdir_lock(fs_outdir *o, const char *dir, const char *option, fs_error *err)
{
    memset(o, 0, sizeof *o);
    o->lock_fd = -1;
    fs_status s = fs_normalise_dir(dir, o->path, sizeof o->path, option, err);
    if (s != FS_OK || (s = lock_path(o, option, err)) != FS_OK)
        return s;
    char parent[FS_OUT_PATH];
    parent_of(o->path, parent, sizeof parent);
    if (access(parent, W_OK) != 0 && (errno == EACCES || errno == EROFS || errno == EPERM))
        return FS_OK; /* no footsim can replace a folder in a folder it cannot write: nothing to hold */
    if ((s = take_lock(o, option, err)) == FS_OK)
        remember(o->lock, 0);
    return s;
}

void fs_outdir_unlock(fs_outdir *o)
{
    if (o->lock_fd >= 0)
        forget(o->lock);
    release_lock(o);
}

void fs_outdir_abort(fs_outdir *o)
{
    if (!o->open)
        return;
    fs_remove_tree(o->partial);
    forget(o->partial);
    forget(o->lock);
    release_lock(o);
    o->open = 0;
}

/* Swaps partial and path in one step; where the filesystem cannot (EINVAL: NFS, some FUSE) or
 * FOOTSIM_TEST_NO_EXCHANGE is set (tests), moves the old folder aside, the new one in, and the
 * old one back if that fails. On success old names the folder to remove ("" when none). */
static int swap_in(const char *partial, const char *path, char *old, size_t size)
{
    old[0] = 0;
    struct stat st;
    if (lstat(path, &st) != 0)
        return rename(partial, path);
    if (!getenv("FOOTSIM_TEST_NO_EXCHANGE")) {
        if (renameat2(AT_FDCWD, partial, AT_FDCWD, path, RENAME_EXCHANGE) == 0) {
            snprintf(old, size, "%s", partial);
            return 0;
        }
        if (errno != EINVAL && errno != ENOSYS)
            return -1;
    }
    char aside[FS_OUT_PATH + 48];
    snprintf(aside, sizeof aside, "%s.old.%ld", path, (long)getpid());
    if (rename(path, aside) != 0)
        return -1;
    if (rename(partial, path) != 0) {
        int e = errno;
        if (rename(aside, path) != 0) { /* left as path.old.<pid>: the next run puts it back */
        }
        errno = e;
        return -1;
    }
    snprintf(old, size, "%s", aside);
    return 0;
}

fs_status fs_outdir_commit(fs_outdir *o, fs_error *err)
{
    if (!o->open)
        return fs_fail(err, FS_IO, "%s: no results to put in place", o->path);
    char parent[FS_OUT_PATH], old[FS_OUT_PATH + 64];
    parent_of(o->path, parent, sizeof parent);
    fs_status s = FS_OK;
    /* its files were fsync'd as they were written; now its folders (frames/ and itself) */
    sync_failed = 0;
    nftw(o->partial, sync_folder, 16, FTW_DEPTH | FTW_PHYS);
    if (sync_failed)
        s = write_error(err, o->path, sync_failed);
    else if (swap_in(o->partial, o->path, old, sizeof old) != 0)
        s = fs_fail(err, FS_IO, "%s: cannot put the results in place (%s)", o->path, strerror(errno));
    else if (fsync_path(parent) != 0)
        s = write_error(err, parent, errno);
    if (s != FS_OK) {
        fs_outdir_abort(o);
        return s;
    }
    struct stat st;
    if (old[0]) {
        fs_remove_tree(old);
        if (lstat(old, &st) == 0) /* what the check before the run could not foresee */
            s = fs_fail(err, FS_IO, "%s: the new results are in place, but the old ones could not all be removed: "
                        "they are left in %s; make it writable and remove it", o->path, old);
    }
    forget(o->partial);
    forget(o->lock);
    release_lock(o);
    o->open = 0;
    return s;
}

fs_status fs_outdir_shared(const char *dir, int replace, const char *option, fs_error *err)
{
    char path[FS_OUT_PATH], marker[FS_OUT_PATH + 32];
    fs_status s = fs_normalise_dir(dir, path, sizeof path, option, err);
    if (s == FS_OK)
        s = check_target(path, dir, replace, option, 1, err);
    if (s == FS_OK)
        s = fs_make_dirs(path, err);
    snprintf(marker, sizeof marker, "%s/%s", path, FS_MARKER);
    struct stat st;
    if (s == FS_OK && lstat(marker, &st) != 0)
        s = fs_write_file(marker, fill_marker, NULL, err);
    return s;
}

int fs_json_print(FILE *f, const cJSON *root)
{
    char *text = root ? cJSON_Print(root) : NULL;
    if (text)
        fprintf(f, "%s\n", text);
    free(text);
    return text != NULL;
}

int fs_json_put(cJSON *parent, const char *name, cJSON *item)
{
    if (item && parent && (name ? cJSON_AddItemToObject(parent, name, item) : cJSON_AddItemToArray(parent, item)))
        return 1;
    cJSON_Delete(item);
    return 0;
}
