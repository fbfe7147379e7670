/* io_config.c: INI files read with inih into entries with line numbers, bound through a schema. */
#include "footsim/io/fs_config.h"

#include "footsim/base/fs_path.h"

#include "footsim/io/fs_input.h"
#include "footsim/base/fs_hash.h"

#include <ini.h>
#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---- reading ---------------------------------------------------------------------------- */

/* The bytes of a file are checked before inih sees them (a NUL would end a line early and hide
 * its tail, a bare CR would join every line into one, text after ']' would be dropped), then fed
 * to inih line by line from memory. Entries are found through a hash index over (section, key),
 * rebuilt whenever a public function starts (callers may edit or remove entries), so reading
 * and binding are linear in the number of keys. */

typedef struct reader {
    const char *text, *end, *pos;
    fs_config *cfg;
    int line;       /* line most recently handed to inih */
    int section_line; /* line of the most recent [section] header, 0 before the first */
    int long_line;  /* first line longer than the buffer, or 0 */
    fs_error *err;
    fs_status status;
} reader;

/* inih's line source over memory: counts lines so the handler knows where each key stands. */
static char *read_line(char *buf, int size, void *stream)
{
    reader *r = stream;
    if (r->pos >= r->end)
        return NULL;
    r->line++;
    const char *nl = memchr(r->pos, '\n', (size_t)(r->end - r->pos));
    const char *stop = nl ? nl + 1 : r->end;
    size_t n = (size_t)(stop - r->pos);
    if (n > (size_t)size - 1) {
        if (!r->long_line)
            r->long_line = r->line; /* the rest is skipped; the line is refused after parsing */
        n = (size_t)size - 1;
    }
    memcpy(buf, r->pos, n);
    buf[n] = 0;
    r->pos = stop;
    const char *c = buf + strspn(buf, " \t");
    if (*c == '[') /* check_text has made sure a '[' line is a section header */
        r->section_line = r->line;
    return buf;
}

static unsigned hash_key(const char *section, const char *name)
{
    unsigned h = 2166136261u;
    for (const char *p = section; *p; p++)
        h = (h ^ (unsigned char)*p) * 16777619u;
    h = (h ^ 0xff) * 16777619u;
    for (const char *p = name; *p; p++)
        h = (h ^ (unsigned char)*p) * 16777619u;
    return h;
}

static void index_insert(fs_config *cfg, int i)
{
    unsigned mask = (unsigned)cfg->nslots - 1, h = hash_key(cfg->entries[i].section, cfg->entries[i].name) & mask;
    while (cfg->slots[h] >= 0)
        h = (h + 1) & mask;
    cfg->slots[h] = i;
}

/* Rebuilds the index for the entries as they are now, at a load factor of at most one half. */
static int index_rebuild(fs_config *cfg, int want)
{
    if (want == 0 && cfg->count == 0) { /* nothing to find: no index (a config built by hand owns nothing) */
        free(cfg->slots);
        cfg->slots = NULL;
        cfg->nslots = 0;
        return 1;
    }
    int n = 16;
    while (n < 2 * want)
        n *= 2;
    if (n != cfg->nslots) {
        int *s = realloc(cfg->slots, (size_t)n * sizeof *s);
        if (!s)
            return 0;
        cfg->slots = s;
        cfg->nslots = n;
    }
    for (int i = 0; i < n; i++)
        cfg->slots[i] = -1;
    for (int i = 0; i < cfg->count; i++)
        index_insert(cfg, i);
    return 1;
}

static fs_entry *find_entry(fs_config *cfg, const char *section, const char *name)
{
    if (!cfg->nslots)
        return NULL;
    unsigned mask = (unsigned)cfg->nslots - 1;
    for (unsigned h = hash_key(section, name) & mask; cfg->slots[h] >= 0; h = (h + 1) & mask) {
        fs_entry *e = &cfg->entries[cfg->slots[h]];
        if (!strcmp(e->section, section) && !strcmp(e->name, name))
            return e;
    }
    return NULL;
}

static fs_entry *add_entry(fs_config *cfg)
{
    if (cfg->count == cfg->capacity) {
        int cap = cfg->capacity ? 2 * cfg->capacity : 32;
        fs_entry *e = realloc(cfg->entries, (size_t)cap * sizeof *e);
        if (!e)
            return NULL;
        cfg->entries = e;
        cfg->capacity = cap;
    }
    if (2 * (cfg->count + 1) > cfg->nslots && !index_rebuild(cfg, cfg->count + 1))
        return NULL;
    fs_entry *e = &cfg->entries[cfg->count++];
    memset(e, 0, sizeof *e);
    return e;
}

static int copy_text(char *dst, size_t size, const char *src)
{
    size_t n = strlen(src);
    if (n >= size)
        return 0;
    memcpy(dst, src, n + 1);
    return 1;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    reader *r = user;
    if (r->status != FS_OK) /* inih reads on after a refusal: the first one stands */
        return 0;
    fs_entry *old = find_entry(r->cfg, section, name);
    if (old) {
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: [%s] %s is given twice (first on line %d); keep one",
                            r->cfg->path, r->line, section, name, old->line);
        return 0;
    }
    if (r->cfg->count >= FS_CONFIG_MAX_KEYS) {
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: more than %d keys; a footsim file has at most %d",
                            r->cfg->path, r->line, FS_CONFIG_MAX_KEYS, FS_CONFIG_MAX_KEYS);
        return 0;
    }
    fs_entry *e = add_entry(r->cfg);
    if (!e) {
        r->status = fs_fail(r->err, FS_NO_MEMORY, "%s:%d: out of memory", r->cfg->path, r->line);
        return 0;
    }
    if (!copy_text(e->section, sizeof e->section, section) || !copy_text(e->name, sizeof e->name, name) ||
        !copy_text(e->value, sizeof e->value, value)) {
        r->cfg->count--;
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: section, key or value too long (at most %d characters)",
                            r->cfg->path, r->line, FS_NAME_MAX - 1);
        return 0;
    }
    e->line = r->line;
    e->section_line = r->section_line;
    index_insert(r->cfg, r->cfg->count - 1);
    return 1;
}

static int blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/* Checks the bytes and the shape of every line before inih reads them: no NUL, no bare CR, nothing
 * after a section's ']', no section without keys, at least one key. */
static fs_status check_text(const char *path, const char *text, size_t len, fs_error *err)
{
    int line = 1, keys = 0, section_line = 0, section_keys = 0;
    char section[FS_NAME_MAX] = "";
    for (size_t i = 0; i < len;) {
        size_t end = i;
        while (end < len && text[end] != '\n') {
            if (text[end] == 0)
                return fs_fail(err, FS_BAD_INPUT, "%s:%d: a NUL byte (column %zu); an INI file is text: remove it",
                               path, line, end - i + 1);
            if (text[end] == '\r' && !(end + 1 < len && text[end + 1] == '\n'))
                return fs_fail(err, FS_BAD_INPUT, "%s:%d: a carriage return that does not end a line (old Mac line "
                               "ends?); save the file with LF or CRLF line ends", path, line);
            end++;
        }
        size_t p = i;
        while (p < end && blank(text[p]))
            p++;
        if (p < end && text[p] == '[') {
            const char *close = memchr(text + p, ']', end - p);
            if (!close)
                return fs_fail(err, FS_BAD_INPUT, "%s:%d: a section line without ']'; write [section]", path, line);
            size_t q = (size_t)(close - text) + 1;
            while (q < end && blank(text[q]))
                q++;
            if (q < end && text[q] != ';' && text[q] != '#')
                return fs_fail(err, FS_BAD_INPUT, "%s:%d: text after ']' ('%.*s'); put each key on a line of its own "
                               "below [section]", path, line, (int)(end - q > 40 ? 40 : end - q), text + q);
            if (section_line && section_keys == 0)
                return fs_fail(err, FS_BAD_INPUT, "%s:%d: [%s] has no keys (an empty section, or a misspelt name); "
                               "give its keys, or remove it", path, section_line, section);
            snprintf(section, sizeof section, "%.*s", (int)(close - (text + p) - 1), text + p + 1);
            section_line = line, section_keys = 0;
        } else if (p < end && text[p] != ';' && text[p] != '#') {
            keys++, section_keys++;
        }
        i = end + 1;
        line++;
    }
    if (section_line && section_keys == 0)
        return fs_fail(err, FS_BAD_INPUT, "%s:%d: [%s] has no keys (an empty section, or a misspelt name); give its "
                       "keys, or remove it", path, section_line, section);
    if (keys == 0)
        return fs_fail(err, FS_BAD_INPUT, "%s:1: no keys (the file is empty, or blank, or only comments); give the "
                       "file's [sections] and keys", path);
    return FS_OK;
}

fs_status fs_config_load(fs_config *cfg, const char *path, fs_error *err)
{
    memset(cfg, 0, sizeof *cfg);
    fs_status fits = fs_path_format(cfg->path, sizeof cfg->path, "", err, "%s", path);
    if (fits != FS_OK) /* "PATH: the path is N characters long; footsim takes at most M here: ..." */
        return fits;
    char *text;
    size_t len;
    fs_status s = fs_read_regular(path, FS_CONFIG_MAX_BYTES, "an .ini file", &text, &len, err);
    if (s != FS_OK)
        return s;
    const char *start = text;
    if (len >= 3 && !memcmp(text, "\xEF\xBB\xBF", 3)) /* a UTF-8 byte order mark: skipped */
        start += 3;
    s = check_text(path, start, len - (size_t)(start - text), err);
    reader r = {.text = start, .end = text + len, .pos = start, .cfg = cfg, .err = err, .status = FS_OK};
    int bad = 0;
    if (s == FS_OK) {
        /* A continuation line would silently join two values: refuse it as a syntax error. */
        ini_allow_multiline = 0;
        bad = ini_parse_stream(read_line, &r, on_key, &r);
    }
    free(text);
    if (s == FS_OK && r.status != FS_OK)
        s = r.status;
    else if (s == FS_OK && r.long_line && (bad == 0 || r.long_line <= bad))
        s = fs_fail(err, FS_BAD_INPUT, "%s:%d: line longer than %d characters; shorten it", path, r.long_line,
                    fs_config_max_line());
    else if (s == FS_OK && bad > 0)
        s = fs_fail(err, FS_BAD_INPUT, "%s:%d: not an INI line; write `[section]`, `key = value` or a `;` comment",
                    path, bad);
    else if (s == FS_OK && bad < 0)
        s = fs_fail(err, FS_BAD_INPUT, "%s: cannot be read", path);
    if (s != FS_OK)
        fs_config_free(cfg);
    return s;
}

fs_status fs_config_override(fs_config *cfg, const char *assignment, fs_error *err)
{
    const char *dot = strchr(assignment, '.');
    const char *eq = strchr(assignment, '=');
    if (!dot || !eq || dot > eq || dot == assignment || eq == dot + 1)
        return fs_fail(err, FS_BAD_INPUT, "--set %s: write it as section.key=value, e.g. --set springs.k_d1_N_per_m=9000",
                       assignment);
    char section[FS_NAME_MAX], name[FS_NAME_MAX];
    size_t ns = (size_t)(dot - assignment), nn = (size_t)(eq - dot - 1);
    if (ns >= sizeof section || nn >= sizeof name || strlen(eq + 1) >= FS_VALUE_MAX)
        return fs_fail(err, FS_BAD_INPUT, "--set %s: too long", assignment);
    memcpy(section, assignment, ns);
    section[ns] = 0;
    memcpy(name, dot + 1, nn);
    name[nn] = 0;
    if (!index_rebuild(cfg, cfg->count + 1))
        return fs_fail(err, FS_NO_MEMORY, "--set %s: out of memory", assignment);
    fs_entry *e = find_entry(cfg, section, name);
    if (!e) {
        e = add_entry(cfg);
        if (!e)
            return fs_fail(err, FS_NO_MEMORY, "--set %s: out of memory", assignment);
        strcpy(e->section, section);
        strcpy(e->name, name);
    }
    strcpy(e->value, eq + 1);
    e->line = 0;
    index_rebuild(cfg, cfg->count);
    return FS_OK;
}

void fs_config_free(fs_config *cfg)
{
    free(cfg->entries);
    free(cfg->slots);
    cfg->entries = NULL;
    cfg->slots = NULL;
    cfg->count = cfg->capacity = cfg->nslots = 0;
}

void fs_config_dir(const fs_config *cfg, char *buf, size_t size)
{
    const char *slash = strrchr(cfg->path, '/');
    if (!slash)
        snprintf(buf, size, ".");
    else
        snprintf(buf, size, "%.*s", (int)(slash - cfg->path) > 0 ? (int)(slash - cfg->path) : 1, cfg->path);
}

static const char *where_entry(const fs_config *cfg, const fs_entry *e, char *buf, size_t size)
{
    if (e->line > 0)
        snprintf(buf, size, "%s:%d", cfg->path, e->line);
    else
        snprintf(buf, size, "--set %s.%s", e->section, e->name);
    return buf;
}

const char *fs_config_where_section(const fs_config *cfg, const char *section, char *buf, size_t size)
{
    const fs_entry *first = NULL;
    for (int i = 0; cfg && i < cfg->count; i++) {
        const fs_entry *e = &cfg->entries[i];
        if (strcmp(e->section, section))
            continue;
        if (!first || (e->line > 0 && (first->line == 0 || e->section_line < first->section_line)))
            first = e;
    }
    if (!first)
        return NULL;
    if (first->line > 0)
        snprintf(buf, size, "%s:%d", cfg->path, first->section_line);
    else
        snprintf(buf, size, "--set %s.%s", first->section, first->name);
    return buf;
}

int fs_config_has(const fs_config *cfg, const char *section, const char *name)
{
    for (int i = 0; i < cfg->count; i++)
        if (!strcmp(cfg->entries[i].section, section) && (!name || !strcmp(cfg->entries[i].name, name)))
            return 1;
    return 0;
}

const char *fs_config_where(const fs_config *cfg, const char *section, const char *name, char *buf, size_t size)
{
    if (!cfg) { /* a definition edited in code, compiled without its file */
        snprintf(buf, size, "[%s] %s (set in code)", section, name);
        return buf;
    }
    const fs_entry *e = NULL;
    for (int i = 0; i < cfg->count && !e; i++) /* cfg is const here: no index; a message is rare */
        if (!strcmp(cfg->entries[i].section, section) && !strcmp(cfg->entries[i].name, name))
            e = &cfg->entries[i];
    if (e)
        return where_entry(cfg, e, buf, size);
    snprintf(buf, size, "%s ([%s] %s, default)", cfg->path, section, name);
    return buf;
}

/* ---- binding ---------------------------------------------------------------------------- */

static const char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    char *end = s + strlen(s);
    while (end > s && (end[-1] == ' ' || end[-1] == '\t'))
        *--end = 0;
    return s;
}

fs_number fs_parse_number(const char *text, double *out)
{
    char buf[FS_VALUE_MAX];
    snprintf(buf, sizeof buf, "%s", text);
    const char *s = trim(buf);
    if (!*s)
        return FS_NUMBER_BAD;
    const char *digits = s + (*s == '+' || *s == '-');
    if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) /* strtod reads C's hex floats: 0x1P-1074 */
        return FS_NUMBER_HEX;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end)
        return FS_NUMBER_BAD;
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1))
        return FS_NUMBER_BAD;
    if ((v != 0 && fabs(v) < DBL_MIN) || (errno == ERANGE && fabs(v) <= 1)) /* underflow: below DBL_MIN */
        return FS_NUMBER_SUBNORMAL;
    *out = v == 0 ? 0.0 : v; /* -0 is 0: "-0.0 kg" means nothing */
    return FS_NUMBER_OK;
}

const char *fs_number_problem(fs_number n)
{
    switch (n) {
    case FS_NUMBER_HEX: return "is hexadecimal; write it in decimal";
    case FS_NUMBER_SUBNORMAL: return "is below the smallest normal double (2.2e-308); write 0 or a larger value";
    default: return "is not a finite number";
    }
}

int fs_list_split(char *list, char **item, int max, int *empty_at)
{
    if (!*trim(list))
        return 0;
    int n = 0;
    for (char *p = list;; n++) {
        char *comma = strchr(p, ',');
        if (comma)
            *comma = 0;
        char *word = (char *)trim(p);
        if (!*word) {
            *empty_at = n + 1;
            return -1;
        }
        if (n == max)
            return -2;
        item[n] = word;
        if (!comma)
            return n + 1;
        p = comma + 1;
    }
}

int fs_list_element(const char *text, int count)
{
    if (text[0] != '[' || !isdigit((unsigned char)text[1]))
        return -1;
    long i = 0;
    const char *p = text + 1;
    for (; isdigit((unsigned char)*p); p++)
        if ((i = 10 * i + (*p - '0')) > 1000000)
            return -2;
    if (p[0] != ']' || p[1])
        return -1;
    return i >= 1 && i <= count ? (int)i - 1 : -2;
}

/* "[min, max]", "(min, max]", "[min, max)" as the key's flags say */
static void range_text(const fs_key *k, char *buf, size_t size)
{
    snprintf(buf, size, "%s%g, %g%s", (k->flags & FS_KEY_OPEN_MIN) ? "(" : "[", k->min, k->max,
             (k->flags & FS_KEY_OPEN_MAX) ? ")" : "]");
}

static void describe_range(const fs_key *k, char *buf, size_t size)
{
    char r[64];
    range_text(k, r, sizeof r);
    snprintf(buf, size, "%s%s%s", r, k->unit && *k->unit ? " " : "", k->unit ? k->unit : "");
}

static int in_range(const fs_key *k, double v)
{
    if (k->flags & FS_KEY_OPEN_MIN ? v <= k->min : v < k->min)
        return 0;
    return k->flags & FS_KEY_OPEN_MAX ? v < k->max : v <= k->max;
}

static fs_status bad_value(fs_error *err, const char *where, const fs_key *k, const char *value, const char *why)
{
    char range[96];
    describe_range(k, range, sizeof range);
    switch (k->type) {
    case FS_KEY_CHOICE:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; allowed: %s", where, k->name, value, why, k->choices);
    case FS_KEY_LIST:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; allowed: %d comma-separated numbers, each in %s", where,
                       k->name, value, why, k->count, range);
    case FS_KEY_SERIES:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; allowed: up to %d comma-separated numbers, each in %s",
                       where, k->name, value, why, k->count, range);
    case FS_KEY_PATH:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; give a path relative to the file's folder", where,
                       k->name, value, why);
    default:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; allowed: %s%s in %s", where, k->name, value, why,
                       k->type == FS_KEY_INTEGER ? "a whole number" : "a finite number", "", range);
    }
}

/* The data folders a file's relative path falls back to (fs_config_data_folders), or NULL. */
static const char *const *data_folders;

void fs_config_data_folders(const char *const *folders) { data_folders = folders; }

static int regular_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Where a relative path that is not beside its file is found: from the current folder when it was
 * given on the command line and is there; else under each data folder D, as D/scenarios/rel,
 * D/terrains/rel or D/rel (the shipped files' paths are relative to those folders). 0: nowhere. */
static int find_path(const char *rel, int from_command_line, char *out, size_t size)
{
    if (from_command_line && regular_file(rel)) {
        char real[PATH_MAX];
        if (!realpath(rel, real) || strlen(real) >= size)
            return 0;
        snprintf(out, size, "%s", real);
        return 1;
    }
    static const char *const subs[] = {"scenarios/", "terrains/", ""};
    for (int i = 0; data_folders && data_folders[i]; i++)
        for (size_t k = 0; k < sizeof subs / sizeof *subs; k++) {
            int n = snprintf(out, size, "%s/%s%s", data_folders[i], subs[k], rel);
            if (n > 0 && (size_t)n < size && regular_file(out))
                return 1;
        }
    return 0;
}

static fs_status bind_value(const fs_key *k, const char *value, const char *where, const char *dir,
                            int from_command_line, void *def, fs_error *err)
{
    char *slot = (char *)def + k->offset;
    double v;
    switch (k->type) {
    case FS_KEY_NUMBER: {
        fs_number n = fs_parse_number(value, &v);
        if (n != FS_NUMBER_OK)
            return bad_value(err, where, k, value, fs_number_problem(n));
        if (!in_range(k, v))
            return bad_value(err, where, k, value, "is out of range");
        *(double *)slot = v;
        return FS_OK;
    }
    case FS_KEY_INTEGER: {
        fs_number n = fs_parse_number(value, &v);
        if (n == FS_NUMBER_HEX)
            return bad_value(err, where, k, value, fs_number_problem(n));
        if (n != FS_NUMBER_OK || v != floor(v))
            return bad_value(err, where, k, value, "is not a whole number");
        if (!in_range(k, v))
            return bad_value(err, where, k, value, "is out of range");
        *(int *)slot = (int)v;
        return FS_OK;
    }
    case FS_KEY_LIST:
    case FS_KEY_SERIES: {
        char buf[FS_VALUE_MAX];
        snprintf(buf, sizeof buf, "%s", value);
        double vals[FS_SERIES_MAX];
        char *tok[FS_SERIES_MAX], why[128];
        int most = k->type == FS_KEY_LIST ? FS_LIST_MAX : FS_SERIES_MAX;
        int empty = 0, n = fs_list_split(buf, tok, k->count < most ? k->count : most, &empty);
        if (n == -1) {
            snprintf(why, sizeof why, "has an empty value (value %d: two commas in a row, or a comma first or last)",
                     empty);
            return bad_value(err, where, k, value, why);
        }
        if (n == -2)
            return bad_value(err, where, k, value, "has too many values");
        for (int i = 0; i < n; i++) {
            fs_number num = fs_parse_number(tok[i], &vals[i]);
            if (num != FS_NUMBER_OK) {
                snprintf(why, sizeof why, "has a value that %s", fs_number_problem(num));
                return bad_value(err, where, k, value, why);
            }
            if (!in_range(k, vals[i]))
                return bad_value(err, where, k, value, "has a value out of range");
        }
        if (k->type == FS_KEY_SERIES) {
            fs_series *series = (fs_series *)(void *)slot;
            series->n = n;
            memcpy(series->v, vals, (size_t)n * sizeof *vals);
            return FS_OK;
        }
        if (n != k->count)
            return bad_value(err, where, k, value, "has too few values");
        memcpy(slot, vals, (size_t)n * sizeof *vals);
        return FS_OK;
    }
    case FS_KEY_CHOICE: {
        char buf[FS_VALUE_MAX];
        snprintf(buf, sizeof buf, "%s", value);
        const char *word = trim(buf);
        size_t len = strlen(word);
        int index = 0;
        for (const char *c = k->choices; *c; index++) {
            const char *bar = strchr(c, '|');
            size_t n = bar ? (size_t)(bar - c) : strlen(c);
            if (n == len && !strncmp(c, word, n)) {
                *(int *)slot = index;
                return FS_OK;
            }
            if (!bar)
                break;
            c = bar + 1;
        }
        return bad_value(err, where, k, value, "is not one of the choices");
    }
    case FS_KEY_PATH: {
        char buf[FS_VALUE_MAX];
        snprintf(buf, sizeof buf, "%s", value);
        const char *rel = trim(buf);
        if (!*rel)
            return bad_value(err, where, k, value, "is empty");
        char full[FS_PATH_MAX];
        int n = rel[0] == '/' ? snprintf(full, sizeof full, "%s", rel) : snprintf(full, sizeof full, "%s/%s", dir, rel);
        if (n < 0 || (size_t)n >= sizeof full)
            return bad_value(err, where, k, value, "is too long");
        /* a relative path given on the command line: from the current folder first, as a command-
           line path; then (and for a file's own paths) the file's folder, then the data folders */
        char found[FS_PATH_MAX];
        struct stat st;
        if (rel[0] != '/' && ((from_command_line && regular_file(rel)) || stat(full, &st) != 0) &&
            find_path(rel, from_command_line, found, sizeof found)) {
            n = (int)strlen(found);
            memcpy(full, found, (size_t)n + 1);
        }
        /* the system's reason: no such file, a folder, a FIFO, a symbolic link loop, no permission */
        if (stat(full, &st) != 0)
            return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s': %s (looked for %s%s%s); give a path relative to %s%s", where,
                           k->name, rel, errno == ENOENT ? "no such file" : strerror(errno), from_command_line ? rel : "",
                           from_command_line ? ", then " : "", full, from_command_line ? "the current folder or " : "", dir);
        if (!S_ISREG(st.st_mode))
            return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s': %s is %s, not a file; give a file's path", where, k->name,
                           rel, full, S_ISDIR(st.st_mode) ? "a folder" : S_ISFIFO(st.st_mode) ? "a FIFO"
                           : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device" : "not a regular file");
        memcpy(slot, full, (size_t)n + 1);
        return FS_OK;
    }
    }
    return FS_OK;
}

static int section_known(const fs_key *schema, int nkeys, const char *section)
{
    for (int i = 0; i < nkeys; i++)
        if (!strcmp(schema[i].section, section))
            return 1;
    return 0;
}

/* Lists the names a section allows (or the sections, when section is NULL) into buf. */
static void list_known(const fs_key *schema, int nkeys, const char *section, char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < nkeys && used < size; i++) {
        const char *word = section ? schema[i].name : schema[i].section;
        if (section && strcmp(schema[i].section, section))
            continue;
        if (!section && i > 0 && section_known(schema, i, word))
            continue;
        int n = snprintf(buf + used, size - used, "%s%s", used ? ", " : "", word);
        if (n < 0)
            break;
        used += (size_t)n;
    }
}

int fs_config_max_line(void) { return ini_max_line - 3; }

fs_status fs_config_number(const fs_key *k, const char *value, const char *where, double *out, fs_error *err)
{
    if (k->type != FS_KEY_NUMBER && k->type != FS_KEY_INTEGER)
        return fs_fail(err, FS_BAD_INPUT, "%s: [%s] %s is not a number key", where, k->section, k->name);
    fs_key at_start = *k;
    at_start.offset = 0;
    union { double number; int integer; } slot;
    fs_status s = bind_value(&at_start, value, where, "", 0, &slot, err);
    if (s == FS_OK)
        *out = k->type == FS_KEY_INTEGER ? slot.integer : slot.number;
    return s;
}

fs_status fs_config_check(const fs_key *schema, int nkeys, const void *def, const char *what, fs_error *err)
{
    for (int i = 0; i < nkeys; i++) {
        const fs_key *k = &schema[i];
        const char *slot = (const char *)def + k->offset;
        int n = k->type == FS_KEY_LIST ? k->count : 1, whole = k->type != FS_KEY_NUMBER && k->type != FS_KEY_LIST;
        if (k->type == FS_KEY_PATH)
            continue;
        const double *values = (const double *)(const void *)slot;
        if (k->type == FS_KEY_SERIES) {
            const fs_series *series = (const fs_series *)(const void *)slot;
            if (series->n < 0 || series->n > k->count || series->n > FS_SERIES_MAX)
                return fs_fail(err, FS_BAD_INPUT, "%s: [%s] %s has %d values (0 to %d allowed)", what, k->section,
                               k->name, series->n, k->count);
            n = series->n;
            values = series->v;
            whole = 0;
        }
        for (int j = 0; j < n; j++) {
            double v = whole ? *(const int *)slot : values[j];
            int nchoices = 1;
            for (const char *c = k->choices ? k->choices : ""; *c; c++)
                nchoices += *c == '|';
            int ok = k->type == FS_KEY_CHOICE ? v >= 0 && v < nchoices : isfinite(v) && in_range(k, v);
            if (!ok && k->type == FS_KEY_CHOICE)
                return fs_fail(err, FS_BAD_INPUT, "%s: [%s] %s = %.17g is out of range; allowed: %s", what, k->section,
                               k->name, v, k->choices);
            if (!ok) {
                char range[96];
                describe_range(k, range, sizeof range);
                return fs_fail(err, FS_BAD_INPUT, "%s: [%s] %s = %.17g is out of range; allowed %s", what, k->section,
                               k->name, v, range);
            }
        }
    }
    return FS_OK;
}

/* The elements of list key k given one by one ("name[i] = v", fs_list_element), each set after the
 * whole list by the key's own rules; a bad index refused with its line and the valid range. */
static fs_status bind_elements(fs_config *cfg, const fs_key *k, void *def, fs_error *err)
{
    size_t len = strlen(k->name);
    for (int i = 0; i < cfg->count; i++) {
        fs_entry *e = &cfg->entries[i];
        if (strcmp(e->section, k->section) || strncmp(e->name, k->name, len) || e->name[len] != '[')
            continue;
        char where[FS_PATH_MAX + 80];
        where_entry(cfg, e, where, sizeof where);
        int index = fs_list_element(e->name + len, k->count);
        if (index < 0)
            return fs_fail(err, FS_BAD_INPUT, "%s: %s: %s; give one of %s[1] to %s[%d] (elements are counted from 1)",
                           where, e->name, index == -2 ? "no such element" : "not an element's name", k->name,
                           k->name, k->count);
        fs_key one = *k; /* the element: a number with the list's range */
        one.name = e->name;
        one.type = FS_KEY_NUMBER;
        one.offset = k->offset + (size_t)index * sizeof(double);
        e->used = 1;
        fs_status s = bind_value(&one, e->value, where, "", 0, def, err);
        if (s != FS_OK)
            return s;
    }
    return FS_OK;
}

fs_status fs_config_bind(fs_config *cfg, const fs_key *schema, int nkeys, void *def, fs_error *err)
{
    char dir[FS_PATH_MAX], where[FS_PATH_MAX + 80];
    fs_config_dir(cfg, dir, sizeof dir);
    if (!index_rebuild(cfg, cfg->count)) /* entries may have been edited since the last look */
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory", cfg->path);
    for (int i = 0; i < nkeys; i++) {
        const fs_key *k = &schema[i];
        fs_entry *e = find_entry(cfg, k->section, k->name);
        const char *value = e ? e->value : k->fallback;
        if (!e && k->type == FS_KEY_PATH && !*k->fallback) {
            ((char *)def + k->offset)[0] = 0; /* an optional file, not given */
            continue;
        }
        if (e) {
            e->used = 1;
            where_entry(cfg, e, where, sizeof where);
        } else {
            snprintf(where, sizeof where, "footsim's default for [%s] %s", k->section, k->name);
        }
        fs_status s = bind_value(k, value, where, dir, e && e->line == 0, def, err);
        if (s == FS_OK && k->type == FS_KEY_LIST)
            s = bind_elements(cfg, k, def, err);
        if (s != FS_OK)
            return s;
    }
    for (int i = 0; i < cfg->count; i++) {
        const fs_entry *e = &cfg->entries[i];
        if (e->used)
            continue;
        char known[2048];
        where_entry(cfg, e, where, sizeof where);
        if (!section_known(schema, nkeys, e->section)) {
            list_known(schema, nkeys, NULL, known, sizeof known);
            return fs_fail(err, FS_BAD_INPUT, "%s: unknown section [%s]; sections here are: %s", where, e->section,
                           known);
        }
        list_known(schema, nkeys, e->section, known, sizeof known);
        return fs_fail(err, FS_BAD_INPUT, "%s: unknown key '%s' in [%s]; keys there are: %s", where, e->name,
                       e->section, known);
    }
    return FS_OK;
}

void fs_config_print_keys(const fs_key *schema, int nkeys, const char *title, void *out_file)
{
    FILE *out = out_file;
    fprintf(out, "### %s\n\n| section | key | unit | allowed | default | meaning |\n|---|---|---|---|---|---|\n", title);
    for (int i = 0; i < nkeys; i++) {
        const fs_key *k = &schema[i];
        char range[128];
        switch (k->type) {
        case FS_KEY_CHOICE: {
            /* "a|b" would split a Markdown table cell */
            size_t n = 0;
            for (const char *c = k->choices; *c && n + 3 < sizeof range; c++) {
                if (*c == '|') {
                    memcpy(range + n, ", ", 2);
                    n += 2;
                } else {
                    range[n++] = *c;
                }
            }
            range[n] = 0;
            break;
        }
        case FS_KEY_PATH: snprintf(range, sizeof range, "existing file"); break;
        case FS_KEY_LIST:
        case FS_KEY_SERIES: {
            char r[64];
            range_text(k, r, sizeof r);
            snprintf(range, sizeof range, "%s%d values in %s", k->type == FS_KEY_SERIES ? "up to " : "", k->count, r);
            break;
        }
        default: range_text(k, range, sizeof range);
        }
        fprintf(out, "| %s | %s | %s | %s | %s | %s |\n", k->section, k->name, k->unit ? k->unit : "", range,
                k->fallback, k->help);
    }
    fputc('\n', out);
}

/* Entries in sorted order: section, then key. */
static int by_key(const void *a, const void *b)
{
    const fs_entry *x = *(const fs_entry *const *)a, *y = *(const fs_entry *const *)b;
    int c = strcmp(x->section, y->section);
    return c ? c : strcmp(x->name, y->name);
}

fs_status fs_config_hash(const fs_config *cfg, unsigned long long *hash, fs_error *err)
{
    unsigned long long h = FS_HASH_START;
    const fs_entry **e = malloc((size_t)(cfg->count ? cfg->count : 1) * sizeof *e);
    if (!e)
        return fs_fail(err, FS_NO_MEMORY, "%s: out of memory to hash its %d entries", cfg->path, cfg->count);
    for (int i = 0; i < cfg->count; i++)
        e[i] = &cfg->entries[i];
    qsort(e, (size_t)cfg->count, sizeof *e, by_key);
    for (int i = 0; i < cfg->count; i++) { /* each field with its terminating zero: no two texts collide */
        h = fs_hash_bytes(h, e[i]->section, strlen(e[i]->section) + 1);
        h = fs_hash_bytes(h, e[i]->name, strlen(e[i]->name) + 1);
        h = fs_hash_bytes(h, e[i]->value, strlen(e[i]->value) + 1);
    }
    free(e);
    *hash = h;
    return FS_OK;
}

fs_status fs_ini_hash(const char *path, unsigned long long *hash, fs_error *err)
{
    fs_config cfg;
    fs_status s = fs_config_load(&cfg, path, err);
    if (s == FS_OK)
        s = fs_config_hash(&cfg, hash, err);
    fs_config_free(&cfg);
    return s;
}
