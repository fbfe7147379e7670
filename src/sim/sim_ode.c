/* sim_ode.c: ODE's process-wide handlers and the context their complaints name (fs_ode.h). */
#include "footsim/sim/fs_ode.h"

#include "footsim/base/fs_error.h"

#include <ode/ode.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

/* The text of the simulation stepping now on this thread (its owner keeps it alive), or NULL. */
static _Thread_local const char *ode_context_now;

void fs_ode_context(const char *context) { ode_context_now = context; }

void fs_ode_context_leave(const char *context)
{
    if (ode_context_now == context)
        ode_context_now = NULL;
}

static const char *ode_context(void) { return ode_context_now ? ode_context_now : "ODE"; }

/* ODE calls exit() or abort() after its error and debug handlers return, so these never return. */
static void ode_fatal(const char *kind, int errnum, const char *msg, va_list ap)
{
    fprintf(stderr, "footsim: %s: ODE %s %d: ", ode_context(), kind, errnum);
    vfprintf(stderr, msg, ap);
    fprintf(stderr, "\n  the simulation is numerically broken; try a smaller step_s or the implicit springs\n");
    exit(FS_NUMERICAL);
}

static void ode_error_handler(int errnum, const char *msg, va_list ap) { ode_fatal("error", errnum, msg, ap); }

static void ode_debug_handler(int errnum, const char *msg, va_list ap) { ode_fatal("internal check", errnum, msg, ap); }

static void ode_message_handler(int errnum, const char *msg, va_list ap)
{
    /* Messages are warnings: keep them on stderr, tagged with what footsim was doing. */
    fprintf(stderr, "footsim: %s: ODE message %d: ", ode_context(), errnum);
    vfprintf(stderr, msg, ap);
    fputc('\n', stderr);
}

void fs_ode_init(void)
{
    dSetErrorHandler(ode_error_handler);
    dSetDebugHandler(ode_debug_handler);
    dSetMessageHandler(ode_message_handler);
    dInitODE2(0);
}

void fs_ode_close(void) { dCloseODE(); }

int fs_ode_double_precision(void) { return strstr(dGetConfiguration(), "ODE_double_precision") != NULL; }

void fs_ode_fail(const char *message) { dDebug(1, "%s", message); }
