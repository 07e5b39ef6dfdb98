/* Messages to stderr with the process name in front, so interleaved output of
 * the coupler and the participants stays readable. */
#ifndef FSI_LOG_H
#define FSI_LOG_H

#include <stdarg.h>
#include <stdio.h>
#include <stddef.h>

#include "dim.h"

/* Name printed in front of every message ("coupler", "solid", ...). */
void fsi_log_set_name(const char *name);
const char *fsi_log_name(void);

void fsi_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void fsi_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void fsi_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* 0, or the errno of the first message that could not be written to stderr (under
 * fsi run: the process's OUT/<role>.log, e.g. on a full disk). */
int fsi_log_write_error(void);

/* Writes len bytes of buf to fd, going on after short writes and EINTR. Returns the
 * bytes written; when fewer than len, *err is the errno (ENOSPC when write gave 0). */
size_t fsi_write_all(int fd, const void *buf, size_t len, int *err);

/* Opens path for writing ("w": truncate, "a": append) as a stdio stream that keeps
 * the errno of its first failed write, so that fsi_fclose_checked reports the real
 * reason (e.g. "No space left on device") even when stdio flushed in between. NULL
 * with errno set when the file cannot be opened. */
FILE *fsi_fopen_checked(const char *path, const char *mode);

/* Flushes and closes a file written with stdio. Returns 0, or the errno of the first
 * failed write (EIO when the system gave none): a full disk shows up here at the
 * latest. The file is closed either way. */
int fsi_fclose_checked(FILE *f);

/* "x, y[, z]" of an FSI_DIM vector at full precision (%.9g) into buf; returns buf. */
#define FSI_VECTOR_TEXT_SIZE (FSI_DIM * 24 + 4)
const char *fsi_vector_text(char *buf, size_t size, const double *v);

/* Exit codes shared by every program of the project. */
enum {
    FSI_EXIT_OK = 0,
    FSI_EXIT_RUN_FAILURE = 1,
    FSI_EXIT_BAD_INPUT = 2,
    /* A process that stops because another one aborted the run: never the culprit,
     * so the launcher can name the process that really failed. */
    FSI_EXIT_STOPPED_BY_PEER = 3,
    /* A participant that stops because the coupler was silent for the watchdog
     * timeout: the coupler, not it, stopped answering, and the launcher names it. */
    FSI_EXIT_COUPLER_SILENT = 4
};

#endif
