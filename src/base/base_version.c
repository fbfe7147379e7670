/* base_version.c: the version footsim was built as (fs_version.h). FS_PROJECT_VERSION comes from
 * CMake's project(); FS_GIT_DESCRIBE from the header cmake/git_describe.cmake writes at build time. */
#include "footsim/base/fs_version.h"

#include "fs_version_git.h"

const char *fs_version(void) { return FS_PROJECT_VERSION " (git " FS_GIT_DESCRIBE ")"; }
