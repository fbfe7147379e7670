/* cli_bench.c: 'footsim bench WHAT': checks the output folder and the options and picks the
 * benchmark. What the benchmarks share (the machine, the load) is cli_bench_machine.c, below them;
 * campaign equivalence (bench equivalence, and bench precision's last stage) is
 * cli_bench_equivalence.c. */
#include "cli.h"

#include "footsim/base/fs_error.h"
#include "footsim/io/fs_output.h"

#include <stdio.h>
#include <string.h>

int cli_bench(const cli_args *a)
{
    int known = !strcmp(a->input, "precision") || !strcmp(a->input, "stability") || !strcmp(a->input, "speed") ||
                !strcmp(a->input, "equivalence");
    if (!known) {
        fprintf(stderr, "footsim bench: unknown benchmark '%s'; give precision, stability, speed or equivalence\n",
                a->input);
        return FS_BAD_INPUT;
    }
    if (a->scene && strcmp(a->input, "precision") && strcmp(a->input, "stability")) {
        fprintf(stderr, "footsim bench %s: --scene is for bench precision and bench stability only\n", a->input);
        return FS_BAD_INPUT;
    }
    if (!strcmp(a->input, "equivalence"))
        return cli_bench_equivalence(a);
    /* build/bench by default: the committed results/bench/ changes only on purpose (--out results/bench) */
    const char *dir = a->out ? a->out : "build/bench";
    /* what only bench equivalence takes */
    const char *only = a->nset ? "--set" : a->reference ? "--reference" : a->steps ? "--steps" : NULL;
    if (a->input2 || only) {
        fprintf(stderr, "footsim bench %s: %s%s%s is for bench equivalence only; bench %s takes -j, --quick, --out, "
                "--replace and --data%s\n", a->input, a->input2 ? "a campaign ('" : "", a->input2 ? a->input2 : only,
                a->input2 ? "')" : "", a->input, strcmp(a->input, "speed") ? " (and --scene)" : "");
        return FS_BAD_INPUT;
    }
    if (!strcmp(a->input, "precision") && cli_bench_precision_scenes(a)) /* said */
        return FS_BAD_INPUT;
    if (!strcmp(a->input, "stability") && cli_bench_stability_slices(a)) /* said */
        return FS_BAD_INPUT;
    fs_error err;
    /* the folder must be one footsim writes into (marked, or only bench files), before measuring */
    if (fs_outdir_shared(dir, a->replace, "--out", &err) != FS_OK)
        return cli_report(err.status, err.message);
    if (!strcmp(a->input, "precision"))
        return cli_bench_precision(a, dir);
    if (!strcmp(a->input, "stability"))
        return cli_bench_stability(a, dir);
    return cli_bench_speed(a, dir);
}
