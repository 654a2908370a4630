"""One mesh and assembly per coupled solve: the FE models re-bind their matrices to new loads."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses import thermal_setup
from ballscrew.analyses.operating_point import heat_overrides
from ballscrew.analyses.thermal import solve_field, thermal_field
from ballscrew.case import with_overrides
from ballscrew.thermal import axisymmetric, threed
from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.coolant import ShaftCoolant
from ballscrew.thermal.network import build_network
from ballscrew.thermal.problem import (
    BandHeat,
    Convection,
    RingPart,
    Solid,
    TableMass,
    ThermalProblem,
    same_mesh,
)
from ballscrew.thermal.simulate import simulate
from ballscrew.thermal.threed import build_threed

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gao2019_tcr.toml"
#: ISO VG 68 following the temperature and a friction model that sees it: several iterations.
OIL = {
    "numerics.cells_across": 16,
    "thermal.mesh.size": "10 mm",
    "thermal.transient.time_step": "600 s",
    "medium.viscosity": None,
    "medium.pressure_viscosity": None,
    "kinematics.lubricant": "iso_vg_68",
    "friction.model": "ball_model",
    "thermal.mounting.kind": "free",
    "thermal.contact.source": "given",  # R″ given: no TCR chain to solve
    "thermal.contact.resistance_per_area": "5e-4 m^2*K/W",
}
STEEL = Solid(45.0, 7850.0, 460.0)


def small(heat: float = 30.0, h: float = 20.0, **kwargs) -> ThermalProblem:
    """A Ø40 × 400 mm shaft with one nut, a bearing band and the given extras."""
    nut = RingPart("nut", 0.06, 0.035, True, 400.0, 0.4 * heat, 0.6 * heat)
    return ThermalProblem(
        0.02,
        0.4,
        STEEL,
        STEEL,
        (nut,),
        0.2,
        Convection(h, 0.5 * h, 1.5 * h, h),
        bearings=(BandHeat("bearing", 0.02, 0.02, 0.2 * heat),),
        expansion=11.5e-6,
        **kwargs,
    )


def _counted(monkeypatch, module, name: str) -> list[int]:
    calls: list[int] = []
    original = getattr(module, name)

    def counted(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, counted)
    return calls


def _close(a, b, rel: float = 1e-10) -> None:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert np.max(np.abs(a - b)) <= rel * np.max(np.abs(b))


def test_a_coupled_solve_meshes_and_assembles_once(monkeypatch):
    """Fixed-point iterations and the transient of ``thermal_field`` on the axisymmetric model
    share one build, and the result equals that of a fresh build at the final heat."""
    case = ballscrew.load_case(EXAMPLE, OIL)
    builds = _counted(monkeypatch, axisymmetric, "build_axisymmetric")
    field = thermal_field(case, "axisymmetric", duty=False)  # the duty's segments mesh anew
    assert field.coupling.iterations >= 2  # the heat followed the viscosity
    assert len(builds) == 1
    c = field.coupling
    resolved = with_overrides(
        case, {**heat_overrides(c.heat, c.heat_to_screw, case.operating.speed)}
    )
    resolved = with_overrides(resolved, {"operating.coupled": False})
    fresh = solve_field(resolved, "axisymmetric")
    assert len(builds) == 2
    _close(field.solution.steady, fresh.solution.steady)
    t, tf = field.solution.transient, fresh.solution.transient
    _close(t.max_rise, tf.max_rise)
    _close(t.elongation, tf.elongation)
    assert field.elongation == pytest.approx(fresh.elongation, rel=1e-10)


@pytest.mark.parametrize("build", [build_axisymmetric, build_threed])
def test_rebinding_loads_and_coefficients_equals_a_fresh_build(build):
    """Other heats, convection coefficients, contact conductance, table and coolant values on
    the same mesh: the re-bound model solves as a model built for them (to rounding)."""
    extras = {"table": TableMass(50.0, 5.0, 2e4), "nut_coolant_flux": 0.0}
    if build is build_axisymmetric:
        extras["shaft_coolant"] = ShaftCoolant(0.006, 800.0, 30.0, 0.0)
    args = (0.01, 1) if build is build_axisymmetric else (0.02, 12, 1, 0.1)
    first = build(small(**extras), *args)
    cool = extras.get("shaft_coolant")
    other = small(
        heat=55.0,
        h=7.0,
        table=TableMass(80.0, 12.0, 5e4),
        nut_coolant_flux=-40.0,
        **({"shaft_coolant": replace(cool, coefficient=1500.0, inlet_rise=-2.0)} if cool else {}),
    )
    other = replace(other, parts=(replace(other.parts[0], contact_conductance=250.0),))
    assert same_mesh(first.problem, other)
    rebound = first.rebound(other)
    assert rebound is not None and rebound.extra["operator"] is first.extra["operator"]
    fresh = build(other, *args)
    a, b = simulate(rebound, 3600.0, 600.0), simulate(fresh, 3600.0, 600.0)
    _close(a.steady, b.steady, 1e-12)
    _close(a.transient.elongation, b.transient.elongation, 1e-12)
    assert a.heat_balance_error < 1e-9 and a.transient.heat_balance_error < 1e-9


def test_another_geometry_is_not_rebound():
    disc = build_axisymmetric(small(), 0.01, 1)
    assert disc.rebound(replace(small(), stroke=0.02)) is None
    assert disc.rebound(small(table=TableMass(50.0, 5.0, 2e4))) is None
    assert not same_mesh(small(), replace(small(), expansion=12e-6))


def test_the_3d_coupled_solve_builds_once(monkeypatch):
    case = ballscrew.load_case(
        EXAMPLE,
        {
            **OIL,
            "friction.model": "catalogue",
            "thermal.mesh.size_3d": "8 mm",
            "thermal.mesh.far_size_3d": "80 mm",
            "thermal.mesh.divisions_3d": 12,
            "thermal.mesh.layers_3d": 1,
        },
    )
    builds = _counted(monkeypatch, threed, "build_threed")
    field = thermal_field(case, "3d", duty=False)
    assert len(builds) == 1 and field.solution.transient is not None


def test_the_network_rebinds_loads_and_coefficients_as_a_fresh_build():
    """The network, too, binds other heats, coefficients, coolant and table values to the
    conduction it built once (it had no rebind: every fixed-point iteration rebuilt it)."""
    extras = {
        "table": TableMass(50.0, 5.0, 2e4),
        "shaft_coolant": ShaftCoolant(0.006, 800.0, 30.0, 0.0),
    }
    first = build_network(replace(small(**extras), stroke=0.05), 0.005)
    other = small(
        heat=55.0,
        h=7.0,
        table=TableMass(80.0, 12.0, 5e4),
        nut_coolant_flux=-40.0,
        shaft_coolant=ShaftCoolant(0.006, 1500.0, 12.0, -2.0),
    )
    other = replace(other, stroke=0.05, parts=(replace(other.parts[0], contact_conductance=250.0),))
    rebound = first.rebound(other)
    assert rebound is not None
    fresh = build_network(other, 0.005)
    for mode in ("averaged", "resolved"):
        a = simulate(rebound, 3600.0, 600.0, stroke_mode=mode, feed_speed=0.01)
        b = simulate(fresh, 3600.0, 600.0, stroke_mode=mode, feed_speed=0.01)
        _close(a.steady, b.steady, 1e-12)
        _close(a.transient.elongation, b.transient.elongation, 1e-12)
        assert a.heat_balance_error < 1e-9 and a.transient.heat_balance_error < 1e-9
    assert first.rebound(replace(other, stroke=0.0)) is None


def test_the_natural_convection_fixed_point_builds_its_network_once(monkeypatch):
    """The surface rises iterate on one network whose coefficients are re-bound (four builds
    of the example's network per problem before)."""
    case = ballscrew.load_case(EXAMPLE, {"thermal.drag_torque.source": "catalogue"})
    builds = _counted(monkeypatch, thermal_setup, "build_network")
    _, _, convection, _, _ = thermal_setup.build_problem(case, None)
    assert "iterated" in next(c.correlation for c in convection if c.surface == "nut")
    assert len(builds) == 1
