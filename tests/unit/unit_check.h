/* The check macro every unit test uses: a failed check prints where and why and
 * is counted; the test's main returns unit_check_report() as its exit status. */
#ifndef FSI_UNIT_CHECK_H
#define FSI_UNIT_CHECK_H

#include <stdio.h>

static int failures;
static int checks;

#define CHECK(cond, ...)                                                    \
    do {                                                                    \
        checks++;                                                           \
        if (!(cond)) {                                                      \
            failures++;                                                     \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);            \
            fprintf(stderr, __VA_ARGS__);                                   \
            fputc('\n', stderr);                                            \
        }                                                                   \
    } while (0)

/* "NAME: N of M checks failed" or "NAME: all M checks passed"; 1 on failure. */
static inline int unit_check_report(const char *name)
{
    if (failures)
        fprintf(stderr, "%s: %d of %d checks failed\n", name, failures, checks);
    else
        printf("%s: all %d checks passed\n", name, checks);
    return failures ? 1 : 0;
}

#endif
