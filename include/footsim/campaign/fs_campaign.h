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
#include "footsim/io/fs_output.h"
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
    FS_CAMPAIGN_NMETRICS = 18,
    FS_CAMPAIGN_MAX_BANDS = 8,   /* [band.NAME] sections in a file */
    FS_BAND_ENDS = 2,            /* a band's ends: low and high */
    FS_BAND_MAX_SETS = 16        /* overrides per end */
};

/* The metrics of a trial (the numeric fields of fs_trial_result but the draw; last, the ankle drop
 * at rest, which a trial that did not land lacks: NAN; then a soil's sinkage, print and slip, which
 * rigid ground lacks: NAN), named with units; summaries give their
 * medians, the comparison their tolerances. */
typedef struct fs_metric {
    const char *name;      /* "peak_force_N" */
    const char *tolerance; /* default "relative, absolute" */
    int over_landed;       /* 1: only a trial that landed has it (its median is over those) */
    int reported;          /* 1: compare reports it, never judges it (the step count follows the step) */
} fs_metric;
extern const fs_metric fs_campaign_metrics[FS_CAMPAIGN_NMETRICS];

/* The value of metric m (an index into fs_campaign_metrics) in r. */
double fs_metric_value(const fs_trial_result *r, int m);

/* One foot, terrain or robot of the campaign. */
typedef struct fs_campaign_item {
    char name[FS_NAME_MAX];  /* the section's NAME, or for a sweep "NAME@value" */
    char path[FS_PATH_MAX];  /* absolute; for the one robot of a campaign without [robot.NAME], "": the trial's */
    double sweep_value[2];   /* the swept values (0 without a sweep) */
    int base;                /* a sweep's point: the index of the terrain it is a point of ... */
    int point[2];            /* ... and of its value of each key */
    double step_s;           /* [robot.NAME] step_s: the step its trials take; 0: the trial's run.step_s */
    double tolerance_m;      /* [robot.NAME] tolerance_m: its trials' error-controlled step; 0: the trial's */
    int error_estimate;      /* [robot.NAME] error_estimate: 0 the trial's, 1 doubling, 2 embedded */
} fs_campaign_item;

/* [expect.NAME]: the success rate of foot on terrain under robot must lie in [min_success, max_success]. */
typedef struct fs_expectation {
    char name[FS_NAME_MAX];
    int foot, terrain, robot; /* indices into the campaign's feet, terrains and robots */
    double min_success, max_success;
} fs_expectation;

/* One end of a contact band ([band.NAME] low = ..., high = ...): number keys of the trials, each set
 * by a typed edit of every cell's loaded definitions (fs_scenario_set), as --set would set them. */
typedef struct fs_band_end {
    char name[8];                             /* "low", "high"; "" without a band */
    int nsets;
    char key[FS_BAND_MAX_SETS][2 * FS_NAME_MAX]; /* "section.key" */
    double value[FS_BAND_MAX_SETS];
    char text[FS_VALUE_MAX];                  /* the overrides as the file gives them */
} fs_band_end;

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
    /* [campaign] band = NAME: every trial runs once per end of [band.NAME] on the same seed, and a
       cell's row is its worse end's (docs/campaign.md, "Contact band"); nends 1 without a band (0,
       in a campaign built in code, counts as 1: fs_campaign_nends) */
    char band[FS_NAME_MAX];            /* the band's NAME, or "" */
    int band_choice;                   /* as bound: 0 none, n the n-th [band.NAME] of the file */
    int nends;
    fs_band_end end[FS_BAND_ENDS];
    fs_campaign_item foot[FS_CAMPAIGN_MAX_FEET];
    fs_campaign_item terrain[FS_CAMPAIGN_MAX_TERRAINS];
    fs_campaign_item robot[FS_CAMPAIGN_MAX_ROBOTS]; /* [robot.NAME] file = ...; without any, the trial
                                                       scenario's own robot, named after its file */
    fs_expectation expect[FS_CAMPAIGN_MAX_EXPECT];
    double tolerance[FS_CAMPAIGN_NMETRICS][2]; /* relative, absolute (metric's unit) */
    const char *set[FS_CAMPAIGN_MAX_SET];      /* the command's --set meant for the trials */
    int nset;
    /* what made the results (written into every result file, fs_provenance.h): every --set as
       given, every input file (relative to the campaign file's folder) with its hash, the first
       cell's settings; the seeds are c's own when written */
    fs_provenance provenance;
    fs_scenario *pair;                 /* the trial scenario of each cell and band end, loaded once
                                          (pair[cell * nends + end]): fs_campaign_pair_of;
                                          fs_campaign_free releases them */
} fs_campaign;

/* Reads and checks path. Each of sets ("section.key=value") goes to the campaign file when its
 * section is one of the campaign's (campaign, tolerance, foot.*, terrain.*, expect.*), otherwise
 * to every trial (c keeps the pointers). Then loads the trial scenario for every (foot, terrain)
 * with its overrides, once, and keeps it for the trials (fs_trial_run_scenario places a copy per
 * seed): anything wrong is FS_BAD_INPUT, nothing run. fs_campaign_free releases what it holds. */
fs_status fs_campaign_load(const char *path, const char *const *sets, int nsets, fs_campaign *c, fs_error *err);
void fs_campaign_free(fs_campaign *c);

/* Prints the keys of a campaign file (one section of each kind, NAME as written) as a Markdown table
 * (fs_config_print_keys) to out_file, a FILE *: `footsim keys`, docs/keys.md. Sweep values and
 * [band.NAME] ends are lists of values or overrides, said in docs/campaign.md, not in the table. */
void fs_campaign_print_keys(void *out_file);

/* The n-th key (1-based) a sweep may vary: every number of a terrain, design, robot or scenario
 * file, in that order; NULL past the last. */
const fs_key *fs_campaign_sweepable(int n);

/* A cell is a (foot, terrain, robot), numbered foot-major: cell = (foot * nterrains + terrain) *
 * nrobots + robot. */
int fs_campaign_ncells(const fs_campaign *c);
void fs_campaign_cell_of(const fs_campaign *c, int cell, int *foot, int *terrain, int *robot);

/* The band's ends (1 without a band), and the trial scenarios of a campaign: cells x ends. */
int fs_campaign_nends(const fs_campaign *c);
int fs_campaign_npairs(const fs_campaign *c);

/* The loaded trial scenario of a cell (its first end's, with a band), and of a cell at a band end. */
const fs_scenario *fs_campaign_pair(const fs_campaign *c, int cell);
const fs_scenario *fs_campaign_pair_of(const fs_campaign *c, int cell, int end);

/* The overrides a cell's trial scenario reads its files with: scenario.design, scenario.terrain,
 * robot.design (when the campaign names robots), run.step_s, run.tolerance_m and run.error_estimate
 * (each when the robot's section gives it: its own step, see docs/campaign.md), the sweep's values at the cell's point (to 17
 * digits: the same double read back), then c->set. fs_campaign_load reads the first point of each
 * (foot, terrain, robot) so and makes the later points by typed edits of it. buf holds their text;
 * out gets up to FS_CAMPAIGN_MAX_SET + FS_CAMPAIGN_CELL_SETS pointers; returns the count. */
enum { FS_CAMPAIGN_CELL_SETS = 8 };
int fs_campaign_overrides(const fs_campaign *c, int cell, char buf[FS_CAMPAIGN_CELL_SETS][FS_PATH_MAX + 32],
                          const char **out);

/* Trials are numbered cell-major, then by band end: index = (cell * nends + end) * seeds + seed -
 * first_seed (without a band: cell * seeds + seed - first_seed); a cell's trials are one block. */
int fs_campaign_ntrials(const fs_campaign *c);
void fs_campaign_trial_of(const fs_campaign *c, int index, int *cell, int *seed);
int fs_campaign_trial_end(const fs_campaign *c, int index);

/* The 95 % Wilson score interval of k successes in n > 0 trials. */
void fs_wilson(int k, int n, double *low, double *high);


/* One row of the summary: a cell (foot on terrain under robot) over all seeds. */
typedef struct fs_campaign_row {
    int foot, terrain, robot;
    int trials, landed, fell, undecided, failed_numerics;
    int hung;                              /* trials whose worker was lost, not to physics: killed by the
                                              watchdog (outcome hung) or from outside (outcome killed);
                                              the summary files' "hung" column, which counts both */
    int killed;                            /* of those, the killed (trials.csv tells them apart) */
    double success_rate, ci_low, ci_high;  /* landed / trials and its Wilson interval */
    int nmetric;                           /* trials the medians are over (all but failed_numerics, hung,
                                              killed; the ankle drop at rest's: the landed among them) */
    double median[FS_CAMPAIGN_NMETRICS];   /* over those that have the metric; NAN when none has */
    /* the pitch-stiffness law's prediction (fs_analysis.h, docs/landing.md) */
    int law;                               /* FS_LAW_STANDS, FS_LAW_TOPPLES, or FS_LAW_NONE: no robot */
    double law_K, law_critical_m;          /* N m/rad with any tendon in series; K / (m g), m */
    /* the drop law's (fs_drop_law_apply, docs/landing.md): judged seed by seed on the support the
       seed's drawn terrain gives under the drawn footprint; the cell stands when at least half do */
    int drop_law;                          /* FS_LAW_STANDS, FS_LAW_TOPPLES, or FS_LAW_NONE: no robot */
    int drop_seeds, drop_stands;           /* seeds judged, and how many stand */
    double drop_energy_J, drop_barrier_J;  /* medians over the seeds: E at touchdown, B (work to the largest lean) */
    double drop_saturation_N_m;            /* median M_s: the fold's or the support edge's moment */
    double drop_critical_m;                /* the highest centre of mass it stands on level ground (the
                                              heat map's line), m; NAN when none */
    /* with a band: every field above is the worse end's (the smaller success rate; the first end
       on a tie), the one named here; each end's own count and rate beside it */
    int band_end;                          /* the end that decides, or -1 without a band */
    int end_landed[FS_BAND_ENDS], end_trials[FS_BAND_ENDS];
    double end_rate[FS_BAND_ENDS];
    /* with a band, the laws at each end, with that end's contact in them (fs_pitch_contact_series,
       fs_contact_rebound_gain); the law fields above are those of the end where the drop law stands
       on the fewest seeds (then: the static law topples, the smaller K, the measured worse end) */
    int law_end;                           /* that end, or -1 without a band */
    int end_law[FS_BAND_ENDS], end_drop_law[FS_BAND_ENDS], end_drop_stands[FS_BAND_ENDS];
    double end_law_K[FS_BAND_ENDS], end_drop_energy_J[FS_BAND_ENDS], end_drop_barrier_J[FS_BAND_ENDS];
    double end_restitution[FS_BAND_ENDS];  /* the end's contact's e (fs_contact_restitution) */
} fs_campaign_row;
enum { FS_LAW_NONE = -1, FS_LAW_TOPPLES = 0, FS_LAW_STANDS = 1 };

/* Where a success rate decides, to judge a law's verdict by (tools/law-agreement.py's rule): at least
 * FS_RATE_LANDS lands, at most FS_RATE_FALLS falls, in between undecided. */
#define FS_RATE_LANDS 0.7
#define FS_RATE_FALLS 0.3

/* "stands", "topples" or "n/a". */
const char *fs_law_name(int law);

/* Fills rows[fs_campaign_ncells(c)] (by cell) from results[fs_campaign_ntrials(c)]. */
void fs_campaign_summarize(const fs_campaign *c, const fs_trial_result *results, fs_campaign_row *rows);

/* Writes dir/trials.csv, dir/summary.csv (RFC 4180: one header row, a missing value an empty
 * field, no provenance: summary.json has it), dir/summary.md and dir/schema.sql (a sqlite3 script
 * that makes typed tables of the two CSV files, NULL for a missing value, and of the provenance). */
fs_status fs_campaign_write(const fs_campaign *c, const fs_trial_result *results, const fs_campaign_row *rows,
                            const char *dir, fs_error *err);

/* Writes dir/summary.json, the file fs_campaign_compare reads; write it after all the others. */
fs_status fs_campaign_write_summary(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err);

/* Writes dir/chart.dat and dir/chart.gp: a gnuplot script that draws success.png (or the file
 * named by the gnuplot variable `out`) from the data: a bar chart of the feet across terrains with
 * CI whiskers, or for a sweep each foot's rate and CI band against the swept value. */
fs_status fs_campaign_write_chart(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err);

/* Reads back from a summary.json (path) what fs_campaign_write_chart needs: c's name, seeds, swept
 * keys, feet, terrains (with their swept values) and robots, and rows[fs_campaign_ncells(c)] (rates,
 * intervals, the law's prediction; medians NAN). Nothing else of c is set (c->pair is NULL).
 * rows must hold FS_CAMPAIGN_MAX_FEET x FS_CAMPAIGN_MAX_TERRAINS x FS_CAMPAIGN_MAX_ROBOTS rows.
 * FS_BAD_INPUT (said) when the file is not a campaign's summary. */
fs_status fs_campaign_reload(const char *path, fs_campaign *c, fs_campaign_row *rows, fs_error *err);

/* Checks every expectation, printing each with its numbers to out; returns how many failed. */
int fs_campaign_check(const fs_campaign *c, const fs_campaign_row *rows, FILE *out);

/* The expectations a summary.json records (path): each printed to out with whether it was met,
 * *failed of *total not met. FS_BAD_INPUT (said) when the file is not a campaign's summary. */
fs_status fs_campaign_summary_expectations(const char *path, FILE *out, int *failed, int *total, fs_error *err);

/* Compares two summary.json files, cell by cell. First their provenance: results made with other
 * seeds, overrides or input files (by content; a changed input named by its path) are refused
 * (FS_INPUTS_DIFFER, each difference said) unless force, when they are only reported; another
 * footsim version or other settings are only reported (CI compares new code against an old
 * baseline); a summary without provenance is reported as not checked. Then FS_OK when every
 * success rate lies in its baseline's [ci_low, ci_high], no cell has more undecided or hung trials
 * than the baseline's, and every judged median lies within the baseline's tolerance
 * (|result - baseline| <= relative * |baseline| + absolute); a metric marked reported (steps) is
 * reported, never judged; FS_EXPECTATION_FAILED when not, or when a row is missing on either side;
 * FS_BAD_INPUT (or the reading's status) when a file cannot be read as a summary.
 * The Markdown (out, unless NULL) lists the quantities outside what is allowed, or every quantity
 * with all; *json (unless json is NULL; the caller frees it) gets every quantity with its verdict
 * ("identical", "within", "outside", "reported", "not judged", "not compared", "missing in the
 * result/baseline"; for equivalence "equivalent", "differs"), the provenance's differences, the
 * counts, the verdict, the exit status and the error, whatever the status. *nbad (unless NULL):
 * how many quantities are outside (differ). */
typedef struct fs_compare_opts {
    int force;               /* compare results of other inputs anyway */
    int all;                 /* the Markdown lists every quantity */
    int equivalence;         /* judge equivalence to a reference (below) */
    const char *result_name; /* names the result in the Markdown's heading (NULL: its path) */
} fs_compare_opts;
struct cJSON;
fs_status fs_campaign_compare_with(const char *result_path, const char *baseline_path, const fs_compare_opts *o,
                                   FILE *out, struct cJSON **json, int *nbad, fs_error *err);
/* fs_campaign_compare_with without --all or JSON. */
fs_status fs_campaign_compare(const char *result_path, const char *baseline_path, int force, FILE *out, fs_error *err);

/* Campaign equivalence (docs/bench.md): whether a campaign run at some setting (a step, a solver)
 * tells what a reference campaign of the same seeds and inputs tells. Provenance as in
 * fs_campaign_compare, but overrides may differ (they carry the setting). Per cell: the two success
 * rates' 95 % Wilson intervals overlap, and the medians of the well-posed metrics (impact impulse,
 * final lean, ankle drop at rest, settle time, mean and final contacts) lie within 5 % of the reference's or
 * an absolute floor (0.5 deg, 0.1 mm, 5 ms, 1 contact), whichever is larger; peak force is reported,
 * not judged. FS_OK when every cell is equivalent, FS_EXPECTATION_FAILED when not or a row is
 * missing (*ndiffer, unless NULL: how many quantities differ), FS_BAD_INPUT and FS_INPUTS_DIFFER as
 * fs_campaign_compare. result_name names the result in the table's heading (NULL: result_path).
 * The Markdown lists every judged quantity (fs_campaign_compare_with with all). */
fs_status fs_campaign_equivalence(const char *result_path, const char *result_name, const char *reference_path,
                                  int force, FILE *out, int *ndiffer, fs_error *err);

/* ---- provenance and the journal (campaign_journal.c) -------------------------------------- */

/* The provenance line a journal keeps ("# provenance: footsim VERSION; seeds A to B;
 * SETTINGS; inputs PATH=HASH ...; overrides ..."), without its newline; malloc'd (NULL: out of
 * memory). Two runs with the same line ran the same trials. */
char *fs_campaign_provenance(const fs_campaign *c);

/* The same line of the results a summary.json (path) records, to compare with
 * fs_campaign_provenance's; malloc'd, NULL when the file has none or cannot be read. */
char *fs_campaign_summary_provenance(const char *path);

/* Shards: trial index belongs to shard (1-based) of nshards when index % nshards == shard - 1, so
 * any nshards splits any campaign into disjoint shares, each spread over every cell. */
static inline int fs_campaign_in_shard(int index, int shard, int nshards)
{
    return index % nshards == shard - 1;
}

/* A journal is a campaign's finished trials, one record each, behind a header that says what made
 * them: the campaign file (absolute), its --set as given, the shard, the trial count and the
 * provenance line, then a line `check CRC` (the CRC-32 of the header's bytes before it, fs_crc.h).
 * A record is one line `LEN CRC PAYLOAD`: the payload's length in bytes and its CRC-32 (8 hex
 * digits), then the payload, which holds every field of a trial's result exactly (numbers in C99
 * hex notation), so results read back are bit for bit those written. A run appends each record as
 * its trial ends (fs_journal_append: one write, then fdatasync; a write that fails is cut off
 * again); a shard's results folder holds the same format sorted by index (trials.journal). A trial
 * whose worker was killed (FS_KILLED) may have a second record after its first: the second
 * attempt's. Format 1 (an earlier footsim's: no check line, no frame) is still read. */
enum { FS_JOURNAL_FORMAT = 2 };
typedef struct fs_journal_head {
    char campaign[FS_PATH_MAX];          /* the campaign file, absolute */
    char *set[FS_CAMPAIGN_MAX_SET];      /* the --set as given (malloc'd) */
    int nset;
    int shard, nshards;                  /* 1/1: the whole campaign */
    int ntrials;                         /* the whole campaign's */
    char *provenance;                    /* fs_campaign_provenance (malloc'd) */
} fs_journal_head;

/* The head of c loaded from campaign_path with sets, run as shard/nshards. */
fs_status fs_journal_head_of(const fs_campaign *c, const char *campaign_path, const char *const *sets, int nsets,
                             int shard, int nshards, fs_journal_head *h, fs_error *err);
void fs_journal_head_free(fs_journal_head *h);

/* Where a and b (called name_a and name_b) differ, in words ("inputs: 'feet/bio.ini=12..' in
 * NAME_A, 'feet/bio.ini=34..' in NAME_B"), into why (size bytes); 0 when they are the same
 * campaign (provenance and trial count; the shard and the campaign file's path are not compared). */
int fs_journal_differs(const fs_journal_head *a, const fs_journal_head *b, const char *name_a, const char *name_b,
                       char *why, size_t size);

/* 1 when a and b differ in their footsim version alone (the first part of the provenance; the
 * trials' count the same), else 0. */
int fs_journal_version_only(const fs_journal_head *a, const fs_journal_head *b);

/* Writes the journal at path whole (fs_write_file): h's header and the record of every trial i
 * with done[i] nonzero, by index. */
fs_status fs_journal_write(const char *path, const fs_journal_head *h, const fs_trial_result *results,
                           const unsigned char *done, fs_error *err);

/* What fs_journal_read found past the records it kept: a resume keeps those and runs the rest. */
typedef struct fs_journal_tail {
    int format;              /* the file's format: 1 is rewritten (fs_journal_write) before appending */
    long long good_bytes;    /* the bytes of the header and the records kept */
    int torn;                /* the file ends in a record cut short (a kill, a full disk, a size limit) */
    int line;                /* a record that failed its check, or 0: the first line not kept */
    char why[160];           /* what is wrong with that line */
} fs_journal_tail;

/* Reads the journal at path (a regular file, never a FIFO or a symbolic link): its head, and its
 * records into results[h->ntrials] and done (both malloc'd): done[i] is how many records trial i
 * has (2 only when its first says its worker was killed), results[i] the last. A record cut short at
 * the end of the file is left out. A record that fails its checksum or cannot be read (or, format 1,
 * any line that is not a record) is FS_BAD_INPUT ("path:line: ...") when tail is NULL; with a tail
 * (format 2) the records before it are kept, and tail says where the good part ends and why. The
 * header wrong, or lines that end in CR LF: FS_BAD_INPUT, naming --fresh. FS_NO_MEMORY. */
fs_status fs_journal_read(const char *path, fs_journal_head *h, fs_trial_result **results, unsigned char **done,
                          int *ndone, fs_journal_tail *tail, fs_error *err);

/* An open journal being appended to (one process at a time: an exclusive flock on it). */
typedef struct fs_journal {
    char path[FS_OUT_PATH]; /* as long as any path a results folder's files may have (fs_output.h) */
    int fd;
} fs_journal;

/* Opens path for appending; creates it with h's header (written whole) when it does not exist.
 * keep_bytes >= 0: the file is cut to that length first (fs_journal_tail.good_bytes: a torn or
 * damaged end removed, so that new records never follow it). FS_BAD_INPUT when path is not a
 * regular file (a FIFO, a folder, a symbolic link: named) or another process holds it. */
fs_status fs_journal_open(fs_journal *j, const char *path, const fs_journal_head *h, long long keep_bytes,
                          fs_error *err);

/* Appends index's record and syncs it to the disk; FS_IO when it cannot (the record cut off again). */
fs_status fs_journal_append(fs_journal *j, int index, const fs_trial_result *r, fs_error *err);
void fs_journal_close(fs_journal *j);

#endif
