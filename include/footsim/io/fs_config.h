/* fs_config.h: INI files read into a table of keys, and bound to C structs through a schema.
 *
 * A file is read whole (with inih) into entries that remember their line. Command-line
 * overrides ("section.key=value") are added on top. Binding walks a schema (one fs_key per
 * allowed key: type, unit, range, default as text) and fills a def struct; anything the schema
 * does not know, any malformed or out-of-range value, any duplicate, is refused with
 * "file:line: what is wrong, and what is allowed" and FS_BAD_INPUT. Defaults are parsed and
 * checked by the same code as file values, so a default can never be out of range. */
#ifndef FS_CONFIG_H
#define FS_CONFIG_H

#include "footsim/base/fs_error.h"

#include <stddef.h>

enum { FS_NAME_MAX = 64, FS_VALUE_MAX = 256, FS_PATH_MAX = 1024, FS_LIST_MAX = 8, FS_SERIES_MAX = 16 };

/* A list key of varying length (FS_KEY_SERIES): n values, n from 0 (the key left out, or blank) to
 * the key's count. */
typedef struct fs_series {
    int n;
    double v[FS_SERIES_MAX];
} fs_series;

/* Caps on a file (docs/keys.md): bytes and keys. */
enum { FS_CONFIG_MAX_BYTES = 1024 * 1024, FS_CONFIG_MAX_KEYS = 10000 };

/* The longest line an input file may have, in characters (the INI reader's buffer, less its line
 * end and terminator): a longer one is refused with its file:line. */
int fs_config_max_line(void);

typedef struct fs_entry {
    char section[FS_NAME_MAX];
    char name[FS_NAME_MAX];
    char value[FS_VALUE_MAX];
    int line;  /* line in the file, or 0 for an override from the command line */
    int section_line; /* line of the [section] header it stands under, or 0 */
    int used;  /* set by binding */
} fs_entry;

typedef struct fs_config {
    char path[FS_PATH_MAX]; /* the file as named by the user */
    fs_entry *entries;
    int count, capacity;
    int *slots, nslots;     /* hash index over (section, name); rebuilt by each public function */
} fs_config;

typedef enum fs_key_type {
    FS_KEY_NUMBER,  /* double, finite, in [min, max] ((min, ...] with FS_KEY_OPEN_MIN, [..., max) with
                       FS_KEY_OPEN_MAX) */
    FS_KEY_INTEGER, /* int, in [min, max] */
    FS_KEY_LIST,    /* exactly `count` comma-separated doubles, each in range */
    FS_KEY_CHOICE,  /* one word of `choices` ("a|b|c"), stored as its int index */
    FS_KEY_PATH,    /* a path relative to the file's folder; must name an existing file (a key
                       whose default is "" is optional: left out, it stays "") */
    FS_KEY_SERIES   /* 0 to `count` (at most FS_SERIES_MAX) comma-separated doubles, each in range,
                       into an fs_series (a spring's force-deflection curve) */
} fs_key_type;

enum { FS_KEY_OPEN_MIN = 1, FS_KEY_OPEN_MAX = 2 };

typedef struct fs_key {
    const char *section;
    const char *name;
    fs_key_type type;
    size_t offset;       /* where the value goes in the def struct */
    double min, max;
    int flags;
    int count;           /* FS_KEY_LIST: number of values; FS_KEY_SERIES: the most */
    const char *choices; /* FS_KEY_CHOICE */
    const char *unit;    /* for messages and the key table */
    const char *fallback;/* the default, as text */
    const char *help;
} fs_key;

/* One number as footsim reads it everywhere (files, --set, command-line options): decimal, the
 * whole text but blanks, finite, and a normal double or 0; -0 reads as 0. */
typedef enum fs_number { FS_NUMBER_OK, FS_NUMBER_BAD, FS_NUMBER_HEX, FS_NUMBER_SUBNORMAL } fs_number;
fs_number fs_parse_number(const char *text, double *out);
/* What is wrong with it, for messages: "is not a finite number", "is hexadecimal; ...", ... */
const char *fs_number_problem(fs_number n);

/* Splits a comma-separated list in place into at most max items, each trimmed of blanks (a blank
 * list has none). Returns the count; -1 when an item is empty (",,", a comma first or last), with
 * *empty_at its 1-based place; -2 when there are more than max. Every list key (and a campaign's
 * sweep values) is read by it. */
int fs_list_split(char *list, char **item, int max, int *empty_at);

/* One element of a list key (FS_KEY_LIST) is named by the key's name and its place in brackets,
 * counted from 1: `splay_deg[3] = 0` in a file, `--set chains.splay_deg[3]=0`. It is set after the
 * whole list (the file's or the default), read by the key's own rules (a number in its range).
 * fs_list_element reads text "[i]" (nothing before or after it): i - 1, the element's 0-based index,
 * when i is a whole number from 1 to count; -1 when text is not of that form; -2 for a whole number
 * outside 1..count (0 included: elements are counted from 1). */
int fs_list_element(const char *text, int count);

/* Reads path into cfg. Refuses, with file:line and the real reason: a missing, unreadable or
 * not regular file, one over FS_CONFIG_MAX_BYTES or FS_CONFIG_MAX_KEYS keys, a NUL byte, a
 * carriage return that does not end a line, text after a section's ']', a section without keys,
 * a file without keys (empty, blank, only comments or a byte order mark), a syntax error, a line
 * over FS_VALUE_MAX characters, a continuation line and a key given twice in one section. A
 * UTF-8 byte order mark is skipped. Time and memory are linear in the file's size. */
fs_status fs_config_load(fs_config *cfg, const char *path, fs_error *err);

/* Adds a "section.key=value" override; it replaces the file's value when bound. */
fs_status fs_config_override(fs_config *cfg, const char *assignment, fs_error *err);

/* Fills def from the schema's defaults, then from cfg; then refuses any entry of cfg that no
 * key of the schema used (unknown section or key, with the known ones listed).
 * A relative path (a file key) is looked for: given by an override (--set), first from the current
 * folder, as a path on the command line is; then relative to cfg's file's folder; then under each
 * data folder (fs_config_data_folders) D, as D/scenarios/PATH, D/terrains/PATH and D/PATH. */
fs_status fs_config_bind(fs_config *cfg, const fs_key *schema, int nkeys, void *def, fs_error *err);

/* Reads value as the number or integer key k reads it from a file (the same rules and range, the
 * message led by where), into *out: for values of a key given elsewhere, such as a sweep's. */
fs_status fs_config_number(const fs_key *k, const char *value, const char *where, double *out, fs_error *err);

/* Checks a definition edited in code against the schema that binds files to it: every number,
 * whole number, list value and choice in its range, as a file's value would be. `what` names the
 * definition in the message ("scenarios/x.ini, edited in code"). FS_OK, or FS_BAD_INPUT naming the
 * key, the value and the range. */
fs_status fs_config_check(const fs_key *schema, int nkeys, const void *def, const char *what, fs_error *err);

/* "file:line" (or "--set section.key", or "file ([section] key, default)") for messages about a
 * key's value that only a later check can judge, such as a relation between two keys. cfg may be
 * NULL for a definition edited in code: "[section] key (set in code)". */
const char *fs_config_where(const fs_config *cfg, const char *section, const char *name, char *buf,
                            size_t size);

/* "file:line" of the [section] header a key of the section stands under (the first such header), or
 * "--set section.key" when only an override gives the section; NULL when nothing gives it or cfg is
 * NULL. For messages about a section as a whole (one that has no effect, one that lacks a key). */
const char *fs_config_where_section(const fs_config *cfg, const char *section, char *buf, size_t size);

/* Whether the file or an override gives [section] name (any key of the section when name is NULL). */
int fs_config_has(const fs_config *cfg, const char *section, const char *name);

/* The data folders a relative path that is not beside its file falls back to, in order, NULL-
 * terminated (the program's --data and installed data; none by default). The array and its text
 * must outlive every load. Process-wide on purpose: the data a program reads are one setting of
 * the program, set once before anything is loaded. */
void fs_config_data_folders(const char *const *folders);

/* The folder of cfg's file, for resolving relative paths. */
void fs_config_dir(const fs_config *cfg, char *buf, size_t size);

void fs_config_free(fs_config *cfg);

/* A hash of a file's parsed content (FNV-1a, 64 bits): its entries (section, key, value) in sorted
 * order, so that comments, blank lines, spacing and the order of keys do not change it, and any
 * changed value does. For provenance: which inputs made a result. FS_NO_MEMORY (hash untouched)
 * when the sort's memory is refused. */
fs_status fs_config_hash(const fs_config *cfg, unsigned long long *hash, fs_error *err);

/* fs_config_hash of the INI file at path; FS_BAD_INPUT when it cannot be read, FS_NO_MEMORY. */
fs_status fs_ini_hash(const char *path, unsigned long long *hash, fs_error *err);

/* Writes the schema as a Markdown table (key, unit, range, default, meaning) to out. */
void fs_config_print_keys(const fs_key *schema, int nkeys, const char *title, void *out_file);

#endif
