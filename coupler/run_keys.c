/* The [run] section: time, windows, output cadence and liveness (docs/cases.md). */
#include "run_keys.h"

#include <math.h>
#include <string.h>

#include "case_check.h"
#include "protocol.h"

static const fsi_key_spec run_keys[] = {
    {"title", FSI_KEY_STRING, "-", "untitled", 0, 0, 0, NULL,
     "Name of the scene, printed in the run log."},
    {"end_time", FSI_KEY_REAL, "s", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Simulated time at which the run ends."},
    {"scheme", FSI_KEY_CHOICE, "-", "serial_staggered", 0, 0, 0, "serial_staggered|implicit",
     "Coupling scheme: serial_staggered = explicit: solid state at t_k, fluid advances, "
     "fluid loads, solid advances (sub-cycling inside the window), once per window; "
     "implicit = the same sequence repeated within the window, both sides restarting from "
     "the window's start, until the interface motion and loads converge "
     "(coupling_tolerance), with the motion of each repetition chosen by "
     "coupling_acceleration (docs/coupling.md, Implicit coupling)."},
    {"coupling_tolerance", FSI_KEY_REAL, "-", "1e-4", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0,
     1.0, NULL,
     "Implicit: a window has converged when the relative residual of the interface "
     "displacement over the window, |d_out - d_in| / |d_out|, and the relative change of "
     "the fluid's loads from the last iteration, |F_i - F_{i-1}| / |F_i|, are both below "
     "this (the force measure from the second iteration on)."},
    {"coupling_absolute_tolerance", FSI_KEY_REAL, "m", "1e-12", FSI_BOUND_MIN, 0, 0, NULL,
     "Implicit: a displacement residual below this RMS over the interface particles counts "
     "as converged whatever the relative measure says (a structure at rest moves by "
     "round-off only)."},
    {"coupling_min_iterations", FSI_KEY_INT, "-", "1", FSI_BOUND_MIN, 1, 0, NULL,
     "Implicit: iterations every window takes before convergence is judged."},
    {"coupling_max_iterations", FSI_KEY_INT, "-", "50", FSI_BOUND_MIN, 1, 0, NULL,
     "Implicit: iterations after which a window that has not converged is given up; "
     "coupling_on_max_iterations says what then."},
    {"coupling_on_max_iterations", FSI_KEY_CHOICE, "-", "stop", 0, 0, 0, "stop|continue",
     "Implicit: stop = the run stops, naming the window, its time and the residuals; "
     "continue = the last iteration is accepted with a warning (counted in the run log)."},
    {"coupling_acceleration", FSI_KEY_CHOICE, "-", "iqn_ils", 0, 0, 0,
     "constant|aitken|iqn_ils",
     "Implicit: how the next iteration's interface motion follows from the last ones: "
     "constant under-relaxation (coupling_relaxation), Aitken's dynamic relaxation "
     "(Kuttler & Wall 2008) or interface quasi-Newton with least-squares Jacobian, IQN-ILS "
     "(Degroote, Bathe & Vierendeels 2009)."},
    {"coupling_relaxation", FSI_KEY_REAL, "-", "0.5", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0,
     1.0, NULL,
     "Implicit: the relaxation factor of constant relaxation, and the first one of Aitken "
     "and of IQN-ILS (when it has no history yet) in each window."},
    {"coupling_reuse", FSI_KEY_INT, "-", "8", FSI_BOUND_MIN, 0, 0, NULL,
     "Implicit, IQN-ILS: accepted windows whose secant pairs are reused; the history "
     "restarts when the set of interface particles changes (fracture, particles entering "
     "the fluid's reach)."},
    {"coupling_filter", FSI_KEY_REAL, "-", "1e-10", FSI_BOUND_MIN, 0, 0, NULL,
     "Implicit, IQN-ILS: a secant pair whose part not spanned by the newer ones is below "
     "this fraction of its norm is dropped (the relative Gram-Schmidt filter, QR2 of "
     "Haelterman et al. 2016)."},
    {"coupling_max_columns", FSI_KEY_INT, "-", "100", FSI_BOUND_MIN, 1, 0, NULL,
     "Implicit, IQN-ILS: most secant pairs kept; the oldest go first."},
    {"max_window", FSI_KEY_REAL, "s", "1e-3", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Largest coupling window; the window is the smallest of this and the participants' "
     "proposed stable steps."},
    {"output_interval", FSI_KEY_REAL, "s", "0.01", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Simulated time between output frames; windows end exactly on frame times so fluid "
     "and solid frames line up."},
    {"checkpoint_interval", FSI_KEY_REAL, "s", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Simulated time between coupled checkpoints of the coupler and every participant "
     "(fsi run --checkpoint-interval sets it), each taken at the first output frame time from "
     "a multiple of it on; fsi run --restart OUT goes on from the newest complete one "
     "(docs/checkpoints.md). 0: none."},
    {"probe_interval", FSI_KEY_REAL, "s", "1e-3", FSI_BOUND_MIN, 0, 0, NULL,
     "Simulated time between rows of probes.csv; 0 writes a row after every window."},
    {"heartbeat_interval", FSI_KEY_REAL, "s", "0.25", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0,
     2.0, NULL, "Wall time between liveness messages of every process."},
    /* The defaults are FSI_DEFAULT_HEARTBEAT_INTERVAL and FSI_DEFAULT_WATCHDOG_TIMEOUT
     * (protocol.h), written out because the table holds text. */
    {"watchdog_timeout", FSI_KEY_REAL, "s", "10", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 60.0,
     NULL,
     "A process not heard from for this long (wall time) is taken as dead or hung and the "
     "run stops, naming it. At least twice heartbeat_interval."},
    {"window_timeout", FSI_KEY_REAL, "s", "600", FSI_BOUND_MIN, 0, 0, NULL,
     "Longest wall time one coupling window may take while everyone is alive (a deadlock "
     "between participants keeps their heartbeats going); the run stops naming who has not "
     "reported. 0 switches the check off."},
    {"register_timeout", FSI_KEY_REAL, "s", "30", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Wall time the coupler waits for every participant to register."},
    {"progress_interval", FSI_KEY_REAL, "s", "2", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Wall time between progress lines."},
};

const fsi_key_table fsi_run_key_table = {
    "run", "Time, coupling windows, output cadence and liveness of the whole run.", run_keys,
    (int)(sizeof run_keys / sizeof run_keys[0])};

int fsi_run_keys_check(const fsi_case *c, FILE *errors)
{
    int n = 0;
    double heartbeat =
        fsi_case_get_real(c, "run", "heartbeat_interval", FSI_DEFAULT_HEARTBEAT_INTERVAL);
    double watchdog =
        fsi_case_get_real(c, "run", "watchdog_timeout", FSI_DEFAULT_WATCHDOG_TIMEOUT);
    /* Two missed heartbeats must not yet count as death: a loaded machine delays one. */
    if (watchdog < 2.0 * heartbeat) {
        const char *at = fsi_case_origin(c, "run", "watchdog_timeout");
        fprintf(errors,
                "%s: [run] watchdog_timeout: %g s is less than twice heartbeat_interval "
                "(%g s): live processes would be declared dead\n",
                at && strcmp(at, "default") != 0 ? at : fsi_case_path(c), watchdog, heartbeat);
        n++;
    }
    double output = fsi_case_get_real(c, "run", "output_interval", 0.01);
    double end = fsi_case_get_real(c, "run", "end_time", 0.0);
    if (output > 0 && end / output > 1e6) {
        const char *at = fsi_case_origin(c, "run", "output_interval");
        fprintf(errors, "%s: [run] output_interval: %g s gives %.3g frames up to end_time "
                        "%g s (more than a million)\n",
                at && strcmp(at, "default") != 0 ? at : fsi_case_path(c), output, end / output,
                end);
        n++;
    }
    /* Windows end on probe times too (and on frame times, whose count is bounded
     * above): the shorter of the two bounds the window, and every window is at least
     * one step of every participant. */
    static const struct {
        const char *key;
        double reference;   /* the key's default */
    } window_keys[] = {{"max_window", 1e-3}, {"probe_interval", 1e-3}};
    fsi_step_factor shortest = {"run", NULL, INFINITY, 1.0, 1.0};
    for (size_t i = 0; i < sizeof window_keys / sizeof window_keys[0]; i++) {
        const double v = fsi_case_get_real(c, "run", window_keys[i].key, 0.0);
        if (v > 0.0 && v < shortest.value)
            shortest = (fsi_step_factor){"run", window_keys[i].key, v, window_keys[i].reference,
                                         1.0};
    }
    if (shortest.key) {
        fsi_case_checker k = {c, errors, 0};
        char what[128];
        snprintf(what, sizeof what, "the coupling window (%s)", shortest.key);
        n += fsi_case_check_step(&k, shortest.value, what, &shortest, 1);
    }
    return n;
}
