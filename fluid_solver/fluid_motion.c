/* Prescribed wall motions (fluid_motion.h). */
#include "fluid_motion.h"

#include <math.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

void fluid_motion_read(fluid_motion *m, const fsi_case *c, const char *section)
{
    memset(m, 0, sizeof *m);
    const char *kind = fsi_case_get(c, section, "motion");
    if (!kind || strcmp(kind, "harmonic") != 0)
        return;
    m->kind = FLUID_MOTION_HARMONIC;
    m->amplitude = fsi_case_get_real(c, section, "motion_amplitude", 0.0);
    m->period = fsi_case_get_real(c, section, "motion_period", 1.0);
    m->phase = fsi_case_get_real(c, section, "motion_phase", 0.0) * PI / 180.0;
    double e[FSI_DIM] = {0};
    if (fsi_case_get_vector(c, section, "motion_direction", e) != 0)
        e[0] = 1.0;
    double norm = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        norm += e[d] * e[d];
    norm = sqrt(norm);
    /* A zero direction is refused by fluid_check.c; here it simply means no motion. */
    for (int d = 0; d < FSI_DIM; d++)
        m->direction[d] = norm > 0.0 ? e[d] / norm : 0.0;
}

void fluid_motion_at(const fluid_motion *m, double t, double *displacement, double *velocity,
                     double *acceleration)
{
    double s = 0.0, v = 0.0, a = 0.0;
    if (m->kind == FLUID_MOTION_HARMONIC && m->period > 0.0) {
        const double w = 2.0 * PI / m->period, arg = w * t + m->phase;
        s = m->amplitude * (sin(arg) - sin(m->phase));
        v = m->amplitude * w * cos(arg);
        a = -m->amplitude * w * w * sin(arg);
    }
    for (int d = 0; d < FSI_DIM; d++) {
        if (displacement)
            displacement[d] = s * m->direction[d];
        if (velocity)
            velocity[d] = v * m->direction[d];
        if (acceleration)
            acceleration[d] = a * m->direction[d];
    }
}

double fluid_motion_reach(const fluid_motion *m, int d)
{
    /* sin(arg) - sin(phi) spans at most 2. */
    return m->kind == FLUID_MOTION_NONE ? 0.0 : 2.0 * fabs(m->amplitude * m->direction[d]);
}

int fluid_motion_same(const fluid_motion *a, const fluid_motion *b)
{
    if (a->kind != b->kind)
        return 0;
    if (a->kind == FLUID_MOTION_NONE)
        return 1;
    int same = a->amplitude == b->amplitude && a->period == b->period && a->phase == b->phase;
    for (int d = 0; d < FSI_DIM; d++)
        same = same && a->direction[d] == b->direction[d];
    return same;
}
