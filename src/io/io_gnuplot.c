/* io_gnuplot.c: names written into gnuplot scripts and data files as data (fs_gnuplot.h). */
#include "footsim/io/fs_gnuplot.h"

/* A byte a single-quoted gnuplot string holds as itself: not a control byte (a line end would end
 * the command) and not the quote (doubled, it would read as an empty string at the start); bytes
 * from 0x80 (UTF-8) are text. */
static int plain(unsigned char c) { return c >= 0x20 && c != 0x7f && c != '\''; }

void fs_gp_string(FILE *f, const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    if (!*p) {
        fputs("''", f);
        return;
    }
    for (int pieces = 0; *p; pieces++) {
        if (pieces)
            fputs(" . ", f);
        if (!plain(*p)) { /* quotes and control bytes in double quotes: the quote as itself, the
                             others as octal escapes; nothing else is ever written there */
            fputc('"', f);
            for (; *p && !plain(*p); p++)
                if (*p == '\'')
                    fputc('\'', f);
                else
                    fprintf(f, "\\%03o", *p);
            fputc('"', f);
            continue;
        }
        fputc('\'', f);
        for (; *p && plain(*p); p++)
            fputc(*p, f);
        fputc('\'', f);
    }
}

void fs_gp_data_text(FILE *f, const char *s)
{
    for (const unsigned char *p = (const unsigned char *)s; *p; p++)
        fputc(*p == '"' ? '\'' : *p < 0x20 || *p == 0x7f ? ' ' : *p, f);
}
