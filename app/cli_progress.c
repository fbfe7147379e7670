/* cli_progress.c: how a long command says where it is (cli.h): on a terminal, one line redrawn in
 * place; without one (a log, CI, a Slurm job), a plain line at every tenth of the work and at least
 * once a minute, and one at the end. */
#include "cli.h"

#include "footsim/sim/fs_sim.h" /* fs_clock_s */

#include <stdio.h>
#include <unistd.h>

void cli_progress_start(cli_progress *p, const char *who, const char *unit)
{
    *p = (cli_progress){who, unit, isatty(STDERR_FILENO), fs_clock_s(), 0, 0};
    p->last_line_s = p->t0;
}

void cli_progress_update(cli_progress *p, int done, int total, int failed)
{
    double now = fs_clock_s(), elapsed = now - p->t0;
    double eta = done > 0 ? elapsed * (total - done) / done : 0;
    int tenth = total > 0 ? (int)(10L * done / total) : 10;
    if (p->tty) {
        enum { WIDTH = 30 };
        int filled = total > 0 ? (int)((long)WIDTH * done / total) : WIDTH;
        fprintf(stderr, "\r%s: [%.*s%*s] %d/%d %s, %d failed, %.0f s, ETA %.0f s ", p->who, filled,
                "##############################", WIDTH - filled, "", done, total, p->unit, failed, elapsed, eta);
        if (done == total)
            fputc('\n', stderr);
    } else if (done == total || tenth > p->last_tenth || now - p->last_line_s >= 60) {
        fprintf(stderr, "%s: %d/%d %s done, %d failed, %.0f s elapsed, about %.0f s to go\n", p->who, done, total,
                p->unit, failed, elapsed, eta);
        p->last_tenth = tenth;
        p->last_line_s = now;
    }
    fflush(stderr);
}
