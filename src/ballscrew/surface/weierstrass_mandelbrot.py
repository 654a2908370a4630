"""Synthetic Weierstrass–Mandelbrot (W–M) profiles for tests and demonstrations, equation (F1).

    (F1) z(x) = G^(D−1) Σ_{n = n₁}^{n_max} cos(2π γⁿ x + φ_n) / γ^((2−D) n)

Each term is a cosine of frequency γⁿ (cycles/m) with a random phase φ_n ~ U(0, 2π) drawn from
``np.random.default_rng(seed)``; the phases make the profile one realisation of a random process
and leave its power spectrum (F2) and structure function (F4) unchanged. n₁ comes from the
sampling length L (γ^(n₁) ≥ 1/L, the first frequency a record of length L resolves), n_max
from the Nyquist limit (γ^(n_max) < 1/(2Δx)), so the profile holds exactly the band a
measurement with this length and spacing would see.

Sources: Berry, M. V. & Lewis, Z. V. (1980), Proc. R. Soc. Lond. A 370:459 (the W–M function);
Majumdar, A. & Bhushan, B. (1990), J. Tribol. 112:205 and Majumdar, A. & Tien, C. L. (1990),
"Fractal characterization and simulation of rough surfaces", Wear 136:313–327 (F1)–(F4). Theory
manual: ``docs/theory/surface.md``. ``D`` is the profile dimension 1 < D < 2, ``G`` in m.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ballscrew.errors import InputError
from ballscrew.fractal.domain_extension import validate_dimension
from ballscrew.surface.profile import MIN_POINTS, Profile, check_spacing
from ballscrew.validation import positive

__all__ = [
    "MAX_GAMMA",
    "MIN_GAMMA",
    "check_gamma",
    "weierstrass_mandelbrot_profile",
    "wm_frequency_indices",
]

#: x-block size of the vectorised sum (bounds the memory of the cos/sin matrices).
_BLOCK = 1 << 15


#: Smallest W–M frequency ratio γ accepted. The line count of (F1), ln(ω_max/ω_min)/ln γ, and
#: the ln ω sub-bins of the spectral fits (ln γ/16 wide) grow as 1/ln γ: at γ = 1.01 a profile
#: of 10⁷ points has about 26 000 sub-bins; at γ = 1 + 10⁻⁷ it needed 9 GB.
MIN_GAMMA = 1.01

#: Largest W–M frequency ratio γ accepted. (F1) stands for a continuous spectrum only while its
#: lines are dense on a log scale: γ = 1.5 (Majumdar & Tien, 1990) puts about 17 lines in the
#: three decades a typical profile spans; at γ = 10 there are three, one per decade, and the
#: ln γ-wide smoothing of the fits covers a third of the band. Beyond it no line need fall inside
#: the measured band and D and G lose their meaning.
MAX_GAMMA = 10.0


def check_gamma(gamma: float) -> float:
    """Return the W–M frequency ratio γ as a float after checking
    :data:`MIN_GAMMA` ≤ γ ≤ :data:`MAX_GAMMA`."""
    allowed = f"W-M frequency ratio {MIN_GAMMA:g} ≤ γ ≤ {MAX_GAMMA:g} (usually 1.5)"
    try:
        value = float(gamma)
    except (TypeError, ValueError):
        raise InputError("gamma", gamma, allowed) from None
    if not (math.isfinite(value) and MIN_GAMMA <= value <= MAX_GAMMA):
        raise InputError("gamma", gamma, allowed)
    return value


def wm_frequency_indices(
    length: float,
    spacing: float,
    *,
    gamma: float = 1.5,
    frequency_min: float | None = None,
    frequency_max: float | None = None,
) -> NDArray[np.int64]:
    """Frequency indices n = n₁ … n_max of (F1) for a record of ``length`` sampled at ``spacing``.

    n₁ is the smallest n with γⁿ ≥ ``frequency_min`` (default 1/L) and n_max the largest with
    γⁿ < ``frequency_max`` (default the Nyquist frequency 1/(2Δx)); frequencies in cycles/m.
    """
    g = check_gamma(gamma)
    L = positive("length", length)
    dx = check_spacing(spacing)
    f_lo = 1.0 / L if frequency_min is None else positive("frequency_min", frequency_min)
    f_hi = 0.5 / dx if frequency_max is None else positive("frequency_max", frequency_max)
    ln_g = math.log(g)
    n1 = math.ceil(math.log(f_lo) / ln_g - 1e-9)
    n_max = math.ceil(math.log(f_hi) / ln_g - 1e-9) - 1
    if n_max < n1:
        raise InputError(
            "frequency band",
            (f_lo, f_hi),
            f"a band [f_min, f_max) that holds at least one frequency γⁿ (γ = {g})",
        )
    return np.arange(n1, n_max + 1, dtype=np.int64)


def weierstrass_mandelbrot_profile(
    D: float,
    G: float,
    length: float,
    spacing: float,
    *,
    gamma: float = 1.5,
    seed: int | np.random.Generator | None = None,
    profiles: int = 1,
    frequency_min: float | None = None,
    frequency_max: float | None = None,
) -> Profile:
    """One (or ``profiles`` independent) realisations of the W–M profile (F1), m.

    Args:
        D: profile fractal dimension, 1 < D < 2.
        G: fractal roughness, m.
        length: sampling length L, m; the profile has round(L/Δx) points at x = 0, Δx, ….
        spacing: sampling interval Δx, m.
        gamma: frequency ratio γ > 1 (1.5 in MB 1990).
        seed: seed of ``np.random.default_rng`` (or a Generator) for the phases φ_n.
        profiles: number of rows; each row gets its own phases (an areal-like stack of
            independent profiles, for testing row averaging).
        frequency_min, frequency_max: band of the sum in cycles/m (default 1/L and the
            Nyquist frequency 1/(2Δx)).

    Returns:
        A :class:`Profile` (1-D heights for ``profiles == 1``, else rows) whose metadata holds
        D, G, γ, the indices n₁, n_max and the seed.
    """
    d = validate_dimension(D)
    g_rough = positive("G", G)
    g = check_gamma(gamma)
    L = positive("length", length)
    dx = check_spacing(spacing)
    if isinstance(profiles, bool) or int(profiles) != profiles or profiles < 1:
        raise InputError("profiles", profiles, "an integer >= 1")
    n_pts = round(L / dx)
    if n_pts < MIN_POINTS:
        raise InputError("length", length, f"at least {MIN_POINTS} sampling intervals long")
    n = wm_frequency_indices(
        n_pts * dx, dx, gamma=g, frequency_min=frequency_min, frequency_max=frequency_max
    )
    rng = _generator(seed)
    phase = rng.uniform(0.0, 2.0 * math.pi, size=(int(profiles), n.size))
    freq = g ** n.astype(np.float64)
    amplitude = g_rough ** (d - 1.0) * g ** (-(2.0 - d) * n.astype(np.float64))
    # z = Re Σ_n A_n e^{iφ_n} e^{2πi γⁿ x}. Within a block x = x₀ + mΔx, so the factor
    # e^{2πi γⁿ mΔx} is computed once and each block is one complex matrix product.
    coeff = amplitude * np.exp(1j * phase)
    block = min(_BLOCK, n_pts)
    offset = np.exp(2j * math.pi * np.mod(np.outer(freq, np.arange(block) * dx), 1.0))
    z = np.empty((int(profiles), n_pts))
    for start in range(0, n_pts, block):
        size = min(block, n_pts - start)
        shift = np.exp(2j * math.pi * np.mod(freq * (start * dx), 1.0))
        z[:, start : start + size] = ((coeff * shift) @ offset[:, :size]).real
    metadata = {
        "generator": "Weierstrass-Mandelbrot (F1)",
        "D": d,
        "G": g_rough,
        "gamma": g,
        "n1": int(n[0]),
        "n_max": int(n[-1]),
        "frequency_min": float(freq[0]),
        "frequency_max": float(freq[-1]),
        "seed": seed if isinstance(seed, int) else None,
    }
    heights = z[0] if profiles == 1 else z
    return Profile(heights, dx, None, metadata, "synthetic")


def _generator(seed: int | np.random.Generator | None) -> np.random.Generator:
    """``seed`` itself if a Generator, else ``np.random.default_rng(seed)``."""
    if isinstance(seed, np.random.Generator):
        return seed
    if isinstance(seed, bool | float | str | bytes):
        raise InputError("seed", seed, "an integer >= 0, a numpy Generator or None")
    try:
        return np.random.default_rng(seed)
    except (TypeError, ValueError):
        raise InputError("seed", seed, "an integer >= 0, a numpy Generator or None") from None
