"""Ball kinematics, quasi-static ball balance and drag torque of a ball screw.

Physics reference ``kinematics-wear.md`` §2, §3 and §9.1 (Wei & Lin 2003; Wei, Lin & Horng 2009;
Lin, Ravani & Velinsky 1994; Harris & Kotzalas 2006).

1. :mod:`~ballscrew.kinematics.frames` — Frenet frame at the ball and contact frames at A, B (§2.1).
2. :mod:`~ballscrew.kinematics.motion` — nut-raceway control and rolling closure (E2.1)–(E2.5).
3. :mod:`~ballscrew.kinematics.sliding` — sliding field over the contact, exact (E2.6) and
   closed form (E2.7), on the contact-pressure grid.
4. :mod:`~ballscrew.kinematics.balance` — Levels 0, 1 (E3.5) and 2 (E3.6) of the ball balance.
5. :mod:`~ballscrew.kinematics.torque` — drag torque of the ball model (E3.7).
6. :mod:`~ballscrew.kinematics.api` — case-level API: :func:`ball_kinematics`,
   :func:`drag_torque` (catalogue E9.1), :func:`computed_drag_torque` (for the thermal model),
   :func:`speed_sweep`; :mod:`~ballscrew.kinematics.limits` — whirling and d·n limits.
"""

from ballscrew.kinematics.api import (
    SpeedSweep,
    ball_kinematics,
    computed_drag_torque,
    curve_speeds,
    drag_torque,
    nut_loads,
    speed_sweep,
)
from ballscrew.kinematics.balance import BallState, solve_ball
from ballscrew.kinematics.frames import BallFrame, ContactAxes, ball_frame, contact_axes
from ballscrew.kinematics.limits import SpeedLimitWarning, critical_speed, groove_root_diameter
from ballscrew.kinematics.model import BallModel, ball_model
from ballscrew.kinematics.motion import BallMotion, ball_motion
from ballscrew.kinematics.sliding import (
    SlidingField,
    deformed_radius,
    sliding_field,
    sliding_field_closed_form,
)
from ballscrew.kinematics.torque import BallDrag, ball_drag

__all__ = [
    "BallDrag",
    "BallFrame",
    "BallModel",
    "BallMotion",
    "BallState",
    "ContactAxes",
    "SlidingField",
    "SpeedLimitWarning",
    "SpeedSweep",
    "ball_drag",
    "ball_frame",
    "ball_kinematics",
    "ball_model",
    "ball_motion",
    "computed_drag_torque",
    "contact_axes",
    "critical_speed",
    "curve_speeds",
    "deformed_radius",
    "drag_torque",
    "groove_root_diameter",
    "nut_loads",
    "sliding_field",
    "sliding_field_closed_form",
    "solve_ball",
    "speed_sweep",
]
