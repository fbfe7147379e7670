/* cli.h: the footsim command's shared argument handling and its subcommands. */
#ifndef FS_CLI_H
#define FS_CLI_H

enum { CLI_MAX_SET = 256 };

/* What every subcommand may be given. */
typedef struct cli_args {
    const char *command;
    const char *input;              /* the scenario or design file */
    const char *out;                /* --out DIR, or NULL */
    int json;                       /* --json */
    const char *set[CLI_MAX_SET];   /* --set section.key=value, in order */
    int nset;
} cli_args;

int cli_run(const cli_args *a);
int cli_model(const cli_args *a);
int cli_stiffness(const cli_args *a);
int cli_keys(const cli_args *a);
int cli_demo(const cli_args *a);

/* Prints "footsim: message" to stderr and returns the status. */
int cli_report(int status, const char *message);

#endif
