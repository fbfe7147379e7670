/* campaign_optimize.c: the design search of fs_optimize.h: its file, a candidate put into the
 * campaign's definitions, the penalised objective and NLopt's Subplex over it. */
#include "footsim/campaign/fs_optimize.h"

#include "footsim/analysis/fs_analysis.h"
#include "footsim/base/fs_path.h"

#include <math.h>
#include <nlopt.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the file ----------------------------------------------------------------------------- */

#define O(member) offsetof(fs_optimize, member)

/* [optimize]'s six keys (and relative_to's row in fs_optimize_print_keys), six a [param.NAME]
   (key, min, max, start, log, weight), three a [constraint.NAME] (of, max, min) */
enum { MAX_KEYS = 7 + 6 * FS_OPTIMIZE_MAX_PARAMS + 3 * FS_OPTIMIZE_MAX_CONSTRAINTS };

typedef struct binder {
    fs_key keys[MAX_KEYS];
    int nkeys;
    char sections[FS_OPTIMIZE_MAX_PARAMS][FS_NAME_MAX];
    char csections[FS_OPTIMIZE_MAX_CONSTRAINTS][FS_NAME_MAX];
    char relative_to[FS_VALUE_MAX];         /* [optimize] relative_to, a foot's name (bound by hand) */
    char relative_where[FS_PATH_MAX + 80];
    char key_choices[16384];
    char sweep_choices[FS_OPTIMIZE_MAX_CONSTRAINTS * 2 * (FS_NAME_MAX + 6) + 8];
    int key_choice[FS_OPTIMIZE_MAX_PARAMS]; /* bound: the n-th sweepable key */
} binder;

static fs_key *add_key(binder *b, const char *section, const char *name, fs_key_type type, size_t offset,
                       const char *fallback, const char *help)
{
    if (b->nkeys == MAX_KEYS) { /* MAX_KEYS counts every key a file can have: a key added without it */
        fprintf(stderr, "footsim: internal error: a design search file's keys outgrow MAX_KEYS (%d)\n", MAX_KEYS);
        abort();
    }
    fs_key *k = &b->keys[b->nkeys++];
    *k = (fs_key){section, name, type, offset, 0, 0, 0, 0, NULL, "", fallback, help};
    return k;
}

/* The sections "PREFIX.NAME" of cfg, in file order, into sections[*n] (at most max; what: their
 * kind, for the message). */
static fs_status collect_sections(const fs_config *cfg, const char *prefix, char (*sections)[FS_NAME_MAX], int *n,
                                  int max, const char *what, fs_error *err)
{
    size_t len = strlen(prefix);
    for (int i = 0; i < cfg->count; i++) {
        const char *sec = cfg->entries[i].section;
        if (strncmp(sec, prefix, len) || sec[len] != '.')
            continue;
        int known = 0;
        for (int k = 0; k < *n; k++)
            known |= !strcmp(sections[k], sec);
        if (known)
            continue;
        if (*n == max)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s]: at most %d %s", cfg->path, sec, max, what);
        snprintf(sections[(*n)++], FS_NAME_MAX, "%s", sec);
    }
    return FS_OK;
}

/* The [param.NAME] and [constraint.NAME] sections, in file order. */
static fs_status collect_params(const fs_config *cfg, binder *b, fs_optimize *o, fs_error *err)
{
    fs_status s = collect_sections(cfg, "param", b->sections, &o->nparams, FS_OPTIMIZE_MAX_PARAMS, "parameters", err);
    if (s == FS_OK)
        s = collect_sections(cfg, "constraint", b->csections, &o->nconstraints, FS_OPTIMIZE_MAX_CONSTRAINTS,
                             "constraints", err);
    if (s != FS_OK)
        return s;
    for (int p = 0; p < o->nparams; p++)
        snprintf(o->param[p].name, FS_NAME_MAX, "%s", b->sections[p] + 6);
    for (int n = 0; n < o->nconstraints; n++)
        snprintf(o->constraint[n].name, FS_NAME_MAX, "%s", b->csections[n] + 11);
    if (!o->nparams)
        return fs_fail(err, FS_BAD_INPUT, "%s: no parameters; add a section like [param.k_d1] with key = "
                                          "springs.k_d1_N_per_m, min, max and start", cfg->path);
    return FS_OK;
}

/* [optimize] relative_to names a foot of the campaign, which only the campaign's loading knows:
 * taken here as text (and marked bound), checked once the campaign is loaded. */
static void take_relative_to(fs_config *cfg, binder *b)
{
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        if (strcmp(e->section, "optimize") || strcmp(e->name, "relative_to"))
            continue;
        snprintf(b->relative_to, sizeof b->relative_to, "%s", e->value); /* the last given wins */
        fs_config_where(cfg, "optimize", "relative_to", b->relative_where, sizeof b->relative_where);
        e->used = 1;
    }
}

/* A [param.NAME] key naming one element of a list key ("chains.splay_deg[3]", counted from 1) is no
 * word of the key's choices: taken here as text (and marked bound), checked against the schemas with
 * its line. *taken: 1 when it was such a key. */
static fs_status take_element_key(fs_config *cfg, const char *sec, fs_opt_param *q, int *taken, fs_error *err)
{
    *taken = 0;
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        if (strcmp(e->section, sec) || strcmp(e->name, "key") || !strchr(e->value, '['))
            continue;
        char where[FS_PATH_MAX + 80], base[FS_VALUE_MAX];
        fs_config_where(cfg, sec, "key", where, sizeof where);
        const char *text = e->value + strspn(e->value, " \t");
        snprintf(base, sizeof base, "%.*s", (int)(strchr(text, '[') - text), text);
        int element;
        const fs_key *k = fs_scenario_key(text, 0, &element);
        fs_key_type type = FS_KEY_NUMBER;
        int count = 0;
        if (!k) { /* why: a list key's element out of its range, or no list key of that name */
            char first[FS_VALUE_MAX + 4];
            snprintf(first, sizeof first, "%s[1]", base);
            const fs_key *list = fs_scenario_key(first, 0, &element);
            if (list)
                type = list->type, count = list->count;
        }
        if (!k && type == FS_KEY_LIST)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] key = %s: no such element; %s has %d, give %s[1] to %s[%d] "
                           "(elements are counted from 1)", where, sec, text, base, count, base, base, count);
        if (!k)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] key = %s names no element of a list of a design, robot, "
                           "scenario or terrain file; give e.g. chains.splay_deg[1], or a number such as "
                           "chains.splay_factor", where, sec, text);
        snprintf(q->key, sizeof q->key, "%s", text);
        q->key[strcspn(q->key, " \t")] = 0;
        e->used = 1;
        *taken = 1;
    }
    return FS_OK;
}

/* A fs_optimize to bind into, and where each param's choice index lands (the binder's). */
typedef struct target {
    fs_optimize o;
    int key_choice[FS_OPTIMIZE_MAX_PARAMS];
    int log[FS_OPTIMIZE_MAX_PARAMS];
    int sweep_choice;              /* 0 none; 2n + 1: constraint n's max, 2n + 2: its min */
} target;

#define T(member) offsetof(target, member)

/* Adds the keys of [optimize] and of the [param.NAME] and [constraint.NAME] sections named in b
 * (t->o's counts of each). */
static fs_status add_file_keys(fs_config *cfg, binder *b, target *t, fs_error *err)
{
    fs_optimize *o = &t->o;
    fs_status s = FS_OK;
    add_key(b, "optimize", "campaign", FS_KEY_PATH, T(o.campaign_path), "",
            "the campaign whose trials every candidate runs and whose expectations are the targets");
    fs_key *k = add_key(b, "optimize", "max_evaluations", FS_KEY_INTEGER, T(o.max_evaluations), "40",
                        "the most candidates the search runs");
    k->min = 1, k->max = 100000;
    k = add_key(b, "optimize", "validation_first_seed", FS_KEY_INTEGER, T(o.validation_first_seed), "1001",
                "the best design is rerun on as many fresh seeds, from this one");
    k->max = 1e9;
    k = add_key(b, "optimize", "objective", FS_KEY_CHOICE, T(o.objective), "none",
                "what the search minimises: least_stiff (the parameters' sum, each over its min times its weight) or lightest "
                "(the foot's mass)");
    k->choices = "none|least_stiff|lightest";
    for (int n = 0; n < o->nconstraints; n++) {
        k = add_key(b, b->csections[n], "of", FS_KEY_CHOICE, T(o.constraint[n].of), "none",
                    "what it bounds: foot_mass_kg (the foot's total mass) or ankle_drop_m (the arch's static "
                    "ankle drop under its design load)");
        k->choices = "none|foot_mass_kg|ankle_drop_m";
        k = add_key(b, b->csections[n], "max", FS_KEY_NUMBER, T(o.constraint[n].max), "1e12",
                    "the upper bound, in the quantity's unit");
        k->min = 0, k->max = 1e12;
        k = add_key(b, b->csections[n], "min", FS_KEY_NUMBER, T(o.constraint[n].min), "0",
                    "the lower bound, in the quantity's unit");
        k->min = 0, k->max = 1e12;
    }
    snprintf(b->sweep_choices, sizeof b->sweep_choices, "none");
    for (int n = 0; n < o->nconstraints; n++) {
        size_t len = strlen(b->sweep_choices);
        snprintf(b->sweep_choices + len, sizeof b->sweep_choices - len, "|%s.max|%s.min", o->constraint[n].name,
                 o->constraint[n].name);
    }
    k = add_key(b, "optimize", "sweep", FS_KEY_CHOICE, T(sweep_choice), "none",
                "a constraint's bound, NAME.max or NAME.min: one search per value of sweep_values, on the same seeds");
    k->choices = b->sweep_choices;
    k = add_key(b, "optimize", "sweep_values", FS_KEY_SERIES, T(o.sweep_values), "",
                "the swept bound's values, comma-separated, in the quantity's unit");
    k->min = 0, k->max = 1e12, k->count = FS_SERIES_MAX;
    snprintf(b->key_choices, sizeof b->key_choices, "none");
    for (int n = 1; fs_campaign_sweepable(n); n++) {
        char word[2 * FS_NAME_MAX + 2];
        snprintf(word, sizeof word, "%s.%s", fs_campaign_sweepable(n)->section, fs_campaign_sweepable(n)->name);
        size_t len = strlen(b->key_choices);
        snprintf(b->key_choices + len, sizeof b->key_choices - len, "|%s", word);
    }
    for (int p = 0; p < o->nparams; p++) {
        const char *sec = b->sections[p];
        int taken;
        if ((s = take_element_key(cfg, sec, &o->param[p], &taken, err)) != FS_OK)
            return s;
        t->key_choice[p] = -1; /* taken: a list's element */
        if (!taken) {
            k = add_key(b, sec, "key", FS_KEY_CHOICE, T(key_choice[p]), "none", "the number the search varies");
            k->choices = b->key_choices;
        }
        k = add_key(b, sec, "min", FS_KEY_NUMBER, T(o.param[p].min), "0", "its lower bound");
        k->min = -1e12, k->max = 1e12;
        k = add_key(b, sec, "max", FS_KEY_NUMBER, T(o.param[p].max), "0", "its upper bound");
        k->min = -1e12, k->max = 1e12;
        k = add_key(b, sec, "start", FS_KEY_NUMBER, T(o.param[p].start), "0", "where the search starts");
        k->min = -1e12, k->max = 1e12;
        k = add_key(b, sec, "log", FS_KEY_CHOICE, T(log[p]), "no", "yes: searched in log space (min > 0)");
        k->choices = "no|yes";
        k = add_key(b, sec, "weight", FS_KEY_NUMBER, T(o.param[p].weight), "1",
                    "its weight in objective = least_stiff's sum (each parameter over its min); 0 leaves it out, "
                    "e.g. a splay or a length searched beside the springs");
        k->min = 0, k->max = 1e6;
    }
    return s;
}

static fs_status bind_file(fs_config *cfg, binder *b, target *t, fs_error *err)
{
    take_relative_to(cfg, b);
    fs_status s = collect_params(cfg, b, &t->o, err);
    if (s == FS_OK)
        s = add_file_keys(cfg, b, t, err);
    return s == FS_OK ? fs_config_bind(cfg, b->keys, b->nkeys, t, err) : s;
}

void fs_optimize_print_keys(void *out_file)
{
    binder *b = calloc(1, sizeof *b);
    target *t = calloc(1, sizeof *t);
    fs_config cfg = {0}; /* no entries: no [param.NAME] key names a list's element */
    fs_error err;
    if (!b || !t) {
        free(b);
        free(t);
        return;
    }
    snprintf(b->sections[0], FS_NAME_MAX, "param.NAME");
    snprintf(b->csections[0], FS_NAME_MAX, "constraint.NAME");
    snprintf(t->o.constraint[0].name, FS_NAME_MAX, "NAME");
    t->o.nparams = t->o.nconstraints = 1;
    if (add_file_keys(&cfg, b, t, &err) == FS_OK) {
        /* [optimize] relative_to is read by hand (a foot of the campaign): said here as a key */
        fs_key *k = add_key(b, "optimize", "relative_to", FS_KEY_CHOICE, 0, "",
                            "a foot of the campaign, run once: every other foot's cell must land at least as "
                            "often as this foot's cell of the same terrain and robot, on the same seeds");
        k->choices = "a [foot.NAME] of the campaign";
        for (int i = 0; i < b->nkeys; i++)
            if (b->keys[i].choices == b->key_choices)
                b->keys[i].choices = "a number key of a design, terrain, robot or scenario file (section.key), "
                                     "or one element of a list key (section.key[i])";
        fs_config_print_keys(b->keys, b->nkeys, "Design search files (scenarios/optimize_*.ini)", out_file);
    }
    free(b);
    free(t);
}

/* [optimize] sweep names a constraint's bound and sweep_values gives it distinct values, each on
 * the right side of the constraint's other bound. */
static fs_status check_sweep(const fs_config *cfg, const target *t, fs_optimize *o, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    const fs_series *v = &o->sweep_values;
    o->sweep_constraint = t->sweep_choice > 0 ? (t->sweep_choice - 1) / 2 : -1;
    o->sweep_min = t->sweep_choice > 0 && !(t->sweep_choice % 2);
    if (o->sweep_constraint < 0 && v->n)
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep_values without sweep; name the bound they are values of, e.g. "
                       "sweep = NAME.max for a [constraint.NAME]",
                       fs_config_where(cfg, "optimize", "sweep_values", where, sizeof where));
    if (o->sweep_constraint < 0)
        return FS_OK;
    const fs_opt_constraint *c = &o->constraint[o->sweep_constraint];
    const char *bound = o->sweep_min ? "min" : "max";
    if (!v->n)
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep = %s.%s has no values; give sweep_values = v1, v2, ... (one "
                       "search each)", fs_config_where(cfg, "optimize", "sweep", where, sizeof where), c->name, bound);
    fs_config_where(cfg, "optimize", "sweep_values", where, sizeof where);
    for (int i = 0; i < v->n; i++) {
        for (int j = 0; j < i; j++)
            if (v->v[j] == v->v[i])
                return fs_fail(err, FS_BAD_INPUT, "%s: sweep_values: %g is given twice (values %d and %d); give each "
                               "value once", where, v->v[i], j + 1, i + 1);
        double other = o->sweep_min ? c->max : c->min;
        if (o->sweep_min ? !(v->v[i] < other) : !(v->v[i] > other))
            return fs_fail(err, FS_BAD_INPUT, "%s: sweep_values: %s.%s = %g is not %s its %s = %g; give values %s it",
                           where, c->name, bound, v->v[i], o->sweep_min ? "below" : "above",
                           o->sweep_min ? "max" : "min", other, o->sweep_min ? "below" : "above");
    }
    return FS_OK;
}

void fs_optimize_sweep_to(fs_optimize *o, int i)
{
    fs_opt_constraint *c = &o->constraint[o->sweep_constraint];
    *(o->sweep_min ? &c->min : &c->max) = o->sweep_values.v[i];
}

/* Every parameter names a key, with min < max, the start within, min > 0 for a log one. */
static fs_status check_params(const fs_config *cfg, const target *t, fs_optimize *o, fs_error *err)
{
    char where[FS_PATH_MAX + 80], sec[FS_NAME_MAX + 8];
    int weighed = 0; /* parameters in least_stiff's sum */
    if (!o->campaign_path[0])
        return fs_fail(err, FS_BAD_INPUT, "%s: [optimize] campaign is missing; name the campaign whose trials and "
                                          "expectations the search uses", cfg->path);
    if (o->objective == FS_OBJECTIVE_NONE)
        return fs_fail(err, FS_BAD_INPUT, "%s: [optimize] objective is missing; name what the search minimises: "
                                          "objective = least_stiff or objective = lightest", cfg->path);
    for (int p = 0; p < o->nparams; p++) {
        fs_opt_param *q = &o->param[p];
        snprintf(sec, sizeof sec, "param.%s", q->name);
        const fs_key *k = t->key_choice[p] > 0 ? fs_campaign_sweepable(t->key_choice[p]) : NULL;
        if (!k && t->key_choice[p] != -1)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] needs key = a number of a design, robot, scenario or terrain "
                           "file, e.g. springs.k_d1_N_per_m, or a list's element, e.g. chains.splay_deg[1]",
                           cfg->path, sec);
        if (k)
            snprintf(q->key, sizeof q->key, "%s.%s", k->section, k->name);
        q->log = t->log[p];
        if (!(q->min < q->max) || q->start < q->min || q->start > q->max)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] min = %g, max = %g, start = %g: give min < max and the start "
                           "between them", fs_config_where(cfg, sec, "start", where, sizeof where), sec, q->min,
                           q->max, q->start);
        if (q->log && !(q->min > 0))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] log = yes needs min > 0 (it is %g)",
                           fs_config_where(cfg, sec, "log", where, sizeof where), sec, q->min);
        if (o->objective == FS_OBJECTIVE_LEAST_STIFF && q->weight > 0 && !(q->min > 0))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] min = %g: objective = least_stiff sums each parameter over its "
                           "min, which needs min > 0; give min > 0, or weight = 0 to leave %s out of the sum",
                           fs_config_where(cfg, sec, "min", where, sizeof where), sec, q->min, q->name);
        if (o->objective != FS_OBJECTIVE_LEAST_STIFF && fs_config_has(cfg, sec, "weight"))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] weight is a term of objective = least_stiff's sum; objective = "
                           "lightest minimises the foot's mass and weighs no parameter: remove it",
                           fs_config_where(cfg, sec, "weight", where, sizeof where), sec);
        weighed += q->weight > 0;
    }
    if (o->objective == FS_OBJECTIVE_LEAST_STIFF && o->nparams && !weighed)
        return fs_fail(err, FS_BAD_INPUT, "%s: objective = least_stiff, but every parameter has weight = 0: the sum "
                       "is always 0; give the stiffnesses weight = 1 (the default)",
                       fs_config_where(cfg, "optimize", "objective", where, sizeof where));
    for (int n = 0; n < o->nconstraints; n++) {
        char csec[FS_NAME_MAX + 16];
        snprintf(csec, sizeof csec, "constraint.%s", o->constraint[n].name);
        if (o->constraint[n].of == FS_QUANTITY_NONE)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] names no quantity; give of = foot_mass_kg or of = ankle_drop_m",
                           fs_config_where(cfg, csec, fs_config_has(cfg, csec, "max") ? "max" : "min", where, sizeof where),
                           csec);
        int swept = t->sweep_choice > 0 && (t->sweep_choice - 1) / 2 == n;
        int has_max = fs_config_has(cfg, csec, "max") || (swept && t->sweep_choice % 2),
            has_min = fs_config_has(cfg, csec, "min") || (swept && !(t->sweep_choice % 2));
        if (!has_max && !has_min)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] has no bound; give max = the largest value allowed and/or "
                           "min = the smallest (%s)", fs_config_where(cfg, csec, "of", where, sizeof where), csec,
                           o->constraint[n].of == FS_QUANTITY_FOOT_MASS_KG ? "kg" : "m");
        if (!has_max)
            o->constraint[n].max = HUGE_VAL;
        if (!swept && !(o->constraint[n].min < o->constraint[n].max))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] min = %g is not below max = %g; give min < max",
                           fs_config_where(cfg, csec, "min", where, sizeof where), csec, o->constraint[n].min,
                           o->constraint[n].max);
    }
    return check_sweep(cfg, t, o, err);
}

/* relative_to, taken as text, is one of the loaded campaign's feet, and some other foot is left. */
static fs_status find_reference(const binder *b, fs_optimize *o, fs_error *err)
{
    o->reference = -1;
    if (!b->relative_to[0])
        return FS_OK;
    char feet[FS_CAMPAIGN_MAX_FEET * (FS_NAME_MAX + 2)] = "";
    for (int f = 0; f < o->campaign.nfeet; f++) {
        if (!strcmp(o->campaign.foot[f].name, b->relative_to))
            o->reference = f;
        size_t len = strlen(feet);
        snprintf(feet + len, sizeof feet - len, "%s%s", f ? ", " : "", o->campaign.foot[f].name);
    }
    if (o->reference < 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: [optimize] relative_to = %s is not a foot of campaign %s; its feet: %s",
                       b->relative_where, b->relative_to, o->campaign.path, feet);
    if (o->campaign.nfeet < 2)
        return fs_fail(err, FS_BAD_INPUT, "%s: [optimize] relative_to = %s leaves no foot to search: campaign %s has "
                       "only that foot; add the foot the parameters change", b->relative_where, b->relative_to,
                       o->campaign.path);
    return FS_OK;
}

static int foot_of(const fs_campaign *c, int cell) { return cell / c->nrobots / c->nterrains; }

/* The first cell a candidate is put into: the first foot's, or the second's when the first is the
 * reference. */
static int first_candidate(const fs_optimize *o)
{
    return o->reference == 0 ? o->campaign.nterrains * o->campaign.nrobots : 0;
}

fs_status fs_optimize_load(const char *path, const char *const *sets, int nsets, fs_optimize *o, fs_error *err)
{
    memset(o, 0, sizeof *o);
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    /* --set optimize.KEY=... changes this file; any other goes to the campaign (and on to the trials) */
    const char *rest[FS_CAMPAIGN_MAX_SET];
    int nrest = 0;
    for (int i = 0; s == FS_OK && i < nsets; i++)
        if (!strncmp(sets[i], "optimize.", 9))
            s = fs_config_override(&cfg, sets[i], err);
        else if (nrest < FS_CAMPAIGN_MAX_SET)
            rest[nrest++] = sets[i];
        else
            s = fs_fail(err, FS_BAD_INPUT, "--set: at most %d overrides", FS_CAMPAIGN_MAX_SET);
    binder *b = calloc(1, sizeof *b);
    target *t = calloc(1, sizeof *t);
    if (s == FS_OK && (!b || !t))
        s = fs_fail(err, FS_NO_MEMORY, "out of memory");
    if (s == FS_OK)
        s = bind_file(&cfg, b, t, err);
    if (s == FS_OK) {
        *o = t->o;
        s = check_params(&cfg, t, o, err);
    }
    snprintf(o->path, sizeof o->path, "%s", path);
    fs_path_stem(path, o->name, sizeof o->name);
    free(t);
    fs_config_free(&cfg);
    if (s == FS_OK)
        s = fs_campaign_load(o->campaign_path, rest, nrest, &o->campaign, err);
    if (s == FS_OK)
        s = find_reference(b, o, err);
    free(b);
    if (s == FS_OK && !o->campaign.nexpect)
        s = fs_fail(err, FS_BAD_INPUT, "%s: campaign %s states no expectations: give it [expect.NAME] sections, the "
                    "targets the search must meet", path, o->campaign_path);
    /* every parameter must be a number of every cell's scenario, and its bounds within the key's range */
    for (int p = 0; s == FS_OK && p < o->nparams; p++) {
        fs_scenario *sc = &o->campaign.pair[first_candidate(o)];
        const fs_key *k;
        if (!fs_scenario_number(sc, o->param[p].key, &k))
            s = fs_fail(err, FS_BAD_INPUT, "%s: [param.%s] key = %s is not a number the trials have", path,
                        o->param[p].name, o->param[p].key);
        else if (o->param[p].min < k->min || o->param[p].max > k->max)
            s = fs_fail(err, FS_BAD_INPUT, "%s: [param.%s] min = %g, max = %g leave %s's range [%g, %g]", path,
                        o->param[p].name, o->param[p].min, o->param[p].max, o->param[p].key, k->min, k->max);
    }
    int npairs = s == FS_OK ? fs_campaign_npairs(&o->campaign) : 0; /* cells, times a band's ends */
    if (s == FS_OK) {
        o->file_x = calloc((size_t)npairs * (size_t)o->nparams, sizeof o->file_x[0]);
        o->view = malloc(sizeof *o->view);
        if (!o->file_x || !o->view)
            s = fs_fail(err, FS_NO_MEMORY, "out of memory");
    }
    for (int pair = 0; s == FS_OK && pair < npairs; pair++)
        for (int p = 0; p < o->nparams; p++)
            o->file_x[pair * o->nparams + p] = *fs_scenario_number(&o->campaign.pair[pair], o->param[p].key, NULL);
    if (s == FS_OK) {
        double x[FS_OPTIMIZE_MAX_PARAMS];
        for (int p = 0; p < o->nparams; p++)
            x[p] = o->param[p].start;
        s = fs_optimize_apply(o, x, err);
    }
    if (s != FS_OK)
        fs_optimize_free(o);
    return s;
}

void fs_optimize_free(fs_optimize *o)
{
    if (o->campaign.pair)
        fs_campaign_free(&o->campaign);
    free(o->file_x);
    free(o->view);
    free(o->run_x);
    free(o->run_first_seed);
    free(o->run_seeds);
    free(o->run_closeness);
    free(o->run_rows);
    o->file_x = NULL;
    o->view = NULL;
    o->run_x = NULL, o->run_first_seed = o->run_seeds = NULL, o->run_closeness = NULL, o->run_rows = NULL;
    o->nrun = o->run_capacity = 0;
}

/* ---- the candidates that ran -------------------------------------------------------------- */

int fs_optimize_recall(fs_optimize *o, const double *x, fs_campaign_row *rows, double *closeness)
{
    size_t n = (size_t)o->nparams, ncells = (size_t)fs_campaign_ncells(&o->campaign);
    for (int i = 0; i < o->nrun; i++)
        if (o->run_first_seed[i] == o->campaign.first_seed && o->run_seeds[i] == o->campaign.seeds &&
            !memcmp(o->run_x + (size_t)i * n, x, n * sizeof x[0])) {
            memcpy(rows, o->run_rows + (size_t)i * ncells, ncells * sizeof rows[0]);
            if (closeness)
                *closeness = o->run_closeness[i];
            o->repeats++;
            return 1;
        }
    return 0;
}

/* Grows a run_ array to capacity elements of size each. */
static int grow(void **array, int capacity, size_t size)
{
    void *p = realloc(*array, (size_t)capacity * size);
    if (p)
        *array = p;
    return p != NULL;
}

fs_status fs_optimize_remember(fs_optimize *o, const double *x, const fs_campaign_row *rows, double closeness,
                               fs_error *err)
{
    size_t n = (size_t)o->nparams, ncells = (size_t)fs_campaign_ncells(&o->campaign);
    if (o->nrun == o->run_capacity) {
        int cap = o->run_capacity ? 2 * o->run_capacity : 64;
        if (!grow((void **)&o->run_x, cap, n * sizeof o->run_x[0]) ||
            !grow((void **)&o->run_first_seed, cap, sizeof o->run_first_seed[0]) ||
            !grow((void **)&o->run_seeds, cap, sizeof o->run_seeds[0]) ||
            !grow((void **)&o->run_closeness, cap, sizeof o->run_closeness[0]) ||
            !grow((void **)&o->run_rows, cap, ncells * sizeof o->run_rows[0]))
            return fs_fail(err, FS_NO_MEMORY, "%s: out of memory for the candidates that ran", o->path);
        o->run_capacity = cap;
    }
    int i = o->nrun++;
    memcpy(o->run_x + (size_t)i * n, x, n * sizeof x[0]);
    o->run_first_seed[i] = o->campaign.first_seed;
    o->run_seeds[i] = o->campaign.seeds;
    o->run_closeness[i] = closeness;
    memcpy(o->run_rows + (size_t)i * ncells, rows, ncells * sizeof rows[0]);
    return FS_OK;
}

/* ---- a candidate -------------------------------------------------------------------------- */

fs_status fs_optimize_apply(fs_optimize *o, const double *x, fs_error *err)
{
    int nends = fs_campaign_nends(&o->campaign);
    for (int pair = 0; pair < fs_campaign_npairs(&o->campaign); pair++) { /* every cell at a band's every end */
        if (foot_of(&o->campaign, pair / nends) == o->reference)
            continue; /* the reference foot stays as its files give it */
        fs_scenario *sc = &o->campaign.pair[pair];
        for (int p = 0; p < o->nparams; p++)
            *fs_scenario_number(sc, o->param[p].key, NULL) = x ? x[p] : o->file_x[pair * o->nparams + p];
        fs_status s = fs_scenario_compile(sc, err);
        if (s != FS_OK)
            return s;
    }
    return FS_OK;
}

double fs_optimize_objective(const fs_optimize *o, const double *x)
{
    if (o->objective == FS_OBJECTIVE_LIGHTEST)
        return fs_optimize_quantity(o, FS_QUANTITY_FOOT_MASS_KG);
    double sum = 0;
    for (int p = 0; p < o->nparams; p++) /* a weight of 1 gives x / min to the bit */
        if (o->param[p].weight > 0)
            sum += x[p] / o->param[p].min * o->param[p].weight;
    return sum;
}

double fs_optimize_quantity(const fs_optimize *o, int q)
{
    const fs_scenario *sc = &o->campaign.pair[first_candidate(o)];
    if (q == FS_QUANTITY_FOOT_MASS_KG)
        return sc->geom.total_mass_kg;
    if (q != FS_QUANTITY_ANKLE_DROP_M || sc->design.kind != FS_FOOT_BIOMIMETIC)
        return NAN;
    fs_planar_load load = {.load_N = sc->design.design_load_kg * sc->def.gravity_m_per_s2,
                           .gravity_m_per_s2 = sc->def.gravity_m_per_s2, .frictionless = 1};
    fs_planar_result r;
    fs_error err;
    if (fs_planar_equilibrium(&sc->design, &sc->geom, 2, &load, &r, &err) != FS_OK || !r.converged || !r.stable)
        return NAN;
    return r.ankle_drop_m;
}

double fs_optimize_violation(const fs_optimize *o)
{
    double v = 0;
    for (int n = 0; n < o->nconstraints; n++) {
        const fs_opt_constraint *k = &o->constraint[n];
        double q = fs_optimize_quantity(o, k->of);
        if (!isfinite(q))
            v += 1;
        else if (q > k->max)
            v += k->max > 0 ? (q - k->max) / k->max : q - k->max;
        else if (q < k->min)
            v += (k->min - q) / k->min;
    }
    return v;
}

int fs_optimize_ntargets(const fs_optimize *o)
{
    const fs_campaign *c = &o->campaign;
    return c->nexpect + (o->reference >= 0 ? (c->nfeet - 1) * c->nterrains * c->nrobots : 0);
}

int fs_optimize_reference_cell(const fs_optimize *o, int cell)
{
    const fs_campaign *c = &o->campaign;
    if (o->reference < 0)
        return -1;
    int per_foot = c->nterrains * c->nrobots;
    return o->reference * per_foot + cell % per_foot;
}

/* Expectation i's cell and how far its success rate lies below min_success (*low) and above
 * max_success (the returned sum's other term). */
static double expectation_miss(const fs_campaign *c, int i, const fs_campaign_row *rows, int *cell, double *low)
{
    const fs_expectation *e = &c->expect[i];
    *cell = (e->foot * c->nterrains + e->terrain) * c->nrobots + e->robot;
    double rate = rows[*cell].success_rate;
    *low = fmax(0, e->min_success - rate);
    return *low + fmax(0, rate - e->max_success);
}

/* How far a searched foot's cell lands less often than the reference foot's in its terrain and robot. */
static double relative_miss(const fs_optimize *o, int cell, const fs_campaign_row *rows)
{
    return fmax(0, rows[fs_optimize_reference_cell(o, cell)].success_rate - rows[cell].success_rate);
}

double fs_optimize_shortfall(const fs_optimize *o, const fs_campaign_row *rows)
{
    const fs_campaign *c = &o->campaign;
    double miss = 0;
    int cell;
    double low;
    for (int i = 0; i < c->nexpect; i++)
        miss += expectation_miss(c, i, rows, &cell, &low);
    for (cell = 0; o->reference >= 0 && cell < fs_campaign_ncells(c); cell++)
        if (foot_of(c, cell) != o->reference)
            miss += relative_miss(o, cell, rows);
    return miss;
}

int fs_optimize_pareto(const double *a, const double *b, int n, int *keep)
{
    int count = 0;
    for (int i = 0; i < n; i++) {
        keep[i] = 1;
        for (int j = 0; j < n && keep[i]; j++) {
            if (j == i)
                continue;
            int as_good = a[j] <= a[i] && b[j] <= b[i], better = a[j] < a[i] || b[j] < b[i];
            if (as_good && (better || j < i)) /* dominated, or an equal point came first */
                keep[i] = 0;
        }
        count += keep[i];
    }
    return count;
}

/* One cell's closeness: the mean over its trials (at every end of a band) that did not land of
 * 1 - (time up / window). */
static double cell_closeness(const fs_campaign *c, int cell, const fs_trial_result *results)
{
    double window = fs_campaign_pair(c, cell)->def.duration_s, miss = 0;
    int n = 0;
    int per_cell = c->seeds * fs_campaign_nends(c); /* a cell's trials, at every band end */
    for (int k = 0; k < per_cell; k++) {
        const fs_trial_result *r = &results[cell * per_cell + k];
        if (r->outcome == FS_LANDED)
            continue;
        double up = isfinite(r->end_time_s) ? fmin(1, fmax(0, r->end_time_s / window)) : 0;
        miss += 1 - up;
        n++;
    }
    return n ? miss / n : 0;
}

double fs_optimize_closeness(const fs_optimize *o, const fs_trial_result *results, const fs_campaign_row *rows)
{
    const fs_campaign *c = &o->campaign;
    double sum = 0;
    int cell;
    double low;
    for (int i = 0; i < c->nexpect; i++) { /* a target met has nothing to climb; one landing too often, */
        expectation_miss(c, i, rows, &cell, &low); /* later falls would lead away from */
        if (low > 0)
            sum += cell_closeness(c, cell, results);
    }
    for (cell = 0; o->reference >= 0 && cell < fs_campaign_ncells(c); cell++)
        if (foot_of(c, cell) != o->reference && relative_miss(o, cell, rows) > 0)
            sum += cell_closeness(c, cell, results);
    return sum;
}

fs_status fs_optimize_run_trials(fs_optimize *o, fs_optimize_trials trials, void *user, fs_trial_result *results,
                                 int reference, fs_error *err)
{
    const fs_campaign *c = &o->campaign;
    if (o->reference < 0)
        return trials(user, c, results, err);
    int per_foot = c->nterrains * c->nrobots;
    for (int f = 0; f < c->nfeet; f++) {
        if (f == o->reference && !reference)
            continue;
        /* foot f's cells alone: cells are numbered foot-major, so they and their trials are a block */
        *o->view = *c;
        o->view->foot[0] = c->foot[f];
        o->view->nfeet = 1;
        o->view->nexpect = 0;
        o->view->pair = c->pair + f * per_foot * fs_campaign_nends(c); /* with its band's ends */
        fs_status s = trials(user, o->view,
                             results + (size_t)f * (size_t)per_foot * (size_t)fs_campaign_nends(c) * (size_t)c->seeds, err);
        if (s != FS_OK)
            return s;
    }
    return FS_OK;
}

/* ---- the search --------------------------------------------------------------------------- */

typedef struct search {
    fs_optimize *o;
    fs_optimize_trials trials;
    fs_optimize_report report;
    void *user;
    fs_trial_result *results;
    fs_campaign_row *rows;
    double weight;               /* per unit of shortfall */
    int evaluations;
    double best[FS_OPTIMIZE_MAX_PARAMS], best_value;
    fs_status status;            /* the first failure; the search is then forced to stop */
    fs_error err;
} search;

/* The search's coordinates: log x for a log parameter. */
static double to_u(const fs_opt_param *q, double x) { return q->log ? log(x) : x; }
static double to_x(const fs_opt_param *q, double u) { return q->log ? exp(u) : u; }

static double penalised(unsigned n, const double *u, double *grad, void *data)
{
    (void)grad;
    search *s = data;
    fs_optimize *o = s->o;
    double x[FS_OPTIMIZE_MAX_PARAMS];
    for (unsigned p = 0; p < n; p++)
        x[p] = fmin(o->param[p].max, fmax(o->param[p].min, to_x(&o->param[p], u[p])));
    fs_status st = fs_optimize_apply(o, x, &s->err);
    double violation = st == FS_OK ? fs_optimize_violation(o) : 0, obj = fs_optimize_objective(o, x), value;
    int ntargets = fs_optimize_ntargets(o);
    if (st == FS_OK && violation > 0) {
        /* infeasible: no trial runs; worse than any candidate that runs, however many targets it
           misses (each target's shortfall is at most 1, its slope less than one) */
        value = obj + s->weight * (ntargets + 1 + violation);
        s->evaluations++;
        if (s->report)
            s->report(s->user, o, s->evaluations, x, obj, NAN, violation, NULL);
    } else {
        double closeness = 0;
        if (st == FS_OK && !fs_optimize_recall(o, x, s->rows, &closeness)) {
            st = fs_optimize_run_trials(o, s->trials, s->user, s->results, 0, &s->err);
            if (st == FS_OK) {
                fs_campaign_summarize(&o->campaign, s->results, s->rows);
                closeness = fs_optimize_closeness(o, s->results, s->rows);
                st = fs_optimize_remember(o, x, s->rows, closeness, &s->err);
            }
        }
        if (st != FS_OK) {
            s->status = st;
            return HUGE_VAL;
        }
        double miss = fs_optimize_shortfall(o, s->rows);
        /* how soon the misses fell, worth less than one seed on any target */
        double slope = closeness / (ntargets + 1) / o->campaign.seeds;
        value = obj + s->weight * (miss + slope);
        s->evaluations++;
        if (s->report)
            s->report(s->user, o, s->evaluations, x, obj, miss, 0, s->rows);
    }
    if (value < s->best_value) {
        s->best_value = value;
        memcpy(s->best, x, n * sizeof x[0]);
    }
    return value;
}

fs_status fs_optimize_run(fs_optimize *o, fs_optimize_trials trials, fs_optimize_report report, void *user,
                          fs_trial_result *results, fs_campaign_row *rows, double *best, double *value,
                          fs_error *err)
{
    unsigned n = (unsigned)o->nparams;
    search s = {.o = o, .trials = trials, .report = report, .user = user, .results = results, .rows = rows,
                .best_value = HUGE_VAL, .status = FS_OK};
    /* one seed short of a target (1/seeds of shortfall) costs 100 times the objective's whole range:
       its value with every parameter at its upper bound (a mass or a stiffness grows with them) */
    double upper[FS_OPTIMIZE_MAX_PARAMS];
    for (int p = 0; p < o->nparams; p++)
        upper[p] = o->param[p].max;
    fs_status st = fs_optimize_apply(o, upper, err);
    if (st != FS_OK)
        return st;
    double range = fs_optimize_objective(o, upper);
    s.weight = 100 * range * o->campaign.seeds;
    /* the reference foot's trials, once: they do not change with the candidate */
    if (o->reference >= 0 && (st = fs_optimize_run_trials(o, trials, user, results, 1, err)) != FS_OK)
        return st;
    double lo[FS_OPTIMIZE_MAX_PARAMS], hi[FS_OPTIMIZE_MAX_PARAMS], u[FS_OPTIMIZE_MAX_PARAMS], step[FS_OPTIMIZE_MAX_PARAMS];
    for (unsigned p = 0; p < n; p++) {
        const fs_opt_param *q = &o->param[p];
        lo[p] = to_u(q, q->min), hi[p] = to_u(q, q->max), u[p] = to_u(q, q->start);
        step[p] = (hi[p] - lo[p]) / 8; /* the first simplex spans an eighth of each range */
    }
    nlopt_opt opt = nlopt_create(NLOPT_LN_SBPLX, n);
    if (!opt)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the optimizer");
    nlopt_set_lower_bounds(opt, lo);
    nlopt_set_upper_bounds(opt, hi);
    nlopt_set_initial_step(opt, step);
    nlopt_set_min_objective(opt, penalised, &s);
    nlopt_set_maxeval(opt, o->max_evaluations);
    nlopt_set_xtol_rel(opt, 1e-3);
    double minf;
    nlopt_result r = nlopt_optimize(opt, u, &minf);
    nlopt_destroy(opt);
    if (s.status != FS_OK) {
        *err = s.err;
        return s.status;
    }
    if (r < 0 && r != NLOPT_ROUNDOFF_LIMITED && s.evaluations == 0)
        return fs_fail(err, FS_NUMERICAL, "%s: the optimizer stopped before any evaluation (NLopt code %d)", o->path,
                       (int)r);
    memcpy(best, s.best, n * sizeof best[0]);
    *value = s.best_value;
    return FS_OK;
}
