/* Problem lines and object lists for the solvers' case checks (case_check.h). */
#include "case_check.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *fsi_case_where(const fsi_case *c, const char *section, const char *key)
{
    const char *o = key ? fsi_case_origin(c, section, key) : NULL;
    if (!o || strcmp(o, "default") == 0 || strcmp(o, "derived") == 0)
        o = fsi_case_origin(c, section, NULL);
    return o ? o : fsi_case_path(c);
}

void fsi_case_problem(fsi_case_checker *k, const char *section, const char *key,
                      const char *fmt, ...)
{
    fprintf(k->out, "%s: [%s]%s%s: ", fsi_case_where(k->c, section, key), section,
            key ? " " : "", key ? key : "");
    va_list ap;
    va_start(ap, fmt);
    vfprintf(k->out, fmt, ap);
    va_end(ap);
    fputc('\n', k->out);
    k->errors++;
}

int fsi_case_object_list(const fsi_case *c, const char *role, const char *kind,
                         const char ***out)
{
    *out = NULL;
    int n = fsi_case_objects(c, role, kind, NULL, 0);
    if (n <= 0)
        return 0;
    *out = malloc((size_t)n * sizeof **out);
    if (!*out)
        return -1;
    return fsi_case_objects(c, role, kind, *out, n);
}

/* How much shorter than with its reference value factor f makes the step (log). */
static double shortening(const fsi_step_factor *f)
{
    if (!(f->value > 0.0) || !(f->reference > 0.0))
        return INFINITY;
    return -f->exponent * log(f->value / f->reference);
}

int fsi_case_check_step(fsi_case_checker *k, double step, const char *what,
                        const fsi_step_factor *factors, int n_factors)
{
    const double end = fsi_case_get_real(k->c, "run", "end_time", 0.0);
    /* run.end_time counts as a factor of the step count only; 10 s is the longest
     * benchmark's. */
    const fsi_step_factor end_factor = {"run", "end_time", end, 10.0, -1.0};
    const int too_short = !(step >= FSI_MIN_STEP) || !isnormal(step);
    if (!too_short && !(end / step > FSI_MAX_STEPS))
        return 0;
    const fsi_step_factor *blame = NULL;
    for (int i = 0; i < n_factors; i++)
        if (!blame || shortening(&factors[i]) > shortening(blame))
            blame = &factors[i];
    if (!blame || (!too_short && shortening(&end_factor) > shortening(blame)))
        blame = &end_factor;
    if (too_short)
        fsi_case_problem(k, blame->section, blame->key, "%s is %.3g s, below %g s: no scene "
                         "needs so short a step (sound in steel crosses a micrometre in 2e-10 "
                         "s); a value is far outside its physical range", what, step,
                         FSI_MIN_STEP);
    else
        fsi_case_problem(k, blame->section, blame->key, "%s is at most %.3g s: end_time = %g "
                         "s takes at least %.3g steps, more than %.3g (days of wall time even "
                         "for a hundred particles at the rates of docs/performance.md)", what,
                         step, end, end / step, FSI_MAX_STEPS);
    return 1;
}
