/* Reading a material from a validated case, and the checks across keys that the
 * single-key rules of material_keys.c cannot express. One set of checks serves
 * both the launcher (material_case_check, every problem to a stream) and the
 * solid at start-up (material_from_case, the first problem to msg), so a case that
 * passes `fsi run --check` never fails later for a material reason.
 *
 * Decisions:
 *  - drucker_prager needs cohesion and friction_angle written in the case. Their
 *    table defaults (0) exist only because the key table is shared with
 *    linear_elastic; a soil's strength silently defaulting to a frictionless,
 *    cohesionless cone (no strength at all) or to phi = 0 is a trap.
 *  - Drucker-Prager keys given with any other model (linear_elastic or a
 *    hyperelastic one) are an error, not ignored: they would suggest a strength the
 *    model does not have (the same rule as load keys on a region that does not load,
 *    solid_check.c).
 *  - dilation_angle > friction_angle is rejected: on the cone the plastic work per
 *    unit dlambda is sigma : dg/dsigma = k + (beta - alpha) I1, which for beta >
 *    alpha turns negative under enough confinement (I1 << 0), i.e. plastic flow
 *    would create energy. */
#include <math.h>
#include <stdarg.h>
#include <string.h>

#include "dim.h"
#include "material.h"

typedef struct {
    const fsi_case *c;
    const char *section;
    FILE *out;          /* all problems, one line each (may be NULL) */
    char *msg;          /* the first problem (may be NULL) */
    size_t msg_size;
    int n;
} reporter;

static int given(const fsi_case *c, const char *section, const char *key)
{
    const char *o = fsi_case_origin(c, section, key);
    return o && strcmp(o, "default") != 0;
}

/* Where a problem is: the key's own line, or the section header for a defaulted
 * or absent key (as solid_check.c does). */
static const char *where(const fsi_case *c, const char *section, const char *key)
{
    const char *o = fsi_case_origin(c, section, key);
    if (!o || strcmp(o, "default") == 0)
        o = fsi_case_origin(c, section, NULL);
    if (!o)
        o = fsi_case_path(c);
    return o ? o : "case";
}

static void problem(reporter *r, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void problem(reporter *r, const char *key, const char *fmt, ...)
{
    char text[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    const char *w = where(r->c, r->section, key);
    if (r->out)
        fprintf(r->out, "%s: [%s] %s: %s\n", w, r->section, key, text);
    if (r->msg && r->msg_size > 0 && r->n == 0)
        snprintf(r->msg, r->msg_size, "%s: [%s] %s: %s", w, r->section, key, text);
    r->n++;
}

static const double DEG = 3.14159265358979323846 / 180.0;

/* The words of the constitutive key (material_keys.c lists the same ones). */
static const struct {
    const char *name;
    material_kind kind;
} KINDS[] = {
    {"linear_elastic", MATERIAL_LINEAR_ELASTIC},
    {"drucker_prager", MATERIAL_DRUCKER_PRAGER},
    {"saint_venant_kirchhoff", MATERIAL_SAINT_VENANT_KIRCHHOFF},
    {"neo_hookean", MATERIAL_NEO_HOOKEAN},
};
#define N_KINDS ((int)(sizeof KINDS / sizeof KINDS[0]))

const char *material_kind_name(material_kind k)
{
    for (int i = 0; i < N_KINDS; i++)
        if (KINDS[i].kind == k)
            return KINDS[i].name;
    return "unknown";
}

/* Fills m from the case without deriving; returns the number of problems. */
static int read_and_check(material *m, reporter *r)
{
    const fsi_case *c = r->c;
    const char *s = r->section;

    const char *kind = fsi_case_get(c, s, "constitutive");
    memset(m, 0, sizeof *m);
    m->kind = MATERIAL_LINEAR_ELASTIC;
    if (kind) {
        int found = 0;
        for (int i = 0; i < N_KINDS && !found; i++)
            if (strcmp(kind, KINDS[i].name) == 0) {
                m->kind = KINDS[i].kind;
                found = 1;
            }
        if (!found)
            problem(r, "constitutive",
                    "unknown model '%s' (linear_elastic, drucker_prager, "
                    "saint_venant_kirchhoff or neo_hookean)",
                    kind);
    }
    m->plane = MATERIAL_PLANE_STRAIN;
#if FSI_DIM == 2
    const char *plane = fsi_case_get(c, s, "plane");
    if (plane && strcmp(plane, "stress") == 0)
        m->plane = MATERIAL_PLANE_STRESS;
    else if (plane && strcmp(plane, "strain") != 0)
        problem(r, "plane", "unknown idealisation '%s' (strain or stress)", plane);
#endif
    m->density = fsi_case_get_real(c, s, "density", NAN);
    m->youngs_modulus = fsi_case_get_real(c, s, "youngs_modulus", NAN);
    m->poisson_ratio = fsi_case_get_real(c, s, "poisson_ratio", NAN);
    m->cohesion = fsi_case_get_real(c, s, "cohesion", 0.0);
    double phi_deg = fsi_case_get_real(c, s, "friction_angle", 0.0);
    double psi_deg = fsi_case_get_real(c, s, "dilation_angle", 0.0);
    m->friction_angle = phi_deg * DEG;
    m->dilation_angle = psi_deg * DEG;

    /* Single-key rules again, for cases that skipped validation; after validation
     * none of these can fire. */
    if (!(m->density > 0.0))
        problem(r, "density", "needs a value > 0 kg/m^3");
    if (!(m->youngs_modulus > 0.0))
        problem(r, "youngs_modulus", "needs a value > 0 Pa");
    if (!(m->poisson_ratio >= 0.0 && m->poisson_ratio <= MATERIAL_MAX_POISSON))
        problem(r, "poisson_ratio",
                "%.6g is outside 0 <= nu <= %.3g: near 0.5 the bulk modulus dwarfs the "
                "shear modulus (incompressible limit) and the explicit step vanishes",
                m->poisson_ratio, MATERIAL_MAX_POISSON);
    if (!(m->cohesion >= 0.0))
        problem(r, "cohesion", "needs a value >= 0 Pa");
    if (!(phi_deg >= 0.0 && phi_deg < 90.0))
        problem(r, "friction_angle", "needs 0 <= phi < 90 degrees");
    if (!(psi_deg >= 0.0 && psi_deg < 90.0))
        problem(r, "dilation_angle", "needs 0 <= psi < 90 degrees");

    static const char *const dp_keys[] = {"cohesion", "friction_angle", "dilation_angle"};
    if (m->kind == MATERIAL_DRUCKER_PRAGER) {
        if (m->plane == MATERIAL_PLANE_STRESS)
            problem(r, "plane",
                    "plane = stress is not supported with constitutive = drucker_prager "
                    "(the return mapping would have to find eps_zz together with the "
                    "plastic flow); use plane = strain");
        for (int i = 0; i < 2; i++)
            if (!given(c, s, dp_keys[i]))
                problem(r, dp_keys[i], "required with constitutive = drucker_prager");
        if (psi_deg > phi_deg)
            problem(r, "dilation_angle",
                    "%.6g deg exceeds friction_angle = %.6g deg: with psi > phi the plastic "
                    "flow would create energy under confinement; use psi <= phi (0 for no "
                    "plastic volume change, phi for associated flow)",
                    psi_deg, phi_deg);
        if (m->cohesion == 0.0 && phi_deg == 0.0 && given(c, s, "cohesion") &&
            given(c, s, "friction_angle"))
            problem(r, "cohesion",
                    "cohesion = 0 and friction_angle = 0 give a cone of zero strength (the "
                    "material would flow under any shear); give c > 0 or phi > 0");
    } else {
        for (int i = 0; i < 3; i++)
            if (given(c, s, dp_keys[i]))
                problem(r, dp_keys[i],
                        "only used with constitutive = drucker_prager (this material is "
                        "%s)",
                        material_kind_name(m->kind));
    }
    return r->n;
}

int material_case_check(const fsi_case *c, const char *section, FILE *errors)
{
    material m;
    reporter r = {c, section, errors, NULL, 0, 0};
    return read_and_check(&m, &r);
}

int material_from_case(material *m, const fsi_case *c, const char *section, char *msg,
                       size_t msg_size)
{
    reporter r = {c, section, NULL, msg, msg_size, 0};
    if (msg && msg_size > 0)
        msg[0] = '\0';
    if (read_and_check(m, &r) > 0)
        return -1;
    material_derive(m);
    return 0;
}
