"""Temperature and pressure dependence of lubricating oils: viscosity, density, conductivity.

SI at the interface (K, m²/s, Pa s, kg/m³, W/(m K), 1/Pa); the published formulas work in
mm²/s, °C or GPa⁻¹ inside, as their sources state.

* :class:`Walther` — ASTM D341 (Walther) viscosity–temperature line through two points.
* :func:`viscosity_index`, its inverses :func:`nu40_from_viscosity_index` and
  :func:`nu100_from_viscosity_index` — ASTM D2270 viscosity index, with its Table 1 for
  ν100 = 2–70 mm²/s and its closed forms above; :data:`ISO_VISCOSITY_GRADES` (ISO 3448).
* :func:`density` — linear thermal expansion of oil; :func:`thermal_conductivity` — Cragoe
  (1929); :func:`pressure_viscosity_coefficient` — Gold et al. (2001), mineral oils.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from ballscrew.errors import InputError
from ballscrew.lubrication.d2270_table import D2270_H, D2270_L, D2270_NU100
from ballscrew.validation import nonnegative, positive

__all__ = [
    "ISO_VISCOSITY_GRADES",
    "T_REF_15C",
    "Walther",
    "density",
    "nu40_from_viscosity_index",
    "nu100_from_viscosity_index",
    "pressure_viscosity_coefficient",
    "reference_viscosities",
    "thermal_conductivity",
    "viscosity_index",
]

T_REF_15C = 288.15
"""Reference temperature of oil densities, 15 °C [K]."""
_KELVIN = 273.15
_MM2 = 1e-6  # m²/s per mm²/s (cSt)
_WALTHER_SHIFT = 0.7  # mm²/s, ASTM D341 Z = ν + 0.7
FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Walther:
    """ASTM D341 (Walther) viscosity–temperature line of a petroleum oil.

        log10 log10(ν + 0.7) = A − B log10 T        (ν in mm²/s, T in K)

    ASTM D341 (2009), eq. 1 with Z = ν + 0.7, the form for ν ≥ 2 mm²/s; below 2 mm²/s the
    standard adds small correction terms that are not included here. Build it with
    :meth:`through`; evaluate with :meth:`kinematic`, invert with :meth:`temperature`.
    """

    a: float
    """Intercept A [-]."""
    b: float
    """Slope B [-] (> 0: the viscosity falls with temperature)."""

    @classmethod
    def through(
        cls, t1: float, nu1: float, t2: float, nu2: float, fields: tuple[str, str] = ("nu1", "nu2")
    ) -> Walther:
        """The line through (t1, ν1) and (t2, ν2): temperatures [K], kinematic viscosities [m²/s].

            B = [w(ν1) − w(ν2)] / [log10 T2 − log10 T1],  A = w(ν1) + B log10 T1,
            w(ν) = log10 log10(ν + 0.7)

        ``fields`` name the two viscosities in errors. The viscosity must fall with temperature
        (ν2 < ν1 for t2 > t1), otherwise :class:`InputError` naming the second field.
        """
        t1, t2 = positive("t1", t1, "K"), positive("t2", t2, "K")
        nu1, nu2 = positive(fields[0], nu1, "m²/s"), positive(fields[1], nu2, "m²/s")
        if t1 == t2:
            raise InputError("t2", t2, f"a temperature other than t1 = {t1} K")
        if (t2 - t1) * (nu2 - nu1) >= 0.0:
            raise InputError(
                fields[1],
                nu2,
                f"a viscosity that falls with temperature ({'<' if t2 > t1 else '>'} "
                f"{fields[0]} = {nu1:.6g} m²/s at {t2} K vs {t1} K)",
            )
        w1, w2 = _w(nu1), _w(nu2)
        b = (w1 - w2) / (math.log10(t2) - math.log10(t1))
        return cls(w1 + b * math.log10(t1), b)

    def kinematic(self, temperature: float) -> float:
        """ν(T) = 10^(10^(A − B log10 T)) − 0.7 mm²/s, returned in m²/s; T [K]."""
        t = positive("temperature", temperature, "K")
        return (10.0 ** (10.0 ** (self.a - self.b * math.log10(t))) - _WALTHER_SHIFT) * _MM2

    def temperature(self, kinematic: float) -> float:
        """T(ν) = 10^((A − w(ν))/B) [K], the inverse of :meth:`kinematic`; ν [m²/s]."""
        nu = positive("kinematic", kinematic, "m²/s")
        return 10.0 ** ((self.a - _w(nu)) / self.b)

    def temperature_coefficient(self, temperature: float) -> float:
        """β_ν = −(1/ν) dν/dT = B Z ln Z/(ν T) [1/K], Z = ν + 0.7 (ν in mm²/s); T [K].

        From differentiating the ASTM D341 line: dZ/dT = −B Z ln Z / T.
        """
        t = positive("temperature", temperature, "K")
        nu = self.kinematic(t) / _MM2
        z = nu + _WALTHER_SHIFT
        return self.b * z * math.log(z) / (nu * t)


def _w(nu: float) -> float:
    """w(ν) = log10 log10(ν + 0.7), ν in m²/s converted to mm²/s."""
    return math.log10(math.log10(nu / _MM2 + _WALTHER_SHIFT))


ISO_VISCOSITY_GRADES = (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000,
                        1500, 2200, 3200)  # fmt: skip
"""ISO 3448:1992 viscosity grades VG: the grade's mid-point ν40 in mm²/s (limits ±10 %)."""
_VI_B = 0.00715  # ASTM D2270 eq. 7: VI = (10^N − 1)/0.00715 + 100


def _reference_mm2(y: FloatArray) -> tuple[FloatArray, FloatArray]:
    """(L, H) [mm²/s] of ASTM D2270 at ν100 = ``y`` [mm²/s] ≥ 2: Table 1 interpolated linearly
    up to 70 mm²/s, the closed forms of §5.1.2 above."""
    table = y <= 70.0
    low = np.where(table, np.interp(y, D2270_NU100, D2270_L), 0.8353 * y * y + 14.67 * y - 216.0)
    high = np.where(table, np.interp(y, D2270_NU100, D2270_H), 0.1684 * y * y + 11.85 * y - 97.0)
    return low, high


def _vi_mm2(u: float, y: FloatArray) -> FloatArray:
    """VI of ν40 = ``u`` and ν100 = ``y`` [mm²/s] (y ≥ 2, < u), ASTM D2270 eqs. 3 and 7–8."""
    low, high = _reference_mm2(y)
    with np.errstate(over="ignore"):
        n = np.log10(high / u) / np.log10(y)
        return np.where(
            u >= high, 100.0 * (low - u) / (low - high), (10.0**n - 1.0) / _VI_B + 100.0
        )


def reference_viscosities(nu100: float) -> tuple[float, float]:
    """(L, H) of ASTM D2270 for an oil of ``nu100`` ≥ 2 mm²/s, all [m²/s].

    L and H are ν40 of the VI = 0 and VI = 100 reference oils of the same ν100. ASTM D2270-10:
    for 2 ≤ ν100 ≤ 70 mm²/s its Table 1 (:mod:`~ballscrew.lubrication.d2270_table`), linearly
    interpolated as §5.1.1 prescribes; above 70 mm²/s (§5.1.2)

        L = 0.8353 Y² + 14.67 Y − 216,  H = 0.1684 Y² + 11.85 Y − 97      (Y = ν100, mm²/s)

    VI is undefined below ν100 = 2 mm²/s: :class:`InputError`.
    """
    y = positive("nu100", nu100, "m²/s") / _MM2
    if y < 2.0:
        raise InputError("nu100", nu100, ">= 2e-06 m²/s (VI is undefined below 2 mm²/s)")
    low, high = _reference_mm2(np.asarray(y))
    return float(low) * _MM2, float(high) * _MM2


def viscosity_index(nu40: float, nu100: float) -> float:
    """Viscosity index of an oil from ν40 and ν100 [m²/s], ASTM D2270-10, unrounded.

        Procedure A (U ≥ H, VI ≤ 100):  VI = 100 (L − U)/(L − H)                      (eq. 3)
        Procedure B (U < H, VI > 100):  N = (log10 H − log10 U)/log10 Y,
                                        VI = (10^N − 1)/0.00715 + 100                 (eqs. 7–8)

    U = ν40, Y = ν100 in mm²/s; L, H from :func:`reference_viscosities`. VI is undefined for
    ν100 < 2 mm²/s.
    """
    u = positive("nu40", nu40, "m²/s") / _MM2
    reference_viscosities(nu100)  # refuses ν100 < 2 mm²/s
    y = nu100 / _MM2
    if y >= u:
        raise InputError("nu100", nu100, f"< nu40 = {nu40:.6g} m²/s (viscosity falls with T)")
    return float(_vi_mm2(u, np.asarray(y)))


def _check_vi(vi: float) -> float:
    vi = float(vi)
    if not math.isfinite(vi):
        raise InputError("viscosity_index", vi, "a finite number")
    return vi


def nu40_from_viscosity_index(nu100: float, vi: float) -> float:
    """ν40 [m²/s] of an oil of ``nu100`` [m²/s] ≥ 2 mm²/s and viscosity index ``vi``.

    The inverse of :func:`viscosity_index` in U (ASTM D2270 eqs. 3 and 7–8 solved for U):

        VI ≤ 100:  U = L − VI (L − H)/100
        VI > 100:  U = H / Y^N,  N = log10(1 + 0.00715 (VI − 100))
    """
    low, high = (v / _MM2 for v in reference_viscosities(nu100))
    y = nu100 / _MM2
    vi = _check_vi(vi)
    if vi <= 100.0:
        return (low - vi * (low - high) / 100.0) * _MM2
    n = math.log10(1.0 + _VI_B * (vi - 100.0))
    return high / y**n * _MM2


def nu100_from_viscosity_index(nu40: float, vi: float) -> float:
    """ν100 [m²/s] of an oil of ``nu40`` [m²/s] and viscosity index ``vi``.

    The root Y of VI(U, Y) = ``vi`` (:func:`viscosity_index`: ASTM D2270 eqs. 3 and 7–8 with L(Y)
    and H(Y) of Table 1 or §5.1.2) over 2 mm²/s ≤ Y < U; VI rises with Y at a fixed U. Bracketed
    on the rows of Table 1 and a geometric grid above 70 mm²/s, then solved by Brent's method to
    machine precision. :class:`InputError` naming ``viscosity_index`` when no ν100 in that
    range has this VI (below: the oil would have ν100 < 2 mm²/s, where VI is undefined).
    """
    u = positive("nu40", nu40, "m²/s") / _MM2
    vi = _check_vi(vi)
    if u <= 2.0:
        raise InputError("nu40", nu40, "> 2e-06 m²/s (ν100 < ν40 must reach 2 mm²/s for a VI)")
    above = np.geomspace(70.0, u, 200)[1:] if u > 70.0 else np.empty(0)
    grid = np.concatenate([D2270_NU100, above])
    grid = np.append(grid[grid < u], u * (1.0 - 1e-12))
    excess = _vi_mm2(u, grid) - vi
    if excess[0] > 0.0 or excess[-1] < 0.0:
        low, high = _vi_mm2(u, grid[[0, -1]])
        raise InputError(
            "viscosity_index",
            vi,
            f"{low:.6g} to {high:.6g} for nu40 = {nu40:.6g} m²/s (ν100 from 2 mm²/s to nu40)",
        )
    i = int(np.argmax(excess >= 0.0))
    if excess[i] == 0.0:
        return float(grid[i]) * _MM2
    root = brentq(
        lambda y: float(_vi_mm2(u, np.asarray(y))) - vi,
        grid[i - 1],
        grid[i],
        xtol=1e-13,
        rtol=1e-15,
    )
    return root * _MM2


def density(temperature: float, density_15: float, expansion: float = 6.4e-4) -> float:
    """ρ(T) = ρ15 [1 − α_ρ (T − 288.15 K)] [kg/m³] of a mineral oil.

    Linear thermal expansion about 15 °C; ``density_15`` ρ15 [kg/m³]; ``expansion`` α_ρ [1/K],
    default 6.4e-4 1/K, a typical value of paraffinic lubricating oils [ASSUMED: typical, not a
    measured value; give the oil's own when known]. Valid while α_ρ (T − 288.15) stays small
    (about −20…150 °C).
    """
    t = positive("temperature", temperature, "K")
    rho15 = positive("density_15", density_15, "kg/m³")
    alpha = nonnegative("expansion", expansion, "1/K")
    factor = 1.0 - alpha * (t - T_REF_15C)
    if factor <= 0.0:
        raise InputError("temperature", temperature, f"< {T_REF_15C + 1.0 / alpha:.1f} K")
    return rho15 * factor


def thermal_conductivity(temperature: float, density_15: float) -> float:
    """λ(T) = (0.1172 / d) [1 − 0.00054 (T − 273.15 K)] [W/(m K)] of a petroleum oil.

    Cragoe (1929), *Thermal properties of petroleum products*, US Bureau of Standards Misc.
    Publ. 97, §VI: k = (0.813/d)[1 − 0.0003 (t − 32 °F)] Btu in/(h ft² °F), converted to SI
    (0.813 Btu in/(h ft² °F) = 0.1172 W/(m K); 0.0003/°F = 0.00054/K) [UNVERIFIED against the
    original table; the SI constants follow from the quoted form]. d is the specific gravity
    at 15.6 °C, taken as ρ15/999 kg/m³; ``density_15`` ρ15 [kg/m³]; T [K].
    """
    t = positive("temperature", temperature, "K")
    d = positive("density_15", density_15, "kg/m³") / 999.0
    factor = 1.0 - 0.00054 * (t - _KELVIN)
    if factor <= 0.0:
        raise InputError("temperature", temperature, f"< {_KELVIN + 1.0 / 0.00054:.0f} K")
    return 0.1172 / d * factor


_GOLD_2001 = {"mineral": (9.904, 0.1390)}
"""Gold et al. (2001) α = s ν^t: oil class → (s [1/GPa], t [-]), ν in mm²/s."""


def pressure_viscosity_coefficient(kinematic: float, oil_class: str = "mineral") -> float:
    """Pressure–viscosity coefficient α_p [1/Pa] from the kinematic viscosity ν [m²/s].

        α_p = s ν^t  [1/GPa, ν in mm²/s at the same temperature]

    Gold, Schmidt, Dicke, Loos & Assmann (2001), "Viscosity–pressure–temperature behaviour of
    mineral and synthetic oils", J. Synthetic Lubrication 18(1):51–79; mineral oils:
    s = 9.904, t = 0.1390 [UNVERIFIED: coefficients as quoted in later literature, the original
    table was not available to check]. Other oil classes are not included.
    """
    nu = positive("kinematic", kinematic, "m²/s") / _MM2
    try:
        s, t = _GOLD_2001[oil_class]
    except KeyError:
        raise InputError("oil_class", oil_class, "one of " + ", ".join(_GOLD_2001)) from None
    return s * nu**t * 1e-9
