"""Temperature field and thermal elongation of the ball screw (theory manual: *Thermal*).

Heat sources in :mod:`.heat_sources`, convection in :mod:`.convection`, the table, coolant and
the natural-convection fixed point in :mod:`.boundary`, the problem in
:mod:`.problem`, the rival discretisations in :mod:`.models` (the 1-D network in
:mod:`.network`, the 2-D axisymmetric scikit-fem model in :mod:`.axisymmetric` and the 3-D model
in :mod:`.threed`, imported on use; their load-independent matrices, built once and re-bound to
new loads, in :mod:`.fe_operator`), solves in :mod:`.simulate`, the elongation in
:mod:`.elongation`; :mod:`ballscrew.analyses.thermal` composes them for a case. The thermal
contact resistance of the balls is :mod:`ballscrew.contact_resistance`.
"""

from ballscrew.thermal.boundary import (
    dittus_boelter,
    fixed_point,
    gnielinski,
    mounting_coefficient,
    pipe_coefficient,
)
from ballscrew.thermal.convection import (
    Air,
    flat_plate_laminar,
    horizontal_cylinder_natural,
    rotating_cylinder,
)
from ballscrew.thermal.elongation import (
    displacement_profile,
    shaft_displacement,
    thermal_elongation,
    thermoelastic_elongation,
)
from ballscrew.thermal.heat_sources import (
    PalmgrenTorque,
    friction_heat,
    nut_heat_shares,
    palmgren_torque,
)
from ballscrew.thermal.models import THERMAL_MODELS, MeshOptions, build_model
from ballscrew.thermal.network import build_network
from ballscrew.thermal.problem import (
    AxialGrid,
    BandHeat,
    Convection,
    RingPart,
    Sensor,
    Solid,
    ThermalProblem,
    axial_grid,
)
from ballscrew.thermal.simulate import Solution, Transient, simulate, time_to_fraction

__all__ = [
    "THERMAL_MODELS",
    "Air",
    "AxialGrid",
    "BandHeat",
    "Convection",
    "MeshOptions",
    "PalmgrenTorque",
    "RingPart",
    "Sensor",
    "Solid",
    "Solution",
    "ThermalProblem",
    "Transient",
    "axial_grid",
    "build_model",
    "build_network",
    "displacement_profile",
    "dittus_boelter",
    "fixed_point",
    "flat_plate_laminar",
    "friction_heat",
    "gnielinski",
    "horizontal_cylinder_natural",
    "mounting_coefficient",
    "nut_heat_shares",
    "palmgren_torque",
    "pipe_coefficient",
    "rotating_cylinder",
    "shaft_displacement",
    "simulate",
    "thermal_elongation",
    "thermoelastic_elongation",
    "time_to_fraction",
]
