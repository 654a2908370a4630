"""2-D axisymmetric FE model (scikit-fem) of the screw shaft and the nut assembly.

The (r, z) half-section is meshed with structured quadrilaterals, generated here without gmsh: a
tensor grid for the shaft and one for the nut assembly, whose bore nodes duplicate the shaft surface
nodes ("duplicated nodes"; theory manual ``docs/theory/thermal.md``). The balls of each nut are the
interface term
    ∫_Γ h_c (T_n − T_s)(v_n − v_s) 2πr dΓ = h_c Jᵀ M_Γ J,
with J the jump operator (+1 on a nut-bore DOF, −1 on the shaft-surface DOF it faces, found by
coordinates) and M_Γ the bore facet mass matrix; a stroke offset of m cells pairs each bore
DOF with the shaft DOF m·Δz further along, and the time average sums the offsets with their
weights. Every integrand carries the axisymmetric weight 2πr. Friction heat is a flux on the
bore (nut side) and on the faced shaft surface (screw side), normalised to the exact watts. A
cooled nut whose coolant enters above ambient adds the flux h_cool·θ_in on the nut OD. A hollow
shaft is meshed from its bore radius r_i; its coolant and a table mass are extra unknowns
(:mod:`~ballscrew.thermal.fe_operator`), the coolant's cells being the shaft's axial cells.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray
from scipy.spatial import cKDTree
from skfem import (
    Basis,
    BilinearForm,
    ElementQuad1,
    ElementQuad2,
    FacetBasis,
    LinearForm,
    MeshQuad1,
    asm,
)
from skfem.helpers import dot, grad

from ballscrew.errors import InputError
from ballscrew.thermal.discretisation import Discretisation
from ballscrew.thermal.fe_assembly import (
    BoreInterface,
    bearing_loads,
    body_integrals,
    body_matrices,
    face_matrices,
    surface_film,
    twin_dofs,
)
from ballscrew.thermal.fe_operator import CoolantChannel, FeOperator, Readouts, fe_discretisation
from ballscrew.thermal.problem import AxialGrid, ThermalProblem, axial_grid

TWO_PI = 2.0 * math.pi


@BilinearForm
def conduction(u, v, w):
    """∇u·∇v 2πr (multiply by λ)."""
    return dot(grad(u), grad(v)) * TWO_PI * w.x[0]


@BilinearForm
def mass(u, v, w):
    """u v 2πr (capacity ×ρc, film ×h, interface ×h_c)."""
    return u * v * TWO_PI * w.x[0]


@LinearForm
def surface(v, w):
    """v 2πr: its sum is the area; times a flux it is a load."""
    return v * TWO_PI * w.x[0]


def _area_weight(integrand: NDArray[np.float64], x: NDArray[np.float64]) -> NDArray[np.float64]:
    """The integrand times 2πr (:data:`~ballscrew.thermal.fe_assembly.AreaWeight`)."""
    return integrand * TWO_PI * x[0]


@dataclass(frozen=True)
class AxisymmetricMesh:
    """Quadrilateral mesh of shaft and nut assembly with duplicated interface nodes."""

    mesh: MeshQuad1
    body: NDArray[np.int64]
    """Per element: 0 shaft, 1 nut assembly."""
    part: NDArray[np.int64]
    """Per element: ring part index (−1 in the shaft)."""
    r_shaft: NDArray[np.float64]
    """Radial grid lines of the shaft [m]."""
    r_ring: NDArray[np.float64]
    """Radial grid lines of the nut assembly [m]."""
    z_shaft: NDArray[np.float64]
    """Axial grid lines of the shaft [m]."""
    z_ring: NDArray[np.float64]
    """Axial grid lines of the nut assembly at its mean position [m]."""
    cells: tuple[NDArray[np.int64], NDArray[np.int64]]
    """Element index of each (z, r) grid cell of shaft and ring (−1: no element)."""
    facets: dict[str, NDArray[np.int64]]
    """Boundary facets: 'shaft_surface', 'shaft_ends', 'ring_outer', 'ring_ends', 'bore<k>' and,
    for a hollow shaft, 'shaft_bore'."""


def _radial_lines(a: float, b: float, size: float) -> NDArray[np.float64]:
    return np.linspace(a, b, max(1, math.ceil((b - a) / size - 1e-9)) + 1)


def build_mesh(problem: ThermalProblem, grid: AxialGrid, size: float) -> AxisymmetricMesh:
    """Structured mesh: shaft on (r_shaft × grid.z), ring on (r_ring × grid.ring_z)."""
    R = problem.shaft_radius
    r_shaft = _radial_lines(problem.bore_radius, R, size)
    radii = sorted({p.outer_radius for p in problem.parts})
    r_ring = np.unique(
        np.concatenate(
            [_radial_lines(a, b, size) for a, b in zip([R, *radii[:-1]], radii, strict=True)]
        )
    )
    shaft = MeshQuad1.init_tensor(r_shaft, grid.z)
    ring = MeshQuad1.init_tensor(r_ring, grid.ring_z)
    centroid = ring.p[:, ring.t].mean(axis=1)
    cell = np.clip(
        np.floor((centroid[1] - grid.ring_z[0]) / grid.dz).astype(np.int64), 0, grid.ring_cells - 1
    )
    part = grid.part_of_cell[cell]
    outer = np.array([p.outer_radius for p in problem.parts])[part]
    keep = centroid[0] < outer
    t_ring, part = ring.t[:, keep], part[keep]
    used = np.unique(t_ring)
    renumber = np.full(ring.p.shape[1], -1)
    renumber[used] = np.arange(used.size)
    p = np.hstack([shaft.p, ring.p[:, used]])
    t = np.hstack([shaft.t, renumber[t_ring] + shaft.p.shape[1]])
    mesh = MeshQuad1(p, t)
    n_shaft = shaft.t.shape[1]
    body = np.r_[np.zeros(n_shaft, dtype=np.int64), np.ones(t_ring.shape[1], dtype=np.int64)]
    part_all = np.r_[np.full(n_shaft, -1), part]
    cells = (
        _cell_table(shaft.p[:, shaft.t].mean(axis=1), r_shaft, grid.z, np.arange(n_shaft)),
        _cell_table(centroid[:, keep], r_ring, grid.ring_z, n_shaft + np.arange(keep.sum())),
    )
    return AxisymmetricMesh(
        mesh,
        body,
        part_all,
        r_shaft,
        r_ring,
        grid.z,
        grid.ring_z,
        cells,
        _classify(mesh, body, part_all, problem),
    )


def _cell_table(
    centroids: NDArray[np.float64],
    r: NDArray[np.float64],
    z: NDArray[np.float64],
    elements: NDArray[np.int64],
) -> NDArray[np.int64]:
    """Table [iz, ir] → element of a tensor grid (−1 where no element)."""
    table = np.full((z.size - 1, r.size - 1), -1, dtype=np.int64)
    ir = np.searchsorted(r, centroids[0]) - 1
    iz = np.searchsorted(z, centroids[1]) - 1
    table[iz, ir] = elements
    return table


def locate(am: AxisymmetricMesh, body: str, points: NDArray[np.float64]) -> NDArray[np.int64]:
    """Element of ``body`` ('screw' or 'nut') containing each point (2, n) (r, z)."""
    table, r, z = (
        (am.cells[0], am.r_shaft, am.z_shaft)
        if body == "screw"
        else (am.cells[1], am.r_ring, am.z_ring)
    )
    ir = np.clip(np.searchsorted(r, points[0]) - 1, 0, r.size - 2)
    iz = np.clip(np.searchsorted(z, points[1]) - 1, 0, z.size - 2)
    found = table[iz, ir]
    if np.any(found < 0):
        raise InputError("point", points[:, found < 0].T.tolist(), f"a point inside the {body}")
    return found


def probes(basis: Basis, points: NDArray[np.float64], cells: NDArray[np.int64]) -> sp.csr_matrix:
    """Rows evaluating the FE field at ``points`` (2, n) inside the given elements."""
    mapping = basis.mapping
    ref = mapping.invF(points[:, :, None], tind=cells)
    phis = np.array(
        [basis.elem.gbasis(mapping, ref, k, tind=cells)[0] for k in range(basis.Nbfun)]
    ).reshape(basis.Nbfun, -1)
    rows = np.tile(np.arange(points.shape[1]), basis.Nbfun)
    cols = basis.element_dofs[:, cells].ravel()
    return sp.csr_matrix((phis.ravel(), (rows, cols)), shape=(points.shape[1], basis.N))


def _classify(
    mesh: MeshQuad1, body: NDArray[np.int64], part: NDArray[np.int64], problem: ThermalProblem
) -> dict[str, NDArray[np.int64]]:
    """Name the boundary facets by body and position."""
    R, L = problem.shaft_radius, problem.shaft_length
    tol = 1e-9 * max(L, R)
    bf = mesh.boundary_facets()
    ends = mesh.p[:, mesh.facets[:, bf]]  # (2 coords, 2 nodes, facets)
    r_mid = ends[0].mean(axis=0)
    z_mid = ends[1].mean(axis=0)
    along_z = np.abs(ends[0, 0] - ends[0, 1]) < tol
    elem = mesh.f2t[0, bf]
    shaft = body[elem] == 0
    at_r = np.abs(r_mid - R) < tol
    facets = {
        "shaft_surface": bf[shaft & along_z & at_r],
        "shaft_ends": bf[shaft & ~along_z & ((np.abs(z_mid) < tol) | (np.abs(z_mid - L) < tol))],
        "ring_outer": bf[~shaft & along_z & ~at_r],
        "ring_ends": bf[~shaft & ~along_z],
    }
    if problem.bore_radius > 0.0:
        facets["shaft_bore"] = bf[shaft & along_z & (np.abs(r_mid - problem.bore_radius) < tol)]
    bore = ~shaft & along_z & at_r
    for k, p in enumerate(problem.parts):
        if p.balls:
            facets[f"bore{k}"] = bf[bore & (part[elem] == k)]
    return facets


def build_axisymmetric(
    problem: ThermalProblem, size: float, order: int = 2, grid: AxialGrid | None = None
) -> Discretisation:
    """Assemble the axisymmetric FE model with elements of about ``size`` [m], order 1 or 2."""
    if order not in (1, 2):
        raise InputError("mesh.order", order, "1 or 2")
    grid = axial_grid(problem, size) if grid is None else grid
    am = build_mesh(problem, grid, size)
    mesh = am.mesh
    element = ElementQuad2() if order == 2 else ElementQuad1()
    intorder = 2 * order + 2
    basis = Basis(mesh, element, intorder=intorder)

    def facet_basis(name: str) -> FacetBasis:
        return FacetBasis(mesh, element, facets=am.facets[name], intorder=intorder)

    conductance, capacity = body_matrices(basis, intorder, am.body, problem, conduction, mass)
    fb_surface = facet_basis("shaft_surface")

    surface_dofs = basis.get_dofs(facets=am.facets["shaft_surface"]).all()
    tree = cKDTree(basis.doflocs[:, surface_dofs].T)
    bores: list[BoreInterface | None] = []
    for k, part in enumerate(problem.parts):
        if not part.balls:
            bores.append(None)
            continue
        fb = facet_basis(f"bore{k}")
        dofs = basis.get_dofs(facets=am.facets[f"bore{k}"]).all()
        m_bore = asm(mass, fb)[dofs][:, dofs]
        b_bore = asm(surface, fb)[dofs]
        area = float(b_bore.sum())  # smeared balls: uniform density 1/A_bore
        pairs = twin_dofs(tree, surface_dofs, basis.doflocs[:, dofs], grid.shifts, grid.dz)
        bores.append(BoreInterface(dofs, pairs, m_bore / area, b_bore / area))

    operator = FeOperator(
        conduction=conductance,
        capacity=capacity,
        faces=face_matrices(basis, intorder, am.facets, mass),
        surface_film=surface_film(grid, fb_surface, _area_weight),
        bores=tuple(bores),
        bearings=bearing_loads(problem, fb_surface, _area_weight, size),
        outer=np.asarray(asm(surface, facet_basis("ring_outer"))),
        coolant=(
            _coolant_channel(problem, basis, am, facet_basis) if "shaft_bore" in am.facets else None
        ),
    )
    shaft_basis, shaft_volume, nut_mean = body_integrals(basis, intorder, am.body, surface)
    readouts = Readouts(
        elongation=problem.expansion / problem.section_area * shaft_volume,
        sensors=_sensor_probes(problem, basis, am),
        axis_z=am.z_shaft,
        axis=_axis_probes(problem, basis, am)[1],
        nut_mean=nut_mean,
    )
    extra = {
        "mesh": am,
        "basis": basis,
        "shaft_basis": shaft_basis,
        "element": element,
        "intorder": intorder,
        "order": order,
    }
    return fe_discretisation("axisymmetric", problem, grid, operator, readouts, 400_000, extra)


def _coolant_channel(
    problem: ThermalProblem, basis: Basis, am: AxisymmetricMesh, facet_basis
) -> CoolantChannel:
    """The bore wall ∫uv 2πr dz and its cells B[i, k] = ∫_cell φ_i 2πr_i dz (3-point Gauss,
    exact for the quadratic edge functions)."""
    r_i = problem.bore_radius
    x, w = np.polynomial.legendre.leggauss(3)
    z = am.z_shaft
    a, b = z[:-1, None], z[1:, None]
    zq = (0.5 * (a + b) + 0.5 * (b - a) * x).ravel()
    wq = (0.5 * (b - a) * w).ravel() * TWO_PI * r_i
    points = np.array([np.full(zq.size, r_i), zq])
    rows = probes(basis, points, locate(am, "screw", points))
    cell_of = np.repeat(np.arange(z.size - 1), x.size)
    weights = sp.csr_matrix((wq, (np.arange(zq.size), cell_of)), shape=(zq.size, z.size - 1))
    wall = sp.csr_matrix(asm(mass, facet_basis("shaft_bore")))
    return CoolantChannel(wall, sp.csr_matrix(rows.T @ weights))


def _nudged(problem: ThermalProblem, body: str, r: float, z: float) -> tuple[float, float]:
    """A point strictly inside ``body`` (the bore and shaft surface share coordinates)."""
    R, eps = problem.shaft_radius, 1e-9 * problem.shaft_length
    if body == "screw":
        radius = max(min(r, R - eps), problem.bore_radius + eps)
        return radius, float(np.clip(z, eps, problem.shaft_length - eps))
    start = problem.ring_centre - 0.5 * problem.ring_length
    return max(r, R + eps), float(np.clip(z, start + eps, start + problem.ring_length - eps))


def _sensor_probes(problem: ThermalProblem, basis: Basis, am: AxisymmetricMesh) -> sp.csr_matrix:
    rows = [sp.csr_matrix((0, basis.N))]
    for s in problem.sensors:
        point = np.array(_nudged(problem, s.body, s.r, s.z))[:, None]
        rows.append(probes(basis, point, locate(am, s.body, point)))
    return sp.csr_matrix(sp.vstack(rows))


def _axis_probes(
    problem: ThermalProblem, basis: Basis, am: AxisymmetricMesh
) -> tuple[NDArray[np.float64], sp.csr_matrix]:
    """Rows giving the cross-section mean 2/(R² − r_i²)∫θ r dr at each shaft grid line (Gauss
    in r; r_i = 0 for a solid shaft)."""
    x, w = np.polynomial.legendre.leggauss(3)
    a, b = am.r_shaft[:-1, None], am.r_shaft[1:, None]
    rq = (0.5 * (a + b) + 0.5 * (b - a) * x).ravel()
    wq = (0.5 * (b - a) * w).ravel() * rq * 2.0 * math.pi / problem.section_area
    z = am.z_shaft
    eps = 1e-9 * problem.shaft_length
    zq = np.clip(z, eps, problem.shaft_length - eps)
    points = np.array([np.tile(rq, zq.size), np.repeat(zq, rq.size)])
    rows = probes(basis, points, locate(am, "screw", points))
    weights = sp.kron(sp.identity(z.size), sp.csr_matrix(wq[None, :]))
    return z, sp.csr_matrix(weights @ rows)
