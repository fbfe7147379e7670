/* cli.h: the footsim command's shared argument handling and its subcommands. */
#ifndef FS_CLI_H
#define FS_CLI_H

#include "footsim/model/fs_scenario.h"
#include "footsim/sim/fs_observer.h"
#include "footsim/sim/fs_soil_grid.h"

#include <stddef.h>
#include <stdio.h>

enum { CLI_MAX_SET = 256 };

/* What every subcommand may be given. */
typedef struct cli_args {
    const char *command;
    const char *input;              /* the scenario or design file */
    const char *input2;             /* a second one, for commands that take two (render-compare) */
    const char *out;                /* --out DIR, or NULL */
    int json;                       /* --json */
    const char *set[CLI_MAX_SET];   /* --set section.key=value, in order */
    int nset;
    int frames;                     /* --frames: write DIR/frames/NNNNNN.png */
    const char *fps, *size, *camera;/* --fps N, --size WxH, --camera NAME (as given; checked by the renderer) */
    int video;                      /* --video: also DIR/video.mp4 */
    const char *exaggerate;         /* --exaggerate F: displacements from the neutral pose times F */
    const char *frames_of;          /* --frames-of SELECTORS: frames of chosen campaign trials */
    const char *height_x, *height_y;/* --height X Y */
    const char *png;                /* --png FILE */
    const char *scenario;           /* --scenario FILE */
    const char *seed;               /* --seed N */
    const char *jobs;               /* -j N: worker processes (campaign) */
    const char *reference;          /* --reference S: the reference step (bench equivalence) */
    const char *steps;              /* --steps S1,S2,...: the steps to judge (bench equivalence) */
    const char *data;               /* --data DIR: where relative data files are looked for first */
    int quick;                      /* --quick: a smaller sweep (bench) */
    const char *scene;              /* --scene NAME[,NAME...]: only these scenes (bench precision) */
    int replace;                    /* --replace: replace a non-empty --out footsim did not make */
    int force;                      /* --force: compare results of different provenance */
    int equivalence;                /* --equivalence: compare judges equivalence to a reference */
    int all;                        /* --all: compare's Markdown lists every quantity */
    int mjcf;                       /* --mjcf: export as MuJoCo MJCF */
    const char *shard;              /* --shard I/N (campaign) */
    int fresh;                      /* --fresh: start a campaign over, its journal removed */
    const char *more[CLI_MAX_SET];  /* merge: the folders after the first */
    int nmore;
} cli_args;

/* Frames of a run (app/cli_frames.c; app/cli_render.c without the renderer). cli_frames_open
 * checks the frame options and prepares the renderer before anything is simulated (exit 2 when
 * they are wrong or no renderer is built in); it fills obs with the observer that draws each
 * frame. cli_frames_close finishes (video). */
typedef struct fs_run_observer fs_run_observer;
typedef struct fs_scenario fs_scenario;
typedef struct cli_frames cli_frames;
int cli_frames_open(const cli_args *a, const fs_scenario *sc, const char *dir, cli_frames **frames,
                    fs_run_observer *obs);
int cli_frames_close(cli_frames *frames, int ok, const char *shown_dir);
/* What every frame says after its time (the seed: "SEED 3"), and the last frame drawn again
 * saying label (the seed and the outcome), once the run has ended. No-ops without frames. */
void cli_frames_label(cli_frames *frames, const char *label);
int cli_frames_finish(cli_frames *frames, const char *label);
/* The same with the frames straight in frames_dir (made already); no video. */
int cli_frames_open_at(const cli_args *a, const fs_scenario *sc, const char *frames_dir, cli_frames **frames,
                       fs_run_observer *obs);
/* Checks the frame options for sc and that frames can be drawn, before anything is simulated. */
int cli_frames_check(const cli_args *a, const fs_scenario *sc);

/* campaign --frames-of (app/cli_frames_of.c): cli_frames_of_open checks the selectors against the
 * campaign and the frame options before any trial runs (NULL and 0 without --frames-of);
 * cli_frames_of_write draws each chosen trial (run again, alone, as the campaign ran it) into
 * dir/frames/<foot>-<terrain>-<robot>-seed<N>/ (shown_dir: what the folder will be called) and
 * frees (f may be NULL). Neither changes any result. */
typedef struct fs_campaign fs_campaign;
typedef struct fs_trial_result fs_trial_result;
typedef struct cli_frames_of cli_frames_of;
int cli_frames_of_open(const cli_args *a, const fs_campaign *c, cli_frames_of **f);
void cli_frames_of_free(cli_frames_of *f); /* when not handed to cli_frames_of_write */
int cli_frames_of_write(cli_frames_of *f, const fs_campaign *c, const fs_trial_result *results, const char *dir,
                        const char *shown_dir);

/* render-compare A B: both runs side by side in DIR/frames/, and DIR/filmstrip.png
 * (app/cli_compare.c; app/cli_render.c without the renderer: exit 2). */
int cli_render_compare(const cli_args *a);


int cli_run(const cli_args *a);
int cli_model(const cli_args *a);
int cli_stiffness(const cli_args *a);
int cli_keys(const cli_args *a);
int cli_demo(const cli_args *a);
int cli_terrain(const cli_args *a);
int cli_trial(const cli_args *a);
int cli_walk(const cli_args *a);
int cli_campaign(const cli_args *a);  /* app/cli_campaign.c */
int cli_optimize(const cli_args *a);  /* app/cli_optimize.c */
/* Runs every trial of c in `jobs` worker processes into results (by trial index) through the
 * library (fs_campaign_run_trials), with progress and its messages on stderr under the name who
 * (app/cli_campaign.c). Returns an fs_status. */
struct fs_campaign;
struct fs_trial_result;
struct fs_error;
int cli_campaign_trials(const struct fs_campaign *c, struct fs_trial_result *results, int jobs, const char *who,
                        struct fs_error *err);
int cli_compare(const cli_args *a);
/* plot RUN_DIR|CAMPAIGN_DIR [--out DIR]: a run's time series as DIR/plot.png, or a campaign's chart
 * drawn again from its summary.json as DIR/success.png (app/cli_plot.c). */
int cli_plot(const cli_args *a);
int cli_export(const cli_args *a);    /* app/cli_export.c */
int cli_merge(const cli_args *a);     /* app/cli_campaign.c: shard folders into one campaign's results */

/* bench precision|stability|speed (app/bench/cli_bench*.c). Each writes its CSVs, charts and a Markdown
 * table to --out DIR (default build/bench/), whole or not at all. bench equivalence [CAMPAIGN]
 * (app/bench/cli_bench_equivalence.c) writes its own folder (default build/equivalence/<name>/). */
int cli_bench(const cli_args *a);
int cli_bench_precision(const cli_args *a, const char *dir);
/* bench precision's --scene checked (0, or FS_BAD_INPUT with the names said on stderr): before the
 * output folder is touched. */
int cli_bench_precision_scenes(const cli_args *a);
int cli_bench_stability(const cli_args *a, const char *dir);
/* bench stability's --scene checked alone, before the output folder is touched (as
 * cli_bench_precision_scenes): FS_BAD_INPUT, said, for an unknown slice. */
int cli_bench_stability_slices(const cli_args *a);
int cli_bench_speed(const cli_args *a, const char *dir);
int cli_bench_equivalence(const cli_args *a);

/* Campaign equivalence (app/bench/cli_bench_equivalence.c, docs/bench.md), for bench equivalence
 * and bench precision's last stage: the campaign at the reference step and at each step (every
 * cell's run.step_s set after the spec's overrides), with the same seeds and workers, each step
 * judged against the reference (fs_campaign_equivalence). Into DIR: equivalence.md (a row a step),
 * h<STEP>.md (each comparison), reference/ (the reference campaign's files). cli_equivalence_open
 * checks everything before anything runs (the steps, the campaign loaded at every step, DIR; exit 2
 * and nothing written for a bad step or campaign) and prepares DIR; cli_equivalence_run runs the
 * campaigns and writes the files (0, or the exit status of what failed: 4 when a file cannot be
 * written; verdicts are results, not failures); cli_equivalence_table prints the verdict table
 * (Markdown); cli_equivalence_close releases e (NULL allowed) and removes what was not put in
 * place. Messages go to stderr. */
typedef struct cli_equivalence_spec {
    const char *campaign;             /* the campaign file, found */
    const char *shown;                /* how equivalence.md names it */
    const char *const *set;           /* overrides ("section.key=value"), before the step */
    int nset;
    const char *reference;            /* the reference step, s, as text */
    const char *steps;                /* the steps to judge, s, separated by commas */
    int jobs;                         /* worker processes of every campaign */
    const char *command;              /* what equivalence.md says made it */
    const char *who;                  /* names the command in messages ("footsim bench equivalence") */
    const char *option;               /* names DIR in messages ("--out") */
} cli_equivalence_spec;
typedef struct cli_equivalence cli_equivalence;
int cli_equivalence_open(cli_equivalence **e, const cli_equivalence_spec *spec, const char *dir, int replace);
int cli_equivalence_run(cli_equivalence *e);
void cli_equivalence_table(FILE *f, const cli_equivalence *e);
void cli_equivalence_close(cli_equivalence *e);

/* -j N: worker processes, default all cores online (1 to 1024; exit 2 otherwise). */
int cli_parse_jobs(const cli_args *a, int *jobs);

/* The machine a benchmark ran on, one line: CPU model, cores, compiler, ODE version. */
void cli_machine(char *out, size_t size);

/* The 1-minute load average from /proc/loadavg, or -1 when it cannot be read. */
double cli_load_average(void);

/* A CSV field's number: v in fmt into buf, or "" when v is not finite (in every CSV footsim
 * writes, a missing value is an empty field). */
const char *cli_csv_num(char *buf, size_t size, const char *fmt, double v);
/* A CSV field's text: s itself, or s quoted into buf (quotes doubled) when it holds a comma, a
 * quote or a line break (RFC 4180). */
const char *cli_csv_text(char *buf, size_t size, const char *s);

typedef struct fs_provenance fs_provenance;

/* A run's final soil surface (cli_surface.c): cli_surface_observer gives an observer that calls
 * inner's (frames; NULL: none) and keeps the soil's surface at each call, the last being the run's
 * end (nothing without a soil); cli_surface_write writes it into dir, when there is one: surface.png
 * (16-bit heightmap, black the lowest height), surface.csv (x_mm, y_mm, surface_mm, print_mm; RFC
 * 4180), surface.provenance.json (prov, and the grid and the PNG's scale) and surface.ini (a terrain
 * file loading the PNG back as rigid heightmap ground). An fs_status. */
typedef struct cli_surface {
    const fs_run_observer *inner;
    fs_run_observer obs;
    fs_soil_surface s;
    fs_terrain_def material;
} cli_surface;
const fs_run_observer *cli_surface_observer(cli_surface *c, const fs_run_observer *inner);
int cli_surface_write(const cli_surface *c, const char *dir, const fs_provenance *prov, struct fs_error *err);
void cli_surface_free(cli_surface *c);
/* Writes dir/STEM.provenance.json beside dir/csv (fs_provenance_write_beside): p, and how the file
 * was made: "command", "date_utc", "machine" (NULL: null), "load_average_start" and "_end" (below
 * 0 or NAN: null). An fs_status. */
int cli_csv_beside(const char *dir, const char *csv, const fs_provenance *p, const char *command, const char *date_utc,
                   const char *machine, double load_start, double load_end, struct fs_error *err);
/* --scene's comma-separated names (list, NULL for none) among names[0..n-1]: sets chosen[k] for each
 * one given (the caller sets the rest) and returns 0; an unknown or empty name is said on stderr
 * with the names there are ("footsim bench BENCH: ... no NOUN is called ...") and FS_BAD_INPUT
 * returned. */
int cli_bench_choose(const char *bench, const char *noun, const char *list, const char *const *names, int n,
                     int *chosen);
/* What made a bench's results (fs_provenance.h): the files of the n scenarios it loaded, relative
 * to the shipped scenarios/ folder, with their hashes; settings as text (which columns vary); no
 * overrides (benches take none) and no seeds (set them when the runs draw from one). An fs_status;
 * fs_provenance_free releases p, also after a failure. */
int cli_bench_provenance(fs_provenance *p, const fs_scenario *const *sc, int n, const char *settings,
                         struct fs_error *err);

/* Progress of a long command on stderr (cli_progress.c): on a terminal one line redrawn in place
 * (done/total, failures, elapsed, ETA); without one, a plain line at every tenth of the work, at
 * least once a minute, and at the end, never a carriage return. `who` names the command ("footsim
 * campaign"), `unit` what is counted ("trials"). cli_progress_update gives the state after a task;
 * cli_progress_tick repeats it (a terminal's clock moves; a log gets its line once a minute passed
 * since the last): call it every few seconds while tasks run (the worker pool's progress callback
 * is called so, fs_pool.h). cli_progress_say prints a message line (a result, a dead worker) above
 * the progress line. cli_progress_round: a command of several rounds of tasks (optimize: one round
 * of trials per candidate) says which round it starts (1-based; unit "candidate"); every reporter
 * then shows the round and counts elapsed time, ETA and tenths over the whole command; NULL ends
 * the rounds. */
typedef struct cli_progress {
    const char *who, *unit;
    int tty;
    double t0, last_line_s;
    int last_tenth;
    int done, total, failed, started; /* the last state given */
} cli_progress;
void cli_progress_start(cli_progress *p, const char *who, const char *unit);
void cli_progress_update(cli_progress *p, int done, int total, int failed);
void cli_progress_tick(cli_progress *p);
void cli_progress_say(cli_progress *p, const char *format, ...);
void cli_progress_round(const char *unit, int round, int nrounds);

/* Whether an executable is on PATH. */
int cli_have_program(const char *name);

/* Runs 'gnuplot -e "out='TMP'" SCRIPT' in dir and installs TMP as dir/png_name once it is a whole
 * PNG (fs_png_check): the chart whole or not at all. Without gnuplot, or when it fails, says so
 * (naming `who`) and returns 0; a damaged chart (a full disk) is FS_IO, said. */
int cli_gnuplot(const char *dir, const char *script, const char *png_name, const char *who);
/* The same, the chart going to png (any path; whole or not at all): 0 drawn, -1 not drawn (no
 * gnuplot, or it failed: said), else the exit status of a damaged chart (FS_IO). While gnuplot
 * draws, SIGINT, SIGTERM and SIGHUP kill it before they do what they did (the caller's handler,
 * or the default), and a footsim killed outright takes it along (Linux: PR_SET_PDEATHSIG): no
 * gnuplot outlives the command. Names reach a script only as data (fs_gnuplot.h). */
int cli_gnuplot_to(const char *dir, const char *script, const char *png, const char *who);
/* cli_gnuplot_to of dir/png_name, the messages naming shown_dir (where the chart will be: a
 * campaign draws in its partial folder) instead of dir. */
int cli_gnuplot_shown(const char *dir, const char *shown_dir, const char *script, const char *png_name,
                      const char *who);

/* Data files (app/cli_data.c). A design, scenario, terrain or campaign path given on the command
 * line that exists as given (or is absolute, or starts with ./ or ../) is used as is; a relative one
 * that does not is looked for under --data DIR, then the current folder, then the installed data
 * (P/share/footsim beside P/bin/footsim, wherever P is; then the configured
 * CMAKE_INSTALL_FULL_DATADIR/footsim): in each as given, then in the kind's folder (scenarios/,
 * scenarios/feet/, terrains/), so 'footsim run static_load.ini' finds the shipped scenario. Paths
 * inside a file stay relative to that file, and a path in --set is looked for from the current
 * folder first; either falls back to the same folders (cli_data_folders hands them to the
 * library: fs_config_data_folders). cli_data_find returns path itself when nothing is
 * found (the reader then says so), else buf. cli_data_set_dir checks --data (exit 2 when it is not
 * a folder). cli_data_path resolves one of footsim's own names ("scenarios/static_load.ini") to
 * text that lives as long as the process. */
typedef enum cli_data_kind { CLI_DATA_NONE = -1, CLI_DATA_SCENARIO, CLI_DATA_DESIGN, CLI_DATA_TERRAIN } cli_data_kind;
int cli_data_set_dir(const char *dir);
const char *cli_data_find(const char *path, cli_data_kind kind, char *buf, size_t size);
const char *cli_data_path(const char *rel);
void cli_data_folders(void);
/* The shipped robots' folder (scenarios/robots under --data, here, the installed data) into buf,
 * or NULL when there is none. */
const char *cli_data_robots(char *buf, size_t size);
/* The installed data folder the search ends with (for help). */
const char *cli_data_installed(void);
/* The landing trial (scenarios/landing_trial.ini, read from the current folder) of the biomimetic
 * foot under robot (relative to scenarios/, e.g. "robots/drop_weight.ini") on flat ground: as loaded
 * into trial, and placed for seed 1 (fs_trial_place) into scene: bench precision's
 * landing_biomimetic, for the tools that measure it (tools/). */
fs_status cli_flat_landing(const char *robot, fs_scenario *trial, fs_scenario *scene, fs_error *err);

/* Prints "footsim: message" to stderr and returns the status. */
int cli_report(int status, const char *message);

/* A command's results folder into dir: --out as given, or results/KIND/NAME. 0, or exit 2 after
 * saying so when it would not fit whole (fs_path_format): never cut short. */
int cli_results_dir(const cli_args *a, const char *kind, const char *name, char *dir, size_t size);

/* A zeroed block for a command's large working state (a scenario, a campaign, a results folder's
 * paths): on the heap, owned and freed by the command, never a function-static, so that nothing
 * lives from one call to the next. NULL after "footsim: out of memory" on stderr (the caller
 * returns FS_NO_MEMORY). */
void *cli_zalloc(size_t size);

/* A command's results in a folder of its own: run(user, observer) with frames of framed (when
 * --frames), then name (the result as JSON, to_json(result)) beside them, swapped in whole at the
 * end; dir_out gets the folder as shown. */
typedef struct cli_folder_job {
    const char *dir;                 /* the folder asked for */
    const fs_scenario *framed;       /* the scenario the frames are framed on */
    fs_status (*run)(void *user, const fs_run_observer *obs, fs_error *err);
    void *user;
    const char *name;                /* the JSON file */
    struct cJSON *(*to_json)(const void *result, fs_error *err); /* NULL: err set */
    const void *result;
    const struct fs_provenance *provenance; /* what made the result, put into the JSON (NULL: none) */
    /* more files beside the JSON (a trial's trajectory.csv), written into dir; NULL: none */
    fs_status (*write_more)(void *user, const char *dir, fs_error *err);
    /* what every frame says (a trial's seed), and the last once the run ended (and its outcome);
       NULL: nothing */
    void (*frame_label)(const void *user, const void *result, int ended, char *label, size_t size);
} cli_folder_job;
/* Runs j into its folder j->dir (out: the caller's results folder, on the heap with the rest of its
 * work, aborted here when not committed); dir_out gets the folder as shown. 0 or an exit status. */
typedef struct fs_outdir fs_outdir;
int cli_in_folder(const cli_args *a, const cli_folder_job *j, fs_outdir *out, char *dir_out, size_t size);

/* Prints root as JSON on stdout: 0, or exit 5 said. */
struct cJSON;
int cli_print_json(struct cJSON *root);
/* Runs a command that reads a design (model, stiffness) on its scenario (fs_scenario_for_design),
 * which lives on the heap for the command and is freed on every path. */
int cli_with_design(const cli_args *a, int (*command)(const cli_args *a, const fs_scenario *sc));

/* What campaign and merge add to the library's files (app/cli_campaign.c): the --frames-of trials
 * (frames_of, or NULL) and the chart drawn by gnuplot, into the partial folder before it is put in
 * place (an fs_campaign_extra_fn, user a cli_campaign_files; drawn says whether the chart was). */
typedef struct fs_campaign_row fs_campaign_row;
typedef struct cli_campaign_files {
    cli_progress progress; /* first: campaign's progress callback's user */
    cli_frames_of *frames_of;
    int drawn;
} cli_campaign_files;
int cli_campaign_files_add(const char *partial, const char *shown, const struct fs_campaign *c,
                           const struct fs_trial_result *results, const fs_campaign_row *rows, void *user);
/* A finished campaign's rows and expectations on stdout, and where its files are; exit 1 when an
 * expectation fails. */
int cli_campaign_report(const struct fs_campaign *c, const fs_campaign_row *rows, const char *dir, int drawn);
/* The command that runs a campaign of a (input, -j, --shard, --set, --data) again into dir, quoted
 * for a POSIX shell, into buf. */
void cli_campaign_command(const cli_args *a, const char *dir, char *buf, size_t size);

#endif
