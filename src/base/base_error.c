/* base_error.c: error messages (fs_fail) and warnings handed to the program (fs_warn). ODE's
 * handlers are the sim layer's (fs_ode.h). */
#include "footsim/base/fs_error.h"

#include <stdarg.h>
#include <stdio.h>

fs_status fs_fail(fs_error *err, fs_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
        err->status = status;
    }
    return status;
}

static fs_warning_fn warning_fn;
static void *warning_user;
static _Thread_local long warnings;

void fs_warning_handler(fs_warning_fn fn, void *user)
{
    warning_fn = fn;
    warning_user = user;
}

void fs_warn(const char *fmt, ...)
{
    warnings++;
    if (!warning_fn)
        return;
    char text[FS_ERROR_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    warning_fn(text, warning_user);
}

long fs_warning_count(void) { return warnings; }
