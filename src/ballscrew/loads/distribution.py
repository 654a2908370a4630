"""Elastic load distribution over every ball of a nut: Hertz contacts and elastic bodies.

Every ball j of every loaded turn sits at an axial position z_j on a flank σ_j = ±1 (+1: the
nut the external load presses on). Its normal contact approach is

    δ_j = s [σ_j (v_j + e_j) + g] + Δd_j − c_r cosβ f_j,     s = sinβ cosα,
    v_j = x + Σ_i C_ji σ_i s Q_i,
    Q_j = (max(δ_j, 0) / K)^(3/2)                               (Hertz, no tension),

with v the axial displacement of the screw relative to the nut at z_j: a rigid part x plus the
strain of the screw shaft and the nut body between the balls. Both are bars (Mei et al. 2003;
Zhen & An 2018): the force each ball hands from the screw to the nut accumulates along the nut,
so with c = 1/(EA) the flexibility is

    C_ji = (c_s + c_n [flange at the loaded end]) z_j − (c_s + c_n) min(z_i, z_j)

(the screw carries the load out at the loaded end z → +∞). e_j is the lead error (axial, screw
relative to nut), Δd_j the ball-diameter excess, g the interference the spacer of a double nut
builds in (found from the preload; for a single nut preloaded by oversized balls the two "nuts"
are the two contact pairs of the same balls at the same z_j, g the ball oversize),
K = K_A + K_B the Hertz constants of a ball's two contacts.
The nut ring widens and the shaft shrinks under the radial line load f_j = cosβ n_t ⟨Q⟩_j / L
of the turn around ball j (n_t balls per turn, ⟨Q⟩_j their mean load); Lamé thick ring and
solid shaft give c_r = [(r_o² + r²)/(r_o² − r²) + ν_n]/(2π E_n) + (1 − ν_s)/(2π E_s) of radial
approach per line load (the thick-ring expansion of the MESYS ball-screw manual).

One Newton solve on (Q, x[, g]) with a backtracking line search; the force balance
Σ σ_j s Q_j = F_a (a single nut: F_p + F_a on its one flank) is a linear row of the system, so it
holds to rounding. Up to SPARSE_BALLS balls the Jacobian is dense; above, Newton solves the same
step as a sparse system with twice as many more unknowns, the bars' tail forces
t_k = Σ_{i≥k} σ_i Q_i and displacements u_k = Σ_{l≤k} Δz_l t_l over the balls in axial order
(Σ_i min(z_i, z_j) σ_i Q_i = u_j: two bidiagonal rows per ball for a dense one), banded in
axial order but for the rigid displacements, by sparse LU.
The contact angle under load follows the distance of the groove curvature centres
A = (f_s + f_N − 1) D_b: cos β_j = A cos β₀ / (A + δ_j) (Harris & Kotzalas 2007); the axial
share s keeps β₀ (the change is of order δ/A, 1–2 %).

The helix does not place the balls symmetrically: their loads leave a radial force and a tilting
moment on the nut. ``support="guided"`` (default) lets the housing take them (the nut moves only
axially). ``support="free"`` makes the nut a rigid body on its balls: the radial displacement u
and tilt γ join x, each ball's approach gains −h_j·(0, u, γ) and the balance gains the radial
and tilting rows Σ Q_j h_j + (F_r, M) = 0 (:mod:`ballscrew.loads.rigid_nut`; Jones 1960).
Theory manual, *Loads*.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache, cached_property, partial

import numpy as np
import scipy.sparse as sp
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq
from scipy.sparse.linalg import splu

from ballscrew.backend import blas_single_thread
from ballscrew.errors import ConvergenceError, InputError
from ballscrew.loads.ball_load import validate_angles, validate_balls
from ballscrew.loads.contact_law import TabulatedContact
from ballscrew.loads.preload_method import flank_forces
from ballscrew.loads.rigid_nut import ball_directions, validate_support
from ballscrew.validation import positive

__all__ = [
    "LIFT_OFF_SEARCH",
    "SPARSE_BALLS",
    "BallLayout",
    "Distribution",
    "NutBodies",
    "ball_layout",
    "body_properties",
    "expand_errors",
    "lift_off_load",
    "loaded_contact_angle",
    "solve_distribution",
]

_TOLERANCE = 1e-13
"""Newton stop on max |residual| relative to the system's scale max(1, max |q̂|, max |f̂|): the
rows are loads in units of the reference load, so a large radial load or tilting moment on a
free nut leaves rounding of order ε max |q̂| (an absolute 1e-13 was unreachable there)."""
_MAX_ITERATIONS = 60
SPARSE_BALLS = 400
"""Balls (both nuts) from which Newton factorises the sparse bar system instead of the dense
Jacobian: the measured crossover (one solve of a double nut, 300 balls: dense 9.7 ms, sparse
12.8 ms; 400: 18.9 and 15.2 ms; 800: 132 and 32 ms)."""


@dataclass(frozen=True)
class BallLayout:
    """Where the balls are: one entry per ball, nut 1 first (SI)."""

    z: NDArray[np.float64]
    """Axial position along the nut [m], growing towards the loaded end."""
    flank: NDArray[np.float64]
    """σ = +1 for nut 1 (the loaded nut), −1 for nut 2."""
    nut: NDArray[np.int64]
    """0 for nut 1, 1 for nut 2."""
    turn: NDArray[np.int64]
    """Turn of the ball within its nut, 0 = the turn nearest the loaded end."""
    angle: NDArray[np.float64]
    """Angle θ of the ball around the screw axis [rad] (a right-hand helix: θ = 2π z/L from
    nut 1's ball nearest the loaded end)."""
    lead: float
    """Lead L [m]."""
    nuts: int
    shared: bool = False
    """True: the two "nuts" are the two contact pairs of the same balls (a single nut preloaded
    by oversized balls, four-point contact): both flanks at the same axial positions."""

    @property
    def balls(self) -> int:
        """Balls per nut."""
        return self.z.size // self.nuts

    @property
    def turns(self) -> int:
        """Started turns per nut."""
        return int(self.turn.max()) + 1


def ball_layout(
    balls_per_nut: int,
    nuts: int,
    lead: float,
    pitch_diameter: float,
    ball_diameter: float,
    lead_angle: float,
    spacer: float,
    shared: bool = False,
) -> BallLayout:
    """Axial positions of touching balls on the helix; nut 1 at the loaded end.

    Balls touch along the helix of length π d_m / cos α per turn, so consecutive balls are
    Δz = L D_b cos α / (π d_m) apart axially. Nut 2 lies beyond nut 1 away from the loaded end,
    its nearest ball ``spacer`` [m] from nut 1's; with ``shared`` (two "nuts" that are the two
    contact pairs of the same balls, four-point contact) at nut 1's positions.
    """
    z_count = validate_balls(balls_per_nut)
    if nuts not in (1, 2) or (shared and nuts != 2):
        raise InputError("nuts", nuts, "2 where the flanks share the balls, else 1 or 2")
    lead = positive("lead", lead, "m")
    step = lead * ball_diameter * math.cos(lead_angle) / (math.pi * pitch_diameter)
    own = np.arange(z_count) * step  # distance from the nut's end nearest the loaded end
    if shared:
        starts = [own[-1], own[-1]]
    else:
        top = own[-1] if nuts == 1 else 2.0 * own[-1] + positive("spacer", spacer, "m")
        starts = [top, top - own[-1] - spacer][:nuts]
    turn = np.floor(own / lead + 1e-12).astype(np.int64)
    z = np.concatenate([start - own for start in starts])
    return BallLayout(
        z=z,
        flank=np.repeat([1.0, -1.0][:nuts], z_count),
        nut=np.repeat(np.arange(nuts), z_count),
        turn=np.tile(turn, nuts),
        angle=2.0 * math.pi * (z - z[0]) / lead,
        lead=lead,
        nuts=nuts,
        shared=shared,
    )


@dataclass(frozen=True)
class NutBodies:
    """Elastic screw shaft and nut body under the balls (defaults: rigid bodies)."""

    screw_rigidity: float = math.inf
    """E_s A_s of the shaft under the nut [N]."""
    nut_rigidity: float = math.inf
    """E_n A_n of the nut body [N]."""
    ring_compliance: float = 0.0
    """c_r: radial widening of nut ring plus shrinking of the shaft per radial line load
    [m²/N]."""
    flange_at_loaded_end: bool = True
    """True: the nut flange is at the end where the shaft carries the load out (shaft and nut
    body strained in opposite senses, the less even case); False: at the other end."""


def body_properties(
    pitch_diameter: float,
    ball_diameter: float,
    contact_angle: float,
    root_diameter: float,
    nut_outer_diameter: float,
    screw_elastic: tuple[float, float],
    nut_elastic: tuple[float, float],
    flange_at_loaded_end: bool = True,
) -> NutBodies:
    """Bar rigidities and ring compliance of shaft and nut from their diameters.

    Shaft: A_s = π d_r²/4. Nut body: A_n = π (D_o² − (d_m + D_b)²)/4 outside the groove
    bottom. Ring (Lamé thick cylinder under internal pressure at the contact radius
    r = (d_m + D_b cosβ)/2, solid shaft under external pressure, plane stress; Timoshenko &
    Goodier 1970, §33): c_r = [(D_o² + 4r²)/(D_o² − 4r²) + ν_n]/(2π E_n) + (1 − ν_s)/(2π E_s).
    ``screw_elastic`` and ``nut_elastic`` are (E [Pa], ν).
    """
    e_s, nu_s = screw_elastic
    e_n, nu_n = nut_elastic
    d_r = positive("root_diameter", root_diameter, "m")
    d_o = positive("nut_outer_diameter", nut_outer_diameter, "m")
    bore = pitch_diameter + ball_diameter
    if not d_o > bore:
        raise InputError(
            "nut_outer_diameter", d_o, f"> the nut groove bottom d_m + D_b = {bore:.6g} m"
        )
    r2 = (0.5 * (pitch_diameter + ball_diameter * math.cos(contact_angle))) ** 2
    ro2 = 0.25 * d_o**2
    ring = ((ro2 + r2) / (ro2 - r2) + nu_n) / (2.0 * math.pi * e_n)
    return NutBodies(
        screw_rigidity=e_s * 0.25 * math.pi * d_r**2,
        nut_rigidity=e_n * 0.25 * math.pi * (d_o**2 - bore**2),
        ring_compliance=ring + (1.0 - nu_s) / (2.0 * math.pi * e_s),
        flange_at_loaded_end=flange_at_loaded_end,
    )


def expand_errors(name: str, values: ArrayLike | None, layout: BallLayout) -> NDArray[np.float64]:
    """Per-ball values from ``values`` given per ball (nuts × balls) or per turn (nuts × turns),
    nut 1 first, each nut from its end nearest the loaded end; None → zeros. Where the flanks
    share the balls (four-point contact) the values are of the one nut's balls, on both flanks."""
    if values is None:
        return np.zeros(layout.z.size)
    v = np.asarray(values, dtype=float).ravel()
    if not np.all(np.isfinite(v)):
        raise InputError(name, values, "finite numbers")
    rows = 1 if layout.shared else layout.nuts
    nut = np.zeros_like(layout.nut) if layout.shared else layout.nut
    if v.size == rows * layout.balls:
        return v.reshape(rows, layout.balls)[nut, np.tile(np.arange(layout.balls), layout.nuts)]
    if v.size == rows * layout.turns:
        return v.reshape(rows, layout.turns)[nut, layout.turn]
    raise InputError(
        name,
        f"{v.size} values",
        f"{rows * layout.balls} (one per ball) or {rows * layout.turns} (one per turn), "
        "nut 1 first",
    )


@dataclass(frozen=True)
class Distribution:
    """Normal load of every ball, nut 1 first (SI)."""

    layout: BallLayout
    loads: NDArray[np.float64]
    """Normal ball load Q_j [N] (0: lifted off)."""
    approach: NDArray[np.float64]
    """Normal approach δ_j of the ball's two contacts [m] (≤ 0: lifted off)."""
    axial_share: float
    """s = sinβ cosα."""
    axial_load: float
    """External load F_a [N] (on nut 1)."""
    interference: float
    """Interference g of the preload (axial, per nut or flank) [m]: the spacer's, or a
    preloaded single nut's ball oversize or lead offset; 0 for a nut without preload."""
    displacement: float
    """Axial displacement of the shaft at the loaded end relative to the nut flange [m]."""
    compliance: float
    """Tangent dD/dF_a [m/N]."""
    iterations: int
    directions: NDArray[np.float64]
    """h_j of every ball, shape (balls, 5): axial, radial (2) and tilting (2) direction of its
    load on the nut (:func:`~ballscrew.loads.rigid_nut.ball_directions`)."""
    radial_displacement: NDArray[np.float64]
    """Radial displacement (u₁, u₂) of the nut relative to the screw at its centre [m]; 0 for
    a guided nut."""
    tilt: NDArray[np.float64]
    """Tilt (γ₁, γ₂) of the nut relative to the screw about its centre [rad]; 0 if guided."""

    @property
    def stiffness(self) -> float:
        """Tangent axial stiffness dF_a/dD of the nut assembly [N/m]."""
        return 1.0 / self.compliance

    @property
    def resultant(self) -> NDArray[np.float64]:
        """Σ Q_j h_j: axial force, radial force (2) [N] and tilting moment (2) [N·m] of the
        balls on the nut about its centre; a guided nut's housing takes the last four."""
        return self.loads @ self.directions

    @property
    def nut_forces(self) -> NDArray[np.float64]:
        """Axial force Σ s Q of each nut [N], nut 1 first."""
        return self.axial_share * self.loads.reshape(self.layout.nuts, -1).sum(axis=1)

    def per_nut(self, values: NDArray[np.float64]) -> NDArray[np.float64]:
        """``values`` reshaped (nuts, balls)."""
        return values.reshape(self.layout.nuts, -1)


def _bar_coefficients(bodies: NutBodies) -> tuple[float, float]:
    """(ℓ, k) = (c_s + c_n [flange at the loaded end], c_s + c_n) of C = ℓ z_j − k min(z_i, z_j)."""
    c_s, c_n = 1.0 / bodies.screw_rigidity, 1.0 / bodies.nut_rigidity
    return c_s + (c_n if bodies.flange_at_loaded_end else 0.0), c_s + c_n


def _flexibility(layout: BallLayout, bodies: NutBodies) -> tuple[NDArray[np.float64], float]:
    """C (m/N) for the signed axial ball forces, and the coefficient of the displacement."""
    lead_coef, bar = _bar_coefficients(bodies)
    z = layout.z
    flex = lead_coef * z[:, None] - bar * np.minimum(z[:, None], z[None, :])
    return flex, lead_coef


def _window(layout: BallLayout) -> sp.csr_matrix:
    """Averaging over the balls of the same nut within half a lead: f_j = cosβ n_t ⟨Q⟩_j / L
    with n_t balls per turn, so a nut's end turns see the local mean load, not half of it.
    Where the flanks share the balls both contact pairs press the ring: f_j = cosβ n_t
    (⟨Q₁⟩_j + ⟨Q₂⟩_j) / L. Sparse: each ball's neighbours within half a lead are a run of the
    balls of its nut in axial order."""
    z, n = layout.z, layout.z.size
    half = 0.5 * layout.lead * (1 + 1e-12)
    groups = [np.arange(n)] if layout.shared else [np.flatnonzero(layout.nut == k) for k in (0, 1)]
    rows, cols = [], []
    for members in groups[: 1 if layout.shared else layout.nuts]:
        order = members[np.argsort(z[members], kind="stable")]
        zs = z[order]
        lo = np.searchsorted(zs, zs - half, side="left")
        count = np.searchsorted(zs, zs + half, side="right") - lo
        first = np.cumsum(count) - count  # where each ball's run starts in the flat list
        rows.append(np.repeat(order, count))
        cols.append(order[np.arange(count.sum()) - np.repeat(first - lo, count)])
    row, col = np.concatenate(rows), np.concatenate(cols)
    per_turn = layout.lead / float(np.abs(z[1] - z[0])) if layout.balls > 1 else 1.0
    pairs = layout.nuts if layout.shared else 1
    weight = pairs * per_turn / np.bincount(row, minlength=n).astype(float)
    return sp.csr_matrix((weight[row], (row, col)), shape=(n, n))


Law = Callable[[NDArray[np.float64]], tuple[NDArray[np.float64], NDArray[np.float64]]]
"""Scaled contact law d ↦ (q(d), dq/dd)."""


def _hertz_law(d: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """q = max(d, 0)^(3/2) and its slope (Hertz in the scaled units)."""
    dp = np.maximum(d, 0.0)
    return dp**1.5, 1.5 * np.sqrt(dp)


def _scaled_law(contact: TabulatedContact, q_ref: float, d_ref: float) -> Law:
    """The tabulated Q(δ) in the scaled units q = Q/q_ref, d = δ/d_ref."""

    def law(d: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        q, slope = contact.load(d * d_ref)
        return q / q_ref, slope * (d_ref / q_ref)

    return law


@dataclass(frozen=True)
class _Bars:
    """The scaled a = κ σ_j (ℓ z_j − k min(z_i, z_j)) σ_i − R_ji (the bars' flexibility,
    equations above, and the ring's banded window R) as an operator, ``a @ q`` in O(n), and its
    sparse Jacobian."""

    kappa: float
    lead_coef: float
    bar: float
    """k = c_s + c_n."""
    z: NDArray[np.float64]
    sigma: NDArray[np.float64]
    ring: sp.csr_matrix

    @cached_property
    def _axial(self) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
        """The balls in axial order and Δz_k, min(z_a, z_b) = Σ_{k ≤ min(a, b)} Δz_k."""
        order = np.argsort(self.z, kind="stable")
        return order, np.diff(self.z[order], prepend=0.0)

    def __matmul__(self, q: NDArray[np.float64]) -> NDArray[np.float64]:
        """a q through the tail forces t and displacements u of σ q in axial order."""
        order, dz = self._axial
        tail = np.cumsum((self.sigma * q)[order][::-1])[::-1]
        u = np.empty_like(tail)
        u[order] = np.cumsum(dz * tail)
        return self.kappa * self.sigma * (self.lead_coef * self.z * tail[0] - self.bar * u) - (
            self.ring @ q
        )

    def jacobian(
        self, b: NDArray[np.float64], g: NDArray[np.float64]
    ) -> tuple[sp.csr_matrix, sp.csr_matrix, NDArray[np.int64]]:
        """(E, F, p) of J = E + diag(φ', 0) F on (q, ξ, t, û), û = κ k u: the rows of q are
        q_j + φ'_j [R q − σ_j (κ ℓ z_j t_first − û_j) − B ξ]_j, then G q, the tail rows
        t_k − t_{k+1} − σ q = 0 and the displacement rows û_k − û_{k−1} − κ k Δz_k t_k = 0.
        Rows and columns in the order p, which makes J banded but for the last 1 + len(ξ)
        columns and len(ξ) rows (LU without fill-reducing permutation)."""
        n, m = b.shape
        order, dz = self._axial
        rank = np.empty(n, dtype=np.int64)
        rank[order] = np.arange(n)
        t0, u0 = n + m, 2 * n + m
        size = 3 * n + m
        k = np.arange(n)
        eye = sp.csr_matrix((np.ones(n), (k, k)), shape=(n, size))
        balance = sp.coo_matrix(g).tocsr()
        tail = sp.csr_matrix(
            (
                np.concatenate([np.ones(n), -np.ones(n - 1), -self.sigma[order]]),
                (np.concatenate([k, k[:-1], k]), np.concatenate([t0 + k, t0 + k[1:], order])),
            ),
            shape=(n, size),
        )
        bars = sp.csr_matrix(
            (
                np.concatenate([np.ones(n), -np.ones(n - 1), -self.kappa * self.bar * dz]),
                (np.concatenate([k, k[1:], k]), np.concatenate([u0 + k, u0 + k[:-1], t0 + k])),
            ),
            shape=(n, size),
        )
        e = sp.vstack([eye, sp.hstack([balance, sp.csr_matrix((m, size - n))]), tail, bars])
        rows = sp.hstack(
            [
                self.ring,
                sp.csr_matrix(-b),
                sp.csr_matrix(
                    (
                        np.concatenate(
                            [-self.kappa * self.lead_coef * self.sigma * self.z, self.sigma]
                        ),
                        (
                            np.concatenate([k, k]),
                            np.concatenate([np.full(n, t0 - n - m), u0 - n - m + rank]),
                        ),
                    ),
                    shape=(n, 2 * n),
                ),
            ]
        ).tocsr()
        f = sp.vstack([rows, sp.csr_matrix((2 * n + m, size))])
        # banded order: (q, t, û) of each ball in axial order, then the dense t_first and ξ
        banded = np.column_stack([order, t0 + k, u0 + k]).ravel()
        perm = np.concatenate([np.delete(banded, 1), [t0], n + np.arange(m)])
        return e.tocsr()[perm][:, perm], f.tocsr()[perm][:, perm], perm


Solver = Callable[[NDArray[np.float64]], NDArray[np.float64]]
"""x ↦ J⁻¹ x for the Jacobian of the (q, ξ) system at the solution."""


def _newton(
    a: NDArray[np.float64] | _Bars,
    b: NDArray[np.float64],
    c: NDArray[np.float64],
    g: NDArray[np.float64],
    f: NDArray[np.float64],
    y: NDArray[np.float64],
    law: Law = _hertz_law,
) -> tuple[NDArray[np.float64], Solver, int]:
    """Solve q = φ(A q + B ξ + c), G q = f for y = (q, ξ) (scaled units; Hertz φ(d) = d₊^(3/2)).

    Stops when max |residual| < 1e-13 max(1, max |q|, max |f|). Returns the solution, the
    solver of the Jacobian at it and the iteration count. Small dense systems: BLAS runs on one
    thread (threaded BLAS on busy cores is many times slower here). Where A is the bars'
    operator (:class:`_Bars`) each step solves their sparse system instead.
    """
    n, m = b.shape
    diagonal = np.arange(n)
    f_max = float(np.max(np.abs(f), initial=1.0))

    def residual(y: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        q, slope = law(a @ y[:n] + b @ y[n:] + c)
        return np.concatenate([y[:n] - q, g @ y[:n] - f]), slope

    if isinstance(a, np.ndarray):
        jac = np.zeros((n + m, n + m))

        def factor(slope: NDArray[np.float64]) -> Solver:
            np.multiply(-slope[:, None], a, out=jac[:n, :n])
            jac[diagonal, diagonal] += 1.0
            jac[:n, n:] = -slope[:, None] * b
            jac[n:, :n] = g
            return partial(np.linalg.solve, jac)

    else:
        e, f_rows, perm = a.jacobian(b, g)
        slopes = perm < n  # where the unknowns q sit in the banded order

        def factor(slope: NDArray[np.float64]) -> Solver:
            d = np.zeros(3 * n + m)
            d[slopes] = slope[perm[slopes]]
            try:
                lu = splu((e + sp.diags(d) @ f_rows).tocsc(), permc_spec="NATURAL")
            except RuntimeError as err:  # "Factor is exactly singular"
                raise np.linalg.LinAlgError(str(err)) from err

            def solve(rhs: NDArray[np.float64]) -> NDArray[np.float64]:
                x = np.empty(3 * n + m)
                x[perm] = lu.solve(np.concatenate([rhs, np.zeros(2 * n)])[perm])
                return x[: n + m]

            return solve

    r, slope = residual(y)
    norm = float(np.max(np.abs(r)))
    with blas_single_thread():
        for it in range(1, _MAX_ITERATIONS + 1):
            tolerance = _TOLERANCE * max(f_max, float(np.max(np.abs(y[:n]))))
            if norm < tolerance:
                return y, factor(slope), it - 1
            try:
                step = factor(slope)(-r)
            except np.linalg.LinAlgError:  # a stiffness so far off that J is singular
                break
            t, phi = 1.0, norm
            while True:
                trial = y + t * step
                r_t, slope_t = residual(trial)
                norm_t = float(np.max(np.abs(r_t)))
                if norm_t < (1.0 - 1e-4 * t) * phi or t < 1e-6:
                    break
                t *= 0.5
            y, r, slope, norm = trial, r_t, slope_t, norm_t
    raise ConvergenceError("ball load distribution (Newton)", it, norm, tolerance)


def solve_distribution(
    layout: BallLayout,
    hertz_constant: float,
    contact_angle: float,
    lead_angle: float,
    axial_load: float,
    preload: float,
    bodies: NutBodies | None = None,
    lead_error: ArrayLike | None = None,
    ball_excess: ArrayLike | None = None,
    interference: float | None = None,
    contact: TabulatedContact | None = None,
    support: str = "guided",
    radial_load: float = 0.0,
    tilting_moment: float = 0.0,
    start: Distribution | None = None,
) -> Distribution:
    """Normal load of every ball under the axial load F_a on nut 1, equations above.

    A double nut's spacer interference g is found from its preload (F_a = 0: nut 1 carries F_p)
    unless ``interference`` is given; a single nut carries F_p + F_a. With ``contact`` every
    ball follows that tabulated law Q(δ) (a numerical, non-Hertzian contact pair) instead of
    Hertz; K then only scales the unknowns and starts Newton.

    Args:
        layout: where the balls are (:func:`ball_layout`).
        hertz_constant: K = K_A + K_B, δ = K Q^(2/3) of a ball's two contacts [m N^(-2/3)].
        contact_angle, lead_angle: β₀ and α [rad].
        axial_load: F_a ≥ 0 [N].
        preload: F_p [N] (> 0 for a double nut).
        bodies: elastic bodies; None = rigid.
        lead_error: axial lead error e of the screw relative to the nut [m], per ball or turn.
        ball_excess: ball-diameter excess Δd [m], per ball or per turn.
        interference: the spacer interference g [m] of a double nut, if known.
        contact: the load–approach law of a ball's two contacts; None = Hertz, δ = K Q^(2/3).
        support: "guided" (the housing takes the balls' radial force and tilting moment) or
            "free" (a rigid nut balanced by its balls in radial displacement and tilt too).
        radial_load, tilting_moment: external force [N] along e₁ (towards θ = 0) and moment
            [N·m] about e₂ on a free nut, at its centre.
        start: the solution at a neighbouring load of the same nut (every other argument
            alike) for Newton to start from, where the nut has SPARSE_BALLS balls or more;
            smaller nuts start from the rigid solution (their results do not depend on it).
    """
    beta, alpha = validate_angles(contact_angle, lead_angle)
    k = positive("hertz_constant", hertz_constant, "m N^-2/3")
    fa = float(axial_load)
    fp = float(preload)
    if not (math.isfinite(fa) and fa >= 0.0):
        raise InputError("axial_load", axial_load, "a finite number >= 0 N")
    if not (math.isfinite(fp) and fp >= 0.0) or (layout.nuts == 2 and fp == 0.0):
        raise InputError("preload", preload, "> 0 N for a double nut, >= 0 N for one nut")
    if layout.nuts == 1 and fa + fp == 0.0:
        raise InputError("axial_load", axial_load, "> 0 N where the preload is 0 N")
    free = validate_support(support, float(radial_load), float(tilting_moment))
    bodies = bodies or NutBodies()
    s = math.sin(beta) * math.cos(alpha)
    z_count = layout.balls
    sigma = layout.flank
    f_ref = max(fp, fa) if layout.nuts == 2 else fp + fa
    q_ref = f_ref / (z_count * s)
    d_ref = k * q_ref ** (2.0 / 3.0)
    ring = math.cos(beta) ** 2 * bodies.ring_compliance / layout.lead * _window(layout)
    a: NDArray[np.float64] | _Bars
    if sigma.size >= SPARSE_BALLS:
        lead_coef, bar = _bar_coefficients(bodies)
        a = _Bars(s * s * q_ref / d_ref, lead_coef, bar, layout.z, sigma, ring * (q_ref / d_ref))
    else:
        flex, lead_coef = _flexibility(layout, bodies)
        a = (s * s * sigma[:, None] * flex * sigma[None, :] - ring.toarray()) * q_ref / d_ref
    c = (s * sigma * expand_errors("lead_error", lead_error, layout)) / d_ref
    c = c + expand_errors("ball_excess", ball_excess, layout) / d_ref
    force_row = sigma / z_count
    f1, f2 = (float(v) for v in flank_forces(fp, fa, layout.nuts))
    q0 = np.where(sigma > 0, f1, f2) / f_ref  # rigid bodies, no errors
    law = _hertz_law if contact is None else _scaled_law(contact, q_ref, d_ref)
    radius = layout.lead / (2.0 * math.pi * math.tan(alpha))  # d_m/2
    h = ball_directions(layout.z, layout.angle, sigma, radius, beta, alpha)
    # unknowns x̂ = x s/d_ref and, free: û = u/d_ref, γ̂ = γ r/d_ref; rows Σ q̂ h/(Z·scale)
    scale = np.array([s, 1.0, 1.0, radius, radius])[: 5 if free else 1]
    rigid_h = h[:, 1 : scale.size] / scale[1:]
    b = np.column_stack([sigma, -rigid_h])
    rows = np.vstack([force_row, rigid_h.T / z_count])
    external = np.array([-radial_load, 0.0, 0.0, -tilting_moment])[: scale.size - 1] * s
    if layout.nuts == 1:
        g_hat = 0.0
    elif interference is None:
        g_hat = _preload_interference(a, b, c, rows, fp / f_ref, law)
    else:
        g_hat = interference * s / d_ref
    c_load = c + g_hat
    y0 = np.concatenate([q0, [(f1 / f_ref) ** (2.0 / 3.0) - g_hat], np.zeros(scale.size - 1)])
    arm = lead_coef * s * q_ref * sigma * (layout.z.max() - layout.z)
    x_scale = d_ref / s
    if start is not None and isinstance(a, _Bars):  # y of the neighbouring solution
        rigid0 = np.concatenate([start.radial_displacement, start.tilt])[: scale.size - 1]
        y0 = np.concatenate(
            [
                start.loads / q_ref,
                [(start.displacement - float(arm @ start.loads) / q_ref) / x_scale],
                rigid0 * scale[1:] / d_ref,
            ]
        )
    axial = fa if layout.nuts == 2 else f1  # one nut: F_p + F_a
    y, jacobian_solve, its = _newton(
        a,
        b,
        c_load,
        rows,
        np.append(axial, external / scale[1:]) / f_ref,
        y0,
        law,
    )
    n = sigma.size
    rhs = np.zeros(n + scale.size)
    rhs[n] = 1.0 / f_ref
    with blas_single_thread():
        dy = jacobian_solve(rhs)
    q = y[:n] * q_ref
    approach = (a @ y[:n] + b @ y[n:] + c_load) * d_ref
    rigid = y[n + 1 :] * d_ref / scale[1:]
    return Distribution(
        layout=layout,
        loads=q,
        approach=approach,
        axial_share=s,
        axial_load=fa,
        interference=g_hat * d_ref / s,
        displacement=x_scale * y[n] + float(arm @ y[:n]),
        compliance=x_scale * dy[n] + float(arm @ dy[:n]),
        iterations=its,
        directions=h,
        radial_displacement=np.pad(rigid[:2], (0, 2 - rigid[:2].size)),
        tilt=np.pad(rigid[2:], (0, 2 - rigid[2:].size)),
    )


def _preload_interference(
    a: NDArray[np.float64] | _Bars,
    b: NDArray[np.float64],
    c: NDArray[np.float64],
    rows: NDArray[np.float64],
    preload_hat: float,
    law: Law,
) -> float:
    """ĝ at which nut 1 carries the preload with no external load (scaled units); ``b`` and
    ``rows``: the columns and balance rows of the nut's displacements (axial first).

    Newton starts from equal ball loads with x̂ and ĝ such that the median ball *of each nut*
    has the approach of that load: the bodies' strain and the ring's widening at equal loads,
    a@q₀, reach several Hertz approaches on a long nut, of opposite sign on the two nuts, and a
    start that leaves one nut with no loaded ball makes x̂ and ĝ act alike on the loaded balls,
    so the Jacobian is singular (ĝ = q₀^(2/3) alone failed from 15 turns per nut on, ĝ from the
    median over both nuts from 30 turns on). The approach of nut k is ±x̂ + ĝ + (a@q₀ + c).
    """
    n, m = b.shape
    sigma = b[:, 0]
    g = np.vstack([rows, np.where(sigma > 0, 1.0 / (n // 2), 0.0)])
    q0 = np.full(n, preload_hat)
    d0 = a @ q0 + c
    median_1, median_2 = (float(np.median(d0[side])) for side in (sigma > 0, sigma < 0))
    g0 = preload_hat ** (2.0 / 3.0) - 0.5 * (median_1 + median_2)
    start = np.concatenate([q0, [0.5 * (median_2 - median_1)], np.zeros(m - 1), [g0]])
    f = np.zeros(m + 1)
    f[-1] = preload_hat
    y, _, _ = _newton(a, np.column_stack([b, np.ones(n)]), c, g, f, start, law)
    return float(y[-1])


def loaded_contact_angle(
    approach: ArrayLike, contact_angle: float, curvature_distance: float
) -> NDArray[np.float64]:
    """Contact angle under load, cos β = A cos β₀ / (A + max(δ, 0)) (Harris & Kotzalas 2007).

    A = (f_s + f_N − 1) D_b is the distance of the two groove curvature centres.
    """
    a = positive("curvature_distance", curvature_distance, "m")
    d = np.maximum(np.asarray(approach, dtype=float), 0.0)
    return np.arccos(a * math.cos(contact_angle) / (a + d))


LIFT_OFF_SEARCH = 2.0**1.5 * 2.0**7
"""The lift-off search stops at this many times the preload (128 × the rigid nut's
2^1.5 F_p): a long nut's bars keep an external load from its far end and nut 2 (a 30-turn
nut's last ball there lifts off near 870 F_p, beyond any static load rating)."""


def lift_off_load(
    layout: BallLayout,
    hertz_constant: float,
    contact_angle: float,
    lead_angle: float,
    preload: float,
    bodies: NutBodies | None = None,
    rtol: float = 1e-6,
    contact: TabulatedContact | None = None,
    support: str = "guided",
    lead_error: ArrayLike | None = None,
    ball_excess: ArrayLike | None = None,
    radial_load: float = 0.0,
    tilting_moment: float = 0.0,
) -> float:
    """Axial load at which the last ball of nut 2 lifts off [N]; inf where nut 2 still
    carries at LIFT_OFF_SEARCH × F_p.

    The root of the largest approach of nut 2's balls, max_j δ_j(F_a) (positive while one of
    them carries, continuous across the lift-off), by Brent's method (``xtol`` = ``rtol`` ×
    the bracket's end) on a bracket doubled from 2^1.5 F_p, with the preload interference of
    F_a = 0 kept. Every other argument as in :func:`solve_distribution`, so the lift-off is
    that of the distribution the case solves (lead and ball-diameter errors, a free nut's
    external radial load and tilting moment). Each solve starts from the one before
    (``start`` of :func:`solve_distribution`).
    """
    if layout.nuts != 2:
        raise InputError("nuts", layout.nuts, "2 (lift-off of the second nut)")
    solve = partial(
        solve_distribution,
        layout,
        hertz_constant,
        contact_angle,
        lead_angle,
        preload=preload,
        bodies=bodies,
        lead_error=lead_error,
        ball_excess=ball_excess,
        contact=contact,
        support=support,
        radial_load=radial_load,
        tilting_moment=tilting_moment,
    )
    last = [solve(axial_load=0.0)]  # each solve starts from the one before (a long nut's)
    g = last[0].interference

    @cache
    def approach(fa: float) -> float:
        last[0] = dist = solve(axial_load=fa, interference=g, start=last[0])
        return float(dist.per_nut(dist.approach)[1].max())

    lo, hi = 0.0, 2.0**1.5 * preload
    while approach(hi) > 0.0:
        if hi >= LIFT_OFF_SEARCH * preload:
            return math.inf
        lo, hi = hi, 2.0 * hi
    return float(brentq(approach, lo, hi, xtol=rtol * hi, rtol=4.0 * np.finfo(float).eps))
