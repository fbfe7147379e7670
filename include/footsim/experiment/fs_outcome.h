/* fs_outcome.h: how a landing trial is judged, on the physics of its history and never on a clock
 * alone (docs/landing.md states every rule with its reason).
 *
 * A judge is fed one sample of the trial's state after every step (time, the robot's lean, the
 * kinetic energy of every body, the fastest body's speed, the foot's contact count) and decides:
 *   fell      the lean passed fall_lean_rad (at once); or, after touchdown, the foot had no contact
 *             for lost_ground_s (at once); or, at the end, a foot shape lies deeper than the
 *             terrain's sink bound; or the robot came to rest not upright or not supported;
 *   landed    at rest (every body slower than rest_speed for rest_hold_s) upright (lean below
 *             landed_lean_rad) and supported (in contact); or, when the window ends, upright,
 *             supported and its motion dying out: the mean kinetic energy over the window's last
 *             motion_window_s is at most motion_decay times the mean over the motion_window_s
 *             before, or below motion_floor_J (as slow as rest);
 *   undecided the window ended before either (reported as its own count, never folded in).
 * Each decision names the rule that made it. The judge is a pure function of its samples: the
 * unit tests feed it histories built by hand. It allocates nothing. */
#ifndef FS_OUTCOME_H
#define FS_OUTCOME_H

/* FS_HUNG and FS_KILLED are no judge's decisions: a campaign gives FS_HUNG to a trial whose worker
 * the pool's watchdog killed (no answer in its time) and FS_KILLED to one whose worker died any other
 * way than by a numerical failure (its exit status 3): a signal from outside (the OOM killer's
 * SIGKILL), a crash, another exit status. Neither says anything of the physics. */
typedef enum fs_outcome {
    FS_LANDED = 0,
    FS_FELL = 1,
    FS_FAILED_NUMERICS = 2,
    FS_UNDECIDED = 3,
    FS_HUNG = 4,
    FS_KILLED = 5
} fs_outcome;
enum { FS_NOUTCOMES = 6 };

/* Which rule decided a trial (fs_rule_name gives the words). */
typedef enum fs_rule {
    FS_RULE_NONE = 0,       /* not decided yet */
    FS_RULE_LEANED,         /* fell: the lean passed fall_lean_rad */
    FS_RULE_LOST_GROUND,    /* fell: no foot contact for lost_ground_s after touchdown */
    FS_RULE_SANK,           /* fell: at the end a foot shape deeper than the sink bound */
    FS_RULE_RESTED_TILTED,  /* fell: at rest leaning landed_lean_rad or more, or out of contact */
    FS_RULE_AT_REST,        /* landed: at rest, upright, supported */
    FS_RULE_DYING,          /* landed: the window ended upright, supported, motion dying out */
    FS_RULE_WINDOW,         /* undecided: the window ended first */
    FS_RULE_NUMERICS,       /* failed_numerics: the state checks stopped the trial */
    FS_RULE_WATCHDOG,       /* hung: the pool's watchdog killed the trial's worker */
    FS_RULE_KILLED,         /* killed: the trial's worker died, not of a numerical failure */
    FS_NRULES
} fs_rule;

typedef struct fs_outcome_rules {
    double fall_lean_rad, landed_lean_rad;
    double lost_ground_s;          /* > 0 */
    double sink_bound_m;           /* the terrain's: soft ground states its own */
    double rest_speed_m_per_s, rest_hold_s;
    double window_s;               /* the trial's length: the window ends here */
    double motion_window_s;        /* the two spans compared at the end of the window */
    double motion_decay;           /* in (0, 1]: the last span's mean at most this times the one before's */
    double motion_floor_J;         /* kinetic energy counted as rest */
} fs_outcome_rules;

typedef struct fs_outcome_sample {
    double t_s;
    double lean_rad;               /* the robot's lean from upright (0 where it is held) */
    double kinetic_J;              /* of every body */
    double max_speed_m_per_s;      /* of the fastest body (points of it) */
    int contacts;                  /* foot-terrain contact points */
    double weight;                 /* the sample's step over step_s (an error-controlled step's varies);
                                      0 is taken as 1 */
} fs_outcome_sample;

typedef struct fs_judge {
    fs_outcome_rules r;
    int touched;
    double touchdown_s, last_contact_s, rest_since_s;
    double kinetic_sum_J[2];       /* summed over [end - 2w, end - w) and [end - w, end] ... */
    double samples[2];             /* ... over this many samples (their weights) */
    int at_rest;
    int outcome, rule;             /* fs_outcome, fs_rule; outcome is FS_UNDECIDED until decided */
} fs_judge;

void fs_judge_init(fs_judge *j, const fs_outcome_rules *rules);

/* One step's sample. Returns nonzero when the trial is over: it fell (decided) or came to rest
 * (decided by fs_judge_finish, which looks at the end state). */
int fs_judge_step(fs_judge *j, const fs_outcome_sample *s);

/* The end of the trial (stopped by fs_judge_step or at the end of the window): decides what is not
 * decided yet from the last sample and the deepest foot shape's penetration, m. */
void fs_judge_finish(fs_judge *j, const fs_outcome_sample *last, double penetration_m);

/* "landed", "fell", "failed_numerics", "undecided", "hung", "killed". */
const char *fs_outcome_name(int outcome);
/* "leaned past the fall angle", ...: what decided it. */
const char *fs_rule_name(int rule);

#endif
