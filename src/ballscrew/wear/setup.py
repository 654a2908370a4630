"""What stays fixed during a wear run: grid, gaps, surface, compliance and torque factor (SI)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from ballscrew.fractal.conventions import profile_roughness_from_surface
from ballscrew.geometry import ScrewGeometry
from ballscrew.loads import ball_load, nut_forces, preload_after_wear, preload_drag_torque
from ballscrew.lubrication import AsperitySurface, composite_roughness
from ballscrew.lubrication.film import FilmModel
from ballscrew.wear.load_classes import UNIFORM, LoadClasses
from ballscrew.wear.programme import WearLevel, WearOptions
from ballscrew.wear.strips import working_raceway_length

__all__ = ["FLANKS", "FilmRoughness", "WearSetup", "nut_force_pair"]

FloatArray = NDArray[np.float64]
FLANKS: tuple[int, int] = (1, -1)
"""The two flanks of the screw groove: +1 loaded by nut 1, −1 by nut 2 (the two loaded flanks
of a preloaded single nut)."""


@dataclass(frozen=True)
class FilmRoughness:
    """How the composite roughness σ_Λ of the film parameter (E6.6) follows the raceway's
    profile (D, G) as it runs in.

    The profile model's σ_Λ is Σ(D, G) = √(σ_F3(D, G_p)² + σ_b²): (F3) over the measurement band
    [l_c, L_u] (:func:`~ballscrew.lubrication.composite_roughness`) of the profile G_p with the
    RMS height of the 3-D surface (D + 1, G)
    (:func:`~ballscrew.fractal.conventions.profile_roughness_from_surface`) and a rough ball's
    σ_b over the same band in quadrature (Tallian 1967). A measured σ_Λ belongs to the ``[surface]``
    (D_ss, G_ss) (the run-in raceway when running-in is given, ASSUMED) and runs in by the
    profile model's ratio: σ_Λ(h) = σ_meas Σ(D(h), G(h))/Σ(D_ss, G_ss), D(h), G(h) of the
    running-in law (:class:`~ballscrew.wear.programme.RunningIn`).
    """

    band: tuple[float, float]
    """(L_u, l_c) of the roughness measurement [m]."""
    ball: float = 0.0
    """σ_b of a rough ball over the band [m] (0: smooth)."""
    measured: float | None = None
    """Measured σ_Λ of the ``[surface]`` raceway [m]; None: the profile model's."""

    def sigma(self, D: float, G: float, steady: tuple[float, float], gamma: float = 1.5) -> float:
        """σ_Λ [m] of the surface of profile dimension D and surface roughness G [m] (3-D
        Yan–Komvopoulos); ``steady``: the (D_ss, G_ss) of a measured σ."""
        model = math.hypot(self._profile_sigma(D, G, gamma), self.ball)
        if self.measured is None:
            return model
        reference = self._profile_sigma(*steady, gamma)
        return self.measured * model / math.hypot(reference, self.ball)

    def _profile_sigma(self, D: float, G: float, gamma: float) -> float:
        """(F3) over the band of the profile with the RMS height of the surface (D + 1, G)."""
        g = profile_roughness_from_surface(D, G, gamma)
        return composite_roughness(D, g, *self.band, gamma=gamma)


@dataclass(frozen=True)
class WearSetup:
    """Everything fixed during a wear run (SI)."""

    geometry: ScrewGeometry
    spec: WearOptions
    balls: int
    """Balls Z on each loaded flank: per nut of a double nut, all of a four-point nut, half of
    an offset-lead nut."""
    e_star: float
    hardness: float
    surface: AsperitySurface
    """Rough screw raceway; ``cell_area`` is the grid cell ΔA (σ from E5.3 with L_s = √ΔA)."""
    viscosity: float | None
    pressure_viscosity: float | None
    rx: float
    ry: float
    x: FloatArray
    y: FloatArray
    dx: float
    dy: float
    nominal_gap: dict[int, FloatArray]
    compliance: float
    """C_a of (E1.8) [m N^(−2/3)]."""
    raceway_length: float
    """L_w of (E8.3) [m]."""
    initial_preload: float
    torque_factor: float
    """Factor on the catalogue torque of (E9.1) (torque_scale or the initial-torque fit)."""
    tolerance: float
    max_iterations: int
    film_roughness: FilmRoughness
    """σ_Λ of the film parameter as the surface runs in (used with ``spec.running_in``)."""
    film_model: str | FilmModel = "hamrock_dowson"
    """Film-thickness model: a registered name (``ballscrew.lubrication.FILM_MODELS``) or that
    model corrected for the supply state and inlet heating (``ballscrew.lubrication.supply``)."""
    entrainment: str = "rolling"
    """Entrainment-speed rule of the film (``ballscrew.kinematics.motion.ENTRAINMENT_RULES``)."""
    body_compliance: float = 0.0
    """c_b of shaft and nut body in the preload loop, per nut [m/N] (0: rigid bodies)."""
    ball_classes: tuple[tuple[float, tuple[LoadClasses, LoadClasses]], ...] = ()
    """Per axial load of the programme, the ball-load classes of nut 1 and nut 2 (elastic
    distribution at the initial preload); empty or an absent load: every ball the mean load."""
    torque_offset: float = 0.0
    """Preload-independent drag torque T_0 (seals, wipers, grease churning) [N m]."""

    @property
    def cell_area(self) -> float:
        return self.dx * self.dy

    @property
    def lubricated(self) -> bool:
        return self.viscosity is not None and self.pressure_viscosity is not None

    def surface_at(self, depth: float) -> AsperitySurface:
        """The raceway surface after the worn depth ``depth`` [m] (running-in, if any): its
        (D, G) and its σ_Λ (:class:`FilmRoughness`, a measured one included)."""
        law = self.spec.running_in
        if law is None:
            return self.surface
        s = self.surface
        steady = (s.Ds - 1.0, s.G)
        d, g = law.surface(*steady, depth)
        roughness = self.film_roughness.sigma(d, g, steady, s.gamma)
        return replace(s, Ds=d + 1.0, G=g, roughness=roughness)

    def lubricant(self, level: WearLevel | None) -> tuple[float | None, float | None]:
        """(η₀, α_p) of ``level``'s operating point, or the run's own values."""
        if level is None or level.viscosity is None or not self.lubricated:
            return self.viscosity, self.pressure_viscosity
        alpha = level.pressure_viscosity
        return level.viscosity, self.pressure_viscosity if alpha is None else alpha

    def raceway_length_of(self, level: WearLevel | None) -> float:
        """L_w (E8.3) of ``level``'s stroke, or of the ``[wear]`` stroke [m]."""
        if level is None or level.stroke is None or level.stroke == self.spec.stroke:
            return self.raceway_length
        g = self.geometry
        return working_raceway_length(
            level.stroke, g.lead, g.pitch_radius, g.ball_radius, g.contact_angle
        )

    def load_classes(self, axial_load: float, nut: int) -> LoadClasses:
        """The ball-load classes of ``nut`` (1 or 2) at ``axial_load`` [N]."""
        for load, classes in self.ball_classes:
            if load == axial_load:
                return classes[nut - 1]
        return UNIFORM

    def preload(self, max_depth: float) -> float:
        """F_p after wear h_max (E1.13), contacts and bodies in series [N]."""
        g = self.geometry
        return float(
            preload_after_wear(
                self.initial_preload,
                self.compliance,
                max_depth,
                g.contact_angle,
                g.lead_angle,
                self.body_compliance,
            )
        )

    def torque(self, preload: float) -> float:
        """Drag torque T = f · K_T F_p L/(2π) + T_0 (E9.1, E9.3, E9.4) [N m]."""
        g = self.geometry
        drag = self.torque_factor * preload_drag_torque(preload, g.lead, g.lead_angle)
        return drag + self.torque_offset

    def ball_load(self, nut_force: float) -> float:
        """Q = F/(Z sinβ cosλ) (E1.6) [N]."""
        g = self.geometry
        return float(ball_load(nut_force, self.balls, g.contact_angle, g.lead_angle))


def nut_force_pair(preload: float, axial_load: float) -> tuple[float, float]:
    """(F_1, F_2) of nut 1 and nut 2 of the double nut, or of the two flanks of a preloaded
    single nut (E1.10–E1.11); without preload F_1 = F_a, F_2 = 0.

    ``axial_load`` is signed: F_a ≥ 0 presses on nut 1; F_a < 0, the reverse direction, presses
    on nut 2, which then carries the larger force of |F_a| (the pair swapped).
    """
    load = abs(float(axial_load))
    if preload <= 0.0:
        pair = (load, 0.0)
    else:
        f = nut_forces(preload, load)
        pair = (float(f[0]), float(f[1]))
    return pair if axial_load >= 0.0 else pair[::-1]
