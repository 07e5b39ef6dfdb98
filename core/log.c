#define _GNU_SOURCE /* fopencookie */
#include "log.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

/* A stdio stream over a file descriptor that keeps the errno of its first failed
 * write: stdio flushes its buffer in the middle of fprintf calls and later calls
 * overwrite errno, so without it a full disk could only be reported as EIO. */
typedef struct {
    int fd;
    int first_error;
} checked_stream;

size_t fsi_write_all(int fd, const void *buf, size_t len, int *err)
{
    size_t done = 0;
    while (done < len) {
        ssize_t k = write(fd, (const char *)buf + done, len - done);
        if (k < 0 && errno == EINTR)
            continue;
        if (k <= 0) {
            *err = k < 0 ? errno : ENOSPC;
            break;
        }
        done += (size_t)k;
    }
    return done;
}

static ssize_t checked_write(void *cookie, const char *buf, size_t size)
{
    checked_stream *s = cookie;
    int err = 0;
    size_t done = fsi_write_all(s->fd, buf, size, &err);
    if (done < size) {
        if (!s->first_error)
            s->first_error = err;
        errno = s->first_error;
        return done > 0 ? (ssize_t)done : -1;
    }
    return (ssize_t)done;
}

static int checked_close(void *cookie)
{
    checked_stream *s = cookie;
    int err = s->first_error;
    if (close(s->fd) != 0 && !err)
        err = errno;
    free(s);
    if (err) {
        errno = err;
        return -1;
    }
    return 0;
}

FILE *fsi_fopen_checked(const char *path, const char *mode)
{
    int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (mode[0] == 'a' ? O_APPEND : O_TRUNC);
    checked_stream *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->fd = open(path, flags, 0644);
    if (s->fd < 0) {
        int err = errno;
        free(s);
        errno = err;
        return NULL;
    }
    cookie_io_functions_t io = {.write = checked_write, .close = checked_close};
    FILE *f = fopencookie(s, "w", io);
    if (!f) {
        int err = errno;
        close(s->fd);
        free(s);
        errno = err;
    }
    return f;
}

int fsi_fclose_checked(FILE *f)
{
    errno = 0;
    int bad = fflush(f) != 0 || ferror(f);
    int err = errno;
    /* A stream of fsi_fopen_checked reports its first write error on close. */
    if (fclose(f) != 0) {
        if (!bad || !err)
            err = errno;
        bad = 1;
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
