"""The full TCR chain of the TCR reference screw (aggregated R and its trends), through screw_tcr.

The reference numbers were computed on a published grid: 40 × 200 cells over ±2.6 × the
Hertz semi-axis along the rolling direction and ±2.4 × across the groove, element TCR on the
solver cells themselves. The TCR is mesh dependent, so these tests use that grid.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew import load_case
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.tcr_models import gaussian_joint
from ballscrew.case import CaseError
from ballscrew.contact_resistance.correlations import correlation_conductance
from ballscrew.loads import nut_forces

DOC_GRID = {
    "numerics.cells": [40, 200],
    "numerics.box_factor": [2.6, 2.4],
    "tcr.rebin": False,
    "tcr.headline": "V2",  # the paper's cell model, here on the solver cells
}
PAPER_CELLS = {"tcr.headline": "V2"}
"""Gao et al.'s cell model (V2 on 8 µm cells) as the headline: an option, not the default."""


@pytest.fixture
def doc_case(gao_case_path):
    return load_case(gao_case_path, DOC_GRID)


def test_t_agg1_full_chain_on_the_exact_gap(doc_case):
    result = ballscrew.screw_tcr(doc_case, variant="V2")
    assert result.variant == "V2"
    assert result.nut_forces == pytest.approx((1500.0, 1500.0))
    nut = result.nuts[0]
    # P–K on the exact gap (screw and nut contacts): 0.5 % on the stated grid.
    assert nut.screw.contact.solution.dx == pytest.approx(6.14853e-6, rel=1e-5)
    assert nut.screw.contact.solution.dy == pytest.approx(9.92481e-6, rel=1e-5)
    assert nut.screw.contact.solution.peak_pressure == pytest.approx(0.961650e9, rel=5e-3)
    assert nut.screw.contact.solution.approach == pytest.approx(1.434781e-6, rel=5e-3)
    assert nut.nut.contact.solution.peak_pressure == pytest.approx(0.868679e9, rel=5e-3)
    assert nut.nut.contact.solution.approach == pytest.approx(1.404833e-6, rel=5e-3)
    # Full chain (aggregated screw TCR): 3 %.
    assert nut.screw.tcr.resistance == pytest.approx(1.07658, rel=0.03)
    assert nut.nut.tcr.resistance == pytest.approx(0.980292, rel=0.03)
    assert nut.ball_resistance == pytest.approx(2.05687, rel=0.03)
    assert result.resistance == pytest.approx(1.90451e-2, rel=0.03)
    assert result.apparent_area == pytest.approx(7.16536e-6, rel=0.03)
    assert result.resistance_per_area == pytest.approx(1.36465e-7, rel=0.03)
    # Per-nut axial stiffness, 1.5 F/δ_a with δ_a = 4.0217 µm (P4): 559 N/µm.
    assert nut.axial_deflection == pytest.approx(4.0217e-6, rel=5e-3)
    assert nut.axial_stiffness == pytest.approx(559e6, rel=5e-3)


def test_t_agg1_mt_variant(doc_case):
    result = ballscrew.screw_tcr(doc_case, variant="MT")
    assert result.resistance == pytest.approx(5.32407e-3, rel=0.03)
    assert result.resistance_per_area == pytest.approx(3.81488e-8, rel=0.03)


def quadratic(case, **overrides):
    return ballscrew.case.with_overrides(case, {"numerics.gap_model": "quadratic", **overrides})


def test_t_tr1_resistance_falls_with_d(doc_case):
    values = [
        ballscrew.screw_tcr(
            quadratic(doc_case, **{"surface.D": d, "surface.G": 1.38e-10})
        ).resistance
        for d in (1.4, 1.475, 1.59, 1.7)
    ]
    assert np.all(np.diff(values) < 0)
    np.testing.assert_allclose(values, [2.6931e-2, 1.7919e-2, 8.0877e-3, 3.1716e-3], rtol=0.03)


def test_t_tr2_resistance_rises_with_g(doc_case):
    values = [
        ballscrew.screw_tcr(quadratic(doc_case, **{"surface.D": 1.475, "surface.G": g})).resistance
        for g in (5e-11, 1.38e-10, 9e-10, 5e-9)
    ]
    assert np.all(np.diff(values) > 0)
    np.testing.assert_allclose(values, [1.2955e-2, 1.7919e-2, 3.2723e-2, 4.9373e-2], rtol=0.03)


def test_t_tr3_axial_load_through_lift_off(doc_case):
    ratios = [0.0, 1.0, 2.0, 2.5, 2.828, 3.5, 4.0]
    results = [
        ballscrew.screw_tcr(quadratic(doc_case, **{"operating.axial_load": 1500.0 * k}))
        for k in ratios
    ]
    r = np.array([x.resistance for x in results])
    r2 = np.array([x.resistance_per_area for x in results])
    np.testing.assert_allclose(r[1:] / r[0], [1.016, 1.078, 1.152, 1.298, 1.191, 1.131], rtol=0.02)
    np.testing.assert_allclose(
        r2[1:] / r2[0], [1.016, 1.078, 1.152, 1.298, 1.373, 1.425], rtol=0.02
    )
    # Past lift-off (2^{3/2} F_p) only nut 1 carries load, and R″ keeps rising.
    assert [len(x.nuts) for x in results] == [2, 2, 2, 2, 2, 1, 1]
    assert np.all(np.diff(r2[4:]) > 0)


def test_single_nut_tcr_takes_its_loaded_flank(gao_case_path):
    """A preloaded single nut (oversized balls, the default) carries F1 of (P1) on its loaded
    flank, not F_p + F_a (the old one-flank single nut, the bug fixed here), and F2 on the other
    (left out before, a bug fixed here too); without preload it carries F_a."""
    over = {"screw.nuts": 1, "operating.axial_load": 500.0, "numerics.cells_across": 24}
    result = ballscrew.screw_tcr(load_case(gao_case_path, over))
    forces = nut_forces(1500.0, 500.0)
    assert result.nut_forces == pytest.approx((float(forces.f1), float(forces.f2)))
    assert result.nut_forces[0] == pytest.approx(1756.957, rel=1e-6)
    assert [n.index for n in result.nuts] == [1, 2]  # both flanks (the four-point pairs)
    bare = ballscrew.screw_tcr(load_case(gao_case_path, {**over, "operating.preload": 0.0}))
    assert bare.nut_forces == (500.0, 0.0)


def test_rough_ball_is_refused(gao_case_path):
    case = load_case(gao_case_path, {"surface.ball": {"D": 1.5, "G": 1e-10}})
    with pytest.raises(ballscrew.errors.InputError, match=r"surface\.ball"):
        ballscrew.screw_tcr(case)


def test_bad_tcr_options_are_case_errors(gao_case_path):
    with pytest.raises(CaseError, match=r"tcr\.variant"):
        load_case(gao_case_path, {"tcr.variant": "V3"})
    with pytest.raises(CaseError, match=r"tcr\.cell_size"):
        load_case(gao_case_path, {"tcr.cell_size": 0})


def test_fractal_cells_cover_exactly_the_solved_contact_area(gao_case_path):
    result = ballscrew.screw_tcr(load_case(gao_case_path))
    for side in ("screw", "nut"):
        contact = getattr(result.nuts[0], side)
        assert contact.tcr.cell_size == (8e-6, 8e-6)
        assert contact.tcr.apparent_area == pytest.approx(
            contact.contact.solution.contact_area, rel=1e-12
        )


def test_fractal_cell_result_converges_with_the_solver_grid(gao_case_path):
    coarse, fine = (
        ballscrew.screw_tcr(
            load_case(gao_case_path, {**PAPER_CELLS, "numerics.cells_across": n})
        ).resistance
        for n in (64, 128)
    )
    assert fine == pytest.approx(coarse, rel=0.015)
    # ... and lands near the reference solver-cell value of the aggregated TCR (similar cells).
    assert fine == pytest.approx(1.90451e-2, rel=0.05)


def test_fractal_cell_result_is_smooth_in_the_axial_load(gao_case_path):
    base = load_case(gao_case_path, PAPER_CELLS)
    loads = np.linspace(0.0, 2.5 * 1500.0, 6)
    r = [
        ballscrew.screw_tcr(
            ballscrew.case.with_overrides(base, {"operating.axial_load": f})
        ).resistance
        for f in loads
    ]
    assert np.all(np.diff(r) > 0), r  # flat, then rising as nut 2 unloads (paper Fig. 14)
    assert r[-1] / r[0] < 1.1


def test_every_model_on_the_same_contacts(doc_case):
    result = ballscrew.screw_tcr(doc_case)
    assert tuple(result.models) == (
        *("V2", "MT", "V1", "CMY", "Mikic"),
        *("V2/patch", "MT/patch", "V1/patch"),
    )
    headline = result.models[result.variant]
    assert headline.resistance == pytest.approx(result.resistance, rel=1e-12)
    assert headline.resistance_per_area == pytest.approx(result.resistance_per_area, rel=1e-12)
    spread = result.uncertainty
    values = [m.resistance_per_area for m in result.models.values()]
    assert spread.low == min(values) and spread.high == max(values)
    assert spread.ratio > 1.0
    # The Gaussian correlations sit above the fractal variants on this ground raceway.
    assert result.models["CMY"].resistance > result.models["V2"].resistance


def test_correlations_take_measured_roughness(doc_case):
    rough = ballscrew.case.with_overrides(
        doc_case,
        {
            "tcr.headline": "CMY",
            "tcr.models": ["CMY"],
            "tcr.rms_roughness": 0.6e-6,
            "tcr.rms_slope": 0.06,
        },
    )
    smooth = ballscrew.case.with_overrides(rough, {"tcr.rms_roughness": 0.3e-6})
    r_rough = ballscrew.screw_tcr(rough).models["CMY"].resistance
    r_smooth = ballscrew.screw_tcr(smooth).models["CMY"].resistance
    assert ballscrew.screw_tcr(rough).uncertainty is None  # one model: no spread
    assert r_rough > r_smooth  # h_c ∝ m/σ: rougher conducts less


def test_a_correlation_outside_its_range_is_left_out_with_a_warning(doc_case):
    soft = ballscrew.case.with_overrides(
        doc_case, {"materials.screw.hardness": 1.5e9, "materials.nut.hardness": 1.5e9}
    )
    with pytest.warns(UserWarning, match=r"CMY left out"):
        result = ballscrew.screw_tcr(soft)
    assert "CMY" not in result.models and "V2" in result.models


@pytest.mark.parametrize(
    ("overrides", "field"),
    [
        ({"tcr.models": ["V2", "nope"]}, "tcr.models"),
        ({"tcr.cutoff_length": 1e-3, "tcr.sampling_length": 1e-4}, "tcr"),
        ({"tcr.rms_roughness": 1e-6}, "tcr"),
    ],
)
def test_bad_model_options_are_refused(doc_case, overrides, field):
    with pytest.raises(CaseError, match=field):
        ballscrew.case.with_overrides(doc_case, overrides)


def test_patch_models_have_no_cell_size_and_converge_with_the_grid(gao_case_path):
    """MB on the whole Hertz patch: the same R″ for any Δ_f, and grid-converged to 5 %."""

    def r2(**overrides):
        case = load_case(gao_case_path, {"tcr.models": ["V2"], **overrides})
        return {k: m.resistance_per_area for k, m in ballscrew.screw_tcr(case).models.items()}

    fine, coarse = r2(**{"tcr.cell_size": 4e-6}), r2(**{"tcr.cell_size": 16e-6})
    assert coarse["V2"] / fine["V2"] > 1.5  # the cell model follows Δ_f
    assert coarse["V2/patch"] == pytest.approx(fine["V2/patch"], rel=1e-12)
    grid = [r2(**{"numerics.cells_across": n})["V2/patch"] for n in (24, 48)]
    assert grid[1] == pytest.approx(grid[0], rel=0.05)


def test_the_four_contacts_solved_together_equal_the_single_solves(gao_case_path, monkeypatch):
    """Under an axial load both nuts carry different ball loads: four distinct contacts (two
    sides × two nuts), each on its own Hertz-sized cells, solved in one batched call; each
    equals its own single solve (solve_raceway_contact) to 1e-10, with the same iterations."""
    from ballscrew.analyses import screw_tcr as chain
    from ballscrew.analyses.ball_contact import solve_raceway_contact
    from ballscrew.analyses.parameters import ScrewParameters
    from ballscrew.contact import batch

    calls, original = [], batch.solve_batch
    monkeypatch.setattr(
        batch, "solve_batch", lambda h, *a, **k: calls.append(len(h)) or original(h, *a, **k)
    )
    case = load_case(gao_case_path, {"operating.axial_load": "1500 N", "numerics.cells_across": 32})
    result = chain.screw_tcr(case)
    params = ScrewParameters.from_case(case)
    assert len({n.ball_load for n in result.nuts}) == 2
    assert calls == [4]  # one call for all four
    for nut, spec in zip(result.nuts, params.nuts, strict=True):
        for side in ("screw", "nut"):
            together = getattr(nut, side).contact.solution
            alone = solve_raceway_contact(
                params.geometry, side, nut.ball_load, params.contact_modulus(side),
                case.numerics, spec.flank,
            ).solution  # fmt: skip
            assert together.iterations == alone.iterations
            assert (together.dx, together.dy) == (alone.dx, alone.dy)
            np.testing.assert_allclose(
                together.pressure, alone.pressure, rtol=0, atol=1e-10 * alone.peak_pressure
            )
            assert together.approach == pytest.approx(alone.approach, rel=1e-10)


def test_a_gas_in_the_gap_is_a_case_choice(doc_case):
    """Air between the asperities (λ_f = 0.026 W/(m K), M = 0.27 µm): every gap conducts
    λ_f/(L + M) instead of λ_f/L, so each model's R rises against M = 0 (the liquid default);
    the element models across Yovanovich's mean-plane separation (``tcr.gap_model =
    "mean_plane"``) rise further, their gap being microns instead of the MB cap's nanometres."""
    air = {"medium.name": "air", "medium.thermal_conductivity": 0.026, "tcr.models": ["V2", "CMY"]}
    liquid = ballscrew.screw_tcr(ballscrew.case.with_overrides(doc_case, air)).models
    gas = ballscrew.case.with_overrides(doc_case, air | {"medium.rarefaction": 0.27e-6})
    rarefied = ballscrew.screw_tcr(gas).models
    plane = ballscrew.screw_tcr(ballscrew.case.with_overrides(gas, {"tcr.gap_model": "mean_plane"}))
    for name in ("V2", "CMY"):
        assert rarefied[name].resistance > liquid[name].resistance
    assert plane.models["V2"].resistance > rarefied["V2"].resistance
    assert plane.models["CMY"].resistance == pytest.approx(rarefied["CMY"].resistance, rel=1e-12)
    with pytest.raises(CaseError, match=r"medium\.rarefaction"):
        ballscrew.case.with_overrides(doc_case, {"medium.rarefaction": -1e-9})


def test_lift_off_doubles_the_patches_at_root_two_times_the_pressure(gao_case_path):
    """At lift-off (F1 = 2^{3/2} F_p, F2 = 0) a ball of nut 1 carries 2^{3/2} Q_0: Hertz gives it
    patches twice as large at √2 times the pressure, so S does not change and, for a model whose
    conductance is local in the pressure (CMY), R(lift-off)/R(0) = Σ 1/G(√2 p_0) / Σ 1/G(p_0)
    over the screw and nut contacts of the preload solution (theory manual, *Axial load and
    lift-off*). The step's sign is the sign of −dh/dp."""
    base = load_case(gao_case_path, {"numerics.cells_across": 24})
    lifted = ballscrew.case.with_overrides(base, {"operating.axial_load": 4243.0})
    before, after = ballscrew.screw_tcr(base), ballscrew.screw_tcr(lifted)
    assert [n.index for n in after.nuts] == [1]
    assert after.apparent_area == pytest.approx(before.apparent_area, rel=0.01)
    params = ScrewParameters.from_case(base)

    def ball(scale: float) -> float:
        total = 0.0
        for side in ("screw", "nut"):
            sol = getattr(before.nuts[0], side).contact.solution
            joint = gaussian_joint(params, base.tcr, side)
            total += 1.0 / correlation_conductance(
                scale * sol.pressure, sol.dx, sol.dy, joint, "CMY"
            )
        return total

    predicted = ball(math.sqrt(2.0)) / ball(1.0)
    ratio = after.models["CMY"].resistance / before.models["CMY"].resistance
    assert ratio == pytest.approx(predicted, rel=0.01)
    assert predicted == pytest.approx(0.746, abs=0.005)  # h rises with p: R falls by a quarter
