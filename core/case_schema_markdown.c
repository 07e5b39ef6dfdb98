/* docs/cases.md from a case schema (see fsi_case_schema_markdown in case_file.h).
 * Kept apart from the reader: it only walks the key tables and writes text. */
#include "case_check.h"
#include "case_file.h"
#include "case_file_internal.h"
#include "dim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *type_name(fsi_key_type t)
{
    switch (t) {
    case FSI_KEY_REAL: return "real";
    case FSI_KEY_INT: return "integer";
    case FSI_KEY_BOOL: return "bool";
    case FSI_KEY_STRING: return "string";
    case FSI_KEY_CHOICE: return "choice";
    case FSI_KEY_VECTOR: return "vector";
    }
    return "?";
}

/* Writes text for a table cell: '|' would end the cell, line breaks the row. */
static void md_cell(const char *text, FILE *out)
{
    for (const char *p = text ? text : ""; *p; p++) {
        if (*p == '|')
            fputs("\\|", out);
        else if (*p == '\n' || *p == '\r')
            fputc(' ', out);
        else
            fputc(*p, out);
    }
}

static void md_bounds(const fsi_key_spec *k, FILE *out)
{
    char lo[40], hi[40];
    fsi_case_format_number(k->min, lo, sizeof lo);
    fsi_case_format_number(k->max, hi, sizeof hi);
    int open = k->bounds & FSI_BOUND_MIN_OPEN;
    int has_min = open || (k->bounds & FSI_BOUND_MIN);
    int has_max = k->bounds & FSI_BOUND_MAX;
    if (has_min && has_max)
        fprintf(out, open ? "> %s and <= %s" : "%s .. %s", lo, hi);
    else if (has_min)
        fprintf(out, "%s %s", open ? ">" : ">=", lo);
    else if (has_max)
        fprintf(out, "<= %s", hi);
}

static void md_allowed(const fsi_key_spec *k, FILE *out)
{
    switch (k->type) {
    case FSI_KEY_REAL:
    case FSI_KEY_INT:
        md_bounds(k, out);
        break;
    case FSI_KEY_BOOL:
        fputs("true, false", out);
        break;
    case FSI_KEY_CHOICE: {
        char *words = fsi_case_choices_text(k->choices);
        md_cell(words, out);
        free(words);
        break;
    }
    case FSI_KEY_VECTOR:
        fprintf(out, "%d numbers", FSI_DIM);
        break;
    case FSI_KEY_STRING:
        break;
    }
}

static void md_default(const fsi_key_spec *k, FILE *out)
{
    if (!k->default_value) {
        fputs("required", out);
    } else if (!*k->default_value) {
        fputs("(empty)", out);
    } else {
        fputc('`', out);
        md_cell(k->default_value, out);
        fputc('`', out);
    }
}

static void md_table(const fsi_key_table *t, FILE *out)
{
    fputs("| key | type | unit | default | allowed | meaning |\n"
          "|---|---|---|---|---|---|\n", out);
    for (int i = 0; i < t->n_keys; i++) {
        const fsi_key_spec *k = &t->keys[i];
        fputs("| `", out);
        md_cell(k->key, out);
        fprintf(out, "` | %s | ", type_name(k->type));
        md_cell(k->unit, out);
        fputs(" | ", out);
        md_default(k, out);
        fputs(" | ", out);
        md_allowed(k, out);
        fputs(" | ", out);
        md_cell(k->description, out);
        fputs(" |\n", out);
    }
}

static void md_paragraph(const char *text, FILE *out)
{
    if (text && *text)
        fprintf(out, "%s\n\n", text);
}

static void md_section(const fsi_key_table *t, FILE *out)
{
    fprintf(out, "\n## [%s]\n\n", t->name);
    md_paragraph(t->description, out);
    md_table(t, out);
}

static void md_external(FILE *out)
{
    fputs("\n### solver = external (any participant)\n\n"
          "Runs the program given by `executable` (required, non-empty) as the participant; "
          "all other keys of the section and its object sections are passed to it as they "
          "are.\n", out);
}

static void md_roles_heading(const fsi_case_schema *schema, FILE *out)
{
    fputs("\n## Participant sections", out);
    for (int i = 0; i < schema->n_roles; i++) {
        const char *sep = i == 0 ? " " : i == schema->n_roles - 1 ? " and " : ", ";
        fprintf(out, "%s[%s]", sep, schema->roles[i]);
    }
    fputs("\n\n", out);
}

/* A solver's keys: one table per key table of [ROLE] (common solid keys, material
 * keys, ...), each under the table's name, then its own keys under the heading of
 * its solver section [ROLE.NAME], and the support it derives. */
static void md_solver_keys(const fsi_solver_spec *sv, FILE *out)
{
    int printed = 0;
    for (int i = 0; i < sv->n_key_tables; i++) {
        const fsi_key_table *t = sv->key_tables[i];
        if (!t || t->n_keys == 0)
            continue;
        fprintf(out, "%s#### Keys in [%s]: %s\n\n", printed ? "\n" : "", sv->role, t->name);
        md_paragraph(t->description, out);
        md_table(t, out);
        printed = 1;
    }
    if (sv->own_keys && sv->own_keys->n_keys > 0) {
        fprintf(out, "%s#### [%s.%s]: the keys of solver %s\n\n", printed ? "\n" : "",
                sv->role, sv->name, sv->name);
        md_paragraph(sv->own_keys->description, out);
        md_table(sv->own_keys, out);
        printed = 1;
    }
    if (!printed)
        fputs("No keys of its own.\n", out);
    if (sv->support)
        fprintf(out, "\nDerived: `[%s] %s` (m), the radius its sums reach (see Derived keys "
                "above).\n", sv->role, FSI_CASE_SUPPORT_KEY);
}

static void md_object_kind(const fsi_solver_spec *sv, const fsi_object_kind *k, FILE *out)
{
    fprintf(out, "\n#### [%s.%s NAME] sections (", sv->role, k->kind);
    if (k->min_count <= 0)
        fputs("any number", out);
    else if (k->min_count == 1)
        fputs("at least one", out);
    else
        fprintf(out, "at least %d", k->min_count);
    fputs(")\n\n", out);
    md_paragraph(k->description, out);
    if (k->keys && k->keys->n_keys > 0)
        md_table(k->keys, out);
    else
        fputs("No keys.\n", out);
}

static void md_solver(const fsi_solver_spec *sv, FILE *out)
{
    fprintf(out, "\n### solver = %s (%s)\n\n", sv->name, sv->role);
    md_paragraph(sv->description, out);
    if (sv->executable)
        fprintf(out, "Program: `%s`.\n\n", sv->executable);
    md_solver_keys(sv, out);
    for (int i = 0; i < sv->n_objects; i++)
        md_object_kind(sv, &sv->objects[i], out);
}

void fsi_case_schema_markdown(const fsi_case_schema *schema, FILE *out)
{
    fputs("# Case files\n\n"
          "A case file is an INI file: `[section]` lines, `key = value` lines and comments "
          "(lines starting with `#` or `;`, or `;` after a blank at the end of a line). "
          "Section names and keys are case-sensitive. Any key can be overridden on the "
          "command line with `--set section.key=value`: the key is the text after the last "
          "`.` before the `=` and the section everything before that `.`, so "
          "`--set \"solid.block beam.max=1,0.2\"` sets `max` in `[solid.block beam]`. This "
          "reference is generated from the key tables in the code.\n", out);
    /* The bounds of case_check.h; the checks are the solvers' and fsi_run_keys_check. */
    fprintf(out, "\n## Time steps\n\n"
            "Besides each key's own range, `fsi run` (and `--check`) estimates from the case "
            "the step every part will take: the coupling window (the shortest of "
            "`max_window` and a positive `probe_interval`), the fluid's step at rest (the "
            "acoustic limit cfl_acoustic h / c0 or the viscous limit cfl_viscous rho0 h^2 / "
            "mu, with c0 from 000 Eq. 7 when derived; a moving fluid only shortens it) and "
            "the solid's sub-step (time_step_safety dx / sqrt(M / rho), the lattice bound of "
            "the solid's stable step, which the model's step never exceeds). A case is "
            "refused when one of them is below %g s or not a normal number (sound in steel "
            "crosses a micrometre in 2e-10 s: such a step comes from a value far outside its "
            "physical range), or when `end_time` would take more than %.0e of them (at the "
            "rates of docs/performance.md, days of wall time even for a hundred particles). "
            "The message names the step, its inputs with their values, and the key whose "
            "value shortens it most against an ordinary case (water, c0 below water's 1480 "
            "m/s, millimetre spacing, the default factors, a steel-stiff solid).\n",
            FSI_MIN_STEP, FSI_MAX_STEPS);
    for (int i = 0; i < schema->n_sections; i++)
        md_section(&schema->sections[i], out);
    if (schema->n_roles == 0)
        return;
    md_roles_heading(schema, out);
    fprintf(out, "A participant section runs one solver, chosen with `solver = NAME`; it "
            "may hold the keys below and the keys the chosen solver lists under `Keys in "
            "[ROLE]`. `solver = external` runs the program named by `executable` and passes "
            "every other key to it unchecked.\n\n"
            "A solver's own keys (e.g. a fluid scheme's kernel factors) go in its solver "
            "section `[ROLE.SOLVER]`, e.g. `[fluid.ulph]`, and nowhere else: a case may carry "
            "one for every solver of the role, so that `--set fluid.solver=NAME` swaps "
            "solvers without editing the file. Each solver section is checked against its "
            "solver's keys and given its defaults whether that solver is chosen or not, so a "
            "typo in any of them is an error; the chosen solver's section is created with its "
            "defaults when the case has none (the resolved case shows every value in "
            "effect). A solver's own key written in `[ROLE]` is an error that names its "
            "section. From the command line: `--set fluid.ulph.artificial_viscosity=0.2`.\n\n"
            "Derived keys: validation writes `[ROLE] %s` (m), the radius within which the "
            "chosen solver's particle sums reach (a fluid's kernel support), into the "
            "resolved case for the solvers that have one, so that the other participant and "
            "the case checks can read it without knowing the solver (docs/coupling.md). It "
            "is not a setting: a value written for it is refused. The example and external "
            "fluids have none.\n\n", FSI_CASE_SUPPORT_KEY);
    fputs("Some solvers also take object sections: repeated, named sections "
          "`[ROLE.KIND NAME]` that belong to the participant section ROLE, e.g. "
          "`[solid.block beam]`. NAME is one word of letters, digits, `_` and `-`, and two "
          "objects of the same kind may not share it. The kinds a solver takes, their keys "
          "and how many of each it needs are listed with the solver. Object sections of an "
          "external participant are passed to it unchecked.\n\n", out);
    if (schema->participant) {
        md_paragraph(schema->participant->description, out);
        md_table(schema->participant, out);
    }
    for (int i = 0; i < schema->n_solvers; i++)
        md_solver(&schema->solvers[i], out);
    md_external(out);
}

/* The parts `fsi keys NAME` can print, in the order of the whole reference. */
static int is_role(const fsi_case_schema *schema, const char *name)
{
    for (int i = 0; i < schema->n_roles; i++)
        if (strcmp(schema->roles[i], name) == 0)
            return 1;
    return 0;
}

int fsi_case_schema_markdown_part(const fsi_case_schema *schema, const char *name, FILE *out)
{
    for (int i = 0; i < schema->n_sections; i++)
        if (strcmp(schema->sections[i].name, name) == 0) {
            md_section(&schema->sections[i], out);
            return 0;
        }
    int found = 0;
    if (is_role(schema, name) && schema->participant) {
        fprintf(out, "\n## [%s]\n\n", name);
        md_paragraph(schema->participant->description, out);
        md_table(schema->participant, out);
        found = 1;
    }
    for (int i = 0; i < schema->n_solvers; i++) {
        const fsi_solver_spec *sv = &schema->solvers[i];
        if (strcmp(sv->name, name) == 0 || strcmp(sv->role, name) == 0) {
            md_solver(sv, out);
            found = 1;
        }
    }
    if (strcmp(name, "external") == 0 || is_role(schema, name)) {
        md_external(out);
        found = 1;
    }
    return found ? 0 : -1;
}

void fsi_case_schema_part_names(const fsi_case_schema *schema, FILE *out)
{
    const char *sep = "";
    for (int i = 0; i < schema->n_sections; i++, sep = " ")
        fprintf(out, "%s%s", sep, schema->sections[i].name);
    for (int i = 0; i < schema->n_roles; i++, sep = " ")
        fprintf(out, "%s%s", sep, schema->roles[i]);
    for (int i = 0; i < schema->n_solvers; i++, sep = " ")
        fprintf(out, "%s%s", sep, schema->solvers[i].name);
    fprintf(out, "%s%s", sep, "external");
}
