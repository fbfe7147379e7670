/* sim_ode.c: ODE's process-wide handlers, the guard that brings ODE's errors back to the caller,
 * and the context their complaints name (fs_ode.h). */
#include "footsim/sim/fs_ode.h"

#include <ode/ode.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The text of the simulation stepping now on this thread (its owner keeps it alive), or NULL. */
static _Thread_local const char *ode_context_now;

void fs_ode_context(const char *context) { ode_context_now = context; }

void fs_ode_context_leave(const char *context)
{
    if (ode_context_now == context)
        ode_context_now = NULL;
}

static const char *ode_context(void) { return ode_context_now ? ode_context_now : "ODE"; }

/* The innermost fs_ode_guard of this thread, and the message of the ODE error that left it. The
 * message lives outside the guard's frame: a local changed between setjmp and longjmp would be
 * indeterminate after the jump. */
static _Thread_local jmp_buf *guard_now;
static _Thread_local char guard_message[FS_ERROR_MAX];

/* ODE ends the process after its error and debug handlers return (exit or abort, ODE 0.16), so
 * within a guard these leave ODE by longjmp; outside one (a call the library makes unguarded,
 * which should not happen) the text is a warning and ODE ends the process as it would. */
static void ode_fatal(const char *kind, int errnum, const char *msg, va_list ap)
{
    char what[FS_ERROR_MAX / 2];
    vsnprintf(what, sizeof what, msg, ap);
    snprintf(guard_message, sizeof guard_message,
             "%s: ODE %s %d: %s; the simulation is numerically broken: try a smaller step_s or the implicit springs",
             ode_context(), kind, errnum, what);
    if (guard_now)
        longjmp(*guard_now, 1);
    fs_warn("%s (outside a guarded call: ODE ends the process)", guard_message);
}

static void ode_error_handler(int errnum, const char *msg, va_list ap) { ode_fatal("error", errnum, msg, ap); }

static void ode_debug_handler(int errnum, const char *msg, va_list ap) { ode_fatal("internal check", errnum, msg, ap); }

static void ode_message_handler(int errnum, const char *msg, va_list ap)
{
    /* Messages are warnings, tagged with what footsim was doing. */
    char what[FS_ERROR_MAX / 2];
    vsnprintf(what, sizeof what, msg, ap);
    fs_warn("%s: ODE message %d: %s", ode_context(), errnum, what);
}

fs_status fs_ode_guard(fs_status (*fn)(void *arg, fs_error *err), void *arg, int *interrupted, fs_error *err)
{
    jmp_buf here;
    jmp_buf *const outer = guard_now;
    if (setjmp(here)) {
        guard_now = outer;
        if (interrupted)
            *interrupted = 1;
        return fs_fail(err, FS_NUMERICAL, "%s", guard_message);
    }
    guard_now = &here;
    fs_status s = fn(arg, err);
    guard_now = outer;
    return s;
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
