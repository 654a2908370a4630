"""1-D axial network against the reference problem, the fin solution and a closed-form interface.

The reference problems are defined here and reused by ``test_axisymmetric.py``:
- the reference problem of ``benchmarks/bench_thermal.py``: shaft Ø40×1000 mm, nut ring
  Ø40/Ø70×100 mm at z = 450–550 mm, k = 45, ρ = 7850, c_p = 460, h = 20 W/(m² K),
  R″ = 5e-4 m² K/W, 30 W at the interface split 50/50, α = 11.5e-6 /K;
- a thin fin heated over a band, whose exact solution is a piecewise cosh/sinh (below);
- a nut covering the whole (end-insulated) shaft, all heat crossing the interface: the jump
  is exactly q·R″ and the nut profile logarithmic.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.thermal.network import build_network
from ballscrew.thermal.problem import (
    BandHeat,
    Convection,
    RingPart,
    Sensor,
    Solid,
    ThermalProblem,
    axial_grid,
)
from ballscrew.thermal.simulate import simulate, time_to_fraction

STEEL = Solid(45.0, 7850.0, 460.0)
R_PP = 5e-4  # m² K/W


def engine_problem(stroke: float = 0.0) -> ThermalProblem:
    """The reference problem (the interface conductance is R″ over the 2π·20·100 mm² bore)."""
    g = 2 * math.pi * 0.02 * 0.1 / R_PP
    nut = RingPart("nut", 0.1, 0.035, True, g, 15.0, 15.0)
    return ThermalProblem(
        0.02,
        1.0,
        STEEL,
        STEEL,
        (nut,),
        0.5,
        Convection(20, 20, 20, 20),
        stroke=stroke,
        expansion=11.5e-6,
    )


# Reference values: 1-D network (5 mm cells) and 2-D axisymmetric P2 (1 mm) values
NETWORK_T_MAX, NETWORK_ELONGATION = 45.221, 104.62e-6
NETWORK_HISTORY = {15: 31.70, 30: 37.29, 60: 42.29, 90: 44.09}
FE_T_MAX, FE_ELONGATION = 45.169, 104.68e-6
FE_HISTORY = {15: 31.66, 60: 42.25, 90: 44.04}


def fin_problem() -> ThermalProblem:
    """Ø10 × 500 mm steel shaft, 5 W over the band 100–140 mm; an unheated, uncoupled 20 mm
    ring insulates the last 20 mm of surface. Bi = hR/k = 0.002: the 1-D fin is exact to ~0.1 %."""
    ring = RingPart("sleeve", 0.02, 0.01, True, 0.0)
    return ThermalProblem(
        0.005,
        0.5,
        STEEL,
        STEEL,
        (ring,),
        0.49,
        Convection(20.0, 20.0, 20.0, 20.0),
        bearings=(BandHeat("band", 0.12, 0.04, 5.0),),
        expansion=11.5e-6,
    )


def fin_solution(problem: ThermalProblem, z: np.ndarray) -> np.ndarray:
    """Exact 1-D fin: λA θ″ − hP θ·[uncovered] + q′ = 0, h_e A θ at both end faces.

    Segments: free | heated band | free | covered (adiabatic surface). Piecewise
    θ = a cosh m(z−c) + b sinh m(z−c) + q′/(hP), or a + b(z−c) where covered; the 8 constants
    from the end conditions and C¹ continuity.
    """
    k, r, length = problem.shaft.conductivity, problem.shaft_radius, problem.shaft_length
    h, he = problem.convection.screw, problem.convection.screw_ends
    area, perimeter = math.pi * r**2, 2 * math.pi * r
    band = problem.bearings[0]
    z1, z2 = band.position - band.width / 2, band.position + band.width / 2
    z3 = length - problem.parts[0].length
    edges = [0.0, z1, z2, z3, length]
    m = math.sqrt(h * perimeter / (k * area))
    heat = [0.0, band.power / band.width, 0.0, 0.0]
    covered = [False, False, False, True]

    def basis(i: int, x: float) -> tuple[np.ndarray, float, np.ndarray]:
        """(value coefficients, particular value, slope coefficients) at x in segment i."""
        s = x - edges[i]
        if covered[i]:
            return np.array([1.0, s]), 0.0, np.array([0.0, 1.0])
        c, sh = math.cosh(m * s), math.sinh(m * s)
        return np.array([c, sh]), heat[i] / (h * perimeter), m * np.array([sh, c])

    a = np.zeros((8, 8))
    rhs = np.zeros(8)
    v, p, d = basis(0, 0.0)  # λA θ′(0) = h_e A θ(0)
    a[0, 0:2] = k * d - he * v
    rhs[0] = he * p
    for j in range(3):  # continuity of θ and θ′ at edges[j + 1]
        v0, p0, d0 = basis(j, edges[j + 1])
        v1, p1, d1 = basis(j + 1, edges[j + 1])
        a[1 + 2 * j, 2 * j : 2 * j + 2] = v0
        a[1 + 2 * j, 2 * j + 2 : 2 * j + 4] = -v1
        rhs[1 + 2 * j] = p1 - p0
        a[2 + 2 * j, 2 * j : 2 * j + 2] = d0
        a[2 + 2 * j, 2 * j + 2 : 2 * j + 4] = -d1
    v, p, d = basis(3, length)  # −λA θ′(L) = h_e A θ(L)
    a[7, 6:8] = k * d + he * v
    rhs[7] = -he * p
    coef = np.linalg.solve(a, rhs)
    out = np.empty_like(z)
    for n, x in enumerate(z):
        i = min(int(np.searchsorted(edges, x, side="right")) - 1, 3)
        v, p, _ = basis(i, x)
        out[n] = v @ coef[2 * i : 2 * i + 2] + p
    return out


def sleeve_problem(h_out: float = 25.0, heat: float = 20.0) -> ThermalProblem:
    """A nut covering the whole Ø40 × 200 mm shaft; shaft and nut ends insulated; all the heat
    enters the screw side of the interface, so it all crosses R″ and leaves through the nut OD."""
    length, r, ro = 0.2, 0.02, 0.035
    g = 2 * math.pi * r * length / R_PP
    nut = RingPart("nut", length, ro, True, g, heat, 0.0)
    sensors = (
        Sensor("nut mid-wall", "nut", 0.0275, 0.1),
        Sensor("nut OD", "nut", ro, 0.05),
        Sensor("screw axis", "screw", 0.0, 0.1),
        Sensor("nut bore", "nut", r, 0.07),
        Sensor("screw surface", "screw", r, 0.07),
    )
    return ThermalProblem(
        r, length, STEEL, STEEL, (nut,), 0.1, Convection(20.0, 0.0, h_out, 0.0), sensors=sensors
    )


def sleeve_solution(problem: ThermalProblem, radius: float) -> float:
    """Nut temperature rise at ``radius``: θ = Q/(2πL)[1/(h r_o) + ln(r_o/r)/λ]."""
    nut = problem.parts[0]
    q = nut.screw_heat
    length, ro = problem.shaft_length, nut.outer_radius
    k, h = problem.ring.conductivity, problem.convection.nut
    return q / (2 * math.pi * length) * (1 / (h * ro) + math.log(ro / radius) / k)


def test_reference_problem_network_steady():
    """Peak 45.221 °C and 104.62 µm with 5 mm cells (reference values)."""
    sol = simulate(build_network(engine_problem(), 0.005), None)
    assert 20.0 + sol.max_temperature_rise == pytest.approx(NETWORK_T_MAX, abs=0.01)
    assert sol.elongation == pytest.approx(NETWORK_ELONGATION, rel=1e-3)
    assert sol.heat_input == pytest.approx(30.0, rel=1e-14)
    assert sol.heat_balance_error < 1e-9


def test_reference_problem_network_transient():
    """T_max at 15/30/60/90 min, 95.5 % of the steady rise after 90 min; energy conserved."""
    sol = simulate(build_network(engine_problem(), 0.005), 5400.0, 60.0)
    t = sol.transient
    for minute, value in NETWORK_HISTORY.items():
        assert 20.0 + t.max_rise[minute] == pytest.approx(value, abs=0.015), minute
    assert t.max_rise[-1] / sol.max_temperature_rise == pytest.approx(0.955, abs=1e-3)
    assert t.heat_in == pytest.approx(30.0 * 5400.0, rel=1e-12)
    assert t.heat_balance_error < 1e-6
    assert time_to_fraction(t.time, t.max_rise, sol.max_temperature_rise) < 5400.0


def test_fin_solution():
    """Cross-section mean temperature of a band-heated thin shaft equals the 1-D fin solution."""
    problem = fin_problem()
    disc = build_network(problem, 0.002)
    sol = simulate(disc, None)
    exact = fin_solution(problem, disc.axis_z)
    assert np.max(np.abs(sol.axis - exact)) < 2e-3 * exact.max()
    assert sol.heat_balance_error < 1e-9


def test_interface_jump_equals_q_times_r():
    """Closed-form two-body problem: θ_screw − θ_bore = q·R″ with q = Q/(2πRL); nut profile
    logarithmic (the network's radial model is exact for this through-flow)."""
    problem = sleeve_problem()
    disc = build_network(problem, 0.01)
    sol = simulate(disc, None)
    q = problem.parts[0].screw_heat / (2 * math.pi * problem.shaft_radius * problem.shaft_length)
    jump = sol.steady[disc.extra["shaft_surface"]] - sol.steady[disc.extra["ring_bore"]]
    np.testing.assert_allclose(jump, q * R_PP, rtol=1e-9)
    bore = sol.steady[disc.extra["ring_bore"]]
    np.testing.assert_allclose(bore, sleeve_solution(problem, problem.shaft_radius), rtol=1e-9)
    expected = [sleeve_solution(problem, s.r) for s in problem.sensors[:2]]
    np.testing.assert_allclose(sol.sensors[:2], expected, rtol=1e-9)


def test_stroke_spreads_the_screw_heat_and_conserves_energy():
    """A 200 mm stroke: the nut covers the shaft a trapezoidal fraction of the time; the heat
    in is unchanged, steady and transient balances hold, and the peak falls."""
    still = simulate(build_network(engine_problem(), 0.005), None)
    moving = simulate(build_network(engine_problem(0.2), 0.005), 600.0, 20.0)
    assert moving.heat_input == pytest.approx(30.0, rel=1e-12)
    assert moving.heat_balance_error < 1e-9
    assert moving.transient.heat_balance_error < 1e-6
    assert moving.max_temperature_rise < still.max_temperature_rise
    grid = axial_grid(engine_problem(0.2), 0.005)
    cover = grid.coverage(np.array([0.3525, 0.375, 0.4225, 0.5025, 0.6475]))
    # nut centre uniform over 0.4–0.6 m, nut 100 mm long: z is covered while the centre is
    # within ±50 mm, i.e. |(z − 0.05, z + 0.05) ∩ (0.4, 0.6)| / 0.2 of the time
    np.testing.assert_allclose(cover, [0.0, 0.125, 0.3625, 0.5, 0.0], atol=0.026)


def test_resolved_stroke_matches_the_time_average():
    """Moving heat source resolved step by step (Δt = 0.25 s, nut period 4 s) against the
    time-averaged model after 10 min: the heat stored agrees to 0.1 %; the shaft's share of it
    (the elongation) is 1.1 % lower when resolved (1.3 % at Δt → 0): the averaged operator
    misses the correlation between where the nut is and how hot the screw is there."""
    problem = engine_problem(0.2)
    disc = build_network(problem, 0.005)
    averaged = simulate(disc, 600.0, 0.25)
    resolved = simulate(disc, 600.0, 0.25, stroke_mode="resolved", feed_speed=0.1)
    assert np.ptp(resolved.transient.offset) == 2 * disc.grid.half_stroke_cells
    assert resolved.transient.heat_balance_error < 1e-6
    assert resolved.transient.stored == pytest.approx(averaged.transient.stored, rel=2e-3)
    assert resolved.transient.elongation[-1] == pytest.approx(
        averaged.transient.elongation[-1], rel=0.02
    )
