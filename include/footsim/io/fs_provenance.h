/* fs_provenance.h: what made a result, recorded in every results file footsim writes (a run's
 * metrics.json, a trial's trial.json, a campaign's summary.json and summary.md) or beside it (a
 * CSV file holds data only, one header row and its rows: its record goes into the JSON beside it,
 * a campaign's summary.json, or a sidecar NAME.provenance.json): the footsim version (fs_version), every --set as the user gave it,
 * each input file read with a hash of its content, the step and solver settings, and the seeds.
 *
 * Input paths are written relative to one folder (the campaign's, the scenario's, the bench's
 * scenarios/), never with the machine's folders. An INI file is hashed by its parsed content
 * (fs_config_hash: a comment, blank line or reordering changes nothing, any value does); any other
 * file (a heightmap's PNG) by its bytes. Hashes are FNV-1a, 64 bits, written as 16 hex digits.
 *
 * The record owns what it holds (fs_provenance_free releases it; do not copy it by assignment).
 * Two records are the same (fs_provenance_equal) when every field is: version, overrides in order,
 * inputs in order with their hashes, settings and seeds; the text (fs_provenance_print) and the
 * JSON (fs_provenance_json) are pure functions of the record, so equal records print equal bytes. */
#ifndef FS_PROVENANCE_H
#define FS_PROVENANCE_H

#include "footsim/base/fs_error.h"
#include "footsim/io/fs_config.h"

#include <stdio.h>

enum { FS_PROVENANCE_SETTINGS_MAX = 2048 }; /* a campaign's: the first cell's, up to 7 robots' own steps and tolerances, its band */

typedef struct fs_provenance_input {
    char *path;              /* relative to the record's folder */
    unsigned long long hash;
} fs_provenance_input;

typedef struct fs_provenance {
    char dir[FS_PATH_MAX];   /* absolute: the folder input paths are relative to */
    const char *version;     /* fs_version(), or version_text for a record read back */
    char *version_text;      /* owned: the version of a record read from JSON, else NULL */
    char **overrides;        /* every --set as given, in order */
    int noverrides;
    fs_provenance_input *inputs; /* each file once, in the order noted */
    int ninputs;
    char settings[FS_PROVENANCE_SETTINGS_MAX]; /* step and solver settings, as text ("" when none) */
    int first_seed, nseeds;  /* seeds first_seed .. first_seed + nseeds - 1; nseeds 0: none drawn */
} fs_provenance;

/* An empty record whose inputs are written relative to `relative_to`: a folder, or a file's folder.
 * FS_BAD_INPUT when it does not exist. */
fs_status fs_provenance_init(fs_provenance *p, const char *relative_to, fs_error *err);
void fs_provenance_free(fs_provenance *p);

/* Records the overrides (copied), after any recorded before. FS_NO_MEMORY when out of memory. */
fs_status fs_provenance_overrides(fs_provenance *p, const char *const *sets, int n, fs_error *err);

/* Notes an input once (by its real path): an INI file by its parsed content, any other file by its
 * bytes. An empty path is no input (FS_OK); a file that cannot be read is FS_BAD_INPUT. */
fs_status fs_provenance_add_ini(fs_provenance *p, const char *path, fs_error *err);
fs_status fs_provenance_add_data(fs_provenance *p, const char *path, fs_error *err);

/* Adds from's inputs (their hashes as from recorded them, their paths relative to p's folder) and,
 * where p has none, its settings and seeds: a result made of another's (a design search of its
 * campaign). */
fs_status fs_provenance_include(fs_provenance *p, const fs_provenance *from, fs_error *err);

/* The record as one line of text without a newline: "footsim V; seeds A to B; SETTINGS; inputs
 * PATH=HASH ...; overrides 'SET' ..." ("seeds none", "overrides none" when there are none).
 * fs_provenance_line writes it as "# provenance: TEXT\n", the line a campaign's journal keeps
 * (never a CSV file's: CSV files hold only their header and rows). */
void fs_provenance_print(const fs_provenance *p, FILE *f);
void fs_provenance_line(const fs_provenance *p, FILE *f);

/* Writes dir/STEM.provenance.json beside the CSV file dir/NAME (STEM: NAME without ".csv"), whole
 * or not at all: {"file": NAME, "provenance": fs_provenance_json(p), "run": run} ("run": what else
 * says how the file was made, e.g. the machine and the date of a benchmark; null when run is
 * NULL; run is not freed). Status as fs_write_in. */
struct cJSON;
fs_status fs_provenance_write_beside(const char *dir, const char *name, const fs_provenance *p,
                                     const struct cJSON *run, fs_error *err);

/* The record as a JSON object (the caller frees it with cJSON_Delete; NULL when out of memory):
 * {"footsim", "overrides": [...], "inputs": [{"path", "hash"}...], "settings", "seeds",
 * "first_seed"}; `footsim compare` reads these fields. */
struct cJSON *fs_provenance_json(const fs_provenance *p);

/* Reads a record back from the JSON object fs_provenance_json wrote (a summary's "provenance", a
 * journal's header), to compare with fs_provenance_equal. FS_BAD_INPUT when a field is missing or
 * of the wrong kind; p is to be freed either way. The folder (dir) is not recorded: "" */
fs_status fs_provenance_from_json(const struct cJSON *o, fs_provenance *p, fs_error *err);

/* Whether a and b record the same version, overrides, inputs, settings and seeds. */
int fs_provenance_equal(const fs_provenance *a, const fs_provenance *b);

#endif
