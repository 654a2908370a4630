"""Preload left after wear: which contact the preload update sees (``wear.preload_contact``).

The preload loop of each nut at F_a = 0 holds its interference (E1.13): the approach of the
ball's contacts plus the elastic bodies. Wear of depth h(y) on the screw flank shortens it.

* ``"hertz"`` (default): the worn flank is the unworn Hertz contact pushed back by its largest
  depth, C_a F^(2/3) + c_b F = C_a F_p0^(2/3) + c_b F_p0 − h_max/(sinβ cosλ) (E1.13).
* ``"worn"``: the screw contact is that of the worn, more conforming groove. Its approach at the
  ball load Q, measured from the unworn raceway, is the Polonsky–Keer solution on the worn gap
  g_0 + h(y) (E8.5); the depth the preload loop loses is the difference of the approaches on the
  worn and the unworn gap at the same Q on the same grid,

      h_eff(Q) = δ_worn(Q) − δ_unworn(Q)   (h_eff = h for a uniform depth h; < h_max in a
                                            conforming groove, whose contact is wider),

  and F_p' is the root of F = G(F) = F_p(E1.13 with h_eff(Q(F)) for h_max), Q = F/(Z sinβ cosλ)
  (E1.6). The fixed-point iteration F ← G(F) starts from the preload before the step (or
  F_p0), stops when |G(F) − F| ≤ 1e-6 F_p0 and raises
  :class:`~ballscrew.errors.ConvergenceError` with that residual after 40 iterations. It
  contracts, |G'| ≈ 0.02–0.15 on the step-stress screw, so the value returned lies within
  |G'|/(1 − |G'|) of that residual from the root. Where the groove is shallower than the
  ball's conformity G rises with F (the wider contact of a larger load loses less) and the
  iterates fall monotonically to the root; where the ball bridges a deep, narrow groove on its
  shoulders G falls with F and they alternate about it (4 µm worn over half the grid:
  697 → 716 → 714.7 → 714.8 N). An iterate whose worn contact takes the whole interference
  (G(F_k) = 0) gives 0 N only when G(ε) ≤ ε at ε = 1e-6 F_p0: a bridged groove has G(0+) > 0
  (≈ 798 N for the one above), and G(ε) > ε brackets a root in (ε, F_k], solved by Brent's
  method to the same tolerance. The grid's discretisation of the approach cancels in the
  difference; a worn contact that reaches the edge of the fixed grid warns once per update, at
  the Q of the largest pressure on the grid's rim (:class:`~ballscrew.wear.step.GridEdgeWarning`).
  The nut contact and the bodies stay as in (E1.13).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from scipy.optimize import brentq

from ballscrew.contact import solve_normal_batch
from ballscrew.errors import ConvergenceError
from ballscrew.registry import Registry
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.setup import FLANKS, FloatArray, WearSetup
from ballscrew.wear.step import warn_at_grid_edge

__all__ = ["PRELOAD_CONTACTS", "preload_after"]

PreloadContact = Callable[[WearSetup, FloatArray, float], tuple[float, int]]

PRELOAD_CONTACTS: Registry[PreloadContact] = Registry(
    "screw contact of the preload update", "wear.preload_contact"
)
"""How the worn screw flank enters the preload law (E1.13): (setup, depth (2, ny), preload before
these depths [N]) → (F_p [N], contact solves made)."""

TOLERANCE = 1e-6
"""|G(F_p) − F_p| of the worn-contact preload at convergence, relative to F_p0."""
MAX_ITERATIONS = 40
"""Fixed-point iterations of the worn-contact preload before a ``ConvergenceError``."""


@PRELOAD_CONTACTS.register(
    "hertz", "unworn Hertz contact pushed back by the largest depth (E1.13; contact-only groove)"
)
def hertz_preload(setup: WearSetup, depth: FloatArray, previous: float) -> tuple[float, int]:
    """F_p of (E1.13) with the largest depth h_max of either flank; no contact solve."""
    return setup.preload(float(depth.max())), 0


@PRELOAD_CONTACTS.register(
    "worn", "the worn groove's own contact: h_eff = δ_worn(Q) − δ_unworn(Q) for h_max in (E1.13)"
)
def worn_preload(setup: WearSetup, depth: FloatArray, previous: float) -> tuple[float, int]:
    """F_p of (E1.13) with the effective depth of the deeper flank's worn contact: the root of
    F = G(F) by the fixed point from ``previous`` (module doc)."""
    h_max = float(depth.max())
    floor = setup.preload(h_max)  # h_eff ≤ h_max: G(F) ≥ F_p(h_max) for every F
    if h_max <= 0.0:
        return floor, 0
    k = int(np.argmax(depth.max(axis=1)))
    nominal = setup.nominal_gap[FLANKS[k]]
    gaps = np.stack([worn_gap(nominal, depth[k]), nominal])
    pressures = None
    edge: tuple[float, FloatArray, float] | None = None  # largest rim pressure, p, Q

    def balance(force: float) -> float:
        """G(F): F_p of (E1.13) with h_eff(Q(F)) for h_max."""
        nonlocal pressures, edge
        q = setup.ball_load(force)
        worn, unworn = solve_normal_batch(
            gaps,
            setup.dx,
            setup.dy,
            setup.e_star,
            np.array([q, q]),
            setup.tolerance,
            max_iterations=setup.max_iterations,
            initial=pressures,
        )
        p = np.asarray(worn.pressure)
        rim = float(max(p[[0, -1], :].max(), p[:, [0, -1]].max()))
        if rim > 0.0 and (edge is None or rim > edge[0]):
            edge = (rim, p, q)
        pressures = np.stack([worn.pressure, unworn.pressure])
        return setup.preload(min(max(worn.approach - unworn.approach, 0.0), h_max))

    start = min(max(previous, floor), setup.initial_preload)
    detail = f"h_max = {h_max:.3g} m"
    try:
        force, evaluations = _preload_root(balance, start, setup.initial_preload, detail)
    finally:  # one warning per update, at the Q of the largest pressure on the grid's rim
        if edge is not None:
            warn_at_grid_edge(edge[1], edge[2], "the worn contact of the preload update")
    return force, 2 * evaluations


def _preload_root(
    balance: Callable[[float], float], start: float, scale: float, detail: str
) -> tuple[float, int]:
    """Root of F = G(F) (``balance``: G) by the fixed point from ``start`` to TOLERANCE·``scale``,
    and the evaluations of G made.

    Where the iterate F_k reaches G(F_k) = 0 (the worn contact took the whole interference),
    0 N is returned only when G(ε) ≤ ε at ε = TOLERANCE·``scale``: a groove the ball bridges on
    its shoulders has G(0+) > 0, and G(ε) > ε with G(F_k) − F_k < 0 brackets a root in
    (ε, F_k], found by :func:`scipy.optimize.brentq` to the same tolerance.
    """
    tolerance = TOLERANCE * scale
    evaluations = 0

    def g(force: float) -> float:
        nonlocal evaluations
        evaluations += 1
        return balance(force)

    force = start
    residual = float("inf")
    for _ in range(MAX_ITERATIONS):
        if force <= 0.0:
            return 0.0, evaluations
        updated = g(force)
        if updated <= 0.0 < force - tolerance and g(tolerance) > tolerance:
            root = brentq(lambda f: g(f) - f, tolerance, force, xtol=tolerance)
            return float(root), evaluations
        residual = abs(updated - force)
        force = updated
        if residual <= tolerance:
            return force, evaluations
    raise ConvergenceError(
        "worn-groove preload update (wear.preload_contact = 'worn')",
        MAX_ITERATIONS,
        residual / scale,
        TOLERANCE,
        f"|G(F_p) − F_p| = {residual:.3g} N at F_p = {force:.6g} N, {detail}",
    )


def preload_after(
    setup: WearSetup, depth: FloatArray, previous: float | None = None
) -> tuple[float, int]:
    """F_p after the worn depths ``depth`` (2, ny) of both flanks, by ``wear.preload_contact``
    (:data:`PRELOAD_CONTACTS`), and the contact solves it made; ``previous``: the preload before
    these depths grew (None: the initial preload F_p0), where the worn contact's iteration
    starts."""
    start = setup.initial_preload if previous is None else previous
    return PRELOAD_CONTACTS[setup.spec.preload_contact](setup, depth, start)
