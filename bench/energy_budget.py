#!/usr/bin/python3
"""Where a coupled run's energy comes from, from its two diagnostics files.

    bench/energy_budget.py RUN_DIR [--interval S]

For every interval it prints, since the start (J, or J/m in 2D):
  - the fluid's energy change, K + P + E_c, and what its budget allows, the walls'
    work minus the work it did on the solid's moving boundary (docs/output.md); their
    difference is energy the fluid scheme made (positive) or dissipated (negative);
  - the same for the solid: K + U + P against the interface and impedance works;
  - the coupling's gap, the fluid's work on the boundary minus the work the solid
    received over its own motion: the energy the exchange itself made (the lag of the
    motion the fluid is given, docs/coupling.md).
A run that gains energy shows in which of the three it does. Reads only; an
unfinished run's files are read as far as they go.
"""
import argparse
import os
import sys

import numpy as np


def read(path):
    if not os.path.exists(path):
        sys.exit(f"energy_budget: {path}: no such file (a coupled run's folder?)")
    # the names, then a '# units' line (a comment to genfromtxt), then one row a window
    data = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))
    if data.size < 1:
        sys.exit(f"energy_budget: {path}: no rows yet")
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run", help="a run's output folder (fluid_ and solid_diagnostics.csv)")
    ap.add_argument("--interval", type=float, default=0.01, help="rows every S seconds")
    a = ap.parse_args()
    if not a.interval > 0:
        sys.exit("energy_budget: --interval must be positive")
    f = read(os.path.join(a.run, "fluid_diagnostics.csv"))
    s = read(os.path.join(a.run, "solid_diagnostics.csv"))
    fe = f["kinetic_energy"] + f["potential_energy"] + f["compression_energy"]
    fe = fe - fe[0]
    f_allowed = f["wall_work"] - f["boundary_work"]
    se = s["kinetic_energy"] + s["strain_energy"] + s["potential_energy"]
    se = se - se[0]
    s_allowed = s["interface_work"] + s["impedance_work"]
    print("energies since the start [J, J/m in 2D]; 'made' = change - what the budget allows")
    print(f"{'t [s]':>8} | {'fluid dE':>9} {'allowed':>9} {'made':>9} | "
          f"{'solid dE':>9} {'allowed':>9} {'made':>9} | {'exchange':>9} | {'total made':>10}")
    end = min(f["time"][-1], s["time"][-1])
    t = a.interval
    while True:
        t = min(t, end)
        i = np.searchsorted(f["time"], t * (1 + 1e-12), side="right") - 1
        j = np.searchsorted(s["time"], t * (1 + 1e-12), side="right") - 1
        fm = fe[i] - f_allowed[i]
        sm = se[j] - s_allowed[j]
        gap = f["boundary_work"][i] - s["interface_work"][j]
        print(f"{f['time'][i]:8.4f} | {fe[i]:9.4g} {f_allowed[i]:9.4g} {fm:9.4g} | "
              f"{se[j]:9.4g} {s_allowed[j]:9.4g} {sm:9.4g} | {gap:9.4g} | {fm + sm + gap:10.4g}")
        if t >= end:
            break
        t += a.interval


if __name__ == "__main__":
    main()
