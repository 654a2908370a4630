"""Thermal contact resistance (TCR) of ball–raceway contacts from fractal contact mechanics.

Physics reference: ``contact-tcr.md`` §6 (element TCR, T1–T8; variants V2 [REC], MT, V1) and §7
(aggregation A1–A5). Results depend on the fractal cell size Δ_f (§6.5).
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
from ballscrew.thermal.element_resistance import (
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

__all__ = [
    "DEFAULT_CELL_SIZE",
    "GAP_MODELS",
    "VARIANTS",
    "ContactTCR",
    "ElementTCR",
    "FractalTCRModel",
    "constriction_alleviation_factor",
    "contact_tcr",
    "cooper_mikic_yovanovich_conductance",
    "element_tcr",
    "experimental_tcr",
    "gap_conductance",
    "gap_thickness",
    "harmonic_mean_conductivity",
    "heater_power",
    "mean_apparent_area",
    "parallel_resistance",
    "rebin_forces",
    "series_resistance",
    "solid_conductance_mt",
    "solid_conductance_v1",
    "solid_conductance_v2",
    "spot_conductance",
    "unit_area_resistance",
]
