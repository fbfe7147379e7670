/* fs_carriage.h: a kinematic carriage that carries a simulation's robot body (the walking
 * machine's actuator).
 *
 * fs_carriage_attach puts a kinematic body height_m above the robot body, joined to it by a
 * vertical slider and a suspension spring-damper (k, c, rest length height_m) of the scenario's
 * spring implementation, and tells the sim's checks its work (fs_check_set_work): the slider's
 * force and torque and the suspension's force times the robot's displacement and turn over each
 * step, or each substep (explicit springs: the suspension's force from the state before it, as
 * applied; implicit: after, as backward Euler applies it). Where it goes is a path, a function of
 * the time into the step being taken (fs_carriage_set_path). Before each step, fs_carriage_drive:
 * with fixed steps it sets the carriage's velocity so that it reaches start + path(step_s) at the
 * step's end (its substeps move it alike); under a tolerance (run.tolerance_m) the sim sets it at
 * each ODE step it tries to reach the path at that ODE step's own end, and saves and puts back the
 * carriage's position with the rest of the state when it rejects a step (sim_adapt.c), so that
 * the path must depend on nothing a rejected step changes. fs_sim_step prepares the suspension with
 * the sim's own springs (fs_sim.suspension), and its damper's c / k bounds the error-controlled
 * step as the foot's dampers do. The carriage lives in the
 * sim's world and goes with fs_sim_free; the carriage's memory (ODE writes the slider's feedback
 * into it) must stay until then. Only fs_carriage_new allocates. */
#ifndef FS_CARRIAGE_H
#define FS_CARRIAGE_H

#include "footsim/sim/fs_sim.h"

/* Opaque: its ODE body and joint are the sim layer's (sim_carriage.c). */
typedef struct fs_carriage fs_carriage;

/* Attaches a new carriage (*out) above sim's robot body (the sim must have one); FS_NO_MEMORY when
 * there is no memory for it. It lives in the sim's world: free it (fs_carriage_free) only after the
 * sim (fs_sim_free), which steps it until then. */
fs_status fs_carriage_new(fs_sim *sim, double height_m, double k_N_per_m, double c_Ns_per_m, fs_carriage **out,
                          fs_error *err);
void fs_carriage_free(fs_carriage *c);

/* Where the carriage is to be elapsed_s into the step being taken, relative to where it started:
 * forward dx_m and up dz_m. Called with elapsed_s = step_s once a step with fixed steps, and with
 * each ODE step's end under a tolerance (tries that are rejected among them). */
typedef void (*fs_carriage_path_fn)(void *user, double elapsed_s, double *dx_m, double *dz_m);
void fs_carriage_set_path(fs_carriage *c, fs_carriage_path_fn fn, void *user);

/* Before a step (fs_drive_spec.before_step): the step starts now; the carriage follows its path
 * over it. */
void fs_carriage_drive(fs_carriage *c);

#endif
