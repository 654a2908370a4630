"""Hardness and accuracy-grade factors of the static axial load rating (NBS catalogue).

The NBS ball-screw catalogue (*Components for linear motion*, ch. 4 "Ball screws", §2.5.1–2.5.3,
pp. 109–110) reduces the basic static rating C_0a of its static safety factor
a_S = f_H f_ac C_0a / P_a by

* the hardness factor f_H = (HV10 / 700)³ ≤ 1 of the raceways (700 HV10 ≈ 60 HRC; the catalogue
  states f_H = 0.98–1.0 for its 58–62 HRC raceways), and
* the accuracy factor f_ac of the precision class: 1.0 for classes 1–5, 0.9 and 0.7 for the
  rolled classes 7 and 10 (read from the catalogue's table, whose class cells for 0.9 and 0.7 are
  not legible in the copy we had: ASSIGNED to classes 7 and 10, the ISO 3408 classes after 5).

Neither factor is applied to the dynamic rating C_a: the catalogue gives none for it.
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
"""f_ac by accuracy (precision) class (NBS catalogue §2.5.3; classes 0, 2, 4 are the JIS
grades between ISO 1, 3 and 5 and take their neighbours' 1.0)."""

_KGF_MM2 = 9.80665e6  # Pa per kgf/mm²


def hardness_factor(hardness: float) -> float:
    """f_H = min(1, (HV / 700)³) of a raceway of indentation hardness H = HV·g [Pa] [-]."""
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
