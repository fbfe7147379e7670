/* Tests of campaign_run.c (fs_campaign_run.h), the campaign runner the command and Python share: a
 * small campaign (2 feet x 1 terrain x 3 seeds, short trials) run in two workers writes the same
 * bytes as run in one; a progress callback that returns 0 stops it with its finished trials in the
 * journal and nothing else written, and the same call finishes it into the same bytes; its shards
 * merged are the same bytes too, and a missing shard is named; a journal of other overrides is
 * refused and kept; a folder holding the results runs nothing; a worker that exits with status 3
 * makes its trial failed_numerics, said through the callback. A campaign with a contact band runs
 * every trial at both ends, its cell's rate the smaller end's, the same bytes in one worker or two
 * and after a stop between the ends; its high end (no edits) is the band-less campaign's trials bit
 * for bit; a wrong band is refused with its file and line. */
#include "fs_test.h"

#include "footsim/campaign/fs_campaign_run.h"
#include "footsim/campaign/fs_optimize.h"
#include "footsim/io/fs_output.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char tmp[64];
static const char *const FILES[] = {"summary.json", "summary.csv", "summary.md", "trials.csv", "schema.sql",
                                    "chart.dat", "chart.gp"};
enum { NFILES = sizeof FILES / sizeof FILES[0], NTRIALS = 6 };
static const char *const SETS[] = {"run.duration_s=0.15"};

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    REQUIRE(f != NULL);
    fputs(text, f);
    fclose(f);
}

/* $tmp/trial.ini (the campaign tests' trial, paths absolute) and $tmp/small.ini. */
static void make_campaign(void)
{
    if (tmp[0])
        return;
    snprintf(tmp, sizeof tmp, "/tmp/fs_campaign_run_XXXXXX");
    REQUIRE(mkdtemp(tmp) != NULL);
    char path[256], text[2048];
    snprintf(path, sizeof path, "%s/trial.ini", tmp);
    snprintf(text, sizeof text, "[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\nterrain = %s/terrains/flat.ini\n"
             "[start]\ndrop_m = 0.001\n[load]\nmass_kg = 0\n[robot]\ndesign = %s/scenarios/robots/drop_weight.ini\n"
             "[run]\nduration_s = 1.0\nstep_s = 1e-4\ncontact_layer_m = 5e-4\n[landing]\nlanded_tilt_deg = 15\n",
             FS_SOURCE_DIR, FS_SOURCE_DIR, FS_SOURCE_DIR);
    write_text(path, text);
    snprintf(path, sizeof path, "%s/small.ini", tmp);
    snprintf(text, sizeof text, "[campaign]\ntrial = trial.ini\nseeds = 3\n[foot.bio]\nfile = %s/scenarios/feet/biomimetic.ini\n"
             "[foot.flat]\nfile = %s/scenarios/feet/flat.ini\n[terrain.bumpy]\nfile = %s/terrains/simply_uneven.ini\n",
             FS_SOURCE_DIR, FS_SOURCE_DIR, FS_SOURCE_DIR);
    write_text(path, text);
}

/* The campaign loaded with sets, its head for shard/nshards (1/1: whole). */
typedef struct loaded {
    fs_campaign c;
    fs_journal_head h;
} loaded;

static loaded *load_file(const char *file, const char *const *sets, int nsets, int shard, int nshards)
{
    make_campaign();
    char path[256];
    snprintf(path, sizeof path, "%s/%s", tmp, file);
    loaded *l = calloc(1, sizeof *l);
    fs_error err;
    REQUIRE(l != NULL);
    REQUIRE(fs_campaign_load(path, sets, nsets, &l->c, &err) == FS_OK);
    REQUIRE(fs_journal_head_of(&l->c, path, sets, nsets, shard, nshards, &l->h, &err) == FS_OK);
    return l;
}

static loaded *load(const char *const *sets, int nsets, int shard, int nshards)
{
    return load_file("small.ini", sets, nsets, shard, nshards);
}

static void unload(loaded *l)
{
    fs_journal_head_free(&l->h);
    fs_campaign_free(&l->c);
    free(l);
}

/* What the callbacks saw. */
typedef struct seen {
    int calls, last_done, total, went_back, stop_at;
    char said[8][512];
    int nsaid;
} seen;

static int watch(const fs_campaign_progress *p, void *user)
{
    seen *s = user;
    if (p->say) {
        if (s->nsaid < 8)
            snprintf(s->said[s->nsaid++], sizeof s->said[0], "%s", p->say);
        return 1;
    }
    s->went_back += p->done < s->last_done;
    s->last_done = p->done;
    s->total = p->total;
    s->calls++;
    return !(s->stop_at > 0 && p->done >= s->stop_at);
}

static int run_into(loaded *l, const char *name, int jobs, seen *s, const fs_campaign_test_hooks *t,
                    fs_campaign_row *rows, fs_campaign_state *st, fs_error *err)
{
    char dir[256];
    snprintf(dir, sizeof dir, "%s/%s", tmp, name);
    fs_campaign_run_opts o = {.jobs = jobs, .shard = l->h.nshards > 1 ? l->h.shard : 0,
                              .nshards = l->h.nshards > 1 ? l->h.nshards : 0, .progress = watch, .user = s, .test = t};
    return fs_campaign_run(&l->c, &l->h, dir, &o, rows, st, err);
}

/* Whether every file of folders a and b (under tmp) is the same bytes. */
static int same_files(const char *a, const char *b)
{
    int same = 1;
    for (int i = 0; i < NFILES; i++) {
        char pa[256], pb[256];
        snprintf(pa, sizeof pa, "%s/%s/%s", tmp, a, FILES[i]);
        snprintf(pb, sizeof pb, "%s/%s/%s", tmp, b, FILES[i]);
        FILE *fa = fopen(pa, "rb"), *fb = fopen(pb, "rb");
        int ca = 0, cb = 0;
        if (!fa || !fb)
            same = 0;
        while (fa && fb && same && (ca = fgetc(fa)) == (cb = fgetc(fb)) && ca != EOF)
            ;
        if (fa && fb && ca != cb) {
            fprintf(stderr, "  %s differs between %s and %s\n", FILES[i], a, b);
            same = 0;
        }
        if (fa)
            fclose(fa);
        if (fb)
            fclose(fb);
    }
    return same;
}

static int exists(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", tmp, name);
    struct stat st;
    return lstat(path, &st) == 0;
}

static void test_workers_do_not_change_the_bytes(void)
{
    loaded *l = load(SETS, 1, 1, 1);
    fs_campaign_row rows[2];
    fs_campaign_state st;
    fs_error err;
    seen two = {0}, one = {0};
    REQUIRE(run_into(l, "two", 2, &two, NULL, rows, &st, &err) == FS_OK);
    CHECK(st.committed && !st.stopped && !st.finished_already && !st.journal_kept && st.total == NTRIALS);
    CHECK(two.last_done == NTRIALS && two.total == NTRIALS && !two.went_back && two.calls >= NTRIALS);
    CHECK(rows[0].trials == 3 && rows[1].trials == 3 && rows[0].foot == 0 && rows[1].foot == 1);
    CHECK(!exists("two.journal"));
    REQUIRE(run_into(l, "one", 1, &one, NULL, rows, &st, &err) == FS_OK);
    CHECK(same_files("two", "one"));
    /* run again: the folder holds these results, nothing runs */
    seen again = {0};
    REQUIRE(run_into(l, "two", 2, &again, NULL, rows, &st, &err) == FS_OK);
    CHECK(st.finished_already && !st.committed && again.calls == 0);
    unload(l);
}

static void test_a_stop_is_resumed_into_the_same_bytes(void)
{
    loaded *l = load(SETS, 1, 1, 1);
    fs_campaign_row rows[2];
    fs_campaign_state st;
    fs_error err;
    seen stop = {.stop_at = 2};
    REQUIRE(run_into(l, "stopped", 2, &stop, NULL, rows, &st, &err) == FS_OK);
    CHECK(st.stopped && !st.committed && st.journal_kept && st.total == NTRIALS);
    CHECK(st.kept >= 2 && st.kept < NTRIALS);
    CHECK(!exists("stopped") && exists("stopped.journal/journal"));
    /* a journal of other overrides is refused, and kept */
    static const char *const other[] = {"run.duration_s=0.2"};
    loaded *o = load(other, 1, 1, 1);
    seen refused = {0};
    CHECK(run_into(o, "stopped", 2, &refused, NULL, rows, &st, &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "another run of this campaign") != NULL && strstr(err.message, "--fresh") != NULL);
    CHECK(exists("stopped.journal/journal") && refused.calls == 0);
    unload(o);
    int kept = 0;
    {
        char want[64];
        seen go = {0};
        REQUIRE(run_into(l, "stopped", 2, &go, NULL, rows, &st, &err) == FS_OK);
        CHECK(st.committed && !st.stopped && !exists("stopped.journal"));
        for (int i = 0; i < go.nsaid; i++)
            for (int k = 2; k < NTRIALS; k++) {
                snprintf(want, sizeof want, ": %d of %d trials done, %d to run", k, NTRIALS, NTRIALS - k);
                if (!strncmp(go.said[i], "resuming from ", 14) && strstr(go.said[i], want))
                    kept = k;
            }
    }
    CHECK(kept >= 2);
    seen whole = {0};
    REQUIRE(run_into(l, "whole", 1, &whole, NULL, rows, &st, &err) == FS_OK);
    CHECK(same_files("stopped", "whole"));
    unload(l);
}

static void test_shards_merge_into_the_same_bytes(void)
{
    fs_campaign_state st;
    fs_error err;
    const char *names[2] = {"s1", "s2"};
    for (int k = 0; k < 2; k++) {
        loaded *l = load(SETS, 1, k + 1, 2);
        seen s = {0};
        REQUIRE(run_into(l, names[k], 2, &s, NULL, NULL, &st, &err) == FS_OK);
        CHECK(st.committed && st.total == NTRIALS / 2);
        char journal[64];
        snprintf(journal, sizeof journal, "%s/trials.journal", names[k]);
        CHECK(exists(journal) && !exists("s1/summary.json"));
        unload(l);
    }
    char d1[256], d2[256], out[256];
    snprintf(d1, sizeof d1, "%s/s1", tmp);
    snprintf(d2, sizeof d2, "%s/s2", tmp);
    snprintf(out, sizeof out, "%s/merged", tmp);
    const char *both[2] = {d1, d2};
    fs_campaign_merged *m = calloc(1, sizeof *m);
    REQUIRE(m != NULL);
    /* one shard missing: named */
    CHECK(fs_campaign_merge(both, 1, 0, m, &err) == FS_BAD_INPUT);
    CHECK(m->missing_shard == 2 && m->head.nshards == 2 && strstr(err.message, "3 of 6 trials missing") != NULL);
    fs_campaign_merge_free(m);
    REQUIRE(fs_campaign_merge(both, 2, 0, m, &err) == FS_OK);
    /* into a shard's own folder: refused */
    CHECK(fs_campaign_merge_write(m, d1, 0, NULL, NULL, &st, &err) == FS_BAD_INPUT);
    CHECK(fs_campaign_merge_write(m, out, 0, NULL, NULL, &st, &err) == FS_OK && st.committed);
    fs_campaign_merge_free(m);
    free(m);
    if (!exists("one")) { /* alone: make the whole run to compare with */
        loaded *l = load(SETS, 1, 1, 1);
        seen s = {0};
        REQUIRE(run_into(l, "one", 1, &s, NULL, NULL, &st, &err) == FS_OK);
        unload(l);
    }
    CHECK(same_files("merged", "one"));
}

static void test_a_crashed_worker_is_failed_numerics(void)
{
    loaded *l = load(SETS, 1, 1, 1);
    fs_campaign_row rows[2];
    fs_campaign_state st;
    fs_error err;
    fs_campaign_test_hooks t = {.crash_seed = 2, .stop_seed = -1, .kill_seed = -1};
    seen s = {0};
    REQUIRE(run_into(l, "crash", 2, &s, &t, rows, &st, &err) == FS_OK);
    CHECK(st.committed && rows[0].failed_numerics == 1 && rows[1].failed_numerics == 1);
    int told = 0;
    for (int i = 0; i < s.nsaid; i++)
        told += strstr(s.said[i], "seed 2, exited with status 3; counted as failed_numerics") != NULL;
    CHECK(told == 2);
    unload(l);
}


/* $tmp/band.ini: the biomimetic foot on flat ground under drop_weight, one seed, 1 s trials, and a
 * band whose low end raises the robot's centre of mass to 0.3 m and whose high end is the trial as
 * it is. By the pitch-stiffness law (docs/landing.md) Table I's foot (K = 12.8 N m/rad) holds
 * drop_weight's 26 kg at its own height (m g h = 5.1 N m) but not at 0.3 m (m g h = 76.5 N m, six
 * times K): the high end lands, and the low end cannot come to rest upright (it falls, or is still
 * toppling when the 1 s window ends: not landed either way). */
static void make_band_campaign(const char *name, const char *band)
{
    make_campaign();
    char path[256], text[2048];
    snprintf(path, sizeof path, "%s/%s", tmp, name);
    snprintf(text, sizeof text, "[campaign]\ntrial = trial.ini\nseeds = 1\nband = tall\n[foot.bio]\nfile = "
             "%s/scenarios/feet/biomimetic.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n[band.tall]\n%s\n",
             FS_SOURCE_DIR, FS_SOURCE_DIR, band);
    write_text(path, text);
}

/* The rows of $tmp/dir/trials.csv after its header, into buf; with end ("high,"), only the rows of
 * that band end, its field taken out (it follows foot, terrain and robot). */
static void trial_rows(const char *dir, const char *end, char *buf, size_t size)
{
    char path[256], line[4096];
    snprintf(path, sizeof path, "%s/%s/trials.csv", tmp, dir);
    FILE *f = fopen(path, "r");
    REQUIRE(f != NULL);
    buf[0] = 0;
    for (int n = 0; fgets(line, sizeof line, f); n++) {
        char *p = line;
        for (int k = 0; end && k < 3; k++)
            p = strchr(p, ',') + 1;
        if (n == 0 || (end && strncmp(p, end, strlen(end))))
            continue; /* the header, or another end's row */
        if (end)
            memmove(p, p + strlen(end), strlen(p + strlen(end)) + 1); /* "high," taken out */
        strncat(buf, line, size - strlen(buf) - 1);
    }
    fclose(f);
}

static void test_a_band_runs_each_trial_at_both_ends(void)
{
    make_band_campaign("band.ini", "low = robot.com_height_m=0.3\nhigh =");
    loaded *l = load_file("band.ini", NULL, 0, 1, 1);
    CHECK(fs_campaign_nends(&l->c) == 2 && fs_campaign_ntrials(&l->c) == 2);
    CHECK(fs_campaign_trial_end(&l->c, 0) == 0 && fs_campaign_trial_end(&l->c, 1) == 1);
    fs_campaign_row rows[1];
    fs_campaign_state st;
    fs_error err;
    seen two = {0};
    REQUIRE(run_into(l, "band2", 2, &two, NULL, rows, &st, &err) == FS_OK);
    CHECK(st.committed && st.total == 2 && two.total == 2);
    /* each end's count, and the cell's rate the smaller: the low end does not land, the high end does */
    CHECK(rows[0].end_trials[0] == 1 && rows[0].end_trials[1] == 1);
    CHECK(rows[0].end_landed[0] == 0 && rows[0].end_landed[1] == 1);
    CHECK(rows[0].band_end == 0 && rows[0].trials == 1 && rows[0].landed == 0 && rows[0].success_rate == 0);
    CHECK(rows[0].success_rate == fmin(rows[0].end_rate[0], rows[0].end_rate[1]));
    /* footsim plot reads the band back from summary.json: its ends, and each end's rate per row */
    {
        char path[256];
        snprintf(path, sizeof path, "%s/band2/summary.json", tmp);
        fs_campaign *back = calloc(1, sizeof *back);
        fs_campaign_row *back_rows = calloc(FS_CAMPAIGN_MAX_FEET * FS_CAMPAIGN_MAX_TERRAINS * FS_CAMPAIGN_MAX_ROBOTS,
                                            sizeof *back_rows);
        REQUIRE(back && back_rows && fs_campaign_reload(path, back, back_rows, &err) == FS_OK);
        CHECK(!strcmp(back->band, "tall") && fs_campaign_nends(back) == 2 && !strcmp(back->end[1].name, "high"));
        CHECK(back_rows[0].band_end == 0 && back_rows[0].end_rate[0] == 0 && back_rows[0].end_rate[1] == 1);
        free(back), free(back_rows);
    }
    /* one worker stopped after the low end's trial, then resumed: the high end's runs */
    seen stop = {.stop_at = 1};
    REQUIRE(run_into(l, "band1", 1, &stop, NULL, rows, &st, &err) == FS_OK);
    CHECK(st.stopped && st.kept == 1 && exists("band1.journal/journal"));
    seen go = {0};
    REQUIRE(run_into(l, "band1", 1, &go, NULL, rows, &st, &err) == FS_OK);
    int resumed = 0;
    for (int i = 0; i < go.nsaid; i++)
        resumed += strstr(go.said[i], "1 of 2 trials done, 1 to run") != NULL;
    CHECK(st.committed && resumed == 1);
    CHECK(same_files("band2", "band1"));
    /* the high end is the trial as it is: the band-less campaign's trial, every number the same */
    static const char *const none[] = {"campaign.band=none"};
    loaded *p = load_file("band.ini", none, 1, 1, 1);
    CHECK(fs_campaign_nends(&p->c) == 1 && fs_campaign_ntrials(&p->c) == 1);
    seen plain = {0};
    REQUIRE(run_into(p, "plain", 1, &plain, NULL, NULL, &st, &err) == FS_OK);
    char high[4096], alone[4096];
    trial_rows("band2", "high,", high, sizeof high);
    trial_rows("plain", NULL, alone, sizeof alone);
    CHECK(alone[0] && !strcmp(high, alone));
    unload(p);
    unload(l);
}

/* The laws over a band (no trial run: the summary of made-up outcomes). The low end puts drop_weight's
 * centre of mass at 0.3 m on a lively rubber pad (docs/contact.md's: e = 0.49), the high end is the
 * trial as it is. The low end lands and the high end falls, so the measured worse end is the high
 * one; but the laws topple at the low end (K = 12.8 N m/rad against m g h = 76.5) and stand at the
 * high end (against 5.1): the cell's law must be the low end's, each end's verdict given. The high
 * end's contact is the band's stiffest and overdamped (zeta 1.12): its law is the band-less
 * campaign's, every number the same; the pad's compliance softens the low end's K. */
static void test_a_band_cells_law_is_its_worse_ends(void)
{
    make_band_campaign("band_law.ini", "low = robot.com_height_m=0.3, sole.stiffness_N_per_m=100100, "
                                       "sole.damping_Ns_per_m=208.011\nhigh =");
    loaded *l = load_file("band_law.ini", NULL, 0, 1, 1);
    fs_trial_result res[2];
    memset(res, 0, sizeof res);
    res[0].outcome = FS_LANDED, res[1].outcome = FS_FELL;
    fs_campaign_row rows[1], plain[1];
    fs_campaign_summarize(&l->c, res, rows);
    CHECK(rows[0].band_end == 1 && rows[0].law_end == 0);
    CHECK(rows[0].end_law[0] == FS_LAW_TOPPLES && rows[0].end_drop_law[0] == FS_LAW_TOPPLES);
    CHECK(rows[0].end_law[1] == FS_LAW_STANDS && rows[0].end_drop_law[1] == FS_LAW_STANDS);
    CHECK(rows[0].law == FS_LAW_TOPPLES && rows[0].drop_law == FS_LAW_TOPPLES && rows[0].drop_stands == 0);
    CHECK_NEAR(rows[0].end_restitution[0], 0.49, 0.01);
    CHECK(rows[0].end_restitution[1] == 0);
    CHECK(rows[0].end_law_K[0] < rows[0].end_law_K[1]);
    static const char *const none[] = {"campaign.band=none"};
    loaded *p = load_file("band_law.ini", none, 1, 1, 1);
    fs_campaign_summarize(&p->c, &res[1], plain);
    CHECK(plain[0].law_end == -1 && plain[0].law == rows[0].end_law[1] && plain[0].drop_law == rows[0].end_drop_law[1]);
    CHECK(plain[0].law_K == rows[0].end_law_K[1] && plain[0].drop_stands == rows[0].end_drop_stands[1]);
    CHECK(plain[0].drop_energy_J == rows[0].end_drop_energy_J[1] && plain[0].drop_barrier_J == rows[0].end_drop_barrier_J[1]);
    unload(p);
    unload(l);
}

/* A design search over a campaign with a band: a candidate reaches both ends' scenarios (each keeping
 * its end's edits), and the closeness of its misses counts the trials of both ends. */
static void test_a_band_reaches_the_optimizer(void)
{
    make_band_campaign("band_opt.ini", "low = robot.com_height_m=0.3\nhigh =\n[expect.lands]\nfoot = bio\n"
                       "terrain = flat\nmin_success = 1");
    char path[256];
    snprintf(path, sizeof path, "%s/opt.ini", tmp);
    write_text(path, "[optimize]\ncampaign = band_opt.ini\nobjective = least_stiff\nmax_evaluations = 2\n[param.scale]\nkey = springs.scale\n"
                     "min = 1\nmax = 100\nstart = 10\nlog = yes\n");
    fs_optimize *o = calloc(1, sizeof *o);
    fs_error err;
    REQUIRE(o != NULL);
    fs_status loaded_ok = fs_optimize_load(path, NULL, 0, o, &err);
    if (loaded_ok != FS_OK)
        fprintf(stderr, "  %s\n", err.message);
    REQUIRE(loaded_ok == FS_OK);
    double x[1] = {21.5};
    REQUIRE(fs_optimize_apply(o, x, &err) == FS_OK);
    const fs_campaign *c = &o->campaign;
    REQUIRE(fs_campaign_npairs(c) == 2);
    for (int e = 0; e < 2; e++) {
        fs_scenario *sc = (fs_scenario *)fs_campaign_pair_of(c, 0, e);
        CHECK(*fs_scenario_number(sc, "springs.scale", NULL) == 21.5);
    }
    CHECK(fs_campaign_pair_of(c, 0, 0)->def.robot.com_height_m == 0.3);
    CHECK(fs_campaign_pair_of(c, 0, 1)->def.robot.com_height_m < 0.3);
    /* the low end landed, the high end fell a quarter into its 1 s window: one miss, 0.75 of the window short */
    fs_trial_result r[2];
    memset(r, 0, sizeof r);
    r[0].outcome = FS_LANDED;
    r[1].outcome = FS_FELL;
    r[0].end_time_s = 1, r[1].end_time_s = 0.25;
    fs_campaign_row rows[1];
    fs_campaign_summarize(c, r, rows);
    CHECK(rows[0].success_rate == 0); /* the worse end's */
    CHECK(fabs(fs_optimize_closeness(o, r, rows) - 0.75) < 1e-12);
    /* a target met counts nothing, however many of its trials fell */
    o->campaign.expect[0].min_success = 0;
    CHECK(fs_optimize_closeness(o, r, rows) == 0);
    fs_optimize_free(o);
    free(o);
}

/* A wrong band: refused at loading with the file's line (or --set), nothing run. */
static void refused(const char *band, const char *const *sets, int nsets, const char *want)
{
    make_band_campaign("bad.ini", band);
    char path[256];
    snprintf(path, sizeof path, "%s/bad.ini", tmp);
    fs_campaign c;
    fs_error err = {FS_OK, ""};
    CHECK(fs_campaign_load(path, sets, nsets, &c, &err) == FS_BAD_INPUT);
    if (!strstr(err.message, want))
        fprintf(stderr, "  wanted '%s' in: %s\n", want, err.message);
    CHECK(strstr(err.message, want) != NULL);
}

static void test_a_wrong_band_is_refused(void)
{
    /* the band section's lines: 10 low, 11 high */
    refused("low = robot.com_height_m=0.3\nmiddle = run.step_s=1e-4", NULL, 0, "bad.ini:11: [band.tall] has no key 'middle'");
    refused("low = sole.softness=3\nhigh =", NULL, 0, "bad.ini:10: [band.tall] low: 'sole.softness' is not a number key");
    refused("low = sole.stiffness_N_per_m\nhigh =", NULL, 0, "bad.ini:10: [band.tall] low: 'sole.stiffness_N_per_m' has no '='");
    refused("low = sole.stiffness_N_per_m=-5\nhigh =", NULL, 0, "bad.ini:10: [band.tall] low: sole.stiffness_N_per_m");
    refused("low = sole.stiffness_N_per_m=1e5,, start.drop_m=0.01\nhigh =", NULL, 0, "bad.ini:10: [band.tall] low: an override is empty");
    refused("low = start.drop_m=0.01, start.drop_m=0.02\nhigh =", NULL, 0, "bad.ini:10: [band.tall] low sets start.drop_m twice");
    static const char *const clash[] = {"robot.com_height_m=0.1"};
    refused("low = robot.com_height_m=0.3\nhigh =", clash, 1, "--set robot.com_height_m=0.1: robot.com_height_m is set by band tall's low end");
    static char robot_file[FS_PATH_MAX];
    snprintf(robot_file, sizeof robot_file, "robot.r.file=%s/scenarios/robots/drop_weight.ini", FS_SOURCE_DIR);
    const char *own[] = {robot_file, "robot.r.tolerance_m=1e-6"}; /* a robot's own tolerance, which a band would overwrite */
    refused("low = run.tolerance_m=3e-6\nhigh =", own, 2,
            "--set robot.r.tolerance_m: band tall's low end sets run.tolerance_m, which robot r gives its own");
    own[1] = "robot.r.step_s=5e-4";
    refused("low =\nhigh = run.step_s=2e-4", own, 2,
            "--set robot.r.step_s: band tall's high end sets run.step_s, which robot r gives its own");
    { /* a band's step where the robot gives only its tolerance: no clash, the band's step at that end */
        fs_campaign c;
        fs_error err = {FS_OK, ""};
        char path[256];
        make_band_campaign("steps.ini", "low =\nhigh = run.step_s=2e-4");
        snprintf(path, sizeof path, "%s/steps.ini", tmp);
        own[1] = "robot.r.tolerance_m=1e-6";
        REQUIRE(fs_campaign_load(path, own, 2, &c, &err) == FS_OK);
        CHECK(fs_campaign_pair_of(&c, 0, 1)->def.step_s == 2e-4 && fs_campaign_pair_of(&c, 0, 0)->def.step_s == 1e-4);
        CHECK(fs_campaign_pair_of(&c, 0, 1)->def.tolerance_m == 1e-6);
        fs_campaign_free(&c);
    }
    static const char *const other[] = {"campaign.band=wide"};
    refused("low = robot.com_height_m=0.3\nhigh =", other, 1, "band = 'wide' is not one of the choices; allowed: none|tall");
}

static void test_cleanup(void)
{
    if (tmp[0])
        fs_remove_tree(tmp);
}

FS_TEST_MAIN(TEST(test_workers_do_not_change_the_bytes), TEST(test_a_stop_is_resumed_into_the_same_bytes),
             TEST(test_shards_merge_into_the_same_bytes), TEST(test_a_crashed_worker_is_failed_numerics),
             TEST(test_a_band_runs_each_trial_at_both_ends), TEST(test_a_wrong_band_is_refused),
             TEST(test_a_band_reaches_the_optimizer), TEST(test_a_band_cells_law_is_its_worse_ends),
             TEST(test_cleanup))
