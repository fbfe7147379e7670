/* cli_bench_equivalence.c: campaign equivalence (docs/bench.md, issue 12), for 'footsim bench
 * equivalence' and the last stage of 'footsim bench precision'.
 *
 * A campaign runs once at a reference step and once at each step to judge (every cell's run.step_s
 * set last, over any robot's own step), all with the same seeds and the same workers so that wall
 * times compare; each step's summary is judged against the reference's by fs_campaign_equivalence.
 * Writes into DIR, file by file, each whole or not at all: DIR/reference/ (the reference campaign's
 * files, a results folder replaced whole), DIR/h<STEP>.md (each comparison, STEP as given) and
 * DIR/equivalence.md (one row a step: verdict, quantities that differ, wall time, speed-up on the
 * reference). The steps' own campaigns go to a scratch folder beside reference/ that is removed on
 * every path footsim controls; DIR/reference/ is put in place only once every campaign has run.
 * Comparisons an earlier run at other steps left (DIR/h<STEP>.md, STEP a step) are removed last,
 * so that the folder holds the run equivalence.md describes.
 *
 * Everything is checked before any trial runs (exit 2, nothing written for a bad step or
 * campaign): the steps (numbers in run.step_s's range, none given twice), the campaign loaded at
 * every step, DIR and DIR/reference. Verdicts are results: exit 0 when it ran, whatever they are;
 * 4 when a file cannot be written. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/io/fs_output.h"
#include "footsim/model/fs_scenario.h"
#include "footsim/sim/fs_sim.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

enum { MAX_STEPS = 32, STEP_TEXT = 32 };


/* One campaign: the reference or a step to judge. */
typedef struct eq_run {
    char text[STEP_TEXT];            /* the step as given: the file h<text>.md */
    char set[STEP_TEXT + 16];        /* "run.step_s=<text>", the campaign's last override */
    double step_s;
    fs_campaign *c;                  /* loaded at open */
    double wall_s;                   /* its trials, run and summarized */
    int equivalent, differ;          /* the verdict and the quantities that differ (steps) */
} eq_run;

struct cli_equivalence {
    cli_equivalence_spec spec;
    const char *set[FS_CAMPAIGN_MAX_SET]; /* the spec's, then run.step_s */
    int nset;
    eq_run ref, step[MAX_STEPS];
    int nsteps;
    char dir[FS_OUT_PATH];           /* as given */
    fs_outdir reference, scratch;    /* DIR/reference; DIR/steps, never put in place */
    char date[32], machine[512];
    double load;                     /* at the start of the runs */
    char *provenance;                /* the reference campaign's (fs_campaign_provenance) */
};

/* ---- checks --------------------------------------------------------------------------------- */

/* Whether text is a number (*step_s), and (*in_range) one in run.step_s's range. */
static int step_of(const char *text, double *step_s, int *in_range)
{
    char *end;
    size_t len = strlen(text);
    *step_s = strtod(text, &end);
    int number = len > 0 && strspn(text, "0123456789.eE+-") == len && *end == 0;
    *in_range = number && *step_s >= FS_STEP_MIN_S && *step_s <= FS_STEP_MAX_S;
    return number;
}

/* One step as given (len characters of text) into r: a number of seconds in run.step_s's range. */
static int parse_step(const cli_equivalence_spec *sp, const char *option, const char *text, size_t len, eq_run *r)
{
    int in_range;
    snprintf(r->text, sizeof r->text, "%.*s", (int)(len < STEP_TEXT ? len : STEP_TEXT - 1), text);
    int number = len < STEP_TEXT && step_of(r->text, &r->step_s, &in_range);
    if (!number || !in_range) {
        int many = !strcmp(option, "--steps");
        fprintf(stderr, "%s: %s: '%.*s' is %s; give %s in seconds from %g to %g (run.step_s's range), e.g. %s\n",
                sp->who, option, (int)len, text, number ? "out of range" : "not a number of seconds",
                many ? "steps separated by commas" : "a step", FS_STEP_MIN_S, FS_STEP_MAX_S,
                many ? "--steps 1e-4,1e-3" : "--reference 1e-5");
        return FS_BAD_INPUT;
    }
    snprintf(r->set, sizeof r->set, "run.step_s=%s", r->text);
    return 0;
}

static int parse_steps(cli_equivalence *e)
{
    const cli_equivalence_spec *sp = &e->spec;
    int s = parse_step(sp, "--reference", sp->reference, strlen(sp->reference), &e->ref);
    for (const char *p = sp->steps; !s;) {
        size_t len = strcspn(p, ",");
        if (e->nsteps == MAX_STEPS) {
            fprintf(stderr, "%s: --steps: at most %d steps; run the rest in a second command with another --out\n",
                    sp->who, MAX_STEPS);
            return FS_BAD_INPUT;
        }
        eq_run *r = &e->step[e->nsteps];
        s = parse_step(sp, "--steps", p, len, r);
        for (int i = 0; !s && i < e->nsteps; i++)
            if (e->step[i].step_s == r->step_s) {
                fprintf(stderr, "%s: --steps: %s and %s are the same step; give each step once\n", sp->who,
                        e->step[i].text, r->text);
                s = FS_BAD_INPUT;
            }
        e->nsteps++;
        if (!p[len])
            break;
        p += len + 1;
    }
    return s;
}

/* The campaign loaded with the spec's overrides and r's step last (every cell's step). */
static int load_at(cli_equivalence *e, eq_run *r)
{
    fs_error err;
    e->set[e->nset] = r->set;
    r->c = cli_zalloc(sizeof *r->c);
    if (!r->c)
        return FS_NO_MEMORY;
    if (fs_campaign_load(e->spec.campaign, e->set, e->nset + 1, r->c, &err) != FS_OK) {
        free(r->c);
        r->c = NULL;
        return cli_report(err.status, err.message);
    }
    return 0;
}

int cli_equivalence_open(cli_equivalence **out, const cli_equivalence_spec *spec, const char *dir, int replace)
{
    cli_equivalence *e = cli_zalloc(sizeof *e);
    *out = e;
    if (!e)
        return FS_NO_MEMORY;
    e->spec = *spec;
    e->reference.lock_fd = e->scratch.lock_fd = -1;
    snprintf(e->dir, sizeof e->dir, "%s", dir);
    if (spec->nset >= FS_CAMPAIGN_MAX_SET) {
        fprintf(stderr, "%s: at most %d --set options here (the step takes one more)\n", spec->who,
                FS_CAMPAIGN_MAX_SET - 1);
        return FS_BAD_INPUT;
    }
    for (int i = 0; i < spec->nset; i++)
        e->set[e->nset++] = spec->set[i];
    int s = parse_steps(e);
    if (!s)
        s = load_at(e, &e->ref);
    for (int i = 0; !s && i < e->nsteps; i++)
        s = load_at(e, &e->step[i]);
    /* the folders last: nothing is made for a bad step or campaign */
    fs_error err;
    char path[FS_OUT_PATH + 32];
    if (!s && fs_outdir_shared(dir, replace, spec->option, &err) != FS_OK)
        s = cli_report(err.status, err.message);
    snprintf(path, sizeof path, "%s/reference", dir);
    if (!s && fs_outdir_open(&e->reference, path, replace, spec->option, &err) != FS_OK)
        s = cli_report(err.status, err.message);
    snprintf(path, sizeof path, "%s/steps", dir);
    if (!s && fs_outdir_open(&e->scratch, path, 0, spec->option, &err) != FS_OK)
        s = cli_report(err.status, err.message);
    return s;
}

void cli_equivalence_close(cli_equivalence *e)
{
    if (!e)
        return;
    fs_outdir_abort(&e->scratch);   /* the steps' campaigns: never kept */
    fs_outdir_abort(&e->reference); /* when it was not put in place */
    for (int i = -1; i < e->nsteps; i++) {
        eq_run *r = i < 0 ? &e->ref : &e->step[i];
        if (r->c)
            fs_campaign_free(r->c);
        free(r->c);
    }
    free(e->provenance);
    free(e);
}

/* ---- the campaigns ---------------------------------------------------------------------------- */

/* Runs r's campaign (its wall time: the trials and their summary) and writes its files into dir:
 * all of them for the reference, only summary.json for a step. */
static fs_status run_one(cli_equivalence *e, eq_run *r, int reference, const char *dir, fs_error *err)
{
    const fs_campaign *c = r->c;
    int ntrials = fs_campaign_ntrials(c), ncells = fs_campaign_ncells(c);
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    fs_campaign_row *rows = malloc((size_t)ncells * sizeof *rows);
    fs_status s = results && rows ? FS_OK : fs_fail(err, FS_NO_MEMORY, "out of memory");
    double start = fs_clock_s();
    if (s == FS_OK)
        s = cli_campaign_trials(c, results, e->spec.jobs, e->spec.who, err);
    if (s == FS_OK)
        fs_campaign_summarize(c, results, rows);
    r->wall_s = fs_clock_s() - start;
    if (s == FS_OK && reference) {
        s = fs_campaign_write(c, results, rows, dir, err);
        if (s == FS_OK)
            s = fs_campaign_write_chart(c, rows, dir, err);
        int g = s == FS_OK ? cli_gnuplot(dir, "chart.gp", "success.png", "bench equivalence") : 0;
        if (g)
            s = fs_fail(err, (fs_status)g, "%s/success.png: the chart could not be written", dir);
    } else if (s == FS_OK && mkdir(dir, 0777) != 0) {
        s = fs_fail(err, FS_IO, "%s: cannot make the folder (%s); give --out a folder that can be written", dir,
                    strerror(errno));
    }
    if (s == FS_OK)
        s = fs_campaign_write_summary(c, rows, dir, err);
    free(results);
    free(rows);
    return s;
}

/* Judges step r (its summary in the scratch folder) against the reference, put in place: writes
 * DIR/h<STEP>.md and sets r's verdict. */
static fs_status judge(cli_equivalence *e, eq_run *r, fs_error *err)
{
    char result[FS_OUT_PATH + 128], reference[FS_OUT_PATH + 32], path[FS_OUT_PATH + STEP_TEXT + 8];
    char name[STEP_TEXT + 64];
    snprintf(result, sizeof result, "%s/h%s/summary.json", e->scratch.partial, r->text);
    snprintf(name, sizeof name, "The campaign at h = %s s", r->text);
    snprintf(reference, sizeof reference, "%s/summary.json", e->reference.path);
    snprintf(path, sizeof path, "%s/h%s.md", e->dir, r->text);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    fs_status s = fs_campaign_equivalence(result, name, reference, 0, f, &r->differ, err);
    if (fclose(f) != 0 && s <= FS_EXPECTATION_FAILED)
        s = fs_fail(err, FS_NO_MEMORY, "out of memory");
    if (s <= FS_EXPECTATION_FAILED) {
        r->equivalent = s == FS_OK;
        s = fs_write_atomic(path, buf, len, err);
    }
    free(buf);
    return s;
}

static int fill_equivalence(FILE *f, const void *user)
{
    const cli_equivalence *e = user;
    const cli_equivalence_spec *sp = &e->spec;
    fprintf(f, "# Campaign equivalence: `%s`\n\n`%s` on %s; %s; load average %.2f at the start; %d worker%s (-j %d). "
            "Reference: h = %s s, %.3g s of wall time (the trials alone). A step is *equivalent* when every cell's "
            "success intervals overlap the reference's and its medians of impulse, final lean, ankle drop at rest, settle "
            "time and contacts lie within 5 %% or a floor (`footsim compare --equivalence`; each step's table in "
            "`h<STEP>.md`, the reference campaign's files in `reference/`).\n\n",
            sp->shown, sp->command, e->date, e->machine, e->load, sp->jobs, sp->jobs > 1 ? "s" : "", sp->jobs,
            e->ref.text, e->ref.wall_s);
    cli_equivalence_table(f, e);
    const char *prov = e->provenance; /* the journal's line: "# provenance: footsim ..." */
    fprintf(f, "\nProvenance (of the reference): %s.\n", strncmp(prov, "# provenance: ", 14) ? prov : prov + 14);
    return 1;
}

void cli_equivalence_table(FILE *f, const cli_equivalence *e)
{
    fprintf(f, "| step h (s) | verdict | quantities that differ | wall time (s) | speed-up on the reference |\n"
               "|--:|---|--:|--:|--:|\n");
    for (int i = 0; i < e->nsteps; i++) {
        const eq_run *r = &e->step[i];
        fprintf(f, "| %s | %s | %d | %.3g | %.1f |\n", r->text, r->equivalent ? "equivalent" : "**not equivalent**",
                r->differ, r->wall_s, r->wall_s > 0 ? e->ref.wall_s / r->wall_s : INFINITY);
    }
}

/* Removes DIR/h<STEP>.md files an earlier run of other steps left (footsim's: named for a step in
 * run.step_s's range), so that the folder holds one run's comparisons, those equivalence.md lists;
 * says each on stderr. */
static void remove_stale(const cli_equivalence *e)
{
    DIR *d = opendir(e->dir);
    const struct dirent *ent;
    while (d && (ent = readdir(d))) {
        const char *n = ent->d_name;
        size_t len = strlen(n);
        if (len < 5 || n[0] != 'h' || strcmp(n + len - 3, ".md") || len - 4 >= STEP_TEXT)
            continue;
        char text[STEP_TEXT];
        snprintf(text, sizeof text, "%.*s", (int)(len - 4), n + 1);
        double h;
        int ours;
        step_of(text, &h, &ours);
        for (int i = 0; ours && i < e->nsteps; i++)
            ours = strcmp(text, e->step[i].text) != 0;
        char path[FS_OUT_PATH + STEP_TEXT + 8];
        snprintf(path, sizeof path, "%s/h%s.md", e->dir, text);
        if (ours && unlink(path) == 0)
            fprintf(stderr, "%s: removed %s, a comparison from an earlier run at another step\n", e->spec.who, path);
    }
    if (d)
        closedir(d);
}

int cli_equivalence_run(cli_equivalence *e)
{
    const cli_equivalence_spec *sp = &e->spec;
    time_t now = time(NULL);
    strftime(e->date, sizeof e->date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    cli_machine(e->machine, sizeof e->machine);
    e->load = cli_load_average();
    fs_error err;
    char dir[FS_OUT_PATH + 128];
    int n = e->nsteps + 1;
    fprintf(stderr, "%s: %s, %d trials, the reference at h = %s s (campaign 1 of %d) ...\n", sp->who, sp->shown,
            fs_campaign_ntrials(e->ref.c), e->ref.text, n);
    fs_status s = run_one(e, &e->ref, 1, e->reference.partial, &err);
    for (int i = 0; s == FS_OK && i < e->nsteps; i++) {
        fprintf(stderr, "%s: h = %s s (campaign %d of %d) ...\n", sp->who, e->step[i].text, i + 2, n);
        snprintf(dir, sizeof dir, "%s/h%s", e->scratch.partial, e->step[i].text);
        s = run_one(e, &e->step[i], 0, dir, &err);
    }
    if (s == FS_OK && !(e->provenance = fs_campaign_provenance(e->ref.c)))
        s = fs_fail(&err, FS_NO_MEMORY, "out of memory");
    /* the reference in place once every campaign has run; then the comparisons, which name it */
    if (s == FS_OK)
        s = fs_outdir_commit(&e->reference, &err);
    for (int i = 0; s == FS_OK && i < e->nsteps; i++)
        s = judge(e, &e->step[i], &err);
    if (s == FS_OK)
        s = fs_write_in(e->dir, "equivalence.md", fill_equivalence, e, &err);
    if (s == FS_OK)
        remove_stale(e);
    fs_outdir_abort(&e->scratch);
    return s == FS_OK ? 0 : cli_report(s, err.message);
}

/* ---- footsim bench equivalence -------------------------------------------------------------- */

int cli_bench_equivalence(const cli_args *a)
{
    int jobs = 1; /* one worker unless -j: wall times compare between runs of the command */
    if (a->jobs && cli_parse_jobs(a, &jobs))
        return FS_BAD_INPUT;
    if (a->quick)
        return cli_report(FS_BAD_INPUT, "bench equivalence: --quick is for the sweeps; for a cheaper run give fewer "
                                        "seeds (--set campaign.seeds=N), a larger --reference or fewer --steps");
    char found[FS_PATH_MAX], out[FS_PATH_MAX + 64], command[4 * FS_PATH_MAX];
    const char *shown = a->input2 ? a->input2 : "scenarios/equivalence_flat.ini";
    const char *campaign = a->input2 ? cli_data_find(a->input2, CLI_DATA_SCENARIO, found, sizeof found)
                                     : cli_data_path(shown);
    const char *base = strrchr(campaign, '/');
    base = base ? base + 1 : campaign;
    /* build/equivalence/<campaign name>: results/ changes only on purpose (--out) */
    snprintf(out, sizeof out, "build/equivalence/%.*s", (int)strcspn(base, "."), base);
    cli_equivalence_spec spec = {.campaign = campaign, .shown = shown, .set = a->set, .nset = a->nset,
                                 .reference = a->reference ? a->reference : "1e-5",
                                 .steps = a->steps ? a->steps : "1e-4,2e-4,5e-4,1e-3,2e-3,5e-3,1e-2",
                                 .jobs = jobs, .command = command, .who = "footsim bench equivalence",
                                 .option = "--out"};
    /* the command as it ran, for equivalence.md */
    int n = snprintf(command, sizeof command, "footsim bench equivalence %s -j %d", shown, jobs);
    for (int i = 0; i < a->nset && n > 0 && (size_t)n < sizeof command; i++)
        n += snprintf(command + n, sizeof command - (size_t)n, " --set %s", a->set[i]);
    if (n > 0 && (size_t)n < sizeof command)
        snprintf(command + n, sizeof command - (size_t)n, " --reference %s --steps %s", spec.reference, spec.steps);
    const char *dir = a->out ? a->out : out;
    cli_equivalence *e;
    int s = cli_equivalence_open(&e, &spec, dir, a->replace);
    if (!s)
        s = cli_equivalence_run(e);
    if (!s) {
        printf("footsim bench equivalence: %s\n\n", shown);
        cli_equivalence_table(stdout, e);
        printf("\nresults: %s/equivalence.md, h<STEP>.md, reference/\n", dir);
    }
    cli_equivalence_close(e);
    return s;
}
