/* test_io_output.c: the results-folder writer as a library (issue 33, and issue 31's "the library
 * imposes no process policy"): writing a results folder installs no signal handler and no exit
 * handler of its own; a folder is footsim's by its marker only, never by its files' names; a path
 * is never cut short: one too long to use whole (with footsim's suffixes) is refused, exit 2. */
#include "fs_test.h"

#include "footsim/base/fs_path.h"
#include "footsim/io/fs_output.h"

#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

static char dir[64];

static void setup(void)
{
    snprintf(dir, sizeof dir, "/tmp/footsim-test-XXXXXX");
    REQUIRE(mkdtemp(dir) != NULL);
}

static void teardown(void) { fs_remove_tree(dir); }

static int fill_text(FILE *f, const void *user)
{
    fputs(user, f);
    return 1;
}

static int handler_is_default(int sig)
{
    struct sigaction sa;
    return sigaction(sig, NULL, &sa) == 0 && sa.sa_handler == SIG_DFL;
}

static int exists(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0;
}

/* A results folder written and replaced, a file written whole, a folder given up: SIGINT, SIGTERM
 * and SIGHUP keep the process's own disposition (here the default). */
static void writing_installs_no_handler(void)
{
    char out[128], file[128];
    snprintf(out, sizeof out, "%s/res", dir);
    snprintf(file, sizeof file, "%s/note.txt", dir);
    fs_error err;
    for (int round = 0; round < 2; round++) {
        fs_outdir o;
        REQUIRE(fs_outdir_open(&o, out, 0, "--out", &err) == FS_OK);
        CHECK(fs_write_in(o.partial, "a.txt", fill_text, "a\n", &err) == FS_OK);
        CHECK(fs_outdir_commit(&o, &err) == FS_OK);
    }
    fs_outdir given_up;
    REQUIRE(fs_outdir_open(&given_up, out, 0, "--out", &err) == FS_OK);
    fs_outdir_abort(&given_up);
    CHECK(fs_write_atomic(file, "x\n", 2, &err) == FS_OK);
    CHECK(handler_is_default(SIGTERM));
    CHECK(handler_is_default(SIGHUP));
    CHECK(handler_is_default(SIGINT));
}

/* A folder holding files named as footsim names its own, without the marker, is refused (exit 2)
 * and kept; --replace replaces it. */
static void ownership_is_by_marker_only(void)
{
    char out[128], draft[160];
    snprintf(out, sizeof out, "%s/thesis", dir);
    snprintf(draft, sizeof draft, "%s/summary.md", out);
    REQUIRE(mkdir(out, 0777) == 0);
    fs_error err;
    REQUIRE(fs_write_atomic(draft, "draft\n", 6, &err) == FS_OK);
    fs_outdir o;
    CHECK(fs_outdir_open(&o, out, 0, "--out", &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "a folder footsim did not make") != NULL);
    CHECK(exists(draft));
    CHECK(fs_outdir_shared(out, 0, "--out", &err) == FS_BAD_INPUT);
    REQUIRE(fs_outdir_open(&o, out, 1, "--out", &err) == FS_OK);
    CHECK(fs_outdir_commit(&o, &err) == FS_OK);
    CHECK(!exists(draft));
}

/* fs_path_fits and fs_path_format refuse what would not fit whole, and take what does. */
static void paths_are_never_cut_short(void)
{
    static char path[PATH_MAX + 64];
    fs_error err;
    CHECK(fs_path_fits("", 0, 0, "--out", &err) == FS_BAD_INPUT && strstr(err.message, "--out '': an empty path"));
    /* PATH_MAX - 1 - room characters fit; one more does not */
    size_t room = FS_DIR_ROOM, most = PATH_MAX - 1 - room;
    for (size_t i = 0; i < most; i++)
        path[i] = i % 101 == 0 ? '/' : 'a';
    path[most] = 0;
    CHECK(fs_path_fits(path, room, FS_NAME_ROOM, "--out", &err) == FS_OK);
    path[most] = 'a', path[most + 1] = 0;
    CHECK(fs_path_fits(path, room, FS_NAME_ROOM, "--out", &err) == FS_BAD_INPUT);
    CHECK(strstr(err.message, "characters long") && strstr(err.message, "give a shorter path"));
    /* a name: at most NAME_MAX, the last at most NAME_MAX - name_room */
    char name[NAME_MAX + 8];
    memset(name, 'n', NAME_MAX + 1);
    name[NAME_MAX + 1] = 0;
    snprintf(path, sizeof path, "/tmp/%s/x", name);
    CHECK(fs_path_fits(path, 0, 0, "--out", &err) == FS_BAD_INPUT && strstr(err.message, "give a shorter name"));
    name[NAME_MAX] = 0;
    snprintf(path, sizeof path, "/tmp/%s/x", name);
    CHECK(fs_path_fits(path, 0, FS_NAME_ROOM, "--out", &err) == FS_OK);
    snprintf(path, sizeof path, "/tmp/x/%s/", name);
    CHECK(fs_path_fits(path, 0, FS_NAME_ROOM, "--out", &err) == FS_BAD_INPUT);
    CHECK(fs_path_fits(path, 0, 0, "--out", &err) == FS_OK);
    /* a checked snprintf */
    char small[8];
    CHECK(fs_path_format(small, sizeof small, "--out", &err, "%s/%s", "abc", "def") == FS_OK && !strcmp(small, "abc/def"));
    CHECK(fs_path_format(small, sizeof small, "--out", &err, "%s/%s", "abc", "defg") == FS_BAD_INPUT);
    CHECK(strstr(err.message, "--out") == err.message && strstr(err.message, "at most 7"));
    /* a results folder too long is refused before anything is made */
    fs_outdir o;
    char component[201], first[512];
    memset(component, 'b', 200);
    component[200] = 0;
    snprintf(first, sizeof first, "%s/%s", dir, component);
    snprintf(path, sizeof path, "%s", dir);
    while (strlen(path) < PATH_MAX - FS_DIR_ROOM + 10)
        strcat(strcat(path, "/"), component);
    CHECK(fs_outdir_open(&o, path, 0, "--out", &err) == FS_BAD_INPUT);
    CHECK(!exists(first));
}

FS_TEST_MAIN(TEST(setup), TEST(writing_installs_no_handler), TEST(ownership_is_by_marker_only),
             TEST(paths_are_never_cut_short), TEST(teardown))
