/* cli_progress.c: how a long command says where it is (cli.h): on a terminal, one line redrawn in
 * place; without one (a log, CI, a Slurm job), a plain line at every tenth of the work and at least
 * once a minute, and one at the end. A command of several rounds (optimize: a round per candidate)
 * names its round, and every reporter then counts the whole command's work. */
#include "cli.h"

#include "footsim/sim/fs_sim.h" /* fs_clock_s */

#include <stdarg.h>
#include <stdio.h>
#include <unistd.h>

/* The round a command is in (cli_progress_round), shared by the reporters of its rounds. */
static struct {
    const char *unit;
    int round, nrounds;
    double t0, last_line_s;
    int last_tenth;
} rounds;

void cli_progress_round(const char *unit, int round, int nrounds)
{
    if (!unit) {
        rounds.unit = NULL;
        return;
    }
    if (!rounds.unit || round <= 1) {
        rounds.t0 = rounds.last_line_s = fs_clock_s();
        rounds.last_tenth = 0;
    }
    rounds.unit = unit;
    rounds.round = round;
    rounds.nrounds = nrounds;
}

void cli_progress_start(cli_progress *p, const char *who, const char *unit)
{
    *p = (cli_progress){who, unit, isatty(STDERR_FILENO), fs_clock_s(), 0, 0, 0, 0, 0, 0};
    p->last_line_s = p->t0;
}

/* The fraction of the command's work done: this reporter's, or within the rounds. */
static double fraction(const cli_progress *p)
{
    double f = p->total > 0 ? (double)p->done / p->total : 1;
    if (rounds.unit && rounds.nrounds > 0)
        f = (rounds.round - 1 + f) / rounds.nrounds;
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

/* Prints the state: redrawn on a terminal; a plain line otherwise when a tenth more is done, a
 * minute has passed since the last line, or the work is finished. */
static void show(cli_progress *p)
{
    int in_rounds = rounds.unit != NULL;
    double now = fs_clock_s(), elapsed = now - (in_rounds ? rounds.t0 : p->t0), f = fraction(p);
    double eta = f > 0 ? elapsed * (1 - f) / f : 0;
    int finished = p->done == p->total && (!in_rounds || rounds.round >= rounds.nrounds);
    double *last_line = in_rounds ? &rounds.last_line_s : &p->last_line_s;
    int *last_tenth = in_rounds ? &rounds.last_tenth : &p->last_tenth, tenth = (int)(10 * f);
    char round[64] = "";
    if (in_rounds)
        snprintf(round, sizeof round, "%s %d/%d, ", rounds.unit, rounds.round, rounds.nrounds);
    if (p->tty) {
        enum { WIDTH = 30 };
        int filled = (int)(WIDTH * f);
        fprintf(stderr, "\r%s: [%.*s%*s] %s%d/%d %s, %d failed, %.0f s, ETA %.0f s ", p->who, filled,
                "##############################", WIDTH - filled, "", round, p->done, p->total, p->unit, p->failed,
                elapsed, eta);
        if (p->done == p->total)
            fputc('\n', stderr);
    } else if (finished || tenth > *last_tenth || now - *last_line >= 60) {
        fprintf(stderr, "%s: %s%d/%d %s done, %d failed, %.0f s elapsed, about %.0f s to go\n", p->who, round, p->done,
                p->total, p->unit, p->failed, elapsed, eta);
        *last_tenth = tenth;
        *last_line = now;
    }
    fflush(stderr);
}

void cli_progress_update(cli_progress *p, int done, int total, int failed)
{
    p->done = done;
    p->total = total;
    p->failed = failed;
    p->started = 1;
    show(p);
}

void cli_progress_tick(cli_progress *p)
{
    if (p->started && p->done < p->total)
        show(p);
}

void cli_progress_say(cli_progress *p, const char *format, ...)
{
    if (p->tty && p->started)
        fputs("\r\033[K", stderr); /* the message takes the progress line's place; it is redrawn below */
    va_list ap;
    va_start(ap, format);
    vfprintf(stderr, format, ap);
    va_end(ap);
    fputc('\n', stderr);
    if (p->tty && p->started && p->done < p->total)
        show(p);
    fflush(stderr);
}
