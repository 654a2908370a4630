"""The matrices of an FE thermal model that do not depend on its loads, and their binding.

Mesh, basis, conduction, capacity, unit film matrices and the ball-contact geometry are built once
per mesh (:class:`FeOperator`); :func:`bind` combines them with a problem's heat flows,
convection coefficients, contact conductances, coolant and table, all of which enter the
system C θ̇ + A θ = f linearly. The coupled operating point re-binds the same operator at
every fixed-point iteration and for the transient instead of meshing and assembling again
(theory manual ``docs/theory/thermal.md``, *One assembly per coupled solve*).

Besides the FE unknowns the system may hold (in this order):

* the coolant of a hollow shaft, one bulk rise θ_c,k per axial cell k of the bore, upwind:
      W (θ_c,k − θ_c,k−1) = h ∫_cell k (θ_w − θ_c,k) dA,   θ_c,−1 = θ_in,
  with W = ṁc_p, the energy balance of the plug flow (Incropera & DeWitt 2007, Sec. 8.3)
  cell by cell; the wall sees the sink h ∫_bore (θ_w − θ_c) v dA;
* the table as one lumped node θ_t of capacity C_t, joined to the nut assembly's outer
  surface by h_j and to ambient by G_t: C_t θ̇_t = h_j ∫_od (θ − θ_t) dA − G_t θ_t.

Both keep the discrete energy balance exact: the column sums of A are the convective losses,
W at the coolant outlet and G_t at the table.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from numpy.typing import NDArray

from ballscrew.thermal.discretisation import Discretisation
from ballscrew.thermal.fe_assembly import CONVECTIVE_FACES, BoreInterface, interface_terms
from ballscrew.thermal.problem import AxialGrid, ThermalProblem

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class CoolantChannel:
    """The bore of a hollow shaft on the FE mesh."""

    wall: sp.csr_matrix
    """Unit film matrix of the bore ∫ u v dA [m²]."""
    cells: sp.csr_matrix
    """B[i, k] = ∫_cell k φ_i dA over the bore's axial cell k [m²] (FE DOFs × cells)."""


@dataclass(frozen=True)
class FeOperator:
    """What an FE model assembles once per mesh (SI)."""

    conduction: sp.csr_matrix
    """Σ_bodies λ_b ∫ ∇u·∇v [W/K]."""
    capacity: sp.csr_matrix
    """Σ_bodies ρc_b ∫ u v [J/K]."""
    faces: dict[str, sp.csr_matrix]
    """Unit film matrices of :data:`~ballscrew.thermal.fe_assembly.CONVECTIVE_FACES`."""
    surface_film: Callable[[FloatArray], sp.csr_matrix]
    """Stroke weights → unit film of the shaft surface outside the nut, ∫(1 − coverage) u v."""
    bores: tuple[BoreInterface | None, ...]
    """Per part of the nut assembly: its bore (None: a spacer)."""
    bearings: tuple[FloatArray, ...]
    """Per bearing: its band load for 1 W."""
    outer: FloatArray
    """∫_od v dA of the nut assembly's outer surface [m²] (a flux's load per W/m²)."""
    coolant: CoolantChannel | None = None
    film_cache: dict[bytes, sp.csr_matrix] = field(default_factory=dict, compare=False)

    @property
    def size(self) -> int:
        """FE unknowns."""
        return int(self.conduction.shape[0])

    def film(self, weights: FloatArray) -> sp.csr_matrix:
        """:attr:`surface_film` at ``weights``, assembled once per distinct weights."""
        key = np.asarray(weights, dtype=float).tobytes()
        if key not in self.film_cache:
            self.film_cache[key] = sp.csr_matrix(self.surface_film(weights))
        return self.film_cache[key]


@dataclass(frozen=True)
class Readouts:
    """Linear read-outs over the FE unknowns (see :class:`Discretisation`)."""

    elongation: FloatArray
    sensors: sp.csr_matrix
    axis_z: FloatArray
    axis: sp.csr_matrix
    nut_mean: FloatArray
    """Row giving the volume mean of the nut assembly (1/V)∫θ dV."""


def fe_discretisation(
    model: str,
    problem: ThermalProblem,
    grid: AxialGrid,
    op: FeOperator,
    readouts: Readouts,
    direct_limit: int,
    extra: dict,
) -> Discretisation:
    """The :class:`Discretisation` of ``problem`` on ``op``; its ``rebind`` re-uses ``op``.

    ``extra`` gains ``nut_mean`` (the nut assembly's volume-mean row), ``coolant`` (the
    unknowns of the bore coolant's cells, inlet to outlet; empty for a solid shaft) and
    ``operator``.
    """

    def discretise(p: ThermalProblem) -> Discretisation:
        total = op.size + extra_unknowns(op, p)
        coolant = np.arange(op.size, total - (p.table is not None))
        capacity, assemble = bind(op, p)
        return Discretisation(
            model=model,
            problem=p,
            grid=grid,
            capacity=capacity,
            assemble=assemble,
            elongation=pad(readouts.elongation, total),
            sensors=pad(readouts.sensors, total),
            axis_z=readouts.axis_z,
            axis=pad(readouts.axis, total),
            direct_limit=direct_limit,
            extra={
                **extra,
                "nut_mean": pad(readouts.nut_mean, total),
                "coolant": coolant,
                "operator": op,
            },
            rebind=discretise,
        )

    return discretise(problem)


def extra_unknowns(op: FeOperator, problem: ThermalProblem) -> int:
    """Unknowns after the FE ones: coolant cells and the table node."""
    cells = 0 if op.coolant is None or problem.shaft_coolant is None else op.coolant.cells.shape[1]
    return cells + (problem.table is not None)


def pad(rows: sp.spmatrix | FloatArray, total: int) -> sp.csr_matrix | FloatArray:
    """Read-out rows over the FE unknowns extended by zero columns to ``total`` unknowns."""
    if isinstance(rows, np.ndarray):
        return np.concatenate([rows, np.zeros(total - rows.shape[-1])])
    extra = sp.csr_matrix((rows.shape[0], total - rows.shape[1]))
    return sp.csr_matrix(sp.hstack([rows, extra]))


def bind(
    op: FeOperator, problem: ThermalProblem
) -> tuple[sp.csr_matrix, Callable[[FloatArray], tuple[sp.csr_matrix, FloatArray]]]:
    """(capacity C, weights → (A, f)) of ``problem`` on the operator's mesh."""
    n = op.size
    conv = problem.convection
    static = op.conduction
    for name, h in zip(CONVECTIVE_FACES, (conv.screw_ends, conv.nut, conv.nut_ends), strict=True):
        if h > 0.0 and name in op.faces:
            static = static + h * op.faces[name]
    fixed = np.zeros(n)
    for bearing, unit in zip(problem.bearings, op.bearings, strict=True):
        fixed += bearing.power * unit
    if problem.nut_coolant_flux != 0.0:
        fixed += problem.nut_coolant_flux * op.outer
    extra, extra_load, capacity = _extra_blocks(op, problem)
    couplings = [
        (bore, p.contact_conductance, p.nut_heat, p.screw_heat)
        for p, bore in zip(problem.parts, op.bores, strict=True)
        if bore is not None
    ]

    def assemble(weights: FloatArray) -> tuple[sp.csr_matrix, FloatArray]:
        a = static + conv.screw * op.film(weights) if conv.screw > 0 else static
        jumps, f = interface_terms(n, couplings, weights)
        f += fixed
        if jumps is not None:
            a = a + jumps
        if extra is None:
            return sp.csr_matrix(a), f
        m = extra_load.size
        a = sp.block_diag([a, sp.csr_matrix((m, m))], format="csr") + extra
        return sp.csr_matrix(a), np.concatenate([f, extra_load])

    return capacity, assemble


def _extra_blocks(
    op: FeOperator, problem: ThermalProblem
) -> tuple[sp.csr_matrix | None, FloatArray, sp.csr_matrix]:
    """The coolant and table terms on the extended unknowns: (A part or None, load, C)."""
    n = op.size
    m = extra_unknowns(op, problem)
    if m == 0:
        return None, np.zeros(0), sp.csr_matrix(op.capacity)
    total = n + m
    rows: list[FloatArray] = []
    cols: list[FloatArray] = []
    vals: list[FloatArray] = []
    load = np.zeros(m)
    stored = np.zeros(m)

    def add(block: sp.spmatrix, row0: int, col0: int) -> None:
        coo = sp.coo_matrix(block)
        rows.append(coo.row + row0)
        cols.append(coo.col + col0)
        vals.append(coo.data)

    cool, channel = problem.shaft_coolant, op.coolant
    cells = 0
    if cool is not None and channel is not None:
        h, w = cool.coefficient, cool.capacity_rate
        b = channel.cells
        cells = b.shape[1]
        wetted = np.asarray(b.sum(axis=0)).ravel()
        advection = sp.diags([np.full(cells, w), np.full(cells - 1, -w)], [0, -1])
        add(h * channel.wall, 0, 0)
        add(-h * b, 0, n)
        add(-h * b.T, n, 0)
        add(sp.diags(h * wetted) + advection, n, n)
        load[0] = w * cool.inlet_rise
    table = problem.table
    if table is not None:
        t = n + cells
        outer = op.faces.get("ring_outer", sp.csr_matrix((n, n)))
        joint = table.joint_coefficient
        row = np.asarray(outer.sum(axis=1)).ravel()  # ∫_od φ_i dA, consistent with the matrix
        add(joint * outer, 0, 0)
        add(sp.csr_matrix(-joint * row[:, None]), 0, t)
        add(sp.csr_matrix(-joint * row[None, :]), t, 0)
        add(sp.csr_matrix([[joint * row.sum() + table.conductance]]), t, t)
        stored[-1] = table.capacity
    a = sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(total, total)
    )
    capacity = sp.csr_matrix(sp.block_diag([op.capacity, sp.diags(stored)]))
    return a, load, capacity
