/* fs_path.h: names taken from paths, and paths checked before footsim uses them.
 *
 * fs_path_stem writes a path's last component without its extension ("scenarios/static_load.ini"
 * -> "static_load"; a leading dot is kept: ".ini" -> ".ini"), cut to size - 1 characters.
 * fs_path_relative writes absolute path `to` relative to absolute folder `from` ("/a/b/c.ini" from
 * "/a/d" -> "../b/c.ini"), for results that record their inputs without the machine's folders.
 *
 * A path footsim builds or is given is never cut short: fs_path_format is the one way footsim puts
 * a path into a buffer (a checked snprintf), and fs_path_fits refuses a path footsim could not use
 * whole, with the room it needs beside it. Both refuse with FS_BAD_INPUT, naming `what` (an option
 * such as "--out", or what the path is) and the limit, before anything is simulated or written. */
#ifndef FS_PATH_H
#define FS_PATH_H

#include "footsim/base/fs_error.h"

#include <stddef.h>

/* The room a results folder's path leaves within PATH_MAX (4096 on Linux) for what footsim puts
 * beside and in it (".partial.<pid>", ".journal/journal.tmp.<pid>", "frames/NNNNNN.png.tmp.<pid>",
 * a --frames-of trial's folder), and the room its last component leaves within NAME_MAX (255) for
 * ".partial.<pid>", ".old.<pid>", ".journal" and the lock ".NAME.footsim-lock" beside it. A file
 * footsim writes whole needs FS_FILE_ROOM for its ".tmp.<pid>" beside it. */
enum { FS_DIR_ROOM = 512, FS_NAME_ROOM = 32, FS_FILE_ROOM = 32 };

void fs_path_stem(const char *path, char *out, size_t size);
void fs_path_relative(const char *to, const char *from, char *out, size_t size);

/* Refuses (FS_BAD_INPUT) an empty path, one longer than PATH_MAX - 1 - room characters, one with a
 * component longer than NAME_MAX, or whose last component is longer than NAME_MAX - name_room. */
fs_status fs_path_fits(const char *path, size_t room, size_t name_room, const char *what, fs_error *err);

/* snprintf of a path into out (size bytes); refuses (FS_BAD_INPUT) one that would not fit whole. */
fs_status fs_path_format(char *out, size_t size, const char *what, fs_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

#endif
