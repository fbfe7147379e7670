/* fs_path.h: names taken from paths. fs_path_stem writes a path's last component without its
 * extension ("scenarios/static_load.ini" -> "static_load"; a leading dot is kept: ".ini" ->
 * ".ini"), cut to size - 1 characters. */
#ifndef FS_PATH_H
#define FS_PATH_H

#include <stddef.h>

void fs_path_stem(const char *path, char *out, size_t size);

#endif
