/* The progress line's durations (coupler/progress.h): never negative, never an
 * overflowed number; "--:--:--" when unknown or beyond a thousand hours. The issue:
 * a run at t = 1e-300 s of 0.5 s printed "ETA -2562047788015215:-30:-8". And the
 * coupler's detail (the window, steps and speeds) printed in its place. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "progress.h"
#include "unit_check.h"

static void expect_text(double s, const char *want)
{
    char buf[32];
    fsi_duration_text(buf, sizeof buf, s);
    CHECK(strcmp(buf, want) == 0, "%g s: '%s', expected '%s'", s, buf, want);
}

int main(void)
{
    expect_text(0.0, "0:00:00");
    expect_text(59.4, "0:00:59");
    expect_text(3661.0, "1:01:01");
    expect_text(999.0 * 3600.0 + 59 * 60 + 59, "999:59:59");
    expect_text(FSI_PROGRESS_MAX_SECONDS, "--:--:--");
    expect_text(1e300, "--:--:--");
    expect_text(INFINITY, "--:--:--");
    expect_text(NAN, "--:--:--");
    expect_text(-1.0, "--:--:--");

    /* The whole line at the start of a run whose first window is tiny: the ETA
     * extrapolates to about 1e300 s. */
    FILE *f = tmpfile();
    CHECK(f != NULL, "tmpfile");
    if (!f)
        return unit_check_report("test_progress");
    fsi_progress p;
    fsi_progress_init(&p, f, 0.0, 0.5);
    p.wall_start -= 1.0;    /* a second of wall time has passed */
    fsi_progress_update(&p, 1e-300, 1, 1);
    fsi_progress_update(&p, 0.25, 2, 1);
    rewind(f);
    char line[256];
    int lines = 0;
    while (fgets(line, sizeof line, f)) {
        lines++;
        const char *eta = strstr(line, "ETA ");
        CHECK(eta != NULL, "no ETA in '%s'", line);
        if (!eta)
            continue;
        CHECK(strchr(eta, '-') == NULL || strncmp(eta, "ETA --:--:--", 12) == 0,
              "negative ETA: '%s'", line);
        if (lines == 1)
            CHECK(strncmp(eta, "ETA --:--:--", 12) == 0, "unknown ETA not dashed: '%s'", line);
        else
            CHECK(strncmp(eta, "ETA 0:00:01", 11) == 0, "half-way ETA: '%s'", line);
    }
    CHECK(lines == 2, "%d progress lines, expected 2", lines);
    fclose(f);

    /* The coupler's detail (window, steps, speeds) sits between the rate and the time. */
    f = tmpfile();
    CHECK(f != NULL, "tmpfile");
    if (!f)
        return unit_check_report("test_progress");
    fsi_progress_init(&p, f, 0.0, 0.5);
    snprintf(p.detail, sizeof p.detail, "window 1e-04 s | max speed fluid 2 m/s");
    fsi_progress_update(&p, 0.25, 2, 1);
    rewind(f);
    const char *got = fgets(line, sizeof line, f);
    CHECK(got && strstr(line, "windows/s | window 1e-04 s | max speed fluid 2 m/s | elapsed "),
          "detail not in its place: '%s'", got ? line : "");
    fclose(f);
    return unit_check_report("test_progress");
}
