/* Frame 0 of every participant, without a run (write_initial.h). */
#include "write_initial.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "log.h"

/* Starts one participant alone and waits for it; its exit status, or -1. */
static int run_alone(participant_plan *p, const char *log_path)
{
    fsi_plan_environment(p);
    const pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        const int fd = open(log_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0)
            _exit(FSI_EXIT_RUN_FAILURE);
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        close(fd);
        for (int i = 0; p->env[i]; i++)
            putenv(p->env[i]);
        setenv("FSI_WRITE_INITIAL", "1", 1);
        unsetenv("FSI_RESTART_DIR");
        char *argv[] = {p->program, NULL};
        execv(p->program, argv);
        fprintf(stderr, "cannot start %s\n", p->program);
        _exit(FSI_EXIT_RUN_FAILURE);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int fsi_write_initial_frames(participant_plan *plan, int n_plan, const char *out_dir)
{
    char log_path[4200];
    for (int i = 0; i < n_plan; i++) {
        snprintf(log_path, sizeof log_path, "%s/%s.log", out_dir, plan[i].role);
        const int rc = run_alone(&plan[i], log_path);
        if (rc != 0) {
            fprintf(stderr, "fsi run: --write-initial: %s (%s) did not write frame 0 (exit "
                    "%d); see %s\n", plan[i].role, plan[i].program, rc, log_path);
            return -1;
        }
        printf("fsi run: frame 0 of %s written to %s/%s.h5\n", plan[i].role, out_dir,
               plan[i].role);
    }
    return 0;
}
