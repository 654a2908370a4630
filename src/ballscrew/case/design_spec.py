"""Case section ``[design]``: catalogue ratings, mounting and limits of ``ballscrew check``.

Example (THK BNFN4010-5 on a 1.3 m shaft)::

    [design]
    dynamic_load_rating = "52.7 kN"   # C_a from the maker's table (else from the geometry)
    static_load_rating = "141.1 kN"   # C_0a from the maker's table (else from the geometry)
    static_rating_model = "iso76"     # C_0a from the geometry: 4200 MPa, or "palmgren"
    accuracy_grade = 5                # C5 / P5: f_ac = 1 (0.9 for class 7, 0.7 for class 10)
    mounting = "fixed-supported"
    unsupported_length = "1.3 m"      # between the bearings (buckling and whirling)
    nut_distance = "1.0 m"            # fixed bearing to nut (shaft stiffness); default the length
    root_diameter = "34.4 mm"         # thread minor diameter d_r; default the groove bottom
    load_factor = 1.2                 # f_w
    reliability = 90                  # percent
    required_life = "20000 h"
    bearing_stiffness = "1000 N/um"   # support bearings, in series with nut and shaft
    temperature_rise = "3 K"          # for the pretension that takes up the elongation
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from ballscrew.case.base import Model, model_choice, quantity
from ballscrew.design.life import RELIABILITY_FACTORS
from ballscrew.design.ratings import STATIC_RATING_MODELS
from ballscrew.design.shaft import MOUNTINGS

__all__ = ["DesignSpec"]

Reliability = Literal[tuple(RELIABILITY_FACTORS)]  # type: ignore[valid-type]
Mounting = Literal[MOUNTINGS]  # type: ignore[valid-type]


class DesignSpec(Model):
    """Catalogue ratings, shaft mounting and allowed limits of the design check (SI)."""

    dynamic_load_rating: (
        quantity(
            "force",
            "dynamic axial load rating C_a (maker's); None = from the geometry",
            gt=0,
            le=1e9,
        )
        | None
    ) = None
    static_load_rating: (
        quantity(
            "force",
            "static axial load rating C_0a (maker's); None = from the geometry",
            gt=0,
            le=1e9,
        )
        | None
    ) = None
    static_rating_model: model_choice(
        STATIC_RATING_MODELS,
        "limit of C_0a from the geometry: 'iso76' Hertz 4200 MPa, 'palmgren' permanent "
        "deformation 1e-4 D_w",
    ) = "iso76"
    accuracy_grade: Literal[0, 1, 2, 3, 4, 5, 7, 10] = Field(
        5,
        description="accuracy class (ISO 3408 / JIS C or P grade number): f_ac of C_0a",
    )
    catalogue_rigidity: (
        quantity(
            "stiffness", "nut rigidity K of the maker's table at preload 0.1 C_a", gt=0, le=1e13
        )
        | None
    ) = None
    mounting: Mounting = Field("fixed-supported", description="end fixity of the screw shaft")
    unsupported_length: quantity(
        "length", "shaft length between the bearings (buckling, whirling)", gt=0, le=100.0
    )
    nut_distance: (
        quantity(
            "length",
            "fixed bearing to nut (shaft stiffness); None = the length (fixed-fixed: half)",
            gt=0,
            le=100.0,
        )
        | None
    ) = None
    root_diameter: (
        quantity("length", "thread minor diameter d_r; None = the groove bottom", gt=0, le=5.0)
        | None
    ) = None
    load_factor: Annotated[
        float, Field(ge=1.0, le=10.0, description="load factor f_w (1–1.2 smooth, 2–3.5 shocks)")
    ] = 1.2
    reliability: Reliability = Field(90, description="reliability of the rating life, percent")
    required_life: (
        quantity(
            "time",
            "required life in hours of the duty cycle, its rest included ([operating]: of running)",
            gt=0,
            le=1e11,
        )
        | None
    ) = None
    min_static_safety: Annotated[
        float, Field(gt=0.0, le=20.0, description="smallest allowed f_s = C_0a/F_a,max")
    ] = 1.5
    max_preload_share: (
        Annotated[float, Field(gt=0.0, le=1.0, description="largest preload / C_a")] | None
    ) = None
    dn_limit: Annotated[
        float, Field(gt=0.0, le=1e7, description="d·n limit, pitch diameter [mm] × speed [rpm]")
    ] = 70_000.0
    bearing_stiffness: (
        quantity("stiffness", "axial stiffness of the support bearings", gt=0, le=1e13) | None
    ) = None
    temperature_rise: (
        quantity(
            "temperature_difference", "shaft temperature rise for the pretension", ge=0, le=500
        )
        | None
    ) = None
