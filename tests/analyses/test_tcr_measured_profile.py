"""A measured profile's D and G flow into every TCR model with one convention (theory manual,
*Roughness conventions*): the fractal models read them as the Majumdar–Bhushan profile's, the
correlations as (σ, m) of that profile over [``tcr.cutoff_length``, ``tcr.sampling_length``]."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.tcr_models import gaussian_joint
from ballscrew.contact_resistance.correlations import fractal_roughness
from ballscrew.surface import fractal_parameters, read_profile

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
PROFILE = EXAMPLES / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"


def _run(case_path, D: float, G: float, band: tuple[float, float]) -> ballscrew.ScrewTCR:
    overrides = {
        "surface.D": D,
        "surface.G": G,
        "tcr.cutoff_length": band[0],
        "tcr.sampling_length": band[1],
        "numerics.cells_across": 16,
    }
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ballscrew.screw_tcr(ballscrew.load_case(case_path, overrides))


def test_a_measured_profile_feeds_every_model(gao_case_path):
    """The fitted D, G of the example profile (2 mm at 0.5 µm): the correlations' σ and m are
    the profile's own within 25 % over its band (the W–M sum is discrete in frequency), and
    every model's R″ rises when G doubles, so each of them reads the measured surface."""
    profile = read_profile(PROFILE)
    fit = fractal_parameters(profile)
    assert fit.D == pytest.approx(1.59, abs=0.01) and fit.G == pytest.approx(9e-10, rel=0.05)
    heights = np.atleast_2d(np.asarray(profile.heights))
    band = (2.0 * profile.spacing, heights.shape[1] * profile.spacing)
    own_sigma = float(np.sqrt(np.mean(np.var(heights, axis=1))))
    own_slope = float(np.sqrt(np.mean(np.diff(heights, axis=1) ** 2)) / profile.spacing)

    result = _run(gao_case_path, fit.D, fit.G, band)
    params = ScrewParameters.from_case(result.case)
    for side in ("screw", "nut"):
        joint = gaussian_joint(params, result.case.tcr, side)
        assert (joint.sigma, joint.slope) == fractal_roughness(fit.D, fit.G, band[1], band[0])
        assert joint.sigma == pytest.approx(own_sigma, rel=0.25)
        assert joint.slope == pytest.approx(own_slope, rel=0.25)
    rougher = _run(gao_case_path, fit.D, 2.0 * fit.G, band)
    assert set(rougher.models) == set(result.models) and len(result.models) == 8
    for name, model in result.models.items():
        assert rougher.models[name].resistance_per_area > model.resistance_per_area, name
