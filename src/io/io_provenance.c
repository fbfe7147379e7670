/* io_provenance.c: the record of what made a result (fs_provenance.h): its inputs hashed, written
 * as a line of text or a JSON object. */
#include "footsim/io/fs_provenance.h"

#include "footsim/io/fs_output.h"

#include "footsim/base/fs_hash.h"
#include "footsim/base/fs_path.h"
#include "footsim/base/fs_version.h"
#include "footsim/io/fs_input.h"

#include <cJSON.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* The largest data file hashed (a heightmap is refused by its reader well below). */
#define DATA_MAX_BYTES (1L << 30)

fs_status fs_provenance_init(fs_provenance *p, const char *relative_to, fs_error *err)
{
    memset(p, 0, sizeof *p);
    p->version = fs_version();
    char full[PATH_MAX];
    struct stat st;
    if (!realpath(relative_to, full) || stat(full, &st) != 0)
        return fs_fail(err, FS_BAD_INPUT, "%s: %s", relative_to, strerror(errno));
    char *slash = strrchr(full, '/');
    if (!S_ISDIR(st.st_mode) && slash)
        *(slash == full ? slash + 1 : slash) = 0;
    size_t n = strlen(full);
    if (n >= sizeof p->dir)
        return fs_fail(err, FS_BAD_INPUT, "%s: a folder path over %zu characters", relative_to, sizeof p->dir - 1);
    memcpy(p->dir, full, n + 1);
    return FS_OK;
}

void fs_provenance_free(fs_provenance *p)
{
    for (int i = 0; i < p->noverrides; i++)
        free(p->overrides[i]);
    for (int i = 0; i < p->ninputs; i++)
        free(p->inputs[i].path);
    free(p->overrides);
    free(p->inputs);
    free(p->version_text);
    p->version_text = NULL;
    p->overrides = NULL;
    p->inputs = NULL;
    p->noverrides = p->ninputs = 0;
}

fs_status fs_provenance_overrides(fs_provenance *p, const char *const *sets, int n, fs_error *err)
{
    if (n <= 0)
        return FS_OK;
    char **grown = realloc(p->overrides, (size_t)(p->noverrides + n) * sizeof *grown);
    if (!grown)
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the provenance");
    p->overrides = grown;
    for (int i = 0; i < n; i++) {
        if (!(p->overrides[p->noverrides] = strdup(sets[i])))
            return fs_fail(err, FS_NO_MEMORY, "out of memory for the provenance");
        p->noverrides++;
    }
    return FS_OK;
}

/* FNV-1a of a file's bytes. */
static fs_status hash_file(const char *path, unsigned long long *hash, fs_error *err)
{
    FILE *f = fs_open_regular(path, DATA_MAX_BYTES, "an input file", err);
    if (!f)
        return FS_BAD_INPUT;
    unsigned char buf[65536];
    unsigned long long h = FS_HASH_START;
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, f)) > 0)
        h = fs_hash_bytes(h, buf, k);
    int bad = ferror(f);
    fclose(f);
    if (bad)
        return fs_fail(err, FS_BAD_INPUT, "%s: cannot read it to hash it", path);
    *hash = h;
    return FS_OK;
}

/* Notes path once: hashed by how (0 bytes, 1 INI), or with *known's hash when known is given. */
static fs_status add(fs_provenance *p, const char *path, int ini, const unsigned long long *known, fs_error *err)
{
    char full[PATH_MAX], rel[2 * PATH_MAX];
    if (!path || !*path)
        return FS_OK;
    if (!realpath(path, full))
        return fs_fail(err, FS_BAD_INPUT, "%s: %s", path, strerror(errno));
    fs_path_relative(full, p->dir, rel, sizeof rel);
    if (strlen(rel) >= sizeof rel - 1) /* perhaps cut short: a provenance names every input whole */
        return fs_fail(err, FS_BAD_INPUT, "%.64s...: too far from %.64s... to record relative to it; move the files "
                       "closer", full, p->dir);
    for (int i = 0; i < p->ninputs; i++)
        if (!strcmp(p->inputs[i].path, rel))
            return FS_OK;
    unsigned long long h = known ? *known : 0;
    fs_status s = known ? FS_OK : ini ? fs_ini_hash(full, &h, err) : hash_file(full, &h, err);
    if (s != FS_OK)
        return s;
    fs_provenance_input *grown = realloc(p->inputs, (size_t)(p->ninputs + 1) * sizeof *grown);
    char *copy = strdup(rel);
    if (!grown || !copy) {
        free(copy);
        if (grown)
            p->inputs = grown;
        return fs_fail(err, FS_NO_MEMORY, "out of memory for the provenance");
    }
    p->inputs = grown;
    p->inputs[p->ninputs++] = (fs_provenance_input){copy, h};
    return FS_OK;
}

fs_status fs_provenance_add_ini(fs_provenance *p, const char *path, fs_error *err) { return add(p, path, 1, NULL, err); }

fs_status fs_provenance_add_data(fs_provenance *p, const char *path, fs_error *err) { return add(p, path, 0, NULL, err); }

fs_status fs_provenance_include(fs_provenance *p, const fs_provenance *from, fs_error *err)
{
    fs_status s = FS_OK;
    for (int i = 0; s == FS_OK && i < from->ninputs; i++) {
        char full[3 * PATH_MAX];
        s = fs_path_format(full, sizeof full, from->inputs[i].path, err, "%s/%s", from->dir, from->inputs[i].path);
        if (s == FS_OK)
            s = add(p, full, 0, &from->inputs[i].hash, err);
    }
    if (!p->settings[0])
        memcpy(p->settings, from->settings, sizeof p->settings);
    if (!p->nseeds)
        p->first_seed = from->first_seed, p->nseeds = from->nseeds;
    return s;
}

void fs_provenance_print(const fs_provenance *p, FILE *f)
{
    fprintf(f, "footsim %s; ", p->version ? p->version : fs_version());
    if (p->nseeds > 0)
        fprintf(f, "seeds %d to %d", p->first_seed, p->first_seed + p->nseeds - 1);
    else
        fputs("seeds none", f);
    fprintf(f, "; %s; inputs", p->settings[0] ? p->settings : "settings as the inputs give them");
    for (int i = 0; i < p->ninputs; i++)
        fprintf(f, " %s=%016llx", p->inputs[i].path, p->inputs[i].hash);
    fputs(p->ninputs ? "; overrides" : " none; overrides", f);
    for (int i = 0; i < p->noverrides; i++)
        fprintf(f, " '%s'", p->overrides[i]);
    if (!p->noverrides)
        fputs(" none", f);
}

void fs_provenance_line(const fs_provenance *p, FILE *f)
{
    fputs("# provenance: ", f);
    fs_provenance_print(p, f);
    fputc('\n', f);
}

cJSON *fs_provenance_json(const fs_provenance *p)
{
    /* every add checked: a record short of memory is no record (NULL), never a partial one */
    cJSON *prov = cJSON_CreateObject();
    int ok = prov != NULL;
    ok = ok && cJSON_AddStringToObject(prov, "footsim", p->version ? p->version : fs_version()) != NULL;
    cJSON *given = ok ? cJSON_AddArrayToObject(prov, "overrides") : NULL;
    ok = ok && given != NULL;
    for (int i = 0; ok && i < p->noverrides; i++)
        ok = fs_json_put(given, NULL, cJSON_CreateString(p->overrides[i]));
    cJSON *inputs = ok ? cJSON_AddArrayToObject(prov, "inputs") : NULL;
    ok = ok && inputs != NULL;
    for (int i = 0; ok && i < p->ninputs; i++) {
        char hash[24];
        snprintf(hash, sizeof hash, "%016llx", p->inputs[i].hash);
        cJSON *in = cJSON_CreateObject();
        ok = in && cJSON_AddStringToObject(in, "path", p->inputs[i].path) && cJSON_AddStringToObject(in, "hash", hash);
        ok = fs_json_put(inputs, NULL, ok ? in : (cJSON_Delete(in), NULL)) && ok;
    }
    ok = ok && cJSON_AddStringToObject(prov, "settings", p->settings) != NULL;
    ok = ok && cJSON_AddNumberToObject(prov, "seeds", p->nseeds) != NULL;
    ok = ok && cJSON_AddNumberToObject(prov, "first_seed", p->first_seed) != NULL;
    if (!ok) {
        cJSON_Delete(prov);
        return NULL;
    }
    return prov;
}

int fs_provenance_equal(const fs_provenance *a, const fs_provenance *b)
{
    const char *va = a->version ? a->version : fs_version(), *vb = b->version ? b->version : fs_version();
    if (strcmp(va, vb) || strcmp(a->settings, b->settings) || a->first_seed != b->first_seed ||
        a->nseeds != b->nseeds || a->noverrides != b->noverrides || a->ninputs != b->ninputs)
        return 0;
    for (int i = 0; i < a->noverrides; i++)
        if (strcmp(a->overrides[i], b->overrides[i]))
            return 0;
    for (int i = 0; i < a->ninputs; i++)
        if (strcmp(a->inputs[i].path, b->inputs[i].path) || a->inputs[i].hash != b->inputs[i].hash)
            return 0;
    return 1;
}

/* The text of a string member of o, or NULL. */
static const char *text_of(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

fs_status fs_provenance_from_json(const cJSON *o, fs_provenance *p, fs_error *err)
{
    memset(p, 0, sizeof *p);
    const cJSON *given = cJSON_GetObjectItemCaseSensitive(o, "overrides");
    const cJSON *inputs = cJSON_GetObjectItemCaseSensitive(o, "inputs");
    const cJSON *seeds = cJSON_GetObjectItemCaseSensitive(o, "seeds");
    const cJSON *first = cJSON_GetObjectItemCaseSensitive(o, "first_seed");
    const char *version = text_of(o, "footsim"), *settings = text_of(o, "settings");
    if (!version || !settings || !cJSON_IsArray(given) || !cJSON_IsArray(inputs) || !cJSON_IsNumber(seeds) ||
        !cJSON_IsNumber(first) || strlen(settings) >= sizeof p->settings)
        return fs_fail(err, FS_BAD_INPUT, "provenance: not a record footsim wrote (it needs footsim, overrides, "
                       "inputs, settings, seeds and first_seed)");
    fs_status s = FS_OK;
    const cJSON *item;
    cJSON_ArrayForEach(item, given) {
        const char *set = cJSON_IsString(item) ? item->valuestring : NULL;
        s = set ? fs_provenance_overrides(p, &set, 1, err) : fs_fail(err, FS_BAD_INPUT, "provenance: an override is not text");
        if (s != FS_OK)
            break;
    }
    cJSON_ArrayForEach(item, inputs) {
        const char *path = text_of(item, "path"), *hash = text_of(item, "hash");
        char *end = NULL;
        unsigned long long h = hash ? strtoull(hash, &end, 16) : 0;
        if (s != FS_OK)
            break;
        if (!path || !hash || strlen(hash) != 16 || *end)
            s = fs_fail(err, FS_BAD_INPUT, "provenance: an input without a path and a 16-digit hash");
        fs_provenance_input *grown = s == FS_OK ? realloc(p->inputs, (size_t)(p->ninputs + 1) * sizeof *grown) : NULL;
        char *copy = grown ? strdup(path) : NULL;
        if (grown)
            p->inputs = grown;
        if (s == FS_OK && !copy)
            s = fs_fail(err, FS_NO_MEMORY, "out of memory for the provenance");
        if (s == FS_OK)
            p->inputs[p->ninputs++] = (fs_provenance_input){copy, h};
    }
    /* the version is kept as text of its own: the record outlives o */
    p->version_text = s == FS_OK ? strdup(version) : NULL;
    if (s == FS_OK && !p->version_text)
        s = fs_fail(err, FS_NO_MEMORY, "out of memory for the provenance");
    p->version = p->version_text;
    memcpy(p->settings, settings, strlen(settings) + 1);
    p->nseeds = (int)seeds->valuedouble;
    p->first_seed = (int)first->valuedouble;
    return s;
}

typedef struct beside {
    const char *name;
    const fs_provenance *p;
    const cJSON *run;
} beside;

static int fill_beside(FILE *f, const void *user)
{
    const beside *b = user;
    cJSON *root = cJSON_CreateObject();
    cJSON *run = b->run ? cJSON_Duplicate(b->run, 1) : cJSON_CreateNull();
    int ok = root && cJSON_AddStringToObject(root, "file", b->name) != NULL;
    ok = fs_json_put(root, "provenance", fs_provenance_json(b->p)) && ok;
    ok = fs_json_put(root, "run", run) && ok;
    ok = ok && fs_json_print(f, root);
    cJSON_Delete(root);
    return ok;
}

fs_status fs_provenance_write_beside(const char *dir, const char *name, const fs_provenance *p, const cJSON *run,
                                     fs_error *err)
{
    char file[FS_PATH_MAX];
    size_t n = strlen(name);
    int stem = n > 4 && !strcmp(name + n - 4, ".csv") ? (int)(n - 4) : (int)n;
    if (snprintf(file, sizeof file, "%.*s.provenance.json", stem, name) >= (int)sizeof file)
        return fs_fail(err, FS_BAD_INPUT, "%s: a file name too long for its provenance's", name);
    const beside b = {name, p, run};
    return fs_write_in(dir, file, fill_beside, &b, err);
}
