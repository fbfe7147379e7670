/* cli_plot.c: charts drawn by gnuplot from a script footsim writes beside its data. */
#include "cli.h"

#include "footsim/io/fs_config.h"

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
    char png[2 * FS_PATH_MAX], temp[128], var[160];
    snprintf(png, sizeof png, "%s/%s", dir, png_name);
    if (!cli_have_program("gnuplot")) {
        remove(png); /* a chart of an earlier run would not match these results */
        fprintf(stderr, "footsim %s: gnuplot is not installed: no chart %s (apt-get install gnuplot-nox "
                        "draws it; or run 'gnuplot %s' in %s later)\n", who, png, script, dir);
        return 0;
    }
    snprintf(temp, sizeof temp, "%s.tmp.%ld", png_name, (long)getpid());
    snprintf(var, sizeof var, "out='%s'", temp);
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
    char full[2 * FS_PATH_MAX + 128];
    snprintf(full, sizeof full, "%s/%s", dir, temp);
    if (pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0 && rename(full, png) == 0)
        return 1;
    remove(full);
    fprintf(stderr, "footsim %s: gnuplot failed: no chart %s (the data and script %s are in %s)\n", who, png,
            script, dir);
    return 0;
}
