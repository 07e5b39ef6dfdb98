/* The least-squares fit's moment matrix inverse: see solid_fit.h. */
#include "solid_fit.h"

#include <math.h>
#include <string.h>

int solid_fit_inverse(const double *a, int n, double *out, double max_condition)
{
    double w[SOLID_FIT_MAX_BASIS * SOLID_FIT_MAX_BASIS];
    memcpy(w, a, sizeof(double) * (size_t)(n * n));
    for (int r = 0; r < n; r++)
        for (int c = 0; c < n; c++)
            out[r * n + c] = r == c;
    double norm_a = 0.0;
    for (int k = 0; k < n * n; k++)
        norm_a += a[k] * a[k];
    norm_a = sqrt(norm_a);
    for (int c = 0; c < n; c++) {
        int pivot = c;
        for (int r = c + 1; r < n; r++)
            if (fabs(w[r * n + c]) > fabs(w[pivot * n + c]))
                pivot = r;
        if (!(fabs(w[pivot * n + c]) > 1e-300 * norm_a))
            return -1;
        if (pivot != c)
            for (int k = 0; k < n; k++) {
                double t = w[c * n + k];
                w[c * n + k] = w[pivot * n + k];
                w[pivot * n + k] = t;
                t = out[c * n + k];
                out[c * n + k] = out[pivot * n + k];
                out[pivot * n + k] = t;
            }
        const double inv = 1.0 / w[c * n + c];
        for (int k = 0; k < n; k++) {
            w[c * n + k] *= inv;
            out[c * n + k] *= inv;
        }
        for (int r = 0; r < n; r++) {
            if (r == c || w[r * n + c] == 0.0)
                continue;
            const double f = w[r * n + c];
            for (int k = 0; k < n; k++) {
                w[r * n + k] -= f * w[c * n + k];
                out[r * n + k] -= f * out[c * n + k];
            }
        }
    }
    double norm_inv = 0.0;
    for (int k = 0; k < n * n; k++)
        norm_inv += out[k] * out[k];
    if (!(sqrt(norm_inv) * norm_a <= max_condition))
        return -1;
    /* Exactly symmetric, like A. */
    for (int r = 0; r < n; r++)
        for (int c = r + 1; c < n; c++)
            out[r * n + c] = out[c * n + r] = 0.5 * (out[r * n + c] + out[c * n + r]);
    return 0;
}

