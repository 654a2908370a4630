"""Surface characterisation: fractal D and G of measured profiles, readers, synthetic W–M profiles.

* :func:`fractal_parameters` — D and G by the power spectrum (F2) and the structure function
  (F4), both reported with their fit ranges; :class:`FractalFit`, :class:`SurfaceFit`.
* :func:`read_profile` — CSV/text profiles and ISO 25178-71 / BCR SDF files (WYKO/Veeco Vision,
  Zygo, MountainsMap exports) into a :class:`Profile` (heights and spacing in m).
* :func:`weierstrass_mandelbrot_profile` — synthetic W–M profiles (F1) for tests.

The profile dimension 1 < D < 2 and G in m are those of the theory manual,
``docs/theory/surface.md`` (the 3-D surface dimension is Ds = D + 1). Sources: Majumdar & Bhushan
(1990), J. Tribol. 112:205; Majumdar & Tien (1990), "Fractal characterization and simulation of
rough surfaces", Wear 136:313–327; Berry & Lewis (1980), Proc. R. Soc. Lond. A 370:459; ISO
25178-71:2017.
"""

from ballscrew.surface.fit import (
    FractalFit,
    SurfaceFit,
    fit_power_spectrum,
    fit_structure_function,
    fractal_parameters,
)
from ballscrew.surface.io import (
    read_profile,
    read_sdf,
    read_text_profile,
    write_sdf,
    write_text_profile,
)
from ballscrew.surface.profile import Profile
from ballscrew.surface.spectral import log_smoothed_spectrum, power_spectrum, wm_power_spectrum
from ballscrew.surface.structure_function import (
    band_limited_ratio,
    structure_function,
    structure_function_constant,
    wm_structure_function,
)
from ballscrew.surface.weierstrass_mandelbrot import (
    weierstrass_mandelbrot_profile,
    wm_frequency_indices,
)

__all__ = [
    "FractalFit",
    "Profile",
    "SurfaceFit",
    "band_limited_ratio",
    "fit_power_spectrum",
    "fit_structure_function",
    "fractal_parameters",
    "log_smoothed_spectrum",
    "power_spectrum",
    "read_profile",
    "read_sdf",
    "read_text_profile",
    "structure_function",
    "structure_function_constant",
    "weierstrass_mandelbrot_profile",
    "wm_frequency_indices",
    "wm_power_spectrum",
    "wm_structure_function",
    "write_sdf",
    "write_text_profile",
]
