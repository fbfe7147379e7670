/* cli_optimize.c: `footsim optimize FILE`: the design search of fs_optimize.h, each candidate's
 * trials run in the campaign's worker pool, every evaluation printed and kept in evaluations.csv,
 * the best design rerun on fresh seeds, the trade-off between the targets' shortfall and the
 * objective (the Pareto front of the candidates that ran: pareto.csv, pareto.gp, pareto.png), and
 * result.md saying what it found beside the foot's own design (its file's), the start and the
 * reference foot. */
#include "cli.h"

#include "footsim/base/fs_path.h"
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

/* Whether some parameter's weight in least_stiff's sum is not 1 (then the reports name the weights;
 * with every weight 1 they read as before weights existed). */
static int weighted(const fs_optimize *o)
{
    for (int p = 0; p < o->nparams; p++)
        if (o->param[p].weight != 1)
            return 1;
    return 0;
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
                    : weighted(o) ? "objective: the parameters' weighted sum, each over its min"
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

/* The head of a rates table: a column per terrain x robot. */
static void rates_header_md(FILE *f, const fs_campaign *c)
{
    fputs("\nSuccess (landed / trials, 95 % Wilson interval) in each terrain and robot:\n\n| design |", f);
    for (int i = 0; i < c->nterrains * c->nrobots; i++)
        fprintf(f, " %s, %s |", c->terrain[i / c->nrobots].name, c->robot[i % c->nrobots].name);
    fputs("\n|---|", f);
    for (int i = 0; i < c->nterrains * c->nrobots; i++)
        fputs("---|", f);
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
            : weighted(o) ? "the sum of the parameters each over its min times its weight (the table's; the least "
                            "stiff design)"
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
    if (o->objective == FS_OBJECTIVE_LEAST_STIFF && weighted(o)) {
        fputs("\nWeights in the objective (each parameter over its min, times its weight; 0: left out):", f);
        for (int p = 0; p < o->nparams; p++)
            fprintf(f, "%s %s %g", p ? "," : "", o->param[p].name, o->param[p].weight);
        fputs(".\n", f);
    }
    fprintf(f, "\nFoot mass: %.4g kg as its file gives it, %.4g kg the best; the arch's static ankle drop under its "
               "design load: %.3g mm, %.3g mm%s.\n",
            x->quantity_file[FS_QUANTITY_FOOT_MASS_KG], x->quantity_best[FS_QUANTITY_FOOT_MASS_KG],
            1e3 * x->quantity_file[FS_QUANTITY_ANKLE_DROP_M], 1e3 * x->quantity_best[FS_QUANTITY_ANKLE_DROP_M],
            isnan(x->quantity_file[FS_QUANTITY_ANKLE_DROP_M]) || isnan(x->quantity_best[FS_QUANTITY_ANKLE_DROP_M])
                ? " (NaN: the arch has no stable equilibrium under that load)"
                : "");
    rates_header_md(f, c);
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
    if (s == FS_OK && x && fs_optimize_recall(o, x, rows, NULL)) { /* the search ran it on these seeds */
        r->round++;
        return FS_OK;
    }
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

/* What one search found, for a sweep's front: its best, that best's objective and quantities, and
 * its shortfall on the search's seeds and on fresh ones; the foot's file design the same way. */
typedef struct search_point {
    double best[FS_OPTIMIZE_MAX_PARAMS];
    double objective, quantity[3];
    double shortfall, shortfall_fresh;
    double violation;                /* of the constraints (fs_optimize_violation); 0: feasible */
    double file_x[FS_OPTIMIZE_MAX_PARAMS], file_objective, file_quantity[3];
} search_point;

/* One search and its reruns (rows: 4 cells' worth: the best, the file's design, the start, the best
 * on fresh seeds), its files written into dir (shown: where the user will find it). *gnuplot: what
 * cli_gnuplot_shown said (> 0: the exit status of a damaged chart). */
static fs_status search_into(fs_optimize *o, optimize_run *run, fs_trial_result *results, fs_campaign_row *rows,
                             const fs_provenance *prov, const char *dir, const char *shown, search_point *pt,
                             int *gnuplot, fs_error *err)
{
    const fs_campaign *c = &o->campaign;
    int ncells = fs_campaign_ncells(c), cand = o->reference == 0 ? 1 : 0;
    double start[FS_OPTIMIZE_MAX_PARAMS], value;
    for (int p = 0; p < o->nparams; p++) {
        start[p] = o->param[p].start;
        pt->file_x[p] = o->file_x[cand * c->nterrains * c->nrobots * fs_campaign_nends(c) * o->nparams + p];
    }
    run->nlog = 0;
    run->round = 1;
    *gnuplot = 0;
    int repeats = o->repeats;
    fs_status st = fs_optimize_run(o, run_trials, report, run, results, rows, pt->best, &value, err);
    /* the foot's own design, the start and the best again on the search's seeds (the reference's
       trials kept), then the best and the reference on fresh ones */
    optimize_out x = {o, run, start, pt->best, rows + ncells, rows + 2 * ncells, rows, rows + 3 * ncells,
                      .first_fresh = o->validation_first_seed, .prov = prov};
    run->round = o->max_evaluations + (o->reference >= 0); /* the reruns are the last rounds */
    if (st == FS_OK)
        st = evaluate_at(o, run, NULL, results, rows + ncells, x.quantity_file, err);
    pt->file_objective = st == FS_OK ? fs_optimize_objective(o, pt->file_x) : NAN;
    if (st == FS_OK)
        st = evaluate_at(o, run, start, results, rows + 2 * ncells, x.quantity_start, err);
    if (st == FS_OK)
        st = evaluate_at(o, run, pt->best, results, rows, x.quantity_best, err);
    pt->objective = st == FS_OK ? fs_optimize_objective(o, pt->best) : NAN;
    pt->violation = st == FS_OK ? fs_optimize_violation(o) : NAN;
    int first = o->campaign.first_seed;
    o->campaign.first_seed = o->validation_first_seed;
    if (st == FS_OK)
        st = evaluate(o, run, results, rows + 3 * ncells, 1, err);
    o->campaign.first_seed = first;
    cli_progress_round(NULL, 0, 0);
    memcpy(pt->quantity, x.quantity_best, sizeof pt->quantity);
    memcpy(pt->file_quantity, x.quantity_file, sizeof pt->file_quantity);
    int *front = st == FS_OK ? pareto_of(run) : NULL;
    if (st == FS_OK && !front)
        st = fs_fail(err, FS_NO_MEMORY, "out of memory");
    x.front = front;
    if (st == FS_OK)
        st = fs_write_in(dir, "evaluations.csv", fill_evaluations, &x, err);
    if (st == FS_OK)
        st = fs_provenance_write_beside(dir, "evaluations.csv", prov, NULL, err);
    if (st == FS_OK)
        st = fs_write_in(dir, "pareto.csv", fill_pareto, &x, err);
    if (st == FS_OK)
        st = fs_write_in(dir, "pareto.gp", fill_pareto_gp, &x, err);
    if (st == FS_OK)
        st = fs_write_in(dir, "result.md", fill_result, &x, err);
    int g = st == FS_OK ? cli_gnuplot_shown(dir, shown, "pareto.gp", "pareto.png", "optimize") : 0;
    if (g > 0)
        st = (fs_status)g, *gnuplot = g; /* said */
    if (st == FS_OK) {
        pt->shortfall = fs_optimize_shortfall(o, rows);
        pt->shortfall_fresh = fs_optimize_shortfall(o, rows + 3 * ncells);
        printf("best:");
        for (int p = 0; p < o->nparams; p++)
            printf(" %s = %.6g (start %.6g)", o->param[p].key, pt->best[p], start[p]);
        printf("\ntargets %s on the search's seeds and %s on fresh seeds %d to %d", pt->shortfall == 0 ? "met" : "MISSED",
               pt->shortfall_fresh == 0 ? "met" : "MISSED", o->validation_first_seed,
               o->validation_first_seed + o->campaign.seeds - 1);
        if (pt->violation > 0)
            printf("; its constraints BROKEN by %.3g (no candidate met them)", pt->violation);
        printf("\n");
        if (o->repeats > repeats)
            printf("%d evaluation%s met a candidate that had run on these seeds and reused its trials' results\n",
                   o->repeats - repeats, o->repeats - repeats == 1 ? "" : "s");
    }
    free(front);
    return st;
}

/* ---- a sweep of a constraint's bound: front.csv, front.gp, result.md -------------------------- */

typedef struct sweep_out {
    const fs_optimize *o;
    const search_point *pt;          /* one per value */
    const int *front;                /* by value: on the trade-off's front */
    const fs_campaign_row *rows;     /* per value: the best on the search's seeds, then on fresh ones
                                        (2 * ncells); then the file's design's and the reference's
                                        (the first search's: every search runs them alike) */
    const char (*folder)[FS_NAME_MAX];
    const fs_provenance *prov;
} sweep_out;

static const fs_opt_constraint *swept(const fs_optimize *o) { return &o->constraint[o->sweep_constraint]; }

/* A search's folder: "NAME_max_VALUE" (or _min_). */
static void sweep_folder(const fs_optimize *o, int i, char *buf, size_t size)
{
    snprintf(buf, size, "%s_%s_%g", swept(o)->name, o->sweep_min ? "min" : "max", o->sweep_values.v[i]);
}

static int fill_front(FILE *f, const void *user)
{
    const sweep_out *x = user;
    const fs_optimize *o = x->o;
    char b[32];
    fprintf(f, "design,%s_%s", swept(o)->name, o->sweep_min ? "min" : "max");
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, ",%s", o->param[p].key);
    fprintf(f, ",objective,%s,shortfall,shortfall_fresh,front\n", quantity_name(swept(o)->of));
    int q = swept(o)->of;
    for (int i = -1; i < o->sweep_values.n; i++) { /* the foot's file design first */
        const search_point *pt = &x->pt[i < 0 ? 0 : i];
        fprintf(f, "%s,%s", i < 0 ? "file" : "best", i < 0 ? "" : cli_csv_num(b, sizeof b, "%.17g", o->sweep_values.v[i]));
        for (int p = 0; p < o->nparams; p++)
            fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", i < 0 ? pt->file_x[p] : pt->best[p]));
        fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", i < 0 ? pt->file_objective : pt->objective));
        fprintf(f, ",%s", cli_csv_num(b, sizeof b, "%.17g", i < 0 ? pt->file_quantity[q] : pt->quantity[q]));
        if (i < 0)
            fputs(",,,0\n", f); /* its shortfall is in result.md's table of rates */
        else
            fprintf(f, ",%s,%s,%d\n", cli_csv_num(b, sizeof b, "%.17g", pt->shortfall),
                    cli_csv_num(b, sizeof b, "%.17g", pt->shortfall_fresh), x->front[i]);
    }
    return 1;
}

static int fill_front_gp(FILE *f, const void *user)
{
    const sweep_out *x = user;
    const fs_optimize *o = x->o;
    fputs("# A sweep of a constraint's bound: 'gnuplot front.gp' in this folder draws front.png from front.csv\n"
          "# (each search's best, and the foot's file design; the bounds' labels above and below in turn, so\n"
          "# that two bests at one point stay apart).\nif (!exists(\"out\")) out = 'front.png'\nsearch = ", f);
    fs_gp_string(f, o->name);
    fputs("\nobjective = ", f);
    fs_gp_string(f, o->objective == FS_OBJECTIVE_LIGHTEST ? "objective: the foot's mass, kg"
                    : weighted(o) ? "objective: the parameters' weighted sum, each over its min"
                                  : "objective: the parameters' sum, each over its min");
    fputs("\nquantity = ", f);
    fs_gp_string(f, quantity_name(swept(o)->of));
    fprintf(f, "\nobj = %d\n", o->nparams + 3);
    fputs("set terminal pngcairo size 720,480 noenhanced font 'sans,10'\nset output out\n"
          "set datafile separator ','\nset title 'Design search ' . search . ': each bound''s best'\n"
          "set xlabel quantity . ' of the design (the swept bound''s quantity)'\nset ylabel objective\n"
          "set key outside bottom center horizontal\nset grid\n"
          "plot 'front.csv' skip 1 using (strcol(1) eq 'best' && column(obj + 2) > 0 ? column(obj + 1) : 1/0):obj "
          "with points pt 6 ps 1.5 lc rgb '#999999' title 'best, missing a target', \\\n"
          "     'front.csv' skip 1 using (column(obj + 4) == 1 ? column(obj + 1) : 1/0):obj with linespoints pt 7 lw 2 "
          "lc rgb '#b2182b' title 'front (targets met)', \\\n"
          "     'front.csv' skip 1 using (strcol(1) eq 'best' && int(column(0)) % 2 ? column(obj + 1) : 1/0):obj:"
          "(sprintf('%g', column(2))) with labels offset 0,1 notitle, \\\n"
          "     'front.csv' skip 1 using (strcol(1) eq 'best' && !(int(column(0)) % 2) ? column(obj + 1) : 1/0):obj:"
          "(sprintf('%g', column(2))) with labels offset 0,-1 notitle, \\\n"
          "     'front.csv' skip 1 using (strcol(1) eq 'file' ? column(obj + 1) : 1/0):obj with points pt 5 ps 1.5 "
          "lc rgb '#2166ac' title 'the foot''s file design'\n", f);
    return 1;
}

static int fill_sweep_result(FILE *f, const void *user)
{
    const sweep_out *x = user;
    const fs_optimize *o = x->o;
    const fs_campaign *c = &o->campaign;
    const fs_opt_constraint *k = swept(o);
    int n = o->sweep_values.n, ncells = fs_campaign_ncells(c), q = k->of, last = c->first_seed + c->seeds - 1;
    const char *bound = o->sweep_min ? "min" : "max";
    fprintf(f, "# Design search %s: a sweep of %s.%s\n\nOne search per value of constraint %s's %s (%s), each at most "
               "%d evaluations of NLopt's Subplex on campaign `%s`'s %d common seeds per cell (seeds %d to %d), "
               "objective %s; each search's own files (result.md, evaluations.csv, pareto.png) in its folder. The "
               "front (`front.csv`, `front.png`): each bound's best, objective against its %s; a best is on it when "
               "it meets every target on the search's seeds within its bound and no other such best is at least as good in "
               "both.\n\n",
            o->name, k->name, bound, k->name, bound, quantity_name(q), o->max_evaluations, c->name, c->seeds,
            c->first_seed, last, o->objective == FS_OBJECTIVE_LIGHTEST ? "the foot's mass"
            : weighted(o) ? "the parameters' sum each over its min times its weight" : "the parameters' sum each over its min",
            quantity_name(q));
    fprintf(f, "| design | %s | folder |", bound);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, " %s |", o->param[p].name);
    fprintf(f, " objective | %s | shortfall, seeds %d to %d | shortfall, fresh seeds %d to %d | front |\n|---|--:|---|",
            quantity_name(q), c->first_seed, last, o->validation_first_seed, o->validation_first_seed + c->seeds - 1);
    for (int p = 0; p < o->nparams + 5; p++)
        fputs("--:|", f);
    fputc('\n', f);
    int cand = o->reference == 0 ? 1 : 0;
    fprintf(f, "| %s as its file gives it | | |", c->foot[cand].name);
    for (int p = 0; p < o->nparams; p++)
        fprintf(f, " %.4g |", x->pt[0].file_x[p]);
    fprintf(f, " %.4g | %.4g | %.3f | | |\n", x->pt[0].file_objective, x->pt[0].file_quantity[q],
            fs_optimize_shortfall(o, x->rows + 2 * n * ncells));
    for (int i = 0; i < n; i++) {
        const search_point *pt = &x->pt[i];
        fprintf(f, "| best | %.4g | `%s/` |", o->sweep_values.v[i], x->folder[i]);
        for (int p = 0; p < o->nparams; p++)
            fprintf(f, " %.4g |", pt->best[p]);
        fprintf(f, " %.4g | %.4g | %.3f | %.3f | %s |\n", pt->objective, pt->quantity[q], pt->shortfall,
                pt->shortfall_fresh, x->front[i] ? "yes" : pt->violation > 0 ? "breaks a constraint" : "");
    }
    rates_header_md(f, c);
    char what[256];
    snprintf(what, sizeof what, "%s as its file gives it, seeds %d to %d", c->foot[cand].name, c->first_seed, last);
    rates_md(f, o, x->rows + 2 * n * ncells, cand, what);
    for (int i = 0; i < n; i++) {
        snprintf(what, sizeof what, "best at %s = %g, seeds %d to %d", bound, o->sweep_values.v[i], c->first_seed, last);
        rates_md(f, o, x->rows + 2 * i * ncells, cand, what);
        snprintf(what, sizeof what, "best at %s = %g, fresh seeds %d to %d", bound, o->sweep_values.v[i],
                 o->validation_first_seed, o->validation_first_seed + c->seeds - 1);
        rates_md(f, o, x->rows + (2 * i + 1) * ncells, cand, what);
    }
    if (o->reference >= 0) {
        snprintf(what, sizeof what, "%s (the reference), seeds %d to %d", c->foot[o->reference].name, c->first_seed, last);
        rates_md(f, o, x->rows, o->reference, what);
        snprintf(what, sizeof what, "%s (the reference), fresh seeds %d to %d", c->foot[o->reference].name,
                 o->validation_first_seed, o->validation_first_seed + c->seeds - 1);
        rates_md(f, o, x->rows + ncells, o->reference, what);
    }
    fputs("\nProvenance: ", f);
    fs_provenance_print(x->prov, f);
    fputs(".\n", f);
    return 1;
}

/* The sweep: one search per value into its folder under dir, then the front. */
static fs_status sweep_into(fs_optimize *o, optimize_run *run, fs_trial_result *results, fs_campaign_row *rows,
                            const fs_provenance *prov, const fs_outdir *out, int *gnuplot, int *met, fs_error *err)
{
    int n = o->sweep_values.n, ncells = fs_campaign_ncells(&o->campaign);
    search_point *pt = calloc((size_t)n, sizeof *pt);
    fs_campaign_row *kept = calloc((size_t)(2 * n + 1) * (size_t)ncells, sizeof *kept);
    char (*folder)[FS_NAME_MAX] = calloc((size_t)n, sizeof *folder);
    int *front = calloc((size_t)n, sizeof *front), *index = calloc((size_t)n, sizeof *index);
    double *a = calloc((size_t)n, sizeof *a), *b = calloc((size_t)n, sizeof *b);
    fs_status st = pt && kept && folder && front && index && a && b ? FS_OK : fs_fail(err, FS_NO_MEMORY, "out of memory");
    *met = 0;
    for (int i = 0; st == FS_OK && i < n; i++) {
        char dir[FS_OUT_PATH], shown[FS_OUT_PATH];
        sweep_folder(o, i, folder[i], sizeof folder[i]);
        fs_optimize_sweep_to(o, i);
        printf("sweep %d/%d: %s.%s = %g, into %s/\n", i + 1, n, swept(o)->name, o->sweep_min ? "min" : "max",
               o->sweep_values.v[i], folder[i]);
        st = fs_path_format(dir, sizeof dir, "a sweep's folder", err, "%s/%s", out->partial, folder[i]);
        if (st == FS_OK)
            st = fs_path_format(shown, sizeof shown, "a sweep's folder", err, "%s/%s", out->path, folder[i]);
        if (st == FS_OK)
            st = fs_make_dirs(dir, err);
        if (st == FS_OK)
            st = search_into(o, run, results, rows, prov, dir, shown, &pt[i], gnuplot, err);
        if (st != FS_OK)
            break;
        memcpy(kept + 2 * i * ncells, rows, (size_t)ncells * sizeof *rows);
        memcpy(kept + (2 * i + 1) * ncells, rows + 3 * ncells, (size_t)ncells * sizeof *rows);
        if (i == 0) /* the file's design (the reference's rows are in every block: its trials are kept) */
            memcpy(kept + 2 * n * ncells, rows + ncells, (size_t)ncells * sizeof *rows);
        *met |= pt[i].shortfall == 0 && pt[i].shortfall_fresh == 0 && pt[i].violation == 0;
    }
    /* the front: the bests that meet every target on the search's seeds, objective against the
       quantity (toward the bound: less of it for a max, more for a min) */
    int m = 0;
    for (int i = 0; st == FS_OK && i < n; i++)
        if (pt[i].shortfall == 0 && pt[i].violation == 0) {
            double v = pt[i].quantity[swept(o)->of];
            a[m] = o->sweep_min ? -v : v, b[m] = pt[i].objective, index[m++] = i;
        }
    if (st == FS_OK) {
        int kept_flags[FS_SERIES_MAX] = {0}; /* for the m bests that met, then spread by index */
        fs_optimize_pareto(a, b, m, kept_flags);
        for (int i = 0; i < m; i++)
            front[index[i]] = kept_flags[i];
    }
    sweep_out x = {o, pt, front, kept, (const char(*)[FS_NAME_MAX])folder, prov};
    if (st == FS_OK)
        st = fs_write_in(out->partial, "front.csv", fill_front, &x, err);
    if (st == FS_OK)
        st = fs_provenance_write_beside(out->partial, "front.csv", prov, NULL, err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "front.gp", fill_front_gp, &x, err);
    if (st == FS_OK)
        st = fs_write_in(out->partial, "result.md", fill_sweep_result, &x, err);
    int g = st == FS_OK ? cli_gnuplot_shown(out->partial, out->path, "front.gp", "front.png", "optimize") : 0;
    if (g > 0)
        st = (fs_status)g, *gnuplot = g;
    free(pt), free(kept), free(folder), free(front), free(index), free(a), free(b);
    return st;
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
    fs_status st = run.log && results && rows ? FS_OK : fs_fail(&err, FS_NO_MEMORY, "out of memory");
    printf("optimize %s: %d parameters, %d trials per candidate", o->name, o->nparams,
           o->reference >= 0 ? ntrials - per_foot_trials : ntrials);
    if (o->reference >= 0)
        printf(" (foot %s's %d run once, the reference)", o->campaign.foot[o->reference].name, per_foot_trials);
    printf(", at most %d candidates", o->max_evaluations);
    if (o->sweep_constraint >= 0)
        printf(" per search, %d searches (a sweep of %s.%s)", o->sweep_values.n, swept(o)->name,
               o->sweep_min ? "min" : "max");
    printf("\n");
    /* what made the results: the optimize file, every --set, and its campaign's inputs and settings */
    fs_provenance prov = {.ninputs = 0};
    if (st == FS_OK && (st = fs_provenance_init(&prov, o->path, &err)) == FS_OK &&
        (st = fs_provenance_overrides(&prov, a->set, a->nset, &err)) == FS_OK &&
        (st = fs_provenance_add_ini(&prov, o->path, &err)) == FS_OK)
        st = fs_provenance_include(&prov, &o->campaign.provenance, &err);
    int g = 0, met = 0;
    search_point pt;
    if (st == FS_OK && o->sweep_constraint >= 0)
        st = sweep_into(o, &run, results, rows, &prov, out, &g, &met, &err);
    else if (st == FS_OK && (st = search_into(o, &run, results, rows, &prov, out->partial, out->path, &pt, &g, &err)) ==
                                FS_OK)
        met = pt.shortfall == 0 && pt.shortfall_fresh == 0 && pt.violation == 0;
    if (st == FS_OK)
        st = fs_outdir_commit(out, &err);
    if (st == FS_OK && o->sweep_constraint >= 0)
        printf("results: %s/result.md, front.csv, front.provenance.json, front.png; each search's in its folder\n",
               out->path);
    else if (st == FS_OK)
        printf("results: %s/result.md, evaluations.csv, evaluations.provenance.json, pareto.csv, pareto.png\n", out->path);
    fs_outdir_abort(out);
    fs_provenance_free(&prov);
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
