/* cli_bench_speed.c: 'footsim bench speed' (not built yet). */
#include "cli.h"

#include "footsim/fs_error.h"

#include <stdio.h>

int cli_bench_speed(const cli_args *a, const char *dir)
{
    (void)a;
    (void)dir;
    fprintf(stderr, "footsim bench speed: not built yet\n");
    return FS_BAD_INPUT;
}
