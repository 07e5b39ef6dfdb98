"""2D linear elasticity with biquadratic (9-node Lagrange) elements on a rectangle.

The finite-element references of bench/fe_cantilever.py (S1) and
bench/fe_clamped_plate.py (C4): the PD solid solves 2D elasticity, and beam or plate
formulas leave out what 2D elasticity keeps (shear deflection, the clamp's local
field). 3x3 Gauss points; the elements do not lock in bending, so the answer converges
fast with the mesh. Post-processing only (scipy from Debian).
"""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl


def elasticity_matrix(e, nu, plane):
    """Voigt D (xx, yy, xy with engineering shear) for 'stress' or 'strain'."""
    if plane == "stress":
        return e / (1 - nu ** 2) * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
    c = e / ((1 + nu) * (1 - 2 * nu))
    return c * np.array([[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])


def shape_1d(t):
    """Quadratic Lagrange functions on [-1, 1] (nodes -1, 0, 1) and their derivatives."""
    return (np.array([t * (t - 1) / 2, 1 - t * t, t * (t + 1) / 2]),
            np.array([t - 0.5, -2 * t, t + 0.5]))


GAUSS = np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
WEIGHT = np.array([5.0, 8.0, 5.0]) / 9.0


def element_stiffness(hx, hy, d):
    k = np.zeros((18, 18))
    for a, wa in zip(GAUSS, WEIGHT):
        for b, wb in zip(GAUSS, WEIGHT):
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


def element_load(hx, hy):
    """Consistent nodal weights of a unit body force on one element (sum hx hy)."""
    w = np.zeros(9)
    for a, wa in zip(GAUSS, WEIGHT):
        for b, wb in zip(GAUSS, WEIGHT):
            w += np.outer(shape_1d(a)[0], shape_1d(b)[0]).ravel() * wa * wb * hx * hy / 4
    return w


# Consistent nodal weights of a uniform traction on a quadratic edge (per edge length).
EDGE_WEIGHTS = (1 / 6, 4 / 6, 1 / 6)


class Mesh:
    """nx x ny elements on [0, lx] x [0, ly]; node (i, j) for i < 2 nx + 1, j < 2 ny + 1."""

    def __init__(self, nx, ny, lx, ly, d):
        self.nx, self.ny, self.lx, self.ly = nx, ny, lx, ly
        self.nodes_x, self.nodes_y = 2 * nx + 1, 2 * ny + 1
        self.ndof = 2 * self.nodes_x * self.nodes_y
        self.hx, self.hy = lx / nx, ly / ny
        ke = element_stiffness(self.hx, self.hy, d)
        rows, cols = [], []
        for ei in range(nx):
            for ej in range(ny):
                dofs = self.element_dofs(ei, ej)
                rows.append(np.repeat(dofs, 18))
                cols.append(np.tile(dofs, 18))
        vals = np.tile(ke.ravel(), nx * ny)
        self.k = sp.csr_matrix((vals, (np.concatenate(rows), np.concatenate(cols))),
                               shape=(self.ndof, self.ndof))

    def node(self, i, j):
        return i * self.nodes_y + j

    def element_dofs(self, ei, ej):
        return np.array([[2 * self.node(2 * ei + a, 2 * ej + b),
                          2 * self.node(2 * ei + a, 2 * ej + b) + 1]
                         for a in range(3) for b in range(3)]).ravel()

    def solve(self, f, fixed):
        """Displacements (nodes_x, nodes_y, 2) with the dofs 'fixed' held at zero."""
        free = np.setdiff1d(np.arange(self.ndof), fixed)
        u = np.zeros(self.ndof)
        u[free] = spl.spsolve(self.k[free][:, free].tocsc(), f[free])
        return u.reshape(self.nodes_x, self.nodes_y, 2)
