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

  and F_p' solves (E1.13) with h_eff(Q(F_p')) for h_max (fixed point, Q = F_p'/(Z sinβ cosλ),
  (E1.6)). The grid's discretisation of the approach cancels in the difference. The nut
  contact and the bodies stay as in (E1.13).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ballscrew.contact import solve_normal_batch
from ballscrew.registry import Registry
from ballscrew.wear.profile import worn_gap
from ballscrew.wear.setup import FLANKS, FloatArray, WearSetup

__all__ = ["PRELOAD_CONTACTS", "preload_after"]

PreloadContact = Callable[[WearSetup, FloatArray], tuple[float, int]]

PRELOAD_CONTACTS: Registry[PreloadContact] = Registry(
    "screw contact of the preload update", "wear.preload_contact"
)
"""How the worn screw flank enters the preload law (E1.13): (setup, depth (2, ny)) → (F_p [N],
contact solves made)."""

_ITERATIONS = 4
_RELATIVE = 1e-4


@PRELOAD_CONTACTS.register(
    "hertz", "unworn Hertz contact pushed back by the largest depth (E1.13; contact-only groove)"
)
def hertz_preload(setup: WearSetup, depth: FloatArray) -> tuple[float, int]:
    """F_p of (E1.13) with the largest depth h_max of either flank; no contact solve."""
    return setup.preload(float(depth.max())), 0


@PRELOAD_CONTACTS.register(
    "worn", "the worn groove's own contact: h_eff = δ_worn(Q) − δ_unworn(Q) for h_max in (E1.13)"
)
def worn_preload(setup: WearSetup, depth: FloatArray) -> tuple[float, int]:
    """F_p of (E1.13) with the effective depth of the deeper flank's worn contact (module doc)."""
    h_max = float(depth.max())
    preload = setup.preload(h_max)
    if h_max <= 0.0:
        return preload, 0
    k = int(np.argmax(depth.max(axis=1)))
    nominal = setup.nominal_gap[FLANKS[k]]
    gaps = np.stack([worn_gap(nominal, depth[k]), nominal])
    solves = 0
    for _ in range(_ITERATIONS):
        if preload <= 0.0:
            break
        q = setup.ball_load(preload)
        worn, unworn = solve_normal_batch(
            gaps,
            setup.dx,
            setup.dy,
            setup.e_star,
            np.array([q, q]),
            setup.tolerance,
            max_iterations=setup.max_iterations,
        )
        solves += 2
        effective = min(max(worn.approach - unworn.approach, 0.0), h_max)
        updated = setup.preload(effective)
        done = abs(updated - preload) <= _RELATIVE * max(preload, 1.0)
        preload = updated
        if done:
            break
    return preload, solves


def preload_after(setup: WearSetup, depth: FloatArray) -> tuple[float, int]:
    """F_p after the worn depths ``depth`` (2, ny) of both flanks, by ``wear.preload_contact``
    (:data:`PRELOAD_CONTACTS`), and the contact solves it made."""
    return PRELOAD_CONTACTS[setup.spec.preload_contact](setup, depth)
