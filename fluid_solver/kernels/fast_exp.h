/* exp(-t), t >= 0, inline for the kernel of 000 Eq. 17 (gaussian_kernel.h).
 *
 * Why not libm's exp: it was a sixth of a step (a call per pair, with its error
 * handling). Why no table: a loop over a row's kernel values vectorises only without
 * a table lookup (a gather the compiler will not emit). The method: with
 * N = round(-t / ln 2),
 *
 *     exp(-t) = 2^N exp(u),   u = -t - N ln 2,  |u| <= ln 2 / 2,
 *
 * ln 2 split in a part with 32 significant bits (N times it is exact for |N| < 2^11)
 * and the rest (Cody and Waite's reduction), exp(u) by its Taylor series to u^12 (the
 * next term is below 2e-16 of it), 2^N built in the exponent bits from the integer the
 * rounding leaves in the low bits. Within a few units in the last place of libm's exp
 * (unit test: below 1e-15 relative over [0, 40]). */
#ifndef FSI_FAST_EXP_H
#define FSI_FAST_EXP_H

#include <stdint.h>
#include <string.h>

/* exp(-t) for 0 <= t <= 700, without a check or a branch (a loop of them vectorises). */
static inline double fast_exp_neg_unchecked(double t)
{
    const double inv_ln2 = 1.4426950408889634;      /* 1 / ln 2 */
    const double ln2_hi = 6.93147180369123816490e-01; /* ln 2, 32 bits */
    const double ln2_lo = 1.90821492927058770002e-10; /* ln 2 - ln2_hi */
    const double shifter = 6755399441055744.0;       /* 1.5 2^52: rounds to an integer */
    const double shifted = -t * inv_ln2 + shifter;
    const double n = shifted - shifter;
    const double u = (-t - n * ln2_hi) - n * ln2_lo;
    /* Taylor to u^12, Horner's rule (1/k! correctly rounded) */
    double p = 1.0 / 479001600.0;
    p = p * u + 1.0 / 39916800.0;
    p = p * u + 1.0 / 3628800.0;
    p = p * u + 1.0 / 362880.0;
    p = p * u + 1.0 / 40320.0;
    p = p * u + 1.0 / 5040.0;
    p = p * u + 1.0 / 720.0;
    p = p * u + 1.0 / 120.0;
    p = p * u + 1.0 / 24.0;
    p = p * u + 1.0 / 6.0;
    p = p * u + 0.5;
    p = p * u + 1.0;
    p = p * u + 1.0;
    /* shifted's low bits hold N (two's complement, mod 2^52): N + 1023 in the exponent
     * field, everything above it shifted out */
    uint64_t bits;
    memcpy(&bits, &shifted, sizeof bits);
    const uint64_t scale_bits = (bits + 1023u) << 52;
    double scale;
    memcpy(&scale, &scale_bits, sizeof scale);
    return scale * p;
}

/* exp(-t) for any t >= 0: 0 beyond 700 (far beyond any support), NaN for NaN. */
static inline double fast_exp_neg(double t)
{
    if (!(t <= 700.0))
        return t > 700.0 ? 0.0 : t;
    return fast_exp_neg_unchecked(t);
}

#endif
