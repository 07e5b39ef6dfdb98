/* Initial velocity fields (initial_velocity.h). */
#include "initial_velocity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* f(s) of the benchmark's mode shape (003 Eq. 52, docs/validation.md S2), unnormalised. */
static double mode_f(double s, double length)
{
    double kl = SOLID_MODE_KL, k = kl / length;
    return (cos(kl) + cosh(kl)) * (cosh(k * s) - cos(k * s)) +
           (sin(kl) - sinh(kl)) * (sinh(k * s) - sin(k * s));
}

double solid_cantilever_mode(double s, double length)
{
    if (s < 0.0 || !(length > 0.0))
        return 0.0;
    return mode_f(s, length) / mode_f(length, length);
}

int solid_initial_velocity(const fsi_case *c, const char *role, double c0, solid_particles *p,
                           char *msg, size_t msg_size)
{
    const char *kind = fsi_case_get(c, role, "initial_velocity");
    if (!kind || strcmp(kind, "none") == 0)
        return 0;
    if (strcmp(kind, "cantilever_mode") != 0) {
        snprintf(msg, msg_size, "[%s] initial_velocity: unknown field '%s'", role, kind);
        return -1;
    }
    double amplitude = fsi_case_get_real(c, role, "mode_amplitude", 0.01);
    double length = fsi_case_get_real(c, role, "mode_length", 0.0);
    double origin = fsi_case_get_real(c, role, "mode_origin", 0.0);
    if (!(length > 0.0)) {
        snprintf(msg, msg_size, "[%s] mode_length: cantilever_mode needs a length > 0", role);
        return -1;
    }
    double tip = amplitude * c0;
    if (!isfinite(tip)) {
        snprintf(msg, msg_size, "[%s] cantilever_mode: tip velocity mode_amplitude * c0 = "
                 "%g * %g is not finite", role, amplitude, c0);
        return -1;
    }
    for (int i = 0; i < p->n; i++) {
        if (p->flags[i] & SOLID_CLAMPED)
            continue;
        double s = p->x0[i * FSI_DIM] - origin;
        p->v[i * FSI_DIM + 1] = tip * solid_cantilever_mode(s, length);
    }
    return 0;
}
