"""The load programme and the options of a wear run, as plain SI values."""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["RunningIn", "WearLevel", "WearOptions"]


@dataclass(frozen=True)
class WearLevel:
    """One level of the programme: a constant axial load and speed for some revolutions.

    The lubricant state of the level (its operating point) is optional: None keeps the run's
    own viscosity and the ``[wear]`` stroke.
    """

    axial_load: float
    """External axial load F_a [N], signed: ≥ 0 loads nut 1, < 0 (a reverse duty segment) nut 2."""
    speed: float
    """Screw speed ω_s [rad/s]."""
    revolutions: float
    """Screw revolutions of the level [-]."""
    viscosity: float | None = None
    """η₀ at the level's contact temperature [Pa s]; None = the run's viscosity."""
    pressure_viscosity: float | None = None
    """α_p at the level's contact temperature [1/Pa]; None = the run's value."""
    stroke: float | None = None
    """Stroke S of the level [m] (sets L_w, (E8.3)); None = :attr:`WearOptions.stroke`."""
    temperature: float | None = None
    """Contact temperature of the level's operating point [K] (reported only)."""
    segments: tuple[WearLevel, ...] = ()
    """A duty cycle run over and over for ``revolutions``: the level wears at the
    revolution-weighted mean of its segments' rates per revolution (each segment at its own
    speed, load, stroke and lubricant state; valid while one cycle wears much less than
    ``max_depth_step``). Empty: the level runs at its own speed and load."""

    def parts(self) -> tuple[tuple[float, WearLevel], ...]:
        """(share of the revolutions, level) of each constant part: the segments or itself."""
        if not self.segments:
            return ((1.0, self),)
        total = sum(seg.revolutions for seg in self.segments)
        return tuple((seg.revolutions / total, seg) for seg in self.segments)


@dataclass(frozen=True)
class RunningIn:
    """Initial (as-machined) raceway surface and the worn depth over which it runs in.

    Exponential approach of each surface parameter to its steady (run-in) value with the worn
    depth h of the flank (the transient law of Queener, Smith & Mitchell 1965, applied to the
    fractal parameters, which settle during running-in (Ge & Chen 1999)):

        D(h) = D_ss + (D_0 − D_ss) e^(−h/h_r),   ln G(h) = ln G_ss + (ln G_0 − ln G_ss) e^(−h/h_r)
    """

    D: float
    """Initial profile fractal dimension D_0 (1 < D_0 < 2) [-]."""
    G: float
    """Initial fractal roughness G_0 [m]."""
    depth: float
    """Running-in depth h_r [m]."""

    def surface(self, D_ss: float, G_ss: float, depth: float) -> tuple[float, float]:
        """(D, G) after the worn depth ``depth`` [m], given the steady (D_ss, G_ss)."""
        weight = math.exp(-max(depth, 0.0) / self.depth)
        d = D_ss + (self.D - D_ss) * weight
        g = math.exp(math.log(G_ss) + (math.log(self.G) - math.log(G_ss)) * weight)
        return d, g


@dataclass(frozen=True)
class WearOptions:
    """Wear law, load programme and integration settings of a wear run (SI)."""

    model: str
    """Registered wear law (``ballscrew.wear.WEAR_LAWS``)."""
    coefficient: float
    """Wear coefficient K [-]."""
    stroke: float
    """Reciprocating stroke S of the nut [m]."""
    max_depth_step: float
    """Largest growth of h_max per time step [m]."""
    torque_sampling: float
    """Screw revolutions between drag-torque samples [-]."""
    torque_scale: float
    """Factor on the catalogue drag-torque coefficient [-]."""
    initial_torque: float | None
    """Measured drag torque at N = 0 [N m]; None = use ``torque_scale``."""
    programme: tuple[WearLevel, ...]
    grid: tuple[int, int]
    """Contact-grid cells (along the rolling direction, across the groove)."""
    box_factor: float
    """Grid half-widths / Hertz semi-axes at the largest ball load [-]."""
    checkpoint_every: int
    """Time steps between checkpoint saves."""
    film_factor: float = 1.0
    """Supply factor φ on the EHL film, h = φ h_flooded (1: fully flooded) [-]."""
    running_in: RunningIn | None = None
    """Initial surface and running-in depth; None: one surface throughout."""
    load_classes: int = 3
    """Ball-load classes per nut of the elastic distribution (:mod:`.load_classes`) [-]."""
    torque_offset: float = 0.0
    """Preload-independent drag torque T_0 added to (E9.1) [N m]."""
    asperity_roughness: str = "film"
    """σ of the asperities of the JGP load sharing (``ballscrew.wear.step.ASPERITY_HEIGHTS``):
    "film" σ_Λ of the film parameter, "cell" the micro-contact cell's."""
    preload_contact: str = "hertz"
    """Screw contact of the preload update (``ballscrew.wear.preload.PRELOAD_CONTACTS``)."""
