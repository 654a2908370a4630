"""Benchmark of the normal-contact solvers on smooth and rough gaps: iterations and wall time.

Gaps: screw contact A of the reference screw at F_a = 3 kN (curvatures 354.5 and 12.11 1/m,
Q = 85.9 N, E* = 113.19 GPa) on N × N cells over 3a × 3b, smooth, plus the example's measured
W-M profile (Rq 0.37 µm) across the rolling direction, or plus uncorrelated Gaussian heights of
Rq 0.05, 0.2 and 0.5 µm (seeds 0, 1, 2). For each: ``pcg`` (default) and ``pk`` iterations (pcg:
fine + coarse in fine-grid equivalents), the final Σ|Δp|/Σp when not converged within
``--max-iterations``, and the median wall time of ``--repeats`` solves after a warm-up.

Usage: python benchmarks/bench_rough_contact.py [--repeats 5] [--max-iterations 400]
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np

from ballscrew.contact import cell_centres, hertz, solve_normal
from ballscrew.surface import read_profile

PROFILE = Path(__file__).resolve().parents[1] / "examples/profiles/synthetic_wm_D1.59_G9e-10.sdf"
RX, RY, E_STAR, LOAD = 1 / 354.5, 1 / 12.11, 113.19e9, 85.9


def gap(n: int, roughness: str) -> tuple[np.ndarray, float, float]:
    """Contact A on n × n cells with ``roughness`` "smooth", "profile" or "Rq=<µm>:<seed>"."""
    reference = hertz(RX, RY, E_STAR, LOAD)
    dx, dy = 3 * reference.a / n, 3 * reference.b / n
    x, y = cell_centres(n, dx), cell_centres(n, dy)
    h = x[:, None] ** 2 / (2 * RX) + y[None, :] ** 2 / (2 * RY)
    if roughness == "profile":
        profile = read_profile(PROFILE)
        z = np.asarray(profile.heights).ravel()
        h = h + np.interp(x - x[0], np.arange(z.size) * profile.spacing, z)[:, None]
    elif roughness.startswith("Rq="):
        rq, seed = roughness[3:].split(":")
        h = h + float(rq) * 1e-6 * np.random.default_rng(int(seed)).standard_normal(h.shape)
    return h - h.min(), dx, dy


def run(h: np.ndarray, dx: float, dy: float, method: str, repeats: int, limit: int) -> str:
    """``iterations [residual] median-time`` of one solver on one gap."""

    def solve():
        return solve_normal(
            h, dx, dy, E_STAR, LOAD, method=method, max_iterations=limit, raise_on_failure=False
        )

    result = solve()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        solve()
        times.append(time.perf_counter() - start)
    work = result.iterations + result.coarse_work
    state = "" if result.converged else f" (res {result.residual:.2g})"
    return f"{work:7.2f}{state:>12} {1e3 * statistics.median(times):9.1f} ms"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--max-iterations", type=int, default=400)
    args = parser.parse_args()
    cases = [(64, "smooth"), (256, "smooth"), (64, "profile"), (128, "profile")]
    cases += [(64, "Rq=0.05:0"), (64, "Rq=0.2:1"), (128, "Rq=0.5:2")]
    print(
        f"{'gap':>18} {'pcg it':>7} {'':12} {'pcg time':>12} | {'pk it':>7} {'':12} {'pk time':>12}"
    )
    for n, roughness in cases:
        h, dx, dy = gap(n, roughness)
        pcg = run(h, dx, dy, "pcg", args.repeats, args.max_iterations)
        pk = run(h, dx, dy, "pk", args.repeats, args.max_iterations)
        print(f"{f'{n}² {roughness}':>18} {pcg} | {pk}")


if __name__ == "__main__":
    main()
