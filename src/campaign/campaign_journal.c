/* campaign_journal.c: a campaign's finished trials, one checksummed line each, behind the header
 * that says what made them (fs_campaign.h): written as trials end, read back to resume a run or to
 * merge shards; a torn or damaged end is cut off before anything follows it. */
#include "footsim/campaign/fs_campaign.h"

#include "footsim/base/fs_crc.h"
#include "footsim/io/fs_input.h"
#include "footsim/io/fs_output.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAGIC "footsim campaign journal"

/* A record's numbers: NDOUBLES_OLD of them before footsim measured a soil's print, the soil's five
 * after them since (a record with the first only, from an earlier footsim, leaves those NAN: the
 * format is the same). */
enum { NDOUBLES_OLD = 17, NDOUBLES = 22 };

/* The numbers of a record, in the order they are written. */
static double *double_field(fs_trial_result *r, int k)
{
    double *const f[NDOUBLES] = {&r->draw.x_m, &r->draw.y_m, &r->draw.yaw_deg, &r->draw.pitch_deg,
                                 &r->draw.roll_deg, &r->robot_mass_kg, &r->end_time_s, &r->touchdown_s,
                                 &r->peak_tilt_deg, &r->final_tilt_deg, &r->peak_force_N, &r->impact_impulse_Ns,
                                 &r->settle_time_s, &r->mean_contacts, &r->final_contacts, &r->ankle_drop_m,
                                 &r->slip_m, &r->soil_sinkage_m, &r->print_depth_m, &r->print_area_m2,
                                 &r->print_volume_m3, &r->print_slip_m};
    return f[k];
}

static char *dup_text(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

fs_status fs_journal_head_of(const fs_campaign *c, const char *campaign_path, const char *const *sets, int nsets,
                             int shard, int nshards, fs_journal_head *h, fs_error *err)
{
    memset(h, 0, sizeof *h);
    char full[PATH_MAX];
    if (!realpath(campaign_path, full))
        return fs_fail(err, FS_BAD_INPUT, "%s: %s", campaign_path, strerror(errno));
    if (strlen(full) >= sizeof h->campaign)
        return fs_fail(err, FS_BAD_INPUT, "%.64s...: path too long", full);
    memcpy(h->campaign, full, strlen(full) + 1);
    h->shard = shard, h->nshards = nshards, h->ntrials = fs_campaign_ntrials(c);
    h->provenance = fs_campaign_provenance(c);
    for (int i = 0; h->provenance && i < nsets && i < FS_CAMPAIGN_MAX_SET; i++)
        if ((h->set[h->nset++] = dup_text(sets[i])) == NULL)
            break;
    if (!h->provenance || (h->nset && !h->set[h->nset - 1])) {
        fs_journal_head_free(h);
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    }
    return FS_OK;
}

void fs_journal_head_free(fs_journal_head *h)
{
    for (int i = 0; i < h->nset; i++)
        free(h->set[i]);
    free(h->provenance);
    h->nset = 0;
    h->provenance = NULL;
}

/* The n-th "; "-separated part of a provenance line: its start and length; 0 past the last. */
static int part_of(const char *s, int n, const char **start, size_t *len)
{
    for (int i = 0; i < n; i++) {
        const char *next = strstr(s, "; ");
        if (!next)
            return 0;
        s = next + 2;
    }
    const char *end = strstr(s, "; ");
    *start = s;
    *len = end ? (size_t)(end - s) : strlen(s);
    return 1;
}

int fs_journal_differs(const fs_journal_head *a, const fs_journal_head *b, const char *name_a, const char *name_b,
                       char *why, size_t size)
{
    if (!strcmp(a->provenance, b->provenance)) {
        if (a->ntrials == b->ntrials)
            return 0;
        snprintf(why, size, "trials: %d in %s, %d in %s", a->ntrials, name_a, b->ntrials, name_b);
        return 1;
    }
    /* the first part that differs ... */
    const char *pa = "", *pb = "";
    size_t la = 0, lb = 0;
    int n = 0;
    for (;; n++) {
        int ha = part_of(a->provenance, n, &pa, &la), hb = part_of(b->provenance, n, &pb, &lb);
        if (!ha)
            pa = "", la = 0;
        if (!hb)
            pb = "", lb = 0;
        if (!ha || !hb || la != lb || strncmp(pa, pb, la))
            break;
    }
    /* ... its name: the version (the first part), the settings, or its first word ("inputs") ... */
    char name[32];
    const char *p = la ? pa : pb;
    if (n == 0)
        snprintf(name, sizeof name, "footsim version");
    else if (!strncmp(p, "step_s", 6))
        snprintf(name, sizeof name, "settings");
    else
        snprintf(name, sizeof name, "%.*s", (int)strcspn(p, " ;"), p);
    /* ... and the first word in it that differs */
    size_t i = 0;
    while (i < la && i < lb && pa[i] == pb[i])
        i++;
    while (i > 0 && pa[i - 1] != ' ')
        i--;
    size_t ea = i, eb = i;
    while (ea < la && pa[ea] != ' ')
        ea++;
    while (eb < lb && pb[eb] != ' ')
        eb++;
    if (i > 1 && (isdigit((unsigned char)pa[i]) || pa[i] == '-' || pa[i] == '.')) /* a value: with its key */
        for (i--; i > 0 && pa[i - 1] != ' ';)
            i--;
    snprintf(why, size, "%s: '%.*s' in %s, '%.*s' in %s", name, (int)(ea - i), pa + (i < la ? i : la), name_a,
             (int)(eb - i), pb + (i < lb ? i : lb), name_b);
    return 1;
}

int fs_journal_version_only(const fs_journal_head *a, const fs_journal_head *b)
{
    const char *ra = strstr(a->provenance, "; "), *rb = strstr(b->provenance, "; ");
    return a->ntrials == b->ntrials && ra && rb && !strcmp(ra, rb) && strcmp(a->provenance, b->provenance);
}

/* ---- writing ------------------------------------------------------------------------------ */

/* Writes a header's lines, then its check line (the CRC-32 of the lines before it); 0: out of memory. */
static int print_head(FILE *f, const fs_journal_head *h)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (!m)
        return 0;
    fprintf(m, MAGIC " %d\ncampaign %s\n", FS_JOURNAL_FORMAT, h->campaign);
    for (int i = 0; i < h->nset; i++)
        fprintf(m, "set %s\n", h->set[i]);
    fprintf(m, "shard %d/%d\ntrials %d\nprovenance %s\n", h->shard, h->nshards, h->ntrials, h->provenance);
    int ok = fclose(m) == 0;
    if (ok) {
        fwrite(text, 1, len, f);
        fprintf(f, "check %08" PRIx32 "\n", fs_crc32(0, text, len));
    }
    free(text);
    return ok;
}

/* A record's payload: index, seed, outcome, rule, steps, the numbers, " |" and the failure text. */
static void print_payload(FILE *f, int index, const fs_trial_result *r)
{
    fs_trial_result copy = *r;
    fprintf(f, "%d %d %d %d %ld", index, r->draw.seed, r->outcome, r->rule, r->steps);
    for (int k = 0; k < NDOUBLES; k++)
        fprintf(f, " %a", *double_field(&copy, k));
    fputs(" |", f);
    for (const char *s = r->failure; *s && s < r->failure + sizeof r->failure; s++)
        if (*s == '\\')
            fputs("\\\\", f);
        else if (*s == '\n')
            fputs("\\n", f);
        else if (*s == '\r')
            fputs("\\r", f);
        else
            fputc(*s, f);
}

/* A whole record line, "LEN CRC PAYLOAD\n" (malloc'd, *len bytes), or NULL: out of memory. */
static char *record_line(int index, const fs_trial_result *r, size_t *len)
{
    char *payload = NULL, *line = NULL;
    size_t n = 0;
    FILE *m = open_memstream(&payload, &n);
    if (!m)
        return NULL;
    print_payload(m, index, r);
    if (fclose(m) != 0) {
        free(payload);
        return NULL;
    }
    m = open_memstream(&line, len);
    if (m) {
        fprintf(m, "%zu %08" PRIx32 " %s\n", n, fs_crc32(0, payload, n), payload);
        if (fclose(m) != 0) {
            free(line);
            line = NULL;
        }
    }
    free(payload);
    return line;
}

/* Writes index's record line to f; 0: out of memory. */
static int print_record(FILE *f, int index, const fs_trial_result *r)
{
    size_t len;
    char *line = record_line(index, r, &len);
    if (line)
        fwrite(line, 1, len, f);
    free(line);
    return line != NULL;
}

typedef struct whole_journal {
    const fs_journal_head *h;
    const fs_trial_result *results;
    const unsigned char *done;
} whole_journal;

static int fill_journal(FILE *f, const void *user)
{
    const whole_journal *x = user;
    int ok = print_head(f, x->h);
    for (int i = 0; ok && x->done && i < x->h->ntrials; i++)
        if (x->done[i])
            ok = print_record(f, i, &x->results[i]);
    return ok && !ferror(f);
}

fs_status fs_journal_write(const char *path, const fs_journal_head *h, const fs_trial_result *results,
                           const unsigned char *done, fs_error *err)
{
    const whole_journal x = {h, results, done};
    return fs_write_file(path, fill_journal, &x, err);
}

/* Refuses (FS_BAD_INPUT) a journal path that is there and is not a regular file, naming what it is. */
static fs_status check_regular(const char *path, const struct stat *st, fs_error *err)
{
    if (S_ISREG(st->st_mode))
        return FS_OK;
    return fs_fail(err, FS_BAD_INPUT, "%s: is %s, not footsim's journal (a regular file footsim made); move it "
                   "away, or start over with --fresh", path, fs_file_kind(st->st_mode));
}

fs_status fs_journal_open(fs_journal *j, const char *path, const fs_journal_head *h, long long keep_bytes,
                          fs_error *err)
{
    j->fd = -1;
    if ((size_t)snprintf(j->path, sizeof j->path, "%s", path) >= sizeof j->path)
        return fs_fail(err, FS_BAD_INPUT, "%.64s...: the journal's path is too long (at most %zu bytes)", path,
                       sizeof j->path - 1);
    struct stat st;
    fs_status s = fs_check_own_file(path, "a campaign journal", "move it away, or start over with --fresh", err);
    if (s == FS_OK && lstat(path, &st) != 0)
        s = fs_journal_write(path, h, NULL, NULL, err);
    if (s != FS_OK) {
        return s;
    }
    /* O_NONBLOCK, O_NOFOLLOW: what took its place meanwhile is refused below, never waited on */
    j->fd = open(path, O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (j->fd < 0)
        return fs_fail(err, errno == ELOOP ? FS_BAD_INPUT : FS_IO, "%s: cannot open the journal (%s)", path,
                       strerror(errno));
    if (fstat(j->fd, &st) != 0 || (s = check_regular(path, &st, err)) != FS_OK) {
        if (s == FS_OK)
            s = fs_fail(err, FS_IO, "%s: cannot open the journal (%s)", path, strerror(errno));
        fs_journal_close(j);
        return s;
    }
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET}; /* not inherited by the workers */
    if (fcntl(j->fd, F_SETLK, &fl) != 0) {
        fs_journal_close(j);
        return fs_fail(err, FS_BAD_INPUT, "%s: another footsim is writing this journal; wait for it to end", path);
    }
    /* a torn or damaged end is cut off before anything is appended: a record never follows one */
    if (keep_bytes >= 0 && keep_bytes < (long long)st.st_size &&
        (ftruncate(j->fd, (off_t)keep_bytes) != 0 || fdatasync(j->fd) != 0)) {
        s = fs_fail(err, FS_IO, "%s: cannot cut the journal's damaged end off (%s)", path, strerror(errno));
        fs_journal_close(j);
        return s;
    }
    return FS_OK;
}

fs_status fs_journal_append(fs_journal *j, int index, const fs_trial_result *r, fs_error *err)
{
    size_t len = 0;
    char *line = record_line(index, r, &len);
    if (!line)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    struct stat st;
    off_t before = fstat(j->fd, &st) == 0 ? st.st_size : -1;
    size_t done = 0;
    errno = 0;
    while (done < len) { /* one write in practice: a record is well under a page */
        ssize_t n = write(j->fd, line + done, len - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        done += (size_t)n;
    }
    free(line);
    if (done == len && fdatasync(j->fd) == 0)
        return FS_OK;
    int e = errno ? errno : EIO;
    if (done < len && before >= 0 && ftruncate(j->fd, before) == 0) /* the part written cut off again */
        (void)fdatasync(j->fd);
    return fs_fail(err, FS_IO, "%s: cannot write the journal (%s)", j->path, strerror(e));
}

void fs_journal_close(fs_journal *j)
{
    if (j->fd >= 0)
        close(j->fd);
    j->fd = -1;
}

/* ---- reading ------------------------------------------------------------------------------ */

/* Parses one record's payload (NUL-terminated) into r; its index into *index. Format 1 knows the
 * outcomes and rules up to hung and watchdog only. */
static int parse_record(const char *line, int format, int *index, fs_trial_result *r)
{
    memset(r, 0, sizeof *r);
    const char *p = line;
    char *end;
    long v[5];
    for (int k = 0; k < 5; k++) {
        errno = 0;
        v[k] = strtol(p, &end, 10);
        if (end == p || errno || *end != ' ')
            return 0;
        p = end;
    }
    int noutcomes = format == 1 ? FS_HUNG + 1 : FS_NOUTCOMES, nrules = format == 1 ? FS_RULE_WATCHDOG + 1 : FS_NRULES;
    if (v[0] < 0 || v[0] > INT_MAX || v[1] < INT_MIN || v[1] > INT_MAX)
        return 0;
    if (v[2] < 0 || v[2] >= noutcomes || v[3] < 0 || v[3] >= nrules)
        return 0;
    *index = (int)v[0];
    r->draw.seed = (int)v[1], r->outcome = (int)v[2], r->rule = (int)v[3], r->steps = v[4];
    for (int k = 0; k < NDOUBLES; k++) {
        if (k == NDOUBLES_OLD && !strncmp(p, " |", 2)) { /* an earlier footsim's record: all of it or none */
            for (; k < NDOUBLES; k++)
                *double_field(r, k) = NAN;
            break;
        }
        *double_field(r, k) = strtod(p, &end);
        if (end == p || *end != ' ')
            return 0;
        p = end;
    }
    if (strncmp(p, " |", 2))
        return 0;
    p += 2;
    size_t n = 0;
    for (; *p && n + 1 < sizeof r->failure; p++) {
        char ch = *p;
        if (ch == '\\') {
            ch = p[1] == 'n' ? '\n' : p[1] == 'r' ? '\r' : p[1] == '\\' ? '\\' : 0;
            if (!ch)
                return 0;
            p++;
        }
        r->failure[n++] = ch;
    }
    return *p == 0;
}

/* The payload of a format-2 record line (n bytes, its newline removed), or NULL with why filled:
 * "LEN CRC PAYLOAD", LEN the payload's bytes, CRC its CRC-32 in 8 hex digits. */
static const char *unframe(const char *l, size_t n, char *why, size_t size)
{
    size_t i = 0, len = 0;
    while (i < n && i < 8 && l[i] >= '0' && l[i] <= '9')
        len = len * 10 + (size_t)(l[i++] - '0');
    if (i == 0 || i >= n || l[i] != ' ' || n - i < 10 || l[i + 9] != ' ' ||
        strspn(l + i + 1, "0123456789abcdef") < 8) {
        snprintf(why, size, "not a journal record (no length and checksum in front)");
        return NULL;
    }
    uint32_t crc = (uint32_t)strtoul(l + i + 1, NULL, 16);
    const char *payload = l + i + 10;
    size_t have = n - (size_t)(payload - l);
    if (have != len || memchr(payload, 0, have)) {
        snprintf(why, size, "the record holds %zu bytes where its length says %zu", have, len);
        return NULL;
    }
    uint32_t got = fs_crc32(0, payload, have);
    if (got != crc) {
        snprintf(why, size, "the record fails its checksum (its CRC-32 is %08" PRIx32 ", the record says %08" PRIx32
                 ")", got, crc);
        return NULL;
    }
    return payload;
}

/* Reads the header line by line; returns the line number of the first record, or 0 when the header
 * is wrong (err filled). *format: the file's; *bytes: the header's length. */
static int read_head(FILE *f, const char *path, fs_journal_head *h, int *format, long long *bytes, char **line,
                     size_t *cap, fs_error *err)
{
    int no = 0;
    uint32_t crc = 0;
    *bytes = 0;
    for (;;) {
        ssize_t n = getline(line, cap, f);
        no++;
        if (n <= 0 || (*line)[n - 1] != '\n') {
            fs_fail(err, FS_BAD_INPUT, "%s:%d: the journal's header ends early; it is not a whole campaign journal "
                    "(run the campaign with --fresh to start over)", path, no);
            return 0;
        }
        char *l = *line;
        if (n >= 2 && l[n - 2] == '\r') {
            fs_fail(err, FS_BAD_INPUT, "%s:%d: the journal's lines end in CR LF (a carriage return before each "
                    "newline, as a Windows editor or transfer leaves them), not footsim's LF: restore the file as "
                    "footsim wrote it (sed -i 's/\\r$//' FILE), or start over with --fresh", path, no);
            return 0;
        }
        *bytes += n;
        l[n - 1] = 0;
        int ok = (size_t)n - 1 == strlen(l); /* no NUL inside */
        if (no == 1) {
            *format = !strcmp(l, MAGIC " 1") ? 1 : !strcmp(l, MAGIC " 2") ? 2 : 0;
            ok = ok && *format;
        } else if (!ok) {
        } else if (*format > 1 && h->provenance && !strncmp(l, "check ", 6)) {
            if (strlen(l) != 14 || strspn(l + 6, "0123456789abcdef") != 8 ||
                (uint32_t)strtoul(l + 6, NULL, 16) != crc) {
                fs_fail(err, FS_BAD_INPUT, "%s:%d: the journal's header fails its checksum: it was edited or "
                        "damaged; move it away, or start over with --fresh", path, no);
                return 0;
            }
            return no + 1;
        } else if (h->provenance) {
            ok = 0; /* nothing follows the provenance but the check line */
        } else if (!strncmp(l, "campaign ", 9))
            ok = (size_t)snprintf(h->campaign, sizeof h->campaign, "%s", l + 9) < sizeof h->campaign;
        else if (!strncmp(l, "set ", 4) && h->nset < FS_CAMPAIGN_MAX_SET)
            ok = (h->set[h->nset++] = dup_text(l + 4)) != NULL;
        else if (!strncmp(l, "shard ", 6))
            ok = sscanf(l + 6, "%d/%d", &h->shard, &h->nshards) == 2 && h->nshards >= 1 && h->shard >= 1 &&
                 h->shard <= h->nshards;
        else if (!strncmp(l, "trials ", 7))
            ok = sscanf(l + 7, "%d", &h->ntrials) == 1 && h->ntrials >= 1 && h->ntrials <= FS_CAMPAIGN_MAX_TRIALS;
        else if (!strncmp(l, "provenance ", 11)) {
            if ((h->provenance = dup_text(l + 11)) == NULL)
                ok = 0;
            else if (!h->campaign[0] || !h->nshards || !h->ntrials)
                ok = 0;
            else if (*format == 1)
                return no + 1;
        } else
            ok = 0;
        if (!ok) {
            fs_fail(err, FS_BAD_INPUT, "%s:%d: not a line of a footsim campaign journal (format %d)%s", path, no,
                    FS_JOURNAL_FORMAT, no == 1 ? "" : "; move the file away or start over with --fresh");
            return 0;
        }
        l[n - 1] = '\n';
        crc = fs_crc32(crc, l, (size_t)n);
    }
}

fs_status fs_journal_read(const char *path, fs_journal_head *h, fs_trial_result **results, unsigned char **done,
                          int *ndone, fs_journal_tail *tail, fs_error *err)
{
    memset(h, 0, sizeof *h);
    *results = NULL, *done = NULL, *ndone = 0;
    fs_journal_tail t = {0};
    /* a journal to append to: footsim's own file (a link, a folder, a FIFO named as such) */
    if (tail && fs_check_own_file(path, "a campaign journal", "move it away, or start over with --fresh", err) != FS_OK)
        return FS_BAD_INPUT;
    FILE *f = fs_open_regular(path, 1L << 40, "a campaign journal", err); /* a FIFO: refused, not waited on */
    if (!f)
        return FS_BAD_INPUT;
    char *line = NULL;
    size_t cap = 0;
    int no = read_head(f, path, h, &t.format, &t.good_bytes, &line, &cap, err);
    fs_status s = no ? FS_OK : FS_BAD_INPUT;
    int *line_of = NULL;
    if (s == FS_OK) {
        *results = malloc((size_t)h->ntrials * sizeof **results);
        *done = calloc((size_t)h->ntrials, 1);
        line_of = calloc((size_t)h->ntrials, sizeof *line_of);
        if (!*results || !*done || !line_of)
            s = fs_fail(err, FS_NO_MEMORY, "out of memory");
    }
    for (; s == FS_OK; no++) {
        ssize_t n = getline(&line, &cap, f);
        if (n <= 0)
            break;
        if (line[n - 1] != '\n') { /* a record cut short by a kill or a failed write: its trial runs again */
            t.torn = 1;
            break;
        }
        line[n - 1] = 0;
        const char *payload = t.format == 1 ? line : unframe(line, (size_t)n - 1, t.why, sizeof t.why);
        int index;
        fs_trial_result r;
        if (!payload)
            ;
        else if (t.format == 1 && ((size_t)n - 1 != strlen(line) || !parse_record(line, 1, &index, &r)))
            snprintf(t.why, sizeof t.why, "not a trial record");
        else if (t.format > 1 && !parse_record(payload, t.format, &index, &r))
            snprintf(t.why, sizeof t.why, "the record passes its checksum but is not a trial record");
        else if (index >= h->ntrials)
            snprintf(t.why, sizeof t.why, "trial %d, but the campaign has %d trials", index, h->ntrials);
        else if ((*done)[index] && ((*results)[index].outcome != FS_KILLED || (*done)[index] > 1))
            snprintf(t.why, sizeof t.why, "trial %d repeated (first on line %d)", index, line_of[index]);
        else {
            (*results)[index] = r;
            if (!(*done)[index]++)
                ++*ndone;
            line_of[index] = no;
            t.good_bytes += n;
            continue;
        }
        t.line = no;
        if (t.format == 1)
            s = fs_fail(err, FS_BAD_INPUT, "%s:%d: %s; the journal, of an earlier footsim's format without "
                        "checksums, is damaged and cannot be resumed: %s", path, no, t.why,
                        tail ? "start over with --fresh (the journal is removed)" : "make it again");
        else if (!tail)
            s = fs_fail(err, FS_BAD_INPUT, "%s:%d: %s; the file is damaged", path, no, t.why);
        break;
    }
    free(line);
    free(line_of);
    fclose(f);
    if (s != FS_OK) {
        free(*results), free(*done);
        *results = NULL, *done = NULL, *ndone = 0;
        fs_journal_head_free(h);
    } else if (tail) {
        *tail = t;
    }
    return s;
}
