"""Named lubricants at 40 °C: a view of the lubricant library.

:data:`LUBRICANTS` holds, for every entry of
:data:`~ballscrew.lubrication.lubricant_library.LUBRICANT_LIBRARY`, its dynamic viscosity η₀
and Barus coefficient α_p at 40 °C (ISO 3448's reference temperature), computed by the
library's laws (ASTM D341 viscosity, linear density, Gold et al. 2001 α_p). It is kept for code
that wants a lubricant at one temperature; a case takes its named lubricant from the library at
``[lubrication] temperature`` (default 40 °C), and the operating point at the contact
temperature.
"""

from __future__ import annotations

from dataclasses import dataclass

from ballscrew.errors import InputError
from ballscrew.lubrication.lubricant_library import LUBRICANT_LIBRARY, T40

__all__ = ["LUBRICANTS", "Lubricant", "lubricant"]


@dataclass(frozen=True)
class Lubricant:
    """EHL properties of a lubricant at 40 °C."""

    name: str
    viscosity: float
    """Dynamic viscosity η₀ [Pa s]."""
    pressure_viscosity: float
    """Barus coefficient α_p [1/Pa]."""
    source: str
    """Where the numbers come from."""


def _at_40c(key: str) -> Lubricant:
    entry = LUBRICANT_LIBRARY[key]
    state = entry.at(T40)
    return Lubricant(
        entry.name,
        state.viscosity,
        state.pressure_viscosity,
        f"{entry.source}; at 40 °C: η = ρ(40 °C) ν40, α_p of Gold et al. (2001)",
    )


LUBRICANTS: dict[str, Lubricant] = {key: _at_40c(key) for key in LUBRICANT_LIBRARY}
"""Named lubricants by key at 40 °C (the keys of the library, ``"iso_vg_68"`` …)."""


def lubricant(name: str) -> Lubricant:
    """The named lubricant ``name`` at 40 °C; :class:`InputError` lists the known names."""
    try:
        return LUBRICANTS[name]
    except (KeyError, TypeError):
        raise InputError("lubricant", name, "one of " + ", ".join(sorted(LUBRICANTS))) from None
