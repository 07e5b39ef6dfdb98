#include "cli_args.h"

#include <stdlib.h>
#include <string.h>

#include "log.h"

fsi_args fsi_args_begin(int argc, char **argv, const char *command, void (*usage)(FILE *))
{
    return (fsi_args){.argc = argc, .argv = argv, .i = 0, .arg = NULL, .command = command,
                      .usage = usage, .error = 0};
}

int fsi_args_next(fsi_args *a)
{
    if (a->error || a->i + 1 >= a->argc)
        return 0;
    a->arg = a->argv[++a->i];
    if (strcmp(a->arg, "--help") == 0 || strcmp(a->arg, "-h") == 0) {
        a->usage(stdout);
        exit(FSI_EXIT_OK);
    }
    if (strcmp(a->arg, "--version") == 0) {
        printf("%s %s\n", a->command, FSI_VERSION);
        exit(FSI_EXIT_OK);
    }
    return 1;
}

/* The length of the option name in the argument: up to '=' or the end. */
static size_t name_length(const char *arg)
{
    const char *eq = strchr(arg, '=');
    return eq ? (size_t)(eq - arg) : strlen(arg);
}

static int is_option(const fsi_args *a, const char *name)
{
    size_t n = name_length(a->arg);
    return n == strlen(name) && strncmp(a->arg, name, n) == 0;
}

int fsi_arg_value(fsi_args *a, const char *name, const char **value)
{
    if (a->error || !is_option(a, name))
        return 0;
    const char *eq = strchr(a->arg, '=');
    if (eq)
        *value = eq + 1;
    else if (a->i + 1 < a->argc)
        *value = a->argv[++a->i];
    else
        *value = NULL;
    if (!*value || !**value) {
        fprintf(stderr, "%s: %s needs a value (%s VALUE or %s=VALUE)\n", a->command, name, name,
                name);
        a->error = 1;
        *value = NULL;
    }
    return 1;
}

int fsi_arg_flag(fsi_args *a, const char *name)
{
    if (a->error || !is_option(a, name))
        return 0;
    if (strchr(a->arg, '=')) {
        fprintf(stderr, "%s: %s takes no value ('%s')\n", a->command, name, a->arg);
        a->error = 1;
    }
    return 1;
}

int fsi_arg_positional(const fsi_args *a)
{
    return !a->error && a->arg[0] != '-';
}

void fsi_arg_unknown(fsi_args *a)
{
    if (a->error)
        return;
    if (a->arg[0] == '-')
        fprintf(stderr, "%s: unknown option '%s'\n", a->command, a->arg);
    else
        fprintf(stderr, "%s: unexpected argument '%s'\n", a->command, a->arg);
    a->usage(stderr);
    a->error = 1;
}

void fsi_arg_bad_value(fsi_args *a, const char *name, const char *value, const char *what)
{
    fprintf(stderr, "%s: %s %s, not '%s'\n", a->command, name, what, value);
    a->error = 1;
}
