/* fs_output.h: results written whole or not at all.
 *
 * fs_write_atomic writes text to "path.tmp.<pid>" and renames it over path, so a reader (or a
 * run killed half way) sees either the old complete file or the new one. */
#ifndef FS_OUTPUT_H
#define FS_OUTPUT_H

#include "footsim/base/fs_error.h"

#include <stddef.h>
#include <stdio.h>

/* Creates dir and its missing parents. */
fs_status fs_make_dirs(const char *dir, fs_error *err);

/* Writes len bytes of data to path atomically. */
fs_status fs_write_atomic(const char *path, const char *data, size_t len, fs_error *err);

/* Opens "path.tmp.<pid>" for writing; fs_commit_file closes it and renames it to path (or
 * removes it when ok is 0). For outputs too large to build in memory. */
FILE *fs_open_temp(const char *path, char *temp, size_t size, fs_error *err);
fs_status fs_commit_file(FILE *f, const char *temp, const char *path, int ok, fs_error *err);

/* A folder of results written whole or not at all: write everything into `partial` (a sibling of
 * `final`), then fs_commit_dir swaps it with `final` in one step (renameat2 RENAME_EXCHANGE) and
 * removes the old one. A reader, or a run killed at any moment, sees the old folder complete or the
 * new one complete. On failure `partial` is removed. */
fs_status fs_commit_dir(const char *partial, const char *final, fs_error *err);

/* Removes a folder and everything in it (best effort). */
void fs_remove_tree(const char *dir);

#endif
