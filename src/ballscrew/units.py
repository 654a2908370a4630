"""Unit handling at the edges of ballscrew.

Inside the package every quantity is a float in SI units. Case files may give a number (taken as
SI) or a string with a unit (``"10 mm"``, ``"1000 rpm"``, ``"45 deg"``); :func:`to_si` converts
such strings, checking that the dimension is the expected one.

A string is read as ONE finite decimal number followed by ONE unit expression: unit names joined
by ``*``, ``/``, spaces and parentheses, with small integer exponents (``W/(m^2*K)``, ``1/Pa``).
There is never arithmetic on numbers, so no string can hang the reader or overflow.

Dimensions are checked strictly, with the angle as a dimension of its own: a dimensionless unit
(``%``, ``ppm``) is no length, ``"45 deg deg"`` is no angle. For a rotational speed a frequency
(``Hz``, ``1/s``) means revolutions per second; for a temperature difference ``degC`` and
``degF`` mean a difference (``"10 degC"`` = 10 K), for an absolute temperature a point on the
scale (``"20 degC"`` = 293.15 K).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from functools import cache
from typing import Any

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
    "stiffness": "N/m",
    "volume_flow": "m^3/s",
    "heat_capacity": "J/K",
    "dimensionless": "",
}

#: Longest quantity string read (longer ones are refused before parsing).
MAX_LENGTH = 200

#: Deepest nesting of parentheses in a unit expression.
MAX_DEPTH = 3

_NUMBER = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d{1,4})?)(.*)", re.DOTALL)
_TOKEN = re.compile(
    r"\s*(?:(?P<name>°?[^\W\d]+|%)|(?P<one>1(?=\s*/))|(?P<power>\^|\*\*)\s*(?P<exp>[+-]?[1-9])"
    r"(?![\d.])|(?P<op>[*/·])|(?P<open>\()|(?P<close>\)))"
)


@cache
def registry() -> pint.UnitRegistry:
    """The package-wide pint registry (created on first use)."""
    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    ureg.formatter.default_format = "~P"
    return ureg


def _expected(kind: str) -> str:
    """Text naming the SI unit of ``kind`` in error messages."""
    return SI_UNITS[kind] or "no unit"


def _short(value: object) -> str:
    """``repr(value)`` cut to a length that fits in a one-line message."""
    text = repr(value)
    return text if len(text) <= 60 else f"{text[:57]}..."


def _check_unit_syntax(text: str) -> str:
    """``text`` in pint spelling after checking it is a plain unit expression (no numbers)."""
    depth, previous, pos, pieces = 0, "op", 0, []
    while pos < len(text.rstrip()):
        match = _TOKEN.match(text, pos)
        if match is None:
            raise ValueError(f"unexpected {text[pos:].strip()!r}")
        token = match.lastgroup if match.lastgroup != "exp" else "power"
        if token == "power" and previous not in ("name", "close"):
            raise ValueError("an exponent must follow a unit name or ')'")
        depth += {"open": 1, "close": -1}.get(token, 0)
        if not 0 <= depth <= MAX_DEPTH:
            raise ValueError(f"unbalanced or too deeply nested parentheses (at most {MAX_DEPTH})")
        if token == "name":
            pieces.append(" " + ("percent" if match["name"] == "%" else match["name"]))
        elif token == "power":
            pieces.append(f"**{match['exp']}")
        elif token == "op":
            pieces.append("*" if match["op"] == "·" else match["op"])
        else:
            pieces.append(" " + match[0].strip())
        previous, pos = token, match.end()
    if depth:
        raise ValueError("unbalanced parentheses")
    unit = "".join(pieces).strip()
    return f"1{unit}" if unit.startswith("/") else unit


def parse_quantity(text: str) -> tuple[float, pint.Unit | None]:
    """Split ``text`` into a finite number and a pint unit (None when there is no unit).

    Raises ``ValueError`` for anything but one decimal number followed by one unit expression.
    """
    if len(text) > MAX_LENGTH:
        raise ValueError(f"longer than {MAX_LENGTH} characters")
    match = _NUMBER.fullmatch(text)
    if match is None:
        raise ValueError("it must be a number followed by a unit, e.g. '10 mm'")
    magnitude = float(match[1])
    if not math.isfinite(magnitude):
        raise ValueError(f"the number {match[1]} is not finite")
    unit_text = _check_unit_syntax(match[2])
    if not unit_text:
        return magnitude, None
    try:
        unit = registry().parse_units(unit_text)
    except Exception as exc:  # pint raises several unrelated types for unknown names
        raise ValueError(f"unknown unit {_short(match[2].strip())}") from exc
    return magnitude, unit


def _frequency_as_speed(unit: pint.Unit, kind: str) -> float:
    """2π when ``unit`` is a frequency given for a rotational speed (revolutions per time)."""
    if kind != "angular_velocity":
        return 1.0
    _, root = registry().get_root_units(unit)
    return 2.0 * math.pi if root == registry().parse_units("1/s") else 1.0


def _convert(magnitude: float, unit: pint.Unit, kind: str) -> float:
    """``magnitude`` in ``unit`` as a float in the SI unit of ``kind`` (dimension checked)."""
    ureg = registry()
    target = ureg.parse_units(SI_UNITS[kind])
    if kind != "dimensionless" and any(
        ureg.get_root_units(name)[1] == ureg.dimensionless for name in unit._units
    ):
        raise pint.DimensionalityError(unit, target)  # %, ppm: no scale for a dimensional value
    factor = _frequency_as_speed(unit, kind)
    if ureg.get_root_units(unit)[1] != ureg.get_root_units(target)[1] and factor == 1.0:
        raise pint.DimensionalityError(unit, target)
    quantity = ureg.Quantity(magnitude * factor, unit)
    if kind == "temperature_difference":
        quantity = quantity - ureg.Quantity(0.0, unit)
    return float(quantity.to(target if factor == 1.0 else "1/s").magnitude)


def to_si(value: object, kind: str) -> float:
    """Convert ``value`` to a float in the SI unit of ``kind``.

    Numbers are returned unchanged (already SI) if finite. Strings are one number and one unit
    (see the module docstring) and must have the dimension of ``kind``; a bare number in a
    string is taken as SI. Raises ``ValueError`` with a message that names the expected unit
    when the value cannot be read, has the wrong dimension or is not finite.
    """
    unit_name = _expected(kind)
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ValueError(f"expected a number or a string such as '10 {SI_UNITS[kind]}'")
    if isinstance(value, int | float):
        try:
            number = float(value)
        except OverflowError:
            number = math.inf
        if not math.isfinite(number):
            raise ValueError(f"{_short(value)} is not a finite number (in {unit_name})")
        return number
    try:
        magnitude, unit = parse_quantity(value)
    except ValueError as exc:
        raise ValueError(
            f"cannot read {_short(value)} as a quantity in {unit_name}: {exc}"
        ) from None
    if unit is None:
        return magnitude
    try:
        result = _convert(magnitude, unit, kind)
    except pint.DimensionalityError:
        noun = kind.replace("_", " ")
        article = "an" if noun[0] in "aeiou" else "a"
        raise ValueError(
            f"{_short(value)} is not {article} {noun} (expected {unit_name})"
        ) from None
    except (pint.PintError, ArithmeticError):
        result = math.nan
    if not math.isfinite(result):
        raise ValueError(f"{_short(value)} cannot be expressed as a finite number of {unit_name}")
    return result


def split_list(items: str | Sequence[Any]) -> list[Any]:
    """The items of a comma list given on the command line or in Python: ``"a, b"`` or
    ``["a", " b"]`` → ``["a", "b"]``. Each text item is stripped; empty ones (``"a,,b"``, a
    trailing comma, ``""``) are dropped, so the caller decides whether an empty list is an
    error. Items that are not text pass unchanged, for the caller's check to name them."""
    parts = items.split(",") if isinstance(items, str) else list(items)
    stripped = [p.strip() if isinstance(p, str) else p for p in parts]
    return [p for p in stripped if p != ""]


# --- Display in engineering units ---------------------------------------------------------------


#: Engineering display units of each kind: (symbol, SI value of one display unit) from the
#: smallest to the largest; a value is shown in the largest unit it reaches (at least 1), so
#: 9.633e8 Pa reads 963.3 MPa. One spelling each: µm, N·m, °C, rpm.
DISPLAY_UNITS: dict[str, tuple[tuple[str, float], ...]] = {
    "length": (("nm", 1e-9), ("µm", 1e-6), ("mm", 1e-3), ("m", 1.0)),
    "displacement": (("µm", 1e-6),),
    "area": (("mm²", 1e-6), ("m²", 1.0)),
    "angle": (("°", math.pi / 180.0),),
    "force": (("N", 1.0), ("kN", 1e3), ("MN", 1e6)),
    "pressure": (("Pa", 1.0), ("kPa", 1e3), ("MPa", 1e6), ("GPa", 1e9)),
    "angular_velocity": (("rpm", math.pi / 30.0),),
    "velocity": (("mm/s", 1e-3), ("m/s", 1.0)),
    "temperature": (("°C", 1.0),),
    "temperature_difference": (("K", 1.0),),
    "time": (("s", 1.0), ("min", 60.0), ("h", 3600.0)),
    "duration": (("s", 1.0), ("h", 3600.0)),
    "power": (("W", 1.0), ("kW", 1e3)),
    "torque": (("N·m", 1.0),),
    "stiffness": (("N/µm", 1e6),),
    "viscosity": (("mPa·s", 1e-3), ("Pa·s", 1.0)),
    "thermal_resistance": (("K/W", 1.0),),
    "area_resistance": (("mm²·K/W", 1e-6), ("m²·K/W", 1.0)),
    "heat_transfer_coefficient": (("W/(m²·K)", 1.0),),
    "thermal_conductivity": (("W/(m·K)", 1.0),),
    "energy": (("J", 1.0), ("kJ", 1e3), ("MJ", 1e6)),
    "revolutions": (("rev", 1.0),),
    "percent": (("%", 0.01),),
    "kinematic_viscosity": (("mm²/s", 1e-6),),
    "volume_flow": (("L/min", 1e-3 / 60.0),),
    "dimensionless": (("", 1.0),),
}

#: Display unit of a zero of each kind whose smallest unit would read oddly (0 nm).
ZERO_UNITS: dict[str, str] = {"length": "mm"}

#: Largest magnitude (SI) of each kind that is solver noise, not data: far below any physical
#: value of a ball screw (1e-9 rpm, 1e-15 m) and far above float round-off of typical values.
NOISE_FLOOR: dict[str, float] = {
    "length": 1e-15,
    "displacement": 1e-15,
    "angular_velocity": 1e-10,
    "velocity": 1e-12,
    "force": 1e-9,
    "torque": 1e-12,
    "power": 1e-9,
    "angle": 1e-12,
}

#: Kind of a summary value from its SI unit (the unit spelling of ``summary.json``).
KIND_OF_UNIT: dict[str, str] = {
    "m": "length",
    "m^2": "area",
    "rad": "angle",
    "N": "force",
    "Pa": "pressure",
    "rad/s": "angular_velocity",
    "m/s": "velocity",
    "K": "temperature_difference",
    "s": "time",
    "W": "power",
    "J": "energy",
    "N*m": "torque",
    "N/m": "stiffness",
    "Pa*s": "viscosity",
    "K/W": "thermal_resistance",
    "m^2*K/W": "area_resistance",
    "W/(m^2*K)": "heat_transfer_coefficient",
    "W/(m*K)": "thermal_conductivity",
    "rev": "revolutions",
    "m^2/s": "kinematic_viscosity",
    "m^3/s": "volume_flow",
    "": "dimensionless",
}

#: Lengths that are small displacements (shown in µm whatever their size).
_DISPLACEMENTS = ("depth", "elongation", "displacement", "approach", "deflection")
#: Words that make a temperature a difference (kelvin), not an absolute value (°C).
_DIFFERENCES = ("rise", "difference", "delta", "error")


def display_kind(unit: str, key: str = "") -> str | None:
    """The display kind of a value in SI ``unit`` named ``key`` (a dotted summary key or a case
    field); None when the unit has no engineering display. An absolute temperature (a key that
    names a temperature, not a rise) is in °C, a worn depth or elongation in µm, a count of
    revolutions in rev, a relative difference in %."""
    name = key.rsplit(".", 1)[-1].lower()
    if not unit and "relative_difference" in key.lower():
        return "percent"
    if unit == "K" and "temperature" in name and not any(w in name for w in _DIFFERENCES):
        return "temperature"
    if not unit and ("revolutions" in name or name.endswith("_life")):
        return "revolutions"
    if unit == "m" and any(word in name for word in _DISPLACEMENTS):
        return "displacement"
    return KIND_OF_UNIT.get(unit)


_CELSIUS = 273.15
_EXPONENT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def format_number(value: float, digits: int = 4) -> str:
    """``value`` to ``digits`` significant figures, plainly written (``74.24``, ``12000``,
    ``0.1198``); beyond 1e-3 … 1e6 as ``1.44×10⁶``. Trailing zeros are dropped."""
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    if value == 0.0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    rounded = round(value, digits - 1 - exponent)
    if rounded != 0.0:
        exponent = math.floor(math.log10(abs(rounded)))  # 9.9996 → 10.00 moves up a decade
    if -3 <= exponent < 6:
        text = f"{rounded:.{max(0, digits - 1 - exponent)}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    mantissa = f"{rounded / 10.0**exponent:.{digits - 1}f}".rstrip("0").rstrip(".")
    return f"{mantissa}×10{str(exponent).translate(_EXPONENT)}"


def display_unit(kind: str, magnitude: float = 1.0) -> tuple[str, float]:
    """(symbol, SI value of one symbol) in which to show SI values of ``kind`` up to about
    ``magnitude`` — for a table column or a plot axis, divide the values by the second item.

    ``kind`` is a key of :data:`DISPLAY_UNITS` or an SI unit of :data:`KIND_OF_UNIT`. For
    ``temperature`` the values must first be shifted by −273.15 (see :func:`to_display`).
    """
    kind = KIND_OF_UNIT.get(kind, kind)
    units = DISPLAY_UNITS[kind]
    size = abs(float(magnitude))
    if size == 0.0 and kind in ZERO_UNITS:  # a zero stroke reads 0 mm, not 0 nm
        return next(u for u in units if u[0] == ZERO_UNITS[kind])
    chosen = units[0]
    for symbol, scale in units:
        if size >= scale * (1.0 - 1e-12):
            chosen = (symbol, scale)
    return chosen


def to_display(values: object, kind: str, magnitude: float | None = None) -> tuple[object, str]:
    """(values in the display unit, its symbol): SI ``values`` (a number or a numpy array) of
    ``kind`` for a plot axis or a table; ``magnitude`` picks the unit (default: the largest
    value)."""
    import numpy as np

    array = np.asarray(values, dtype=float)
    if kind == "temperature":
        return array - _CELSIUS, "°C"
    if magnitude is None:
        finite = np.abs(array[np.isfinite(array)])
        magnitude = float(finite.max()) if finite.size else 1.0
    symbol, scale = display_unit(kind, magnitude)
    return array / scale, symbol


SIDE_BY_SIDE_SPREAD = 100.0
"""Largest over smallest value above which :func:`in_display_units` picks the unit by their
geometric mean, not by the largest."""


def in_display_units(values: Sequence[float], unit: str) -> tuple[tuple[float, ...], str]:
    """SI ``values`` of one quantity, in their ``summary.json`` unit spelling (``"N"``,
    ``"rad/s"``), in ONE engineering unit, so values set side by side (a demand and its
    capacity) read alike: ``((800.0, 1.2e4), "N")`` → ``((0.8, 12.0), "kN")``.

    The largest finite value picks the unit; where it is :data:`SIDE_BY_SIDE_SPREAD` times the
    smallest non-zero one or more, their geometric mean does, so neither reads as a tiny
    fraction: ``((881.0, 2e7), "N")`` → ``((0.881, 2e4), "kN")``, not 8.81×10⁻⁴ MN. A unit with
    no engineering display (``"h"``, ``"mm·rpm"``) is kept, the values as given."""
    numbers = tuple(float(v) for v in values)
    kind = KIND_OF_UNIT.get(unit)
    if kind is None:
        return numbers, unit
    sizes = [abs(v) for v in numbers if math.isfinite(v)]
    magnitude = max(sizes, default=1.0)
    smallest = min((v for v in sizes if v > 0.0), default=magnitude)
    if magnitude >= SIDE_BY_SIDE_SPREAD * smallest:
        magnitude = math.sqrt(magnitude * smallest)
    shown, symbol = to_display(numbers, kind, magnitude)
    return tuple(float(v) for v in shown), symbol


def format_quantity(
    value: float, kind: str, digits: int = 4, zero_below: float | None = None
) -> str:
    """``value`` (SI) of ``kind`` in engineering units, e.g. ``format_quantity(9.633e8,
    "pressure")`` → ``"963.3 MPa"``, ``format_quantity(74.24e-6, "displacement")`` →
    ``"74.24 µm"``, ``format_quantity(293.15, "temperature")`` → ``"20 °C"``.

    ``kind``: a key of :data:`DISPLAY_UNITS` or an SI unit of :data:`KIND_OF_UNIT`. A value
    smaller in magnitude than ``zero_below`` (default: the kind's :data:`NOISE_FLOOR`) is
    solver noise and shown as 0.
    """
    kind = KIND_OF_UNIT.get(kind, kind)
    if kind not in DISPLAY_UNITS:
        raise ValueError(f"unknown kind {kind!r}; one of {', '.join(DISPLAY_UNITS)}")
    value = float(value)
    floor = NOISE_FLOOR.get(kind, 0.0) if zero_below is None else zero_below
    if kind == "temperature":
        number, symbol = value - _CELSIUS, "°C"
    elif abs(value) < floor:
        number, symbol = 0.0, display_unit(kind, 0.0)[0]
    else:
        symbol, scale = display_unit(kind, value)
        number = value / scale
    return f"{format_number(number, digits)} {symbol}".rstrip()
