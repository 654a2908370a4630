"""Case section ``[thermal]``: what the temperature-field model needs beyond the screw.

The thermal model (theory manual ``docs/theory/thermal.md``) is a screw shaft with its support
bearings and a nut assembly (one nut, or two nuts with a spacer) on it. Every dimensional value is
SI (m, s, K, W, N·m, W/(m² K), m² K/W) or a string with a unit (``"1000 mm"``, ``"20 degC"``, ``"1.5
h"``). A bare number for a temperature is kelvin, so write ambient temperatures as ``"20 degC"``.

Only ``[thermal]`` is needed; every key has a default. Geometry defaults scale with the pitch
diameter d_m of ``[screw]`` (shaft Ø = d_m, nut Ø = 1.75 d_m, nut length = 2.5 d_m).
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from ballscrew.case.base import Model, model_choice, quantity
from ballscrew.contact_resistance.correlations import CORRELATIONS
from ballscrew.contact_resistance.element import ELEMENT_MODELS
from ballscrew.loads.drag_torque import DRAG_TORQUE_MODELS
from ballscrew.thermal.models import THERMAL_MODELS

#: Longest shaft, stroke or position a thermal model accepts, m.
MAX_LENGTH = 100.0

#: Largest heat-transfer coefficient, W/(m² K) (boiling water is about 1e5).
MAX_H = 1e6

#: Longest simulated time or time step, s (a year).
MAX_TIME = 3.2e7


class BearingSpec(Model):
    """One support bearing (set): its friction heat Q = M·ω (Q2), part of it into the screw.

    Give either the catalogue friction ``torque`` or the Palmgren parameters (Q3: ``f0``,
    ``viscosity``, ``mean_diameter``, ``static_load_rating``, ``axial_load``).
    """

    name: str = Field("bearing", description="label used in the report")
    position: quantity(
        "length",
        "axial position of the bearing centre from the shaft end z = 0",
        ge=0,
        le=MAX_LENGTH,
    )
    width: quantity(
        "length", "width of the shaft band the bearing heat enters", gt=0, le=MAX_LENGTH
    ) = 0.02
    torque: (
        quantity("torque", "catalogue friction torque M_be (overrides Palmgren)", ge=0, le=1e5)
        | None
    ) = None
    f0: Annotated[
        float, Field(gt=0, le=20, description="Palmgren f₀ (1–2 angular contact, grease/oil)")
    ] = 2.0
    viscosity: quantity(
        "kinematic_viscosity",
        "lubricant kinematic viscosity ν₀ at working temperature",
        gt=0,
        le=1.0,
    ) = 20e-6
    mean_diameter: (
        quantity("length", "bearing pitch diameter d_m,be", gt=0, le=MAX_LENGTH) | None
    ) = None
    static_load_rating: quantity("force", "basic static load rating C₀", gt=0, le=1e9) | None = None
    axial_load: quantity("force", "axial load F_a on the bearing (its preload)", ge=0, le=1e9) = 0.0
    radial_load: quantity("force", "radial load F_r on the bearing", ge=0, le=1e9) = 0.0
    f1: Annotated[
        float | None, Field(gt=0, le=1, description="Palmgren f₁; None = 0.001 (P₀/C₀)^0.33")
    ] = None
    shaft_fraction: Annotated[
        float, Field(ge=0, le=1, description="fraction of the bearing heat into the screw (Q2)")
    ] = 0.5

    @model_validator(mode="after")
    def _torque_or_palmgren(self) -> BearingSpec:
        if self.torque is None and (self.mean_diameter is None or self.static_load_rating is None):
            raise ValueError(
                "torque = None is not allowed: give the catalogue torque, or mean_diameter and "
                "static_load_rating for the Palmgren estimate"
            )
        return self


class DragTorqueSpec(Model):
    """Friction torque of the ball screw itself, heat Q_bs = M_bs·ω (Q4).

    ``operating_point`` (default): the torque and its split between screw and nut come from
    the coupled operating point (``[friction]`` model, lubricant viscosity at the computed
    temperature); ``[thermal] screw_heat_fraction`` splits the heat of the other sources.
    """

    source: model_choice(
        DRAG_TORQUE_MODELS,
        "friction torque of the coupled operating point (default), catalogue preload torque "
        "K·F_p·L/(2π), a given torque, or the drag torque computed by the ball kinematics model",
    ) = "operating_point"
    torque: quantity("torque", "drag torque M_bs for source = 'given'", ge=0, le=1e5) | None = None

    @model_validator(mode="after")
    def _given_needs_torque(self) -> DragTorqueSpec:
        if self.source == "given" and self.torque is None:
            raise ValueError("torque = None is not allowed: source = 'given' needs a torque")
        return self


class ConvectionSpec(Model):
    """Heat-transfer coefficients: overrides of the correlations (Q5, Q6) and the air."""

    screw: (
        quantity("heat_transfer_coefficient", "override h of the screw surface", ge=0, le=MAX_H)
        | None
    ) = None
    screw_ends: (
        quantity("heat_transfer_coefficient", "override h of the shaft end faces", ge=0, le=MAX_H)
        | None
    ) = None
    nut: (
        quantity("heat_transfer_coefficient", "override h of the nut/spacer OD", ge=0, le=MAX_H)
        | None
    ) = None
    nut_ends: (
        quantity("heat_transfer_coefficient", "override h of the nut end faces", ge=0, le=MAX_H)
        | None
    ) = None
    temperature_difference: quantity(
        "temperature_difference",
        "surface − air ΔT of the natural-convection correlation: the starting guess of the "
        'iteration, or the value used with natural = "fixed" ("10 degC" = 10 K)',
        gt=0,
        le=1000.0,
    ) = 10.0
    natural: Literal["iterated", "fixed"] = Field(
        "iterated",
        description="'iterated': natural convection at the computed mean surface rise of the "
        "screw and of the nut (fixed point); 'fixed': at temperature_difference",
    )
    tolerance: Annotated[
        float, Field(gt=0, le=0.1, description="relative tolerance of the ΔT iteration")
    ] = 1e-6
    max_iterations: Annotated[
        int, Field(ge=1, le=1000, description="most iterations of the ΔT fixed point")
    ] = 50
    air_kinematic_viscosity: quantity(
        "kinematic_viscosity", "kinematic viscosity ν of air", gt=0, le=1.0
    ) = 1.589e-5
    air_conductivity: quantity(
        "thermal_conductivity", "thermal conductivity λ of air", gt=0, le=10.0
    ) = 0.0263
    air_prandtl: Annotated[float, Field(gt=0, le=1e5, description="Prandtl number of air")] = 0.707


class MountingSpec(Model):
    """The nut assembly seated in a table or housing: its heat path besides convection (Q8).

    Defaults: a nut on a machine axis bolted to a table. ``kind = "free"`` is the nut in still
    air only (before this section existed).
    """

    kind: Literal["table", "free"] = Field(
        "table", description="'table': the nut's outer surface conducts into a table; 'free': none"
    )
    contact_conductance: quantity(
        "heat_transfer_coefficient",
        "contact conductance h_c of the nut–table joint (GUESS: 2000, in the 10³–10⁴ range of "
        "ground steel/cast-iron joints at ~1 MPa in air, Madhusudana 2014)",
        ge=0,
        le=MAX_H,
    ) = 2000.0
    contact_fraction: Annotated[
        float,
        Field(
            ge=0,
            le=1,
            description="share of the nut-assembly outer area in contact with the table (GUESS: "
            "0.5, the flange face and the pilot bore); contact_area overrides",
        ),
    ] = 0.5
    contact_area: quantity("area", "nut–table contact area A_c", ge=0, le=100.0) | None = None
    table_area: (
        quantity(
            "area",
            "area of the table losing heat to ambient (GUESS: 1 m², a machine table and its "
            "saddle); None = a table held at ambient",
            gt=0,
            le=1e4,
        )
        | None
    ) = 1.0
    table_coefficient: quantity(
        "heat_transfer_coefficient",
        "h of the table to ambient (GUESS: 10, natural convection and radiation of cast iron "
        "a few K above the air)",
        ge=0,
        le=MAX_H,
    ) = 10.0

    table_heat_capacity: (
        quantity(
            "heat_capacity",
            "heat capacity m·c of the table for transients (e.g. 200 kg of cast iron: 1e5 J/K; "
            "needs table_area); None = a quasi-steady table",
            gt=0,
            le=1e10,
        )
        | None
    ) = None

    @property
    def table_conductance(self) -> float | None:
        """G_t = h_t A_t of the table to ambient [W/K]; None for a table held at ambient."""
        return None if self.table_area is None else self.table_area * self.table_coefficient


class CoolantSpec(Model):
    """A cooled nut: a given h over the area of its cooling channels (Q10)."""

    nut_coefficient: quantity(
        "heat_transfer_coefficient",
        "h of the nut's cooling channels (e.g. pipe_coefficient of the flow)",
        ge=0,
        le=MAX_H,
    ) = 0.0
    nut_channel_area: quantity("area", "wetted area of the nut's channels", ge=0, le=100.0) = 0.0
    inlet_temperature: (
        quantity("temperature", "coolant temperature; None = ambient", gt=150.0, lt=700.0) | None
    ) = None


class ShaftCoolantSpec(Model):
    """Coolant through an axial bore of the screw (hollow-shaft cooling, Q11), inlet at z = 0.

    Off unless ``bore_diameter`` is given. h from the pipe correlations at the flow's Reynolds
    number (laminar Nu below Re = 2300), or ``coefficient``; all three thermal models solve it.
    """

    bore_diameter: quantity("length", "diameter of the coolant bore", gt=0, le=5.0) | None = None
    flow_rate: quantity("volume_flow", 'coolant flow V̇ ("2 L/min")', gt=0, le=10.0) = 3.333e-5
    fluid: Literal["water", "oil VG 10", "oil VG 32", "custom"] = Field(
        "water", description="named coolant, or 'custom' with the four properties below"
    )
    density: quantity("density", "ρ of a custom coolant", gt=0, le=3e4) | None = None
    specific_heat: quantity("specific_heat", "c_p of a custom coolant", gt=0, le=1e5) | None = None
    viscosity: quantity("viscosity", "μ of a custom coolant", gt=0, le=1e3) | None = None
    conductivity: quantity("thermal_conductivity", "λ of a custom coolant", gt=0, le=1e3) | None = (
        None
    )
    inlet_temperature: (
        quantity("temperature", "coolant inlet temperature; None = ambient", gt=150.0, lt=700.0)
        | None
    ) = None
    correlation: Literal["gnielinski", "dittus_boelter"] = Field(
        "gnielinski", description="turbulent Nusselt correlation of the bore"
    )
    coefficient: (
        quantity("heat_transfer_coefficient", "override h of the bore wall", gt=0, le=MAX_H) | None
    ) = None

    @model_validator(mode="after")
    def _custom_needs_properties(self) -> ShaftCoolantSpec:
        props = (self.density, self.specific_heat, self.viscosity, self.conductivity)
        if self.fluid == "custom" and None in props:
            raise ValueError(
                "fluid = 'custom' is not allowed without density, specific_heat, viscosity and "
                "conductivity"
            )
        return self


class ContactSpec(Model):
    """Thermal path across the balls between screw and nut (A4)."""

    source: Literal["tcr", "given"] = Field(
        "tcr",
        description="'tcr': R of each nut from the TCR chain (screw_tcr, [tcr] headline); 'given': "
        "resistance_per_area over the nut bore",
    )
    resistance_per_area: (
        quantity(
            "area_resistance", "R″ smeared over the nut bore, for source = 'given'", gt=0, le=1.0
        )
        | None
    ) = None
    constriction: bool = Field(
        True,
        description="add the macro-constriction of the Hertz patches into ball and raceways "
        "(Yovanovich) in series with the micro TCR (source = 'tcr')",
    )
    tcr_model: str | None = Field(
        None,
        description="micro TCR of the balls from this model of screw_tcr's side-by-side models "
        "(source = 'tcr'); None = the headline model ([tcr] headline)",
    )

    @field_validator("tcr_model")
    @classmethod
    def _known_tcr_model(cls, name: str | None) -> str | None:
        names = tcr_model_names()
        if name is not None and name not in names:
            raise ValueError(f"is not allowed: it must be one of {', '.join(names)}")
        return name

    @model_validator(mode="after")
    def _given_needs_value(self) -> ContactSpec:
        if self.source == "given" and self.resistance_per_area is None:
            raise ValueError(
                "resistance_per_area = None is not allowed: source = 'given' needs a value"
            )
        if self.source == "given" and self.tcr_model is not None:
            raise ValueError(f"tcr_model = {self.tcr_model!r} needs source = 'tcr'")
        return self


def tcr_model_names() -> tuple[str, ...]:
    """Names of the TCR models of ``screw_tcr``: element variants, correlations, and each
    element variant on the whole Hertz patch (``V2/patch``)."""
    element = tuple(ELEMENT_MODELS.names)
    return (*element, *CORRELATIONS.names, *(f"{n}/patch" for n in element))


class StrokeSpec(Model):
    """Reciprocating nut: the moving heat source (``docs/theory/thermal.md``)."""

    length: quantity(
        "length", "stroke of the nut centre (0 = stationary nut)", ge=0, le=MAX_LENGTH
    ) = 0.0
    feed_speed: (
        quantity("velocity", "nut speed; None = ω·L/(2π) from the screw speed", ge=0, le=100.0)
        | None
    ) = None
    mode: Literal["averaged", "resolved"] = Field(
        "averaged",
        description="'averaged': heat and contact time-averaged over the stroke; 'resolved': "
        "the nut position at each time step (needs time_step ≪ stroke/feed_speed)",
    )


class TransientSpec(Model):
    """Implicit-Euler transient from ambient."""

    duration: quantity(
        "time", "simulated time (the paper: 1.5 h; at most a year)", gt=0, le=MAX_TIME
    ) = 5400.0
    time_step: quantity("time", "constant time step Δt", gt=0, le=MAX_TIME) = 60.0
    snapshots: Annotated[
        int, Field(ge=1, le=1000, description="full temperature fields stored over time")
    ] = 10

    @model_validator(mode="after")
    def _step_fits(self) -> TransientSpec:
        if self.time_step > self.duration:
            raise ValueError(
                f"time_step = {self.time_step:g} is not allowed: it must not exceed "
                f"duration = {self.duration:g} s"
            )
        return self


class MeshSpec(Model):
    """Discretisation of the axisymmetric FE model, the axial network and the 3-D model."""

    size: quantity("length", "target element size (both directions)", gt=0, le=1.0) = 0.002
    order: Literal[1, 2] = Field(2, description="Lagrange order of the quadrilateral elements")
    network_cell: quantity(
        "length", "target axial cell length of the 1-D network", gt=0, le=1.0
    ) = 0.005
    size_3d: quantity(
        "length", "3-D model: axial element size over the nut and its stroke", gt=0, le=1.0
    ) = 0.008
    far_size_3d: quantity(
        "length", "3-D model: axial element size of the shaft away from the nut", gt=0, le=1.0
    ) = 0.03
    divisions_3d: int = Field(
        32, ge=8, le=1024, multiple_of=4, description="3-D model: circumferential divisions"
    )
    layers_3d: int = Field(
        4, ge=1, le=64, description="3-D model: radial layers of the shaft O-grid"
    )
    helical_patches: bool = Field(
        True,
        description="3-D model: balls as helical contact patches (False: smeared over the bore)",
    )


class SensorSpec(Model):
    """A named temperature sensor point (r, θ, z), in the nut or in the screw."""

    name: str = Field(description="label of the sensor")
    body: Literal["nut", "screw"] = Field(description="body the sensor is fixed to")
    r: quantity("length", "radius of the sensor point", ge=0, le=MAX_LENGTH)
    z: quantity(
        "length",
        "axial position from the shaft end z = 0 (nut: at its mean position)",
        ge=0,
        le=MAX_LENGTH,
    )
    theta: quantity(
        "angle",
        'angle from the x axis ("90 deg" also works); only the 3-D model reads it',
        ge=-2 * math.pi,
        le=2 * math.pi,
    ) = 0.0


class ThermalSpec(Model):
    """Thermal model of screw shaft, nuts, spacer and bearings (``docs/theory/thermal.md``)."""

    model: model_choice(THERMAL_MODELS, "default model of `ballscrew thermal`") = "axisymmetric"
    shaft_length: quantity("length", "length of the screw shaft", gt=0, le=MAX_LENGTH) = 1.0
    shaft_diameter: (
        quantity("length", "thermal diameter of the shaft; None = pitch diameter d_m", gt=0, le=5.0)
        | None
    ) = None
    nut_outer_diameter: (
        quantity(
            "length",
            "nut outer diameter; None = 1.75 d_m [GUESS: a flanged nut body]",
            gt=0,
            le=5.0,
        )
        | None
    ) = None
    nut_length: (
        quantity("length", "length of each nut; None = 2.5 d_m [GUESS]", gt=0, le=MAX_LENGTH) | None
    ) = None
    spacer_length: quantity("length", "spacer length between two nuts", ge=0, le=MAX_LENGTH) = 0.01
    spacer_outer_diameter: (
        quantity("length", "spacer outer diameter; None = nut outer diameter", gt=0, le=5.0) | None
    ) = None
    nut_position: (
        quantity(
            "length", "centre of the nut assembly from z = 0; None = mid-screw", ge=0, le=MAX_LENGTH
        )
        | None
    ) = None
    ambient_temperature: quantity(
        "temperature", 'ambient (initial) temperature; write "20 degC"', gt=150.0, lt=700.0
    ) = 293.15
    screw_heat_fraction: Annotated[
        float, Field(ge=0, le=1, description="share of the ball-screw friction heat into the screw")
    ] = 0.5
    thermoelastic_check: bool = Field(
        True, description="axisymmetric FE: thermo-elastic tip displacement vs α∫ΔT dz"
    )
    bearings: list[BearingSpec] = Field(default_factory=list, description="support bearings")
    drag_torque: DragTorqueSpec = DragTorqueSpec()
    convection: ConvectionSpec = ConvectionSpec()
    mounting: MountingSpec = MountingSpec()
    coolant: CoolantSpec = CoolantSpec()
    shaft_coolant: ShaftCoolantSpec = ShaftCoolantSpec()
    contact: ContactSpec = ContactSpec()
    stroke: StrokeSpec = StrokeSpec()
    transient: TransientSpec = TransientSpec()
    mesh: MeshSpec = MeshSpec()
    sensors: list[SensorSpec] = Field(default_factory=list, description="named sensor points")

    @model_validator(mode="after")
    def _fits_on_shaft(self) -> ThermalSpec:
        for k, bearing in enumerate(self.bearings):
            if not 0.0 <= bearing.position <= self.shaft_length:
                raise ValueError(
                    f"bearings.{k}.position = {bearing.position:g} is not allowed: it must lie "
                    f"on the shaft, in [0, {self.shaft_length:g}] m"
                )
        if self.nut_position is not None and self.nut_position > self.shaft_length:
            raise ValueError(
                f"nut_position = {self.nut_position:g} is not allowed: it must lie on the "
                f"shaft, in [0, {self.shaft_length:g}] m"
            )
        bore = self.shaft_coolant.bore_diameter
        if bore is not None and self.shaft_diameter is not None and bore >= self.shaft_diameter:
            raise ValueError(
                f"shaft_coolant.bore_diameter = {bore:g} is not allowed: it must be below the "
                f"shaft diameter {self.shaft_diameter:g} m"
            )
        if self.mounting.table_heat_capacity is not None and self.mounting.table_area is None:
            raise ValueError(
                "mounting.table_heat_capacity is not allowed with table_area = None (a table "
                "held at ambient has no temperature of its own)"
            )
        names = [s.name for s in self.sensors]
        if len(set(names)) != len(names):
            raise ValueError(f"sensors = {names!r} is not allowed: sensor names must be unique")
        return self
