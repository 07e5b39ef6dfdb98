#define _GNU_SOURCE
#include "private_network.h"

#include <errno.h>
#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "log.h"

static int write_proc_file(const char *path, const char *text)
{
    int fd = open(path, O_WRONLY);
    if (fd < 0)
        return -1;
    ssize_t len = (ssize_t)strlen(text);
    ssize_t written = write(fd, text, (size_t)len);
    close(fd);
    return written == len ? 0 : -1;
}

/* Runs `ip ARGS...` and waits for it; iproute2 does the netlink work. */
static int run_ip(char *const argv[])
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        execvp("ip", argv);
        _exit(127);
    }
    int status;
    if (waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

/* A new user + network namespace with ourselves mapped to root inside, as
 * `unshare -rn` does; its only interface, loopback, is down. */
static int enter_namespace(void)
{
    uid_t uid = getuid();
    gid_t gid = getgid();
    if (unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) {
        fsi_error("cannot create a private network namespace (unshare: %s); user namespaces "
                  "may be disabled here: run with --lcm-url on a network of your own",
                  strerror(errno));
        return -1;
    }
    char map[64];
    /* Map ourselves to root inside, as `unshare -r` does, to own the new namespace. */
    if (write_proc_file("/proc/self/setgroups", "deny") != 0 && errno != ENOENT)
        goto map_failed;
    snprintf(map, sizeof map, "0 %u 1", (unsigned)uid);
    if (write_proc_file("/proc/self/uid_map", map) != 0)
        goto map_failed;
    snprintf(map, sizeof map, "0 %u 1", (unsigned)gid);
    if (write_proc_file("/proc/self/gid_map", map) != 0)
        goto map_failed;
    return 0;

map_failed:
    fsi_error("cannot map user ids in the private namespace: %s", strerror(errno));
    return -1;
}

int fsi_leave_network(void)
{
    return enter_namespace();
}

int fsi_enter_private_network(void)
{
    if (enter_namespace() != 0)
        return -1;
    char *const lo_up[] = {"ip", "link", "set", "lo", "up", NULL};
    char *const route[] = {"ip", "route", "add", "224.0.0.0/4", "dev", "lo", NULL};
    if (run_ip(lo_up) != 0 || run_ip(route) != 0) {
        fsi_error("cannot bring up loopback multicast in the private namespace "
                  "(is iproute2 installed? run launch/setup.sh)");
        return -1;
    }
    return 0;
}
