"""The raceway's one RMS roughness σ_Λ for the film parameter Λ = h/σ_Λ and the TCR film path.

A case gives it once: ``tcr.rms_roughness`` when measured, else the fractal profile (``surface.D``,
``surface.G``) over the band [``tcr.cutoff_length``, ``tcr.sampling_length``] of a roughness
measurement (``ballscrew.lubrication.composite_roughness``; theory manual, *Lubrication*,
E6.6). The fractal asperity model keeps its own σ over one micro-contact cell (E5.3).
"""

from __future__ import annotations

from ballscrew.case import Case

__all__ = ["roughness_input"]


def roughness_input(case: Case) -> float | tuple[float, float]:
    """``AsperitySurface.roughness`` of the case's raceway: the measured σ [m] or the band
    (L_u, l_c) [m] of (F3)."""
    tcr = case.tcr
    if tcr.rms_roughness is not None:
        return float(tcr.rms_roughness)
    return (tcr.sampling_length, tcr.cutoff_length)
