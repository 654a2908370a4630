"""Double-nut load split: lift-off of the unloaded nut against the makers' formula."""

from __future__ import annotations

import ballscrew


def _lift_off_load(preload: float) -> float:
    """Smallest axial load at which ``nut_forces`` unloads nut 2 (bisection on F_2 > 0), N."""
    low, high = 0.0, 10.0 * preload
    for _ in range(200):
        mid = 0.5 * (low + high)
        if ballscrew.nut_forces(preload, mid).f2 > 0.0:
            low = mid
        else:
            high = mid
        if high - low <= 1e-12 * preload:
            break
    return high


def test_hiwin_lift_off_load(validation, dataset) -> None:
    data = dataset("nut_forces", "hiwin_lift_off")
    preload = 1500.0
    validation.check(
        "hiwin_lift_off_load",
        kind="verification",
        model="nut_forces (Hertz double nut)",
        source="HIWIN BS-08-2-EN-1704-K (2017), §3.7 F 3.6",
        reference=data,
        quantity="lift-off load of the unloaded nut / preload",
        unit="-",
        measured=data["lift_off_over_preload"],
        predicted=_lift_off_load(preload) / preload,
        tolerance=1e-6,
        relative=True,
        tolerance_basis="both are the same closed form F_lim = 2^(3/2) F_p; the tolerance is the "
        "root-finding accuracy of nut_forces and of the bisection",
        assumptions=(
            "preload 1500 N (any preload: the ratio is independent of it)",
            "lift-off = the smallest external load at which nut_forces returns F_2 = 0",
        ),
    )
