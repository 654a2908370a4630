"""Per-ball load distribution against the closed form of a threaded joint with elastic bars.

No published per-ball distribution of a ball screw with numbers we could read was found (Mei et
al. 2003 and Zhen & An 2018 give theirs as figures), so the bar part of the model is verified
against the classical closed form of the load distribution over the threads of a bolt and nut
(Sopwith 1948; Yamamoto 1980, *The Theory and Computation of Threads Connection*). With equal
thread (here ball) springs k and bars of compliance c = 1/(E_s A_s) + 1/(E_n A_n) per length,
the force of the j-th carrier, counted from the unloaded end of a nut loaded at its flange end
(bolt in tension, nut in compression: the "standard nut"), obeys

    Q_{j+1} − 2 Q_j + Q_{j−1} = k s² c Δz Q_j,   Q_1 − Q_0 = k s² c Δz Q_0,

whose solution is Q_j ∝ cosh(μ (j + 1/2)), cosh μ = 1 + k s² c Δz / 2 (s = sinβ cosλ the axial
share of a ball load, Δz the axial ball spacing). Hertz contacts have no single spring constant,
so the check is made on the tangent problem about a uniform state: a lead error e_j that cancels
the body strain of a uniform load Q̄ makes every ball carry Q̄, and every ball then has the same
tangent spring k = 3/(2K) Q̄^{1/3}; the increments of the ball loads for a small load increment
(central difference) must follow the closed form. A verification of the equations and the
solver (bars, lead-error input, Newton), not a validation against measurements.

The free nut's five-degree-of-freedom balance is verified against the classical ball load
distribution of a ball bearing under radial load with zero clearance (Stribeck 1901; Sjövall's
integral, as tabulated by Harris & Kotzalas 2007): rigid rings, Hertz balls, only the balls within
±90° of the load carry, Q(ψ) = Q_max cos^(3/2) ψ and F_r = Z Q_max J_r cosβ per row with
J_r = (1/2π) ∫ cos^(5/2) ψ dψ = Γ(7/4)/(2√π Γ(9/4)) = 0.22883, i.e. Q_max = 4.37 F_r/(Z cosβ).
Two such rows of the same flank, 30 mm apart, on a vanishing lead angle, make the nut (one row
alone cannot tell a radial shift from a tilt); the axial load that keeps the zone at ±90° is
F_a = Z Q_max J_a sinβ per row (J_a = (1/2π) ∫ cos^(3/2) ψ dψ), and the moment of the balls' axial
components about the nut's centre, r sinβ F_r/cosβ, is applied as the external moment, so the
closed form holds with the nut shifted radially and not tilted.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.loads.distribution import BallLayout, NutBodies, ball_layout, solve_distribution

MM = 1e-3
BETA = math.radians(45.0)
LEAD, D_M, D_B = 10 * MM, 40 * MM, 6.35 * MM
ALPHA = math.atan(LEAD / (math.pi * D_M))
HERTZ = 1.0e-7  # K of a ball's two contacts [m N^-2/3]
Q_BAR = 200.0  # uniform ball load of the reference state [N]
SOURCE = (
    "Sopwith (1948), Proc. IMechE 159; Yamamoto (1980): thread-load distribution of a "
    "bolt-nut joint with elastic bars, cosh law"
)
REFERENCE = {
    "citation": "Sopwith, D.G. (1948), The distribution of load in screw threads, Proc. IMechE "
    "159, 373-383; Yamamoto, A. (1980), The Theory and Computation of Threads Connection, Yokendo",
    "location": "load distribution over the threads of a bolt and nut with elastic bars and equal "
    "thread springs (the discrete form of the cosh law)",
    "retrieved_via": "the closed form as derived in this test's docstring from the bar equations "
    "(the sources were not read in this work)",
    "quote": "Q_j ∝ cosh(μ (j + 1/2)), cosh μ = 1 + k s² c Δz / 2",
    "verified": False,
}
ASSUMPTIONS = (
    "single nut of 40 balls in one row (4 turns of a 40 x 10 screw with 6.35 mm balls; 591 "
    "balls, 30 turns, for the long nut), "
    "contact angle 45°, Hertz constant K = 1e-7 m N^-2/3",
    "nut flange at the loaded end; ring expansion off (the closed form has bars only)",
    "uniform reference load 200 N per ball made by a compensating lead error; increment ±1e-4 "
    "of the load",
)


def _tangent_shares(e_a: float, balls: int = 40) -> tuple[np.ndarray, np.ndarray, float]:
    """(shares from the solver, closed-form shares, μ) for bar rigidity E A = ``e_a`` [N] and
    a nut of ``balls`` balls."""
    layout = ball_layout(balls, 1, LEAD, D_M, D_B, ALPHA, 0.0)
    bodies = NutBodies(screw_rigidity=e_a, nut_rigidity=e_a, ring_compliance=0.0)
    s = math.sin(BETA) * math.cos(ALPHA)
    c = 2.0 / e_a
    z = layout.z
    # body strain of the uniform state: v_j - x = s Q̄ Σ_i C_ji with C_ji = c (z_j - min(z_i, z_j))
    strain = s * Q_BAR * c * (z[:, None] - np.minimum(z[:, None], z[None, :])).sum(axis=1)
    load = layout.z.size * s * Q_BAR

    def loads(f: float) -> np.ndarray:
        args = (HERTZ, BETA, ALPHA, f, 0.0, bodies)
        return solve_distribution(layout, *args, lead_error=-strain).loads

    base = loads(load)
    assert np.allclose(base, Q_BAR, rtol=1e-9)  # the compensated state is uniform
    d = 1e-4 * load
    dq = (loads(load + d) - loads(load - d)) / (2 * d)
    k = 1.5 / HERTZ * Q_BAR ** (1.0 / 3.0)
    dz = float(np.abs(np.diff(z)).mean())
    mu = math.acosh(1.0 + 0.5 * k * s * s * c * dz)
    j = np.argsort(np.argsort(z))  # 0 at the end away from the load
    closed = np.cosh(mu * (j + 0.5))
    return dq / dq.sum(), closed / closed.sum(), mu


STEEL_SHAFT = 206e9 * math.pi / 4 * (34.4 * MM) ** 2


@pytest.mark.parametrize(
    ("label", "e_a", "balls"),
    [("steel_40mm", STEEL_SHAFT, 40), ("soft", 2e7, 40), ("steel_40mm_30_turns", STEEL_SHAFT, 591)],
)
def test_tangent_distribution_follows_the_cosh_law(
    validation, label: str, e_a: float, balls: int
) -> None:
    """Also a long nut (30 turns, 591 balls: end/far-end ratio 3.8e3), whose steep load
    gradient stopped the double nut's preload solve before."""
    shares, closed, mu = _tangent_shares(e_a, balls)
    worst = int(np.argmax(np.abs(shares / closed - 1.0)))
    loaded_end = int(np.argmax(closed))
    validation.check(
        f"distribution_cosh_{label}_loaded_end",
        kind="verification against a closed form",
        model="solve_distribution (bars, Hertz, lead error)",
        source=SOURCE,
        reference=REFERENCE | {"bar rigidity E A [N]": e_a, "mu": mu, "balls": balls},
        quantity="share of a load increment taken by the ball at the loaded end",
        unit="-",
        measured=float(closed[loaded_end]),
        predicted=float(shares[loaded_end]),
        tolerance=1e-6,
        relative=True,
        tolerance_basis="central difference of ±1e-4 of the load: O(1e-8) nonlinearity",
        assumptions=ASSUMPTIONS,
    )
    assert shares[worst] == pytest.approx(closed[worst], rel=1e-6)


STRIBECK = {
    "citation": "Stribeck, R. (1901), Kugellager für beliebige Belastungen, Zeitschrift des VDI "
    "45; Harris, T.A., Kotzalas, M.N. (2007), Rolling Bearing Analysis, 5th ed., CRC Press "
    "(Sjövall's radial integral J_r)",
    "location": "ball bearing under radial load with zero clearance: Q_max = 4.37 F_r/(Z cos β), "
    "loaded zone ±90°",
    "retrieved_via": "the closed form J_r = Γ(7/4)/(2√π Γ(9/4)) derived in this test's docstring "
    "(the sources were not read in this work)",
    "quote": "Q_max = 4.37 F_r / (Z cos β)",
    "verified": False,
}


def test_free_nut_reproduces_the_stribeck_radial_distribution(validation) -> None:
    balls, beta, radius, spacing, alpha = 120, math.radians(40.0), 20 * MM, 30 * MM, 1e-7
    j_r = math.gamma(7 / 4) / (2.0 * math.sqrt(math.pi) * math.gamma(9 / 4))
    j_a = math.gamma(5 / 4) / (2.0 * math.sqrt(math.pi) * math.gamma(7 / 4))
    theta = np.repeat(2.0 * math.pi * np.arange(balls) / balls, 2)
    layout = BallLayout(
        z=np.tile([0.5 * spacing, -0.5 * spacing], balls),  # two rows, interleaved
        flank=np.ones(2 * balls),
        nut=np.zeros(2 * balls, dtype=np.int64),
        turn=np.zeros(2 * balls, dtype=np.int64),
        angle=theta,
        lead=2.0 * math.pi * radius * math.tan(alpha),
        nuts=1,
    )
    f_r = 1000.0
    q_max = f_r / (2 * balls * j_r * math.cos(beta))
    s = math.sin(beta) * math.cos(alpha)
    d = solve_distribution(
        layout,
        HERTZ,
        beta,
        alpha,
        2 * balls * q_max * j_a * s,
        0.0,
        NutBodies(),
        support="free",
        radial_load=f_r,
        tilting_moment=-radius * s * f_r / math.cos(beta),
    )
    # the nut gives way along F_r: the zone is centred opposite, ψ = θ − π
    closed = q_max * np.maximum(np.cos(theta - math.pi), 0.0) ** 1.5
    coefficient = float(d.loads.max()) * balls * math.cos(beta) / (0.5 * f_r)
    validation.check(
        "distribution_free_nut_stribeck_radial",
        kind="verification against a closed form",
        model="solve_distribution (free nut: five-DOF balance, Hertz, rigid bodies)",
        source="Stribeck (1901); Sjövall integral J_r (Harris & Kotzalas 2007)",
        reference=STRIBECK | {"balls per row": balls, "rows": 2, "contact angle [deg]": 40.0},
        quantity="Q_max Z cos β / F_r of a row (Stribeck's 4.37 for zero clearance)",
        unit="-",
        measured=1.0 / j_r,
        predicted=coefficient,
        tolerance=1e-4,
        relative=True,
        tolerance_basis="discrete balls against the integral: 5e-4 at 40 balls per row, 3e-5 "
        "at 120 (error ∝ Z^-2.6)",
        assumptions=(
            "two rows of 120 balls on one flank, 30 mm apart, pitch radius 20 mm, contact angle "
            "40°, lead angle 1e-7 rad; rigid bodies",
            "the axial load of a ±90° zone and the moment of the axial components applied, so "
            "the closed form has no tilt",
        ),
    )
    assert np.abs(d.loads - closed).max() < 1e-4 * q_max
    assert abs(d.tilt[1]) * radius < 1e-6 * d.radial_displacement[0]
