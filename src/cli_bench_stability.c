/* cli_bench_stability.c: 'footsim bench stability' (not built yet). */
#include "cli.h"

#include "footsim/fs_error.h"

#include <stdio.h>

int cli_bench_stability(const cli_args *a, const char *dir)
{
    (void)a;
    (void)dir;
    fprintf(stderr, "footsim bench stability: not built yet\n");
    return FS_BAD_INPUT;
}
