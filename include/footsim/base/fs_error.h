/* fs_error.h: how footsim reports failure.
 *
 * Every function that can fail takes an fs_error* and returns an fs_status. On failure it fills
 * the message with "where: what is wrong, and what would be right"; "where" is "file:line" for
 * input, or an argument's name. The command prints the message and exits with the status. */
#ifndef FS_ERROR_H
#define FS_ERROR_H

#include <stddef.h>

/* Exit statuses of the footsim command; the library returns the same values. */
typedef enum fs_status {
    FS_OK = 0,
    FS_EXPECTATION_FAILED = 1, /* an experiment ran, but its stated expectations failed */
    FS_BAD_INPUT = 2,          /* refused before anything was simulated or written */
    FS_NUMERICAL = 3,          /* the simulation produced a non-finite or exploding state */
    FS_IO = 4,                 /* a result could not be written */
    FS_NO_MEMORY = 5,          /* the system refused memory footsim needed (nothing was written) */
    FS_INPUTS_DIFFER = 6       /* compare: two results made of other inputs, seeds or overrides */
} fs_status;

enum { FS_ERROR_MAX = 1024 };

typedef struct fs_error {
    fs_status status;
    char message[FS_ERROR_MAX];
} fs_error;

/* Sets err (which may be NULL) to status and a printf-style message; returns status. */
fs_status fs_fail(fs_error *err, fs_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Warnings: what the library accepts but doubts (a heightmap that covers only part of the region
 * the foot can reach, a message from ODE). The library never prints one: it counts it (per thread,
 * fs_warning_count) and hands its text to the handler the program installed, if any. The footsim
 * command's handler prints "footsim: warning: TEXT" on stderr; a program that installs none sees
 * only the count. Install the handler before the first call that may warn (it is process-wide). */
typedef void (*fs_warning_fn)(const char *text, void *user);
void fs_warning_handler(fs_warning_fn fn, void *user);
void fs_warn(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
long fs_warning_count(void);

/* ODE's errors, which reach the caller as FS_NUMERICAL from the call that stepped or built the
 * simulation, are the sim layer's: footsim/sim/fs_ode.h. */

#endif
