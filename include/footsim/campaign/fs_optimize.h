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
 *   key = springs.k_d1_N_per_m          ; any number of a design, robot, scenario or terrain file,
 *                                       ; or one element of a list, counted from 1: chains.splay_deg[1]
 *   min = 12000                         ; the search stays within [min, max]
 *   max = 1.2e6
 *   start = 120000
 *   log = yes                           ; searched in log space (for values spanning decades)
 *   weight = 1                          ; its term in least_stiff's sum (0: left out, e.g. a splay)
 *
 * One objective: the sum of the parameters, each divided by its min times its weight (the least
 * stiff design when they are stiffnesses), or the foot's mass (lightest, where no weight applies). The targets enter as a penalty: every expectation's shortfall (how far the
 * success rate lies outside [min_success, max_success]) times a weight large enough that one seed
 * short of a target costs more than the objective's whole range, so no stiffness saved buys a
 * target missed; plus, worth less than one seed, how soon the trials of the targets missed fell
 * (fs_optimize_closeness), so that the search has a slope to follow where no rate changes yet. Noise: every candidate runs the same seeds (common random numbers), so a
 * candidate's success rates are a deterministic, stepwise function of it; NLopt's Subplex
 * (derivative-free, bound-constrained, tolerant of steps) searches it. The best candidate is then
 * rerun on as many fresh seeds, and both sets of rates are reported with their Wilson intervals.
 *
 * A candidate is applied as typed edits of each cell's loaded definitions (fs_scenario_number) and
 * a compile, never by writing text.
 *
 * Several targets at once are the campaign's several [expect.NAME] sections (any foot, terrain,
 * robot, each with its own rate). Two more kinds of demand, in the optimize file:
 *
 *   [optimize]
 *   relative_to = flat       ; a foot of the campaign: every cell of every other foot must land at
 *                            ; least as often as this foot in the same terrain x robot on the same
 *                            ; seeds. This foot is not a candidate: no parameter is put into its
 *                            ; cells, and its trials run once, before the search, and are reused.
 *   [constraint.light]
 *   of = foot_mass_kg        ; or ankle_drop_m: the arch's static ankle drop under its design load
 *   max = 0.5                ; the bounds: max, min or both (at least one)
 *
 * A constraint is static (the candidate's compiled design alone): checked after a candidate is put
 * into the cells and before any of its trials run; a candidate that breaks one runs no trial and is
 * penalised above any candidate that runs (more than every target missed entirely).
 *
 * The trade-off between the objective and a constraint: a sweep of one bound, one search per value
 * on the same common seeds (`footsim optimize` writes each search's files in a folder of its own,
 * and front.csv of their bests):
 *
 *   [optimize]
 *   sweep = light.max               ; a constraint's bound: NAME.max or NAME.min
 *   sweep_values = 0.26, 0.28, 0.3  ; its values, distinct, each on the right side of the other bound
 */
#ifndef FS_OPTIMIZE_H
#define FS_OPTIMIZE_H

#include "footsim/campaign/fs_campaign.h"

enum { FS_OPTIMIZE_MAX_PARAMS = 16, FS_OPTIMIZE_MAX_CONSTRAINTS = 8 };

typedef struct fs_opt_param {
    char name[FS_NAME_MAX];        /* the section's NAME */
    char key[FS_VALUE_MAX];        /* "section.key" */
    double min, max, start;
    int log;                       /* searched in log space */
    double weight;                 /* its term in least_stiff's sum: weight x / min (0: left out) */
} fs_opt_param;

/* What a search minimises ([optimize] objective): the least stiff design (the sum of the parameters,
 * each over its lower bound times its weight, 1 unless [param.NAME] weight says otherwise: for spring
 * stiffnesses, how many times the softest allowed; a splay or a length given weight 0 is left out), or the
 * lightest (the foot's total mass, kg, as the candidate's design compiles it). */
typedef enum fs_objective { FS_OBJECTIVE_NONE, FS_OBJECTIVE_LEAST_STIFF, FS_OBJECTIVE_LIGHTEST } fs_objective;

/* What a constraint bounds ([constraint.NAME] of): the foot's total mass, kg, as the candidate's
 * design compiles it; the arch's ankle drop, m: the planar statics (fs_planar_equilibrium) of its
 * middle chain under the design's design_load_kg, heel and toe sliding freely (frictionless: the
 * larger of the two drops `footsim stiffness` prints, 0.30 mm for Table I's foot); a design with
 * no stable equilibrium there (the arch folds) breaks any ankle-drop bound. A lower bound on the
 * drop keeps a foot compliant; an upper one bounds its travel. */
typedef enum fs_quantity { FS_QUANTITY_NONE, FS_QUANTITY_FOOT_MASS_KG, FS_QUANTITY_ANKLE_DROP_M } fs_quantity;

typedef struct fs_opt_constraint {
    char name[FS_NAME_MAX];        /* the section's NAME */
    int of;                        /* fs_quantity */
    double min, max;               /* the bounds, in the quantity's unit (max HUGE_VAL: none) */
} fs_opt_constraint;

typedef struct fs_optimize {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];
    char campaign_path[FS_PATH_MAX];
    int max_evaluations;
    int validation_first_seed;     /* the fresh seeds the best design is checked on */
    int objective;                 /* fs_objective: what the search minimises, named in the file */
    int nparams;
    fs_opt_param param[FS_OPTIMIZE_MAX_PARAMS];
    int reference;                 /* relative_to: the index of the campaign's reference foot; -1 none */
    int nconstraints;
    fs_opt_constraint constraint[FS_OPTIMIZE_MAX_CONSTRAINTS];
    int sweep_constraint;          /* [optimize] sweep: the constraint whose bound is swept; -1 none */
    int sweep_min;                 /* 1: its min is swept; 0: its max */
    fs_series sweep_values;        /* the bound's values: one search each, in the file's order */
    fs_campaign campaign;          /* loaded: its cells' scenarios are what a candidate edits */
    double *file_x;                /* each cell's parameters as its files give them, at every end of a
                                      band: [(cell * nends + end) * nparams + p]
                                      (the foot's own design: Table I's for feet/biomimetic.ini) */
    fs_campaign *view;             /* one foot's cells of campaign, for running them alone */
    /* the candidates whose trials ran (fs_optimize_recall): each one's parameters, seeds, rows and
       closeness, so that a candidate met again runs no trial */
    int nrun, run_capacity;
    double *run_x;                 /* [i * nparams + p] */
    int *run_first_seed, *run_seeds;
    double *run_closeness;
    fs_campaign_row *run_rows;     /* [i * ncells + cell] */
    int repeats;                   /* candidates answered from those, not run again */
} fs_optimize;

/* Reads and checks path (file:line messages, FS_BAD_INPUT) and loads its campaign with sets (as
 * footsim campaign takes them); every parameter's key, range and start are checked against every
 * cell's scenario before anything runs. fs_optimize_free releases it. */
fs_status fs_optimize_load(const char *path, const char *const *sets, int nsets, fs_optimize *o, fs_error *err);
void fs_optimize_free(fs_optimize *o);

/* Prints the keys of a design search file (one [param.NAME] and one [constraint.NAME], NAME as
 * written) as a Markdown table (fs_config_print_keys) to out_file, a FILE *: `footsim keys`,
 * docs/keys.md. */
void fs_optimize_print_keys(void *out_file);

/* Sets the swept bound (o->sweep_constraint's max or min) to o->sweep_values.v[i]. */
void fs_optimize_sweep_to(fs_optimize *o, int i);

/* Puts candidate x (nparams values) into every cell's scenario but the reference foot's, and
 * compiles them. x NULL: each cell's values as its files give them (o->file_x). */
fs_status fs_optimize_apply(fs_optimize *o, const double *x, fs_error *err);

/* The quantity q of the candidate as fs_optimize_apply left it (the first cell that is not the
 * reference foot's); NAN for an ankle drop the statics cannot find (the arch folds). */
double fs_optimize_quantity(const fs_optimize *o, int q);

/* How far the candidate as applied breaks its constraints: the sum over them of (value - max) /
 * max for those above their bound (a bound of 0: value - max), (min - value) / min for those below,
 * 1 for an ankle drop that is NAN; 0 when it is feasible. */
double fs_optimize_violation(const fs_optimize *o);

/* The targets: the campaign's expectations, then (with relative_to) every cell of every other foot. */
int fs_optimize_ntargets(const fs_optimize *o);

/* The objective of x, after fs_optimize_apply(o, x): the sum of x_i / min_i * weight_i over the
 * parameters of weight above 0 (least_stiff), or the foot's total mass in kg (lightest). */
double fs_optimize_objective(const fs_optimize *o, const double *x);

/* How far the rows miss the targets: the sum over expectations of the distance of the success rate
 * outside [min_success, max_success], plus (relative_to) over every other foot's cell how far its
 * rate lies below the reference foot's in the same terrain x robot; 0 when every target is met. */
double fs_optimize_shortfall(const fs_optimize *o, const fs_campaign_row *rows);

/* The cell of the reference foot in the terrain and robot of cell; -1 without relative_to. */
int fs_optimize_reference_cell(const fs_optimize *o, int cell);

/* How close the trials that missed came, a continuous measure for the search where the success
 * rates are flat (every candidate near the start may miss every target alike): for each target
 * that rows (the summary of results) land too rarely, an expectation's cell below its min_success
 * or a cell landing less often than the reference foot's, the mean over its trials that did not
 * land of 1 - (the time they stayed up / the window): 0 when all landed, near 1 when all fell at
 * once. A cell above its max_success counts 0 here (later falls would lead away from it). A target met counts 0 however
 * many of its trials fell, so that among designs meeting every target the least stiff ranks
 * first, not the one whose few falls came latest. */
double fs_optimize_closeness(const fs_optimize *o, const fs_trial_result *results, const fs_campaign_row *rows);

/* Runs every trial of c (a campaign, or one foot's cells of it: o->view) into results, by c's trial
 * index; the caller's (the command runs them in its worker pool). */
typedef fs_status (*fs_optimize_trials)(void *user, const fs_campaign *c, fs_trial_result *results, fs_error *err);

/* Runs the trials of o->campaign through trials, foot by foot (each foot's cells a view of the
 * campaign: a trial depends on its cell's scenario and its seed alone), into results (every trial
 * of the campaign, by its index): the reference foot's only when reference is 1, every other
 * foot's always. */
fs_status fs_optimize_run_trials(fs_optimize *o, fs_optimize_trials trials, void *user, fs_trial_result *results,
                                 int reference, fs_error *err);

/* Called after every evaluation with its number, candidate, objective, shortfall, violation (of
 * the constraints; > 0: infeasible, no trial ran, rows NULL) and rows. */
typedef void (*fs_optimize_report)(void *user, const fs_optimize *o, int evaluation, const double *x, double objective,
                                   double shortfall, double violation, const fs_campaign_row *rows);

/* A candidate's trials depend on its parameters and the campaign's seeds alone (each trial on its
 * cell's scenario and its seed), so a candidate met again need not run again: Subplex revisits
 * points, the search's start and best are evaluated again after it, and a sweep starts every
 * search at the same start. fs_optimize_recall fills rows (fs_campaign_ncells) and *closeness
 * (NULL: not wanted) with those of the candidate x (nparams values, compared bit for bit) on the
 * campaign's current seeds (first_seed and seeds) and returns 1, counting o->repeats; 0 when x has
 * not run on them. fs_optimize_remember keeps what x gave (FS_NO_MEMORY when it cannot grow; the
 * search then stops with it). fs_optimize_free releases them. */
int fs_optimize_recall(fs_optimize *o, const double *x, fs_campaign_row *rows, double *closeness);
fs_status fs_optimize_remember(fs_optimize *o, const double *x, const fs_campaign_row *rows, double closeness,
                               fs_error *err);

/* The Pareto front of n points (a[i], b[i]), both minimised: keep[i] = 1 when no other point is at
 * least as good in both and better in one (of equal points, the first kept); returns how many. */
int fs_optimize_pareto(const double *a, const double *b, int n, int *keep);

/* Searches: starts at the parameters' start values, evaluates at most max_evaluations candidates,
 * leaves the best (least penalised objective) in best[nparams] and its penalised value in *value.
 * With relative_to, first runs the reference foot's trials once (into results, kept there).
 * results holds fs_campaign_ntrials(&o->campaign) trials, rows fs_campaign_ncells rows. */
fs_status fs_optimize_run(fs_optimize *o, fs_optimize_trials trials, fs_optimize_report report, void *user,
                          fs_trial_result *results, fs_campaign_row *rows, double *best, double *value,
                          fs_error *err);

#endif
