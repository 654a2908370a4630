"""Design check of a ball screw by the makers' formulas: life, static safety, speed and
buckling limits, stiffness of the nut, the shaft and the drive, thermal pretension.

Plain functions of SI numbers; no case. The load ratings C_a and C_0a are catalogue inputs, or
computed from the geometry (:mod:`ballscrew.design.ratings`, Lundberg–Palmgren, and ISO 76 or
Palmgren's permanent deformation).
"""

from ballscrew.design.life import (
    LIFT_OFF_FACTOR,
    RELIABILITY_FACTORS,
    combined_life,
    cube_mean_loads,
    life_hours,
    life_travel,
    preloaded_half_loads,
    rating_life,
    reliability_factor,
    static_safety_factor,
)
from ballscrew.design.rating_factors import (
    ACCURACY_FACTORS,
    accuracy_factor,
    hardness_factor,
)
from ballscrew.design.ratings import (
    MAX_PRELOAD_SHARE,
    STATIC_CONTACT_PRESSURE,
    STATIC_RATING_MODELS,
    balls_per_turn,
    circuit_ball_count,
    dynamic_load_rating,
    static_load_rating,
)
from ballscrew.design.shaft import (
    BUCKLING_SAFETY,
    MOUNTINGS,
    PERMISSIBLE_STRESS,
    SPEED_SAFETY,
    buckling_load,
    maker_buckling_load,
    maker_critical_speed,
    permissible_tension,
    shaft_axial_stiffness,
    thermal_elongation,
    thermal_pretension,
)
from ballscrew.design.stiffness import (
    CATALOGUE_RIGIDITY_SHARE,
    catalogue_nut_rigidity,
    lost_motion,
    nut_load_curve,
    nut_load_deflection,
    nut_stiffness,
    series_stiffness,
)

__all__ = [
    "ACCURACY_FACTORS",
    "BUCKLING_SAFETY",
    "CATALOGUE_RIGIDITY_SHARE",
    "LIFT_OFF_FACTOR",
    "MAX_PRELOAD_SHARE",
    "MOUNTINGS",
    "PERMISSIBLE_STRESS",
    "RELIABILITY_FACTORS",
    "SPEED_SAFETY",
    "STATIC_CONTACT_PRESSURE",
    "STATIC_RATING_MODELS",
    "accuracy_factor",
    "balls_per_turn",
    "buckling_load",
    "catalogue_nut_rigidity",
    "circuit_ball_count",
    "combined_life",
    "cube_mean_loads",
    "dynamic_load_rating",
    "hardness_factor",
    "life_hours",
    "life_travel",
    "lost_motion",
    "maker_buckling_load",
    "maker_critical_speed",
    "nut_load_curve",
    "nut_load_deflection",
    "nut_stiffness",
    "permissible_tension",
    "preloaded_half_loads",
    "rating_life",
    "reliability_factor",
    "series_stiffness",
    "shaft_axial_stiffness",
    "static_load_rating",
    "static_safety_factor",
    "thermal_elongation",
    "thermal_pretension",
]
