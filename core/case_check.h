/* Helpers of the solvers' semantic case checks (fsi_solver_spec.check) and of the
 * code that reads object sections: one problem per line as
 * "FILE:LINE: [section] key: message", and the list of a kind's object sections. */
#ifndef FSI_CASE_CHECK_H
#define FSI_CASE_CHECK_H

#include <stdio.h>

#include "case_file.h"

typedef struct {
    const fsi_case *c;
    FILE *out;
    int errors;
} fsi_case_checker;

/* Where a problem is: the key's own "FILE:LINE" (or --set), or the section's header
 * when the key was defaulted or is absent (key may be NULL). */
const char *fsi_case_where(const fsi_case *c, const char *section, const char *key);

/* Writes "WHERE: [section] key: message" (without " key" when key is NULL) and counts
 * it in k->errors. */
void fsi_case_problem(fsi_case_checker *k, const char *section, const char *key,
                      const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* The object sections [role.kind NAME] in file order in a new array *out (NULL when
 * there are none; free it); returns how many, or -1 when memory runs out. */
int fsi_case_object_list(const fsi_case *c, const char *role, const char *kind,
                         const char ***out);

#endif
