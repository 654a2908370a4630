"""Wear per duty segment at its operating point, the running-in surface and the film supply
factor; the contact-only, flooded, single-surface limit keeps the reference numbers (test_life)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.wear import wear_options, wear_setup
from ballscrew.analyses.wear_duty import CalibrationRangeWarning, duty_programme
from ballscrew.case import Case
from ballscrew.errors import InputError
from ballscrew.fractal.conventions import profile_roughness_from_surface
from ballscrew.wear.life import _State, _step_rates
from ballscrew.wear.programme import RunningIn, WearLevel
from ballscrew.wear.setup import nut_force_pair
from ballscrew.wear.step import flank_rate

from .conftest import REF_PATH

RPM = math.pi / 30.0
SEGMENTS = [
    {"speed": 300 * RPM, "axial_load": 2000.0, "stroke": 0.3, "duration": 600.0},
    {"speed": 0.0, "duration": 300.0},
    {"speed": 1500 * RPM, "axial_load": 1000.0, "stroke": 0.2, "dwell": 1.0, "duration": 300.0},
]


def duty_case(repeat: int = 1, **extra: object) -> Case:
    raw = ballscrew.load_case(REF_PATH).model_dump()
    raw["wear"].pop("programme")
    raw["wear"].update({"grid": [12, 48], "torque_sampling": 2.0e4, **extra})
    raw["medium"].update({"viscosity": None, "pressure_viscosity": None})
    raw["kinematics"]["lubricant"] = "iso_vg_68"
    raw.update({"duty": SEGMENTS, "duty_repeat": repeat})
    return type(ballscrew.load_case(REF_PATH)).model_validate(raw)


@pytest.fixture(scope="module")
def case() -> Case:
    return duty_case()


def test_segments_at_their_operating_points(case: Case) -> None:
    levels = duty_programme(case)
    assert len(levels) == 2  # the standstill wears nothing
    first, second = levels
    assert first.revolutions == pytest.approx(300 / 60 * 600)
    lead = case.screw.lead
    stroke_time = 0.2 / (1500 * RPM * lead / (2 * math.pi))
    share = stroke_time / (stroke_time + 1.0)
    assert second.revolutions == pytest.approx(share * 1500 / 60 * 300)
    assert (first.stroke, second.stroke) == (0.3, 0.2)
    point = ballscrew.operating_point(case, 1500 * RPM, 1000.0)
    assert second.viscosity == pytest.approx(point.viscosity, rel=1e-3)
    assert second.temperature == pytest.approx(point.contact_temperature, abs=0.05)
    assert second.temperature > first.temperature  # faster: hotter, thinner oil
    assert second.viscosity < first.viscosity


def test_programme_and_duty_together_are_refused(case: Case) -> None:
    raw = case.model_dump()
    raw["wear"]["programme"] = [{"axial_load": 1000.0, "speed": 10.0, "revolutions": 1e4}]
    both = type(case).model_validate(raw)
    with pytest.raises(InputError, match=r"wear\.programme"):
        wear_options(both)


def test_duty_life_is_monotone_and_warns_outside_the_calibrated_range(case: Case) -> None:
    with pytest.warns(CalibrationRangeWarning, match="1500 rpm"):
        life = ballscrew.wear_life(case)
    assert life.max_wear_depth[-1] > 0.0
    assert np.all(np.diff(life.max_wear_depth) >= 0.0)
    assert np.all(life.preload >= 0.0) and np.all(np.diff(life.preload) <= 1e-9)
    assert life.level_boundaries[-1] == pytest.approx(
        sum(lv.revolutions for lv in duty_programme(case))
    )


def test_a_repeated_cycle_wears_at_the_weighted_mean_rate() -> None:
    setup = wear_setup(duty_case(repeat=5))
    (cycle,) = setup.spec.programme
    assert cycle.revolutions == pytest.approx(5 * sum(s.revolutions for s in cycle.segments))
    state = _State(0, 0.0, np.zeros((2, setup.y.size)), {}, {}, 0, 0, {})
    mixed = _step_rates(setup, state, setup.initial_preload, cycle)
    parts = sum(
        share * _step_rates(setup, state, setup.initial_preload, part)
        for share, part in cycle.parts()
    )
    np.testing.assert_allclose(mixed, parts, rtol=1e-6, atol=1e-30)


def _rate_1500(setup, level=None) -> float:
    f1 = nut_force_pair(1500.0, 2000.0)[0]
    zero = np.zeros(setup.y.size)
    return float(flank_rate(setup, 1, f1, 1500 * RPM, zero, level=level).depth_per_revolution.max())


def test_film_supply_factor_keeps_the_screw_wearing_at_1500_rpm(ref_case: Case) -> None:
    """Flooded at 0.06 Pa·s the film all but stops the wear at 1500 rpm (3.6e-17 m/rev against
    3.3e-12 m/rev at 100 rpm); a starved or grease supply (φ = 0.3) keeps it at 1e-12 m/rev."""
    setup = wear_setup(ref_case)
    flooded = _rate_1500(setup)
    starved = _rate_1500(
        dataclasses.replace(setup, spec=dataclasses.replace(setup.spec, film_factor=0.3))
    )
    f1 = nut_force_pair(1500.0, 2000.0)[0]
    slow = flank_rate(setup, 1, f1, 100 * RPM, np.zeros(setup.y.size)).depth_per_revolution.max()
    assert flooded < 1e-4 * slow
    assert 0.1 * slow < starved < slow
    same = dataclasses.replace(setup, spec=dataclasses.replace(setup.spec, film_factor=1.0))
    assert _rate_1500(same) == flooded


def test_level_viscosity_is_used(ref_case: Case) -> None:
    """A hot level (η = 0.0123 Pa·s, ISO VG 68 at 80 °C) wears where the 40 °C film does not."""
    setup = wear_setup(ref_case)
    hot = WearLevel(2000.0, 1500 * RPM, 1.0, viscosity=0.0123, pressure_viscosity=1.5e-8)
    assert _rate_1500(setup, hot) > 1e4 * _rate_1500(setup)


def test_running_in_surface_law(ref_case: Case) -> None:
    law = RunningIn(D=1.3, G=1e-9, depth=0.2e-6)
    setup = wear_setup(ref_case)
    rough = dataclasses.replace(setup, spec=dataclasses.replace(setup.spec, running_in=law))
    assert rough.surface_at(0.0).Ds == pytest.approx(2.3)
    assert rough.surface_at(0.0).G == pytest.approx(1e-9)
    worn = rough.surface_at(0.2e-6)
    assert worn.Ds - 2.4 == pytest.approx((2.3 - 2.4) * math.exp(-1.0))
    assert math.log(worn.G / 1e-10) == pytest.approx(math.log(10.0) * math.exp(-1.0))
    assert rough.surface_at(10e-6).G == pytest.approx(1e-10, rel=1e-12)
    assert setup.surface_at(1e-6) is setup.surface  # off by default
    f1 = nut_force_pair(1500.0, 2000.0)[0]
    zero = np.zeros(setup.y.size)
    new = flank_rate(rough, 1, f1, 100 * RPM, zero).depth_per_revolution.max()
    steady = flank_rate(setup, 1, f1, 100 * RPM, zero).depth_per_revolution.max()
    assert new > 1.5 * steady  # the rougher new raceway wears faster


def test_running_in_case_section(coarse_case: Case) -> None:
    from ballscrew.case import with_overrides

    case = with_overrides(
        coarse_case, {"wear.running_in": {"D": 1.3, "G": "1e-9 m", "depth": "0.2 um"}}
    )
    assert wear_options(case).running_in == RunningIn(1.3, 1e-9, 0.2e-6)
    life = ballscrew.wear_life(case)
    base = ballscrew.wear_life(coarse_case)
    assert life.max_wear_depth[-1] > base.max_wear_depth[-1]
    assert np.all(np.diff(life.max_wear_depth) >= 0.0) and life.preload.min() >= 0.0


def test_summary_lists_the_segments_operating_points(case: Case) -> None:
    import json

    from ballscrew.analyses.wear_report import summary

    with pytest.warns(CalibrationRangeWarning):
        result = ballscrew.wear_life(case)
    options = json.loads(json.dumps(summary(result)))["options"]
    assert options["programme"] == "duty" and options["film_factor"] == 1.0
    temperatures = [s["contact_temperature"]["value"] for s in options["segments"]]
    assert temperatures == [lv.temperature for lv in duty_programme(case)]


def test_a_starved_supply_wears_faster_than_a_flooded_one(case: Case) -> None:
    """The wear chain takes the case's supply state: a starved inlet thins the film, the
    asperities carry more of the load and the raceway wears faster (1500 rpm, 1 kN)."""
    starved = ballscrew.case.with_overrides(
        case, {"lubrication.supply": "starved", "lubrication.inlet_ratio": 1.2}
    )
    rates = []
    for c in (case, starved):
        setup = wear_setup(c)
        level = duty_programme(c)[1]
        flank, gap = next(iter(setup.nominal_gap.items()))
        force = nut_force_pair(setup.initial_preload, 1000.0)[0]
        depth = np.zeros(gap.shape[1])
        rates.append(flank_rate(setup, flank, force, 1500 * RPM, depth, level=level))
    flooded, thin = rates
    assert not isinstance(wear_setup(starved).film_model, str)
    assert thin.psi > flooded.psi
    assert thin.depth_per_revolution.max() > flooded.depth_per_revolution.max()


def _band_sigma(D: float, G: float, band: tuple[float, float]) -> float:
    """(F3) written out: σ² = G^(2(D−1)) (L_u^(4−2D) − l_c^(4−2D)) / (2 ln γ (4 − 2D)), γ = 1.5."""
    upper, lower = band
    return math.sqrt(
        G ** (2 * (D - 1))
        * (upper ** (4 - 2 * D) - lower ** (4 - 2 * D))
        / (2 * math.log(1.5) * (4 - 2 * D))
    )


@pytest.mark.parametrize("measured", [None, 2.0e-7])
def test_running_in_acts_on_the_roughness_of_the_film_parameter(measured: float | None) -> None:
    """σ_Λ of Λ = h_c/σ_Λ runs in with the surface: the profile's (F3) at D(h), G(h) of the
    running-in law (the example's G are 3-D surface G, surface.G_convention = "surface": the
    law runs on them and (F3) takes the profile G of each); a measured tcr.rms_roughness (of the
    [surface] raceway) by the same law's ratio, σ_meas Σ(D(h), G(h))/Σ(D_ss, G_ss) — it used to
    stay at σ_meas, the new raceway's Λ ignoring running-in. The engine's wear does not read σ_Λ."""
    overrides: dict[str, object] = {
        "wear.grid": [12, 48],
        "wear.running_in": {"D": 1.3, "G": "1e-9 m", "depth": "0.2 um"},
    }
    if measured is not None:
        overrides.update({"tcr.rms_roughness": measured, "tcr.rms_slope": 0.05})
    setup = wear_setup(ballscrew.load_case(REF_PATH, overrides))
    band = (8e-4, 2.5e-6)  # the [tcr] defaults
    steady = _band_sigma(1.4, profile_roughness_from_surface(1.4, 1e-10), band)
    for h in (0.0, 0.1e-6, 0.2e-6, 1e-6):
        weight = math.exp(-h / 0.2e-6)
        d = 1.4 + (1.3 - 1.4) * weight
        g = math.exp(math.log(1e-10) + (math.log(1e-9) - math.log(1e-10)) * weight)
        sigma = _band_sigma(d, profile_roughness_from_surface(d, g), band)
        expected = sigma if measured is None else measured * sigma / steady
        assert setup.surface_at(h).film_roughness == pytest.approx(expected, rel=1e-12)
    run_in = setup.surface_at(50e-6).film_roughness
    assert run_in == pytest.approx(steady if measured is None else measured, rel=1e-12)
    assert setup.surface_at(0.0).film_roughness > 3.0 * run_in  # the new raceway is rougher
    f1 = nut_force_pair(1500.0, 2000.0)[0]
    zero = np.zeros(setup.y.size)
    new = flank_rate(setup, 1, f1, 100 * RPM, zero)
    assert new.film_parameter == pytest.approx(
        new.film_thickness / setup.surface_at(0.0).film_roughness, rel=1e-12
    )
    other = dataclasses.replace(
        setup, film_roughness=dataclasses.replace(setup.film_roughness, measured=1e-6)
    )
    np.testing.assert_array_equal(
        flank_rate(other, 1, f1, 100 * RPM, zero).depth_per_revolution, new.depth_per_revolution
    )


def test_a_rough_ball_adds_in_quadrature_as_the_raceway_runs_in() -> None:
    """With surface.ball the raceway's σ runs in and the ball's stays: σ_Λ(h) = √(σ_F3(D(h),
    G(h))² + σ_b²) (Tallian 1967); it used to stay at the composite of the [surface] set."""
    setup = wear_setup(
        ballscrew.load_case(
            REF_PATH,
            {
                "wear.grid": [12, 48],
                "wear.running_in": {"D": 1.3, "G": "1e-9 m", "depth": "0.2 um"},
                "surface.ball": {"D": 1.5, "G": "1e-11 m"},
            },
        )
    )
    band = (8e-4, 2.5e-6)
    ball = _band_sigma(1.5, profile_roughness_from_surface(1.5, 1e-11), band)
    assert setup.surface_at(0.0).film_roughness == pytest.approx(
        math.hypot(_band_sigma(1.3, profile_roughness_from_surface(1.3, 1e-9), band), ball),
        rel=1e-12,
    )
    assert setup.surface_at(50e-6).film_roughness == pytest.approx(
        math.hypot(_band_sigma(1.4, profile_roughness_from_surface(1.4, 1e-10), band), ball),
        rel=1e-12,
    )
