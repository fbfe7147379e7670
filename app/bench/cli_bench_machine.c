/* cli_bench_machine.c: what every benchmark records of where it ran: the machine (CPU, cores,
 * compiler, ODE's precision) and the load average; and of what made its results (provenance). Below the benchmarks; calls none of them. */
#include "cli.h"

#include "footsim/model/fs_scenario.h"
#include "footsim/io/fs_provenance.h"
#include "footsim/sim/fs_ode.h"

#include <cjson/cJSON.h>
#include <math.h>

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

int cli_bench_choose(const char *bench, const char *noun, const char *list, const char *const *names, int n,
                     int *chosen)
{
    for (const char *p = list; p; p++) { /* each name, p then past its comma */
        size_t len = strcspn(p, ",");
        int k = 0;
        while (k < n && (strlen(names[k]) != len || strncmp(names[k], p, len)))
            k++;
        if (k == n) {
            fprintf(stderr, "footsim bench %s: --scene %s: %s%s%s%.*s%s; give one or more of", bench, list,
                    len ? "no " : "an empty name", len ? noun : "", len ? " is called '" : "", (int)len, p,
                    len ? "'" : "");
            for (int j = 0; j < n; j++)
                fprintf(stderr, "%s %s", j ? "," : "", names[j]);
            fprintf(stderr, ", separated by commas\n");
            return FS_BAD_INPUT;
        }
        chosen[k] = 1;
        p += len;
        if (*p == 0)
            break;
    }
    return 0;
}

int cli_bench_provenance(fs_provenance *p, const fs_scenario *const *sc, int n, const char *settings, fs_error *err)
{
    fs_status s = fs_provenance_init(p, cli_data_path("scenarios/static_load.ini"), err);
    for (int i = 0; s == FS_OK && i < n; i++)
        s = fs_scenario_inputs(sc[i], p, err);
    snprintf(p->settings, sizeof p->settings, "%s", settings);
    return s;
}

const char *cli_csv_num(char *buf, size_t size, const char *fmt, double v)
{
    if (!isfinite(v))
        return "";
    snprintf(buf, size, fmt, v);
    return buf;
}

const char *cli_csv_text(char *buf, size_t size, const char *s)
{
    if (!strpbrk(s, ",\"\r\n"))
        return s;
    size_t n = 0;
    if (size < 3)
        return "";
    buf[n++] = '"';
    for (; *s && n + 3 < size; s++) {
        if (*s == '"')
            buf[n++] = '"';
        buf[n++] = *s;
    }
    buf[n++] = '"';
    buf[n] = 0;
    return buf;
}

int cli_csv_beside(const char *dir, const char *csv, const fs_provenance *p, const char *command, const char *date_utc,
                   const char *machine, double load_start, double load_end, fs_error *err)
{
    cJSON *run = cJSON_CreateObject();
    int ok = run != NULL;
    const char *texts[][2] = {{"command", command}, {"date_utc", date_utc}, {"machine", machine}};
    for (int i = 0; i < 3; i++)
        ok = ok && (texts[i][1] ? cJSON_AddStringToObject(run, texts[i][0], texts[i][1])
                                : cJSON_AddNullToObject(run, texts[i][0])) != NULL;
    const double loads[2] = {load_start, load_end};
    static const char *const load_keys[2] = {"load_average_start", "load_average_end"};
    for (int i = 0; i < 2; i++) /* unknown (-1, or not measured: NAN): null */
        ok = ok && (loads[i] >= 0 ? cJSON_AddNumberToObject(run, load_keys[i], loads[i])
                                  : cJSON_AddNullToObject(run, load_keys[i])) != NULL;
    fs_status s = ok ? fs_provenance_write_beside(dir, csv, p, run, err)
                     : fs_fail(err, FS_NO_MEMORY, "out of memory for %s's provenance", csv);
    cJSON_Delete(run);
    return s;
}
