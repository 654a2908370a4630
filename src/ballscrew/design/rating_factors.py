"""Hardness and accuracy-class factors of the axial load ratings (NBS catalogue).

The NBS ball-screw catalogue (*Components for linear motion*, ch. 4 "Ball screws", §2.5.1–2.5.3
and §2.7.3, pp. 109–112) multiplies the ratings by

* the hardness factor f_H = (HV10 / 700)³ ≤ 1 of the raceways (700 HV10 ≈ 60 HRC; the catalogue
  calls f_H 0.98–1.0 for its 58–62 HRC raceways), and
* the accuracy factor f_ac of the precision class: 1 for classes 1–5, 0.9 for class 7, 0.7 for
  class 10 (table "fac", p. 110),

in the static safety factor a_S = f_H f_ac C_0a / P_a, and, by the same factors, in the life of a
nut whose raceways are not of 60 HRC or whose class is not 1–5 (§2.7.3; that formula is printed
as an image in the copy we read, only its list of factors is legible).
"""

from __future__ import annotations

from ballscrew.errors import InputError
from ballscrew.validation import positive

__all__ = [
    "ACCURACY_FACTORS",
    "REFERENCE_HARDNESS_HV",
    "accuracy_factor",
    "hardness_factor",
]

REFERENCE_HARDNESS_HV = 700.0
"""Raceway Vickers hardness HV10 at which f_H reaches 1 (NBS catalogue §2.5.2)."""

ACCURACY_FACTORS: dict[int, float] = {
    0: 1.0,
    1: 1.0,
    2: 1.0,
    3: 1.0,
    4: 1.0,
    5: 1.0,
    7: 0.9,
    10: 0.7,
}
"""f_ac by accuracy (precision) class (NBS catalogue §2.5.3; classes 0, 2, 4, JIS grades between
ISO 1, 3 and 5, take their neighbours' 1)."""

_KGF_MM2 = 9.80665e6  # Pa per kgf/mm²


def hardness_factor(hardness: float) -> float:
    """f_H = min(1, (HV / 700)³) of a raceway of indentation hardness H = HV·g in Pa."""
    hv = positive("hardness", hardness, "Pa") / _KGF_MM2
    return min(1.0, (hv / REFERENCE_HARDNESS_HV) ** 3)


def accuracy_factor(grade: int) -> float:
    """f_ac of an accuracy class (:data:`ACCURACY_FACTORS`) [-]."""
    try:
        return ACCURACY_FACTORS[grade]
    except (KeyError, TypeError):
        raise InputError(
            "design.accuracy_grade", grade, f"one of {sorted(ACCURACY_FACTORS)}"
        ) from None
