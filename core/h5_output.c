/* Particle output to HDF5 with an XDMF sidecar; layout and guarantees in
 * h5_output.h and docs/output.md.
 *
 * Every HDF5 file is written under a temporary name, closed and then renamed into
 * place, and never opened for writing again: a reader (h5py, h5dump, ParaView) can
 * hold any published file for as long as it likes without blocking the writer or
 * seeing a half-written object. */
#include "h5_output.h"

#include "dim.h"
#include "log.h"

#include <hdf5.h>

#include <dirent.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* One point field of a frame, remembered so the sidecar can be rewritten. */
typedef struct {
    char *name;
    int ncomp;
    int is_int;
} field_rec;

/* A value of a frame shared by all its points (fsi_h5_write_frame_constant). */
typedef struct {
    char *name;
    double value;
} constant_rec;

typedef struct {
    int frame;
    double time;
    int n;
    field_rec *fields;
    int nfields;
    int cap;
    constant_rec *constants;
    int nconstants;
} frame_rec;

/* What a dataset holds (fsi_h5_describe, fsi_h5_name_flags), keyed by the field's
 * name, "static/NAME" for a static field. */
typedef struct {
    char *key;
    char *unit;
    char *description;
    int flag_kind;          /* FSI_H5_FLAG_VALUES or _MASKS, when nflags > 0 */
    int nflags;
    int32_t *flag_values;
    char *flag_meanings;
} dataset_info;

struct fsi_h5_writer {
    char *dir;         /* the output folder */
    char *name;        /* NAME: NAME.h5, NAME.xmf, NAME.frames/ */
    char *solver;
    char *frames_rel;  /* "NAME.frames": what the master and the sidecar reference */
    char *frames_dir;  /* "DIR/NAME.frames" */
    hid_t file;        /* the open frame's temporary file */
    char *frame_path;  /* its final name, and the temporary it is written as */
    char *frame_tmp;
    int in_frame;
    int frame_failed;  /* a write of the open frame failed: do not publish it */
    int last_frame;    /* highest frame number begun, -1 before the first */
    frame_rec cur;
    frame_rec *done;   /* complete frames, in the order they were written */
    int ndone;
    int cap;
    int *vertex_counts; /* point counts whose vertex index file exists */
    int nvertex;
    const int *order;  /* point i of the caller's arrays is row order[i] (or NULL) */
    int order_n;
    unsigned char *scratch; /* rows in stored order */
    size_t scratch_bytes;
    dataset_info *info;     /* fsi_h5_describe, fsi_h5_name_flags */
    int ninfo;
};

/* ------------------------------------------------------------------ helpers */

static char *str_printf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

static char *str_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (len < 0)
        return NULL;
    char *s = malloc((size_t)len + 1);
    if (!s)
        return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)len + 1, fmt, ap);
    va_end(ap);
    return s;
}

static void frame_rec_clear(frame_rec *f)
{
    for (int i = 0; i < f->nfields; i++)
        free(f->fields[i].name);
    free(f->fields);
    for (int i = 0; i < f->nconstants; i++)
        free(f->constants[i].name);
    free(f->constants);
    memset(f, 0, sizeof *f);
}

static int frame_rec_add_constant(frame_rec *f, const char *name, double value)
{
    constant_rec *p = realloc(f->constants, (size_t)(f->nconstants + 1) * sizeof *p);
    if (!p)
        return -1;
    f->constants = p;
    char *copy = strdup(name);
    if (!copy)
        return -1;
    f->constants[f->nconstants++] = (constant_rec){copy, value};
    return 0;
}

static int frame_rec_add(frame_rec *f, const char *name, int ncomp, int is_int)
{
    if (f->nfields == f->cap) {
        int cap = f->cap ? 2 * f->cap : 8;
        field_rec *p = realloc(f->fields, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        f->fields = p;
        f->cap = cap;
    }
    char *copy = strdup(name);
    if (!copy)
        return -1;
    f->fields[f->nfields++] = (field_rec){copy, ncomp, is_int};
    return 0;
}

/* Moves the open frame into the list of complete frames (ownership moves too). */
static int push_done(fsi_h5_writer *w)
{
    if (w->ndone == w->cap) {
        int cap = w->cap ? 2 * w->cap : 16;
        frame_rec *p = realloc(w->done, (size_t)cap * sizeof *p);
        if (!p)
            return -1;
        w->done = p;
        w->cap = cap;
    }
    w->done[w->ndone++] = w->cur;
    memset(&w->cur, 0, sizeof w->cur);
    return 0;
}

/* ------------------------------------------------ what datasets hold */

static const dataset_info vertex_index_info = {
    "index", "1", "Polyvertex connectivity of the sidecar: point i is vertex i (XDMF readers "
    "make no cells without it).", 0, 0, NULL, NULL};

static const dataset_info *find_info(const fsi_h5_writer *w, const char *key)
{
    for (int i = 0; i < w->ninfo; i++)
        if (strcmp(w->info[i].key, key) == 0)
            return &w->info[i];
    return NULL;
}

/* The entry of key, created empty when missing; NULL when memory runs out. */
static dataset_info *info_entry(fsi_h5_writer *w, const char *key)
{
    dataset_info *e = (dataset_info *)find_info(w, key);
    if (e)
        return e;
    dataset_info *p = realloc(w->info, (size_t)(w->ninfo + 1) * sizeof *p);
    if (!p)
        return NULL;
    w->info = p;
    e = &w->info[w->ninfo];
    *e = (dataset_info){.key = strdup(key)};
    if (!e->key)
        return NULL;
    w->ninfo++;
    return e;
}

static void info_clear(dataset_info *e)
{
    free(e->key);
    free(e->unit);
    free(e->description);
    free(e->flag_values);
    free(e->flag_meanings);
}

/* ------------------------------------------------------- failure messages */

static char last_error[1024];

static void h5_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Every failure message goes through here, so fsi_h5_last_error() can give it to a
 * caller that aborts the run with it. */
static void h5_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(last_error, sizeof last_error, fmt, ap);
    va_end(ap);
    fsi_error("%s", last_error);
}

const char *fsi_h5_last_error(void)
{
    return last_error;
}

typedef struct {
    int err;
    char desc[256];
} h5_cause;

/* The first failure since cause_reset(). HDF5 records the errno of a failed system
 * call only in the text of its error stack ("..., errno = 28, error message = ...");
 * the stack is cleared by the next API call (the cleanup after a failure), so it is
 * read by the automatic error handler, which HDF5 calls as the failing API call
 * returns. */
static h5_cause first_cause;
static int have_cause;

static void cause_reset(void)
{
    have_cause = 0;
    first_cause = (h5_cause){0, ""};
}

static herr_t find_cause(unsigned depth, const H5E_error2_t *e, void *data)
{
    h5_cause *c = data;
    (void)depth; /* walked downward: the last description is the innermost cause */
    if (e->desc)
        snprintf(c->desc, sizeof c->desc, "%s: %s", e->func_name ? e->func_name : "",
                 e->desc);
    const char *p = e->desc ? strstr(e->desc, "errno = ") : NULL;
    if (p && c->err == 0)
        c->err = atoi(p + 8);
    return 0;
}

static herr_t on_hdf5_error(hid_t stack, void *data)
{
    (void)data;
    if (!have_cause) {
        H5Ewalk2(stack, H5E_WALK_DOWNWARD, find_cause, &first_cause);
        have_cause = 1;
    }
    return 0;
}

/* Why the last operation failed: the system's error text when there is one. */
static void failure_reason(int saved_errno, char *out, size_t size)
{
    int err = have_cause && first_cause.err ? first_cause.err : saved_errno;
    if (err)
        snprintf(out, size, "%s", strerror(err));
    else
        snprintf(out, size, "HDF5: %s", have_cause ? first_cause.desc : "unknown error");
    cause_reset();
}

static void report(const char *path, const char *what, ...) __attribute__((format(printf, 2, 3)));

/* "h5 output: cannot write PATH (WHAT): REASON" */
static void report(const char *path, const char *what, ...)
{
    int saved = errno;
    char reason[300], detail[512];
    failure_reason(saved, reason, sizeof reason);
    va_list ap;
    va_start(ap, what);
    vsnprintf(detail, sizeof detail, what, ap);
    va_end(ap);
    h5_error("h5 output: cannot write %s (%s): %s", path, detail, reason);
}

/* ------------------------------------------------------------- HDF5 pieces */

/* Creation property list without modification times, so that two runs writing
 * the same data produce byte-identical files. */
static hid_t untimed_plist(hid_t cls)
{
    hid_t p = H5Pcreate(cls);
    if (p < 0)
        return -1;
    if (H5Pset_obj_track_times(p, 0) < 0) {
        H5Pclose(p);
        return -1;
    }
    return p;
}

static hid_t create_file(const char *path)
{
    errno = 0;
    cause_reset();
    hid_t fcpl = untimed_plist(H5P_FILE_CREATE);
    hid_t f = fcpl >= 0 ? H5Fcreate(path, H5F_ACC_TRUNC, fcpl, H5P_DEFAULT) : -1;
    if (fcpl >= 0)
        H5Pclose(fcpl);
    return f;
}

/* An attribute of n values, or a scalar one when n is 0. */
static int write_attr_n(hid_t loc, const char *name, hid_t ftype, hid_t mtype,
                        const void *value, int n)
{
    hsize_t dims[1] = {(hsize_t)n};
    hid_t space = n > 0 ? H5Screate_simple(1, dims, NULL) : H5Screate(H5S_SCALAR);
    if (space < 0)
        return -1;
    hid_t a = H5Acreate2(loc, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT);
    int rc = (a >= 0 && H5Awrite(a, mtype, value) >= 0) ? 0 : -1;
    if (a >= 0)
        H5Aclose(a);
    H5Sclose(space);
    return rc;
}

static int write_attr(hid_t loc, const char *name, hid_t ftype, hid_t mtype,
                      const void *value)
{
    return write_attr_n(loc, name, ftype, mtype, value, 0);
}

/* Fixed-length, null-terminated: reads back as a plain string in h5dump, h5py
 * and C without variable-length memory to free. */
static int write_attr_string(hid_t loc, const char *name, const char *value)
{
    hid_t t = H5Tcopy(H5T_C_S1);
    if (t < 0)
        return -1;
    int rc = -1;
    if (H5Tset_size(t, strlen(value) + 1) >= 0 && H5Tset_strpad(t, H5T_STR_NULLTERM) >= 0)
        rc = write_attr(loc, name, t, t, value);
    H5Tclose(t);
    return rc;
}

/* The attributes saying what a dataset holds: unit, description and, for flags, the
 * CF conventions' flag_values or flag_masks with flag_meanings. */
static int write_dataset_info(hid_t d, const dataset_info *info)
{
    if (!info)
        return 0;
    if ((info->unit && write_attr_string(d, "unit", info->unit) < 0) ||
        (info->description && write_attr_string(d, "description", info->description) < 0))
        return -1;
    if (info->nflags > 0 &&
        (write_attr_n(d, info->flag_kind == FSI_H5_FLAG_MASKS ? "flag_masks" : "flag_values",
                      H5T_STD_I32LE, H5T_NATIVE_INT32, info->flag_values, info->nflags) < 0 ||
         write_attr_string(d, "flag_meanings", info->flag_meanings) < 0))
        return -1;
    return 0;
}

/* Dataset shaped [n][ncomp], or [n] for one component, with the attributes of info
 * (NULL: none). */
static int write_dataset(hid_t loc, const char *name, hid_t ftype, hid_t mtype,
                         const void *data, int n, int ncomp, const dataset_info *info)
{
    if (n < 0 || ncomp < 1 || (n > 0 && !data))
        return -1;
    hsize_t dims[2] = {(hsize_t)n, (hsize_t)ncomp};
    hid_t space = H5Screate_simple(ncomp == 1 ? 1 : 2, dims, NULL);
    hid_t dcpl = untimed_plist(H5P_DATASET_CREATE);
    hid_t d = -1;
    int rc = -1;
    if (space >= 0 && dcpl >= 0)
        d = H5Dcreate2(loc, name, ftype, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    /* HDF5 rejects a NULL buffer even for zero elements. */
    if (d >= 0 && (n == 0 || H5Dwrite(d, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0) &&
        write_dataset_info(d, info) == 0)
        rc = 0;
    if (d >= 0)
        H5Dclose(d);
    if (dcpl >= 0)
        H5Pclose(dcpl);
    if (space >= 0)
        H5Sclose(space);
    return rc;
}

static int write_frame_attrs(hid_t g, double time, long step, int frame)
{
    int64_t step64 = step;
    int32_t frame32 = frame;
    if (write_attr(g, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time) < 0 ||
        write_attr(g, "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &step64) < 0 ||
        write_attr(g, "frame", H5T_STD_I32LE, H5T_NATIVE_INT32, &frame32) < 0)
        return -1;
    return 0;
}

/* Closes a file written under the temporary name tmp and renames it to path; on any
 * failure (rc < 0 on entry included) removes the temporary and leaves path as it was. */
static int publish(hid_t file, int rc, const char *tmp, const char *path, const char *what)
{
    if (rc < 0)
        report(tmp, "%s", what);
    errno = 0;
    if (H5Fclose(file) < 0 && rc == 0) {
        report(tmp, "%s, closing", what);
        rc = -1;
    }
    if (rc == 0 && rename(tmp, path) != 0) {
        h5_error("h5 output: cannot rename %s to %s: %s", tmp, path, strerror(errno));
        rc = -1;
    }
    if (rc < 0)
        remove(tmp);
    return rc;
}

static char *frame_file_name(const fsi_h5_writer *w, int frame, const char *suffix)
{
    return str_printf("%s/%06d.h5%s", w->frames_dir, frame, suffix);
}

/* ---------------------------------------------------------- master file */

static int write_master_contents(const fsi_h5_writer *w, hid_t file)
{
    int32_t dim = FSI_DIM;
    if (write_attr_string(file, "participant", w->name) < 0 ||
        write_attr_string(file, "solver", w->solver) < 0 ||
        write_attr(file, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT32, &dim) < 0 ||
        write_attr_string(file, "fsi_version", FSI_VERSION) < 0)
        return -1;
    char target[64];
    char *static_rel = str_printf("%s/static.h5", w->frames_rel);
    int rc = static_rel && H5Lcreate_external(static_rel, "/", file, "static", H5P_DEFAULT,
                                              H5P_DEFAULT) >= 0 ? 0 : -1;
    free(static_rel);
    /* Dense link storage from the first link: for hundreds of links it is about
     * twice as fast to build as the default compact-then-dense (measured, 500 links
     * 11 ms against 19 ms), and the master is rebuilt after every frame. */
    hid_t gcpl = rc == 0 ? untimed_plist(H5P_GROUP_CREATE) : -1;
    hid_t frames = gcpl >= 0 && H5Pset_link_phase_change(gcpl, 0, 0) >= 0
                       ? H5Gcreate2(file, "frames", H5P_DEFAULT, gcpl, H5P_DEFAULT) : -1;
    if (gcpl >= 0)
        H5Pclose(gcpl);
    if (frames < 0)
        return -1;
    for (int i = 0; i < w->ndone && rc == 0; i++) {
        char *rel = str_printf("%s/%06d.h5", w->frames_rel, w->done[i].frame);
        snprintf(target, sizeof target, "%06d", w->done[i].frame);
        if (!rel || H5Lcreate_external(rel, "/", frames, target, H5P_DEFAULT, H5P_DEFAULT) < 0)
            rc = -1;
        free(rel);
    }
    H5Gclose(frames);
    return rc;
}

/* NAME.h5: root attributes and external links to the static file and to every complete
 * frame, rewritten whole after each frame (links only, so it stays small). */
static int write_master(const fsi_h5_writer *w)
{
    char *path = str_printf("%s/%s.h5", w->dir, w->name);
    char *tmp = str_printf("%s/%s.h5.tmp", w->dir, w->name);
    int rc = -1;
    if (path && tmp) {
        hid_t file = create_file(tmp);
        if (file < 0)
            report(tmp, "master file");
        else
            rc = publish(file, write_master_contents(w, file), tmp, path, "master file");
    }
    free(path);
    free(tmp);
    return rc;
}

/* ------------------------------------------------------------ static file */

typedef struct {
    hid_t dst;
    const char *skip; /* a field being replaced is not copied */
    int rc;
    int found;
} copy_state;

static herr_t copy_one(hid_t src, const char *name, const H5L_info_t *info, void *data)
{
    (void)info;
    copy_state *s = data;
    if (s->skip && strcmp(name, s->skip) == 0) {
        s->found = 1;
        return 0;
    }
    if (H5Ocopy(src, name, s->dst, name, H5P_DEFAULT, H5P_DEFAULT) < 0) {
        s->rc = -1;
        return -1;
    }
    return 0;
}

/* NAME.frames/static.h5 holding the fields of the current one plus 'field' (NULL:
 * none), written as a new file: the published one is never modified. */
static int write_static_file(fsi_h5_writer *w, const char *field, hid_t ftype, hid_t mtype,
                             const void *data, int n, int ncomp)
{
    char *path = str_printf("%s/static.h5", w->frames_dir);
    char *tmp = str_printf("%s/static.h5.tmp", w->frames_dir);
    int rc = -1;
    if (!path || !tmp)
        goto out;
    hid_t file = create_file(tmp);
    if (file < 0) {
        report(tmp, "static data");
        goto out;
    }
    rc = 0;
    if (field) {
        hid_t old = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
        copy_state s = {file, field, 0, 0};
        if (old < 0 || H5Literate(old, H5_INDEX_NAME, H5_ITER_INC, NULL, copy_one, &s) < 0 ||
            s.rc < 0)
            rc = -1;
        if (old >= 0)
            H5Fclose(old);
        if (s.found) {
            h5_error("h5 output: static field '%s' written twice to %s", field, path);
            rc = -1;
        } else {
            char *key = str_printf("static/%s", field);
            if (!key || (rc == 0 && write_dataset(file, field, ftype, mtype, data, n, ncomp,
                                                  find_info(w, key)) < 0))
                rc = -1;
            free(key);
        }
    }
    char what[300];
    snprintf(what, sizeof what, "static field '%s' (%d x %d)", field ? field : "(none)", n,
             ncomp);
    rc = publish(file, rc, tmp, path, what);
out:
    free(path);
    free(tmp);
    return rc;
}

/* ------------------------------------------------------ vertex index files */

/* NAME.frames/vertices_N.h5:/index = 0..N-1, the Polyvertex connectivity the sidecar
 * gives every frame of N points. Without it the Xdmf3 readers build no cells. Written
 * once per distinct point count. */
static int ensure_vertices(fsi_h5_writer *w, int n)
{
    for (int i = 0; i < w->nvertex; i++)
        if (w->vertex_counts[i] == n)
            return 0;
    int *counts = realloc(w->vertex_counts, (size_t)(w->nvertex + 1) * sizeof *counts);
    int32_t *index = malloc((size_t)(n > 0 ? n : 1) * sizeof *index);
    char *path = str_printf("%s/vertices_%d.h5", w->frames_dir, n);
    char *tmp = str_printf("%s/vertices_%d.h5.tmp", w->frames_dir, n);
    int rc = -1;
    if (counts)
        w->vertex_counts = counts;
    if (counts && index && path && tmp) {
        for (int i = 0; i < n; i++)
            index[i] = i;
        hid_t file = create_file(tmp);
        if (file < 0)
            report(tmp, "vertex index");
        else
            rc = publish(file,
                         write_dataset(file, "index", H5T_STD_I32LE, H5T_NATIVE_INT32, index,
                                       n, 1, &vertex_index_info),
                         tmp, path, "vertex index");
    } else
        h5_error("h5 output: out of memory for the vertex index of %d points", n);
    if (rc == 0)
        w->vertex_counts[w->nvertex++] = n;
    free(index);
    free(path);
    free(tmp);
    return rc;
}

/* --------------------------------------------------------------- XDMF text */

static void xml_escaped(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
    }
}

/* Checked with ParaView 5.11 (tests/system/test_paraview_xdmf.sh and by hand):
 * its Xdmf3 readers take the component count from the DataItem for every type,
 * but the legacy "XDMF Reader", which the GUI also offers for .xmf, reads a
 * "Tensor" as 9 components whatever the data holds, so a 2x2 tensor comes out
 * misaligned. "Matrix" (components = last DataItem dimension) reads correctly in
 * all of them, hence 2-D tensors are "Matrix". 2-D vectors stay "Vector": all
 * readers read them correctly (the legacy one pads them to 3 with z = 0). */
static const char *attribute_type(int ncomp)
{
    if (ncomp == 1)
        return "Scalar";
    if (ncomp == FSI_DIM)
        return "Vector";
    return FSI_DIM == 3 ? "Tensor" : "Matrix";
}

static void xmf_data_item(FILE *f, const fsi_h5_writer *w, const frame_rec *fr,
                          const char *field, int ncomp, int is_int)
{
    fprintf(f, "          <DataItem Dimensions=\"%d", fr->n);
    if (ncomp > 1)
        fprintf(f, " %d", ncomp);
    fprintf(f, "\" NumberType=\"%s\" Precision=\"%d\" Format=\"HDF\">",
            is_int ? "Int" : "Float", is_int ? 4 : 8);
    xml_escaped(f, w->frames_rel);
    fprintf(f, "/%06d.h5:/", fr->frame);
    xml_escaped(f, field);
    fputs("</DataItem>\n", f);
}

static void xmf_grid(FILE *f, const fsi_h5_writer *w, const frame_rec *fr)
{
    fprintf(f, "      <Grid Name=\"frame_%06d\" GridType=\"Uniform\">\n", fr->frame);
    fprintf(f, "        <Time Value=\"%.17g\"/>\n", fr->time);
    /* Explicit connectivity: without it the Xdmf3 readers make N points and no cell. */
    fprintf(f, "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
               "NodesPerElement=\"1\">\n", fr->n);
    fprintf(f, "          <DataItem Dimensions=\"%d\" NumberType=\"Int\" Precision=\"4\" "
               "Format=\"HDF\">", fr->n);
    xml_escaped(f, w->frames_rel);
    fprintf(f, "/vertices_%d.h5:/index</DataItem>\n", fr->n);
    fputs("        </Topology>\n", f);
    fprintf(f, "        <Geometry GeometryType=\"%s\">\n", FSI_DIM == 2 ? "XY" : "XYZ");
    xmf_data_item(f, w, fr, "position", FSI_DIM, 0);
    fputs("        </Geometry>\n", f);
    for (int i = 0; i < fr->nfields; i++) {
        const field_rec *fd = &fr->fields[i];
        fputs("        <Attribute Name=\"", f);
        xml_escaped(f, fd->name);
        fprintf(f, "\" AttributeType=\"%s\" Center=\"Node\">\n", attribute_type(fd->ncomp));
        xmf_data_item(f, w, fr, fd->name, fd->ncomp, fd->is_int);
        fputs("        </Attribute>\n", f);
    }
    /* A grid-centred attribute: ParaView's three XDMF readers give it as field data. */
    for (int i = 0; i < fr->nconstants; i++) {
        fputs("        <Attribute Name=\"", f);
        xml_escaped(f, fr->constants[i].name);
        fprintf(f, "\" AttributeType=\"Scalar\" Center=\"Grid\">\n"
                   "          <DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" "
                   "Format=\"XML\">%.17g</DataItem>\n"
                   "        </Attribute>\n", fr->constants[i].value);
    }
    fputs("      </Grid>\n", f);
}

/* Written to a temporary and renamed over the sidecar, so a reader (or a crash)
 * only ever sees a complete file listing complete frames. */
static int write_xmf(const fsi_h5_writer *w)
{
    char *path = str_printf("%s/%s.xmf", w->dir, w->name);
    char *tmp = str_printf("%s/%s.xmf.tmp", w->dir, w->name);
    int rc = -1;
    FILE *f = path && tmp ? fsi_fopen_checked(tmp, "w") : NULL;
    if (!f) {
        h5_error("h5 output: cannot write %s: %s", tmp ? tmp : w->name, strerror(errno));
        goto out;
    }
    fputs("<?xml version=\"1.0\" ?>\n"
          "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
          "<Xdmf Version=\"3.0\">\n"
          "  <Domain>\n"
          "    <Grid Name=\"", f);
    /* Named after the participant: the block's name when run.xmf includes the series. */
    xml_escaped(f, w->name);
    fputs("\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", f);
    for (int i = 0; i < w->ndone; i++)
        xmf_grid(f, w, &w->done[i]);
    fputs("    </Grid>\n"
          "  </Domain>\n"
          "</Xdmf>\n",
          f);
    int err = fsi_fclose_checked(f);
    if (err) {
        h5_error("h5 output: cannot write %s: %s", tmp, strerror(err));
        remove(tmp);
        goto out;
    }
    if (rename(tmp, path) != 0) {
        h5_error("h5 output: cannot rename %s to %s: %s", tmp, path, strerror(errno));
        remove(tmp);
        goto out;
    }
    rc = 0;
out:
    free(path);
    free(tmp);
    return rc;
}

/* -------------------------------------------------------------- public API */

/* Frame, static, vertex and temporary files of an earlier run in the same folder
 * (`fsi run --force`) would be confused with this run's. Only names this writer
 * creates are removed. */
static void remove_stale(const fsi_h5_writer *w)
{
    DIR *d = opendir(w->frames_dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        int ours = (len > 3 && strcmp(e->d_name + len - 3, ".h5") == 0) ||
                   (len > 7 && strcmp(e->d_name + len - 7, ".h5.tmp") == 0);
        if (ours) {
            char *p = str_printf("%s/%s", w->frames_dir, e->d_name);
            if (p)
                remove(p);
            free(p);
        }
    }
    closedir(d);
}

/* One field of a frame file read back: its name, components and kind. */
static herr_t field_of_frame(hid_t group, const char *name, const H5L_info_t *info, void *data)
{
    (void)info;
    frame_rec *f = data;
    if (strcmp(name, "position") == 0)
        return 0;
    hid_t ds = H5Dopen2(group, name, H5P_DEFAULT);
    if (ds < 0)
        return -1;
    hid_t space = H5Dget_space(ds), type = H5Dget_type(ds);
    hsize_t dims[2] = {0, 1};
    const int rank = H5Sget_simple_extent_dims(space, dims, NULL);
    const int is_int = H5Tget_class(type) == H5T_INTEGER;
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(ds);
    if (rank < 1 || rank > 2)
        return -1;
    return frame_rec_add(f, name, rank == 2 ? (int)dims[1] : 1, is_int) == 0 ? 0 : -1;
}

/* A constant of a frame file read back: a root attribute other than time, step and
 * frame (fsi_h5_write_frame_constant). */
static herr_t constant_of_frame(hid_t file, const char *name, const H5A_info_t *info, void *data)
{
    (void)info;
    if (strcmp(name, "time") == 0 || strcmp(name, "step") == 0 || strcmp(name, "frame") == 0)
        return 0;
    double value;
    hid_t a = H5Aopen(file, name, H5P_DEFAULT);
    const int ok = a >= 0 && H5Aread(a, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (a >= 0)
        H5Aclose(a);
    return ok && frame_rec_add_constant(data, name, value) == 0 ? 0 : -1;
}

/* A restarted run (FSI_RESTART_FRAMES = F, docs/checkpoints.md) keeps frames 0 .. F-1 of
 * the run it goes on with: their records are read back from their files (time, points,
 * fields), so that the master and the sidecar list them again; later frames (written
 * after the checkpoint, before the run stopped) are removed. 0, or -1 with a message. */
static int resume_frames(fsi_h5_writer *w, int frames)
{
    for (int k = 0; k < frames; k++) {
        char *path = frame_file_name(w, k, "");
        hid_t file = path ? H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT) : -1;
        frame_rec f = {.frame = k};
        int ok = file >= 0;
        if (ok) {
            hid_t attr = H5Aopen(file, "time", H5P_DEFAULT);
            ok = attr >= 0 && H5Aread(attr, H5T_NATIVE_DOUBLE, &f.time) >= 0;
            if (attr >= 0)
                H5Aclose(attr);
            hid_t ds = ok ? H5Dopen2(file, "position", H5P_DEFAULT) : -1;
            hsize_t dims[2] = {0, 0};
            if (ds >= 0) {
                hid_t space = H5Dget_space(ds);
                ok = H5Sget_simple_extent_dims(space, dims, NULL) == 2;
                H5Sclose(space);
                H5Dclose(ds);
            } else
                ok = 0;
            f.n = (int)dims[0];
            ok = ok && H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, NULL, field_of_frame, &f) >= 0;
            hsize_t at = 0;
            ok = ok && H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, &at, constant_of_frame,
                                   &f) >= 0;
            H5Fclose(file);
        }
        if (!ok || (w->cur = f, push_done(w)) != 0) {
            h5_error("h5 output: restart: frame %d of the run (%s) cannot be read back", k,
                     path ? path : w->frames_dir);
            frame_rec_clear(&f);
            memset(&w->cur, 0, sizeof w->cur);
            free(path);
            return -1;
        }
        free(path);
        w->last_frame = k;
    }
    /* Frames after the checkpoint, and temporaries. */
    DIR *d = opendir(w->frames_dir);
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL) {
        int k;
        char tail[8] = "";
        const size_t len = strlen(e->d_name);
        const int tmp = len > 7 && strcmp(e->d_name + len - 7, ".h5.tmp") == 0;
        const int later = sscanf(e->d_name, "%d.h5%7s", &k, tail) == 1 && k >= frames;
        if (tmp || later) {
            char *p = str_printf("%s/%s", w->frames_dir, e->d_name);
            if (p)
                remove(p);
            free(p);
        }
    }
    if (d)
        closedir(d);
    return 0;
}

fsi_h5_writer *fsi_h5_create(const char *dir, const char *name, const char *solver)
{
    /* Failures are reported once by us, with file and field names and the cause
     * on_hdf5_error keeps; HDF5's own stack dump would bury that message. */
    H5Eset_auto2(H5E_DEFAULT, on_hdf5_error, NULL);
    if (!dir || !name || !*name || !solver || strchr(name, '/')) {
        h5_error("h5 output: missing folder, name or solver (or a '/' in the name)");
        return NULL;
    }
    fsi_h5_writer *w = calloc(1, sizeof *w);
    if (!w) {
        h5_error("h5 output: out of memory");
        return NULL;
    }
    w->file = -1;
    w->last_frame = -1;
    w->dir = strdup(dir);
    w->name = strdup(name);
    w->solver = strdup(solver);
    w->frames_rel = str_printf("%s.frames", name);
    w->frames_dir = str_printf("%s/%s.frames", dir, name);
    if (!w->dir || !w->name || !w->solver || !w->frames_rel || !w->frames_dir) {
        h5_error("h5 output: out of memory");
        fsi_h5_close(w);
        return NULL;
    }
    if (mkdir(w->frames_dir, 0777) != 0 && errno != EEXIST) {
        h5_error("h5 output: cannot create the folder %s: %s", w->frames_dir,
                  strerror(errno));
        fsi_h5_close(w);
        return NULL;
    }
    const char *resume = getenv("FSI_RESTART_FRAMES");
    if (resume && *resume) {
        if (resume_frames(w, atoi(resume)) != 0) {
            fsi_h5_close(w);
            return NULL;
        }
    } else
        remove_stale(w);
    if (fsi_h5_describe(w, "position", "m",
                        "Particle position in the current configuration.") != 0 ||
        write_static_file(w, NULL, 0, 0, NULL, 0, 0) < 0 || write_master(w) < 0 ||
        write_xmf(w) < 0) {
        fsi_h5_close(w);
        return NULL;
    }
    return w;
}

int fsi_h5_describe(fsi_h5_writer *w, const char *field, const char *unit,
                    const char *description)
{
    if (!w || !field || !unit || !*unit || !description || !*description) {
        h5_error("h5 output: field '%s' described without a unit or a description",
                 field ? field : "(null)");
        return -1;
    }
    dataset_info *e = info_entry(w, field);
    char *u = strdup(unit), *d = strdup(description);
    if (!e || !u || !d) {
        free(u);
        free(d);
        h5_error("h5 output: out of memory describing '%s'", field);
        return -1;
    }
    free(e->unit);
    free(e->description);
    e->unit = u;
    e->description = d;
    return 0;
}

int fsi_h5_describe_fields(fsi_h5_writer *w, const fsi_h5_field_info *info, int n)
{
    for (int i = 0; i < n; i++)
        if (fsi_h5_describe(w, info[i].field, info[i].unit, info[i].description) != 0)
            return -1;
    return 0;
}

int fsi_h5_name_flags(fsi_h5_writer *w, const char *field, int kind, int n,
                      const int32_t *values, const char *meanings)
{
    if (!w || !field || n < 1 || !values || !meanings ||
        (kind != FSI_H5_FLAG_VALUES && kind != FSI_H5_FLAG_MASKS)) {
        h5_error("h5 output: bad flag names for '%s'", field ? field : "(null)");
        return -1;
    }
    dataset_info *e = info_entry(w, field);
    int32_t *v = malloc((size_t)n * sizeof *v);
    char *m = strdup(meanings);
    if (!e || !v || !m) {
        free(v);
        free(m);
        h5_error("h5 output: out of memory naming the flags of '%s'", field);
        return -1;
    }
    memcpy(v, values, (size_t)n * sizeof *v);
    free(e->flag_values);
    free(e->flag_meanings);
    e->flag_kind = kind;
    e->nflags = n;
    e->flag_values = v;
    e->flag_meanings = m;
    return 0;
}

static int write_static(fsi_h5_writer *w, const char *field, hid_t ftype, hid_t mtype,
                        const void *data, int n, int ncomp)
{
    if (!w || !field || n < 0 || ncomp < 1 || (n > 0 && !data)) {
        h5_error("h5 output: bad static field '%s'", field ? field : "(null)");
        return -1;
    }
    return write_static_file(w, field, ftype, mtype, data, n, ncomp);
}

int fsi_h5_write_static_real(fsi_h5_writer *w, const char *field, const double *data,
                             int n, int ncomp)
{
    return write_static(w, field, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, n, ncomp);
}

int fsi_h5_write_static_int(fsi_h5_writer *w, const char *field, const int32_t *data,
                            int n, int ncomp)
{
    return write_static(w, field, H5T_STD_I32LE, H5T_NATIVE_INT32, data, n, ncomp);
}

int fsi_h5_set_point_order(fsi_h5_writer *w, const int *order, int n)
{
    if (!w || (order && n < 0))
        return -1;
    w->order = order;
    w->order_n = order ? n : 0;
    return 0;
}

/* data (n rows of row_bytes) in stored order: data itself, or the scratch holding row
 * i at order[i]. NULL when memory runs out. */
static const void *in_point_order(fsi_h5_writer *w, const void *data, int n, size_t row_bytes)
{
    if (!w->order || n != w->order_n || n == 0)
        return data;
    const size_t bytes = (size_t)n * row_bytes;
    if (bytes > w->scratch_bytes) {
        unsigned char *grown = realloc(w->scratch, bytes);
        if (!grown)
            return NULL;
        w->scratch = grown;
        w->scratch_bytes = bytes;
    }
    for (int i = 0; i < n; i++)
        memcpy(w->scratch + (size_t)w->order[i] * row_bytes,
               (const unsigned char *)data + (size_t)i * row_bytes, row_bytes);
    return w->scratch;
}

/* Drops the open frame's temporary file; nothing of it is published. */
static void abandon_frame(fsi_h5_writer *w)
{
    if (w->file >= 0)
        H5Fclose(w->file);
    w->file = -1;
    if (w->frame_tmp)
        remove(w->frame_tmp);
    free(w->frame_tmp);
    free(w->frame_path);
    w->frame_tmp = w->frame_path = NULL;
    w->in_frame = 0;
    frame_rec_clear(&w->cur);
}

int fsi_h5_begin_frame(fsi_h5_writer *w, int frame, double time, long step, int n,
                       const double *position)
{
    if (!w)
        return -1;
    if (w->in_frame) {
        h5_error("h5 output: frame %d begun in %s before frame %d ended", frame,
                  w->frames_dir, w->cur.frame);
        return -1;
    }
    if (frame < 0 || n < 0 || (n > 0 && !position)) {
        h5_error("h5 output: bad frame %d with %d points for %s", frame, n, w->frames_dir);
        return -1;
    }
    if (frame <= w->last_frame) {
        h5_error("h5 output: frame %d of %s begun after frame %d (frame numbers must "
                  "increase)", frame, w->frames_dir, w->last_frame);
        return -1;
    }
    w->last_frame = frame;
    if (n > 0 && !(position = in_point_order(w, position, n, FSI_DIM * sizeof *position))) {
        h5_error("h5 output: out of memory for frame %d of %s", frame, w->frames_dir);
        return -1;
    }
    w->frame_path = frame_file_name(w, frame, "");
    w->frame_tmp = frame_file_name(w, frame, ".tmp");
    w->cur = (frame_rec){.frame = frame, .time = time, .n = n};
    w->in_frame = 1;
    w->frame_failed = 0;
    if (!w->frame_path || !w->frame_tmp) {
        h5_error("h5 output: out of memory for frame %d of %s", frame, w->frames_dir);
        abandon_frame(w);
        return -1;
    }
    w->file = create_file(w->frame_tmp);
    if (w->file < 0 || write_frame_attrs(w->file, time, step, frame) < 0 ||
        write_dataset(w->file, "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, position, n,
                      FSI_DIM, find_info(w, "position")) < 0) {
        report(w->frame_tmp, "frame %d, attributes or position", frame);
        abandon_frame(w);
        return -1;
    }
    return 0;
}

static int write_field(fsi_h5_writer *w, const char *field, hid_t ftype, hid_t mtype,
                       const void *data, int ncomp, int is_int, size_t item_bytes)
{
    if (!w || !field)
        return -1;
    if (!w->in_frame) {
        h5_error("h5 output: field '%s' written to %s outside a frame", field,
                  w->frames_dir);
        return -1;
    }
    if (ncomp != 1 && ncomp != FSI_DIM && ncomp != FSI_DIM * FSI_DIM) {
        h5_error("h5 output: field '%s' of frame %d in %s has %d components "
                  "(1, %d or %d allowed)", field, w->cur.frame, w->frame_tmp, ncomp, FSI_DIM,
                  FSI_DIM * FSI_DIM);
        w->frame_failed = 1;
        return -1;
    }
    if (w->cur.n > 0 && !(data = in_point_order(w, data, w->cur.n, (size_t)ncomp * item_bytes))) {
        h5_error("h5 output: out of memory for field '%s' of %s", field, w->frame_tmp);
        w->frame_failed = 1;
        return -1;
    }
    errno = 0;
    cause_reset();
    if (write_dataset(w->file, field, ftype, mtype, data, w->cur.n, ncomp,
                      find_info(w, field)) < 0 ||
        frame_rec_add(&w->cur, field, ncomp, is_int) < 0) {
        report(w->frame_tmp, "field '%s' of frame %d", field, w->cur.frame);
        w->frame_failed = 1;
        return -1;
    }
    return 0;
}

int fsi_h5_write_field_real(fsi_h5_writer *w, const char *field, const double *data,
                            int ncomp)
{
    return write_field(w, field, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, ncomp, 0,
                       sizeof *data);
}

int fsi_h5_write_field_int(fsi_h5_writer *w, const char *field, const int32_t *data,
                           int ncomp)
{
    return write_field(w, field, H5T_STD_I32LE, H5T_NATIVE_INT32, data, ncomp, 1,
                       sizeof *data);
}

int fsi_h5_write_frame_constant(fsi_h5_writer *w, const char *name, double value)
{
    if (!w || !name)
        return -1;
    if (!w->in_frame) {
        h5_error("h5 output: constant '%s' written to %s outside a frame", name,
                 w->frames_dir);
        return -1;
    }
    errno = 0;
    cause_reset();
    if (write_attr(w->file, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value) < 0 ||
        frame_rec_add_constant(&w->cur, name, value) < 0) {
        report(w->frame_tmp, "constant '%s' of frame %d", name, w->cur.frame);
        w->frame_failed = 1;
        return -1;
    }
    return 0;
}

int fsi_h5_end_frame(fsi_h5_writer *w)
{
    if (!w || !w->in_frame) {
        h5_error("h5 output: end of a frame that was not begun%s%s", w ? " in " : "",
                  w ? w->frames_dir : "");
        return -1;
    }
    int frame = w->cur.frame;
    if (w->frame_failed) {
        abandon_frame(w);
        return -1;
    }
    char what[64];
    snprintf(what, sizeof what, "frame %d", frame);
    hid_t file = w->file;
    w->file = -1;
    /* Order matters: the frame and its vertex index are in place before the master
     * and the sidecar name them. */
    if (publish(file, 0, w->frame_tmp, w->frame_path, what) < 0 ||
        ensure_vertices(w, w->cur.n) < 0) {
        abandon_frame(w);
        return -1;
    }
    free(w->frame_tmp);
    free(w->frame_path);
    w->frame_tmp = w->frame_path = NULL;
    w->in_frame = 0;
    if (push_done(w) < 0) {
        h5_error("h5 output: out of memory listing frame %d of %s", frame, w->frames_dir);
        frame_rec_clear(&w->cur);
        return -1;
    }
    if (write_master(w) < 0 || write_xmf(w) < 0) {
        /* The previous master and sidecar stay, listing the frames before this one. */
        frame_rec_clear(&w->done[--w->ndone]);
        return -1;
    }
    return 0;
}

int fsi_h5_frames(const fsi_h5_writer *w)
{
    return w ? w->ndone : 0;
}

void fsi_h5_close(fsi_h5_writer *w)
{
    if (!w)
        return;
    /* An unfinished frame is never published, as after a crash. */
    if (w->in_frame)
        abandon_frame(w);
    frame_rec_clear(&w->cur);
    for (int i = 0; i < w->ndone; i++)
        frame_rec_clear(&w->done[i]);
    free(w->done);
    free(w->vertex_counts);
    free(w->scratch);
    for (int i = 0; i < w->ninfo; i++)
        info_clear(&w->info[i]);
    free(w->info);
    free(w->dir);
    free(w->name);
    free(w->solver);
    free(w->frames_rel);
    free(w->frames_dir);
    free(w);
}
