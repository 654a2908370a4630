"""A library of named lubricants with their properties against temperature.

Each :class:`LibraryLubricant` holds ν40, ν100 and ρ15 and answers :meth:`LibraryLubricant.at`
with η(T), α_p(T), ρ(T), λ(T) and the temperature–viscosity coefficient β(T), from
:mod:`ballscrew.lubrication.viscosity` (ASTM D341, Gold et al. 2001, Cragoe 1929).

Data, each entry saying where its numbers come from:

* Oils: ν40 = the ISO VG grade mid-point (ISO 3448:1992). ν100 [ASSUMED]: a typical value of a
  paraffinic mineral oil of viscosity index ≈ 95–100 (the range of solvent-refined HM hydraulic
  and CKD gear oils), rounded to 0.05 mm²/s; not a particular product. Their ASTM D2270 VIs
  (:attr:`LibraryLubricant.viscosity_index`) are 95.6–100.5. ρ15 [ASSUMED]: 860–890
  kg/m³ rising with the grade, typical of paraffinic mineral oils.
* Greases: the EHL film of a greased contact is governed by its base oil (Harris & Kotzalas,
  *Rolling Bearing Analysis*, 2006), so an entry carries the base oil's ν40, ν100 and ρ15, and its
  thickener and NLGI consistency grade (NLGI/ASTM D217) as data. Base-oil grades are typical of
  each grease family [ASSUMED].
"""

from __future__ import annotations

from dataclasses import dataclass

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.lubrication.viscosity import (
    T_REF_15C,
    Walther,
    density,
    pressure_viscosity_coefficient,
    thermal_conductivity,
    viscosity_index,
)
from ballscrew.validation import positive

__all__ = ["LUBRICANT_LIBRARY", "LibraryLubricant", "LubricantState", "library_lubricant"]

T40, T100 = 313.15, 373.15
"""The ASTM D2270 reference temperatures, 40 °C and 100 °C [K]."""
_EXPANSION = 6.4e-4  # 1/K, α_ρ of viscosity.density [ASSUMED typical]


@dataclass(frozen=True)
class LubricantState:
    """Properties of a lubricant (a grease: of its base oil) at one temperature."""

    temperature: float
    """T [K]."""
    viscosity: float
    """Dynamic viscosity η = ρ ν [Pa s]."""
    kinematic: float
    """Kinematic viscosity ν [m²/s]."""
    pressure_viscosity: float
    """Barus coefficient α_p [1/Pa]."""
    density: float
    """ρ [kg/m³]."""
    conductivity: float
    """Thermal conductivity λ [W/(m K)]."""
    temperature_viscosity: float
    """β = −(1/η) dη/dT [1/K]."""


@dataclass(frozen=True)
class LibraryLubricant:
    """A named oil or grease: its viscosities at 40 and 100 °C and its density at 15 °C."""

    name: str
    kind: str
    """"oil" or "grease"."""
    nu40: float
    """Kinematic viscosity at 40 °C [m²/s] (a grease: of its base oil)."""
    nu100: float
    """Kinematic viscosity at 100 °C [m²/s]."""
    density_15: float
    """Density at 15 °C [kg/m³]."""
    source: str
    """Where the numbers come from, and which are assumed."""
    thickener: str | None = None
    """Grease thickener (None for an oil)."""
    nlgi_grade: int | None = None
    """NLGI consistency grade of a grease (None for an oil)."""

    def __post_init__(self) -> None:
        if self.kind not in ("oil", "grease"):
            raise InputError("kind", self.kind, "oil or grease")
        positive("density_15", self.density_15, "kg/m³")
        self.walther  # noqa: B018 — refuses viscosities that do not fall with temperature

    @property
    def walther(self) -> Walther:
        """The ASTM D341 line through (40 °C, ν40) and (100 °C, ν100)."""
        return Walther.through(T40, self.nu40, T100, self.nu100, ("nu40", "nu100"))

    @property
    def viscosity_index(self) -> float:
        """ASTM D2270 viscosity index of ν40 and ν100 (a grease: of its base oil), unrounded."""
        return viscosity_index(self.nu40, self.nu100)

    def at(self, temperature: float) -> LubricantState:
        """Properties at ``temperature`` [K].

        ν(T): ASTM D341;  ρ(T) = ρ15 [1 − α_ρ (T − 288.15)];  η = ρ ν;
        α_p(T) = Gold et al. (2001) of ν(T);  λ(T): Cragoe (1929);
        β = β_ν + α_ρ/[1 − α_ρ (T − 288.15)],  β_ν from the D341 line.
        """
        walther = self.walther
        nu = walther.kinematic(temperature)
        rho = density(temperature, self.density_15, _EXPANSION)
        beta_rho = _EXPANSION / (1.0 - _EXPANSION * (temperature - T_REF_15C))
        return LubricantState(
            temperature=float(temperature),
            viscosity=rho * nu,
            kinematic=nu,
            pressure_viscosity=pressure_viscosity_coefficient(nu),
            density=rho,
            conductivity=thermal_conductivity(temperature, self.density_15),
            temperature_viscosity=walther.temperature_coefficient(temperature) + beta_rho,
        )

    def temperature_at(self, viscosity: float) -> float:
        """The temperature [K] at which the dynamic viscosity is ``viscosity`` [Pa s].

        Inverse of :meth:`at`: T = T_D341(η/ρ(T)), the ASTM D341 line inverted at the
        kinematic viscosity, iterated on the density (α_ρ (ΔT) ≪ 1: a few steps).
        """
        eta = positive("viscosity", viscosity, "Pa s")
        walther = self.walther
        temperature = walther.temperature(eta / self.density_15)
        for _ in range(50):
            rho = density(temperature, self.density_15, _EXPANSION)
            new = walther.temperature(eta / rho)
            if abs(new - temperature) < 1e-9:
                return new
            temperature = new
        raise ConvergenceError("lubricant temperature", 50, abs(new - temperature), 1e-9)


_MM2 = 1e-6
_OIL_SOURCE = (
    "ν40 = ISO VG mid-point (ISO 3448); ν100 typical of a VI ≈ 95–100 paraffinic mineral oil "
    "[ASSUMED]; ρ15 typical [ASSUMED]"
)
# ISO VG → (ν100 [mm²/s], ρ15 [kg/m³]), both [ASSUMED typical of VI ≈ 95–100 mineral oils].
_MINERAL_OILS = {
    10: (2.65, 860.0),
    15: (3.4, 860.0),
    22: (4.3, 865.0),
    32: (5.35, 870.0),
    46: (6.7, 875.0),
    68: (8.6, 880.0),
    100: (11.1, 880.0),
    150: (14.6, 885.0),
    220: (18.9, 890.0),
    320: (24.1, 895.0),
    460: (30.5, 900.0),
}
# key → (thickener, NLGI grade, base-oil ISO VG), all typical of the family [ASSUMED].
_GREASES = {
    "lithium_nlgi2_vg32": ("lithium soap", 2, 32),
    "lithium_nlgi2_vg100": ("lithium soap", 2, 100),
    "lithium_complex_nlgi2_vg220": ("lithium complex soap", 2, 220),
    "calcium_sulfonate_nlgi2_vg320": ("calcium sulfonate complex", 2, 320),
    "polyurea_nlgi2_vg100": ("polyurea", 2, 100),
}


def _oil(grade: int) -> LibraryLubricant:
    nu100, rho15 = _MINERAL_OILS[grade]
    return LibraryLubricant(
        f"ISO VG {grade} mineral oil", "oil", grade * _MM2, nu100 * _MM2, rho15, _OIL_SOURCE
    )


def _grease(thickener: str, nlgi: int, grade: int) -> LibraryLubricant:
    base = _oil(grade)
    return LibraryLubricant(
        f"{thickener} grease NLGI {nlgi}, ISO VG {grade} mineral base oil",
        "grease",
        base.nu40,
        base.nu100,
        base.density_15,
        f"base oil: {_OIL_SOURCE}; thickener and NLGI grade typical of the family [ASSUMED]",
        thickener,
        nlgi,
    )


LUBRICANT_LIBRARY: dict[str, LibraryLubricant] = {
    **{f"iso_vg_{g}": _oil(g) for g in _MINERAL_OILS},
    **{key: _grease(*spec) for key, spec in _GREASES.items()},
}
"""Named lubricants by key: ``iso_vg_10`` … ``iso_vg_460`` and the greases."""


def library_lubricant(name: str) -> LibraryLubricant:
    """The library lubricant ``name``; :class:`InputError` listing the known names otherwise."""
    try:
        return LUBRICANT_LIBRARY[name]
    except (KeyError, TypeError):
        raise InputError(
            "lubricant", name, "one of " + ", ".join(sorted(LUBRICANT_LIBRARY))
        ) from None
