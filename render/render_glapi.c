/* render_glapi.c: libOSMesa opened with dlopen when the first renderer is opened. */
#include "render_glapi.h"

#include <dlfcn.h>
#include <stdlib.h>

/* Process-wide on purpose: OSMesa is one shared library, opened once per process with dlopen, and
 * this is the table of its functions every renderer calls through (no renderer's own state). */
render_gl_api fs_render_gl;

/* The runtime library of Debian's libosmesa6 (and the development link, as a second choice). */
static const char *const LIBRARIES[] = {"libOSMesa.so.8", "libOSMesa.so"};

/* The library: FOOTSIM_OSMESA when set, else the first of LIBRARIES that loads. */
static void *open_library(const char **tried)
{
    const char *chosen = getenv("FOOTSIM_OSMESA");
    if (chosen && *chosen) {
        *tried = chosen;
        return dlopen(chosen, RTLD_NOW | RTLD_LOCAL);
    }
    void *lib = NULL;
    for (size_t i = 0; i < sizeof LIBRARIES / sizeof LIBRARIES[0] && !lib; i++) {
        *tried = LIBRARIES[i];
        lib = dlopen(LIBRARIES[i], RTLD_NOW | RTLD_LOCAL);
    }
    return lib;
}

fs_status fs_render_gl_load(fs_error *err)
{
    static int loaded; /* the library is loaded once per process (see fs_render_gl above) */
    if (loaded)
        return FS_OK;
    const char *tried = "";
    void *lib = open_library(&tried);
    if (!lib)
        return fs_fail(err, FS_BAD_INPUT, "OSMesa is not available (%s); install it (apt-get install libosmesa6) "
                       "or run without --frames", dlerror());
    /* POSIX's way to a function pointer from dlsym: store through a void ** */
    const char *missing_name = NULL;
#define RENDER_GL_LOAD(ret, member, params, symbol)                                                  \
    if (!(*(void **)&gl.member = dlsym(lib, symbol)) && !missing_name)                               \
        missing_name = symbol;
    RENDER_GL_FUNCTIONS(RENDER_GL_LOAD)
#undef RENDER_GL_LOAD
    if (missing_name)
        return fs_fail(err, FS_BAD_INPUT, "%s: OSMesa library without %s; install Debian's libosmesa6", tried,
                       missing_name);
    loaded = 1;
    return FS_OK;
}
