"""Steady state and transient from ambient of a discrete thermal model, with energy bookkeeping.

The steady state is that of the time-averaged stroke (for a resolved stroke it is the mean of
the periodic state). The transient is implicit Euler at a constant step from θ = 0, with the
time-averaged operator (factorised once) or the nut offset of each step (``resolved``).
"""

from __future__ import annotations

import time as _time
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ballscrew.budget import check_count, check_memory
from ballscrew.errors import InputError
from ballscrew.progress import advance
from ballscrew.thermal.discretisation import Discretisation
from ballscrew.thermal.problem import stroke_offset
from ballscrew.thermal.timestepping import StepSystem, implicit_euler, solve_steady


@dataclass(frozen=True)
class Transient:
    """Histories of the transient from ambient (index 0 is t = 0)."""

    time: NDArray[np.float64]
    """Times [s]."""
    max_rise: NDArray[np.float64]
    """Largest temperature rise [K]."""
    elongation: NDArray[np.float64]
    """Thermal elongation α∫θ̄ dz of the shaft [m]."""
    sensors: NDArray[np.float64]
    """Sensor rises (time, sensor) [K]."""
    axis: NDArray[np.float64]
    """Shaft cross-section mean rise (time, axial station) [K]."""
    snapshot_times: NDArray[np.float64]
    """Times of the stored full fields [s]."""
    snapshots: NDArray[np.float64]
    """Full solution vectors (snapshot, unknown) [K]."""
    offset: NDArray[np.int64]
    """Nut stroke offset of each step (cells; zeros for a time-averaged stroke)."""
    heat_in: float
    """∫ Q dt [J]."""
    stored: float
    """Heat stored at the end, 1ᵀCθ [J]."""
    convected: float
    """∫ convective loss dt [J]."""

    @property
    def heat_balance_error(self) -> float:
        """|heat in − stored − convected| / |heat in| [-] (heat in < 0: a coolant below ambient)."""
        if self.heat_in == 0.0:
            return 0.0
        return abs(self.heat_in - self.stored - self.convected) / abs(self.heat_in)


@dataclass(frozen=True)
class Solution:
    """Steady state and (optionally) transient of one discrete model."""

    discretisation: Discretisation
    steady: NDArray[np.float64]
    """Steady temperature rise of every unknown [K]."""
    heat_input: float
    """Heat entering [W]."""
    heat_loss: float
    """Steady convective loss [W]."""
    transient: Transient | None
    seconds: dict[str, float] = field(default_factory=dict)
    """Wall-clock seconds of 'assembly', 'steady' and 'transient'."""

    @property
    def max_temperature_rise(self) -> float:
        """Largest steady temperature rise [K]."""
        return float(np.max(self.steady))

    @property
    def elongation(self) -> float:
        """Steady thermal elongation of the shaft ΔL = α∫θ̄ dz (Q7) [m]."""
        return float(self.discretisation.elongation @ self.steady)

    @property
    def heat_balance_error(self) -> float:
        """|heat in − loss| / |heat in| in steady state [-] (loss: convection and coolant
        outflow; heat in includes a coolant's inlet enthalpy, negative below ambient)."""
        if self.heat_input == 0.0:
            return abs(self.heat_loss)
        return abs(self.heat_input - self.heat_loss) / abs(self.heat_input)

    @property
    def sensors(self) -> NDArray[np.float64]:
        """Steady sensor rises [K]."""
        return self.discretisation.sensors @ self.steady

    @property
    def axis(self) -> NDArray[np.float64]:
        """Steady cross-section mean rise of the shaft along ``axis_z`` [K]."""
        return self.discretisation.axis @ self.steady


def time_to_fraction(
    time: NDArray[np.float64], series: NDArray[np.float64], final: float, fraction: float = 0.95
) -> float:
    """First time the series reaches ``fraction``·``final`` (linear between steps) [s].

    NaN when it is not reached within the record, 0 when ``final`` is not a rise.
    """
    if not final > 0.0:
        return 0.0
    target = fraction * final
    above = np.nonzero(np.asarray(series) >= target)[0]
    if above.size == 0:
        return float("nan")
    k = int(above[0])
    if k == 0:
        return float(time[0])
    t0, t1, y0, y1 = time[k - 1], time[k], series[k - 1], series[k]
    return float(t0 + (target - y0) * (t1 - t0) / (y1 - y0))


def simulate(
    disc: Discretisation,
    duration: float | None = 5400.0,
    time_step: float = 60.0,
    snapshots: int = 10,
    stroke_mode: str = "averaged",
    feed_speed: float = 0.0,
    steady: NDArray[np.float64] | None = None,
) -> Solution:
    """Steady state and, unless ``duration`` is None, the transient of ``disc``.

    ``steady``: the steady rise of ``disc`` already solved (a coupled operating point's last
    field): taken as it is instead of solving A θ = f again (a full AMG solve on the 3-D model).
    """
    if stroke_mode not in ("averaged", "resolved"):
        raise InputError("stroke.mode", stroke_mode, "'averaged' or 'resolved'")
    seconds: dict[str, float] = {}
    advance("thermal steady state", 0, 1)
    t0 = _time.perf_counter()
    grid = disc.grid
    averaged = disc.assemble(grid.weights)
    seconds["assembly"] = _time.perf_counter() - t0
    t0 = _time.perf_counter()
    a, f = averaged
    if steady is None:
        steady = solve_steady(a, f, disc.direct_limit)
    loss = float(np.asarray(a.sum(axis=0)).ravel() @ steady)
    seconds["steady"] = _time.perf_counter() - t0
    advance("thermal steady state", 1, 1)
    transient = None
    if duration is not None:
        t0 = _time.perf_counter()
        transient = _march(disc, averaged, duration, time_step, snapshots, stroke_mode, feed_speed)
        seconds["transient"] = _time.perf_counter() - t0
    return Solution(disc, steady, float(np.sum(f)), loss, transient, seconds)


def check_transient(disc: Discretisation | None, duration: float, time_step: float) -> None:
    """Refuse a transient with too many time steps or (with ``disc``) too large a history."""
    steps = duration / time_step
    key = "thermal.transient.time_step"
    check_count(key, time_step, steps, f"time steps over the duration {duration:g} s")
    if disc is None:
        return
    per_step = 8.0 * (disc.axis.shape[0] + disc.sensors.shape[0] + 4)
    check_memory(key, time_step, steps * per_step, f"the history of {steps:.3g} time steps")


def _march(
    disc: Discretisation,
    averaged: tuple,
    duration: float,
    time_step: float,
    snapshots: int,
    stroke_mode: str,
    feed_speed: float,
) -> Transient:
    if not (duration > 0.0 and 0.0 < time_step <= duration):
        raise InputError("thermal.transient.time_step", time_step, f"a step in (0, {duration:g}] s")
    check_transient(disc, duration, time_step)
    steps = max(1, round(duration / time_step))
    dt = duration / steps
    grid = disc.grid
    resolved = stroke_mode == "resolved" and grid.half_stroke_cells > 0
    offsets = np.zeros(steps + 1, dtype=np.int64)
    if resolved:
        offsets[1:] = [stroke_offset(n * dt, grid, feed_speed) for n in range(1, steps + 1)]
    index = {int(m): k for k, m in enumerate(grid.shifts)}

    def system(n: int) -> StepSystem:
        if not resolved:
            return StepSystem("averaged", *averaged)
        weights = np.zeros(grid.shifts.size)
        weights[index[int(offsets[n])]] = 1.0
        return StepSystem(int(offsets[n]), *disc.assemble(weights))

    n_out = steps + 1
    max_rise = np.zeros(n_out)
    elongation = np.zeros(n_out)
    sensors = np.zeros((n_out, disc.sensors.shape[0]))
    axis = np.zeros((n_out, disc.axis.shape[0]))
    snap_steps = np.unique(np.linspace(0, steps, min(snapshots, steps) + 1).round().astype(int))
    snap_index = {int(s): k for k, s in enumerate(snap_steps)}
    snaps = np.zeros((snap_steps.size, disc.unknowns))

    def observe(n: int, theta: NDArray[np.float64], loss: float) -> None:
        advance("thermal transient", n, steps)
        max_rise[n] = theta.max()
        elongation[n] = disc.elongation @ theta
        sensors[n] = disc.sensors @ theta
        axis[n] = disc.axis @ theta
        if n in snap_index:
            snaps[snap_index[n]] = theta

    cache = max(4, min(256, 1_000_000 // disc.unknowns))  # LU factors kept for a resolved stroke
    final, heat_in, convected = implicit_euler(
        disc.capacity, dt, steps, system, observe, cache_size=cache, direct_limit=disc.direct_limit
    )
    stored = float(np.asarray(disc.capacity.sum(axis=0)).ravel() @ final)
    return Transient(
        time=dt * np.arange(n_out),
        max_rise=max_rise,
        elongation=elongation,
        sensors=sensors,
        axis=axis,
        snapshot_times=dt * snap_steps,
        snapshots=snaps,
        offset=offsets,
        heat_in=heat_in,
        stored=stored,
        convected=convected,
    )
