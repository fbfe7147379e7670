/* cli_data.c: where the design, scenario, terrain and campaign files named on the command line (and
 * the shipped ones footsim names itself: demo, bench) are found. See cli.h. */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/experiment/fs_trial.h"
#include "footsim/io/fs_config.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef FS_DATADIR
#define FS_DATADIR "/usr/local/share/footsim"
#endif
#ifndef FS_BINDIR_TO_DATADIR
#define FS_BINDIR_TO_DATADIR "../share/footsim"
#endif
#ifndef FS_BINDIR_NAME
#define FS_BINDIR_NAME "bin"
#endif

/* --data DIR, or NULL. Process-wide on purpose: it is an option of the one command this process
 * runs, set once by main before the command starts and read by every lookup of a data file. */
static const char *data_dir;

int cli_data_set_dir(const char *dir)
{
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "footsim: --data %s: not a folder; give the folder that holds scenarios/ and terrains/\n",
                dir);
        return FS_BAD_INPUT;
    }
    data_dir = dir;
    return 0;
}

static int is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The installed data folder beside the command (P/bin/footsim -> P/share/footsim, wherever P was
 * installed to), canonical, or "" when the command is not in a bin folder or there is none. */
static const char *beside_command(void)
{
    /* static on purpose: where the running executable lives is a fact of the process, found once */
    static char dir[PATH_MAX];
    static int done;
    if (done)
        return dir;
    done = 1;
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return dir;
    exe[n] = 0;
    char *slash = strrchr(exe, '/');
    if (!slash)
        return dir;
    *slash = 0;
    size_t bl = strlen(FS_BINDIR_NAME), el = strlen(exe);
    if (el <= bl || exe[el - bl - 1] != '/' || strcmp(exe + el - bl, FS_BINDIR_NAME))
        return dir;
    char guess[PATH_MAX + 64];
    snprintf(guess, sizeof guess, "%s/%s", exe, FS_BINDIR_TO_DATADIR);
    if (!realpath(guess, dir))
        dir[0] = 0;
    return dir;
}

void cli_data_folders(void)
{
    /* static on purpose: the library keeps the array (fs_config_data_folders), set once per process */
    static const char *folders[5];
    int n = 0;
    const char *roots[] = {data_dir, ".", beside_command(), FS_DATADIR};
    for (size_t r = 0; r < sizeof roots / sizeof *roots; r++)
        if (roots[r] && *roots[r])
            folders[n++] = roots[r];
    folders[n] = NULL;
    fs_config_data_folders(folders);
}

const char *cli_data_robots(char *buf, size_t size)
{
    const char *roots[] = {data_dir, ".", beside_command(), FS_DATADIR};
    for (size_t r = 0; r < sizeof roots / sizeof *roots; r++) {
        struct stat st;
        if (roots[r] && *roots[r] && snprintf(buf, size, "%s/scenarios/robots", roots[r]) < (int)size &&
            stat(buf, &st) == 0 && S_ISDIR(st.st_mode))
            return buf;
    }
    return NULL;
}

const char *cli_data_installed(void) { return *beside_command() ? beside_command() : FS_DATADIR; }

const char *cli_data_find(const char *path, cli_data_kind kind, char *buf, size_t size)
{
    static const char *const subs[] = {[CLI_DATA_SCENARIO] = "scenarios/", [CLI_DATA_DESIGN] = "scenarios/feet/",
                                       [CLI_DATA_TERRAIN] = "terrains/"};
    struct stat st;
    /* as given when it is there (the reader says what is wrong with it) or names its own place */
    if (kind == CLI_DATA_NONE || !path || !*path || path[0] == '/' || !strncmp(path, "./", 2) || !strncmp(path, "../", 3) ||
        stat(path, &st) == 0)
        return path;
    const char *roots[] = {data_dir, ".", beside_command(), FS_DATADIR};
    for (size_t r = 0; r < sizeof roots / sizeof *roots; r++) {
        if (!roots[r] || !*roots[r])
            continue;
        for (int s = 0; s < 2; s++) {
            int here = !strcmp(roots[r], "."); /* "scenarios/x.ini", not "./scenarios/x.ini" */
            int n = snprintf(buf, size, "%s%s%s%s", here ? "" : roots[r], here ? "" : "/", s ? subs[kind] : "", path);
            if (n > 0 && (size_t)n < size && is_file(buf))
                return buf;
        }
    }
    return path;
}

const char *cli_data_path(const char *rel)
{
    enum { SLOTS = 16 };
    /* static on purpose: the contract (cli.h) is text that lives as long as the process, for
     * footsim's own few names; a cache of what was found, never a result of a simulation */
    static struct {
        const char *rel;
        char full[FS_PATH_MAX];
    } found[SLOTS];
    int i = 0;
    for (; i < SLOTS && found[i].rel; i++)
        if (!strcmp(found[i].rel, rel))
            return found[i].full;
    if (i == SLOTS)
        return rel;
    char buf[FS_PATH_MAX];
    const char *p = cli_data_find(rel, CLI_DATA_SCENARIO, buf, sizeof buf);
    found[i].rel = rel;
    snprintf(found[i].full, sizeof found[i].full, "%s", p);
    return found[i].full;
}

fs_status cli_flat_landing(const char *robot, fs_scenario *trial, fs_scenario *scene, fs_error *err)
{
    char body[FS_PATH_MAX + 16];
    snprintf(body, sizeof body, "robot.design=%s", robot);
    const char *set[] = {"scenario.terrain=../terrains/flat.ini", "scenario.design=feet/biomimetic.ini", body};
    fs_status s = fs_scenario_load("scenarios/landing_trial.ini", set, 3, trial, err);
    if (s == FS_OK)
        s = fs_scenario_load("scenarios/landing_trial.ini", set, 3, scene, err);
    return s == FS_OK ? fs_trial_place(scene, 1, NULL, err) : s;
}
