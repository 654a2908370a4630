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

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray

from ballscrew.thermal.discretisation import Discretisation, band_overlap, laplacian
from ballscrew.thermal.problem import AxialGrid, ThermalProblem, axial_grid


def annulus_split(inner: float, outer: float) -> tuple[float, float]:
    """(bore→mean, mean→OD) radial resistance of an annulus per unit 1/(2πλΔz) [-].

    For steady through-flow T(r) = T_i − Q′ ln(r/r_i)/(2πλ); the area-mean temperature sits at
    r_o² ln(r_o/r_i)/(r_o² − r_i²) − ½ of the total ln(r_o/r_i).
    """
    total = math.log(outer / inner)
    to_mean = outer**2 * total / (outer**2 - inner**2) - 0.5
    return to_mean, total - to_mean


def build_network(problem: ThermalProblem, cell: float) -> Discretisation:
    """The axial network of ``problem`` with cells of at most ``cell`` [m]."""
    grid = axial_grid(problem, cell)
    R, L = problem.shaft_radius, problem.shaft_length
    ks, kr = problem.shaft.conductivity, problem.ring.conductivity
    conv = problem.convection
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
    cool, table = problem.shaft_coolant, problem.table
    coolant = n + np.arange(ns if cool is not None else 0)
    n += coolant.size
    table_node = n
    n += table is not None
    r_in, area_s = problem.bore_radius, problem.section_area
    area_r = np.pi * (ro**2 - R**2)

    ii: list[NDArray[np.int64]] = []
    jj: list[NDArray[np.int64]] = []
    gg: list[NDArray[np.float64]] = []
    ground = np.zeros(n)

    def link(i: NDArray[np.int64], j: NDArray[np.int64], g: NDArray[np.float64]) -> None:
        ii.append(np.asarray(i))
        jj.append(np.asarray(j))
        gg.append(np.broadcast_to(np.asarray(g, dtype=float), np.shape(i)).copy())

    zc = 0.5 * (z[1:] + z[:-1])
    link(mean_s[:-1], mean_s[1:], ks * area_s / np.diff(zc))
    if cool is None:
        link(mean_s, surf_s, 8.0 * np.pi * ks * dzs)
    else:
        to_bore, to_surface = annulus_split(r_in, R)
        link(mean_s, surf_s, 2.0 * np.pi * ks * dzs / to_surface)
        wall = 1.0 / (to_bore / (2.0 * np.pi * ks) + 1.0 / (cool.coefficient * 2.0 * np.pi * r_in))
        link(mean_s, coolant, wall * dzs)

    def end_face(h: float, area: float, half: float, k: float) -> float:
        return 0.0 if h <= 0.0 else 1.0 / (1.0 / (h * area) + half / (k * area))

    ground[mean_s[0]] += end_face(conv.screw_ends, area_s, 0.5 * dzs[0], ks)
    ground[mean_s[-1]] += end_face(conv.screw_ends, area_s, 0.5 * dzs[-1], ks)

    half_r = 0.5 * dz / (kr * area_r)
    link(mean_r[:-1], mean_r[1:], 1.0 / (half_r[:-1] + half_r[1:]))
    split = np.array([annulus_split(R, r) for r in ro])
    link(bore_r, mean_r, 2.0 * np.pi * kr * dz / split[:, 0])
    link(mean_r, od_r, 2.0 * np.pi * kr * dz / split[:, 1])
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
        link(od_r, np.full(nr, table_node), table.joint_coefficient * 2.0 * np.pi * ro * dz)
        ground[table_node] += table.conductance
    static = laplacian(n, np.concatenate(ii), np.concatenate(jj), np.concatenate(gg), ground)
    if cool is not None:
        w = cool.capacity_rate
        advection = sp.coo_matrix(
            (
                np.r_[np.full(ns, w), np.full(ns - 1, -w)],
                (np.r_[coolant, coolant[1:]], np.r_[coolant, coolant[:-1]]),
            ),
            shape=(n, n),
        )
        static = sp.csr_matrix(static + advection)
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
    for b in problem.bearings:
        overlap = band_overlap(z, b.position, b.width, L)
        bearing_heat += b.power * overlap / overlap.sum()
    has_contact = g_contact > 0.0

    def assemble(weights: NDArray[np.float64]) -> tuple[sp.csr_matrix, NDArray[np.float64]]:
        cover = grid.coverage(zc, weights)
        a = static + sp.diags(
            np.concatenate(
                [np.zeros(ns), conv.screw * surf_area * (1.0 - cover), np.zeros(n - 2 * ns)]
            )
        )
        f = fixed_load.copy()
        f[bore_r] += q_nut
        f[surf_s] += bearing_heat
        active = np.nonzero(weights)[0]
        rows, cols, vals = [], [], []
        for k in active:
            facing = surf_s[grid.first + grid.shifts[k] + np.arange(nr)]
            rows.append(bore_r[has_contact])
            cols.append(facing[has_contact])
            vals.append(weights[k] * g_contact[has_contact])
            np.add.at(f, facing, weights[k] * q_screw)
        if rows:
            a = a + laplacian(n, np.concatenate(rows), np.concatenate(cols), np.concatenate(vals))
        return sp.csr_matrix(a), f

    elongation = problem.expansion * np.concatenate([dzs, np.zeros(n - ns)])
    sensors = _sensor_rows(problem, grid, zc, ro, (mean_s, surf_s, bore_r, od_r), n)
    axis = sp.csr_matrix((np.ones(ns), (np.arange(ns), mean_s)), shape=(ns, n))
    return Discretisation(
        model="network",
        problem=problem,
        grid=grid,
        capacity=capacity,
        assemble=assemble,
        elongation=elongation,
        sensors=sensors,
        axis_z=zc,
        axis=axis,
        direct_limit=10**9,
        extra={
            "shaft_mean": mean_s,
            "shaft_surface": surf_s,
            "ring_mean": mean_r,
            "ring_bore": bore_r,
            "ring_outer": od_r,
            "ring_z": 0.5 * (grid.ring_z[1:] + grid.ring_z[:-1]),
            "ring_outer_radius": ro,
            "coolant": coolant,
            "table": table_node if table is not None else None,
        },
    )


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
