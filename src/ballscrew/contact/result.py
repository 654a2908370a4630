"""Result of a discrete normal contact solve."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any


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
    def contact(self) -> Any:
        """Boolean mask of the contact set I_c = {p > 0}."""
        return self.pressure > 0.0
