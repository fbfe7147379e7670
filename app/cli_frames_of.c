/* cli_frames_of.c: `footsim campaign FILE --frames-of SELECTORS`: frames of chosen trials of a
 * campaign, in its results folder, without changing any result.
 *
 * SELECTORS is KEY=VALUE[/VALUE...] joined by commas, KEY one of foot, terrain, robot (names of the
 * campaign's sections) and seed (one of its seeds); a key left out matches every value. The
 * selectors and the frame options are checked before any trial runs (exit 2). After the campaign's
 * trials, each chosen trial runs again, alone in this process and with the frames observer, which
 * does not change a trial (cli_frames.sh checks it): its frames go to
 * DIR/frames/<foot>-<terrain>-<robot>-seed<N>/. The summary files never see any of it. */
#include "cli.h"

#include "footsim/campaign/fs_campaign.h"
#include "footsim/experiment/fs_outcome.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/io/fs_output.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { KEY_FOOT, KEY_TERRAIN, KEY_ROBOT, KEY_SEED, NKEYS, MAX_CHOSEN = 100 };
static const char *const key_names[NKEYS] = {"foot", "terrain", "robot", "seed"};

struct cli_frames_of {
    const cli_args *a;
    int n;
    int *trial; /* the chosen trials' indices */
};

/* The index of value among key's choices in c (a name, or a seed), or -1. */
static int value_index(const fs_campaign *c, int key, const char *value, size_t len)
{
    if (key == KEY_SEED) {
        char buf[32], *end;
        if (len == 0 || len >= sizeof buf)
            return -1;
        memcpy(buf, value, len);
        buf[len] = 0;
        long seed = strtol(buf, &end, 10);
        return *end || seed < c->first_seed || seed >= (long)c->first_seed + c->seeds ? -1 : (int)(seed - c->first_seed);
    }
    const fs_campaign_item *items = key == KEY_FOOT ? c->foot : key == KEY_TERRAIN ? c->terrain : c->robot;
    int n = key == KEY_FOOT ? c->nfeet : key == KEY_TERRAIN ? c->nterrains : c->nrobots;
    for (int i = 0; i < n; i++)
        if (strlen(items[i].name) == len && !strncmp(items[i].name, value, len))
            return i;
    return -1;
}

/* What key may be, for a refusal. */
static void allowed(const fs_campaign *c, int key, char *buf, size_t size)
{
    if (key == KEY_SEED) {
        snprintf(buf, size, "a seed from %d to %d", c->first_seed, c->first_seed + c->seeds - 1);
        return;
    }
    const fs_campaign_item *items = key == KEY_FOOT ? c->foot : key == KEY_TERRAIN ? c->terrain : c->robot;
    int n = key == KEY_FOOT ? c->nfeet : key == KEY_TERRAIN ? c->nterrains : c->nrobots;
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < n && used < size; i++)
        used += (size_t)snprintf(buf + used, size - used, "%s%s", i ? ", " : "", items[i].name);
}

/* Parses the selectors into choose[key][value] (1: chosen); 0 or the exit status. */
static int parse(const fs_campaign *c, const char *text, unsigned char *choose[NKEYS], const int count[NKEYS])
{
    int given[NKEYS] = {0};
    for (const char *p = text; *p;) {
        const char *comma = strchr(p, ','), *end = comma ? comma : p + strlen(p), *eq = memchr(p, '=', (size_t)(end - p));
        int key = -1;
        for (int k = 0; eq && k < NKEYS; k++)
            if ((size_t)(eq - p) == strlen(key_names[k]) && !strncmp(p, key_names[k], (size_t)(eq - p)))
                key = k;
        if (key < 0 || given[key]) {
            fprintf(stderr, "footsim campaign: --frames-of %s: '%.*s' is not a selector; allowed: foot=NAME, "
                            "terrain=NAME, robot=NAME, seed=N (each once, several values joined by /), joined by "
                            "commas, e.g. foot=biomimetic,terrain=flat,seed=1/2\n", text, (int)(end - p), p);
            return FS_BAD_INPUT;
        }
        given[key] = 1;
        for (const char *v = eq + 1; v <= end;) {
            const char *slash = memchr(v, '/', (size_t)(end - v)), *vend = slash ? slash : end;
            int i = value_index(c, key, v, (size_t)(vend - v));
            if (i < 0) {
                char list[2048];
                allowed(c, key, list, sizeof list);
                fprintf(stderr, "footsim campaign: --frames-of %s: %s '%.*s' is not in this campaign; allowed: %s\n",
                        text, key_names[key], (int)(vend - v), v, list);
                return FS_BAD_INPUT;
            }
            choose[key][i] = 1;
            v = vend + 1;
        }
        p = comma ? comma + 1 : end;
    }
    for (int k = 0; k < NKEYS; k++)
        if (!given[k])
            memset(choose[k], 1, (size_t)count[k]);
    return 0;
}

void cli_frames_of_free(cli_frames_of *f)
{
    if (f)
        free(f->trial);
    free(f);
}

int cli_frames_of_open(const cli_args *a, const fs_campaign *c, cli_frames_of **out)
{
    *out = NULL;
    if (!a->frames_of)
        return 0;
    int count[NKEYS] = {c->nfeet, c->nterrains, c->nrobots, c->seeds}, ntrials = fs_campaign_ntrials(c);
    unsigned char *choose[NKEYS] = {NULL};
    cli_frames_of *f = calloc(1, sizeof *f);
    int s = f ? 0 : FS_NO_MEMORY;
    for (int k = 0; k < NKEYS && !s; k++)
        s = (choose[k] = calloc((size_t)count[k] + 1, 1)) ? 0 : FS_NO_MEMORY;
    if (!s && !(f->trial = malloc(MAX_CHOSEN * sizeof *f->trial)))
        s = FS_NO_MEMORY;
    if (s)
        cli_report(s, "out of memory");
    if (!s)
        s = parse(c, a->frames_of, choose, count);
    for (int t = 0; t < ntrials && !s; t++) {
        int cell, seed, foot, terrain, robot;
        fs_campaign_trial_of(c, t, &cell, &seed);
        fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
        if (!(choose[KEY_FOOT][foot] && choose[KEY_TERRAIN][terrain] && choose[KEY_ROBOT][robot] &&
              choose[KEY_SEED][seed - c->first_seed]))
            continue;
        if (f->n == MAX_CHOSEN)
            s = cli_report(FS_BAD_INPUT, "--frames-of: it chooses more than 100 trials; name a foot, terrain, robot "
                                         "or seeds to choose fewer");
        else
            f->trial[f->n++] = t;
        /* the frame options and the renderer, checked on the first chosen trial's scenario */
        if (!s && f->n == 1)
            s = cli_frames_check(a, fs_campaign_pair(c, cell));
    }
    if (!s && f->n == 0)
        s = cli_report(FS_BAD_INPUT, "--frames-of: no trial of the campaign matches; check the names and seeds");
    for (int k = 0; k < NKEYS; k++)
        free(choose[k]);
    if (s) {
        cli_frames_of_free(f);
        return s;
    }
    f->a = a;
    *out = f;
    return 0;
}

/* The i-th chosen trial: its frames folder, and the trial run again with the frames observer. */
static int draw_trial(const cli_frames_of *f, const fs_campaign *c, int i, const fs_trial_result *recorded,
                      const char *dir, const char *shown_dir)
{
    int cell, seed, foot, terrain, robot, end = fs_campaign_trial_end(c, f->trial[i]);
    fs_campaign_trial_of(c, f->trial[i], &cell, &seed);
    fs_campaign_cell_of(c, cell, &foot, &terrain, &robot);
    const char *dash = c->band[0] ? "-" : "", *end_name = c->end[end].name; /* a band's end: in the folder's name */
    /* drawing takes a while (the trial run again, a frame every 1/fps s): say which, after the
       trials' progress line */
    fprintf(stderr, "footsim campaign: --frames-of: drawing %d of %d: %s on %s under %s%s%s, seed %d\n", i + 1, f->n,
            c->foot[foot].name, c->terrain[terrain].name, c->robot[robot].name, c->band[0] ? " at band end " : "",
            end_name, seed);
    /* fits: a results folder leaves FS_DIR_ROOM for this (fs_normalise_dir, before any trial) */
    char path[FS_OUT_PATH], shown[FS_OUT_PATH];
    fs_error err;
    if (fs_path_format(path, sizeof path, "--out", &err, "%s/frames/%s-%s-%s%s%s-seed%d", dir, c->foot[foot].name,
                       c->terrain[terrain].name, c->robot[robot].name, dash, end_name, seed) != FS_OK ||
        fs_path_format(shown, sizeof shown, "--out", &err, "%s/frames/%s-%s-%s%s%s-seed%d", shown_dir,
                       c->foot[foot].name, c->terrain[terrain].name, c->robot[robot].name, dash, end_name, seed) != FS_OK)
        return cli_report(err.status, err.message);
    if (fs_make_dirs(path, &err) != FS_OK)
        return cli_report(err.status, err.message);
    /* the pose the seed draws, to frame the camera on: on the heap, freed on every path */
    fs_scenario *placed = cli_zalloc(sizeof *placed);
    if (!placed)
        return FS_NO_MEMORY;
    int s = 0;
    const fs_scenario *pair = fs_campaign_pair_of(c, cell, end);
    if (fs_scenario_copy(placed, pair, &err) != FS_OK ||
        fs_trial_place(placed, seed, NULL, &err) != FS_OK)
        s = cli_report(err.status, err.message);
    cli_frames *frames = NULL;
    fs_run_observer obs;
    if (!s)
        s = cli_frames_open_at(f->a, placed, path, &frames, &obs);
    char label[128];
    snprintf(label, sizeof label, "SEED %d", seed);
    cli_frames_label(frames, label);
    fs_scenario_free(placed);
    free(placed);
    if (s)
        return s;
    fs_trial_result r;
    fs_status rs = fs_trial_run_scenario(pair, seed, &obs, &r, &err);
    /* a worker that died leaves a record of its own; the trial drawn again dies here the same way */
    if (rs == FS_OK && (r.outcome != recorded->outcome || r.rule != recorded->rule))
        fprintf(stderr, "footsim campaign: --frames-of: %s drew %s (%s) where the campaign recorded %s (%s); the "
                        "campaign's results stand\n", path, fs_outcome_name(r.outcome), fs_rule_name(r.rule),
                fs_outcome_name(recorded->outcome), fs_rule_name(recorded->rule));
    int fs = 0;
    if (rs == FS_OK) {
        snprintf(label, sizeof label, "SEED %d  %s (%s)", seed, fs_outcome_name(r.outcome), fs_rule_name(r.rule));
        fs = cli_frames_finish(frames, label);
    }
    int closed = cli_frames_close(frames, rs == FS_OK && !fs, shown);
    fs = fs ? fs : closed;
    if (rs != FS_OK)
        return cli_report(rs, err.message);
    return fs;
}

int cli_frames_of_write(cli_frames_of *f, const fs_campaign *c, const fs_trial_result *results, const char *dir,
                        const char *shown_dir)
{
    int s = 0;
    for (int i = 0; f && i < f->n && !s; i++)
        s = draw_trial(f, c, i, &results[f->trial[i]], dir, shown_dir);
    cli_frames_of_free(f);
    return s;
}
