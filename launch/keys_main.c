/* `fsi keys`: the case-file reference (docs/cases.md) generated from the registry,
 * so the documentation cannot drift from what `fsi run` accepts. A flawed schema
 * (a key defined twice for one section, a default its own key rejects) prints no
 * reference: every case would fail validation with it. */
#include <stdio.h>

#include "case_file.h"
#include "solver_registry.h"

int main(void)
{
    const fsi_case_schema *schema = fsi_project_schema();
    int flaws = fsi_case_schema_check(schema, stderr);
    if (flaws > 0) {
        fprintf(stderr, "fsi keys: the case schema has %d flaw%s\n", flaws, flaws == 1 ? "" : "s");
        return 1;
    }
    fsi_case_schema_markdown(schema, stdout);
    return 0;
}
