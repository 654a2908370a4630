"""The supplied film: starved and greased inlets, inlet heating, the [lubrication] section."""

from __future__ import annotations

import itertools
import json
import math

import pytest
from typer.testing import CliRunner

import ballscrew
from ballscrew.analyses.friction import friction_torque
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.parameters import ScrewParameters, track_replenishment
from ballscrew.case import CaseError
from ballscrew.cli import app
from ballscrew.contact.hertz import hamrock_brewe
from ballscrew.errors import InputError
from ballscrew.lubrication import hamrock_dowson
from ballscrew.lubrication.film_corrections import (
    critical_inlet_ratio,
    dowson_higginson_density,
    thermal_loading,
    thermal_reduction_gupta,
)
from ballscrew.lubrication.lubricant_library import library_lubricant
from ballscrew.lubrication.supply import Replenishment, supplied_film_model

# contact A of the reference screw (tests/lubrication/test_film.py)
RX, RY, E_PRIME = 2.820e-3, 34.93e-3, 2.2637e11
ETA, ALPHA, U, Q = 0.06, 2.1e-8, 0.09333, 39.41
ARGS = (RX, RY, E_PRIME, ETA, ALPHA, U, Q)


def test_nothing_to_correct_keeps_the_registered_name():
    assert supplied_film_model("hamrock_dowson") == "hamrock_dowson"


def test_starved_film_is_the_published_power_of_the_inlet_distance():
    flooded = hamrock_dowson(*ARGS)
    b = hamrock_brewe(RX, RY, 0.5 * E_PRIME, Q).a
    m_star = critical_inlet_ratio(RX, b, flooded.central, True)
    assert m_star > 1.0
    m = 1.0 + 0.25 * (m_star - 1.0)
    starved = supplied_film_model("hamrock_dowson", inlet_ratio=m)(*ARGS)
    # Hamrock & Dowson (1977, IV): h_c,S/h_c,F = ((m − 1)/(m* − 1))^0.29
    assert starved.central / flooded.central == pytest.approx(0.25**0.29, rel=1e-12)
    at_critical = supplied_film_model("hamrock_dowson", inlet_ratio=m_star)(*ARGS)
    assert at_critical.central == pytest.approx(flooded.central, rel=1e-12)


def test_starvation_drives_the_film_to_zero_as_the_meniscus_reaches_the_hertz_edge():
    flooded = hamrock_dowson(*ARGS).central
    films = [
        supplied_film_model("hamrock_dowson", inlet_ratio=m)(*ARGS).central
        for m in (1.5, 1.1, 1.01, 1.0001, 1.0)
    ]
    assert all(b < a for a, b in itertools.pairwise(films))
    assert films[0] < flooded and films[-2] < 0.1 * flooded and films[-1] == 0.0


def test_thermal_factor_is_gupta_at_the_lubricants_loading():
    oil = library_lubricant("iso_vg_68").at(313.15)
    thermal = (oil.temperature_viscosity, oil.conductivity)
    fast = (RX, RY, E_PRIME, ETA, ALPHA, 20.0, Q)
    film = supplied_film_model("hamrock_dowson", thermal=thermal)(*fast)
    loading = thermal_loading(*thermal[:1], ETA, 20.0, thermal[1])
    p_h = hamrock_brewe(RX, RY, 0.5 * E_PRIME, Q).p0
    phi = thermal_reduction_gupta(loading, p_h / E_PRIME)
    assert film.central == pytest.approx(phi * hamrock_dowson(*fast).central, rel=1e-12)
    assert phi == pytest.approx(0.438, abs=1e-3)  # L = 9.3 at 20 m/s, VG 68 at 40 °C
    slow = supplied_film_model("hamrock_dowson", thermal=thermal)(*ARGS)
    assert slow.central == pytest.approx(hamrock_dowson(*ARGS).central, rel=5e-3)


# a 40 mm pitch-diameter screw with 6.35 mm balls whose balls roll at u_e = 0.0099 m/s per rad/s
GREASED = Replenishment(0.040, 6.35e-3, 870.0, 1.0 / 0.0099)


def _args(speed):
    return (RX, RY, E_PRIME, ETA, ALPHA, speed, Q)


def test_greased_film_is_the_skf_replenishment_factor_of_the_flooded_film():
    model = supplied_film_model("hamrock_dowson", replenishment=GREASED)
    for u in (0.01, 0.1, 1.0):
        # SKF (2013) in catalogue units: ν [mm²/s], n [r/min], d + D = 2 d_m, D − d = D_w/0.3
        nu, n = ETA / 870.0 * 1e6, u / 0.0099 * 30.0 / math.pi
        phi = math.exp(-6e-8 * nu * n * 80.0 * math.sqrt(3.1 / (2.0 * 6.35 / 0.3)))
        flooded, film = hamrock_dowson(*_args(u)), model(*_args(u))
        assert film.central / flooded.central == pytest.approx(phi, rel=1e-12)
        assert film.minimum / flooded.minimum == pytest.approx(phi, rel=1e-12)


def test_greased_film_is_flooded_at_rest_and_thins_relative_to_it_with_speed():
    model = supplied_film_model("hamrock_dowson", replenishment=GREASED)
    speeds = (1e-5, 0.01, 0.1, 0.5, 1.0, 3.0)
    ratios = [model(*_args(u)).central / hamrock_dowson(*_args(u)).central for u in speeds]
    assert ratios[0] == pytest.approx(1.0, abs=1e-6)
    assert all(b < a for a, b in itertools.pairwise(ratios)) and ratios[-1] < 0.8
    slower_oil = Replenishment(0.040, 6.35e-3, 870.0, 1.0 / 0.0099, constant=3e-8)
    oil = supplied_film_model("hamrock_dowson", replenishment=slower_oil)(*_args(1.0))
    assert oil.central > model(*_args(1.0)).central  # oil bath refills faster than grease


def test_replenishment_agrees_with_the_meniscus_rule_where_both_are_flooded():
    """Both starvation rules leave the film flooded at low speed (the meniscus of the former
    grease default, m = 1.5, lies beyond m*), and part as the contact speeds up."""
    meniscus = supplied_film_model("hamrock_dowson", inlet_ratio=1.5)
    greased = supplied_film_model("hamrock_dowson", replenishment=GREASED)
    slow = _args(1e-4)
    assert meniscus(*slow).central == hamrock_dowson(*slow).central
    assert greased(*slow).central == pytest.approx(hamrock_dowson(*slow).central, rel=1e-5)
    fast = _args(1.0)
    assert greased(*fast).central < hamrock_dowson(*fast).central
    assert meniscus(*fast).central < hamrock_dowson(*fast).central


def test_case_grease_replenishes_unless_given_a_meniscus(wear_case_path):
    grease = ballscrew.load_case(wear_case_path, {"lubrication.supply": "grease"})
    assert grease.lubrication.replenished and grease.lubrication.meniscus is None
    rep = track_replenishment(grease, 870.0)
    geometry = ScrewParameters.from_case(grease).geometry
    assert (rep.pitch_diameter, rep.ball_diameter) == (
        geometry.pitch_diameter,
        geometry.ball_diameter,
    )
    meniscus = ballscrew.load_case(
        wear_case_path, {"lubrication.supply": "grease", "lubrication.inlet_ratio": 1.5}
    )
    assert not meniscus.lubrication.replenished and meniscus.lubrication.meniscus == 1.5
    assert track_replenishment(meniscus, 870.0) is None
    starved = ballscrew.load_case(
        wear_case_path, {"lubrication.supply": "starved", "lubrication.inlet_ratio": 2.0}
    )
    assert not starved.lubrication.replenished


def _case(path, overrides):
    return ballscrew.load_case(path, {"friction.model": "ball_model", **overrides})


def test_case_supply_thins_the_film_of_every_chain(wear_case_path):
    flooded = _case(wear_case_path, {})
    starved = _case(
        wear_case_path, {"lubrication.supply": "starved", "lubrication.inlet_ratio": 1.05}
    )
    grease = _case(wear_case_path, {"lubrication.supply": "grease"})
    hot = _case(wear_case_path, {"lubrication.thermal": True})
    films = {
        name: ball_model(case).film(60.0, 0.5).central
        for name, case in (("flooded", flooded), ("starved", starved), ("grease", grease))
    }
    assert films["starved"] < films["grease"] < films["flooded"]
    assert ball_model(hot).film(60.0, 5.0).central < ball_model(flooded).film(60.0, 5.0).central
    dry = friction_torque(starved, speed=100.0)
    wet = friction_torque(flooded, speed=100.0)
    assert dry.film_parameter < wet.film_parameter
    assert dry.parts["sliding"] > wet.parts["sliding"]  # more asperity (boundary) traction


@pytest.mark.parametrize(
    ("overrides", "text"),
    [
        ({"lubrication.supply": "starved"}, "inlet_ratio is missing"),
        ({"lubrication.supply": "starved", "lubrication.inlet_ratio": 0.5}, "inlet_ratio"),
        ({"lubrication.supply": "oil bath"}, "supply"),
        ({"lubrication.inlet_ratio": 2.0}, "not allowed with supply = 'flooded'"),
        ({"lubrication.inlet_layer": "0.2 um"}, "inlet_layer = 2e-07 m is not allowed with"),
        (
            {"lubrication.supply": "starved", "lubrication.inlet_layer": "-0.1 um"},
            "inlet_layer",
        ),
        (
            {"lubrication.supply": "grease", "lubrication.inlet_layer": "2 mm"},
            "inlet_layer",
        ),
        (
            {
                "lubrication.supply": "starved",
                "lubrication.inlet_ratio": 2.0,
                "lubrication.inlet_layer": "0.2 um",
            },
            "not allowed with inlet_ratio",
        ),
    ],
)
def test_bad_supply_is_a_one_line_error(wear_case_path, overrides, text):
    with pytest.raises(CaseError) as err:
        ballscrew.load_case(wear_case_path, overrides)
    message = str(err.value)
    assert text in message and "\n" not in message.strip()


# a known oil layer on the track: Chevalier et al. (1998), Damiens et al. (2004)


def test_layer_fed_film_is_the_thin_layer_law_of_the_flooded_film():
    flooded = hamrock_dowson(*ARGS)
    rho = dowson_higginson_density(hamrock_brewe(RX, RY, 0.5 * E_PRIME, Q).p0)
    assert 1.1 < rho < 1.3  # p_h ≈ 1 GPa on the reference contact
    layer = rho * flooded.central  # r = 1: h_c/h_c,ff = 2^(−1/3)
    film = supplied_film_model("hamrock_dowson", inlet_layer=layer)(*ARGS)
    assert film.central == pytest.approx(2.0 ** (-1.0 / 3.0) * flooded.central, rel=1e-12)
    assert film.minimum / film.central == pytest.approx(flooded.minimum / flooded.central)


def test_layer_fed_film_limits_and_monotone_in_the_layer():
    flooded = hamrock_dowson(*ARGS)
    rho = dowson_higginson_density(hamrock_brewe(RX, RY, 0.5 * E_PRIME, Q).p0)
    films = [
        supplied_film_model("hamrock_dowson", inlet_layer=h)(*ARGS).central
        for h in (1e-3, 1e-6, 1e-7, 3e-8, 1e-8, 1e-9, 0.0)
    ]
    assert films[0] == pytest.approx(flooded.central, rel=1e-9)  # flooded
    assert all(b < a for a, b in itertools.pairwise(films))
    assert films[-2] == pytest.approx(1e-9 / rho, rel=1e-3)  # h_c → h_oil/ρ̄
    assert films[-1] == 0.0


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"inlet_layer": -1e-9}, "lubrication.inlet_layer"),
        ({"inlet_layer": 1e-7, "inlet_ratio": 2.0}, "lubrication.inlet_layer"),
    ],
)
def test_bad_layer_is_a_one_line_input_error(kwargs, field):
    with pytest.raises(InputError) as err:
        supplied_film_model("hamrock_dowson", **kwargs)
    assert str(err.value).startswith(field) and "\n" not in str(err.value)


def test_case_layer_starves_and_replaces_the_grease_replenishment(wear_case_path):
    starved = _case(
        wear_case_path, {"lubrication.supply": "starved", "lubrication.inlet_layer": "50 nm"}
    )
    assert (
        starved.lubrication.layer == pytest.approx(50e-9) and starved.lubrication.meniscus is None
    )
    grease = _case(
        wear_case_path, {"lubrication.supply": "grease", "lubrication.inlet_layer": "50 nm"}
    )
    assert not grease.lubrication.replenished and grease.lubrication.layer == pytest.approx(50e-9)
    assert track_replenishment(grease, 870.0) is None
    flooded = ball_model(_case(wear_case_path, {})).film(60.0, 0.5).central
    thin = ball_model(starved).film(60.0, 0.5).central
    assert thin < flooded and thin < 50e-9  # cannot exceed the oil of the layer
    assert ball_model(grease).film(60.0, 0.5).central == pytest.approx(thin, rel=1e-12)


def test_operating_point_film_falls_as_the_layer_thins_and_bad_layer_exits_2(
    tmp_path, gao_case_path
):
    runner = CliRunner()

    def film(*sets):
        out = tmp_path / f"op{len(list(tmp_path.iterdir()))}"
        args = ["operating-point", str(gao_case_path), "--out", str(out), "--curve-points", "0"]
        result = runner.invoke(app, [*args, *(a for s in sets for a in ("--set", s))])
        assert result.exit_code == 0, result.output
        return json.loads((out / "summary.json").read_text())["film_thickness"]["value"]

    flooded = film()
    layers = ("1 um", "200 nm", "50 nm")
    films = [film("lubrication.supply=starved", f"lubrication.inlet_layer={h}") for h in layers]
    assert flooded > films[0] > films[1] > films[2] > 0.0
    assert films[2] < 50e-9 / 1.2  # below h_oil/ρ̄
    out = tmp_path / "bad"
    bad = runner.invoke(
        app,
        [
            "operating-point",
            str(gao_case_path),
            "--out",
            str(out),
            "--set",
            "lubrication.supply=starved",
            "--set",
            "lubrication.inlet_layer=-1e-7",
        ],
    )
    assert bad.exit_code == 2
    assert "inlet_layer" in bad.output and "Traceback" not in bad.output
    assert len(bad.output.strip().splitlines()) == 1
    assert not out.exists()
