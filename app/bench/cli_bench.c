/* cli_bench.c: 'footsim bench WHAT': picks the benchmark, and what they share (clock, machine). */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/io/fs_output.h"

#include <ode/ode.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void cli_machine(char *out, size_t size)
{
    char cpu[256] = "unknown CPU", line[512];
    FILE *f = fopen("/proc/cpuinfo", "r");
    while (f && fgets(line, sizeof line, f))
        if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
            snprintf(cpu, sizeof cpu, "%s", strchr(line, ':') + 2);
            cpu[strcspn(cpu, "\n")] = 0;
            break;
        }
    if (f)
        fclose(f);
    const char *config = dGetConfiguration();
    snprintf(out, size, "%s, %ld cores online, %s %s, ODE %s", cpu, sysconf(_SC_NPROCESSORS_ONLN),
#ifdef __clang__
             "clang",
#else
             "gcc",
#endif
             __VERSION__, strstr(config, "ODE_double_precision") ? "double precision" : "single precision");
}

double cli_load_average(void)
{
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f && fscanf(f, "%lf", &l) != 1)
        l = -1;
    if (f)
        fclose(f);
    return l;
}

/* What benches write into their shared folder (never replaced as a folder; file by file). */
static const char *const bench_files[] = {"precision.*", "stability*", "speed.*", "skips.csv", "render.csv",
                                          "own_code_before_after.csv", NULL};

int cli_bench(const cli_args *a)
{
    const char *dir = a->out ? a->out : "results/bench";
    int known = !strcmp(a->input, "precision") || !strcmp(a->input, "stability") || !strcmp(a->input, "speed");
    fs_error err;
    /* the folder must be one footsim writes into (marked, or only bench files), before measuring */
    if (known && fs_outdir_shared(dir, bench_files, a->replace, "--out", &err) != FS_OK)
        return cli_report(err.status, err.message);
    if (!strcmp(a->input, "precision"))
        return cli_bench_precision(a, dir);
    if (!strcmp(a->input, "stability"))
        return cli_bench_stability(a, dir);
    if (!strcmp(a->input, "speed"))
        return cli_bench_speed(a, dir);
    fprintf(stderr, "footsim bench: unknown benchmark '%s'; give precision, stability or speed\n", a->input);
    return FS_BAD_INPUT;
}
