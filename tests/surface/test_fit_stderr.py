"""The structure-function fit gives no standard errors, and says why (None with a reason, never
a silent NaN); the PSD fit gives them."""

from __future__ import annotations

import json
import math
from pathlib import Path

from ballscrew.analyses.surface import surface_characterisation
from ballscrew.surface.fit import SF_STDERR_REASON

EXAMPLE_PROFILE = (
    Path(__file__).resolve().parents[2] / "examples" / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
)


def test_the_structure_function_gives_none_with_its_reason_and_the_psd_numbers():
    result = surface_characterisation(EXAMPLE_PROFILE, gamma=1.6, resolution=1e-6)
    sf, psd = result.fit.structure_function, result.fit.psd
    assert sf.D_stderr is None and sf.lnG_stderr is None
    assert sf.stderr_reason == SF_STDERR_REASON and "correlated" in SF_STDERR_REASON
    assert sf.as_dict()["stderr_reason"] == SF_STDERR_REASON
    assert psd.stderr_reason is None and math.isfinite(psd.D_stderr) and psd.D_stderr > 0.0
    methods = json.loads(json.dumps(result.summary(), allow_nan=False))["methods"]
    assert methods["structure_function"]["D_standard_error"] is None
    assert methods["structure_function"]["standard_error_reason"] == SF_STDERR_REASON
    assert "standard_error_reason" not in methods["psd"]
