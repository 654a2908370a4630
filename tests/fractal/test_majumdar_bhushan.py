"""Majumdar–Bhushan contact (F3), (F5)–(F15) against worked examples (D = 1.59, 1.475, 1.5).

Reference numbers are worked examples; the quadrature checks rebuild (F11), (F12) and (F14) from the
single-asperity laws (F6) and the size distribution (F9) written out here.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad

from ballscrew.errors import ConvergenceError, InputError
from ballscrew.fractal import (
    asperity_elastic_load,
    asperity_interference,
    asperity_plastic_load,
    asperity_tip_radius,
    critical_area,
    elastic_load,
    largest_spot_area,
    plastic_load,
    profile_rms_roughness,
    real_contact_area,
    size_distribution,
    total_load,
)

E_STAR = 206e9 / (2 * (1 - 0.3**2))  # 113.187 GPa (K1, steel–steel)
H = 6.5e9
PAPER = {"D": 1.59, "G": 9e-10, "E_star": E_STAR, "H": H}
PSI_DOC = {1.475: 2.02055, 1.5: 2.00071, 1.59: 1.93509}


def test_material_constants_as_in_doc() -> None:
    assert pytest.approx(113.187e9, rel=1e-5) == E_STAR
    assert H / E_STAR == pytest.approx(0.0574272, rel=1e-5)


# ---------------------------------------------------------------------- critical area a_c


@pytest.mark.parametrize(
    ("G", "D", "a_c"),
    [(9e-10, 1.59, 1.36555e-13), (1.38e-10, 1.475, 5.91591e-14), (1e-9, 1.5, 1.47113e-12)],
)
def test_critical_area_t_mb1(G: float, D: float, a_c: float) -> None:
    assert critical_area(D=D, G=G, E_star=E_STAR, H=H) == pytest.approx(a_c, rel=1e-5)


def test_critical_area_overflows_to_inf_near_d_1() -> None:
    assert critical_area(D=1.0 + 1e-3, G=1e-9, E_star=E_STAR, H=H) == math.inf


# ----------------------------------------------------------------------- element at 0.1 N


def test_forward_load_t_mb2() -> None:
    assert float(total_load(1e-12, **PAPER)) == pytest.approx(0.0276611, rel=1e-5)


def test_inversion_table_t_mb2() -> None:
    load = np.array([1e-3, 1e-2, 1e-1])
    a_l = largest_spot_area(load, **PAPER)
    np.testing.assert_allclose(a_l, [3.46497e-14, 3.44737e-13, 4.06690e-12], rtol=1e-5)
    p_e = elastic_load(a_l, **PAPER)
    p_p = plastic_load(a_l, **PAPER)
    # 1e-3 N: all plastic, A_r = P/H
    assert p_e[0] == 0.0
    assert p_p[0] == pytest.approx(1e-3, rel=1e-12)
    assert p_e[1] / load[1] == pytest.approx(0.1771, abs=5e-5)
    assert p_e[2] == pytest.approx(0.0414667, rel=1e-5)
    assert p_p[2] == pytest.approx(0.0585333, rel=1e-5)
    a_r = real_contact_area(a_l, D=1.59)
    np.testing.assert_allclose(a_r, [1.53846e-13, 1.53065e-12, 1.80572e-11], rtol=1e-5)
    assert a_r[0] == pytest.approx(1e-3 / H, rel=1e-12)


def test_inversion_is_exact_in_plastic_regime() -> None:
    a_c = critical_area(**PAPER)
    p_c = float(total_load(a_c, **PAPER))
    load = p_c * np.array([1e-12, 1e-3, 0.5, 1.0])
    np.testing.assert_allclose(largest_spot_area(load, **PAPER), load / p_c * a_c, rtol=1e-14)


# --------------------------------------------------------------------- D = 1.5 log branch


def test_d_15_log_branch_t_mb3() -> None:
    kw = {"D": 1.5, "G": 1e-9, "E_star": E_STAR, "H": H}
    a_l = float(largest_spot_area(0.1, **kw))
    assert a_l == pytest.approx(4.28092e-12, rel=1e-5)
    assert float(elastic_load(a_l, **kw)) / 0.1 == pytest.approx(0.2399, abs=5e-5)
    # (F13) written out: P_e = c √π E* G^(1/2) a_l^(3/4) ln(a_l/a_c), c = ψ^(1/4)
    c = PSI_DOC[1.5] ** 0.25
    a_c = 1.47113e-12
    f13 = c * math.sqrt(math.pi) * E_STAR * 1e-9**0.5 * a_l**0.75 * math.log(a_l / a_c)
    assert float(elastic_load(a_l, **kw)) == pytest.approx(f13, rel=2e-5)


def test_d_near_15_agrees_to_6_digits_t_mb3() -> None:
    base = {"G": 1e-9, "E_star": E_STAR, "H": H}
    a15 = float(largest_spot_area(0.1, D=1.5, **base))
    a16 = float(largest_spot_area(0.1, D=1.5 + 1e-6, **base))
    assert f"{a15:.5e}" == f"{a16:.5e}"  # six significant digits
    assert abs(a16 / a15 - 1) < 2e-6


@pytest.mark.parametrize("eps", [1e-15, 1e-12, 1e-9])
def test_d_15_branch_is_smooth(eps: float) -> None:
    base = {"G": 1e-9, "E_star": E_STAR, "H": H}
    a_l = np.array([2e-12, 1e-11, 1e-9])
    centre = elastic_load(a_l, D=1.5, **base)
    for d in (1.5 - eps, 1.5 + eps):
        # the change is first order in eps with an O(10) coefficient; no cancellation noise
        np.testing.assert_allclose(elastic_load(a_l, D=d, **base), centre, rtol=100 * eps + 1e-14)


# ------------------------------------------------------------------------------ (F3), (F5)–(F14)


@pytest.mark.parametrize("D", [1.475, 1.59])
def test_real_area_and_loads_match_quadrature(D: float) -> None:
    """(F11), (F12), (F14) equal the integrals of (F6)·(F9) over the spot population."""
    G = 9e-10
    c = PSI_DOC[D] ** ((2 - D) / 2)
    a_c = G**2 * (2 * E_STAR / H) ** (2 / (D - 1))
    a_l = 300 * a_c

    def n(a: float) -> float:  # (F9)
        return D / 2 * c * a_l ** (D / 2) * a ** (-(D + 2) / 2)

    def f_e(a: float) -> float:  # (F6)
        return 4 * math.sqrt(math.pi) / 3 * E_STAR * G ** (D - 1) * a ** ((3 - D) / 2)

    def in_log(f):  # integrate f(a) da as f(e^t) e^t dt
        return lambda t: f(math.exp(t)) * math.exp(t)

    pe, _ = quad(in_log(lambda a: f_e(a) * n(a)), math.log(a_c), math.log(a_l), epsrel=1e-12)
    pp, _ = quad(in_log(lambda a: H * a * n(a)), -200.0, math.log(a_c), epsrel=1e-12, limit=200)
    ar, _ = quad(in_log(lambda a: a * n(a)), -200.0, math.log(a_l), epsrel=1e-12, limit=200)
    kw = {"D": D, "G": G, "E_star": E_STAR, "H": H}
    assert float(elastic_load(a_l, **kw)) == pytest.approx(pe, rel=1e-5)
    assert float(plastic_load(a_l, **kw)) == pytest.approx(pp, rel=1e-5)
    assert float(real_contact_area(a_l, D=D)) == pytest.approx(ar, rel=1e-5)


def test_single_asperity_laws() -> None:
    a = np.array([1e-14, 1e-12])
    D, G = 1.59, 9e-10
    np.testing.assert_allclose(
        asperity_interference(a, D=D, G=G), G ** (D - 1) * a ** ((2 - D) / 2), rtol=1e-14
    )
    np.testing.assert_allclose(
        asperity_tip_radius(a, D=D, G=G), a ** (D / 2) / (math.pi**2 * G ** (D - 1)), rtol=1e-14
    )
    np.testing.assert_allclose(
        asperity_elastic_load(a, D=D, G=G, E_star=E_STAR),
        4 * math.sqrt(math.pi) / 3 * E_STAR * G ** (D - 1) * a ** ((3 - D) / 2),
        rtol=1e-14,
    )
    np.testing.assert_allclose(asperity_plastic_load(a, H=H), H * a, rtol=1e-15)


def test_size_distribution_is_zero_above_largest_spot() -> None:
    n = size_distribution([1e-13, 1e-12, 2e-12], 1e-12, D=1.59)
    assert n[0] > n[1] > 0.0
    assert n[2] == 0.0
    # (F9) at a = a_l: (D/2) c a_l^(-1)
    assert n[1] == pytest.approx(0.795 * 1.14492 / 1e-12, rel=1e-5)


def test_profile_rms_roughness_integrates_the_psd() -> None:
    D, G, L_u, w_h, gamma = 1.59, 9e-10, 1e-3, 1e7, 1.5

    def psd(w: float) -> float:  # (F2)
        return G ** (2 * (D - 1)) / (2 * math.log(gamma)) * w ** (-(5 - 2 * D))

    var, _ = quad(lambda t: psd(math.exp(t)) * math.exp(t), math.log(1 / L_u), math.log(w_h))
    assert profile_rms_roughness(D, G, L_u, w_h, gamma) == pytest.approx(math.sqrt(var), rel=1e-8)
    assert profile_rms_roughness(D, G, L_u) > profile_rms_roughness(D, G, L_u, w_h)


# ---------------------------------------------------------------------------------- properties


@settings(max_examples=40, deadline=None)
@given(D=st.floats(1.05, 1.95), log_g=st.floats(-12.0, -8.0))
def test_load_continuous_and_increasing(D: float, log_g: float) -> None:
    kw = {"D": D, "G": 10.0**log_g, "E_star": E_STAR, "H": H}
    a_c = critical_area(**kw)
    if math.isfinite(a_c) and a_c < 1e300:
        below, at, above = total_load(a_c * np.array([1 - 1e-12, 1.0, 1 + 1e-12]), **kw)
        assert below < at < above
        assert above / below - 1 < 1e-11
    a_l = np.logspace(-40, 0, 4001)
    p = total_load(a_l, **kw)
    assert np.all(np.diff(p) > 0.0)


@settings(max_examples=40, deadline=None)
@given(D=st.floats(1.05, 1.95), log_g=st.floats(-12.0, -8.0))
def test_inversion_round_trip_twelve_decades(D: float, log_g: float) -> None:
    kw = {"D": D, "G": 10.0**log_g, "E_star": E_STAR, "H": H}
    load = np.logspace(-9, 3, 241)
    a_l = largest_spot_area(load, **kw)
    np.testing.assert_allclose(total_load(a_l, **kw), load, rtol=1e-10)
    assert np.all(np.diff(a_l) > 0.0)


def test_inversion_keeps_shape_and_zero_load() -> None:
    load = np.array([[0.0, 1e-3], [0.1, 0.0]])
    a_l = largest_spot_area(load, **PAPER)
    assert a_l.shape == (2, 2)
    assert a_l[0, 0] == 0.0
    assert a_l[1, 1] == 0.0
    assert a_l[1, 0] == pytest.approx(4.06690e-12, rel=1e-5)


def test_inversion_reports_non_convergence() -> None:
    with pytest.raises(ConvergenceError, match="largest_spot_area"):
        largest_spot_area([1e-1, 1.0], max_iter=1, **PAPER)


@pytest.mark.parametrize("bad", [-1e-3, math.nan, math.inf])
def test_inversion_rejects_bad_loads(bad: float) -> None:
    with pytest.raises(InputError, match="load"):
        largest_spot_area([0.1, bad], **PAPER)


@pytest.mark.parametrize(
    "kw",
    [
        {"D": 1.59, "G": 0.0, "E_star": E_STAR, "H": H},
        {"D": 1.59, "G": 9e-10, "E_star": -1.0, "H": H},
        {"D": 1.59, "G": 9e-10, "E_star": E_STAR, "H": math.nan},
        {"D": 2.0, "G": 9e-10, "E_star": E_STAR, "H": H},
    ],
)
def test_rejects_bad_surface(kw: dict) -> None:
    with pytest.raises(InputError):
        total_load(1e-12, **kw)
