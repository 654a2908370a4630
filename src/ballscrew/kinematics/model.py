"""Parameters of the ball model of one case: geometry, elastic constants, lubricant, roughness.

Built once per case by ``ballscrew.analyses.kinematics.ball_model``; every solver of the
package takes it. Hertz
quantities at load Q are scaled from the unit-load solution (a, b ∝ Q^(1/3), δ ∝ Q^(2/3)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ballscrew.contact import hertz
from ballscrew.contact.hertz import HertzContact
from ballscrew.geometry import RacewayCurvature, ScrewGeometry, raceway_curvature
from ballscrew.geometry.screw import SIDES, Side
from ballscrew.kinematics.frames import BallFrame, ball_frame
from ballscrew.kinematics.inertia import ball_inertia, ball_mass
from ballscrew.kinematics.motion import BallMotion
from ballscrew.kinematics.sliding import deformed_radius
from ballscrew.lubrication import (
    AsperitySurface,
    FilmThickness,
    LoadSharing,
    ehl_rolling_resistance,
    share_load,
)
from ballscrew.lubrication.film import FilmModel, film_function

__all__ = ["BallModel"]

#: Load sharings kept per model (the oldest dropped first): the few contacts of one solve.
_SHARINGS_KEPT = 16


@dataclass(frozen=True)
class BallModel:
    """Everything the ball balance needs about one screw (SI)."""

    geometry: ScrewGeometry
    balls: int
    """Loaded balls per nut Z."""
    ball_density: float
    e_star_screw: float
    e_star_nut: float
    surface: AsperitySurface
    """Rough screw raceway at A (3-D fractal, Ds = D + 1); the load sharing reads its asperity
    heights at the film parameter's σ_Λ (:attr:`AsperitySurface.film_heights`)."""
    viscosity: float | None = None
    """η₀ [Pa s]; None = no lubricant data (dry contacts)."""
    pressure_viscosity: float | None = None
    """α_p [1/Pa]."""
    boundary_friction: float = 0.1
    limiting_shear: float = 0.07
    traction_cells: int = 32
    traction_law: str = "film"
    """Registered traction law (``ballscrew.kinematics.traction_laws.TRACTION_LAWS``)."""
    lubricant_density: float = 870.0
    """ρ [kg/m³] for the kinematic viscosity ν = η₀/ρ of the ``skf`` traction law (GUESS: a
    mineral oil near 40 °C, the density the friction model takes without a named lubricant)."""
    entrainment: str = "rolling"
    """Rule for the entrainment speed u_e (``ballscrew.kinematics.motion.ENTRAINMENT_RULES``)."""
    film_model: str | FilmModel = "hamrock_dowson"
    """Registered film-thickness model (``ballscrew.lubrication.FILM_MODELS``), or one bound to
    the supply state (``ballscrew.lubrication.supply``)."""

    @property
    def lubricated(self) -> bool:
        """True when η₀ and α_p are both known."""
        return self.viscosity is not None and self.pressure_viscosity is not None

    @cached_property
    def frame(self) -> BallFrame:
        return ball_frame(self.geometry)

    @cached_property
    def mass(self) -> float:
        return ball_mass(self.geometry.ball_diameter, self.ball_density)

    @cached_property
    def inertia(self) -> float:
        return ball_inertia(self.geometry.ball_diameter, self.ball_density)

    def curvature(self, contact: Side) -> RacewayCurvature:
        """Exact gap curvatures (G15)–(G17) at A or B (nominal contact angle)."""
        return self._curvatures[contact]

    @cached_property
    def _curvatures(self) -> dict[str, RacewayCurvature]:
        return {c: raceway_curvature(self.geometry, c) for c in SIDES}

    def e_star(self, contact: Side) -> float:
        return self.e_star_screw if contact == "screw" else self.e_star_nut

    @cached_property
    def _unit_hertz(self) -> dict[str, HertzContact]:
        return {
            c: hertz(self.curvature(c).rx, self.curvature(c).ry, self.e_star(c), 1.0) for c in SIDES
        }

    def hertz_constant(self, contact: Side) -> float:
        """K of the Hertz approach δ = K Q^(2/3), m N^(−2/3) (1.513e-7 at A, reference screw)."""
        return self._unit_hertz[contact].approach

    def hertz_semi_axes(self, contact: Side, load: ArrayLike) -> tuple[Any, Any]:
        """Hertz semi-axes (along x = t, along y = across the groove) at load Q [m]: a, b ∝
        Q^(1/3) from the unit-load solution; floats for a float load, arrays for an array."""
        unit = self._unit_hertz[contact]
        scale = np.maximum(load, 0.0) ** (1.0 / 3.0)
        if np.ndim(scale) == 0:
            return unit.a * float(scale), unit.b * float(scale)
        return unit.a * scale, unit.b * scale

    def deformed_radius(self, contact: Side = "screw") -> float:
        """Harris R_d = 2 r_g r_b/(r_g + r_b) of the contact surface across the groove [m]."""
        return deformed_radius(self.geometry.groove_radius(contact), self.geometry.ball_radius)

    def entrainment_speed(self, motion: BallMotion, contact: Side = "screw") -> float:
        """u_e of ``contact`` for ``motion`` by the model's entrainment rule (E2.8) [m/s]."""
        return motion.entrainment(contact, self.entrainment)

    def film(self, load: float, speed: float, contact: Side = "screw") -> FilmThickness | None:
        """EHL film carrying the whole load (None without lubricant or motion)."""
        if not self.lubricated or speed == 0.0 or load <= 0.0:
            return None
        return film_function(self.film_model)(*self._ehl_inputs(load, speed, contact))

    def sharing(self, load: float, speed: float, contact: Side = "screw") -> LoadSharing:
        """JGP asperity share ψ(Λ) of ``contact`` (E6.4) on the asperity heights of the film
        parameter's composite roughness σ_Λ (E6.6), the one σ of Λ; dry (ψ = 1) without
        lubricant or entrainment."""
        if not self.lubricated or speed == 0.0:
            return LoadSharing(1.0, float(load), 0.0, None)
        key = (float(load), abs(float(speed)), contact)
        known = self._sharings.get(key)
        if known is None:
            if len(self._sharings) >= _SHARINGS_KEPT:
                self._sharings.pop(next(iter(self._sharings)))
            known = self._sharings[key] = self._share(*key)
        return known

    @cached_property
    def _sharings(self) -> dict[tuple[float, float, str], LoadSharing]:
        """The load sharings solved on this model by (Q, |u_e|, contact): the flanks of a
        preloaded nut solve the same contact at the same load and speed (mirror images)."""
        return {}

    def _share(self, load: float, speed: float, contact: Side) -> LoadSharing:
        """:func:`~ballscrew.lubrication.share_load` of ``contact`` at Q and u_e ≥ 0."""
        c = self.curvature(contact)
        a, b = self.hertz_semi_axes(contact, load)
        return share_load(
            load,
            c.rx,
            c.ry,
            self.viscosity,
            self.pressure_viscosity,
            speed,
            math.pi * a * b,
            self.surface.film_heights,
            film_model=self.film_model,
        )

    def rolling_resistance(self, load: float, speed: float, contact: Side) -> float:
        """EHL rolling-resistance magnitude F_R (E3.4) [N]; 0 without lubricant or motion."""
        if not self.lubricated or speed == 0.0 or load <= 0.0:
            return 0.0
        return ehl_rolling_resistance(*self._ehl_inputs(load, speed, contact))

    def _ehl_inputs(
        self, load: float, speed: float, contact: Side
    ) -> tuple[float, float, float, float, float, float, float]:
        """(R_x, R_y, E′ = 2E*, η₀, α_p, u_e, Q) of contact ``contact``: the inputs of a
        film model (E6.1) and of the rolling resistance (E3.4)."""
        c = self.curvature(contact)
        return (
            c.rx,
            c.ry,
            2.0 * self.e_star(contact),
            self.viscosity,
            self.pressure_viscosity,
            abs(speed),
            load,
        )
