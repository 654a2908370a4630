"""Benchmark of the thermal models on a reference screw.

Reference problem: steel shaft Ø40 × 1000 mm, nut ring Ø40/Ø70 × 100 mm at z = 450–550 mm,
k = 45 W/(m K), ρ = 7850 kg/m³, c_p = 460 J/(kg K), h = 20 W/(m² K) on every outer face,
interface R″ = 5e-4 m² K/W, 30 W at the interface split 50/50; steady state and a 90-step
implicit-Euler transient (Δt = 60 s) from ambient. Reference values: 2-D axisymmetric P2 (1 mm,
scikit-fem 12.0.2) 45.169 °C / 104.68 µm; 1-D network (5 mm) 45.221 °C / 104.62 µm.

Tables: (1) axisymmetric FE: unknowns, assembly, steady solve, 90-step transient [s] (best of
``repeats``); (2) the 1-D network and a 1000-point sweep of it (steady, and steady + 90-step
transient per point); (3) ``thermal_field`` end to end on examples/gao2019_tcr.toml, each model
(one FE mesh and assembly for the coupled fixed point and the transient); (4) the
3-D hexahedral model, balls smeared over the bore and as 30 helical patches.

Usage: python benchmarks/bench_thermal.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

import ballscrew as bs
from ballscrew.thermal.axisymmetric import build_axisymmetric
from ballscrew.thermal.network import build_network
from ballscrew.thermal.problem import Convection, RingPart, Solid, ThermalProblem
from ballscrew.thermal.simulate import simulate
from ballscrew.thermal.threed import BallPatches, build_threed

STEEL = Solid(45.0, 7850.0, 460.0)
REPORT = {"axisymmetric": (45.169, 104.68), "network": (45.221, 104.62)}


def reference(r_pp: float = 5e-4, h: float = 20.0, heat: float = 30.0) -> ThermalProblem:
    """The reference test problem of this benchmark."""
    nut = RingPart("nut", 0.1, 0.035, True, 2 * math.pi * 0.02 * 0.1 / r_pp, heat / 2, heat / 2)
    return ThermalProblem(
        0.02, 1.0, STEEL, STEEL, (nut,), 0.5, Convection(h, h, h, h), expansion=11.5e-6
    )


def best(func: Callable[[], object], repeats: int) -> tuple[float, object]:
    """Best wall time of ``repeats`` calls [s] and the last result."""
    times, out = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        out = func()
        times.append(time.perf_counter() - start)
    return min(times), out


def fe_table(repeats: int, quick: bool) -> None:
    print("\n(1) Axisymmetric FE (scikit-fem, quadrilaterals), reference screw")
    print(
        f"{'mesh':>12} {'unknowns':>9} {'assembly s':>11} {'steady s':>9} {'90 steps s':>11} "
        f"{'T_max °C':>9} {'ΔL µm':>8}"
    )
    meshes = [(2, 0.004), (2, 0.002)] if quick else [(1, 0.002), (2, 0.004), (2, 0.002), (2, 0.001)]
    problem = reference()
    for order, size in meshes:
        t_build, disc = best(lambda o=order, s=size: build_axisymmetric(problem, s, o), repeats)
        simulate(disc, 5400.0, 60.0)  # warm-up
        runs = [simulate(disc, 5400.0, 60.0) for _ in range(repeats)]
        sol = runs[-1]
        t_asm = t_build + min(r.seconds["assembly"] for r in runs)
        t_steady = min(r.seconds["steady"] for r in runs)
        t_transient = min(r.seconds["transient"] for r in runs)
        print(
            f"{f'Q{order} {size * 1e3:g} mm':>12} {disc.unknowns:>9d} {t_asm:>11.3f} "
            f"{t_steady:>9.3f} {t_transient:>11.3f} "
            f"{20 + sol.max_temperature_rise:>9.3f} {sol.elongation * 1e6:>8.2f}"
        )
    t, v = REPORT["axisymmetric"]
    print(f"{'report':>12} {'':>9} {'':>11} {'':>9} {'':>11} {t:>9.3f} {v:>8.2f}")


def network_table(repeats: int, points: int) -> None:
    print("\n(2) 1-D axial network, reference screw")
    problem = reference()
    disc = build_network(problem, 0.005)
    t_build, _ = best(lambda: build_network(problem, 0.005), repeats)
    t_steady, sol = best(lambda: simulate(disc, None), repeats)
    t_full, _ = best(lambda: simulate(disc, 5400.0, 60.0), repeats)
    print(
        f"  5 mm cells: {disc.unknowns} unknowns, build {t_build * 1e3:.2f} ms, steady "
        f"{t_steady * 1e3:.2f} ms, steady + 90 steps {t_full * 1e3:.2f} ms; "
        f"T_max {20 + sol.max_temperature_rise:.3f} °C, ΔL {sol.elongation * 1e6:.2f} µm "
        f"(report {REPORT['network'][0]} °C, {REPORT['network'][1]} µm)"
    )
    rng = np.random.default_rng(4)
    samples = np.column_stack(
        [rng.uniform(1e-5, 1e-3, points), rng.uniform(5, 60, points), rng.uniform(5, 80, points)]
    )
    for label, duration in (("steady", None), ("steady + 90-step transient", 5400.0)):
        start = time.perf_counter()
        rises = [
            simulate(build_network(reference(*p), 0.005), duration, 60.0).max_temperature_rise
            for p in samples
        ]
        elapsed = time.perf_counter() - start
        print(
            f"  sweep of {points} points (R″, h, Q random; build + {label}): {elapsed:.2f} s "
            f"({elapsed / points * 1e3:.2f} ms/point; max rise {min(rises):.1f}–"
            f"{max(rises):.1f} K)"
        )


def case_table(quick: bool) -> None:
    print("\n(3) thermal_field(case) end to end, examples/gao2019_tcr.toml (TCR cached)")
    path = Path(__file__).resolve().parents[1] / "examples" / "gao2019_tcr.toml"
    case = bs.load_case(path)
    tcr = bs.screw_tcr(case, variant=None)
    for model in ("network", "axisymmetric", "3d"):
        r = bs.thermal_field(case, model, tcr=tcr, duty=False)  # the operating point alone
        print(
            f"  {model:>12}: {r.unknowns:>6d} unknowns, {r.seconds:6.2f} s "
            f"(steady {r.solution.seconds['steady']:.3f} s, transient "
            f"{r.solution.seconds['transient']:.3f} s), max rise {r.max_temperature_rise:.2f} K, "
            f"ΔL {r.elongation * 1e6:.1f} µm, 95 % of the rise "
            + (
                f"after {r.time_to_95 / 60:.0f} min"
                if math.isfinite(r.time_to_95)
                else "not reached"
            )
        )


def threed_table(repeats: int, quick: bool) -> None:
    print("\n(4) 3-D FE (scikit-fem, trilinear hexahedra, O-grid), reference screw")
    print(
        f"{'mesh':>24} {'unknowns':>9} {'assembly s':>11} {'steady s':>9} {'90 steps s':>11} "
        f"{'T_max °C':>9} {'ΔL µm':>8}"
    )
    meshes = [(32, 3, 0.01, None)]
    if not quick:
        meshes += [(48, 4, 0.005, None)]
    meshes += [(32, 3, 0.005, BallPatches(30, 0.02))]
    problem = reference()
    for div, layers, size, patches in meshes:
        t_build, disc = best(
            lambda d=div, n=layers, s=size, p=patches: build_threed(
                problem, s, d, n, patches=None if p is None else [p]
            ),
            repeats,
        )
        runs = [simulate(disc, 5400.0, 60.0) for _ in range(repeats)]
        sol = runs[-1]
        t_asm = t_build + min(r.seconds["assembly"] for r in runs)
        t_steady = min(r.seconds["steady"] for r in runs)
        t_transient = min(r.seconds["transient"] for r in runs)
        label = f"{div}×{layers} {size * 1e3:g} mm " + ("30 patches" if patches else "smeared")
        print(
            f"{label:>24} {disc.unknowns:>9d} {t_asm:>11.3f} {t_steady:>9.3f} "
            f"{t_transient:>11.3f} {20 + sol.max_temperature_rise:>9.3f} "
            f"{sol.elongation * 1e6:>8.2f}"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer meshes and sweep points")
    args = parser.parse_args()
    repeats = 1 if args.quick else 3
    fe_table(repeats, args.quick)
    network_table(repeats, 100 if args.quick else 1000)
    case_table(args.quick)
    threed_table(1 if args.quick else 2, args.quick)


if __name__ == "__main__":
    main()
