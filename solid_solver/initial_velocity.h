/* Initial velocity fields of the solid ([solid] initial_velocity).
 *
 * cantilever_mode: the first bending mode of a cantilever clamped at x = x_c
 * (mode_origin) with free end at x_c + L (mode_length), moving transversally along y
 * (benchmarks S2, 003 Eqs. 51-52 after Gray et al. 2001; S3 uses the same field):
 *     vy(x) = V0L c0 f(s) / f(L),  s = x - x_c,  k = 1.875 / L,
 *     f(s) = (cos kL + cosh kL)(cosh ks - cos ks) + (sin kL - sinh kL)(sinh ks - sin ks),
 * with V0L = mode_amplitude and c0 = sqrt(K / rho), K the bulk modulus (Gray et al.
 * 2001 and 003 define the sound speed this way; for a solid it is neither the P-wave
 * nor the bar speed, but it is what the published amplitudes A / L are scaled with).
 * So the free end starts with vy = V0L c0 exactly. Points with s < 0 (the clamp)
 * start at rest, and clamped points always do. */
#ifndef FSI_SOLID_INITIAL_VELOCITY_H
#define FSI_SOLID_INITIAL_VELOCITY_H

#include <stddef.h>

#include "case_file.h"
#include "solid_particles.h"

/* kL of the first cantilever mode (root of cos kL cosh kL = -1, rounded as in the
 * benchmark papers). */
#define SOLID_MODE_KL 1.875

/* f(s) / f(L) of the first cantilever mode for s = x - origin; 0 for s < 0. */
double solid_cantilever_mode(double s, double length);

/* Sets p->v from [role] initial_velocity (none leaves it at 0). c0 = sqrt(K / rho)
 * [m/s] comes from the material. Returns 0, or -1 with a message (missing
 * mode_length, a field that is not finite). */
int solid_initial_velocity(const fsi_case *c, const char *role, double c0, solid_particles *p,
                           char *msg, size_t msg_size);

#endif
