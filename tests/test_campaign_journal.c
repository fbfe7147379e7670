/* Tests of campaign_journal.c (issue 33): a journal cut at every byte offset and then resumed
 * (cut back to its last whole record, the rest appended) is byte for byte the uninterrupted one,
 * after any sequence of such cuts; every single-byte change of a record (a flipped digit, another
 * outcome, a number made nan) is caught by its checksum, named by line, with the records before it
 * kept; a header changed anywhere is refused; format 1 is read when clean and refused (naming
 * --fresh) when not; CR LF line ends are named; a FIFO, a folder or a symbolic link is refused
 * without blocking; a killed trial may have a second record, nothing else may, and a record of a trial
 * the campaign has not is damage at its line. No simulation runs:
 * the records are made up. */
#include "fs_test.h"

#include "footsim/base/fs_crc.h"
#include "footsim/campaign/fs_campaign.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

enum { NTRIALS = 6, NREC = 5 };

static char dir[64];

static void make_dir(void)
{
    if (dir[0])
        return;
    /* in memory where there is a tmpfs: each append syncs, and a disk's syncs would take a minute */
    snprintf(dir, sizeof dir, "/dev/shm/fs_journal_XXXXXX");
    if (!mkdtemp(dir)) {
        snprintf(dir, sizeof dir, "/tmp/fs_journal_XXXXXX");
        if (!mkdtemp(dir))
            dir[0] = 0;
    }
}

static void path_of(const char *name, char *out, size_t size) { snprintf(out, size, "%s/%s", dir, name); }

static void head_of(fs_journal_head *h)
{
    memset(h, 0, sizeof *h);
    snprintf(h->campaign, sizeof h->campaign, "/nowhere/small.ini");
    h->set[h->nset++] = strdup("run.duration_s=0.15");
    h->shard = h->nshards = 1;
    h->ntrials = NTRIALS;
    h->provenance = strdup("# provenance: footsim test; seeds 1 to 3; inputs small.ini=00");
}

/* Record k: trial index order 3, 0, 5, 1, 2 (order of completion), awkward numbers and text. */
static int record_of(int k, fs_trial_result *r)
{
    static const int order[NREC] = {3, 0, 5, 1, 2};
    memset(r, 0, sizeof *r);
    r->draw.seed = order[k] % 3 + 1;
    r->draw.x_m = -1.0 / 3 + k, r->draw.yaw_deg = 1e-310 * k, r->draw.roll_deg = -0.0;
    r->outcome = k % 4, r->rule = 1 + k;
    r->end_time_s = 0.15, r->touchdown_s = k == 2 ? NAN : 0.01 * k, r->peak_force_N = k == 4 ? INFINITY : 123.456;
    r->steps = 1500 + k;
    r->soil_sinkage_m = NAN, r->print_volume_m3 = k == 3 ? NAN : 1e-6 * (k + 1), r->print_slip_m = 0.001 * k;
    snprintf(r->failure, sizeof r->failure, k == 1 ? "line\nbreak \\ and\r|bar" : "");
    return order[k];
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static char *slurp(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    *n = file_size(path);
    char *b = f && *n >= 0 ? malloc((size_t)*n + 1) : NULL;
    if (b && fread(b, 1, (size_t)*n, f) != (size_t)*n) {
        free(b);
        b = NULL;
    }
    if (f)
        fclose(f);
    return b;
}

static void spit(const char *path, const char *data, long n)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(data, 1, (size_t)n, f);
        fclose(f);
    }
}

/* Appends records first .. NREC - 1 to path (created with the header when absent), after cutting
 * it to keep bytes (-1: as it is). */
static int append_from(const char *path, const fs_journal_head *h, long long keep, int first)
{
    fs_journal j;
    fs_error err;
    if (fs_journal_open(&j, path, h, keep, &err) != FS_OK) {
        fprintf(stderr, "  %s\n", err.message);
        return 0;
    }
    int ok = 1;
    for (int k = first; k < NREC && ok; k++) {
        fs_trial_result r;
        int i = record_of(k, &r);
        ok = fs_journal_append(&j, i, &r, &err) == FS_OK;
    }
    fs_journal_close(&j);
    return ok;
}

/* The whole journal, the offset where each record starts (start[NREC]: the end). */
static char *whole(const fs_journal_head *h, long *n, long start[NREC + 1])
{
    char path[128];
    path_of("whole", path, sizeof path);
    unlink(path);
    if (!append_from(path, h, -1, NREC))
        return NULL;
    start[0] = file_size(path);
    for (int k = 0; k < NREC; k++) {
        fs_journal j;
        fs_error err;
        fs_trial_result r;
        int i = record_of(k, &r);
        if (fs_journal_open(&j, path, h, -1, &err) != FS_OK || fs_journal_append(&j, i, &r, &err) != FS_OK)
            return NULL;
        fs_journal_close(&j);
        start[k + 1] = file_size(path);
    }
    return slurp(path, n);
}

/* The fixture of most tests: the temporary folder, the head, the whole journal (*n bytes, its
 * records' starts) and the path of the test's own file, `name` in the folder. */
static char *fixture(fs_journal_head *h, long *n, long start[NREC + 1], const char *name, char path[128])
{
    make_dir();
    head_of(h);
    path_of(name, path, 128);
    return whole(h, n, start);
}

/* Reads path with a tail; the number of records read (-1: refused) and the tail. */
static int read_tail(const char *path, fs_journal_tail *t, unsigned char *done_out, fs_trial_result *res_out)
{
    fs_journal_head h;
    fs_trial_result *res;
    unsigned char *done;
    int ndone;
    fs_error err;
    if (fs_journal_read(path, &h, &res, &done, &ndone, t, &err) != FS_OK)
        return -1;
    if (done_out)
        memcpy(done_out, done, NTRIALS);
    if (res_out)
        memcpy(res_out, res, NTRIALS * sizeof *res);
    free(res), free(done);
    fs_journal_head_free(&h);
    return ndone;
}

static void test_crc(void)
{
    CHECK(fs_crc32(0, "123456789", 9) == 0xCBF43926u);
    CHECK(fs_crc32(fs_crc32(0, "1234", 4), "56789", 5) == 0xCBF43926u);
    CHECK(fs_crc32(0, "", 0) == 0);
}

/* Written, read back: every field bit for bit, nan, infinity, -0 and the escaped text included. */
static void test_round_trip(void)
{
    fs_journal_head h;
    long n, start[NREC + 1];
    char path[128];
    char *data = fixture(&h, &n, start, "whole", path);
    REQUIRE(data);
    fs_journal_tail t;
    unsigned char done[NTRIALS] = {0};
    fs_trial_result res[NTRIALS];
    CHECK(read_tail(path, &t, done, res) == NREC);
    CHECK(t.format == FS_JOURNAL_FORMAT && !t.torn && !t.line && t.good_bytes == n);
    for (int k = 0; k < NREC; k++) {
        fs_trial_result r;
        int i = record_of(k, &r);
        CHECK(done[i] == 1);
        CHECK(res[i].draw.seed == r.draw.seed && res[i].outcome == r.outcome && res[i].rule == r.rule &&
              res[i].steps == r.steps && !strcmp(res[i].failure, r.failure));
        CHECK(!memcmp(&res[i].draw.x_m, &r.draw.x_m, sizeof r.draw.x_m) &&
              !memcmp(&res[i].draw.roll_deg, &r.draw.roll_deg, sizeof(double)) &&
              !memcmp(&res[i].touchdown_s, &r.touchdown_s, sizeof(double)) &&
              !memcmp(&res[i].peak_force_N, &r.peak_force_N, sizeof(double)));
        /* a soil's numbers, after the others: NAN (rigid ground) and a print's volume and slip */
        CHECK(!memcmp(&res[i].soil_sinkage_m, &r.soil_sinkage_m, sizeof(double)) &&
              !memcmp(&res[i].print_volume_m3, &r.print_volume_m3, sizeof(double)) &&
              !memcmp(&res[i].print_slip_m, &r.print_slip_m, sizeof(double)));
    }
    CHECK(!done[4]);
    free(data);
    fs_journal_head_free(&h);
}

/* Cut at every byte offset past the header, resumed (cut back, the rest appended): the whole
 * journal's bytes; a cut inside the header is refused. */
static void test_every_cut(void)
{
    fs_journal_head h;
    long n, start[NREC + 1];
    char path[128];
    char *data = fixture(&h, &n, start, "cut", path);
    REQUIRE(data);
    int bad = 0, refused_head = 0;
    for (long cut = 0; cut <= n; cut++) {
        spit(path, data, cut);
        fs_journal_tail t;
        int got = read_tail(path, &t, NULL, NULL);
        if (cut < start[0]) {
            refused_head += got < 0;
            continue;
        }
        int k = 0; /* the whole records before the cut */
        while (k < NREC && start[k + 1] <= cut)
            k++;
        int ok = got == k && t.good_bytes == start[k] && t.torn == (cut != start[k]) && !t.line &&
                 append_from(path, &h, t.torn ? t.good_bytes : -1, k);
        long m;
        char *after = ok ? slurp(path, &m) : NULL;
        ok = ok && after && m == n && !memcmp(after, data, (size_t)n);
        free(after);
        if (!ok && bad++ < 5)
            fprintf(stderr, "  cut at byte %ld (records start at %ld): resumed journal differs\n", cut, start[k]);
    }
    CHECK(bad == 0);
    CHECK(refused_head == start[0]);
    free(data);
    fs_journal_head_free(&h);
}

/* Cuts, each followed by a resume that appends one record and is cut again, in a pseudo-random
 * sequence: the end is still the whole journal. */
static void test_cut_sequences(void)
{
    fs_journal_head h;
    long n, start[NREC + 1];
    char path[128];
    char *data = fixture(&h, &n, start, "seq", path);
    REQUIRE(data);
    unsigned seed = 12345;
    int bad = 0;
    for (int round = 0; round < 200; round++) {
        spit(path, data, start[0]);
        int k = 0; /* records in the file */
        for (int step = 0; step < 12 && k < NREC; step++) {
            fs_journal_tail t;
            k = read_tail(path, &t, NULL, NULL);
            /* resume: cut back, append record k, then the run is cut somewhere in what it wrote */
            fs_journal j;
            fs_error err;
            fs_trial_result r;
            int i = record_of(k, &r);
            if (k < 0 || fs_journal_open(&j, path, &h, t.torn ? t.good_bytes : -1, &err) != FS_OK ||
                fs_journal_append(&j, i, &r, &err) != FS_OK) {
                bad++;
                break;
            }
            fs_journal_close(&j);
            seed = seed * 1103515245u + 12345u;
            long len = start[k + 1] - start[k];
            long cut = start[k] + (long)((seed >> 8) % (unsigned)(len + 1)); /* len + 1 choices: no cut */
            if (truncate(path, cut) != 0)
                bad++;
            k = cut == start[k + 1] ? k + 1 : k;
        }
        fs_journal_tail t;
        int got = read_tail(path, &t, NULL, NULL);
        if (got >= 0 && got < NREC && !append_from(path, &h, t.torn ? t.good_bytes : -1, got))
            bad++;
        long m;
        char *after = slurp(path, &m);
        if (!after || m != n || memcmp(after, data, (size_t)n))
            bad++;
        free(after);
    }
    CHECK(bad == 0);
    free(data);
    fs_journal_head_free(&h);
}

/* Every byte of every record changed (its lowest bit flipped): caught at that record's line, the
 * records before it kept; without a tail (merge) refused with path:line. */
static void test_every_flip(void)
{
    fs_journal_head h;
    long n, start[NREC + 1];
    char path[128];
    char *data = fixture(&h, &n, start, "flip", path);
    REQUIRE(data);
    int head_lines = 8; /* magic, campaign, set, shard, trials, provenance, check: record k on line 8 + k */
    int bad = 0;
    for (long b = start[0]; b < n; b++) {
        int k = 0;
        while (start[k + 1] <= b)
            k++;
        data[b] ^= 1;
        spit(path, data, n);
        data[b] ^= 1;
        fs_journal_tail t;
        int got = read_tail(path, &t, NULL, NULL);
        int ok;
        if (b == n - 1) /* the last newline: a record cut short */
            ok = got == k && t.torn && t.good_bytes == start[k];
        else
            ok = got == k && t.line == head_lines + k && t.good_bytes == start[k] && t.why[0];
        fs_journal_head hh;
        fs_trial_result *res;
        unsigned char *done;
        int nd;
        fs_error err;
        fs_status s = fs_journal_read(path, &hh, &res, &done, &nd, NULL, &err);
        if (b != n - 1) {
            char where[160];
            snprintf(where, sizeof where, "%s:%d: ", path, head_lines + k);
            ok = ok && s == FS_BAD_INPUT && !strncmp(err.message, where, strlen(where));
        } else if (s == FS_OK) {
            free(res), free(done);
            fs_journal_head_free(&hh);
        }
        if (!ok && bad++ < 5)
            fprintf(stderr, "  byte %ld flipped: read %d records, line %d, torn %d (%s)\n", b, got, t.line, t.torn,
                    t.why);
    }
    CHECK(bad == 0);
    /* the three on record 1 (trial 0, seed 1, outcome 1, rule 2, 1501 steps, line 9): a
       digit changed, another outcome, a number made nan; each caught, record 0 kept */
    static const char *const edits[][2] = {{"1501", "1502"}, {" 1 2 1501", " 0 2 1501"}, {"1501 ", "1501 nan "}};
    for (int e = 0; e < 3; e++) {
        char *at = strstr(data + start[1], edits[e][0]);
        REQUIRE(at && at < data + start[2]);
        long len = (long)strlen(edits[e][0]), put = (long)strlen(edits[e][1]);
        if (e == 2) /* the number after the steps, whole */
            len += (long)strcspn(at + len, " ");
        long before = (long)(at - data), m = n - len + put;
        char *edited = malloc((size_t)m);
        REQUIRE(edited);
        memcpy(edited, data, (size_t)before);
        memcpy(edited + before, edits[e][1], (size_t)put);
        memcpy(edited + before + put, at + len, (size_t)(n - before - len));
        spit(path, edited, m);
        free(edited);
        fs_journal_tail t;
        CHECK(read_tail(path, &t, NULL, NULL) == 1 && t.line == head_lines + 1 && t.good_bytes == start[1]);
    }
    free(data);
    fs_journal_head_free(&h);
}

/* The header changed anywhere: refused, not resumed. */
static void test_header_flips(void)
{
    fs_journal_head h;
    long n, start[NREC + 1];
    char path[128];
    char *data = fixture(&h, &n, start, "hflip", path);
    REQUIRE(data);
    int accepted = 0;
    for (long b = 0; b < start[0]; b++) {
        data[b] ^= 1;
        spit(path, data, n);
        data[b] ^= 1;
        fs_journal_tail t;
        accepted += read_tail(path, &t, NULL, NULL) >= 0;
    }
    CHECK(accepted == 0);
    free(data);
    fs_journal_head_free(&h);
}

static const char format1[] =
    "footsim campaign journal 1\ncampaign /nowhere/small.ini\nset run.duration_s=0.15\nshard 1/1\ntrials 6\n"
    "provenance # provenance: footsim test; seeds 1 to 3; inputs small.ini=00\n"
    "1 2 3 7 1500 0x1p+0 0x0p+0 0x0p+0 0x0p+0 0x0p+0 0x1.ap+4 0x1.3p-3 0x1p-6 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p-3 "
    "0x1p+2 0x1p+2 0x1p-9 0x1p-9 |\n";

/* Format 1: read when clean (a torn last line left out); a torn line followed by more (what the
 * old append made of a cut) refused naming --fresh; the header of one without a check line is
 * fine. */
static void test_format1(void)
{
    make_dir();
    char path[128];
    path_of("old", path, sizeof path);
    spit(path, format1, (long)strlen(format1));
    fs_journal_tail t;
    unsigned char done[NTRIALS] = {0};
    fs_trial_result res1[NTRIALS];
    CHECK(read_tail(path, &t, done, res1) == 1 && t.format == 1 && done[1] && !t.torn);
    /* a record from before the soil's numbers: its 17 numbers read, the soil's NAN */
    CHECK(res1[1].steps == 1500 && res1[1].slip_m == 0x1p-9 && isnan(res1[1].soil_sinkage_m) &&
          isnan(res1[1].print_depth_m) && isnan(res1[1].print_slip_m));
    char buf[2048];
    snprintf(buf, sizeof buf, "%s3 1 3 7 15", format1);
    spit(path, buf, (long)strlen(buf));
    CHECK(read_tail(path, &t, done, NULL) == 1 && t.torn);
    snprintf(buf, sizeof buf, "%s3 1 3 7 15%s", format1, strchr(strstr(format1, "provenance"), '\n') + 1);
    spit(path, buf, (long)strlen(buf));
    fs_journal_head h;
    fs_trial_result *res;
    unsigned char *d;
    int nd;
    fs_error err;
    CHECK(fs_journal_read(path, &h, &res, &d, &nd, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, 8, "--fresh");
}

/* CR LF: named as such, not as a difference of two strings that look the same. */
static void test_crlf(void)
{
    make_dir();
    char path[128], buf[2048];
    path_of("crlf", path, sizeof path);
    size_t k = 0;
    for (const char *p = format1; *p && k + 2 < sizeof buf; p++) {
        if (*p == '\n')
            buf[k++] = '\r';
        buf[k++] = *p;
    }
    spit(path, buf, (long)k);
    fs_journal_head h;
    fs_trial_result *res;
    unsigned char *d;
    int nd;
    fs_error err;
    fs_journal_tail t;
    CHECK(fs_journal_read(path, &h, &res, &d, &nd, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, path, 1, "CR LF");
    CHECK(strstr(err.message, "--fresh") != NULL);
}

/* A FIFO, a folder, a symbolic link where the journal is: refused with their kind, never waited on
 * (an alarm fails the test instead of hanging it). */
static void test_not_regular(void)
{
    make_dir();
    char fifo[128], folder[128], link[128];
    path_of("fifo", fifo, sizeof fifo);
    path_of("folder", folder, sizeof folder);
    path_of("link", link, sizeof link);
    REQUIRE(mkfifo(fifo, 0600) == 0 && mkdir(folder, 0700) == 0);
    char target[128];
    path_of("whole", target, sizeof target);
    REQUIRE(symlink(target, link) == 0);
    alarm(20);
    fs_journal_head h, hh;
    head_of(&h);
    fs_trial_result *res;
    unsigned char *d;
    int nd;
    fs_error err;
    fs_journal_tail t;
    fs_journal j;
    CHECK(fs_journal_read(fifo, &hh, &res, &d, &nd, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, fifo, 0, "a FIFO");
    CHECK(fs_journal_open(&j, fifo, &h, -1, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, fifo, 0, "a FIFO");
    CHECK(fs_journal_read(folder, &hh, &res, &d, &nd, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, folder, 0, "a folder");
    CHECK(fs_journal_open(&j, folder, &h, -1, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, folder, 0, "a folder");
    CHECK(fs_journal_read(link, &hh, &res, &d, &nd, &t, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, link, 0, "a symbolic link");
    CHECK(fs_journal_open(&j, link, &h, -1, &err) == FS_BAD_INPUT);
    fs_check_refusal(err.message, link, 0, "a symbolic link");
    alarm(0);
    fs_journal_head_free(&h);
}

/* A trial whose worker was killed may have a second record (its second try), which replaces the
 * first; any other repeat is damage at its line. */
static void test_killed_twice(void)
{
    make_dir();
    fs_journal_head h;
    head_of(&h);
    char path[128];
    path_of("killed", path, sizeof path);
    unlink(path);
    fs_journal j;
    fs_error err;
    REQUIRE(fs_journal_open(&j, path, &h, -1, &err) == FS_OK);
    fs_trial_result r;
    record_of(0, &r);
    r.outcome = FS_KILLED, r.rule = FS_RULE_KILLED;
    CHECK(fs_journal_append(&j, 3, &r, &err) == FS_OK); /* killed once */
    record_of(1, &r);
    r.outcome = FS_KILLED, r.rule = FS_RULE_KILLED;
    CHECK(fs_journal_append(&j, 0, &r, &err) == FS_OK); /* killed ... */
    r.outcome = FS_LANDED, r.rule = 5;
    CHECK(fs_journal_append(&j, 0, &r, &err) == FS_OK); /* ... then landed */
    record_of(2, &r);
    CHECK(fs_journal_append(&j, 5, &r, &err) == FS_OK);
    fs_journal_close(&j);
    fs_journal_tail t;
    unsigned char done[NTRIALS] = {0};
    fs_trial_result res[NTRIALS];
    CHECK(read_tail(path, &t, done, res) == 3 && !t.line);
    CHECK(done[3] == 1 && res[3].outcome == FS_KILLED && done[0] == 2 && res[0].outcome == FS_LANDED);
    REQUIRE(fs_journal_open(&j, path, &h, -1, &err) == FS_OK);
    CHECK(fs_journal_append(&j, 5, &r, &err) == FS_OK); /* 5 again: not a kill's retry */
    fs_journal_close(&j);
    CHECK(read_tail(path, &t, done, res) == 3 && t.line == 12 && strstr(t.why, "repeated"));
    /* a whole record (its checksum right) of a trial the campaign has not: named, cut off there */
    REQUIRE(fs_journal_open(&j, path, &h, t.good_bytes, &err) == FS_OK);
    CHECK(fs_journal_append(&j, NTRIALS + 93, &r, &err) == FS_OK);
    fs_journal_close(&j);
    CHECK(read_tail(path, &t, done, res) == 3 && t.line == 12 && strstr(t.why, "trial 99, but the campaign has 6"));
    fs_journal_head_free(&h);
}

static void cleanup(void)
{
    if (!dir[0])
        return;
    const char *names[] = {"whole", "cut", "seq", "flip", "hflip", "old", "crlf", "fifo", "link", "killed"};
    char path[128];
    for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
        path_of(names[i], path, sizeof path);
        unlink(path);
    }
    path_of("folder", path, sizeof path);
    rmdir(path);
    rmdir(dir);
}

static void test_cleanup(void) { cleanup(); }

FS_TEST_MAIN(TEST(test_crc), TEST(test_round_trip), TEST(test_every_cut), TEST(test_cut_sequences),
             TEST(test_every_flip), TEST(test_header_flips), TEST(test_format1), TEST(test_crlf),
             TEST(test_not_regular), TEST(test_killed_twice), TEST(test_cleanup))
