/* fuzz_file.h: the fuzzers' helpers: an input written to a temporary file, since footsim's parsers
 * read files, and a folder laid out as the shipped data for the inputs that name other files. */
#ifndef FUZZ_FILE_H
#define FUZZ_FILE_H

#include "footsim/base/fs_error.h"

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Writes data to path; 0 if it cannot. */
static int fuzz_write(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    fwrite(data, 1, size, f);
    fclose(f);
    return 1;
}

/* Writes data to /tmp/footsim-fuzz-<pid><ext> and puts the path in path; 0 if it cannot. */
static inline int fuzz_write_temp(const uint8_t *data, size_t size, const char *ext, char *path, size_t n)
{
    snprintf(path, n, "/tmp/footsim-fuzz-%ld%s", (long)getpid(), ext);
    return fuzz_write(path, data, size);
}

/* FUZZ_VERBOSE=1 in the environment: says how each input ended (to check what a seed reaches). */
static inline void fuzz_said(int status, const fs_error *err)
{
    if (getenv("FUZZ_VERBOSE"))
        fprintf(stderr, "fuzz: %s\n", status == FS_OK ? "accepted" : err->message);
}

#ifdef FS_SOURCE_DIR
/* The fuzzer's data folder (a harness runs one per process, so it is the process's): DIR/terrains
 * and DIR/scenarios/{feet,robots,*.ini} are symbolic links to the source's shipped files. */
static char fuzz_dir[64];

static void fuzz_remove_data(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", fuzz_dir);
    if (fuzz_dir[0] && system(cmd) != 0)
        fprintf(stderr, "fuzz: could not remove %s\n", fuzz_dir);
}

static int fuzz_link(const char *from_rel, const char *to_rel)
{
    char from[4096], to[160];
    snprintf(from, sizeof from, "%s/%s", FS_SOURCE_DIR, from_rel);
    snprintf(to, sizeof to, "%s/%s", fuzz_dir, to_rel);
    return symlink(from, to) == 0;
}

/* Overrides for every input that names a terrain: the ground sampled coarsely and only under the
 * foot. The parse is what is fuzzed; the shipped rocks and the walking machine's path at full
 * resolution take seconds an input under the sanitizers. */
static const char *const fuzz_coarse[] = {"start.region_margin_m=0", "rough.resolution_m=0.005"};
enum { FUZZ_NCOARSE = 2 };

/* Makes the folder once; returns it, or NULL. A fuzzed scenario or campaign written to
 * DIR/scenarios/ names the shipped files as the shipped ones do ("feet/flat.ini",
 * "../terrains/rough.ini", "landing_trial.ini"); anything else it names is missing, and refused. */
static const char *fuzz_data_folder(void)
{
    if (fuzz_dir[0])
        return fuzz_dir;
    snprintf(fuzz_dir, sizeof fuzz_dir, "/tmp/footsim-fuzz-data-XXXXXX");
    char scen[128];
    if (!mkdtemp(fuzz_dir)) {
        fuzz_dir[0] = 0;
        return NULL;
    }
    atexit(fuzz_remove_data);
    snprintf(scen, sizeof scen, "%s/scenarios", fuzz_dir);
    if (mkdir(scen, 0700) != 0 || !fuzz_link("terrains", "terrains") || !fuzz_link("scenarios/feet", "scenarios/feet") ||
        !fuzz_link("scenarios/robots", "scenarios/robots"))
        return NULL;
    DIR *d = opendir(FS_SOURCE_DIR "/scenarios");
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        char from[300], to[300];
        if (n < 5 || strcmp(e->d_name + n - 4, ".ini"))
            continue;
        snprintf(from, sizeof from, "scenarios/%s", e->d_name);
        snprintf(to, sizeof to, "scenarios/%s", e->d_name);
        fuzz_link(from, to);
    }
    if (d)
        closedir(d);
    return fuzz_dir;
}

/* Writes data as DIR/scenarios/fuzz.ini of the data folder; puts the path in path; 0 if it cannot. */
static int fuzz_write_in_data(const uint8_t *data, size_t size, char *path, size_t n)
{
    const char *dir = fuzz_data_folder();
    if (!dir)
        return 0;
    snprintf(path, n, "%s/scenarios/fuzz.ini", dir);
    return fuzz_write(path, data, size);
}
#endif

#endif
