/* The command-line conventions every program of launch/ shares, in one place: a long
 * option's value given as "--name value" or "--name=value", --help and -h (usage on
 * stdout, exit 0), --version (exit 0), and one message and exit status 2 for an
 * unknown option or a missing value.
 *
 *     fsi_args a = fsi_args_begin(argc, argv, "fsi run", usage);
 *     while (fsi_args_next(&a)) {
 *         const char *v;
 *         if (fsi_arg_value(&a, "--out", &v)) out = v;
 *         else if (fsi_arg_flag(&a, "--force")) force = 1;
 *         else if (fsi_arg_positional(&a)) case_path = a.arg;
 *         else fsi_arg_unknown(&a);
 *     }
 *     if (a.error) return FSI_EXIT_BAD_INPUT;
 */
#ifndef FSI_CLI_ARGS_H
#define FSI_CLI_ARGS_H

#include <stdio.h>

typedef struct {
    int argc;
    char **argv;
    int i;                      /* index of the argument being looked at */
    const char *arg;            /* argv[i] */
    const char *command;        /* "fsi run": names the program in messages */
    void (*usage)(FILE *out);   /* prints the program's usage */
    int error;                  /* set once a message was printed: stop, exit 2 */
} fsi_args;

fsi_args fsi_args_begin(int argc, char **argv, const char *command, void (*usage)(FILE *));

/* Moves to the next argument; 0 when there is none or after an error. Answers
 * --help and -h (usage on stdout) and --version ("COMMAND VERSION") itself and exits 0. */
int fsi_args_next(fsi_args *a);

/* 1 when the argument is option 'name' (e.g. "--out") with its value in *value:
 * "--out=DIR", or "--out DIR" (the next argument, taken). Without a value (the last
 * argument, or "--out="), a message names the option and a->error is set; the
 * function still returns 1 with *value = NULL, so the caller's chain ends there. */
int fsi_arg_value(fsi_args *a, const char *name, const char **value);

/* 1 when the argument is the flag 'name' (e.g. "--force"). "--force=..." is refused
 * with a message (a->error set, returns 1): a flag takes no value. */
int fsi_arg_flag(fsi_args *a, const char *name);

/* 1 when the argument is not an option (does not start with '-'). */
int fsi_arg_positional(const fsi_args *a);

/* Reports the argument as unknown (or a positional one too many) with the usage on
 * stderr, and sets a->error. */
void fsi_arg_unknown(fsi_args *a);

/* Reports a bad value of option 'name' ("needs a whole number >= 1") and sets
 * a->error: "COMMAND: NAME WHAT, not 'VALUE'". */
void fsi_arg_bad_value(fsi_args *a, const char *name, const char *value, const char *what);

#endif
