#include "progress.h"

#include <unistd.h>

#include "timers.h"

void fsi_progress_init(fsi_progress *p, FILE *out, double interval, double t_end)
{
    p->out = out;
    p->interval = interval;
    p->t_end = t_end;
    p->wall_start = p->wall_last = fsi_wall_seconds();
    p->windows_last = 0;
    p->tty = isatty(fileno(out));
    p->detail[0] = '\0';
}

void fsi_duration_text(char *buf, size_t len, double s)
{
    /* Checked before the conversion: a long cannot hold every double (a run that has
     * barely started extrapolates to 1e300 s, which wrapped to a negative ETA). */
    if (!(s >= 0.0) || !(s < FSI_PROGRESS_MAX_SECONDS)) {
        snprintf(buf, len, "--:--:--");
        return;
    }
    long total = (long)(s + 0.5);
    snprintf(buf, len, "%ld:%02ld:%02ld", total / 3600, (total / 60) % 60, total % 60);
}

void fsi_progress_update(fsi_progress *p, double t, long windows, int force)
{
    double now = fsi_wall_seconds();
    if (!force && now - p->wall_last < p->interval)
        return;
    double elapsed = now - p->wall_start;
    double rate = (double)(windows - p->windows_last) / (now - p->wall_last + 1e-12);
    double fraction = p->t_end > 0 ? t / p->t_end : 1.0;
    char eta[32] = "--:--:--";
    if (fraction > 0)
        fsi_duration_text(eta, sizeof eta, elapsed * (1.0 - fraction) / fraction);
    char spent[32];
    fsi_duration_text(spent, sizeof spent, elapsed);
    fprintf(p->out, "%st = %.6g s / %.6g s (%5.1f %%) | %ld windows, %.0f windows/s | %s%s"
            "elapsed %s, ETA %s%s", p->tty ? "\r" : "", t, p->t_end, 100.0 * fraction, windows,
            rate, p->detail, p->detail[0] ? " | " : "", spent, eta, p->tty ? "   " : "\n");
    fflush(p->out);
    p->wall_last = now;
    p->windows_last = windows;
}
