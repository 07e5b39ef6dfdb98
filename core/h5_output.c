/* Particle output to HDF5 with an XDMF sidecar; layout and guarantees in
 * h5_output.h and docs/output.md. */
#include "h5_output.h"

#include "dim.h"
#include "log.h"

#include <hdf5.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One point field of a frame, remembered so the sidecar can be rewritten. */
typedef struct {
    char *name;
    int ncomp;
    int is_int;
} field_rec;

typedef struct {
    int frame;
    double time;
    int n;
    field_rec *fields;
    int nfields;
    int cap;
} frame_rec;

struct fsi_h5_writer {
    char *h5_path;
    const char *h5_base; /* points into h5_path: what the sidecar references */
    char *xmf_path;
    char *xmf_tmp;
    hid_t file;  /* open only while a frame or a static write is in progress */
    hid_t group; /* the open frame group */
    int in_frame;
    int frame_failed; /* a write of the open frame failed: do not list it */
    frame_rec cur;
    frame_rec *done; /* complete frames, in the order they were written */
    int ndone;
    int cap;
    const int *order; /* point i of the caller's arrays is row order[i] (or NULL) */
    int order_n;
    unsigned char *scratch; /* rows in stored order */
    size_t scratch_bytes;
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
    memset(f, 0, sizeof *f);
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

static hid_t create_group(hid_t loc, const char *name)
{
    hid_t gcpl = untimed_plist(H5P_GROUP_CREATE);
    if (gcpl < 0)
        return -1;
    hid_t g = H5Gcreate2(loc, name, H5P_DEFAULT, gcpl, H5P_DEFAULT);
    H5Pclose(gcpl);
    return g;
}

static int write_attr(hid_t loc, const char *name, hid_t ftype, hid_t mtype,
                      const void *value)
{
    hid_t space = H5Screate(H5S_SCALAR);
    if (space < 0)
        return -1;
    hid_t a = H5Acreate2(loc, name, ftype, space, H5P_DEFAULT, H5P_DEFAULT);
    int rc = (a >= 0 && H5Awrite(a, mtype, value) >= 0) ? 0 : -1;
    if (a >= 0)
        H5Aclose(a);
    H5Sclose(space);
    return rc;
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

/* Dataset shaped [n][ncomp], or [n] for one component. */
static int write_dataset(hid_t loc, const char *name, hid_t ftype, hid_t mtype,
                         const void *data, int n, int ncomp)
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
    if (d >= 0 && (n == 0 || H5Dwrite(d, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0))
        rc = 0;
    if (d >= 0)
        H5Dclose(d);
    if (dcpl >= 0)
        H5Pclose(dcpl);
    if (space >= 0)
        H5Sclose(space);
    return rc;
}

static int write_root(hid_t file, const char *participant, const char *solver)
{
    int32_t dim = FSI_DIM;
    if (write_attr_string(file, "participant", participant) < 0 ||
        write_attr_string(file, "solver", solver) < 0 ||
        write_attr(file, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT32, &dim) < 0 ||
        write_attr_string(file, "fsi_version", FSI_VERSION) < 0)
        return -1;
    hid_t s = create_group(file, "static");
    hid_t f = create_group(file, "frames");
    if (s >= 0)
        H5Gclose(s);
    if (f >= 0)
        H5Gclose(f);
    return (s >= 0 && f >= 0) ? 0 : -1;
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

static void close_file(fsi_h5_writer *w)
{
    if (w->group >= 0)
        H5Gclose(w->group);
    w->group = -1;
    if (w->file >= 0)
        H5Fclose(w->file);
    w->file = -1;
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
    xml_escaped(f, w->h5_base);
    fprintf(f, ":/frames/%06d/", fr->frame);
    xml_escaped(f, field);
    fputs("</DataItem>\n", f);
}

static void xmf_grid(FILE *f, const fsi_h5_writer *w, const frame_rec *fr)
{
    fprintf(f, "      <Grid Name=\"frame_%06d\" GridType=\"Uniform\">\n", fr->frame);
    fprintf(f, "        <Time Value=\"%.17g\"/>\n", fr->time);
    fprintf(f, "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%d\" "
               "NodesPerElement=\"1\"/>\n", fr->n);
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
    fputs("      </Grid>\n", f);
}

/* Written to a temporary and renamed over the sidecar, so a reader (or a crash)
 * only ever sees a complete file listing complete frames. */
static int write_xmf(const fsi_h5_writer *w)
{
    FILE *f = fopen(w->xmf_tmp, "w");
    if (!f) {
        fsi_error("h5 output: cannot write %s: %s", w->xmf_tmp, strerror(errno));
        return -1;
    }
    fputs("<?xml version=\"1.0\" ?>\n"
          "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
          "<Xdmf Version=\"3.0\">\n"
          "  <Domain>\n"
          "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
          f);
    for (int i = 0; i < w->ndone; i++)
        xmf_grid(f, w, &w->done[i]);
    fputs("    </Grid>\n"
          "  </Domain>\n"
          "</Xdmf>\n",
          f);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fsi_error("h5 output: error writing %s", w->xmf_tmp);
        remove(w->xmf_tmp);
        return -1;
    }
    if (rename(w->xmf_tmp, w->xmf_path) != 0) {
        fsi_error("h5 output: cannot rename %s to %s: %s", w->xmf_tmp, w->xmf_path,
                  strerror(errno));
        remove(w->xmf_tmp);
        return -1;
    }
    return 0;
}

/* -------------------------------------------------------------- public API */

static fsi_h5_writer *writer_alloc(const char *dir, const char *name)
{
    fsi_h5_writer *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->file = -1;
    w->group = -1;
    w->h5_path = str_printf("%s/%s.h5", dir, name);
    w->xmf_path = str_printf("%s/%s.xmf", dir, name);
    w->xmf_tmp = str_printf("%s/%s.xmf.tmp", dir, name);
    if (!w->h5_path || !w->xmf_path || !w->xmf_tmp) {
        fsi_h5_close(w);
        return NULL;
    }
    const char *slash = strrchr(w->h5_path, '/');
    w->h5_base = slash ? slash + 1 : w->h5_path;
    return w;
}

fsi_h5_writer *fsi_h5_create(const char *dir, const char *name, const char *solver)
{
    /* Failures are reported once by us, with file and field names; HDF5's own
     * stack dump would bury that message. */
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    if (!dir || !name || !*name || !solver) {
        fsi_error("h5 output: missing folder, name or solver");
        return NULL;
    }
    fsi_h5_writer *w = writer_alloc(dir, name);
    if (!w) {
        fsi_error("h5 output: out of memory");
        return NULL;
    }
    hid_t fcpl = untimed_plist(H5P_FILE_CREATE);
    hid_t file = fcpl >= 0 ? H5Fcreate(w->h5_path, H5F_ACC_TRUNC, fcpl, H5P_DEFAULT) : -1;
    if (fcpl >= 0)
        H5Pclose(fcpl);
    if (file < 0) {
        fsi_error("h5 output: cannot create %s", w->h5_path);
        fsi_h5_close(w);
        return NULL;
    }
    int rc = write_root(file, name, solver);
    if (H5Fclose(file) < 0 || rc < 0) {
        fsi_error("h5 output: cannot write the root attributes of %s", w->h5_path);
        fsi_h5_close(w);
        return NULL;
    }
    if (write_xmf(w) < 0) {
        fsi_h5_close(w);
        return NULL;
    }
    return w;
}

static int open_file(fsi_h5_writer *w)
{
    w->file = H5Fopen(w->h5_path, H5F_ACC_RDWR, H5P_DEFAULT);
    if (w->file < 0) {
        fsi_error("h5 output: cannot reopen %s", w->h5_path);
        return -1;
    }
    return 0;
}

static int write_static(fsi_h5_writer *w, const char *field, hid_t ftype, hid_t mtype,
                        const void *data, int n, int ncomp)
{
    if (!w || !field)
        return -1;
    /* Between frames the file is closed; during a frame it is already open. */
    int opened = 0;
    if (w->file < 0) {
        if (open_file(w) < 0)
            return -1;
        opened = 1;
    }
    int rc = -1;
    hid_t g = H5Gopen2(w->file, "static", H5P_DEFAULT);
    if (g >= 0) {
        rc = write_dataset(g, field, ftype, mtype, data, n, ncomp);
        H5Gclose(g);
    }
    if (opened && H5Fclose(w->file) < 0)
        rc = -1;
    if (opened)
        w->file = -1;
    if (rc < 0)
        fsi_error("h5 output: cannot write static field '%s' (%d x %d) to %s", field, n,
                  ncomp, w->h5_path);
    return rc;
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

int fsi_h5_begin_frame(fsi_h5_writer *w, int frame, double time, long step, int n,
                       const double *position)
{
    if (!w)
        return -1;
    if (w->in_frame) {
        fsi_error("h5 output: frame %d begun in %s before frame %d ended", frame,
                  w->h5_path, w->cur.frame);
        return -1;
    }
    if (frame < 0 || n < 0 || (n > 0 && !position)) {
        fsi_error("h5 output: bad frame %d with %d points for %s", frame, n, w->h5_path);
        return -1;
    }
    if (n > 0 && !(position = in_point_order(w, position, n, FSI_DIM * sizeof *position))) {
        fsi_error("h5 output: out of memory for frame %d of %s", frame, w->h5_path);
        return -1;
    }
    if (open_file(w) < 0)
        return -1;
    char name[32];
    snprintf(name, sizeof name, "frames/%06d", frame);
    w->group = create_group(w->file, name);
    if (w->group < 0 || write_frame_attrs(w->group, time, step, frame) < 0 ||
        write_dataset(w->group, "position", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, position, n,
                      FSI_DIM) < 0) {
        fsi_error("h5 output: cannot write frame %d (group /%s or its position) to %s",
                  frame, name, w->h5_path);
        /* The partial group stays in the file but is never listed in the sidecar. */
        close_file(w);
        return -1;
    }
    w->cur = (frame_rec){.frame = frame, .time = time, .n = n};
    w->in_frame = 1;
    w->frame_failed = 0;
    return 0;
}

static int write_field(fsi_h5_writer *w, const char *field, hid_t ftype, hid_t mtype,
                       const void *data, int ncomp, int is_int, size_t item_bytes)
{
    if (!w || !field)
        return -1;
    if (!w->in_frame) {
        fsi_error("h5 output: field '%s' written to %s outside a frame", field, w->h5_path);
        return -1;
    }
    if (ncomp != 1 && ncomp != FSI_DIM && ncomp != FSI_DIM * FSI_DIM) {
        fsi_error("h5 output: field '%s' of frame %d in %s has %d components "
                  "(1, %d or %d allowed)", field, w->cur.frame, w->h5_path, ncomp, FSI_DIM,
                  FSI_DIM * FSI_DIM);
        w->frame_failed = 1;
        return -1;
    }
    if (w->cur.n > 0 && !(data = in_point_order(w, data, w->cur.n, (size_t)ncomp * item_bytes))) {
        fsi_error("h5 output: out of memory for field '%s' of %s", field, w->h5_path);
        w->frame_failed = 1;
        return -1;
    }
    if (write_dataset(w->group, field, ftype, mtype, data, w->cur.n, ncomp) < 0 ||
        frame_rec_add(&w->cur, field, ncomp, is_int) < 0) {
        fsi_error("h5 output: cannot write field '%s' of frame %d to %s", field,
                  w->cur.frame, w->h5_path);
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

int fsi_h5_end_frame(fsi_h5_writer *w)
{
    if (!w || !w->in_frame) {
        fsi_error("h5 output: end of a frame that was not begun%s%s", w ? " in " : "",
                  w ? w->h5_path : "");
        return -1;
    }
    int frame = w->cur.frame;
    H5Gclose(w->group);
    w->group = -1;
    herr_t closed = H5Fclose(w->file);
    w->file = -1;
    w->in_frame = 0;
    if (closed < 0 || w->frame_failed) {
        if (closed < 0)
            fsi_error("h5 output: cannot close %s after frame %d", w->h5_path, frame);
        frame_rec_clear(&w->cur);
        return -1;
    }
    if (push_done(w) < 0) {
        fsi_error("h5 output: out of memory listing frame %d of %s", frame, w->h5_path);
        frame_rec_clear(&w->cur);
        return -1;
    }
    return write_xmf(w);
}

int fsi_h5_frames(const fsi_h5_writer *w)
{
    return w ? w->ndone : 0;
}

void fsi_h5_close(fsi_h5_writer *w)
{
    if (!w)
        return;
    /* An unfinished frame stays out of the sidecar, as after a crash. */
    close_file(w);
    frame_rec_clear(&w->cur);
    for (int i = 0; i < w->ndone; i++)
        frame_rec_clear(&w->done[i]);
    free(w->done);
    free(w->scratch);
    free(w->h5_path);
    free(w->xmf_path);
    free(w->xmf_tmp);
    free(w);
}
