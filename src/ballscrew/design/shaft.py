"""Screw shaft: buckling load, critical speed, d·n, axial stiffness and thermal pretension.

The shaft is an Euler–Bernoulli beam of the root (thread minor) diameter d_r, I = π d_r⁴/64,
A = π d_r²/4. The makers publish the same two beam formulas with their constants folded in:

* buckling P = η₁ π² E I / l² (end-fixity factor η₁ = 1/4, 1, 2, 4 for fixed–free,
  supported–supported, fixed–supported, fixed–fixed); the permissible load is 0.5 P. THK writes
  0.5 P = η₂ d_r⁴/l² · 10⁴ (mm, N; η₂ = 1.3, 5, 10, 20; General Catalog A-694 eq. 6), HIWIN
  P = 4.072·10⁵ f_k d_r⁴/l² (f_k = 0.0625, 0.25, 0.5, 1; F 3.25);
* critical (whirling) speed ω = (λ₁/l)² √(E I/(ρ A)), :func:`ballscrew.kinematics.critical_speed`;
  the permissible speed is 0.8 ω. THK writes 0.8 ω = λ₂ d_r/l² · 10⁷ rpm (mm; λ₂ = 3.4, 9.7,
  15.1, 21.9; A-696 eq. 8), HIWIN ω = 2.71·10⁸ f_n d_r/l² rpm (f_n = 0.147, 0.446, 0.692, 1;
  F 3.27);
* permissible tension/compression σ_perm A with σ_perm = 147 MPa (THK A-694 eq. 7);
* axial stiffness A E/a with one end fixed (a: bearing to nut), A E l/(a (l − a)) with both
  (minimum 4 A E/l, nut in the middle; THK A-708 eqs. 32–33, HIWIN §3.7.7, Rexroth p. 105);
* free thermal elongation α ΔT l, and the pretension E A α ΔT that takes it up.
"""

from __future__ import annotations

import math

from ballscrew.errors import InputError
from ballscrew.validation import nonnegative, positive

__all__ = [
    "BUCKLING_SAFETY",
    "HIWIN_BUCKLING",
    "HIWIN_SPEED",
    "MOUNTINGS",
    "PERMISSIBLE_STRESS",
    "SPEED_SAFETY",
    "THK_BUCKLING",
    "THK_SPEED",
    "buckling_load",
    "maker_buckling_load",
    "maker_critical_speed",
    "permissible_tension",
    "shaft_axial_stiffness",
    "thermal_elongation",
    "thermal_pretension",
]

MOUNTINGS = ("fixed-free", "supported-supported", "fixed-supported", "fixed-fixed")
"""End fixities of the screw shaft."""

END_FIXITY: dict[str, float] = {
    "fixed-free": 0.25,
    "supported-supported": 1.0,
    "fixed-supported": 2.0,
    "fixed-fixed": 4.0,
}
"""Euler buckling factor η₁ (buckling load η₁ π² E I/l²; THK A-694)."""

BUCKLING_SAFETY = 0.5
"""Share of the buckling load the makers allow (THK A-694, HIWIN F 3.26)."""

SPEED_SAFETY = 0.8
"""Share of the critical speed the makers allow (THK A-696, HIWIN F 3.28)."""

PERMISSIBLE_STRESS = 147.0e6
"""Permissible tensile/compressive stress of the screw shaft, Pa (THK A-694 eq. 7)."""

THK_BUCKLING = {
    "fixed-free": 1.3,
    "supported-supported": 5.0,
    "fixed-supported": 10.0,
    "fixed-fixed": 20.0,
}
"""THK η₂: permissible load 0.5 P = η₂ d_r⁴/l² · 10⁴ N (d_r, l in mm)."""

THK_SPEED = {
    "fixed-free": 3.4,
    "supported-supported": 9.7,
    "fixed-supported": 15.1,
    "fixed-fixed": 21.9,
}
"""THK λ₂: permissible speed 0.8 ω = λ₂ d_r/l² · 10⁷ rpm (d_r, l in mm)."""

HIWIN_BUCKLING = {
    "fixed-free": 0.0625,
    "supported-supported": 0.25,
    "fixed-supported": 0.5,
    "fixed-fixed": 1.0,
}
"""HIWIN f_k: buckling load 4.072·10⁵ f_k d_r⁴/l² N (d_r, l in mm)."""

HIWIN_SPEED = {
    "fixed-free": 0.147,
    "supported-supported": 0.446,
    "fixed-supported": 0.692,
    "fixed-fixed": 1.0,
}
"""HIWIN f_n: critical speed 2.71·10⁸ f_n d_r/l² rpm (d_r, l in mm)."""

_RPM = 2.0 * math.pi / 60.0


def _mounting(mounting: str) -> str:
    if mounting not in MOUNTINGS:
        raise InputError("mounting", mounting, ", ".join(MOUNTINGS))
    return mounting


def buckling_load(
    root_diameter: float, length: float, youngs_modulus: float, mounting: str
) -> float:
    """Euler buckling load η₁ π² E I / l² of the shaft, N (without the makers' 0.5)."""
    d = positive("root_diameter", root_diameter, "m")
    l_b = positive("length", length, "m")
    e = positive("youngs_modulus", youngs_modulus, "Pa")
    inertia = math.pi * d**4 / 64.0
    return END_FIXITY[_mounting(mounting)] * math.pi**2 * e * inertia / l_b**2


def maker_buckling_load(root_diameter: float, length: float, mounting: str, maker: str) -> float:
    """Permissible buckling load 0.5 P by the maker's constant form, N.

    THK: η₂ d_r⁴/l² · 10⁴; HIWIN: 0.5 · 4.072·10⁵ f_k d_r⁴/l² (d_r, l in mm).
    """
    d = positive("root_diameter", root_diameter, "m") * 1e3
    l_b = positive("length", length, "m") * 1e3
    m = _mounting(mounting)
    if maker == "THK":
        return THK_BUCKLING[m] * d**4 / l_b**2 * 1.0e4
    if maker == "HIWIN":
        return BUCKLING_SAFETY * 4.072e5 * HIWIN_BUCKLING[m] * d**4 / l_b**2
    raise InputError("maker", maker, "THK, HIWIN")


def maker_critical_speed(root_diameter: float, length: float, mounting: str, maker: str) -> float:
    """Permissible speed 0.8 ω by the maker's constant form, rad/s.

    THK: λ₂ d_r/l² · 10⁷ rpm; HIWIN: 0.8 · 2.71·10⁸ f_n d_r/l² rpm (d_r, l in mm).
    """
    d = positive("root_diameter", root_diameter, "m") * 1e3
    l_b = positive("length", length, "m") * 1e3
    m = _mounting(mounting)
    if maker == "THK":
        return THK_SPEED[m] * d / l_b**2 * 1.0e7 * _RPM
    if maker == "HIWIN":
        return SPEED_SAFETY * 2.71e8 * HIWIN_SPEED[m] * d / l_b**2 * _RPM
    raise InputError("maker", maker, "THK, HIWIN")


def permissible_tension(root_diameter: float, stress: float = PERMISSIBLE_STRESS) -> float:
    """Permissible tensile/compressive load σ A of the shaft, N (THK: 116 d_r² N, d_r in mm)."""
    d = positive("root_diameter", root_diameter, "m")
    return positive("stress", stress, "Pa") * math.pi * d**2 / 4.0


def shaft_axial_stiffness(
    root_diameter: float,
    length: float,
    youngs_modulus: float,
    mounting: str,
    nut_distance: float | None = None,
) -> float:
    """Axial stiffness of the shaft between the fixed bearing(s) and the nut, N/m.

    One fixed end: A E/a with a = ``nut_distance`` (default ``length``). Fixed–fixed: the two
    shaft parts in parallel, A E l/(a (l − a)) with l = ``length`` the bearing span and a
    (default l/2) one bearing to the nut; the minimum 4 A E/l at mid-span (THK A-708 eqs.
    32–33; Bosch Rexroth R310RU 3301, 2006, p. 105 eqs. 17–19).
    """
    d = positive("root_diameter", root_diameter, "m")
    l_s = positive("length", length, "m")
    e = positive("youngs_modulus", youngs_modulus, "Pa")
    bar = math.pi * d**2 / 4.0 * e
    if _mounting(mounting) != "fixed-fixed":
        return bar / (l_s if nut_distance is None else positive("nut_distance", nut_distance, "m"))
    a = 0.5 * l_s if nut_distance is None else positive("nut_distance", nut_distance, "m")
    if a >= l_s:
        raise InputError("nut_distance", a, f"< the bearing span {l_s} m for fixed-fixed")
    return bar * l_s / (a * (l_s - a))


def thermal_elongation(length: float, expansion: float, temperature_rise: float) -> float:
    """Free thermal elongation α ΔT l of the shaft, m."""
    return (
        positive("length", length, "m")
        * nonnegative("expansion", expansion, "1/K")
        * nonnegative("temperature_rise", temperature_rise, "K")
    )


def thermal_pretension(
    root_diameter: float, youngs_modulus: float, expansion: float, temperature_rise: float
) -> float:
    """Pretension E A α ΔT that takes up the thermal elongation of a shaft fixed at both ends, N."""
    d = positive("root_diameter", root_diameter, "m")
    e = positive("youngs_modulus", youngs_modulus, "Pa")
    strain = nonnegative("expansion", expansion, "1/K") * nonnegative(
        "temperature_rise", temperature_rise, "K"
    )
    return e * math.pi * d**2 / 4.0 * strain
