"""Ball kinematics, quasi-static ball balance and drag torque of a ball screw.

Theory manual ``docs/theory/kinematics.md`` and, for (E9.1), ``docs/theory/loads.md`` (Wei & Lin
2003; Wei, Lin & Horng 2009; Lin, Ravani & Velinsky 1994; Harris & Kotzalas 2006).

1. :mod:`~ballscrew.kinematics.frames` — Frenet frame at the ball and contact frames at A, B.
2. :mod:`~ballscrew.kinematics.motion` — nut-raceway control and rolling closure (E2.1)–(E2.5).
3. :mod:`~ballscrew.kinematics.sliding` — sliding field over the contact, exact (E2.6) and
   closed form (E2.7), on the contact-pressure grid.
4. :mod:`~ballscrew.kinematics.balance` — Levels 0, 1 (E3.5) and 2 (E3.6) of the ball balance.
5. :mod:`~ballscrew.kinematics.torque` — drag torque of the ball model (E3.7).
6. :mod:`~ballscrew.kinematics.limits` — whirling and d·n limits.
7. :mod:`~ballscrew.kinematics.traction_laws` — rival traction laws of the contacts
   (:data:`TRACTION_LAWS`: JGP film law, SKF sliding weighting).

The case-level functions (``ball_kinematics``, ``drag_torque``, ``computed_drag_torque``,
``run_kinematics``) compose these in :mod:`ballscrew.analyses.kinematics`.
"""

from ballscrew.kinematics.balance import BallState, solve_ball
from ballscrew.kinematics.frames import BallFrame, ContactAxes, ball_frame, contact_axes
from ballscrew.kinematics.limits import SpeedLimitWarning, critical_speed, groove_root_diameter
from ballscrew.kinematics.model import BallModel
from ballscrew.kinematics.motion import BallMotion, ball_motion
from ballscrew.kinematics.sliding import (
    SlidingField,
    deformed_radius,
    sliding_field,
    sliding_field_closed_form,
)
from ballscrew.kinematics.torque import BallDrag, ball_drag
from ballscrew.kinematics.traction_laws import (
    TRACTION_LAWS,
    TractionWeights,
    skf_sliding_friction,
    skf_weighting,
)

__all__ = [
    "TRACTION_LAWS",
    "BallDrag",
    "BallFrame",
    "BallModel",
    "BallMotion",
    "BallState",
    "ContactAxes",
    "SlidingField",
    "SpeedLimitWarning",
    "TractionWeights",
    "ball_drag",
    "ball_frame",
    "ball_motion",
    "contact_axes",
    "critical_speed",
    "deformed_radius",
    "groove_root_diameter",
    "skf_sliding_friction",
    "skf_weighting",
    "sliding_field",
    "sliding_field_closed_form",
    "solve_ball",
]
