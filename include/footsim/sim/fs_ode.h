/* fs_ode.h: ODE's process-wide pieces, routed through footsim.
 *
 * ODE's error, debug and message handlers are process-wide and take no user data. fs_ode_init
 * installs footsim's: an ODE error prints "footsim: <context>: ODE error ..." and exits with
 * FS_NUMERICAL instead of aborting (ODE does not let its error handlers return; results are
 * written atomically, so nothing is left half done); a message is a warning on stderr. Call
 * fs_ode_init once before creating any ODE object, fs_ode_close at the end.
 *
 * The context names what footsim is doing, for ODE's complaints ("scenarios/static_load.ini"):
 * the name of the simulation being stepped, the one piece of state footsim keeps outside a
 * simulation, as a pointer per thread to text the caller owns (an fs_sim sets it to its own name
 * before each ODE call and leaves it when destroyed). fs_ode_context_leave(context) forgets
 * context if it is the current one. */
#ifndef FS_ODE_H
#define FS_ODE_H

void fs_ode_init(void);
void fs_ode_close(void);

void fs_ode_context(const char *context);
void fs_ode_context_leave(const char *context);

/* Whether the ODE footsim is linked with computes in double precision (its build configuration),
 * for the record of the machine a benchmark ran on. */
int fs_ode_double_precision(void);

/* Calls ODE's debug handler with message, as an internal error of ODE's would: the handler
 * installed by fs_ode_init exits with FS_NUMERICAL. Never returns; for tests of that path. */
void fs_ode_fail(const char *message);

#endif
