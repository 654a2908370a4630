"""The cell-free fractal models (MB on the whole apparent area) on the flat-joint rows.

``V2/patch``, ``V1/patch`` and ``MT/patch`` give the Majumdar–Bhushan spot population to the
whole apparent contact instead of an arbitrary cell. On a ball–raceway contact that is the Hertz
patch; on the flat joints of the textbook and vendor tables it is the specimen's face, which the
sources do not give: a 25.4 mm (1 in) disc is ASSUMED, typical of contact-conductance test
specimens. Every other input is that of ``test_tcr_textbook.py`` (Fried, Lienhard) and
``test_tcr.py`` / ``test_tcr_sources.py`` (vendor), with the same gap and medium terms (no gap
conduction in vacuum; Yovanovich's gas gap Y + M in air) and the same tolerances, fixed before
predicting. These rows are the evidence for the choice of the headline model (theory manual,
*Which model is the headline*): the correlations CMY and Mikic pass 5 of these 13 rows each,
the patch models 3 (V2, V1) and 1 (MT).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from ballscrew.contact_resistance import FractalTCRModel, element_tcr

from .test_tcr import AIR_STEEL
from .test_tcr import SOURCE as VENDOR
from .test_tcr_sources import BECU_AIR
from .test_tcr_textbook import (
    ASSUMPTIONS,
    LIENHARD_PRESSURE,
    METALS,
    MPA,
    STAINLESS,
    TOLERANCE_BASIS,
    element_model,
)

DATA = Path(__file__).parent / "data" / "tcr.toml"
SPECIMEN_AREA = math.pi * 0.0254**2 / 4  # m², a 1 in disc (ASSUMED: the sources give none)
PATCH_MODELS = ("V2", "V1", "MT")
SPECIMEN = (
    "apparent area of the MB population: the specimen's face, a 25.4 mm disc (5.07e-4 m², "
    "ASSUMED; the element rows use a 1 mm² cell, GUESS); MB's conductance per unit area "
    "falls as this area grows (V2, V1 as A^-1/2 for the spots)"
)

# (row, model) within the tolerance at the 1 in disc; every other pair is a strict xfail. The
# errors against the middle of each range: V2/patch and V1/patch −99 … −94 % on every vacuum
# row (the spots alone, 15–100× low), +65 % on Lienhard's stainless steel in air, −68 % on
# copper in air and −100 % on BeCu at 330 MPa; MT/patch +14 % on stainless steel at 0.1 MPa in
# vacuum, +180 … +5700 % elsewhere.
PASSES = {
    ("lienhard_aluminium_air", "V2"),
    ("lienhard_aluminium_air", "V1"),
    ("moldflow_steel_air_steel_7MPa", "V2"),
    ("moldflow_steel_air_steel_7MPa", "V1"),
    ("moldflow_steel_air_steel_15MPa", "V2"),
    ("moldflow_steel_air_steel_15MPa", "V1"),
    ("fried_stainless_vacuum_0.1MPa", "MT"),
}


def _h(model: FractalTCRModel, pressure: float) -> float:
    """h = 1/R″ of the MB population of the whole specimen at ``pressure`` [W/(m² K)]."""
    result = element_tcr(np.array([pressure * SPECIMEN_AREA]), SPECIMEN_AREA, model)
    return float(1.0 / result.unit_area_resistance[0])


def _textbook_rows() -> list[tuple[str, str, float, str, str, float, float]]:
    """(row id, dataset key, pressure [Pa], medium, metal, low, high [W/(m² K)]) of every
    Fried and Lienhard row of ``test_tcr_textbook.py``."""
    with DATA.open("rb") as fh:
        data = tomllib.load(fh)
    rows = []
    fs, fm = data["fried_stainless_vacuum"], data["fried_metals_vacuum"]
    for i, mpa in enumerate(fs["pressure_MPa"]):
        low, high = 1.0 / fs["resistance_high_m2K_W"][i], 1.0 / fs["resistance_low_m2K_W"][i]
        rows.append((f"fried_stainless_vacuum_{mpa:g}MPa", "fried_stainless_vacuum", mpa * MPA,
                     "vacuum", "stainless", low, high))  # fmt: skip
    for m, name in enumerate(fm["metals"]):
        for i, mpa in enumerate(fm["pressure_MPa"]):
            low = 1.0 / fm["resistance_high_m2K_W"][m][i]
            high = 1.0 / fm["resistance_low_m2K_W"][m][i]
            rows.append((f"fried_{name}_vacuum_{mpa:g}MPa", "fried_metals_vacuum", mpa * MPA,
                         "vacuum", name, low, high))  # fmt: skip
    for key, names, media in (
        ("lienhard_stainless", ["stainless", "stainless"], data["lienhard_stainless"]["media"]),
        ("lienhard_metals_air", data["lienhard_metals_air"]["metals"], ["air", "air"]),
    ):
        entry = data[key]
        for i, (name, medium) in enumerate(zip(names, media, strict=True)):
            low, high = entry["conductance_low_W_m2K"][i], entry["conductance_high_W_m2K"][i]
            rows.append((f"lienhard_{name}_{medium}", key, LIENHARD_PRESSURE, medium, name,
                         low, high))  # fmt: skip
    return rows


def _check(validation, data, row, variant, predicted, low, high, assumptions) -> None:
    validation.check(
        f"{row}_{variant}_patch",
        model=f"element {variant} on the whole apparent area ({variant}/patch)",
        source=data["citation"],
        assumptions=(*assumptions, SPECIMEN),
        reference=data,
        quantity="contact conductance",
        unit="W/(m² K)",
        measured=0.5 * (low + high),
        predicted=predicted,
        tolerance=(high - low) / (high + low),
        relative=True,
        tolerance_basis=TOLERANCE_BASIS,
        known_miss=(row, variant) not in PASSES,
    )


@pytest.mark.parametrize("variant", PATCH_MODELS)
@pytest.mark.parametrize("row", _textbook_rows(), ids=lambda row: row[0])
def test_textbook_rows(validation, dataset, variant, row) -> None:
    row_id, key, pressure, medium, name, low, high = row
    metal = STAINLESS if name == "stainless" else METALS[name]
    h = _h(element_model(variant, medium, metal), pressure)
    assumptions = ASSUMPTIONS if metal is STAINLESS else (metal.note, *ASSUMPTIONS[2:])
    _check(validation, dataset("tcr", key), row_id, variant, h, low, high, assumptions)


@pytest.mark.parametrize("variant", PATCH_MODELS)
@pytest.mark.parametrize("index", [1, 2])
def test_moldflow_steel_air_steel(validation, dataset, variant, index) -> None:
    data = dataset("tcr", "moldflow_steel_air_steel")
    pressure = data["pressure_MPa"][index]
    measured = data["conductance_W_m2K"][index]
    h = _h(replace(AIR_STEEL, variant=variant), pressure * MPA)
    row = f"moldflow_steel_air_steel_{pressure:g}MPa"
    basis = (f"{VENDOR}: ground steel, air, D = 1.59, G = 9e-10 m as test_tcr.py",)
    _check(validation, data, row, variant, h, 0.5 * measured, 1.5 * measured, basis)


@pytest.mark.parametrize("variant", PATCH_MODELS)
def test_moldflow_becu_air_steel(validation, dataset, variant) -> None:
    data = dataset("tcr", "moldflow_becu_air_steel")
    measured = data["conductance_W_m2K"]
    h = _h(replace(BECU_AIR, variant=variant), data["pressure_MPa"] * MPA)
    basis = (f"{VENDOR}: BeCu–steel, air, 330 MPa, as test_tcr_sources.py",)
    row = "moldflow_becu_air_steel_330MPa"
    _check(validation, data, row, variant, h, 0.5 * measured, 1.5 * measured, basis)
