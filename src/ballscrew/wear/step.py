"""One contact of a wear step: pressure, asperity share, sliding and the wear-depth rate.

All contacts of a wear step (both flanks, both nuts, the ball-load classes of each, the segments
of a duty cycle) share the fixed grid and differ only in gap and load: :func:`step_rates` solves
them in one :func:`ballscrew.contact.solve_normal_batch` call (each result equals its own single
solve); :func:`flank_rate` is one contact of it.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ballscrew.budget import check_memory, contact_batch_bytes
from ballscrew.contact import ContactResult, solve_normal_batch
from ballscrew.kinematics.motion import entrainment_speed
from ballscrew.kinematics.sliding import sliding_field_closed_form
from ballscrew.lubrication import AsperitySurface, film_parameter, share_loads
from ballscrew.lubrication.film import film_function
from ballscrew.registry import Registry
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.rates import cell_wear_rate
from ballscrew.wear.setup import FloatArray, WearSetup
from ballscrew.wear.strips import depth_per_revolution, raceway_depth_rate, strip_wear_speed

__all__ = [
    "ASPERITY_HEIGHTS",
    "FlankRate",
    "GridEdgeWarning",
    "StepContact",
    "entrainment_speed",
    "flank_rate",
    "step_rates",
    "warn_at_grid_edge",
]


ASPERITY_HEIGHTS: Registry[Callable[[AsperitySurface], AsperitySurface]] = Registry(
    "asperity heights of the wear load sharing", "wear.asperity_roughness"
)
"""Which RMS height σ the asperities of the JGP load sharing (E6.3)–(E6.4) of the wear engine
have; the wear law's micro-contact (E7.2)–(E7.3) stays at the cell scale under either."""


@ASPERITY_HEIGHTS.register(
    "film", "σ_Λ of the film parameter (E6.6), the combined roughness the ball model uses"
)
def film_heights(surface: AsperitySurface) -> AsperitySurface:
    """The surface with σ = σ_Λ (:attr:`AsperitySurface.film_heights`): Johnson, Greenwood &
    Poon (1972) on the Greenwood–Williamson heights of the combined roughness of both surfaces
    (Greenwood & Tripp 1970), the σ of Λ = h/σ_Λ that the friction and kinematics models share."""
    return surface.film_heights


@ASPERITY_HEIGHTS.register(
    "cell", "σ of one wear-grid cell (E5.3, L_s = √ΔA): the fractal wear model's own convention"
)
def cell_heights(surface: AsperitySurface) -> AsperitySurface:
    """The surface as it is: the bearing ratio (E5.15) on σ of the micro-contact cell (E5.3
    with the sampling length L_s = √ΔA), the convention of the 3-D fractal wear model, whose
    asperities of one cell carry the asperity share."""
    return surface


class GridEdgeWarning(UserWarning):
    """The (worn) contact touches the edge of the fixed grid: the box is too small."""


def warn_at_grid_edge(pressure: FloatArray, load: float, what: str = "the contact") -> None:
    """Warn (:class:`GridEdgeWarning`) when ``pressure`` is nonzero on a boundary cell of the
    fixed wear grid: the contact there would be clipped by the box."""
    if pressure[[0, -1], :].any() or pressure[:, [0, -1]].any():
        warnings.warn(
            f"{what} at Q = {load:.4g} N reaches the edge of the fixed wear grid; "
            "increase wear.box_factor",
            GridEdgeWarning,
            stacklevel=3,
        )


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
    film_thickness: float | None = None
    """Central EHL film h_c of the whole ball load Q (times ``wear.film_factor``) [m]; None when
    dry or at rest."""
    film_roughness: float = math.nan
    """Composite RMS roughness σ_Λ (E6.6) of the flank's surface at its worn depth [m]."""
    separation: float | None = None
    """Mean-plane separation h = φ h_c((1 − ψ)Q) of the engine's load sharing (E6.4): the film
    of the film-borne load, whose asperities (``wear.asperity_roughness``) carry ψQ [m]; None when
    dry or at rest."""

    @property
    def film_parameter(self) -> float | None:
        """Film parameter Λ = h_c/σ_Λ (E6.6) of the whole ball load, the operating point's;
        None when dry or at rest."""
        if self.film_thickness is None:
            return None
        return film_parameter(self.film_thickness, self.film_roughness)


@dataclass(frozen=True)
class StepContact:
    """One ball contact of a wear step: which flank, worn how far, under which nut force."""

    flank: int
    """Screw flank s = ±1."""
    nut_force: float
    """Nut force F [N]; the ball carries ``load_ratio`` Q(F) (E1.6)."""
    speed: float
    """Screw speed ω_s [rad/s]."""
    depth: FloatArray
    """Worn depth h(y) of the flank [m]."""
    initial: FloatArray | None = None
    """Warm-start pressure [Pa] or None (the solver's nested-grid start)."""
    level: WearLevel | None = None
    """Programme level (lubricant state, stroke); None: the run's own."""
    load_ratio: float = 1.0
    """Ball load over the nut's mean ball load (a load class; 1: uniform)."""


class _Film(NamedTuple):
    """Asperity share ψ, central film h_c of the whole load and separation h of one contact."""

    psi: float
    central: float | None
    separation: float | None


def step_rates(setup: WearSetup, contacts: Sequence[StepContact]) -> tuple[FlankRate, ...]:
    """:class:`FlankRate` of every contact of a wear step, all solved in one batch.

    The contacts (both flanks, both nuts, the load classes, the duty segments, worn or unworn
    gaps) share the fixed grid, dx, dy and E* and differ in gap and load, so their pressures
    come from one :func:`~ballscrew.contact.solve_normal_batch` call (batched FFTs; each result
    equals its own single solve). A batch takes a warm start for all its contacts or for none:
    contacts with and without one are two calls. The batch's memory is checked against the
    budget first (``wear.grid``).
    """
    nx, ny = setup.x.size, setup.y.size
    check_memory(
        "wear.grid",
        [nx, ny],
        contact_batch_bytes(len(contacts), nx, ny),
        f"{len(contacts)} contacts of a wear step on the {nx} × {ny} grid",
    )
    loads = [c.load_ratio * setup.ball_load(c.nut_force) for c in contacts]
    gaps = [worn_gap(setup.nominal_gap[c.flank], c.depth) for c in contacts]
    solved: dict[int, ContactResult] = {}
    for warm in (True, False):
        group = [i for i, c in enumerate(contacts) if (c.initial is not None) == warm]
        if not group:
            continue
        starts = [contacts[i].initial for i in group] if warm else None
        results = solve_normal_batch(
            np.stack([gaps[i] for i in group]),
            setup.dx,
            setup.dy,
            setup.e_star,
            np.array([loads[i] for i in group]),
            setup.tolerance,
            max_iterations=setup.max_iterations,
            initial=None if starts is None else np.stack(starts),
        )
        solved.update(zip(group, results, strict=True))
    films = _asperity_shares(setup, contacts, loads, [solved[i] for i in range(len(contacts))])
    return tuple(
        _rate(setup, c.flank, q, solved[i], c.speed, c.depth, c.level, films[i])
        for i, (c, q) in enumerate(zip(contacts, loads, strict=True))
    )


def _asperity_shares(
    setup: WearSetup,
    contacts: Sequence[StepContact],
    loads: Sequence[float],
    solved: Sequence[ContactResult],
) -> list[_Film]:
    """JGP asperity share ψ (E6.4) of each contact, A_n its loaded cells, with its separation h,
    the central film h_c of its whole load and σ_Λ; the contacts on one surface, lubricant and
    speed are solved together (:func:`share_loads`) on the asperity heights of
    ``wear.asperity_roughness`` (:data:`ASPERITY_HEIGHTS`); dry or at rest: ψ = 1 and no film."""
    heights = ASPERITY_HEIGHTS[setup.spec.asperity_roughness]
    groups: dict[tuple[object, ...], list[int]] = {}
    for i, c in enumerate(contacts):
        eta, alpha = setup.lubricant(c.level)
        if eta is not None and alpha is not None:
            surface = setup.surface_at(float(np.max(c.depth)))
            key = (
                surface,
                eta,
                alpha,
                entrainment_speed(setup.geometry, c.speed, setup.entrainment),
            )
            groups.setdefault(key, []).append(i)
    films = [_Film(1.0, None, None) for _ in contacts]
    factor = setup.spec.film_factor
    film = film_function(setup.film_model)
    for (surface, eta, alpha, speed), group in groups.items():
        shares = share_loads(
            [loads[i] for i in group],
            setup.rx,
            setup.ry,
            eta,
            alpha,
            speed,
            [_loaded_area(setup, solved[i]) for i in group],
            heights(surface),
            film_model=setup.film_model,
            film_factor=factor,
        )
        args = (setup.rx, setup.ry, 2.0 * surface.e_star, eta, alpha, abs(speed))
        for i, share in zip(group, shares, strict=True):
            if share.film is not None:
                whole = factor * film(*args, loads[i]).central
                films[i] = _Film(share.psi, whole, share.separation)
            else:
                films[i] = _Film(share.psi, None, None)
    return films


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
    distribution; 1: the uniform distribution). One contact of :func:`step_rates`.
    """
    contact = StepContact(flank, nut_force, screw_speed, depth, initial, level, load_ratio)
    return step_rates(setup, [contact])[0]


def _rate(
    setup: WearSetup,
    flank: int,
    q: float,
    sol: ContactResult,
    screw_speed: float,
    depth: FloatArray,
    level: WearLevel | None,
    film: _Film,
) -> FlankRate:
    """Sliding, cell wear and raceway depth rate of one solved contact of film state ``film``."""
    p = np.asarray(sol.pressure, dtype=float)
    warn_at_grid_edge(p, q)
    cell = setup.cell_area
    surface = setup.surface_at(float(np.max(depth)))
    speed = sliding_field_closed_form(
        setup.geometry, screw_speed, setup.x, setup.y, flank, curvature=True
    ).speed
    s = surface
    w = cell_wear_rate(
        setup.spec.model,
        film.psi * p,
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
    per_rev = depth_per_revolution(rate, screw_speed)
    return FlankRate(
        q,
        p,
        float(film.psi),
        w,
        per_rev,
        sol.iterations,
        film.central,
        surface.film_roughness,
        film.separation,
    )


def _loaded_area(setup: WearSetup, sol: ContactResult) -> float:
    """Nominal area A_n of a solved contact: its loaded cells [m²]."""
    return float(np.count_nonzero(np.asarray(sol.pressure) > 0.0)) * setup.cell_area
