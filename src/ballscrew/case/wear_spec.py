"""Case section ``[wear]``: the fractal wear model and the load programme of a life test.

Theory manual: ``docs/theory/wear.md`` (wear models A and C, wear strips, working raceway length,
life integration, drag torque, the step-stress test and the calibrated wear coefficient of the
reference screw of ``examples/wear_step_stress.toml``).

The key names ``coefficient``, ``torque_scale``, ``initial_torque`` and ``programme`` are a
contract with the calibration code; do not rename them.

Example::

    [wear]
    model = "A"                    # Archard–fractal on plastic asperities (E7.2, default)
    coefficient = 1.304e-4         # K (omit: the reference calibration, REFERENCE_COEFFICIENTS)
    stroke = "0.30 m"              # reciprocating stroke S → L_w (E8.3) [assumed]
    torque_sampling = 4.8e4        # revolutions between drag-torque samples

    [[wear.programme]]
    axial_load = "2000 N"
    speed = "100 rpm"
    revolutions = 4.8e5
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, model_validator

from ballscrew.case.base import MAX_FORCE, MAX_SPEED, Model, model_choice, quantity
from ballscrew.wear.preload import PRELOAD_CONTACTS
from ballscrew.wear.rates import WEAR_LAWS
from ballscrew.wear.step import ASPERITY_HEIGHTS

#: Most screw revolutions of one level (a very long life test is about 1e9).
MAX_REVOLUTIONS = 1e12

#: Most drag-torque samples over the whole programme.
MAX_TORQUE_SAMPLES = 1e6


class WearLevel(Model):
    """One level of the load programme: constant axial load and speed for some revolutions."""

    axial_load: quantity(
        "force", "external axial working load F_a of the level (N)", ge=0, le=MAX_FORCE
    )
    speed: quantity(
        "angular_velocity", 'screw speed ω_s (rad/s; "100 rpm" also works)', gt=0, le=MAX_SPEED
    )
    revolutions: Annotated[
        float,
        Field(
            gt=0,
            le=MAX_REVOLUTIONS,
            description="screw revolutions of the level (dimensionless count, at most 1e12)",
        ),
    ]


class RunningInSpec(Model):
    """The as-machined raceway surface and the worn depth over which it runs in.

    Each fractal parameter approaches the steady (run-in) value of ``[surface]`` exponentially
    with the worn depth h: X(h) = X_ss + (X_0 − X_ss) e^(−h/h_r), ln G likewise (theory manual,
    *Wear*, running-in).
    """

    D: Annotated[
        float,
        Field(gt=1.0, lt=2.0, description="initial profile fractal dimension D_0 (1 < D_0 < 2)"),
    ]
    G: quantity("length", "initial fractal roughness G_0 (m)", gt=0, le=1e-6)
    depth: quantity(
        "length",
        "running-in depth h_r of the exponential approach (m, 1 nm to 0.1 mm)",
        ge=1e-9,
        le=1e-4,
    )


class CalibratedRange(Model):
    """Speeds and axial loads of the test the wear coefficient was calibrated on."""

    speed_min: quantity("angular_velocity", "lowest calibrated screw speed", gt=0, le=MAX_SPEED)
    speed_max: quantity("angular_velocity", "highest calibrated screw speed", gt=0, le=MAX_SPEED)
    load_min: quantity("force", "lowest calibrated axial load", ge=0, le=MAX_FORCE)
    load_max: quantity("force", "highest calibrated axial load", ge=0, le=MAX_FORCE)

    @model_validator(mode="after")
    def _ordered(self) -> CalibratedRange:
        if self.speed_min > self.speed_max or self.load_min > self.load_max:
            raise ValueError("speed_min ≤ speed_max and load_min ≤ load_max are required")
        return self


REFERENCE_RANGE = CalibratedRange(
    speed_min=100.0 * 3.141592653589793 / 30.0,
    speed_max=100.0 * 3.141592653589793 / 30.0,
    load_min=2000.0,
    load_max=4000.0,
)
"""Where the default wear coefficient was calibrated: the step-stress test, 100 rpm, 2–4 kN."""

REFERENCE_COEFFICIENTS = {"film": 9.607e-5, "cell": 1.304e-4}
"""The wear coefficient K that gives the step-stress example screw (Model A, 32 × 128 grid) the
h_max = 2.43 µm at 1.44e6 rev of the reference test, per ``wear.asperity_roughness`` ('cell' with
the paper's ball-centre entrainment; 'film' under either entrainment rule, ψ = 1 there): the K a
case without its own coefficient runs with (theory manual, *Wear*)."""


class WearSpec(Model):
    """Fractal wear model, load programme and integration options of ``ballscrew wear``."""

    model: model_choice(
        WEAR_LAWS,
        "per-asperity wear volume: 'A' plastic hemispherical Archard–fractal (default), "
        "'C' cap-volume fractal (needs surface dimension D + 1 < 2.5)",
    ) = "A"
    coefficient: (
        Annotated[
            float,
            Field(
                gt=0,
                lt=1,
                description="wear coefficient K (dimensionless probability per asperity "
                "encounter, below 1); None: the reference calibration of the step-stress screw "
                "for the case's asperity_roughness (REFERENCE_COEFFICIENTS: 9.607e-5 for 'film', "
                "1.304e-4 for 'cell')",
            ),
        ]
        | None
    ) = None
    stroke: quantity(
        "length",
        "reciprocating stroke S of the nut (m, 1 mm to 100 m), sets L_w (E8.3)",
        ge=1e-3,
        le=100.0,
    ) = 0.30
    max_depth_step: quantity(
        "length",
        "largest growth of h_max per time step (m, 1 nm to 0.1 mm); the paper's 0.1 µm",
        ge=1e-9,
        le=1e-4,
    ) = 1e-7
    torque_sampling: Annotated[
        float,
        Field(
            ge=1,
            le=MAX_REVOLUTIONS,
            description="screw revolutions between drag-torque samples (count, ≥ 1; at most "
            f"{MAX_TORQUE_SAMPLES:.0e} samples over the programme)",
        ),
    ] = 4.8e4
    torque_scale: Annotated[
        float,
        Field(gt=0, le=1e3, description="factor on the catalogue K_T = 0.05/√tanλ of (E9.1), -"),
    ] = 1.0
    initial_torque: (
        quantity(
            "torque",
            "measured drag torque at N = 0 (N·m); if given, K_T is rescaled so T(0) matches "
            "it and torque_scale is ignored",
            gt=0,
            le=1e5,
        )
        | None
    ) = None
    torque_offset: quantity(
        "torque",
        "preload-independent drag torque T_0 (N·m; seals, wipers, grease churning) added to "
        "the torque of (E9.1); default 0",
        ge=-1e5,
        le=1e5,
    ) = 0.0
    programme: list[WearLevel] = Field(
        default_factory=lambda: [
            WearLevel(axial_load=load, speed=100.0 * 3.141592653589793 / 30.0, revolutions=4.8e5)
            for load in (2000.0, 3000.0, 4000.0)
        ],
        min_length=1,
        description="load levels run one after the other ([[wear.programme]] tables); default "
        "the paper's three-level step-stress test (2000/3000/4000 N, 100 rpm, 4.8e5 rev each)",
    )
    grid: tuple[Annotated[int, Field(ge=4, le=1024)], Annotated[int, Field(ge=4, le=4096)]] = Field(
        (32, 128),
        description="contact-grid cells (along the helix x, across the groove y); fixed for the "
        "whole run; the cell area ΔA is the fractal micro-contact cell (reference grid 32 × 128)",
    )
    box_factor: Annotated[
        float,
        Field(
            gt=1.0,
            le=4.0,
            description="grid half-widths / Hertz semi-axes at the largest ball load (default 1.4)",
        ),
    ] = 1.4
    film_factor: Annotated[
        float,
        Field(
            gt=0.0,
            le=1.0,
            description="supply factor φ on the EHL film, h = φ h_flooded (1: fully flooded oil; "
            "below 1 for a starved or grease supply)",
        ),
    ] = 1.0
    asperity_roughness: model_choice(
        ASPERITY_HEIGHTS,
        "RMS height σ of the asperities that share the ball load with the EHL film (JGP): "
        "'film' σ_Λ of the film parameter Λ, as the friction and kinematics models (default), "
        "'cell' the σ of one wear-grid cell (the fractal wear model's convention, with which "
        "the reference coefficient 1.304e-4 was calibrated); the wear law's micro-contact stays "
        "at the cell scale",
    ) = "film"
    preload_contact: model_choice(
        PRELOAD_CONTACTS,
        "screw contact of the preload update after wear (E1.13): 'hertz' the unworn Hertz "
        "contact pushed back by the largest depth (default), 'worn' the worn, more conforming "
        "groove's own contact (numerical approach on the worn gap)",
    ) = "hertz"
    running_in: RunningInSpec | None = Field(
        None,
        description="initial raceway surface and running-in depth ([wear.running_in]); "
        "None: the [surface] values throughout",
    )
    calibrated: CalibratedRange | None = Field(
        None,
        description="speed and load range of the test the coefficient was calibrated on "
        "([wear.calibrated]; written by ballscrew calibrate); a programme outside it warns. "
        "None with the default coefficient: the reference test (100 rpm, 2000–4000 N)",
    )
    load_classes: Annotated[
        int,
        Field(
            ge=1,
            le=64,
            description="ball-load classes per nut for loads.distribution = 'elastic' (count; "
            "the balls sorted by load in equal-count classes; 3 converges within 0.5 % of the "
            "per-ball sum on the reference screw); ignored for 'uniform'",
        ),
    ] = 3
    checkpoint_every: Annotated[
        int,
        Field(ge=1, le=1_000_000_000, description="time steps between checkpoint saves (count)"),
    ] = 1

    @property
    def wear_coefficient(self) -> float:
        """K in force: :attr:`coefficient`, else the reference calibration for
        :attr:`asperity_roughness` (:data:`REFERENCE_COEFFICIENTS`)."""
        if self.coefficient is not None:
            return self.coefficient
        return REFERENCE_COEFFICIENTS[self.asperity_roughness]

    @property
    def reference_calibration(self) -> bool:
        """True when the K in force is the reference calibration of :attr:`asperity_roughness`
        (left out, or written with that value): it holds for the reference test's speeds and
        loads (:data:`REFERENCE_RANGE`)."""
        return self.wear_coefficient == REFERENCE_COEFFICIENTS[self.asperity_roughness]

    @model_validator(mode="after")
    def _few_enough_samples(self) -> WearSpec:
        total = sum(level.revolutions for level in self.programme)
        if total / self.torque_sampling > MAX_TORQUE_SAMPLES:
            raise ValueError(
                f"torque_sampling = {self.torque_sampling:g} is not allowed: the programme's "
                f"{total:g} revolutions would give more than {MAX_TORQUE_SAMPLES:.0e} drag-torque "
                f"samples; use torque_sampling ≥ {total / MAX_TORQUE_SAMPLES:g}"
            )
        return self
