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
 * when the key was defaulted or derived or is absent (key may be NULL). */
const char *fsi_case_where(const fsi_case *c, const char *section, const char *key);

/* Writes "WHERE: [section] key: message" (without " key" when key is NULL) and counts
 * it in k->errors. */
void fsi_case_problem(fsi_case_checker *k, const char *section, const char *key,
                      const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* The object sections [role.kind NAME] in file order in a new array *out (NULL when
 * there are none; free it); returns how many, or -1 when memory runs out. */
int fsi_case_object_list(const fsi_case *c, const char *role, const char *kind,
                         const char ***out);

/* Bounds on a participant's time step, checked before anything runs (docs/cases.md,
 * "Time steps"):
 *   FSI_MIN_STEP   a step below 1e-12 s (or one that is not a normal double) comes from
 *                  a value far outside its physical range: sound in steel crosses a
 *                  micrometre in 2e-10 s, so no scene a particle method resolves needs
 *                  it, and denormal steps lose their precision;
 *   FSI_MAX_STEPS  at the rates of docs/performance.md (5e5-2e6 particle-steps/s, a
 *                  coupling window at least 0.15 ms of messages) 1e9 steps take days
 *                  of wall time even for a hundred particles: a run with more is a
 *                  mistake, not a plan. */
#define FSI_MIN_STEP 1e-12
#define FSI_MAX_STEPS 1e9

/* One input of a step: the step grows as (value / reference)^exponent, where the
 * reference is the value of an ordinary case (a key's default, water at millimetre
 * spacing); the input farthest from its reference towards a shorter step is the one a
 * message names. */
typedef struct {
    const char *section, *key;
    double value, reference, exponent;
} fsi_step_factor;

/* Refuses a step (one problem, returns 1) when it is below FSI_MIN_STEP or not a
 * normal number, or when run.end_time / step exceeds FSI_MAX_STEPS; returns 0
 * otherwise. 'what' says whose step and how it was estimated, e.g. "the fluid's
 * acoustic step limit cfl_acoustic h / c0 = 0.25 * 0.0012 m / 40 m/s"; the problem is
 * put on the factor (or run.end_time) that shortens it most. */
int fsi_case_check_step(fsi_case_checker *k, double step, const char *what,
                        const fsi_step_factor *factors, int n_factors);

#endif
