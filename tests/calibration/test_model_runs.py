"""One memo of model runs: each parameter set is simulated once, the count is the fit's
``evaluations``, and the fitted values and run counts are those of the two-cache fitter."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.calibration import fit_parameters, fit_wear_coefficient
from ballscrew.calibration.search import KLine, ModelRuns

from .multi_model import GRID, MEASURED_AT, START, MultiModel, history
from .test_subsets import noisy

# (fitted parameters) → (model runs, fitted values) of the fitter before the caches were
# merged (a K-line cache on top of the model cache), on the noisy synthetic torque history;
# the counts include one run per model parameter for the covariance's central differences
BEFORE = {
    ("wear_coefficient",): (11, {"wear_coefficient": 2.001592747269178e-4}),
    ("wear_coefficient", "torque_scale"): (
        12,
        {"wear_coefficient": 2.0024196939789375e-4, "torque_scale": 1.20093573070365},
    ),
    ("wear_coefficient", "film_factor", "torque_scale"): (
        34,
        {
            "wear_coefficient": 2.0144669841595588e-4,
            "film_factor": 0.49648568499627854,
            "torque_scale": 1.2014791374459257,
        },
    ),
    ("wear_coefficient", "running_in_depth"): (
        26,
        {"wear_coefficient": 2.0038351460419551e-4, "running_in_depth": 2.9872486174920855e-7},
    ),
}


class Recorder(MultiModel):
    """The synthetic model, recording the parameter sets it was run at."""

    def __init__(self) -> None:
        super().__init__()
        self.seen: list[tuple[tuple[str, float], ...]] = []

    def __call__(self, values):
        self.seen.append(tuple(sorted(values.items())))
        return super().__call__(values)


@pytest.mark.parametrize("names", list(BEFORE), ids=["+".join(n) for n in BEFORE])
def test_runs_and_values_as_before(names) -> None:
    runs, expected = BEFORE[names]
    start = {k: v for k, v in START.items() if k in names or k == "wear_coefficient"}
    model = Recorder()
    result = fit_parameters(model, noisy(names), names, start)
    assert model.runs == result.evaluations == runs
    assert len(set(model.seen)) == len(model.seen)  # no parameter set run twice
    for name, value in expected.items():
        assert result.values[name] == pytest.approx(value, rel=1e-9)


def test_k_only_fit_counts_the_same_runs() -> None:
    """:func:`fit_wear_coefficient` goes through the same memo: 11 runs, the same K."""
    model = Recorder()
    data = noisy(("wear_coefficient",))
    result = fit_wear_coefficient(lambda k: model({"wear_coefficient": k}), data)
    assert model.runs == result.evaluations == 11
    assert len(set(model.seen)) == len(model.seen)
    assert result.wear_coefficient == pytest.approx(2.0015925983675914e-4, rel=1e-9)


def test_k_line_reads_the_shared_memo() -> None:
    """Two K-lines at the same other values share every run; the memo counts each once."""
    model = Recorder()
    data = noisy(("wear_coefficient",))
    runs = ModelRuns(model, data, 5, "test")
    a, b = KLine(runs, START, False), KLine(runs, {**START, "wear_coefficient": 1.0}, False)
    first = a.rms_at(-9.0)
    assert b.rms_at(-9.0) == first and model.runs == runs.evaluations == 1
    expected = history({**START, "wear_coefficient": 1.2340980408667956e-4}, GRID)
    at_data = np.interp(MEASURED_AT, GRID, expected.friction_torque)
    np.testing.assert_allclose(a.at_data(-9.0), at_data, rtol=1e-12)
