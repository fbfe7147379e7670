/* experiment_outcome.c: the rules that decide a landing trial (fs_outcome.h). */
#include "footsim/experiment/fs_outcome.h"

#include <math.h>
#include <string.h>

const char *fs_outcome_name(int outcome)
{
    static const char *names[FS_NOUTCOMES] = {"landed", "fell", "failed_numerics", "undecided", "hung",
                                                 "killed"};
    return outcome >= 0 && outcome < FS_NOUTCOMES ? names[outcome] : "unknown";
}

const char *fs_rule_name(int rule)
{
    static const char *names[FS_NRULES] = {"none",    "leaned",    "lost_ground",  "sank",    "rested_tilted",
                                           "at_rest", "dying_out", "window_ended", "numerics", "watchdog",
                                           "worker_died"};
    return rule >= 0 && rule < FS_NRULES ? names[rule] : "unknown";
}

void fs_judge_init(fs_judge *j, const fs_outcome_rules *rules)
{
    memset(j, 0, sizeof *j);
    j->r = *rules;
    j->rest_since_s = -1;
    j->outcome = FS_UNDECIDED;
}

static void decide(fs_judge *j, int outcome, int rule)
{
    j->outcome = outcome;
    j->rule = rule;
}

int fs_judge_step(fs_judge *j, const fs_outcome_sample *s)
{
    if (j->rule != FS_RULE_NONE)
        return 1;
    if (s->lean_rad > j->r.fall_lean_rad) {
        decide(j, FS_FELL, FS_RULE_LEANED);
        return 1;
    }
    if (s->contacts > 0) {
        if (!j->touched)
            j->touched = 1, j->touchdown_s = s->t_s;
        j->last_contact_s = s->t_s;
    } else if (j->touched && s->t_s - j->last_contact_s >= j->r.lost_ground_s) {
        decide(j, FS_FELL, FS_RULE_LOST_GROUND);
        return 1;
    }
    /* the motion over the window's last two spans: their mean kinetic energies */
    double w = j->r.motion_window_s, end = j->r.window_s;
    int span = s->t_s >= end - w ? 1 : s->t_s >= end - 2 * w ? 0 : -1;
    double weight = s->weight > 0 ? s->weight : 1; /* a mean over time */
    if (span >= 0)
        j->kinetic_sum_J[span] += s->kinetic_J * weight, j->samples[span] += weight;
    /* at rest: every body slow for rest_hold_s, after touchdown */
    if (j->touched && s->max_speed_m_per_s < j->r.rest_speed_m_per_s) {
        if (j->rest_since_s < 0)
            j->rest_since_s = s->t_s;
        j->at_rest = s->t_s - j->rest_since_s >= j->r.rest_hold_s;
    } else {
        j->rest_since_s = -1;
    }
    return j->at_rest;
}

/* The mean kinetic energy of the last span at most motion_decay times the span before's, or below
 * the floor. A span with no samples (the window cut short) has none: not dying. */
static int dying(const fs_judge *j)
{
    if (!j->samples[0] || !j->samples[1])
        return 0;
    double before = j->kinetic_sum_J[0] / j->samples[0], last = j->kinetic_sum_J[1] / j->samples[1];
    return last <= j->r.motion_decay * before || last < j->r.motion_floor_J;
}

void fs_judge_finish(fs_judge *j, const fs_outcome_sample *last, double penetration_m)
{
    if (j->rule != FS_RULE_NONE)
        return;
    int upright = last->lean_rad < j->r.landed_lean_rad, supported = last->contacts > 0;
    if (penetration_m > j->r.sink_bound_m)
        decide(j, FS_FELL, FS_RULE_SANK);
    else if (j->at_rest)
        decide(j, upright && supported ? FS_LANDED : FS_FELL, upright && supported ? FS_RULE_AT_REST
                                                                                   : FS_RULE_RESTED_TILTED);
    else if (upright && supported && dying(j))
        decide(j, FS_LANDED, FS_RULE_DYING);
    else
        decide(j, FS_UNDECIDED, FS_RULE_WINDOW);
}
