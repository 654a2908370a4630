"""Axial loads: ball load (Q1) and the preloaded double nut (P1)–(P3), (E1.7)–(E1.13).

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

__all__ = [
    "DRAG_TORQUE_MODELS",
    "DragTorqueInputs",
    "NutForces",
    "axial_deflection_from_approaches",
    "ball_load",
    "nut_axial_compliance",
    "nut_axial_deflection",
    "nut_forces",
    "preload_after_wear",
    "preload_drag_torque",
    "preloaded_axial_stiffness",
    "validate_angles",
    "validate_balls",
]
