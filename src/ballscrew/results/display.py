"""Numbers and names as an engineer reads them: rpm, µm, °C, MPa/GPa, N·m, N/µm.

Results stay SI inside (``summary.json``, NetCDF); these helpers convert at the edge, for report
tables, plot axes and headlines. One spelling per unit (``µm``, ``N·m``, ``m²·K/W``).
"""

from __future__ import annotations

import math
import re

import numpy as np

__all__ = [
    "engineering",
    "engineering_array",
    "format_quantity",
    "readable",
    "significant",
    "spelling",
]


_SPELLING = {
    "N*m": "N·m",
    "N m": "N·m",
    "um": "µm",
    "m^2*K/W": "m²·K/W",
    "m^2": "m²",
    "m^3": "m³",
    "m^2/s": "m²/s",
    "W/m^2/K": "W/(m²·K)",
    "W/(m^2*K)": "W/(m²·K)",
    "W/m/K": "W/(m·K)",
    "W/(m*K)": "W/(m·K)",
    "1": "",
    "-": "",
}


NOISE = {"rad/s": 1e-9, "m/s": 1e-12}
"""Magnitudes below which a solver's speed is round-off (a spin of 1e-15 rad/s), shown as 0."""


def spelling(unit: str) -> str:
    """The one spelling of ``unit``: ``N*m`` → ``N·m``, ``kg/m^3`` → ``kg/m³``, ``um`` → ``µm``."""
    if unit in _SPELLING:
        return _SPELLING[unit]
    return unit.replace("^2", "²").replace("^3", "³").replace("*", "·").replace(" ", "·")


def _length(value: float) -> tuple[float, str]:
    size = abs(value)
    if size == 0.0 or size >= 1e-3:
        return value * 1e3, "mm"
    if size >= 1e-6:
        return value * 1e6, "µm"
    return value * 1e9, "nm"


def engineering(value: float, unit: str, key: str = "") -> tuple[float, str]:
    """``value`` in SI ``unit`` → (value, unit) in the engineer's unit.

    Lengths in mm, µm or nm by size; pressures and moduli in MPa or GPa; angular speeds in rpm;
    angles in degrees; stiffness in N/µm; small areas and unit-area resistances per mm²;
    absolute temperatures (a ``key`` naming a temperature, not a rise or difference) in °C;
    durations of an hour or more in h.
    Other units are returned with their one spelling.
    """
    unit = spelling(unit)
    if not isinstance(value, int | float) or isinstance(value, bool) or not math.isfinite(value):
        return value, unit
    name = key.lower()
    if unit == "m":
        return _length(value)
    if unit == "Pa":
        return (value * 1e-9, "GPa") if abs(value) >= 1e8 else (value * 1e-6, "MPa")
    if unit == "rad/s":
        return value * 30.0 / math.pi, "rpm"
    if unit == "rad":
        return math.degrees(value), "°"
    if unit == "N/m":
        return value * 1e-6, "N/µm"
    if unit == "m²·K/W" and 0.0 < abs(value) < 1e-3:
        return value * 1e6, "mm²·K/W"
    if unit == "m²" and 0.0 < abs(value) < 1e-3:
        return value * 1e6, "mm²"
    if (
        unit == "K"
        and "temperature" in name
        and not any(word in name for word in ("rise", "difference", "delta", "error"))
    ):
        return value - 273.15, "°C"
    if unit == "s" and abs(value) >= 3600.0:
        return value / 3600.0, "h"
    return value, unit


_FACTORS = {
    "mm": 1e3,
    "µm": 1e6,
    "nm": 1e9,
    "GPa": 1e-9,
    "MPa": 1e-6,
    "rpm": 30.0 / math.pi,
    "°": 180.0 / math.pi,
    "N/µm": 1e-6,
    "h": 1.0 / 3600.0,
    "mm²·K/W": 1e6,
    "mm²": 1e6,
}


def engineering_array(values: np.ndarray, unit: str, key: str = "") -> tuple[np.ndarray, str]:
    """:func:`engineering` for an array: one unit for all, chosen by the largest magnitude."""
    values = np.asarray(values, dtype=float)
    finite = np.abs(values[np.isfinite(values)])
    _, shown = engineering(float(finite.max()) if finite.size else 0.0, unit, key)
    if shown == "°C":
        return values - 273.15, shown
    return values * _FACTORS.get(shown, 1.0), shown


def significant(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures (trailing zeros dropped), without an exponent
    for 1e-3 ≤ |v| < 1e6: ``0.0195``, ``1500``, ``2.43e-7``."""
    if value == 0 or not math.isfinite(value):
        return f"{value:g}"
    size = abs(value)
    if 1e-3 <= size < 1e6:
        decimals = max(0, digits - 1 - math.floor(math.log10(size)))
        text = f"{value:.{decimals}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    mantissa = mantissa.rstrip("0").rstrip(".") if "." in mantissa else mantissa
    return f"{mantissa}e{int(exponent)}"


def format_quantity(value: float, unit: str, key: str = "", digits: int = 4) -> str:
    """``"1.35 GPa"``: :func:`engineering` then :func:`significant`."""
    shown, shown_unit = engineering(value, unit, key)
    if not isinstance(shown, int | float) or isinstance(shown, bool):
        return f"{shown} {shown_unit}".strip()
    return f"{significant(shown, digits)} {shown_unit}".strip()


_NUT = re.compile(r"\bnut(\d+)\b")


def readable(name: str) -> str:
    """A field name as words: ``nut1.orbital_speed`` → ``nut 1: orbital speed``,
    ``operating.axial_load`` → ``axial load``, ``F1`` → ``F1``."""
    parts = [p for p in name.split(".") if p]
    if len(parts) > 1 and parts[0] in (
        "operating",
        "numerics",
        "screw",
        "surface",
        "medium",
        "nuts",
    ):
        parts = parts[1:]
    words = [_NUT.sub(r"nut \1", p.replace("_", " ")) for p in parts]
    return ": ".join(words)
