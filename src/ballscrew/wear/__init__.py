"""Fractal wear of the screw raceway and the preload/torque degradation it causes.

Theory manual: *Wear* (cell wear rates of Models A and C, wear strips, working raceway length,
reciprocation, worn groove, time integration, drag torque).

1. :mod:`ballscrew.wear.rates`: cell wear rates w(p_asp, |Δv|) of Model A and Model C.
2. :mod:`ballscrew.wear.strips`: strips W_j (E8.1), ḣ_j = Z W_j/L_w (E8.2), L_w (E8.3),
   reciprocation (E8.4).
3. :mod:`ballscrew.wear.profile`: the worn gap g_0 + h(y) for the next contact (E8.5).
4. :mod:`ballscrew.wear.life`: :func:`integrate_wear`, the time integration with preload
   updates (E1.13), drag torque (E9.1) and checkpoint/resume; the case-level
   ``ballscrew.wear_life(case)`` is :mod:`ballscrew.analyses.wear`.
"""

from ballscrew.wear.history import WearLife
from ballscrew.wear.life import check_wear_work, integrate_wear
from ballscrew.wear.preload import PRELOAD_CONTACTS, preload_after
from ballscrew.wear.profile import worn_gap, worn_gap_function
from ballscrew.wear.programme import WearLevel, WearOptions
from ballscrew.wear.rates import WEAR_LAWS, cell_wear_rate, wear_rate_model_a, wear_rate_model_c
from ballscrew.wear.setup import WearSetup
from ballscrew.wear.step import ASPERITY_HEIGHTS, FlankRate, GridEdgeWarning, flank_rate
from ballscrew.wear.strips import (
    depth_per_revolution,
    raceway_depth_rate,
    reciprocating_rate,
    strip_wear_speed,
    working_raceway_length,
)

__all__ = [
    "ASPERITY_HEIGHTS",
    "PRELOAD_CONTACTS",
    "WEAR_LAWS",
    "FlankRate",
    "GridEdgeWarning",
    "WearLevel",
    "WearLife",
    "WearOptions",
    "WearSetup",
    "cell_wear_rate",
    "check_wear_work",
    "depth_per_revolution",
    "flank_rate",
    "integrate_wear",
    "preload_after",
    "raceway_depth_rate",
    "reciprocating_rate",
    "strip_wear_speed",
    "wear_rate_model_a",
    "wear_rate_model_c",
    "working_raceway_length",
    "worn_gap",
    "worn_gap_function",
]
