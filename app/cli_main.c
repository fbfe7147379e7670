/* cli_main.c: the footsim command: subcommands, --help, and argument checks. */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/base/fs_path.h"
#include "footsim/base/fs_version.h"
#include "footsim/io/fs_config.h"
#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_ode.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct command {
    const char *name;
    int (*run)(const cli_args *);
    const char *input;   /* what the positional argument is, or NULL when there is none */
    const char *options; /* the options it takes, for checks and --help */
    const char *help;
} command;

static const command commands[] = {
    {"run", cli_run, "SCENARIO", "--out --replace --set --frames --fps --size --camera --exaggerate --video --data",
     "Runs a scenario until the foot is at rest and writes DIR/metrics.json and DIR/trajectory.csv\n"
     "  (default DIR: results/runs/<scenario name>/).\n"
     "  --frames writes DIR/frames/000000.png, ... at --fps (60) frames per simulated second, --size WxH\n"
     "  (1280x720), seen by --camera foot|side|front|three-quarter|follow (foot: the foot filling the\n"
     "  frame); --exaggerate F multiplies each body's displacement from its first pose, in the ankle\n"
     "  body's frame, by F (said on every frame); --video also encodes DIR/video.mp4 with ffmpeg."},
    {"render-compare", cli_render_compare, "SCENARIO_A SCENARIO_B", "--out --replace --set --fps --size --camera --exaggerate --video --data",
     "Runs both scenarios and writes their frames side by side (A left, B right) to DIR/frames/ and key\n"
     "  frames from touch-down to rest to DIR/filmstrip.png (default DIR: results/compare/A-foot_vs_B-foot/).\n"
     "  --set a:KEY=V changes A only, b:KEY=V B only, KEY=V both. Frame options as for run."},
    {"model", cli_model, "DESIGN", "--json --set --data",
     "Prints the built model in SI units and world coordinates: bodies, joints, springs, geoms."},
    {"stiffness", cli_stiffness, "DESIGN", "--json --set --data",
     "Prints each chain's joint stiffness K (midfoot, MTP), analytic (exact geometry and the paper's\n"
     "  eq. 4) beside K measured in the ODE model, and the arch's static check under the design load.\n"
     "  Exit 1 when analytic and measured differ by more than 1 %."},
    {"terrain", cli_terrain, "TERRAIN", "--height --png --replace --scenario --set --data",
     "Describes a terrain file: --height X Y prints the surface height (m) at (X, Y), the surface the\n"
     "  foot collides with; --png FILE writes a shaded top-down picture; with neither, a summary.\n"
     "  --scenario S: both over S's region (the foot's footprint at its start and the margin), the\n"
     "  picture with the footprint drawn."},
    {"trial", cli_trial, "SCENARIO", "--seed --json --out --replace --frames --fps --size --camera --exaggerate --video --set --data",
     "Runs one landing trial of a trial scenario (scenarios/landing_trial.ini) for --seed N (1):\n"
     "  the drawn pose, the outcome (landed, fell or undecided), the rule that decided it and the\n"
     "  metrics. With --frames (or --out DIR) it also writes DIR/trial.json, its time series\n"
     "  DIR/trajectory.csv (with the robot's lean: footsim plot DIR draws it) and the frames of\n"
     "  exactly that trial (default DIR: results/trials/<scenario>-seed<N>/)."},
    {"campaign", cli_campaign, "CAMPAIGN", "-j --out --replace --set --frames-of --fps --size --camera --exaggerate --data --shard --fresh",
     "Runs every foot on every terrain for every seed of a campaign file (docs/campaign.md) in -j N\n"
     "  worker processes (default: the CPUs it may use) and writes DIR/summary.md, summary.csv, summary.json,\n"
     "  trials.csv, schema.sql and success.png (default DIR: results/campaigns/<campaign name>/). Exit 1 when an\n"
     "  expectation of the file fails. --set campaign.seeds=5 changes the campaign file; other\n"
     "  sections go to every trial. --frames-of foot=F,terrain=T,robot=R,seed=N (any of them; repeat\n"
     "  a key with / for several values: seed=1/3) also draws the chosen trials into\n"
     "  DIR/frames/<foot>-<terrain>-<robot>-seed<N>/ (frame options as for run); results unchanged.\n"
     "  Each finished trial is kept in the journal DIR.journal/ as it ends: run the same command again\n"
     "  after a crash or Ctrl-C and it runs only the trials left (the files are the same as an\n"
     "  uninterrupted run's); a journal of other inputs, overrides or version is refused (exit 2);\n"
     "  a finished DIR of the same campaign is left as it is; --fresh starts over. Ctrl-C or SIGTERM\n"
     "  stops the workers, keeps the journal, prints the command that continues; exit 130 or 143.\n"
     "  --shard I/N runs only the trials whose index is I-1 modulo N and writes DIR/trials.journal;\n"
     "  'footsim merge' makes the campaign's files of the N shard folders."},
    {"merge", cli_merge, "DIR...", "--out --replace --force",
     "Merges the shard folders of one campaign (footsim campaign --shard I/N) into its result files,\n"
     "  the same bytes as the campaign run on one machine (default DIR: results/campaigns/<name>/).\n"
     "  Refused (exit 2, saying which) when the shards come from other campaigns, inputs, overrides or\n"
     "  versions, or when trials are missing or repeated. Exit 1 when an expectation fails. --force\n"
     "  merges shards run by another footsim version (said, both versions named): the summaries are\n"
     "  this version's (its laws) and their provenance names it; use it only where the two versions'\n"
     "  trials are the same bits (rerun a shard's trials to check)."},
    {"optimize", cli_optimize, "FILE", "-j --out --replace --set --data",
     "Searches a design (docs/landing.md, fs_optimize.h): the parameters of the file's [param.NAME]\n"
     "  sections within their bounds for the least stiff design whose trials (its campaign's) meet the\n"
     "  campaign's expectations, by NLopt's Subplex on common seeds; reruns the best on fresh seeds and\n"
     "  writes DIR/result.md and evaluations.csv (default DIR: results/optimize/<name>/). Exit 1 when\n"
     "  the best misses a target. --set optimize.max_evaluations=N; other sections go to the campaign."},
    {"compare", cli_compare, "RESULT BASELINE", "--force --equivalence --json --all",
     "Compares two summary.json files and prints, as Markdown, what is outside what the baseline\n"
     "  allows (--all: every quantity of every cell, with its verdict), or with --json one JSON object:\n"
     "  every quantity with its baseline, result, allowed range and verdict, the provenance's\n"
     "  differences (a changed input by its path), the counts, the verdict and the exit status.\n"
     "  A step count (median_steps) is reported, never judged. Exit 0 when every quantity is within,\n"
     "  1 when a success rate leaves the baseline's 95 % interval, a cell has more undecided or hung\n"
     "  trials, a median moves further than the baseline's tolerance or a cell is missing; 2 when a\n"
     "  file cannot be read as a campaign's summary.json; 6 when they were made with other seeds,\n"
     "  overrides or input files, unless --force (a version or settings that differ are only\n"
     "  reported). --equivalence judges RESULT, run at another setting (--set run.step_s=...),\n"
     "  against BASELINE as a reference campaign of the same seeds and inputs: exit 1 unless every\n"
     "  cell's success intervals overlap and its medians of impulse, final lean, ankle drop at rest,\n"
     "  settle time and contacts lie within 5 % or a floor (docs/bench.md)."},
    {"plot", cli_plot, "RUN_DIR|CAMPAIGN_DIR", "--out --replace",
     "Draws a results folder with gnuplot (PNG). A run's folder (footsim run): its trajectory.csv as\n"
     "  DIR/plot.png: ankle drop, contact points, every chain's joint angles and spring-damper forces\n"
     "  against time (script DIR/plot.gp). A campaign's folder: its chart drawn again from summary.json\n"
     "  as DIR/success.png (chart.dat, chart.gp). DIR is the folder itself unless --out DIR."},
    {"walk", cli_walk, "SCENARIO", "--json --out --replace --frames --fps --size --camera --exaggerate --video --set --data",
     "Runs the walking machine of a walk scenario (scenarios/walking.ini): steps completed, falls,\n"
     "  toe contact points on the rough section and off it, peak ground force. With --frames (or\n"
     "  --out DIR) it also writes DIR/walk.json and the frames of the walk (default DIR:\n"
     "  results/walks/<scenario>/), whole."},
    {"bench", cli_bench, "precision|stability|speed|equivalence [CAMPAIGN]",
     "-j --quick --out --replace --set --reference --steps --data",
     "Benchmarks (docs/bench.md), written to DIR (default: build/bench/; the committed results are\n"
     "  refreshed only with --out results/bench):\n"
     "  precision  run time against error: ODE's steppers, step sizes and both spring implementations\n"
     "             against the planar reference model, and a landing trial against its finest run;\n"
     "             last, campaign equivalence of scenarios/equivalence_flat.ini (DIR/precision_equivalence/);\n"
     "  stability  where the numerics break: step size x stiffness x load x mass ratio x drop height;\n"
     "  speed      steps per second of each shipped scenario, where the time goes, what each skip saves;\n"
     "  equivalence  a campaign (default scenarios/equivalence_flat.ini) at the --reference step (1e-5)\n"
     "             and at each of --steps (1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,1e-2), with the same seeds and\n"
     "             workers, each judged against the reference as 'footsim compare --equivalence' does;\n"
     "             --set goes to the campaign (before the step). Writes DIR/equivalence.md (a row a step:\n"
     "             verdict, quantities that differ, wall time, speed-up on the reference), DIR/h<STEP>.md\n"
     "             (each comparison) and DIR/reference/ (default DIR: build/equivalence/<campaign name>/).\n"
     "             Exit 0 whatever the verdicts.\n"
     "  --quick runs a smaller sweep (minutes instead of tens of minutes); -j N runs stability in N\n"
     "  worker processes (default: the CPUs it may use; the results do not depend on N), and each\n"
     "  campaign of equivalence in N (default 1, so that wall times compare)."},
    {"export", cli_export, "DESIGN", "--mjcf --scenario --out --replace --set --data",
     "Writes the foot as MuJoCo MJCF (docs/export.md) to --out FILE (default results/export/<design>.xml;\n"
     "  a file there that footsim did not export is kept unless --replace):\n"
     "  bodies with their masses and inertias, the hinges as a tree, the springs as spatial tendons, the\n"
     "  contact spheres and box; with --scenario S, in S's start pose with its ground (a heightfield's\n"
     "  samples in FILE's name with .hfield.bin), gravity, step, robot and load."},
    {"keys", cli_keys, NULL, "",
     "Prints every key of design and scenario files: unit, allowed range, default, meaning (Markdown)."},
    {"demo", cli_demo, NULL, "--data",
     "Runs the paper's first experiments (static load, 10 degree tilt) and the stiffness check,\n"
     "  and says where the results went."},
};
enum { NCOMMANDS = sizeof commands / sizeof commands[0] };

static void usage(FILE *out)
{
    fprintf(out, "usage: footsim COMMAND [ARGS] [OPTIONS]\n       footsim --version\n\ncommands:\n");
    for (int i = 0; i < NCOMMANDS; i++)
        fprintf(out, "  %-10s %s %s\n", commands[i].name, commands[i].input ? commands[i].input : "",
                commands[i].options);
    fprintf(out, "\n'footsim COMMAND --help' says more. Exit status: 0 ok, 1 expectations failed, 2 bad input,\n"
                 "3 numerical failure, 4 results could not be written, 5 out of memory.\n");
}

static void command_help(const command *c)
{
    printf("usage: footsim %s%s%s", c->name, c->input ? " " : "", c->input ? c->input : "");
    if (strstr(c->options, "--mjcf"))
        printf(" --mjcf [--scenario SCENARIO] [--out FILE [--replace]]");
    else if (strstr(c->options, "--replace") && strstr(c->options, "--out"))
        printf(" [--out DIR [--replace]]");
    else if (strstr(c->options, "--out"))
        printf(" [--out DIR]");
    if (strstr(c->options, "-j "))
        printf(" [-j N]");
    if (strstr(c->options, "--seed"))
        printf(" [--seed N]");
    if (strstr(c->options, "--json"))
        printf(" [--json]");
    if (strstr(c->options, "--quick"))
        printf(" [--quick]");
    if (strstr(c->options, "--force"))
        printf(" [--force]");
    if (strstr(c->options, "--equivalence"))
        printf(" [--equivalence] [--all]");
    if (strstr(c->options, "--shard"))
        printf(" [--shard I/N] [--fresh]");
    if (strstr(c->options, "--steps"))
        printf(" [--reference S] [--steps S1,S2,...]");
    if (strstr(c->options, "--height"))
        printf(" [--height X Y] [--png FILE [--replace]] [--scenario SCENARIO]");
    if (strstr(c->options, "--frames "))
        printf(" [--frames [--fps N] [--size WxH] [--camera NAME] [--exaggerate F] [--video]]");
    if (strstr(c->options, "--frames-of"))
        printf(" [--frames-of SELECTORS [--fps N] [--size WxH] [--camera NAME] [--exaggerate F]]");
    if (strstr(c->options, "--set"))
        printf(" [--set section.key=value]...");
    if (strstr(c->options, "--data"))
        printf(" [--data DIR]");
    printf("\n\n  %s\n", c->help);
    if (strstr(c->options, "--replace") && (!strcmp(c->name, "bench") || !strcmp(c->name, "plot")))
        printf("\n  DIR is written file by file, each whole, never replaced as a folder; a non-empty folder\n"
               "  without footsim's %s marker or only %s files in it is refused unless --replace.\n", FS_MARKER,
               c->name);
    else if (strstr(c->options, "--replace") && !strstr(c->options, "--out"))
        printf("\n  An existing FILE is replaced only when it is a PNG already; anything else there (a user's\n"
               "  notes, data) is refused unless --replace is given.\n");
    else if (strstr(c->options, "--replace"))
        printf("\n  DIR is replaced whole, and only when footsim made it (its %s marker, or an earlier\n"
               "  version's files): a non-empty folder of anything else is refused unless --replace is given.\n",
               FS_MARKER);
    if (strstr(c->options, "--data"))
        printf("\n  A relative design, scenario, terrain or campaign path not found as given is looked for under\n"
               "  --data DIR, then the current folder, then the installed data (%s), each\n"
               "  as given and in its scenarios/, scenarios/feet/ or terrains/ folder ('footsim run static_load.ini'\n"
               "  works anywhere); the shipped scenarios demo and bench run are found the same way.\n",
               cli_data_installed());
    if (strstr(c->options, "--set"))
        printf("\n  --set overrides one value of the file (or, for a scenario, of its design) without editing\n"
               "  it, checked like the file itself; repeat it for several. 'footsim keys' lists them all.\n"
               "  Paths: a relative path in --set (--set scenario.design=myfoot.ini) is looked for from the\n"
               "  current folder first, then relative to the file it overrides; a path inside a file is\n"
               "  relative to that file. Either, when not there, is looked for under --data DIR, the current\n"
               "  folder and the installed data, each in scenarios/, terrains/ and itself.\n");
}

/* Whether the space-separated options list names option as a whole word (--frames is not
 * --frames-of). */
static int takes_option(const char *options, const char *option)
{
    size_t n = strlen(option);
    for (const char *p = strstr(options, option); p; p = strstr(p + 1, option))
        if ((p == options || p[-1] == ' ') && (p[n] == ' ' || p[n] == 0))
            return 1;
    return 0;
}

/* Parses argv after the command name into a, refusing what c does not take. */
static int parse_args(const command *c, int argc, char **argv, cli_args *a)
{
    for (int i = 0; i < argc; i++) {
        const char *arg = argv[i];
        if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) {
            command_help(c);
            return -1;
        }
        int takes_value = !strcmp(arg, "--out") || !strcmp(arg, "--data") || !strcmp(arg, "--set") || !strcmp(arg, "--fps") ||
                          !strcmp(arg, "--size") || !strcmp(arg, "--camera") || !strcmp(arg, "--png") ||
                          !strcmp(arg, "--scenario") || !strcmp(arg, "--height") || !strcmp(arg, "-j") ||
                          !strcmp(arg, "--seed") || !strcmp(arg, "--exaggerate") || !strcmp(arg, "--frames-of") ||
                          !strcmp(arg, "--shard") || !strcmp(arg, "--reference") || !strcmp(arg, "--steps");
        if (!strcmp(arg, "-j") && !strstr(c->options, "-j ")) {
            fprintf(stderr, "footsim %s: unknown option -j; it takes: %s\n", c->name, *c->options ? c->options : "no options");
            return 2;
        }
        if (arg[0] == '-' && arg[1] == '-' && !takes_option(c->options, arg)) {
            fprintf(stderr, "footsim %s: unknown option %s; it takes: %s\n", c->name, arg,
                    *c->options ? c->options : "no options");
            return 2;
        }
        if (takes_value && i + 1 >= argc) {
            fprintf(stderr, "footsim %s: %s needs a value\n", c->name, arg);
            return 2;
        }
        if (!strcmp(arg, "--height") && i + 2 >= argc) {
            fprintf(stderr, "footsim %s: --height needs two values, X and Y in metres\n", c->name);
            return 2;
        }
        if (!strcmp(arg, "--out") && a->out) {
            fprintf(stderr, "footsim %s: --out given twice (%s and %s); give one folder\n", c->name, a->out, argv[i + 1]);
            return 2;
        }
        if (!strcmp(arg, "--out"))
            a->out = argv[++i];
        else if (!strcmp(arg, "--height")) {
            a->height_x = argv[++i];
            a->height_y = argv[++i];
        } else if (!strcmp(arg, "--data"))
            a->data = argv[++i];
        else if (!strcmp(arg, "--png"))
            a->png = argv[++i];
        else if (!strcmp(arg, "--scenario"))
            a->scenario = argv[++i];
        else if (!strcmp(arg, "--seed"))
            a->seed = argv[++i];
        else if (!strcmp(arg, "-j"))
            a->jobs = argv[++i];
        else if (!strncmp(arg, "-j", 2) && strstr(c->options, "-j "))
            a->jobs = arg + 2;
        else if (!strcmp(arg, "--shard"))
            a->shard = argv[++i];
        else if (!strcmp(arg, "--reference"))
            a->reference = argv[++i];
        else if (!strcmp(arg, "--steps"))
            a->steps = argv[++i];
        else if (!strcmp(arg, "--fresh"))
            a->fresh = 1;
        else if (!strcmp(arg, "--replace"))
            a->replace = 1;
        else if (!strcmp(arg, "--quick"))
            a->quick = 1;
        else if (!strcmp(arg, "--force") && strstr(c->options, "--force"))
            a->force = 1;
        else if (!strcmp(arg, "--equivalence") && strstr(c->options, "--equivalence"))
            a->equivalence = 1;
        else if (!strcmp(arg, "--all") && strstr(c->options, "--all"))
            a->all = 1;
        else if (!strcmp(arg, "--json"))
            a->json = 1;
        else if (!strcmp(arg, "--mjcf"))
            a->mjcf = 1;
        else if (!strcmp(arg, "--frames"))
            a->frames = 1;
        else if (!strcmp(arg, "--video"))
            a->video = a->frames = 1;
        else if (!strcmp(arg, "--fps"))
            a->fps = argv[++i];
        else if (!strcmp(arg, "--size"))
            a->size = argv[++i];
        else if (!strcmp(arg, "--camera"))
            a->camera = argv[++i];
        else if (!strcmp(arg, "--exaggerate"))
            a->exaggerate = argv[++i];
        else if (!strcmp(arg, "--frames-of"))
            a->frames_of = argv[++i];
        else if (!strcmp(arg, "--set")) {
            if (a->nset == CLI_MAX_SET) {
                fprintf(stderr, "footsim %s: at most %d --set options\n", c->name, CLI_MAX_SET);
                return 2;
            }
            a->set[a->nset++] = argv[++i];
        } else if (c->input && !a->input)
            a->input = arg;
        else if (c->input && strchr(c->input, ' ') && !a->input2)
            a->input2 = arg;
        else if (c->input && strstr(c->input, "...") && a->nmore < CLI_MAX_SET)
            a->more[a->nmore++] = arg;
        else {
            fprintf(stderr, "footsim %s: unexpected argument '%s'; see 'footsim %s --help'\n", c->name, arg, c->name);
            return 2;
        }
    }
    if (c->input && !a->input) {
        fprintf(stderr, "footsim %s: give a %s file; see 'footsim %s --help'\n", c->name, c->input, c->name);
        return 2;
    }
    return 0;
}

/* What kind of data file a command's positional arguments are (compare's are results, bench's a name). */
static cli_data_kind data_kind(const char *command)
{
    static const char *const scenarios[] = {"run", "render-compare", "trial", "walk", "campaign", "optimize"};
    for (size_t i = 0; i < sizeof scenarios / sizeof *scenarios; i++)
        if (!strcmp(command, scenarios[i]))
            return CLI_DATA_SCENARIO;
    if (!strcmp(command, "model") || !strcmp(command, "stiffness") || !strcmp(command, "export"))
        return CLI_DATA_DESIGN;
    return !strcmp(command, "terrain") ? CLI_DATA_TERRAIN : CLI_DATA_NONE;
}

int cli_report(int status, const char *message)
{
    fprintf(stderr, "footsim: %s\n", message);
    return status;
}

int cli_results_dir(const cli_args *a, const char *kind, const char *name, char *dir, size_t size)
{
    fs_error err;
    fs_status s = a->out ? fs_path_format(dir, size, "--out", &err, "%s", a->out)
                         : fs_path_format(dir, size, "--out", &err, "results/%s/%s", kind, name);
    return s == FS_OK ? 0 : cli_report(s, err.message);
}

void *cli_zalloc(size_t size)
{
    void *p = calloc(1, size);
    if (!p)
        cli_report(FS_NO_MEMORY, "out of memory");
    return p;
}

/* The library's warnings (fs_warn), said on stderr. */
static void print_warning(const char *text, void *user)
{
    (void)user;
    fprintf(stderr, "footsim: warning: %s\n", text);
}

int main(int argc, char **argv)
{
    signal(SIGXFSZ, SIG_IGN); /* a file-size limit fails the write (EFBIG): exit 4 with a message */
    fs_warning_handler(print_warning, NULL);
    /* the command's process policy (the library sets none): what it leaves half written is
     * removed at exit and on SIGINT, SIGTERM and SIGHUP; a file-size limit (ulimit -f) is a write
     * error (exit 4, said, nothing half written left), not SIGXFSZ's silent death */
    signal(SIGXFSZ, SIG_IGN);
    fs_output_install_cleanup();
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? FS_BAD_INPUT : 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("footsim %s\n", fs_version());
        return 0;
    }
    for (int i = 0; i < NCOMMANDS; i++) {
        if (strcmp(argv[1], commands[i].name))
            continue;
        cli_args a = {.command = commands[i].name};
        int s = parse_args(&commands[i], argc - 2, argv + 2, &a);
        if (s)
            return s < 0 ? 0 : s;
        if (a.data && (s = cli_data_set_dir(a.data)) != 0)
            return s;
        cli_data_folders();
        /* relative data files not found as given: --data, here, the installed data */
        cli_data_kind kind = data_kind(a.command);
        char input[FS_PATH_MAX], input2[FS_PATH_MAX], scenario[FS_PATH_MAX]; /* live until the command ends */
        a.input = cli_data_find(a.input, kind, input, sizeof input);
        a.input2 = cli_data_find(a.input2, kind, input2, sizeof input2);
        a.scenario = cli_data_find(a.scenario, CLI_DATA_SCENARIO, scenario, sizeof scenario);
        fs_ode_init();
        s = commands[i].run(&a);
        fs_ode_close();
        return s;
    }
    fprintf(stderr, "footsim: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return FS_BAD_INPUT;
}
