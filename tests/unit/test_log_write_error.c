/* Unit test of the write checks in core/log.c: a message that cannot be written
 * (stderr on a full disk) is remembered, and fsi_fclose_checked reports a failed
 * write. /dev/full fails every write with ENOSPC, as a full disk does. */
#include "log.h"

#include <errno.h>
#include <stdio.h>

#include "unit_check.h"

int main(void)
{
    FILE *full = fopen("/dev/full", "w");
    CHECK(full != NULL, "open /dev/full");
    if (full) {
        fprintf(full, "a row\n");
        CHECK(fsi_fclose_checked(full) == ENOSPC, "fsi_fclose_checked on a full disk");
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
