"""1-D axial thermal network of the screw with the nut assembly (the fast model, for sweeps).

Unknowns per axial cell (theory manual ``docs/theory/thermal.md``, 1-D axial network):
- shaft: mean temperature (capacity ρc·πR²·Δz) and a massless surface node. Mean-to-surface
  conductance 8πλΔz: the parabolic radial profile of a solid cylinder, T̄ − T_s = Q′/(8πλ).
- nut assembly: mean temperature (capacity ρc·π(r_o² − R²)Δz) with massless bore and OD nodes;
  bore-to-mean and mean-to-OD resistances split the annulus' ln(r_o/R)/(2πλΔz) at the
  area-mean temperature of the logarithmic through-flow profile:
      R_bore→mean = [r_o² ln(r_o/R)/(r_o² − R²) − ½] / (2πλΔz).
- axial conduction λA/Δz between cell means; end faces h·A through a half cell.
- balls: a resistor 1/(h_c 2πR Δz) between the nut bore node and the shaft surface node it
  faces at each stroke offset, weighted by the offset's time fraction; friction heat enters the
  two surface nodes. Convection h(1 − coverage)·2πRΔz from the shaft surface.
- hollow shaft with coolant (optional): the shaft cell is the annulus r_i … R, split like the
  nut; a coolant node per cell, bore wall h·2πr_iΔz to the cell mean, upwind advection
  ṁc_p(θ_c,k − θ_c,k−1) from the inlet at z = 0 (the energy balance of the flow).
- table (optional): one lumped node of capacity C_t, joint h_j·2πr_oΔz to every nut OD node and
  G_t to ambient.
Steady and transient solves take milliseconds (a few hundred unknowns).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray

from ballscrew.thermal.discretisation import Discretisation, Entries, band_overlap, links
from ballscrew.thermal.problem import AxialGrid, ThermalProblem, axial_grid


def annulus_split(inner: float, outer: float) -> tuple[float, float]:
    """(bore→mean, mean→OD) radial resistance of an annulus per unit 1/(2πλΔz) [-].

    For steady through-flow T(r) = T_i − Q′ ln(r/r_i)/(2πλ); the area-mean temperature sits at
    r_o² ln(r_o/r_i)/(r_o² − r_i²) − ½ of the total ln(r_o/r_i).
    """
    total = math.log(outer / inner)
    to_mean = outer**2 * total / (outer**2 - inner**2) - 0.5
    return to_mean, total - to_mean


@dataclass(frozen=True)
class _Layout:
    """Nodes and geometry of a network, fixed by the mesh (:func:`same_mesh`)."""

    grid: AxialGrid
    n: int
    mean_s: NDArray[np.int64]
    surf_s: NDArray[np.int64]
    mean_r: NDArray[np.int64]
    bore_r: NDArray[np.int64]
    od_r: NDArray[np.int64]
    coolant: NDArray[np.int64]
    table_node: int
    part: NDArray[np.int64]
    """Part of the nut assembly of every ring cell."""
    ro: NDArray[np.float64]
    """Outer radius of every ring cell [m]."""
    zc: NDArray[np.float64]
    """Shaft cell centres [m]."""
    conduction: Entries
    """The conduction of shaft and nut, which no coefficient of the problem changes [W/K]."""
    bearing_bands: tuple[NDArray[np.float64], ...]
    """Per bearing: the share of its heat entering each shaft cell [-]."""


def build_network(problem: ThermalProblem, cell: float) -> Discretisation:
    """The axial network of ``problem`` with cells of at most ``cell`` [m].

    The conduction of shaft and nut is assembled once; the ``rebind`` of the result binds
    other heats, convection and contact coefficients, coolant and table values (those
    :func:`~ballscrew.thermal.problem.same_mesh` ignores) to it.
    """
    layout = _layout(problem, cell)
    n, ns = layout.n, layout.zc.size
    grid, mean_s, surf_s = layout.grid, layout.mean_s, layout.surf_s
    elongation = problem.expansion * np.concatenate([np.diff(grid.z), np.zeros(n - ns)])
    nodes = (mean_s, surf_s, layout.bore_r, layout.od_r)
    sensors = _sensor_rows(problem, grid, layout.zc, layout.ro, nodes, n)
    axis = sp.csr_matrix((np.ones(ns), (np.arange(ns), mean_s)), shape=(ns, n))
    extra = {
        "shaft_mean": mean_s,
        "shaft_surface": surf_s,
        "ring_mean": layout.mean_r,
        "ring_bore": layout.bore_r,
        "ring_outer": layout.od_r,
        "ring_z": 0.5 * (grid.ring_z[1:] + grid.ring_z[:-1]),
        "ring_outer_radius": layout.ro,
        "coolant": layout.coolant,
        "table": layout.table_node if problem.table is not None else None,
    }

    def discretise(p: ThermalProblem) -> Discretisation:
        capacity, assemble = _bind(layout, p)
        return Discretisation(
            model="network",
            problem=p,
            grid=grid,
            capacity=capacity,
            assemble=assemble,
            elongation=elongation,
            sensors=sensors,
            axis_z=layout.zc,
            axis=axis,
            direct_limit=10**9,
            extra=dict(extra),
            rebind=discretise,
        )

    return discretise(problem)


def _layout(problem: ThermalProblem, cell: float) -> _Layout:
    """Nodes, geometry and the conduction matrix of the network of ``problem``."""
    grid = axial_grid(problem, cell)
    R, L = problem.shaft_radius, problem.shaft_length
    ks, kr = problem.shaft.conductivity, problem.ring.conductivity
    z = grid.z
    dzs = np.diff(z)
    ns = dzs.size
    nr = grid.ring_cells
    part = grid.part_of_cell
    ro = np.array([problem.parts[p].outer_radius for p in part])
    dz = grid.dz
    mean_s, surf_s = np.arange(ns), ns + np.arange(ns)
    mean_r, bore_r, od_r = 2 * ns + np.arange(nr), 2 * ns + nr + np.arange(nr), 2 * ns + 2 * nr
    od_r = od_r + np.arange(nr)
    n = 2 * ns + 3 * nr
    coolant = n + np.arange(ns if problem.shaft_coolant is not None else 0)
    n += coolant.size
    table_node = n
    n += problem.table is not None
    area_s = problem.section_area
    area_r = np.pi * (ro**2 - R**2)

    zc = 0.5 * (z[1:] + z[:-1])
    ii = [mean_s[:-1]]
    jj = [mean_s[1:]]
    gg = [ks * area_s / np.diff(zc)]
    if problem.shaft_coolant is None:
        gg.append(8.0 * np.pi * ks * dzs)
    else:
        _, to_surface = annulus_split(problem.bore_radius, R)
        gg.append(2.0 * np.pi * ks * dzs / to_surface)
    ii.append(mean_s)
    jj.append(surf_s)
    half_r = 0.5 * dz / (kr * area_r)
    split = np.array([annulus_split(R, r) for r in ro])
    ii += [mean_r[:-1], bore_r, mean_r]
    jj += [mean_r[1:], mean_r, od_r]
    gg += [
        1.0 / (half_r[:-1] + half_r[1:]),
        2.0 * np.pi * kr * dz / split[:, 0],
        2.0 * np.pi * kr * dz / split[:, 1],
    ]
    conduction = links(np.concatenate(ii), np.concatenate(jj), np.concatenate(gg))
    bands = []
    for b in problem.bearings:
        overlap = band_overlap(z, b.position, b.width, L)
        bands.append(overlap / overlap.sum())
    return _Layout(
        grid,
        n,
        mean_s,
        surf_s,
        mean_r,
        bore_r,
        od_r,
        coolant,
        table_node,
        part,
        ro,
        zc,
        conduction,
        tuple(bands),
    )


def _bind(
    layout: _Layout, problem: ThermalProblem
) -> tuple[
    sp.csr_matrix, Callable[[NDArray[np.float64]], tuple[sp.csr_matrix, NDArray[np.float64]]]
]:
    """(capacity C, weights → (A, f)) of ``problem``'s coefficients and heats on ``layout``."""
    grid, n, ro, part = layout.grid, layout.n, layout.ro, layout.part
    mean_s, surf_s, mean_r, bore_r, od_r = (
        layout.mean_s,
        layout.surf_s,
        layout.mean_r,
        layout.bore_r,
        layout.od_r,
    )
    coolant, table_node = layout.coolant, layout.table_node
    R = problem.shaft_radius
    ks, kr = problem.shaft.conductivity, problem.ring.conductivity
    conv = problem.convection
    dzs = np.diff(grid.z)
    ns, nr, dz = dzs.size, grid.ring_cells, grid.dz
    area_s = problem.section_area
    area_r = np.pi * (ro**2 - R**2)
    cool, table = problem.shaft_coolant, problem.table
    ground = np.zeros(n)
    ii: list[NDArray[np.int64]] = []
    jj: list[NDArray[np.int64]] = []
    gg: list[NDArray[np.float64]] = []

    def end_face(h: float, area: float, half: float, k: float) -> float:
        return 0.0 if h <= 0.0 else 1.0 / (1.0 / (h * area) + half / (k * area))

    if cool is not None:
        r_in = problem.bore_radius
        to_bore, _ = annulus_split(r_in, R)
        wall = 1.0 / (to_bore / (2.0 * np.pi * ks) + 1.0 / (cool.coefficient * 2.0 * np.pi * r_in))
        ii.append(mean_s)
        jj.append(coolant)
        gg.append(wall * dzs)
    ground[mean_s[0]] += end_face(conv.screw_ends, area_s, 0.5 * dzs[0], ks)
    ground[mean_s[-1]] += end_face(conv.screw_ends, area_s, 0.5 * dzs[-1], ks)
    ground[od_r] += conv.nut * 2.0 * np.pi * ro * dz
    ground[mean_r[0]] += end_face(conv.nut_ends, area_r[0], 0.5 * dz, kr)
    ground[mean_r[-1]] += end_face(conv.nut_ends, area_r[-1], 0.5 * dz, kr)
    step = np.pi * np.abs(ro[1:] ** 2 - ro[:-1] ** 2)  # exposed annulus where the OD steps
    bigger = np.where(ro[:-1] > ro[1:], mean_r[:-1], mean_r[1:])
    for cell_index, a_step in zip(bigger, step, strict=True):
        if a_step > 0.0:
            ground[cell_index] += end_face(conv.nut_ends, a_step, 0.5 * dz, kr)
    fixed_load = np.zeros(n)
    fixed_load[od_r] += problem.nut_coolant_flux * 2.0 * np.pi * ro * dz
    if table is not None:
        ii.append(od_r)
        jj.append(np.full(nr, table_node))
        gg.append(table.joint_coefficient * 2.0 * np.pi * ro * dz)
        ground[table_node] += table.conductance
    nodes = np.arange(n)
    static = [layout.conduction, (nodes, nodes, ground)]
    if ii:
        static.append(links(np.concatenate(ii), np.concatenate(jj), np.concatenate(gg)))
    if cool is not None:
        w = cool.capacity_rate
        upwind = (
            np.r_[coolant, coolant[1:]],
            np.r_[coolant, coolant[:-1]],
            np.r_[np.full(ns, w), np.full(ns - 1, -w)],
        )
        static.append(upwind)
        fixed_load[coolant[0]] += w * cool.inlet_rise

    capacity = sp.diags(
        np.concatenate(
            [
                problem.shaft.heat_capacity * area_s * dzs,
                np.zeros(ns),
                problem.ring.heat_capacity * area_r * dz,
                np.zeros(2 * nr + coolant.size),
                [table.capacity] if table is not None else [],
            ]
        )
    ).tocsr()

    cells_per_part = np.array(grid.part_cells)[part]
    g_contact = np.array([problem.parts[p].contact_conductance for p in part]) / cells_per_part
    q_screw = np.array([problem.parts[p].screw_heat for p in part]) / cells_per_part
    q_nut = np.array([problem.parts[p].nut_heat for p in part]) / cells_per_part
    surf_area = 2.0 * np.pi * R * dzs
    bearing_heat = np.zeros(ns)
    for b, band in zip(problem.bearings, layout.bearing_bands, strict=True):
        bearing_heat += b.power * band
    has_contact = g_contact > 0.0

    def assemble(weights: NDArray[np.float64]) -> tuple[sp.csr_matrix, NDArray[np.float64]]:
        film = conv.screw * surf_area * (1.0 - grid.coverage(layout.zc, weights))
        entries = [*static, (surf_s, surf_s, film)]
        f = fixed_load.copy()
        f[bore_r] += q_nut
        f[surf_s] += bearing_heat
        for k in np.nonzero(weights)[0]:
            facing = surf_s[grid.first + grid.shifts[k] + np.arange(nr)]
            entries.append(
                links(bore_r[has_contact], facing[has_contact], weights[k] * g_contact[has_contact])
            )
            np.add.at(f, facing, weights[k] * q_screw)
        return _matrix(n, entries), f

    return capacity, assemble


def _matrix(n: int, entries: list[Entries]) -> sp.csr_matrix:
    """The n × n matrix of all ``entries`` (repeated positions add up), built at once."""
    rows, cols, vals = (np.concatenate(part) for part in zip(*entries, strict=True))
    return sp.csr_matrix((vals, (rows, cols)), shape=(n, n))


def _interpolation(centres: NDArray[np.float64], zq: float) -> tuple[list[int], list[float]]:
    """Cells and weights of linear interpolation at ``zq`` between cell centres (clamped)."""
    if zq <= centres[0]:
        return [0], [1.0]
    if zq >= centres[-1]:
        return [centres.size - 1], [1.0]
    k = int(np.searchsorted(centres, zq) - 1)
    t = (zq - centres[k]) / (centres[k + 1] - centres[k])
    return [k, k + 1], [1.0 - t, t]


def _sensor_rows(
    problem: ThermalProblem,
    grid: AxialGrid,
    zc: NDArray[np.float64],
    ro: NDArray[np.float64],
    nodes: tuple[NDArray[np.int64], ...],
    n: int,
) -> sp.csr_matrix:
    """Sensor read-outs from the radial profiles the network assumes.

    Shaft: T(r) = T_s + 2(T̄ − T_s)(1 − r²/R²) (parabolic, mean T̄). Nut: logarithmic between
    the bore and OD nodes. Linear in z between cell centres.
    """
    mean_s, surf_s, bore_r, od_r = nodes
    R = problem.shaft_radius
    ring_zc = 0.5 * (grid.ring_z[1:] + grid.ring_z[:-1])
    rows, cols, vals = [], [], []
    for k, s in enumerate(problem.sensors):
        if s.body == "screw":
            cells, w = _interpolation(zc, s.z)
            shape = 2.0 * (1.0 - (min(s.r, R) / R) ** 2)
            for c, wc in zip(cells, w, strict=True):
                rows += [k, k]
                cols += [int(mean_s[c]), int(surf_s[c])]
                vals += [wc * shape, wc * (1.0 - shape)]
        else:
            cells, w = _interpolation(ring_zc, s.z)
            for c, wc in zip(cells, w, strict=True):
                t = math.log(min(max(s.r, R), ro[c]) / R) / math.log(ro[c] / R)
                rows += [k, k]
                cols += [int(bore_r[c]), int(od_r[c])]
                vals += [wc * (1.0 - t), wc * t]
    return sp.csr_matrix((vals, (rows, cols)), shape=(len(problem.sensors), n))
