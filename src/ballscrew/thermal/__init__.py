"""Thermal contact resistance (TCR) of ball–raceway contacts and the ball screw's temperatures.

Physics reference: ``contact-tcr.md`` §6 (element TCR, T1–T8; variants V2 [REC], MT, V1) and §7
(aggregation A1–A5). Results depend on the fractal cell size Δ_f (§6.5).

Temperature field (§9, issue #4): heat sources (Q2–Q4) in :mod:`.heat_sources`, convection
(Q5, Q6) in :mod:`.convection`, the smeared ball contact in :mod:`.constriction`, the problem
in :mod:`.problem`, the 1-D network in :mod:`.network`, the 2-D axisymmetric scikit-fem model
in :mod:`.axisymmetric` (imported on use), solves in :mod:`.simulate`, elongation (Q7) in
:mod:`.elongation`; ``ballscrew.analyses.thermal`` composes them for a case.
"""

from ballscrew.thermal.aggregation import (
    DEFAULT_CELL_SIZE,
    ContactTCR,
    contact_tcr,
    experimental_tcr,
    heater_power,
    mean_apparent_area,
    parallel_resistance,
    rebin_forces,
    series_resistance,
    unit_area_resistance,
)
from ballscrew.thermal.constriction import (
    ball_contact_constriction,
    elliptic_constriction_resistance,
    smeared_conductance,
)
from ballscrew.thermal.convection import (
    Air,
    flat_plate_laminar,
    horizontal_cylinder_natural,
    rotating_cylinder,
)
from ballscrew.thermal.element_resistance import (
    ELEMENT_MODELS,
    GAP_MODELS,
    VARIANTS,
    ElementTCR,
    FractalTCRModel,
    constriction_alleviation_factor,
    cooper_mikic_yovanovich_conductance,
    element_tcr,
    gap_conductance,
    gap_thickness,
    harmonic_mean_conductivity,
    solid_conductance_mt,
    solid_conductance_v1,
    solid_conductance_v2,
    spot_conductance,
)
from ballscrew.thermal.elongation import (
    displacement_profile,
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
    "DEFAULT_CELL_SIZE",
    "ELEMENT_MODELS",
    "GAP_MODELS",
    "THERMAL_MODELS",
    "VARIANTS",
    "Air",
    "AxialGrid",
    "BandHeat",
    "ContactTCR",
    "Convection",
    "ElementTCR",
    "FractalTCRModel",
    "MeshOptions",
    "PalmgrenTorque",
    "RingPart",
    "Sensor",
    "Solid",
    "Solution",
    "ThermalProblem",
    "Transient",
    "axial_grid",
    "ball_contact_constriction",
    "build_model",
    "build_network",
    "constriction_alleviation_factor",
    "contact_tcr",
    "cooper_mikic_yovanovich_conductance",
    "displacement_profile",
    "element_tcr",
    "elliptic_constriction_resistance",
    "experimental_tcr",
    "flat_plate_laminar",
    "friction_heat",
    "gap_conductance",
    "gap_thickness",
    "harmonic_mean_conductivity",
    "heater_power",
    "horizontal_cylinder_natural",
    "mean_apparent_area",
    "nut_heat_shares",
    "palmgren_torque",
    "parallel_resistance",
    "rebin_forces",
    "rotating_cylinder",
    "series_resistance",
    "simulate",
    "smeared_conductance",
    "solid_conductance_mt",
    "solid_conductance_v1",
    "solid_conductance_v2",
    "spot_conductance",
    "thermal_elongation",
    "thermoelastic_elongation",
    "time_to_fraction",
    "unit_area_resistance",
]
