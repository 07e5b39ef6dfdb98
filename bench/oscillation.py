"""Period and amplitude of a free oscillation from a probe signal (post-processing).

Used by the solid validation benchmarks (S2, S3): the tip starts at rest in its
undeformed position with a mode-shaped velocity, so the signal is a sine about a
mean close to zero. The period is the mean spacing of successive same-direction
mean crossings (linearly interpolated), the amplitude the mean half peak-to-peak
over the complete cycles."""
import sys

import fsi_results


def crossings(t, u, level):
    """Times where u crosses level upwards (linear interpolation)."""
    out = []
    for i in range(1, len(u)):
        a, b = u[i - 1] - level, u[i] - level
        if a < 0.0 <= b:
            out.append(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (b - a))
    return out


def period_amplitude(t, u):
    """(period, amplitude, cycles) of a signal that oscillates about its mean."""
    level = 0.5 * (max(u) + min(u))
    up = crossings(t, u, level)
    down = crossings(t, [-x for x in u], -level)
    if len(up) < 2 and len(down) < 2:
        return float("nan"), float("nan"), 0
    spans = []
    for c in (up, down):
        if len(c) >= 2:
            spans.append(((c[-1] - c[0]), len(c) - 1))
    period = sum(s for s, _ in spans) / sum(n for _, n in spans)
    # Amplitude: half peak-to-peak of each full cycle between upward crossings.
    halves = []
    for a, b in zip(up, up[1:]):
        seg = [x for x, tt in zip(u, t) if a <= tt <= b]
        if seg:
            halves.append(0.5 * (max(seg) - min(seg)))
    if not halves:
        halves = [0.5 * (max(u) - min(u))]
    return period, sum(halves) / len(halves), max(len(up), len(down)) - 1


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: oscillation.py OUT_DIR PROBE_COLUMN")
    p = fsi_results.read_probes(sys.argv[1])
    period, amp, cycles = period_amplitude(p["time"], p[sys.argv[2]])
    print(f"period {period:.9g} amplitude {amp:.9g} cycles {cycles}")


if __name__ == "__main__":
    main()
