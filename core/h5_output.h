/* Particle output: per participant a master file NAME.h5, an XDMF sidecar NAME.xmf
 * that ParaView opens as a time series, and a folder NAME.frames/ holding the data
 * (docs/output.md).
 *
 * Layout seen through NAME.h5 (external links into NAME.frames/):
 *   /                      attributes: participant, solver, dimension, fsi_version
 *   /static/<field>        written once (e.g. id, initial position, mass)
 *   /frames/NNNNNN/<field> one file per output frame, attributes time [s], step, frame
 *                          and the frame's constants (fsi_h5_write_frame_constant)
 * Every dataset carries the attributes unit and description its field was given
 * (fsi_h5_describe), integer flags also flag_values or flag_masks and flag_meanings.
 * Every frame holds "position" (n x FSI_DIM) and any number of point fields with
 * 1 (scalar), FSI_DIM (vector) or FSI_DIM*FSI_DIM (tensor) components.
 *
 * Robustness: every file is written under a temporary name, closed and renamed into
 * place, and never opened for writing again; NAME.h5 and NAME.xmf are rebuilt after
 * each complete frame. So a reader holding any file (ParaView, h5py, h5dump during the
 * run) never blocks the writer and always sees complete files, and a process killed
 * at any moment leaves files listing every complete frame.
 *
 * Ownership: the writer copies nothing it is given; arrays only need to live for the
 * duration of the call. */
#ifndef FSI_H5_OUTPUT_H
#define FSI_H5_OUTPUT_H

#include <stdint.h>

typedef struct fsi_h5_writer fsi_h5_writer;

/* Creates DIR/NAME.h5, DIR/NAME.xmf and DIR/NAME.frames/ (its stale *.h5 removed).
 * Returns NULL with a message on stderr when they cannot be created. */
fsi_h5_writer *fsi_h5_create(const char *dir, const char *name, const char *solver);

/* What a dataset holds (docs/output.md, "Units and meanings"): every dataset of that
 * name gets the attributes "unit" (SI, "1" for a pure number, e.g. "m/s", "kg/m^3")
 * and "description" (one sentence). field is a frame field's name ("velocity") or
 * "static/NAME" for a static field. "position" is described by the writer. Call before
 * the dataset is written; the strings are copied; a second call replaces the first. */
int fsi_h5_describe(fsi_h5_writer *w, const char *field, const char *unit,
                    const char *description);

typedef struct {
    const char *field, *unit, *description;
} fsi_h5_field_info;
/* fsi_h5_describe for each of n entries. */
int fsi_h5_describe_fields(fsi_h5_writer *w, const fsi_h5_field_info *info, int n);

/* The named values of an integer field (field as for fsi_h5_describe), as the CF
 * conventions write them: the attribute flag_values (FSI_H5_FLAG_VALUES: each point
 * holds one of the values) or flag_masks (FSI_H5_FLAG_MASKS: each point holds any sum
 * of the bits), n int32 values, and flag_meanings, their n names separated by single
 * spaces ("fluid wall moving_boundary"). */
enum { FSI_H5_FLAG_VALUES = 0, FSI_H5_FLAG_MASKS = 1 };
int fsi_h5_name_flags(fsi_h5_writer *w, const char *field, int kind, int n,
                      const int32_t *values, const char *meanings);

/* Static data, written once before or between frames. ncomp components per point. */
int fsi_h5_write_static_real(fsi_h5_writer *w, const char *field, const double *data,
                             int n, int ncomp);
int fsi_h5_write_static_int(fsi_h5_writer *w, const char *field, const int32_t *data,
                            int n, int ncomp);

/* From now on, frames of n points are stored in a fixed order although the caller's
 * arrays are permuted (a solver that reorders its particles for locality): row i of
 * every position and field array passed goes to row order[i] of the file (order a
 * permutation of 0..n-1, owned by the caller and valid until the next call or the
 * last frame). NULL: rows as passed. Frames of another size are stored as passed. */
int fsi_h5_set_point_order(fsi_h5_writer *w, const int *order, int n);

/* Opens frame 'frame' at simulated time 'time' after coupling window 'step',
 * with n points whose coordinates are position[n * FSI_DIM]. Frame numbers must
 * increase from call to call. */
int fsi_h5_begin_frame(fsi_h5_writer *w, int frame, double time, long step, int n,
                       const double *position);
/* A point field of the open frame: n * ncomp values, ncomp in {1, FSI_DIM, FSI_DIM^2}. */
int fsi_h5_write_field_real(fsi_h5_writer *w, const char *field, const double *data,
                            int ncomp);
int fsi_h5_write_field_int(fsi_h5_writer *w, const char *field, const int32_t *data,
                           int ncomp);
/* A value of the open frame that is the same for all its points (the smoothing
 * length): a float64 attribute of the frame's root group, and in the sidecar an
 * attribute of the whole grid (ParaView shows it as field data). */
int fsi_h5_write_frame_constant(fsi_h5_writer *w, const char *name, double value);
/* Closes the frame: publishes its file, then rebuilds NAME.h5 and the sidecar. */
int fsi_h5_end_frame(fsi_h5_writer *w);

/* Number of complete frames written so far. */
int fsi_h5_frames(const fsi_h5_writer *w);

void fsi_h5_close(fsi_h5_writer *w);

/* The message of the last failure of any writer of this process (file, what and the
 * system's reason; "" before any): for a solver's fsi_abort(). */
const char *fsi_h5_last_error(void);

#endif
