"""What every discrete thermal model hands to the solver driver.

A model (network or axisymmetric FE) reduces :class:`~ballscrew.thermal.problem.ThermalProblem`
to the matrices of C dθ/dt + A(w) θ = f(w), where w are the time fractions of the nut's stroke
offsets (:attr:`AxialGrid.weights` for the time average, one offset for a resolved stroke), and
to linear read-outs of the unknowns: sensors, elongation, screw temperature along the axis.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray

from ballscrew.thermal.problem import AxialGrid, ThermalProblem, same_mesh

Assembler = Callable[[NDArray[np.float64]], tuple[sp.csr_matrix, NDArray[np.float64]]]


@dataclass(frozen=True)
class Discretisation:
    """Matrices and read-outs of one discrete thermal model."""

    model: str
    """'network' or 'axisymmetric'."""
    problem: ThermalProblem
    grid: AxialGrid
    capacity: sp.csr_matrix
    """C [J/K]."""
    assemble: Assembler
    """Stroke-offset weights → (A [W/K], f [W])."""
    elongation: NDArray[np.float64]
    """Row e with ΔL = e·θ = α∫θ̄ dz over the shaft [m/K]."""
    sensors: sp.csr_matrix
    """Rows reading the sensor temperature rises [-]."""
    axis_z: NDArray[np.float64]
    """Axial stations of the shaft profile [m]."""
    axis: sp.csr_matrix
    """Rows reading the cross-section mean rise of the shaft at ``axis_z``."""
    direct_limit: int = 60_000
    """Largest size solved by sparse LU (2-D fill is small, so 2-D models raise it)."""
    extra: dict[str, Any] = field(default_factory=dict)
    """Model-specific data for fields and plots (mesh, cells)."""
    rebind: Callable[[ThermalProblem], Discretisation] | None = None
    """The same mesh and matrices bound to another problem that
    :func:`~ballscrew.thermal.problem.same_mesh` accepts (None: the model builds anew)."""

    def rebound(self, problem: ThermalProblem) -> Discretisation | None:
        """This model's mesh and matrices with the loads and coefficients of ``problem``, or
        None when its mesh does not fit ``problem`` (or the model cannot re-bind)."""
        if self.rebind is None or not same_mesh(self.problem, problem):
            return None
        return self.rebind(problem)

    @property
    def unknowns(self) -> int:
        """Number of unknowns."""
        return int(self.capacity.shape[0])


def nut_mean_row(disc: Discretisation) -> NDArray[np.float64]:
    """Row r with r·θ the mean rise of the nut assembly: its volume mean (1/V)∫θ dV on the FE
    models (``extra['nut_mean']``), the mean of its cells' mean rises on the network."""
    row = disc.extra.get("nut_mean")
    if row is not None:
        return np.asarray(row)
    ring = disc.extra["ring_mean"]
    out = np.zeros(disc.unknowns)
    out[ring] = 1.0 / len(ring)
    return out


def coolant_outlet_rise(disc: Discretisation, theta: NDArray[np.float64]) -> float | None:
    """Bulk rise of the bore coolant at its outlet, its last cell (``extra['coolant']``, inlet
    to outlet) [K]; None for a solid shaft."""
    cells = disc.extra.get("coolant")
    return None if cells is None or len(cells) == 0 else float(theta[cells[-1]])


Entries = tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64]]
"""(rows, columns, values) of sparse matrix entries; repeated positions add up."""


def links(i: NDArray[np.int64], j: NDArray[np.int64], g: NDArray[np.float64]) -> Entries:
    """Entries of the conductance matrix of resistors g between nodes i and j [W/K]."""
    i, j, g = np.asarray(i), np.asarray(j), np.asarray(g, dtype=float)
    return (
        np.concatenate([i, j, i, j]),
        np.concatenate([i, j, j, i]),
        np.concatenate([g, g, -g, -g]),
    )


def laplacian(
    n: int,
    i: NDArray[np.int64],
    j: NDArray[np.int64],
    g: NDArray[np.float64],
    ground: NDArray[np.float64] | None = None,
) -> sp.csr_matrix:
    """Conductance matrix of resistors g between nodes i and j, plus g_0 to ambient [W/K]."""
    rows, cols, vals = links(i, j, g)
    a = sp.coo_matrix((vals, (rows, cols)), shape=(n, n)).tocsr()
    if ground is not None:
        a = a + sp.diags(np.asarray(ground, dtype=float))
    return sp.csr_matrix(a)


def band_overlap(
    edges: NDArray[np.float64], centre: float, width: float, length: float
) -> NDArray[np.float64]:
    """Length of each cell [edges[k], edges[k+1]] inside the band, band clipped to [0, L]."""
    lo = max(centre - 0.5 * width, 0.0)
    hi = min(centre + 0.5 * width, length)
    return np.clip(np.minimum(edges[1:], hi) - np.maximum(edges[:-1], lo), 0.0, None)
