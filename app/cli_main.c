/* cli_main.c: the footsim command: its subcommands, their options, --help, and argument checks.
 *
 * One typed table of options (cli_options) drives everything about them: which commands take each
 * option, what its argument is (none, one value, two values, a repeatable value), where it goes in
 * cli_args, its line in 'footsim --help' and in each command's usage, and through
 * tools/gen-commands-doc.sh docs/commands.md and the man page's OPTIONS section. */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/base/fs_path.h"
#include "footsim/base/fs_version.h"
#include "footsim/io/fs_config.h"
#include "footsim/io/fs_output.h"
#include "footsim/sim/fs_ode.h"

#include <cjson/cJSON.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The commands, one bit each, for the options table. */
enum {
    CMD_RUN = 1 << 0, CMD_RENDER_COMPARE = 1 << 1, CMD_MODEL = 1 << 2, CMD_STIFFNESS = 1 << 3, CMD_TERRAIN = 1 << 4,
    CMD_TRIAL = 1 << 5, CMD_CAMPAIGN = 1 << 6, CMD_MERGE = 1 << 7, CMD_OPTIMIZE = 1 << 8, CMD_COMPARE = 1 << 9,
    CMD_PLOT = 1 << 10, CMD_WALK = 1 << 11, CMD_BENCH = 1 << 12, CMD_EXPORT = 1 << 13, CMD_KEYS = 1 << 14,
    CMD_DEMO = 1 << 15
};

/* What an option takes. */
typedef enum cli_arg {
    ARG_FLAG,   /* nothing: sets an int to 1 */
    ARG_VALUE,  /* one value: a const char * */
    ARG_PAIR,   /* two values: two const char * */
    ARG_REPEAT  /* one value, repeatable: appended to cli_args.set */
} cli_arg;

typedef struct cli_option {
    const char *name;   /* "--out" */
    cli_arg arg;
    const char *value;  /* what its value is called in usage ("DIR"; a pair's "X Y") */
    unsigned commands;  /* the commands that take it */
    unsigned as_file;   /* of those, the ones whose value is a FILE, not value (export --out) */
    unsigned required;  /* of those, the ones it must be given to (usage shows it unbracketed) */
    size_t field, field2; /* where it goes in cli_args (field2: a pair's second value) */
    const char *help;   /* what it does, for --help, docs/commands.md and the man page */
} cli_option;

#define FIELD(f) offsetof(cli_args, f)
enum {
    CMD_FRAMES_TAKERS = CMD_RUN | CMD_RENDER_COMPARE | CMD_TRIAL | CMD_CAMPAIGN | CMD_WALK,
    CMD_SETS = CMD_RUN | CMD_RENDER_COMPARE | CMD_MODEL | CMD_STIFFNESS | CMD_TERRAIN | CMD_TRIAL | CMD_CAMPAIGN |
               CMD_OPTIMIZE | CMD_WALK | CMD_BENCH | CMD_EXPORT,
    CMD_OUTS = CMD_RUN | CMD_RENDER_COMPARE | CMD_TRIAL | CMD_CAMPAIGN | CMD_MERGE | CMD_OPTIMIZE | CMD_PLOT | CMD_WALK |
               CMD_BENCH | CMD_EXPORT
};

static const cli_option options[] = {
    {"--mjcf", ARG_FLAG, NULL, CMD_EXPORT, 0, CMD_EXPORT, FIELD(mjcf), 0,
     "export as MuJoCo MJCF (the one format export writes)"},
    {"--scenario", ARG_VALUE, "SCENARIO", CMD_TERRAIN | CMD_EXPORT, 0, 0, FIELD(scenario), 0,
     "a scenario: terrain describes the terrain over its region; export puts the foot in its start pose on its ground"},
    {"--out", ARG_VALUE, "DIR", CMD_OUTS, CMD_EXPORT, 0, FIELD(out), 0,
     "where the results go (export: the file). A results folder is replaced whole, and only when footsim made it "
     "(its .footsim-results marker says so, never its files' names); a path too long to use whole (over PATH_MAX "
     "less 512 characters, or a name over NAME_MAX less 32) is refused, exit 2"},
    {"--replace", ARG_FLAG, NULL, CMD_OUTS | CMD_TERRAIN, 0, 0, FIELD(replace), 0,
     "replace on purpose a folder (or a file) footsim did not make"},
    {"-j", ARG_VALUE, "N", CMD_CAMPAIGN | CMD_OPTIMIZE | CMD_BENCH, 0, 0, FIELD(jobs), 0,
     "worker processes, 1 to 1024 (also -jN); default: the CPUs this process may use (bench equivalence: 1); "
     "the results do not depend on it"},
    {"--seed", ARG_VALUE, "N", CMD_TRIAL | CMD_EXPORT, 0, 0, FIELD(seed), 0,
     "the trial's seed (default 1); export: the start pose that trial draws (with --scenario)"},
    {"--json", ARG_FLAG, NULL, CMD_MODEL | CMD_STIFFNESS | CMD_TRIAL | CMD_COMPARE | CMD_WALK, 0, 0, FIELD(json), 0,
     "print the result as JSON"},
    {"--quick", ARG_FLAG, NULL, CMD_BENCH, 0, 0, FIELD(quick), 0, "a smaller sweep: minutes instead of tens of minutes"},
    {"--scene", ARG_VALUE, "NAME[,NAME...]", CMD_BENCH, 0, 0, FIELD(scene), 0,
     "bench precision: run only the named scenes (chain, landing_flat, landing_biomimetic, landing_biomimetic_rough, "
     "flat_rig_TERRAIN: docs/bench.md), with --quick too, and skip the campaign-equivalence stage; bench stability: "
     "run only the named slices (stiffness, load, mass, drop, soil, law); an unknown name is refused, exit 2"},
    {"--force", ARG_FLAG, NULL, CMD_COMPARE | CMD_MERGE, 0, 0, FIELD(force), 0,
     "compare results made of other seeds, overrides or input files (reported, not refused); merge shards "
     "run by another footsim version"},
    {"--equivalence", ARG_FLAG, NULL, CMD_COMPARE, 0, 0, FIELD(equivalence), 0,
     "judge RESULT, run at another setting, against BASELINE as a reference campaign (docs/bench.md)"},
    {"--all", ARG_FLAG, NULL, CMD_COMPARE, 0, 0, FIELD(all), 0,
     "list every quantity of every cell with its verdict, not only those outside what the baseline allows"},
    {"--shard", ARG_VALUE, "I/N", CMD_CAMPAIGN, 0, 0, FIELD(shard), 0,
     "run only the trials whose index is I-1 modulo N (any N, 1/1 too) and write them to DIR/trials.journal, "
     "for merge"},
    {"--fresh", ARG_FLAG, NULL, CMD_CAMPAIGN, 0, 0, FIELD(fresh), 0,
     "start a campaign over: the journal of an interrupted run is removed, a finished folder run again"},
    {"--reference", ARG_VALUE, "S", CMD_BENCH, 0, 0, FIELD(reference), 0, "bench equivalence: the reference step, s (1e-5)"},
    {"--steps", ARG_VALUE, "S1,S2,...", CMD_BENCH, 0, 0, FIELD(steps), 0,
     "bench equivalence: the steps to judge, s (1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,1e-2)"},
    {"--height", ARG_PAIR, "X Y", CMD_TERRAIN, 0, 0, FIELD(height_x), FIELD(height_y),
     "print the surface height, m, at (X, Y), m: the surface the foot collides with"},
    {"--png", ARG_VALUE, "FILE", CMD_TERRAIN, 0, 0, FIELD(png), 0, "write a shaded top-down picture of the terrain"},
    {"--frames", ARG_FLAG, NULL, CMD_RUN | CMD_TRIAL | CMD_WALK, 0, 0, FIELD(frames), 0,
     "also draw DIR/frames/000000.png, ... (renderer builds only)"},
    {"--frames-of", ARG_VALUE, "SELECTORS", CMD_CAMPAIGN, 0, 0, FIELD(frames_of), 0,
     "also draw the chosen trials (foot=F,terrain=T,robot=R,seed=N; any of them; seed=1/3 for several) into "
     "DIR/frames/<foot>-<terrain>-<robot>-seed<N>/"},
    {"--fps", ARG_VALUE, "N", CMD_FRAMES_TAKERS, 0, 0, FIELD(fps), 0, "frames per simulated second (60)"},
    {"--size", ARG_VALUE, "WxH", CMD_FRAMES_TAKERS, 0, 0, FIELD(size), 0, "the frames' size in pixels (1280x720)"},
    {"--camera", ARG_VALUE, "NAME", CMD_FRAMES_TAKERS, 0, 0, FIELD(camera), 0,
     "foot (the foot filling the frame, the default), side, front, three-quarter or follow"},
    {"--exaggerate", ARG_VALUE, "F", CMD_FRAMES_TAKERS, 0, 0, FIELD(exaggerate), 0,
     "draw each body's displacement from its first pose, in the ankle body's frame, times F (said on every frame)"},
    {"--video", ARG_FLAG, NULL, CMD_RUN | CMD_RENDER_COMPARE | CMD_TRIAL | CMD_WALK, 0, 0, FIELD(video), 0,
     "also encode DIR/video.mp4 with ffmpeg (implies --frames)"},
    {"--set", ARG_REPEAT, "section.key=value", CMD_SETS, 0, 0, FIELD(set), 0,
     "override one value of the file without editing it, checked like the file; repeatable"},
    {"--data", ARG_VALUE, "DIR", CMD_SETS | CMD_DEMO, 0, 0, FIELD(data), 0,
     "where relative data files are looked for first (then the current folder, then the installed data)"},
};
enum { NOPTIONS = sizeof options / sizeof options[0] };

typedef struct command {
    const char *name;
    int (*run)(const cli_args *);
    unsigned id;          /* its bit */
    const char *input;    /* what the positional arguments are, or NULL when there are none */
    int npositional;      /* how many it takes: 0, 1, 2, or -1: one or more */
    cli_data_kind data;   /* what kind of data file its positional arguments are */
    const char *help;
} command;

static const command commands[] = {
    {"run", cli_run, CMD_RUN, "SCENARIO", 1, CLI_DATA_SCENARIO,
     "Runs a scenario until the foot is at rest and writes DIR/metrics.json and DIR/trajectory.csv\n"
     "  (default DIR: results/runs/<scenario name>/).\n"
     "  --frames writes DIR/frames/000000.png, ... at --fps (60) frames per simulated second, --size WxH\n"
     "  (1280x720), seen by --camera foot|side|front|three-quarter|follow (foot: the foot filling the\n"
     "  frame); --exaggerate F multiplies each body's displacement from its first pose, in the ankle\n"
     "  body's frame, by F (said on every frame); --video also encodes DIR/video.mp4 with ffmpeg."},
    {"render-compare", cli_render_compare, CMD_RENDER_COMPARE, "SCENARIO_A SCENARIO_B", 2, CLI_DATA_SCENARIO,
     "Runs both scenarios and writes their frames side by side (A left, B right) to DIR/frames/ and key\n"
     "  frames from touch-down to rest to DIR/filmstrip.png (default DIR: results/compare/A-foot_vs_B-foot/).\n"
     "  --set a:KEY=V changes A only, b:KEY=V B only, KEY=V both. Frame options as for run."},
    {"model", cli_model, CMD_MODEL, "DESIGN", 1, CLI_DATA_DESIGN,
     "Prints the built model in SI units and world coordinates: bodies, joints, springs, geoms."},
    {"stiffness", cli_stiffness, CMD_STIFFNESS, "DESIGN", 1, CLI_DATA_DESIGN,
     "Prints each chain's joint stiffness K (midfoot, MTP), analytic (exact geometry and the paper's\n"
     "  eq. 4) beside K measured in the ODE model, and the arch's static check under the design load.\n"
     "  A design with a nonlinear spring law (docs/model.md) also gets chain 3's K at that check's\n"
     "  gripping equilibrium, each law's tangent there (JSON: static_check.loaded_stiffness).\n"
     "  Exit 1 when analytic and measured differ by more than 1 %."},
    {"terrain", cli_terrain, CMD_TERRAIN, "TERRAIN", 1, CLI_DATA_TERRAIN,
     "Describes a terrain file: --height X Y prints the surface height (m) at (X, Y), the surface the\n"
     "  foot collides with; --png FILE writes a shaded top-down picture; with neither, a summary.\n"
     "  --scenario S: both over S's region (the foot's footprint at its start and the margin), the\n"
     "  picture with the footprint drawn."},
    {"trial", cli_trial, CMD_TRIAL, "SCENARIO", 1, CLI_DATA_SCENARIO,
     "Runs one landing trial of a trial scenario (scenarios/landing_trial.ini) for --seed N (1):\n"
     "  the drawn pose, the outcome (landed, fell or undecided), the rule that decided it and the\n"
     "  metrics. With --frames (or --out DIR) it also writes DIR/trial.json, its time series\n"
     "  DIR/trajectory.csv (with the robot's lean: footsim plot DIR draws it) and the frames of\n"
     "  exactly that trial (default DIR: results/trials/<scenario>-seed<N>/). On a soil (a terrain\n"
     "  with [soil], docs/soil.md) DIR also gets the soil's final surface: surface.png (16-bit\n"
     "  heightmap), surface.csv (mm), surface.provenance.json and surface.ini (a terrain file that\n"
     "  loads it back as rigid ground)."},
    {"campaign", cli_campaign, CMD_CAMPAIGN, "CAMPAIGN", 1, CLI_DATA_SCENARIO,
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
    {"merge", cli_merge, CMD_MERGE, "DIR...", -1, CLI_DATA_NONE,
     "Merges the shard folders of one campaign (footsim campaign --shard I/N) into its result files,\n"
     "  the same bytes as the campaign run on one machine (default DIR: results/campaigns/<name>/).\n"
     "  Refused (exit 2, saying which) when the shards come from other campaigns, inputs, overrides or\n"
     "  versions, or when trials are missing or repeated. Exit 1 when an expectation fails. --force\n"
     "  merges shards run by another footsim version (said, both versions named): the summaries are\n"
     "  this version's (its laws) and their provenance names it; use it only where the two versions'\n"
     "  trials are the same bits (rerun a shard's trials to check)."},
    {"optimize", cli_optimize, CMD_OPTIMIZE, "FILE", 1, CLI_DATA_SCENARIO,
     "Searches a design (docs/landing.md, fs_optimize.h): the parameters of the file's [param.NAME]\n"
     "  sections within their bounds for the least stiff design whose trials (its campaign's) meet the\n"
     "  campaign's expectations, and with [optimize] relative_to = FOOT land at least as often as that\n"
     "  foot (run once) in every terrain and robot, within its [constraint.NAME] bounds, by NLopt's\n"
     "  Subplex on common seeds; reruns the best on fresh seeds and writes DIR/result.md,\n"
     "  evaluations.csv and the trade-off's Pareto front pareto.csv, pareto.png (default DIR:\n"
     "  results/optimize/<name>/). Exit 1 when the best misses a target. With [optimize] sweep =\n"
     "  NAME.max (or .min) and sweep_values = v1, v2, ...: one search per value of that constraint's\n"
     "  bound, each in its folder DIR/NAME_max_v/, and DIR/front.csv, front.png, result.md of their\n"
     "  bests (exit 1 when none meets every target). --set optimize.max_evaluations=N; other sections\n"
     "  go to the campaign."},
    {"compare", cli_compare, CMD_COMPARE, "RESULT BASELINE", 2, CLI_DATA_NONE,
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
    {"plot", cli_plot, CMD_PLOT, "RUN_DIR|CAMPAIGN_DIR", 1, CLI_DATA_NONE,
     "Draws a results folder with gnuplot (PNG). A run's folder (footsim run): its trajectory.csv as\n"
     "  DIR/plot.png: ankle drop, contact points, every chain's joint angles and spring-damper forces\n"
     "  against time (script DIR/plot.gp). A campaign's folder: its chart drawn again from summary.json\n"
     "  as DIR/success.png (chart.dat, chart.gp). DIR is the folder itself unless --out DIR."},
    {"walk", cli_walk, CMD_WALK, "SCENARIO", 1, CLI_DATA_SCENARIO,
     "Runs the walking machine of a walk scenario (scenarios/walking.ini): steps completed, falls,\n"
     "  toe contact points on the rough section and off it, peak ground force. With --frames (or\n"
     "  --out DIR) it also writes DIR/walk.json and the frames of the walk (default DIR:\n"
     "  results/walks/<scenario>/), whole. On a soil (a terrain with [soil], docs/soil.md) each step's\n"
     "  sinkage, slip and the energy the soil took are printed and in walk.json, each printed step\n"
     "  \"on the soil\", or \"on rigid ground\" where its stance was beyond a soil section, and DIR\n"
     "  also gets the soil's final surface: surface.png, .csv, .provenance.json and .ini, as trial\n"
     "  writes it."},
    {"bench", cli_bench, CMD_BENCH, "precision|stability|speed|equivalence [CAMPAIGN]", 2, CLI_DATA_NONE,
     "Benchmarks (docs/bench.md), written to DIR (default: build/bench/; the committed results are\n"
     "  refreshed only with --out results/bench):\n"
     "  precision  run time against error: ODE's steppers, step sizes and both spring implementations\n"
     "             against the planar reference model, and a landing trial against its finest run;\n"
     "             last, campaign equivalence of scenarios/equivalence_flat.ini (DIR/precision_equivalence/);\n"
     "             --scene NAME[,NAME...] runs only those scenes (their rows, fronts and goals; a\n"
     "             flat_rig_* scene with --quick too) and skips the equivalence stage;\n"
     "  stability  where the numerics break: step size x stiffness x load x mass ratio x drop height x\n"
     "             soil x spring law; --scene SLICE[,SLICE...] runs only those slices (stiffness, load,\n"
     "             mass, drop, soil, law) and writes their tables, charts and safe envelope alone;\n"
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
    {"export", cli_export, CMD_EXPORT, "DESIGN", 1, CLI_DATA_DESIGN,
     "Writes the foot as MuJoCo MJCF (docs/export.md) to --out FILE (default results/export/<design>.xml;\n"
     "  a file there that footsim did not export is kept unless --replace):\n"
     "  bodies with their masses and inertias, the hinges as a tree, the springs as spatial tendons, the\n"
     "  contact spheres and box; with --scenario S, in S's start pose with its ground (a heightfield's\n"
     "  samples in FILE's name with .hfield.bin), gravity, step, robot and load. --seed N (a trial\n"
     "  scenario): in the start pose trial N draws, on its terrain (tools/mujoco_trial.c runs it)."},
    {"keys", cli_keys, CMD_KEYS, NULL, 0, CLI_DATA_NONE,
     "Prints every key of design, scenario, terrain, robot, campaign and design search files: unit,\n"
     "  allowed range, default, meaning (Markdown)."},
    {"demo", cli_demo, CMD_DEMO, NULL, 0, CLI_DATA_NONE,
     "Runs the paper's first experiments (static load, 10 degree tilt) and the stiffness check,\n"
     "  and says where the results went."},
};
enum { NCOMMANDS = sizeof commands / sizeof commands[0] };

static int takes(const command *c, const cli_option *o) { return (o->commands & c->id) != 0; }

/* The option called name (exact), or NULL. */
static const cli_option *option_named(const char *name)
{
    for (int k = 0; k < NOPTIONS; k++)
        if (!strcmp(options[k].name, name))
            return &options[k];
    return NULL;
}

/* The option's value as a command's usage names it. */
static const char *value_of(const command *c, const cli_option *o)
{
    return o->as_file & c->id ? "FILE" : o->value;
}

/* The names of the options c takes, separated by spaces, into buf. */
static const char *option_names(const command *c, char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = 0;
    for (int k = 0; k < NOPTIONS && n < size; k++)
        if (takes(c, &options[k]))
            n += (size_t)snprintf(buf + n, size - n, "%s%s", n ? " " : "", options[k].name);
    return buf;
}

/* Prints text wrapped to `width` columns, each line after `indent` spaces (the first's already there). */
static void print_wrapped(FILE *out, const char *text, int indent, int width)
{
    int col = indent;
    const char *p = text;
    while (*p) {
        size_t w = strcspn(p, " ");
        if (col > indent && col + 1 + (int)w > width) {
            fprintf(out, "\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
            fputc(' ', out);
            col++;
        }
        fprintf(out, "%.*s", (int)w, p);
        col += (int)w;
        p += w;
        while (*p == ' ')
            p++;
    }
    fputc('\n', out);
}

/* One option's line of a list: name and value, then its help wrapped beside them; with commands,
 * which commands take it. */
static void print_option(FILE *out, const cli_option *o, const char *value, int with_commands)
{
    char head[64], text[1024];
    snprintf(head, sizeof head, "  %s%s%s", o->name, value ? " " : "", value ? value : "");
    size_t n = (size_t)snprintf(text, sizeof text, "%s", o->help);
    if (with_commands) {
        n += (size_t)snprintf(text + n, sizeof text - n, " [");
        for (int i = 0, first = 1; i < NCOMMANDS && n < sizeof text; i++)
            if (takes(&commands[i], o)) {
                n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", first ? "" : ", ", commands[i].name);
                first = 0;
            }
        if (n < sizeof text)
            snprintf(text + n, sizeof text - n, "]");
    }
    int len = (int)strlen(head);
    enum { COL = 26 };
    if (len + 2 > COL)
        fprintf(out, "%s\n%*s", head, COL, "");
    else
        fprintf(out, "%s%*s", head, COL - len, "");
    print_wrapped(out, text, COL, 100);
}

static void usage(FILE *out)
{
    fprintf(out, "usage: footsim COMMAND [ARGS] [OPTIONS]\n       footsim --version\n\ncommands:\n");
    char names[512];
    for (int i = 0; i < NCOMMANDS; i++)
        fprintf(out, "  %-10s %s %s\n", commands[i].name, commands[i].input ? commands[i].input : "",
                option_names(&commands[i], names, sizeof names));
    fprintf(out, "\noptions [the commands that take each]:\n");
    for (int k = 0; k < NOPTIONS; k++)
        print_option(out, &options[k], options[k].value, 1);
    fprintf(out, "  --help, -h                this help; after a command, the command's\n"
                 "  --version                 the version and the git description footsim was built from\n");
    fprintf(out, "\n'footsim COMMAND --help' says more. Exit status: 0 ok, 1 expectations failed, 2 bad input,\n"
                 "3 numerical failure, 4 results could not be written, 5 out of memory.\n");
}

static void command_help(const command *c)
{
    printf("usage: footsim %s%s%s", c->name, c->input ? " " : "", c->input ? c->input : "");
    for (int k = 0; k < NOPTIONS; k++) {
        const cli_option *o = &options[k];
        if (!takes(c, o))
            continue;
        const char *open = o->required & c->id ? "" : "[", *close = o->required & c->id ? "" : "]";
        if (o->arg == ARG_FLAG)
            printf(" %s%s%s", open, o->name, close);
        else
            printf(" %s%s %s%s%s", open, o->name, value_of(c, o), close, o->arg == ARG_REPEAT ? "..." : "");
    }
    printf("\n\n  %s\n", c->help);
    int any = 0;
    for (int k = 0; k < NOPTIONS; k++)
        if (takes(c, &options[k])) {
            if (!any++)
                printf("\n  options:\n");
            print_option(stdout, &options[k], options[k].arg == ARG_FLAG ? NULL : value_of(c, &options[k]), 0);
        }
    const cli_option *out = option_named("--out"), *replace = option_named("--replace");
    if (takes(c, replace) && (c->id & (CMD_BENCH | CMD_PLOT)))
        printf("\n  DIR is written file by file, each whole, never replaced as a folder; a non-empty folder\n"
               "  without footsim's %s marker or only %s files in it is refused unless --replace.\n", FS_MARKER,
               c->name);
    else if (takes(c, replace) && (!takes(c, out) || (out->as_file & c->id)))
        printf("\n  An existing FILE is replaced only when it is %s already; anything else there (a user's\n"
               "  notes, data) is refused unless --replace is given.\n", c->id & CMD_EXPORT ? "footsim's export" : "a PNG");
    else if (takes(c, replace))
        printf("\n  DIR is replaced whole, and only when footsim made it (its %s marker, or an earlier\n"
               "  version's files): a non-empty folder of anything else is refused unless --replace is given.\n",
               FS_MARKER);
    if (takes(c, option_named("--data")))
        printf("\n  A relative design, scenario, terrain or campaign path not found as given is looked for under\n"
               "  --data DIR, then the current folder, then the installed data (%s), each\n"
               "  as given and in its scenarios/, scenarios/feet/ or terrains/ folder ('footsim run static_load.ini'\n"
               "  works anywhere); the shipped scenarios demo and bench run are found the same way.\n",
               cli_data_installed());
    if (takes(c, option_named("--set")))
        printf("\n  --set overrides one value of the file (or, for a scenario, of its design) without editing\n"
               "  it, checked like the file itself; repeat it for several. 'footsim keys' lists them all.\n"
               "  Paths: a relative path in --set (--set scenario.design=myfoot.ini) is looked for from the\n"
               "  current folder first, then relative to the file it overrides; a path inside a file is\n"
               "  relative to that file. Either, when not there, is looked for under --data DIR, the current\n"
               "  folder and the installed data, each in scenarios/, terrains/ and itself.\n");
}

static int unknown_option(const command *c, const char *arg)
{
    char names[512];
    option_names(c, names, sizeof names);
    fprintf(stderr, "footsim %s: unknown option %s; it takes: %s\n", c->name, arg, *names ? names : "no options");
    return FS_BAD_INPUT;
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
        const cli_option *o = option_named(arg);
        const char *attached = NULL; /* -jN */
        if (!o && !strncmp(arg, "-j", 2) && arg[2]) {
            o = option_named("-j");
            attached = arg + 2;
        }
        if (o && !takes(c, o))
            return unknown_option(c, arg);
        if (!o && arg[0] == '-' && arg[1] == '-')
            return unknown_option(c, arg);
        if (!o) { /* a positional argument */
            if (c->npositional != 0 && !a->input)
                a->input = arg;
            else if (c->npositional == 2 && !a->input2)
                a->input2 = arg;
            else if (c->npositional < 0 && a->nmore < CLI_MAX_SET)
                a->more[a->nmore++] = arg;
            else {
                fprintf(stderr, "footsim %s: unexpected argument '%s'; see 'footsim %s --help'\n", c->name, arg,
                        c->name);
                return FS_BAD_INPUT;
            }
            continue;
        }
        int nvalues = o->arg == ARG_FLAG || attached ? 0 : o->arg == ARG_PAIR ? 2 : 1;
        if (i + nvalues >= argc) {
            if (o->arg == ARG_PAIR)
                fprintf(stderr, "footsim %s: %s needs two values, %s\n", c->name, arg, o->value);
            else
                fprintf(stderr, "footsim %s: %s needs a value\n", c->name, arg);
            return FS_BAD_INPUT;
        }
        char *base = (char *)a;
        const char **field = (const char **)(void *)(base + o->field);
        switch (o->arg) {
        case ARG_FLAG:
            *(int *)(void *)(base + o->field) = 1;
            break;
        case ARG_VALUE:
            if (*field && o->field == FIELD(out)) {
                fprintf(stderr, "footsim %s: --out given twice (%s and %s); give one folder\n", c->name, a->out,
                        argv[i + 1]);
                return FS_BAD_INPUT;
            }
            *field = attached ? attached : argv[++i];
            break;
        case ARG_PAIR:
            *field = argv[++i];
            *(const char **)(void *)(base + o->field2) = argv[++i];
            break;
        case ARG_REPEAT:
            if (a->nset == CLI_MAX_SET) {
                fprintf(stderr, "footsim %s: at most %d %s options\n", c->name, CLI_MAX_SET, o->name);
                return FS_BAD_INPUT;
            }
            a->set[a->nset++] = argv[++i];
            break;
        }
    }
    if (a->video)
        a->frames = 1;
    if (c->input && !a->input) {
        fprintf(stderr, "footsim %s: give a %s file; see 'footsim %s --help'\n", c->name, c->input, c->name);
        return FS_BAD_INPUT;
    }
    return 0;
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

int cli_print_json(cJSON *root)
{
    return fs_json_print(stdout, root) ? 0 : cli_report(FS_NO_MEMORY, "out of memory");
}

int cli_with_design(const cli_args *a, int (*command)(const cli_args *a, const fs_scenario *sc))
{
    fs_scenario *sc = cli_zalloc(sizeof *sc);
    if (!sc)
        return FS_NO_MEMORY;
    fs_error err;
    int s = fs_scenario_for_design(a->input, a->set, a->nset, sc, &err) != FS_OK ? cli_report(err.status, err.message)
                                                                                  : command(a, sc);
    fs_scenario_free(sc);
    free(sc);
    return s;
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
        cli_data_kind kind = commands[i].data;
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
