"""One contact of a wear step: pressure, asperity share, sliding and the wear-depth rate.

The contacts of one flank within a step (the nuts and the ball-load classes of each) share the
worn gap and the fixed grid and differ only in load: :func:`flank_rates` solves them together
(:func:`ballscrew.contact.solve_normal_batch`; each result equals its own single solve).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ballscrew.contact import ContactResult, solve_normal, solve_normal_batch
from ballscrew.geometry import ScrewGeometry
from ballscrew.kinematics.sliding import sliding_field_closed_form
from ballscrew.lubrication import share_load
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.rates import cell_wear_rate
from ballscrew.wear.setup import FloatArray, WearSetup
from ballscrew.wear.strips import depth_per_revolution, raceway_depth_rate, strip_wear_speed

__all__ = ["FlankRate", "GridEdgeWarning", "entrainment_speed", "flank_rate", "flank_rates"]


class GridEdgeWarning(UserWarning):
    """The (worn) contact touches the edge of the fixed grid: the box is too small."""


@dataclass(frozen=True)
class FlankRate:
    """Wear of one flank under one nut force: the contact chain of one ball."""

    load: float
    """Ball load Q [N]."""
    pressure: FloatArray
    """Pressure p [Pa] on the grid."""
    psi: float
    """Asperity share ψ (E6.4)."""
    cell_rate: FloatArray
    """Cell wear rates w [m/s]."""
    depth_per_revolution: FloatArray
    """Δh_j per screw revolution if this force acted all the time [m/rev]."""
    iterations: int


def entrainment_speed(geometry: ScrewGeometry, screw_speed: float) -> float:
    """u_e = V = (ω_s/2)(r_m/cosλ − r_b cosβ cosλ), (E2.4), (E2.8), m/s (REF 100 rpm: 0.09333)."""
    lam, beta = geometry.lead_angle, geometry.contact_angle
    return (
        0.5
        * screw_speed
        * (
            geometry.pitch_radius / math.cos(lam)
            - geometry.ball_radius * math.cos(beta) * math.cos(lam)
        )
    )


def flank_rate(
    setup: WearSetup,
    flank: int,
    nut_force: float,
    screw_speed: float,
    depth: FloatArray,
    initial: FloatArray | None = None,
    level: WearLevel | None = None,
    load_ratio: float = 1.0,
) -> FlankRate:
    """Wear-depth rate across the groove of ``flank`` under one nut force (the inner loop).

    ``level`` gives the lubricant state and stroke of the running programme level (None: the
    run's own); the surface is that after the flank's largest worn depth (running-in). Every ball
    carries ``load_ratio`` times the nut's mean ball load (a load class of the elastic
    distribution; 1: the uniform distribution).
    """
    q = load_ratio * setup.ball_load(nut_force)
    gap = worn_gap(setup.nominal_gap[flank], depth)
    sol = solve_normal(
        gap,
        setup.dx,
        setup.dy,
        setup.e_star,
        q,
        setup.tolerance,
        max_iterations=setup.max_iterations,
        initial=initial,
    )
    return _rate(setup, flank, q, sol, screw_speed, depth, level)


def _solve_together(
    setup: WearSetup, gap: FloatArray, loads: list[float], initial: list[FloatArray | None]
) -> list[ContactResult]:
    """The contacts of ``loads`` on one gap: one batched solve for those with a warm start and
    one for those without (a batch takes a start for all or none)."""
    out: list[ContactResult | None] = [None] * len(loads)
    for warm in (True, False):
        group = [i for i, p in enumerate(initial) if (p is not None) == warm]
        if not group:
            continue
        stack = np.broadcast_to(gap, (len(group), *gap.shape)).copy()
        starts = np.stack([initial[i] for i in group]) if warm else None
        solved = solve_normal_batch(
            stack,
            setup.dx,
            setup.dy,
            setup.e_star,
            np.array([loads[i] for i in group]),
            setup.tolerance,
            max_iterations=setup.max_iterations,
            initial=starts,
        )
        for i, sol in zip(group, solved, strict=True):
            out[i] = sol
    return [sol for sol in out if sol is not None]


def flank_rates(
    setup: WearSetup,
    flank: int,
    contacts: Sequence[tuple[float, float]],
    screw_speed: float,
    depth: FloatArray,
    initial: Sequence[FloatArray | None],
    level: WearLevel | None = None,
) -> tuple[FlankRate, ...]:
    """:func:`flank_rate` of several (nut force, load ratio) ``contacts`` of one flank, their
    contacts solved together (batched FFTs); ``initial`` gives each one's warm start or None."""
    loads = [ratio * setup.ball_load(force) for force, ratio in contacts]
    gap = worn_gap(setup.nominal_gap[flank], depth)
    solved = _solve_together(setup, gap, loads, list(initial))
    return tuple(
        _rate(setup, flank, q, sol, screw_speed, depth, level)
        for q, sol in zip(loads, solved, strict=True)
    )


def _rate(
    setup: WearSetup,
    flank: int,
    q: float,
    sol: ContactResult,
    screw_speed: float,
    depth: FloatArray,
    level: WearLevel | None,
) -> FlankRate:
    """Asperity share, sliding, cell wear and raceway depth rate of one solved contact."""
    p = np.asarray(sol.pressure, dtype=float)
    if p[[0, -1], :].any() or p[:, [0, -1]].any():
        warnings.warn(
            f"the contact at Q = {q:.4g} N reaches the edge of the fixed wear grid; "
            "increase wear.box_factor",
            GridEdgeWarning,
            stacklevel=2,
        )
    cell = setup.cell_area
    surface = setup.surface_at(float(np.max(depth)))
    eta, alpha = setup.lubricant(level)
    if eta is not None and alpha is not None:
        area = float(np.count_nonzero(p > 0.0)) * cell
        psi = share_load(
            q,
            setup.rx,
            setup.ry,
            eta,
            alpha,
            entrainment_speed(setup.geometry, screw_speed),
            area,
            surface,
            film_model=setup.film_model,
            film_factor=setup.spec.film_factor,
        ).psi
    else:
        psi = 1.0
    speed = sliding_field_closed_form(
        setup.geometry, screw_speed, setup.x, setup.y, flank, curvature=True
    ).speed
    s = surface
    w = cell_wear_rate(
        setup.spec.model,
        psi * p,
        speed,
        cell,
        s.Ds,
        s.G,
        s.e_star,
        s.hardness,
        setup.spec.coefficient,
        s.gamma,
    )
    rate = raceway_depth_rate(
        strip_wear_speed(w, setup.dx), setup.balls, setup.raceway_length_of(level)
    )
    return FlankRate(q, p, float(psi), w, depth_per_revolution(rate, screw_speed), sol.iterations)
