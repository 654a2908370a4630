"""Losses of the nut outside the ball–raceway contacts: ball–ball friction, drag, recirculation.

Each function gives the power [W] of one mechanism for one ball (or one ball stream); the ball
model (:mod:`ballscrew.friction.ball_losses`) sums them over the loaded balls and divides by ω_s.

* :func:`ball_ball_power` — sliding friction at the contact of two adjacent balls. Balls of a
  ball screw are not caged and turn in the same sense, so the surfaces of two neighbours slide
  past each other at twice their surface speed; Olaru, Puiu, Balan & Puiu (2005) name this
  "friction moment between the balls", M_B = μ_bb F_B d_w/2, among the ball-screw losses, and
  Lin, Duan & Okwudire (2019) show experimentally and by model that ball-to-ball friction is
  significant in ball screws and linear bearings. The contact force F_B has no closed form in
  either source: it comes from a model of :mod:`ballscrew.friction.ball_train` (``ratio``, a
  GUESSED fraction of the ball load, or ``return_push``).
* :func:`drag_power` — hydrodynamic drag of a ball moving through the lubricant held in the nut
  (Harris & Kotzalas 2007, *Rolling Bearing Analysis*, Vol. 2:
  F_v = (π/32) C_D ρ_e d² (d_m ω_m)^1.95, the sphere drag ½ C_D ρ_e (π d²/4) V² with an exponent
  1.95 fitted for bearings; here the exponent 2 of the sphere drag is kept) with the sphere drag
  coefficient of Schiller & Naumann (1933).
* :func:`recirculation_power` — kinetic energy of the balls lost where they leave the loaded
  track into the ball return (ASSUMED model: every ball entering the return is stopped in its
  translation and rolling and re-accelerated when it re-enters; no published model found).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ballscrew.friction.ball_train import (
    DEFAULT_BALL_BALL_LOAD_RATIO,
    DEFAULT_BALL_TRAIN,
    DEFAULT_RETURN_FRACTION,
    DEFAULT_RETURN_FRICTION,
)
from ballscrew.validation import nonnegative, positive

__all__ = [
    "DEFAULT_BALL_BALL_FRICTION",
    "DEFAULT_BALL_BALL_LOAD_RATIO",
    "DEFAULT_CIRCUITS",
    "DEFAULT_LUBRICANT_FILL",
    "NutLossParameters",
    "ball_ball_power",
    "drag_power",
    "recirculation_power",
    "sphere_drag_coefficient",
]

DEFAULT_BALL_BALL_FRICTION = 0.1
"""μ_bb at the ball–ball contact: boundary friction of lubricated hardened steel, the same GUESS
as ``kinematics.boundary_friction`` (the ball–ball contact has no entrainment to build a film:
its surfaces move in opposite directions)."""

DEFAULT_LUBRICANT_FILL = 0.1
"""X, the volume fraction of lubricant in the free space of the nut, which sets the effective
density ρ_e = X ρ of the drag. GUESS: Harris & Kotzalas (2007) use the same fraction for an
oil–air mixture in a bearing cavity; a nut is not flooded."""

DEFAULT_CIRCUITS = 2
"""Ball circuits per nut (returns per nut). GUESS: THK's BNFN type has 2 circuits per nut."""


@dataclass(frozen=True)
class NutLossParameters:
    """Parameters of the losses of :mod:`ballscrew.friction.nut_losses` (SI)."""

    ball_ball_load_ratio: float = DEFAULT_BALL_BALL_LOAD_RATIO
    """F_B/Q."""
    ball_ball_friction: float = DEFAULT_BALL_BALL_FRICTION
    """μ_bb."""
    lubricant_fill: float = DEFAULT_LUBRICANT_FILL
    """X, volume fraction of lubricant in the nut."""
    circuits: int = DEFAULT_CIRCUITS
    """Ball circuits per nut."""
    ball_train: str = DEFAULT_BALL_TRAIN
    """Model of F_B (:data:`ballscrew.friction.ball_train.BALL_TRAIN_MODELS`)."""
    return_friction: float = DEFAULT_RETURN_FRICTION
    """μ_r of a ball on the wall of the return path (``return_push``)."""
    return_fraction: float = DEFAULT_RETURN_FRACTION
    """n_r/n_l, balls in the return per loaded ball of a circuit (``return_push``)."""


def ball_ball_power(contact_force: float, friction: float, surface_speed: float) -> float:
    """P_bb = μ_bb F_B · 2 v_s [W] at one ball–ball contact.

    Two neighbours with the same angular velocity Ω touch at ±r_b t (t the direction of the
    track), so their surfaces slide past each other at 2 v_s, v_s = r_b |Ω × t| the surface
    speed of one ball [m/s]; the friction moment on each ball is M_B = μ_bb F_B r_b (Olaru et
    al. 2005). ``contact_force`` F_B [N]; ``friction`` μ_bb.
    """
    nonnegative("ball_ball_force", contact_force, "N")
    nonnegative("friction.ball_ball_friction", friction)
    return friction * contact_force * 2.0 * abs(surface_speed)


def sphere_drag_coefficient(reynolds: float) -> float:
    """C_D of a sphere: 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above.

    Schiller, L. & Naumann, A. (1933), Z. Ver. Dtsch. Ing. 77:318 (as given by Clift, Grace &
    Weber 1978, *Bubbles, Drops and Particles*, Table 5.2). Re = ρ V d/η > 0.
    """
    re = positive("reynolds", reynolds)
    return 24.0 / re * (1.0 + 0.15 * re**0.687) if re < 1000.0 else 0.44


def drag_power(
    speed: float, diameter: float, density: float, viscosity: float, fill: float
) -> float:
    """P_v = F_v V,  F_v = ½ C_D(Re) X ρ (π d²/4) V²  [W] of one ball moving at V in the nut.

    Harris & Kotzalas (2007), drag of the balls in the lubricant of the bearing cavity, with the
    lubricant fraction X (ρ_e = X ρ); C_D of :func:`sphere_drag_coefficient` at Re = ρ V d/η.
    ``speed`` V: ball-centre speed relative to the nut [m/s]; ``diameter`` d [m];
    ``density`` ρ [kg/m³]; ``viscosity`` η [Pa s]; ``fill`` X in [0, 1]. 0 at rest.
    """
    v = abs(float(speed))
    d = positive("ball_diameter", diameter, "m")
    rho = positive("lubricant_density", density, "kg/m³")
    eta = positive("viscosity", viscosity, "Pa s")
    x = nonnegative("friction.lubricant_fill", fill)
    if v == 0.0 or x == 0.0:
        return 0.0
    cd = sphere_drag_coefficient(rho * v * d / eta)
    return 0.5 * cd * x * rho * math.pi * d * d / 4.0 * v**3


def recirculation_power(
    speed: float, rolling_speed: float, mass: float, inertia: float, diameter: float, circuits: int
) -> float:
    """P_r = n_c (V/d) (½ m V² + ½ I Ω²) [W] of one nut (ASSUMED model).

    The balls of each of the n_c circuits leave the loaded track at the rate V/d (a closed ball
    chain moving at V); each is taken as losing its kinetic energy of translation and rolling
    in the return and regaining it from the screw when it re-enters. ``speed`` V [m/s];
    ``rolling_speed`` |Ω| [rad/s]; ``mass`` m [kg], ``inertia`` I [kg m²] and ``diameter`` d
    [m] of a ball; ``circuits`` n_c. No published model of the return loss was found.
    """
    v = abs(float(speed))
    d = positive("ball_diameter", diameter, "m")
    nonnegative("friction.circuits", circuits)
    energy = 0.5 * mass * v * v + 0.5 * inertia * float(rolling_speed) ** 2
    return circuits * v / d * energy
