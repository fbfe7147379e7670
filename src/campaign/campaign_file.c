/* campaign_file.c: a campaign file bound with fs_config into an fs_campaign: its feet, terrains,
 * robots, sweep, expectations and tolerances checked, and the trial scenario of every cell (foot,
 * terrain, robot) loaded once; which trial an index is. */
#include "campaign_internal.h"

#include "footsim/base/fs_path.h"
#include "footsim/model/fs_scenario.h"

#include <errno.h>
#include <limits.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the campaign file ---------------------------------------------------------------------- */

/* the static keys (add_static_keys: [campaign]'s, band, two sweeps, [tolerance]'s), then per section:
   a foot's file, a terrain's file, a robot's file, step_s, tolerance_m and error_estimate, an
   expectation's five */
enum { MAX_KEYS = 8 + FS_CAMPAIGN_NMETRICS + 2 * FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_FEET +
                  4 * FS_CAMPAIGN_MAX_ROBOTS + 5 * FS_CAMPAIGN_MAX_EXPECT };
enum { NSECTIONS = FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_ROBOTS + FS_CAMPAIGN_MAX_EXPECT };

/* The schema of one file, built from the sections it has, and the text its keys point to. */
typedef struct binder {
    fs_key keys[MAX_KEYS];
    int nkeys;
    char sections[NSECTIONS][FS_NAME_MAX];
    int nsections;
    char foot_choices[FS_CAMPAIGN_MAX_FEET * FS_NAME_MAX];
    char terrain_choices[FS_CAMPAIGN_MAX_TERRAINS * FS_NAME_MAX];
    char robot_choices[FS_CAMPAIGN_MAX_ROBOTS * FS_NAME_MAX];
    char sweep_choices[16384];
    char sweep_values[2][FS_VALUE_MAX];  /* sweep_values and sweep2_values as given, or "" */
    char sweep_where[2][FS_PATH_MAX + 80];
    char values[2][FS_CAMPAIGN_MAX_TERRAINS][FS_NAME_MAX]; /* the sweep's values, parsed */
    fs_campaign_item base[FS_CAMPAIGN_MAX_TERRAINS];         /* the terrains a sweep expands */
    /* the [band.NAME] sections, taken out of the file before binding (their values are lists of
       overrides, which no key type reads): each end's text and where it was given */
    int nbands;
    char band_name[FS_CAMPAIGN_MAX_BANDS][FS_NAME_MAX];
    char band_text[FS_CAMPAIGN_MAX_BANDS][FS_BAND_ENDS][FS_VALUE_MAX];
    char band_where[FS_CAMPAIGN_MAX_BANDS][FS_BAND_ENDS][FS_PATH_MAX + 80];
    char band_section_where[FS_CAMPAIGN_MAX_BANDS][FS_PATH_MAX + 80];
    char band_choices[(FS_CAMPAIGN_MAX_BANDS + 1) * FS_NAME_MAX];
} binder;

#define C(member) offsetof(fs_campaign, member)

static const fs_key campaign_keys[] = {
    {"campaign", "trial", FS_KEY_PATH, C(trial_path), 0, 0, 0, 0, NULL, "", "",
     "the trial scenario (with [robot] and [landing]), relative to the campaign file"},
    {"campaign", "seeds", FS_KEY_INTEGER, C(seeds), 1, FS_CAMPAIGN_MAX_SEEDS, 0, 0, NULL, "", "50",
     "trials per foot, terrain and robot"},
    {"campaign", "first_seed", FS_KEY_INTEGER, C(first_seed), 0, 1e9, 0, 0, NULL, "", "1",
     "seeds are first_seed, first_seed + 1, ..."},
};

/* A robot's error_estimate: its choice index, 0 for the trial's own, else the scenario's
   fs_error_estimate + 1, and the word run.error_estimate takes. */
#define ESTIMATE_CHOICES "trial|doubling|embedded"
static const char *const estimate_choice[] = {"trial", "doubling", "embedded"};
_Static_assert(FS_ESTIMATE_DOUBLING == 0 && FS_ESTIMATE_EMBEDDED == 1, "estimate_choice[e + 1] names fs_error_estimate e");

/* A band's ends, in the order their trials and columns take. */
static const char *const band_end_names[FS_BAND_ENDS] = {"low", "high"};
enum { NCAMPAIGN_KEYS = sizeof campaign_keys / sizeof campaign_keys[0] };

static int is_campaign_section(const char *section)
{
    return !strcmp(section, "campaign") || !strcmp(section, "tolerance") || !strncmp(section, "foot.", 5) ||
           !strncmp(section, "terrain.", 8) || !strncmp(section, "robot.", 6) || !strncmp(section, "expect.", 7) ||
           !strncmp(section, "band.", 5);
}

static fs_key *add_key(binder *b, const char *section, const char *name, fs_key_type type, size_t offset)
{
    if (b->nkeys == MAX_KEYS) { /* MAX_KEYS counts every key a file can have: a key added without it */
        fprintf(stderr, "footsim: internal error: a campaign file's keys outgrow MAX_KEYS (%d)\n", MAX_KEYS);
        abort();
    }
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

static const char *const sweep_values_key[2] = {"sweep_values", "sweep2_values"};
static const char *const sweep_key[2] = {"sweep", "sweep2"};

/* Takes [campaign] sweep_values and sweep2_values out of cfg (fs_config has no list of arbitrary
 * length). */
static void take_sweep_values(fs_config *cfg, binder *b)
{
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        for (int w = 0; w < 2; w++) {
            if (strcmp(e->section, "campaign") || strcmp(e->name, sweep_values_key[w]))
                continue;
            snprintf(b->sweep_values[w], sizeof b->sweep_values[w], "%s", e->value);
            fs_config_where(cfg, "campaign", sweep_values_key[w], b->sweep_where[w], sizeof b->sweep_where[w]);
            memmove(e, e + 1, (size_t)(cfg->count - i - 1) * sizeof *e);
            cfg->count--;
            i--;
            break;
        }
    }
}

/* Splits the values of sweep w; each must be a finite number, given once (equal as numbers: 1 and
 * 1e0 would make two points of one name). Returns the count, or -1 (err set). */
static int parse_sweep(const binder *b, int w, char values[][FS_NAME_MAX], fs_error *err)
{
    char buf[FS_VALUE_MAX], *tok[FS_CAMPAIGN_MAX_TERRAINS];
    double v[FS_CAMPAIGN_MAX_TERRAINS];
    snprintf(buf, sizeof buf, "%s", b->sweep_values[w]);
    int empty = 0, n = fs_list_split(buf, tok, FS_CAMPAIGN_MAX_TERRAINS, &empty);
    if (n == -1) {
        fs_fail(err, FS_BAD_INPUT, "%s: %s: value %d is empty (two commas in a row, or a comma first or last); "
                "allowed: comma-separated numbers, e.g. 0, 0.001, 0.002", b->sweep_where[w], sweep_values_key[w], empty);
        return -1;
    }
    if (n == -2) {
        fs_fail(err, FS_BAD_INPUT, "%s: %s: more than %d values", b->sweep_where[w], sweep_values_key[w],
                FS_CAMPAIGN_MAX_TERRAINS);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        fs_number num = fs_parse_number(tok[i], &v[i]);
        if (num != FS_NUMBER_OK || strlen(tok[i]) >= FS_NAME_MAX / 4) {
            fs_fail(err, FS_BAD_INPUT, "%s: %s: '%s' %s; allowed: comma-separated numbers", b->sweep_where[w],
                    sweep_values_key[w], tok[i], num != FS_NUMBER_OK ? fs_number_problem(num) : "is too long");
            return -1;
        }
        for (int j = 0; j < i; j++)
            if (v[j] == v[i]) {
                fs_fail(err, FS_BAD_INPUT, "%s: %s: '%s' is '%s' again (both %.15g): each point would be there "
                        "twice under one name; give each value once", b->sweep_where[w], sweep_values_key[w], tok[i],
                        tok[j], v[i]);
                return -1;
            }
        snprintf(values[i], FS_NAME_MAX, "%s", tok[i]);
    }
    if (n == 0)
        fs_fail(err, FS_BAD_INPUT, "%s: %s is empty; give the values of the swept key, e.g. 0, 0.001, 0.002",
                b->sweep_where[w], sweep_values_key[w]);
    return n ? n : -1;
}

const fs_key *fs_campaign_sweepable(int n)
{
    const fs_key *schema[4] = {fs_terrain_keys, fs_design_keys, fs_robot_keys, fs_scenario_keys};
    const int nkeys[4] = {fs_terrain_nkeys, fs_design_nkeys, fs_robot_nkeys, fs_scenario_nkeys};
    for (int s = 0, k = 0; s < 4; s++)
        for (int i = 0; i < nkeys[s]; i++)
            if ((schema[s][i].type == FS_KEY_NUMBER || schema[s][i].type == FS_KEY_INTEGER) && ++k == n)
                return &schema[s][i];
    return NULL;
}

/* ---- contact bands ------------------------------------------------------------------------- */

/* Takes every [band.NAME] section out of cfg into b: its ends' text and where each was given; a key
 * other than low and high is refused, with its line. */
static fs_status take_bands(fs_config *cfg, binder *b, fs_error *err)
{
    snprintf(b->band_choices, sizeof b->band_choices, "none");
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        if (strncmp(e->section, "band.", 5))
            continue;
        char where[FS_PATH_MAX + 80];
        fs_config_where(cfg, e->section, e->name, where, sizeof where);
        fs_status s = check_name(cfg, e, e->section + 5, err);
        if (s != FS_OK)
            return s;
        int band = 0, end = 0;
        while (band < b->nbands && strcmp(b->band_name[band], e->section + 5))
            band++;
        if (band == b->nbands) {
            if (b->nbands == FS_CAMPAIGN_MAX_BANDS)
                return fs_fail(err, FS_BAD_INPUT, "%s: [%s]: at most %d bands in a campaign file", where, e->section,
                               FS_CAMPAIGN_MAX_BANDS);
            snprintf(b->band_name[b->nbands], FS_NAME_MAX, "%s", e->section + 5);
            snprintf(b->band_section_where[b->nbands], sizeof b->band_section_where[0], "%s", where);
            append_choice(b->band_choices, sizeof b->band_choices, e->section + 5);
            b->nbands++;
        }
        while (end < FS_BAND_ENDS && strcmp(band_end_names[end], e->name))
            end++;
        if (end == FS_BAND_ENDS)
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] has no key '%s'; allowed: low and high, each the band end's "
                           "overrides as section.key=value, comma-separated (empty: the trials' own values)", where,
                           e->section, e->name);
        snprintf(b->band_text[band][end], FS_VALUE_MAX, "%s", e->value);
        snprintf(b->band_where[band][end], sizeof b->band_where[0][0], "%s", where);
        memmove(e, e + 1, (size_t)(cfg->count - i - 1) * sizeof *e);
        cfg->count--;
        i--;
    }
    return FS_OK;
}

/* The number key "section.key" of the trials (a terrain's, design's, robot's or scenario's), or NULL. */
static const fs_key *trial_number_key(const char *name)
{
    for (int n = 1; fs_campaign_sweepable(n); n++) {
        const fs_key *k = fs_campaign_sweepable(n);
        size_t len = strlen(k->section);
        if (!strncmp(name, k->section, len) && name[len] == '.' && !strcmp(name + len + 1, k->name))
            return k;
    }
    return NULL;
}

/* Whether the override `set` ("section.key=value", spaces allowed) sets key. */
static int sets_key(const char *set, const char *key)
{
    size_t len = strlen(key);
    const char *rest = set + strspn(set, " \t");
    return !strncmp(rest, key, len) && (rest[len] == '=' || rest[len] == ' ' || rest[len] == '\t');
}

/* One end of band `band` read from its text: each override a number key of the trials given once,
 * its value read by the key's own rules (range, a whole number for an integer). */
static fs_status parse_band_end(const binder *b, int band, int e, fs_band_end *end, fs_error *err)
{
    const char *where = b->band_where[band][e][0] ? b->band_where[band][e] : b->band_section_where[band];
    char buf[FS_VALUE_MAX], *tok[FS_BAND_MAX_SETS];
    memset(end, 0, sizeof *end);
    snprintf(end->name, sizeof end->name, "%s", band_end_names[e]);
    snprintf(end->text, sizeof end->text, "%s", b->band_text[band][e]);
    snprintf(buf, sizeof buf, "%s", b->band_text[band][e]);
    int empty = 0, n = fs_list_split(buf, tok, FS_BAND_MAX_SETS, &empty);
    if (n < 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: [band.%s] %s: %s; give section.key=value overrides, comma-separated, "
                       "e.g. sole.stiffness_N_per_m=1.001e5, sole.damping_Ns_per_m=208", where, b->band_name[band],
                       end->name, n == -1 ? "an override is empty (two commas in a row, or a comma first or last)"
                                          : "more than 16 overrides");
    for (int i = 0; i < n; i++) {
        char *eq = strchr(tok[i], '=');
        char *key = tok[i], *value = eq ? eq + 1 : NULL;
        if (eq) {
            *eq = 0;
            while (eq > key && (eq[-1] == ' ' || eq[-1] == '\t'))
                *--eq = 0;
            value += strspn(value, " \t");
        }
        const fs_key *k = eq ? trial_number_key(key) : NULL;
        if (!k)
            return fs_fail(err, FS_BAD_INPUT, "%s: [band.%s] %s: '%s' %s; give section.key=value with a number key of "
                           "a terrain, design, robot or scenario file (docs/keys.md), e.g. sole.stiffness_N_per_m=1.001e5",
                           where, b->band_name[band], end->name, key,
                           eq ? "is not a number key of the trials" : "has no '='");
        if (strlen(key) >= sizeof end->key[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [band.%s] %s: '%s' is too long", where, b->band_name[band], end->name,
                           key);
        for (int j = 0; j < end->nsets; j++)
            if (!strcmp(end->key[j], key))
                return fs_fail(err, FS_BAD_INPUT, "%s: [band.%s] %s sets %s twice; give each key once", where,
                               b->band_name[band], end->name, key);
        char what[FS_PATH_MAX + 200];
        snprintf(what, sizeof what, "%s: [band.%s] %s: %s", where, b->band_name[band], end->name, key);
        fs_status s = fs_config_number(k, value, what, &end->value[end->nsets], err);
        if (s != FS_OK)
            return s;
        snprintf(end->key[end->nsets++], sizeof end->key[0], "%s", key);
    }
    return FS_OK;
}

/* Every band of the file read (so a wrong one is refused whichever is chosen), and the chosen one
 * kept in c: its ends' keys must be neither swept, nor given by --set, nor a robot's own step_s or
 * tolerance_m, which it would overwrite. */
static fs_status bind_bands(const fs_config *cfg, const binder *b, fs_campaign *c, fs_error *err)
{
    c->nends = 1;
    for (int band = 0; band < b->nbands; band++)
        for (int e = 0; e < FS_BAND_ENDS; e++) {
            fs_band_end end;
            fs_status s = parse_band_end(b, band, e, &end, err);
            if (s != FS_OK)
                return s;
            if (band + 1 != c->band_choice)
                continue;
            char where[FS_PATH_MAX + 80];
            fs_config_where(cfg, "campaign", "band", where, sizeof where);
            for (int i = 0; i < end.nsets; i++) {
                for (int w = 0; w < c->nsweep; w++)
                    if (!strcmp(end.key[i], c->sweep[w]))
                        return fs_fail(err, FS_BAD_INPUT, "%s: band %s's %s end sets %s, the key the campaign sweeps; "
                                       "sweep it, or give it in the band, not both", where, b->band_name[band],
                                       end.name, end.key[i]);
                for (int j = 0; j < c->nset; j++)
                    if (sets_key(c->set[j], end.key[i]))
                        return fs_fail(err, FS_BAD_INPUT, "--set %s: %s is set by band %s's %s end (%s), which would "
                                       "overwrite it; change the band ([band.%s] %s), or choose none with --set "
                                       "campaign.band=none", c->set[j], end.key[i], b->band_name[band], end.name,
                                       where, b->band_name[band], end.name);
                for (int r = 0; r < c->nrobots; r++) { /* a robot's own step or tolerance: the band would win */
                    const char *own = !strcmp(end.key[i], "run.step_s") && c->robot[r].step_s > 0 ? "step_s"
                                      : !strcmp(end.key[i], "run.tolerance_m") && c->robot[r].tolerance_m > 0
                                          ? "tolerance_m" : NULL;
                    char sec[FS_NAME_MAX + 8], rwhere[FS_PATH_MAX + 80];
                    snprintf(sec, sizeof sec, "robot.%s", c->robot[r].name);
                    if (own)
                        return fs_fail(err, FS_BAD_INPUT, "%s: band %s's %s end sets %s, which robot %s gives its own "
                                       "(%s); give it in the band or in the robot's section, not both",
                                       fs_config_where(cfg, sec, own, rwhere, sizeof rwhere), b->band_name[band],
                                       end.name, end.key[i], c->robot[r].name, where);
                }
            }
            c->end[e] = end;
            c->nends = FS_BAND_ENDS;
            snprintf(c->band, sizeof c->band, "%s", b->band_name[band]);
        }
    return FS_OK;
}

/* The [campaign] and [tolerance] keys. */
static void add_static_keys(binder *b)
{
    for (int i = 0; i < NCAMPAIGN_KEYS; i++)
        b->keys[b->nkeys++] = campaign_keys[i];
    /* the keys a sweep may vary: every number of a terrain, design, robot or scenario file */
    snprintf(b->sweep_choices, sizeof b->sweep_choices, "none");
    for (int n = 1; fs_campaign_sweepable(n); n++) {
        char word[2 * FS_NAME_MAX + 2];
        snprintf(word, sizeof word, "%s.%s", fs_campaign_sweepable(n)->section, fs_campaign_sweepable(n)->name);
        append_choice(b->sweep_choices, sizeof b->sweep_choices, word);
    }
    fs_key *k = add_key(b, "campaign", "band", FS_KEY_CHOICE, C(band_choice));
    k->choices = b->band_choices;
    k->fallback = "none";
    k->help = "a [band.NAME]: every trial runs at its low and its high end on the same seed; a cell lands only as "
              "often as its worse end";
    for (int w = 0; w < 2; w++) {
        k = add_key(b, "campaign", sweep_key[w], FS_KEY_CHOICE, C(sweep_choice[w]));
        k->choices = b->sweep_choices;
        k->fallback = "none";
        k->help = w ? "a second key to sweep over sweep2_values: every pair of values is a point"
                    : "a terrain, design, robot or scenario key to sweep over sweep_values: each terrain becomes a "
                      "terrain per value";
    }
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

/* The groups of named sections, in the order their names are kept in binder.sections. */
enum { GROUP_FOOT, GROUP_TERRAIN, GROUP_ROBOT, GROUP_EXPECT, NGROUPS };
static const int group_max[NGROUPS] = {FS_CAMPAIGN_MAX_FEET, FS_CAMPAIGN_MAX_TERRAINS, FS_CAMPAIGN_MAX_ROBOTS,
                                       FS_CAMPAIGN_MAX_EXPECT};

/* Where group g's section names start in binder.sections. */
static int group_first(int g)
{
    int first = 0;
    for (int i = 0; i < g; i++)
        first += group_max[i];
    return first;
}

/* Collects the [foot.NAME], [terrain.NAME], [robot.NAME] and [expect.NAME] sections of cfg, in file order. */
static fs_status collect_sections(const fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    int *count[NGROUPS] = {&c->nfeet, &c->nterrains, &c->nrobots, &c->nexpect};
    for (int i = 0; i < cfg->count; i++) {
        const fs_entry *e = &cfg->entries[i];
        const char *dot = strchr(e->section, '.');
        if (!dot || !is_campaign_section(e->section))
            continue;
        fs_status s = check_name(cfg, e, dot + 1, err);
        if (s != FS_OK)
            return s;
        int g = e->section[0] == 'f' ? GROUP_FOOT : e->section[0] == 't' ? GROUP_TERRAIN
                : e->section[0] == 'r' ? GROUP_ROBOT : GROUP_EXPECT;
        if (!note_section(b->sections + group_first(g), count[g], group_max[g], e->section))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s]: too many sections of this group (at most %d feet, %d terrains, "
                           "%d robots, %d expectations)", cfg->path, e->section, group_max[0], group_max[1],
                           group_max[2], group_max[3]);
    }
    return FS_OK;
}

/* Adds the keys of the [foot.NAME], [terrain.NAME], [robot.NAME] and [expect.NAME] sections named in
 * b->sections, c's counts of each. */
static void add_section_keys(binder *b, fs_campaign *c)
{
    for (int i = 0; i < c->nfeet; i++) {
        const char *sec = b->sections[group_first(GROUP_FOOT) + i];
        snprintf(c->foot[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        append_choice(b->foot_choices, sizeof b->foot_choices, c->foot[i].name);
        add_key(b, sec, "file", FS_KEY_PATH, C(foot[i].path))->help = "the foot's design file";
    }
    for (int i = 0; i < c->nterrains; i++) {
        const char *sec = b->sections[group_first(GROUP_TERRAIN) + i];
        snprintf(c->terrain[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        add_key(b, sec, "file", FS_KEY_PATH, C(terrain[i].path))->help = "the terrain file";
    }
    for (int i = 0; i < c->nrobots; i++) {
        const char *sec = b->sections[group_first(GROUP_ROBOT) + i];
        snprintf(c->robot[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        append_choice(b->robot_choices, sizeof b->robot_choices, c->robot[i].name);
        add_key(b, sec, "file", FS_KEY_PATH, C(robot[i].path))->help = "the robot file";
        fs_key *k = add_key(b, sec, "step_s", FS_KEY_NUMBER, C(robot[i].step_s));
        k->max = FS_STEP_MAX_S; /* run.step_s's range (check_relations), or 0 */
        k->unit = "s";
        k->fallback = "0";
        k->help = "the step of this robot's trials (0: the trial's run.step_s); a --set run.step_s overrides it, "
                  "a band end may not set it";
        k = add_key(b, sec, "tolerance_m", FS_KEY_NUMBER, C(robot[i].tolerance_m));
        int element;
        k->max = fs_scenario_key("run.tolerance_m", 0, &element)->max; /* run.tolerance_m's range */
        k->unit = "m";
        k->fallback = "0";
        k->help = "this robot's trials take the error-controlled step to this tolerance (0: the trial's "
                  "run.tolerance_m); a --set run.tolerance_m overrides it, a band end may not set it";
        k = add_key(b, sec, "error_estimate", FS_KEY_CHOICE, C(robot[i].error_estimate));
        k->choices = ESTIMATE_CHOICES;
        k->fallback = "trial";
        k->help = "with tolerance_m: the step's error estimate (trial: the trial's run.error_estimate)";
    }
    for (int i = 0; i < c->nexpect; i++) {
        const char *sec = b->sections[group_first(GROUP_EXPECT) + i];
        snprintf(c->expect[i].name, FS_NAME_MAX, "%s", strchr(sec, '.') + 1);
        fs_key *k = add_key(b, sec, "foot", FS_KEY_CHOICE, C(expect[i].foot));
        k->choices = b->foot_choices;
        k->help = "the foot whose success rate is judged";
        k = add_key(b, sec, "terrain", FS_KEY_CHOICE, C(expect[i].terrain));
        k->choices = b->terrain_choices;
        k->help = "... on this terrain";
        if (c->nrobots) { /* one robot: it is the default; several: check_expect_given wants it named */
            k = add_key(b, sec, "robot", FS_KEY_CHOICE, C(expect[i].robot));
            k->choices = b->robot_choices;
            k->fallback = c->robot[0].name;
            k->help = "... under this robot (needed when the file has several)";
        }
        k = add_key(b, sec, "min_success", FS_KEY_NUMBER, C(expect[i].min_success));
        k->max = 1;
        k->fallback = "0";
        k->help = "the least success rate (landed / trials) the expectation allows";
        k = add_key(b, sec, "max_success", FS_KEY_NUMBER, C(expect[i].max_success));
        k->max = 1;
        k->fallback = "1";
        k->help = "the most success rate (landed / trials) the expectation allows";
    }
}

/* Adds the keys of every [foot.NAME], [terrain.NAME], [robot.NAME] and [expect.NAME] section of cfg. */
static fs_status add_dynamic_keys(fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    fs_status s = collect_sections(cfg, b, c, err);
    if (s == FS_OK)
        add_section_keys(b, c);
    return s;
}

void fs_campaign_print_keys(void *out_file)
{
    binder *b = calloc(1, sizeof *b);
    fs_campaign *c = calloc(1, sizeof *c);
    if (!b || !c) {
        free(b);
        free(c);
        return;
    }
    static const char *const named[NGROUPS] = {"foot.NAME", "terrain.NAME", "robot.NAME", "expect.NAME"};
    for (int g = 0; g < NGROUPS; g++)
        snprintf(b->sections[group_first(g)], FS_NAME_MAX, "%s", named[g]);
    c->nfeet = c->nterrains = c->nrobots = c->nexpect = 1;
    add_static_keys(b);
    add_section_keys(b, c);
    for (int i = 0; i < b->nkeys; i++) { /* the choices a file's own names make, said as such */
        fs_key *k = &b->keys[i];
        if (k->choices == b->sweep_choices)
            k->choices = "none, or a number key of a design, terrain, robot or scenario file (section.key)";
        else if (k->choices == b->band_choices)
            k->choices = "none, or a [band.NAME] of the file";
        else if (k->choices == b->foot_choices || k->choices == b->terrain_choices || k->choices == b->robot_choices)
            k->choices = !strcmp(k->name, "foot") ? "a [foot.NAME] of the file"
                         : !strcmp(k->name, "terrain") ? "a [terrain.NAME] of the file" : "a [robot.NAME] of the file";
        if (!strcmp(k->name, "robot") && !strncmp(k->section, "expect.", 7))
            k->fallback = "the one robot";
    }
    fs_config_print_keys(b->keys, b->nkeys, "Campaign files (scenarios/*.ini with [campaign])", out_file);
    free(b);
    free(c);
}

/* Parses the values of each swept key into b->values (one empty "value" for a key not swept);
 * returns FS_OK or FS_BAD_INPUT. */
static fs_status sweep_values(binder *b, int nsweep, int n[2], fs_error *err)
{
    for (int w = 0; w < 2; w++) {
        n[w] = 1;
        b->values[w][0][0] = 0;
        if (w < nsweep && (n[w] = parse_sweep(b, w, b->values[w], err)) < 0)
            return FS_BAD_INPUT;
    }
    return FS_OK;
}

/* A point's name: "NAME@v1" or "NAME@v1,v2". */
static void point_name(char *out, const char *base, const char *v1, const char *v2)
{
    snprintf(out, FS_NAME_MAX, "%.24s@%.15s%s%.15s", base, v1, v2[0] ? "," : "", v2);
}

/* How many keys the file sweeps: sweep2 only beside sweep. */
static int nsweep_of(const binder *b) { return b->sweep_values[1][0] ? 2 : b->sweep_values[0][0] ? 1 : 0; }

/* The terrain names an expectation may give: each terrain, or for a sweep each point's. */
static fs_status terrain_choices(binder *b, const fs_campaign *c, fs_error *err)
{
    int nsweep = nsweep_of(b);
    if (!nsweep) {
        for (int i = 0; i < c->nterrains; i++)
            append_choice(b->terrain_choices, sizeof b->terrain_choices, c->terrain[i].name);
        return FS_OK;
    }
    int n[2];
    if (sweep_values(b, nsweep, n, err) != FS_OK)
        return FS_BAD_INPUT;
    for (int t = 0; t < (c->nterrains ? c->nterrains : 1); t++)
        for (int i = 0; i < n[0]; i++)
            for (int j = 0; j < n[1]; j++) {
                char label[FS_NAME_MAX];
                point_name(label, c->nterrains ? c->terrain[t].name : "terrain", b->values[0][i], b->values[1][j]);
                append_choice(b->terrain_choices, sizeof b->terrain_choices, label);
            }
    return FS_OK;
}

/* A sweep: every terrain becomes a point per value (per pair of values, with two keys), each with
 * the keys' values, read by the keys' own rules (a whole number for an integer key, the range);
 * the relations they enter are checked when each point's trial scenario is compiled. */
static fs_status expand_sweep(const fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    char where[FS_PATH_MAX + 80];
    for (int w = 0; w < 2; w++) {
        int named = c->sweep_choice[w] > 0, valued = b->sweep_values[w][0] != 0;
        if (valued && !named)
            return fs_fail(err, FS_BAD_INPUT, "%s: %s without %s; name the key to sweep, e.g. %s = %s",
                           b->sweep_where[w], sweep_values_key[w], sweep_key[w], sweep_key[w],
                           w ? "robot.com_height_m" : "rough.rms_m");
        if (named && !valued)
            return fs_fail(err, FS_BAD_INPUT, "%s: %s needs %s (comma-separated values of the key)",
                           fs_config_where(cfg, "campaign", sweep_key[w], where, sizeof where), sweep_key[w],
                           sweep_values_key[w]);
    }
    if (c->sweep_choice[1] && !c->sweep_choice[0])
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep2 without sweep; name the first key with sweep = ...",
                       fs_config_where(cfg, "campaign", "sweep2", where, sizeof where));
    c->nsweep = nsweep_of(b);
    if (!c->nsweep)
        return FS_OK;
    for (int w = 0; w < c->nsweep; w++) {
        const fs_key *k = fs_campaign_sweepable(c->sweep_choice[w]);
        snprintf(c->sweep[w], sizeof c->sweep[w], "%s.%s", k->section, k->name);
    }
    if (c->nsweep == 2 && !strcmp(c->sweep[0], c->sweep[1]))
        return fs_fail(err, FS_BAD_INPUT, "%s: sweep2 = %s is sweep's key too; sweep two different keys",
                       fs_config_where(cfg, "campaign", "sweep2", where, sizeof where), c->sweep[1]);
    if (sweep_values(b, c->nsweep, c->nvalues, err) != FS_OK)
        return FS_BAD_INPUT;
    for (int i = 0; i < c->nset; i++) /* a swept key's values are the sweep's: one --set would be overwritten */
        for (int w = 0; w < c->nsweep; w++) {
            size_t len = strlen(c->sweep[w]);
            const char *rest = c->set[i] + strspn(c->set[i], " \t");
            if (!strncmp(rest, c->sweep[w], len) && (rest[len] == '=' || rest[len] == ' ' || rest[len] == '\t'))
                return fs_fail(err, FS_BAD_INPUT, "--set %s: %s is the key the campaign sweeps (%s); give its values "
                               "with --set campaign.%s=..., not one value", c->set[i], c->sweep[w],
                               b->sweep_where[w], sweep_values_key[w]);
        }
    long points = (long)c->nterrains * c->nvalues[0] * c->nvalues[1];
    if (points > FS_CAMPAIGN_MAX_TERRAINS)
        return fs_fail(err, FS_BAD_INPUT, "%s: %d terrains x %d x %d values = %ld points; a campaign may have at most "
                       "%d: fewer values or terrains", fs_config_where(cfg, "campaign", "sweep", where, sizeof where),
                       c->nterrains, c->nvalues[0], c->nvalues[1], points, FS_CAMPAIGN_MAX_TERRAINS);
    fs_campaign_item *base = b->base;
    fs_status s = FS_OK;
    memcpy(base, c->terrain, (size_t)c->nterrains * sizeof base[0]);
    c->nbase = c->nterrains;
    int n = 0;
    for (int t = 0; t < c->nbase; t++)
        for (int i = 0; i < c->nvalues[0]; i++)
            for (int j = 0; j < c->nvalues[1]; j++) {
                fs_campaign_item *p = &c->terrain[n++];
                *p = base[t];
                point_name(p->name, base[t].name, b->values[0][i], b->values[1][j]);
                p->base = t;
                p->point[0] = i, p->point[1] = j;
                for (int w = 0; w < c->nsweep && s == FS_OK; w++)
                    s = fs_config_number(fs_campaign_sweepable(c->sweep_choice[w]), b->values[w][w ? j : i],
                                         b->sweep_where[w], &p->sweep_value[w], err);
            }
    c->nterrains = n;
    return s;
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
    long ntrials = (long)c->nfeet * c->nterrains * (c->nrobots ? c->nrobots : 1) * c->seeds * c->nends;
    if (ntrials > FS_CAMPAIGN_MAX_TRIALS)
        return fs_fail(err, FS_BAD_INPUT, "%s: %d feet x %d terrains x %d robots x %d seeds%s = %ld trials; a campaign "
                       "may run at most %d: fewer seeds, or split it",
                       fs_config_where(cfg, "campaign", "seeds", where, sizeof where), c->nfeet, c->nterrains,
                       c->nrobots ? c->nrobots : 1, c->seeds, c->nends > 1 ? " x 2 band ends" : "", ntrials,
                       FS_CAMPAIGN_MAX_TRIALS);
    for (int i = 0; i < c->nfeet; i++)
        if (!c->foot[i].path[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [foot.%s] has no file; give file = the design", cfg->path,
                           c->foot[i].name);
    for (int i = 0; i < c->nterrains; i++)
        if (!c->terrain[i].path[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [terrain.%s] has no file; give file = the terrain", cfg->path,
                           c->terrain[i].name);
    for (int i = 0; i < c->nrobots; i++) {
        char sec[FS_NAME_MAX + 8];
        snprintf(sec, sizeof sec, "robot.%s", c->robot[i].name);
        if (!c->robot[i].path[0])
            return fs_fail(err, FS_BAD_INPUT, "%s: [robot.%s] has no file; give file = the robot, e.g. "
                           "robots/drop_weight.ini", cfg->path, c->robot[i].name);
        if (c->robot[i].step_s > 0 && c->robot[i].step_s < FS_STEP_MIN_S)
            return fs_fail(err, FS_BAD_INPUT, "%s: step_s = %g is below run.step_s's least, %g s; give 0 for the "
                           "trial's own step, or a step of at least %g s",
                           fs_config_where(cfg, sec, "step_s", where, sizeof where), c->robot[i].step_s,
                           FS_STEP_MIN_S, FS_STEP_MIN_S);
        if (c->robot[i].error_estimate && !(c->robot[i].tolerance_m > 0))
            return fs_fail(err, FS_BAD_INPUT, "%s: error_estimate is the error-controlled step's and this robot has "
                           "no tolerance_m; give tolerance_m too (e.g. 1e-6), or leave error_estimate out",
                           fs_config_where(cfg, sec, "error_estimate", where, sizeof where));
    }
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

/* The expectations must name their foot and terrain (and robot, when there are several): the
 * choice's default would pick the first. */
static fs_status check_expect_given(const fs_config *cfg, const fs_campaign *c, fs_error *err)
{
    for (int i = 0; i < c->nexpect; i++) {
        char sec[FS_NAME_MAX + 8];
        snprintf(sec, sizeof sec, "expect.%s", c->expect[i].name);
        int foot = 0, terrain = 0, robot = 0;
        for (int j = 0; j < cfg->count; j++) {
            foot |= !strcmp(cfg->entries[j].section, sec) && !strcmp(cfg->entries[j].name, "foot");
            terrain |= !strcmp(cfg->entries[j].section, sec) && !strcmp(cfg->entries[j].name, "terrain");
            robot |= !strcmp(cfg->entries[j].section, sec) && !strcmp(cfg->entries[j].name, "robot");
        }
        if (!foot || !terrain || (c->nrobots > 1 && !robot))
            return fs_fail(err, FS_BAD_INPUT, "%s: [%s] needs foot = and terrain = (a [foot.NAME] and a [terrain.NAME])%s",
                           cfg->path, sec, c->nrobots > 1 ? " and robot = (a [robot.NAME])" : "");
    }
    return FS_OK;
}

/* Paths become absolute, so that the trial scenario resolves them wherever it lies. */
static fs_status absolute_paths(const fs_config *cfg, fs_campaign *c, fs_error *err)
{
    fs_campaign_item *items[FS_CAMPAIGN_MAX_FEET + FS_CAMPAIGN_MAX_TERRAINS + FS_CAMPAIGN_MAX_ROBOTS];
    int n = 0;
    for (int i = 0; i < c->nfeet; i++)
        items[n++] = &c->foot[i];
    for (int i = 0; i < c->nterrains; i++)
        items[n++] = &c->terrain[i];
    for (int i = 0; i < c->nrobots; i++)
        items[n++] = &c->robot[i];
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

/* Band end e's edits of a cell's scenario, compiled (none: left as loaded, not compiled again). */
static fs_status apply_end(const fs_campaign *c, int e, fs_scenario *sc, fs_error *err)
{
    const fs_band_end *end = &c->end[e];
    fs_status s = FS_OK;
    for (int i = 0; i < end->nsets && s == FS_OK; i++)
        s = fs_scenario_set(sc, end->key[i], end->value[i], err);
    return s == FS_OK && end->nsets ? fs_scenario_compile(sc, err) : s;
}

/* Loads (and so checks) the trial scenario of every cell, once, for the trials. A sweep's points
 * are typed edits: the first point of each (foot, terrain, robot) is read from its files with its
 * values among the overrides (so the file's relations are judged on them, as with --set); every
 * later point copies it, gets its own values (fs_scenario_set) and is compiled, without reading a
 * file. A band's ends are typed edits too: each end of a first point copies the point as read and
 * gets its end's values; a later point copies the first point's same end. */
static fs_status load_pairs(fs_campaign *c, fs_error *err)
{
    int ncells = fs_campaign_ncells(c), nends = fs_campaign_nends(c);
    c->pair = calloc((size_t)ncells * nends, sizeof *c->pair);
    if (!c->pair)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the campaign's %d scenarios", ncells * nends);
    fs_status s = FS_OK;
    for (int cell = 0; cell < ncells && s == FS_OK; cell++) {
        int f, t, r;
        fs_campaign_cell_of(c, cell, &f, &t, &r);
        const fs_campaign_item *point = &c->terrain[t];
        int from = point->point[0] * c->nvalues[1] + point->point[1]; /* how far past its first point */
        fs_scenario *sc = &c->pair[cell * nends];
        fs_error e;
        if (!from) { /* read from the files, the first point with its values as --set would give them */
            char buf[FS_CAMPAIGN_CELL_SETS][FS_PATH_MAX + 32];
            const char *ov[FS_CAMPAIGN_MAX_SET + FS_CAMPAIGN_CELL_SETS];
            int n = fs_campaign_overrides(c, cell, buf, ov);
            s = fs_scenario_load(c->trial_path, ov, n, sc, &e);
            for (int end = nends - 1; end >= 0 && s == FS_OK; end--) { /* end 0 edited last: the others copy it */
                if (end)
                    s = fs_scenario_copy(&sc[end], sc, &e);
                if (s == FS_OK)
                    s = apply_end(c, end, &sc[end], &e);
            }
        } else { /* a later point: the first one's definitions, its values set in them, compiled */
            for (int end = 0; end < nends && s == FS_OK; end++) {
                s = fs_scenario_copy(&sc[end], &c->pair[((f * c->nterrains + t - from) * c->nrobots + r) * nends + end],
                                     &e);
                for (int w = 0; w < c->nsweep && s == FS_OK; w++)
                    s = fs_scenario_set(&sc[end], c->sweep[w], point->sweep_value[w], &e);
                if (s == FS_OK)
                    s = fs_scenario_compile(&sc[end], &e);
            }
        }
        for (int end = 0; end < nends && s == FS_OK; end++)
            s = fs_scenario_require(&sc[end], "trial", &e);
        if (s != FS_OK) {
            const fs_campaign_item *rb = &c->robot[r];
            char gives[FS_NAME_MAX + 96] = ""; /* a --set the message names may be the robot section's */
            if (rb->step_s > 0 || rb->tolerance_m > 0 || rb->error_estimate)
                snprintf(gives, sizeof gives, "; [robot.%s] gives its trials its step_s, tolerance_m or "
                         "error_estimate as --set run.*", rb->name);
            fs_fail(err, s, "%s (campaign %s: foot %s on terrain %s under robot %s%s%s%s)", e.message, c->path,
                    c->foot[f].name, c->terrain[t].name, rb->name, c->band[0] ? ", band " : "", c->band, gives);
        }
    }
    if (s == FS_OK && !c->robot[0].path[0]) /* the trial's own robot: named after its file */
        fs_path_stem(c->pair[0].def.robot_path[0] ? c->pair[0].def.robot_path : "none", c->robot[0].name,
                     sizeof c->robot[0].name);
    if (s != FS_OK)
        fs_campaign_free(c);
    return s;
}

void fs_campaign_free(fs_campaign *c)
{
    for (int i = 0; c->pair && i < fs_campaign_npairs(c); i++)
        fs_scenario_free(&c->pair[i]);
    free(c->pair);
    c->pair = NULL;
    fs_provenance_free(&c->provenance);
}

int fs_campaign_ncells(const fs_campaign *c) { return c->nfeet * c->nterrains * c->nrobots; }

void fs_campaign_cell_of(const fs_campaign *c, int cell, int *foot, int *terrain, int *robot)
{
    *robot = cell % c->nrobots;
    *terrain = cell / c->nrobots % c->nterrains;
    *foot = cell / c->nrobots / c->nterrains;
}

int fs_campaign_nends(const fs_campaign *c) { return c->nends > 1 ? c->nends : 1; }

int fs_campaign_npairs(const fs_campaign *c) { return fs_campaign_ncells(c) * fs_campaign_nends(c); }

const fs_scenario *fs_campaign_pair(const fs_campaign *c, int cell) { return fs_campaign_pair_of(c, cell, 0); }

const fs_scenario *fs_campaign_pair_of(const fs_campaign *c, int cell, int end)
{
    return &c->pair[cell * fs_campaign_nends(c) + end];
}

static fs_status bind_file(fs_config *cfg, binder *b, fs_campaign *c, fs_error *err)
{
    take_sweep_values(cfg, b);
    fs_status s = take_bands(cfg, b, err);
    add_static_keys(b);
    if (s == FS_OK)
        s = add_dynamic_keys(cfg, b, c, err);
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

/* What made the campaign's results: the sets as given, the campaign file, the trial scenario and
 * every cell's files with their hashes, the first cell's settings. */
static fs_status provenance(fs_campaign *c, const char *const *sets, int nsets, fs_error *err)
{
    fs_provenance *p = &c->provenance;
    fs_status s = fs_provenance_init(p, c->path, err);
    if (s == FS_OK)
        s = fs_provenance_overrides(p, sets, nsets, err);
    if (s == FS_OK)
        s = fs_provenance_add_ini(p, c->path, err);
    if (s == FS_OK)
        s = fs_provenance_add_ini(p, c->trial_path, err);
    for (int i = 0; s == FS_OK && i < fs_campaign_ncells(c); i++)
        s = fs_scenario_inputs(fs_campaign_pair(c, i), p, err);
    fs_scenario_settings(&c->pair[0], p->settings, sizeof p->settings);
    for (int r = 1; r < c->nrobots; r++) { /* a robot whose trials take another step (cell r: the first foot and terrain) */
        const fs_scenario_def *d = &fs_campaign_pair(c, r)->def, *d0 = &c->pair[0].def;
        int step = d->step_s != d0->step_s; /* an estimate matters only under a tolerance */
        int tol = d->tolerance_m != d0->tolerance_m || (d->tolerance_m > 0 && d->error_estimate != d0->error_estimate);
        if (!step && !tol)
            continue;
        size_t used = strlen(p->settings);
        snprintf(p->settings + used, sizeof p->settings - used, "; robot %s:", c->robot[r].name);
        used = strlen(p->settings);
        if (step)
            snprintf(p->settings + used, sizeof p->settings - used, " step_s %.6g%s", d->step_s, tol ? "," : "");
        used = strlen(p->settings);
        if (tol)
            snprintf(p->settings + used, sizeof p->settings - used, " tolerance_m %.6g%s%s", d->tolerance_m,
                     d->tolerance_m > 0 ? ", error_estimate " : "",
                     d->tolerance_m > 0 ? estimate_choice[d->error_estimate + 1] : "");
    }
    if (c->band[0]) { /* said in the settings too: the campaign file's hash alone does not name it */
        size_t used = strlen(p->settings);
        snprintf(p->settings + used, sizeof p->settings - used, "; band %s", c->band);
    }
    p->first_seed = c->first_seed;
    p->nseeds = c->seeds;
    return s;
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
        s = bind_bands(&cfg, b, c, err);
    if (s == FS_OK)
        s = check_relations(&cfg, c, err);
    if (s == FS_OK)
        s = absolute_paths(&cfg, c, err);
    if (s == FS_OK && c->nrobots == 0)
        c->nrobots = 1; /* the trial scenario's own robot (named once its scenario is loaded) */
    free(b);
    fs_config_free(&cfg);
    if (s == FS_OK)
        s = load_pairs(c, err);
    if (s == FS_OK && (s = provenance(c, sets, nsets, err)) != FS_OK)
        fs_campaign_free(c);
    return s;
}

int fs_campaign_overrides(const fs_campaign *c, int cell, char buf[FS_CAMPAIGN_CELL_SETS][FS_PATH_MAX + 32],
                          const char **out)
{
    int foot, terrain, robot, n = 0;
    fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
    snprintf(buf[0], sizeof buf[0], "scenario.design=%s", c->foot[foot].path);
    snprintf(buf[1], sizeof buf[1], "scenario.terrain=%s", c->terrain[terrain].path);
    out[n++] = buf[0];
    out[n++] = buf[1];
    if (c->robot[robot].path[0]) {
        snprintf(buf[2], sizeof buf[2], "robot.design=%s", c->robot[robot].path);
        out[n++] = buf[2];
    }
    if (c->robot[robot].step_s > 0) { /* 17 digits: the same double read back */
        snprintf(buf[3], sizeof buf[3], "run.step_s=%.17g", c->robot[robot].step_s);
        out[n++] = buf[3];
    }
    if (c->robot[robot].tolerance_m > 0) {
        snprintf(buf[4], sizeof buf[4], "run.tolerance_m=%.17g", c->robot[robot].tolerance_m);
        out[n++] = buf[4];
    }
    if (c->robot[robot].error_estimate) {
        snprintf(buf[5], sizeof buf[5], "run.error_estimate=%s", estimate_choice[c->robot[robot].error_estimate]);
        out[n++] = buf[5];
    }
    for (int w = 0; w < c->nsweep; w++) { /* the swept values, exactly (17 digits read back the same double) */
        double v = c->terrain[terrain].sweep_value[w];
        if (fs_campaign_sweepable(c->sweep_choice[w])->type == FS_KEY_INTEGER)
            snprintf(buf[6 + w], sizeof buf[6 + w], "%s=%d", c->sweep[w], (int)v);
        else
            snprintf(buf[6 + w], sizeof buf[6 + w], "%s=%.17g", c->sweep[w], v);
        out[n++] = buf[6 + w];
    }
    for (int i = 0; i < c->nset; i++)
        out[n++] = c->set[i];
    return n;
}

int fs_campaign_ntrials(const fs_campaign *c) { return fs_campaign_npairs(c) * c->seeds; }

void fs_campaign_trial_of(const fs_campaign *c, int index, int *cell, int *seed)
{
    *seed = c->first_seed + index % c->seeds;
    *cell = index / c->seeds / fs_campaign_nends(c);
}

int fs_campaign_trial_end(const fs_campaign *c, int index) { return index / c->seeds % fs_campaign_nends(c); }
