"""Case section ``[kinematics]``: ball kinematics, quasi-static ball balance, lubrication, limits.

Every key has a default, so a case without the section is valid. Theory manual:
``docs/theory/kinematics.md``, ``docs/theory/fractal-contact.md`` and
``docs/theory/lubrication.md``.

Example::

    [kinematics]
    level = 1                              # 0 static, 1 centrifugal + groove, 2 full balance
    speed_range = ["0 rpm", "3000 rpm"]    # curves of the `kinematics` command
    lubricant = "iso_vg_68"                # fills medium.viscosity / pressure_viscosity if unset
    unsupported_length = "800 mm"          # whirling check; default: [design]'s
    mounting = "fixed-supported"

The whirling check takes ``unsupported_length``, ``mounting`` and ``root_diameter`` from this
section where given, else from ``[design]`` (which ``ballscrew init`` writes).
"""

from __future__ import annotations

import math
import re
from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from ballscrew.case.base import MAX_SPEED, Model, nearest_hint, quantity
from ballscrew.case.design_spec import Mounting
from ballscrew.kinematics.motion import ENTRAINMENT_RULES
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY


def known_lubricant(cls: type, name: str | None) -> str | None:
    """The library key of ``name`` (validator of every lubricant key): case, spaces and hyphens
    do not matter, so ``"ISO VG 68"`` is ``"iso_vg_68"``."""
    if name is None:
        return None
    key = re.sub(r"[\s\-]+", "_", name.strip().lower())
    if key not in LUBRICANT_LIBRARY:
        hint = nearest_hint(key, LUBRICANT_LIBRARY)
        known = ", ".join(sorted(LUBRICANT_LIBRARY))
        raise ValueError(f"is not allowed: not a lubricant of the library{hint}; known: {known}")
    return key


_Speed = quantity(
    "angular_velocity", 'screw speed (rad/s; "3000 rpm" also works)', ge=0, le=MAX_SPEED
)


class KinematicsSpec(Model):
    """Options of the kinematics, ball-balance, lubrication and drag-torque models."""

    level: Literal[0, 1, 2] = Field(
        0,
        description="ball balance: 0 static load (Q1), 1 centrifugal force + groove geometry "
        "(E3.5), 2 full balance with traction, EHL rolling resistance, gyroscopic moment (E3.6)",
    )
    speed_range: tuple[_Speed, _Speed] | None = Field(
        None,
        description="lowest and highest screw speed of the curves vs speed; None = 0 to the "
        "larger of the case speed and the d·n-limit speed",
    )
    speed_points: Annotated[
        int, Field(ge=2, le=500, description="number of speeds on the curves vs speed")
    ] = 13
    lubricant: str | None = Field(
        None,
        description="named lubricant of the library (ballscrew.lubrication.LUBRICANT_LIBRARY) "
        "for medium values that are not given; the same as medium.lubricant; None = [medium] only",
    )
    entrainment: Literal[tuple(ENTRAINMENT_RULES)] = Field(  # type: ignore[valid-type]
        "rolling",
        description="entrainment speed u_e of the EHL film, load sharing, traction and rolling "
        "resistance (E2.8): 'rolling' = the surfaces' rolling speed past each contact; "
        "'ball_centre' = the ball-centre speed V (the wear paper's simplification, about "
        "1 + γ smaller)",
    )
    boundary_friction: Annotated[
        float,
        Field(
            ge=0.0,
            le=1.0,
            description="μ_b on the asperity-borne pressure (E3.3) [GUESS 0.1: boundary friction "
            "of lubricated steel; SKF's μ_bl is 0.15]",
        ),
    ] = 0.1
    limiting_shear: Annotated[
        float,
        Field(ge=0.0, le=1.0, description="limiting shear stress / pressure of the film, τ_L/p"),
    ] = 0.07
    micro_contact_size: quantity(
        "length",
        "side √ΔA of the fractal micro-contact cell; σ from (E5.3) with L_s = √ΔA",
        gt=0,
        le=1e-2,
    ) = 10e-6
    traction_cells: Annotated[
        int, Field(ge=8, le=512, description="cells per axis of the traction grid (Level 2)")
    ] = 32
    unsupported_length: (
        quantity(
            "length",
            "unsupported screw length between bearings (whirling check); None = "
            "design.unsupported_length",
            gt=0,
            le=100.0,
        )
        | None
    ) = None
    mounting: Mounting = Field(
        "fixed-supported",
        description="end fixity of the screw shaft for the whirling speed; when not given here, "
        "design.mounting",
    )
    root_diameter: (
        quantity(
            "length",
            "screw root diameter; None = design.root_diameter, else the groove bottom",
            gt=0,
            le=5.0,
        )
        | None
    ) = None
    critical_speed_factor: Annotated[
        float, Field(gt=0.0, le=1.0, description="allowed fraction of the whirling speed")
    ] = 0.8
    dn_limit: Annotated[
        float,
        Field(gt=0.0, le=1e8, description="d·n limit, pitch diameter [mm] × speed [rpm]"),
    ] = 70_000.0
    speed_warnings: bool = Field(
        True, description="warn when the speed exceeds the whirling-speed or d·n limit"
    )

    _known_lubricant = field_validator("lubricant")(known_lubricant)

    @model_validator(mode="after")
    def _range_increases(self) -> KinematicsSpec:
        if self.speed_range is not None:
            low, high = self.speed_range
            if not (math.isfinite(high) and high > low):
                raise ValueError(
                    f"speed_range = ({low:g}, {high:g}) rad/s is not allowed: the highest speed "
                    "must exceed the lowest"
                )
        return self
