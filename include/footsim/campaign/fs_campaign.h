/* fs_campaign.h: landing campaigns: feet x terrains x seeds of landing trials, their statistics,
 * their result files, the expectations they check and the comparison against a baseline.
 *
 * A campaign file (docs/campaign.md) names a trial scenario, the feet ([foot.NAME] file = ...),
 * the terrains ([terrain.NAME] file = ..., or one terrain swept over values of one of its keys),
 * the seeds, the expectations ([expect.NAME]) and the tolerances of the comparison. Loading binds
 * it with fs_config (file:line messages, FS_BAD_INPUT) and loads the trial scenario once for every
 * (foot, terrain) pair, so a campaign that cannot run is refused before any trial runs.
 *
 * Everything written is a pure function of the campaign and the trial results, ordered by foot,
 * terrain and seed (never by completion), numbers in fixed formats, no timestamps: the files do
 * not depend on how many processes ran the trials. Each file is written whole or not at all, the
 * summary (summary.json) last. */
#ifndef FS_CAMPAIGN_H
#define FS_CAMPAIGN_H

#include "footsim/base/fs_stats.h"
#include "footsim/io/fs_config.h"
#include "footsim/experiment/fs_trial.h"

#include <stdio.h>

enum {
    FS_CAMPAIGN_MAX_FEET = 8,
    FS_CAMPAIGN_MAX_ROBOTS = 8,
    FS_CAMPAIGN_MAX_TERRAINS = 256, /* a sweep's points count: base terrains x values x values */
    FS_CAMPAIGN_MAX_EXPECT = 32,
    FS_CAMPAIGN_MAX_SEEDS = 100000,
    FS_CAMPAIGN_MAX_TRIALS = 1000000, /* feet x terrains x robots x seeds (docs/keys.md) */
    FS_SUMMARY_MAX_BYTES = 64 * 1024 * 1024, /* a summary.json compare reads */
    FS_CAMPAIGN_MAX_SET = 256,
    FS_CAMPAIGN_NMETRICS = 12
};

/* The metrics of a trial (the numeric fields of fs_trial_result but the draw), named with units;
 * summaries give their medians, the comparison their tolerances. */
typedef struct fs_metric {
    const char *name;      /* "peak_force_N" */
    const char *tolerance; /* default "relative, absolute" */
} fs_metric;
extern const fs_metric fs_campaign_metrics[FS_CAMPAIGN_NMETRICS];

/* The value of metric m (an index into fs_campaign_metrics) in r. */
double fs_metric_value(const fs_trial_result *r, int m);

/* An input file of a campaign, for its provenance: its path relative to the campaign file's folder
 * and the hash of its parsed content (fs_config_hash). */
typedef struct fs_campaign_input {
    char path[FS_PATH_MAX];
    unsigned long long hash;
} fs_campaign_input;
enum { FS_CAMPAIGN_MAX_INPUTS = 2 + FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_ROBOTS };

/* One foot, terrain or robot of the campaign. */
typedef struct fs_campaign_item {
    char name[FS_NAME_MAX];  /* the section's NAME, or for a sweep "NAME@value" */
    char path[FS_PATH_MAX];  /* absolute; for the one robot of a campaign without [robot.NAME], "": the trial's */
    char set[2][FS_VALUE_MAX]; /* a sweep's overrides "section.key=value" (first and second key), or "" */
    double sweep_value[2];   /* the swept values (0 without a sweep) */
    int base;                /* a sweep's point: the index of the terrain it is a point of ... */
    int point[2];            /* ... and of its value of each key */
} fs_campaign_item;

/* [expect.NAME]: the success rate of foot on terrain under robot must lie in [min_success, max_success]. */
typedef struct fs_expectation {
    char name[FS_NAME_MAX];
    int foot, terrain, robot; /* indices into the campaign's feet, terrains and robots */
    double min_success, max_success;
} fs_expectation;

typedef struct fs_campaign {
    char path[FS_PATH_MAX];
    char name[FS_NAME_MAX];            /* the file's base name without .ini */
    char trial_path[FS_PATH_MAX];      /* the trial scenario, as the file resolves it */
    int seeds, first_seed;             /* seeds first_seed, first_seed + 1, ... */
    char sweep[2][2 * FS_NAME_MAX];    /* the "section.key" swept ([campaign] sweep, sweep2), or "" */
    int sweep_choice[2];               /* as bound: 0 none, n the n-th sweepable key (fs_campaign_sweepable) */
    int nsweep;                        /* 0, 1 or 2 keys swept */
    int nbase, nvalues[2];             /* a sweep's terrains before it, and its values of each key; the
                                          terrains become nbase x nvalues[0] x nvalues[1] points,
                                          named "NAME@v1" or "NAME@v1,v2" */
    int nfeet, nterrains, nrobots, nexpect;
    fs_campaign_item foot[FS_CAMPAIGN_MAX_FEET];
    fs_campaign_item terrain[FS_CAMPAIGN_MAX_TERRAINS];
    fs_campaign_item robot[FS_CAMPAIGN_MAX_ROBOTS]; /* [robot.NAME] file = ...; without any, the trial
                                                       scenario's own robot, named after its file */
    fs_expectation expect[FS_CAMPAIGN_MAX_EXPECT];
    double tolerance[FS_CAMPAIGN_NMETRICS][2]; /* relative, absolute (metric's unit) */
    const char *set[FS_CAMPAIGN_MAX_SET];      /* the command's --set meant for the trials */
    int nset;
    /* provenance (written into every result file): every --set as given, and the input files */
    const char *given[FS_CAMPAIGN_MAX_SET];
    int ngiven;
    fs_campaign_input input[FS_CAMPAIGN_MAX_INPUTS];
    int ninputs;
    fs_scenario *pair;                 /* the trial scenario of each cell, loaded once:
                                          fs_campaign_pair; fs_campaign_free releases them */
} fs_campaign;

/* Reads and checks path. Each of sets ("section.key=value") goes to the campaign file when its
 * section is one of the campaign's (campaign, tolerance, foot.*, terrain.*, expect.*), otherwise
 * to every trial (c keeps the pointers). Then loads the trial scenario for every (foot, terrain)
 * with its overrides, once, and keeps it for the trials (fs_trial_run_scenario places a copy per
 * seed): anything wrong is FS_BAD_INPUT, nothing run. fs_campaign_free releases what it holds. */
fs_status fs_campaign_load(const char *path, const char *const *sets, int nsets, fs_campaign *c, fs_error *err);
void fs_campaign_free(fs_campaign *c);

/* The n-th key (1-based) a sweep may vary: every number of a terrain, design, robot or scenario
 * file, in that order; NULL past the last. */
const fs_key *fs_campaign_sweepable(int n);

/* A cell is a (foot, terrain, robot), numbered foot-major: cell = (foot * nterrains + terrain) *
 * nrobots + robot. */
int fs_campaign_ncells(const fs_campaign *c);
void fs_campaign_cell_of(const fs_campaign *c, int cell, int *foot, int *terrain, int *robot);

/* The loaded trial scenario of a cell. */
const fs_scenario *fs_campaign_pair(const fs_campaign *c, int cell);

/* The overrides of a cell's trials: scenario.design, scenario.terrain, robot.design (when the
 * campaign names robots), the sweep's, then c->set. buf holds their text; out gets up to
 * FS_CAMPAIGN_MAX_SET + 5 pointers; returns the count. */
int fs_campaign_overrides(const fs_campaign *c, int cell, char buf[5][FS_PATH_MAX + 32], const char **out);

/* Trials are numbered cell-major: index = cell * seeds + seed - first_seed. */
int fs_campaign_ntrials(const fs_campaign *c);
void fs_campaign_trial_of(const fs_campaign *c, int index, int *cell, int *seed);

/* The 95 % Wilson score interval of k successes in n > 0 trials. */
void fs_wilson(int k, int n, double *low, double *high);


/* One row of the summary: a cell (foot on terrain under robot) over all seeds. */
typedef struct fs_campaign_row {
    int foot, terrain, robot;
    int trials, landed, fell, undecided, failed_numerics;
    int hung;                              /* trials whose worker the watchdog killed (not physics) */
    double success_rate, ci_low, ci_high;  /* landed / trials and its Wilson interval */
    int nmetric;                           /* trials the medians are over (all but failed_numerics, hung) */
    double median[FS_CAMPAIGN_NMETRICS];   /* NAN when nmetric is 0 */
    /* the pitch-stiffness law's prediction (fs_analysis.h, docs/landing.md) */
    int law;                               /* FS_LAW_STANDS, FS_LAW_TOPPLES, or FS_LAW_NONE: a flat sole */
    double law_K, law_critical_m;          /* N m/rad with any tendon in series; K / (m g), m */
} fs_campaign_row;
enum { FS_LAW_NONE = -1, FS_LAW_TOPPLES = 0, FS_LAW_STANDS = 1 };

/* "stands", "topples" or "n/a". */
const char *fs_law_name(int law);

/* Fills rows[fs_campaign_ncells(c)] (by cell) from results[fs_campaign_ntrials(c)]. */
void fs_campaign_summarize(const fs_campaign *c, const fs_trial_result *results, fs_campaign_row *rows);

/* Writes dir/trials.csv, dir/summary.csv and dir/summary.md. */
fs_status fs_campaign_write(const fs_campaign *c, const fs_trial_result *results, const fs_campaign_row *rows,
                            const char *dir, fs_error *err);

/* Writes dir/summary.json, the file fs_campaign_compare reads; write it after all the others. */
fs_status fs_campaign_write_summary(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err);

/* Writes dir/chart.dat and dir/chart.gp: a gnuplot script that draws success.png (or the file
 * named by the gnuplot variable `out`) from the data: a bar chart of the feet across terrains with
 * CI whiskers, or for a sweep each foot's rate and CI band against the swept value. */
fs_status fs_campaign_write_chart(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err);

/* Checks every expectation, printing each with its numbers to out; returns how many failed. */
int fs_campaign_check(const fs_campaign *c, const fs_campaign_row *rows, FILE *out);

/* Compares two summary.json files, printing a table of what changed to out. First their
 * provenance: results made with other seeds, overrides or input files (by content) are refused
 * (FS_BAD_INPUT, each difference named) unless force, when they are only reported; another footsim
 * version is only reported (CI compares new code against an old baseline); a summary without
 * provenance is reported as not checked. Then FS_OK when every
 * success rate lies in its baseline's [ci_low, ci_high], no cell has more undecided trials than the
 * baseline's, and every median lies within the baseline's tolerance
 * (|result - baseline| <= relative * |baseline| + absolute); FS_EXPECTATION_FAILED when
 * not, or when a row is missing on either side; FS_BAD_INPUT when a file cannot be read as a summary. */
fs_status fs_campaign_compare(const char *result_path, const char *baseline_path, int force, FILE *out, fs_error *err);

#endif
