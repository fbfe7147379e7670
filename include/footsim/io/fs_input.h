/* fs_input.h: opening the files footsim reads, safely.
 *
 * Only regular files are read, and only up to a stated size: a folder, FIFO, device or socket is
 * refused (a FIFO would block, /dev/zero would fill memory), naming what it is; a file that cannot
 * be opened is refused with the system's reason (no such file, permission denied, a symbolic link
 * loop, ...), not a guess. Every refusal is FS_BAD_INPUT, "path: what is wrong; what would do". */
#ifndef FS_INPUT_H
#define FS_INPUT_H

#include "footsim/base/fs_error.h"

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

/* Opens path for reading ("rb") when it is a regular file of at most max_bytes; `what` names it in
 * messages ("a design file", "a heightmap"). */
FILE *fs_open_regular(const char *path, long max_bytes, const char *what, fs_error *err);

/* What a file that is not a regular file is, in words ("a folder", "a FIFO", "a socket", ...), from
 * its st_mode. */
const char *fs_file_kind(mode_t mode);

/* Reads a whole regular file of at most max_bytes into *data (malloc'd, NUL-terminated; *len bytes
 * without the terminator). */
fs_status fs_read_regular(const char *path, long max_bytes, const char *what, char **data, size_t *len,
                          fs_error *err);

#endif
