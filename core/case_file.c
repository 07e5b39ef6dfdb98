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

static int ascii_equal_nocase(const char *a, const char *b)
{
    for (; *a && *b; a++, b++)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
            return 0;
    return *a == *b;
}

/* Shortest text that reads back as the same double, so bounds print as "0.1". */
static void format_number(double x, char *buf, size_t size)
{
    snprintf(buf, size, "%.15g", x);
    if (strtod(buf, NULL) != x)
        snprintf(buf, size, "%.17g", x);
}

/* A list of names for "known: ..." lists and "did you mean" suggestions. */
typedef struct {
    const char **items;
    int n, cap;
} name_list;

static void names_add(name_list *l, const char *name)
{
    for (int i = 0; i < l->n; i++)
        if (strcmp(l->items[i], name) == 0)
            return;
    l->items = grow(l->items, l->n, &l->cap, sizeof *l->items);
    l->items[l->n++] = name;
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
    l->items = NULL;
    l->n = l->cap = 0;
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

typedef enum { FROM_FILE, FROM_SET, FROM_DEFAULT } origin_kind;

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
} entry;

typedef struct {
    char *name;
    origin from;        /* the header line, or the --set that created the section */
    entry **entries;    /* pointers, so getters' strings survive later additions */
    int n_entries, cap_entries;
} section;

struct fsi_case {
    char *path;
    section **sections;
    int n_sections, cap_sections;
    int n_overrides;
};

static origin origin_copy(const origin *o)
{
    origin c = *o;
    c.set_text = o->set_text ? xstrdup(o->set_text) : NULL;
    return c;
}

static section *find_section(const fsi_case *c, const char *name)
{
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

static entry *add_entry(section *s, const char *key, const char *value, const origin *from)
{
    entry *e = xrealloc(NULL, sizeof *e);
    e->key = xstrdup(key);
    e->value = xstrdup(value);
    e->from = origin_copy(from);
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
            free(s->entries[j]);
        }
        free(s->entries);
        free(s->name);
        free(s->from.set_text);
        free(s);
    }
    free(c->sections);
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

static char *where_text(const fsi_case *c, const origin *o)
{
    switch (o->kind) {
    case FROM_FILE:
        return xasprintf("%s:%d", c->path, o->line);
    case FROM_SET:
        return xasprintf("--set %s", o->set_text);
    case FROM_DEFAULT:
        break;
    }
    return xstrdup(c->path);
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
} read_state;

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
    char *name = trimmed_copy(text + 1, (size_t)(close - text - 1));
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
    return str;
}

static int on_key(void *user, const char *inih_section, const char *name, const char *value)
{
    read_state *st = user;
    (void)inih_section;     /* cut at 50 bytes by inih; the reader tracks sections */
    st->pending = 0;
    origin here = { FROM_FILE, st->lineno, NULL };
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
    add_entry(st->current, name, value, &here);
    return 1;
}

static fsi_case *case_new(const char *path)
{
    fsi_case *c = xrealloc(NULL, sizeof *c);
    c->path = xstrdup(path);
    c->sections = NULL;
    c->n_sections = c->cap_sections = 0;
    c->n_overrides = 0;
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

int fsi_case_override(fsi_case *c, const char *assignment, FILE *errors)
{
    const char *eq = strchr(assignment, '=');
    const char *dot = strchr(assignment, '.');
    if (!eq || !dot || dot > eq) {
        if (errors)
            fprintf(errors, "--set %s: expected section.key=value\n", assignment);
        return -1;
    }
    if (strpbrk(assignment, "\n\r")) {
        if (errors)
            fprintf(errors, "--set %s: may not contain a line break\n", assignment);
        return -1;
    }
    char *sec = trimmed_copy(assignment, (size_t)(dot - assignment));
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
    int rc = 0;
    if (why) {
        if (errors)
            fprintf(errors, "--set %s: %s\n", assignment, why);
        rc = -1;
    } else {
        origin from = { FROM_SET, ++c->n_overrides, (char *)assignment };
        section *s = find_section(c, sec);
        if (!s)
            s = add_section(c, sec, &from);
        entry *e = find_entry(s, key);
        if (e) {
            free(e->value);
            free(e->from.set_text);
            e->value = xstrdup(value);
            e->from = origin_copy(&from);
        } else {
            add_entry(s, key, value, &from);
        }
    }
    free(why_text);
    free(sec);
    free(key);
    free(value);
    return rc;
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

static char *choices_text(const char *choices)
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
        format_number(k->min, num, sizeof num);
        return xasprintf("%s must be > %s", text, num);
    }
    if ((k->bounds & FSI_BOUND_MIN) && !(x >= k->min)) {
        format_number(k->min, num, sizeof num);
        return xasprintf("%s must be >= %s", text, num);
    }
    if ((k->bounds & FSI_BOUND_MAX) && !(x <= k->max)) {
        format_number(k->max, num, sizeof num);
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
    const fsi_key_table *tables[2];
    int n_tables;
    const char *skip[3];        /* NULL-terminated: keys the caller checks itself */
    int report_unknown;         /* 0 for external solvers (pass-through) */
    const char *unknown_hint;   /* e.g. "solver spring_oscillators" */
    name_list suggested;        /* keys offered as "did you mean" */
} key_scope;

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
    name_list known = { 0 };
    for (int i = 0; sc->skip[i]; i++)
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
        report(d, c, &e->from, s->name, e->key, "unknown key '%s' (known keys%s%s: %s)", e->key,
               sc->unknown_hint ? " with " : "", sc->unknown_hint ? sc->unknown_hint : "",
               list);
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
                add_entry(s, k->key, k->default_value, &by_default);
            else if (!suggested)
                report(d, c, &s->from, s->name, k->key, "required key missing");
        }
    }
}

static const fsi_key_table *find_table(const fsi_key_table *tables, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (strcmp(tables[i].name, name) == 0)
            return &tables[i];
    return NULL;
}

static int is_role(const fsi_case_schema *schema, const char *name)
{
    for (int i = 0; i < schema->n_roles; i++)
        if (strcmp(schema->roles[i], name) == 0)
            return 1;
    return 0;
}

static const fsi_solver_spec *find_solver(const fsi_case_schema *schema, const char *name)
{
    for (int i = 0; i < schema->n_solvers; i++)
        if (strcmp(schema->solvers[i].name, name) == 0)
            return &schema->solvers[i];
    return NULL;
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
}

static void validate_participant(diag_list *d, const fsi_case *c, section *s,
                                 const fsi_case_schema *schema)
{
    key_scope sc = { .skip = { "solver", NULL, NULL }, .report_unknown = 1 };
    if (schema->participant)
        sc.tables[sc.n_tables++] = schema->participant;
    const entry *solver = find_entry(s, "solver");
    char *hint = NULL;
    if (!solver) {
        report(d, c, &s->from, s->name, "solver", "required key missing");
        sc.report_unknown = 0;  /* without a solver we cannot tell which keys are valid */
    } else if (!*solver->value) {
        report(d, c, &solver->from, s->name, "solver", "value is empty");
        sc.report_unknown = 0;
    } else if (strcmp(solver->value, "external") == 0) {
        sc.skip[1] = "executable";
        sc.report_unknown = 0;
        check_external(d, c, s);
    } else {
        const fsi_solver_spec *spec = find_solver(schema, solver->value);
        if (!spec || strcmp(spec->role, s->name) != 0) {
            report_bad_solver(d, c, s, solver, schema);
            sc.report_unknown = 0;
        } else {
            if (spec->keys)
                sc.tables[sc.n_tables++] = spec->keys;
            hint = xasprintf("solver %s", spec->name);
            sc.unknown_hint = hint;
        }
    }
    check_entries(d, c, s, &sc);
    fill_defaults(d, c, s, &sc);
    names_free(&sc.suggested);
    free(hint);
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
    if (guess)
        report(d, c, &s->from, NULL, NULL, "unknown section [%s] (did you mean [%s]? known: %s)",
               s->name, guess, list);
    else
        report(d, c, &s->from, NULL, NULL, "unknown section [%s] (known: %s)", s->name, list);
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
            key_scope sc = { .tables = { t }, .n_tables = 1 };
            fill_defaults(d, c, s, &sc);
        }
        names_free(&required);
    }
}

int fsi_case_validate(fsi_case *c, const fsi_case_schema *schema, FILE *errors)
{
    diag_list diags = { 0 };
    int n_present = c->n_sections;
    for (int i = 0; i < n_present; i++) {
        section *s = c->sections[i];
        const fsi_key_table *t = find_table(schema->sections, schema->n_sections, s->name);
        if (t) {
            key_scope sc = { .tables = { t }, .n_tables = 1, .report_unknown = 1 };
            check_entries(&diags, c, s, &sc);
            fill_defaults(&diags, c, s, &sc);
            names_free(&sc.suggested);
        } else if (is_role(schema, s->name)) {
            validate_participant(&diags, c, s, schema);
        } else {
            report_unknown_section(&diags, c, s, schema);
        }
    }
    add_absent_sections(&diags, c, schema);
    return diag_flush(&diags, errors);
}

/* ---------------------------------------------------------------- getters */

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

static void write_entry(const fsi_case *c, const entry *e, FILE *out)
{
    char *where = e->from.kind == FROM_DEFAULT ? xstrdup("default") : where_text(c, &e->from);
    size_t len = strlen(e->key) + 3 + strlen(e->value);
    size_t pad = len < WRITE_ALIGN ? WRITE_ALIGN - len : 0;
    if (len + pad + 5 + strlen(where) <= WRITE_MAX_LINE)
        fprintf(out, "%s = %s%*s ; # %s\n", e->key, e->value, (int)pad, "", where);
    else    /* a long origin (deep path) goes above, so the key line stays short */
        fprintf(out, "# %s\n%s = %s\n", where, e->key, e->value);
    free(where);
}

void fsi_case_write_resolved(const fsi_case *c, FILE *out)
{
    fprintf(out, "# Resolved case read from %s: every key with its value and, in a\n"
                 "# comment, where the value came from.\n", c->path);
    for (int i = 0; i < c->n_sections; i++) {
        const section *s = c->sections[i];
        fprintf(out, "\n[%s]\n", s->name);
        for (int j = 0; j < s->n_entries; j++)
            write_entry(c, s->entries[j], out);
    }
    fflush(out);
}

/* --------------------------------------------------------------- markdown */

static const char *type_name(fsi_key_type t)
{
    switch (t) {
    case FSI_KEY_REAL: return "real";
    case FSI_KEY_INT: return "integer";
    case FSI_KEY_BOOL: return "bool";
    case FSI_KEY_STRING: return "string";
    case FSI_KEY_CHOICE: return "choice";
    case FSI_KEY_VECTOR: return "vector";
    }
    return "?";
}

/* Writes text for a table cell: '|' would end the cell, line breaks the row. */
static void md_cell(const char *text, FILE *out)
{
    for (const char *p = text ? text : ""; *p; p++) {
        if (*p == '|')
            fputs("\\|", out);
        else if (*p == '\n' || *p == '\r')
            fputc(' ', out);
        else
            fputc(*p, out);
    }
}

static char *allowed_text(const fsi_key_spec *k)
{
    char lo[40], hi[40];
    format_number(k->min, lo, sizeof lo);
    format_number(k->max, hi, sizeof hi);
    switch (k->type) {
    case FSI_KEY_REAL:
    case FSI_KEY_INT: {
        int open = k->bounds & FSI_BOUND_MIN_OPEN;
        int has_min = open || (k->bounds & FSI_BOUND_MIN);
        int has_max = k->bounds & FSI_BOUND_MAX;
        if (has_min && has_max)
            return open ? xasprintf("> %s and <= %s", lo, hi) : xasprintf("%s .. %s", lo, hi);
        if (has_min)
            return xasprintf("%s %s", open ? ">" : ">=", lo);
        if (has_max)
            return xasprintf("<= %s", hi);
        return xstrdup("");
    }
    case FSI_KEY_BOOL:
        return xstrdup("true, false");
    case FSI_KEY_CHOICE:
        return choices_text(k->choices);
    case FSI_KEY_VECTOR:
        return xasprintf("%d numbers", FSI_DIM);
    case FSI_KEY_STRING:
        break;
    }
    return xstrdup("");
}

static void md_table(const fsi_key_table *t, FILE *out)
{
    fputs("| key | type | unit | default | allowed | meaning |\n"
          "|---|---|---|---|---|---|\n", out);
    for (int i = 0; i < t->n_keys; i++) {
        const fsi_key_spec *k = &t->keys[i];
        fputs("| `", out);
        md_cell(k->key, out);
        fprintf(out, "` | %s | ", type_name(k->type));
        md_cell(k->unit, out);
        fputs(" | ", out);
        if (!k->default_value) {
            fputs("required", out);
        } else if (!*k->default_value) {
            fputs("(empty)", out);
        } else {
            fputc('`', out);
            md_cell(k->default_value, out);
            fputc('`', out);
        }
        fputs(" | ", out);
        char *allowed = allowed_text(k);
        md_cell(allowed, out);
        free(allowed);
        fputs(" | ", out);
        md_cell(k->description, out);
        fputs(" |\n", out);
    }
}

static void md_paragraph(const char *text, FILE *out)
{
    if (text && *text)
        fprintf(out, "%s\n\n", text);
}

static void md_roles_heading(const fsi_case_schema *schema, FILE *out)
{
    fputs("\n## Participant sections", out);
    for (int i = 0; i < schema->n_roles; i++) {
        const char *sep = i == 0 ? " " : i == schema->n_roles - 1 ? " and " : ", ";
        fprintf(out, "%s[%s]", sep, schema->roles[i]);
    }
    fputs("\n\n", out);
}

void fsi_case_schema_markdown(const fsi_case_schema *schema, FILE *out)
{
    fputs("# Case files\n\n"
          "A case file is an INI file: `[section]` lines, `key = value` lines and comments "
          "(lines starting with `#` or `;`, or `;` after a blank at the end of a line). "
          "Section names and keys are case-sensitive. Any key can be overridden on the "
          "command line with `--set section.key=value`. This reference is generated from "
          "the key tables in the code.\n", out);
    for (int i = 0; i < schema->n_sections; i++) {
        const fsi_key_table *t = &schema->sections[i];
        fprintf(out, "\n## [%s]\n\n", t->name);
        md_paragraph(t->description, out);
        md_table(t, out);
    }
    if (schema->n_roles == 0)
        return;
    md_roles_heading(schema, out);
    fputs("A participant section runs one solver, chosen with `solver = NAME`; it may hold "
          "the keys below and the keys of the chosen solver. `solver = external` runs the "
          "program named by `executable` and passes every other key to it unchecked.\n\n",
          out);
    if (schema->participant) {
        md_paragraph(schema->participant->description, out);
        md_table(schema->participant, out);
    }
    for (int i = 0; i < schema->n_solvers; i++) {
        const fsi_solver_spec *sv = &schema->solvers[i];
        fprintf(out, "\n### solver = %s (%s)\n\n", sv->name, sv->role);
        md_paragraph(sv->description, out);
        if (sv->executable)
            fprintf(out, "Program: `%s`.\n\n", sv->executable);
        if (sv->keys && sv->keys->n_keys > 0)
            md_table(sv->keys, out);
        else
            fputs("No keys of its own.\n", out);
    }
    fputs("\n### solver = external (any participant)\n\n"
          "Runs the program given by `executable` (required, non-empty) as the participant; "
          "all other keys of the section are passed to it as they are.\n", out);
}
