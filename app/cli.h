/* cli.h: the footsim command's shared argument handling and its subcommands. */
#ifndef FS_CLI_H
#define FS_CLI_H

#include <stddef.h>

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
    const char *height_x, *height_y;/* --height X Y */
    const char *png;                /* --png FILE */
    const char *scenario;           /* --scenario FILE */
    const char *seed;               /* --seed N */
    const char *jobs;               /* -j N: worker processes (campaign) */
    const char *data;               /* --data DIR: where relative data files are looked for first */
    int quick;                      /* --quick: a smaller sweep (bench) */
    int replace;                    /* --replace: replace a non-empty --out footsim did not make */
    int force;                      /* --force: compare results of different provenance */
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

/* render-compare A B: both runs side by side in DIR/frames/, and DIR/filmstrip.png
 * (app/cli_compare.c; app/cli_render.c without the renderer: exit 2). */
int cli_render_compare(const cli_args *a);

/* What each command writes in its results folder (NULL-terminated): an earlier version's folder,
 * without the marker, is recognised by these (fs_outdir_open). */
extern const char *const cli_run_files[], *const cli_campaign_files[], *const cli_compare_files[];
extern const char *const cli_optimize_files[]; /* app/cli_optimize.c */
extern const char *const cli_trial_files[];

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
/* Runs every trial of c in `jobs` worker processes into results (by trial index), with progress on
 * stderr under the name who; a dead worker's trial is failed_numerics, a worker the watchdog killed
 * makes its trial hung (app/cli_campaign.c). Returns
 * an fs_status. */
struct fs_campaign;
struct fs_trial_result;
struct fs_error;
int cli_campaign_trials(const struct fs_campaign *c, struct fs_trial_result *results, int jobs, const char *who,
                        struct fs_error *err);
int cli_compare(const cli_args *a);

/* bench precision|stability|speed (app/bench/cli_bench*.c). Each writes its CSVs, charts and a Markdown
 * table to --out DIR (default results/bench/), whole or not at all. */
int cli_bench(const cli_args *a);
int cli_bench_precision(const cli_args *a, const char *dir);
int cli_bench_stability(const cli_args *a, const char *dir);
int cli_bench_speed(const cli_args *a, const char *dir);

/* -j N: worker processes, default all cores online (1 to 1024; exit 2 otherwise). */
int cli_parse_jobs(const cli_args *a, int *jobs);

/* The machine a benchmark ran on, one line: CPU model, cores, compiler, ODE version. */
void cli_machine(char *out, size_t size);

/* The 1-minute load average from /proc/loadavg, or -1 when it cannot be read. */
double cli_load_average(void);

/* Progress of a long command on stderr (cli_progress.c): on a terminal one line redrawn in place
 * (done/total, failures, elapsed, ETA); without one, a plain line at every tenth of the work, at
 * least once a minute, and at the end. `who` names the command ("footsim campaign"), `unit` what
 * is counted ("trials"). */
typedef struct cli_progress {
    const char *who, *unit;
    int tty;
    double t0, last_line_s;
    int last_tenth;
} cli_progress;
void cli_progress_start(cli_progress *p, const char *who, const char *unit);
void cli_progress_update(cli_progress *p, int done, int total, int failed);

/* Whether an executable is on PATH. */
int cli_have_program(const char *name);

/* Runs 'gnuplot -e "out='TMP'" SCRIPT' in dir and installs TMP as dir/png_name once it is a whole
 * PNG (fs_png_check): the chart whole or not at all. Without gnuplot, or when it fails, says so
 * (naming `who`) and returns 0; a damaged chart (a full disk) is FS_IO, said. */
int cli_gnuplot(const char *dir, const char *script, const char *png_name, const char *who);

/* Data files (app/cli_data.c). A design, scenario, terrain or campaign path given on the command
 * line that exists as given (or is absolute, or starts with ./ or ../) is used as is; a relative one
 * that does not is looked for under --data DIR, then the current folder, then the installed data
 * (P/share/footsim beside P/bin/footsim, wherever P is; then the configured
 * CMAKE_INSTALL_FULL_DATADIR/footsim): in each as given, then in the kind's folder (scenarios/,
 * scenarios/feet/, terrains/), so 'footsim run static_load.ini' finds the shipped scenario. Paths
 * inside a file stay relative to that file. cli_data_find returns path itself when nothing is
 * found (the reader then says so), else buf. cli_data_set_dir checks --data (exit 2 when it is not
 * a folder). cli_data_path resolves one of footsim's own names ("scenarios/static_load.ini") to
 * text that lives as long as the process. */
typedef enum cli_data_kind { CLI_DATA_NONE = -1, CLI_DATA_SCENARIO, CLI_DATA_DESIGN, CLI_DATA_TERRAIN } cli_data_kind;
int cli_data_set_dir(const char *dir);
const char *cli_data_find(const char *path, cli_data_kind kind, char *buf, size_t size);
const char *cli_data_path(const char *rel);
/* The installed data folder the search ends with (for help). */
const char *cli_data_installed(void);

/* Prints "footsim: message" to stderr and returns the status. */
int cli_report(int status, const char *message);

/* A zeroed block for a command's large working state (a scenario, a campaign, a results folder's
 * paths): on the heap, owned and freed by the command, never a function-static, so that nothing
 * lives from one call to the next. NULL after "footsim: out of memory" on stderr (the caller
 * returns FS_NO_MEMORY). */
void *cli_zalloc(size_t size);

#endif
