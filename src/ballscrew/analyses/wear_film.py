"""Film parameter Λ and asperity share ψ of each part of a wear programme.

The wear laws act on the asperity-borne load only, ψQ (Johnson, Greenwood & Poon 1972); a part
whose EHL film carries practically all of the load wears practically nothing. This module gives,
per programme level (and per duty segment), for the mean ball of the more loaded nut at the start
of the level, so that a report can say why a level wears nothing:

* the film parameter Λ = h_c/σ_Λ (E6.6; :func:`ballscrew.lubrication.film_parameter`) of the
  operating point and the ball model: the central film of the whole ball load (times
  ``wear.film_factor``) over the composite roughness σ_Λ of the raceway (after running-in, if
  any), and its regime (Hamrock 1994);
* the wear engine's own asperity share ψ and its mean-plane separation h (the film of the
  film-borne load), on the asperity heights of ``wear.asperity_roughness``: the cell-scale
  micro-contact of the wear grid (σ of one cell, E5.3, "cell") or σ_Λ ("film").

Both come from one contact of :func:`ballscrew.wear.step.step_rates` each, on the raceway worn by
the earlier levels, under the preload left at the level's start and with the solved contact's
loaded cells as the nominal area A_n. Under the uniform ball-load distribution that is the ψ the
engine applies at the level's first step (to the contact solver's tolerance); under load classes
it is that of the class of the mean load.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ballscrew.lubrication import film_parameter, regime
from ballscrew.wear.history import WearLife
from ballscrew.wear.programme import WearLevel
from ballscrew.wear.setup import FLANKS, WearSetup, nut_force_pair
from ballscrew.wear.step import StepContact, step_rates

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
    film_thickness: float | None
    """Central EHL film h_c of the whole ball load Q, times ``wear.film_factor`` [m]; None
    when dry or at rest."""
    film_roughness: float
    """Composite RMS roughness σ_Λ (E6.6) of the raceway at the level's start [m]."""
    asperity_share: float
    """ψ = F_asp/Q ∈ [0, 1] of the wear engine (1: dry, at rest or boundary lubrication)."""
    separation: float | None = None
    """Mean-plane separation h of the wear engine's load sharing: the film of the film-borne
    load (1 − ψ)Q [m]; None when dry or at rest."""

    @property
    def film_parameter(self) -> float | None:
        """Λ = h_c/σ_Λ (E6.6), the operating point's film parameter; None when dry or at
        rest."""
        if self.film_thickness is None:
            return None
        return film_parameter(self.film_thickness, self.film_roughness)

    @property
    def regime(self) -> str | None:
        """Lubrication regime of :attr:`film_parameter` (boundary, mixed, EHL); None when dry
        or at rest."""
        lam = self.film_parameter
        return None if lam is None else regime(lam)

    @property
    def name(self) -> str:
        """'level k' or 'level k, segment j' (1-based)."""
        text = f"level {self.level + 1}"
        return text if self.segment is None else f"{text}, segment {self.segment + 1}"


def part_films(
    setup: WearSetup, programme: tuple[WearLevel, ...], life: WearLife | None = None
) -> tuple[PartFilm, ...]:
    """Λ, ψ and h of every constant part of ``programme`` (the module docstring), all its
    contacts solved in one :func:`~ballscrew.wear.step.step_rates` batch.

    ``life``: the run whose raceway and preload each level starts from (the levels it has not
    reached are left out); None: every level on the unworn raceway at the initial preload.
    """
    starts = _level_starts(setup, life, len(programme))
    parts = [
        (i, j if level.segments else None, part)
        for i, level in enumerate(programme)
        if i in starts
        for j, (_, part) in enumerate(level.parts())
    ]
    contacts: dict[int, StepContact] = {}
    for k, (i, _, part) in enumerate(parts):
        preload, depth = starts[i]
        forces = nut_force_pair(preload, part.axial_load)
        nut = int(forces[1] > forces[0])  # the more loaded nut: its flank is FLANKS[nut]
        if forces[nut] > 0.0:  # an unloaded part: no contact, ψ = 1
            contacts[k] = StepContact(FLANKS[nut], forces[nut], part.speed, depth[nut], level=part)
    rates = dict(zip(contacts, step_rates(setup, list(contacts.values())), strict=True))
    return tuple(
        PartFilm(
            i, j, part.speed, part.axial_load, rates[k].load, rates[k].film_thickness,
            rates[k].film_roughness, rates[k].psi, rates[k].separation,
        )
        if k in rates
        else PartFilm(i, j, part.speed, part.axial_load, 0.0, None, math.nan, 1.0)
        for k, (i, j, part) in enumerate(parts)
    )  # fmt: skip


def _level_starts(
    setup: WearSetup, life: WearLife | None, levels: int
) -> dict[int, tuple[float, np.ndarray]]:
    """{level: (preload [N], worn depth of both flanks (2, ny) [m])} at the start of each level
    ``life`` has reached: its last record before the level (its first record for level 1)."""
    if life is None:
        return dict.fromkeys(range(levels), (setup.initial_preload, np.zeros((2, setup.y.size))))
    reached = np.asarray(life.level)
    out = {}
    for k in range(levels):
        if not np.any(reached >= k):
            break
        earlier = np.flatnonzero(reached < k)
        index = int(earlier[-1]) if earlier.size else 0
        out[k] = (float(life.preload[index]), np.asarray(life.profiles[index]))
    return out


def full_film_messages(films: tuple[PartFilm, ...]) -> list[str]:
    """One line per part whose asperity share is below :data:`FULL_FILM_SHARE`."""
    return [
        f"{f.name} ({f.speed / _RPM:.4g} rpm, {f.axial_load:.4g} N) wears practically nothing: "
        f"the EHL film (Λ = {f.film_parameter:.3g}) carries all but ψ = {f.asperity_share:.2g} "
        "of the ball load on the wear engine's asperities, and the wear law acts on "
        "the asperity-borne load ψQ only"
        for f in films
        if f.asperity_share < FULL_FILM_SHARE and f.film_parameter is not None
    ]


def warn_full_film(films: tuple[PartFilm, ...]) -> None:
    """Issue :func:`full_film_messages` as :class:`FullFilmWarning`."""
    for text in full_film_messages(films):
        warnings.warn(text, FullFilmWarning, stacklevel=3)
