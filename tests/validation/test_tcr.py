"""Element TCR model on a flat, rough steel–steel joint in air against vendor conductance data."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.contact.elastic import composite_modulus
from ballscrew.contact_resistance import FractalTCRModel, element_tcr
from ballscrew.contact_resistance.correlations import (
    CORRELATIONS,
    GaussianJoint,
    fractal_roughness,
    gas_rarefaction_parameter,
)

SOURCE = "Autodesk Moldflow Insight 2014 help, HTC table"
ELEMENT_AREA = 1.0e-6  # m²
MPA = 1.0e6

ASSUMPTIONS = (
    "flat, conforming, nominally ground steel–steel joint in air (source: 'steel/air/steel, "
    "no gap, normal grinding')",
    "fractal roughness D = 1.59, G = 9e-10 m (ASSUMED: the ground raceway of Gao et al. 2019 "
    "stands in for 'normal grinding'; the source gives no roughness)",
    "E = 206 GPa, ν = 0.3 on both sides (E* = 113 GPa), hardness 6.5 GPa, λ = 40 W/mK "
    "(ASSUMED: hardened bearing steel as in the example case; mould steels may be softer)",
    "interstitial air λ_f = 0.026 W/mK (ASSUMED, 20 °C)",
    "element variant V2; the air gap as a gas (Yovanovich 1982): gap model 'mean_plane' "
    "(Y of σ = 0.302 µm over L_u = 0.8 mm) and rarefaction M = αβΛ = 0.273 µm (Λ = 0.064 µm, "
    "γ = 1.4, Pr = 0.71, accommodation 0.87; ASSUMED as the correlation rows)",
    "apparent element area A = 1 mm² (GUESS: the element model depends on A; over "
    "A = 1e-8 … 1e-4 m² it gives h = 4.5e4 … 2.2e4 W/m²K at 7 MPa with the gas gap; with "
    "the MB-cap gap and no M it gave 2.1e6 … 2.2e5, all ≥ 10× the data)",
    "h = 1/(R A) with R the element resistance at load P = p A",
)


SUBJECT = {"model": "element_tcr (fractal, V2)", "source": SOURCE, "assumptions": ASSUMPTIONS}
"""What every comparison of this module shares."""


AIR_STEEL = FractalTCRModel(
    D=1.59,
    G=9e-10,
    E_star=composite_modulus(206e9, 0.3, 206e9, 0.3),
    H=6.5e9,
    lambda_1=40.0,
    lambda_2=40.0,
    lambda_f=0.026,
    gap_model="mean_plane",
    sampling_length=8e-4,
    rarefaction=gas_rarefaction_parameter(0.064e-6, 0.87, 1.4, 0.71),
)
"""The element model of the vendor's ground steel joint in air (V2, gas gap)."""


def _conductance(pressure: float) -> float:
    """h = 1/(R A) of one element under contact pressure ``pressure``, W/(m² K)."""
    result = element_tcr(np.array([pressure * ELEMENT_AREA]), ELEMENT_AREA, AIR_STEEL)
    return float(1.0 / result.unit_area_resistance[0])


@pytest.mark.parametrize("index", [1, 2])
def test_moldflow_steel_air_steel_conductance(validation, dataset, index) -> None:
    data = dataset("tcr", "moldflow_steel_air_steel")
    pressure = data["pressure_MPa"][index]
    validation.check(
        f"moldflow_steel_air_steel_{pressure:g}MPa",
        **SUBJECT,
        reference=data,
        quantity=f"contact conductance at {pressure:g} MPa",
        unit="W/(m² K)",
        measured=data["conductance_W_m2K"][index],
        predicted=_conductance(pressure * MPA),
        tolerance=0.5,
        relative=True,
        tolerance_basis="±10 % stated in the table, widened to ±50 % because the surface's "
        "roughness is not given and the fractal parameters are a stand-in",
        # passes with the gas gap (+18 %, −26 %); the MB-cap gap without M gave +3250 %, +1438 %.
        # h is mostly the gas gap (2.2e4 W/m²K); the V2 spots give 3.3e3 and 5.1e3.
        known_miss=False,
    )


def test_moldflow_conductance_pressure_trend(validation, dataset) -> None:
    data = dataset("tcr", "moldflow_steel_air_steel")
    (_, p7, p15), (_, h7, h15) = data["pressure_MPa"], data["conductance_W_m2K"]
    validation.check(
        "moldflow_steel_air_steel_trend",
        **SUBJECT,
        reference=data,
        quantity=f"h({p15:g} MPa) / h({p7:g} MPa)",
        unit="-",
        measured=h15 / h7,
        predicted=_conductance(p15 * MPA) / _conductance(p7 * MPA),
        tolerance=0.14,
        relative=True,
        tolerance_basis="two values of ±10 % each, in quadrature; the ratio is far less "
        "sensitive to the unknown roughness than the values",
        known_miss=True,  # −38 % (gas gap); −54 % with the MB-cap gap
    )


def test_moldflow_touching_unloaded(validation, dataset) -> None:
    data = dataset("tcr", "moldflow_steel_air_steel")
    validation.not_compared(
        "moldflow_steel_air_steel_0MPa",
        **SUBJECT,
        reference=data,
        quantity="contact conductance at 0 MPa (touching, unloaded)",
        unit="W/(m² K)",
        measured=data["conductance_W_m2K"][0],
        reason="the element model treats an unloaded element as out of contact (R = ∞); the air "
        "conductance of touching, unloaded surfaces is outside its scope. Missing: a gas-gap "
        "conductance model at zero load (e.g. Yovanovich's gap model with the roughness σ).",
    )


CORRELATION_ASSUMPTIONS = (
    "flat, conforming, nominally ground steel–steel joint in air (source: 'steel/air/steel, "
    "no gap, normal grinding')",
    "σ = 0.302 µm, m = 0.0597 from D = 1.59, G = 9e-10 m over the ISO 4288 / ISO 3274 "
    "roughness band λs = 2.5 µm … λc = 0.8 mm (ASSUMED: the ground raceway of Gao et al. 2019 "
    "stands in for 'normal grinding'; the source gives no roughness)",
    "E = 206 GPa, ν = 0.3 on both sides, microhardness 6.5 GPa, λ = 40 W/mK (ASSUMED)",
    "air λ_f = 0.026 W/mK, rarefaction M = αβΛ = 0.273 µm with Λ = 0.064 µm (20 °C, 1 atm), "
    "γ = 1.4, Pr = 0.71 and accommodation coefficient 0.87 (ASSUMED, typical of air on steel)",
    "h = h_c + h_g of the correlation at the apparent pressure (no cell, no element area)",
)
# (model, pressure index) → known miss: the predicted conductance exceeds the +50 % band.
CORRELATION_MISSES = {("CMY", 1), ("Mikic", 1), ("Mikic", 2)}


def _correlation_conductance(model: str, pressure: float) -> float:
    sigma, slope = fractal_roughness(1.59, 9e-10, 8e-4, 2.5e-6)
    joint = GaussianJoint(
        sigma=sigma,
        slope=slope,
        lambda_s=40.0,
        lambda_f=0.026,
        hardness=6.5e9,
        E_star=composite_modulus(206e9, 0.3, 206e9, 0.3),
        rarefaction=gas_rarefaction_parameter(0.064e-6, 0.87, 1.4, 0.71),  # air (Yovanovich 1982)
    )
    return float(CORRELATIONS[model](np.array([pressure]), joint)[0])


@pytest.mark.parametrize("model", ["CMY", "Mikic"])
@pytest.mark.parametrize("index", [1, 2])
def test_moldflow_conductance_by_correlation(validation, dataset, model, index) -> None:
    data = dataset("tcr", "moldflow_steel_air_steel")
    pressure = data["pressure_MPa"][index]
    validation.check(
        f"moldflow_steel_air_steel_{pressure:g}MPa_{model}",
        model=f"{model} correlation + Yovanovich gas gap",
        source=SOURCE,
        assumptions=CORRELATION_ASSUMPTIONS,
        reference=data,
        quantity=f"contact conductance at {pressure:g} MPa",
        unit="W/(m² K)",
        measured=data["conductance_W_m2K"][index],
        predicted=_correlation_conductance(model, pressure * MPA),
        tolerance=0.5,
        relative=True,
        tolerance_basis="±10 % stated in the table, widened to ±50 % because the surface's "
        "roughness is not given and σ, m are a stand-in",
        known_miss=(model, index) in CORRELATION_MISSES,
    )
