#include "log.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

static char log_name[64] = "fsi";
static int write_errno; /* errno of the first message that could not be written */

void fsi_log_set_name(const char *name)
{
    snprintf(log_name, sizeof log_name, "%s", name);
}

const char *fsi_log_name(void)
{
    return log_name;
}

static void log_line(const char *level, const char *fmt, va_list ap)
{
    char line[2048];
    vsnprintf(line, sizeof line, fmt, ap);
    /* One fprintf per line so lines of different processes do not interleave. */
    errno = 0;
    /* The flush matters only if stderr was made buffered (freopen). */
    if ((fprintf(stderr, "[%s] %s%s\n", log_name, level, line) < 0 || fflush(stderr) != 0) &&
        !write_errno)
        write_errno = errno ? errno : EIO;
}

int fsi_log_write_error(void)
{
    return write_errno;
}

void fsi_info(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("", fmt, ap);
    va_end(ap);
}

void fsi_warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("warning: ", fmt, ap);
    va_end(ap);
}

void fsi_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    log_line("error: ", fmt, ap);
    va_end(ap);
}

int fsi_fclose_checked(FILE *f)
{
    errno = 0;
    int bad = fflush(f) != 0 || ferror(f);
    int err = errno;
    if (fclose(f) != 0 && !bad) {
        bad = 1;
        err = errno;
    }
    return bad ? (err ? err : EIO) : 0;
}

const char *fsi_vector_text(char *buf, size_t size, const double *v)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int d = 0; d < FSI_DIM && len < size; d++) {
        int n = snprintf(buf + len, size - len, "%s%.9g", d ? ", " : "", v[d]);
        if (n < 0)
            break;
        len += (size_t)n;
    }
    return buf;
}
