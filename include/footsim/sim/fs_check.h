/* fs_check.h: the state checked after every step, and the classification of a run's numerics.
 *
 * fs_sim_step ends with fs_check_step. It checks, in this order:
 * 1. finite: every position, velocity and angular velocity of every body (foot and robot);
 * 2. speed: the fastest point of each body (COM speed plus angular speed times its reach, as
 *    fs_sim_max_speed) stays below [check] max_speed_m_per_s;
 * 3. loop closure: for each hinge, the distance between its anchor as body 1 carries it and as
 *    body 2 carries it (dJointGetHingeAnchor against dJointGetHingeAnchor2) stays below
 *    [check] max_loop_error_m;
 * 4. energy, every [check] energy_every steps: the foot's and robot's energy E (fs_sim_energy:
 *    kinetic, gravitational, springs) may not exceed what it started with plus the work put in:
 *        E(t) - E(t1) - W(t) <= energy_margin_J + energy_margin_rel * W_abs(t)
 *    where t1 is the end of the first step (the reference is taken there), W the work done on the
 *    foot since then by the load at the ankle (its force over each step times the ankle's
 *    displacement) and by any driver that reports it (fs_check_set_work: the walking machine's
 *    carriage), and W_abs the sum of the magnitudes of those increments. Gravity is inside E.
 *    The physics: everything else footsim models takes energy out (dampers, friction, contact
 *    damping) or stores it where E does not count it (the ground's contact springs, which start
 *    unloaded), so exactly integrated, the left side is never above 0. The margin covers what
 *    the integrator itself adds: the explicit springs' energy wobble (about h omega / 2 of the
 *    oscillating energy) and ODE's position correction of joints and contacts (ERP).
 *
 * Classes: stable (every check passes); drifting (finite and below the speed bound, but a loop
 * has opened beyond its bound or the energy has grown beyond its bound: the numbers are no longer
 * the model's); blown up (a non-finite state, or a speed beyond any the scenario can produce).
 * By default any failure stops the step with FS_NUMERICAL and a message naming the body or
 * hinge, the time, the value against its bound and what to try. With record_drift set (the
 * stability benchmark), a drift is only recorded (first_drift_*) and the run goes on until it
 * blows up. Nothing here allocates; the checks cost a few per cent of a step (see docs/bench.md). */
#ifndef FS_CHECK_H
#define FS_CHECK_H

#include "footsim/base/fs_error.h"

struct fs_sim;

typedef enum fs_check_class { FS_CHECK_STABLE = 0, FS_CHECK_DRIFTING = 1, FS_CHECK_BLOWN_UP = 2 } fs_check_class;

/* Which check failed. */
typedef enum fs_check_kind {
    FS_CHECK_OK = 0,
    FS_CHECK_NONFINITE,
    FS_CHECK_SPEED,
    FS_CHECK_LOOP,
    FS_CHECK_ENERGY
} fs_check_kind;

typedef struct fs_check {
    int record_drift;          /* fs_sim_options.record_drift: 0 stop at any failure, 1 only when blown up */
    int started;               /* the reference has been taken (after the first step) */
    long steps;                /* steps checked */
    double energy_ref_J;       /* E(t1) */
    double work_J, work_abs_J; /* W and W_abs since t1 */
    double ankle_prev[3];      /* the ankle at the start of the coming step */
    double load_next[3];       /* the load's force during the coming step, N */
    double (*work_fn)(void *user, const struct fs_sim *sim); /* a driver's work (fs_check_set_work) */
    void *work_user;
    /* the worst seen, for reports and the benchmark */
    double max_speed_m_per_s, max_loop_error_m, max_energy_excess_J, energy_bound_J;
    /* the first drift (record_drift) and the failure that stopped the run */
    fs_check_kind first_drift;
    double first_drift_time_s;
    char drift_where[48];      /* the hinge or body of the first drift */
    fs_check_kind failure;
    double failure_time_s;
    char failure_where[48];    /* the body or hinge */
} fs_check;

/* Checks sim's state after a step (fs_sim_step calls it). FS_OK, or FS_NUMERICAL with err saying
 * which body or hinge, when, the value against its bound, and what to try. */
fs_status fs_check_step(struct fs_sim *sim, fs_error *err);

/* Something outside the foot that does work on it (a driven carriage): fn(user, sim) returns its
 * work over the step just taken, J. fs_check_step calls it after the ODE step and before the
 * energy check, so that W(t) includes the step being checked; the first step's work comes before
 * the reference E(t1) and is not counted. */
typedef double (*fs_check_work_fn)(void *user, const struct fs_sim *sim);
void fs_check_set_work(struct fs_sim *sim, fs_check_work_fn fn, void *user);

/* The class of a check kind: stable, drifting or blown up. */
fs_check_class fs_check_class_of(fs_check_kind kind);
const char *fs_check_class_name(fs_check_class c);
const char *fs_check_kind_name(fs_check_kind k);

/* The largest step at which the explicit springs are stable, s, each body taken as a mass m on
 * springs to fixed points: symplectic Euler on m x'' = -k x - c x' is stable while
 * k h^2 + 2 c h < 4 m, i.e. h < (sqrt(c^2 + 4 k m) - c) / k (2 m / c without springs, 2 sqrt(m/k)
 * without dampers), with k and c the sums over the springs on the body; the smallest over the
 * bodies. The default foot: the phalanx (8 g, d2 and d3: c = 400 N s/m) gives 4.0e-5 s. */
double fs_check_explicit_step_limit(const struct fs_sim *sim);

#endif
