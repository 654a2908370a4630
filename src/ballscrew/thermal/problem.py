"""The thermal problem of a screw shaft with a nut assembly, in plain SI dataclasses.

A solid shaft (radius R, length L, axis z from 0 to L) carries a nut assembly: a ring of
axial parts (nut, spacer, nut) on the bore radius R. The balls of each nut are smeared over
its bore as an interface conductance; the ball-screw friction heat enters at that interface,
part into the screw side and part into the nut side. Support bearings heat bands of the shaft
surface. Every outer surface loses heat by convection to ambient; the spacer bore and the shaft
surface under it are adiabatic (an air gap). The nut may reciprocate over a stroke (moving
heat source, ``docs/theory/thermal.md``). Temperatures are rises θ = T − T_ambient [K].

The models (:mod:`~ballscrew.thermal.network`, :mod:`~ballscrew.thermal.axisymmetric`) share
:class:`AxialGrid`: a uniform axial spacing over the range the nut sweeps, so that every nut
position of the stroke falls on grid lines.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.thermal.coolant import ShaftCoolant


@dataclass(frozen=True)
class Solid:
    """Thermal properties of a body."""

    conductivity: float
    """λ [W/(m K)]."""
    density: float
    """ρ [kg/m³]."""
    specific_heat: float
    """c_p [J/(kg K)]."""

    @property
    def heat_capacity(self) -> float:
        """Volumetric heat capacity ρ c_p [J/(m³ K)]."""
        return self.density * self.specific_heat


@dataclass(frozen=True)
class RingPart:
    """One axial part of the nut assembly: a nut with balls or a spacer."""

    name: str
    length: float
    """Axial length [m]."""
    outer_radius: float
    """Outer radius [m]."""
    balls: bool = True
    """True for a nut: its bore is in contact with the screw through the balls."""
    contact_conductance: float = 0.0
    """Total conductance 1/R of its balls between screw and nut surface [W/K] (0: none)."""
    screw_heat: float = 0.0
    """Friction heat generated at its contacts that enters the screw [W]."""
    nut_heat: float = 0.0
    """Friction heat generated at its contacts that enters the nut [W]."""


@dataclass(frozen=True)
class BandHeat:
    """Heat entering the shaft surface uniformly over an axial band (a support bearing)."""

    name: str
    position: float
    """Band centre z [m]."""
    width: float
    """Band width [m]; clipped to the shaft."""
    power: float
    """Heat into the shaft [W]."""


@dataclass(frozen=True)
class Convection:
    """Heat-transfer coefficients to ambient [W/(m² K)]."""

    screw: float
    """Shaft outer surface (outside the nut)."""
    screw_ends: float
    """Shaft end faces z = 0 and z = L."""
    nut: float
    """Outer surfaces of nuts and spacer."""
    nut_ends: float
    """End faces (annuli) of the nut assembly and its steps."""


@dataclass(frozen=True)
class Sensor:
    """A temperature sensor point (r, θ, z) fixed to the screw or to the nut."""

    name: str
    body: Literal["nut", "screw"]
    r: float
    """Radius [m]."""
    z: float
    """Axial position [m]; for the nut, at its mean position."""
    theta: float = 0.0
    """Angle from the x axis [rad]; read by the 3-D model, ignored by the axisymmetric ones."""


@dataclass(frozen=True)
class TableMass:
    """The table as a lumped heat capacity between the nut joint and ambient (Q8 transient).

    Node θ_t: C_t dθ_t/dt = h_j ∫(θ_od − θ_t) dA − G_t θ_t, with the joint h_j smeared over the
    outer surface of the nut assembly.
    """

    joint_coefficient: float
    """h_j = h_c A_c / A_od of the nut–table joint over the nut outer area [W/(m² K)]."""
    conductance: float
    """G_t of the table to ambient [W/K]."""
    capacity: float
    """C_t = m c of the table [J/K]."""

    def __post_init__(self) -> None:
        for name in ("joint_coefficient", "conductance"):
            if not getattr(self, name) >= 0.0:
                raise InputError(f"thermal.mounting.{name}", getattr(self, name), "a value ≥ 0")
        if not self.capacity > 0.0:
            raise InputError("thermal.mounting.table_heat_capacity", self.capacity, "> 0 J/K")


@dataclass(frozen=True)
class ThermalProblem:
    """Geometry, materials, heat sources and cooling of the screw–nut thermal model (SI)."""

    shaft_radius: float
    shaft_length: float
    shaft: Solid
    ring: Solid
    parts: tuple[RingPart, ...]
    """Nut assembly parts from low to high z (contiguous)."""
    ring_centre: float
    """z of the centre of the nut assembly (mean position) [m]."""
    convection: Convection
    bearings: tuple[BandHeat, ...] = ()
    stroke: float = 0.0
    """Stroke of the reciprocating nut [m] (0: stationary)."""
    expansion: float = 0.0
    """Thermal expansion coefficient α of the shaft [1/K]."""
    sensors: tuple[Sensor, ...] = field(default=())
    shaft_coolant: ShaftCoolant | None = None
    """Coolant through an axial bore of the shaft (None: a solid shaft)."""
    nut_coolant_flux: float = 0.0
    """h_cool·θ_in of a cooled nut whose coolant enters θ_in above ambient, smeared over the
    nut assembly's outer surface [W/m²] (its h_cool is part of ``convection.nut``)."""
    table: TableMass | None = None
    """The table as a lumped heat capacity (None: quasi-steady, inside ``convection.nut``)."""

    def __post_init__(self) -> None:
        cool = self.shaft_coolant
        if cool is not None and not cool.bore_radius < self.shaft_radius:
            raise InputError(
                "thermal.shaft_coolant.bore_diameter",
                2.0 * cool.bore_radius,
                f"a diameter < the shaft diameter {2.0 * self.shaft_radius:g} m",
            )
        for name in ("shaft_radius", "shaft_length"):
            if not getattr(self, name) > 0.0:
                raise InputError(name, getattr(self, name), "a length > 0 m")
        if not self.parts:
            raise InputError("parts", (), "at least one nut")
        for part in self.parts:
            if not part.length > 0.0:
                raise InputError(f"{part.name}.length", part.length, "a length > 0 m")
            if not part.outer_radius > self.shaft_radius:
                raise InputError(
                    f"{part.name}.outer_radius",
                    part.outer_radius,
                    f"a radius > the shaft radius {self.shaft_radius:g} m",
                )
            if min(part.contact_conductance, part.screw_heat, part.nut_heat) < 0.0:
                raise InputError(f"{part.name}", part, "conductance and heat ≥ 0")
        for b in self.bearings:
            if not (0.0 <= b.position <= self.shaft_length and b.width > 0 and b.power >= 0):
                raise InputError(
                    f"{b.name}", b, f"a band on [0, {self.shaft_length:g}] m, width > 0, power ≥ 0"
                )
        c = self.convection
        if min(c.screw, c.screw_ends, c.nut, c.nut_ends) < 0.0:
            raise InputError("convection", c, "heat-transfer coefficients ≥ 0")
        if not self.stroke >= 0.0:
            raise InputError("stroke", self.stroke, "a stroke ≥ 0 m")
        half = 0.5 * (self.ring_length + self.stroke)
        tol = 1e-9 * self.shaft_length
        if self.ring_centre - half < -tol or self.ring_centre + half > self.shaft_length + tol:
            raise InputError(
                "nut_position",
                self.ring_centre,
                f"a position that keeps the nut assembly ({self.ring_length:g} m) and its "
                f"stroke ({self.stroke:g} m) on the shaft [0, {self.shaft_length:g}] m",
            )

        for s in self.sensors:
            self._check_sensor(s)

    def _check_sensor(self, s: Sensor) -> None:
        R, tol = self.shaft_radius, 1e-9 * self.shaft_length
        if s.body == "screw":
            bore = self.bore_radius
            if not (bore <= s.r <= R + tol and -tol <= s.z <= self.shaft_length + tol):
                raise InputError(
                    f"sensors.{s.name}",
                    (s.r, s.z),
                    f"a point in the screw: r in [{bore:g}, {R:g}] m, z in "
                    f"[0, {self.shaft_length:g}] m",
                )
            return
        start = self.ring_centre - 0.5 * self.ring_length
        ends = start + np.cumsum([p.length for p in self.parts])
        k = int(np.searchsorted(ends, s.z - tol))
        inside_z = start - tol <= s.z <= ends[-1] + tol
        r_out = self.parts[min(k, len(self.parts) - 1)].outer_radius
        if not (inside_z and R - tol <= s.r <= r_out + tol):
            raise InputError(
                f"sensors.{s.name}",
                (s.r, s.z),
                f"a point in the nut assembly: z in [{start:g}, {ends[-1]:g}] m and r in "
                f"[{R:g}, outer radius] m",
            )

    @property
    def ring_length(self) -> float:
        """Length of the nut assembly [m]."""
        return float(sum(p.length for p in self.parts))

    @property
    def heat_input(self) -> float:
        """Total heat entering the system [W]."""
        return float(
            sum(p.screw_heat + p.nut_heat for p in self.parts) + sum(b.power for b in self.bearings)
        )

    @property
    def shaft_area(self) -> float:
        """Cross-section πR² of the shaft [m²]."""
        return math.pi * self.shaft_radius**2

    @property
    def bore_radius(self) -> float:
        """Radius r_i of the coolant bore of the shaft [m] (0: a solid shaft)."""
        return 0.0 if self.shaft_coolant is None else self.shaft_coolant.bore_radius

    @property
    def section_area(self) -> float:
        """Steel cross-section π(R² − r_i²) of the shaft [m²]."""
        return math.pi * (self.shaft_radius**2 - self.bore_radius**2)


def same_mesh(a: ThermalProblem, b: ThermalProblem) -> bool:
    """True when ``a`` and ``b`` differ at most in what an FE model binds after meshing.

    That is heat flows, convection coefficients, contact conductances, the cooled nut's flux,
    the bore coolant's h, ṁc_p and inlet rise and the table's h_j, G_t and C_t (all linear
    terms of C θ̇ + A θ = f); geometry, materials, stroke, sensors and the presence of a
    coolant bore or a table node must agree.
    """
    return _meshed(a) == _meshed(b)


def _meshed(p: ThermalProblem) -> ThermalProblem:
    """``p`` with every quantity :func:`same_mesh` ignores set to a fixed value."""
    cool = p.shaft_coolant
    return replace(
        p,
        parts=tuple(
            replace(q, contact_conductance=0.0, screw_heat=0.0, nut_heat=0.0) for q in p.parts
        ),
        convection=Convection(0.0, 0.0, 0.0, 0.0),
        bearings=tuple(replace(b, power=0.0) for b in p.bearings),
        nut_coolant_flux=0.0,
        shaft_coolant=None if cool is None else ShaftCoolant(cool.bore_radius, 0.0, 1.0),
        table=None if p.table is None else TableMass(0.0, 0.0, 1.0),
    )


@dataclass(frozen=True)
class AxialGrid:
    """Axial grid shared by the models: uniform spacing ``dz`` over the swept range.

    The ring occupies cells ``first .. first + ring_cells`` of the shaft grid at its mean
    position; a stroke offset of ``m`` cells moves it by ``m·dz``.
    """

    z: NDArray[np.float64]
    """Shaft grid lines, 0 … L [m]."""
    dz: float
    """Uniform spacing in the swept range [m]."""
    first: int
    """Index in ``z`` of the ring's low end at its mean position."""
    part_cells: tuple[int, ...]
    """Cells of each ring part."""
    shifts: NDArray[np.int64]
    """Stroke offsets (cells) sampled by the time average."""
    weights: NDArray[np.float64]
    """Time fraction of each offset (sums to 1)."""

    @property
    def ring_cells(self) -> int:
        """Cells of the whole nut assembly."""
        return int(sum(self.part_cells))

    @property
    def ring_z(self) -> NDArray[np.float64]:
        """Ring grid lines at the mean position [m]."""
        return self.z[self.first : self.first + self.ring_cells + 1]

    @property
    def part_bounds(self) -> NDArray[np.float64]:
        """z of the part boundaries at the mean position, low end first [m]."""
        edges = np.concatenate([[0], np.cumsum(self.part_cells)])
        return self.z[self.first] + edges * self.dz

    @property
    def part_of_cell(self) -> NDArray[np.int64]:
        """Part index of each ring cell."""
        return np.repeat(np.arange(len(self.part_cells)), self.part_cells)

    @property
    def half_stroke_cells(self) -> int:
        """Largest stroke offset (cells)."""
        return int(np.max(np.abs(self.shifts)))

    def coverage(
        self, zq: NDArray[np.float64], weights: NDArray[np.float64] | None = None
    ) -> NDArray[np.float64]:
        """Fraction of time the nut assembly covers the shaft surface at ``zq`` [-]."""
        w = self.weights if weights is None else weights
        lo = self.z[self.first] + self.shifts * self.dz
        hi = lo + self.ring_cells * self.dz
        zq = np.asarray(zq, dtype=float)
        inside = (zq[..., None] > lo) & (zq[..., None] < hi)
        return inside.astype(float) @ w


def _ring_spacing(lengths: list[float], size: float) -> tuple[int, NDArray[np.int64]] | None:
    """Ring cells n and part boundary indices: the n ≥ L/size that best fits every part (None
    when no n up to 2 L/size gives every part a cell)."""
    total = sum(lengths)
    cum = np.cumsum(lengths)
    n0 = max(len(lengths), math.ceil(total / size - 1e-9))
    best: tuple[float, int, NDArray[np.int64]] | None = None
    for n in range(n0, 2 * n0 + 1):
        idx = np.rint(cum / (total / n)).astype(np.int64)
        if np.any(np.diff(np.concatenate([[0], idx])) < 1):
            continue
        err = float(np.max(np.abs(idx * total / n - cum)))
        if best is None or err < best[0] - 1e-12 * total:
            best = (err, n, idx)
        if err <= 1e-9 * total:
            break
    return None if best is None else (best[1], best[2])


def _uniform(a: float, b: float, size: float) -> NDArray[np.float64]:
    """Grid lines from a to b (both included), spacing ≤ size."""
    n = max(1, math.ceil((b - a) / size - 1e-9))
    return np.linspace(a, b, n + 1)


def axial_grid(problem: ThermalProblem, size: float) -> AxialGrid:
    """Axial grid with spacing ≤ ``size``: uniform over the nut's swept range, parts on lines.

    Part boundaries are snapped to the uniform ring spacing (the spacing is chosen to fit them;
    the error is reported by :attr:`AxialGrid.part_bounds`). The stroke is sampled at every
    multiple of ``dz`` with trapezoidal weights (uniform time in each position: constant feed
    speed, reversal time neglected).
    """
    if not size > 0.0:
        raise InputError("mesh.size", size, "a length > 0 m")
    lengths = [p.length for p in problem.parts]
    spacing = _ring_spacing(lengths, size)
    if spacing is None:  # a part far shorter than a cell; one cell long always fits
        short = min(problem.parts, key=lambda part: part.length)
        field = "thermal.nut_length" if short.balls else "thermal.spacer_length"
        cell = f"at least one axial cell of the thermal model's mesh ({size:g} m, [thermal.mesh])"
        raise InputError(field, short.length, cell if short.balls else f"0 (none) or {cell}")
    n_ring, idx = spacing
    dz = problem.ring_length / n_ring
    m_max = round(0.5 * problem.stroke / dz)
    lo = problem.ring_centre - 0.5 * problem.ring_length - m_max * dz
    hi = lo + (n_ring + 2 * m_max) * dz
    length = problem.shaft_length
    tol = 1e-9 * length
    if lo < -tol or hi > length + tol:
        raise InputError(
            "stroke", problem.stroke, "a stroke that keeps the nut assembly on the shaft"
        )
    mid = lo + dz * np.arange(n_ring + 2 * m_max + 1)
    parts = [mid]
    if lo > tol:
        parts.insert(0, _uniform(0.0, lo, size)[:-1])
    else:
        mid[0] = 0.0
    if hi < length - tol:
        parts.append(_uniform(hi, length, size)[1:])
    else:
        mid[-1] = length
    z = np.concatenate(parts)
    first = (len(parts[0]) if lo > tol else 0) + m_max
    shifts = np.arange(-m_max, m_max + 1)
    weights = np.ones(shifts.size)
    if m_max > 0:
        weights[[0, -1]] = 0.5
    weights /= weights.sum()
    cells = tuple(int(c) for c in np.diff(np.concatenate([[0], idx])))
    return AxialGrid(z, dz, int(first), cells, shifts, weights)


def stroke_offset(time: float, grid: AxialGrid, speed: float) -> int:
    """Nut offset (cells) at ``time`` for a triangle-wave stroke at ``speed`` [m/s].

    The nut starts at its mean position moving towards +z, turns at ±half stroke.
    """
    m = grid.half_stroke_cells
    if m == 0 or speed <= 0.0:
        return 0
    amplitude = m * grid.dz
    period = 4.0 * amplitude / speed
    phase = ((time / period + 0.25) % 1.0) * 4.0  # 0..4, 1 = mean position going +z
    position = (phase - 1.0) if phase <= 2.0 else (3.0 - phase)
    return int(np.rint(position * m))
