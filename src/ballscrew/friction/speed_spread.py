"""Contact forces of a ball train whose loaded balls want different orbital speeds.

A loaded ball rolling without slip between the raceways has a free speed v_i that depends on
its contact angle β_i and radius r_b,i (the closure (E2.4) of :mod:`ballscrew.kinematics.motion`
with e_A = −e_B):

    v_i = (ω_s/2) (r_m/cosλ − r_b,i cosβ_i cosλ).

Balls of a circuit are not caged and cannot pass each other: a ball forced to move at u_i ≠ v_i
creeps at the screw contact A (the nut contact B neither spins nor slips, and its linear creep
stiffness is orders of magnitude higher, so B keeps rolling); with B rolling the creep at A is
2(u_i − v_i), and the moment balance about the ball centre gives B the same tangential force as A,
so the raceways drive the ball along the track with

    T_i = clip(k_i (v_i − u_i), −c_i, c_i),   k_i = 6 μ Q_i/(|ω_sp| b_i),   c_i = 2 μ Q_i.

k_i is four times the creep stiffness of a contact whose slip field is dominated by spin about
its centre, (3/2) μ Q/(ω_sp b) (Coulomb traction μ p along the local slip; the creep u tilts the
slip direction by u x/(ω_sp r²) and the force ∫ μ p x²/r³ dA u/ω_sp ≈ (3/2) μ Q u/(ω_sp b) for an
ellipse long across the track, b its semi-axis across: full Coulomb slip about the spin pole,
theory manual *Friction*, (F5g)); c_i is the whole contact sliding one way. Between the two the
law is taken as linear up to the cap (ASSUMED; the exact Coulomb curve bends smoothly from
slope k to c). The spin and the speeds scale with ω_s, so the forces do not depend on it
except through μ.

With C_i ≥ 0 the force at the contact ahead of ball i (ball i + 1 is ahead), each ball balances
C_(i−1) + T_i = C_i, C_0 = 0, and C_n = R, the push the leading ball hands to the balls in the
return (:func:`ballscrew.friction.ball_train.return_resistance`). Contacts are unilateral:
C_i ≥ 0, u_i ≤ u_(i+1) and C_i (u_(i+1) − u_i) = 0. This complementarity problem is the
optimality condition of the isotonic regression

    min Σ φ_i(u_i) + R u_n   subject to   u_1 ≤ u_2 ≤ … ≤ u_n,   φ_i' = −T_i,

(C_i its Lagrange multipliers), solved exactly by pool-adjacent-violators (Ayer et al. 1955;
Best & Chakravarti 1990 for convex separable losses): a group of touching balls moves at the
speed u where its drives balance, Σ T_j(u) = R (only for the group with the leading ball),
which is the k-weighted mean speed while no ball saturates. A faster ball behind a slower
group closes up and joins it; a faster ball ahead separates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError

__all__ = [
    "NutBalls",
    "TrainSpread",
    "circuit_trains",
    "creep_stiffness",
    "free_speed",
    "group_speed",
    "spread_forces",
    "traction_capacity",
]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class TrainSpread:
    """The loaded balls of one circuit in the direction of travel (SI; any common speed unit)."""

    speeds: FloatArray
    """v_i, free speed of each ball along the track [m/s]."""
    stiffness: FloatArray
    """k_i, drive of the raceways per speed mismatch [N s/m] (0: an unloaded ball)."""
    capacity: FloatArray
    """c_i, the largest drive of the raceways [N]."""


def free_speed(
    pitch_radius: float,
    lead_angle: float,
    ball_radius: ArrayLike,
    contact_angle: ArrayLike,
    screw_speed: float = 1.0,
) -> FloatArray:
    """v = (ω_s/2)(r_m/cosλ − r_b cosβ cosλ) [m/s], the rolling closure (E2.4) per ball.

    ``ball_radius`` r_b and ``contact_angle`` β broadcast (one per ball); ``screw_speed`` 1 gives
    the speed per unit screw speed [m/rad].
    """
    cos_l = math.cos(lead_angle)
    r_b = np.asarray(ball_radius, dtype=float)
    beta = np.asarray(contact_angle, dtype=float)
    return 0.5 * screw_speed * (pitch_radius / cos_l - r_b * np.cos(beta) * cos_l)


def creep_stiffness(
    friction: float, loads: ArrayLike, spin: float, semi_axis: ArrayLike
) -> FloatArray:
    """k = 6 μ Q/(|ω_sp| b) [N s/m]: the drive of the raceways on a ball per speed mismatch.

    ``friction`` μ of the traction law at A, ``loads`` Q [N], ``spin`` ω_sp at A [rad/s] (the
    same unit of time as the speeds), ``semi_axis`` b across the track [m] (0 for an unloaded
    ball: k = 0).
    """
    omega = abs(float(spin))
    if not omega > 0.0:
        raise InputError("spin", spin, "!= 0 rad/s: the creep law needs spin at A (β > 0)")
    q = np.maximum(np.asarray(loads, dtype=float), 0.0)
    b = np.asarray(semi_axis, dtype=float)
    safe = np.where(q > 0.0, b, 1.0)
    return np.where(q > 0.0, 6.0 * friction * q / (omega * safe), 0.0)


def traction_capacity(friction: float, loads: ArrayLike) -> FloatArray:
    """c = 2 μ Q [N]: both contacts of a ball sliding one way (equal forces at A and B)."""
    return 2.0 * friction * np.maximum(np.asarray(loads, dtype=float), 0.0)


def _drives(
    speeds: FloatArray, stiffness: FloatArray, capacity: FloatArray, u: ArrayLike
) -> FloatArray:
    """T_i = clip(k_i (v_i − u), −c_i, c_i) [N], u broadcast against the balls."""
    return np.clip(stiffness * (speeds - np.asarray(u)), -capacity, capacity)


def group_speed(
    speeds: FloatArray, stiffness: FloatArray, capacity: FloatArray, push: float = 0.0
) -> float:
    """The speed u of a group of touching balls: Σ T_i(u) = R, exactly.

    Σ T_i(u) is piecewise linear and falling between the breakpoints v_i ± c_i/k_i, so u lies
    between the two breakpoints that bracket R (the k-weighted mean speed,
    less R/Σk, while no ball saturates); between them the saturated balls are known and u solves
    the linear balance of the others. A group without load moves at its mean free speed.
    """
    loaded = stiffness > 0.0
    if not np.any(loaded):
        return float(np.mean(speeds))
    total = float(np.sum(capacity))
    if not total > push:
        raise InputError(
            "friction.return_fraction",
            "a return push of " + f"{push:.3g} N",
            f"< the traction capacity {total:.3g} N of the balls pushing it",
        )
    v, k, c = speeds[loaded], stiffness[loaded], capacity[loaded]
    points = np.sort(np.concatenate([v - c / k, v + c / k]))
    excess = _drives(v, k, c, points[:, None]).sum(axis=1) - push  # falls from Σc − R to −Σc − R
    j = int(np.flatnonzero(excess >= 0.0)[-1])
    # between the bracketing breakpoints the saturated balls are fixed: solve the linear part
    mid = 0.5 * (points[j] + points[j + 1])
    free = np.abs(v - mid) * k < c
    held = np.sum(np.where(free, 0.0, np.sign(v - mid) * c))
    return float((np.sum(k[free] * v[free]) + held - push) / np.sum(k[free]))


def spread_forces(train: TrainSpread, push: float = 0.0) -> tuple[FloatArray, FloatArray]:
    """Contact forces C_i ahead of each ball [N] and the ball speeds u_i of one circuit.

    Pool-adjacent-violators on a stack of groups: one Python pass over the balls, each merge
    solving its group with :func:`group_speed` (vectorised over the group); a circuit holds tens
    of balls. ``push`` R ≥ 0 acts ahead of the leading ball (C_n = R).
    """
    v, k, c = train.speeds, train.stiffness, train.capacity
    n = v.size
    starts: list[int] = []
    values: list[float] = []
    for i in range(n):
        start, lead = i, push if i == n - 1 else 0.0
        value = group_speed(v[i : i + 1], k[i : i + 1], c[i : i + 1], lead)
        while values and values[-1] > value:  # the group behind is faster: it closes up
            start = starts.pop()
            values.pop()
            value = group_speed(v[start : i + 1], k[start : i + 1], c[start : i + 1], lead)
        starts.append(start)
        values.append(value)
    sizes = np.diff([*starts, n])
    u = np.repeat(values, sizes)
    total = np.cumsum(_drives(v, k, c, u))  # C_i = C_(i−1) + T_i
    behind = np.concatenate([[0.0], total[np.asarray(starts[1:], dtype=int) - 1]])
    forces = total - np.repeat(behind, sizes)  # summed within each group of touching balls
    ends = np.cumsum(sizes) - 1
    forces[ends] = 0.0  # the contact ahead of a group is open: its drives balance
    forces[-1] = push  # the leading group's drives balance the return
    return np.maximum(forces, 0.0), u  # rounding below 0 inside a group


@dataclass(frozen=True)
class NutBalls:
    """Per-ball state of one nut along its balls, from the load distribution (SI)."""

    loads: FloatArray
    """Normal ball load Q_i [N]."""
    angles: FloatArray
    """Contact angle β_i under load [rad]."""
    diameter_excess: FloatArray
    """Ball-diameter excess Δd_i over the nominal diameter [m]."""


def circuit_trains(
    speeds: FloatArray, stiffness: FloatArray, capacity: FloatArray, circuits: int
) -> tuple[TrainSpread, ...]:
    """The balls of a nut (in their order along the nut) split into ``circuits`` runs of
    consecutive balls, each run in both directions of travel (the screw turned both ways)."""
    runs = np.array_split(np.arange(speeds.size), circuits)
    return tuple(
        TrainSpread(speeds[run][::sense], stiffness[run][::sense], capacity[run][::sense])
        for run in runs
        if run.size
        for sense in (1, -1)
    )
