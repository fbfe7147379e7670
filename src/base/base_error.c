/* base_error.c: error messages (fs_fail). ODE's handlers are the sim layer's (fs_ode.h). */
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
