#!/usr/bin/python3
"""2D plane-stress finite-element reference for benchmark S1 (post-processing only).

Timoshenko's formula is beam theory; the PD solid solves 2D elasticity with a fully
clamped face. This solves the same 2D problem (bench/fe_plane.py), the face x = 0 fully
clamped (u = v = 0) and the tip load as a uniform shear traction on x = L, and prints
v at (L, H/2) against Timoshenko's value.

    /usr/bin/python3 bench/fe_cantilever.py [NX NY]      (default 100 x 20 elements)
"""
import sys

import numpy as np

from fe_plane import EDGE_WEIGHTS, Mesh, elasticity_matrix

# S1 (docs/validation.md, cases/s1_cantilever.ini)
L, H, E, NU, F = 1.0, 0.2, 22e9, 0.3, 85000.0


def tip_deflection(nx, ny):
    mesh = Mesh(nx, ny, L, H, elasticity_matrix(E, NU, "stress"))
    f = np.zeros(mesh.ndof)
    traction = -F / H
    for ej in range(ny):
        for b, c in zip(range(3), EDGE_WEIGHTS):
            f[2 * mesh.node(mesh.nodes_x - 1, 2 * ej + b) + 1] += traction * mesh.hy * c
    fixed = np.array([[2 * mesh.node(0, j), 2 * mesh.node(0, j) + 1]
                      for j in range(mesh.nodes_y)]).ravel()
    return mesh.solve(f, fixed)[-1, ny, 1]


def main():
    nx, ny = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) == 3 else (100, 20)
    g = E / (2 * (1 + NU))
    timoshenko = F * L ** 3 / (3 * E * H ** 3 / 12) + F * L / (5 / 6 * g * H)
    v = -tip_deflection(nx, ny)
    print(f"{nx} x {ny} elements: v(L, H/2) = {v:.6e} m, Timoshenko {timoshenko:.6e} m, "
          f"ratio {v / timoshenko:.5f}")


if __name__ == "__main__":
    main()
