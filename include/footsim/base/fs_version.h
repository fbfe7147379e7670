/* fs_version.h: which footsim this is. fs_version() returns the project version and the git
 * description of the tree it was built from, captured when it was built ('git describe --always
 * --dirty'; "unknown" outside a git checkout): "0.1.0 (git 96b8084-dirty)". Static text; results
 * record it to say what made them. */
#ifndef FS_VERSION_H
#define FS_VERSION_H

const char *fs_version(void);

#endif
