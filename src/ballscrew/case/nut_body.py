"""The nut body must enclose its balls: a check of ``loads.nut_outer_diameter`` at case load.

The elastic load distribution (:func:`ballscrew.loads.distribution.body_properties`) treats the
nut as a thick ring (Lamé; Timoshenko & Goodier 1970, §33) outside the groove bottom d_m + D_b,
loaded at the contact radius r = (d_m + D_b cos β)/2. Its compliance
[(D_o² + 4r²)/(D_o² − 4r²) + ν]/(2π E) grows without bound as D_o nears 2r, and the Newton
solution of the ball loads stops converging once the wall beyond the groove bottom is a few
tenths of a millimetre (0.4–1.5 mm on the diameter for a 40 mm screw with 6.35 mm balls,
depending on preload and the nut's modulus). A real nut keeps a wall of about two balls there
(DIN 69051 flanged nuts: D_o ≈ d_m + 5 D_b); the bound below asks for half a ball.
"""

from __future__ import annotations

from typing import Any

__all__ = ["NUT_WALL_BALLS", "check_nut_body", "least_nut_outer_diameter"]

NUT_WALL_BALLS = 0.5
"""Least wall of the nut body beyond its groove bottom, in ball diameters (radial) [GUESS: the
elastic ring's Newton solve was seen to fail 0.4–1.5 mm over the groove on the example screw;
real nuts have walls of several balls]."""


def least_nut_outer_diameter(pitch_diameter: float, ball_diameter: float) -> float:
    """Least nut outer diameter D_o = d_m + D_b + 2 · 0.5 D_b = d_m + 2 D_b [m]."""
    return pitch_diameter + (1.0 + 2.0 * NUT_WALL_BALLS) * ball_diameter


def check_nut_body(case: Any) -> Any:
    """``Case`` validator: ``loads.nut_outer_diameter``, when given, is at least
    :func:`least_nut_outer_diameter` of the screw (one-line error otherwise)."""
    d_o = case.loads.nut_outer_diameter
    if d_o is None:
        return case
    d_m, d_w = case.screw.pitch_diameter, case.screw.ball_diameter
    least = least_nut_outer_diameter(d_m, d_w)
    if not d_o >= least:
        raise ValueError(
            f"loads.nut_outer_diameter = {d_o:g} m ({d_o * 1e3:.4g} mm) is not allowed: at least "
            f"d_m + 2·D_b = {least:g} m ({least * 1e3:.4g} mm; the groove bottom d_m + D_b = "
            f"{(d_m + d_w) * 1e3:.4g} mm and a wall of half a ball around it, which the nut's "
            "elastic ring needs)"
        )
    return case
