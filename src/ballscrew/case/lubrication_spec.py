"""Case section ``[lubrication]``: supply state of the contacts and the film corrections.

Every key has a default, so a case without the section is valid (fully flooded, isothermal: the
film of ``[medium] film_model`` unchanged). Theory manual: ``docs/theory/lubrication.md``.

Example::

    [lubrication]
    supply = "starved"          # "flooded" (default), "starved" or "grease"
    inlet_ratio = 2.0           # inlet meniscus distance / Hertz semi-axis b (starved; grease
                                # without it: SKF kinematic replenishment)
    # inlet_layer = "0.2 um"    # or instead: the oil layer on the track ahead of the contact
                                # (Chevalier et al. 1998 thin-layer starvation)
    thermal = true              # inlet shear-heating reduction (Gupta et al. 1992)
    temperature = "40 degC"     # inlet temperature of the named lubricant's properties
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from ballscrew.case.base import Model, quantity
from ballscrew.errors import InputError

Supply = Literal["flooded", "starved", "grease"]


def check_oil_viscosities(medium: Any) -> Any:
    """``[medium]`` validator: an unnamed oil by ν40 (``viscosity_40`` or ``viscosity_grade``) and
    ν100 (``viscosity_100`` or ``viscosity_index``), each given one way, that falls with
    temperature, not together with a named lubricant or a dynamic viscosity."""
    keys = ("viscosity_40", "viscosity_grade", "viscosity_100", "viscosity_index")
    given = [key for key in keys if getattr(medium, key) is not None]
    if not given:
        return medium
    for pair in (keys[:2], keys[2:]):
        if all(key in given for key in pair):
            raise ValueError(
                f"{pair[1]} = {getattr(medium, pair[1]):g} is not allowed with {pair[0]}: give "
                f"{'nu40' if pair[0] == 'viscosity_40' else 'nu100'} one way"
            )
        if not any(key in given for key in pair):
            raise ValueError(
                f"{' or '.join(pair)} is missing: an oil by viscosities needs it with "
                f"{' and '.join(given)}"
            )
    nu40, nu100 = medium.viscosity_40, medium.viscosity_100
    if nu40 is not None and nu100 is not None and nu100 >= nu40:
        raise ValueError(
            f"viscosity_100 = {nu100:g} m^2/s is not allowed: it must be below viscosity_40 = "
            f"{nu40:g} m^2/s (the viscosity falls with temperature)"
        )
    for other in ("lubricant", "viscosity"):
        if getattr(medium, other) is not None:
            raise ValueError(
                f"{other} = {getattr(medium, other)!r} is not allowed with {given[0]}: "
                "give the oil one way"
            )
    try:
        medium.oil_viscosities()
    except InputError as err:
        raise ValueError(str(err)) from None
    return medium


class LubricationSpec(Model):
    """Supply state of the ball contacts and the thermal correction of the film."""

    supply: Supply = Field(
        "flooded",
        description="flooded: Hamrock–Dowson film; starved: inlet meniscus at inlet_ratio "
        "(Hamrock & Dowson 1977, IV) or oil layer inlet_layer on the track (Chevalier et al. "
        "1998); grease: base-oil film, starved by kinematic replenishment (SKF 2013 φ_rs, "
        "K_rs = 6e-8) or, given inlet_ratio or inlet_layer, by that meniscus or layer",
    )
    inlet_ratio: (
        Annotated[
            float,
            Field(
                ge=1.0,
                le=1e3,
                description="inlet meniscus distance from the contact centre / Hertz semi-axis "
                "along rolling, m >= 1 (starved: required); None = in the grease state the "
                "kinematic replenishment of the track (SKF 2013 φ_rs; bearing section "
                "D - d = D_w/0.3 [GUESS], K_Z = 3.1 [ASSUMED])",
            ),
        ]
        | None
    ) = None
    inlet_layer: (
        quantity(
            "length",
            "oil layer thickness h_oil on the track ahead of a contact (starved or grease, "
            "instead of inlet_ratio): h_c/h_c,ff = r/(1 + r^3)^(1/3), r = h_oil/(rho_bar h_c,ff) "
            "(Chevalier et al. 1998; exponent 3 [ASSUMED])",
            ge=0,
            le=1e-3,
        )
        | None
    ) = None
    thermal: bool = Field(
        False, description="reduce the film for inlet shear heating (Gupta et al. 1992)"
    )
    temperature: quantity(
        "temperature",
        "inlet temperature at which a named lubricant's properties are taken",
        gt=0,
        le=700,
    ) = 313.15

    @model_validator(mode="after")
    def _inlet_for_starved(self) -> LubricationSpec:
        if self.inlet_ratio is not None and self.inlet_layer is not None:
            raise ValueError(
                f"inlet_layer = {self.inlet_layer:g} m is not allowed with inlet_ratio = "
                f"{self.inlet_ratio:g}: give the inlet meniscus or the oil layer, not both"
            )
        if self.supply == "starved" and self.inlet_ratio is None and self.inlet_layer is None:
            raise ValueError(
                "inlet_ratio is missing: supply = 'starved' needs the inlet meniscus ratio m >= 1 "
                "or the oil layer inlet_layer >= 0 m"
            )
        for key in ("inlet_ratio", "inlet_layer"):
            value = getattr(self, key)
            if self.supply == "flooded" and value is not None:
                raise ValueError(
                    f"{key} = {value:g}{' m' if key == 'inlet_layer' else ''} is not allowed "
                    "with supply = 'flooded': use 'starved' or 'grease'"
                )
        return self

    @property
    def meniscus(self) -> float | None:
        """The inlet ratio m of a starved supply, or of a greased one given it (None else)."""
        return None if self.supply == "flooded" else self.inlet_ratio

    @property
    def layer(self) -> float | None:
        """The oil layer h_oil,∞ [m] on the track of a starved or greased supply (None else)."""
        return None if self.supply == "flooded" else self.inlet_layer

    @property
    def replenished(self) -> bool:
        """True for a greased supply with neither an inlet ratio nor an oil layer: its film is
        thinned by the kinematic replenishment of the track (SKF 2013)."""
        return self.supply == "grease" and self.inlet_ratio is None and self.inlet_layer is None
