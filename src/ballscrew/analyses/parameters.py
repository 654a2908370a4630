"""The physical parameters of one case, built once: :class:`ScrewParameters`.

Every analysis starts here. A validated :class:`~ballscrew.case.Case` holds what the user wrote;
:class:`ScrewParameters` holds what the physics needs, derived once and in one place: the screw
geometry, the composite moduli E* of the ball against each raceway, the hardness, the fractal
roughness, the lubricant (the ``[medium]`` values completed by a named lubricant of the library
at ``[lubrication] temperature``, its film bound to the ``[lubrication]`` supply state), and the
nuts with their axial forces and loaded flanks. The physics packages never see the case; they take
these numbers and small frozen dataclasses.

The nut forces of a spacer-preloaded double nut follow from equal Hertz deflection of the two
nuts, F1^(2/3) + F2^(2/3) = 2 F_p^(2/3) with F1 − F2 = F_a (Hertz point contacts, rigid bodies;
lift-off of nut 2 at F_a = 2^(3/2) F_p), see the theory manual, *Loads*. A single nut preloaded
by oversized balls (four-point contact) or by an offset lead loads both flanks the same way
(:mod:`ballscrew.loads.preload_method`); a single nut without preload carries F_a on one flank.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ballscrew.analyses.roughness import profile_roughness, surface_roughness
from ballscrew.case import Case
from ballscrew.contact.elastic import composite_modulus
from ballscrew.contact.hertz import hertz
from ballscrew.geometry import ScrewGeometry, raceway_curvature
from ballscrew.geometry.screw import SIDES, Side
from ballscrew.kinematics.motion import entrainment_speed
from ballscrew.loads import Flanks, ball_load, flank_forces, nut_axial_compliance, preload_flanks
from ballscrew.lubrication.film import FilmModel
from ballscrew.lubrication.lubricant_library import (
    LibraryLubricant,
    LubricantState,
    library_lubricant,
)
from ballscrew.lubrication.supply import Replenishment, supplied_film_model
from ballscrew.materials import Material
from ballscrew.validation import case_with

__all__ = [
    "SIDES",
    "Lubrication",
    "Material",
    "NutLoad",
    "ScrewParameters",
    "Side",
    "film_model",
    "library_entry",
    "lubricant_state",
]


@dataclass(frozen=True)
class NutLoad:
    """One nut of the screw and the axial force it carries."""

    index: int
    """1 = the nut the axial load presses on, 2 = the one it unloads."""
    force: float
    """Axial force on the nut [N] (0 once lifted off)."""
    flank: int
    """Loaded flank of the groove: +1 for nut 1, −1 for nut 2."""
    ball_load: float
    """Normal load of each of its balls, Q = F/(Z sinβ cosα) [N]."""

    @property
    def loaded(self) -> bool:
        """True while the nut's balls touch both raceways."""
        return self.force > 0.0


@dataclass(frozen=True)
class Lubrication:
    """The interstitial medium and, where known, its EHL properties at the inlet."""

    name: str
    thermal_conductivity: float
    """λ_f of the medium between the asperities [W/(m K)]."""
    viscosity: float | None
    """Inlet dynamic viscosity η₀ [Pa s]; None = no lubricant data (dry contacts)."""
    pressure_viscosity: float | None
    """Barus coefficient α_p [1/Pa]; None = unknown."""
    film_model: str | FilmModel = "hamrock_dowson"
    """Registered EHL film-thickness model (``ballscrew.lubrication.FILM_MODELS``), or that
    model bound to the supply state and the inlet heating of ``[lubrication]``."""
    density: float = 870.0
    """ρ of the lubricant at the inlet [kg/m³] (the named lubricant's; 870 otherwise, ASSUMED
    paraffinic mineral oil)."""
    rarefaction: float = 0.0
    """Gas rarefaction parameter M of the medium across the gap [m] (0 for a liquid)."""

    @property
    def lubricated(self) -> bool:
        """True when η₀ and α_p are both known."""
        return self.viscosity is not None and self.pressure_viscosity is not None


def library_entry(case: Case) -> LibraryLubricant | None:
    """The case's lubricant with its laws against temperature: the library entry named by
    ``[medium] lubricant`` or ``[kinematics] lubricant``, or the oil given by ``[medium]``
    ν40 and ν100 (:meth:`~ballscrew.case.models.MediumSpec.oil_viscosities`) and ``density_15``;
    None without either."""
    medium = case.medium
    oil = medium.oil_viscosities()
    if oil is not None:
        return LibraryLubricant(
            medium.name,
            "oil",
            *oil,
            medium.density_15,
            "[medium] viscosity_40 or viscosity_grade, viscosity_100 or viscosity_index, "
            "density_15 of the case",
        )
    name = medium.lubricant or case.kinematics.lubricant
    return None if name is None else library_lubricant(name)


def lubricant_state(case: Case, viscosity: float | None = None) -> LubricantState | None:
    """The named lubricant at ``[lubrication] temperature``, or, for a given ``viscosity``
    [Pa s] when ``[medium]`` gives none, at the temperature where it has that viscosity
    (the caller's contact temperature); None without a named lubricant."""
    entry = library_entry(case)
    if entry is None:
        return None
    if viscosity is None or case.medium.viscosity is not None:
        return entry.at(case.lubrication.temperature)
    return entry.at(entry.temperature_at(viscosity))


def film_model(case: Case, named: LubricantState | None) -> str | FilmModel:
    """``medium.film_model`` bound to the supply state and inlet heating of ``[lubrication]``.

    The thermal correction takes β and λ of the named lubricant ``named``, or of ISO VG 68
    mineral oil at the inlet temperature when no lubricant is named (ASSUMED); the kinematic
    replenishment of a greased track takes ρ of ``named`` (870 kg/m³ otherwise, ASSUMED) and the
    screw speed per entrainment speed of ``[kinematics] entrainment``.
    """
    spec = case.lubrication
    thermal = None
    if spec.thermal:
        oil = named or library_lubricant("iso_vg_68").at(spec.temperature)
        thermal = (oil.temperature_viscosity, oil.conductivity)
    replenishment = track_replenishment(case, oil_density(named))
    return supplied_film_model(
        case.medium.film_model, spec.meniscus, thermal, replenishment, spec.layer
    )


def oil_density(named: LubricantState | None) -> float:
    """ρ of the lubricant at the inlet [kg/m³]: the named lubricant's, else 870 (ASSUMED,
    paraffinic mineral oil: the default of :attr:`Lubrication.density`)."""
    return Lubrication.density if named is None else named.density


def track_replenishment(case: Case, density: float) -> Replenishment | None:
    """The kinematic replenishment of a greased track with an oil of ``density`` [kg/m³]
    (None unless ``[lubrication]`` asks for it): the screw's d_m and D_w, and its speed per
    entrainment speed of ``[kinematics] entrainment`` (Level 0, u_e ∝ ω)."""
    if not case.lubrication.replenished:
        return None
    geometry = ScrewGeometry.from_spec(case.screw)
    return Replenishment(
        geometry.pitch_diameter,
        geometry.ball_diameter,
        density,
        1.0 / entrainment_speed(geometry, 1.0, case.kinematics.entrainment),
    )


@dataclass(frozen=True)
class ScrewParameters:
    """Everything the physics needs about the screw of one case, in SI units.

    Build it with :meth:`from_case`; :meth:`with_loads` gives the same screw at another preload
    or axial load (the nut forces are recomputed, nothing else).
    """

    name: str
    geometry: ScrewGeometry
    balls_per_nut: int
    nut_count: int
    """1 (single nut) or 2 (spacer-preloaded double nut)."""
    preload: float
    """Preload F_p [N]."""
    axial_load: float
    """External axial load F_a ≥ 0 [N]; it loads nut 1 and unloads nut 2."""
    speed: float
    """Screw speed ω [rad/s]."""
    ball: Material
    screw: Material
    nut: Material
    D: float
    """Profile fractal dimension of the raceways, 1 < D < 2."""
    G: float
    """Fractal roughness of the raceways, the Majumdar–Bhushan profile G [m] (TCR models, σ_Λ)."""
    G_surface: float
    """The same raceways' 3-D Yan–Komvopoulos surface G [m] (asperity load sharing, wear);
    both converted once from the case's ``surface.G_convention``."""
    smooth_ball: bool
    """True when the case gives no ball roughness."""
    lubrication: Lubrication
    nuts: tuple[NutLoad, ...]
    """Every nut of the screw, loaded or lifted off, nut 1 first; a single nut preloaded on
    both flanks appears once, with its loaded flank (flank 1)."""
    preload_method: str = "spacer"
    """spacer, oversized_balls or offset_lead (:mod:`ballscrew.loads.preload_method`)."""
    flank_loads: tuple[NutLoad, ...] = ()
    """Every loaded flank, flank 1 first: the nuts of a double nut; the two contact pairs of a
    four-point nut or the two halves of an offset-lead nut; the one flank of a single nut
    without preload."""

    @classmethod
    def from_case(cls, case: Case) -> ScrewParameters:
        """The parameters of a validated case."""
        case_with(case, "screw", "operating", "materials", "surface", "medium", "numerics")
        spec, op = case.screw, case.operating
        geometry = ScrewGeometry.from_spec(spec)
        medium = case.medium
        eta, alpha = medium.viscosity, medium.pressure_viscosity
        named = lubricant_state(case)
        if named is not None:
            eta = named.viscosity if eta is None else eta
            alpha = named.pressure_viscosity if alpha is None else alpha
        params = cls(
            name=case.name,
            geometry=geometry,
            balls_per_nut=spec.balls_per_nut,
            nut_count=spec.nuts,
            preload=op.preload,
            axial_load=op.axial_load,
            speed=op.speed,
            ball=Material(**case.materials.ball.properties),
            screw=Material(**case.materials.screw.properties),
            nut=Material(**case.materials.nut.properties),
            D=case.surface.D,
            G=profile_roughness(case, case.surface.D, case.surface.G),
            G_surface=surface_roughness(case, case.surface.D, case.surface.G),
            smooth_ball=case.surface.ball is None,
            lubrication=Lubrication(
                medium.name,
                medium.thermal_conductivity,
                eta,
                alpha,
                film_model(case, named),
                oil_density(named),
                medium.rarefaction,
            ),
            nuts=(),
            preload_method=spec.resolved_preload_method,
        )
        return params.with_loads()

    def with_loads(
        self, preload: float | None = None, axial_load: float | None = None
    ) -> ScrewParameters:
        """The same screw at ``preload`` and ``axial_load`` [N] (None = unchanged)."""
        fp = self.preload if preload is None else float(preload)
        fa = self.axial_load if axial_load is None else float(axial_load)
        flanks = preload_flanks(self.preload_method, self.nut_count, self.balls_per_nut, fp)
        forces = flank_forces(fp, fa, flanks.count)[: flanks.count]
        g = self.geometry
        loads = tuple(
            NutLoad(
                index=k,
                force=float(force),
                flank=1 if k == 1 else -1,
                ball_load=float(ball_load(force, flanks.balls, g.contact_angle, g.lead_angle))
                if force > 0.0
                else 0.0,
            )
            for k, force in enumerate(forces, start=1)
        )
        return dataclasses.replace(
            self, preload=fp, axial_load=fa, nuts=loads[: self.nut_count], flank_loads=loads
        )

    @property
    def flanks(self) -> Flanks:
        """The loaded flanks: how many, the balls on each, shared balls (four-point contact)."""
        return preload_flanks(self.preload_method, self.nut_count, self.balls_per_nut, self.preload)

    @property
    def nut_forces(self) -> tuple[float, float]:
        """(F1, F2): axial force on the loaded and the unloaded nut, or flank of a preloaded
        single nut [N] (F2 = 0 for a single nut without preload)."""
        forces = [n.force for n in self.flank_loads]
        return forces[0], forces[1] if len(forces) > 1 else 0.0

    @property
    def loaded_nut(self) -> NutLoad:
        """Nut 1, the one the axial load presses on."""
        return self.nuts[0]

    def material(self, side: Side) -> Material:
        """Material of the screw or the nut."""
        return self.screw if side == "screw" else self.nut

    def contact_modulus(self, side: Side) -> float:
        """Composite modulus E* of the ball against the ``side`` raceway [Pa].

        1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (Johnson 1985, §4.2).
        """
        race = self.material(side)
        return composite_modulus(
            self.ball.youngs_modulus,
            self.ball.poissons_ratio,
            race.youngs_modulus,
            race.poissons_ratio,
        )

    def hardness(self, side: Side) -> float:
        """Hardness of the softer of ball and ``side`` raceway [Pa]."""
        return min(self.ball.hardness, self.material(side).hardness)

    @property
    def hertz_constants(self) -> tuple[float, float]:
        """(K_A, K_B): Hertz constants δ = K Q^(2/3) of the ball–screw and ball–nut contacts
        [m N^(−2/3)]."""
        g = self.geometry
        k = [
            hertz(c.rx, c.ry, self.contact_modulus(side), 1.0).approach
            for side, c in ((s, raceway_curvature(g, s)) for s in SIDES)
        ]
        return k[0], k[1]

    @property
    def nut_compliance(self) -> float:
        """C_a of one loaded flank (one nut of a double nut), δ_a = C_a F^(2/3): the Hertz
        constants of both contacts of a ball (Hertz point contacts, rigid bodies; theory
        manual, *Loads*) [m N^(−2/3)]."""
        g = self.geometry
        k_a, k_b = self.hertz_constants
        balls = self.flanks.balls
        return float(nut_axial_compliance(k_a, k_b, balls, g.contact_angle, g.lead_angle))

    @property
    def axial_projection(self) -> float:
        """sinβ cosα: axial share of a normal contact approach (ball load → nut force)."""
        g = self.geometry
        return math.sin(g.contact_angle) * math.cos(g.lead_angle)
