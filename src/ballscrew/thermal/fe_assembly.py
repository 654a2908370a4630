"""Matrices shared by the finite-element thermal models (axisymmetric and 3-D).

Body conduction and capacity, convection, and the ball-contact coupling between the nut bore and
the screw surface over the stroke.

Both models hold the screw shaft (body 0) and the nut assembly (body 1) in one scikit-fem mesh,
each with its own conductivity and heat capacity, and lose heat by convection on the tagged end
and outer faces. Only their weak forms differ (2πr weighting in the axisymmetric one).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray
from scipy.spatial import cKDTree
from skfem import Basis, BilinearForm, FacetBasis, LinearForm, asm

from ballscrew.errors import InputError
from ballscrew.thermal.problem import AxialGrid, ThermalProblem

CONVECTIVE_FACES = ("shaft_ends", "ring_outer", "ring_ends")
"""Faces with a fixed convection coefficient; the screw surface is handled per stroke offset."""

AreaWeight = Callable[[NDArray[np.float64], NDArray[np.float64]], NDArray[np.float64]]
"""(integrand, quadrature points x) → integrand times the model's area weight (2πr in the
axisymmetric model, 1 in 3-D); the axial coordinate is the last one of x."""


def body_matrices(
    basis: Basis,
    intorder: int,
    body: NDArray[np.int64],
    problem: ThermalProblem,
    conduction: BilinearForm,
    mass: BilinearForm,
) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """Conduction and capacity matrices K = Σ_bodies λ_b ∫ ∇u·∇v, C = Σ_bodies ρc_b ∫ u v.

    ``body`` gives each element's body (0 = shaft, 1 = nut assembly); ``conduction`` and ``mass``
    are the model's weak forms (with the 2πr weight in the axisymmetric model).
    """
    mesh, element = basis.mesh, basis.elem
    conductance = sp.csr_matrix((basis.N, basis.N))
    capacity = sp.csr_matrix((basis.N, basis.N))
    for b, solid in ((0, problem.shaft), (1, problem.ring)):
        cb = Basis(mesh, element, elements=np.nonzero(body == b)[0], intorder=intorder)
        conductance = conductance + solid.conductivity * asm(conduction, cb)
        capacity = capacity + solid.heat_capacity * asm(mass, cb)
    return conductance, capacity


def body_integrals(
    basis: Basis, intorder: int, body: NDArray[np.int64], measure: LinearForm
) -> tuple[Basis, NDArray[np.float64], NDArray[np.float64]]:
    """(shaft basis, ∫_shaft φ_i dV, nut-assembly mean row ∫_nut φ_i dV / V_nut).

    ``measure`` is the model's unit load form (v, or v·2πr in the axisymmetric model).
    """
    mesh, element = basis.mesh, basis.elem
    shaft = Basis(mesh, element, elements=np.nonzero(body == 0)[0], intorder=intorder)
    ring = Basis(mesh, element, elements=np.nonzero(body == 1)[0], intorder=intorder)
    volume = np.asarray(asm(measure, ring))
    return shaft, np.asarray(asm(measure, shaft)), volume / volume.sum()


def face_matrices(
    basis: Basis,
    intorder: int,
    facets: Mapping[str, NDArray[np.int64]],
    mass: BilinearForm,
    names: Sequence[str] = CONVECTIVE_FACES,
) -> dict[str, sp.csr_matrix]:
    """Unit film matrices ∫_f u v of the named faces that have facets (h = 1 W/(m² K))."""
    out = {}
    for name in names:
        if facets[name].size:
            face = FacetBasis(basis.mesh, basis.elem, facets=facets[name], intorder=intorder)
            out[name] = sp.csr_matrix(asm(mass, face))
    return out


def bearing_loads(
    problem: ThermalProblem, surface: FacetBasis, weight: AreaWeight, size: float
) -> tuple[NDArray[np.float64], ...]:
    """Per bearing: its load vector for 1 W, spread evenly over its band of the shaft surface.

    g_i = ∫_band φ_i dA / ∫_band dA on ``surface`` (the shaft surface's facet basis), the band
    being the bearing's width clipped to the shaft; ``size`` is the axial element size, which a
    band must exceed to be seen by the quadrature.
    """
    loads = []
    for bearing in problem.bearings:
        lo = max(bearing.position - 0.5 * bearing.width, 0.0)
        hi = min(bearing.position + 0.5 * bearing.width, problem.shaft_length)

        @LinearForm
        def band(v, w, lo=lo, hi=hi):
            inside = (w.x[-1] >= lo) & (w.x[-1] <= hi)
            return weight(inside * v, w.x)

        g = np.asarray(asm(band, surface))
        if not g.sum() > 0.0:
            raise InputError(
                f"bearings.{bearing.name}.width",
                bearing.width,
                f"a band wider than the mesh {size:g} m",
            )
        loads.append(g / g.sum())
    return tuple(loads)


def surface_film(
    grid: AxialGrid, surface: FacetBasis, weight: AreaWeight
) -> Callable[[NDArray[np.float64]], sp.csr_matrix]:
    """Stroke weights → unit film of the shaft surface outside the nut, ∫(1 − coverage) u v dA."""

    def film(weights: NDArray[np.float64]) -> sp.csr_matrix:
        @BilinearForm
        def form(u, v, w):
            return weight((1.0 - grid.coverage(w.x[-1], weights)) * u * v, w.x)

        return asm(form, surface)

    return film


@dataclass(frozen=True)
class BoreInterface:
    """The nut bore of one nut, ready for the contact coupling of :func:`interface_terms`.

    ``mass`` and ``load`` are the bore's facet mass matrix and load vector weighted by a density
    that integrates to 1 over the bore (uniform 1/A_bore when the balls are smeared, or one
    patch per ball), so a conductance in W/K and heat flows in W apply to them directly.
    """

    dofs: NDArray[np.int64]
    """Nut-side bore DOFs."""
    pairs: list[NDArray[np.int64]]
    """Screw-surface twin of each bore DOF, one array per stroke offset."""
    mass: sp.csr_matrix
    """Weighted facet mass matrix on the bore DOFs, ∫ ρ u v dΓ."""
    load: NDArray[np.float64]
    """Weighted facet load on the bore DOFs, ∫ ρ v dΓ (sums to 1)."""


def twin_dofs(
    tree: cKDTree,
    surface_dofs: NDArray[np.int64],
    bore_locations: NDArray[np.float64],
    shifts: NDArray[np.int64],
    dz: float,
) -> list[NDArray[np.int64]]:
    """The screw-surface DOF facing each nut-bore DOF, for every stroke offset m·dz.

    ``tree`` indexes the screw-surface DOF locations; ``bore_locations`` has the axial
    coordinate in its last row. Duplicated interface nodes coincide exactly, so a mismatch is a
    meshing bug.
    """
    pairs = []
    for m in shifts:
        shifted = bore_locations.copy()
        shifted[-1] += m * dz
        dist, idx = tree.query(shifted.T)
        if np.max(dist) > 1e-6 * dz:
            raise RuntimeError("nut bore and shaft surface DOFs do not align")  # a bug
        pairs.append(surface_dofs[idx])
    return pairs


def interface_terms(
    n: int,
    couplings: Sequence[tuple[BoreInterface, float, float, float]],
    weights: NDArray[np.float64],
) -> tuple[sp.csr_matrix | None, NDArray[np.float64]]:
    """Contact coupling and contact heat of the nuts, averaged over the stroke offsets.

    For each (bore, conductance G [W/K], nut-side heat [W], screw-side heat [W]) and each
    offset k of weight w_k the jump term w_k·G·Jᵀ M J couples bore DOF i to its screw twin
    (J = +1 on the bore, −1 on the twin), the nut-side heat goes into the bore and w_k of the
    screw-side heat into the twins. Returns (sum of the jump terms or None, load vector).
    """
    f = np.zeros(n)
    jumps = []
    for bore, conductance, nut_heat, screw_heat in couplings:
        f[bore.dofs] += nut_heat * bore.load
        nb = bore.dofs.size
        rows = np.r_[np.arange(nb), np.arange(nb)]
        for k in np.nonzero(weights)[0]:
            np.add.at(f, bore.pairs[k], weights[k] * screw_heat * bore.load)
            if conductance > 0.0:
                values = np.r_[np.ones(nb), -np.ones(nb)]
                jump = sp.csr_matrix((values, (rows, np.r_[bore.dofs, bore.pairs[k]])), (nb, n))
                jumps.append(weights[k] * conductance * (jump.T @ bore.mass @ jump))
    return (sum(jumps[1:], jumps[0]) if jumps else None), f
