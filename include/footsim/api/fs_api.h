/* fs_api.h: footsim for any program (a Python session through ctypes, a GUI, another language):
 * opaque handles on the heap, plain scalars, and arrays the caller owns.
 *
 * Contract:
 * - A caller never needs the size or the layout of a footsim struct but fs_error (a status and
 *   FS_ERROR_MAX characters, fs_error.h): a scenario, a simulation and a trial's result are
 *   pointers made by an *_open call and released by its *_close. This header includes neither
 *   ODE's header nor any header that does, so that these calls stay as they are when the structs
 *   behind the pointers change (issue 31, the model apart from its data).
 * - Every call that can fail takes an fs_error (may be NULL) and returns an fs_status, or NULL for
 *   an *_open: the message is footsim's own, "file:line: what is wrong, and what would be right"
 *   for input. Bad input is refused before anything is simulated.
 * - Reading is by functions into the caller's arrays (n rows of 3 doubles for positions, 9 for
 *   rotations, row-major); stepping allocates nothing, and no accessor copies the simulation.
 * - Call fs_ode_init (footsim/sim/fs_ode.h, included here) once before the first simulation or
 *   trial. ODE's errors come back as FS_NUMERICAL (the simulation is then dead: only
 *   fs_sim_close may follow); warnings go to the handler of fs_warning_handler (fs_error.h).
 * - Handles are not shared between threads: one thread steps one simulation at a time.
 *
 * - A campaign runs its trials in forked worker processes that run only C code and leave with
 *   _exit (sound after a fork from Python); its progress callback runs in the caller's process. */
#ifndef FS_API_H
#define FS_API_H

#include "footsim/base/fs_error.h"
#include "footsim/sim/fs_ode.h"

typedef struct fs_scenario fs_scenario;
typedef struct fs_sim fs_sim;
typedef struct fs_trial_result fs_trial_result;

/* ---- scenarios ------------------------------------------------------------------------------ */

/* Loads a scenario file with overrides ("section.key=value", as the command's --set) into a new
 * handle, or NULL with err set (FS_BAD_INPUT with file:line, FS_NO_MEMORY). A design, terrain or
 * robot key reaches its file through the scenario (fs_scenario.h). */
fs_scenario *fs_scenario_open(const char *path, const char *const *overrides, int noverrides, fs_error *err);
/* A design file (a foot) alone, in a scenario with every other key at its default (the command's
 * `footsim stiffness DESIGN`), for the stiffness model and the law; overrides as above. */
fs_scenario *fs_scenario_open_design(const char *path, const char *const *overrides, int noverrides, fs_error *err);
void fs_scenario_close(fs_scenario *sc);

/* The file's base name without .ini ("landing_trial"); the handle owns it. */
const char *fs_scenario_title(const fs_scenario *sc);
/* 1 for a landing trial ([robot] or [landing]), 0 otherwise. */
int fs_scenario_trial(const fs_scenario *sc);
/* The value of a number or integer key "section.key" of the scenario, its design, terrain or
 * robot, as loaded (FS_BAD_INPUT naming the key when no schema has it as a number). */
fs_status fs_scenario_get(const fs_scenario *sc, const char *key, double *value, fs_error *err);

/* ---- simulations ---------------------------------------------------------------------------- */

/* Builds a simulation of sc at its start pose (a trial scenario as its file places the foot: no
 * seed drawn). The simulation keeps its own copy of sc: closing sc first is harmless. */
fs_sim *fs_sim_open(const fs_scenario *sc, fs_error *err);
void fs_sim_close(fs_sim *sim);

/* Takes nsteps steps of the scenario's run.step_s (fs_sim_step for each; torques added with
 * fs_sim_apply_torque act in the first only). Stops at the first failure: FS_NUMERICAL with the
 * body or hinge and the time named, or ODE's message (the sim is then dead). */
fs_status fs_sim_advance(fs_sim *sim, long nsteps, fs_error *err);
/* Simulated time, s; the step, s; 1 once an ODE error killed the simulation. */
double fs_sim_time(const fs_sim *sim);
double fs_sim_step_size(const fs_sim *sim);
int fs_sim_dead(const fs_sim *sim);
/* The warnings (fs_warning_handler's) given while this simulation was built and stepped. */
long fs_sim_warnings(const fs_sim *sim);

/* Bodies: the foot's, then the robot's when it has a body of its own or is merged into the ankle
 * body (named "robot"; its pose is then the ankle body's). Names are the design's ("heel",
 * "talus", "metatarsal1", ...); fs_sim_body_index gives -1 for a name it lacks. */
int fs_sim_body_count(const fs_sim *sim);
const char *fs_sim_body_name(const fs_sim *sim, int i);
int fs_sim_body_index(const fs_sim *sim, const char *name);
/* Every body's mass, kg (mass_kg: count); the robot's is its mass_kg, also when merged. */
void fs_sim_body_masses(const fs_sim *sim, double *mass_kg);
/* Every body's centre of mass, m (pos: count x 3), and rotation (R: count x 9, row-major, world =
 * R body), world frame; either may be NULL. */
void fs_sim_poses(const fs_sim *sim, double *pos, double *R);
/* Every body's linear velocity, m/s (v: count x 3), and angular velocity, rad/s (w: count x 3);
 * either may be NULL. */
void fs_sim_velocities(const fs_sim *sim, double *v, double *w);
/* Adds torque_N_m (world frame) to body i for the coming step only (each of its substeps too).
 * FS_BAD_INPUT for a body that is not there or a torque that is not finite. */
fs_status fs_sim_apply_torque(fs_sim *sim, int i, const double torque_N_m[3], fs_error *err);

/* The load's point (the ankle), world frame, m. */
void fs_sim_ankle_position(const fs_sim *sim, double p[3]);
/* The ground's contacts in the last step: how many, and the first max of them, each a point, m
 * (pos: max x 3), and the ground's force on the foot there, N (force: max x 3); either may be
 * NULL. Returns how many it wrote. */
int fs_sim_contact_count(const fs_sim *sim);
int fs_sim_contacts(const fs_sim *sim, double *pos, double *force, int max);
/* The foot's spring-dampers, named as the design names them; their force now (tension positive),
 * N, and length, m, into arrays of count (either may be NULL). */
int fs_sim_spring_count(const fs_sim *sim);
const char *fs_sim_spring_name(const fs_sim *sim, int i);
void fs_sim_spring_forces(const fs_sim *sim, double *force_N, double *length_m);
/* Energy now: kinetic, gravitational (relative to z = 0) and in the springs, J (each may be NULL);
 * returns their sum. */
double fs_sim_energies(const fs_sim *sim, double *kinetic_J, double *potential_J, double *elastic_J);
/* The worst of the state checks so far (fs_check.h): the fastest point, m/s, the widest open
 * loop, m, and the energy beyond its bound's reference, J (each may be NULL). */
void fs_sim_check_worst(const fs_sim *sim, double *max_speed_m_per_s, double *max_loop_error_m,
                        double *max_energy_excess_J);

/* ---- landing trials ------------------------------------------------------------------------- */

/* Runs seed's landing trial of sc (a trial scenario: FS_BAD_INPUT otherwise) and returns its
 * result, or NULL with err set. A numerical failure is an outcome ("failed_numerics"), not an
 * error. sc is left as it was (each trial places a copy). */
fs_trial_result *fs_trial_open(const fs_scenario *sc, int seed, fs_error *err);
void fs_trial_close(fs_trial_result *r);
/* "landed", "fell", "failed_numerics", "undecided"; the rule that decided it (fs_outcome.h); the
 * failure's message for failed_numerics, else "". The handle owns the text. */
const char *fs_trial_outcome(const fs_trial_result *r);
const char *fs_trial_rule(const fs_trial_result *r);
const char *fs_trial_failure(const fs_trial_result *r);
int fs_trial_seed(const fs_trial_result *r);
/* The metrics campaigns summarise, named with their units ("peak_force_N", ...): their count,
 * the name of metric m, and its value in r (NAN where the trial lacks it: the drop at rest of a
 * trial that did not land). fs_trial_metric_find gives -1 for a name it lacks. */
int fs_trial_metric_count(void);
const char *fs_trial_metric_name(int m);
int fs_trial_metric_find(const char *name);
double fs_trial_metric(const fs_trial_result *r, int m);

/* ---- the stiffness model and the pitch-stiffness law (fs_analysis.h) ------------------------ */

/* Chain c's (0-4) joint-space stiffness over (midfoot, MTP) at the neutral pose, N m/rad, from
 * the exact geometry (exact, 2 x 2 row-major) and with the paper's eq. 4 lever arms (eq4); either
 * may be NULL. FS_BAD_INPUT for a flat foot or a chain out of range. */
fs_status fs_scenario_chain_stiffness(const fs_scenario *sc, int chain, double exact[4], double eq4[4], fs_error *err);
/* The foot's pitch stiffness under load_N at the ankle, N m/rad (fs_pitch_stiffness_foot). */
fs_status fs_scenario_pitch_stiffness(const fs_scenario *sc, double load_N, double *K_N_m_per_rad, fs_error *err);
/* The pitch-stiffness law for the scenario's robot on a foot of pitch stiffness K_foot (NAN: the
 * scenario's foot under the robot's weight, 0 when its arch folds, as a campaign's law), with the
 * landing's upright bound: K in series with the robot's joint, the demand m g h, the highest
 * centre of mass that stands, the lean at rest, N m/rad, N m/rad, m, rad, and whether it stands
 * (each may be NULL). FS_BAD_INPUT for a scenario without a robot. */
fs_status fs_scenario_pitch_law(const fs_scenario *sc, double K_foot, double *K, double *demand,
                                double *critical_height_m, double *lean_rad, int *stands, fs_error *err);

/* ---- campaigns (fs_campaign_run.h) --------------------------------------------------------- */

/* Loads a campaign file with overrides (as the command's --set: a campaign section's key goes to
 * the campaign file, any other to every trial), every trial scenario loaded and checked: NULL with
 * err set when anything is wrong, before anything runs. */
typedef struct fs_campaign_handle fs_campaign_handle;
fs_campaign_handle *fs_campaign_open(const char *path, const char *const *overrides, int noverrides, fs_error *err);
void fs_campaign_close(fs_campaign_handle *h);
/* The file's base name without .ini; its trials (feet x terrains x robots x seeds) and cells. */
const char *fs_campaign_title(const fs_campaign_handle *h);
int fs_campaign_trial_count(const fs_campaign_handle *h);
int fs_campaign_cell_count(const fs_campaign_handle *h);

/* Told the trials done (a resumed journal's included), the total and the failures after every
 * trial and at least every 0.2 s, and each line worth saying in `say` (else NULL); its 0 stops the
 * campaign cleanly and resumably. */
typedef int (*fs_campaign_progress_cb)(int done, int total, int failed, const char *say, void *user);
enum { FS_CAMPAIGN_FRESH = 1, FS_CAMPAIGN_REPLACE = 2 };        /* flags */
enum { FS_CAMPAIGN_FAILED = -1, FS_CAMPAIGN_DONE = 0, FS_CAMPAIGN_STOPPED = 1, FS_CAMPAIGN_ALREADY = 2 }; /* *how */
/* Runs the campaign into the results folder dir as `footsim campaign FILE --out DIR -j jobs` does
 * (the same files, byte for byte; no success.png: that is gnuplot's, run by the command): jobs
 * worker processes (<= 0: the CPUs it may use), shard/nshards (0/0: the whole campaign; else
 * DIR/trials.journal), flags FS_CAMPAIGN_FRESH (start over) and FS_CAMPAIGN_REPLACE (replace a
 * folder footsim did not make); resumed from DIR.journal/ when a run stopped. *how: DONE, STOPPED
 * (the callback's 0: the finished trials kept in DIR.journal/; the same call goes on), ALREADY
 * (DIR holds these results: nothing ran). */
fs_status fs_campaign_execute(fs_campaign_handle *h, const char *dir, int jobs, int shard, int nshards, int flags,
                              fs_campaign_progress_cb progress, void *user, int *how, fs_error *err);

#endif
