"""Elastic ball-load distribution: balance, the rigid limit, decay, lift-off, errors, stiffness."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import InputError
from ballscrew.loads import ball_load, nut_forces
from ballscrew.loads.distribution import (
    LIFT_OFF_SEARCH,
    SPARSE_BALLS,
    NutBodies,
    ball_layout,
    body_properties,
    lift_off_load,
    loaded_contact_angle,
    solve_distribution,
)

D_M, LEAD, BALL, BETA = 0.04, 0.01, 0.00635, math.pi / 4
ALPHA = math.atan(LEAD / (math.pi * D_M))
K = 2.448e-7  # K_A + K_B of the 40 × 10 reference screw (f = 0.52, steel), m N^-2/3
STEEL = (2.06e11, 0.3)
BODIES = body_properties(D_M, BALL, BETA, 0.0335, 0.07, STEEL, STEEL)
S = math.sin(BETA) * math.cos(ALPHA)


def layout(nuts: int = 2, balls: int = 90):
    return ball_layout(balls, nuts, LEAD, D_M, BALL, ALPHA, LEAD)


def solve(fa: float, fp: float = 1500.0, nuts: int = 2, bodies=BODIES, **kw):
    return solve_distribution(layout(nuts), K, BETA, ALPHA, fa, fp, bodies, **kw)


def test_layout_of_a_five_turn_double_nut() -> None:
    lay = layout()
    assert lay.z.size == 180 and lay.turns == 5
    assert lay.z[:90].min() - lay.z[90:].max() == pytest.approx(LEAD)  # the spacer gap
    assert np.all(np.diff(lay.z[:90]) < 0)  # each nut from its loaded end


@pytest.mark.parametrize("fa", [0.0, 1000.0, 4000.0, 9000.0])
def test_force_balance_to_1e_10(fa: float) -> None:
    rng = np.random.default_rng(1)
    d = solve(fa, lead_error=rng.normal(0, 1e-6, 10), ball_excess=rng.normal(0, 5e-7, 180))
    signed = d.axial_share * np.sum(d.layout.flank * d.loads)
    assert signed == pytest.approx(fa, abs=1e-10 * max(fa, 1500.0))
    assert np.all(d.loads >= 0.0)


def test_preload_is_carried_by_each_nut_without_load() -> None:
    d = solve(0.0)
    assert d.nut_forces == pytest.approx([1500.0, 1500.0], rel=1e-12)


@pytest.mark.parametrize("fa", [0.0, 2000.0, 6000.0])
def test_rigid_bodies_give_the_uniform_distribution(fa: float) -> None:
    d = solve(fa, bodies=NutBodies())
    f1, f2 = nut_forces(1500.0, fa)
    uniform = [ball_load(f, 90, BETA, ALPHA) for f in (f1, f2)]
    assert d.per_nut(d.loads) == pytest.approx(np.repeat(uniform, 90).reshape(2, 90), rel=1e-9)


def test_very_stiff_bodies_approach_the_uniform_limit() -> None:
    stiff = NutBodies(1e20, 1e20, 0.0)
    d = solve(2000.0, bodies=stiff)
    assert np.ptp(d.per_nut(d.loads), axis=1) == pytest.approx([0, 0], abs=1e-6)


def test_single_nut_load_decays_monotonically_from_the_loaded_end() -> None:
    d = solve(3000.0, fp=0.0, nuts=1)
    q = d.loads
    assert np.all(np.diff(q) < 0) and q[0] / q[-1] > 1.05


@pytest.mark.parametrize("fa", [0.0, 500.0])
def test_a_preloaded_single_nut_carries_preload_plus_load(fa: float) -> None:
    """One nut's flank carries F_p + F_a; rigid bodies give 1.5 F / (C F^(2/3))."""
    d = solve(fa, fp=1500.0, nuts=1, bodies=NutBodies())
    force = 1500.0 + fa
    assert d.nut_forces == pytest.approx([force], rel=1e-10)
    compliance = K / (S * (90 * S) ** (2.0 / 3.0))
    assert d.stiffness == pytest.approx(1.5 * force ** (1.0 / 3.0) / compliance, rel=1e-8)


def test_flange_at_the_free_end_spreads_the_load_more_evenly() -> None:
    other = NutBodies(BODIES.screw_rigidity, BODIES.nut_rigidity, BODIES.ring_compliance, False)
    tc = solve(3000.0, fp=0.0, nuts=1).loads
    tt = solve(3000.0, fp=0.0, nuts=1, bodies=other).loads
    assert tt.max() / tt.mean() < tc.max() / tc.mean()


def test_lift_off_of_the_second_nut() -> None:
    contacts = lift_off_load(layout(), K, BETA, ALPHA, 1500.0, NutBodies())
    assert contacts == pytest.approx(2.0**1.5 * 1500.0, rel=1e-5)
    with_bodies = lift_off_load(layout(), K, BETA, ALPHA, 1500.0, BODIES, rtol=1e-5)
    beyond = solve(1.05 * with_bodies)
    assert np.all(beyond.per_nut(beyond.loads)[1] == 0.0)  # zero, never negative
    assert beyond.nut_forces[0] == pytest.approx(1.05 * with_bodies, rel=1e-12)
    before = solve(0.95 * with_bodies)
    assert before.nut_forces[1] > 0.0


def test_no_lift_off_where_soft_bars_keep_the_load_from_nut_2() -> None:
    """Bars of E A = 5 MN (the shaft of a 40 mm screw is 190 MN) take an external load up
    within nut 1's first turns: nut 2 still carries at LIFT_OFF_SEARCH F_p, so no lift-off
    (inf), where the search stops instead of doubling on."""
    soft = NutBodies(screw_rigidity=5e6, nut_rigidity=5e6)
    assert lift_off_load(layout(), K, BETA, ALPHA, 1500.0, soft, rtol=1e-4) == math.inf
    top = solve(LIFT_OFF_SEARCH * 1500.0, bodies=soft)
    assert top.nut_forces[1] > 0.0


def test_an_undersized_ball_lifts_off_alone() -> None:
    excess = np.zeros(180)
    excess[40] = -20e-6  # 20 µm smaller than its neighbours
    d = solve(0.0, ball_excess=excess)
    assert d.loads[40] == 0.0 and np.all(np.delete(d.loads, 40) > 0.0)


def test_a_lead_error_loads_its_turn() -> None:
    turn = np.zeros(10)
    turn[2] = 2e-6  # nut 1, third turn: the screw groove 2 µm towards the loaded flank
    d, ref = solve(2000.0, lead_error=turn), solve(2000.0)
    q, q0 = d.per_nut(d.loads)[0], ref.per_nut(ref.loads)[0]
    in_turn = d.layout.turn[:90] == 2
    assert np.all(q[in_turn] > q0[in_turn]) and np.all(q[~in_turn] < q0[~in_turn])


@pytest.mark.parametrize("fa", [0.0, 2500.0, 8000.0])
def test_stiffness_is_the_derivative_of_the_load_deflection_curve(fa: float) -> None:
    g = solve(0.0).interference
    h = 1.0
    lo = solve(max(fa - h, 0.0), interference=g).displacement
    hi = solve(fa + h, interference=g).displacement
    assert solve(fa, interference=g).compliance == pytest.approx(
        (hi - lo) / (fa + h - max(fa - h, 0.0)), rel=1e-4
    )


def test_bodies_soften_the_nut() -> None:
    rigid, elastic = solve(0.0, bodies=NutBodies()), solve(0.0)
    no_ring = NutBodies(BODIES.screw_rigidity, BODIES.nut_rigidity, 0.0)
    assert elastic.stiffness < solve(0.0, bodies=no_ring).stiffness < rigid.stiffness
    assert rigid.stiffness == pytest.approx(
        2 * 1.5 * 1500.0 / (K * (1500.0 / (90 * S)) ** (2 / 3) / S), rel=1e-9
    )


def test_contact_angle_grows_with_the_approach() -> None:
    gap = 0.04 * BALL
    angles = loaded_contact_angle([-1e-6, 0.0, 5e-6], BETA, gap)
    assert angles[0] == angles[1] == pytest.approx(BETA)
    assert math.cos(angles[2]) == pytest.approx(gap * math.cos(BETA) / (gap + 5e-6))


def test_bad_inputs_are_named() -> None:
    with pytest.raises(InputError, match="lead_error"):
        solve(0.0, lead_error=np.zeros(7))
    with pytest.raises(InputError, match="nut_outer_diameter"):
        body_properties(D_M, BALL, BETA, 0.0335, 0.045, STEEL, STEEL)
    with pytest.raises(InputError, match="preload"):
        solve(100.0, fp=0.0)


def test_preload_after_wear_with_bodies_in_series() -> None:
    from ballscrew.loads import preload_after_wear

    c_a, c_b = 3.749e-8, 2e-10
    depths = np.array([0.0, 1e-6, 2.43e-6, 1e-4])
    rigid = preload_after_wear(1500.0, c_a, depths, BETA, ALPHA)
    bodies = preload_after_wear(1500.0, c_a, depths, BETA, ALPHA, c_b)
    left = c_a * bodies ** (2 / 3) + c_b * bodies  # the interference each preload needs
    lost = c_a * 1500.0 ** (2 / 3) + c_b * 1500.0 - depths / S
    assert left[:3] == pytest.approx(lost[:3], rel=1e-12) and bodies[3] == rigid[3] == 0.0
    assert np.all(bodies[1:3] > rigid[1:3])  # a softer loop loses its preload more slowly
    assert preload_after_wear(1500.0, c_a, depths, BETA, ALPHA, 0.0) == pytest.approx(rigid)


def test_a_long_double_nut_converges() -> None:
    """20 turns per nut (400 balls): Newton's start left nut 2 without a loaded ball, so the
    preload interference failed with a singular Jacobian from 15 turns per nut on."""
    long_nut = ball_layout(400, 2, LEAD, D_M, BALL, ALPHA, LEAD)
    rest = solve_distribution(long_nut, K, BETA, ALPHA, 0.0, 3030.0, BODIES)
    assert rest.nut_forces == pytest.approx([3030.0, 3030.0], rel=1e-10)
    loaded = solve_distribution(
        long_nut, K, BETA, ALPHA, 2000.0, 3030.0, BODIES, interference=rest.interference
    )
    assert loaded.nut_forces[0] - loaded.nut_forces[1] == pytest.approx(2000.0, rel=1e-10)


@pytest.mark.parametrize(("turns", "support"), [(30, "guided"), (40, "free")])
def test_a_30_and_40_turn_double_nut_converges(turns: int, support: str) -> None:
    """591 and 788 balls per nut (the `ballscrew init` 40 × 10 starter at 10 × 3 and 10 × 4
    turns): the bodies' strain of equal loads is ±5 Hertz approaches, of opposite sign on the
    two nuts, and the preload start from the median over both nuts left nut 1 with no loaded
    ball (singular Jacobian, from 30 turns on). Each nut's preload and the balance hold to
    1e-10. As in a bolt and nut (Sopwith 1948) the bars concentrate the load at the ends it
    enters by: the preload at the nuts' ends next to the spacer, the external load at nut 1's
    loaded end; its far end and nut 2 hardly see the external load, so nut 2 barely unloads."""
    balls = {30: 591, 40: 788}[turns]
    long_nut = ball_layout(balls, 2, LEAD, D_M, BALL, ALPHA, LEAD)
    fp = 10800.0
    rest = solve_distribution(long_nut, K, BETA, ALPHA, 0.0, fp, BODIES, support=support)
    assert rest.nut_forces == pytest.approx([fp, fp], rel=1e-10)
    loaded = solve_distribution(
        long_nut,
        K,
        BETA,
        ALPHA,
        20000.0,
        fp,
        BODIES,
        interference=rest.interference,
        support=support,
    )
    assert loaded.nut_forces[0] - loaded.nut_forces[1] == pytest.approx(20000.0, rel=1e-10)
    if support == "free":
        assert np.abs(loaded.resultant[1:]).max() < 1e-10 * 20000.0 * D_M
    preloaded = rest.per_nut(rest.loads)[0]  # the preload flows in at the spacer end
    assert preloaded[-1] > 10.0 * preloaded[0]
    added = loaded.per_nut(loaded.loads - rest.loads)[0]  # the load at the loaded end
    assert added[0] > 20.0 * added[-1] and loaded.nut_forces[1] > 0.9 * fp


def test_a_long_nut_started_from_a_neighbouring_load_finds_the_same_root() -> None:
    """Above SPARSE_BALLS balls (the sparse bar system) a solve started from the solution at a
    neighbouring load (the stiffness curve, the lift-off search) converges in fewer Newton
    iterations to the root of the cold start: loads, displacement and compliance to 1e-12."""
    long_nut = ball_layout(300, 2, LEAD, D_M, BALL, ALPHA, LEAD)
    assert long_nut.z.size >= SPARSE_BALLS
    g = solve_distribution(long_nut, K, BETA, ALPHA, 0.0, 3030.0, BODIES).interference
    near = solve_distribution(long_nut, K, BETA, ALPHA, 5000.0, 3030.0, BODIES, interference=g)
    cold = solve_distribution(long_nut, K, BETA, ALPHA, 6000.0, 3030.0, BODIES, interference=g)
    warm = solve_distribution(
        long_nut, K, BETA, ALPHA, 6000.0, 3030.0, BODIES, interference=g, start=near
    )
    assert warm.iterations < cold.iterations
    assert warm.loads == pytest.approx(cold.loads, rel=1e-12, abs=1e-12 * cold.loads.max())
    assert warm.displacement == pytest.approx(cold.displacement, rel=1e-12)
    assert warm.compliance == pytest.approx(cold.compliance, rel=1e-12)
    assert warm.nut_forces[0] - warm.nut_forces[1] == pytest.approx(6000.0, rel=1e-12)
