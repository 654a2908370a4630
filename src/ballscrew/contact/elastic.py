"""Elastic constants of a contact pair."""

from __future__ import annotations


def composite_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Contact (composite) modulus E* of two elastic bodies, Pa.

    (K1)  1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂         Johnson, *Contact Mechanics* (1985), §3.2.

    Steel on steel (E = 206 GPa, ν = 0.3) gives E* = 113.19 GPa. Hamrock's reduced modulus is
    E′ = 2E*.
    """
    return 1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)
