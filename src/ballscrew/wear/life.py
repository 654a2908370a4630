"""Wear life of a preloaded nut: the integrator over the load programme.

A double nut, or a single nut preloaded on both flanks (four-point contact or an offset lead):
"nut 1" and "nut 2" below are then its two loaded flanks with the set-up's balls per flank.

The set-up is :mod:`.setup`, one contact of a step :mod:`.step`, the history :mod:`.history`
and the checkpoint files :mod:`.checkpoint`. The time integration of the wear over a load
programme (theory manual, *Wear*):

1. F_1, F_2 from the current preload and the level's axial load (E1.10–E1.11; lift-off gives
   F_2 = 0 and no wear from that nut); a reverse load (F_a < 0) swaps them, nut 2 loaded.
2. For each screw flank s = ±1 and each nut force: ball load Q = F/(Z sinβ cosλ) (E1.6), the
   Polonsky–Keer pressure on the fixed grid over the worn gap g_0 + h_s(y) (E8.5), warm-started
   from the previous pressure of the same flank and nut; the JGP asperity share ψ at the
   entrainment speed u_e (E2.4, E2.8, E6.4) with A_n = the loaded cells' area and ΔA = the grid
   cell; the sliding speed of (E2.7) with the curvature term; the cell wear rates of Model A or
   C (E7.2, E7.3); strips (E8.1), Z balls over L_w (E8.2–E8.3), reciprocation ½ F_1 + ½ F_2
   (E8.4).
3. Explicit step ΔN = min(max_depth_step / max_j ḣ_j, revolutions to the next level end or
   torque sample); h_s += ḣ_s ΔN.
4. Preload from the largest depth (E1.13) with C_a of the Hertz constants (E1.8), or from the
   worn groove's own contact (``wear.preload_contact = "worn"``, :mod:`.preload`); drag torque
   T = K_T F_p L/(2π) (E9.1), K_T scaled by ``torque_scale`` or fitted to ``initial_torque``.

The whole state is saved to a checkpoint file after every ``checkpoint_every`` steps; a stopped
run resumes from its last saved step and produces the same history.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ballscrew.budget import check_count, check_memory, check_work
from ballscrew.errors import InputError
from ballscrew.progress import advance
from ballscrew.units import format_quantity
from ballscrew.wear.checkpoint import ignore_checkpoint, load_checkpoint, save_checkpoint
from ballscrew.wear.history import WearLife
from ballscrew.wear.preload import preload_after
from ballscrew.wear.programme import WearLevel, WearOptions
from ballscrew.wear.setup import FLANKS, FloatArray, WearSetup, nut_force_pair
from ballscrew.wear.step import StepContact, step_rates
from ballscrew.wear.strips import reciprocating_rate

__all__ = ["check_wear_work", "integrate_wear"]

log = logging.getLogger("ballscrew")
_CHECKPOINT_VERSION = 1


@dataclass
class _State:
    level: int
    revolutions: float
    depth: FloatArray  # (2, ny)
    warm: dict[str, FloatArray]
    records: dict[str, list[Any]]
    solves: int
    steps: int
    initial_psi: dict[str, float]


_RECORD_KEYS = (
    "revolutions",
    "max_depth",
    "preload",
    "torque",
    "forces",
    "level",
    "sampled",
    "profiles",
)


def _save(path: Path, state: _State, fingerprint: str) -> None:
    arrays: dict[str, Any] = {f"rec_{k}": np.asarray(v) for k, v in state.records.items()}
    arrays.update({f"warm_{k}": v for k, v in state.warm.items()})
    arrays["depth"] = state.depth
    meta = {
        "version": _CHECKPOINT_VERSION,
        "fingerprint": fingerprint,
        "level": state.level,
        "revolutions": state.revolutions,
        "solves": state.solves,
        "steps": state.steps,
        "initial_psi": state.initial_psi,
    }
    save_checkpoint(path, meta, arrays)


def _load(path: Path, fingerprint: str, ny: int) -> _State | None:
    """The saved state, or None (with a warning) if the checkpoint is missing or unsound."""
    loaded = load_checkpoint(path)
    if loaded is None:
        return None
    meta, data = loaded
    if meta.get("version") != _CHECKPOINT_VERSION:
        return ignore_checkpoint(path, f"format version {meta.get('version')!r}")
    if meta.get("fingerprint") != fingerprint:
        raise InputError(
            "checkpoint", str(path), "a checkpoint of this same case and [wear] section"
        )
    try:
        state = _State(
            level=int(meta["level"]),
            revolutions=float(meta["revolutions"]),
            depth=np.asarray(data["depth"], dtype=float),
            warm={k[5:]: v for k, v in data.items() if k.startswith("warm_")},
            records={k: list(data[f"rec_{k}"]) for k in _RECORD_KEYS},
            solves=int(meta["solves"]),
            steps=int(meta["steps"]),
            initial_psi=dict(meta["initial_psi"]),
        )
    except (KeyError, TypeError, ValueError):
        return ignore_checkpoint(path, "entries are missing")
    lengths = {len(v) for v in state.records.values()}
    sound = (
        state.depth.shape == (2, ny)
        and np.isfinite(state.depth).all()
        and len(lengths) == 1
        and lengths != {0}
        and data["rec_profiles"].shape[1:] == (2, ny)
        and 0 <= state.revolutions < math.inf
        and state.level >= 0
    )
    return state if sound else ignore_checkpoint(path, "its arrays do not fit this case")


def _record(
    state: _State, setup: WearSetup, fp: float, forces: tuple[float, float], sampled: bool
) -> None:
    h_max = float(state.depth.max())
    r = state.records
    r["revolutions"].append(state.revolutions)
    r["max_depth"].append(h_max)
    r["preload"].append(fp)
    r["torque"].append(setup.torque(fp))
    r["forces"].append(np.array(forces))
    r["level"].append(state.level)
    r["sampled"].append(sampled)
    r["profiles"].append(state.depth.copy())


def _preload(setup: WearSetup, state: _State) -> float:
    """F_p after the state's worn depths (``wear.preload_contact``) from the last recorded
    preload, its solves counted."""
    fp, solves = preload_after(setup, state.depth, float(state.records["preload"][-1]))
    state.solves += solves
    return fp


def _is_sample(revolutions: float, every: float) -> bool:
    k = round(revolutions / every)
    return k >= 1 and abs(revolutions - k * every) <= 1e-9 * max(revolutions, 1.0)


def _step_rates(setup: WearSetup, state: _State, preload: float, level: WearLevel) -> FloatArray:
    """ḣ per revolution of both flanks (2, ny) under reciprocation (E8.4) at ``level``.

    A duty-cycle level's rate is the revolution-weighted mean of its segments' rates; a nut's
    rate is the ball-share-weighted mean over its load classes, ḣ = Σ_k w_k ḣ(r_k Q̄) (every ball
    passes every raceway point; :mod:`.load_classes`). Every contact of the step (both flanks,
    both nuts, all classes and segments) is solved in one batch (:func:`.step.step_rates`).
    """
    nuts: dict[tuple[int, int], list[FloatArray | None]] = {}  # (part, flank): ḣ of each nut
    entries: list[tuple[list[FloatArray | None], int, str, float]] = []
    contacts: list[StepContact] = []
    for index, (_, part) in enumerate(level.parts()):
        forces = nut_force_pair(preload, part.axial_load)
        for k, flank in enumerate(FLANKS):
            sums = nuts[index, k] = [np.zeros(setup.y.size) if f > 0.0 else None for f in forces]
            for nut, force in enumerate(forces, start=1):
                if force <= 0.0:
                    continue
                key = f"{flank:+d}_{nut}" + (f"_{index}" if level.segments else "")
                classes = setup.load_classes(part.axial_load, nut)
                for c, (ratio, weight) in enumerate(
                    zip(classes.ratios, classes.weights, strict=True)
                ):
                    if ratio > 0.0:  # lifted-off balls wear nothing
                        name = key + (f"_c{c}" if c else "")
                        entries.append((sums, nut, name, weight))
                        contacts.append(
                            StepContact(
                                flank, force, part.speed, state.depth[k], state.warm.get(name),
                                part, ratio,
                            )
                        )  # fmt: skip
    for (sums, nut, name, weight), out in zip(entries, step_rates(setup, contacts), strict=True):
        state.warm[name] = out.pressure
        state.solves += 1
        state.initial_psi.setdefault(name, out.psi)
        sums[nut - 1] += weight * out.depth_per_revolution
    rates = np.zeros_like(state.depth)
    for (index, k), (first, second) in nuts.items():
        loaded = first if first is not None else np.zeros(setup.y.size)
        rates[k] += level.parts()[index][0] * reciprocating_rate(loaded, second)
    return rates


def check_wear_work(
    spec: WearOptions, taken: int, revolutions: float, level: int, rates: FloatArray | None = None
) -> None:
    """Refuse a run whose time steps, history memory or contact work would exceed the limits.

    The steps still to go are at least one per torque sample and level end, plus (given the
    current ``rates``) the depth-limited steps: remaining revolutions × max ḣ / max_depth_step.
    Checked before the set-up, before the first step and at every step, so a run stops with an
    error (the guard) instead of running for ever.
    """
    ends = np.cumsum([lv.revolutions for lv in spec.programme])
    remaining = float(ends[-1]) - revolutions
    if not math.isfinite(remaining):
        bad = int(np.flatnonzero(~np.isfinite(ends))[0])
        raise InputError(
            f"wear.programme[{bad}].revolutions",
            spec.programme[bad].revolutions,
            "a finite number of revolutions",
        )
    samples = remaining / spec.torque_sampling + len(ends) - level
    peak = math.inf if rates is None or not np.all(np.isfinite(rates)) else float(rates.max())
    depth = 0.0 if rates is None or remaining <= 0.0 else remaining * peak / spec.max_depth_step
    if depth > samples:
        field, value = "wear.max_depth_step", spec.max_depth_step
        cause = (
            f"depth-limited at {peak:.3g} m/rev (wear.coefficient = {spec.coefficient:g}, "
            f"wear.stroke = {spec.stroke:g} m)"
        )
    else:
        field, value, cause = "wear.torque_sampling", spec.torque_sampling, "one per sample"
    total = taken + samples + depth
    check_count(field, value, total, f"time steps of the wear run ({taken} taken, rest {cause})")
    nx, ny = spec.grid
    record = 2.0 * 8.0 * (2 * ny + 30)  # a profile per flank and the scalars, twice
    check_memory(field, value, total * record, f"the wear history of {total:.3g} steps")
    solves = 2 * len(FLANKS) * (samples + depth)  # two nuts per flank and step, at most
    what = f"contact-grid cell solves of the wear run ({nx * ny} cells × {solves:.3g} solves)"
    check_work("wear.grid", list(spec.grid), nx * ny * solves, what)


def _finish(setup: WearSetup, state: _State, complete: bool, wall: float) -> WearLife:
    r = state.records
    spec = setup.spec
    loads = np.array([lv.axial_load for lv in spec.programme])
    boundaries = np.cumsum([lv.revolutions for lv in spec.programme])
    extras: dict[str, Any] = {}
    solves = state.solves
    if complete:
        last = spec.programme[-1].parts()[-1][1]
        nut = 1 if last.axial_load >= 0.0 else 2  # the loaded nut: 2 under a reverse load
        f1 = nut_force_pair(float(r["preload"][-1]), last.axial_load)[nut - 1]
        if f1 > 0.0:
            warm = state.warm.get(f"+1_{nut}")
            worn, unworn = step_rates(
                setup,
                [
                    StepContact(1, f1, last.speed, state.depth[0], warm, last),
                    StepContact(1, f1, last.speed, np.zeros_like(setup.y), level=last),
                ],
            )
            solves += 2
            extras["ellipse_major_axis"] = _extent(worn.pressure, setup.dy)
            extras["ellipse_major_axis_unworn"] = _extent(unworn.pressure, setup.dy)
            extras["final_pressure"] = worn.pressure
        extras["worn_band_width"] = _band(state.depth[0], setup.dy)
    return WearLife(
        revolutions=np.asarray(r["revolutions"], dtype=float),
        max_wear_depth=np.asarray(r["max_depth"], dtype=float),
        preload=np.asarray(r["preload"], dtype=float),
        friction_torque=np.asarray(r["torque"], dtype=float),
        nut_forces=np.asarray(r["forces"], dtype=float).reshape(-1, 2),
        level=np.asarray(r["level"], dtype=np.int64),
        sampled=np.asarray(r["sampled"], dtype=bool),
        y=setup.y.copy(),
        profiles=np.asarray(r["profiles"], dtype=float),
        level_boundaries=boundaries.astype(float),
        level_loads=loads,
        contact_solves=solves,
        steps=state.steps,
        wall_time=wall,
        complete=complete,
        model=spec.model,
        coefficient=spec.coefficient,
        raceway_length=setup.raceway_length,
        compliance=setup.compliance,
        cell_area=setup.cell_area,
        initial_psi=dict(state.initial_psi),
        x=setup.x.copy(),
        **extras,
    )


def _extent(pressure: FloatArray, dy: float) -> float:
    cols = np.flatnonzero((pressure > 0.0).any(axis=0))
    return float((cols[-1] - cols[0] + 1) * dy) if cols.size else 0.0


def _band(depth: FloatArray, dy: float, fraction: float = 0.05) -> float:
    peak = float(depth.max())
    if peak <= 0.0:
        return 0.0
    cols = np.flatnonzero(depth > fraction * peak)
    return float((cols[-1] - cols[0] + 1) * dy)


def integrate_wear(
    setup: WearSetup,
    fingerprint: str,
    *,
    checkpoint: str | Path | None = None,
    resume: bool = False,
    max_steps: int | None = None,
) -> WearLife:
    """Wear, preload and drag torque over the load programme of ``setup``.

    Args:
        setup: the fixed inputs of the run.
        fingerprint: identifies the inputs; a checkpoint of other inputs is refused.
        checkpoint: file (``.npz``) to save the state to after every ``checkpoint_every`` steps.
        resume: continue from ``checkpoint`` if it exists (it must come from the same inputs).
        max_steps: stop after this many time steps of this call (the result then has
            ``complete = False``; resume it later from the checkpoint).
    """
    start = time.perf_counter()
    spec = setup.spec
    path = None if checkpoint is None else Path(checkpoint)
    state = _load(path, fingerprint, setup.y.size) if path is not None and resume else None
    if state is not None:
        log.info("wear: resumed at N = %.4g rev (step %d)", state.revolutions, state.steps)
    else:
        state = _State(
            0, 0.0, np.zeros((2, setup.y.size)), {}, {k: [] for k in _RECORD_KEYS}, 0, 0, {}
        )
        first = spec.programme[0]
        fp0 = setup.initial_preload
        _record(state, setup, fp0, nut_force_pair(fp0, first.axial_load), True)
    ends = np.cumsum([lv.revolutions for lv in spec.programme])
    every = spec.torque_sampling
    taken = 0
    preload = _preload(setup, state)
    while state.level < len(spec.programme):
        level = spec.programme[state.level]
        end = float(ends[state.level])
        if state.revolutions >= end * (1.0 - 1e-12):
            state.level += 1
            continue
        if max_steps is not None and taken >= max_steps:
            if path is not None:
                _save(path, state, fingerprint)
            return _finish(setup, state, False, time.perf_counter() - start)
        rates = _step_rates(setup, state, preload, level)
        check_wear_work(spec, state.steps, state.revolutions, state.level, rates)
        next_sample = (math.floor(state.revolutions / every + 1e-9) + 1) * every
        target = min(end, next_sample)
        peak = float(rates.max())
        dn = target - state.revolutions
        if peak > 0.0:
            dn = min(dn, spec.max_depth_step / peak)
        state.depth = state.depth + rates * dn
        state.revolutions = target if dn >= target - state.revolutions else state.revolutions + dn
        state.steps += 1
        taken += 1
        sampled = _is_sample(state.revolutions, every)
        preload = _preload(setup, state)
        _record(state, setup, preload, nut_force_pair(preload, level.axial_load), sampled)
        advance("wear", state.revolutions, ends[-1])
        if sampled or state.revolutions >= end * (1.0 - 1e-12):
            log.debug(
                "wear: level %d/%d, N = %s, h_max = %s, F_p = %s, T = %s",
                state.level + 1,
                len(spec.programme),
                format_quantity(state.revolutions, "revolutions"),
                format_quantity(state.records["max_depth"][-1], "displacement"),
                format_quantity(state.records["preload"][-1], "force"),
                format_quantity(state.records["torque"][-1], "torque"),
            )
        if path is not None and state.steps % spec.checkpoint_every == 0:
            _save(path, state, fingerprint)
    if path is not None:
        _save(path, state, fingerprint)
    return _finish(setup, state, True, time.perf_counter() - start)
