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

typedef struct fsi_case fsi_case;

/* A kind of object section a solver accepts: repeated, named sections that belong
 * to the participant, written [ROLE.KIND NAME], e.g. [solid.block beam]. NAME is
 * one word of letters, digits, '_' and '-'; each object's keys are checked against
 * 'keys' and get its defaults, like an ordinary section. */
typedef struct {
    const char *kind;           /* e.g. "block" */
    const char *description;    /* for docs/cases.md */
    const fsi_key_table *keys;
    int min_count;              /* fewer objects of this kind is an error */
} fsi_object_kind;

/* The key a fluid solver's support radius is resolved into, in its participant
 * section (fsi_solver_spec.support): derived, never written by the user. */
#define FSI_CASE_SUPPORT_KEY "support"

/* A solver that can fill a participant section ([fluid] or [solid]):
 * 'solver = name' selects it and makes its keys valid in that section. */
typedef struct {
    const char *name;
    const char *role;           /* the section it may appear in: "fluid" or "solid" */
    const char *executable;     /* program in the build's bin directory */
    const char *description;
    /* 1 for the example participants of examples/ (no geometry; the template for a
     * program of one's own), 0 for the project's solvers (`fsi solvers` lists both). */
    int example;
    /* The keys of the participant section [ROLE] besides the common ones, in several
     * tables (e.g. keys every solid model has, material keys); a key may be defined
     * in only one of them (and not in own_keys). */
    const fsi_key_table *const *key_tables;
    int n_key_tables;
    /* The solver's own keys, written in its solver section [ROLE.NAME] (e.g.
     * [fluid.ulph]), or NULL when it has none there. Every solver section a case
     * holds is checked against its solver's table whether that solver is chosen or
     * not, so one case can carry the settings of several solvers; the chosen one's is
     * created with its defaults when absent (fsi_case_solver_section). */
    const fsi_key_table *own_keys;
    /* The radius [m] within which the solver's particle sums reach (a fluid's kernel
     * support) for a case whose participant section 'role' and solver section passed
     * their key checks, or NULL when it has none. fsi_case_validate writes it into
     * [ROLE] FSI_CASE_SUPPORT_KEY (origin "derived") before the semantic checks, so
     * that the other participant and the checks can read it without knowing the
     * solver (docs/coupling.md). */
    double (*support)(const fsi_case *c, const char *role);
    const fsi_object_kind *objects;     /* object sections it accepts, may be NULL */
    int n_objects;
    /* Semantic checks beyond single keys (e.g. overlapping blocks), or NULL. Called
     * by fsi_case_validate only when the participant section and all its object
     * sections passed the key checks, so every key has a valid value or default.
     * Writes each problem as one line "WHERE: message" to 'errors' (see
     * fsi_case_origin for WHERE) and returns how many it wrote. */
    int (*check)(const fsi_case *c, const char *role, FILE *errors);
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

/* Reads a case file. Syntax errors (a line that is neither a section, a key = value
 * nor a comment; a key before any section; a key or a section given twice) are
 * written to 'errors' as "FILE:LINE: message" and NULL is returned. Blanks inside
 * a section name are cut to one space: [solid.block   beam] is "solid.block beam". */
fsi_case *fsi_case_read(const char *path, FILE *errors);

/* The solver section of the solver chosen in [role] ("fluid.ulph" for solver = ulph),
 * owned by the case, or NULL when [role] names no solver or 'external'. It is the
 * section to read the solver's own keys from; after validation it exists (with the
 * defaults) when the solver has own keys. */
const char *fsi_case_solver_section(const fsi_case *c, const char *role);

/* Applies a command-line override "section.key=value" (it wins over the file; its
 * origin in messages is "--set section.key=value"). The key is the text between the
 * last '.' before the '=' and the '=', the section everything before that '.', so
 * "solid.block beam.max=1,0.2" sets 'max' in [solid.block beam] (keys containing a
 * '.' cannot be set this way). An absent section is created. Returns 0, or -1 with
 * a message on 'errors' when the text is not of that form. */
int fsi_case_override(fsi_case *c, const char *assignment, FILE *errors);

/* Checks every section and key against the schema and fills in defaults:
 * unknown section, unknown key (with a "did you mean" suggestion, or the section it
 * belongs in when it is another section's key), missing required key, bad value
 * (type, bound, choice), unknown solver, solver sections [ROLE.SOLVER] (each against
 * its solver's own_keys, chosen or not; an unknown one names the known solvers and
 * object kinds), object sections (unknown kind, bad name, no participant section,
 * fewer than min_count of a kind: reported at the participant's header line), a
 * value written for the derived FSI_CASE_SUPPORT_KEY. Creates the chosen solver's
 * section with its defaults when absent, resolves each support radius, then runs
 * each solver's 'check' whose participant passed. Reports ALL errors, each as "FILE:LINE: [section] key: message"
 * (the section's header line for a missing key), and returns how many there were
 * (0 = valid). A participant section whose solver is "external" must have
 * 'executable' and may hold any other keys and object sections (passed through;
 * only the form of their [ROLE.KIND NAME] headers is checked).
 * Flaws of the schema itself (a key defined twice for one section, a default that
 * breaks its own rule) are reported as "internal error in the case schema: ...". */
int fsi_case_validate(fsi_case *c, const fsi_case_schema *schema, FILE *errors);

/* Writes each flaw of the schema to 'errors' (may be NULL) and returns how many
 * there are: a key defined twice among the tables that apply to one solver (the
 * participant table, all its key_tables and its own_keys) or a table defining the
 * derived FSI_CASE_SUPPORT_KEY, two sections, solvers or object kinds of one name, a
 * solver named like an object kind of its role (both would be [ROLE.NAME...]), a
 * default its own key rejects, a solver whose role is no participant section, an
 * object kind that is not one word. */
int fsi_case_schema_check(const fsi_case_schema *schema, FILE *errors);

/* True when the case has this section. */
int fsi_case_has_section(const fsi_case *c, const char *section);

/* Resolved value as text, or NULL when absent (after validation, defaults count). */
const char *fsi_case_get(const fsi_case *c, const char *section, const char *key);

/* Typed getters for validated cases; 'fallback' is returned when absent. */
double fsi_case_get_real(const fsi_case *c, const char *section, const char *key, double fallback);
long fsi_case_get_int(const fsi_case *c, const char *section, const char *key, long fallback);
int fsi_case_get_bool(const fsi_case *c, const char *section, const char *key, int fallback);
/* 1 when the key's value (a choice) is word, 0 otherwise or when absent. */
int fsi_case_choice_is(const fsi_case *c, const char *section, const char *key, const char *word);
/* Fills out[0..FSI_DIM-1]; returns 0, or -1 when absent. */
int fsi_case_get_vector(const fsi_case *c, const char *section, const char *key, double *out);

/* Object sections [ROLE.KIND NAME] of one kind, in file order (sections created by
 * --set come after the file's): returns how many there are and puts the first
 * max_sections of their full section names ("solid.block beam", owned by the case)
 * in 'sections' (may be NULL when max_sections is 0), ready for the getters. Works
 * on unvalidated cases too. */
int fsi_case_objects(const fsi_case *c, const char *role, const char *kind,
                     const char **sections, int max_sections);

/* The NAME of an object section name "ROLE.KIND NAME" (a pointer into 'section'),
 * or NULL when 'section' is not of that form. */
const char *fsi_case_object_name(const char *section);

/* Where a value came from, for messages: "FILE:LINE" for a key of the file,
 * "--set section.key=value" for an override, "default" for a default, "derived" for
 * a value validation derived (FSI_CASE_SUPPORT_KEY), NULL when the key is absent. With key NULL: where the section starts (its header's
 * "FILE:LINE", the --set that created it, or "default" for a section the file
 * lacks). The string belongs to the case. */
const char *fsi_case_origin(const fsi_case *c, const char *section, const char *key);

/* Writes the resolved case as an INI file: every section (object and solver
 * sections included), every key including defaults and derived values, each section
 * header and key line commented with its origin ("# default", "# derived",
 * "# FILE:LINE", "# --set ..."). Reading it back gives the same sections and values,
 * and keys that were defaults or derived have that origin again (so a solver can
 * still tell what the user gave, and validating it again derives anew). */
void fsi_case_write_resolved(const fsi_case *c, FILE *out);

/* The file the case was read from. */
const char *fsi_case_path(const fsi_case *c);

void fsi_case_free(fsi_case *c);

/* Writes docs/cases.md for a schema: one table per section, per key table of each
 * solver, per solver section and per object kind, with key, type, unit, default
 * (or "required"), allowed range or choices, meaning. */
void fsi_case_schema_markdown(const fsi_case_schema *schema, FILE *out);

/* One part of that reference (`fsi keys NAME`): a fixed section ("run"), a solver
 * with its keys and object sections ("tlsph"), every solver of a role ("fluid"), or
 * "external". Returns 0, or -1 (nothing written) when NAME is none of them. */
int fsi_case_schema_markdown_part(const fsi_case_schema *schema, const char *name, FILE *out);

/* The names fsi_case_schema_markdown_part takes, separated by blanks. */
void fsi_case_schema_part_names(const fsi_case_schema *schema, FILE *out);

#endif
