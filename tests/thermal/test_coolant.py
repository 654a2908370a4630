"""Hollow-shaft coolant (Q11), coolant inlet temperature (Q10) and the table's heat capacity."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew as bs
from ballscrew.analyses.thermal_cooling import bore_coefficient, bore_flow, shaft_coolant
from ballscrew.analyses.thermal_setup import thermal_spec
from ballscrew.case import with_overrides
from ballscrew.cli import app
from ballscrew.errors import InputError
from ballscrew.thermal import build_network, simulate
from ballscrew.thermal.coolant import (
    FLUIDS,
    LAMINAR_LIMIT,
    NU_LAMINAR,
    TURBULENT_LIMIT,
    BoreFlow,
    ShaftCoolant,
    bore_nusselt,
    bore_outlet_rise,
)
from ballscrew.thermal.problem import Sensor, TableMass
from ballscrew.thermal.simulate import time_to_fraction

from .test_boundary_conditions import EXAMPLE, field, nut_rise

FAST = {
    "thermal.mesh.size": "5 mm",
    "thermal.transient.time_step": "300 s",
    "thermal.drag_torque.source": "catalogue",
    "thermal.convection.natural": "fixed",
}
BORE = {
    "thermal.shaft_coolant.bore_diameter": "12 mm",
    "thermal.shaft_coolant.flow_rate": "2 L/min",
}


@pytest.fixture(scope="module")
def case():
    return bs.load_case(EXAMPLE, FAST)


def test_bore_nusselt_laminar_and_turbulent_by_hand():
    """Laminar 4.36 (flux) / 3.66 (wall temperature); water Re = 10⁴, Pr = 5.83: Dittus–Boelter
    Nu = 0.023·10⁴^0.8·5.83^0.4 = 73.8 (hand-evaluated); Gnielinski within 15 % of it."""
    assert bore_nusselt(1000.0, 5.83) == 4.36
    assert bore_nusselt(1000.0, 5.83, wall="temperature") == 3.66
    assert bore_nusselt(1e4, 5.83, "dittus_boelter") == pytest.approx(73.8, abs=0.1)
    assert bore_nusselt(1e4, 5.83) == pytest.approx(73.8, rel=0.15)
    water = FLUIDS["water"]
    assert water.prandtl == pytest.approx(5.83, abs=0.01)  # Incropera Table A.6, 300 K
    # 12 mm bore, 2 L/min of water: u = 0.295 m/s, Re = 4122, turbulent
    flow = BoreFlow(0.012, 2e-3 / 60.0, water)
    assert flow.velocity == pytest.approx(0.2947, abs=1e-4)
    assert flow.reynolds == pytest.approx(4123, abs=2)
    assert flow.capacity_rate == pytest.approx(997 * 2e-3 / 60 * 4179, rel=1e-12)
    # Gnielinski at Re = 4123, Pr = 5.83: f = 0.0405, Nu = 30.77, h = Nu·0.613/0.012 ≈ 1572
    assert flow.coefficient() == pytest.approx(1572, rel=2e-3)


def test_cooled_shaft_energy_balance_and_colder_screw(case):
    """Heat removed by the bore flow = ṁc_p(θ_out − θ_in); the cooled screw runs colder and its
    elongation falls."""
    solid = field(case)
    cooled = field(case, BORE)
    problem = cooled.problem
    disc = build_network(problem, 0.005)
    sol = simulate(disc, None)
    cool = problem.shaft_coolant
    nodes = disc.extra["coolant"]
    outlet = sol.steady[nodes[-1]]
    removed = cool.capacity_rate * (outlet - cool.inlet_rise)
    # heat across the bore wall, by hand: annulus (bore → mean) in series with the film h
    mean = sol.steady[disc.extra["shaft_mean"]]
    r_i, r_o, lam = cool.bore_radius, problem.shaft_radius, problem.shaft.conductivity
    to_mean = r_o**2 * math.log(r_o / r_i) / (r_o**2 - r_i**2) - 0.5
    g = 1.0 / (to_mean / (2 * math.pi * lam) + 1.0 / (cool.coefficient * 2 * math.pi * r_i))
    dz = np.diff(disc.grid.z)
    across_wall = float(np.sum(g * dz * (mean - sol.steady[nodes])))
    assert removed == pytest.approx(across_wall, rel=1e-9)
    assert sol.heat_balance_error < 1e-10
    assert 0.0 < removed < problem.heat_input
    assert cooled.elongation < 0.5 * solid.elongation
    assert cooled.max_temperature_rise < solid.max_temperature_rise
    bore = {c.surface: c for c in cooled.convection}["shaft bore coolant"]
    assert (
        bore.value == pytest.approx(cool.coefficient) and "Gnielinski, Re = 412" in bore.correlation
    )
    with pytest.raises(InputError, match=r"sensors\.axis"):
        replace(problem, sensors=(Sensor("axis", "screw", 0.0, 0.5),))


def test_bore_outlet_matches_the_closed_form():
    """A shaft held at a uniform rise: the network's outlet = θ_w − (θ_w − θ_in) e^(−NTU)."""
    from ballscrew.thermal.coolant import ShaftCoolant
    from ballscrew.thermal.problem import Convection, RingPart, Solid, ThermalProblem

    steel = Solid(1e6, 7850.0, 460.0)  # near-infinite λ: an isothermal shaft
    cool = ShaftCoolant(0.005, 2000.0, 5.0, 0.0)
    problem = ThermalProblem(
        0.02,
        1.0,
        steel,
        steel,
        (RingPart("nut", 0.1, 0.04, True, 0.0, 50.0, 0.0),),
        0.5,
        Convection(0.0, 0.0, 0.0, 0.0),
        shaft_coolant=cool,
    )
    sol = simulate(build_network(problem, 0.002), None)
    disc = sol.discretisation
    wall = float(np.mean(sol.steady[disc.extra["shaft_mean"]]))
    outlet = sol.steady[disc.extra["coolant"][-1]]
    assert cool.capacity_rate * outlet == pytest.approx(50.0, rel=1e-7)  # all heat to the flow
    area = 2 * math.pi * 0.005 * 1.0
    assert outlet == pytest.approx(bore_outlet_rise(wall, 0.0, 2000.0, area, 5.0), rel=2e-3)


def test_coolant_inlet_temperature_cools_below_ambient(case):
    """Inlet 5 K below ambient: nut and shaft run colder than with coolant at ambient."""
    nut = {"thermal.coolant.nut_coefficient": 500.0, "thermal.coolant.nut_channel_area": 0.01}
    at_ambient = field(case, nut)
    chilled = field(case, nut | {"thermal.coolant.inlet_temperature": "15 degC"})
    assert nut_rise(chilled) < nut_rise(at_ambient)
    assert chilled.heat_balance_error < 1e-10
    axi = bs.thermal_field(
        with_overrides(case, nut | {"thermal.coolant.inlet_temperature": "15 degC"}),
        "axisymmetric",
        transient=False,
    )
    assert nut_rise(axi) == pytest.approx(nut_rise(chilled), abs=0.3)
    bore = field(case, BORE)
    chilled_bore = field(case, BORE | {"thermal.shaft_coolant.inlet_temperature": "15 degC"})
    assert chilled_bore.elongation < bore.elongation


def table_case(case, capacity):
    extra = {"thermal.mounting.table_heat_capacity": capacity} if capacity else {}
    return field(case, extra, transient=True)


def test_table_capacity_slows_the_transient_and_keeps_the_energy_balance(case):
    """The table as a lumped mass: the nut's time constant grows with C_t, energy is conserved,
    and the steady state is that of the quasi-steady table (to 2 %)."""
    quasi = table_case(case, None)
    light, heavy = table_case(case, "2e4 J/K"), table_case(case, "2e5 J/K")
    for r in (light, heavy):
        assert r.transient_heat_balance_error < 1e-10
        assert nut_rise(r) == pytest.approx(nut_rise(quasi), rel=0.02)
    k = [s.name for s in heavy.sensors].index("nut 1")

    def time_to_half(r):  # time to half the nut's steady rise; inf: beyond the record
        t = r.solution.transient
        time = time_to_fraction(t.time, t.sensors[:, k], nut_rise(r), 0.5)
        return math.inf if math.isnan(time) else time

    # about 300 s, 1200 s and beyond the 5400 s record (C_t/G_t = 2000 s and 20000 s)
    assert time_to_half(quasi) < time_to_half(light) < time_to_half(heavy)
    assert time_to_half(light) < 0.5 * heavy.solution.transient.time[-1]
    assert heavy.solution.transient.sensors[-1, k] < light.solution.transient.sensors[-1, k]
    assert any("mounting" in c.surface for c in quasi.convection)
    assert not any("mounting" in c.surface for c in heavy.convection)


def test_table_mass_alone_stores_heat():
    table = TableMass(100.0, 10.0, 1e5)
    assert table.capacity == 1e5
    with pytest.raises(InputError, match="table_heat_capacity"):
        TableMass(100.0, 10.0, 0.0)


def test_bad_coolant_input_is_one_line_and_exit_2(tmp_path):
    text = (
        EXAMPLE.read_text()
        + '\n[thermal.shaft_coolant]\nbore_diameter = "12 mm"\nfluid = "brine"\n'
    )
    path = tmp_path / "case.toml"
    path.write_text(text)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["thermal", str(path), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert "thermal.shaft_coolant.fluid" in result.output and "Traceback" not in result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists()


def test_coolant_errors_name_the_case_field_its_value_and_range():
    """The bore was named a diameter but given its radius, ṁc_p [W/K] was named a flow rate."""
    with pytest.raises(InputError) as error:
        ShaftCoolant(-0.004, 800.0, 30.0)
    assert str(error.value).startswith("thermal.shaft_coolant.bore_diameter = -0.008 ")
    assert str(error.value).endswith("> 0 m")
    with pytest.raises(InputError) as error:
        ShaftCoolant(0.004, 800.0, 0.0)
    message = str(error.value)
    assert message.startswith("shaft_coolant.capacity_rate = 0.0 is not allowed: ")
    assert "> 0 W/K" in message and "thermal.shaft_coolant.flow_rate" in message
    water = FLUIDS["water"]
    with pytest.raises(InputError) as error:
        BoreFlow(0.012, -1e-5, water)
    assert str(error.value) == (
        "thermal.shaft_coolant.flow_rate = -1e-05 is not allowed: a finite number > 0 m³/s"
    )
    with pytest.raises(InputError, match=r"^thermal.shaft_coolant.bore_diameter = 0.0 "):
        BoreFlow(0.0, 1e-5, water)


@pytest.mark.parametrize(
    ("flow_rate", "regime"),
    [(0.05 / 60e3, "laminar Nu = 4.36"), (1.3 / 60e3, "blend"), (20 / 60e3, "Gnielinski")],
)
def test_the_bore_coefficient_names_the_regime_it_computed(flow_rate, regime):
    """The label follows bore_nusselt's regimes (Re ≤ LAMINAR_LIMIT laminar, a blend below
    TURBULENT_LIMIT); it called the blend "Gnielinski"."""
    overrides = {
        "thermal.shaft_coolant.bore_diameter": "12 mm",
        "thermal.shaft_coolant.flow_rate": flow_rate,
    }
    spec = thermal_spec(bs.load_case(EXAMPLE, overrides))
    h, label = bore_coefficient(spec)
    flow = bore_flow(spec)
    assert regime in label and f"Re = {flow.reynolds:.4g}" in label
    laminar = NU_LAMINAR["flux"] * flow.fluid.conductivity / flow.diameter
    assert (h == pytest.approx(laminar)) == (flow.reynolds <= LAMINAR_LIMIT)
    assert (regime == "blend") == (LAMINAR_LIMIT < flow.reynolds < TURBULENT_LIMIT)
    assert shaft_coolant(spec).coefficient == h
