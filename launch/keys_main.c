/* `fsi keys [NAME]`: the case-file reference (docs/cases.md) generated from the
 * registry, so the documentation cannot drift from what `fsi run` accepts; with NAME
 * only that part of it (a section, a solver, a role). A flawed schema (a key defined
 * twice for one section, a default its own key rejects) prints no reference: every
 * case would fail validation with it. */
#include <stdio.h>

#include "case_file.h"
#include "cli_args.h"
#include "log.h"
#include "solver_registry.h"

static void usage(FILE *out)
{
    fprintf(out, "usage: fsi keys [NAME]\n"
                 "  the case-file reference (docs/cases.md); with NAME only its part for a\n"
                 "  section, a solver or every solver of a role:\n  ");
    fsi_case_schema_part_names(fsi_project_schema(), out);
    fputc('\n', out);
}

int main(int argc, char **argv)
{
    const char *name = NULL;
    fsi_args a = fsi_args_begin(argc, argv, "fsi keys", usage);
    while (fsi_args_next(&a)) {
        if (fsi_arg_positional(&a) && !name)
            name = a.arg;
        else
            fsi_arg_unknown(&a);
    }
    if (a.error)
        return FSI_EXIT_BAD_INPUT;
    const fsi_case_schema *schema = fsi_project_schema();
    int flaws = fsi_case_schema_check(schema, stderr);
    if (flaws > 0) {
        fprintf(stderr, "fsi keys: the case schema has %d flaw%s\n", flaws, flaws == 1 ? "" : "s");
        return FSI_EXIT_RUN_FAILURE;
    }
    if (!name) {
        fsi_case_schema_markdown(schema, stdout);
        return FSI_EXIT_OK;
    }
    if (fsi_case_schema_markdown_part(schema, name, stdout) != 0) {
        fprintf(stderr, "fsi keys: no section, solver or role '%s'; one of: ", name);
        fsi_case_schema_part_names(schema, stderr);
        fputc('\n', stderr);
        return FSI_EXIT_BAD_INPUT;
    }
    return FSI_EXIT_OK;
}
