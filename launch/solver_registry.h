/* Every section and solver a case file may name: the schema `fsi run` validates
 * against and docs/cases.md is generated from. */
#ifndef FSI_SOLVER_REGISTRY_H
#define FSI_SOLVER_REGISTRY_H

#include "case_file.h"

const fsi_case_schema *fsi_project_schema(void);

/* The solver spec for 'name', or NULL. */
const fsi_solver_spec *fsi_find_solver(const char *name);

#endif
