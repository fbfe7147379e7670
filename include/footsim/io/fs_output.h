/* fs_output.h: results written whole or not at all, only where footsim may write.
 *
 * Files. fs_write_file is the one way footsim writes a file: the content goes to "path.tmp.<pid>"
 * through a callback, is flushed and fsync'd, and is renamed over path, whose folder is then
 * fsync'd; a reader, or a run killed at any moment, sees the old complete file or the new one.
 * The target must be absent or a regular file: a device, FIFO, folder or symbolic link is never
 * replaced. A temporary file is removed on every error path; at exit() (ODE's error handler) and
 * on SIGINT, SIGTERM and SIGHUP by fs_output_cleanup, which a program installs with
 * fs_output_install_cleanup (the library installs no handler of its own); one left by a kill -9 is
 * removed by the next write of the same path. A full disk is reported as "No space left on device" (FS_IO). fs_commit_temp installs a
 * file another program wrote (gnuplot, ffmpeg) the same way.
 *
 * Folders. A results folder (run, campaign, render-compare) is replaced whole: fs_outdir_open
 * checks the target before anything is simulated (FS_BAD_INPUT: a path too long to use whole
 * (fs_path_fits with FS_DIR_ROOM), a symbolic link, not a folder, a non-empty folder footsim did
 * not make, another footsim writing it; FS_IO: a folder footsim made that cannot be removed, as it
 * or something in it is read-only or immutable), takes a lock on it, and makes
 * a partial folder beside it holding the marker file FS_MARKER; fs_outdir_commit swaps the partial
 * folder in, in one step (renameat2 RENAME_EXCHANGE; where the filesystem refuses that, EINVAL,
 * two renames that never lose the old folder), and removes the old one. A folder footsim made is
 * one with the marker, whatever its files are named: a folder without it (a user's, or one an
 * earlier footsim made before the marker) is read, never replaced, unless `replace` (--replace). */
#ifndef FS_OUTPUT_H
#define FS_OUTPUT_H

#include "footsim/base/fs_error.h"
#include "footsim/base/fs_path.h"

#include <stddef.h>
#include <stdio.h>

enum { FS_OUT_PATH = 4096 };

/* The marker file of a results folder, and its format version (the file's first line reads
 * "footsim results folder, format 1"). */
#define FS_MARKER ".footsim-results"
enum { FS_MARKER_FORMAT = 1 };

/* Creates dir and its missing parents; refuses (FS_BAD_INPUT) when it cannot, naming why. */
fs_status fs_make_dirs(const char *dir, fs_error *err);

/* Writes path through fill (which returns 1, or 0 when it could not produce the content), whole
 * or not at all. */
typedef int (*fs_fill_fn)(FILE *f, const void *user);
fs_status fs_write_file(const char *path, fs_fill_fn fill, const void *user, fs_error *err);

/* fs_write_file of dir/name. */
fs_status fs_write_in(const char *dir, const char *name, fs_fill_fn fill, const void *user, fs_error *err);

/* Writes len bytes of data to path, through fs_write_file. */
fs_status fs_write_atomic(const char *path, const char *data, size_t len, fs_error *err);

/* Refuses (FS_BAD_INPUT) a path footsim must not write a file at: a device, FIFO, socket,
 * folder or symbolic link, a file in a folder that does not exist or cannot be written, or (unless
 * replace, --replace) an existing non-empty file that is not `kind` ("a PNG"), that is, does not
 * begin with its nsig (at most 64) signature bytes: a user's file is never overwritten by accident. */
fs_status fs_check_file_target(const char *path, const char *what, const unsigned char *signature, size_t nsig,
                               const char *kind, int replace, fs_error *err);

/* path as the user will find it: one in a partial results folder of this process
 * (DIR.partial.<pid>/NAME, renamed or removed when the command ends) as DIR/NAME; any other as it
 * is. Returns buf or path. For messages. */
const char *fs_output_shown(const char *path, char *buf, size_t size);

/* Refuses (FS_BAD_INPUT) what footsim must not read back or append to as a file of its own (a
 * campaign journal): a symbolic link (never followed: its target is not footsim's to append to), a
 * folder, FIFO, socket or device, each named, then `fix` (what to do). Absent or a regular file:
 * FS_OK. `what` names the file ("a campaign journal"). */
fs_status fs_check_own_file(const char *path, const char *what, const char *fix, fs_error *err);

/* A temporary name for path beside it ("path.tmp.<pid>"), removed at exit unless committed. */
fs_status fs_temp_name(const char *path, char *temp, size_t size, fs_error *err);

/* fsyncs temp and renames it over path (a regular file or nothing), then fsyncs the folder. On
 * failure temp is removed. */
fs_status fs_commit_temp(const char *temp, const char *path, fs_error *err);

/* Installs handler for sig (no SA_RESTART) unless sig is ignored (nohup: it stays ignored). */
void fs_catch_signal(int sig, void (*handler)(int));

/* Removes the temporary files and partial folders this process has not committed, with system
 * calls only: safe in a signal handler. */
void fs_output_cleanup(void);

/* For a program (the footsim command) that wants them: fs_output_cleanup at exit, and on SIGINT,
 * SIGTERM and SIGHUP (unless ignored; the signal then ends the process as it would have). A
 * handler installed after it (fs_catch_signal) replaces it for its signal. 0, or -1 when atexit
 * refused. */
int fs_output_install_cleanup(void);

/* Removes a folder and everything in it (best effort; never follows symbolic links). */
void fs_remove_tree(const char *dir);

typedef struct fs_outdir {
    char path[FS_OUT_PATH];        /* the results folder, normalised */
    char partial[FS_OUT_PATH + 48];/* where everything is written: path.partial.<pid> */
    char lock[FS_OUT_PATH + 48];   /* .<name>.footsim-lock beside it, held while writing */
    int lock_fd;
    int open;
} fs_outdir;

/* Checks and prepares the results folder dir (see above); `replace` lets a non-empty folder
 * without the marker be replaced on purpose (--replace). `option` names the option in messages
 * ("--out"). */
fs_status fs_outdir_open(fs_outdir *o, const char *dir, int replace, const char *option, fs_error *err);

/* Puts the partial folder in place of the results folder, whole (see above); on failure the old
 * folder stays and the partial one is removed. */
fs_status fs_outdir_commit(fs_outdir *o, fs_error *err);

/* Gives up: removes the partial folder, releases the lock. Safe to call twice. */
void fs_outdir_abort(fs_outdir *o);

/* Takes only the lock of results folder dir (normalised into o->path), as fs_outdir_open does,
 * for a command that reads the folder and writes beside its files (plot): while it holds it, no
 * footsim replaces the folder, and it refuses (FS_BAD_INPUT, naming the holder's process) while
 * another holds it. A folder whose parent cannot be written is read without a lock (none can
 * replace it). Released by fs_outdir_unlock (safe to call twice), or at exit. */
fs_status fs_outdir_lock(fs_outdir *o, const char *dir, const char *option, fs_error *err);
void fs_outdir_unlock(fs_outdir *o);

/* A folder footsim writes file by file and never replaces (results/bench/, plot --out): refused
 * as fs_outdir_open refuses a results folder (a symbolic link, not a folder, a non-empty folder
 * without the marker, unless replace); made when missing; given the marker when it has none. */
fs_status fs_outdir_shared(const char *dir, int replace, const char *option, fs_error *err);

/* Normalises a folder path: no trailing slash, no "." components or repeated slashes; a final
 * ".." is resolved. Refuses the root, the empty path and one fs_path_fits refuses with
 * FS_DIR_ROOM and FS_NAME_ROOM. */
fs_status fs_normalise_dir(const char *dir, char *out, size_t size, const char *option, fs_error *err);

/* Puts item into a JSON tree being built for a result: into parent under name (an object), or at
 * its end when name is NULL (an array). cJSON's adds fail silently on out of memory, leaving a
 * field out of a result file; a builder ands every put (and every cJSON_Add...ToObject's non-NULL
 * result) and refuses an incomplete tree (FS_NO_MEMORY). When the put fails, or item is NULL
 * because making it failed, item is deleted; returns 1 when put. */
struct cJSON;
int fs_json_put(struct cJSON *parent, const char *name, struct cJSON *item);

/* Writes root as indented JSON text and a newline to f; 1 when written, 0 when root is NULL or its
 * text could not be made (out of memory). The one way footsim prints a JSON result. */
int fs_json_print(FILE *f, const struct cJSON *root);

#endif
