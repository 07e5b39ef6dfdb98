/* Example fluid participant: a linear dashpot (plus an optional spring) on every solid
 * particle it is sent, F_y = -c v_y - k_f u_y, evaluated from the solid state at the
 * start of the window as the serial-staggered scheme prescribes. Its only state is the
 * total it has sent, which it saves at a window's start and restores when an implicit
 * coupling repeats the window. */
#include <math.h>
#include <stdlib.h>

#include "dim.h"
#include "h5_output.h"
#include "log.h"
#include "participant.h"

typedef struct {
    int capacity;
    double *force, *pressure;
} loads;

static int loads_reserve(loads *l, int n)
{
    if (n <= l->capacity)
        return 0;
    double *f = realloc(l->force, (size_t)n * FSI_DIM * sizeof(double));
    if (f)
        l->force = f;
    double *pr = realloc(l->pressure, (size_t)n * sizeof(double));
    if (pr)
        l->pressure = pr;
    if (!f || !pr)
        return -1;
    l->capacity = n;
    return 0;
}

/* What the dashpot carries from one window to the next: its state. */
typedef struct {
    double impulse_y;   /* sum of F_y dt over its particles and windows [N s] */
    long windows;       /* windows computed */
} dashpot_state;

static void dashpot_loads(loads *l, const fsi_interface *solid, double damping,
                          double stiffness)
{
    for (int i = 0; i < solid->n; i++) {
        for (int d = 0; d < FSI_DIM; d++)
            l->force[i * FSI_DIM + d] = 0.0;
        double fy = -damping * solid->velocity[i * FSI_DIM + 1] -
                    stiffness * solid->position[i * FSI_DIM + 1];
        l->force[i * FSI_DIM + 1] = fy;
        /* A pressure the way a fluid would report it: normal load per unit face. */
        double face = pow(solid->volume[i], (FSI_DIM - 1.0) / FSI_DIM);
        l->pressure[i] = -fy / face;
    }
}

int main(void)
{
    fsi_participant *p = fsi_open(NULL, "fluid", NULL, 1e-3);
    if (!p)
        return FSI_EXIT_RUN_FAILURE;
    const fsi_case *c = fsi_participant_case(p);
    double damping = fsi_case_get_real(c, "fluid", "damping", 2.0);
    double stiffness = fsi_case_get_real(c, "fluid", "stiffness", 0.0);
    double time_step = fsi_case_get_real(c, "fluid", "time_step", 1e-3);
    fsi_h5_writer *out = fsi_h5_create(fsi_output_dir(p), fsi_participant_name(p),
                                       "linear_dashpot");
    /* What each field holds: attributes unit and description (docs/output.md). */
    static const fsi_h5_field_info fields[] = {
        {"force", "N", "Dashpot force on the solid particle, -c v_y - k_f u_y along y."},
        {"pressure", "Pa", "The force's normal part per face of the particle's cell."},
    };
    if (!out || fsi_h5_describe_fields(out, fields, 2) != 0) {
        fsi_abort(p, "cannot create the output file");
        return FSI_EXIT_RUN_FAILURE;
    }
    int probe_fy = fsi_add_probe(p, "load0_fy [N]");
    fsi_timers timers = {0};
    int t_loads = fsi_timer_index(&timers, "fluid_loads");
    loads l = {0};
    fsi_interface solid;
    dashpot_state state = {0}, saved = {0};
    fsi_state on_disk = {0};
    /* A run restarted from a coupled checkpoint goes on from its state. */
    if (fsi_restart_state(p) &&
        fsi_state_get(fsi_restart_state(p), "dashpot", &state, sizeof state) != 0) {
        fsi_abort(p, "the checkpoint holds no dashpot state");
        return fsi_close(p, NULL);
    }

    while (fsi_ongoing(p)) {
        /* Implicit coupling: back to the window's start when it is repeated; saved at
         * its first iteration, and written when the coupler takes a checkpoint. */
        if (fsi_requires_reading_checkpoint(p))
            state = saved;
        if (fsi_requires_writing_checkpoint(p)) {
            saved = state;
            fsi_state_clear(&on_disk);
            if (fsi_state_put(&on_disk, "dashpot", &saved, sizeof saved) != 0 ||
                fsi_write_checkpoint(p, &on_disk) != 0) {
                fsi_abort(p, "cannot write the checkpoint of window %d", fsi_window_index(p));
                break;
            }
        }
        fsi_read_interface(p, &solid);
        if (loads_reserve(&l, solid.n) != 0) {
            fsi_abort(p, "out of memory for %d interface particles", solid.n);
            break;
        }
        fsi_timer_start(&timers, t_loads);
        dashpot_loads(&l, &solid, damping, stiffness);
        fsi_timer_stop(&timers, t_loads);
        for (int i = 0; i < solid.n; i++)
            state.impulse_y += l.force[i * FSI_DIM + 1] * fsi_window(p);
        state.windows++;
        fsi_interface reply = {.n = solid.n, .id = solid.id, .pressure = l.pressure,
                               .force = l.force};
        fsi_write_interface(p, &reply);
        fsi_set_probe(p, probe_fy, solid.n > 0 ? l.force[1] : 0.0);
        fsi_advance(p, time_step);
        /* The frame at the window's end shows the loads applied during it; only once
         * the window is accepted (always, in an explicit run). */
        if (fsi_window_complete(p) && fsi_output_frame(p) >= 0 && solid.n > 0 &&
            (fsi_h5_begin_frame(out, fsi_output_frame(p), fsi_time(p) + fsi_window(p),
                                fsi_window_index(p), solid.n, solid.position) != 0 ||
             fsi_h5_write_field_real(out, "force", l.force, FSI_DIM) != 0 ||
             fsi_h5_write_field_real(out, "pressure", l.pressure, 1) != 0 ||
             fsi_h5_end_frame(out) != 0)) {
            fsi_abort(p, "cannot write output frame %d: %s", fsi_output_frame(p),
                      fsi_h5_last_error());
            break;
        }
    }
    fsi_info("loads sent: impulse %.9g N s (y) in %ld windows", state.impulse_y, state.windows);
    fsi_h5_close(out);
    fsi_state_free(&on_disk);
    free(l.force);
    free(l.pressure);
    return fsi_close(p, &timers);
}
