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

/* ODE's handlers, which report through this (an ODE error exits with FS_NUMERICAL), are the sim
 * layer's: footsim/sim/fs_ode.h. */

#endif
