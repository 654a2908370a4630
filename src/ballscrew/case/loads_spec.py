"""Case section ``[loads]``: how the load spreads over the balls, and the nut's elastic bodies.

Example (the elastic distribution of a double nut with a 1 µm lead error in its first turn)::

    [loads]
    distribution = "elastic"        # "uniform" (default, rigid bodies) or "elastic"
    contact = "hertz"               # elastic: "hertz" (default) or "numerical" (groove solver)
    nut_outer_diameter = "70 mm"    # nut body; default d_m + 5 D_b (GUESS)
    spacer = "10 mm"                # axial gap between the halves' nearest balls; default L
    flange = "loaded_end"           # or "free_end"
    lead_error = [1e-6, 0, 0, 0, 0, 0, 0, 0, 0, 0]   # m, per turn (or per ball), nut 1 first
    nut_support = "free"            # "guided" (default): the housing takes radial force/tilt
    nut_radial_load = "200 N"       # free nut: external radial force and tilting moment
    nut_tilting_moment = "5 N*m"
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from ballscrew.case.base import Model, quantity

__all__ = ["LoadsSpec"]

Deviation = Annotated[float, Field(ge=-1e-3, le=1e-3)]


class LoadsSpec(Model):
    """Load distribution over the balls and the elastic screw shaft and nut body (SI)."""

    distribution: Literal["uniform", "elastic"] = Field(
        "uniform",
        description="uniform: every ball of a nut carries F/(Z sinβ cosα); elastic: Hertz "
        "contacts with elastic shaft and nut, lead error and ball-size variation",
    )
    contact: Literal["hertz", "numerical"] = Field(
        "hertz",
        description="load-approach law of every ball's contacts in the elastic distribution: "
        "hertz (closed form) or numerical (the contact solver on the case's raceway gap, "
        "tabulated once with [numerics])",
    )
    nut_outer_diameter: (
        quantity(
            "length",
            "outer diameter of the nut body; None = d_m + 5 D_b [GUESS: DIN 69051 flanged "
            "nuts of 6.35 mm balls on 32–63 mm screws]",
            gt=0,
            le=10.0,
        )
        | None
    ) = None
    spacer: (
        quantity(
            "length",
            "axial gap between the nearest balls of the two nuts; None = the lead",
            gt=0,
            le=10.0,
        )
        | None
    ) = None
    flange: Literal["loaded_end", "free_end"] = Field(
        "loaded_end",
        description="nut flange at the end where the shaft carries the load out, or the other",
    )
    lead_error: list[Deviation] = Field(
        default_factory=list,
        max_length=100_000,
        description="axial lead error of the screw relative to the nut [m], per ball or per "
        "turn, nut 1 first, each nut from its loaded end; empty = none",
    )
    ball_diameter_error: list[Deviation] = Field(
        default_factory=list,
        max_length=100_000,
        description="ball diameter minus nominal [m], per ball or per turn, nut 1 first; "
        "empty = none",
    )

    nut_support: Literal["guided", "free"] = Field(
        "guided",
        description="elastic: guided (the housing takes the balls' radial force and tilting "
        "moment, the nut moves only axially) or free (a rigid nut balanced by its balls in "
        "axial and radial displacement and tilt)",
    )
    nut_radial_load: quantity(
        "force",
        "external radial force on a free nut at its centre, towards the first ball of nut 1",
        ge=-1e7,
        le=1e7,
    ) = 0.0
    nut_tilting_moment: quantity(
        "torque",
        "external tilting moment on a free nut about its centre, in the plane of the radial "
        "load (about e_2 = axis x e_1)",
        ge=-1e6,
        le=1e6,
    ) = 0.0

    @model_validator(mode="after")
    def _options_that_need_elastic(self) -> LoadsSpec:
        elastic = self.distribution == "elastic"
        refusals = (
            (
                self.contact == "numerical" and not elastic,
                "contact = 'numerical' needs loads.distribution = 'elastic' (the uniform "
                "distribution has no contact law)",
            ),
            (
                self.nut_support == "free" and not elastic,
                "nut_support = 'free' needs loads.distribution = 'elastic' (the uniform "
                "distribution has rigid bodies and no ball positions)",
            ),
            (
                self.nut_support == "guided"
                and bool(self.nut_radial_load or self.nut_tilting_moment),
                "nut_radial_load and nut_tilting_moment act on a free nut only (a guided "
                "nut's housing takes them): set loads.nut_support = 'free'",
            ),
        )
        for refused, message in refusals:
            if refused:
                raise ValueError(message)
        return self
