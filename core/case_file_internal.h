/* Helpers that core/case_file.c shares with core/case_schema_markdown.c; not for
 * use outside the case-file reader. */
#ifndef FSI_CASE_FILE_INTERNAL_H
#define FSI_CASE_FILE_INTERNAL_H

#include <stddef.h>

/* Shortest text that reads back as the same double, so bounds print as "0.1". */
void fsi_case_format_number(double x, char *buf, size_t size);

/* The words of a FSI_KEY_CHOICE 'choices' string ("a|b") as "a, b"; the caller
 * frees it. */
char *fsi_case_choices_text(const char *choices);

#endif
