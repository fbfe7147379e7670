/* campaign_journal.c: a campaign's finished trials, one line each, behind the header that says
 * what made them (fs_campaign.h): written as trials end, read back to resume a run or to merge
 * shards. */
#include "footsim/campaign/fs_campaign.h"

#include "footsim/io/fs_output.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAGIC "footsim campaign journal"

enum { NDOUBLES = 17 };

/* The numbers of a record, in the order they are written. */
static double *double_field(fs_trial_result *r, int k)
{
    double *const f[NDOUBLES] = {&r->draw.x_m, &r->draw.y_m, &r->draw.yaw_deg, &r->draw.pitch_deg,
                                 &r->draw.roll_deg, &r->robot_mass_kg, &r->end_time_s, &r->touchdown_s,
                                 &r->peak_tilt_deg, &r->final_tilt_deg, &r->peak_force_N, &r->impact_impulse_Ns,
                                 &r->settle_time_s, &r->mean_contacts, &r->final_contacts, &r->ankle_drop_m,
                                 &r->slip_m};
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

/* ---- writing ------------------------------------------------------------------------------ */

void fs_journal_print_head(FILE *f, const fs_journal_head *h)
{
    fprintf(f, MAGIC " %d\ncampaign %s\n", FS_JOURNAL_FORMAT, h->campaign);
    for (int i = 0; i < h->nset; i++)
        fprintf(f, "set %s\n", h->set[i]);
    fprintf(f, "shard %d/%d\ntrials %d\nprovenance %s\n", h->shard, h->nshards, h->ntrials, h->provenance);
}

void fs_journal_print_record(FILE *f, int index, const fs_trial_result *r)
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
    fputc('\n', f);
}

static int fill_head(FILE *f, const void *user)
{
    fs_journal_print_head(f, user);
    return 1;
}

fs_status fs_journal_open(fs_journal *j, const char *path, const fs_journal_head *h, fs_error *err)
{
    j->fd = -1;
    snprintf(j->path, sizeof j->path, "%s", path);
    struct stat st;
    fs_status s = fs_check_own_file(path, "a campaign journal", "move it away, or start over with --fresh", err);
    if (s != FS_OK)
        return s;
    if (lstat(path, &st) != 0 && (s = fs_write_file(path, fill_head, h, err)) != FS_OK)
        return s;
    j->fd = open(path, O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW);
    if (j->fd < 0)
        return fs_fail(err, FS_IO, "%s: cannot open the journal (%s)", path, strerror(errno));
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET}; /* not inherited by the workers */
    if (fcntl(j->fd, F_SETLK, &fl) != 0) {
        close(j->fd);
        j->fd = -1;
        return fs_fail(err, FS_BAD_INPUT, "%s: another footsim is writing this journal; wait for it to end", path);
    }
    return FS_OK;
}

fs_status fs_journal_append(fs_journal *j, int index, const fs_trial_result *r, fs_error *err)
{
    char *line = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&line, &len);
    if (!f)
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    fs_journal_print_record(f, index, r);
    if (fclose(f) != 0) {
        free(line);
        return fs_fail(err, FS_NO_MEMORY, "out of memory");
    }
    size_t done = 0;
    while (done < len) { /* one write in practice: a record is well under a page */
        ssize_t n = write(j->fd, line + done, len - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        done += (size_t)n;
    }
    free(line);
    if (done < len || fdatasync(j->fd) != 0)
        return fs_fail(err, FS_IO, "%s: cannot write the journal (%s)", j->path,
                       errno == ENOSPC ? "No space left on device" : strerror(errno ? errno : EIO));
    return FS_OK;
}

void fs_journal_close(fs_journal *j)
{
    if (j->fd >= 0)
        close(j->fd);
    j->fd = -1;
}

/* ---- reading ------------------------------------------------------------------------------ */

/* Parses one record line (without its newline) into r; its index into *index. */
static int parse_record(char *line, int *index, fs_trial_result *r)
{
    memset(r, 0, sizeof *r);
    char *p = line, *end;
    long v[5];
    for (int k = 0; k < 5; k++) {
        errno = 0;
        v[k] = strtol(p, &end, 10);
        if (end == p || errno || *end != ' ')
            return 0;
        p = end;
    }
    if (v[0] < 0 || v[0] > INT_MAX || v[1] < INT_MIN || v[1] > INT_MAX)
        return 0;
    if (v[2] < 0 || v[2] >= FS_NOUTCOMES || v[3] < 0 || v[3] >= FS_NRULES) /* hung and watchdog included */
        return 0;
    *index = (int)v[0];
    r->draw.seed = (int)v[1], r->outcome = (int)v[2], r->rule = (int)v[3], r->steps = v[4];
    for (int k = 0; k < NDOUBLES; k++) {
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

/* Reads the header line by line; returns the line number of the first record, or 0 when the header
 * is wrong (err filled). */
static int read_head(FILE *f, const char *path, fs_journal_head *h, char **line, size_t *cap, fs_error *err)
{
    int no = 0;
    for (;;) {
        ssize_t n = getline(line, cap, f);
        no++;
        if (n <= 0 || (*line)[n - 1] != '\n') {
            fs_fail(err, FS_BAD_INPUT, "%s:%d: the journal's header ends early; it is not a whole campaign journal "
                    "(run the campaign with --fresh to start over)", path, no);
            return 0;
        }
        char *l = *line;
        l[n - 1] = 0;
        int ok = 1;
        if (no == 1) {
            int format = 0;
            ok = !strncmp(l, MAGIC " ", strlen(MAGIC) + 1) && sscanf(l + strlen(MAGIC) + 1, "%d", &format) == 1 &&
                 format == FS_JOURNAL_FORMAT;
        } else if (!strncmp(l, "campaign ", 9))
            snprintf(h->campaign, sizeof h->campaign, "%s", l + 9);
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
            else
                return no + 1;
        } else
            ok = 0;
        if (!ok) {
            fs_fail(err, FS_BAD_INPUT, "%s:%d: not a line of a footsim campaign journal (format %d)%s", path, no,
                    FS_JOURNAL_FORMAT, no == 1 ? "" : "; move the file away or start over with --fresh");
            return 0;
        }
    }
}

fs_status fs_journal_read(const char *path, fs_journal_head *h, fs_trial_result **results, unsigned char **done,
                          int *ndone, fs_error *err)
{
    memset(h, 0, sizeof *h);
    *results = NULL, *done = NULL, *ndone = 0;
    if (fs_check_own_file(path, "a campaign journal", "move it away (a campaign starts over with --fresh)", err) != FS_OK)
        return FS_BAD_INPUT;
    FILE *f = fopen(path, "r");
    if (!f)
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot read (%s)", path, strerror(errno));
    char *line = NULL;
    size_t cap = 0;
    int no = read_head(f, path, h, &line, &cap, err);
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
        if (n <= 0 || line[n - 1] != '\n')
            break; /* the end, or a record cut short by a kill: its trial runs again */
        line[n - 1] = 0;
        int index;
        fs_trial_result r;
        if (!parse_record(line, &index, &r))
            s = fs_fail(err, FS_BAD_INPUT, "%s:%d: not a trial record; the journal is damaged: move it away or "
                        "start over with --fresh", path, no);
        else if (index >= h->ntrials)
            s = fs_fail(err, FS_BAD_INPUT, "%s:%d: trial %d, but the campaign has %d trials", path, no, index,
                        h->ntrials);
        else if ((*done)[index])
            s = fs_fail(err, FS_BAD_INPUT, "%s:%d: trial %d repeated (first on line %d)", path, no, index,
                        line_of[index]);
        else {
            (*results)[index] = r;
            (*done)[index] = 1;
            line_of[index] = no;
            ++*ndone;
        }
    }
    free(line);
    free(line_of);
    fclose(f);
    if (s != FS_OK) {
        free(*results), free(*done);
        *results = NULL, *done = NULL;
        fs_journal_head_free(h);
    }
    return s;
}
