"""Units and names as an engineer reads them in report tables and plot axes.

Results stay SI inside (``summary.json``, NetCDF). The conversion itself is
:mod:`ballscrew.units` (one display unit per kind, one spelling per unit: µm, N·m, °C, rpm);
this module applies it to a value known only by its SI unit string and its name, and turns
field names into words.
"""

from __future__ import annotations

import math
import re

import numpy as np

from ballscrew.units import display_kind, to_display

__all__ = ["engineering", "engineering_array", "readable", "spelling"]


_SPELLING = {
    "N*m": "N·m",
    "N m": "N·m",
    "um": "µm",
    "m^2*K/W": "m²·K/W",
    "W/m^2/K": "W/(m²·K)",
    "W/(m^2*K)": "W/(m²·K)",
    "W/m/K": "W/(m·K)",
    "W/(m*K)": "W/(m·K)",
    "1": "",
    "-": "",
}


def spelling(unit: str) -> str:
    """The one spelling of ``unit``: ``N*m`` → ``N·m``, ``kg/m^3`` → ``kg/m³``, ``um`` → ``µm``."""
    if unit in _SPELLING:
        return _SPELLING[unit]
    return unit.replace("^2", "²").replace("^3", "³").replace("*", "·").replace(" ", "·")


def engineering_array(values: np.ndarray, unit: str, key: str = "") -> tuple[np.ndarray, str]:
    """SI ``values`` in ``unit`` named ``key`` → (values, unit) in the engineer's unit, one unit
    for all (chosen by the largest magnitude); units without a display keep their spelling."""
    values = np.asarray(values, dtype=float)
    kind = display_kind(unit, key)
    if kind is None:
        return values, spelling(unit)
    shown, symbol = to_display(values, kind)
    return np.asarray(shown), symbol


def engineering(value: float, unit: str, key: str = "") -> tuple[float, str]:
    """One SI ``value`` in ``unit`` named ``key`` → (value, unit) in the engineer's unit:
    963.3 MPa, 1500 rpm, 40 mm, 2.43 µm of wear, 20 °C, 1410 N/µm, 8 h. Non-numbers pass."""
    if not isinstance(value, int | float) or isinstance(value, bool) or not math.isfinite(value):
        return value, spelling(unit)
    shown, symbol = engineering_array(np.array([float(value)]), unit, key)
    return float(shown[0]), symbol


_NUT = re.compile(r"\bnut(\d+)\b")
#: Case sections a name may start with; the words leave them out.
_SECTIONS = {"operating", "numerics", "screw", "surface", "medium", "nuts"}
#: Summary keys that only group entries; the words leave them out.
_GROUPS = {"steady", "numerical", "recommended", "heat_balance", "contacts", "nuts", "margins"}


#: Summary keys whose name alone would mislead: the design check's stiffnesses, which an engineer
#: compares with the catalogue's nut rigidity.
_WORDS = {
    "axial_stiffness": "nut + shaft stiffness (supports rigid)",
    "drive_stiffness": "drive stiffness, nut + shaft + supports",
    "nut_stiffness": "nut stiffness alone (contacts + bodies)",
}


def readable(name: str) -> str:
    """A field name or dotted summary key as words, for tables, plot axes and the console:
    ``nuts.nut1.orbital_speed`` → ``nut 1: orbital speed``, ``operating.axial_load`` →
    ``axial load``, ``contacts.screw.numerical.peak_pressure`` → ``screw: peak pressure``,
    ``margins.speed.ratio`` → ``speed margin (capacity/demand)``, ``F1`` → ``F1``,
    ``axial_stiffness`` → ``nut + shaft stiffness (supports rigid)``."""
    if name in _WORDS:
        return _WORDS[name]
    parts = [p for p in name.split(".") if p]
    if len(parts) == 3 and parts[0] == "margins" and parts[2] == "ratio":
        return f"{readable(parts[1])} margin (capacity/demand)"
    if len(parts) > 1 and parts[0] in _SECTIONS:
        parts = parts[1:]
    parts = [p for p in parts if p not in _GROUPS] or parts[-1:]
    return ": ".join(_NUT.sub(r"nut \1", p.replace("_", " ")) for p in parts)
