/* The case check of what a solid model accepts of the shared keys (solid_keys.h):
 * the integrator and the kind of constitutive law. A model that commits state in
 * every force evaluation (NOSB-PD's bonds and stress, pseudo-spring's links and
 * stress) never meets RK4's trial stages: the case is refused before anything runs,
 * with the file and line of the key. */
#include <string.h>

#include "case_check.h"
#include "solid_keys.h"

int solid_model_traits_check(const fsi_case *c, const char *role,
                             const solid_model_traits *t, FILE *errors)
{
    fsi_case_checker k = {c, errors, 0};
    const char *integrator = fsi_case_get(c, role, "integrator");
    if (integrator && strcmp(integrator, "rk4") == 0 && !t->stateless)
        fsi_case_problem(&k, role, "integrator",
                         "rk4 evaluates the internal force at trial states it throws away, "
                         "and %s commits its state (%s) in every evaluation; use verlet",
                         t->model, t->state);
    const char *law = fsi_case_get(c, role, "constitutive");
    if (!law)
        return k.errors;
    const int total = strcmp(law, "saint_venant_kirchhoff") == 0 ||
                      strcmp(law, "neo_hookean") == 0;
    const int incremental = strcmp(law, "drucker_prager") == 0;
    if (total && !t->total_form)
        fsi_case_problem(&k, role, "constitutive",
                         "%s is a function of the deformation gradient, which %s does not "
                         "have (it integrates an objective stress rate); use linear_elastic "
                         "or another solver (nosbpd, tlsph)", law, t->model);
    if (incremental && !t->incremental)
        fsi_case_problem(&k, role, "constitutive",
                         "%s needs an incremental stress update (plastic flow), which %s "
                         "does not do (it takes total-form laws of F); use nosbpd or "
                         "pseudo_spring", law, t->model);
    return k.errors;
}
