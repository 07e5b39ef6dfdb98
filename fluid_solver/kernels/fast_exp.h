/* exp(-t), t >= 0, inline for the kernel of 000 Eq. 17 (gaussian_kernel.h).
 *
 * Why not libm's exp: it was a sixth of a step (a call per pair, with its error
 * handling); inline, the kernel values of a row are one loop without calls. The method
 * is the usual table-driven one: with N = round(-t 64 / ln 2), j = N mod 64 and
 * k = (N - j) / 64,
 *
 *     exp(-t) = 2^k 2^(j/64) exp(u),   u = -t - N ln 2 / 64,  |u| <= ln 2 / 128,
 *
 * ln 2 / 64 split in a part with 32 significant bits (N times it is exact) and the
 * rest, 2^(j/64) from the table below (each correctly rounded), exp(u) by its Taylor
 * series to u^5 (the next term is below 4e-17), 2^k built in the exponent bits. Within
 * a few units in the last place of libm's exp (unit test: 2.3e-16 relative over
 * [0, 40]). */
#ifndef FSI_FAST_EXP_H
#define FSI_FAST_EXP_H

#include <stdint.h>
#include <string.h>

/* 2^(j/64), j = 0 .. 63, correctly rounded. */
static const double fast_exp2_table[64] = {
    0x1.0000000000000p+0, 0x1.02c9a3e778061p+0, 0x1.059b0d3158574p+0,
    0x1.0874518759bc8p+0, 0x1.0b5586cf9890fp+0, 0x1.0e3ec32d3d1a2p+0,
    0x1.11301d0125b51p+0, 0x1.1429aaea92de0p+0, 0x1.172b83c7d517bp+0,
    0x1.1a35beb6fcb75p+0, 0x1.1d4873168b9aap+0, 0x1.2063b88628cd6p+0,
    0x1.2387a6e756238p+0, 0x1.26b4565e27cddp+0, 0x1.29e9df51fdee1p+0,
    0x1.2d285a6e4030bp+0, 0x1.306fe0a31b715p+0, 0x1.33c08b26416ffp+0,
    0x1.371a7373aa9cbp+0, 0x1.3a7db34e59ff7p+0, 0x1.3dea64c123422p+0,
    0x1.4160a21f72e2ap+0, 0x1.44e086061892dp+0, 0x1.486a2b5c13cd0p+0,
    0x1.4bfdad5362a27p+0, 0x1.4f9b2769d2ca7p+0, 0x1.5342b569d4f82p+0,
    0x1.56f4736b527dap+0, 0x1.5ab07dd485429p+0, 0x1.5e76f15ad2148p+0,
    0x1.6247eb03a5585p+0, 0x1.6623882552225p+0, 0x1.6a09e667f3bcdp+0,
    0x1.6dfb23c651a2fp+0, 0x1.71f75e8ec5f74p+0, 0x1.75feb564267c9p+0,
    0x1.7a11473eb0187p+0, 0x1.7e2f336cf4e62p+0, 0x1.82589994cce13p+0,
    0x1.868d99b4492edp+0, 0x1.8ace5422aa0dbp+0, 0x1.8f1ae99157736p+0,
    0x1.93737b0cdc5e5p+0, 0x1.97d829fde4e50p+0, 0x1.9c49182a3f090p+0,
    0x1.a0c667b5de565p+0, 0x1.a5503b23e255dp+0, 0x1.a9e6b5579fdbfp+0,
    0x1.ae89f995ad3adp+0, 0x1.b33a2b84f15fbp+0, 0x1.b7f76f2fb5e47p+0,
    0x1.bcc1e904bc1d2p+0, 0x1.c199bdd85529cp+0, 0x1.c67f12e57d14bp+0,
    0x1.cb720dcef9069p+0, 0x1.d072d4a07897cp+0, 0x1.d5818dcfba487p+0,
    0x1.da9e603db3285p+0, 0x1.dfc97337b9b5fp+0, 0x1.e502ee78b3ff6p+0,
    0x1.ea4afa2a490dap+0, 0x1.efa1bee615a27p+0, 0x1.f50765b6e4540p+0,
    0x1.fa7c1819e90d8p+0,
};

/* exp(-t) for 0 <= t <= 700, without a check (a loop of them can be vectorised). */
static inline double fast_exp_neg_unchecked(double t)
{
    const double inv_step = 92.33248261689366;       /* 64 / ln 2 */
    const double step_hi = 0.01083042469326756;      /* ln 2 / 64, 32 bits */
    const double step_lo = 2.9815858269852933e-12;   /* ln 2 / 64 - step_hi */
    const double shifter = 6755399441055744.0;       /* 1.5 2^52: rounds to an integer */
    const double shifted = -t * inv_step + shifter;
    const double n = shifted - shifter;
    int64_t bits;
    memcpy(&bits, &shifted, sizeof bits); /* low bits: 2^51 + N */
    const int j = (int)(bits & 63);
    const int64_t k = (int64_t)n - j; /* 64 k, exactly */
    const double u = (-t - n * step_hi) - n * step_lo;
    const double p =
        1.0 + u * (1.0 + u * (0.5 + u * (1.0 / 6.0 + u * (1.0 / 24.0 + u * (1.0 / 120.0)))));
    const int64_t scale_bits = (k / 64 + 1023) << 52;
    double scale;
    memcpy(&scale, &scale_bits, sizeof scale);
    return scale * (fast_exp2_table[j] * p);
}

/* exp(-t) for any t >= 0: 0 beyond 700 (far beyond any support), NaN for NaN. */
static inline double fast_exp_neg(double t)
{
    if (!(t <= 700.0))
        return t > 700.0 ? 0.0 : t;
    return fast_exp_neg_unchecked(t);
}

#endif
