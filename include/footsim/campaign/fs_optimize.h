/* fs_optimize.h: a design search: the least stiff (or lightest, or smallest) design that meets a
 * campaign's targets.
 *
 * An optimize file (docs/landing.md, scenarios/optimize_single_tall.ini) names a campaign, whose
 * feet, terrains, robot and seeds are the trials every candidate runs and whose expectations
 * ([expect.NAME] min_success, max_success) are the targets, and the parameters to search:
 *
 *   [optimize]
 *   campaign = search_single_tall.ini   ; the trials and the targets
 *   max_evaluations = 40
 *   [param.k_d1]
 *   key = springs.k_d1_N_per_m          ; any number of a design, robot, scenario or terrain file
 *   min = 12000                         ; the search stays within [min, max]
 *   max = 1.2e6
 *   start = 120000
 *   log = yes                           ; searched in log space (for values spanning decades)
 *
 * One objective: the sum of the parameters, each divided by its min (the least stiff design when
 * they are stiffnesses). The targets enter as a penalty: every expectation's shortfall (how far the
 * success rate lies outside [min_success, max_success]) times a weight large enough that one seed
 * short of a target costs more than the objective's whole range, so no stiffness saved buys a
 * target missed; plus, worth less than one seed, how soon the trials that missed fell
 * (fs_optimize_closeness), so that the search has a slope to follow where no rate changes yet. Noise: every candidate runs the same seeds (common random numbers), so a
 * candidate's success rates are a deterministic, stepwise function of it; NLopt's Subplex
 * (derivative-free, bound-constrained, tolerant of steps) searches it. The best candidate is then
 * rerun on as many fresh seeds, and both sets of rates are reported with their Wilson intervals.
 *
 * A candidate is applied as typed edits of each cell's loaded definitions (fs_scenario_number) and
 * a compile, never by writing text. */
#ifndef FS_OPTIMIZE_H
#define FS_OPTIMIZE_H

#include "footsim/campaign/fs_campaign.h"

enum { FS_OPTIMIZE_MAX_PARAMS = 16 };

typedef struct fs_opt_param {
    char name[FS_NAME_MAX];        /* the section's NAME */
    char key[FS_VALUE_MAX];        /* "section.key" */
    double min, max, start;
    int log;                       /* searched in log space */
} fs_opt_param;

/* What a search minimises ([optimize] objective): the least stiff design (the sum of the parameters,
 * each over its lower bound: for spring stiffnesses, how many times the softest allowed), or the
 * lightest (the foot's total mass, kg, as the candidate's design compiles it). */
typedef enum fs_objective { FS_OBJECTIVE_NONE, FS_OBJECTIVE_LEAST_STIFF, FS_OBJECTIVE_LIGHTEST } fs_objective;

typedef struct fs_optimize {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];
    char campaign_path[FS_PATH_MAX];
    int max_evaluations;
    int validation_first_seed;     /* the fresh seeds the best design is checked on */
    int objective;                 /* fs_objective: what the search minimises, named in the file */
    int nparams;
    fs_opt_param param[FS_OPTIMIZE_MAX_PARAMS];
    fs_campaign campaign;          /* loaded: its cells' scenarios are what a candidate edits */
} fs_optimize;

/* Reads and checks path (file:line messages, FS_BAD_INPUT) and loads its campaign with sets (as
 * footsim campaign takes them); every parameter's key, range and start are checked against every
 * cell's scenario before anything runs. fs_optimize_free releases it. */
fs_status fs_optimize_load(const char *path, const char *const *sets, int nsets, fs_optimize *o, fs_error *err);
void fs_optimize_free(fs_optimize *o);

/* Puts candidate x (nparams values) into every cell's scenario and compiles them. */
fs_status fs_optimize_apply(fs_optimize *o, const double *x, fs_error *err);

/* The objective of x, after fs_optimize_apply(o, x): the sum of x_i / min_i (least_stiff), or the
 * foot's total mass in kg (lightest). */
double fs_optimize_objective(const fs_optimize *o, const double *x);

/* How far the rows miss the campaign's expectations: the sum over expectations of the distance of
 * the success rate outside [min_success, max_success]; 0 when every target is met. */
double fs_optimize_shortfall(const fs_campaign *c, const fs_campaign_row *rows);

/* How close the trials that missed came, a continuous measure for the search where the success
 * rates are flat (every candidate near the start may miss every target alike): for each
 * expectation's cell, the mean over its trials that did not land of 1 - (the time they stayed up /
 * the window): 0 when all landed, near 1 when all fell at once. */
double fs_optimize_closeness(const fs_optimize *o, const fs_trial_result *results);

/* Runs one candidate's trials (every trial of o->campaign, as fs_optimize_apply left it) into
 * results; the caller's (the command runs them in its worker pool). */
typedef fs_status (*fs_optimize_trials)(void *user, const fs_optimize *o, fs_trial_result *results, fs_error *err);

/* Called after every evaluation with its number, candidate, objective, shortfall and rows. */
typedef void (*fs_optimize_report)(void *user, const fs_optimize *o, int evaluation, const double *x, double objective,
                                   double shortfall, const fs_campaign_row *rows);

/* Searches: starts at the parameters' start values, evaluates at most max_evaluations candidates,
 * leaves the best (least penalised objective) in best[nparams] and its penalised value in *value.
 * results holds fs_campaign_ntrials(&o->campaign) trials, rows fs_campaign_ncells rows. */
fs_status fs_optimize_run(fs_optimize *o, fs_optimize_trials trials, fs_optimize_report report, void *user,
                          fs_trial_result *results, fs_campaign_row *rows, double *best, double *value,
                          fs_error *err);

#endif
