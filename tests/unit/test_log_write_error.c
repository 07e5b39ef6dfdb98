#define _GNU_SOURCE /* mkstemp */
/* Unit test of the write checks in core/log.c: a message that cannot be written
 * (stderr on a full disk) is remembered, and fsi_fclose_checked reports a failed
 * write with its real reason. /dev/full fails every write with ENOSPC, as a full disk
 * does. */
#include "log.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "unit_check.h"

int main(void)
{
    FILE *full = fopen("/dev/full", "w");
    CHECK(full != NULL, "open /dev/full");
    if (full) {
        fprintf(full, "a row\n");
        CHECK(fsi_fclose_checked(full) == ENOSPC, "fsi_fclose_checked on a full disk");
    }
    /* The disk fills during a flush in the middle of the writes, then space comes
     * back before the close (on a shared disk another process removes a file; in a
     * run, the other participant's failed frame removes its temporary), so the final
     * flush succeeds: a plain stream only remembers that something failed
     * (fsi_fclose_checked could only say EIO); the checked one keeps the first errno.
     * A file size limit stands in for the full disk: it fails writes with EFBIG. */
    struct rlimit old_limit;
    CHECK(getrlimit(RLIMIT_FSIZE, &old_limit) == 0, "getrlimit");
    signal(SIGXFSZ, SIG_IGN);
    char path[] = "/tmp/test_log_write_error_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0, "mkstemp");
    if (fd >= 0) {
        close(fd);
        FILE *checked = fsi_fopen_checked(path, "w");
        CHECK(checked != NULL, "fsi_fopen_checked %s", path);
        struct rlimit small = old_limit;
        small.rlim_cur = 1000;
        CHECK(setrlimit(RLIMIT_FSIZE, &small) == 0, "setrlimit");
        for (int i = 0; checked && i < 2000; i++)
            fprintf(checked, "row %d of a document larger than the limit\n", i);
        CHECK(setrlimit(RLIMIT_FSIZE, &old_limit) == 0, "setrlimit back");
        if (checked) {
            fputs("the tail, written after space came back\n", checked);
            int err = fsi_fclose_checked(checked);
            CHECK(err == EFBIG, "fsi_fclose_checked after a write that failed mid-way: %d "
                  "(%s), expected the first failure's EFBIG", err, strerror(err));
        }
        remove(path);
    }
    FILE *good = fsi_fopen_checked("/dev/null", "a");
    CHECK(good != NULL, "fsi_fopen_checked /dev/null");
    if (good) {
        for (int i = 0; i < 10000; i++)
            fprintf(good, "row %d\n", i);
        CHECK(fsi_fclose_checked(good) == 0, "fsi_fclose_checked on a good checked stream");
    }
    FILE *ok = tmpfile();
    CHECK(ok != NULL, "tmpfile");
    if (ok) {
        fprintf(ok, "a row\n");
        CHECK(fsi_fclose_checked(ok) == 0, "fsi_fclose_checked on a good file");
    }
    /* Keep the report visible: it goes to stdout, the test's stderr is replaced. */
    fsi_info("written");
    CHECK(fsi_log_write_error() == 0, "no log failure yet");
    if (!freopen("/dev/full", "w", stderr)) {
        printf("FAIL: cannot point stderr at /dev/full\n");
        return 1;
    }
    fsi_error("lost on a full disk");
    int err = fsi_log_write_error();
    fsi_info("also lost");
    if (err != ENOSPC || fsi_log_write_error() != ENOSPC) {
        printf("FAIL: fsi_log_write_error() = %d after a lost message, expected ENOSPC\n", err);
        return 1;
    }
    return unit_check_report("test_log_write_error");
}
