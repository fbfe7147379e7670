/* fs_gnuplot.h: text handed to gnuplot as data, never as code. Every name a script footsim writes
 * shows (a campaign's, a terrain's, a column's, a path) goes in through fs_gp_string, which writes
 * it as a gnuplot string expression that evaluates to exactly its bytes: runs of printable bytes in
 * single quotes (where gnuplot expands nothing: no backquote command, no @macro, no backslash),
 * runs of quotes and control bytes (a newline, a carriage return) in double quotes, the quote as
 * itself and each control byte as an octal escape, the pieces joined with gnuplot's '.'. A script
 * assigns such an expression to a variable and uses the variable (a title as `title name`, never
 * inside another string or a format). A name in a data file gnuplot reads (fs_gp_data_text) has the
 * characters that would end its field, line or comment replaced, so the file's columns stay where
 * the script expects them. */
#ifndef FS_GNUPLOT_H
#define FS_GNUPLOT_H

#include <stdio.h>

/* Writes s to f as a gnuplot string expression that evaluates to s, byte for byte. */
void fs_gp_string(FILE *f, const char *s);

/* Writes s to f for a data file's comment or double-quoted field: a double quote becomes a single
 * one and a control byte (a newline) a blank; everything else as it is. */
void fs_gp_data_text(FILE *f, const char *s);

#endif
