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
  697 → 716 → 714.7 → 714.8 N). The grid's
  discretisation of the approach cancels in the difference; a worn contact that reaches the
  edge of the fixed grid warns (:class:`~ballscrew.wear.step.GridEdgeWarning`). The nut contact
  and the bodies stay as in (E1.13).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

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
    tolerance = TOLERANCE * setup.initial_preload
    force = min(max(previous, floor), setup.initial_preload)
    pressures = None
    residual = float("inf")
    for iteration in range(1, MAX_ITERATIONS + 1):
        # the worn contact took the whole interference; G(0+) = 0 is ASSUMED (so where G rises
        # with F; a bridged groove whose G fell to 0 at a larger F could keep a root above 0)
        if force <= 0.0:
            return 0.0, 2 * (iteration - 1)
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
        warn_at_grid_edge(np.asarray(worn.pressure), q, "the worn contact of the preload update")
        pressures = np.stack([worn.pressure, unworn.pressure])
        updated = setup.preload(min(max(worn.approach - unworn.approach, 0.0), h_max))
        residual = abs(updated - force)
        force = updated
        if residual <= tolerance:
            return force, 2 * iteration
    raise ConvergenceError(
        "worn-groove preload update (wear.preload_contact = 'worn')",
        MAX_ITERATIONS,
        residual / setup.initial_preload,
        TOLERANCE,
        f"|G(F_p) − F_p| = {residual:.3g} N at F_p = {force:.6g} N, h_max = {h_max:.3g} m",
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
