/* Helpers of the NOSB-PD unit tests (test_nosbpd_*.c): a CHECK macro, cases written
 * to a scratch file, regular lattices of particles, and a small random generator.
 * Header-only (static functions) because every test is one executable; the
 * model-independent ones are unit_solid_model.h's. */
#ifndef TEST_NOSBPD_COMMON_H
#define TEST_NOSBPD_COMMON_H

#include "nosbpd.h"
#include "unit_solid_model.h"

#endif
