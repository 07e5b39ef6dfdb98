#!/usr/bin/python3
"""2D plane-stress finite-element reference for benchmark S1 (post-processing only).

Timoshenko's formula is beam theory; the PD solid solves 2D elasticity with a fully
clamped face. This solves the same 2D problem with biquadratic (9-node Lagrange)
elements, 3x3 Gauss points, the face x = 0 fully clamped (u = v = 0) and the tip load
as a uniform shear traction on x = L, and prints v at (L, H/2) against Timoshenko's
value. The elements do not lock in bending, so the answer converges fast with the mesh.

    /usr/bin/python3 bench/fe_cantilever.py [NX NY]      (default 100 x 20 elements)
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl

# S1 (docs/benchmarks.md, cases/s1_cantilever.ini)
L, H, E, NU, F = 1.0, 0.2, 22e9, 0.3, 85000.0


def shape_1d(t):
    """Quadratic Lagrange functions on [-1, 1] (nodes -1, 0, 1) and their derivatives."""
    return (np.array([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2]),
            np.array([t - 0.5, -2 * t, t + 0.5]))


def element_stiffness(hx, hy):
    d = E / (1 - NU ** 2) * np.array([[1, NU, 0], [NU, 1, 0], [0, 0, (1 - NU) / 2]])
    gauss = np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
    weight = np.array([5.0, 8.0, 5.0]) / 9.0
    k = np.zeros((18, 18))
    for a, wa in zip(gauss, weight):
        for b, wb in zip(gauss, weight):
            na, dna = shape_1d(a)
            nb, dnb = shape_1d(b)
            dndx = np.outer(dna, nb).ravel() * 2 / hx
            dndy = np.outer(na, dnb).ravel() * 2 / hy
            bm = np.zeros((3, 18))
            bm[0, 0::2] = dndx
            bm[1, 1::2] = dndy
            bm[2, 0::2] = dndy
            bm[2, 1::2] = dndx
            k += bm.T @ d @ bm * wa * wb * hx * hy / 4
    return k


def tip_deflection(nx, ny):
    nodes_x, nodes_y = 2 * nx + 1, 2 * ny + 1
    node = lambda i, j: i * nodes_y + j
    ndof = 2 * nodes_x * nodes_y
    ke = element_stiffness(L / nx, H / ny)
    rows, cols = [], []
    for ei in range(nx):
        for ej in range(ny):
            dofs = np.array([[2 * node(2 * ei + a, 2 * ej + b), 2 * node(2 * ei + a, 2 * ej + b) + 1]
                             for a in range(3) for b in range(3)]).ravel()
            rows.append(np.repeat(dofs, 18))
            cols.append(np.tile(dofs, 18))
    vals = np.tile(ke.ravel(), nx * ny)
    k = sp.csr_matrix((vals, (np.concatenate(rows), np.concatenate(cols))), shape=(ndof, ndof))
    f = np.zeros(ndof)
    traction = -F / H
    for ej in range(ny):    # consistent loads of a quadratic edge: 1/6, 4/6, 1/6
        for b, c in zip(range(3), (1 / 6, 4 / 6, 1 / 6)):
            f[2 * node(nodes_x - 1, 2 * ej + b) + 1] += traction * (H / ny) * c
    fixed = np.array([[2 * node(0, j), 2 * node(0, j) + 1] for j in range(nodes_y)]).ravel()
    free = np.setdiff1d(np.arange(ndof), fixed)
    u = np.zeros(ndof)
    u[free] = spl.spsolve(k[free][:, free].tocsc(), f[free])
    return u[1::2].reshape(nodes_x, nodes_y)[-1, ny]


def main():
    nx, ny = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) == 3 else (100, 20)
    g = E / (2 * (1 + NU))
    timoshenko = F * L ** 3 / (3 * E * H ** 3 / 12) + F * L / (5 / 6 * g * H)
    v = -tip_deflection(nx, ny)
    print(f"{nx} x {ny} elements: v(L, H/2) = {v:.6e} m, Timoshenko {timoshenko:.6e} m, "
          f"ratio {v / timoshenko:.5f}")


if __name__ == "__main__":
    main()
