"""Film parameter Λ and asperity share ψ of each part of a wear programme.

The wear laws act on the asperity-borne load only, ψQ (Johnson, Greenwood & Poon 1972); a part
whose EHL film carries practically all of the load wears practically nothing. This module gives,
per programme level (and per duty segment), the film parameter Λ = h/σ and ψ of the mean ball of
the more loaded nut at the start of the run (unworn raceway, Hertz ellipse as the nominal area
A_n = π a b), so that a report can say why a level wears nothing.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

from ballscrew.contact import hertz
from ballscrew.lubrication import share_load
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.setup import WearSetup, nut_force_pair
from ballscrew.wear.step import entrainment_speed

__all__ = [
    "FULL_FILM_SHARE",
    "FullFilmWarning",
    "PartFilm",
    "full_film_messages",
    "part_films",
    "warn_full_film",
]

FULL_FILM_SHARE = 1e-3
"""Asperity share ψ below which a part is said to wear practically nothing (GUESS: its wear
rate is then below 0.1 % of that of a boundary-lubricated contact, ψ = 1)."""

_RPM = math.pi / 30.0


class FullFilmWarning(UserWarning):
    """A programme part wears practically nothing: the EHL film separates the surfaces."""


@dataclass(frozen=True)
class PartFilm:
    """Film state of one constant part of a programme level (SI)."""

    level: int
    """Index of the level (0-based)."""
    segment: int | None
    """Index of the duty segment within the level; None for a level of its own."""
    speed: float
    """Screw speed ω [rad/s]."""
    axial_load: float
    """Axial load F_a [N]."""
    ball_load: float
    """Mean ball load Q of the more loaded nut [N]."""
    film_parameter: float | None
    """Λ = h/σ: mean-plane separation h under the film-borne load over the raceway's RMS
    roughness σ; None when dry or at rest."""
    asperity_share: float
    """ψ = F_asp/Q ∈ [0, 1] (1: dry, at rest or boundary lubrication)."""

    @property
    def name(self) -> str:
        """'level k' or 'level k, segment j' (1-based)."""
        text = f"level {self.level + 1}"
        return text if self.segment is None else f"{text}, segment {self.segment + 1}"


def _part_film(setup: WearSetup, index: int, segment: int | None, part: WearLevel) -> PartFilm:
    force = max(nut_force_pair(setup.initial_preload, part.axial_load))
    load = setup.ball_load(force)
    eta, alpha = setup.lubricant(part)
    speed = entrainment_speed(setup.geometry, part.speed)
    film, psi = None, 1.0
    if eta is not None and alpha is not None and speed != 0.0 and load > 0.0:
        contact = hertz(setup.rx, setup.ry, setup.e_star, load)
        surface = setup.surface_at(0.0)
        sharing = share_load(
            load,
            setup.rx,
            setup.ry,
            eta,
            alpha,
            abs(speed),
            math.pi * contact.a * contact.b,
            surface,
            film_model=setup.film_model,
            film_factor=setup.spec.film_factor,
        )
        film, psi = sharing.separation / surface.rms_height, sharing.psi
    return PartFilm(index, segment, part.speed, part.axial_load, load, film, psi)


def part_films(setup: WearSetup, programme: tuple[WearLevel, ...]) -> tuple[PartFilm, ...]:
    """Λ and ψ of every constant part of ``programme`` (see the module docstring)."""
    return tuple(
        _part_film(setup, i, j if level.segments else None, part)
        for i, level in enumerate(programme)
        for j, (_, part) in enumerate(level.parts())
    )


def full_film_messages(films: tuple[PartFilm, ...]) -> list[str]:
    """One line per part whose asperity share is below :data:`FULL_FILM_SHARE`."""
    return [
        f"{f.name} ({f.speed / _RPM:.4g} rpm, {f.axial_load:.4g} N) wears practically nothing: "
        f"the EHL film (Λ = {f.film_parameter:.3g}) carries all but ψ = {f.asperity_share:.2g} "
        "of the ball load, and the wear law acts on the asperity-borne load ψQ only"
        for f in films
        if f.asperity_share < FULL_FILM_SHARE and f.film_parameter is not None
    ]


def warn_full_film(films: tuple[PartFilm, ...]) -> None:
    """Issue :func:`full_film_messages` as :class:`FullFilmWarning`."""
    for text in full_film_messages(films):
        warnings.warn(text, FullFilmWarning, stacklevel=3)
