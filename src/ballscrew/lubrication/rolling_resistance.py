"""Hydrodynamic (EHL) rolling resistance of a lubricated ball–raceway contact.

Harris, T. A. & Kotzalas, M. N. (2006), *Rolling Bearing Analysis*, 5th ed., Vol. 2, ch. 3
(hydrodynamic rolling force of a ball in an EHL contact); used for ball screws by Wei, Lin &
Horng (2009), Tribol. Int. 42:1816. Theory manual: ``docs/theory/lubrication.md``, (E3.4), with
medium confidence in the coefficients.
"""

from __future__ import annotations

from ballscrew.lubrication.film import dimensionless_groups

__all__ = ["ehl_rolling_resistance"]


def ehl_rolling_resistance(
    rx: float,
    ry: float,
    e_prime: float,
    viscosity: float,
    pressure_viscosity: float,
    entrainment_speed: float,
    load: float,
) -> float:
    """EHL rolling-resistance force F_R = 2.86 E′ R_x² κ^0.348 Ḡ^0.022 U^0.66 W^0.47, (E3.4), N.

    U, Ḡ, W and the ellipticity κ = κ_HD = 1.03 (R_y/R_x)^0.64 as in Hamrock–Dowson
    (:func:`~ballscrew.lubrication.film.dimensionless_groups`); the example value below is
    reproduced with κ_HD (the exact Hertz a/b = 5.147 gives 4.634e-3 N). It acts on the ball against
    its rolling direction relative to the raceway. Contact A of the reference screw of
    ``examples/wear_step_stress.toml`` at Q = 68.69 N, u_e = 0.09333 m/s, η₀ = 0.06 Pa s, α_p =
    2.1e-8 1/Pa: 4.637e-3 N.
    """
    u, g, w, kappa = dimensionless_groups(
        rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, load
    )
    return 2.86 * e_prime * rx * rx * kappa**0.348 * g**0.022 * u**0.66 * w**0.47
