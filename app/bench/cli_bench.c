/* cli_bench.c: 'footsim bench WHAT': checks the output folder and picks the benchmark. What the
 * benchmarks share (the machine, the load) is cli_bench_machine.c, below them. */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/io/fs_output.h"

#include <stdio.h>
#include <string.h>

/* What benches write into their shared folder (never replaced as a folder; file by file). */
static const char *const bench_files[] = {"precision.*", "stability*", "speed.*", "skips.csv", "render.csv",
                                          "own_code_before_after.csv", NULL};

int cli_bench(const cli_args *a)
{
    /* build/bench by default: the committed results/bench/ changes only on purpose (--out results/bench) */
    const char *dir = a->out ? a->out : "build/bench";
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
