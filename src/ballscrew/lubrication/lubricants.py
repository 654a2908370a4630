"""Named lubricants: inlet viscosity η₀ and Barus pressure–viscosity coefficient α_p at 40 °C.

Data, not physics. Each entry says where its numbers come from:

* Kinematic viscosity: the mid-point of the ISO viscosity grade (ISO 3448:1992, "Industrial
  liquid lubricants — ISO viscosity classification": VG n has ν = n mm²/s at 40 °C, ±10 %).
* Density: 870 kg/m³ at 40 °C for a paraffinic mineral oil [ASSUMED; typical 860–880 kg/m³],
  so η₀ = ρ ν.
* α_p: 2.1e-8 Pa⁻¹ for the ISO VG 68 class is the value of the reference screw of
  ``examples/wear_step_stress.toml``; the other grades are graded around it within the range usually
  quoted for mineral oils at 40 °C, about 1.5–2.5e-8 Pa⁻¹ (Hamrock, *Fundamentals of Fluid Film
  Lubrication*, 1994; Harris & Kotzalas, *Rolling Bearing Analysis*, 2006) [ASSUMED: typical, not
  measured values].
* Greases: EHL films of greased contacts are governed by the base oil (Harris & Kotzalas 2006),
  so a grease entry carries its base oil's values; it does not model starvation.

Use measured η₀ and α_p of the actual lubricant in ``[medium]`` when they are known; they take
precedence over a named lubricant.
"""

from __future__ import annotations

from dataclasses import dataclass

from ballscrew.errors import InputError

__all__ = ["LUBRICANTS", "Lubricant", "lubricant"]

_DENSITY = 870.0  # kg/m³, paraffinic mineral oil at 40 °C [ASSUMED]


@dataclass(frozen=True)
class Lubricant:
    """EHL properties of a lubricant at its inlet temperature."""

    name: str
    viscosity: float
    """Dynamic viscosity η₀ [Pa s]."""
    pressure_viscosity: float
    """Barus coefficient α_p [1/Pa]."""
    source: str
    """Where the numbers come from."""


def _mineral(grade: int, alpha: float, label: str | None = None) -> Lubricant:
    return Lubricant(
        name=label or f"ISO VG {grade} mineral oil",
        viscosity=_DENSITY * grade * 1e-6,
        pressure_viscosity=alpha,
        source=(
            f"ν = {grade} mm²/s at 40 °C (ISO 3448 grade mid-point), ρ = 870 kg/m³ [ASSUMED]; "
            f"α_p = {alpha:.2g} 1/Pa, typical mineral oil at 40 °C [ASSUMED]"
        ),
    )


LUBRICANTS: dict[str, Lubricant] = {
    "iso_vg_32": _mineral(32, 1.9e-8),
    "iso_vg_68": _mineral(68, 2.1e-8),
    "iso_vg_100": _mineral(100, 2.2e-8),
    "iso_vg_220": _mineral(220, 2.4e-8),
    "lithium_grease_vg_100": _mineral(
        100, 2.2e-8, "lithium-soap grease, ISO VG 100 mineral base oil (base-oil values)"
    ),
}
"""Named lubricants by key (``[kinematics] lubricant = "iso_vg_68"``)."""


def lubricant(name: str) -> Lubricant:
    """The named lubricant ``name``; :class:`InputError` lists the known names otherwise."""
    try:
        return LUBRICANTS[name]
    except KeyError:
        raise InputError("lubricant", name, "one of " + ", ".join(sorted(LUBRICANTS))) from None
