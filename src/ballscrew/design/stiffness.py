"""Axial stiffness of the nut, and of the drive in series with the shaft and the bearings.

* Catalogue nut rigidity (THK General Catalog A-709 eqs. 35–36; HIWIN §3.7.7): the tables give
  the theoretical rigidity K at a reference load (preloaded nut: preload 0.1 C_a; without
  preload: axial load 0.3 C_a); at another load K_N = 0.8 K (F/F_ref)^(1/3).
* Hertz model of the preloaded double nut: each half deflects δ = C F^(2/3)
  (:func:`ballscrew.loads.nut_axial_deflection`); the spacer holds the halves at the preload
  deflection δ₀ = C F_p^(2/3), and an axial load F_a moves the nut body by x = δ₁ − δ₀ with
  F₁ − F₂ = F_a (:func:`ballscrew.loads.nut_forces`). The halves act in parallel, so the
  stiffness is the sum of the halves' 1.5 F_i/δ_i
  (:func:`ballscrew.loads.preloaded_axial_stiffness`) until the second half lifts off at
  F_a = 2^(3/2) F_p. A single nut preloaded by oversized balls (four-point contact) or an offset
  lead has the same two loaded flanks (``nuts = 2`` here, with the compliance of one flank); a
  single nut without preload carries F_a on one flank (``nuts = 1``).
* Bodies in series: 1/K = Σ 1/K_i.
* Lost motion at a reversal of the axial load F: 2 (x_nut(F) + F Σ 1/K_i) over the nut's own
  displacement x_nut and the linear springs in series with it (shaft, bearings). A preloaded nut
  has no backlash below lift-off; a nut without preload adds its axial play.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.errors import InputError
from ballscrew.loads import flank_forces, nut_axial_deflection, preloaded_axial_stiffness
from ballscrew.validation import nonnegative, nonnegative_array, positive

__all__ = [
    "CATALOGUE_RIGIDITY_SHARE",
    "catalogue_nut_rigidity",
    "lost_motion",
    "nut_load_curve",
    "nut_load_deflection",
    "nut_stiffness",
    "series_stiffness",
]

CATALOGUE_RIGIDITY_SHARE = 0.8
"""Share of the catalogue's theoretical rigidity the makers advise to use (THK, HIWIN)."""


def catalogue_nut_rigidity(table_rigidity: float, load: float, reference_load: float) -> float:
    """Nut rigidity 0.8 K (F/F_ref)^(1/3) from the table value K at F_ref, N/m.

    Preloaded nut: ``load`` = preload F_a0 and ``reference_load`` = 0.1 C_a; nut without
    preload: the axial load and 0.3 C_a (THK) or 0.28 C_a (HIWIN).
    """
    k = positive("table_rigidity", table_rigidity, "N/m")
    ratio = positive("load", load, "N") / positive("reference_load", reference_load, "N")
    return CATALOGUE_RIGIDITY_SHARE * k * ratio ** (1.0 / 3.0)


def _half_forces(axial_load: float, preload: float, nuts: int) -> tuple[float, float]:
    if nuts not in (1, 2):  # named as the caller's argument, not flank_forces' "flanks"
        raise InputError("nuts", nuts, "1 or 2")
    f1, f2 = flank_forces(preload, axial_load, nuts)
    return float(f1), float(f2)


def _half_force_array(loads: NDArray[np.float64], preload: float, nuts: int) -> NDArray[np.float64]:
    """(F₁, F₂) of the loaded and the other half at every load, shape (loads.size, 2) [N]."""
    return np.array([_half_forces(float(f), preload, nuts) for f in loads.ravel()]).reshape(-1, 2)


def _displacement(first: NDArray[np.float64], preload: float, compliance: float) -> NDArray:
    """x = δ(F₁) − δ(F_p) of the loaded half's forces ``first`` [m]."""
    return nut_axial_deflection(first, compliance) - nut_axial_deflection(preload, compliance)


def nut_load_deflection(
    axial_load: ArrayLike, preload: float, compliance: float, nuts: int = 2
) -> NDArray[np.float64]:
    """Axial displacement x(F_a) of the nut body from the preloaded state, m.

    x = δ(F₁) − δ(F_p) for a double nut (F₁ the loaded half), δ(F_p + F_a) − δ(F_p) for one nut.
    """
    fp = nonnegative("preload", preload, "N")
    loads = nonnegative_array("axial_load", axial_load, "N")
    first = _half_force_array(loads, fp, nuts)[:, 0]
    return _displacement(first, fp, compliance).reshape(loads.shape)


def nut_stiffness(axial_load: float, preload: float, compliance: float, nuts: int = 2) -> float:
    """Tangent axial stiffness dF_a/dx of the nut (both halves in parallel), N/m."""
    fp = nonnegative("preload", preload, "N")
    fa = nonnegative("axial_load", axial_load, "N")
    forces = [f for f in _half_forces(fa, fp, nuts) if f > 0.0]
    if not forces:
        raise InputError("preload", preload, "> 0 N where the axial load is 0 N")
    deflections = nut_axial_deflection(np.array(forces), compliance)
    return float(np.sum(preloaded_axial_stiffness(np.array(forces), deflections)))


def nut_load_curve(
    axial_load: ArrayLike, preload: float, compliance: float, nuts: int = 2
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """(x, dF_a/dx) at every axial load: :func:`nut_load_deflection` and :func:`nut_stiffness`
    from one solve of the halves' forces per load, 1.5 F_i/δ_i summed over the loaded halves
    [m, N/m]."""
    fp = nonnegative("preload", preload, "N")
    loads = nonnegative_array("axial_load", axial_load, "N")
    forces = _half_force_array(loads, fp, nuts)
    loaded = forces > 0.0
    if not loaded.any(axis=1).all():
        raise InputError("preload", preload, "> 0 N where the axial load is 0 N")
    f = np.where(loaded, forces, 1.0)  # an unloaded half adds no stiffness (zeroed below)
    halves = preloaded_axial_stiffness(f, nut_axial_deflection(f, compliance))
    k = np.where(loaded, halves, 0.0).sum(axis=1)
    return _displacement(forces[:, 0], fp, compliance).reshape(loads.shape), k.reshape(loads.shape)


def series_stiffness(*stiffnesses: float) -> float:
    """Stiffness of springs in series, 1/Σ(1/K_i), N/m."""
    if not stiffnesses:
        raise InputError("stiffnesses", (), "one or more stiffnesses > 0 N/m")
    return 1.0 / sum(1.0 / positive("stiffness", k, "N/m") for k in stiffnesses)


def lost_motion(nut_travel: float, load: float, *stiffnesses: float) -> float:
    """Lost motion 2 (x_nut + F Σ 1/K_i) at a reversal of the axial load F, m.

    ``nut_travel`` x_nut(F) is the nut's displacement under F from its unloaded (preloaded)
    state; ``stiffnesses`` the springs in series with it [N/m]. The nut and each spring deflect
    by as much in either direction, so the reversal travels twice the deflection.
    """
    x = nonnegative("nut_travel", nut_travel, "m")
    f = nonnegative("load", load, "N")
    return 2.0 * (x + f * sum(1.0 / positive("stiffness", k, "N/m") for k in stiffnesses))
