"""Thermal contact resistance of ball–raceway contacts (theory manual: *Contact resistance*).

* :mod:`.element` — thermal contact resistance of a fractal contact element: solid spots
  (variants V2, MT, V1 in :data:`ELEMENT_MODELS`) in parallel with the interstitial medium
  (Majumdar & Tien 1991; Gao, Wang & Liu 2019);
* :mod:`.aggregation` — elements of a solved pressure field in parallel, screw and nut contact
  in series, balls and nuts in parallel, and the unit-area value R″ = R·S; the reduction of a
  steady heater experiment;
* :mod:`.constriction` — macro-constriction of the Hertz patches into ball and raceway;
* :mod:`.film_path` — the lubricant film around a ball outside its Hertz patch, a heat path in
  parallel with the patch (``tcr.film_path``).

The element result on Δ_f cells depends on the cell size (a known limitation, see the manual);
:func:`.aggregation.patch_tcr` gives the MB population to the whole solved patch instead.
"""

from ballscrew.contact_resistance.aggregation import (
    DEFAULT_CELL_SIZE,
    ContactTCR,
    contact_tcr,
    experimental_tcr,
    heater_power,
    mean_apparent_area,
    parallel_resistance,
    patch_tcr,
    rebin_forces,
    series_resistance,
    unit_area_resistance,
)
from ballscrew.contact_resistance.constriction import (
    ball_contact_constriction,
    elliptic_constriction_resistance,
    smeared_conductance,
)
from ballscrew.contact_resistance.element import (
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
from ballscrew.contact_resistance.film_path import (
    FilmPath,
    ellipse_gap_conductance,
    hertz_separation,
    loaded_film_conductance,
    with_film_path,
)

__all__ = [
    "DEFAULT_CELL_SIZE",
    "ELEMENT_MODELS",
    "GAP_MODELS",
    "VARIANTS",
    "ContactTCR",
    "ElementTCR",
    "FilmPath",
    "FractalTCRModel",
    "ball_contact_constriction",
    "constriction_alleviation_factor",
    "contact_tcr",
    "cooper_mikic_yovanovich_conductance",
    "element_tcr",
    "ellipse_gap_conductance",
    "elliptic_constriction_resistance",
    "experimental_tcr",
    "gap_conductance",
    "gap_thickness",
    "harmonic_mean_conductivity",
    "heater_power",
    "hertz_separation",
    "loaded_film_conductance",
    "mean_apparent_area",
    "parallel_resistance",
    "patch_tcr",
    "rebin_forces",
    "series_resistance",
    "smeared_conductance",
    "solid_conductance_mt",
    "solid_conductance_v1",
    "solid_conductance_v2",
    "spot_conductance",
    "unit_area_resistance",
    "with_film_path",
]
