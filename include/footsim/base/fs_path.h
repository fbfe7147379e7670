/* fs_path.h: names taken from paths. fs_path_stem writes a path's last component without its
 * extension ("scenarios/static_load.ini" -> "static_load"; a leading dot is kept: ".ini" ->
 * ".ini"), cut to size - 1 characters. fs_path_relative writes absolute path `to` relative to
 * absolute folder `from` ("/a/b/c.ini" from "/a/d" -> "../b/c.ini"), for results that record their
 * inputs without the machine's folders. */
#ifndef FS_PATH_H
#define FS_PATH_H

#include <stddef.h>

void fs_path_stem(const char *path, char *out, size_t size);
void fs_path_relative(const char *to, const char *from, char *out, size_t size);

#endif
