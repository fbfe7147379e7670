/* io_config.c: INI files read with inih into entries with line numbers, bound through a schema. */
#include "footsim/io/fs_config.h"

#include <ini.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* ---- reading ---------------------------------------------------------------------------- */

typedef struct reader {
    FILE *file;
    fs_config *cfg;
    int line;       /* line most recently handed to inih */
    int long_line;  /* first line longer than the buffer, or 0 */
    fs_error *err;
    fs_status status;
} reader;

/* inih's line source: counts lines so the handler knows where each key stands. */
static char *read_line(char *buf, int size, void *stream)
{
    reader *r = stream;
    if (!fgets(buf, size, r->file))
        return NULL;
    r->line++;
    size_t n = strlen(buf);
    if (n == (size_t)size - 1 && buf[n - 1] != '\n' && !feof(r->file)) {
        if (!r->long_line)
            r->long_line = r->line;
        int c; /* skip the rest of the over-long line; it is refused after parsing */
        while ((c = fgetc(r->file)) != EOF && c != '\n') {}
    }
    return buf;
}

static fs_entry *find_entry(fs_config *cfg, const char *section, const char *name)
{
    for (int i = 0; i < cfg->count; i++)
        if (!strcmp(cfg->entries[i].section, section) && !strcmp(cfg->entries[i].name, name))
            return &cfg->entries[i];
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
    fs_entry *old = find_entry(r->cfg, section, name);
    if (old) {
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: [%s] %s is given twice (first on line %d); keep one",
                            r->cfg->path, r->line, section, name, old->line);
        return 0;
    }
    fs_entry *e = add_entry(r->cfg);
    if (!e) {
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: out of memory", r->cfg->path, r->line);
        return 0;
    }
    if (!copy_text(e->section, sizeof e->section, section) || !copy_text(e->name, sizeof e->name, name) ||
        !copy_text(e->value, sizeof e->value, value)) {
        r->status = fs_fail(r->err, FS_BAD_INPUT, "%s:%d: section, key or value too long (at most %d characters)",
                            r->cfg->path, r->line, FS_NAME_MAX - 1);
        return 0;
    }
    e->line = r->line;
    return 1;
}

fs_status fs_config_load(fs_config *cfg, const char *path, fs_error *err)
{
    memset(cfg, 0, sizeof *cfg);
    if (!copy_text(cfg->path, sizeof cfg->path, path))
        return fs_fail(err, FS_BAD_INPUT, "%.64s...: path too long", path);
    struct stat st;
    if (stat(path, &st) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: %s; give the path of an existing .ini file", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return fs_fail(err, FS_BAD_INPUT, "%s: not a regular file; give the path of an .ini file", path);
    reader r = {.cfg = cfg, .err = err, .status = FS_OK};
    r.file = fopen(path, "r");
    if (!r.file)
        return fs_fail(err, FS_BAD_INPUT, "%s: %s", path, strerror(errno));
    /* A continuation line would silently join two values: refuse it as a syntax error. */
    ini_allow_multiline = 0;
    int bad = ini_parse_stream(read_line, &r, on_key, &r);
    fclose(r.file);
    if (r.status != FS_OK)
        return r.status;
    if (r.long_line && (bad == 0 || r.long_line <= bad))
        return fs_fail(err, FS_BAD_INPUT, "%s:%d: line longer than %d characters; shorten it", path, r.long_line,
                       ini_max_line - 3);
    if (bad > 0)
        return fs_fail(err, FS_BAD_INPUT,
                       "%s:%d: not an INI line; write `[section]`, `key = value` or a `;` comment", path, bad);
    if (bad < 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot be read", path);
    return FS_OK;
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
    fs_entry *e = find_entry(cfg, section, name);
    if (!e) {
        e = add_entry(cfg);
        if (!e)
            return fs_fail(err, FS_BAD_INPUT, "--set %s: out of memory", assignment);
        strcpy(e->section, section);
        strcpy(e->name, name);
    }
    strcpy(e->value, eq + 1);
    e->line = 0;
    return FS_OK;
}

void fs_config_free(fs_config *cfg)
{
    free(cfg->entries);
    cfg->entries = NULL;
    cfg->count = cfg->capacity = 0;
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

const char *fs_config_where(const fs_config *cfg, const char *section, const char *name, char *buf, size_t size)
{
    const fs_entry *e = find_entry((fs_config *)cfg, section, name);
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

/* Parses one finite number, the whole of text. */
static int parse_number(const char *text, double *out)
{
    char buf[FS_VALUE_MAX];
    snprintf(buf, sizeof buf, "%s", text);
    const char *s = trim(buf);
    if (!*s)
        return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || errno == ERANGE || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

static void describe_range(const fs_key *k, char *buf, size_t size)
{
    snprintf(buf, size, "%s%g, %g]%s%s", (k->flags & FS_KEY_OPEN_MIN) ? "(" : "[", k->min, k->max,
             k->unit && *k->unit ? " " : "", k->unit ? k->unit : "");
}

static int in_range(const fs_key *k, double v)
{
    if (k->flags & FS_KEY_OPEN_MIN ? v <= k->min : v < k->min)
        return 0;
    return v <= k->max;
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
    case FS_KEY_PATH:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; give a path relative to the file's folder", where,
                       k->name, value, why);
    default:
        return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s' %s; allowed: %s%s in %s", where, k->name, value, why,
                       k->type == FS_KEY_INTEGER ? "a whole number" : "a finite number", "", range);
    }
}

static fs_status bind_value(const fs_key *k, const char *value, const char *where, const char *dir, void *def,
                            fs_error *err)
{
    char *slot = (char *)def + k->offset;
    double v;
    switch (k->type) {
    case FS_KEY_NUMBER:
        if (!parse_number(value, &v))
            return bad_value(err, where, k, value, "is not a finite number");
        if (!in_range(k, v))
            return bad_value(err, where, k, value, "is out of range");
        *(double *)slot = v;
        return FS_OK;
    case FS_KEY_INTEGER:
        if (!parse_number(value, &v) || v != floor(v))
            return bad_value(err, where, k, value, "is not a whole number");
        if (!in_range(k, v))
            return bad_value(err, where, k, value, "is out of range");
        *(int *)slot = (int)v;
        return FS_OK;
    case FS_KEY_LIST: {
        char buf[FS_VALUE_MAX];
        snprintf(buf, sizeof buf, "%s", value);
        double vals[FS_LIST_MAX];
        int n = 0;
        char *save = NULL;
        for (char *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
            if (n == k->count || n == FS_LIST_MAX)
                return bad_value(err, where, k, value, "has too many values");
            if (!parse_number(tok, &vals[n]))
                return bad_value(err, where, k, value, "has a value that is not a finite number");
            if (!in_range(k, vals[n]))
                return bad_value(err, where, k, value, "has a value out of range");
            n++;
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
        struct stat st;
        if (stat(full, &st) != 0 || !S_ISREG(st.st_mode))
            return fs_fail(err, FS_BAD_INPUT, "%s: %s = '%s': no such file (looked for %s); give a path relative to %s",
                           where, k->name, rel, full, dir);
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

fs_status fs_config_bind(fs_config *cfg, const fs_key *schema, int nkeys, void *def, fs_error *err)
{
    char dir[FS_PATH_MAX], where[FS_PATH_MAX + 80];
    fs_config_dir(cfg, dir, sizeof dir);
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
        fs_status s = bind_value(k, value, where, dir, def, err);
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
            snprintf(range, sizeof range, "%d values in %s%g, %g]", k->count, (k->flags & FS_KEY_OPEN_MIN) ? "(" : "[",
                     k->min, k->max);
            break;
        default:
            snprintf(range, sizeof range, "%s%g, %g]", (k->flags & FS_KEY_OPEN_MIN) ? "(" : "[", k->min, k->max);
        }
        fprintf(out, "| %s | %s | %s | %s | %s | %s |\n", k->section, k->name, k->unit ? k->unit : "", range,
                k->fallback, k->help);
    }
    fputc('\n', out);
}
