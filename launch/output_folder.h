/* The output folder of `fsi run` and `fsi replay`: which files in it are a run's
 * (by name, one list in output_folder.c), the checks made before anything is
 * written, what --force removes, and the lock that keeps a second run out while
 * one is going. */
#ifndef FSI_OUTPUT_FOLDER_H
#define FSI_OUTPUT_FOLDER_H

/* The lock file in the output folder: flock'd for the life of the run and holding
 * its pid. It stays after the run and is never an earlier run's result. */
#define FSI_OUTPUT_LOCK ".fsi-run.lock"

/* Takes the output folder 'dir' for the calling process. Refuses (-1, a message
 * under 'command' naming the folder and the reason, nothing written) when 'dir' is
 * not a folder, cannot be read, written or entered, is held by another run (named
 * by its pid), or holds an earlier run's results and 'force' is 0. Otherwise it
 * creates the folder when missing, with 'force' removes the earlier run's files
 * (only those a run writes, by name), and returns the descriptor that holds the
 * lock: keep it open for the life of the run. It is closed on exec, so the
 * processes of the run never hold the lock after their supervisor is gone. */
int fsi_claim_output_dir(const char *dir, int force, const char *command);

/* The values of 'force': refuse earlier results, replace them (--force), or keep them
 * (fsi run --restart goes on with them). */
enum { FSI_CLAIM_REFUSE = 0, FSI_CLAIM_REPLACE = 1, FSI_CLAIM_KEEP = 2 };

#endif
