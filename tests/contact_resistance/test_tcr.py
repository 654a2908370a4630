"""Element and contact TCR (``docs/theory/contact-resistance.md``): element examples at D = 1.59,
screw aggregation arithmetic and the experiment reduction."""

import math

import numpy as np
import pytest

from ballscrew.contact_resistance import (
    VARIANTS,
    FractalTCRModel,
    ball_contact_constriction,
    constriction_alleviation_factor,
    contact_tcr,
    cooper_mikic_yovanovich_conductance,
    element_tcr,
    elliptic_constriction_resistance,
    experimental_tcr,
    gap_thickness,
    harmonic_mean_conductivity,
    heater_power,
    mean_apparent_area,
    parallel_resistance,
    patch_tcr,
    rebin_forces,
    series_resistance,
    solid_conductance_mt,
    solid_conductance_v2,
    unit_area_resistance,
)
from ballscrew.errors import InputError

E_STAR = 206e9 / (2 * (1 - 0.3**2))
H = 6.5e9
A = 1e-10  # element area of the element examples


def model(**overrides) -> FractalTCRModel:
    params = {
        "D": 1.59,
        "G": 9e-10,
        "E_star": E_STAR,
        "H": H,
        "lambda_1": 40.0,
        "lambda_2": 40.0,
        "lambda_f": 0.14,
    }
    params.update(overrides)
    return FractalTCRModel(**params)


# -------------------------------------------------------------------------- element examples

T_TCR1 = [
    # P [N], L_g [m], G_s [W/K], G_g [W/K], R [K/W], R'' [m²K/W]
    (0.1, 1.35451e-8, 2.80844e-4, 8.46948e-4, 886.69, 8.8669e-8),
    (0.01, 8.16711e-9, 8.1767e-5, 1.68795e-3, 565.06, 5.6506e-8),
    (0.001, 5.09943e-9, 2.5923e-5, 2.74118e-3, 361.39, 3.6139e-8),
]


def test_t_tcr1_v2_all_rows_in_one_call() -> None:
    rows = np.array(T_TCR1)
    res = element_tcr(rows[:, 0], A, model())
    assert res.variant == "V2"
    assert np.all(res.apparent_area == A)
    np.testing.assert_allclose(res.gap_thickness, rows[:, 1], rtol=1e-4)
    np.testing.assert_allclose(res.solid_conductance, rows[:, 2], rtol=1e-4)
    np.testing.assert_allclose(res.gap_conductance, rows[:, 3], rtol=1e-4)
    np.testing.assert_allclose(res.resistance, rows[:, 4], rtol=1e-4)
    np.testing.assert_allclose(res.unit_area_resistance, rows[:, 5], rtol=1e-4)


def test_t_tcr1_mt_at_0_1_n() -> None:
    res = element_tcr(0.1, A, model(variant="MT"))
    assert res.variant == "MT"
    assert float(res.solid_conductance) == pytest.approx(6.14897e-3, rel=1e-4)
    assert float(res.resistance) == pytest.approx(142.94, rel=1e-4)


def test_t_tcr1_v1_at_0_1_n() -> None:
    res = element_tcr(0.1, A, model(variant="V1"))
    assert float(res.solid_conductance) == pytest.approx(1.91796e-4, rel=1e-4)
    # V1 = one spot of the real area: 2 λ_s √(A_r/π) with A_r = 1.80572e-11 (MB element at 0.1 N)
    assert float(res.solid_conductance) == pytest.approx(80 * math.sqrt(1.80572e-11 / math.pi))


def test_t_tcr2() -> None:
    res = element_tcr(0.1, A, model(D=1.475, G=1.38e-10))
    assert float(res.largest_spot_area) == pytest.approx(6.0879e-12, rel=1e-4)
    assert float(res.real_area) / A == pytest.approx(0.20572, rel=1e-4)
    assert float(res.gap_thickness) == pytest.approx(1.5005e-8, rel=1e-4)
    assert float(res.solid_conductance) == pytest.approx(4.1594e-4, rel=1e-4)
    assert float(res.gap_conductance) == pytest.approx(7.4106e-4, rel=1e-4)
    assert float(res.resistance) == pytest.approx(864.30, rel=1e-4)


def test_v2_equals_mt_with_doc_equivalent_cutoff() -> None:
    """(T5) is (T2a) with a_s = 2^(−2/(D−1)) a_l."""
    a_l = np.array([1e-14, 4.06690e-12, 1e-10])
    D = 1.59
    v2 = solid_conductance_v2(a_l, D=D, lambda_s=40.0)
    mt = solid_conductance_mt(a_l, D=D, lambda_s=40.0, cutoff_area=2 ** (-2 / (D - 1)) * a_l)
    np.testing.assert_allclose(mt, v2, rtol=1e-12)


def test_mt_cutoff_scaling_and_zero_below_cutoff() -> None:
    # G_s ∝ a_s^((1−D)/2) for a_s ≪ a_l: 10^((D−1)/2) per decade of a_s
    g = solid_conductance_mt(1e-6, D=1.59, lambda_s=40.0, cutoff_area=[1e-20, 1e-21])
    assert g[1] / g[0] == pytest.approx(10 ** (0.59 / 2), rel=1e-4)
    assert solid_conductance_mt(1e-17, D=1.59, lambda_s=40.0, cutoff_area=1e-16) == 0.0


def test_gap_models() -> None:
    a_l = 4.06690e-12  # Majumdar–Bhushan element example at 0.1 N
    delta_l = 1.35451e-8 * math.pi / 2  # largest asperity's interference, from L_g at 0.1 N
    kw = {"D": 1.59, "G": 9e-10}
    assert float(gap_thickness(a_l, **kw, model="interference")) == pytest.approx(delta_l, 1e-4)
    assert float(gap_thickness(a_l, **kw, model="cap_clearance")) == pytest.approx(
        (1 - 2 / math.pi) * delta_l, rel=1e-4
    )
    assert float(gap_thickness(a_l, **kw, factor=2.0)) == pytest.approx(2 * 1.35451e-8, 1e-4)
    two_sigma = gap_thickness([0.0, a_l, 10 * a_l], **kw, model="two_sigma", sampling_length=1e-3)
    assert two_sigma[0] == math.inf
    assert two_sigma[1] == two_sigma[2] > 0.0
    with pytest.raises(InputError, match="sampling_length"):
        gap_thickness(a_l, **kw, model="two_sigma")
    with pytest.raises(InputError, match="mean_cap, cap_clearance, interference, two_sigma"):
        gap_thickness(a_l, **kw, model="nonsense")


def test_constriction_alleviation_option_t_tcr2_numbers() -> None:
    divisor = (1 - math.sqrt(0.20572)) ** 1.5
    expected = 1 / (4.1594e-4 / divisor + 7.4106e-4)
    res = element_tcr(0.1, A, model(D=1.475, G=1.38e-10, constriction_alleviation=True))
    assert float(res.resistance) == pytest.approx(expected, rel=2e-4)
    assert constriction_alleviation_factor([0.0, 2 * A], apparent_area=A).tolist() == [1.0, 0.0]


def test_unloaded_elements_do_not_conduct() -> None:
    res = element_tcr([0.0, 0.1, 0.0], A, model())
    assert res.resistance[0] == res.resistance[2] == math.inf
    assert res.gap_thickness[0] == math.inf
    assert res.solid_conductance[0] == res.gap_conductance[0] == 0.0
    assert res.resistance[1] == pytest.approx(886.69, rel=1e-4)


def test_v2_resistance_vanishes_with_load_documented_artefact() -> None:
    """Known artefact: R″ rises with pressure in V2; as P → 0, L_g → 0 and R → 0 (all variants)."""
    load = np.logspace(-12, -1, 12)
    for variant in VARIANTS:
        r = element_tcr(load, A, model(variant=variant)).resistance
        assert r[0] < 0.05 * r[-1]
    r_v2 = element_tcr(load, A, model()).resistance
    assert np.all(np.diff(r_v2) > 0.0)


def test_real_area_is_capped_at_apparent_area() -> None:
    res = element_tcr(1e4, A, model())  # absurd load: A_r would exceed A
    assert float(res.real_area) == A
    assert float(res.gap_conductance) == 0.0
    perfect = element_tcr(1e4, A, model(constriction_alleviation=True))
    assert float(perfect.resistance) == 0.0  # alleviation divisor 0: perfect contact


def test_unknown_variant_lists_allowed() -> None:
    with pytest.raises(InputError, match="V2, MT, V1"):
        model(variant="V3")


def test_model_rejects_bad_parameters() -> None:
    with pytest.raises(InputError):
        model(D=2.1)
    with pytest.raises(InputError):
        model(lambda_f=0.0)
    with pytest.raises(InputError):
        model(gap_model="two_sigma")


def test_harmonic_mean_and_cmy() -> None:
    assert harmonic_mean_conductivity(40.0, 40.0) == 40.0
    assert harmonic_mean_conductivity(20.0, 60.0) == pytest.approx(30.0)
    # Example: λ_s = 40, σ = 0.2 µm, m = 0.05, p/H = 0.15 → 2.06e6 W/m²K
    h_c = cooper_mikic_yovanovich_conductance(
        0.15 * H, lambda_s=40.0, slope=0.05, sigma=0.2e-6, hardness=H
    )
    assert float(h_c) == pytest.approx(2.06e6, rel=3e-3)


# ---------------------------------------------------------------------------------- re-binning


def test_rebinning_conserves_force_exactly() -> None:
    rng = np.random.default_rng(7)
    p = rng.uniform(0.0, 1.5e9, size=(37, 53))
    dx, dy = 3.1e-6, 4.7e-6
    total = p.sum() * dx * dy
    for cell in (8e-6, 2.3e-6, 1e-4, dx):
        forces = rebin_forces(p, dx, dy, cell)
        assert forces.sum() == pytest.approx(total, rel=1e-13)
        assert forces.min() >= 0.0


def test_rebinning_partial_cells_share_by_overlap() -> None:
    # 10 cells of 3 µm (30 µm) onto 8 µm cells: 4 cells centred, overlaps 7, 8, 8, 7 µm
    p0 = 2e8
    forces = rebin_forces(np.full((10, 1), p0), 3e-6, 8e-6, 8e-6)
    assert forces.shape == (4, 1)
    np.testing.assert_allclose(forces[:, 0], p0 * 8e-6 * np.array([7, 8, 8, 7]) * 1e-6, rtol=1e-12)


def test_rebinning_aggregates_whole_blocks() -> None:
    p = np.arange(24.0).reshape(4, 6)
    forces = rebin_forces(p, 1.0, 1.0, 2.0)
    expected = p.reshape(2, 2, 3, 2).sum(axis=(1, 3))
    np.testing.assert_allclose(forces, expected, rtol=1e-14)


def test_uniform_pressure_parallel_law_uses_t_tcr1() -> None:
    """Uniform p with p·Δ_f² = 0.1 N on Δ_f = 10 µm: every cell is the 0.1 N example element."""
    p = np.full((40, 24), 0.1 / A)  # 100 µm × 60 µm at 2.5 µm spacing → 10 × 6 cells
    res = contact_tcr(p, 2.5e-6, 2.5e-6, model(), cell_size=1e-5)
    assert res.loaded_cells == 60
    assert res.cell_size == (1e-5, 1e-5)
    assert res.variant == "V2"
    assert res.resistance == pytest.approx(886.69 / 60, rel=1e-4)
    assert res.apparent_area == pytest.approx(60 * A, rel=1e-12)
    assert res.unit_area_resistance == pytest.approx(8.8669e-8, rel=1e-4)
    assert res.cell_resistance.shape == (10, 6)
    np.testing.assert_allclose(res.cell_resistance, 886.69, rtol=1e-4)


@pytest.mark.parametrize("step", [1e-6, 0.5e-6, 0.25e-6])
def test_patch_of_uniform_pressure_is_the_element_example(step: float) -> None:
    """(A1p) on a uniform 10 µm × 10 µm patch carrying 0.1 N (zero pressure around it): one
    element of A = 1e-10 m² at P = 0.1 N, the worked V2 example (886.69 K/W), on any grid."""
    inside = round(1e-5 / step)
    p = np.zeros((inside + 8, inside + 4))
    p[4 : 4 + inside, 2 : 2 + inside] = 0.1 / A
    res = patch_tcr(p, step, step, model())
    assert res.apparent_area == pytest.approx(A, rel=1e-12)
    assert res.elements.load[0, 0] == pytest.approx(0.1, rel=1e-12)
    assert res.resistance == pytest.approx(886.69, rel=1e-4)
    assert res.loaded_cells == 1 and res.cell_resistance.shape == (1, 1)
    # the cell model with one Δ_f cell that is exactly the patch gives the same element
    cell = contact_tcr(p[4 : 4 + inside, 2 : 2 + inside], step, step, model(), cell_size=1e-5)
    assert cell.resistance == pytest.approx(res.resistance, rel=1e-12)


def test_patch_takes_the_total_force_on_the_contact_area() -> None:
    """A non-uniform field: the patch element carries Σ p·dx·dy on N(p > 0)·dx·dy, whatever
    the Δ_f a cell model would use."""
    x = np.linspace(-1.0, 1.0, 41)
    p = 1e9 * np.clip(1.0 - x[:, None] ** 2 - x[None, :] ** 2, 0.0, None) ** 0.5
    res = patch_tcr(p, 2e-6, 3e-6, model())
    assert res.elements.load[0, 0] == pytest.approx(p.sum() * 6e-12, rel=1e-12)
    assert res.apparent_area == pytest.approx(np.count_nonzero(p) * 6e-12, rel=1e-12)
    single = element_tcr(np.array([p.sum() * 6e-12]), res.apparent_area, model())
    assert res.resistance == pytest.approx(single.resistance[0], rel=1e-12)
    with pytest.raises(InputError, match="pressure"):
        patch_tcr(np.zeros((4, 4)), 1e-6, 1e-6, model())


def test_solver_grid_option_and_threshold() -> None:
    p = np.zeros((5, 5))
    p[2, 2] = 0.1 / A
    p[2, 3] = 1e-9 * 0.1 / A  # below the 1e-8 relative threshold: unloaded
    res = contact_tcr(p, 1e-5, 1e-5, model(), cell_size=None)
    assert res.cell_size == (1e-5, 1e-5)
    assert res.loaded_cells == 1
    assert res.resistance == pytest.approx(886.69, rel=1e-4)
    assert res.cell_resistance[2, 3] == math.inf
    with_tiny = contact_tcr(p, 1e-5, 1e-5, model(), cell_size=None, load_threshold=0.0)
    assert with_tiny.loaded_cells == 2
    assert with_tiny.resistance < res.resistance


def test_resistance_falls_when_more_cells_are_loaded() -> None:
    p_small = np.zeros((40, 40))
    p_small[15:25, 15:25] = 1e9
    p_large = np.zeros((40, 40))
    p_large[10:30, 10:30] = 1e9
    r_small = contact_tcr(p_small, 2e-6, 2e-6, model())
    r_large = contact_tcr(p_large, 2e-6, 2e-6, model())
    assert r_large.loaded_cells > r_small.loaded_cells
    assert r_large.resistance < r_small.resistance
    assert r_large.apparent_area > r_small.apparent_area


def test_result_depends_on_cell_size_mesh_dependence() -> None:
    """Mesh dependence: same pressure, different Δ_f, different R_c; the result records Δ_f."""
    p = np.full((48, 48), 1e9)
    coarse = contact_tcr(p, 1e-6, 1e-6, model(), cell_size=8e-6)
    fine = contact_tcr(p, 1e-6, 1e-6, model(), cell_size=4e-6)
    assert coarse.apparent_area == pytest.approx(fine.apparent_area, rel=1e-12)
    assert fine.resistance != pytest.approx(coarse.resistance, rel=1e-2)
    assert (coarse.cell_size, fine.cell_size) == ((8e-6, 8e-6), (4e-6, 4e-6))


def test_contact_tcr_rejects_empty_or_bad_fields() -> None:
    with pytest.raises(InputError, match="at least one cell"):
        contact_tcr(np.zeros((4, 4)), 1e-6, 1e-6, model())
    with pytest.raises(InputError, match="2-D"):
        contact_tcr(np.ones(4), 1e-6, 1e-6, model())
    with pytest.raises(InputError, match="pressure"):
        contact_tcr(-np.ones((4, 4)), 1e-6, 1e-6, model())
    with pytest.raises(InputError, match="cell_size"):
        contact_tcr(np.ones((4, 4)), 1e-6, 1e-6, model(), cell_size=0.0)


# ---------------------------------------------------------------------------------- (A2)–(A5)


def test_series_and_parallel_closed_forms() -> None:
    assert float(series_resistance(1.0, 2.0, 3.5)) == 6.5
    assert float(parallel_resistance([2.0, 2.0])) == pytest.approx(1.0)
    assert float(parallel_resistance([1.0, 2.0, 3.0])) == pytest.approx(6.0 / 11.0)
    assert float(parallel_resistance([math.inf, 4.0])) == pytest.approx(4.0)
    assert float(parallel_resistance([math.inf, math.inf])) == math.inf
    np.testing.assert_allclose(parallel_resistance([[2.0, 2.0], [3.0, 6.0]], axis=1), [1.0, 2.0])
    with pytest.raises(InputError):
        parallel_resistance([0.0, 1.0])


@pytest.mark.parametrize("aspect", [1e-3, 1e-4])
def test_elliptic_constriction_limits(aspect: float) -> None:
    """(A6) in its two limits: Holm's circle 1/(4λa), and the slender ellipse, where
    K(e²) → ln(4a/b) (Abramowitz & Stegun 17.3.26), R → ln(4a/b)/(2πλa); the ball patch adds
    the ball's and the raceway's halves."""
    a, lam = 1e-3, 40.0
    assert elliptic_constriction_resistance(a, a, lam) == pytest.approx(1.0 / (4.0 * lam * a))
    slender = math.log(4.0 / aspect) / (2.0 * math.pi * lam * a)
    assert elliptic_constriction_resistance(aspect * a, a, lam) == pytest.approx(slender, rel=1e-5)
    both = ball_contact_constriction((a, 0.5 * a), 40.0, 20.0)
    half = elliptic_constriction_resistance(a, 0.5 * a, 40.0)
    assert both == pytest.approx(3.0 * half)


def test_t_agg1_chain_arithmetic() -> None:
    """Screw aggregation (A2)–(A4): R_sbn = R_sb + R_bn, 108 balls in parallel, R″ = R·S."""
    r_sbn = series_resistance(1.07658, 0.980292)
    assert float(r_sbn) == pytest.approx(2.05687, rel=1e-5)
    r = parallel_resistance([r_sbn, r_sbn], counts=[54, 54])
    assert float(r) == pytest.approx(1.90451e-2, rel=1e-5)
    assert float(unit_area_resistance(r, 7.16536e-6)) == pytest.approx(1.36465e-7, rel=1e-5)
    # a lifted-off nut contributes nothing (A3)
    lifted = parallel_resistance([r_sbn, math.inf], counts=[54, 54])
    assert float(lifted) == pytest.approx(2.05687 / 54, rel=1e-5)
    assert float(parallel_resistance([r_sbn, r_sbn], counts=[54, 0])) == float(lifted)


def test_mean_apparent_area() -> None:
    assert mean_apparent_area([2e-8, 3e-8], [1e-8, 1e-8], [54, 54]) == pytest.approx(
        54 * (1.5e-8 + 2e-8)
    )


def test_t_exp() -> None:
    assert float(heater_power(24.0, 48.0)) == 12.0
    r = experimental_tcr(
        t_nut=35.0, t_screw=32.0, voltage=24.0, heater_resistance=48.0, area=7.19e-6
    )
    assert float(r) == pytest.approx(1.798e-6, rel=5e-4)
    volts = np.array([24.0, 12.0, 6.0])
    np.testing.assert_allclose(heater_power(volts, 48.0), [12.0, 3.0, 0.75])
    with pytest.raises(InputError):
        experimental_tcr(1.0, 0.0, 0.0, 48.0, 1e-6)
