/* Case files: INI text (sections, key = value, '#' or ';' comments), read with
 * Debian's libinih, checked against key tables, with every entry remembering the
 * file and line it came from so that errors can name them (docs/cases.md).
 *
 * Ownership: fsi_case_read() returns a case the caller frees with fsi_case_free();
 * strings returned by the getters belong to the case. */
#ifndef FSI_CASE_FILE_H
#define FSI_CASE_FILE_H

#include <stdio.h>

typedef enum {
    FSI_KEY_REAL,    /* a finite floating-point number, bounds checked */
    FSI_KEY_INT,     /* a whole number, bounds checked */
    FSI_KEY_BOOL,    /* true/false, yes/no, on/off, 1/0 */
    FSI_KEY_STRING,  /* any non-empty text */
    FSI_KEY_CHOICE,  /* one of the words in 'choices' */
    FSI_KEY_VECTOR   /* FSI_DIM reals separated by commas or blanks */
} fsi_key_type;

/* Bounds flags for REAL/INT keys. */
enum {
    FSI_BOUND_NONE = 0,
    FSI_BOUND_MIN = 1,          /* value >= min */
    FSI_BOUND_MIN_OPEN = 2,     /* value >  min */
    FSI_BOUND_MAX = 4           /* value <= max */
};

typedef struct {
    const char *key;
    fsi_key_type type;
    const char *unit;           /* "m", "s", "Pa", "-" for dimensionless */
    const char *default_value;  /* NULL: the key is required */
    int bounds;                 /* FSI_BOUND_* flags */
    double min, max;
    const char *choices;        /* FSI_KEY_CHOICE: words separated by '|' */
    const char *description;    /* one sentence for docs/cases.md */
} fsi_key_spec;

/* The keys of one section, or of one solver inside a participant section. */
typedef struct {
    const char *name;
    const char *description;
    const fsi_key_spec *keys;
    int n_keys;
} fsi_key_table;

/* A solver that can fill a participant section ([fluid] or [solid]):
 * 'solver = name' selects it and makes its keys valid in that section. */
typedef struct {
    const char *name;
    const char *role;           /* the section it may appear in: "fluid" or "solid" */
    const char *executable;     /* program in the build's bin directory */
    const char *description;
    const fsi_key_table *keys;
} fsi_solver_spec;

/* Everything validation needs to know: the fixed sections (e.g. [run]), the keys
 * every participant section has (solver, executable, ...), and the solvers. */
typedef struct {
    const fsi_key_table *sections;       /* fixed sections, each table's name = section */
    int n_sections;
    const fsi_key_table *participant;    /* keys common to [fluid] and [solid] */
    const char *const *roles;            /* participant section names */
    int n_roles;
    const fsi_solver_spec *solvers;
    int n_solvers;
} fsi_case_schema;

typedef struct fsi_case fsi_case;

/* Reads a case file. Syntax errors (a line that is neither a section, a key = value
 * nor a comment; a key before any section; a key given twice in a section) are
 * written to 'errors' as "FILE:LINE: message" and NULL is returned. */
fsi_case *fsi_case_read(const char *path, FILE *errors);

/* Applies a command-line override "section.key=value" (it wins over the file; its
 * origin in messages is "--set section.key=value"). Returns 0, or -1 with a message
 * on 'errors' when the text is not of that form. */
int fsi_case_override(fsi_case *c, const char *assignment, FILE *errors);

/* Checks every section and key against the schema and fills in defaults:
 * unknown section, unknown key (with a "did you mean" suggestion), missing required
 * key, bad value (type, bound, choice), unknown solver. Reports ALL errors, each as
 * "FILE:LINE: [section] key: message" (the section's header line for a missing key),
 * and returns how many there were (0 = valid). A participant section whose solver is
 * "external" must have 'executable' and may hold any other keys (passed through). */
int fsi_case_validate(fsi_case *c, const fsi_case_schema *schema, FILE *errors);

/* True when the case has this section. */
int fsi_case_has_section(const fsi_case *c, const char *section);

/* Resolved value as text, or NULL when absent (after validation, defaults count). */
const char *fsi_case_get(const fsi_case *c, const char *section, const char *key);

/* Typed getters for validated cases; 'fallback' is returned when absent. */
double fsi_case_get_real(const fsi_case *c, const char *section, const char *key, double fallback);
long fsi_case_get_int(const fsi_case *c, const char *section, const char *key, long fallback);
int fsi_case_get_bool(const fsi_case *c, const char *section, const char *key, int fallback);
/* Fills out[0..FSI_DIM-1]; returns 0, or -1 when absent. */
int fsi_case_get_vector(const fsi_case *c, const char *section, const char *key, double *out);

/* Writes the resolved case as an INI file: every section, every key including
 * defaults, each line commented with its origin ("# default", "# FILE:LINE",
 * "# --set"). Reading it back gives the same values. */
void fsi_case_write_resolved(const fsi_case *c, FILE *out);

/* The file the case was read from. */
const char *fsi_case_path(const fsi_case *c);

void fsi_case_free(fsi_case *c);

/* Writes docs/cases.md for a schema: one table per section and per solver with
 * key, type, unit, default (or "required"), allowed range or choices, meaning. */
void fsi_case_schema_markdown(const fsi_case_schema *schema, FILE *out);

#endif
