"""The ball heat paths of the screw: one constriction for the thermal model and the TCR result,
computed once per result, one film quadrature per distinct contact, and the film edge of a
lifted-off ball (theory manual: *Contact resistance*, *Film path around the ball*)."""

from __future__ import annotations

import dataclasses
import math
import warnings
from functools import cache
from types import ModuleType
from typing import Any

import pytest
from scipy.special import ellipk

from ballscrew.analyses import screw_tcr as screw_tcr_module
from ballscrew.analyses import tcr_film
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.screw_tcr import ScrewTCR, screw_tcr
from ballscrew.analyses.thermal_setup import build_problem
from ballscrew.case import load_case, with_overrides

from .test_film_path import COARSE, EXAMPLE, _tcr

GIVEN_TORQUE = {"thermal.drag_torque.source": "given", "thermal.drag_torque.torque": 0.2}
STARVED = {"lubrication.supply": "starved", "lubrication.inlet_ratio": 2.0}


def _interfaces(result: ScrewTCR) -> tuple:
    return build_problem(with_overrides(result.case, GIVEN_TORQUE), result)[3]


def test_thermal_interfaces_take_the_constriction_of_the_heat_paths() -> None:
    """The interfaces keep their numbers (values of the code before the two computations were
    made one, 1e-12) and the constriction is the closed form (A6): per patch
    K(e²)/(2π a)·(1/λ_ball + 1/λ_raceway) (Yovanovich 1971), summed over the screw and nut
    patch of a ball, over 54 balls; λ = 40 W/(m K) for every body of the example."""
    chain = _tcr(0.0, "none")
    interfaces = _interfaces(chain)
    assert [i.micro_resistance for i in interfaces] == pytest.approx([0.03825179077420288] * 2)
    cons = [i.constriction_resistance for i in interfaces]
    assert cons == pytest.approx([2.5129744276823214] * 2, rel=1e-12)
    nut = chain.nuts[0]
    closed = 0.0
    for raceway in (nut.screw, nut.nut):
        a, b = sorted((raceway.contact.hertz.a, raceway.contact.hertz.b), reverse=True)
        closed += 2.0 * ellipk(1.0 - (b / a) ** 2) / (2.0 * math.pi * 40.0 * a)
    assert cons[0] == pytest.approx(closed / 54, rel=1e-12)
    assert all(i.path_resistance is None for i in interfaces)

    lifted = _interfaces(_tcr(5000.0, "meniscus"))
    assert lifted[0].constriction_resistance == pytest.approx(1.6822678846044279, rel=1e-12)
    assert [i.resistance for i in lifted] == pytest.approx(
        [0.5314579854014874, 0.9041646725068996], rel=1e-12
    )
    assert lifted[1].constriction_resistance == 0.0


def _count_calls(monkeypatch: pytest.MonkeyPatch, module: ModuleType, name: str) -> list[int]:
    """Replace ``module.name`` by a wrapper that appends to the returned list at every call."""
    calls: list[int] = []
    original = getattr(module, name)

    def counted(*args: Any, **kwargs: Any) -> Any:
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, counted)
    return calls


def test_heat_paths_are_computed_once_per_result(monkeypatch: pytest.MonkeyPatch) -> None:
    """summary(), the report and heat_path_resistance share one evaluation of the paths (the
    summary and the report each evaluated them twice); the numbers are the earlier ones."""
    calls = _count_calls(monkeypatch, screw_tcr_module, "heat_paths")
    result = dataclasses.replace(_tcr(5000.0, "meniscus"))  # a fresh result, nothing cached
    film = result.summary()["film_path"]
    result.report()
    both = 1.0 / (1.0 / 0.5314579854014874 + 1.0 / 0.9041646725068996)
    assert result.heat_path_resistance == pytest.approx(both, rel=1e-12)
    assert film["resistance"]["value"] == pytest.approx(both, rel=1e-12)
    assert len(calls) == 1


def test_equal_contacts_share_one_film_quadrature(monkeypatch: pytest.MonkeyPatch) -> None:
    """At zero axial load both nuts carry equal balls: two quadratures (screw, nut), not four;
    the films keep the values of the code that ran four."""
    result = _tcr(0.0, "meniscus")
    calls = _count_calls(monkeypatch, tcr_film, "loaded_film_conductance")
    params = ScrewParameters.from_case(result.case)
    films = tcr_film.nut_films(result.case, params, result.nuts, [1, 2])
    assert len(calls) == 2
    for film in films:
        assert film.screw.conductance == pytest.approx(0.0769718129516161, rel=1e-12)
        assert film.nut.conductance == pytest.approx(0.08574848475690444, rel=1e-12)


@cache
def _starved() -> ScrewTCR:
    """Starved supply at 1 kN: both nuts loaded, unequally (different meniscus gaps)."""
    case = load_case(
        EXAMPLE,
        {**COARSE, **STARVED, "operating.axial_load": 1000.0, "tcr.film_path": "meniscus"},
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return screw_tcr(case)


def test_a_lifted_off_ball_takes_the_thickest_meniscus_gap_of_its_side() -> None:
    """With two loaded nuts of unequal load (starved: h_max 1.355 and 0.971 µm on the screw)
    a lifted-off ball (nut 3) is wetted up to the larger, whichever order the nuts come in (it
    took the last loaded nut's: 0.971 µm for nuts (1, 2), 1.355 µm for (2, 1)); with no loaded
    nut, up to the groove-bottom clearance (r_g − r_b)(1 − cos β) = 0.127 mm (1 − cos 45°)."""
    result = _starved()
    params = ScrewParameters.from_case(result.case)
    assert [n.index for n in result.nuts] == [1, 2]
    expected = {"screw": 1.3549766469427256e-06, "nut": 1.3727619215364612e-06}
    for order in (result.nuts, result.nuts[::-1]):
        lifted = tcr_film.nut_films(result.case, params, order, [1, 2, 3])[2]
        assert not lifted.loaded
        for side, h_max in expected.items():
            assert getattr(lifted, side).h_max == pytest.approx(h_max, rel=1e-9)
    alone = tcr_film.nut_films(result.case, params, (), [1])[0]
    clearance = 0.127e-3 * (1.0 - math.sqrt(0.5))
    assert alone.screw.h_max == pytest.approx(clearance, rel=1e-12)
    assert alone.nut.h_max == pytest.approx(clearance, rel=1e-12)
