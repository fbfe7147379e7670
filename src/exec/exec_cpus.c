/* exec_cpus.c: how many workers this process should run by default (fs_pool.h). */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "footsim/exec/fs_pool.h"

#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int fs_pool_jobs_from(int affinity_cpus, const char *cpu_max, const char *slurm_cpus)
{
    int jobs = affinity_cpus > 0 ? affinity_cpus : 1;
    /* cgroup v2 cpu.max: "QUOTA PERIOD" or "max PERIOD"; a quota of 1.5 CPUs allows 2 workers */
    double quota, period;
    if (cpu_max && sscanf(cpu_max, "%lf %lf", &quota, &period) == 2 && quota > 0 && period > 0) {
        int q = (int)ceil(quota / period);
        if (q >= 1 && q < jobs)
            jobs = q;
    }
    /* Slurm gives a task its CPUs */
    if (slurm_cpus && *slurm_cpus) {
        char *end;
        long n = strtol(slurm_cpus, &end, 10);
        if (!*end && n >= 1 && n < jobs)
            jobs = (int)n;
    }
    return jobs < FS_POOL_MAX_JOBS ? jobs : FS_POOL_MAX_JOBS;
}

int fs_pool_default_jobs(void)
{
    cpu_set_t set;
    int cpus = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : (int)sysconf(_SC_NPROCESSORS_ONLN);
    char cpu_max[128] = "";
    FILE *f = fopen("/sys/fs/cgroup/cpu.max", "r");
    if (f) {
        if (!fgets(cpu_max, sizeof cpu_max, f))
            cpu_max[0] = 0;
        fclose(f);
    }
    return fs_pool_jobs_from(cpus, cpu_max, getenv("SLURM_CPUS_PER_TASK"));
}
