"""``thermal_field(case)``: the API contract, the TCR feed, the case section and its errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
import xarray as xr

import ballscrew as bs
from ballscrew.case import CaseError, with_overrides
from ballscrew.contact_resistance.constriction import (
    elliptic_constriction_resistance,
    smeared_conductance,
)
from ballscrew.errors import InputError

RPM = 2 * math.pi / 60
FAST = {"thermal.mesh.size": "5 mm", "thermal.transient.time_step": "300 s"}
FREE_NUT = {"thermal.mounting.kind": "free", "thermal.convection.natural": "fixed"}
"""The boundary conditions these tests pinned: nut in still air, natural convection at 10 K."""


@pytest.fixture(scope="module")
def case():
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
    return bs.load_case(path, FAST | FREE_NUT)


@pytest.fixture(scope="module")
def tcr(case):
    return bs.screw_tcr(case, variant=None)


@pytest.fixture(scope="module")
def results(case, tcr):
    return {m: bs.thermal_field(case, model=m, tcr=tcr) for m in ("network", "axisymmetric")}


@pytest.mark.parametrize("model", ["network", "axisymmetric"])
def test_contract_and_energy_balance(results, model):
    """Heat in = drag heat (Q4: 44.31 W at 1000 r/min, F_p = 1500 N) + half of two bearings
    (Q3: 6.84 W each); steady and transient balances to 1e-6."""
    r = results[model]
    assert r.heat_input == pytest.approx(44.31 + 6.8357, abs=0.01)
    assert r.heat_balance_error < 1e-6
    assert r.transient_heat_balance_error < 1e-6
    assert r.max_temperature_rise > 0 and r.elongation > 0
    assert r.max_temperature == pytest.approx(293.15 + r.max_temperature_rise)
    steady = {s.name: s.steady for s in r.sensors}
    assert set(steady) == {"nut 1", "spacer", "nut 2", "screw"}
    # double nut under preload only: the two nuts mirror each other about the spacer
    assert steady["nut 1"] == pytest.approx(steady["nut 2"], abs=2e-3)
    assert all(s.final <= s.steady + 1e-9 for s in r.sensors)  # heating up from ambient


def test_network_and_axisymmetric_agree_on_the_example(results):
    """With the balls' resistance, bearings and Kreith/Churchill–Chu convection."""
    net, fe = results["network"], results["axisymmetric"]
    assert net.max_temperature_rise == pytest.approx(fe.max_temperature_rise, rel=5e-3)
    assert net.elongation == pytest.approx(fe.elongation, rel=3e-3)
    for a, b in zip(net.sensors, fe.sensors, strict=True):
        assert a.steady - 293.15 == pytest.approx(b.steady - 293.15, rel=1e-2), a.name


def test_thermoelastic_check_and_fields(results):
    fe = results["axisymmetric"]
    assert fe.elongation_thermoelastic == pytest.approx(fe.elongation, rel=1e-6)
    ds = fe.to_xarray()
    assert ds["temperature_steady"].attrs["units"] == "K"
    assert ds["elongation"].attrs["units"] == "m"
    assert ds.sizes["sensor"] == 4
    assert float(ds["max_temperature"][-1]) <= fe.max_temperature + 1e-9
    net = results["network"].to_xarray()
    assert isinstance(net, xr.Dataset) and "ring_bore_temperature_steady" in net


def test_tcr_feeds_the_interface(case, tcr, results):
    """Each nut's micro resistance is its R from screw_tcr (A2–A3); R″ is A4's; the smeared
    conductance is 1/(R·A_bore) with A_bore = 2π·20 mm·60 mm."""
    interfaces = results["network"].interfaces
    area = 2 * math.pi * 0.020 * 0.060
    for nut, i in zip(tcr.nuts, interfaces, strict=True):
        assert i.micro_resistance == pytest.approx(nut.resistance, rel=1e-12)
        assert i.resistance_per_area == pytest.approx(nut.resistance * nut.apparent_area)
        assert i.bore_area == pytest.approx(area, rel=1e-12)
        assert i.conductance_per_area == pytest.approx(
            1 / ((i.micro_resistance + i.constriction_resistance) * area), rel=1e-12
        )
        # macro-constriction of ~100 small patches dominates the micro TCR (scale check):
        # 6× the headline CMY's (0.41 K/W per nut), 65× the paper's V2 cell model's
        assert 0.5 < i.constriction_resistance < 10.0
        assert i.constriction_resistance > 5 * i.micro_resistance


def test_without_constriction_the_nut_runs_cooler(case, tcr, results):
    """Micro TCR only (the paper's literal use): a much stiffer path, so the nut's heat goes
    into the screw: hotter screw, cooler nut."""
    micro = bs.thermal_field(
        with_overrides(case, {"thermal.contact.constriction": False}), "network", tcr=tcr
    )
    full = results["network"]
    nut = {s.name: s.steady for s in micro.sensors}, {s.name: s.steady for s in full.sensors}
    assert nut[0]["nut 1"] < nut[1]["nut 1"]
    assert nut[0]["screw"] > nut[1]["screw"]


def test_given_resistance_per_area(case):
    r = bs.thermal_field(
        with_overrides(
            case,
            {"thermal.contact.source": "given", "thermal.contact.resistance_per_area": 5e-4},
        ),
        "network",
        transient=False,
    )
    assert [i.conductance_per_area for i in r.interfaces] == pytest.approx([2000.0, 2000.0])
    assert r.solution.transient is None and math.isnan(r.time_to_95)


def test_convection_is_reported_and_overridable(case, results):
    conv = {c.surface: c for c in results["network"].convection}
    assert conv["screw"].value == pytest.approx(37.46, abs=0.02)  # Kreith, 1000 r/min
    assert "Kreith" in conv["screw"].correlation
    assert "Churchill" in conv["nut"].correlation
    moved = bs.thermal_field(
        with_overrides(
            case,
            {"thermal.convection.screw": 50.0, "thermal.stroke.length": "200 mm"},
        ),
        "network",
        transient=False,
    )
    conv = {c.surface: c for c in moved.convection}
    assert conv["screw"].value == 50.0 and conv["screw"].correlation == "override"
    assert conv["screw ends"].value == 50.0
    assert "flat plate" in conv["nut"].correlation  # 0.167 m/s beats natural convection


def test_screw_at_rest_has_no_friction_heat(case):
    r = bs.thermal_field(with_overrides(case, {"operating.speed": 0.0}), "network", transient=False)
    assert r.heat_input == 0.0 and r.max_temperature_rise == pytest.approx(0.0, abs=1e-12)
    assert "Churchill" in {c.surface: c for c in r.convection}["screw"].correlation


def test_constriction_limits():
    """Holm's circle 1/(4λa); a slender ellipse → ln(4a/b)/(2πλa) (K(m) → ln(4/√(1−m)))."""
    assert elliptic_constriction_resistance(1e-4, 1e-4, 40.0) == pytest.approx(1 / (4 * 40 * 1e-4))
    a, b = 1e-3, 1e-6
    slender = math.log(4 * a / b) / (2 * math.pi * 40.0 * a)
    assert elliptic_constriction_resistance(b, a, 40.0) == pytest.approx(slender, rel=1e-6)
    assert smeared_conductance(2.0, 0.01) == pytest.approx(50.0)


def test_model_choice_errors(case):
    with pytest.raises(InputError, match=r"thermal.model = 'fem'.*axisymmetric, network, 3d"):
        bs.thermal_field(case, model="fem")


def test_drag_torque_sources(case, tcr):
    """'given' and 'kinematics' torques replace the catalogue one; heat = M·ω (Q4)."""
    given = bs.thermal_field(
        with_overrides(
            case, {"thermal.drag_torque.source": "given", "thermal.drag_torque.torque": 0.2}
        ),
        "network",
        tcr=tcr,
        transient=False,
    )
    balls = [s for s in given.sources if "balls" in s.name]
    assert sum(s.torque for s in balls) == pytest.approx(0.2)
    assert sum(s.heat for s in balls) == pytest.approx(0.2 * 1000 * RPM)
    from ballscrew.analyses import kinematics

    computed = bs.thermal_field(
        with_overrides(case, {"thermal.drag_torque.source": "kinematics"}),
        "network",
        tcr=tcr,
        transient=False,
    )
    balls = [s for s in computed.sources if "balls" in s.name]
    assert sum(s.torque for s in balls) == pytest.approx(kinematics.computed_drag_torque(case))


def test_case_without_thermal_section(case):
    bare = bs.case.case_from_dict(case.model_dump(exclude={"thermal"}))
    with pytest.raises(InputError, match=r"\[thermal\]"):
        bs.thermal_field(bare)
    minimal = bs.case.case_from_dict(case.model_dump(exclude={"thermal"}) | {"thermal": {}})
    r = bs.thermal_field(
        with_overrides(
            minimal,
            {"thermal.contact.source": "given", "thermal.contact.resistance_per_area": 1e-4},
        ),
        "network",
        transient=False,
    )  # every key has a default: nut Ø = 1.75 d_m, length 2.5 d_m, mid-screw
    assert r.problem.parts[0].outer_radius == pytest.approx(0.035)
    assert r.problem.parts[0].length == pytest.approx(0.100)
    assert r.problem.ring_centre == pytest.approx(0.5)


@pytest.mark.parametrize(
    ("key", "value", "message"),
    [
        ("thermal.ambient_temperature", 20, "thermal.ambient_temperature = 20 is not allowed"),
        ("thermal.transient.time_step", "2 h", "time_step"),
        ("thermal.drag_torque.source", "given", "torque"),
        ("thermal.stroke.mode", "fast", "thermal.stroke.mode"),
        ("thermal.mesh.sise", 0.001, "did you mean 'size'"),
    ],
)
def test_bad_thermal_keys_name_the_field(case, key, value, message):
    with pytest.raises(CaseError, match=message):
        with_overrides(case, {key: value})


def test_unit_strings(case):
    c = with_overrides(
        case,
        {
            "thermal.ambient_temperature": "25 degC",
            "thermal.transient.duration": "2 h",
            "thermal.contact.source": "given",
            "thermal.contact.resistance_per_area": "5 mm^2*K/W",
        },
    )
    assert c.thermal.ambient_temperature == pytest.approx(298.15)
    assert c.thermal.transient.duration == pytest.approx(7200.0)
    assert c.thermal.contact.resistance_per_area == pytest.approx(5e-6)


def test_sensor_outside_its_body(case):
    sensors = [{"name": "x", "body": "nut", "r": 0.01, "z": 0.5}]
    bad = bs.case.case_from_dict(
        case.model_dump() | {"thermal": case.thermal.model_dump() | {"sensors": sensors}}
    )
    with pytest.raises(InputError, match=r"sensors\.x"):
        bs.thermal_field(bad, "network")


def test_nut_that_does_not_fit(case):
    with pytest.raises(InputError, match="nut_position"):
        bs.thermal_field(with_overrides(case, {"thermal.nut_position": "0.02 m"}), "network")
    assert np.isfinite(case.thermal.shaft_length)
