"""Boundary conditions (Q8–Q10): the table path, iterated natural convection, coolant."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import ballscrew as bs
from ballscrew.case import with_overrides
from ballscrew.cli import app
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.thermal import (
    Convection,
    RingPart,
    Solid,
    ThermalProblem,
    build_network,
    simulate,
)
from ballscrew.thermal.boundary import (
    dittus_boelter,
    fixed_point,
    gnielinski,
    mounting_coefficient,
    pipe_coefficient,
)
from ballscrew.thermal.convection import Air, rotating_cylinder

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
FAST = {
    "thermal.mesh.size": "5 mm",
    "thermal.transient.time_step": "300 s",
    "thermal.drag_torque.source": "catalogue",  # the fixed heat these numbers were taken with
}
FREE_NUT = {"thermal.mounting.kind": "free", "thermal.convection.natural": "fixed"}


@pytest.fixture(scope="module")
def case():
    return bs.load_case(EXAMPLE, FAST)


def field(case, overrides=None, transient=False):
    return bs.thermal_field(with_overrides(case, overrides or {}), "network", transient=transient)


def nut_rise(result) -> float:
    return {s.name: s.steady for s in result.sensors}["nut 1"] - result.ambient_temperature


def test_mounting_coefficient_is_the_series_joint_and_table():
    """1/G = 1/(h_c A_c) + 1/G_t smeared over A_od; a table at ambient leaves the joint only."""
    assert mounting_coefficient(2000.0, 0.01, 0.02) == pytest.approx(1000.0)
    g = 1.0 / (1.0 / 20.0 + 1.0 / 10.0)
    assert mounting_coefficient(2000.0, 0.01, 0.02, 10.0) == pytest.approx(g / 0.02)
    assert mounting_coefficient(2000.0, 0.01, 0.02, 0.0) == 0.0
    with pytest.raises(InputError, match="contact_conductance"):
        mounting_coefficient(-1.0, 0.01, 0.02)


def lumped_problem(h_nut: float) -> ThermalProblem:
    """Nearly isothermal bodies (λ = 10⁶), all heat into the nut, the nut OD the only path."""
    metal = Solid(1e6, 7800.0, 460.0)
    nut = RingPart("nut", 0.06, 0.035, True, 1e8, 0.0, 30.0)
    return ThermalProblem(
        0.02, 0.3, metal, metal, (nut,), 0.15, Convection(0.0, 0.0, h_nut, 0.0), expansion=1e-5
    )


def test_table_path_is_a_lumped_series_resistance():
    """Lumped nut and shaft: θ = Q (1/(h_c A_c) + 1/G_t); the transient is implicit Euler's
    θ_n = θ_∞ [1 − (1 + Δt/τ)^−n] with τ = C/G."""
    area = 2 * math.pi * 0.035 * 0.06
    h_c, a_c, g_t = 2000.0, 0.5 * area, 10.0
    problem = lumped_problem(mounting_coefficient(h_c, a_c, area, g_t))
    dt, steps = 300.0, 12
    solution = simulate(build_network(problem, 0.01), dt * steps, dt)
    expected = 30.0 * (1.0 / (h_c * a_c) + 1.0 / g_t)
    assert solution.steady == pytest.approx(expected, rel=1e-5)
    capacity = float(solution.discretisation.capacity.sum())
    tau = capacity / (30.0 / expected)
    rise = expected * (1.0 - (1.0 + dt / tau) ** -np.arange(steps + 1))
    assert solution.transient.max_rise == pytest.approx(rise, rel=1e-4)


def test_gnielinski_and_dittus_boelter_by_hand():
    """Pr = 1: Nu = (f/8)(Re − 1000) exactly; Re = 10⁴, Pr = 0.7: f = 0.03148, Nu = 29.82
    (hand-evaluated); at Re = 10⁵ the two correlations agree to ~10 % (Nu 178.6 vs 199.4)."""
    f = (0.790 * math.log(5e4) - 1.64) ** -2
    assert gnielinski(5e4, 1.0) == pytest.approx(f / 8 * 49e3, rel=1e-12)
    assert gnielinski(1e4, 0.7) == pytest.approx(29.82, abs=0.01)
    assert gnielinski(1e5, 0.7) == pytest.approx(178.6, abs=0.1)
    assert dittus_boelter(1e5, 0.7) == pytest.approx(199.4, abs=0.1)
    assert dittus_boelter(1e5, 7.0, heating=False) < dittus_boelter(1e5, 7.0)  # Pr^0.3 < Pr^0.4
    # water-like coolant in a 10 mm bore at 1 m/s: Re = 10⁴, laminar at rest
    assert pipe_coefficient(0.01, 1.0, 1e-6, 0.6, 7.0) == pytest.approx(
        gnielinski(1e4, 7.0) * 0.6 / 0.01
    )
    assert pipe_coefficient(0.01, 0.0, 1e-6, 0.6, 7.0) == pytest.approx(3.66 * 0.6 / 0.01)


def test_kreith_warns_outside_its_range():
    """(Q5) measured for Re_ω < 4.3·10⁵: a 200 mm shaft at 6000 r/min (Re = 1.6·10⁶) warns."""
    with pytest.warns(UserWarning, match="Kreith"):
        rotating_cylinder(0.2, 6000 * math.pi / 30, Air())


def test_fixed_point_converges_or_reports_its_residual():
    x, n = fixed_point(lambda x: (math.sqrt(2.0 * x[0]),), (1.0,), 1e-12)
    assert x[0] == pytest.approx(2.0, rel=1e-11) and n > 1
    with pytest.raises(ConvergenceError, match="residual") as error:
        fixed_point(lambda x: (x[0] + 1.0,), (1.0,), 1e-6, 5)
    assert error.value.residual > 1e-6 and error.value.iterations == 5


def test_old_behaviour_stays_available(case):
    """A free nut with ΔT = 10 K and the micro TCR of that time (the paper's V2 cell model, the
    headline before ``tcr.headline``) reproduces the numbers before mounting and iteration
    existed; the default headline CMY puts more resistance across the balls (64.02 K)."""
    r = field(case, FREE_NUT | {"tcr.headline": "V2"})
    assert nut_rise(r) == pytest.approx(62.116, abs=0.01)
    assert nut_rise(field(case, FREE_NUT)) == pytest.approx(64.024, abs=0.01)
    assert {c.surface for c in r.convection} == {"screw", "screw ends", "nut", "nut ends"}


def test_table_mounting_by_default_cools_the_nut(case):
    """The default seats the nut in a table: a 62 K nut in still air drops to about 4 K."""
    r = field(case)
    conv = {c.surface: c for c in r.convection}
    area = math.pi * (2 * 0.070 * 0.060 + 0.070 * 0.010)
    g = 1.0 / (1.0 / (2000.0 * 0.5 * area) + 1.0 / 10.0)
    assert conv["nut mounting"].value == pytest.approx(g / area, rel=1e-12)
    assert r.problem.convection.nut == pytest.approx(conv["nut"].value + g / area)
    assert 2.0 < nut_rise(r) < 8.0
    at_ambient = field(case, {"thermal.mounting.table_area": None})
    assert nut_rise(at_ambient) < nut_rise(r)


@pytest.mark.parametrize("start", ["0.5 K", "300 K"])
def test_natural_convection_iteration_is_independent_of_the_start(case, start):
    """Natural convection at the computed mean surface rise of the nut (free nut: about 54 K)."""
    free = {"thermal.mounting.kind": "free"}
    reference = field(case, free)
    r = field(case, free | {"thermal.convection.temperature_difference": start})
    assert nut_rise(r) == pytest.approx(nut_rise(reference), rel=1e-5)
    label = {c.surface: c for c in r.convection}["nut"].correlation
    rise = float(label.split("ΔT = ")[1].split(" K")[0])
    assert rise == pytest.approx(nut_rise(r), rel=1e-2)  # the ΔT it was evaluated at


def test_energy_balance_with_every_new_path(case):
    """Table, iterated natural convection and a cooled nut: heat in = heat out to 1e-10."""
    cooled = {"thermal.coolant.nut_coefficient": 500.0, "thermal.coolant.nut_channel_area": 0.01}
    r = field(case, cooled, transient=True)
    assert r.heat_balance_error < 1e-10
    assert r.transient_heat_balance_error < 1e-10
    assert "nut coolant" in {c.surface for c in r.convection}
    assert nut_rise(r) < nut_rise(field(case))


def test_iteration_that_cannot_converge_reports_its_residual(case):
    with pytest.raises(ConvergenceError, match="natural-convection iteration"):
        field(case, {"thermal.mounting.kind": "free", "thermal.convection.max_iterations": 1})


def with_key(text: str, key: str, value: str) -> str:
    """The case text with ``key = value`` set in its section (added where absent)."""
    section, name = key.rsplit(".", 1)
    header = f"[{section}]\n"
    if header not in text:
        return text + f"\n{header}{name} = {value}\n"
    head, body = text.split(header, 1)
    block, sep, rest = body.partition("\n[")
    lines = [line for line in block.splitlines() if not line.startswith(f"{name} =")]
    return head + header + "\n".join([f"{name} = {value}", *lines]) + "\n" + sep + rest


@pytest.mark.parametrize(
    ("key", "value"),
    [
        ("thermal.mounting.contact_conductance", "-1.0"),
        ("thermal.mounting.contact_fraction", "1.5"),
        ("thermal.mounting.kind", '"glued"'),
        ("thermal.coolant.nut_channel_area", "-0.01"),
    ],
)
def test_bad_boundary_input_is_one_line_and_exit_2(tmp_path, key, value):
    path = tmp_path / "case.toml"
    path.write_text(with_key(EXAMPLE.read_text(), key, value))
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["thermal", str(path), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert key in result.output and "Traceback" not in result.output
    assert len(result.output.strip().splitlines()) == 1
    assert not out.exists()
