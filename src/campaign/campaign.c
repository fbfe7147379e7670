/* campaign.c: campaign files bound with fs_config, trial statistics (Wilson intervals,
 * medians), result files, expectations and the comparison of two summaries. */
#include "footsim/campaign/fs_campaign.h"

#include "footsim/base/fs_path.h"
#include "footsim/base/fs_stats.h"

#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"
#include "footsim/model/fs_scenario.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* ---- metrics ------------------------------------------------------------------------------ */

const fs_metric fs_campaign_metrics[FS_CAMPAIGN_NMETRICS] = {
    {"end_time_s", "0.1, 0.005"},   {"touchdown_s", "0.1, 0.005"},     {"peak_tilt_deg", "0.1, 1"},
    {"final_tilt_deg", "0.1, 1"},   {"peak_force_N", "0.1, 10"},       {"impact_impulse_Ns", "0.1, 0.5"},
    {"settle_time_s", "0.1, 0.005"}, {"mean_contacts", "0.1, 1"},      {"final_contacts", "0.1, 1"},
    {"ankle_drop_m", "0.1, 0.001"}, {"slip_m", "0.1, 0.001"},          {"steps", "0.1, 100"},
};

double fs_metric_value(const fs_trial_result *r, int m)
{
    const double v[FS_CAMPAIGN_NMETRICS] = {r->end_time_s,    r->touchdown_s,       r->peak_tilt_deg,
                                            r->final_tilt_deg, r->peak_force_N,      r->impact_impulse_Ns,
                                            r->settle_time_s,  r->mean_contacts,     r->final_contacts,
                                            r->ankle_drop_m,   r->slip_m,            (double)r->steps};
    return v[m];
}

/* ---- the campaign file ---------------------------------------------------------------------- */

enum { MAX_KEYS = 8 + FS_CAMPAIGN_NMETRICS + 2 * FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_FEET * 1 +
                  4 * FS_CAMPAIGN_MAX_EXPECT };

/* The schema of one file, built from the sections it has, and the text its keys point to. */
typedef struct binder {
    fs_key keys[MAX_KEYS];
    int nkeys;
    char sections[FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_EXPECT][FS_NAME_MAX];
    int nsections;
    char foot_choices[FS_CAMPAIGN_MAX_FEET * FS_NAME_MAX];
    char terrain_choices[FS_CAMPAIGN_MAX_TERRAINS * FS_NAME_MAX];
    char sweep_choices[4096];
    char sweep_values[FS_VALUE_MAX];  /* as given, or "" */
    char sweep_where[FS_PATH_MAX + 80];
} binder;

#define C(member) offsetof(fs_campaign, member)

static const fs_key campaign_keys[] = {
    {"campaign", "trial", FS_KEY_PATH, C(trial_path), 0, 0, 0, 0, NULL, "", "",
     "the trial scenario (with [robot] and [landing]), relative to the campaign file"},
    {"campaign", "seeds", FS_KEY_INTEGER, C(seeds), 1, FS_CAMPAIGN_MAX_SEEDS, 0, 0, NULL, "", "50",
     "trials per foot and terrain"},
    {"campaign", "first_seed", FS_KEY_INTEGER, C(first_seed), 0, 1e9, 0, 0, NULL, "", "1",
     "seeds are first_seed, first_seed + 1, ..."},
};
enum { NCAMPAIGN_KEYS = sizeof campaign_keys / sizeof campaign_keys[0] };

static int is_campaign_section(const char *section)
{
    return !strcmp(section, "campaign") || !strcmp(section, "tolerance") || !strncmp(section, "foot.", 5) ||
           !strncmp(section, "terrain.", 8) || !strncmp(section, "expect.", 7);
}

static fs_key *add_key(binder *b, const char *section, const char *name, fs_key_type type, size_t offset)
{
    fs_key *k = &b->keys[b->nkeys++];
    *k = (fs_key){section, name, type, offset, 0, 0, 0, 0, NULL, "", "", ""};
    return k;
}

static void append_choice(char *list, size_t size, const char *word)
{
    size_t n = strlen(list);
    snprintf(list + n, size - n, "%s%s", n ? "|" : "", word);
}

/* A section's NAME after its prefix: letters, digits, '_' and '-', so it is safe in every file. */
static fs_status check_name(const fs_config *cfg, const fs_entry *e, const char *name, fs_error *err)
{
    size_t n = strlen(name);
    int ok = n > 0 && strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == n;
    if (ok)
        return FS_OK;
    char where[FS_PATH_MAX + 80];
    return fs_fail(err, FS_BAD_INPUT, "%s: section [%s] needs a NAME of letters, digits, '_' or '-' after its '.'",
                   fs_config_where(cfg, e->section, e->name, where, sizeof where), e->section);
}

/* Takes [campaign] sweep_values out of cfg (fs_config has no list of arbitrary length). */
static void take_sweep_values(fs_config *cfg, binder *b)
{
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        if (strcmp(e->section, "campaign") || strcmp(e->name, "sweep_values"))
            continue;
        snprintf(b->sweep_values, sizeof b->sweep_values, "%s", e->value);
        fs_config_where(cfg, "campaign", "sweep_values", b->sweep_where, sizeof b->sweep_where);
        memmove(e, e + 1, (size_t)(cfg->count - i - 1) * sizeof *e);
        cfg->count--;
        return;
    }
}

/* Splits the sweep values; each must be a finite number. Returns the count, or -1 (err set). */
static int parse_sweep(const binder *b, char values[][FS_NAME_MAX], fs_error *err)
{
    char buf[FS_VALUE_MAX];
    snprintf(buf, sizeof buf, "%s", b->sweep_values);
    int n = 0;
    char *save = NULL;
    for (char *tok = strtok_r(buf, ", \t", &save); tok; tok = strtok_r(NULL, ", \t", &save)) {
        double v;
        fs_number num = fs_parse_number(tok, &v);
        if (num != FS_NUMBER_OK || strlen(tok) >= FS_NAME_MAX / 2) {
            fs_fail(err, FS_BAD_INPUT, "%s: sweep_values: '%s' %s; allowed: comma-separated numbers", b->sweep_where,
                    tok, num != FS_NUMBER_OK ? fs_number_problem(num) : "is too long");
            return -1;
        }
        if (n == FS_CAMPAIGN_MAX_TERRAINS) {
            fs_fail(err, FS_BAD_INPUT, "%s: sweep_values: more than %d values", b->sweep_where,
                    FS_CAMPAIGN_MAX_TERRAINS);
            return -1;
        }
        snprintf(values[n++], FS_NAME_MAX, "%s", tok);
    }
    if (n == 0)
        fs_fail(err, FS_BAD_INPUT, "%s: sweep_values is empty; give the values of the swept key, e.g. 0, 0.001, 0.002",
                b->sweep_where);
    return n ? n : -1;
}

/* The [campaign] and [tolerance] keys. */
static void add_static_keys(binder *b)
{
    for (int i = 0; i < NCAMPAIGN_KEYS; i++)
        b->keys[b->nkeys++] = campaign_keys[i];
    /* the terrain keys a sweep may vary: every number of a terrain file */
    snprintf(b->sweep_choices, sizeof b->sweep_choices, "none");
    for (int i = 0; i < fs_terrain_nkeys; i++)
        if (fs_terrain_keys[i].type == FS_KEY_NUMBER || fs_terrain_keys[i].type == FS_KEY_INTEGER) {
            char word[2 * FS_NAME_MAX + 2];
            snprintf(word, sizeof word, "%s.%s", fs_terrain_keys[i].section, fs_terrain_keys[i].name);
            append_choice(b->sweep_choices, sizeof b->sweep_choices, word);
        }
    fs_key *k = add_key(b, "campaign", "sweep", FS_KEY_CHOICE, C(sweep_choice));
    k->choices = b->sweep_choices;
    k->fallback = "none";
    k->help = "a terrain key to sweep over sweep_values (the campaign then has one terrain)";
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        k = add_key(b, "tolerance", fs_campaign_metrics[m].name, FS_KEY_LIST, C(tolerance[m]));
        k->max = 1e12;
        k->count = 2;
        k->fallback = fs_campaign_metrics[m].tolerance;
        k->help = "relative, absolute: how far the median may move from the baseline's";
    }
}

/* Finds or adds section in list; returns 0 when the list is full. */
static int note_section(char list[][FS_NAME_MAX], int *count, int max, const char *section)
{
    for (int i = 0; i < *count; i++)
        if (!strcmp(list[i], section))
            return 1;
    if (*count == max)
        return 0;
    memcpy(list[(*count)++], section, FS_NAME_MAX);
    return 1;
}

/* Collects the [foot.NAME], [terrain.NAME] and [expect.NAME] sections of cfg, in file order. */
static fs_status collect_sections(const fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    int *count[3] = {&c->nfeet, &c->nterrains, &c->nexpect};
    const int max[3] = {FS_CAMPAIGN_MAX_FEET, FS_CAMPAIGN_MAX_TERRAINS, FS_CAMPAIGN_MAX_EXPECT};
    for (int i = 0; i < cfg->count; i++) {
        const fs_entry *e = &cfg->entries[i];
        const char *dot = strchr(e->section, '.');
        if (!dot || !is_campaign_section(e->section))
            continue;
        fs_status s = check_name(cfg, e, dot + 1, err);
        if (s != FS_OK)
            return s;
        int group = e->section[0] == 'f' ? 0 : e->section[0] == 't' ? 1 : 2;
        int first = group == 0 ? 0 : group == 1 ? FS_CAMPAIGN_MAX_FEET : FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS;
        if (!note_section(b->sections + first, count[group], max[group], e->section))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s]: too many sections of this group (at most %d feet, %d terrains, "
                           "%d expectations)", cfg->path, e->section, max[0], max[1], max[2]);
    }
    return FS_OK;
}

/* Adds the keys of every [foot.NAME], [terrain.NAME] and [expect.NAME] section of cfg. */
static fs_status add_dynamic_keys(fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    fs_status s = collect_sections(cfg, b, c, err);
    if (s != FS_OK)
        return s;
    for (int i = 0; i < c->nfeet; i++) {
        const char *sec = b->sections[i];
        snprintf(c->foot[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        append_choice(b->foot_choices, sizeof b->foot_choices, c->foot[i].name);
        add_key(b, sec, "file", FS_KEY_PATH, C(foot[i].path))->help = "the foot's design file";
    }
    for (int i = 0; i < c->nterrains; i++) {
        const char *sec = b->sections[FS_CAMPAIGN_MAX_FEET + i];
        snprintf(c->terrain[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        add_key(b, sec, "file", FS_KEY_PATH, C(terrain[i].path))->help = "the terrain file";
    }
    for (int i = 0; i < c->nexpect; i++) {
        const char *sec = b->sections[FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS + i];
        snprintf(c->expect[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        add_key(b, sec, "foot", FS_KEY_CHOICE, C(expect[i].foot))->choices = b->foot_choices;
        add_key(b, sec, "terrain", FS_KEY_CHOICE, C(expect[i].terrain))->choices = b->terrain_choices;
        fs_key *k = add_key(b, sec, "min_success", FS_KEY_NUMBER, C(expect[i].min_success));
        k->max = 1;
        k->fallback = "0";
        k = add_key(b, sec, "max_success", FS_KEY_NUMBER, C(expect[i].max_success));
        k->max = 1;
        k->fallback = "1";
    }
    return FS_OK;
}

/* The terrain names an expectation may give: each terrain, or for a sweep each "NAME@value". */
static fs_status terrain_choices(binder *b, const fs_campaign *c, fs_error *err)
{
    if (!b->sweep_values[0]) {
        for (int i = 0; i < c->nterrains; i++)
            append_choice(b->terrain_choices, sizeof b->terrain_choices, c->terrain[i].name);
        return FS_OK;
    }
    char values[FS_CAMPAIGN_MAX_TERRAINS][FS_NAME_MAX];
    int n = parse_sweep(b, values, err);
    if (n < 0)
        return FS_BAD_INPUT;
    for (int i = 0; i < n; i++) {
        char label[2 * FS_NAME_MAX];
        snprintf(label, sizeof label, "%.30s@%.31s", c->nterrains ? c->terrain[0].name : "terrain", values[i]);
        append_choice(b->terrain_choices, sizeof b->terrain_choices, label);
    }
    return FS_OK;
}

/* One terrain swept over the values: it becomes a terrain per value, with the key's override. */
static fs_status expand_sweep(const fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    int have_sweep = c->sweep_choice > 0;
    char where[FS_PATH_MAX + 80];
    if (!have_sweep && !b->sweep_values[0])
        return FS_OK;
    if (!have_sweep)
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep_values without sweep; name the key to sweep, e.g. sweep = rough.rms_m",
                       b->sweep_where);
    if (!b->sweep_values[0])
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep needs sweep_values (comma-separated values of the key)",
                       fs_config_where(cfg, "campaign", "sweep", where, sizeof where));
    if (c->nterrains != 1)
        return fs_fail(err, FS_BAD_INPUT, "%s: a sweep varies one terrain; give exactly one [terrain.NAME] (there are %d)",
                       fs_config_where(cfg, "campaign", "sweep", where, sizeof where), c->nterrains);
    const fs_key *k = &fs_terrain_keys[0];
    for (int i = 0, n = 0; i < fs_terrain_nkeys; i++)
        if ((fs_terrain_keys[i].type == FS_KEY_NUMBER || fs_terrain_keys[i].type == FS_KEY_INTEGER) &&
            ++n == c->sweep_choice)
            k = &fs_terrain_keys[i];
    snprintf(c->sweep, sizeof c->sweep, "%s.%s", k->section, k->name);
    char values[FS_CAMPAIGN_MAX_TERRAINS][FS_NAME_MAX];
    int n = parse_sweep(b, values, err);
    fs_campaign_item base = c->terrain[0];
    for (int i = 0; i < n; i++) {
        fs_campaign_item *t = &c->terrain[i];
        *t = base;
        snprintf(t->name, sizeof t->name, "%.30s@%.31s", base.name, values[i]);
        snprintf(t->set, sizeof t->set, "%s=%.31s", c->sweep, values[i]);
        t->sweep_value = strtod(values[i], NULL);
    }
    c->nterrains = n;
    return FS_OK;
}

/* Relations between keys that no single key can judge. */
static fs_status check_relations(const fs_config *cfg, const fs_campaign *c, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    if (!c->trial_path[0])
        return fs_fail(err, FS_BAD_INPUT, "%s: [campaign] trial is missing; name the trial scenario, e.g. trial = landing_trial.ini",
                       cfg->path);
    if (c->nfeet == 0 || c->nterrains == 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: no %s; add a section like [%s] with file = ...", cfg->path,
                       c->nfeet ? "terrain" : "foot", c->nfeet ? "terrain.flat" : "foot.biomimetic");
    if ((long)c->first_seed + c->seeds - 1 > INT_MAX)
        return fs_fail(err, FS_BAD_INPUT, "%s: first_seed + seeds passes %d", cfg->path, INT_MAX);
    long ntrials = (long)c->nfeet * c->nterrains * c->seeds;
    if (ntrials > FS_CAMPAIGN_MAX_TRIALS)
        return fs_fail(err, FS_BAD_INPUT, "%s: %d feet x %d terrains x %d seeds = %ld trials; a campaign may run at "
                       "most %d: fewer seeds, or split it", fs_config_where(cfg, "campaign", "seeds", where, sizeof where),
                       c->nfeet, c->nterrains, c->seeds, ntrials, FS_CAMPAIGN_MAX_TRIALS);
    for (int i = 0; i < c->nfeet; i++)
        if (!c->foot[i].path[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [foot.%s] has no file; give file = the design", cfg->path,
                           c->foot[i].name);
    for (int i = 0; i < c->nterrains; i++)
        if (!c->terrain[i].path[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [terrain.%s] has no file; give file = the terrain", cfg->path,
                           c->terrain[i].name);
    for (int i = 0; i < c->nexpect; i++) {
        char sec[FS_NAME_MAX + 8];
        snprintf(sec, sizeof sec, "expect.%s", c->expect[i].name);
        if (c->expect[i].min_success > c->expect[i].max_success)
            return fs_fail(err, FS_BAD_INPUT, "%s: min_success = %g is above max_success = %g; make min <= max",
                           fs_config_where(cfg, sec, "min_success", where, sizeof where), c->expect[i].min_success,
                           c->expect[i].max_success);
    }
    return FS_OK;
}

/* The expectations must name their foot and terrain: the choice's default would pick the first. */
static fs_status check_expect_given(const fs_config *cfg, const fs_campaign *c, fs_error *err)
{
    for (int i = 0; i < c->nexpect; i++) {
        char sec[FS_NAME_MAX + 8];
        snprintf(sec, sizeof sec, "expect.%s", c->expect[i].name);
        int foot = 0, terrain = 0;
        for (int j = 0; j < cfg->count; j++) {
            foot |= !strcmp(cfg->entries[j].section, sec) && !strcmp(cfg->entries[j].name, "foot");
            terrain |= !strcmp(cfg->entries[j].section, sec) && !strcmp(cfg->entries[j].name, "terrain");
        }
        if (!foot || !terrain)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] needs foot = and terrain = (a [foot.NAME] and a [terrain.NAME])",
                           cfg->path, sec);
    }
    return FS_OK;
}

/* Paths become absolute, so that the trial scenario resolves them wherever it lies. */
static fs_status absolute_paths(const fs_config *cfg, fs_campaign *c, fs_error *err)
{
    fs_campaign_item *items[FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS];
    int n = 0;
    for (int i = 0; i < c->nfeet; i++)
        items[n++] = &c->foot[i];
    for (int i = 0; i < c->nterrains; i++)
        items[n++] = &c->terrain[i];
    for (int i = 0; i < n; i++) {
        char full[PATH_MAX];
        if (!realpath(items[i]->path, full))
            return fs_fail(err, FS_BAD_INPUT, "%s: %s: %s", cfg->path, items[i]->path, strerror(errno));
        if (strlen(full) + 24 >= FS_VALUE_MAX)
            return fs_fail(err, FS_BAD_INPUT, "%s: %s: path longer than %d characters; move the files", cfg->path,
                           full, FS_VALUE_MAX - 24);
        memcpy(items[i]->path, full, strlen(full) + 1); /* shorter than FS_VALUE_MAX, checked above */
    }
    return FS_OK;
}

/* Loads (and so checks) the trial scenario of every (foot, terrain), once, for the trials. */
static fs_status load_pairs(fs_campaign *c, fs_error *err)
{
    c->pair = calloc((size_t)c->nfeet * c->nterrains, sizeof *c->pair);
    if (!c->pair)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the campaign's %d scenarios", c->nfeet * c->nterrains);
    fs_status s = FS_OK;
    for (int f = 0; f < c->nfeet && s == FS_OK; f++)
        for (int t = 0; t < c->nterrains && s == FS_OK; t++) {
            char buf[3][FS_PATH_MAX + 32];
            const char *ov[FS_CAMPAIGN_MAX_SET + 3];
            int n = fs_campaign_overrides(c, f, t, buf, ov);
            fs_error e;
            fs_scenario *sc = &c->pair[f * c->nterrains + t];
            s = fs_scenario_load(c->trial_path, ov, n, sc, &e);
            if (s == FS_OK)
                s = fs_scenario_require(sc, "trial", &e);
            if (s != FS_OK)
                fs_fail(err, s, "%s (campaign %s: foot %s on terrain %s)", e.message, c->path, c->foot[f].name,
                        c->terrain[t].name);
        }
    if (s != FS_OK)
        fs_campaign_free(c);
    return s;
}

void fs_campaign_free(fs_campaign *c)
{
    for (int i = 0; c->pair && i < c->nfeet * c->nterrains; i++)
        fs_scenario_free(&c->pair[i]);
    free(c->pair);
    c->pair = NULL;
}

const fs_scenario *fs_campaign_pair(const fs_campaign *c, int foot, int terrain)
{
    return &c->pair[foot * c->nterrains + terrain];
}

static fs_status bind_file(fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    take_sweep_values(cfg, b);
    add_static_keys(b);
    fs_status s = add_dynamic_keys(cfg, b, c, err);
    if (s == FS_OK)
        s = terrain_choices(b, c, err);
    if (s == FS_OK)
        s = check_expect_given(cfg, c, err);
    if (s == FS_OK)
        s = fs_config_bind(cfg, b->keys, b->nkeys, c, err);
    return s;
}

/* An override of the file; "foot.flat.file=x" names section [foot.flat] (fs_config_override
 * splits at the first dot: the entry it makes is moved to the right section here). */
static fs_status override_dotted(fs_config *cfg, const char *assignment, fs_error *err)
{
    fs_status s = fs_config_override(cfg, assignment, err);
    fs_entry *e = &cfg->entries[cfg->count - 1];
    char *dot = strrchr(e->name, '.');
    if (s != FS_OK || e->line != 0 || !dot)
        return s;
    char section[2 * FS_NAME_MAX];
    snprintf(section, sizeof section, "%s.%.*s", e->section, (int)(dot - e->name), e->name);
    if (strlen(section) >= FS_NAME_MAX)
        return fs_fail(err, FS_BAD_INPUT, "--set %s: section name too long", assignment);
    memcpy(e->section, section, FS_NAME_MAX);
    memmove(e->name, dot + 1, strlen(dot + 1) + 1);
    /* the file's entry of that key, when there is one, takes the value */
    for (int i = 0; i < cfg->count - 1; i++) {
        fs_entry *old = &cfg->entries[i];
        if (!strcmp(old->section, e->section) && !strcmp(old->name, e->name)) {
            memcpy(old->value, e->value, sizeof old->value);
            old->line = 0;
            cfg->count--;
            break;
        }
    }
    return FS_OK;
}

fs_status fs_campaign_load(const char *path, const char *const *sets, int nsets, fs_campaign *c, fs_error *err)
{
    memset(c, 0, sizeof *c);
    snprintf(c->path, sizeof c->path, "%s", path);
    fs_path_stem(path, c->name, sizeof c->name);
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    for (int i = 0; s == FS_OK && i < nsets; i++) {
        char section[FS_VALUE_MAX];
        snprintf(section, sizeof section, "%s", sets[i]);
        char *cut = strpbrk(section, "=");
        if (cut)
            *cut = 0;
        cut = strrchr(section, '.'); /* the section may hold a dot itself: foot.flat.file */
        if (cut)
            *cut = 0;
        if (is_campaign_section(section))
            s = override_dotted(&cfg, sets[i], err);
        else if (c->nset == FS_CAMPAIGN_MAX_SET)
            s = fs_fail(err, FS_BAD_INPUT, "--set: at most %d overrides", FS_CAMPAIGN_MAX_SET);
        else
            c->set[c->nset++] = sets[i];
    }
    binder *b = calloc(1, sizeof *b);
    if (!b)
        s = s == FS_OK ? fs_fail(err, FS_NO_MEMORY, "out of memory") : s;
    if (s == FS_OK)
        s = bind_file(&cfg, b, c, err);
    if (s == FS_OK)
        s = expand_sweep(&cfg, b, c, err);
    if (s == FS_OK)
        s = check_relations(&cfg, c, err);
    if (s == FS_OK)
        s = absolute_paths(&cfg, c, err);
    free(b);
    fs_config_free(&cfg);
    return s == FS_OK ? load_pairs(c, err) : s;
}

int fs_campaign_overrides(const fs_campaign *c, int foot, int terrain, char buf[3][FS_PATH_MAX + 32],
                          const char **out)
{
    int n = 0;
    snprintf(buf[0], sizeof buf[0], "scenario.design=%s", c->foot[foot].path);
    snprintf(buf[1], sizeof buf[1], "scenario.terrain=%s", c->terrain[terrain].path);
    out[n++] = buf[0];
    out[n++] = buf[1];
    if (c->terrain[terrain].set[0]) {
        snprintf(buf[2], sizeof buf[2], "%s", c->terrain[terrain].set);
        out[n++] = buf[2];
    }
    for (int i = 0; i < c->nset; i++)
        out[n++] = c->set[i];
    return n;
}

int fs_campaign_ntrials(const fs_campaign *c) { return c->nfeet * c->nterrains * c->seeds; }

void fs_campaign_trial_of(const fs_campaign *c, int index, int *foot, int *terrain, int *seed)
{
    *seed = c->first_seed + index % c->seeds;
    *terrain = index / c->seeds % c->nterrains;
    *foot = index / c->seeds / c->nterrains;
}

/* ---- statistics --------------------------------------------------------------------------- */

void fs_wilson(int k, int n, double *low, double *high)
{
    const double z = 1.959963984540054; /* the 97.5 % quantile of the standard normal */
    double p = (double)k / n, z2n = z * z / n;
    double centre = (p + z2n / 2) / (1 + z2n);
    double half = z / (1 + z2n) * sqrt(p * (1 - p) / n + z2n / (4.0 * n));
    *low = fmax(0, centre - half);
    *high = fmin(1, centre + half);
    /* at k = 0 or k = n the bound is exactly 0 or 1 (centre and half agree but for rounding) */
    if (k == 0)
        *low = 0;
    if (k == n)
        *high = 1;
}

void fs_campaign_summarize(const fs_campaign *c, const fs_trial_result *results, fs_campaign_row *rows)
{
    double *v = malloc((size_t)c->seeds * sizeof *v);
    for (int f = 0; f < c->nfeet; f++)
        for (int t = 0; t < c->nterrains; t++) {
            fs_campaign_row *row = &rows[f * c->nterrains + t];
            memset(row, 0, sizeof *row);
            row->foot = f;
            row->terrain = t;
            const fs_trial_result *r = &results[(f * c->nterrains + t) * c->seeds];
            for (int s = 0; s < c->seeds; s++) {
                row->trials++;
                row->landed += r[s].outcome == FS_LANDED;
                row->fell += r[s].outcome == FS_FELL;
                row->failed_numerics += r[s].outcome == FS_FAILED_NUMERICS;
            }
            row->success_rate = (double)row->landed / row->trials;
            fs_wilson(row->landed, row->trials, &row->ci_low, &row->ci_high);
            for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
                int n = 0;
                for (int s = 0; v && s < c->seeds; s++)
                    if (r[s].outcome != FS_FAILED_NUMERICS)
                        v[n++] = fs_metric_value(&r[s], m);
                row->nmetric = n;
                row->median[m] = fs_median(v, n);
            }
        }
    free(v);
}

/* ---- result files ------------------------------------------------------------------------- */

typedef struct out_ctx {
    const fs_campaign *c;
    const fs_trial_result *results;
    const fs_campaign_row *rows;
} out_ctx;

/* A fill function of out_ctx for fs_write_file. */
typedef struct out_fill {
    int (*fill)(FILE *, const out_ctx *);
    const out_ctx *ctx;
} out_fill;

static int fill_adapter(FILE *f, const void *user)
{
    const out_fill *x = user;
    return x->fill(f, x->ctx);
}

/* Writes dir/name through fill, whole or not at all. */
static fs_status write_file(const char *dir, const char *name, int (*fill)(FILE *, const out_ctx *),
                            const out_ctx *ctx, fs_error *err)
{
    const out_fill x = {fill, ctx};
    return fs_write_in(dir, name, fill_adapter, &x, err);
}

/* A number for CSV: exact (%.17g), or empty when there is none. */
static void csv_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, ",%.17g", v);
    else
        fputs(",", f);
}

/* Free text for CSV: quoted, quotes doubled, line breaks as spaces. */
static void csv_text(FILE *f, const char *s)
{
    fputs(",\"", f);
    for (; *s; s++)
        if (*s == '"')
            fputs("\"\"", f);
        else
            fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
    fputc('"', f);
}

static void csv_row_key(FILE *f, const fs_campaign *c, int foot, int terrain)
{
    fprintf(f, "%s,%s", c->foot[foot].name, c->terrain[terrain].name);
    if (c->sweep[0])
        csv_number(f, c->terrain[terrain].sweep_value);
}

static int fill_trials(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    fprintf(f, "foot,terrain%s%s,seed,x_m,y_m,yaw_deg,pitch_deg,roll_deg,outcome", c->sweep[0] ? "," : "", c->sweep);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, ",%s", fs_campaign_metrics[m].name);
    fputs(",failure\n", f);
    for (int i = 0; i < fs_campaign_ntrials(c); i++) {
        const fs_trial_result *r = &x->results[i];
        int foot, terrain, seed;
        fs_campaign_trial_of(c, i, &foot, &terrain, &seed);
        csv_row_key(f, c, foot, terrain);
        fprintf(f, ",%d", seed);
        const double pose[5] = {r->draw.x_m, r->draw.y_m, r->draw.yaw_deg, r->draw.pitch_deg, r->draw.roll_deg};
        for (int k = 0; k < 5; k++)
            csv_number(f, pose[k]);
        fprintf(f, ",%s", fs_outcome_name(r->outcome));
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            csv_number(f, fs_metric_value(r, m));
        csv_text(f, r->outcome == FS_FAILED_NUMERICS ? r->failure : "");
        fputc('\n', f);
    }
    return 1;
}

static int fill_summary_csv(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    fprintf(f, "foot,terrain%s%s,trials,landed,fell,failed_numerics,success_rate,ci_low,ci_high", c->sweep[0] ? "," : "",
            c->sweep);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, ",median_%s", fs_campaign_metrics[m].name);
    fputc('\n', f);
    for (int i = 0; i < c->nfeet * c->nterrains; i++) {
        const fs_campaign_row *r = &x->rows[i];
        csv_row_key(f, c, r->foot, r->terrain);
        fprintf(f, ",%d,%d,%d,%d", r->trials, r->landed, r->fell, r->failed_numerics);
        csv_number(f, r->success_rate);
        csv_number(f, r->ci_low);
        csv_number(f, r->ci_high);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            csv_number(f, r->median[m]);
        fputc('\n', f);
    }
    return 1;
}

static const fs_campaign_row *row_of(const fs_campaign *c, const fs_campaign_row *rows, int foot, int terrain)
{
    return &rows[foot * c->nterrains + terrain];
}

static int expectation_met(const fs_expectation *e, const fs_campaign_row *r)
{
    return r->success_rate >= e->min_success && r->success_rate <= e->max_success;
}

static int fill_summary_md(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    char trial[FS_NAME_MAX];
    fs_path_stem(c->trial_path, trial, sizeof trial);
    fprintf(f, "# Campaign %s\n\nTrial scenario `%s`, seeds %d to %d (%d per foot and terrain)%s%s. Success: the "
               "trial landed; interval: 95 %% Wilson score. Medians over the trials that did not fail numerically.\n\n",
            c->name, trial, c->first_seed, c->first_seed + c->seeds - 1, c->seeds,
            c->sweep[0] ? "; terrain swept over " : "", c->sweep);
    fputs("| foot | terrain | trials | landed | fell | failed_numerics | success | 95 % CI |", f);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fprintf(f, " %s |", fs_campaign_metrics[m].name);
    fputs("\n|---|---|--:|--:|--:|--:|--:|---|", f);
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
        fputs("--:|", f);
    fputc('\n', f);
    for (int i = 0; i < c->nfeet * c->nterrains; i++) {
        const fs_campaign_row *r = &x->rows[i];
        fprintf(f, "| %s | %s | %d | %d | %d | %d | %.2f | [%.2f, %.2f] |", c->foot[r->foot].name,
                c->terrain[r->terrain].name, r->trials, r->landed, r->fell, r->failed_numerics, r->success_rate,
                r->ci_low, r->ci_high);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++)
            fprintf(f, isfinite(r->median[m]) ? " %.4g |" : " – |", r->median[m]);
        fputc('\n', f);
    }
    if (c->nexpect)
        fputs("\n## Expectations\n\n| expectation | foot | terrain | success | wanted | met |\n|---|---|---|--:|---|---|\n", f);
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        const fs_campaign_row *r = row_of(c, x->rows, e->foot, e->terrain);
        fprintf(f, "| %s | %s | %s | %.2f | [%.2f, %.2f] | %s |\n", e->name, c->foot[e->foot].name,
                c->terrain[e->terrain].name, r->success_rate, e->min_success, e->max_success,
                expectation_met(e, r) ? "yes" : "**no**");
    }
    return 1;
}

static cJSON *summary_json(const out_ctx *x)
{
    const fs_campaign *c = x->c;
    cJSON *root = cJSON_CreateObject();
    char trial[FS_NAME_MAX];
    fs_path_stem(c->trial_path, trial, sizeof trial);
    cJSON_AddStringToObject(root, "campaign", c->name);
    cJSON_AddStringToObject(root, "trial", trial);
    cJSON_AddNumberToObject(root, "seeds", c->seeds);
    cJSON_AddNumberToObject(root, "first_seed", c->first_seed);
    if (c->sweep[0])
        cJSON_AddStringToObject(root, "sweep", c->sweep);
    else
        cJSON_AddNullToObject(root, "sweep");
    cJSON *tol = cJSON_AddObjectToObject(root, "tolerances");
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        cJSON *t = cJSON_AddObjectToObject(tol, fs_campaign_metrics[m].name);
        cJSON_AddNumberToObject(t, "relative", c->tolerance[m][0]);
        cJSON_AddNumberToObject(t, "absolute", c->tolerance[m][1]);
    }
    cJSON *rows = cJSON_AddArrayToObject(root, "rows");
    for (int i = 0; i < c->nfeet * c->nterrains; i++) {
        const fs_campaign_row *r = &x->rows[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "foot", c->foot[r->foot].name);
        cJSON_AddStringToObject(o, "terrain", c->terrain[r->terrain].name);
        if (c->sweep[0])
            cJSON_AddNumberToObject(o, "sweep_value", c->terrain[r->terrain].sweep_value);
        cJSON_AddNumberToObject(o, "trials", r->trials);
        cJSON_AddNumberToObject(o, "landed", r->landed);
        cJSON_AddNumberToObject(o, "fell", r->fell);
        cJSON_AddNumberToObject(o, "failed_numerics", r->failed_numerics);
        cJSON_AddNumberToObject(o, "success_rate", r->success_rate);
        cJSON_AddNumberToObject(o, "ci_low", r->ci_low);
        cJSON_AddNumberToObject(o, "ci_high", r->ci_high);
        for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
            char key[FS_NAME_MAX + 8];
            snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
            cJSON_AddNumberToObject(o, key, r->median[m]); /* NAN is written as null */
        }
        cJSON_AddItemToArray(rows, o);
    }
    cJSON *ex = cJSON_AddArrayToObject(root, "expectations");
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "name", e->name);
        cJSON_AddStringToObject(o, "foot", c->foot[e->foot].name);
        cJSON_AddStringToObject(o, "terrain", c->terrain[e->terrain].name);
        cJSON_AddNumberToObject(o, "min_success", e->min_success);
        cJSON_AddNumberToObject(o, "max_success", e->max_success);
        cJSON_AddNumberToObject(o, "success_rate", row_of(c, x->rows, e->foot, e->terrain)->success_rate);
        cJSON_AddBoolToObject(o, "met", expectation_met(e, row_of(c, x->rows, e->foot, e->terrain)));
        cJSON_AddItemToArray(ex, o);
    }
    return root;
}

static int fill_summary_json(FILE *f, const out_ctx *x)
{
    cJSON *root = summary_json(x);
    char *text = root ? cJSON_Print(root) : NULL;
    if (text)
        fprintf(f, "%s\n", text);
    free(text);
    cJSON_Delete(root);
    return text != NULL;
}

fs_status fs_campaign_write(const fs_campaign *c, const fs_trial_result *results, const fs_campaign_row *rows,
                            const char *dir, fs_error *err)
{
    const out_ctx x = {c, results, rows};
    fs_status s = write_file(dir, "trials.csv", fill_trials, &x, err);
    if (s == FS_OK)
        s = write_file(dir, "summary.csv", fill_summary_csv, &x, err);
    if (s == FS_OK)
        s = write_file(dir, "summary.md", fill_summary_md, &x, err);
    return s;
}

fs_status fs_campaign_write_summary(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err)
{
    const out_ctx x = {c, NULL, rows};
    return write_file(dir, "summary.json", fill_summary_json, &x, err);
}

/* ---- the chart ---------------------------------------------------------------------------- */

/* Bars: a line per terrain with each foot's rate, low and high. Sweep: a block per foot of
 * (value, rate, low, high). */
static int fill_chart_data(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    if (!c->sweep[0]) {
        fputs("# terrain", f);
        for (int ft = 0; ft < c->nfeet; ft++)
            fprintf(f, " %s_rate %s_low %s_high", c->foot[ft].name, c->foot[ft].name, c->foot[ft].name);
        fputc('\n', f);
        for (int t = 0; t < c->nterrains; t++) {
            fprintf(f, "\"%s\"", c->terrain[t].name);
            for (int ft = 0; ft < c->nfeet; ft++) {
                const fs_campaign_row *r = row_of(c, x->rows, ft, t);
                fprintf(f, " %.17g %.17g %.17g", r->success_rate, r->ci_low, r->ci_high);
            }
            fputc('\n', f);
        }
        return 1;
    }
    for (int ft = 0; ft < c->nfeet; ft++) {
        fprintf(f, "%s# %s: %s rate low high\n", ft ? "\n\n" : "", c->foot[ft].name, c->sweep);
        for (int t = 0; t < c->nterrains; t++) {
            const fs_campaign_row *r = row_of(c, x->rows, ft, t);
            fprintf(f, "%.17g %.17g %.17g %.17g\n", c->terrain[t].sweep_value, r->success_rate, r->ci_low, r->ci_high);
        }
    }
    return 1;
}

static int fill_chart_script(FILE *f, const out_ctx *x)
{
    const fs_campaign *c = x->c;
    fprintf(f, "# The chart of campaign %s: 'gnuplot chart.gp' in this folder draws success.png.\n"
               "if (!exists(\"out\")) out = 'success.png'\n"
               "set terminal pngcairo size 960,540 noenhanced font 'sans,11'\n"
               "set output out\n"
               "set title 'Campaign %s: success rate with 95 %% Wilson interval (%d seeds each)'\n"
               "set ylabel 'success rate (landed / trials)'\n"
               "set yrange [0:1.05]\nset grid ytics\nset key outside right top\n",
            c->name, c->name, c->seeds);
    if (!c->sweep[0]) {
        fputs("set style data histogram\nset style histogram errorbars gap 2 lw 1\n"
              "set style fill solid 0.6 border -1\nset xlabel 'terrain'\nplot ",
              f);
        for (int ft = 0; ft < c->nfeet; ft++)
            fprintf(f, "%s'chart.dat' using %d:%d:%d%s title '%s'", ft ? ", \\\n     " : "", 2 + 3 * ft, 3 + 3 * ft,
                    4 + 3 * ft, ft ? "" : ":xtic(1)", c->foot[ft].name);
        fputc('\n', f);
        return 1;
    }
    fprintf(f, "set xlabel '%s'\nplot ", c->sweep);
    for (int ft = 0; ft < c->nfeet; ft++)
        fprintf(f, "%s'chart.dat' index %d using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc %d "
                   "notitle, \\\n     '' index %d using 1:2 with linespoints lw 2 pt 7 lc %d title '%s'",
                ft ? ", \\\n     " : "", ft, ft + 1, ft, ft + 1, c->foot[ft].name);
    fputc('\n', f);
    return 1;
}

fs_status fs_campaign_write_chart(const fs_campaign *c, const fs_campaign_row *rows, const char *dir, fs_error *err)
{
    const out_ctx x = {c, NULL, rows};
    fs_status s = write_file(dir, "chart.dat", fill_chart_data, &x, err);
    return s == FS_OK ? write_file(dir, "chart.gp", fill_chart_script, &x, err) : s;
}

/* ---- expectations ------------------------------------------------------------------------- */

int fs_campaign_check(const fs_campaign *c, const fs_campaign_row *rows, FILE *out)
{
    int failed = 0;
    for (int i = 0; i < c->nexpect; i++) {
        const fs_expectation *e = &c->expect[i];
        const fs_campaign_row *r = row_of(c, rows, e->foot, e->terrain);
        int ok = expectation_met(e, r);
        failed += !ok;
        fprintf(out, "  %-6s %s: %s on %s landed %d of %d (%.2f, 95 %% CI [%.2f, %.2f]); wanted %.2f to %.2f\n",
                ok ? "ok" : "FAILED", e->name, c->foot[e->foot].name, c->terrain[e->terrain].name, r->landed,
                r->trials, r->success_rate, r->ci_low, r->ci_high, e->min_success, e->max_success);
    }
    return failed;
}

/* ---- comparison --------------------------------------------------------------------------- */

static cJSON *read_summary(const char *path, fs_error *err)
{
    char *text;
    size_t len;
    /* a regular file of bounded size: a FIFO or /dev/zero is refused, not waited on or read forever */
    if (fs_read_regular(path, FS_SUMMARY_MAX_BYTES, "a summary.json written by footsim campaign", &text, &len, err) !=
        FS_OK)
        return NULL;
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    free(text);
    if (!root || !cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(root, "rows"))) {
        cJSON_Delete(root);
        fs_fail(err, FS_BAD_INPUT, "%s: not a campaign summary (JSON with \"rows\"); give a summary.json written by "
                                   "footsim campaign", path);
        return NULL;
    }
    return root;
}

static const char *text_of(const cJSON *row, const char *key)
{
    const char *s = cJSON_GetStringValue(cJSON_GetObjectItemCaseSensitive(row, key));
    return s ? s : "?";
}

/* A number of a row: NAN when it is null or missing. */
static double number_of(const cJSON *row, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(row, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

static const cJSON *find_row(const cJSON *rows, const char *foot, const char *terrain)
{
    const cJSON *r;
    cJSON_ArrayForEach(r, rows)
        if (!strcmp(text_of(r, "foot"), foot) && !strcmp(text_of(r, "terrain"), terrain))
            return r;
    return NULL;
}

/* The tolerance of metric m: the baseline's, else footsim's default. */
static void tolerance_of(const cJSON *baseline, int m, double tol[2])
{
    sscanf(fs_campaign_metrics[m].tolerance, "%lf, %lf", &tol[0], &tol[1]);
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(baseline, "tolerances"),
                                                      fs_campaign_metrics[m].name);
    if (cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(t, "relative")))
        tol[0] = number_of(t, "relative");
    if (cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(t, "absolute")))
        tol[1] = number_of(t, "absolute");
}

static int same_number(double a, double b) { return (isnan(a) && isnan(b)) || a == b; }

/* Prints one changed quantity; returns 1 when it is outside what is allowed. */
static int report_change(FILE *out, const cJSON *row, const char *what, double base, double now, double lo, double hi)
{
    int bad = !(now >= lo && now <= hi) && !(isnan(base) && isnan(now));
    fprintf(out, "| %s | %s | %s | %.6g | %.6g | [%.6g, %.6g] | %s |\n", text_of(row, "foot"), text_of(row, "terrain"),
            what, base, now, lo, hi, bad ? "**outside**" : "within");
    return bad;
}

/* Compares one row of each; returns how many quantities left their allowance; counts changes. */
static int compare_row(FILE *out, const cJSON *baseline, const cJSON *b, const cJSON *r, int *changed)
{
    int bad = 0;
    double rate = number_of(r, "success_rate"), base_rate = number_of(b, "success_rate");
    if (!same_number(rate, base_rate) || number_of(r, "trials") != number_of(b, "trials")) {
        (*changed)++;
        bad += report_change(out, r, "success_rate", base_rate, rate, number_of(b, "ci_low"), number_of(b, "ci_high"));
    }
    for (int m = 0; m < FS_CAMPAIGN_NMETRICS; m++) {
        char key[FS_NAME_MAX + 8];
        snprintf(key, sizeof key, "median_%s", fs_campaign_metrics[m].name);
        double base = number_of(b, key), now = number_of(r, key), tol[2];
        if (same_number(base, now))
            continue;
        (*changed)++;
        tolerance_of(baseline, m, tol);
        double allow = tol[0] * fabs(base) + tol[1];
        bad += report_change(out, r, key, base, now, base - allow, base + allow);
    }
    return bad;
}

fs_status fs_campaign_compare(const char *result_path, const char *baseline_path, FILE *out, fs_error *err)
{
    cJSON *result = read_summary(result_path, err);
    cJSON *baseline = result ? read_summary(baseline_path, err) : NULL;
    if (!baseline) {
        cJSON_Delete(result);
        return FS_BAD_INPUT;
    }
    const cJSON *rrows = cJSON_GetObjectItemCaseSensitive(result, "rows");
    const cJSON *brows = cJSON_GetObjectItemCaseSensitive(baseline, "rows");
    fprintf(out, "%s against the baseline %s\n\n| foot | terrain | quantity | baseline | result | allowed | verdict |\n"
                 "|---|---|---|--:|--:|---|---|\n", result_path, baseline_path);
    int bad = 0, changed = 0;
    const cJSON *b, *r;
    cJSON_ArrayForEach(b, brows) {
        r = find_row(rrows, text_of(b, "foot"), text_of(b, "terrain"));
        if (!r) {
            fprintf(out, "| %s | %s | (row) | present | **missing** | | **outside** |\n", text_of(b, "foot"),
                    text_of(b, "terrain"));
            bad++, changed++;
        } else {
            bad += compare_row(out, baseline, b, r, &changed);
        }
    }
    cJSON_ArrayForEach(r, rrows)
        if (!find_row(brows, text_of(r, "foot"), text_of(r, "terrain"))) {
            fprintf(out, "| %s | %s | (row) | **missing** | present | | **outside** |\n", text_of(r, "foot"),
                    text_of(r, "terrain"));
            bad++, changed++;
        }
    fprintf(out, "\n%d rows in the baseline; %d quantities changed, %d outside what the baseline allows: %s\n",
            cJSON_GetArraySize(brows), changed, bad, bad ? "CHANGED" : changed ? "within tolerance" : "identical");
    cJSON_Delete(result);
    cJSON_Delete(baseline);
    return bad ? FS_EXPECTATION_FAILED : FS_OK;
}
