"""Result of a discrete normal contact solve."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass(frozen=True)
class ContactResult:
    """Converged solution of the discrete normal contact problem (C1)-(C2) on a cell-centred grid.

    Arrays have the shape of the gap; axis 0 is x, axis 1 is y. They are NumPy or CuPy arrays, as
    the gap was.
    """

    pressure: Any
    """Cell pressures p ≥ 0 [Pa]."""
    displacement: Any
    """Elastic displacement u = K ∗ p, the sum of both surfaces [m]."""
    approach: float
    """Rigid-body approach δ: the mean of u + h over the contact set [m]."""
    load: float
    """Normal load W = dx·dy·Σp [N]."""
    contact_area: float
    """Area of the cells with p > 0 [m²]."""
    iterations: int
    """Conjugate-gradient iterations taken."""
    residual: float
    """Final relative pressure change Σ|p − p_old| / Σp (Polonsky & Keer 1999, Eq. 40)."""
    converged: bool
    """Whether ``residual`` reached the tolerance."""
    dx: float
    """Cell size along x [m]."""
    dy: float
    """Cell size along y [m]."""
    coarse_work: float = 0.0
    """Iterations on the coarser grids of a nested-grid start, each weighted by its cell count over
    the cell count of this grid (fine-grid equivalents; 0 without a nested start)."""

    @property
    def peak_pressure(self) -> float:
        """Largest cell pressure [Pa]."""
        return float(self.pressure.max())

    @property
    def semi_axes(self) -> tuple[float, float]:
        """Half-widths of the contact along x and y [m], the edges interpolated between cells
        (:func:`contact_semi_axes`)."""
        return contact_semi_axes(self.pressure, self.dx, self.dy)

    @property
    def contact(self) -> Any:
        """Boolean mask of the contact set I_c = {p > 0}."""
        return self.pressure > 0.0


def contact_semi_axes(pressure: Any, dx: float, dy: float) -> tuple[float, float]:
    """Half-widths of the loaded region along x and y [m], the edges placed between cells.

    Along each axis, P(x) = max over the other axis of p: for Hertz P = p0·√(1 − x²/a²), so P²
    falls linearly to 0 at the edge (the square-root edge of a smooth contact, Johnson 1985,
    §4.2). Each edge is extrapolated from the last two loaded cells, x_e = x_k + Δ·P_k²/(P_{k−1}²
    − P_k²), kept within one cell beyond x_k (the next cell is unloaded); a lone loaded cell
    counts its own half-width. The half-width is half the distance of the two edges: exact for
    Hertz to O(Δ²/a), where the extents of the loaded cells are only good to ±Δ/2 (and equal the
    Hertz semi-axes by construction on a grid sized to them). (0, 0) without contact.
    """
    p = pressure.get() if hasattr(pressure, "get") else np.asarray(pressure)
    return _half_width(p.max(axis=1), dx), _half_width(p.max(axis=0), dy)


def _half_width(profile: np.ndarray, step: float) -> float:
    """Half the distance of the two extrapolated edges of the loaded cells of ``profile``."""
    loaded = np.flatnonzero(profile > 0.0)
    if not loaded.size:
        return 0.0
    first, last = int(loaded[0]), int(loaded[-1])
    square = profile.astype(np.float64) ** 2
    beyond = [
        _beyond(square[end], square[end + inward] if first < last else None)
        for end, inward in ((first, 1), (last, -1))
    ]
    return 0.5 * step * (last - first + sum(beyond))


def _beyond(outer: float, inner: float | None) -> float:
    """The edge's distance past the outermost loaded cell centre, in cells: P² extrapolated to 0
    from the cell (``outer``) and its inner neighbour (``inner``), in [0, 1]; ½ for a lone cell."""
    if inner is None:
        return 0.5
    drop = inner - outer
    return float(min(outer / drop, 1.0)) if drop > 0.0 else 1.0
