/* `fsi keys`: the case-file reference (docs/cases.md) generated from the registry,
 * so the documentation cannot drift from what `fsi run` accepts. */
#include <stdio.h>

#include "case_file.h"
#include "solver_registry.h"

int main(void)
{
    fsi_case_schema_markdown(fsi_project_schema(), stdout);
    return 0;
}
