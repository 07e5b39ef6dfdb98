/* The keys of the ISPH scheme in [fluid.isph] (003 §2.1, docs/isph.md). */
#ifndef ISPH_KEYS_H
#define ISPH_KEYS_H

#include "case_file.h"

/* h / dx of the cubic B-spline (support 2h): 1.2, 003 §2.1. */
#define ISPH_H_OVER_DX 1.2
/* Cr of 003 Eq. 49, dt = Cr h / |u|max: 0.1 as 003 states for its runs. */
#define ISPH_COURANT 0.1
/* C of the shifting, 003 Eq. 21 ("0.01-0.1"; Xu et al. 2009 use 0.01-0.1). */
#define ISPH_SHIFTING 0.01
/* The cap of a shift as a fraction of h (Lind et al. 2012). */
#define ISPH_SHIFT_CAP 0.2
/* c_s of 003 Eq. 10 (Smagorinsky; 0.1 in all of 003's runs). */
#define ISPH_SMAGORINSKY 0.1
/* The Skillen et al. 2013 ramp of 003 Eq. 17 in div r (2D values). */
#define ISPH_SURFACE_LOWER 1.4
#define ISPH_SURFACE_UPPER 1.6
/* Where the free surface is, outside a surface particle, in spacings (isph_ppe.h). */
#define ISPH_SURFACE_OFFSET 0.5
/* k of the soft contact with walls and solid (004 Eq. 21: 0.01). */
#define ISPH_WALL_CONTACT 0.01
/* Relative residual of the pressure solve and its iteration cap. */
#define ISPH_PPE_TOLERANCE 1e-6
#define ISPH_PPE_MAX_ITERATIONS 2000
/* 003 Eq. 30: |d| |R_n| / (|u|max dt) in [5, 50]; the lower end. */
#define ISPH_FSI_LAYER 5.0

extern const fsi_key_table fsi_isph_keys;

/* The kernel support 2 h (003 §2.1) of the ISPH fluid of [role] (fsi_solver_spec.support). */
double isph_support(const fsi_case *c, const char *role);

#endif
