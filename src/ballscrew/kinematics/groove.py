"""Contact geometry of a displaced ball between the screw and nut grooves (Jones/Harris).

``docs/theory/kinematics.md`` (E3.5), the "inner race = screw, outer race = nut" form of Jones
(1960) and Harris & Kotzalas (2006) applied to a ball screw. In the normal plane (n, b) of the ball
centre, with the unloaded ball centre c₀ and nominal contact vector e₀ = cosβ₀ n + s sinβ₀ b:

    C_s = c₀ − (r_s − r_b) e₀,         C_n = c₀ + (r_n − r_b) e₀ + s u cosλ b
    δ_A = |c − C_s| − (r_s − r_b),     δ_B = |c − C_n| − (r_n − r_b),   Q_k = (δ_k/K_k)^(3/2)
    e_A = (c − C_s)/|c − C_s|,         e_B = (c − C_n)/|c − C_n|

u is the nut's axial displacement (its normal-plane component u cosλ moves the nut arc centre
along s b, away from the screw arc centre) and c = c₀ + c_n n + c_b b the loaded ball centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ballscrew.geometry import ScrewGeometry
from ballscrew.kinematics.frames import BallFrame, contact_vector

__all__ = ["GrooveContacts", "groove_contacts"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class GrooveContacts:
    """Contact vectors, approaches, loads and contact angles of a displaced ball."""

    direction_screw: FloatArray
    """e_A, unit vector from the ball centre to A."""
    direction_nut: FloatArray
    """e_B, unit vector from the ball centre to B."""
    approach_screw: float
    """δ_A [m] (negative: no contact)."""
    approach_nut: float
    """δ_B [m]."""
    load_screw: float
    """Q_A = (max(δ_A, 0)/K_A)^(3/2) [N]."""
    load_nut: float
    """Q_B [N]."""
    angle_screw: float
    """β_A, from n towards s b [rad]."""
    angle_nut: float
    """β_B, of −e_B from n towards s b [rad]."""


def _excess(vector: FloatArray, arm: float) -> float:
    """|v| − arm without cancellation: (|v|² − arm²)/(|v| + arm)."""
    length = float(np.linalg.norm(vector))
    return float((vector - arm * vector / length) @ (vector + arm * vector / length)) / (
        length + arm
    )


def groove_contacts(
    geometry: ScrewGeometry,
    frame: BallFrame,
    flank: int,
    centre_offset: tuple[float, float],
    nut_displacement: float,
    hertz_screw: float,
    hertz_nut: float,
) -> GrooveContacts:
    """(E3.5) for ball-centre offset (c_n, c_b) [m] and nut axial displacement u [m].

    ``hertz_screw``/``hertz_nut``: K_A, K_B of δ = K Q^(2/3) [m N^(−2/3)].
    """
    r_b = geometry.ball_radius
    e0 = contact_vector(frame, geometry.contact_angle, flank, "screw")
    # Everything relative to the unloaded ball centre c₀: δ ~ 1e-8 m is a small difference of
    # lengths ~3e-4 m, which must not be formed from positions ~r_m = 0.02 m away.
    offset = centre_offset[0] * frame.n + centre_offset[1] * frame.b
    arm_s = geometry.screw_groove_radius - r_b
    arm_n = geometry.nut_groove_radius - r_b
    shift = flank * nut_displacement * math.cos(geometry.lead_angle)
    d_a = offset + arm_s * e0  # c − C_s
    d_b = offset - arm_n * e0 - shift * frame.b  # c − C_n
    len_a, len_b = float(np.linalg.norm(d_a)), float(np.linalg.norm(d_b))
    e_a, e_b = d_a / len_a, d_b / len_b
    delta_a = _excess(d_a, arm_s)
    delta_b = _excess(d_b, arm_n)
    return GrooveContacts(
        direction_screw=e_a,
        direction_nut=e_b,
        approach_screw=delta_a,
        approach_nut=delta_b,
        load_screw=(max(delta_a, 0.0) / hertz_screw) ** 1.5,
        load_nut=(max(delta_b, 0.0) / hertz_nut) ** 1.5,
        angle_screw=math.atan2(flank * float(e_a @ frame.b), float(e_a @ frame.n)),
        angle_nut=math.atan2(-flank * float(e_b @ frame.b), -float(e_b @ frame.n)),
    )
