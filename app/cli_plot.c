/* cli_plot.c: charts drawn by gnuplot from a script footsim writes beside its data. */
#include "cli.h"

#include "footsim/io/fs_config.h"
#include "footsim/io/fs_output.h"
#include "footsim/io/fs_png.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

int cli_have_program(const char *name)
{
    const char *path = getenv("PATH");
    char dir[FS_PATH_MAX], full[FS_PATH_MAX + 64];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        size_t n = strcspn(p, ":");
        snprintf(dir, sizeof dir, "%.*s", (int)n, p);
        snprintf(full, sizeof full, "%s/%s", n ? dir : ".", name);
        if (access(full, X_OK) == 0)
            return 1;
        p += n + (p[n] == ':');
    }
    return 0;
}

int cli_gnuplot(const char *dir, const char *script, const char *png_name, const char *who)
{
    char png[2 * FS_PATH_MAX], temp[2 * FS_PATH_MAX + 64], var[2 * FS_PATH_MAX + 96];
    snprintf(png, sizeof png, "%s/%s", dir, png_name);
    if (!cli_have_program("gnuplot")) {
        fprintf(stderr, "footsim %s: gnuplot is not installed: no chart %s (apt-get install gnuplot-nox "
                        "draws it; or run 'gnuplot %s' in %s later)\n", who, png, script, dir);
        return 0;
    }
    fs_error err;
    if (fs_temp_name(png, temp, sizeof temp, &err) != FS_OK)
        return cli_report(err.status, err.message);
    /* gnuplot runs in dir: it is given the temporary file's name there */
    snprintf(var, sizeof var, "out='%s.tmp.%ld'", png_name, (long)getpid());
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        if (chdir(dir) == 0)
            execlp("gnuplot", "gnuplot", "-e", var, script, (char *)NULL);
        _exit(127);
    }
    int status = -1;
    if (pid > 0)
        waitpid(pid, &status, 0);
    if (!(pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
        remove(temp);
        fprintf(stderr, "footsim %s: gnuplot failed: no chart %s (the data and script %s are in %s)\n", who, png,
                script, dir);
        return 0;
    }
    /* gnuplot says nothing when it could not write all of it (a full disk): the file must be a
     * whole PNG before it joins the results */
    if (fs_png_check(temp, png, &err) != FS_OK || fs_commit_temp(temp, png, &err) != FS_OK) {
        remove(temp);
        return cli_report(err.status, err.message);
    }
    return 0;
}
