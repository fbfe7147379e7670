/* cli_bench_machine.c: what every benchmark records of where it ran: the machine (CPU, cores,
 * compiler, ODE's precision) and the load average; and of what made its results (provenance). Below the benchmarks; calls none of them. */
#include "cli.h"

#include "footsim/model/fs_scenario.h"
#include "footsim/sim/fs_ode.h"

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
    snprintf(out, size, "%s, %ld cores online, %s %s, ODE %s", cpu, sysconf(_SC_NPROCESSORS_ONLN),
#ifdef __clang__
             "clang",
#else
             "gcc",
#endif
             __VERSION__, fs_ode_double_precision() ? "double precision" : "single precision");
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

int cli_bench_provenance(fs_provenance *p, const fs_scenario *const *sc, int n, const char *settings, fs_error *err)
{
    fs_status s = fs_provenance_init(p, cli_data_path("scenarios/static_load.ini"), err);
    for (int i = 0; s == FS_OK && i < n; i++)
        s = fs_scenario_inputs(sc[i], p, err);
    snprintf(p->settings, sizeof p->settings, "%s", settings);
    return s;
}
