"""Named materials of balls, screw shafts and nuts, with their sources (data, not physics).

A case uses them as ``[materials.ball] material = "Si3N4"``; any property the case gives as well
overrides the library's value. Each entry is one frozen :class:`MaterialData` in SI units.

Conventions shared by the entries:

* Hardness H is the Vickers hardness in pressure units, H = HV · g (HV in kgf/mm², g =
  9.80665 m/s²), at the surface hardness a maker states; Rockwell C is converted to Vickers by
  the ASTM E140 table (HRC 58 ≈ HV 653, HRC 60 ≈ HV 697, HRC 62 ≈ HV 746).
* Yield strength of a hardened steel is Tabor's σ_y = H/2.8 (Tabor, *The Hardness of Metals*,
  1951), the relation the reference example uses; a ceramic has no yield point, so its entry
  carries H/2.8 as an equivalent flow stress for the fractal plasticity index [ASSUMED].
* Room-temperature (20–100 °C) values.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

from ballscrew.errors import InputError

__all__ = [
    "MATERIALS",
    "PROPERTY_NAMES",
    "Material",
    "MaterialData",
    "material",
    "material_properties",
]

_G = 9.80665  # m/s², kgf → N
_TABOR = 2.8


def _vickers(hv: float) -> float:
    """H [Pa] of a Vickers hardness HV [kgf/mm²]."""
    return hv * _G * 1e6


@dataclass(frozen=True)
class Material:
    """Mechanical and thermal properties of one part (SI)."""

    youngs_modulus: float
    """E [Pa]."""
    poissons_ratio: float
    """ν [-]."""
    hardness: float
    """Indentation hardness H [Pa]."""
    yield_strength: float
    """σ_y [Pa]."""
    thermal_conductivity: float
    """λ [W/(m K)]."""
    density: float
    """ρ [kg/m³]."""
    specific_heat: float
    """c_p [J/(kg K)]."""
    thermal_expansion: float
    """α_T [1/K]."""


@dataclass(frozen=True)
class MaterialData(Material):
    """A named material of the library: its properties, name and source."""

    name: str = ""
    source: str = ""
    """Where the numbers come from."""


PROPERTY_NAMES: tuple[str, ...] = tuple(f.name for f in fields(Material))
"""The eight property fields, as the case's ``[materials.*]`` tables name them."""


def _entry(name: str, e: float, nu: float, hv: float, lam: float, rho: float, cp: float,
           alpha: float, source: str) -> MaterialData:  # fmt: skip
    h = _vickers(hv)
    return MaterialData(e, nu, h, h / _TABOR, lam, rho, cp, alpha, name=name, source=source)


def _alias(name: str, of: MaterialData, label: str) -> MaterialData:
    return replace(of, name=name, source=f"alias of {of.name} (same steel, {label} name)")


_100CR6 = _entry(
    "100Cr6",
    203e9,
    0.3,
    697.0,
    46.6,
    7833.0,
    475.0,
    11.9e-6,
    "through-hardened bearing steel 100Cr6 = AISI 52100 = SUJ2 (ASTM A295): E = 29.5e6 psi and "
    "ρ = 0.283 lb/in³ (52100 ball maker's data sheet, 'AISI 52100 Chrome Steel'); λ = 46.6 "
    "W/(m K), c_p = 475 J/(kg K), α_T = 11.9e-6 1/K (handbook values quoted by the reference "
    "example); ν = 0.3 [ASSUMED typical steel]; HRC 60, the makers' lower raceway hardness "
    "(HRC 58–62, NBS ball-screw catalogue §2.5.2)",
)
_42CRMO4 = _entry(
    "42CrMo4",
    210e9,
    0.3,
    653.0,
    42.6,
    7850.0,
    473.0,
    11.1e-6,
    "quenched-and-tempered 42CrMo4 = 1.7225 = SCM440 = AISI 4140, raceways induction or case "
    "hardened to HRC 58 (nut and shaft steel of rolled screws) [ASSUMED typical handbook values "
    "for 4140: E = 210 GPa, ρ = 7850 kg/m³, λ = 42.6 W/(m K), c_p = 473 J/(kg K), α_T = 11.1e-6 "
    "1/K]",
)
MATERIALS: dict[str, MaterialData] = {
    m.name: m
    for m in (
        _100CR6,
        _alias("52100", _100CR6, "AISI"),
        _entry(
            "440C", 200e9, 0.28, 697.0, 24.2, 7650.0, 460.0, 10.1e-6,
            "martensitic stainless steel X105CrMo17 = 1.4125 = AISI 440C (EN 10088/ASTM A276), "
            "hardened: E = 200 GPa, ρ = 7650 kg/m³, α_T = 10.1e-6 1/K (0–100 °C), λ = 24.2 "
            "W/(m K), c_p = 460 J/(kg K) (Qinghe Steels 440C data sheet); ν = 0.28 (MakeItFrom, "
            "440C); HRC 60 after a 150–200 °C temper (Rolled Alloys 440C data sheet)",
        ),
        _entry(
            "M50", 214e9, 0.3, 746.0, 25.0, 7870.0, 460.0, 11.21e-6,
            "AISI M50 (80MoCrV42-16) VIM-VAR bearing steel: ρ = 7.87 g/cm³, α_T = 11.21e-6 1/K "
            "(21–93 °C), E = 214 GPa, HRC 62–64 (BTI Metals M50 data sheet); λ = 25 W/(m K), "
            "c_p = 460 J/(kg K) and ν = 0.3 [ASSUMED: typical high-alloy tool steel]",
        ),
        _42CRMO4,
        _alias("SCM440", _42CRMO4, "JIS"),
        _entry(
            "Si3N4", 310e9, 0.27, 1580.0, 30.0, 3290.0, 680.0, 3.3e-6,
            "hot-pressed silicon nitride (HP-Si3N4) bearing balls: E = 310 GPa, ν = 0.27, "
            "ρ = 3.29 g/cm³, HV 1580, λ = 30 W/(m K), α_T = 3.3e-6 1/K (Lily Bearing, 'Ceramic "
            "materials and their properties' table); c_p = 680 J/(kg K) [ASSUMED typical]",
        ),
        _entry(
            "ZrO2", 200e9, 0.3, 1300.0, 2.0, 6040.0, 460.0, 10.3e-6,
            "yttria-stabilised zirconia (ZrO2-Y2O3) balls: E = 200 GPa, ρ = 6.04 g/cm³, HV "
            "1300, λ = 2 W/(m K), α_T = 10.3e-6 1/K (Lily Bearing, 'Ceramic materials and their "
            "properties' table); ν = 0.3 and c_p = 460 J/(kg K) [ASSUMED typical]",
        ),
    )
}  # fmt: skip
"""Named materials by name (``material = "100Cr6"``)."""


def material(name: str, field: str = "material") -> MaterialData:
    """The named material ``name``; :class:`InputError` lists the known names otherwise."""
    try:
        return MATERIALS[name]
    except (KeyError, TypeError):
        raise InputError(field, name, "one of " + ", ".join(MATERIALS)) from None


def material_properties(name: str, field: str = "material") -> dict[str, float]:
    """The eight properties of the named material as a dict of SI numbers."""
    data = material(name, field)
    return {key: getattr(data, key) for key in PROPERTY_NAMES}
