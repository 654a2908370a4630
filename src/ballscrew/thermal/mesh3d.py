"""Structured hexahedral mesh of the screw shaft and the nut assembly, generated in numpy.

No gmsh (GPL): the cross-sections are built as quadrilateral
meshes and extruded along the axial grid lines into trilinear hexahedra (skfem ``MeshHex``).

- Shaft: an O-grid disc, a square core of half-side c·R with (n/4)² cells plus an O-ring of
  ``layers`` layers blending linearly from the square's perimeter to the circle r = R, so
  every node of the circle sits at an angle φ_m = −π/4 + 2π m/n (m = 0 … n−1); no degenerate
  elements (no collapsed wedge at the axis). A hollow shaft (a coolant bore of radius r_i) is
  a tube instead: ``layers`` rings r_i … R on the same n angles, its first n nodes the bore.
- Nut assembly: an annulus R … max outer radius on the same n angles, extruded along the
  ring's axial lines; elements beyond the outer radius of their part (nut or spacer) are
  dropped. Its bore nodes are separate copies of the shaft's surface nodes at the same
  coordinates (duplicated interface nodes), so the contact is the
  jump term of :mod:`~ballscrew.thermal.threed`.

The circumference is a polygon of n sides: its area is n/(2π)·sin(2π/n) of the circle's
(−0.64 % at n = 32, −0.16 % at n = 64); read-outs that divide by the cross-section use the
polygon's area (:attr:`Mesh3D.section_area`) so that a uniform rise is exact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from skfem import MeshHex, MeshQuad

from ballscrew.errors import InputError
from ballscrew.thermal.problem import AxialGrid, ThermalProblem

# skfem's hexahedron corner order in reference coordinates (ξ, η, ζ):
# 000, 010, 100, 001, 110, 011, 101, 111. For a counter-clockwise quad q0 q1 q2 q3 (ξ: q0→q1,
# η: q0→q3) extruded from z_k (b) to z_k+1 (t) that is:
_HEX_FROM_QUAD = ((0, 0), (3, 0), (1, 0), (0, 1), (2, 0), (3, 1), (1, 1), (2, 1))


@dataclass(frozen=True)
class Section:
    """A quadrilateral cross-section mesh."""

    p: NDArray[np.float64]
    """Node coordinates (2, n) [m]."""
    t: NDArray[np.int64]
    """Counter-clockwise quads (4, m)."""

    @property
    def mesh(self) -> MeshQuad:
        """The section as a skfem mesh."""
        return MeshQuad(self.p, self.t)

    @property
    def areas(self) -> NDArray[np.float64]:
        """Area of each quad (shoelace) [m²]."""
        x, y = self.p[0, self.t], self.p[1, self.t]
        return 0.5 * np.sum(x * np.roll(y, -1, axis=0) - np.roll(x, -1, axis=0) * y, axis=0)

    @property
    def node_weights(self) -> NDArray[np.float64]:
        """∫ φ_i dA of the bilinear shape functions (exact section integral of a nodal field)."""
        from skfem import Basis, ElementQuad1, LinearForm, asm

        @LinearForm
        def one(v, w):
            return v

        return np.asarray(asm(one, Basis(self.mesh, ElementQuad1(), intorder=2)))


def _ccw(p: NDArray[np.float64], t: NDArray[np.int64]) -> NDArray[np.int64]:
    """Reorder clockwise quads to counter-clockwise."""
    x, y = p[0, t], p[1, t]
    area = np.sum(x * np.roll(y, -1, axis=0) - np.roll(x, -1, axis=0) * y, axis=0)
    t = t.copy()
    t[:, area < 0] = t[::-1][:, area < 0]
    return t


def circle_angles(divisions: int) -> NDArray[np.float64]:
    """Angles φ_m = −π/4 + 2π m/n of the circumferential nodes [rad]."""
    return -0.25 * math.pi + 2.0 * math.pi * np.arange(divisions) / divisions


def disc_section(radius: float, divisions: int, layers: int, core: float = 0.45) -> Section:
    """O-grid disc: a square core of half-side ``core``·R and ``layers`` blended rings.

    The last ``divisions`` nodes are the circle r = R in the order of :func:`circle_angles`.
    """
    if divisions < 8 or divisions % 4:
        raise InputError("mesh.divisions_3d", divisions, "a multiple of 4, at least 8")
    if layers < 1:
        raise InputError("mesh.layers_3d", layers, "at least 1 radial layer")
    n = divisions // 4
    s = core * radius
    xs = np.linspace(-s, s, n + 1)
    cx, cy = np.meshgrid(xs, xs, indexing="xy")  # node (i, j) → j*(n+1) + i
    p_core = np.vstack([cx.ravel(), cy.ravel()])
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    i, j = i.ravel(), j.ravel()
    k0 = j * (n + 1) + i
    t_core = np.vstack([k0, k0 + 1, k0 + n + 2, k0 + n + 1])
    # square perimeter counter-clockwise from the corner (s, −s)
    ar = np.arange(n)
    right = n + (n + 1) * ar  # i = n, j = 0 … n−1
    top = (n + 1) * n + (n - ar)  # j = n, i = n … 1
    left = (n + 1) * (n - ar)  # i = 0, j = n … 1
    bottom = ar  # j = 0, i = 0 … n−1
    perimeter = np.concatenate([right, top, left, bottom])
    square = p_core[:, perimeter]
    phi = circle_angles(divisions)
    circle = radius * np.vstack([np.cos(phi), np.sin(phi)])
    points = [p_core]
    ring_ids = [perimeter]
    count = p_core.shape[1]
    for k in range(1, layers + 1):
        f = k / layers
        points.append((1.0 - f) * square + f * circle)
        ring_ids.append(count + np.arange(divisions))
        count += divisions
    quads = [t_core]
    m = np.arange(divisions)
    for k in range(layers):
        a, b = ring_ids[k], ring_ids[k + 1]
        quads.append(np.vstack([a[m], b[m], b[(m + 1) % divisions], a[(m + 1) % divisions]]))
    p = np.hstack(points)
    return Section(p, _ccw(p, np.hstack(quads)))


def annulus_section(radii: NDArray[np.float64], divisions: int) -> Section:
    """Annulus on the radial lines ``radii`` (increasing) and the angles of :func:`circle_angles`.

    Node (k, m) (radius k, angle m) is k·n + m: the first n nodes are the bore.
    """
    phi = circle_angles(divisions)
    r = np.asarray(radii, dtype=float)
    p = np.vstack([np.outer(r, np.cos(phi)).ravel(), np.outer(r, np.sin(phi)).ravel()])
    k, m = np.meshgrid(np.arange(r.size - 1), np.arange(divisions), indexing="ij")
    k, m = k.ravel(), m.ravel()
    m1 = (m + 1) % divisions
    inner, outer = k * divisions, (k + 1) * divisions
    t = np.vstack([inner + m, inner + m1, outer + m1, outer + m])
    return Section(p, _ccw(p, t))


MAX_ASPECT = 10.0
"""Largest ratio of the circumferential element size 2πr/n to the radial size of a tube's
layers (flatter elements slow the iterative solve and resolve the wall badly). GUESS: a
common mesh-quality limit, not a measured one."""


def tube_section(inner: float, radius: float, divisions: int, layers: int) -> Section:
    """Annular shaft section r_i … R in ``layers`` geometric rings on the :func:`circle_angles`.

    The ring radii are r_k = r_i q^k with q = (R/r_i)^(1/L): every element has the same shape,
    2πr/n around and r(q − 1) across, and the logarithmic temperature profile of radial
    conduction next to a cooled bore, ΔT ∝ ln r, is linear in the node index (equal rings
    would smear a small bore's steep profile over the first ring). The first ``divisions``
    nodes are the bore r = r_i and the last ``divisions`` the circle r = R, as in
    :func:`disc_section`. A wall whose elements are flatter than 1:MAX_ASPECT is refused.
    """
    if divisions < 8 or divisions % 4:
        raise InputError("mesh.divisions_3d", divisions, "a multiple of 4, at least 8")
    if layers < 1:
        raise InputError("mesh.layers_3d", layers, "at least 1 radial layer")
    flattest = 1.0 + 2.0 * math.pi / divisions / MAX_ASPECT  # the least ring ratio q
    if not radius / inner >= flattest**layers:
        raise InputError(
            "thermal.shaft_coolant.bore_diameter",
            2.0 * inner,
            f"≤ {2.0 * radius / flattest**layers:.4g} m on the 3d mesh (a wall of {layers} "
            f"layers no flatter than 1:{MAX_ASPECT:g} of the element size 2πr/n; fewer "
            "thermal.mesh.layers_3d or more divisions_3d allow a thinner wall)",
        )
    return annulus_section(np.geomspace(inner, radius, layers + 1), divisions)


def extrude(section: Section, z: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray]:
    """Hexahedra of ``section`` between consecutive ``z`` lines.

    Node (iz, i) is iz·n₂ + i; element (iz, q) is iz·m₂ + q.
    """
    n2, m2 = section.p.shape[1], section.t.shape[1]
    nz = z.size
    p = np.vstack([np.tile(section.p, (1, nz)), np.repeat(z, n2)[None, :]])
    layer = np.arange(nz - 1)
    hexes = np.empty((8, (nz - 1) * m2), dtype=np.int64)
    for row, (corner, up) in enumerate(_HEX_FROM_QUAD):
        hexes[row] = ((layer[:, None] + up) * n2 + section.t[corner][None, :]).ravel()
    return p, hexes


@dataclass(frozen=True)
class Mesh3D:
    """Hexahedral mesh of shaft and nut assembly with duplicated interface nodes."""

    mesh: MeshHex
    body: NDArray[np.int64]
    """Per element: 0 shaft, 1 nut assembly."""
    part: NDArray[np.int64]
    """Per element: ring part index (−1 in the shaft)."""
    shaft_section: Section
    ring_section: Section
    z_shaft: NDArray[np.float64]
    """Axial lines of the shaft [m]."""
    z_ring: NDArray[np.float64]
    """Axial lines of the nut assembly at its mean position [m]."""
    ring_cells: NDArray[np.int64]
    """Table [iz, q] → element of the ring (−1: dropped beyond the part's outer radius)."""
    ring_nodes: NDArray[np.int64]
    """Table [iz, i] → node of the ring (−1: unused)."""
    divisions: int
    facets: dict[str, NDArray[np.int64]]
    """Boundary facets: 'shaft_surface', 'shaft_ends', 'ring_outer', 'ring_ends', 'bore<k>'
    (nut k's bore: the nut side of the interface), 'interface<k>' (the shaft surface it faces
    at the mean position: the screw side), 'spacer_bore<k>', 'band<j>' (shaft surface
    facets whose centre lies in bearing band j) and, for a hollow shaft, 'shaft_bore'."""
    bore_radius: float = 0.0
    """Radius r_i of the shaft's coolant bore [m] (0: a solid shaft)."""

    @property
    def shaft_nodes(self) -> int:
        """Nodes of the shaft (numbered first, (iz, i) → iz·n₂ + i)."""
        return self.shaft_section.p.shape[1] * self.z_shaft.size

    @property
    def section_area(self) -> float:
        """Area of the polygonal shaft cross-section [m²]."""
        return float(self.shaft_section.areas.sum())


def build_mesh3d(
    problem: ThermalProblem,
    grid: AxialGrid,
    divisions: int = 48,
    layers: int = 4,
    radial_size: float | None = None,
) -> Mesh3D:
    """Hexahedral mesh of ``problem`` on the axial lines of ``grid``.

    ``divisions``: circumferential divisions (a multiple of 4); ``layers``: radial layers of
    the shaft's O-ring; ``radial_size``: radial element size in the nut (default: the
    circumferential size 2πR/n, at least one layer per radius step).
    """
    R, r_i = problem.shaft_radius, problem.bore_radius
    shaft_sec = (
        tube_section(r_i, R, divisions, layers) if r_i > 0.0 else disc_section(R, divisions, layers)
    )
    size = 2.0 * math.pi * R / divisions if radial_size is None else radial_size
    if not size > 0.0:
        raise InputError("mesh.radial_size", size, "a length > 0 m")
    radii = sorted({p.outer_radius for p in problem.parts})
    lines = [R]
    for a, b in zip([R, *radii[:-1]], radii, strict=True):
        lines.extend(np.linspace(a, b, max(1, math.ceil((b - a) / size - 1e-9)) + 1)[1:])
    r_ring = np.asarray(lines)
    ring_sec = annulus_section(r_ring, divisions)

    p_s, t_s = extrude(shaft_sec, grid.z)
    z_ring = grid.ring_z
    p_r, t_r = extrude(ring_sec, z_ring)
    m2 = ring_sec.t.shape[1]
    iz = np.repeat(np.arange(z_ring.size - 1), m2)
    part = grid.part_of_cell[iz]
    outer = np.array([p.outer_radius for p in problem.parts])[part]
    centroid = ring_sec.p[:, ring_sec.t].mean(axis=1)
    r_cent = np.tile(np.hypot(centroid[0], centroid[1]), z_ring.size - 1)
    keep = r_cent < outer
    t_r, part = t_r[:, keep], part[keep]
    used = np.unique(t_r)
    renumber = np.full(p_r.shape[1], -1)
    renumber[used] = np.arange(used.size)
    n_s = p_s.shape[1]
    p = np.hstack([p_s, p_r[:, used]])
    t = np.hstack([t_s, renumber[t_r] + n_s])
    mesh = MeshHex(p, t)
    e_s = t_s.shape[1]
    body = np.r_[np.zeros(e_s, dtype=np.int64), np.ones(t_r.shape[1], dtype=np.int64)]
    part_all = np.r_[np.full(e_s, -1, dtype=np.int64), part]
    ring_cells = np.full(keep.size, -1, dtype=np.int64)
    ring_cells[keep] = e_s + np.arange(keep.sum())
    ring_nodes = np.where(renumber >= 0, renumber + n_s, -1)
    m3 = Mesh3D(
        mesh=mesh,
        body=body,
        part=part_all,
        shaft_section=shaft_sec,
        ring_section=ring_sec,
        z_shaft=grid.z,
        z_ring=z_ring,
        ring_cells=ring_cells.reshape(z_ring.size - 1, m2),
        ring_nodes=ring_nodes.reshape(z_ring.size, ring_sec.p.shape[1]),
        divisions=divisions,
        facets={},
        bore_radius=r_i,
    )
    m3.facets.update(_classify(m3, problem))
    return m3


def _classify(m3: Mesh3D, problem: ThermalProblem) -> dict[str, NDArray[np.int64]]:
    """Name the boundary facets by body, orientation and position."""
    mesh = m3.mesh
    R, L = problem.shaft_radius, problem.shaft_length
    tol = 1e-9 * max(L, R)
    bf = mesh.boundary_facets()
    xyz = mesh.p[:, mesh.facets[:, bf]]  # (3, 4 nodes, facets)
    radius = np.hypot(xyz[0], xyz[1])
    flat = np.ptp(xyz[2], axis=0) < tol  # constant z: an end face
    at_r = np.all(np.abs(radius - R) < tol, axis=0)
    elem = mesh.f2t[0, bf]
    shaft = m3.body[elem] == 0
    z_mid = xyz[2].mean(axis=0)
    facets = {
        "shaft_surface": bf[shaft & ~flat & at_r],
        "shaft_ends": bf[shaft & flat & ((np.abs(z_mid) < tol) | (np.abs(z_mid - L) < tol))],
        "ring_outer": bf[~shaft & ~flat & ~at_r],
        "ring_ends": bf[~shaft & flat],
    }
    bore = ~shaft & ~flat & at_r
    part = m3.part[elem]
    surface = shaft & ~flat & at_r
    if problem.bore_radius > 0.0:
        at_bore = np.all(np.abs(radius - problem.bore_radius) < tol, axis=0)
        facets["shaft_bore"] = bf[shaft & ~flat & at_bore]
    for k, p in enumerate(problem.parts):
        key = f"bore{k}" if p.balls else f"spacer_bore{k}"
        facets[key] = bf[bore & (part == k)]
        if p.balls and facets[key].size:  # the shaft side of the interface, at the mean position
            lo, hi = z_mid[bore & (part == k)].min(), z_mid[bore & (part == k)].max()
            facets[f"interface{k}"] = bf[surface & (z_mid >= lo - tol) & (z_mid <= hi + tol)]
    for j, b in enumerate(problem.bearings):
        lo, hi = b.position - 0.5 * b.width, b.position + 0.5 * b.width
        facets[f"band{j}"] = bf[surface & (z_mid >= lo) & (z_mid <= hi)]
    return facets
