/* fs_ode.h: ODE's process-wide pieces, routed through footsim.
 *
 * ODE's error, debug and message handlers are process-wide and take no user data. fs_ode_init
 * installs footsim's, which neither print nor end the process:
 * - An ODE error or internal check inside fs_ode_guard (every step, fs_sim_step, and every build,
 *   fs_sim_build, runs in one) leaves ODE by longjmp: the guarded call returns FS_NUMERICAL with
 *   "<context>: ODE error N: ..." in its fs_error, and the process goes on. The simulation it
 *   interrupted is dead: fs_sim_step refuses it from then on, and it may only be destroyed.
 *   What may leak: nothing footsim allocated (the sim's own memory is freed by fs_sim_destroy,
 *   and the world, its bodies, joints and the step's working memory with dWorldDestroy), but
 *   whatever ODE had allocated on the C heap inside the interrupted call beyond its world's own
 *   arena (ODE 0.16's dWorldStep works in the world's arena, so nothing in practice). ODE was
 *   left mid-call: other sims on the same thread stay usable (each world is separate), but a
 *   program that wants certainty runs each simulation in a worker process, as campaigns do.
 * - An ODE error outside any guard (no library call makes one) is passed on as a warning, then ODE
 *   ends the process as it always does.
 * - A message is a warning (fs_warn, fs_error.h): counted, and handed to the program's handler.
 * Call fs_ode_init once before creating any ODE object, fs_ode_close at the end.
 *
 * The context names what footsim is doing, for ODE's complaints ("scenarios/static_load.ini"):
 * the name of the simulation being stepped, the one piece of state footsim keeps outside a
 * simulation, as a pointer per thread to text the caller owns (an fs_sim sets it to its own name
 * before each ODE call and leaves it when destroyed). fs_ode_context_leave(context) forgets
 * context if it is the current one. */
#ifndef FS_ODE_H
#define FS_ODE_H

#include "footsim/base/fs_error.h"

void fs_ode_init(void);
void fs_ode_close(void);

/* Calls fn(arg, err) and returns its status, or FS_NUMERICAL with ODE's message in err when an ODE
 * error or internal check interrupts it (see above), setting *interrupted (if not NULL) to 1 then
 * and leaving it alone otherwise. Guards nest; each thread has its own. */
fs_status fs_ode_guard(fs_status (*fn)(void *arg, fs_error *err), void *arg, int *interrupted, fs_error *err);

void fs_ode_context(const char *context);
void fs_ode_context_leave(const char *context);

/* Whether the ODE footsim is linked with computes in double precision (its build configuration),
 * for the record of the machine a benchmark ran on. */
int fs_ode_double_precision(void);

/* Calls ODE's debug handler with message, as an internal error of ODE's would: inside
 * fs_ode_guard the guarded call returns FS_NUMERICAL; outside one ODE ends the process. For tests
 * of that path. */
void fs_ode_fail(const char *message);

#endif
