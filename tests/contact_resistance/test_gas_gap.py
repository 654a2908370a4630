"""Gas gap of the fractal element: rarefaction term M (T10) and the mean-plane gap model (T9)."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from ballscrew.analyses.screw_tcr import screw_tcr
from ballscrew.case import load_case
from ballscrew.contact_resistance import FractalTCRModel, element_tcr, gap_conductance
from ballscrew.contact_resistance.element import gap_thickness
from ballscrew.errors import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
AIR_M = 2.731854729912039e-07  # M = αβΛ of air, 20 °C, 1 atm, TAC 0.87 [m]
AREA = 1.0e-6  # m²
# 304 stainless joint of the textbook validation rows (σ = 1.41 µm, air, 0.32 MPa)
STAINLESS = FractalTCRModel(
    D=1.59, G=1.2325365487103012e-08, E_star=106.04e9, H=3.0e9, lambda_1=15.0, lambda_2=15.0,
    lambda_f=0.026,
)  # fmt: skip
PRESSURE = 0.32035e6  # Pa


def test_rarefaction_zero_is_the_liquid_gap() -> None:
    """M = 0 gives λ_f (A − A_r)/L_g exactly; M → 0 converges to it (relative change ≈ M/L_g)."""
    lam, a_r, l_g = 0.14, 2.0e-8, 5.0e-8
    hand = lam * (AREA - a_r) / l_g
    assert gap_conductance(a_r, l_g, apparent_area=AREA, lambda_f=lam) == pytest.approx(hand)
    small = gap_conductance(a_r, l_g, apparent_area=AREA, lambda_f=lam, rarefaction=5e-14)
    assert small == pytest.approx(hand * (1.0 - 1e-6), rel=1e-9)


def test_free_molecular_limit() -> None:
    """L_g ≪ M: G_g → λ_f (A − A_r)/M, independent of L_g (Yovanovich 1982)."""
    limit = 0.026 * AREA / AIR_M
    for l_g in (1e-11, 1e-10):
        g = gap_conductance(0.0, l_g, apparent_area=AREA, lambda_f=0.026, rarefaction=AIR_M)
        assert g == pytest.approx(limit, rel=l_g / AIR_M * 1.01)
        assert g < limit


def test_element_old_default_unchanged() -> None:
    """The default element (M = 0, gap 'mean_cap') keeps its pre-T10 value in air: 2.849e5."""
    r = element_tcr(np.array([PRESSURE * AREA]), AREA, STAINLESS)
    assert 1.0 / r.unit_area_resistance[0] == pytest.approx(284916.7, rel=1e-4)


def test_element_rarefaction_divides_the_gap() -> None:
    """With M the element's gap conductance is λ_f (A − A_r)/(L_g + M), solid part unchanged."""
    load = np.array([PRESSURE * AREA])
    old = element_tcr(load, AREA, STAINLESS)
    new = element_tcr(load, AREA, replace(STAINLESS, rarefaction=AIR_M))
    l_g = float(old.gap_thickness[0])
    assert l_g == pytest.approx(91.3e-9, rel=1e-3)
    assert new.gap_conductance[0] == pytest.approx(old.gap_conductance[0] * l_g / (l_g + AIR_M))
    assert new.solid_conductance[0] == old.solid_conductance[0]


def test_mean_plane_gap_is_yovanovich_separation() -> None:
    """'mean_plane': L_g = Y = σ√2 erfc⁻¹(2p/H), σ from (F3) over L_u; here Y/σ = 3.702."""
    D, G, L_u = STAINLESS.D, STAINLESS.G, 8e-4
    sigma = math.sqrt(G ** (2 * D - 2) * L_u ** (4 - 2 * D) / (2 * math.log(1.5) * (4 - 2 * D)))
    assert sigma == pytest.approx(1.41e-6, rel=0.01)
    y = gap_thickness(
        1e-12, D=D, G=G, model="mean_plane", sampling_length=L_u, pressure=PRESSURE, hardness=3e9
    )
    # erfc(3.7177/√2) = 2p/H = 2.1357e-4
    assert y / sigma == pytest.approx(3.7024, rel=1e-4)
    assert math.erfc(float(y / sigma) / math.sqrt(2.0)) == pytest.approx(2 * PRESSURE / 3e9, 1e-3)


def test_gas_gap_in_air_near_the_correlation() -> None:
    """V2 with 'mean_plane' + M in air: h ≈ h_s + λ_f/(Y + M) ≈ 4.98e3 W/m²K (was 2.85e5)."""
    gas = replace(STAINLESS, gap_model="mean_plane", sampling_length=8e-4, rarefaction=AIR_M)
    r = element_tcr(np.array([PRESSURE * AREA]), AREA, gas)
    assert 1.0 / r.unit_area_resistance[0] == pytest.approx(4975.0, rel=5e-3)


def test_bad_gas_inputs() -> None:
    with pytest.raises(InputError, match="rarefaction"):
        replace(STAINLESS, rarefaction=-1e-9)
    with pytest.raises(InputError, match="sampling_length"):
        replace(STAINLESS, gap_model="mean_plane")
    with pytest.raises(InputError, match="pressure"):
        gap_thickness(1e-12, D=1.59, G=1e-9, model="mean_plane", sampling_length=1e-3)
    with pytest.raises(InputError, match="rarefaction"):
        gap_conductance(0.0, 1e-8, apparent_area=AREA, lambda_f=0.1, rarefaction=math.nan)
    with pytest.raises(InputError, match=r"p/H = 0\.6"):  # Y = 0 would leave no gap
        gap_thickness(
            1e-12, D=1.59, G=1e-9, model="mean_plane", sampling_length=1e-3, pressure=1.8e9,
            hardness=3e9,
        )  # fmt: skip


def test_oil_lubricated_screw_unchanged() -> None:
    """The oil medium (a liquid, M = 0) leaves the reference screw at its pre-T10 R and R″."""
    case = load_case(EXAMPLE)
    before = {"V2": (0.0194763643, 1.36676420e-07), "V1": (0.0206448951, 1.44876647e-07)}
    for variant, (r, r_area) in before.items():
        result = screw_tcr(case, variant)
        assert result.resistance == pytest.approx(r, rel=1e-3)
        assert result.resistance_per_area == pytest.approx(r_area, rel=1e-3)
