/* Problem lines and object lists for the solvers' case checks (case_check.h). */
#include "case_check.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *fsi_case_where(const fsi_case *c, const char *section, const char *key)
{
    const char *o = key ? fsi_case_origin(c, section, key) : NULL;
    if (!o || strcmp(o, "default") == 0)
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
