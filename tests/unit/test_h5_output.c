/* Unit test of core/h5_output: writes static data and three frames of varying size,
 * reads everything back through the HDF5 API and checks the XDMF sidecar.
 *
 * The files are left in $FSI_TEST_TMP/h5_output (particles.h5, particles.xmf), where
 * tests/system/test_paraview_xdmf.sh opens them in ParaView; the value formulas
 * below are repeated there, so change both together. */
#include "dim.h"
#include "h5_output.h"

#include <hdf5.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "unit_check.h"

enum { NFRAMES = 3, NSTATIC = 5, MAXN = 7 };
static const int counts[NFRAMES] = {5, 5, 7};

/* Values chosen exactly representable in binary, so text round trips are exact. */
static double frame_time(int f) { return 0.5 + 0.75 * f; }
static long frame_step(int f) { return 10L * f + 3; }
static double position(int f, int i, int c) { return 10.0 * f + i + 0.25 * c; }
static double pressure(int f, int i) { return 1000.0 * f + i + 0.5; }
static double velocity(int f, int i, int c) { return -(100.0 * f + 10.0 * i + c) - 0.125; }
static double stress(int f, int i, int c) { return 1000.0 * f + 10.0 * i + c + 0.75; }
static int32_t material(int f, int i) { return 7 * f + i; }
static int32_t static_id(int i) { return 100 + i; }
static double static_mass(int i) { return 1.0 + 0.5 * i; }
static double static_x0(int i, int c) { return -1.0 * i - 0.5 * c; }
static double smoothing_length(int f) { return 0.125 * (f + 1); }

/* mkdir -p */
static int make_dirs(const char *path)
{
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf)
        return -1;
    for (char *p = buf + 1;; p++) {
        if (*p != '/' && *p != '\0')
            continue;
        char saved = *p;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return -1;
        *p = saved;
        if (saved == '\0')
            return 0;
    }
}

/* ---------------------------------------------------------------- writing */

static int write_static(fsi_h5_writer *w)
{
    int32_t id[NSTATIC];
    double mass[NSTATIC], x0[NSTATIC * FSI_DIM];
    for (int i = 0; i < NSTATIC; i++) {
        id[i] = static_id(i);
        mass[i] = static_mass(i);
        for (int c = 0; c < FSI_DIM; c++)
            x0[i * FSI_DIM + c] = static_x0(i, c);
    }
    int rc = 0;
    rc |= fsi_h5_write_static_int(w, "id", id, NSTATIC, 1);
    rc |= fsi_h5_write_static_real(w, "mass", mass, NSTATIC, 1);
    rc |= fsi_h5_write_static_real(w, "initial_position", x0, NSTATIC, FSI_DIM);
    return rc;
}

static int write_frame(fsi_h5_writer *w, int f)
{
    enum { D = FSI_DIM, T = FSI_DIM * FSI_DIM };
    int n = counts[f];
    double pos[MAXN * D], p[MAXN], v[MAXN * D], s[MAXN * T];
    int32_t m[MAXN];
    for (int i = 0; i < n; i++) {
        p[i] = pressure(f, i);
        m[i] = material(f, i);
        for (int c = 0; c < D; c++) {
            pos[i * D + c] = position(f, i, c);
            v[i * D + c] = velocity(f, i, c);
        }
        for (int c = 0; c < T; c++)
            s[i * T + c] = stress(f, i, c);
    }
    int rc = fsi_h5_begin_frame(w, f, frame_time(f), frame_step(f), n, pos);
    if (rc != 0)
        return rc;
    rc |= fsi_h5_write_field_real(w, "pressure", p, 1);
    rc |= fsi_h5_write_field_real(w, "velocity", v, D);
    rc |= fsi_h5_write_field_real(w, "stress", s, T);
    rc |= fsi_h5_write_field_int(w, "material", m, 1);
    rc |= fsi_h5_write_frame_constant(w, "smoothing_length", smoothing_length(f));
    rc |= fsi_h5_end_frame(w);
    return rc;
}

/* Units, descriptions and flag names of some of the fields (check_info,
 * check_flag_names). */
static void describe(fsi_h5_writer *w)
{
    static const fsi_h5_field_info info[] = {
        {"pressure", "Pa", "Pressure."},
        {"velocity", "m/s", "Velocity."},
        {"static/mass", "kg", "Mass."},
    };
    static const int32_t kinds[] = {1, 2, 4};
    CHECK(fsi_h5_describe_fields(w, info, 3) == 0, "describe fields");
    CHECK(fsi_h5_describe(w, "stress", "", "No unit.") == -1, "a description without a unit");
    CHECK(fsi_h5_name_flags(w, "material", FSI_H5_FLAG_MASKS, 3, kinds, "one two four") == 0,
          "name the material's bits");
}

/* Writes the whole data set into DIR; static data goes in between frames 0 and 1
 * to exercise reopening the closed file. */
static int write_all(const char *dir)
{
    fsi_h5_writer *w = fsi_h5_create(dir, "particles", "test_solver");
    CHECK(w != NULL, "fsi_h5_create in %s", dir);
    if (!w)
        return -1;
    CHECK(fsi_h5_frames(w) == 0, "frames before any frame: %d", fsi_h5_frames(w));
    describe(w);
    int rc = write_frame(w, 0);
    CHECK(rc == 0, "frame 0");
    rc = write_static(w);
    CHECK(rc == 0, "static data");
    for (int f = 1; f < NFRAMES; f++) {
        rc = write_frame(w, f);
        CHECK(rc == 0, "frame %d", f);
    }
    CHECK(fsi_h5_frames(w) == NFRAMES, "frames written: %d", fsi_h5_frames(w));
    fsi_h5_close(w);
    return 0;
}

/* Misuse must be refused without changing what was written. */
static void check_misuse(const char *dir)
{
    fprintf(stderr, "(the following error messages are expected)\n");
    char missing[4200];
    snprintf(missing, sizeof missing, "%s/no/such/folder", dir);
    fsi_h5_writer *bad = fsi_h5_create(missing, "x", "s");
    CHECK(bad == NULL, "create in a missing folder must fail");
    fsi_h5_close(bad);

    fsi_h5_writer *w = fsi_h5_create(dir, "misuse", "s");
    CHECK(w != NULL, "create misuse");
    if (!w)
        return;
    double one[FSI_DIM] = {0};
    CHECK(fsi_h5_write_field_real(w, "p", one, 1) == -1, "field outside a frame");
    CHECK(fsi_h5_end_frame(w) == -1, "end without begin");
    CHECK(fsi_h5_begin_frame(w, 0, 0.0, 0, -1, one) == -1, "negative point count");
    CHECK(fsi_h5_begin_frame(w, 0, 0.0, 0, 1, one) == 0, "begin frame 0");
    CHECK(fsi_h5_begin_frame(w, 1, 0.0, 0, 1, one) == -1, "begin inside a frame");
    CHECK(fsi_h5_write_field_real(w, "p", one, FSI_DIM + 1) == -1, "bad component count");
    CHECK(fsi_h5_end_frame(w) == -1, "end of a frame with a failed field");
    CHECK(fsi_h5_frames(w) == 0, "a failed frame is not counted: %d", fsi_h5_frames(w));
    CHECK(fsi_h5_begin_frame(w, 0, 0.0, 0, 1, one) == -1, "frame number used twice");
    CHECK(fsi_h5_begin_frame(w, 1, 0.0, 0, 1, one) == 0, "begin frame 1 after failures");
    CHECK(fsi_h5_write_field_real(w, "p", one, 1) == 0, "field after failures");
    CHECK(fsi_h5_write_field_real(w, "p", one, 1) == -1, "same field twice");
    CHECK(fsi_h5_end_frame(w) == -1, "end of a frame with a repeated field");
    CHECK(fsi_h5_begin_frame(w, 2, 0.0, 0, 1, one) == 0, "begin frame 2");
    CHECK(fsi_h5_end_frame(w) == 0, "end frame 2");
    CHECK(fsi_h5_frames(w) == 1, "one good frame: %d", fsi_h5_frames(w));
    /* A frame left open at close must not be listed, as after a crash. */
    CHECK(fsi_h5_begin_frame(w, 3, 0.0, 0, 1, one) == 0, "begin frame 3");
    fsi_h5_close(w);
    fprintf(stderr, "(end of expected error messages)\n");
}

/* ---------------------------------------------------------------- reading */

static int read_string_attr(hid_t loc, const char *name, char *out, size_t size)
{
    out[0] = '\0';
    hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
    if (a < 0)
        return -1;
    hid_t ft = H5Aget_type(a);
    int rc = -1;
    size_t len = H5Tget_size(ft);
    if (H5Tget_class(ft) == H5T_STRING && !H5Tis_variable_str(ft) && len < size) {
        hid_t mt = H5Tcopy(H5T_C_S1);
        H5Tset_size(mt, len + 1);
        rc = H5Aread(a, mt, out) < 0 ? -1 : 0;
        H5Tclose(mt);
    }
    H5Tclose(ft);
    H5Aclose(a);
    return rc;
}

static int read_attr(hid_t loc, const char *name, hid_t mtype, void *out)
{
    hid_t a = H5Aopen(loc, name, H5P_DEFAULT);
    if (a < 0)
        return -1;
    int rc = H5Aread(a, mtype, out) < 0 ? -1 : 0;
    H5Aclose(a);
    return rc;
}

/* Reads dataset NAME expecting shape [n][ncomp] ([n] when ncomp is 1) and the
 * given file type class; returns 0 when shape and type match. */
static int read_dataset(hid_t loc, const char *name, hid_t mtype, H5T_class_t cls,
                        int n, int ncomp, void *out)
{
    hid_t d = H5Dopen2(loc, name, H5P_DEFAULT);
    CHECK(d >= 0, "dataset %s exists", name);
    if (d < 0)
        return -1;
    hid_t space = H5Dget_space(d);
    hid_t ft = H5Dget_type(d);
    hsize_t dims[2] = {0, 0};
    int rank = H5Sget_simple_extent_dims(space, dims, NULL);
    int want_rank = ncomp == 1 ? 1 : 2;
    int rc = 0;
    CHECK(rank == want_rank, "%s rank %d, expected %d", name, rank, want_rank);
    CHECK(dims[0] == (hsize_t)n, "%s has %llu rows, expected %d", name,
          (unsigned long long)dims[0], n);
    if (want_rank == 2)
        CHECK(dims[1] == (hsize_t)ncomp, "%s has %llu components, expected %d", name,
              (unsigned long long)dims[1], ncomp);
    CHECK(H5Tget_class(ft) == cls, "%s has the wrong type class", name);
    if (rank != want_rank || dims[0] != (hsize_t)n ||
        (rank == 2 && dims[1] != (hsize_t)ncomp))
        rc = -1;
    if (rc == 0 && H5Dread(d, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0)
        rc = -1;
    CHECK(rc == 0, "read %s", name);
    H5Tclose(ft);
    H5Sclose(space);
    H5Dclose(d);
    return rc;
}

static void check_root(hid_t file)
{
    char s[256];
    int32_t dim = 0;
    CHECK(read_string_attr(file, "participant", s, sizeof s) == 0 &&
              strcmp(s, "particles") == 0, "participant '%s'", s);
    CHECK(read_string_attr(file, "solver", s, sizeof s) == 0 &&
              strcmp(s, "test_solver") == 0, "solver '%s'", s);
    CHECK(read_string_attr(file, "fsi_version", s, sizeof s) == 0 &&
              strcmp(s, FSI_VERSION) == 0, "fsi_version '%s'", s);
    CHECK(read_attr(file, "dimension", H5T_NATIVE_INT32, &dim) == 0 && dim == FSI_DIM,
          "dimension %d", (int)dim);
}

/* The dataset's unit is 'unit' and it has a description. */
static void check_info(hid_t loc, const char *name, const char *unit)
{
    char s[256] = "";
    hid_t d = H5Dopen2(loc, name, H5P_DEFAULT);
    CHECK(d >= 0, "open %s", name);
    if (d < 0)
        return;
    CHECK(read_string_attr(d, "unit", s, sizeof s) == 0 && strcmp(s, unit) == 0,
          "%s: unit '%s', expected '%s'", name, s, unit);
    CHECK(read_string_attr(d, "description", s, sizeof s) == 0 && s[0] != '\0',
          "%s: description '%s'", name, s);
    H5Dclose(d);
}

static void check_flag_names(hid_t loc, const char *name, const char *kind,
                             const char *meanings)
{
    char s[256] = "";
    hid_t d = H5Dopen2(loc, name, H5P_DEFAULT);
    CHECK(d >= 0, "open %s", name);
    if (d < 0)
        return;
    CHECK(H5Aexists(d, kind) > 0, "%s: attribute %s", name, kind);
    CHECK(read_string_attr(d, "flag_meanings", s, sizeof s) == 0 && strcmp(s, meanings) == 0,
          "%s: flag_meanings '%s'", name, s);
    H5Dclose(d);
}

static void check_static(hid_t file)
{
    int32_t id[NSTATIC];
    double mass[NSTATIC], x0[NSTATIC * FSI_DIM];
    if (read_dataset(file, "static/id", H5T_NATIVE_INT32, H5T_INTEGER, NSTATIC, 1, id) == 0)
        for (int i = 0; i < NSTATIC; i++)
            CHECK(id[i] == static_id(i), "static id[%d] = %d", i, (int)id[i]);
    check_info(file, "static/mass", "kg");
    if (read_dataset(file, "static/mass", H5T_NATIVE_DOUBLE, H5T_FLOAT, NSTATIC, 1, mass) == 0)
        for (int i = 0; i < NSTATIC; i++)
            CHECK(mass[i] == static_mass(i), "static mass[%d] = %g", i, mass[i]);
    if (read_dataset(file, "static/initial_position", H5T_NATIVE_DOUBLE, H5T_FLOAT, NSTATIC,
                     FSI_DIM, x0) == 0)
        for (int i = 0; i < NSTATIC; i++)
            for (int c = 0; c < FSI_DIM; c++)
                CHECK(x0[i * FSI_DIM + c] == static_x0(i, c), "initial_position[%d][%d] = %g",
                      i, c, x0[i * FSI_DIM + c]);
}

static void check_real(hid_t g, const char *name, int f, int n, int ncomp,
                       double (*value)(int, int, int))
{
    double buf[MAXN * FSI_DIM * FSI_DIM];
    if (read_dataset(g, name, H5T_NATIVE_DOUBLE, H5T_FLOAT, n, ncomp, buf) != 0)
        return;
    for (int i = 0; i < n; i++)
        for (int c = 0; c < ncomp; c++)
            CHECK(buf[i * ncomp + c] == value(f, i, c), "frame %d %s[%d][%d] = %g, expected %g",
                  f, name, i, c, buf[i * ncomp + c], value(f, i, c));
}

static double pressure3(int f, int i, int c)
{
    (void)c;
    return pressure(f, i);
}

static void check_frame(hid_t file, int f)
{
    char path[32];
    snprintf(path, sizeof path, "frames/%06d", f);
    hid_t g = H5Gopen2(file, path, H5P_DEFAULT);
    CHECK(g >= 0, "group /%s exists", path);
    if (g < 0)
        return;
    double t = -1;
    int64_t step = -1;
    int32_t frame = -1;
    CHECK(read_attr(g, "time", H5T_NATIVE_DOUBLE, &t) == 0 && t == frame_time(f),
          "frame %d time %g", f, t);
    CHECK(read_attr(g, "step", H5T_NATIVE_INT64, &step) == 0 && step == frame_step(f),
          "frame %d step %lld", f, (long long)step);
    CHECK(read_attr(g, "frame", H5T_NATIVE_INT32, &frame) == 0 && frame == f,
          "frame %d frame attribute %d", f, (int)frame);
    double h = -1;
    CHECK(read_attr(g, "smoothing_length", H5T_NATIVE_DOUBLE, &h) == 0 &&
              h == smoothing_length(f), "frame %d smoothing_length %g", f, h);
    check_info(g, "position", "m");
    check_info(g, "pressure", "Pa");
    check_info(g, "velocity", "m/s");
    check_flag_names(g, "material", "flag_masks", "one two four");
    int n = counts[f];
    check_real(g, "position", f, n, FSI_DIM, position);
    check_real(g, "pressure", f, n, 1, pressure3);
    check_real(g, "velocity", f, n, FSI_DIM, velocity);
    check_real(g, "stress", f, n, FSI_DIM * FSI_DIM, stress);
    int32_t m[MAXN];
    if (read_dataset(g, "material", H5T_NATIVE_INT32, H5T_INTEGER, n, 1, m) == 0)
        for (int i = 0; i < n; i++)
            CHECK(m[i] == material(f, i), "frame %d material[%d] = %d", f, i, (int)m[i]);
    H5Gclose(g);
}

/* DIR/NAME opened read-only, or -1 (counted as a failed check). */
static hid_t open_read_only(const char *dir, const char *name)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    CHECK(file >= 0, "open %s", path);
    return file;
}

static void check_h5(const char *dir)
{
    hid_t file = open_read_only(dir, "particles.h5");
    if (file < 0)
        return;
    check_root(file);
    check_static(file);
    H5G_info_t info = {0};
    CHECK(H5Gget_info_by_name(file, "frames", &info, H5P_DEFAULT) >= 0 &&
              info.nlinks == NFRAMES, "/frames holds %llu groups, expected %d",
          (unsigned long long)info.nlinks, NFRAMES);
    for (int f = 0; f < NFRAMES; f++)
        check_frame(file, f);
    H5Fclose(file);
}

/* The Polyvertex connectivity the sidecar points at: 0..n-1. */
static void check_vertices(const char *dir)
{
    hid_t file = open_read_only(dir, "particles.frames/vertices_7.h5");
    if (file < 0)
        return;
    int32_t index[7];
    if (read_dataset(file, "index", H5T_NATIVE_INT32, H5T_INTEGER, 7, 1, index) == 0)
        for (int i = 0; i < 7; i++)
            CHECK(index[i] == i, "vertex index[%d] = %d", i, (int)index[i]);
    H5Fclose(file);
}

static hsize_t frames_listed(hid_t file)
{
    H5G_info_t info = {0};
    return H5Gget_info_by_name(file, "frames", &info, H5P_DEFAULT) >= 0 ? info.nlinks : 0;
}

/* A reader holding the files (ParaView, h5py, h5dump during a run) must not stop the
 * writer, and keeps the consistent snapshot it opened. */
static void check_held_by_reader(const char *dir)
{
    fsi_h5_writer *w = fsi_h5_create(dir, "held", "s");
    CHECK(w != NULL, "create held");
    if (!w)
        return;
    describe(w);
    CHECK(write_frame(w, 0) == 0, "held: frame 0");
    char path[4200];
    snprintf(path, sizeof path, "%s/held.h5", dir);
    hid_t r = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    hid_t g = r >= 0 ? H5Gopen2(r, "frames/000000", H5P_DEFAULT) : -1;
    CHECK(r >= 0 && g >= 0, "reader opens %s and its frame 0", path);
    CHECK(write_static(w) == 0, "static data while a reader holds the files");
    CHECK(write_frame(w, 1) == 0, "frame 1 while a reader holds the files");
    CHECK(write_frame(w, 2) == 0, "frame 2 while a reader holds the files");
    CHECK(frames_listed(r) == 1, "the reader's snapshot still lists 1 frame, not %llu",
          (unsigned long long)frames_listed(r));
    check_real(g, "position", 0, counts[0], FSI_DIM, position);
    if (g >= 0)
        H5Gclose(g);
    if (r >= 0)
        H5Fclose(r);
    fsi_h5_close(w);
    r = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    CHECK(r >= 0 && frames_listed(r) == NFRAMES, "reopened %s lists %d frames", path, NFRAMES);
    if (r >= 0) {
        check_frame(r, 2);
        H5Fclose(r);
    }
}

/* ------------------------------------------------------------------- text */

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = NULL;
    if (fseek(f, 0, SEEK_END) == 0) {
        long len = ftell(f);
        rewind(f);
        buf = len >= 0 ? malloc((size_t)len + 1) : NULL;
        if (buf) {
            size_t got = fread(buf, 1, (size_t)len, f);
            buf[got] = '\0';
        }
    }
    fclose(f);
    return buf;
}

static int count_of(const char *text, const char *needle)
{
    int k = 0;
    for (const char *p = text; (p = strstr(p, needle)) != NULL; p += strlen(needle))
        k++;
    return k;
}

static void check_xmf(const char *dir)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/particles.xmf", dir);
    char *x = read_text(path);
    CHECK(x != NULL, "read %s", path);
    if (!x)
        return;
    CHECK(strstr(x, "<Xdmf Version=\"3.0\">") != NULL, "Xdmf version 3.0");
    CHECK(strstr(x, "CollectionType=\"Temporal\"") != NULL, "temporal collection");
    CHECK(count_of(x, "GridType=\"Uniform\"") == NFRAMES, "%d uniform grids",
          count_of(x, "GridType=\"Uniform\""));
    CHECK(count_of(x, "NumberOfElements=\"5\"") == 2, "two grids of 5 points");
    CHECK(count_of(x, "NumberOfElements=\"7\"") == 1, "one grid of 7 points");
    CHECK(count_of(x, "<Time Value=\"1.25\"/>") == 1, "time of frame 1");
    CHECK(count_of(x, "particles.frames/000002.h5:/stress<") == 1, "stress of frame 2");
    CHECK(count_of(x, "particles.frames/vertices_5.h5:/index<") == 2 &&
              count_of(x, "particles.frames/vertices_7.h5:/index<") == 1,
          "every grid has its Polyvertex connectivity");
    /* material and the topology of each frame */
    CHECK(count_of(x, "NumberType=\"Int\" Precision=\"4\"") == 2 * NFRAMES, "int items");
    CHECK(strstr(x, FSI_DIM == 2 ? "GeometryType=\"XY\"" : "GeometryType=\"XYZ\"") != NULL,
          "geometry type");
    CHECK(count_of(x, "<Attribute ") == 5 * NFRAMES, "%d attributes",
          count_of(x, "<Attribute "));
    CHECK(count_of(x, "<Attribute Name=\"smoothing_length\" AttributeType=\"Scalar\" "
                      "Center=\"Grid\">") == NFRAMES, "a grid attribute per frame");
    CHECK(strstr(x, "<Grid Name=\"particles\" GridType=\"Collection\"") != NULL,
          "the collection is named after the writer");
    CHECK(strstr(x, "/static/") == NULL, "static data is not in the sidecar");
    free(x);

    snprintf(path, sizeof path, "%s/misuse.xmf", dir);
    x = read_text(path);
    CHECK(x != NULL, "read %s", path);
    if (x) {
        CHECK(count_of(x, "GridType=\"Uniform\"") == 1, "misuse.xmf lists only frame 2");
        CHECK(strstr(x, "misuse.frames/000002.h5:/") != NULL, "misuse.xmf lists frame 2");
        free(x);
    }
    const char *left[] = {"particles.xmf.tmp", "particles.h5.tmp",
                          "particles.frames/000002.h5.tmp", "particles.frames/static.h5.tmp",
                          "misuse.frames/000003.h5.tmp", "misuse.frames/000003.h5",
                          "misuse.frames/000000.h5", "misuse.frames/000001.h5"};
    for (size_t i = 0; i < sizeof left / sizeof *left; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, left[i]);
        struct stat st;
        CHECK(stat(path, &st) != 0, "%s left behind (temporary or failed frame)", path);
    }
}

/* Identical input must give identical bytes (no timestamps in the file). */
static void check_same_bytes(const char *a, const char *b, const char *file)
{
    char pa[4200], pb[4200];
    snprintf(pa, sizeof pa, "%s/%s", a, file);
    snprintf(pb, sizeof pb, "%s/%s", b, file);
    FILE *fa = fopen(pa, "rb"), *fb = fopen(pb, "rb");
    CHECK(fa && fb, "open %s and %s", pa, pb);
    if (fa && fb) {
        int ca, cb;
        long off = 0;
        do {
            ca = fgetc(fa);
            cb = fgetc(fb);
            off++;
        } while (ca == cb && ca != EOF);
        CHECK(ca == cb, "%s and %s differ at byte %ld", pa, pb, off - 1);
    }
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
}

int main(void)
{
    const char *tmp = getenv("FSI_TEST_TMP");
    if (!tmp || !*tmp)
        tmp = "/tmp/fsi_test_h5";
    char dir[4096], again[4096];
    snprintf(dir, sizeof dir, "%s/h5_output", tmp);
    snprintf(again, sizeof again, "%s/h5_output_again", tmp);
    if (make_dirs(dir) != 0 || make_dirs(again) != 0) {
        fprintf(stderr, "FAIL: cannot create %s and %s: %s\n", dir, again, strerror(errno));
        return 1;
    }
    write_all(dir);
    /* HDF5 timestamps have one-second resolution: without the pause a file
     * with modification times could still compare equal. */
    sleep(1);
    write_all(again);
    check_h5(dir);
    check_misuse(dir);
    check_vertices(dir);
    check_held_by_reader(dir);
    check_xmf(dir);
    check_same_bytes(dir, again, "particles.h5");
    check_same_bytes(dir, again, "particles.frames/000000.h5");
    check_same_bytes(dir, again, "particles.frames/000002.h5");
    check_same_bytes(dir, again, "particles.frames/static.h5");
    check_same_bytes(dir, again, "particles.frames/vertices_7.h5");
    check_same_bytes(dir, again, "particles.xmf");
    if (failures) {
        fprintf(stderr, "test_h5_output: %d check(s) failed\n", failures);
        return 1;
    }
    printf("test_h5_output: all checks passed (files in %s)\n", dir);
    return 0;
}
