"""Optional full 3-D FE model (scikit-fem, trilinear hexahedra) with helical contact patches.

The optional model with the helical contact patches, for users who need the non-axisymmetric detail
(theory manual ``docs/theory/thermal.md``, 3-D FE model). Mesh: :mod:`~ballscrew.thermal.mesh3d`
(O-grid shaft, annular nut assembly, duplicated interface nodes). Weak form of C θ̇ + A θ = f (in
Cartesian coordinates, no 2πr weight):

    ∫_Ω λ ∇θ·∇v + ∫_Ω ρc_p θ̇ v + Σ_faces ∫ h θ v
        + ∫_Γ h_c(x) (θ_s − θ_n)(v_s − v_n) dΓ  =  ∫_Γ (q_s v_s + q_n v_n) dΓ + bearing bands,

where Γ is the nut bore (nut side n, the faced shaft surface s). The interface term is
h_c Jᵀ M_Γ(h_c) J with J the jump operator (+1 on a bore DOF, −1 on the shaft DOF at the same
coordinates, found with a cKDTree; a stroke offset of m cells pairs it with the DOF m·Δz
further along, time-averaged with the stroke weights as in the axisymmetric model).

Helical contact patches (``docs/theory/geometry.md``; (A3)–(A4) of
``docs/theory/contact-resistance.md``; ``docs/theory/thermal.md``). The centre of ball j of a nut
runs on the helix C(θ) = (r_m cos θ, r_m sin θ, p_h θ), p_h = L/(2π) (G1); its screw and nut
contact points A, B lie at radii r_A, r_B and axial offsets ∓r_b sin β from C (G9–G12). The
model collapses both raceways onto the one interface cylinder r = R, so a patch is centred at
the radial projection (R cos θ_j, R sin θ_j, z(θ_j)) of the ball centre, the mid-point of the
projections of A and B (``axial_offset`` moves it). Its shape on the unrolled cylinder is an
ellipse with semi-axes (s_t, s_n) along and across the helix: the Hertz semi-axes a (along x,
the rolling direction) and b·cos β (along y, across the groove, projected on the cylinder). The n_b
loaded balls of a nut are spaced evenly along the helix over the nut length.

One ball's conductance G_c = 1/R_c with R_c = n_b R_nut (A3: the n_b balls of the nut in
parallel give the nut's R_nut) is spread over its patch S_c:

    h_c(x) = 1/(R_c S_c)  on patch c,   0 elsewhere on the bore,

with S_c the patch area as integrated by the facet quadrature, so that Σ_c ∫ h_c dΓ =
n_b/R_c = 1/R_nut: exactly the conductance of the smeared axisymmetric model
(:func:`~ballscrew.thermal.constriction.smeared_conductance`), whose h = 1/(R_nut A_bore) is
the special case of one patch covering the whole bore (``patches=None``). Patches smaller
than the mesh (real Hertz patches are ~0.1–2 mm) are enlarged to ``min_semi_axis`` (default:
0.75 of the larger of the circumferential and axial element sizes) so every patch is resolved
by quadrature points; G_c is unchanged, so only the local h_c (and the local jump q·R″ =
q/h_c) depends on that choice. The friction heat of a nut enters at its patches, 1/n_b of the
nut's screw share on the shaft side and of its nut share on the nut side per patch,
normalised to the exact watts.

A hollow shaft (``problem.shaft_coolant``) is meshed as a tube r_i … R
(:func:`~ballscrew.thermal.mesh3d.tube_section`); its bore wall and coolant cells, one per axial
cell of the shaft, enter the shared coolant terms of :mod:`~ballscrew.thermal.fe_operator`
(h ∫_bore (θ_w − θ_c,k) v dA and the upwind balance W(θ_c,k − θ_c,k−1)). The bulk rise is
one value per cell: the coolant is assumed mixed over the bore's section.

The patches are fixed in the nut: the model is the quasi-static "frozen" contact (the screw's
rotation, which sweeps the patches around the shaft, is not resolved; at speed it smears the
screw-side pattern towards the axisymmetric one).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray
from scipy.spatial import cKDTree
from skfem import Basis, BilinearForm, ElementHex1, FacetBasis, LinearForm, asm
from skfem.helpers import dot, grad

from ballscrew.errors import InputError
from ballscrew.thermal.axisymmetric import probes
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
from ballscrew.thermal.fe_operator import (
    CoolantChannel,
    FeOperator,
    Readouts,
    fe_discretisation,
)
from ballscrew.thermal.mesh3d import Mesh3D, build_mesh3d, circle_angles
from ballscrew.thermal.problem import AxialGrid, ThermalProblem, axial_grid


@BilinearForm
def conduction(u, v, w):
    """∇u·∇v (multiply by λ)."""
    return dot(grad(u), grad(v))


@BilinearForm
def mass(u, v, w):
    """u v (capacity ×ρc, film ×h)."""
    return u * v


@BilinearForm
def weighted_mass(u, v, w):
    """c(x) u v: the interface term with a spatially varying h_c = w.c."""
    return w.c * u * v


@LinearForm
def unit(v, w):
    """v: its sum is the measure."""
    return v


@LinearForm
def weighted_load(v, w):
    """c(x) v: a distributed flux c [W/m²]."""
    return w.c * v


def _area_weight(integrand: NDArray[np.float64], x: NDArray[np.float64]) -> NDArray[np.float64]:
    """The integrand as it is, in Cartesian coordinates
    (:data:`~ballscrew.thermal.fe_assembly.AreaWeight`)."""
    return integrand


@dataclass(frozen=True)
class BallPatches:
    """The loaded balls of one nut and the patch each one makes on the interface cylinder."""

    balls: int
    """Loaded balls n_b of the nut."""
    lead: float
    """Lead L of the screw [m]; the helix pitch is p_h = L/(2π)."""
    semi_axes: tuple[float, float] = (0.0, 0.0)
    """Patch semi-axes (along the helix, across it) on the cylinder [m]; 0: mesh-resolved."""
    axial_offset: float = 0.0
    """Axial offset of the patch centres from the ball-centre helix [m]."""
    phase: float = 0.0
    """Angle θ of the helix at the nut's low end [rad]."""
    min_semi_axis: float | None = None
    """Smallest semi-axis used [m]; None: 0.75 × the larger element size at the bore."""

    def __post_init__(self) -> None:
        if self.balls < 1:
            raise InputError("balls", self.balls, "at least one loaded ball")
        if not self.lead > 0.0:
            raise InputError("lead", self.lead, "a lead > 0 m")
        if min(self.semi_axes) < 0.0:
            raise InputError("semi_axes", self.semi_axes, "semi-axes ≥ 0 m")


def axial_grid_3d(problem: ThermalProblem, size: float, far_size: float) -> AxialGrid:
    """:func:`axial_grid` with spacing ``size`` over the swept range and ≤ ``far_size`` beyond."""
    grid = axial_grid(problem, size)
    if not far_size > 0.0:
        raise InputError("mesh.far_size_3d", far_size, "a length > 0 m")
    m = grid.half_stroke_cells
    i0 = grid.first - m
    i1 = grid.first + grid.ring_cells + m
    z = grid.z
    lo = np.linspace(0.0, z[i0], max(1, math.ceil(z[i0] / far_size - 1e-9)) + 1)[:-1]
    tail = problem.shaft_length - z[i1]
    hi = np.linspace(z[i1], problem.shaft_length, max(1, math.ceil(tail / far_size - 1e-9)) + 1)
    lo = lo if z[i0] > 0.0 else lo[:0]
    hi = hi[1:] if tail > 0.0 else hi[:0]
    new_z = np.concatenate([lo, z[i0 : i1 + 1], hi])
    return AxialGrid(new_z, grid.dz, lo.size + m, grid.part_cells, grid.shifts, grid.weights)


def patch_index(
    points: NDArray[np.float64],
    radius: float,
    centres_theta: NDArray[np.float64],
    centres_z: NDArray[np.float64],
    pitch: float,
    semi_axes: tuple[float, float],
) -> NDArray[np.int64]:
    """Patch of each point (3, …) on the cylinder r = ``radius`` (−1: none).

    Unrolled coordinates of the point relative to the centre (θ_c, z_c) of patch c:
    s = R·wrap(φ − θ_c), ζ = z − z_c; along the helix u = (R s + p_h ζ)/ℓ, across
    w = (−p_h s + R ζ)/ℓ, ℓ = √(R² + p_h²); inside when (u/s_t)² + (w/s_n)² ≤ 1.
    """
    phi = np.arctan2(points[1], points[0])
    z = points[2]
    out = np.full(phi.shape, -1, dtype=np.int64)
    norm = math.hypot(radius, pitch)
    a, b = semi_axes
    for c, (tc, zc) in enumerate(zip(centres_theta, centres_z, strict=True)):
        s = radius * (np.mod(phi - tc + math.pi, 2.0 * math.pi) - math.pi)
        dz = z - zc
        u = (radius * s + pitch * dz) / norm
        w = (-pitch * s + radius * dz) / norm
        inside = (u / a) ** 2 + (w / b) ** 2 <= 1.0
        out[inside & (out < 0)] = c
    return out


def patch_centres(
    patches: BallPatches, z_lo: float, z_hi: float, margin: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Helix angles θ_j and axial positions z_j of the n_b patch centres of a nut on [z_lo, z_hi].

    The balls are spaced evenly in θ over the helix turns that fit in the nut less ``margin``
    at each end: θ_j = phase + (j + ½)Θ/n_b, Θ = 2π(z_hi − z_lo − 2 margin)/L.
    """
    usable = z_hi - z_lo - 2.0 * margin
    if not usable > 0.0:
        raise InputError(
            "patches", patches, f"patches that fit in the nut length {z_hi - z_lo:g} m"
        )
    pitch = patches.lead / (2.0 * math.pi)
    span = usable / pitch
    rel = (np.arange(patches.balls) + 0.5) * span / patches.balls
    return patches.phase + rel, z_lo + margin + pitch * rel + patches.axial_offset


def build_threed(
    problem: ThermalProblem,
    size: float = 0.005,
    divisions: int = 48,
    layers: int = 4,
    far_size: float | None = None,
    radial_size: float | None = None,
    patches: Sequence[BallPatches | None] | None = None,
    grid: AxialGrid | None = None,
    patch_intorder: int = 9,
) -> Discretisation:
    """Assemble the 3-D FE model.

    ``size``: axial element size over the nut's swept range; ``far_size``: beyond it (default
    4·size); ``divisions``: circumferential divisions; ``layers``: radial layers of the shaft's
    O-ring; ``radial_size``: radial size in the nut. ``patches``: one :class:`BallPatches` (or
    None: smeared) per part of ``problem.parts`` (spacers ignored); None: every nut smeared
    uniformly over its bore (the axisymmetric model's interface). ``patch_intorder``: the
    Gauss rule on the bore facets that samples the patch shapes.
    """
    if patches is not None and len(patches) != len(problem.parts):
        raise InputError("patches", len(patches), f"one entry per part ({len(problem.parts)})")
    far_size = 4.0 * size if far_size is None else far_size
    grid = axial_grid_3d(problem, size, far_size) if grid is None else grid
    m3 = build_mesh3d(problem, grid, divisions, layers, radial_size)
    mesh = m3.mesh
    element = ElementHex1()
    intorder = 3
    basis = Basis(mesh, element, intorder=intorder)
    R = problem.shaft_radius

    def facet_basis(name: str, order: int = intorder) -> FacetBasis:
        return FacetBasis(mesh, element, facets=m3.facets[name], intorder=order)

    conductance, capacity = body_matrices(basis, intorder, m3.body, problem, conduction, mass)
    fb_surface = facet_basis("shaft_surface")

    surface_dofs = basis.get_dofs(facets=m3.facets["shaft_surface"]).all()
    tree = cKDTree(basis.doflocs[:, surface_dofs].T)
    h_circ = 2.0 * math.pi * R / divisions
    bores: list[BoreInterface | None] = []
    patch_info: list[dict[str, object]] = []
    bounds = grid.part_bounds
    for k, part in enumerate(problem.parts):
        if not part.balls:
            bores.append(None)
            continue
        # the patch indicator is sampled at the quadrature points: a finer rule on the bore
        fb = facet_basis(f"bore{k}", intorder if patches is None else patch_intorder)
        dofs = basis.get_dofs(facets=m3.facets[f"bore{k}"]).all()
        spec = None if patches is None else patches[k]
        dx = fb.dx  # (facets, quadrature points)
        if spec is None:
            density = np.full(dx.shape, 1.0 / dx.sum())  # ∫ density dΓ = 1
            info: dict[str, object] = {"part": k, "patches": 0, "area": float(dx.sum())}
        else:
            smallest = (
                0.75 * max(h_circ, grid.dz) if spec.min_semi_axis is None else spec.min_semi_axis
            )
            axes = (max(spec.semi_axes[0], smallest), max(spec.semi_axes[1], smallest))
            pitch = spec.lead / (2.0 * math.pi)
            margin = max(axes) + abs(spec.axial_offset)
            theta, zc = patch_centres(spec, bounds[k], bounds[k + 1], margin)
            index = patch_index(np.asarray(fb.global_coordinates()), R, theta, zc, pitch, axes)
            areas = np.bincount(index[index >= 0], weights=dx[index >= 0], minlength=spec.balls)
            if np.any(areas <= 0.0):
                raise InputError(
                    "patches.min_semi_axis", spec.min_semi_axis, "patches the mesh resolves"
                )
            # each patch carries 1/n_b of the nut: density χ_c/(n_b S_c), ∫ density dΓ = 1
            density = np.where(index >= 0, 1.0 / (spec.balls * areas[np.maximum(index, 0)]), 0.0)
            info = {
                "part": k,
                "patches": spec.balls,
                "theta": theta,
                "z": zc,
                "semi_axes": axes,
                "areas": areas,
                "index": index,
                "facet_basis": fb,
            }
        m_bore = asm(weighted_mass, fb, c=density)[dofs][:, dofs]
        b_bore = np.asarray(asm(weighted_load, fb, c=density))[dofs]
        pairs = twin_dofs(tree, surface_dofs, basis.doflocs[:, dofs], grid.shifts, grid.dz)
        info["dofs"] = dofs
        info["pairs"] = pairs
        patch_info.append(info)
        bores.append(BoreInterface(dofs, pairs, m_bore, b_bore))

    operator = FeOperator(
        conduction=conductance,
        capacity=capacity,
        faces=face_matrices(basis, intorder, m3.facets, mass),
        surface_film=surface_film(grid, fb_surface, _area_weight),
        bores=tuple(bores),
        bearings=bearing_loads(problem, fb_surface, _area_weight, max(size, far_size)),
        outer=np.asarray(asm(unit, facet_basis("ring_outer"))),
        coolant=_coolant_channel(m3, facet_basis("shaft_bore")) if problem.bore_radius else None,
    )
    shaft_basis, shaft_volume, nut_mean = body_integrals(basis, intorder, m3.body, unit)
    readouts = Readouts(
        elongation=problem.expansion / m3.section_area * shaft_volume,
        sensors=_sensor_probes(problem, basis, m3),
        axis_z=m3.z_shaft,
        axis=_axis_rows(m3, basis.N),
        nut_mean=nut_mean,
    )
    extra = {
        "mesh": m3,
        "basis": basis,
        "shaft_basis": shaft_basis,
        "element": element,
        "intorder": intorder,
        "interfaces": patch_info,
        **_profile_nodes(m3),
    }
    # direct_limit 0: AMG-CG, a 3-D LU fills in (19 s against 1.3 s at 35k unknowns)
    return fe_discretisation("3d", problem, grid, operator, readouts, 0, extra)


def _coolant_channel(m3: Mesh3D, fb: FacetBasis) -> CoolantChannel:
    """The bore wall ∫uv dA and its cells B[i, k] = ∫_cell k φ_i dA.

    On the extruded tube a bore node on axial line j has φ_i = ψ_m(s)·(its axial hat), so its
    wall integral b_i = ∫φ_i dA splits between the cells j−1 and j in proportion to their
    lengths Δz: B[i, k] = b_i Δz_k/(Δz_j−1 + Δz_j), exactly, and Σ_k B[i, k] = b_i = (wall·1)_i.
    """
    wall = sp.csr_matrix(asm(mass, fb))
    b = np.asarray(wall.sum(axis=1)).ravel()
    n2 = m3.shaft_section.p.shape[1]
    dz = np.diff(m3.z_shaft)
    cells = dz.size
    bore = np.flatnonzero(b)  # the bore's nodes (iz, m) = iz·n₂ + m
    j = bore // n2
    below = np.where(j > 0, dz[np.maximum(j - 1, 0)], 0.0)
    above = np.where(j < cells, dz[np.minimum(j, cells - 1)], 0.0)
    rows = np.concatenate([bore, bore])
    cols = np.concatenate([j - 1, j])
    vals = np.concatenate([b[bore] * below, b[bore] * above]) / np.tile(below + above, 2)
    keep = (cols >= 0) & (cols < cells) & (vals != 0.0)
    shape = (wall.shape[0], cells)
    return CoolantChannel(wall, sp.csr_matrix((vals[keep], (rows[keep], cols[keep])), shape))


def _profile_nodes(m3: Mesh3D) -> dict[str, NDArray]:
    """Nodes along z on the line φ = −π/4 (the first circle angle), for axial profile plots
    (the network's keys): 'shaft_mean' at the node nearest r = √((R² + r_i²)/2) (R/√2 on a
    solid shaft: where a parabolic radial profile equals its section mean), 'shaft_surface' at
    r = R, 'ring_bore' and 'ring_outer' (outermost node of the part) on the nut's lines
    'ring_z'."""
    sec = m3.shaft_section
    n2, nz = sec.p.shape[1], m3.z_shaft.size
    r = np.hypot(sec.p[0], sec.p[1])
    radius, inner = r.max(), m3.bore_radius
    on_line = np.abs(np.arctan2(sec.p[1], sec.p[0]) + 0.25 * math.pi) < 1e-9
    candidates = np.nonzero(on_line)[0]
    mean_node = candidates[
        np.argmin(np.abs(r[candidates] - math.sqrt(0.5 * (radius**2 + inner**2))))
    ]
    surface_node = n2 - m3.divisions  # the first node of the circle (φ = −π/4)
    base = np.arange(nz) * n2
    radial = m3.ring_nodes[:, :: m3.divisions]  # (z lines, radial lines) at φ = −π/4
    last = radial.shape[1] - 1 - np.argmax(radial[:, ::-1] >= 0, axis=1)
    return {
        "shaft_mean": base + mean_node,
        "shaft_surface": base + surface_node,
        "ring_z": m3.z_ring,
        "ring_bore": radial[:, 0],
        "ring_outer": radial[np.arange(radial.shape[0]), last],
    }


def interface_conductance(
    disc: Discretisation, weights: NDArray[np.float64] | None = None
) -> float:
    """Total screw–nut conductance Σ ∫ h_c dΓ of the assembled interface terms [W/K].

    The interface term adds +G to the nut-side and −G to the shaft-side block sums, so it is
    the sum of A over (bore DOFs) × (faced shaft DOFs), negated.
    """
    weights = disc.grid.weights if weights is None else weights
    a, _ = disc.assemble(weights)
    total = 0.0
    for info in disc.extra["interfaces"]:
        dofs = info["dofs"]
        shaft = np.unique(np.concatenate([info["pairs"][k] for k in np.nonzero(weights)[0]]))
        total -= float(a[dofs][:, shaft].sum())
    return total


def _section_cells(section_mesh, points: NDArray[np.float64]) -> NDArray[np.int64]:
    return np.asarray(section_mesh.element_finder()(points[0], points[1]), dtype=np.int64)


def locate(m3: Mesh3D, body: str, points: NDArray[np.float64]) -> NDArray[np.int64]:
    """Hexahedron of ``body`` ('screw' or 'nut') containing each point (3, n) (x, y, z)."""
    if body == "screw":
        sec, z = m3.shaft_section, m3.z_shaft
    else:
        sec, z = m3.ring_section, m3.z_ring
    q = _section_cells(sec.mesh, points[:2])
    iz = np.clip(np.searchsorted(z, points[2]) - 1, 0, z.size - 2)
    if body == "screw":
        return iz * sec.t.shape[1] + q
    found = m3.ring_cells[iz, q]
    if np.any(found < 0):
        raise InputError("point", points[:, found < 0].T.tolist(), "a point inside the nut")
    return found


def _sensor_point(problem: ThermalProblem, m3: Mesh3D, sensor) -> NDArray[np.float64]:
    """(x, y, z) of a sensor strictly inside its body's polygonal mesh (θ = 0 if not given)."""
    theta = sensor.theta
    R, L = problem.shaft_radius, problem.shaft_length
    eps = 1e-9 * L
    shrink = math.cos(math.pi / m3.divisions) * (1.0 - 1e-9)  # inscribed polygon
    if sensor.body == "screw":
        r = max(min(sensor.r, R * shrink), problem.bore_radius * (1.0 + 1e-9))
        z = float(np.clip(sensor.z, eps, L - eps))
    else:
        start = problem.ring_centre - 0.5 * problem.ring_length
        z = float(np.clip(sensor.z, start + eps, start + problem.ring_length - eps))
        ends = start + np.cumsum([p.length for p in problem.parts])
        part = problem.parts[min(int(np.searchsorted(ends, z)), len(problem.parts) - 1)]
        r = float(np.clip(sensor.r, R * (1.0 + 1e-9), part.outer_radius * shrink))
    return np.array([r * math.cos(theta), r * math.sin(theta), z])


def _sensor_probes(problem: ThermalProblem, basis: Basis, m3: Mesh3D) -> sp.csr_matrix:
    rows = [sp.csr_matrix((0, basis.N))]
    for s in problem.sensors:
        point = _sensor_point(problem, m3, s)[:, None]
        rows.append(probes(basis, point, locate(m3, s.body, point)))
    return sp.csr_matrix(sp.vstack(rows))


def _axis_rows(m3: Mesh3D, n: int) -> sp.csr_matrix:
    """Rows giving the cross-section mean (1/A)∫θ dA of the shaft at each axial line.

    The shaft nodes (iz, i) are iz·n₂ + i, and the section integral of the trilinear field on
    a grid line is exact with the bilinear node weights ∫φ_i dA of the section.
    """
    sec = m3.shaft_section
    w = sec.node_weights / m3.section_area
    nz, n2 = m3.z_shaft.size, sec.p.shape[1]
    rows = np.repeat(np.arange(nz), n2)
    cols = np.arange(nz * n2)
    return sp.csr_matrix((np.tile(w, nz), (rows, cols)), shape=(nz, n))


def bore_temperatures(
    disc: Discretisation, theta: NDArray[np.float64], part: int = 0
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Nut-bore nodal rises of nut ``part`` (ordinal among the nuts) on the (z, φ) grid.

    Returns (z lines, angles φ_m, rises (z, φ)) [m, rad, K].
    """
    m3: Mesh3D = disc.extra["mesh"]
    nodes = m3.ring_nodes[:, : m3.divisions]  # the first n ring-section nodes are the bore
    info = disc.extra["interfaces"][part]
    k = info["part"]
    bounds = disc.grid.part_bounds
    tol = 1e-9 * disc.problem.shaft_length
    rows = (m3.z_ring >= bounds[k] - tol) & (m3.z_ring <= bounds[k + 1] + tol)
    return m3.z_ring[rows], circle_angles(m3.divisions), theta[nodes[rows]]
