#!/usr/bin/python3
"""2D plane-strain finite-element reference for C4 (post-processing only).

C4's reference, 68.6 um (003 Eq. 53), is plate theory: it leaves out the shear
deflection and the clamps' local field, which the PD solid's 2D elasticity keeps. This
solves the 2D problem the coupled run approximates (bench/fe_plane.py): the plate
L x T, both ends fully clamped (u = v = 0, as the mirror clamps impose), its weight as a
body force and the water column's hydrostatic pressure rho_w g H on its upper face.
Prints v at mid-span, mid-thickness (the case's probe) against plate theory and the
Timoshenko beam with shear.

    /usr/bin/python3 bench/fe_clamped_plate.py [NX NY]      (default 400 x 20 elements)
"""
import sys

import numpy as np

from fe_plane import EDGE_WEIGHTS, Mesh, element_load, elasticity_matrix

# C4 (docs/validation.md, cases/c4_plate_under_water.ini)
C4 = dict(L=1.0, T=0.05, E=67.5e9, nu=0.34, rho_s=2700.0, rho_w=1000.0, H=2.0, g=9.81)


def plate_formulas(L, T, E, nu, rho_s, rho_w, H, g):
    """003 Eq. 53 (plate theory, plane strain, plate weight included) and the same with
    the shear of a built-in Timoshenko beam under a uniform load, q L^2 / (8 k G T) at
    mid-span (k = 5/6)."""
    q = g * (rho_w * H + rho_s * T)
    bending = 12 * (1 - nu ** 2) * q * L ** 4 / (384 * E * T ** 3)
    shear = q * L ** 2 / (8 * (5.0 / 6.0) * E / (2 * (1 + nu)) * T)
    return bending, bending + shear


def midspan_deflection(L, T, E, nu, rho_s, rho_w, H, g, nx=400, ny=20):
    """-v at (L/2, T/2) of the 2D plane-strain plate, both ends fully clamped."""
    mesh = Mesh(nx, ny, L, T, elasticity_matrix(E, nu, "strain"))
    f = np.zeros(mesh.ndof)
    body = element_load(mesh.hx, mesh.hy) * (-rho_s * g)
    for ei in range(nx):
        for ej in range(ny):
            f[mesh.element_dofs(ei, ej)[1::2]] += body
    pressure = rho_w * g * H
    for ei in range(nx):
        for a, c in zip(range(3), EDGE_WEIGHTS):
            f[2 * mesh.node(2 * ei + a, mesh.nodes_y - 1) + 1] -= pressure * mesh.hx * c
    fixed = np.array([[2 * mesh.node(i, j), 2 * mesh.node(i, j) + 1]
                      for i in (0, mesh.nodes_x - 1) for j in range(mesh.nodes_y)]).ravel()
    return -mesh.solve(f, fixed)[nx, ny, 1]


def main():
    nx, ny = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) == 3 else (400, 20)
    plate, timoshenko = plate_formulas(**C4)
    v = midspan_deflection(**C4, nx=nx, ny=ny)
    print(f"{nx} x {ny} elements: v(L/2, -T/2) = {v * 1e6:.3f} um; plate theory "
          f"{plate * 1e6:.3f} um (ratio {v / plate:.5f}), Timoshenko {timoshenko * 1e6:.3f} um "
          f"(ratio {v / timoshenko:.5f})")


if __name__ == "__main__":
    main()
