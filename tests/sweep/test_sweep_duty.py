"""The duty cycle is sweepable: its end-of-cycle numbers against a key of a [[duty]] segment."""

from __future__ import annotations

import numpy as np

from ballscrew.analyses.duty_thermal import duty_scalars
from ballscrew.case import load_case, with_overrides
from ballscrew.sweep import parse_axis, run_sweep
from quick_cases import QUICK, write_case

#: The example on the network model: 20 min of strokes at 2 kN, then 10 min at rest.
SHORT_DUTY = QUICK | {
    "thermal.model": "network",
    "thermal.transient.time_step": "300 s",
    "duty_repeat": 1,
    "duty": [
        {"speed": "1500 rpm", "axial_load": "2 kN", "stroke": "400 mm", "duration": "20 min"},
        {"speed": 0, "duration": "10 min"},
    ],
}


def test_a_faster_duty_segment_heats_and_stretches_the_screw_more(tmp_path):
    case = load_case(write_case(tmp_path, "gao2019_tcr.toml", SHORT_DUTY))
    axis = parse_axis("duty.0.speed=50,150")  # rad/s: 477 and 1432 rpm
    ds, computed = run_sweep(case, [axis], duty_scalars, "duty", tmp_path / "sweep", workers=1)
    assert computed == 2 and not ds["failed"].any()
    assert ds["peak_elongation"].attrs["units"] == "m"
    slow, fast = ds["peak_elongation"].values
    assert 0 < slow < fast  # more friction heat per second when faster (same load, stroke)
    assert np.all(ds["final_elongation"].values <= ds["peak_elongation"].values)
    assert np.all(ds["heat_balance_error"].values < 0.02)
    # a point of the sweep is the duty run of that case, as `ballscrew duty` would give it
    one = duty_scalars(with_overrides(case, {"duty.0.speed": 150.0}))
    assert one["peak_elongation"][0] == float(fast)
