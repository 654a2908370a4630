"""Unit handling at the edges of ballscrew.

Inside the package every quantity is a float in SI units. Case files may give a number (taken as
SI) or a string with a unit (``"10 mm"``, ``"1000 rpm"``, ``"45 deg"``); :func:`to_si` converts
such strings through pint, checking that the dimension is the expected one.
"""

from __future__ import annotations

from functools import cache

import pint

#: SI unit (pint spelling) of each physical kind a case file uses.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "area": "m^2",
    "angle": "rad",
    "force": "N",
    "pressure": "Pa",
    "angular_velocity": "rad/s",
    "velocity": "m/s",
    "thermal_conductivity": "W/(m*K)",
    "density": "kg/m^3",
    "specific_heat": "J/(kg*K)",
    "expansion": "1/K",
    "viscosity": "Pa*s",
    "inverse_pressure": "1/Pa",
    "temperature": "K",
    "temperature_difference": "K",
    "time": "s",
    "heat_transfer_coefficient": "W/(m^2*K)",
    "area_resistance": "m^2*K/W",
    "kinematic_viscosity": "m^2/s",
    "power": "W",
    "torque": "N*m",
    "dimensionless": "",
}


@cache
def registry() -> pint.UnitRegistry:
    """The package-wide pint registry (created on first use)."""
    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.formatter.default_format = "~P"
    return ureg


def to_si(value: object, kind: str) -> float:
    """Convert ``value`` to a float in the SI unit of ``kind``.

    Numbers are returned unchanged (already SI). Strings are parsed by pint and must have the
    dimension of ``kind``; a bare number in a string is taken as SI. Raises ``ValueError`` with
    a message that names the expected unit when the string cannot be parsed or has the wrong
    dimension.
    """
    if isinstance(value, bool):
        raise ValueError(f"expected a number or a quantity in {SI_UNITS[kind] or 'no unit'}")
    if isinstance(value, int | float):
        return float(value)
    if not isinstance(value, str):
        raise ValueError(f"expected a number or a string such as '10 {SI_UNITS[kind] or ''}'")
    unit = SI_UNITS[kind]
    try:
        quantity = registry().Quantity(value)
    except Exception as exc:  # pint raises several unrelated types for bad strings
        raise ValueError(f"cannot read {value!r} as a quantity in {unit or 'no unit'}") from exc
    if not isinstance(quantity, pint.Quantity) or quantity.unitless:
        return float(getattr(quantity, "magnitude", quantity))
    try:
        return float(quantity.to(unit).magnitude)
    except pint.DimensionalityError as exc:
        noun = kind.replace("_", " ")
        article = "an" if noun[0] in "aeiou" else "a"
        expected = unit or "no unit"
        raise ValueError(f"{value!r} is not {article} {noun} (expected {expected})") from exc
