/* Case files (see case_file.h and docs/cases.md).
 *
 * The work is split between inih and our own line reader: inih pulls every line
 * through case_reader(), which counts lines, strips the byte-order mark and
 * leading blanks, handles blank lines, comments and [section] headers itself and
 * hands inih only the lines that should be "key = value". Debian's inih passes
 * no line number to the handler and does not report new sections, so this is how
 * every entry and every section learns the line it came from. A line handed to
 * inih for which the handler is not called was rejected by inih: a syntax error
 * at a line we know, which lets us report every one of them, not just the first.
 *
 * Errors are collected, sorted by position and printed together, so that one
 * run of the program shows the user everything that is wrong with the file. */
#include "case_file.h"
#include "case_file_internal.h"
#include "dim.h"

#include <ini.h>

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ memory */

/* A case file is tiny; running out of memory while reading one is not worth a
 * recovery path through every caller. */
static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (!q) {
        fputs("fsi_case: out of memory\n", stderr);
        abort();
    }
    return q;
}

static char *xstrndup(const char *s, size_t n)
{
    char *d = xrealloc(NULL, n + 1);
    memcpy(d, s, n);
    d[n] = '\0';
    return d;
}

static char *xstrdup(const char *s)
{
    return xstrndup(s, strlen(s));
}

static char *xvasprintf(const char *fmt, va_list ap)
{
    va_list ap2;
    va_copy(ap2, ap);
    int n = vsnprintf(NULL, 0, fmt, ap2);
    va_end(ap2);
    if (n < 0)
        return xstrdup("(unprintable message)");
    char *s = xrealloc(NULL, (size_t)n + 1);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    return s;
}

static char *xasprintf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static char *xasprintf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = xvasprintf(fmt, ap);
    va_end(ap);
    return s;
}

/* Makes room for one more element in a growing array. */
static void *grow(void *items, int n, int *cap, size_t size)
{
    if (n < *cap)
        return items;
    *cap = *cap ? 2 * *cap : 8;
    return xrealloc(items, (size_t)*cap * size);
}

/* ------------------------------------------------------------------- text */

static const char *skip_blanks(const char *s)
{
    while (*s && isspace((unsigned char)*s))
        s++;
    return s;
}

/* Copy of s[0..n) without leading and trailing blanks. */
static char *trimmed_copy(const char *s, size_t n)
{
    while (n > 0 && isspace((unsigned char)*s)) {
        s++;
        n--;
    }
    while (n > 0 && isspace((unsigned char)s[n - 1]))
        n--;
    return xstrndup(s, n);
}

/* A section name as the case stores it: trimmed, every run of blanks cut to one
 * space, so that [solid.block  beam], --set "solid.block beam.x=1" and the name
 * a solver gets from fsi_case_objects() are the same section. */
static char *section_name_copy(const char *s, size_t n)
{
    char *name = trimmed_copy(s, n);
    char *out = name;
    for (const char *p = name; *p; p++) {
        if (isspace((unsigned char)*p)) {
            if (out[-1] != ' ')     /* never at the start: the name is trimmed */
                *out++ = ' ';
        } else {
            *out++ = *p;
        }
    }
    *out = '\0';
    return name;
}

static int ascii_equal_nocase(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
            return 0;
    return *a == *b;
}

/* Shortest text that reads back as the same double, so bounds print as "0.1". */
void fsi_case_format_number(double x, char *buf, size_t size)
{
    snprintf(buf, size, "%.15g", x);
    if (strtod(buf, NULL) != x)
        snprintf(buf, size, "%.17g", x);
}

/* A list of names for "known: ..." lists and "did you mean" suggestions; the
 * names made by names_add_text belong to it. */
typedef struct {
    const char **items;
    int n, cap;
    char **owned;
    int n_owned, cap_owned;
} name_list;

static void names_add(name_list *l, const char *name)
{
    for (int i = 0; i < l->n; i++)
        if (strcmp(l->items[i], name) == 0)
            return;
    l->items = grow(l->items, l->n, &l->cap, sizeof *l->items);
    l->items[l->n++] = name;
}

static void names_add_text(name_list *l, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static void names_add_text(name_list *l, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *text = xvasprintf(fmt, ap);
    va_end(ap);
    l->owned = grow(l->owned, l->n_owned, &l->cap_owned, sizeof *l->owned);
    l->owned[l->n_owned++] = text;
    names_add(l, text);
}

static char *names_join(const name_list *l, const char *sep)
{
    size_t len = 1;
    for (int i = 0; i < l->n; i++)
        len += strlen(l->items[i]) + strlen(sep);
    char *s = xrealloc(NULL, len);
    s[0] = '\0';
    for (int i = 0; i < l->n; i++) {
        if (i > 0)
            strcat(s, sep);
        strcat(s, l->items[i]);
    }
    return s;
}

static void names_free(name_list *l)
{
    free(l->items);
    for (int i = 0; i < l->n_owned; i++)
        free(l->owned[i]);
    free(l->owned);
    *l = (name_list){ 0 };
}

static size_t levenshtein(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    size_t *row = xrealloc(NULL, (lb + 1) * sizeof *row);
    for (size_t j = 0; j <= lb; j++)
        row[j] = j;
    for (size_t i = 1; i <= la; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t up = row[j];
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    size_t d = row[lb];
    free(row);
    return d;
}

static int is_prefix(const char *prefix, const char *s)
{
    return strncmp(prefix, s, strlen(prefix)) == 0;
}

/* The known name the user most likely meant, or NULL. Short names get a
 * tighter limit, and a name is never "close" to one it shares no letter
 * position with, or "c" would suggest every one-letter choice. */
static const char *closest_name(const char *typed, const name_list *known)
{
    for (int i = 0; i < known->n; i++)      /* keys are case-sensitive; people forget */
        if (ascii_equal_nocase(typed, known->items[i]))
            return known->items[i];
    size_t lt = strlen(typed);
    size_t limit = lt <= 4 ? 1 : 2;
    const char *best = NULL;
    size_t best_d = limit + 1;
    for (int i = 0; i < known->n; i++) {
        size_t lk = strlen(known->items[i]);
        if ((lk > lt ? lk - lt : lt - lk) > limit)
            continue;               /* cannot be close enough; skip the O(n*m) work */
        size_t d = levenshtein(typed, known->items[i]);
        if (d < best_d && d < (lt < lk ? lt : lk)) {
            best_d = d;
            best = known->items[i];
        }
    }
    if (best)
        return best;
    for (int i = 0; i < known->n; i++) {
        const char *k = known->items[i];
        size_t lk = strlen(k);
        if ((lt <= lk ? lt : lk) >= 3 && (is_prefix(typed, k) || is_prefix(k, typed)))
            return k;
    }
    return NULL;
}

/* ------------------------------------------------------------------ model */

/* FROM_DERIVED: a value validation computed from others (FSI_CASE_SUPPORT_KEY). */
typedef enum { FROM_FILE, FROM_SET, FROM_DEFAULT, FROM_DERIVED } origin_kind;

/* Where a value or section came from, for messages and the resolved file. */
typedef struct {
    origin_kind kind;
    int line;           /* FROM_FILE: the line; FROM_SET: 1 for the first --set, ... */
    char *set_text;     /* FROM_SET: the assignment as the user typed it */
} origin;

typedef struct {
    char *key;
    char *value;
    origin from;
    char *label;        /* 'from' as text, for fsi_case_origin() */
} entry;

typedef struct {
    char *name;
    origin from;        /* the header line, or the --set that created the section */
    char *label;
    entry **entries;    /* pointers, so getters' strings survive later additions */
    int n_entries, cap_entries;
} section;

struct fsi_case {
    char *path;
    section **sections;
    int n_sections, cap_sections;
    int n_overrides;
    /* The names fsi_case_solver_section returned ("fluid.ulph"), kept so that they
     * stay valid as long as the case whether or not the section exists. */
    char **solver_sections;
    int n_solver_sections, cap_solver_sections;
};

static origin origin_copy(const origin *o)
{
    origin c = *o;
    c.set_text = o->set_text ? xstrdup(o->set_text) : NULL;
    return c;
}

/* "FILE:LINE" or "--set ..." for 'o'; for a default, 'default_text'. */
static char *origin_text(const fsi_case *c, const origin *o, const char *default_text)
{
    switch (o->kind) {
    case FROM_FILE:
        return xasprintf("%s:%d", c->path, o->line);
    case FROM_SET:
        return xasprintf("--set %s", o->set_text);
    case FROM_DEFAULT:
    case FROM_DERIVED:
        break;
    }
    return xstrdup(default_text);
}

/* What fsi_case_origin() says about a value or section from 'o'. */
static char *origin_label(const fsi_case *c, const origin *o)
{
    return origin_text(c, o, o->kind == FROM_DERIVED ? "derived" : "default");
}

/* NULL 'name' finds nothing, so the getters return their fallback for the section
 * of a participant without a solver (fsi_case_solver_section). */
static section *find_section(const fsi_case *c, const char *name)
{
    if (!name)
        return NULL;
    for (int i = 0; i < c->n_sections; i++)
        if (strcmp(c->sections[i]->name, name) == 0)
            return c->sections[i];
    return NULL;
}

static section *add_section(fsi_case *c, const char *name, const origin *from)
{
    section *s = xrealloc(NULL, sizeof *s);
    s->name = xstrdup(name);
    s->from = origin_copy(from);
    s->label = origin_label(c, from);
    s->entries = NULL;
    s->n_entries = s->cap_entries = 0;
    c->sections = grow(c->sections, c->n_sections, &c->cap_sections, sizeof *c->sections);
    c->sections[c->n_sections++] = s;
    return s;
}

static entry *find_entry(const section *s, const char *key)
{
    for (int i = 0; i < s->n_entries; i++)
        if (strcmp(s->entries[i]->key, key) == 0)
            return s->entries[i];
    return NULL;
}

static entry *add_entry(const fsi_case *c, section *s, const char *key, const char *value,
                        const origin *from)
{
    entry *e = xrealloc(NULL, sizeof *e);
    e->key = xstrdup(key);
    e->value = xstrdup(value);
    e->from = origin_copy(from);
    e->label = origin_label(c, from);
    s->entries = grow(s->entries, s->n_entries, &s->cap_entries, sizeof *s->entries);
    s->entries[s->n_entries++] = e;
    return e;
}

void fsi_case_free(fsi_case *c)
{
    if (!c)
        return;
    for (int i = 0; i < c->n_sections; i++) {
        section *s = c->sections[i];
        for (int j = 0; j < s->n_entries; j++) {
            free(s->entries[j]->key);
            free(s->entries[j]->value);
            free(s->entries[j]->from.set_text);
            free(s->entries[j]->label);
            free(s->entries[j]);
        }
        free(s->entries);
        free(s->name);
        free(s->from.set_text);
        free(s->label);
        free(s);
    }
    free(c->sections);
    for (int i = 0; i < c->n_solver_sections; i++)
        free(c->solver_sections[i]);
    free(c->solver_sections);
    free(c->path);
    free(c);
}

const char *fsi_case_path(const fsi_case *c)
{
    return c->path;
}

/* ------------------------------------------------------------ diagnostics */

/* Messages are sorted: file lines in order, then --set overrides in the order
 * given, then problems of the file as a whole (missing sections). */
enum { RANK_LINE, RANK_SET, RANK_FILE };

typedef struct {
    int rank;
    int line;
    int seq;
    char *text;
} diag;

typedef struct {
    diag *items;
    int n, cap;
} diag_list;

static void diag_add(diag_list *d, int rank, int line, char *text)
{
    d->items = grow(d->items, d->n, &d->cap, sizeof *d->items);
    d->items[d->n] = (diag){ rank, line, d->n, text };
    d->n++;
}

static int diag_has_line(const diag_list *d, int line)
{
    for (int i = 0; i < d->n; i++)
        if (d->items[i].rank == RANK_LINE && d->items[i].line == line)
            return 1;
    return 0;
}

static int diag_compare(const void *pa, const void *pb)
{
    const diag *a = pa, *b = pb;
    if (a->rank != b->rank)
        return a->rank < b->rank ? -1 : 1;
    if (a->line != b->line)
        return a->line < b->line ? -1 : 1;
    return a->seq < b->seq ? -1 : a->seq > b->seq;
}

/* Prints (when 'out' is given) and frees the messages; returns their number. */
static int diag_flush(diag_list *d, FILE *out)
{
    int n = d->n;
    if (n > 0)
        qsort(d->items, (size_t)n, sizeof *d->items, diag_compare);
    for (int i = 0; i < n; i++) {
        if (out)
            fprintf(out, "%s\n", d->items[i].text);
        free(d->items[i].text);
    }
    if (out)
        fflush(out);
    free(d->items);
    d->items = NULL;
    d->n = d->cap = 0;
    return n;
}

/* Where an error message points: a default has no line, so the file itself. */
static char *where_text(const fsi_case *c, const origin *o)
{
    return origin_text(c, o, c->path);
}

/* Adds "WHERE: [section] key: message", "WHERE: [section]: message" (no key) or
 * "WHERE: message" (no section). */
static void report(diag_list *d, const fsi_case *c, const origin *o, const char *sec,
                   const char *key, const char *fmt, ...) __attribute__((format(printf, 6, 7)));
static void report(diag_list *d, const fsi_case *c, const origin *o, const char *sec,
                   const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *msg = xvasprintf(fmt, ap);
    va_end(ap);
    char *where = where_text(c, o);
    char *text;
    if (sec && key)
        text = xasprintf("%s: [%s] %s: %s", where, sec, key, msg);
    else if (sec)
        text = xasprintf("%s: [%s]: %s", where, sec, msg);
    else
        text = xasprintf("%s: %s", where, msg);
    free(where);
    free(msg);
    int rank = o->kind == FROM_FILE ? RANK_LINE : o->kind == FROM_SET ? RANK_SET : RANK_FILE;
    diag_add(d, rank, o->line, text);
}

/* ---------------------------------------------------------------- reading */

static const char syntax_message[] =
    "syntax error: expected 'key = value', '[section]' or a comment";

typedef struct {
    FILE *file;
    fsi_case *c;
    diag_list *diags;
    char *buf;          /* the current physical line, any length */
    size_t cap;
    int lineno;
    int pending;        /* the current line went to inih, which has not accepted it yet */
    section *current;   /* NULL before the first section */
    int skip_keys;      /* after a rejected [section] line: its keys belong nowhere */
    int resolved;       /* the file is one fsi_case_write_resolved wrote */
    origin_kind line_kind;  /* resolved file: FROM_DEFAULT or FROM_DERIVED when the
                             * current key line ends in "; # default" or "; # derived" */
} read_state;

/* The first line of every file fsi_case_write_resolved writes. */
static const char resolved_marker[] = "# Resolved case read from ";
static const char default_label[] = "; # default";
static const char derived_label[] = "; # derived";

static int ends_with(const char *text, const char *label)
{
    size_t n = strlen(text), m = strlen(label);
    while (n > 0 && isspace((unsigned char)text[n - 1]))
        n--;
    return n >= m && strncmp(text + n - m, label, m) == 0;
}

/* In a resolved file a defaulted or derived key keeps its origin, so that a
 * participant reading it can still tell a key the user gave from one it may ignore,
 * and validating it again derives the value anew instead of refusing it. */
static origin_kind resolved_line_kind(const char *text)
{
    return ends_with(text, default_label)   ? FROM_DEFAULT
           : ends_with(text, derived_label) ? FROM_DERIVED
                                            : FROM_FILE;
}

static void line_error(read_state *st, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void line_error(read_state *st, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *msg = xvasprintf(fmt, ap);
    va_end(ap);
    origin o = { FROM_FILE, line, NULL };
    report(st->diags, st->c, &o, NULL, NULL, "%s", msg);
    free(msg);
}

/* inih calls the handler for an accepted line before it asks for the next one,
 * so a line still pending when the next is read was rejected by inih. */
static void settle_pending_line(read_state *st)
{
    if (st->pending && !diag_has_line(st->diags, st->lineno))
        line_error(st, st->lineno, "%s", syntax_message);
    st->pending = 0;
}

/* Reads one whole physical line with fgets, however long it is. */
static int read_physical_line(read_state *st)
{
    size_t len = 0;
    for (;;) {
        if (st->cap - len < 2) {
            st->cap = st->cap ? 2 * st->cap : 256;
            st->buf = xrealloc(st->buf, st->cap);
        }
        size_t room = st->cap - len;
        if (room > 1u << 30)
            room = 1u << 30;
        if (!fgets(st->buf + len, (int)room, st->file))
            return len > 0;
        len += strlen(st->buf + len);
        if (len > 0 && st->buf[len - 1] == '\n')
            return 1;
    }
}

/* Keys after a rejected header are not stored: they would land in the previous
 * section and cause confusing "given twice" errors. */
static void reject_section_line(read_state *st, const char *message)
{
    line_error(st, st->lineno, "%s", message);
    st->current = NULL;
    st->skip_keys = 1;
}

static void section_line(read_state *st, const char *text)
{
    const char *close = strchr(text + 1, ']');
    if (!close) {
        reject_section_line(st, "syntax error: '[' without a closing ']'");
        return;
    }
    const char *rest = skip_blanks(close + 1);
    if (*rest && *rest != ';' && *rest != '#') {
        char *msg = xasprintf("syntax error: unexpected text after ']': '%s'", rest);
        reject_section_line(st, msg);
        free(msg);
        return;
    }
    char *name = section_name_copy(text + 1, (size_t)(close - text - 1));
    if (!*name) {
        reject_section_line(st, "syntax error: empty section name");
    } else if (find_section(st->c, name)) {
        section *first = find_section(st->c, name);
        char *where = where_text(st->c, &first->from);
        char *msg = xasprintf("section [%s] given twice (first at %s)", name, where);
        reject_section_line(st, msg);
        free(msg);
        free(where);
    } else {
        origin o = { FROM_FILE, st->lineno, NULL };
        st->current = add_section(st->c, name, &o);
        st->skip_keys = 0;
    }
    free(name);
}

/* The ini_reader: see the comment at the top of the file. Lines we handle
 * ourselves reach inih as empty lines, which it skips. */
static char *case_reader(char *str, int num, void *stream)
{
    read_state *st = stream;
    settle_pending_line(st);
    if (!read_physical_line(st))
        return NULL;
    st->lineno++;
    char *text = st->buf;
    size_t len = strlen(text);
    while (len > 0 && (text[len - 1] == '\n' || text[len - 1] == '\r'))
        text[--len] = '\0';
    if (st->lineno == 1 && strncmp(text, "\xEF\xBB\xBF", 3) == 0)
        text += 3;
    if (st->lineno == 1)
        st->resolved = strncmp(text, resolved_marker, strlen(resolved_marker)) == 0;
    text = (char *)skip_blanks(text);
    str[0] = '\0';
    if (*text == '\0' || *text == ';' || *text == '#')
        return str;
    if (*text == '[') {
        section_line(st, text);
        return str;
    }
    /* inih's line buffer has 'num' bytes and would silently cut a longer line
     * in two; only key lines go to inih, so only they are limited. */
    if (strlen(text) > (size_t)num - 1) {
        line_error(st, st->lineno,
                   "line too long: %zu characters, at most %d are allowed in a 'key = value' line",
                   strlen(text), num - 1);
        return str;
    }
    memcpy(str, text, strlen(text) + 1);
    st->pending = 1;
    st->line_kind = st->resolved ? resolved_line_kind(text) : FROM_FILE;
    return str;
}

static int on_key(void *user, const char *inih_section, const char *name, const char *value)
{
    read_state *st = user;
    (void)inih_section;     /* cut at 50 bytes by inih; the reader tracks sections */
    st->pending = 0;
    origin here = { st->line_kind, st->lineno, NULL };
    if (!value) {           /* only if a program turned on ini_allow_no_value */
        line_error(st, st->lineno, "%s", syntax_message);
        return 1;
    }
    if (!*name) {
        line_error(st, st->lineno, "syntax error: key name missing before '='");
        return 1;
    }
    if (st->skip_keys)
        return 1;
    if (!st->current) {
        line_error(st, st->lineno, "key '%s' comes before any [section] line", name);
        return 1;
    }
    entry *old = find_entry(st->current, name);
    if (old) {
        report(st->diags, st->c, &here, st->current->name, name,
               "given twice (first at %s:%d)", st->c->path, old->from.line);
        return 1;
    }
    add_entry(st->c, st->current, name, value, &here);
    return 1;
}

static fsi_case *case_new(const char *path)
{
    fsi_case *c = xrealloc(NULL, sizeof *c);
    c->path = xstrdup(path);
    c->sections = NULL;
    c->n_sections = c->cap_sections = 0;
    c->n_overrides = 0;
    c->solver_sections = NULL;
    c->n_solver_sections = c->cap_solver_sections = 0;
    return c;
}

fsi_case *fsi_case_read(const char *path, FILE *errors)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        if (errors)
            fprintf(errors, "%s: cannot open case file: %s\n", path, strerror(errno));
        return NULL;
    }
    fsi_case *c = case_new(path);
    diag_list diags = { 0 };
    read_state st = { .file = f, .c = c, .diags = &diags };
    errno = 0;
    int r = ini_parse_stream(case_reader, &st, on_key, &st);
    int read_errno = errno;
    settle_pending_line(&st);
    /* Belt and braces: every line inih rejects should already be reported. */
    if (r > 0 && !diag_has_line(&diags, r))
        line_error(&st, r, "%s", syntax_message);
    origin whole = { FROM_DEFAULT, 0, NULL };
    if (r < 0)
        report(&diags, c, &whole, NULL, NULL, "the INI parser failed (inih error %d)", r);
    if (ferror(f))
        report(&diags, c, &whole, NULL, NULL, "cannot read case file after line %d: %s",
               st.lineno, strerror(read_errno ? read_errno : EIO));
    fclose(f);
    free(st.buf);
    if (diag_flush(&diags, errors) > 0) {
        fsi_case_free(c);
        return NULL;
    }
    return c;
}

/* -------------------------------------------------------------- overrides */

/* Names and values from --set must survive fsi_case_write_resolved and a new
 * read, so anything the case file syntax cannot express is refused here. */
static const char *bad_key_reason(const char *key)
{
    if (*key == '[' || *key == ';' || *key == '#')
        return "may not start with '[', ';' or '#'";
    for (const char *p = key; *p; p++)
        if (isspace((unsigned char)*p) || *p == ':' || *p == '=')
            return "may not contain blanks, ':' or '='";
    return NULL;
}

static const char *bad_value_reason(const char *value)
{
    if (*value == ';')
        return "value may not start with ';' (that starts a comment in case files)";
    for (const char *p = value; *p; p++)
        if (*p == ';' && p > value && isspace((unsigned char)p[-1]))
            return "value may not contain ';' after a blank (that starts a comment in case files)";
    return NULL;
}

/* The '.' between section and key in "section.key=value": the last one before
 * the '=', because object section names hold dots ("solid.block beam.max=1") and
 * keys do not; NULL when there is none. */
static const char *key_dot(const char *assignment, const char *eq)
{
    const char *dot = NULL;
    for (const char *p = assignment; p < eq; p++)
        if (*p == '.')
            dot = p;
    return dot;
}

static void set_value(fsi_case *c, const char *sec, const char *key, const char *value,
                      const origin *from)
{
    section *s = find_section(c, sec);
    if (!s)
        s = add_section(c, sec, from);
    entry *e = find_entry(s, key);
    if (!e) {
        add_entry(c, s, key, value, from);
        return;
    }
    free(e->value);
    free(e->from.set_text);
    free(e->label);
    e->value = xstrdup(value);
    e->from = origin_copy(from);
    e->label = origin_label(c, from);
}

int fsi_case_override(fsi_case *c, const char *assignment, FILE *errors)
{
    const char *eq = strchr(assignment, '=');
    const char *dot = eq ? key_dot(assignment, eq) : NULL;
    if (!dot) {
        if (errors)
            fprintf(errors, "--set %s: expected section.key=value\n", assignment);
        return -1;
    }
    if (strpbrk(assignment, "\n\r")) {
        if (errors)
            fprintf(errors, "--set %s: may not contain a line break\n", assignment);
        return -1;
    }
    char *sec = section_name_copy(assignment, (size_t)(dot - assignment));
    char *key = trimmed_copy(dot + 1, (size_t)(eq - dot - 1));
    char *value = trimmed_copy(eq + 1, strlen(eq + 1));
    const char *why = NULL;
    char *why_text = NULL;
    if (!*sec || !*key)
        why = "expected section.key=value";
    else if (strchr(sec, ']'))
        why = "section name may not contain ']'";
    else if (bad_key_reason(key))
        why = why_text = xasprintf("key '%s' %s", key, bad_key_reason(key));
    else
        why = bad_value_reason(value);
    if (why) {
        if (errors)
            fprintf(errors, "--set %s: %s\n", assignment, why);
    } else {
        origin from = { FROM_SET, ++c->n_overrides, (char *)assignment };
        set_value(c, sec, key, value, &from);
    }
    free(why_text);
    free(sec);
    free(key);
    free(value);
    return why ? -1 : 0;
}

/* ---------------------------------------------------------------- values */

typedef enum { NUM_OK, NUM_SYNTAX, NUM_RANGE, NUM_NOT_FINITE } num_status;

static num_status parse_real(const char *text, double *out)
{
    char *end;
    errno = 0;
    double x = strtod(text, &end);
    if (end == text || *skip_blanks(end) != '\0')
        return NUM_SYNTAX;
    if (errno == ERANGE && isinf(x))
        return NUM_RANGE;
    if (!isfinite(x))
        return NUM_NOT_FINITE;
    *out = x;               /* an underflow to (nearly) zero is accepted */
    return NUM_OK;
}

static num_status parse_int(const char *text, long *out)
{
    char *end;
    errno = 0;
    long n = strtol(text, &end, 10);
    if (end == text || *skip_blanks(end) != '\0')
        return NUM_SYNTAX;
    if (errno == ERANGE)
        return NUM_RANGE;
    *out = n;
    return NUM_OK;
}

static int parse_bool(const char *text, int *out)
{
    static const char *const yes[] = { "true", "yes", "on", "1" };
    static const char *const no[] = { "false", "no", "off", "0" };
    for (int i = 0; i < 4; i++) {
        if (ascii_equal_nocase(text, yes[i])) {
            *out = 1;
            return 1;
        }
        if (ascii_equal_nocase(text, no[i])) {
            *out = 0;
            return 1;
        }
    }
    return 0;
}

static char *number_problem(const char *text, num_status st, const char *what)
{
    switch (st) {
    case NUM_OK:
        return NULL;
    case NUM_SYNTAX:
        return xasprintf("'%s' is not %s", text, what);
    case NUM_RANGE:
        return xasprintf("'%s' is out of range", text);
    case NUM_NOT_FINITE:
        break;
    }
    return xasprintf("'%s' is not a finite number", text);
}

/* Parses FSI_DIM reals separated by commas and/or blanks; NULL or a message. */
static char *parse_vector(const char *text, double *out)
{
    int n = 0;
    const char *p = skip_blanks(text);
    while (*p) {
        const char *start = p;
        while (*p && *p != ',' && !isspace((unsigned char)*p))
            p++;
        if (p == start)
            return xasprintf("'%s' has an empty component (expected %d numbers separated "
                             "by commas or blanks)", text, FSI_DIM);
        char *token = xstrndup(start, (size_t)(p - start));
        double x = 0;
        num_status st = parse_real(token, &x);
        if (st != NUM_OK) {
            char *why = number_problem(token, st, "a number");
            char *msg = xasprintf("'%s' is not %d numbers: %s", text, FSI_DIM, why);
            free(why);
            free(token);
            return msg;
        }
        free(token);
        if (n < FSI_DIM)
            out[n] = x;
        n++;
        p = skip_blanks(p);
        if (*p == ',') {
            p = skip_blanks(p + 1);
            if (!*p || *p == ',')
                return xasprintf("'%s' has an empty component (expected %d numbers separated "
                                 "by commas or blanks)", text, FSI_DIM);
        }
    }
    if (n != FSI_DIM)
        return xasprintf("'%s' has %d number%s, expected %d separated by commas or blanks",
                         text, n, n == 1 ? "" : "s", FSI_DIM);
    return NULL;
}

/* Splits a copy of a choices string ("a|b") into words without surrounding
 * blanks; the words point into the returned buffer, freed by the caller. */
static char *choice_words(const char *choices, name_list *words)
{
    char *buf = xstrdup(choices ? choices : "");
    for (char *w = buf;;) {
        char *bar = strchr(w, '|');
        if (bar)
            *bar = '\0';
        char *end = w + strlen(w);
        while (end > w && isspace((unsigned char)end[-1]))
            *--end = '\0';
        names_add(words, skip_blanks(w));
        if (!bar)
            return buf;
        w = bar + 1;
    }
}

static int choice_matches(const char *choices, const char *value)
{
    name_list words = { 0 };
    char *buf = choice_words(choices, &words);
    int match = 0;
    for (int i = 0; i < words.n; i++)
        match |= strcmp(words.items[i], value) == 0;
    names_free(&words);
    free(buf);
    return match;
}

char *fsi_case_choices_text(const char *choices)
{
    name_list words = { 0 };
    char *buf = choice_words(choices, &words);
    char *text = names_join(&words, ", ");
    names_free(&words);
    free(buf);
    return text;
}

static char *choice_problem(const char *choices, const char *text)
{
    name_list words = { 0 };
    char *buf = choice_words(choices, &words);
    char *list = names_join(&words, ", ");
    const char *guess = closest_name(text, &words);
    char *msg = guess ? xasprintf("'%s' is not one of: %s (did you mean '%s'?)", text, list, guess)
                      : xasprintf("'%s' is not one of: %s", text, list);
    free(list);
    names_free(&words);
    free(buf);
    return msg;
}

static char *bound_problem(const fsi_key_spec *k, const char *text, double x)
{
    char num[40];
    if ((k->bounds & FSI_BOUND_MIN_OPEN) && !(x > k->min)) {
        fsi_case_format_number(k->min, num, sizeof num);
        return xasprintf("%s must be > %s", text, num);
    }
    if ((k->bounds & FSI_BOUND_MIN) && !(x >= k->min)) {
        fsi_case_format_number(k->min, num, sizeof num);
        return xasprintf("%s must be >= %s", text, num);
    }
    if ((k->bounds & FSI_BOUND_MAX) && !(x <= k->max)) {
        fsi_case_format_number(k->max, num, sizeof num);
        return xasprintf("%s must be <= %s", text, num);
    }
    return NULL;
}

/* What is wrong with 'text' as a value of key 'k', or NULL when it is fine. */
static char *value_problem(const fsi_key_spec *k, const char *text)
{
    if (!*text) {
        /* When the default itself is empty, writing it out must read back. */
        if (k->default_value && !*k->default_value)
            return NULL;
        return xstrdup("value is empty");
    }
    switch (k->type) {
    case FSI_KEY_REAL: {
        double x = 0;
        num_status st = parse_real(text, &x);
        return st != NUM_OK ? number_problem(text, st, "a number") : bound_problem(k, text, x);
    }
    case FSI_KEY_INT: {
        long n = 0;
        num_status st = parse_int(text, &n);
        return st != NUM_OK ? number_problem(text, st, "a whole number")
                            : bound_problem(k, text, (double)n);
    }
    case FSI_KEY_BOOL: {
        int b;
        if (parse_bool(text, &b))
            return NULL;
        return xasprintf("'%s' is not a boolean (expected true/false, yes/no, on/off or 1/0)",
                         text);
    }
    case FSI_KEY_STRING:
        return NULL;
    case FSI_KEY_CHOICE: {
        if (choice_matches(k->choices, text))
            return NULL;
        return choice_problem(k->choices, text);
    }
    case FSI_KEY_VECTOR: {
        double v[FSI_DIM];
        return parse_vector(text, v);
    }
    }
    return NULL;
}

/* ------------------------------------------------------------- validation */

/* The key tables that apply to one section, and keys handled elsewhere. */
typedef struct {
    const fsi_key_table **tables;
    int n_tables, cap_tables;
    const char *skip[4];        /* NULL-terminated: keys the caller checks itself */
    int report_unknown;         /* 0 for external solvers (pass-through) */
    const char *unknown_hint;   /* e.g. " with solver spring_oscillators" */
    name_list suggested;        /* keys offered as "did you mean" */
    /* For a participant section or a solver section: where an unknown key belongs
     * when another section of the role defines it (key_home). */
    const fsi_case_schema *schema;
    const char *role;
    const fsi_solver_spec *section_solver;  /* the solver of a solver section, else NULL */
} key_scope;

static char *key_home(const key_scope *sc, const char *key);

static void scope_add(key_scope *sc, const fsi_key_table *t)
{
    if (!t)
        return;
    sc->tables = grow(sc->tables, sc->n_tables, &sc->cap_tables, sizeof *sc->tables);
    sc->tables[sc->n_tables++] = t;
}

static void scope_free(key_scope *sc)
{
    free(sc->tables);
    sc->tables = NULL;
    sc->n_tables = sc->cap_tables = 0;
    names_free(&sc->suggested);
}

static int scope_skips(const key_scope *sc, const char *key)
{
    for (int i = 0; sc->skip[i]; i++)
        if (strcmp(sc->skip[i], key) == 0)
            return 1;
    return 0;
}

static const fsi_key_spec *scope_find(const key_scope *sc, const char *key)
{
    for (int t = 0; t < sc->n_tables; t++)
        for (int i = 0; i < sc->tables[t]->n_keys; i++)
            if (strcmp(sc->tables[t]->keys[i].key, key) == 0)
                return &sc->tables[t]->keys[i];
    return NULL;
}

static void report_unknown_key(diag_list *d, const fsi_case *c, const section *s,
                               const entry *e, key_scope *sc)
{
    char *home = key_home(sc, e->key);
    if (home) {
        report(d, c, &e->from, s->name, e->key, "%s", home);
        free(home);
        return;
    }
    name_list known = { 0 };
    for (int i = 0; sc->skip[i]; i++)
        if (strcmp(sc->skip[i], FSI_CASE_SUPPORT_KEY) != 0)     /* never to be written */
            names_add(&known, sc->skip[i]);
    for (int t = 0; t < sc->n_tables; t++)
        for (int i = 0; i < sc->tables[t]->n_keys; i++)
            names_add(&known, sc->tables[t]->keys[i].key);
    const char *guess = closest_name(e->key, &known);
    if (guess) {
        report(d, c, &e->from, s->name, e->key, "unknown key '%s' (did you mean '%s'?)",
               e->key, guess);
        names_add(&sc->suggested, guess);
    } else {
        char *list = names_join(&known, ", ");
        report(d, c, &e->from, s->name, e->key, "unknown key '%s' (known keys%s: %s)", e->key,
               sc->unknown_hint ? sc->unknown_hint : "", list);
        free(list);
    }
    names_free(&known);
}

/* Checks the values given for a section (defaults are not checked: they come
 * from the code, and an empty default may stand for "not set"). */
static void check_entries(diag_list *d, const fsi_case *c, const section *s, key_scope *sc)
{
    for (int i = 0; i < s->n_entries; i++) {
        const entry *e = s->entries[i];
        if (e->from.kind == FROM_DEFAULT || scope_skips(sc, e->key))
            continue;
        const fsi_key_spec *k = scope_find(sc, e->key);
        if (!k) {
            if (sc->report_unknown)
                report_unknown_key(d, c, s, e, sc);
            continue;
        }
        char *why = value_problem(k, e->value);
        if (why) {
            report(d, c, &e->from, s->name, e->key, "%s", why);
            free(why);
        }
    }
}

/* Reports missing required keys at the section's header and adds the defaults.
 * A required key already offered as "did you mean" for a misspelt key is not
 * reported again: the user has one mistake to fix, not two. */
static void fill_defaults(diag_list *d, const fsi_case *c, section *s, const key_scope *sc)
{
    static const origin by_default = { FROM_DEFAULT, 0, NULL };
    for (int t = 0; t < sc->n_tables; t++) {
        for (int i = 0; i < sc->tables[t]->n_keys; i++) {
            const fsi_key_spec *k = &sc->tables[t]->keys[i];
            if (scope_skips(sc, k->key) || find_entry(s, k->key))
                continue;
            int suggested = 0;
            for (int j = 0; j < sc->suggested.n; j++)
                suggested |= strcmp(sc->suggested.items[j], k->key) == 0;
            if (k->default_value)
                add_entry(c, s, k->key, k->default_value, &by_default);
            else if (!suggested)
                report(d, c, &s->from, s->name, k->key, "required key missing");
        }
    }
}

static void check_section(diag_list *d, const fsi_case *c, section *s, key_scope *sc)
{
    check_entries(d, c, s, sc);
    fill_defaults(d, c, s, sc);
    scope_free(sc);
}

static const fsi_key_table *find_table(const fsi_key_table *tables, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(tables[i].name, name) == 0)
            return &tables[i];
    return NULL;
}

/* Index of the participant section 'name' in the schema, or -1. */
static int role_index(const fsi_case_schema *schema, const char *name)
{
    for (int i = 0; i < schema->n_roles; i++)
        if (strcmp(schema->roles[i], name) == 0)
            return i;
    return -1;
}

static const fsi_solver_spec *find_solver(const fsi_case_schema *schema, const char *name)
{
    for (int i = 0; i < schema->n_solvers; i++)
        if (strcmp(schema->solvers[i].name, name) == 0)
            return &schema->solvers[i];
    return NULL;
}

static const fsi_object_kind *find_kind(const fsi_solver_spec *spec, const char *kind)
{
    for (int i = 0; i < spec->n_objects; i++)
        if (strcmp(spec->objects[i].kind, kind) == 0)
            return &spec->objects[i];
    return NULL;
}

typedef enum {
    ROLE_ABSENT,        /* no participant section */
    ROLE_UNSURE,        /* its solver is missing or wrong: already an error there */
    ROLE_EXTERNAL,      /* solver = external: everything passes through */
    ROLE_SOLVER         /* a solver of the schema for this role */
} role_state;

/* What the participant section 'role' says about its solver. */
static role_state role_solver(const fsi_case *c, const fsi_case_schema *schema,
                              const char *role, const fsi_solver_spec **spec)
{
    *spec = NULL;
    const section *s = find_section(c, role);
    if (!s)
        return ROLE_ABSENT;
    const entry *e = find_entry(s, "solver");
    if (!e || !*e->value)
        return ROLE_UNSURE;
    if (strcmp(e->value, "external") == 0)
        return ROLE_EXTERNAL;
    const fsi_solver_spec *found = find_solver(schema, e->value);
    if (!found || strcmp(found->role, role) != 0)
        return ROLE_UNSURE;
    *spec = found;
    return ROLE_SOLVER;
}

static void role_solvers(const fsi_case_schema *schema, const char *role, name_list *out)
{
    for (int i = 0; i < schema->n_solvers; i++)
        if (strcmp(schema->solvers[i].role, role) == 0)
            names_add(out, schema->solvers[i].name);
    names_add(out, "external");
}

static void report_bad_solver(diag_list *d, const fsi_case *c, const section *s,
                              const entry *e, const fsi_case_schema *schema)
{
    name_list known = { 0 };
    role_solvers(schema, s->name, &known);
    char *list = names_join(&known, ", ");
    const fsi_solver_spec *other = find_solver(schema, e->value);
    if (other) {
        report(d, c, &e->from, s->name, "solver",
               "'%s' is a %s solver, not a %s solver (%s solvers: %s)", e->value, other->role,
               s->name, s->name, list);
    } else {
        const char *guess = closest_name(e->value, &known);
        char *hint = guess ? xasprintf(" (did you mean '%s'?)", guess) : xstrdup("");
        report(d, c, &e->from, s->name, "solver", "unknown solver '%s'%s; %s solvers: %s",
               e->value, hint, s->name, list);
        free(hint);
    }
    free(list);
    names_free(&known);
}

/* The solver of role 'role' called 'name', or NULL. */
static const fsi_solver_spec *find_role_solver(const fsi_case_schema *schema, const char *role,
                                               const char *name)
{
    const fsi_solver_spec *sv = find_solver(schema, name);
    return sv && strcmp(sv->role, role) == 0 ? sv : NULL;
}

static int table_has(const fsi_key_table *t, const char *key)
{
    for (int i = 0; t && i < t->n_keys; i++)
        if (strcmp(t->keys[i].key, key) == 0)
            return 1;
    return 0;
}

/* True when 'key' is written in [ROLE] for solver sv: a common key or one of its
 * key_tables. */
static int participant_has(const fsi_case_schema *schema, const fsi_solver_spec *sv,
                           const char *key)
{
    if (table_has(schema->participant, key))
        return 1;
    for (int i = 0; i < sv->n_key_tables; i++)
        if (table_has(sv->key_tables[i], key))
            return 1;
    return 0;
}

/* Where a key that is unknown in the section of scope sc belongs, when another
 * section of the role defines it: "a key of solver ulph; write it in [fluid.ulph]"
 * for a solver's own key in [fluid] or in another solver's section, "a key of
 * [fluid]; write it there" for a participant key in a solver section. NULL when no
 * section of the role knows it. Each key has one place (fsi_case_schema_check). */
static char *key_home(const key_scope *sc, const char *key)
{
    if (!sc->schema)
        return NULL;
    if (sc->section_solver && participant_has(sc->schema, sc->section_solver, key))
        return xasprintf("a key of [%s], not of its solver section; write it there", sc->role);
    name_list owners = { 0 }, places = { 0 };
    for (int i = 0; i < sc->schema->n_solvers; i++) {
        const fsi_solver_spec *sv = &sc->schema->solvers[i];
        if (strcmp(sv->role, sc->role) != 0 || sv == sc->section_solver ||
            !table_has(sv->own_keys, key))
            continue;
        names_add(&owners, sv->name);
        names_add_text(&places, "[%s.%s]", sv->role, sv->name);
    }
    char *home = NULL;
    if (owners.n > 0) {
        char *who = names_join(&owners, ", ");
        char *where = names_join(&places, " or ");
        home = xasprintf("a key of solver%s %s; write it in %s", owners.n > 1 ? "s" : "", who,
                         where);
        free(who);
        free(where);
    }
    names_free(&owners);
    names_free(&places);
    return home;
}

/* FSI_CASE_SUPPORT_KEY is derived (fsi_case_validate): a value the user wrote is
 * refused rather than silently replaced. One read back from a resolved file
 * (origin derived) is derived anew. */
static void refuse_derived(diag_list *d, const fsi_case *c, const section *s)
{
    const entry *e = find_entry(s, FSI_CASE_SUPPORT_KEY);
    if (e && (e->from.kind == FROM_FILE || e->from.kind == FROM_SET))
        report(d, c, &e->from, s->name, e->key,
               "a derived value, not a setting: validation writes the fluid solver's support "
               "radius (from its own keys and spacing) into the resolved case; remove it");
}

/* 'solver = external' runs a program of the user's: it must be named. */
static void check_external(diag_list *d, const fsi_case *c, const section *s)
{
    const entry *e = find_entry(s, "executable");
    if (!e)
        report(d, c, &s->from, s->name, "executable",
               "required key missing (solver = external needs the program to run)");
    else if (!*e->value)
        report(d, c, &e->from, s->name, "executable",
               "value is empty (solver = external needs the program to run)");
    /* Implicit coupling and coupled checkpoints restore a participant's state: a program
     * that cannot must say so before the run, not fail in it (docs/checkpoints.md). */
    const int implicit = fsi_case_choice_is(c, "run", "scheme", "implicit");
    const int checkpoints = fsi_case_get_real(c, "run", "checkpoint_interval", 0.0) > 0.0;
    if ((implicit || checkpoints) && !fsi_case_get_bool(c, s->name, "checkpoints", 0)) {
        const entry *k = find_entry(s, "checkpoints");
        report(d, c, k ? &k->from : &s->from, s->name, "checkpoints",
               implicit ? "the run's scheme = implicit repeats windows, which needs a program "
                          "that saves and restores its state (fsi_requires_writing_checkpoint, "
                          "docs/participant_api.md): set checkpoints = true if this one does"
                        : "the run takes coupled checkpoints (checkpoint_interval), which needs "
                          "a program that writes its state (fsi_write_checkpoint, "
                          "docs/checkpoints.md): set checkpoints = true if this one does");
    }
}

static void validate_participant(diag_list *d, const fsi_case *c, section *s,
                                 const fsi_case_schema *schema)
{
    key_scope sc = { .skip = { "solver", FSI_CASE_SUPPORT_KEY, NULL, NULL },
                     .report_unknown = 1, .schema = schema, .role = s->name };
    scope_add(&sc, schema->participant);
    refuse_derived(d, c, s);
    const entry *solver = find_entry(s, "solver");
    char *hint = NULL;
    if (!solver) {
        report(d, c, &s->from, s->name, "solver", "required key missing");
        sc.report_unknown = 0;  /* without a solver we cannot tell which keys are valid */
    } else if (!*solver->value) {
        report(d, c, &solver->from, s->name, "solver", "value is empty");
        sc.report_unknown = 0;
    } else if (strcmp(solver->value, "external") == 0) {
        sc.skip[2] = "executable";
        sc.report_unknown = 0;
        check_external(d, c, s);
    } else {
        const fsi_solver_spec *spec = find_solver(schema, solver->value);
        if (!spec || strcmp(spec->role, s->name) != 0) {
            report_bad_solver(d, c, s, solver, schema);
            sc.report_unknown = 0;
        } else {
            for (int i = 0; i < spec->n_key_tables; i++)
                scope_add(&sc, spec->key_tables[i]);
            hint = xasprintf(" with solver %s", spec->name);
            sc.unknown_hint = hint;
        }
    }
    check_section(d, c, s, &sc);
    free(hint);
}

/* ----------------------------------------------------------- object sections */

/* "ROLE.KIND NAME" taken apart; role and kind are copies, name points into the
 * section name ("" when it has none). */
typedef struct {
    char *role;
    char *kind;
    const char *name;
} object_header;

/* Splits a section name whose first word holds a '.'; returns 0 for any other. */
static int split_object_header(const char *section_name, object_header *h)
{
    const char *blank = strchr(section_name, ' ');
    size_t word = blank ? (size_t)(blank - section_name) : strlen(section_name);
    const char *dot = memchr(section_name, '.', word);
    if (!dot)
        return 0;
    h->role = xstrndup(section_name, (size_t)(dot - section_name));
    h->kind = xstrndup(dot + 1, word - (size_t)(dot + 1 - section_name));
    h->name = blank ? blank + 1 : "";
    return 1;
}

static void free_object_header(object_header *h)
{
    free(h->role);
    free(h->kind);
}

/* Object names are one word so that --set, the resolved file and messages can
 * quote them without ambiguity; ASCII only, whatever the locale. */
static int is_name_char(char ch)
{
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
           ch == '_' || ch == '-';
}

/* Returns 0 when the name is missing: such a header is no object a solver will
 * see (fsi_case_objects skips it), so its keys are not worth reporting. */
static int check_object_name(diag_list *d, const fsi_case *c, const section *s,
                             const object_header *h)
{
    if (!*h->name) {
        report(d, c, &s->from, s->name, NULL,
               "object name missing (object sections are written [%s.%s NAME])", h->role,
               h->kind);
        return 0;
    }
    for (const char *p = h->name; *p; p++) {
        if (!is_name_char(*p)) {
            report(d, c, &s->from, s->name, NULL,
                   "object name '%s' must be one word of letters, digits, '_' and '-'",
                   h->name);
            break;
        }
    }
    return 1;
}

static void report_unknown_role(diag_list *d, const fsi_case *c, const section *s,
                                const fsi_case_schema *schema, const char *role)
{
    name_list roles = { 0 };
    for (int i = 0; i < schema->n_roles; i++)
        names_add(&roles, schema->roles[i]);
    const char *guess = closest_name(role, &roles);
    char *hint = guess ? xasprintf(" (did you mean '%s'?)", guess) : xstrdup("");
    char *list = names_join(&roles, ", ");
    report(d, c, &s->from, s->name, NULL,
           "unknown participant '%s'%s; object sections are written [ROLE.KIND NAME] with "
           "ROLE one of: %s", role, hint, list);
    free(list);
    free(hint);
    names_free(&roles);
}

static void report_unknown_kind(diag_list *d, const fsi_case *c, const section *s,
                                const fsi_solver_spec *spec, const char *kind)
{
    if (spec->n_objects == 0) {
        report(d, c, &s->from, s->name, NULL,
               "unknown object kind '%s' for solver %s (it takes no object sections)", kind,
               spec->name);
        return;
    }
    name_list kinds = { 0 };
    for (int i = 0; i < spec->n_objects; i++)
        names_add(&kinds, spec->objects[i].kind);
    const char *guess = closest_name(kind, &kinds);
    char *hint = guess ? xasprintf("did you mean '%s'? ", guess) : xstrdup("");
    char *list = names_join(&kinds, ", ");
    report(d, c, &s->from, s->name, NULL, "unknown object kind '%s' for solver %s (%skinds: %s)",
           kind, spec->name, hint, list);
    free(list);
    free(hint);
    names_free(&kinds);
}

static void check_object_keys(diag_list *d, const fsi_case *c, section *s,
                              const object_header *h, const fsi_object_kind *kind)
{
    key_scope sc = { .report_unknown = 1 };
    scope_add(&sc, kind->keys);
    char *hint = xasprintf(" of [%s.%s NAME]", h->role, h->kind);
    sc.unknown_hint = hint;
    check_section(d, c, s, &sc);
    free(hint);
}

/* [ROLE.WORD] without a name where WORD is no solver of the role, nor an object
 * kind of the chosen solver 'spec' (NULL when none is chosen): the error names both
 * lists. */
static void report_unknown_solver_section(diag_list *d, const fsi_case *c, const section *s,
                                          const fsi_case_schema *schema,
                                          const object_header *h, const fsi_solver_spec *spec)
{
    name_list solvers = { 0 }, known = { 0 };
    for (int i = 0; i < schema->n_solvers; i++) {
        const fsi_solver_spec *sv = &schema->solvers[i];
        if (strcmp(sv->role, h->role) != 0)
            continue;
        names_add(&known, sv->name);
        names_add_text(&solvers, "[%s.%s]", h->role, sv->name);
    }
    char *kinds = NULL;
    if (spec) {
        name_list objects = { 0 };
        for (int i = 0; i < spec->n_objects; i++) {
            names_add(&known, spec->objects[i].kind);
            names_add_text(&objects, "[%s.%s NAME]", h->role, spec->objects[i].kind);
        }
        char *list = names_join(&objects, ", ");
        kinds = objects.n > 0 ? xasprintf(" nor an object kind of solver %s (object sections: "
                                          "%s)", spec->name, list)
                              : xasprintf(", and solver %s takes no object sections", spec->name);
        free(list);
        names_free(&objects);
    } else {
        kinds = xasprintf("; object sections are written [%s.KIND NAME]", h->role);
    }
    const char *guess = closest_name(h->kind, &known);
    char *hint = guess ? xasprintf(" (did you mean '%s'?)", guess) : xstrdup("");
    char *list = names_join(&solvers, ", ");
    const int neither = spec && spec->n_objects > 0;
    report(d, c, &s->from, s->name, NULL, "unknown section: '%s'%s is %s %s solver (solver "
           "sections: %s)%s", h->kind, hint, neither ? "neither a" : "no", h->role, list, kinds);
    free(list);
    free(hint);
    free(kinds);
    names_free(&solvers);
    names_free(&known);
}

/* An object section [ROLE.KIND NAME] (the name's first word holds a '.'). Its
 * keys are checked only when its participant runs a solver of the schema:
 * external programs get theirs unchecked, and when the participant's solver is
 * wrong that is the one error to report. The name is checked in every case,
 * because --set and the resolved file rely on its form. */
static void validate_object(diag_list *d, const fsi_case *c, section *s,
                            const fsi_case_schema *schema, const object_header *h)
{
    if (role_index(schema, h->role) < 0) {
        report_unknown_role(d, c, s, schema, h->role);
        return;
    }
    if (!*h->kind) {
        report(d, c, &s->from, s->name, NULL,
               "object kind missing (object sections are written [%s.KIND NAME])", h->role);
        return;
    }
    const fsi_solver_spec *spec;
    const role_state state = role_solver(c, schema, h->role, &spec);
    if (!*h->name && !(state == ROLE_SOLVER && find_kind(spec, h->kind))) {
        report_unknown_solver_section(d, c, s, schema, h, state == ROLE_SOLVER ? spec : NULL);
        return;
    }
    int named = check_object_name(d, c, s, h);
    switch (state) {
    case ROLE_ABSENT:
        report(d, c, &s->from, s->name, NULL, "no [%s] section (the participant this object "
               "belongs to)", h->role);
        break;
    case ROLE_UNSURE:
    case ROLE_EXTERNAL:
        break;
    case ROLE_SOLVER: {
        const fsi_object_kind *kind = find_kind(spec, h->kind);
        if (!kind)
            report_unknown_kind(d, c, s, spec, h->kind);
        else if (named)
            check_object_keys(d, c, s, h, kind);
        break;
    }
    }
}

/* Too few objects of a kind is reported at the participant's header: that is
 * where the missing section would go. */
static void check_object_counts(diag_list *d, const fsi_case *c, const fsi_case_schema *schema,
                                const char *role)
{
    const fsi_solver_spec *spec;
    if (role_solver(c, schema, role, &spec) != ROLE_SOLVER)
        return;
    const section *s = find_section(c, role);
    for (int i = 0; i < spec->n_objects; i++) {
        const fsi_object_kind *k = &spec->objects[i];
        int n = fsi_case_objects(c, role, k->kind, NULL, 0);
        if (n < k->min_count)
            report(d, c, &s->from, role, NULL,
                   "solver %s needs at least %d [%s.%s NAME] section%s, found %d", spec->name,
                   k->min_count, role, k->kind, k->min_count == 1 ? "" : "s", n);
    }
}

static void report_unknown_section(diag_list *d, const fsi_case *c, const section *s,
                                   const fsi_case_schema *schema)
{
    name_list known = { 0 };
    for (int i = 0; i < schema->n_sections; i++)
        names_add(&known, schema->sections[i].name);
    for (int i = 0; i < schema->n_roles; i++)
        names_add(&known, schema->roles[i]);
    const char *guess = closest_name(s->name, &known);
    char *list = names_join(&known, ", ");
    /* "[solid block]": the dot of an object section forgotten */
    const char *objects = strchr(s->name, ' ') ? "; object sections are written [ROLE.KIND NAME]"
                                               : "";
    if (guess)
        report(d, c, &s->from, NULL, NULL,
               "unknown section [%s] (did you mean [%s]? known: %s)%s", s->name, guess, list,
               objects);
    else
        report(d, c, &s->from, NULL, NULL, "unknown section [%s] (known: %s)%s", s->name, list,
               objects);
    free(list);
    names_free(&known);
}

/* Fixed sections absent from the file exist with their defaults, unless they
 * have required keys, which is an error of the file as a whole. */
static void add_absent_sections(diag_list *d, fsi_case *c, const fsi_case_schema *schema)
{
    static const origin by_default = { FROM_DEFAULT, 0, NULL };
    for (int i = 0; i < schema->n_sections; i++) {
        const fsi_key_table *t = &schema->sections[i];
        if (find_section(c, t->name))
            continue;
        name_list required = { 0 };
        for (int k = 0; k < t->n_keys; k++)
            if (!t->keys[k].default_value)
                names_add(&required, t->keys[k].key);
        if (required.n > 0) {
            char *list = names_join(&required, ", ");
            report(d, c, &by_default, t->name, NULL, "section missing (required keys: %s)", list);
            free(list);
        } else {
            section *s = add_section(c, t->name, &by_default);
            key_scope sc = { .report_unknown = 0 };
            scope_add(&sc, t);
            fill_defaults(d, c, s, &sc);
            scope_free(&sc);
        }
        names_free(&required);
    }
}

/* ------------------------------------------------------------ the schema */

static void schema_flaw(diag_list *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void schema_flaw(diag_list *d, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *msg = xvasprintf(fmt, ap);
    va_end(ap);
    diag_add(d, RANK_FILE, 0, xasprintf("internal error in the case schema: %s", msg));
    free(msg);
}

/* The tables 'tables[0..n)' all apply to one section ('owner' in messages): a key
 * may appear in only one of them, once, and its default must pass its own rule
 * (a default is written to the resolved file, and reading that back checks it). */
static void check_key_set(diag_list *d, const char *owner, const fsi_key_table *const *tables,
                          int n)
{
    for (int t = 0; t < n; t++) {
        if (!tables[t])
            continue;
        for (int i = 0; i < tables[t]->n_keys; i++) {
            const fsi_key_spec *k = &tables[t]->keys[i];
            for (int u = 0; u <= t; u++) {
                if (!tables[u])
                    continue;
                int end = u == t ? i : tables[u]->n_keys;
                for (int j = 0; j < end; j++)
                    if (strcmp(tables[u]->keys[j].key, k->key) == 0)
                        schema_flaw(d, "%s: key '%s' is defined in table '%s' and again in "
                                    "table '%s'", owner, k->key, tables[u]->name,
                                    tables[t]->name);
            }
            char *why = k->default_value ? value_problem(k, k->default_value) : NULL;
            if (why) {
                schema_flaw(d, "%s: default of key '%s' in table '%s': %s", owner, k->key,
                            tables[t]->name, why);
                free(why);
            }
        }
    }
}

static void check_solver_objects(diag_list *d, const fsi_solver_spec *sv)
{
    for (int i = 0; i < sv->n_objects; i++) {
        const fsi_object_kind *k = &sv->objects[i];
        char *owner = xasprintf("solver %s, [%s.%s NAME]", sv->name, sv->role, k->kind);
        int bad_name = !*k->kind;
        for (const char *p = k->kind; *p; p++)
            bad_name |= !is_name_char(*p);
        if (bad_name)
            schema_flaw(d, "%s: an object kind is one word of letters, digits, '_' and '-'",
                        owner);
        for (int j = 0; j < i; j++)
            if (strcmp(sv->objects[j].kind, k->kind) == 0)
                schema_flaw(d, "%s: object kind declared twice", owner);
        check_key_set(d, owner, &k->keys, 1);
        free(owner);
    }
}

static void check_solver(diag_list *d, const fsi_case_schema *schema, int index)
{
    const fsi_solver_spec *sv = &schema->solvers[index];
    char *owner = xasprintf("solver %s", sv->name);
    for (int j = 0; j < index; j++)
        if (strcmp(schema->solvers[j].name, sv->name) == 0)
            schema_flaw(d, "%s: two solvers have this name", owner);
    if (strcmp(sv->name, "external") == 0)
        schema_flaw(d, "%s: the name 'external' is reserved", owner);
    if (role_index(schema, sv->role) < 0)
        schema_flaw(d, "%s: role '%s' is not a participant section", owner, sv->role);
    /* The participant section holds the common keys and the solver's key_tables, its
     * solver section its own keys: one place per key, so none may repeat across them. */
    const int n = sv->n_key_tables + 2;
    const fsi_key_table **tables = xrealloc(NULL, (size_t)n * sizeof *tables);
    tables[0] = schema->participant;
    for (int i = 0; i < sv->n_key_tables; i++)
        tables[i + 1] = sv->key_tables[i];
    tables[n - 1] = sv->own_keys;
    check_key_set(d, owner, tables, n);
    for (int i = 0; i < n; i++)
        if (table_has(tables[i], FSI_CASE_SUPPORT_KEY))
            schema_flaw(d, "%s: table '%s' defines '%s', which validation derives", owner,
                        tables[i]->name, FSI_CASE_SUPPORT_KEY);
    free(tables);
    /* [ROLE.NAME] is a solver section, [ROLE.KIND NAME] an object: one word may not
     * be both for a role. */
    for (int j = 0; j < schema->n_solvers; j++)
        if (strcmp(schema->solvers[j].role, sv->role) == 0 &&
            find_kind(&schema->solvers[j], sv->name))
            schema_flaw(d, "%s: solver %s of role %s has an object kind of this name", owner,
                        schema->solvers[j].name, sv->role);
    free(owner);
    check_solver_objects(d, sv);
}

static void schema_flaws(diag_list *d, const fsi_case_schema *schema)
{
    for (int i = 0; i < schema->n_sections; i++) {
        const fsi_key_table *t = &schema->sections[i];
        char *owner = xasprintf("[%s]", t->name);
        if (find_table(schema->sections, i, t->name) || role_index(schema, t->name) >= 0)
            schema_flaw(d, "%s: section defined twice", owner);
        check_key_set(d, owner, &t, 1);
        free(owner);
    }
    if (schema->participant) {
        const fsi_key_table *p = schema->participant;
        check_key_set(d, "participant sections", &p, 1);
    }
    for (int i = 0; i < schema->n_solvers; i++)
        check_solver(d, schema, i);
}

int fsi_case_schema_check(const fsi_case_schema *schema, FILE *errors)
{
    diag_list diags = { 0 };
    schema_flaws(&diags, schema);
    return diag_flush(&diags, errors);
}

/* ------------------------------------------------------------- validate */

/* A stream for solver checks when the caller wants no messages. */
static FILE *null_stream(void)
{
    FILE *f = fopen("/dev/null", "w");
    if (!f)
        f = tmpfile();
    if (!f) {
        fputs("fsi_case: cannot open a scratch stream\n", stderr);
        abort();
    }
    return f;
}

/* Runs the semantic check of every participant whose sections passed the key
 * checks (role_errors[r] == 0): a check may then rely on every key's value. */
static int run_solver_checks(const fsi_case *c, const fsi_case_schema *schema,
                             const int *role_errors, FILE *errors)
{
    int n = 0;
    FILE *out = errors;
    for (int r = 0; r < schema->n_roles; r++) {
        const fsi_solver_spec *spec;
        if (role_errors[r] || role_solver(c, schema, schema->roles[r], &spec) != ROLE_SOLVER ||
            !spec->check)
            continue;
        if (!out)
            out = null_stream();
        int k = spec->check(c, schema->roles[r], out);
        if (k < 0) {    /* a check that fails without saying why still fails the case */
            fprintf(out, "internal error: the check of solver %s returned %d\n", spec->name, k);
            k = 1;
        }
        n += k;
    }
    if (out && out != errors)
        fclose(out);
    else if (out)
        fflush(out);
    return n;
}

/* A solver section [ROLE.SOLVER]: checked against the solver's own keys and given
 * its defaults whether the solver is chosen or not, so that a case can carry the
 * settings of several solvers and a typo in any of them is still an error. */
static void validate_solver_section(diag_list *d, const fsi_case *c, section *s,
                                    const fsi_case_schema *schema, const fsi_solver_spec *sv)
{
    if (!sv->own_keys) {
        report(d, c, &s->from, s->name, NULL, "solver %s has no solver section: its keys are "
               "written in [%s]", sv->name, sv->role);
        return;
    }
    key_scope sc = { .report_unknown = 1, .schema = schema, .role = sv->role,
                     .section_solver = sv };
    scope_add(&sc, sv->own_keys);
    char *hint = xasprintf(" of solver %s", sv->name);
    sc.unknown_hint = hint;
    check_section(d, c, s, &sc);
    free(hint);
}

/* The chosen solver's section exists after validation, with its defaults when the
 * case has none, so that the resolved case shows every value in effect. It goes
 * right after its participant section. */
static void add_chosen_solver_sections(diag_list *d, fsi_case *c, const fsi_case_schema *schema)
{
    static const origin by_default = { FROM_DEFAULT, 0, NULL };
    for (int r = 0; r < schema->n_roles; r++) {
        const fsi_solver_spec *spec;
        if (role_solver(c, schema, schema->roles[r], &spec) != ROLE_SOLVER || !spec->own_keys)
            continue;
        const char *name = fsi_case_solver_section(c, schema->roles[r]);
        if (find_section(c, name))
            continue;
        section *s = add_section(c, name, &by_default);
        int at = 0;
        while (strcmp(c->sections[at]->name, schema->roles[r]) != 0)
            at++;
        memmove(&c->sections[at + 2], &c->sections[at + 1],
                (size_t)(c->n_sections - at - 2) * sizeof *c->sections);
        c->sections[at + 1] = s;
        key_scope sc = { .report_unknown = 0 };
        scope_add(&sc, spec->own_keys);
        fill_defaults(d, c, s, &sc);
        scope_free(&sc);
    }
}

static void remove_entry(section *s, const char *key)
{
    for (int i = 0; i < s->n_entries; i++) {
        entry *e = s->entries[i];
        if (strcmp(e->key, key) != 0)
            continue;
        free(e->key);
        free(e->value);
        free(e->from.set_text);
        free(e->label);
        free(e);
        memmove(&s->entries[i], &s->entries[i + 1],
                (size_t)(s->n_entries - i - 1) * sizeof *s->entries);
        s->n_entries--;
        return;
    }
}

/* Writes each support radius into [ROLE] FSI_CASE_SUPPORT_KEY for the participants
 * whose sections passed (role_errors[r] == 0) and whose solver has one, so that the
 * semantic checks and the other participant read it without knowing the solver. A
 * derived value left from a resolved file for a solver without one is removed. */
static void derive_supports(diag_list *d, fsi_case *c, const fsi_case_schema *schema,
                            int *role_errors)
{
    static const origin derived = { FROM_DERIVED, 0, NULL };
    for (int r = 0; r < schema->n_roles; r++) {
        section *s = find_section(c, schema->roles[r]);
        const entry *old = s ? find_entry(s, FSI_CASE_SUPPORT_KEY) : NULL;
        if (old && (old->from.kind == FROM_FILE || old->from.kind == FROM_SET))
            continue;   /* refused (refuse_derived) */
        const fsi_solver_spec *spec;
        if (role_errors[r] || role_solver(c, schema, schema->roles[r], &spec) != ROLE_SOLVER ||
            !spec->support) {
            if (old)
                remove_entry(s, FSI_CASE_SUPPORT_KEY);
            continue;
        }
        const double support = spec->support(c, schema->roles[r]);
        if (!(support >= 0.0) || !isfinite(support)) {
            report(d, c, &s->from, s->name, FSI_CASE_SUPPORT_KEY, "internal error: solver %s "
                   "derives a support radius of %g m from valid keys", spec->name, support);
            role_errors[r]++;
            continue;
        }
        char text[40];
        fsi_case_format_number(support, text, sizeof text);
        set_value(c, s->name, FSI_CASE_SUPPORT_KEY, text, &derived);
    }
}

/* Checks one section the file (or --set) gave; returns the index of the role it
 * belongs to (a participant section or one of its objects), or -1. */
static int validate_section(diag_list *d, const fsi_case *c, section *s,
                            const fsi_case_schema *schema)
{
    const fsi_key_table *t = find_table(schema->sections, schema->n_sections, s->name);
    int role = role_index(schema, s->name);
    object_header h;
    if (t) {
        key_scope sc = { .report_unknown = 1 };
        scope_add(&sc, t);
        check_section(d, c, s, &sc);
    } else if (role >= 0) {
        validate_participant(d, c, s, schema);
    } else if (split_object_header(s->name, &h)) {
        const fsi_solver_spec *sv = find_role_solver(schema, h.role, h.kind);
        if (sv && !*h.name)
            validate_solver_section(d, c, s, schema, sv);
        else if (sv)
            report(d, c, &s->from, s->name, NULL, "a solver section has no name: write [%s.%s]",
                   h.role, h.kind);
        else
            validate_object(d, c, s, schema, &h);
        role = role_index(schema, h.role);
        free_object_header(&h);
    } else {
        report_unknown_section(d, c, s, schema);
    }
    return role;
}

int fsi_case_validate(fsi_case *c, const fsi_case_schema *schema, FILE *errors)
{
    diag_list diags = { 0 };
    schema_flaws(&diags, schema);
    int schema_errors = diags.n;
    /* Messages are counted per participant, so that a solver's check runs only
     * when everything it reads is known to be valid. */
    int *role_errors = xrealloc(NULL, (size_t)(schema->n_roles + 1) * sizeof *role_errors);
    for (int r = 0; r < schema->n_roles; r++)
        role_errors[r] = schema_errors;
    int n_present = c->n_sections;
    for (int i = 0; i < n_present; i++) {
        int before = diags.n;
        int r = validate_section(&diags, c, c->sections[i], schema);
        if (r >= 0)
            role_errors[r] += diags.n - before;
    }
    for (int r = 0; r < schema->n_roles; r++) {
        int before = diags.n;
        check_object_counts(&diags, c, schema, schema->roles[r]);
        role_errors[r] += diags.n - before;
    }
    add_absent_sections(&diags, c, schema);
    add_chosen_solver_sections(&diags, c, schema);
    derive_supports(&diags, c, schema, role_errors);
    int n = diag_flush(&diags, errors);
    n += run_solver_checks(c, schema, role_errors, errors);
    free(role_errors);
    return n;
}

/* ------------------------------------------------------------- objects */

/* True when 'name' is "ROLE.KIND NAME" for this role and kind, NAME not empty. */
static int is_object_of(const char *name, const char *role, const char *kind)
{
    size_t lr = strlen(role), lk = strlen(kind);
    return strncmp(name, role, lr) == 0 && name[lr] == '.' &&
           strncmp(name + lr + 1, kind, lk) == 0 && name[lr + 1 + lk] == ' ' &&
           name[lr + 2 + lk] != '\0';
}

int fsi_case_objects(const fsi_case *c, const char *role, const char *kind,
                     const char **sections, int max_sections)
{
    int n = 0;
    for (int i = 0; i < c->n_sections; i++) {
        if (!is_object_of(c->sections[i]->name, role, kind))
            continue;
        if (n < max_sections)
            sections[n] = c->sections[i]->name;
        n++;
    }
    return n;
}

const char *fsi_case_object_name(const char *section_name)
{
    const char *blank = strchr(section_name, ' ');
    if (!blank || !blank[1])
        return NULL;
    const char *dot = memchr(section_name, '.', (size_t)(blank - section_name));
    if (!dot || dot == section_name || dot + 1 == blank)
        return NULL;
    return blank + 1;
}

const char *fsi_case_origin(const fsi_case *c, const char *section_name, const char *key)
{
    const section *s = find_section(c, section_name);
    if (!s)
        return NULL;
    if (!key)
        return s->label;
    const entry *e = find_entry(s, key);
    return e ? e->label : NULL;
}

/* ---------------------------------------------------------------- getters */

const char *fsi_case_solver_section(const fsi_case *c, const char *role)
{
    const char *solver = role ? fsi_case_get(c, role, "solver") : NULL;
    if (!solver || !*solver || strcmp(solver, "external") == 0)
        return NULL;
    char *name = xasprintf("%s.%s", role, solver);
    const section *s = find_section(c, name);
    const char *found = s ? s->name : NULL;
    for (int i = 0; !found && i < c->n_solver_sections; i++)
        if (strcmp(c->solver_sections[i], name) == 0)
            found = c->solver_sections[i];
    if (found) {
        free(name);
        return found;
    }
    /* An unvalidated case may lack the section; the name is kept with the case.
     * Every case is made by case_new, never const itself: this is a cache that
     * changes no content. */
    fsi_case *cache = (fsi_case *)c;
    cache->solver_sections = grow(cache->solver_sections, cache->n_solver_sections,
                                  &cache->cap_solver_sections, sizeof *cache->solver_sections);
    cache->solver_sections[cache->n_solver_sections++] = name;
    return name;
}

int fsi_case_has_section(const fsi_case *c, const char *section_name)
{
    return find_section(c, section_name) != NULL;
}

const char *fsi_case_get(const fsi_case *c, const char *section_name, const char *key)
{
    const section *s = find_section(c, section_name);
    const entry *e = s ? find_entry(s, key) : NULL;
    return e ? e->value : NULL;
}

double fsi_case_get_real(const fsi_case *c, const char *section_name, const char *key,
                         double fallback)
{
    const char *v = fsi_case_get(c, section_name, key);
    double x;
    return v && parse_real(v, &x) == NUM_OK ? x : fallback;
}

long fsi_case_get_int(const fsi_case *c, const char *section_name, const char *key,
                      long fallback)
{
    const char *v = fsi_case_get(c, section_name, key);
    long n;
    return v && parse_int(v, &n) == NUM_OK ? n : fallback;
}

int fsi_case_choice_is(const fsi_case *c, const char *section_name, const char *key,
                       const char *word)
{
    const char *v = fsi_case_get(c, section_name, key);
    return v && strcmp(v, word) == 0;
}

int fsi_case_get_bool(const fsi_case *c, const char *section_name, const char *key,
                      int fallback)
{
    const char *v = fsi_case_get(c, section_name, key);
    int b;
    return v && parse_bool(v, &b) ? b : fallback;
}

int fsi_case_get_vector(const fsi_case *c, const char *section_name, const char *key,
                        double *out)
{
    const char *v = fsi_case_get(c, section_name, key);
    if (!v)
        return -1;
    double tmp[FSI_DIM];
    char *why = parse_vector(v, tmp);
    if (why) {
        free(why);
        return -1;
    }
    memcpy(out, tmp, sizeof tmp);
    return 0;
}

/* ---------------------------------------------------------------- writing */

/* Longest "key = value ; # origin" line that still reads back: inih's buffer
 * holds INI_MAX_LINE bytes including the line end and the terminating NUL. */
enum { WRITE_MAX_LINE = INI_MAX_LINE - 3, WRITE_ALIGN = 32 };

static void write_entry(const entry *e, FILE *out)
{
    size_t len = strlen(e->key) + 3 + strlen(e->value);
    size_t pad = len < WRITE_ALIGN ? WRITE_ALIGN - len : 0;
    if (len + pad + 5 + strlen(e->label) <= WRITE_MAX_LINE)
        fprintf(out, "%s = %s%*s ; # %s\n", e->key, e->value, (int)pad, "", e->label);
    else    /* a long origin (deep path) goes above, so the key line stays short */
        fprintf(out, "# %s\n%s = %s\n", e->label, e->key, e->value);
}

/* Section lines are read by our own reader, not inih, so a comment after the
 * header may be of any length. */
static void write_header(const section *s, FILE *out)
{
    size_t len = strlen(s->name) + 2;
    size_t pad = len < WRITE_ALIGN ? WRITE_ALIGN - len : 0;
    fprintf(out, "\n[%s]%*s ; # %s\n", s->name, (int)pad, "", s->label);
}

void fsi_case_write_resolved(const fsi_case *c, FILE *out)
{
    fprintf(out, "%s%s: every section and key with its value and,\n"
                 "# in a comment, where it came from.\n", resolved_marker, c->path);
    for (int i = 0; i < c->n_sections; i++) {
        const section *s = c->sections[i];
        write_header(s, out);
        for (int j = 0; j < s->n_entries; j++)
            write_entry(s->entries[j], out);
    }
    fflush(out);
}
