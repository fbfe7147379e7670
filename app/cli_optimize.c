/* cli_optimize.c: `footsim optimize FILE`: the design search of fs_optimize.h, each candidate's
 * trials run in the campaign's worker pool, every evaluation printed and kept in evaluations.csv,
 * the best design rerun on fresh seeds, and result.md saying what it found beside the start. */
#include "cli.h"

#include "footsim/campaign/fs_optimize.h"
#include "footsim/io/fs_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_EVALUATIONS_KEPT = 100000 };

/* One evaluation, for evaluations.csv. */
typedef struct evaluation {
    double x[FS_OPTIMIZE_MAX_PARAMS];
    double objective, shortfall;
    double rate[FS_CAMPAIGN_MAX_EXPECT];
} evaluation;

typedef struct optimize_run {
    int jobs;
    evaluation *log;
    int nlog;
    int round, nrounds;     /* evaluations so far, and at most: the search's and the three reruns */
} optimize_run;

/* One candidate's trials, in the worker pool; progress counts evaluations and their trials. */
static fs_status run_trials(void *user, const fs_optimize *o, fs_trial_result *results, fs_error *err)
{
    optimize_run *r = user;
    cli_progress_round("evaluation", ++r->round, r->nrounds);
    return (fs_status)cli_campaign_trials(&o->campaign, results, r->jobs, "footsim optimize", err);
}

static double rate_of(const fs_campaign *c, const fs_campaign_row *rows, const fs_expectation *e)
{
    return rows[(e->foot * c->nterrains + e->terrain) * c->nrobots + e->robot].success_rate;
}

static void report(void *user, const fs_optimize *o, int n, const double *x, double objective, double shortfall,
                   const fs_campaign_row *rows)
{
    optimize_run *r = user;
    const fs_campaign *c = &o->campaign;
    printf("evaluation %3d:", n);
    for (int p = 0; p < o->nparams; p++)
        printf(" %s %.4g", o->param[p].name, x[p]);
    printf("; objective %.4g; targets %s", objective, shortfall > 0 ? "missed by" : "met");
    if (shortfall > 0)
        printf(" %.3f", shortfall);
    printf(" (");
    for (int i = 0; i < c->nexpect; i++)
        printf("%s%s %.2f", i ? ", " : "", c->expect[i].name, rate_of(c, rows, &c->expect[i]));
    printf(")\n");
    fflush(stdout);
    if (r->nlog < MAX_EVALUATIONS_KEPT) {
        evaluation *e = &r->log[r->nlog++];
        memcpy(e->x, x, (size_t)o->nparams * sizeof x[0]);
        e->objective = objective;
        e->shortfall = shortfall;
        for (int i = 0; i < c->nexpect; i++)
            e->rate[i] = rate_of(c, rows, &c->expect[i]);
    }
}

/* What the files are written from. */
typedef struct optimize_out {
    const fs_optimize *o;
    const optimize_run *run;
    const double *start, *best;
    const fs_campaign_row *rows_best, *rows_start, *rows_fresh;
    int first_fresh;
    const fs_provenance *prov;
} optimize_out;

static int fill_evaluations(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    const fs_campaign *c = &o->campaign;
    fputs("evaluation", f);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, ",%s", o->param[p].key);
    fputs(",objective,shortfall", f);
    for (int i = 0; i < c->nexpect; i++)
        fprintf(f, ",rate_%s", c->expect[i].name);
    fputc('\n', f);
    for (int n = 0; n < x->run->nlog; n++) {
        const evaluation *e = &x->run->log[n];
        char b[32];
        fprintf(f, "%d", n + 1);
        for (int p = 0; p < o->nparams; p++)
            fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->x[p]));
        fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->objective));
        fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->shortfall));
        for (int i = 0; i < c->nexpect; i++)
            fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->rate[i]));
        fputc('\n', f);
    }
    return 1;
}

static void rates_md(FILE *f, const fs_campaign *c, const fs_campaign_row *rows, const char *what)
{
    fprintf(f, "| %s |", what);
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        const fs_campaign_row *r = &rows[(e->foot * c->nterrains + e->terrain) * c->nrobots + e->robot];
        fprintf(f, " %d/%d [%.2f, %.2f]%s |", r->landed, r->trials, r->ci_low, r->ci_high,
                r->success_rate >= e->min_success && r->success_rate <= e->max_success ? "" : " **missed**");
    }
    fputc('\n', f);
}

static int fill_result(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    const fs_campaign *c = &o->campaign;
    fprintf(f, "# Design search %s\n\nCampaign `%s`: %d seeds per cell (common to every candidate); %d evaluations "
               "of NLopt's Subplex; objective: the sum of the parameters each over its min (the least stiff "
               "design); the targets as a penalty (fs_optimize.h).\n\n| parameter | key | start | best | best / start |\n"
               "|---|---|--:|--:|--:|\n",
            o->name, c->name, c->seeds, x->run->nlog);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, "| %s | `%s` | %.4g | %.4g | %.3g |\n", o->param[p].name, o->param[p].key, x->start[p], x->best[p],
                x->best[p] / x->start[p]);
    fputs("\nSuccess (landed / trials, 95 % Wilson interval) on each target:\n\n| design |", f);
    for (int i = 0; i < c->nexpect; i++)
        fprintf(f, " %s (wanted %.2f to %.2f) |", c->expect[i].name, c->expect[i].min_success, c->expect[i].max_success);
    fputs("\n|---|", f);
    for (int i = 0; i < c->nexpect; i++)
        fputs("---|", f);
    fputc('\n', f);
    char what[128];
    snprintf(what, sizeof what, "start, seeds %d to %d", c->first_seed, c->first_seed + c->seeds - 1);
    rates_md(f, c, x->rows_start, what);
    snprintf(what, sizeof what, "best, seeds %d to %d", c->first_seed, c->first_seed + c->seeds - 1);
    rates_md(f, c, x->rows_best, what);
    snprintf(what, sizeof what, "best, fresh seeds %d to %d", x->first_fresh, x->first_fresh + c->seeds - 1);
    rates_md(f, c, x->rows_fresh, what);
    fputs("\nTo run the best design: `--set", f);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, "%s%s=%.6g", p ? " --set " : " ", o->param[p].key, x->best[p]);
    fputs("`\n\nProvenance: ", f);
    fs_provenance_print(x->prov, f);
    fputs(".\n", f);
    return 1;
}

/* Runs the campaign as it stands and summarizes it into rows. */
static fs_status evaluate(fs_optimize *o, optimize_run *r, fs_trial_result *results, fs_campaign_row *rows,
                          fs_error *err)
{
    fs_status s = run_trials(r, o, results, err);
    if (s == FS_OK)
        fs_campaign_summarize(&o->campaign, results, rows);
    return s;
}

int cli_optimize(const cli_args *a)
{
    int jobs;
    int s = cli_parse_jobs(a, &jobs);
    if (s)
        return s;
    /* the search and its results folder, too large for the stack: on the heap for this command */
    struct optimize_work {
        fs_optimize o;
        fs_outdir out;
    } *w = cli_zalloc(sizeof *w);
    if (!w)
        return FS_NO_MEMORY;
    fs_optimize *o = &w->o;
    fs_outdir *out = &w->out;
    fs_error err;
    if (fs_optimize_load(a->input, a->set, a->nset, o, &err) != FS_OK) {
        free(w); /* fs_optimize_load freed what it read */
        return cli_report(err.status, err.message);
    }
    char dir[FS_OUT_PATH];
    int bad = cli_results_dir(a, "optimize", o->name, dir, sizeof dir);
    if (bad) {
        fs_optimize_free(o);
        free(w);
        return bad;
    }
    if (fs_outdir_open(out, dir, a->replace, "--out", &err) != FS_OK) {
        fs_optimize_free(o);
        free(w);
        return cli_report(err.status, err.message);
    }
    int ntrials = fs_campaign_ntrials(&o->campaign), ncells = fs_campaign_ncells(&o->campaign);
    optimize_run run = {.jobs = jobs, .log = calloc(MAX_EVALUATIONS_KEPT, sizeof(evaluation)),
                        .nrounds = o->max_evaluations + 3};
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    fs_campaign_row *rows = calloc(3 * (size_t)ncells, sizeof *rows);
    double start[FS_OPTIMIZE_MAX_PARAMS], best[FS_OPTIMIZE_MAX_PARAMS], value;
    for (int p = 0; p < o->nparams; p++)
        start[p] = o->param[p].start;
    fs_status st = run.log && results && rows ? FS_OK : fs_fail(&err, FS_NO_MEMORY, "out of memory");
    printf("optimize %s: %d parameters, %d trials per candidate, at most %d candidates\n", o->name, o->nparams, ntrials,
           o->max_evaluations);
    if (st == FS_OK)
        st = fs_optimize_run(o, run_trials, report, &run, results, rows, best, &value, &err);
    /* the start and the best again, on the search's seeds and on fresh ones */
    int first = o->campaign.first_seed;
    run.round = o->max_evaluations; /* the reruns are the last three rounds, however soon the search ended */
    if (st == FS_OK)
        st = fs_optimize_apply(o, start, &err);
    if (st == FS_OK)
        st = evaluate(o, &run, results, rows + ncells, &err);
    if (st == FS_OK)
        st = fs_optimize_apply(o, best, &err);
    if (st == FS_OK)
        st = evaluate(o, &run, results, rows, &err);
    o->campaign.first_seed = o->validation_first_seed;
    if (st == FS_OK)
        st = evaluate(o, &run, results, rows + 2 * ncells, &err);
    o->campaign.first_seed = first;
    cli_progress_round(NULL, 0, 0);
    /* what made the results: the optimize file, every --set, and its campaign's inputs and settings */
    fs_provenance prov = {.ninputs = 0};
    if (st == FS_OK && (st = fs_provenance_init(&prov, o->path, &err)) == FS_OK &&
        (st = fs_provenance_overrides(&prov, a->set, a->nset, &err)) == FS_OK &&
        (st = fs_provenance_add_ini(&prov, o->path, &err)) == FS_OK)
        st = fs_provenance_include(&prov, &o->campaign.provenance, &err);
    optimize_out x = {o, &run, start, best, rows, rows + ncells, rows + 2 * ncells, o->validation_first_seed, &prov};
    if (st == FS_OK)
        st = fs_write_in(out->partial, "evaluations.csv", fill_evaluations, &x, &err);
    if (st == FS_OK)
        st = fs_provenance_write_beside(out->partial, "evaluations.csv", &prov, NULL, &err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "result.md", fill_result, &x, &err);
    if (st == FS_OK)
        st = fs_outdir_commit(out, &err);
    int met = st == FS_OK && fs_optimize_shortfall(&o->campaign, rows) == 0 &&
              fs_optimize_shortfall(&o->campaign, rows + 2 * ncells) == 0;
    if (st == FS_OK) {
        printf("best:");
        for (int p = 0; p < o->nparams; p++)
            printf(" %s = %.6g (start %.6g)", o->param[p].key, best[p], start[p]);
        printf("\ntargets %s on the search's seeds and %s on fresh seeds %d to %d\nresults: %s/result.md, "
               "evaluations.csv, evaluations.provenance.json\n",
               fs_optimize_shortfall(&o->campaign, rows) == 0 ? "met" : "MISSED",
               fs_optimize_shortfall(&o->campaign, rows + 2 * ncells) == 0 ? "met" : "MISSED", o->validation_first_seed,
               o->validation_first_seed + o->campaign.seeds - 1, out->path);
    }
    fs_outdir_abort(out);
    fs_provenance_free(&prov);
    free(run.log);
    free(results);
    free(rows);
    fs_optimize_free(o);
    free(w);
    if (st != FS_OK)
        return cli_report(err.status, err.message);
    return met ? 0 : FS_EXPECTATION_FAILED;
}
