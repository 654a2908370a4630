"""Pydantic models of a ballscrew case file.

A case is one TOML file with the sections ``[screw]``, ``[materials.ball|screw|nut]``,
``[surface]``, ``[medium]``, ``[operating]`` and ``[numerics]`` (and the optional analysis
sections, ``[lubrication]`` among them). Every number is SI; a string
with a unit (``lead = "10 mm"``) is converted by pint. Unknown keys are errors, so a misspelt
parameter is never silently ignored.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field, field_validator, model_validator

from ballscrew.case.base import MAX_FORCE, MAX_SPEED, Model, model_choice, quantity
from ballscrew.case.design_spec import DesignSpec
from ballscrew.case.duty_spec import DutyRepeat, DutySegment, require_time_shares
from ballscrew.case.friction_spec import FrictionSpec
from ballscrew.case.kinematics_spec import KinematicsSpec, known_lubricant
from ballscrew.case.loads_spec import LoadsSpec
from ballscrew.case.lubrication_spec import LubricationSpec, check_oil_viscosities
from ballscrew.case.nut_body import check_nut_body
from ballscrew.case.thermal_spec import ThermalSpec, tcr_model_names
from ballscrew.case.wear_spec import WearSpec
from ballscrew.contact import (
    DEFAULT_BOX_FACTOR,
    DEFAULT_CELLS_ACROSS,
    DEFAULT_MAX_ITERATIONS,
    DEFAULT_TOLERANCE,
)
from ballscrew.contact_resistance.correlations import CORRELATIONS
from ballscrew.contact_resistance.element import ELEMENT_MODELS
from ballscrew.geometry.gap import GAP_MODELS
from ballscrew.loads.preload_method import PRELOAD_METHODS, preload_methods
from ballscrew.lubrication.film import FILM_MODELS
from ballscrew.lubrication.viscosity import ISO_VISCOSITY_GRADES, nu100_from_viscosity_index
from ballscrew.materials import MATERIALS, material_properties


class ScrewSpec(Model):
    """Catalogue geometry of the screw and its nut(s)."""

    pitch_diameter: quantity("length", "ball-centre (pitch-circle) diameter d_m", gt=0, le=5.0)
    lead: quantity("length", "lead L (axial advance per screw revolution)", gt=0, le=1.0)
    ball_diameter: quantity("length", "ball diameter D_b", gt=0, le=1.0)
    screw_conformity: Annotated[
        float, Field(gt=0.5, lt=1.0, description="screw groove radius / ball diameter f_s")
    ]
    nut_conformity: Annotated[
        float, Field(gt=0.5, lt=1.0, description="nut groove radius / ball diameter f_N")
    ]
    contact_angle: quantity(
        "angle",
        'contact angle β in the normal plane (rad; "45 deg" also works)',
        gt=0,
        lt=math.pi / 2,
    )
    balls_per_nut: Annotated[int, Field(ge=1, le=10_000, description="loaded balls per nut")]
    nuts: Literal[1, 2] = Field(2, description="1 (single nut) or 2 (preloaded double nut)")
    preload_method: Literal[PRELOAD_METHODS] | None = Field(  # type: ignore[valid-type]
        None,
        description="how the nut is preloaded: spacer (double nut), oversized_balls "
        "(single nut, four-point contact) or offset_lead (single nut, lead shift); "
        "None = spacer for 2 nuts, oversized_balls for 1",
    )

    @property
    def resolved_preload_method(self) -> str:
        """``preload_method``, or its default for ``nuts``."""
        return self.preload_method or preload_methods(self.nuts)[0]

    def guessed_inputs(self) -> dict[str, str]:
        """Inputs left at a default that is a guess only in this configuration: the preload
        method of a single nut (a double nut has only the spacer)."""
        if self.nuts == 1 and self.preload_method is None:
            return {
                "preload_method": "oversized_balls for a single nut [GUESS: makers preload "
                "single nuts mostly by oversized balls, many also by an offset lead; it "
                "matters only with a preload]"
            }
        return {}

    @model_validator(mode="after")
    def _preload_method_fits(self) -> ScrewSpec:
        method, allowed = self.resolved_preload_method, preload_methods(self.nuts)
        if method not in allowed:
            raise ValueError(
                f"preload_method = {method!r} is not allowed with screw.nuts = "
                f"{self.nuts}: {' or '.join(allowed)}"
            )
        if method == "offset_lead" and self.balls_per_nut % 2:
            raise ValueError(
                f"balls_per_nut = {self.balls_per_nut} is not allowed with "
                'screw.preload_method = "offset_lead": an even number (two equal halves)'
            )
        return self

    @model_validator(mode="after")
    def _ball_fits(self) -> ScrewSpec:
        if self.ball_diameter >= self.pitch_diameter:
            raise ValueError(
                f"ball_diameter = {self.ball_diameter:g} m is not allowed: it must be smaller "
                f"than pitch_diameter = {self.pitch_diameter:g} m"
            )
        return self


class MaterialSpec(Model):
    """Mechanical and thermal properties of one part (ball, screw or nut).

    ``material = "100Cr6"`` fills every property from :data:`ballscrew.materials.MATERIALS`;
    a property given as well overrides the library's value.
    """

    material: str | None = Field(
        None, description="named material (ballscrew.materials); given properties override it"
    )
    youngs_modulus: quantity("pressure", "Young's modulus E", gt=0, le=1e13)
    poissons_ratio: Annotated[float, Field(gt=0.0, lt=0.5, description="Poisson's ratio ν")]
    hardness: quantity("pressure", "indentation hardness H of the surface", gt=0, le=1e12)
    yield_strength: quantity("pressure", "yield strength σ_y", gt=0, le=1e12)
    thermal_conductivity: quantity("thermal_conductivity", "thermal conductivity λ", gt=0, le=1e4)
    density: quantity("density", "density ρ", gt=0, le=1e5)
    specific_heat: quantity("specific_heat", "specific heat capacity c_p", gt=0, le=1e5)
    thermal_expansion: quantity(
        "expansion", "linear thermal expansion coefficient α_T", ge=0, le=1e-2
    )

    @model_validator(mode="before")
    @classmethod
    def _fill_from_library(cls, data: Any) -> Any:
        if not isinstance(data, dict) or data.get("material") is None:
            return data
        name = data["material"]
        if not isinstance(name, str) or name not in MATERIALS:
            raise ValueError(
                f"material = {name!r} is not allowed: it must be one of {', '.join(MATERIALS)}"
            )
        return {**material_properties(name), **data}

    @property
    def properties(self) -> dict[str, float]:
        """The eight property values (SI), without the material's name."""
        return self.model_dump(exclude={"material"})


class Materials(Model):
    """Materials of the three parts in contact."""

    ball: MaterialSpec
    screw: MaterialSpec
    nut: MaterialSpec


class FractalSurface(Model):
    """Weierstrass–Mandelbrot description of a rough surface (profile dimension)."""

    D: Annotated[float, Field(gt=1.0, lt=2.0, description="profile fractal dimension D")]
    G: quantity("length", "fractal roughness G", gt=0, le=1e-3)


G_CONVENTIONS = ("profile", "surface")
"""What the G of a case is: the Majumdar–Bhushan profile G or the 3-D Yan–Komvopoulos surface G
(:mod:`ballscrew.fractal.conventions`)."""


class SurfaceSpec(FractalSurface):
    """Raceway roughness (``D``, ``G``) and, optionally, the ball's (smooth when absent).

    ``G_convention`` says which G the case gives, for ``G``, ``ball.G`` and
    ``wear.running_in.G`` alike; every analysis converts it once to the G its model reads
    (theory manual, *Fractal contact*, roughness conventions).
    """

    ball: FractalSurface | None = Field(None, description="ball roughness; None = smooth ball")
    G_convention: Literal[G_CONVENTIONS] = Field(  # type: ignore[valid-type]
        "profile",
        description="which G the case gives (for surface.G, surface.ball.G and "
        "wear.running_in.G): 'profile' the Majumdar–Bhushan profile G of a measured profile "
        "(ballscrew surface), 'surface' the 3-D Yan–Komvopoulos surface G; each model gets its "
        "own G of the same RMS height",
    )


_KinematicViscosity = quantity("kinematic_viscosity", "kinematic viscosity", gt=0, le=1.0)


class MediumSpec(Model):
    """The interstitial medium between the asperities: lubricant, grease or air."""

    name: str = Field("mineral oil", description="what the medium is, for the report")
    thermal_conductivity: quantity(
        "thermal_conductivity", "conductivity λ_f of the medium", gt=0, le=1e4
    )
    viscosity: quantity("viscosity", "dynamic viscosity η₀ at the inlet", gt=0, le=1e9) | None = (
        None
    )
    pressure_viscosity: (
        quantity("inverse_pressure", "Barus pressure–viscosity coefficient α_p", ge=0, le=1e-6)
        | None
    ) = None
    film_model: model_choice(
        FILM_MODELS, "EHL film-thickness model of the ball contacts (kinematics and wear)"
    ) = "hamrock_dowson"
    lubricant: str | None = Field(
        None,
        description="named lubricant of the library (ballscrew.lubrication.LUBRICANT_LIBRARY) "
        "for the values not given here; None = these values only",
    )
    viscosity_40: _KinematicViscosity | None = Field(
        None, description="an unnamed oil: kinematic viscosity at 40 °C (ASTM D341 with _100)"
    )
    viscosity_grade: int | None = Field(
        None,
        ge=2,
        le=3200,
        description="an unnamed oil: ISO 3448 viscosity grade VG, ν40 = VG mm²/s (instead of "
        "viscosity_40)",
    )
    viscosity_100: _KinematicViscosity | None = Field(
        None, description="an unnamed oil: kinematic viscosity at 100 °C"
    )
    viscosity_index: float | None = Field(
        None,
        ge=-100,
        le=400,
        description="an unnamed oil: ASTM D2270 viscosity index, ν100 from it and ν40 (instead "
        "of viscosity_100)",
    )
    density_15: quantity(
        "density", "an unnamed oil: density at 15 °C [ASSUMED 870]", gt=0, le=1e4
    ) = 870.0
    rarefaction: quantity(
        "length",
        "gas rarefaction parameter M = αβΛ across the gap (0 for a liquid; air at 20 °C and "
        "1 atm about 0.27 µm, Yovanovich 1982)",
        ge=0,
        le=1e-3,
    ) = 0.0

    _known_lubricant = field_validator("lubricant")(known_lubricant)
    _one_oil = model_validator(mode="after")(check_oil_viscosities)

    @field_validator("viscosity_grade")
    @classmethod
    def _iso_grade(cls, grade: int | None) -> int | None:
        if grade is not None and grade not in ISO_VISCOSITY_GRADES:
            raise ValueError(
                "is not allowed: one of the ISO 3448 grades "
                + ", ".join(map(str, ISO_VISCOSITY_GRADES))
            )
        return grade

    def oil_viscosities(self) -> tuple[float, float] | None:
        """(ν40, ν100) [m²/s] of the unnamed oil, None without one.

        ν40 = ``viscosity_40`` or the ISO 3448 grade's mid-point; ν100 = ``viscosity_100`` or,
        from ``viscosity_index``, the inverse of ASTM D2270
        (:func:`~ballscrew.lubrication.viscosity.nu100_from_viscosity_index`).
        """
        nu40 = self.viscosity_40
        if nu40 is None and self.viscosity_grade is not None:
            nu40 = self.viscosity_grade * 1e-6
        if nu40 is None:
            return None
        if self.viscosity_index is not None:
            return nu40, nu100_from_viscosity_index(nu40, self.viscosity_index)
        return None if self.viscosity_100 is None else (nu40, self.viscosity_100)


class OperatingSpec(Model):
    """Operating point: preload, external axial load and screw speed."""

    preload: quantity("force", "preload F_p of the nut(s)", ge=0, le=MAX_FORCE)
    axial_load: quantity(
        "force",
        "external axial load F_a (≥ 0; it loads nut 1 and unloads nut 2; the reverse "
        "direction is its mirror image, nut 2 loaded: signed loads go in [[duty]])",
        ge=0,
        le=MAX_FORCE,
    ) = 0.0
    speed: quantity(
        "angular_velocity", 'screw speed ω (rad/s; "1000 rpm" also works)', ge=0, le=MAX_SPEED
    ) = 0.0
    coupled: bool = Field(
        False,
        description="TCR and kinematics take the lubricant at the temperature of the coupled "
        "operating point (needs [thermal]); false: the [medium] values as given",
    )


BoxFactor = Annotated[float, Field(ge=1.05, le=5.0)]


class NumericsSpec(Model):
    """Numerical settings of the contact solver."""

    cells_across: Annotated[
        int, Field(ge=8, le=4096, description="grid cells across the Hertz contact, each axis")
    ] = DEFAULT_CELLS_ACROSS
    cells: tuple[Annotated[int, Field(ge=4, le=8192)], Annotated[int, Field(ge=4, le=8192)]] | (
        None
    ) = Field(
        None,
        description="explicit grid [nx, ny] over the box, instead of cells_across",
    )
    box_factor: BoxFactor | tuple[BoxFactor, BoxFactor] = Field(
        DEFAULT_BOX_FACTOR,
        description="grid box half-width / Hertz semi-axis, or [along x, along y]",
    )
    tolerance: Annotated[
        float, Field(gt=0.0, le=1e-3, description="relative pressure change to stop the CG")
    ] = DEFAULT_TOLERANCE
    max_iterations: Annotated[
        int, Field(ge=10, le=100_000, description="CG iteration limit before it is an error")
    ] = DEFAULT_MAX_ITERATIONS
    gap_model: model_choice(
        GAP_MODELS, "raceway gap: exact Newton projection or quadratic (Hertz) form"
    ) = "exact"


class TCRSpec(Model):
    """Options of the thermal-contact-resistance models (theory manual)."""

    headline: str = Field(
        "CMY",
        description="model whose R and R″ are the headline and feed the thermal models: CMY "
        "(default, no cell size), Mikic, an element variant on the whole Hertz patch "
        "(V2/patch, …) or on the Δ_f cells of Gao et al. (V2, MT, V1: the paper's cell model)",
    )
    variant: model_choice(
        ELEMENT_MODELS,
        "element solid conductance of the fractal details: V2 (default, reconstruction), MT or V1",
    ) = "V2"
    cell_size: quantity(
        "length", "fractal cell size Δ_f of the cell models (V2, MT, V1)", gt=0, le=1e-2
    ) = 8e-6
    cutoff_area: quantity("area", "lower spot-area cut-off a_s of variant MT", gt=0, le=1e-4) = (
        1e-16
    )
    gap_model: Literal["mean_cap", "cap_clearance", "interference", "two_sigma", "mean_plane"] = (
        Field(
            "mean_cap",
            description="gap-thickness model L_g (T6 = mean_cap; mean_plane = Yovanovich's Y)",
        )
    )
    gap_factor: Annotated[float, Field(gt=0, le=1e3, description="multiplier on L_g")] = 1.0
    rebin: bool = Field(
        True,
        description="re-bin the pressure onto Δ_f cells (false: evaluate on the solver grid)",
    )
    partial_cells: Literal["contact_area", "full_cell"] = Field(
        "contact_area",
        description="apparent area of a cell on the patch edge: its part in contact, or Δ_f²",
    )
    load_threshold: Annotated[
        float, Field(ge=0, lt=1, description="cells below this × the peak load are skipped")
    ] = 1e-8
    models: list[str] = Field(
        default_factory=lambda: [*ELEMENT_MODELS.names, *CORRELATIONS.names],
        description="models reported side by side (element variants and correlations)",
    )
    sampling_length: quantity(
        "length", "longest roughness wavelength L_u for σ and m of the correlations", gt=0, le=1
    ) = 8e-4
    cutoff_length: quantity(
        "length", "shortest roughness wavelength l_c for σ and m of the correlations", gt=0, le=1e-2
    ) = 2.5e-6
    rms_roughness: (
        quantity("length", "measured RMS roughness σ (overrides D, G)", gt=0, le=1e-3) | None
    ) = None
    rms_slope: (
        Annotated[
            float, Field(gt=0, le=10, description="measured RMS profile slope m (overrides D, G)")
        ]
        | None
    ) = None
    film_path: Literal["none", "meniscus"] = Field(
        "none",
        description="lubricant film around each ball outside its Hertz patch as a parallel heat "
        "path: none (Gao et al.'s chain) or meniscus (wetted up to the inlet meniscus of a "
        "starved or greased supply, else to the groove-bottom clearance)",
    )

    @field_validator("headline")
    @classmethod
    def _known_headline(cls, name: str) -> str:
        names = tcr_model_names()
        if name not in names:
            raise ValueError(f"unknown model {name!r}; allowed: {', '.join(names)}")
        return name

    @field_validator("models")
    @classmethod
    def _known_models(cls, names: list[str]) -> list[str]:
        known = (*ELEMENT_MODELS.names, *CORRELATIONS.names)
        for name in names:
            if name not in known:
                raise ValueError(f"unknown model {name!r}; allowed: {', '.join(known)}")
        return names

    @model_validator(mode="after")
    def _roughness_band(self) -> TCRSpec:
        if not self.cutoff_length < self.sampling_length:
            raise ValueError(
                f"cutoff_length = {self.cutoff_length:g} m must be < sampling_length"
                f" = {self.sampling_length:g} m"
            )
        if (self.rms_roughness is None) != (self.rms_slope is None):
            raise ValueError("give both rms_roughness and rms_slope, or neither")
        return self


class Case(Model):
    """One validated ball-screw case (all values SI)."""

    name: str = Field("case", description="short name of the case, used in reports")
    description: str = Field("", description="free text shown in the report")
    screw: ScrewSpec
    materials: Materials
    surface: SurfaceSpec
    medium: MediumSpec
    operating: OperatingSpec
    numerics: NumericsSpec = NumericsSpec()
    tcr: TCRSpec = TCRSpec()
    thermal: ThermalSpec | None = Field(None, description="thermal model; needed by `thermal`")
    kinematics: KinematicsSpec = KinematicsSpec()
    friction: FrictionSpec = FrictionSpec()
    lubrication: LubricationSpec = LubricationSpec()
    loads: LoadsSpec = LoadsSpec()
    wear: WearSpec | None = Field(None, description="wear model and load programme; for `wear`")
    design: DesignSpec | None = None
    duty: list[DutySegment] = Field(
        default_factory=list,
        max_length=10_000,
        description="duty cycle: [[duty]] segments of speed, load, stroke, dwell and duration",
    )
    duty_repeat: DutyRepeat = 1
    assumed: dict[str, str] = Field(
        default_factory=dict,
        max_length=1000,
        description=(
            "inputs written with an assumed or typical value, not a known one: [assumed] "
            '"dotted.key" = "why"; every summary and report lists them with the guesses'
        ),
    )

    @model_validator(mode="before")
    @classmethod
    def _duty_has_time_shares(cls, data: Any) -> Any:
        if isinstance(data, dict):
            require_time_shares(data.get("duty"))
        return data

    @model_validator(mode="after")
    def _one_lubricant(self) -> Case:
        named = {self.medium.lubricant, self.kinematics.lubricant} - {None}
        if len(named) > 1:
            raise ValueError(
                f"medium.lubricant = {self.medium.lubricant!r} is not allowed with "
                f"kinematics.lubricant = {self.kinematics.lubricant!r}: name one lubricant"
            )
        return self

    _nut_around_the_balls = model_validator(mode="after")(check_nut_body)

    @model_validator(mode="after")
    def _a_ball_in_every_circuit(self) -> Case:
        circuits, balls = self.friction.circuits, self.screw.balls_per_nut
        if circuits > balls:
            raise ValueError(
                f"friction.circuits = {circuits} is not allowed: 1 to screw.balls_per_nut = "
                f"{balls} (every circuit holds a ball)"
            )
        return self

    @model_validator(mode="after")
    def _root_in_the_thread(self) -> Case:
        d_m, d_w = self.screw.pitch_diameter, self.screw.ball_diameter
        for key, spec in (("design", self.design), ("kinematics", self.kinematics)):
            root = None if spec is None else spec.root_diameter
            if root is not None and not d_m - 2.0 * d_w < root < d_m:
                raise ValueError(
                    f"{key}.root_diameter = {root:g} m is not allowed: a thread minor diameter "
                    f"between d_m − 2·D_w = {d_m - 2.0 * d_w:g} m and d_m = {d_m:g} m"
                )
        return self

    @model_validator(mode="after")
    def _some_ball_is_loaded(self) -> Case:
        op = self.operating
        if self.screw.nuts == 2 and op.preload <= 0:
            raise ValueError(
                "operating.preload = 0 N is not allowed: a double nut needs a preload > 0 N"
            )
        if op.preload + op.axial_load <= 0:
            raise ValueError(
                "operating.axial_load = 0 N with operating.preload = 0 N lifts every ball off: "
                "the nut needs preload + axial_load > 0 N"
            )
        return self
