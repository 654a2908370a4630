"""The :class:`Profile` container: sampled heights on a uniform grid, in SI units.

Every reader in :mod:`ballscrew.surface.io` and the synthetic generator
(:func:`ballscrew.surface.weierstrass_mandelbrot_profile`) return one. Heights are in metres and
the sampling interval in metres; units are converted at the edge (the readers), never inside.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.validation import real_array

__all__ = [
    "MAX_SAMPLING_LENGTH",
    "MIN_POINTS",
    "MIN_SPACING",
    "Profile",
    "as_rows",
    "check_spacing",
    "sampling_range",
]

#: Fewest points per profile that the estimators accept.
MIN_POINTS = 16

#: Finest sampling interval of a measured profile, m: a tenth of the interatomic distance
#: (about 0.1 nm); no profilometer or AFM samples finer.
MIN_SPACING = 1e-11

#: Longest record n·Δx of a measured profile, m. Roughness records are millimetres long (ISO
#: 4288 evaluation lengths ≤ 40 mm) and a ball-screw thread is at most a few metres; a longer
#: record is a wrong spacing or unit, and its D and G would be meaningless.
MAX_SAMPLING_LENGTH = 1.0

FloatArray = NDArray[np.float64]


def check_spacing(spacing: object, field_name: str = "spacing") -> float:
    """Return ``spacing`` as a float after checking it is finite and > 0 (metres)."""
    try:
        value = float(spacing)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InputError(field_name, spacing, "a sampling interval in m, finite and > 0") from None
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(field_name, spacing, "a sampling interval in m, finite and > 0")
    return value


def sampling_range(spacing: float, n_points: int) -> str | None:
    """None if a sampling interval ``spacing`` [m] of ``n_points`` lies in
    [:data:`MIN_SPACING`, :data:`MAX_SAMPLING_LENGTH` / n]; otherwise the allowed range."""
    top = MAX_SAMPLING_LENGTH / n_points
    if MIN_SPACING <= spacing <= top:
        return None
    return (
        f"a sampling interval {MIN_SPACING:g} m ≤ Δx ≤ {MAX_SAMPLING_LENGTH:g} m / {n_points} "
        f"points = {top:.3g} m (a record of at most {MAX_SAMPLING_LENGTH:g} m)"
    )


def as_rows(heights: ArrayLike, field_name: str = "heights") -> FloatArray:
    """Heights as a C-contiguous 2-D float array (profiles × points), finite rows only.

    A 1-D array becomes one row. Rows that contain a non-finite value (non-measured points,
    ``BAD`` in an SDF file) are left out; if none is left, or a row has fewer than
    :data:`MIN_POINTS` points, :class:`InputError` is raised.
    """
    arr = real_array(field_name, heights, "m", missing_ok=True)
    if arr.ndim == 1:
        arr = arr[None, :]
    if arr.ndim != 2:
        raise InputError(field_name, f"array of shape {arr.shape}", "a 1-D or 2-D array")
    if arr.shape[1] < MIN_POINTS:
        raise InputError(
            field_name, f"{arr.shape[1]} points per profile", f"at least {MIN_POINTS} points"
        )
    good = np.all(np.isfinite(arr), axis=1)
    if not np.any(good):
        raise InputError(
            field_name,
            "no profile without non-measured (NaN) points",
            "at least one complete profile",
        )
    return np.ascontiguousarray(arr[good])


@dataclass(frozen=True, eq=False)
class Profile:
    """Heights sampled at a uniform interval along x.

    Attributes:
        heights: heights z in m; shape ``(n,)`` for one profile or ``(m, n)`` for ``m``
            parallel profiles of an areal measurement (row i at y = i · ``y_spacing``).
            Non-measured points are NaN.
        spacing: sampling interval Δx along each profile, m.
        y_spacing: distance between rows, m (``None`` for a single profile or when unknown).
        metadata: everything else the source said (instrument, dates, original units…).
        source: where it came from (a file path or ``"synthetic"``).
    """

    heights: FloatArray
    spacing: float
    y_spacing: float | None = None
    metadata: dict[str, Any] = field(default_factory=dict)
    source: str = ""

    def __post_init__(self) -> None:
        heights = real_array("heights", self.heights, "m", missing_ok=True)
        if heights.ndim not in (1, 2) or heights.shape[-1] < 2:
            raise InputError(
                "heights", f"array of shape {heights.shape}", "a 1-D or 2-D array of heights in m"
            )
        object.__setattr__(self, "heights", heights)
        object.__setattr__(self, "spacing", check_spacing(self.spacing))
        if self.y_spacing is not None:
            object.__setattr__(self, "y_spacing", check_spacing(self.y_spacing, "y_spacing"))

    @property
    def n_points(self) -> int:
        """Points per profile."""
        return int(self.heights.shape[-1])

    @property
    def n_profiles(self) -> int:
        """Number of profiles (rows)."""
        return 1 if self.heights.ndim == 1 else int(self.heights.shape[0])

    @property
    def length(self) -> float:
        """Sampling length L = n · Δx, m (the record one period of the lowest DFT line spans)."""
        return self.n_points * self.spacing

    @property
    def x(self) -> FloatArray:
        """Positions of the points along the profile, m (starting at 0)."""
        return np.arange(self.n_points) * self.spacing

    @property
    def rows(self) -> FloatArray:
        """Heights as a 2-D array (profiles × points), a view where possible."""
        return np.atleast_2d(self.heights)
