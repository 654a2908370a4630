"""Matrices shared by the finite-element thermal models (axisymmetric and 3-D).

Both models hold the screw shaft (body 0) and the nut assembly (body 1) in one scikit-fem mesh,
each with its own conductivity and heat capacity, and lose heat by convection on the tagged end
and outer faces. Only their weak forms differ (2πr weighting in the axisymmetric one).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray
from skfem import Basis, BilinearForm, FacetBasis, asm

from ballscrew.thermal.problem import ThermalProblem

CONVECTIVE_FACES = ("shaft_ends", "ring_outer", "ring_ends")
"""Faces with a fixed convection coefficient; the screw surface is handled per stroke offset."""


def body_and_convection_matrices(
    basis: Basis,
    intorder: int,
    body: NDArray[np.int64],
    facets: Mapping[str, NDArray[np.int64]],
    problem: ThermalProblem,
    conduction: BilinearForm,
    mass: BilinearForm,
) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """Conductance (conduction + convection on :data:`CONVECTIVE_FACES`) and capacity matrices.

        K = Σ_bodies λ_b ∫ ∇u·∇v + Σ_faces h_f ∫_f u v ,   C = Σ_bodies ρc_b ∫ u v

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
    conv = problem.convection
    for name, h in zip(CONVECTIVE_FACES, (conv.screw_ends, conv.nut, conv.nut_ends), strict=True):
        if h > 0.0 and facets[name].size:
            face = FacetBasis(mesh, element, facets=facets[name], intorder=intorder)
            conductance = conductance + h * asm(mass, face)
    return conductance, capacity
