"""Axial loads: ball load (Q1), the preloaded double nut (P1)–(P3), (E1.7)–(E1.13), and the
single nut preloaded by oversized balls or an offset lead (:mod:`.preload_method`).

Vectorised functions return NumPy float64 scalars for scalar inputs.
"""

from ballscrew.loads.ball_load import ball_load, validate_angles, validate_balls
from ballscrew.loads.double_nut import (
    NutForces,
    axial_deflection_from_approaches,
    nut_axial_compliance,
    nut_axial_deflection,
    nut_forces,
    preload_after_wear,
    preloaded_axial_stiffness,
)
from ballscrew.loads.drag_torque import (
    DRAG_TORQUE_MODELS,
    DragTorqueInputs,
    preload_drag_torque,
)
from ballscrew.loads.preload_method import (
    PRELOAD_METHODS,
    Flanks,
    flank_forces,
    preload_flanks,
    preload_methods,
)

__all__ = [
    "DRAG_TORQUE_MODELS",
    "PRELOAD_METHODS",
    "DragTorqueInputs",
    "Flanks",
    "NutForces",
    "axial_deflection_from_approaches",
    "ball_load",
    "flank_forces",
    "nut_axial_compliance",
    "nut_axial_deflection",
    "nut_forces",
    "preload_after_wear",
    "preload_drag_torque",
    "preload_flanks",
    "preload_methods",
    "preloaded_axial_stiffness",
    "validate_angles",
    "validate_balls",
]
