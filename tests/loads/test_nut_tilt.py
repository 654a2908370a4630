"""The free nut: five-DOF balance (axial, radial, tilt) of the elastic ball-load distribution."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse as sp

from ballscrew.errors import InputError
from ballscrew.loads import ball_load, nut_forces
from ballscrew.loads.distribution import NutBodies, ball_layout, lift_off_load, solve_distribution

from .test_distribution import ALPHA, BALL, BETA, BODIES, D_M, LEAD, K

LAYOUT = ball_layout(90, 2, LEAD, D_M, BALL, ALPHA, LEAD)


def solve(fa: float, layout=LAYOUT, bodies=BODIES, fp: float = 1500.0, **kw):
    return solve_distribution(layout, K, BETA, ALPHA, fa, fp, bodies, **kw)


def two_start(layout):
    """Every ball doubled at θ + π at the same z (a two-start nut): the layout is symmetric."""
    n = layout.balls
    order = np.concatenate([np.tile(np.arange(k * n, (k + 1) * n), 2) for k in range(layout.nuts)])
    shift = np.tile(np.repeat([0.0, math.pi], n), layout.nuts)
    return replace(
        layout,
        z=layout.z[order],
        flank=layout.flank[order],
        nut=layout.nut[order],
        turn=layout.turn[order],
        angle=layout.angle[order] + shift,
    )


def load_vectors(d):
    """Force Q n and moment p × Q n of every ball on the nut, from the geometry (3D vectors)."""
    lay, r = d.layout, D_M / 2
    th, sig = lay.angle, lay.flank
    e_r = np.stack([np.cos(th), np.sin(th), np.zeros_like(th)], axis=1)
    e_t = np.stack([-np.sin(th), np.cos(th), np.zeros_like(th)], axis=1)
    e_z = np.array([0.0, 0.0, 1.0])
    normal = math.cos(BETA) * e_r + (sig * math.sin(BETA))[:, None] * (
        math.cos(ALPHA) * e_z - math.sin(ALPHA) * e_t
    )
    centre = 0.5 * (lay.z.min() + lay.z.max())
    p = r * e_r + (lay.z - centre)[:, None] * e_z
    force = d.loads[:, None] * normal
    return normal, force, np.cross(p, force)


def test_guided_numbers_do_not_move() -> None:
    """The axisymmetric model as it was (numbers of the version before the free nut)."""
    d = solve(2000.0)
    assert d.loads[[0, 89, 90, 179]] == pytest.approx(
        [45.7601817401759, 42.63936486848125, 12.338335286705844, 11.148925562655233],
        rel=1e-12,
    )
    assert d.stiffness == pytest.approx(1166113484.2927778, rel=1e-12)
    assert d.displacement == pytest.approx(1.4335709197647958e-06, rel=1e-12)
    assert d.interference == pytest.approx(3.1747962854349155e-06, rel=1e-12)
    assert np.all(d.tilt == 0.0) and np.all(d.radial_displacement == 0.0)


@pytest.mark.parametrize(
    ("fa", "radial", "moment"), [(0.0, 0.0, 0.0), (2000.0, 0.0, 0.0), (6000.0, 300.0, -8.0)]
)
def test_all_five_balances_to_1e_10(fa: float, radial: float, moment: float) -> None:
    rng = np.random.default_rng(3)
    d = solve(
        fa,
        lead_error=rng.normal(0, 1e-6, 10),
        ball_excess=rng.normal(0, 5e-7, 180),
        support="free",
        radial_load=radial,
        tilting_moment=moment,
    )
    normal, force, torque = load_vectors(d)
    assert np.linalg.norm(normal, axis=1) == pytest.approx(1.0, rel=1e-14)
    external_force = np.array([radial, 0.0, -fa])  # F_a presses nut 1 towards −z
    external_moment = np.array([0.0, moment])
    scale_f = max(np.abs(force).max(), fa, abs(radial))
    scale_m = max(np.abs(torque[:, :2]).max(), abs(moment))
    assert np.abs(force.sum(axis=0) + external_force).max() < 1e-10 * scale_f
    assert np.abs(torque[:, :2].sum(axis=0) + external_moment).max() < 1e-10 * scale_m
    assert d.resultant[1:] == pytest.approx(
        np.concatenate([force.sum(axis=0)[:2], torque.sum(axis=0)[:2]]), abs=1e-9
    )
    assert np.all(d.loads >= 0.0) and np.hypot(*d.tilt) > 0.0


@pytest.mark.parametrize(("radial", "moment"), [(0.0, 1e4), (3e5, 0.0)])
def test_large_loads_on_a_free_nut_converge_and_balance(radial: float, moment: float) -> None:
    """10 kN·m or 300 kN on a 1.5 kN preload: ball loads ~10³ reference loads, whose rounding
    (~1e-13 of them) an absolute Newton stop of 1e-13 could not reach."""
    d = solve(0.0, support="free", radial_load=radial, tilting_moment=moment)
    _, force, torque = load_vectors(d)
    scale_f = max(np.abs(force).max(), radial)
    scale_m = max(np.abs(torque[:, :2]).max(), moment)
    assert d.loads.max() > 1e4  # far beyond the preload's scale
    assert np.abs(force.sum(axis=0) + np.array([radial, 0.0, 0.0])).max() < 1e-10 * scale_f
    assert np.abs(torque[:, :2].sum(axis=0) + np.array([0.0, moment])).max() < 1e-10 * scale_m


def test_the_guided_nut_leaves_a_radial_force_and_moment_to_its_housing() -> None:
    d = solve(2000.0)
    _, force, torque = load_vectors(d)
    radial, moment = np.hypot(*force.sum(axis=0)[:2]), np.hypot(*torque.sum(axis=0)[:2])
    assert radial > 50.0 and moment > 1.0  # the helix: 148 N and 2.1 N·m about the centre
    assert d.resultant[1:] == pytest.approx(
        np.concatenate([force.sum(axis=0)[:2], torque.sum(axis=0)[:2]]), rel=1e-12
    )


@pytest.mark.parametrize("fa", [0.0, 3000.0])
def test_a_symmetric_nut_does_not_tilt(fa: float) -> None:
    """Balls at θ and θ + π at every z: no radial force or moment, free = guided."""
    lay = two_start(LAYOUT)
    guided = solve(fa, lay, fp=3000.0)
    free = solve(fa, lay, fp=3000.0, support="free")
    assert free.loads == pytest.approx(guided.loads, rel=1e-10)
    assert free.stiffness == pytest.approx(guided.stiffness, rel=1e-10)
    assert np.abs(free.radial_displacement).max() < 1e-12 * abs(free.displacement)
    assert np.abs(free.tilt).max() * D_M < 1e-12 * abs(free.displacement)
    _, force, torque = load_vectors(guided)
    assert np.abs(force.sum(axis=0)[:2]).max() < 1e-10 * force.max()
    assert np.abs(torque.sum(axis=0)[:2]).max() < 1e-10 * np.abs(torque).max()


@pytest.mark.parametrize("fa", [0.0, 2000.0, 6000.0])
def test_rigid_symmetric_free_nut_gives_the_uniform_distribution(fa: float) -> None:
    d = solve(fa, two_start(LAYOUT), NutBodies(), fp=3000.0, support="free")
    uniform = [ball_load(f, 180, BETA, ALPHA) for f in nut_forces(3000.0, fa)]
    assert d.per_nut(d.loads) == pytest.approx(np.repeat(uniform, 180).reshape(2, 180), rel=1e-9)


def test_a_radial_load_moves_a_symmetric_nut_along_it() -> None:
    d = solve(0.0, two_start(LAYOUT), NutBodies(), fp=3000.0, support="free", radial_load=500.0)
    assert d.radial_displacement[0] > 1e2 * abs(d.radial_displacement[1])


def test_maxwell_betti_reciprocity_of_the_free_nut() -> None:
    """Hertz balls on rigid bodies store energy: ∂x/∂F_r = ∂u₁/∂F_a and ∂γ₂/∂F_r = ∂u₁/∂M
    (central differences), which holds only if the approach projections are the transposed
    balance rows."""
    g = solve(0.0, bodies=NutBodies(), support="free").interference

    def at(fa=2000.0, fr=0.0, m=0.0):
        return solve(
            fa,
            bodies=NutBodies(),
            support="free",
            interference=g,
            radial_load=fr,
            tilting_moment=m,
        )

    hf, hm = 1.0, 0.02
    dx_dfr = (at(fr=hf).displacement - at(fr=-hf).displacement) / (2 * hf)
    du_dfa = at(fa=2000.0 + hf).radial_displacement[0] - at(fa=2000 - hf).radial_displacement[0]
    assert dx_dfr == pytest.approx(du_dfa / (2 * hf), rel=1e-4)
    dg_dfr = (at(fr=hf).tilt[1] - at(fr=-hf).tilt[1]) / (2 * hf)
    du_dm = (at(m=hm).radial_displacement[0] - at(m=-hm).radial_displacement[0]) / (2 * hm)
    assert dg_dfr == pytest.approx(du_dm, rel=1e-4)


@pytest.mark.parametrize("fa", [0.0, 2500.0, 8000.0])
def test_free_stiffness_is_the_derivative_of_the_load_deflection_curve(fa: float) -> None:
    g = solve(0.0, support="free").interference
    h = 1.0

    def displacement(f: float) -> float:
        return solve(f, support="free", interference=g).displacement

    lo, hi = displacement(max(fa - h, 0.0)), displacement(fa + h)
    assert solve(fa, support="free", interference=g).compliance == pytest.approx(
        (hi - lo) / (fa + h - max(fa - h, 0.0)), rel=1e-4
    )


def _finite_difference_jacobian(a, b, c, g, f, y):
    """Central differences of q − φ(A q + B ξ + c), G q − f (Hertz φ) at y."""
    n = a.shape[0]

    def residual(v):
        d = a @ v[:n] + b @ v[n:] + c
        return np.concatenate([v[:n] - np.maximum(d, 0.0) ** 1.5, g @ v[:n] - f])

    eps = 1e-6
    fd = np.column_stack(
        [(residual(y + eps * e) - residual(y - eps * e)) / (2 * eps) for e in np.eye(y.size)]
    )
    return fd, np.abs(residual(y)).max()


def test_the_newton_jacobian_matches_finite_differences() -> None:
    """J of q − φ(A q + B ξ + c), G q − f (Hertz φ) against central differences: the solver
    Newton returns inverts them."""
    from ballscrew.loads.distribution import _newton

    rng = np.random.default_rng(7)
    n, m = 12, 5
    a = -0.05 * rng.random((n, n))
    b = rng.normal(size=(n, m))
    g = b.T / n
    c = 1.0 + 0.1 * rng.random(n)
    f = g @ np.ones(n) * 1.2
    y, jac_solve, _ = _newton(a, b, c, g, f, np.concatenate([np.ones(n), np.zeros(m)]))
    fd, residual = _finite_difference_jacobian(a, b, c, g, f, y)
    assert jac_solve(fd) == pytest.approx(np.eye(n + m), abs=1e-7)
    assert residual < 1e-12


def test_the_sparse_bar_jacobian_matches_finite_differences() -> None:
    """The sparse system of the bars' tail forces and displacements (long nuts) solves with
    the Jacobian of A = κ σ (ℓ z − k min(z_i, z_j)) σ − R, balls out of axial order and two at
    the same z (a shared-ball nut), R banded: central differences, and the same root."""
    from ballscrew.loads.distribution import _Bars, _newton

    rng = np.random.default_rng(11)
    n, m = 12, 3
    z = rng.permutation(np.append(np.linspace(-0.02, 0.03, n - 1), 0.005))
    sigma = np.where(rng.random(n) < 0.5, 1.0, -1.0)
    kappa, lead_coef, bar = 2.0, 0.4, 1.3
    near = np.abs(z[:, None] - z[None, :]) < 0.006
    ring = 0.01 * near * rng.random((n, n))
    a = kappa * sigma[:, None] * (lead_coef * z[:, None] - bar * np.minimum.outer(z, z))
    a = a * sigma[None, :] - ring
    b = np.column_stack([sigma, rng.normal(size=(n, m - 1))])
    g = b.T / n
    c = 1.0 + 0.1 * rng.random(n)
    f = g @ np.ones(n) * 1.2
    start = np.concatenate([np.ones(n), np.zeros(m)])
    bars = _Bars(kappa, lead_coef, bar, z, sigma, sp.csr_matrix(ring))
    y, jac_solve, _ = _newton(bars, b, c, g, f, start)
    assert bars @ y[:n] == pytest.approx(a @ y[:n], rel=1e-13, abs=1e-15)
    fd, residual = _finite_difference_jacobian(a, b, c, g, f, y)
    eye = np.column_stack([jac_solve(column) for column in fd.T])
    assert eye == pytest.approx(np.eye(n + m), abs=1e-7)
    assert residual < 1e-12
    assert y == pytest.approx(_newton(a, b, c, g, f, start)[0], rel=1e-12, abs=1e-14)


def test_free_nut_of_a_single_nut_and_four_point_contact() -> None:
    single = ball_layout(90, 1, LEAD, D_M, BALL, ALPHA, LEAD)
    d = solve(3000.0, single, fp=0.0, support="free")
    assert d.nut_forces == pytest.approx([3000.0], rel=1e-12)
    assert np.abs(d.resultant[1:3]).max() < 1e-10 * d.loads.max()
    shared = ball_layout(90, 2, LEAD, D_M, BALL, ALPHA, LEAD, shared=True)
    d = solve(1000.0, shared, support="free")
    assert d.nut_forces[0] - d.nut_forces[1] == pytest.approx(1000.0, rel=1e-10)
    assert np.abs(d.resultant[1:3]).max() < 1e-10 * d.loads.max()


def test_lift_off_of_a_free_double_nut() -> None:
    free = lift_off_load(LAYOUT, K, BETA, ALPHA, 1500.0, BODIES, rtol=1e-5, support="free")
    assert 2.0**1.5 * 1500.0 < free < 4.0 * 1500.0
    d = solve(1.02 * free, support="free")
    assert np.all(d.per_nut(d.loads)[1] == 0.0)


def test_bad_support_inputs_are_named() -> None:
    with pytest.raises(InputError, match="nut_support"):
        solve(0.0, support="tilted")
    with pytest.raises(InputError, match="radial_load"):
        solve(0.0, radial_load=100.0)  # a guided nut's housing takes it
    with pytest.raises(InputError, match="tilting_moment"):
        solve(0.0, support="free", tilting_moment=math.nan)
