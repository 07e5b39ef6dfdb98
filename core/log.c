#include "log.h"

#include <stdio.h>
#include <string.h>

static char log_name[64] = "fsi";

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
    fprintf(stderr, "[%s] %s%s\n", log_name, level, line);
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
