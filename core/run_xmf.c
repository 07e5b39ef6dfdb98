#include "run_xmf.h"

#include "log.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

int fsi_write_run_xmf(const char *dir, const char *const *names, int n)
{
    char path[4096], tmp[4112];
    if ((size_t)snprintf(path, sizeof path, "%s/run.xmf", dir) >= sizeof path) {
        fsi_error("cannot write %s/run.xmf: the path is too long", dir);
        return -1;
    }
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fsi_fopen_checked(tmp, "w");
    if (!f) {
        fsi_error("cannot write %s: %s", tmp, strerror(errno));
        return -1;
    }
    /* Each sidecar's temporal collection becomes a block (ParaView's Xdmf3 Reader T and
     * legacy XDMF Reader; Xdmf3 Reader S makes them pieces of one data set). */
    fputs("<?xml version=\"1.0\" ?>\n"
          "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
          "  <Domain>\n", f);
    for (int i = 0; i < n; i++)
        fprintf(f, "    <xi:include href=\"%s.xmf\" xpointer=\"xpointer(//Xdmf/Domain/Grid)\"/>\n",
                names[i]);
    fputs("  </Domain>\n"
          "</Xdmf>\n", f);
    int err = fsi_fclose_checked(f);
    if (err == 0 && rename(tmp, path) != 0)
        err = errno;
    if (err) {
        fsi_error("cannot write %s: %s", path, strerror(err));
        remove(tmp);
        return -1;
    }
    return 0;
}
