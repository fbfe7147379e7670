/* cli_optimize.c: `footsim optimize FILE`: the design search of fs_optimize.h, each candidate's
 * trials run in the campaign's worker pool, every evaluation printed and kept in evaluations.csv,
 * the best design rerun on fresh seeds, the trade-off between the targets' shortfall and the
 * objective (the Pareto front of the candidates that ran: pareto.csv, pareto.gp, pareto.png), and
 * result.md saying what it found beside the foot's own design (its file's), the start and the
 * reference foot. */
#include "cli.h"

#include "footsim/campaign/fs_optimize.h"
#include "footsim/io/fs_gnuplot.h"
#include "footsim/io/fs_output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_EVALUATIONS_KEPT = 100000, MAX_CELLS_KEPT = 64 };

/* One evaluation, for evaluations.csv. */
typedef struct evaluation {
    double x[FS_OPTIMIZE_MAX_PARAMS];
    double objective, shortfall, violation; /* violation > 0: infeasible, no trial ran (rates NAN) */
    double rate[MAX_CELLS_KEPT];            /* each cell's success rate (the first MAX_CELLS_KEPT) */
} evaluation;

typedef struct optimize_run {
    int jobs;
    evaluation *log;
    int nlog;
    int round, nrounds;     /* evaluations so far, and at most: the search's and the three reruns */
} optimize_run;

/* One candidate's trials, in the worker pool; progress counts evaluations and their trials. */
static fs_status run_trials(void *user, const fs_campaign *c, fs_trial_result *results, fs_error *err)
{
    optimize_run *r = user;
    cli_progress_round("evaluation", r->round, r->nrounds);
    return (fs_status)cli_campaign_trials(c, results, r->jobs, "footsim optimize", err);
}

static int cell_of(const fs_campaign *c, const fs_expectation *e)
{
    return (e->foot * c->nterrains + e->terrain) * c->nrobots + e->robot;
}

/* The cells a report shows: with relative_to, every cell (the other feet's are targets); else
 * those of the expectations. */
static int shown_cell(const fs_optimize *o, int cell)
{
    const fs_campaign *c = &o->campaign;
    if (o->reference >= 0)
        return 1;
    for (int i = 0; i < c->nexpect; i++)
        if (cell_of(c, &c->expect[i]) == cell)
            return 1;
    return 0;
}

static void cell_name(const fs_campaign *c, int cell, char *buf, size_t size)
{
    int f, t, r;
    fs_campaign_cell_of(c, cell, &f, &t, &r);
    snprintf(buf, size, "%s/%s/%s", c->foot[f].name, c->terrain[t].name, c->robot[r].name);
}

static void report(void *user, const fs_optimize *o, int n, const double *x, double objective, double shortfall,
                   double violation, const fs_campaign_row *rows)
{
    optimize_run *r = user;
    const fs_campaign *c = &o->campaign;
    r->round = n + 1; /* the next evaluation's, for the progress line */
    printf("evaluation %3d:", n);
    for (int p = 0; p < o->nparams; p++)
        printf(" %s %.4g", o->param[p].name, x[p]);
    printf("; objective %.4g", objective);
    if (violation > 0) {
        printf("; infeasible (constraints broken by %.3g): no trial run\n", violation);
    } else {
        printf("; targets %s", shortfall > 0 ? "missed by" : "met");
        if (shortfall > 0)
            printf(" %.3f", shortfall);
        printf(" (");
        int first = 1;
        for (int cell = 0; cell < fs_campaign_ncells(c); cell++) {
            char name[3 * FS_NAME_MAX + 4];
            if (!shown_cell(o, cell))
                continue;
            cell_name(c, cell, name, sizeof name);
            printf("%s%s %.2f", first ? "" : ", ", name, rows[cell].success_rate);
            first = 0;
        }
        printf(")\n");
    }
    fflush(stdout);
    if (r->nlog < MAX_EVALUATIONS_KEPT) {
        evaluation *e = &r->log[r->nlog++];
        memcpy(e->x, x, (size_t)o->nparams * sizeof x[0]);
        e->objective = objective;
        e->shortfall = shortfall;
        e->violation = violation;
        for (int cell = 0; cell < fs_campaign_ncells(c) && cell < MAX_CELLS_KEPT; cell++)
            e->rate[cell] = rows ? rows[cell].success_rate : NAN;
    }
}

/* What the files are written from. */
typedef struct optimize_out {
    const fs_optimize *o;
    const optimize_run *run;
    const double *start, *best;
    const fs_campaign_row *rows_file, *rows_start, *rows_best, *rows_fresh;
    double quantity_file[3], quantity_start[3], quantity_best[3]; /* by fs_quantity */
    const int *front;        /* by evaluation: on the Pareto front */
    int first_fresh;
    const fs_provenance *prov;
} optimize_out;

static const char *quantity_name(int q) { return q == FS_QUANTITY_FOOT_MASS_KG ? "foot_mass_kg" : "ankle_drop_m"; }

/* An evaluation's number, parameters, objective and shortfall, as CSV fields (no newline). */
static void point_csv(FILE *f, const fs_optimize *o, int n, const evaluation *e)
{
    char b[32];
    fprintf(f, "%d", n + 1);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->x[p]));
    fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->objective));
    fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->shortfall));
}

/* The header's parameter columns: "evaluation,KEY,...". */
static void params_csv(FILE *f, const fs_optimize *o)
{
    fputs("evaluation", f);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, ",%s", o->param[p].key);
}

static int fill_evaluations(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    const fs_campaign *c = &o->campaign;
    int ncells = fs_campaign_ncells(c) < MAX_CELLS_KEPT ? fs_campaign_ncells(c) : MAX_CELLS_KEPT;
    params_csv(f, o);
    fputs(",objective,shortfall,violation,pareto", f);
    for (int cell = 0; cell < ncells; cell++) {
        char name[3 * FS_NAME_MAX + 4];
        cell_name(c, cell, name, sizeof name);
        fprintf(f, ",rate_%s", name);
    }
    fputc('\n', f);
    for (int n = 0; n < x->run->nlog; n++) {
        const evaluation *e = &x->run->log[n];
        char b[32];
        point_csv(f, o, n, e);
        fprintf(f, ",%s,%d", cli_csv_num(b, sizeof b, "%.17g", e->violation), x->front[n]);
        for (int cell = 0; cell < ncells; cell++)
            fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", e->rate[cell]));
        fputc('\n', f);
    }
    return 1;
}

/* The Pareto front alone, by objective: what pareto.gp draws as its line and result.md lists. */
static int fill_pareto(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    params_csv(f, o);
    fputs(",objective,shortfall\n", f);
    double last = -HUGE_VAL;
    for (;;) { /* in rising objective: the least one above the last written */
        int next = -1;
        for (int n = 0; n < x->run->nlog; n++)
            if (x->front[n] && x->run->log[n].objective > last &&
                (next < 0 || x->run->log[n].objective < x->run->log[next].objective))
                next = n;
        if (next < 0)
            break;
        point_csv(f, o, next, &x->run->log[next]);
        fputc('\n', f);
        last = x->run->log[next].objective;
    }
    return 1;
}

static int fill_pareto_gp(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    fputs("# A design search's trade-off: 'gnuplot pareto.gp' in this folder draws pareto.png from\n"
          "# evaluations.csv (every candidate that ran) and pareto.csv (its Pareto front).\n"
          "if (!exists(\"out\")) out = 'pareto.png'\nsearch = ", f);
    fs_gp_string(f, o->name);
    fputs("\nobjective = ", f);
    fs_gp_string(f, o->objective == FS_OBJECTIVE_LIGHTEST ? "objective: the foot's mass, kg"
                                                           : "objective: the parameters' sum, each over its min");
    fprintf(f, "\ncol = %d\n", o->nparams + 2);
    fputs("set terminal pngcairo size 720,480 noenhanced font 'sans,10'\nset output out\n"
          "set datafile separator ','\nset title 'Design search ' . search . ': the candidates that ran and their Pareto front'\n"
          "set xlabel objective\nset ylabel 'shortfall: the targets missed, summed (0: every target met)'\n"
          "set key top right\nset grid\nset yrange [-0.05:*]\n"
          "plot 'evaluations.csv' skip 1 using col:(column(col + 2) == 0 ? column(col + 1) : 1/0) with points pt 6 "
          "lc rgb '#999999' title 'candidates', \\\n"
          "     'pareto.csv' skip 1 using col:(column(col + 1)) with linespoints pt 7 lw 2 lc rgb '#b2182b' title "
          "'Pareto front'\n", f);
    return 1;
}

/* One row of a rates table: the cells of foot (every terrain x robot shown), landed / trials and
 * the Wilson interval; a target missed marked. */
static void rates_md(FILE *f, const fs_optimize *o, const fs_campaign_row *rows, int foot, const char *what)
{
    const fs_campaign *c = &o->campaign;
    fprintf(f, "| %s |", what);
    for (int i = 0; i < c->nterrains * c->nrobots; i++) {
        int cell = foot * c->nterrains * c->nrobots + i, ref = fs_optimize_reference_cell(o, cell);
        const fs_campaign_row *r = &rows[cell];
        int missed = foot != o->reference && ref >= 0 && r->success_rate < rows[ref].success_rate;
        for (int e = 0; e < c->nexpect; e++) {
            const fs_expectation *x = &c->expect[e];
            if (cell_of(c, x) == cell && !(r->success_rate >= x->min_success && r->success_rate <= x->max_success))
                missed = 1;
        }
        fprintf(f, " %d/%d [%.2f, %.2f]%s |", r->landed, r->trials, r->ci_low, r->ci_high, missed ? " **missed**" : "");
    }
    fputc('\n', f);
}

static int fill_result(FILE *f, const void *user)
{
    const optimize_out *x = user;
    const fs_optimize *o = x->o;
    const fs_campaign *c = &o->campaign;
    int last = c->first_seed + c->seeds - 1;
    fprintf(f, "# Design search %s\n\nCampaign `%s`: %d seeds per cell (common to every candidate); %d evaluations "
               "of NLopt's Subplex; objective: %s; the targets as a penalty (fs_optimize.h): ",
            o->name, c->name, c->seeds, x->run->nlog,
            o->objective == FS_OBJECTIVE_LIGHTEST ? "the foot's mass (the lightest design)"
                                                  : "the sum of the parameters each over its min (the least stiff design)");
    if (c->nexpect)
        fprintf(f, "%d expectations of the campaign", c->nexpect);
    if (o->reference >= 0)
        fprintf(f, "%severy cell of the searched foot landing at least as often as the %s foot in the same terrain "
                   "and robot on the same seeds (`relative_to = %s`; its trials run once and reused)",
                c->nexpect ? ", and " : "", c->foot[o->reference].name, c->foot[o->reference].name);
    fputs(".\n", f);
    if (o->nconstraints) {
        fputs("\nConstraints (a candidate that breaks one runs no trial):\n\n| constraint | min | max | the foot's file | "
              "start | best |\n|---|--:|--:|--:|--:|--:|\n", f);
        for (int n = 0; n < o->nconstraints; n++) {
            int q = o->constraint[n].of;
            fprintf(f, "| %s: %s | %.4g | %.4g | %.4g | %.4g | %.4g |\n", o->constraint[n].name, quantity_name(q),
                    o->constraint[n].min, o->constraint[n].max, x->quantity_file[q], x->quantity_start[q],
                    x->quantity_best[q]);
        }
    }
    fputs("\n| parameter | key | the foot's file | start | best | best / file |\n|---|---|--:|--:|--:|--:|\n", f);
    int cand = o->reference == 0 ? 1 : 0, cell0 = cand * c->nterrains * c->nrobots;
    for (int p = 0; p < o->nparams; p++) {
        double file = o->file_x[cell0 * fs_campaign_nends(c) * o->nparams + p]; /* a band's first end */
        fprintf(f, "| %s | `%s` | %.4g | %.4g | %.4g | %.3g |\n", o->param[p].name, o->param[p].key, file, x->start[p],
                x->best[p], x->best[p] / file);
    }
    fprintf(f, "\nFoot mass: %.4g kg as its file gives it, %.4g kg the best; the arch's static ankle drop under its "
               "design load: %.3g mm, %.3g mm%s.\n",
            x->quantity_file[FS_QUANTITY_FOOT_MASS_KG], x->quantity_best[FS_QUANTITY_FOOT_MASS_KG],
            1e3 * x->quantity_file[FS_QUANTITY_ANKLE_DROP_M], 1e3 * x->quantity_best[FS_QUANTITY_ANKLE_DROP_M],
            isnan(x->quantity_file[FS_QUANTITY_ANKLE_DROP_M]) || isnan(x->quantity_best[FS_QUANTITY_ANKLE_DROP_M])
                ? " (NaN: the arch has no stable equilibrium under that load)"
                : "");
    fputs("\nSuccess (landed / trials, 95 % Wilson interval) in each terrain and robot:\n\n| design |", f);
    for (int i = 0; i < c->nterrains * c->nrobots; i++)
        fprintf(f, " %s, %s |", c->terrain[i / c->nrobots].name, c->robot[i % c->nrobots].name);
    fputs("\n|---|", f);
    for (int i = 0; i < c->nterrains * c->nrobots; i++)
        fputs("---|", f);
    fputc('\n', f);
    char what[256];
    for (int foot = 0; foot < c->nfeet; foot++) {
        if (foot == o->reference)
            continue;
        snprintf(what, sizeof what, "%s as its file gives it, seeds %d to %d", c->foot[foot].name, c->first_seed, last);
        rates_md(f, o, x->rows_file, foot, what);
        snprintf(what, sizeof what, "%s start, seeds %d to %d", c->foot[foot].name, c->first_seed, last);
        rates_md(f, o, x->rows_start, foot, what);
        snprintf(what, sizeof what, "%s best, seeds %d to %d", c->foot[foot].name, c->first_seed, last);
        rates_md(f, o, x->rows_best, foot, what);
        snprintf(what, sizeof what, "%s best, fresh seeds %d to %d", c->foot[foot].name, x->first_fresh,
                 x->first_fresh + c->seeds - 1);
        rates_md(f, o, x->rows_fresh, foot, what);
    }
    if (o->reference >= 0) {
        const char *ref = c->foot[o->reference].name;
        snprintf(what, sizeof what, "%s (the reference), seeds %d to %d", ref, c->first_seed, last);
        rates_md(f, o, x->rows_best, o->reference, what);
        snprintf(what, sizeof what, "%s (the reference), fresh seeds %d to %d", ref, x->first_fresh,
                 x->first_fresh + c->seeds - 1);
        rates_md(f, o, x->rows_fresh, o->reference, what);
    }
    fputs("\nThe trade-off (`pareto.csv`, `pareto.png`): the Pareto front of the candidates that ran, shortfall "
          "(the targets missed, summed) against the objective, both minimised; every candidate ran on the same "
          "seeds, so they compare point for point. It is the front of the points the search visited, not of a "
          "sweep of weights. The best is the least penalised: among candidates that miss alike, the one whose "
          "misses stayed up longest ranks first (the search's slope), so it need not lie on the front.\n\n"
          "| evaluation |", f);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, " %s |", o->param[p].name);
    fputs(" objective | shortfall |\n|--:|", f);
    for (int p = 0; p <= o->nparams + 1; p++)
        fputs("--:|", f);
    fputc('\n', f);
    for (int n = 0; n < x->run->nlog; n++) {
        if (!x->front[n])
            continue;
        const evaluation *e = &x->run->log[n];
        fprintf(f, "| %d |", n + 1);
        for (int p = 0; p < o->nparams; p++)
            fprintf(f, " %.4g |", e->x[p]);
        fprintf(f, " %.4g | %.3f |\n", e->objective, e->shortfall);
    }
    fputs("\nTo run the best design: `--set", f);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, "%s%s=%.6g", p ? " --set " : " ", o->param[p].key, x->best[p]);
    fputs("`\n\nProvenance: ", f);
    fs_provenance_print(x->prov, f);
    fputs(".\n", f);
    return 1;
}

/* Runs the campaign as it stands (the reference foot's trials too when reference) and summarizes
 * it into rows. */
static fs_status evaluate(fs_optimize *o, optimize_run *r, fs_trial_result *results, fs_campaign_row *rows,
                          int reference, fs_error *err)
{
    r->round++;
    fs_status s = fs_optimize_run_trials(o, run_trials, r, results, reference, err);
    if (s == FS_OK)
        fs_campaign_summarize(&o->campaign, results, rows);
    return s;
}

/* x (NULL: the files' values) applied, its quantities and rows on the search's seeds. */
static fs_status evaluate_at(fs_optimize *o, optimize_run *r, const double *x, fs_trial_result *results,
                             fs_campaign_row *rows, double quantity[3], fs_error *err)
{
    fs_status s = fs_optimize_apply(o, x, err);
    for (int q = FS_QUANTITY_FOOT_MASS_KG; s == FS_OK && q <= FS_QUANTITY_ANKLE_DROP_M; q++)
        quantity[q] = fs_optimize_quantity(o, q);
    return s == FS_OK ? evaluate(o, r, results, rows, 0, err) : s;
}

/* The Pareto front of the evaluations that ran (shortfall, objective). */
static int *pareto_of(const optimize_run *run)
{
    int n = run->nlog, *front = calloc((size_t)n + 1, sizeof *front), *keep = calloc((size_t)n + 1, sizeof *keep),
        *index = calloc((size_t)n + 1, sizeof *index);
    double *a = calloc((size_t)n + 1, sizeof *a), *b = calloc((size_t)n + 1, sizeof *b);
    int m = 0;
    for (int i = 0; front && keep && index && a && b && i < n; i++)
        if (!(run->log[i].violation > 0) && isfinite(run->log[i].shortfall)) {
            a[m] = run->log[i].shortfall, b[m] = run->log[i].objective, index[m++] = i;
        }
    if (front && keep && index && a && b) {
        fs_optimize_pareto(a, b, m, keep);
        for (int i = 0; i < m; i++)
            front[index[i]] = keep[i];
    }
    free(keep), free(index), free(a), free(b);
    return front;
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
    int per_foot_trials = ntrials / o->campaign.nfeet;
    optimize_run run = {.jobs = jobs, .log = calloc(MAX_EVALUATIONS_KEPT, sizeof(evaluation)), .round = 1,
                        .nrounds = o->max_evaluations + 4 + (o->reference >= 0)};
    fs_trial_result *results = calloc((size_t)ntrials, sizeof *results);
    fs_campaign_row *rows = calloc(4 * (size_t)ncells, sizeof *rows);
    double start[FS_OPTIMIZE_MAX_PARAMS], best[FS_OPTIMIZE_MAX_PARAMS], value;
    for (int p = 0; p < o->nparams; p++)
        start[p] = o->param[p].start;
    fs_status st = run.log && results && rows ? FS_OK : fs_fail(&err, FS_NO_MEMORY, "out of memory");
    printf("optimize %s: %d parameters, %d trials per candidate", o->name, o->nparams,
           o->reference >= 0 ? ntrials - per_foot_trials : ntrials);
    if (o->reference >= 0)
        printf(" (foot %s's %d run once, the reference)", o->campaign.foot[o->reference].name, per_foot_trials);
    printf(", at most %d candidates\n", o->max_evaluations);
    if (st == FS_OK)
        st = fs_optimize_run(o, run_trials, report, &run, results, rows, best, &value, &err);
    /* the foot's own design, the start and the best again on the search's seeds (the reference's
       trials kept), then the best and the reference on fresh ones */
    optimize_out x = {o, &run, start, best, rows + ncells, rows + 2 * ncells, rows, rows + 3 * ncells,
                      .first_fresh = o->validation_first_seed};
    run.round = o->max_evaluations + (o->reference >= 0); /* the reruns are the last rounds */
    if (st == FS_OK)
        st = evaluate_at(o, &run, NULL, results, rows + ncells, x.quantity_file, &err);
    if (st == FS_OK)
        st = evaluate_at(o, &run, start, results, rows + 2 * ncells, x.quantity_start, &err);
    if (st == FS_OK)
        st = evaluate_at(o, &run, best, results, rows, x.quantity_best, &err);
    int first = o->campaign.first_seed;
    o->campaign.first_seed = o->validation_first_seed;
    if (st == FS_OK)
        st = evaluate(o, &run, results, rows + 3 * ncells, 1, &err);
    o->campaign.first_seed = first;
    cli_progress_round(NULL, 0, 0);
    int *front = st == FS_OK ? pareto_of(&run) : NULL;
    if (st == FS_OK && !front)
        st = fs_fail(&err, FS_NO_MEMORY, "out of memory");
    x.front = front;
    /* what made the results: the optimize file, every --set, and its campaign's inputs and settings */
    fs_provenance prov = {.ninputs = 0};
    if (st == FS_OK && (st = fs_provenance_init(&prov, o->path, &err)) == FS_OK &&
        (st = fs_provenance_overrides(&prov, a->set, a->nset, &err)) == FS_OK &&
        (st = fs_provenance_add_ini(&prov, o->path, &err)) == FS_OK)
        st = fs_provenance_include(&prov, &o->campaign.provenance, &err);
    x.prov = &prov;
    if (st == FS_OK)
        st = fs_write_in(out->partial, "evaluations.csv", fill_evaluations, &x, &err);
    if (st == FS_OK)
        st = fs_provenance_write_beside(out->partial, "evaluations.csv", &prov, NULL, &err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "pareto.csv", fill_pareto, &x, &err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "pareto.gp", fill_pareto_gp, &x, &err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "result.md", fill_result, &x, &err);
    int g = st == FS_OK ? cli_gnuplot_shown(out->partial, out->path, "pareto.gp", "pareto.png", "optimize") : 0;
    if (g > 0)
        st = (fs_status)g; /* said */
    if (st == FS_OK)
        st = fs_outdir_commit(out, &err);
    int met = st == FS_OK && fs_optimize_shortfall(o, rows) == 0 && fs_optimize_shortfall(o, rows + 3 * ncells) == 0;
    if (st == FS_OK) {
        printf("best:");
        for (int p = 0; p < o->nparams; p++)
            printf(" %s = %.6g (start %.6g)", o->param[p].key, best[p], start[p]);
        printf("\ntargets %s on the search's seeds and %s on fresh seeds %d to %d\nresults: %s/result.md, "
               "evaluations.csv, evaluations.provenance.json, pareto.csv, pareto.png\n",
               fs_optimize_shortfall(o, rows) == 0 ? "met" : "MISSED",
               fs_optimize_shortfall(o, rows + 3 * ncells) == 0 ? "met" : "MISSED", o->validation_first_seed,
               o->validation_first_seed + o->campaign.seeds - 1, out->path);
    }
    fs_outdir_abort(out);
    fs_provenance_free(&prov);
    free(front);
    free(run.log);
    free(results);
    free(rows);
    fs_optimize_free(o);
    free(w);
    if (st != FS_OK && g > 0)
        return g;
    if (st != FS_OK)
        return cli_report(err.status, err.message);
    return met ? 0 : FS_EXPECTATION_FAILED;
}
