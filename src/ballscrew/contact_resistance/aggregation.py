"""Contact-level thermal contact resistance: re-binning, aggregation and the experiment.

Theory manual: ``docs/theory/contact-resistance.md``, re-binning onto fractal cells (cell size Δ_f),
aggregation and experiment reduction (A1)–(A5).

- (A1) elements of one contact in parallel: 1/R_c = Σ 1/R_ij over loaded cells;
- (A2) the two contacts of a ball in series: R_sbn = R_sb + R_bn (ball conduction neglected);
- (A3) all loaded balls of both nuts in parallel: 1/R = Σ_k n_k/R_sbn,k;
- (A4) apparent area S_c = N_cells(p > 0)·A and unit-area TCR R″ = R·S;
- (A1p) the MB population of the whole solved patch, no cell size (:func:`patch_tcr`);
- (A5) experiment: R″ = (T₁ − T₂) S / Q with Q = U²/R_heater.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ballscrew.budget import check_memory
from ballscrew.contact_resistance.element import ElementTCR, FractalTCRModel, element_tcr
from ballscrew.errors import InputError
from ballscrew.validation import positive

__all__ = [
    "DEFAULT_CELL_SIZE",
    "ContactTCR",
    "contact_tcr",
    "experimental_tcr",
    "heater_power",
    "mean_apparent_area",
    "parallel_resistance",
    "patch_tcr",
    "rebin_forces",
    "series_resistance",
    "unit_area_resistance",
]

DEFAULT_CELL_SIZE = 8.0e-6
"""Default side Δ_f of the square fractal (TCR) cells, m (6–10 µm recommended)."""


def _overlap_weights(n_fine: int, fine: float, coarse: float) -> NDArray[np.float64]:
    """Weights W[I, i] = fraction of fine cell i that lies in coarse cell I (columns sum to 1).

    The n_coarse = ⌈n_fine·fine/coarse⌉ coarse cells are centred on the fine grid, so partial
    coarse cells (if any) sit symmetrically at both ends.
    """
    length = n_fine * fine
    n_coarse = max(1, math.ceil(length / coarse - 1.0e-9))
    offset = 0.5 * (n_coarse * coarse - length)
    fine_edges = np.arange(n_fine + 1) * fine
    coarse_edges = np.arange(n_coarse + 1) * coarse - offset
    lo = np.maximum(coarse_edges[:-1, None], fine_edges[None, :-1])
    hi = np.minimum(coarse_edges[1:, None], fine_edges[None, 1:])
    w = np.clip(hi - lo, 0.0, None)
    return w / w.sum(axis=0, keepdims=True)


def rebin_forces(
    pressure: ArrayLike, dx: float, dy: float, cell_size: float = DEFAULT_CELL_SIZE
) -> NDArray[np.float64]:
    """Re-bin a contact pressure field onto square fractal cells of side Δ_f, conserving force.

    Each solver cell (spacing dx along axis 0, dy along axis 1) carries the force p·dx·dy,
    assumed uniform over the cell. That force is shared among the Δ_f × Δ_f cells it overlaps in
    proportion to the overlap area (separately in x and y), so Σ F_coarse = Σ p·dx·dy exactly
    (to rounding) whether Δ_f is larger or smaller than the solver cells and whether or not it
    divides the grid. The ⌈n·d/Δ_f⌉ fractal cells per axis are centred on the solver grid; when
    Δ_f does not divide the grid length, the cells at both ends stick out beyond the solver box.
    Such partial edge cells are still full fractal cells of area Δ_f² (the solver box encloses
    the contact patch, so the pressure beyond it is zero) and carry only the force of their
    overlap with the grid.

    Args:
        pressure: contact pressure p ≥ 0 on the solver grid, Pa, shape (nx, ny).
        dx: solver cell size along axis 0, m.
        dy: solver cell size along axis 1, m.
        cell_size: side Δ_f of the square fractal cells, m.

    Returns:
        Cell forces in N, shape (⌈nx·dx/Δ_f⌉, ⌈ny·dy/Δ_f⌉).
    """
    p = _pressure_field(pressure)
    dx = positive("dx", dx, "m")
    dy = positive("dy", dy, "m")
    delta = positive("cell_size", cell_size, "m")
    _check_rebin_memory(p.shape, dx, dy, delta)
    wx = _overlap_weights(p.shape[0], dx, delta)
    wy = _overlap_weights(p.shape[1], dy, delta)
    return wx @ (p * (dx * dy)) @ wy.T


def _check_rebin_memory(shape: tuple[int, ...], dx: float, dy: float, delta: float) -> None:
    """Refuse (``tcr.cell_size``) a re-binning whose arrays would not fit the memory budget.

    The overlap weights and their temporaries (4 float arrays of coarse × fine cells per axis)
    and about 30 float arrays of the coarse cells (forces, areas and the element quantities).
    """
    coarse_x = float(np.ceil(shape[0] * dx / delta))
    coarse_y = float(np.ceil(shape[1] * dy / delta))
    weights = 4.0 * (coarse_x * shape[0] + coarse_y * shape[1])
    estimate = 8.0 * (weights + 30.0 * coarse_x * coarse_y)
    what = f"re-binning the pressure onto {coarse_x:.3g} × {coarse_y:.3g} fractal cells"
    check_memory("tcr.cell_size", delta, estimate, what)


def _pressure_field(pressure: ArrayLike) -> NDArray[np.float64]:
    p = np.asarray(pressure, dtype=np.float64)
    if p.ndim != 2 or p.size == 0:
        raise InputError("pressure", f"array of shape {p.shape}", "a non-empty 2-D array (Pa)")
    bad = ~np.isfinite(p) | (p < 0.0)
    if np.any(bad):
        raise InputError("pressure", p[bad].flat[0], "finite values >= 0 Pa")
    return p


PARTIAL_CELLS = ("contact_area", "full_cell")
"""How a fractal cell on the edge of the contact patch counts, see :func:`contact_tcr`."""


@dataclass(frozen=True)
class ContactTCR:
    """Thermal contact resistance of one ball–raceway contact (A1), (A4)."""

    resistance: float
    """Contact resistance R_c = 1/Σ 1/R_ij over the loaded cells (A1), K/W."""
    apparent_area: float
    """Apparent contact area S_c (A4): the sum of the loaded cells' apparent areas, m²."""
    loaded_cells: int
    """Number of cells that carry load above the threshold."""
    cell_size: tuple[float, float]
    """Cell sides (Δx_f, Δy_f) the fractal model was evaluated on, m (result is mesh dependent)."""
    variant: str
    """Element-conductance variant (V2, MT or V1)."""
    elements: ElementTCR
    """Per-cell details (loads, a_l, A_r, L_g, G_s, G_g, R map; R = ∞ in unloaded cells)."""

    @property
    def unit_area_resistance(self) -> float:
        """Unit-area contact resistance R″_c = R_c·S_c (A4), m² K/W."""
        return self.resistance * self.apparent_area

    @property
    def cell_resistance(self) -> NDArray[np.float64]:
        """Per-cell resistance map R_ij, K/W (∞ where the cell is unloaded)."""
        return self.elements.resistance


def contact_tcr(
    pressure: ArrayLike,
    dx: float,
    dy: float,
    model: FractalTCRModel,
    cell_size: float | None = DEFAULT_CELL_SIZE,
    load_threshold: float = 1.0e-8,
    partial_cells: str = "contact_area",
) -> ContactTCR:
    """Thermal contact resistance R_c and apparent area S_c of one contact, (A1) and (A4).

    1. Re-bin p onto Δ_f × Δ_f cells (:func:`rebin_forces`, force-conserving); with
       ``cell_size=None`` the solver grid itself is used (cells dx × dy).
    2. Cells whose force is below ``load_threshold``·max force are treated as unloaded
       (default 1e-8, ``tcr.load_threshold``).
       A fractal cell on the edge of the patch is only partly in contact. With
       ``partial_cells="contact_area"`` (default) its apparent area A is the part of it that
       lies on loaded solver cells, so it carries its force at the local contact pressure and
       S_c equals the solved contact area. With ``"full_cell"`` it counts as a full Δ_f² cell at
       a diluted pressure: in V2 and MT such lightly loaded cells conduct best (L_g → 0 as
       P → 0), so the result then jumps by a few per cent whenever a cell enters the patch.
    3. Element resistances R_ij (T8) for all cells at once (:func:`element_tcr`).
    4. R_c = 1/Σ 1/R_ij (A1), S_c = N_loaded·A (A4).

    The result depends on Δ_f (V2 falls by ≈ 30 % when the cell side is halved), so Δ_f
    is explicit and recorded in the result. Variant V2 is a reconstruction [REC].

    Args:
        pressure: contact pressure on the solver grid, Pa, shape (nx, ny), p ≥ 0.
        dx: solver cell size along axis 0, m.
        dy: solver cell size along axis 1, m.
        model: fractal TCR model parameters and variant.
        cell_size: fractal cell side Δ_f, m (default 8e-6 m), or None for the solver grid.
        load_threshold: relative force threshold (>= 0, < 1) below which a cell counts as
            unloaded.
        partial_cells: apparent area of a fractal cell on the patch edge, "contact_area"
            (the part in contact) or "full_cell" (Δ_f²); see step 2.

    Returns:
        :class:`ContactTCR`.

    Raises:
        InputError: bad grid or parameters, or a field without any positive pressure.
    """
    if not (0.0 <= float(load_threshold) < 1.0):
        raise InputError("load_threshold", load_threshold, "0 <= threshold < 1 (relative)")
    if partial_cells not in PARTIAL_CELLS:
        raise InputError("partial_cells", partial_cells, f"one of {', '.join(PARTIAL_CELLS)}")
    p = _pressure_field(pressure)
    if cell_size is None:
        cell = (positive("dx", dx, "m"), positive("dy", dy, "m"))
        forces = p * (cell[0] * cell[1])
        in_contact = np.where(p > 0.0, cell[0] * cell[1], 0.0)
    else:
        forces = rebin_forces(p, dx, dy, cell_size)
        cell = (float(cell_size), float(cell_size))
        in_contact = rebin_forces((p > 0.0).astype(np.float64), dx, dy, cell_size)
    peak = float(forces.max())
    if peak <= 0.0:
        raise InputError("pressure", "all zero", "at least one cell with p > 0")
    loaded = (forces >= load_threshold * peak) & (forces > 0.0)
    cell_loads = np.where(loaded, forces, 0.0)
    full = cell[0] * cell[1]
    if partial_cells == "contact_area":
        areas = np.where(loaded, np.clip(in_contact, 1e-12 * full, full), full)
    else:
        areas = np.full(forces.shape, full)
    elements = element_tcr(cell_loads, areas, model)
    n_loaded = int(np.count_nonzero(loaded))
    return ContactTCR(
        resistance=float(parallel_resistance(elements.resistance[loaded])),
        apparent_area=float(areas[loaded].sum()),
        loaded_cells=n_loaded,
        cell_size=cell,
        variant=model.variant,
        elements=elements,
    )


def patch_tcr(pressure: ArrayLike, dx: float, dy: float, model: FractalTCRModel) -> ContactTCR:
    """Fractal TCR of one contact with the MB population of the whole solved patch, (A1p).

    One element carries the contact load Q = Σ p·dx·dy on the solved contact area
    S_c = N(p > 0)·dx·dy, so a_l, A_r, G_s and L_g follow from (Q, S_c) alone and no cell size
    enters: R_c = R(Q, S_c) of :func:`element_tcr`. For a uniform pressure p on S_c this is the
    MB closed form of that apparent area; the result converges with the solver grid as S_c does
    (theory manual, *Fractal model without a cell*).

    Args:
        pressure: contact pressure on the solver grid, Pa, shape (nx, ny), p ≥ 0.
        dx: solver cell size along axis 0, m.
        dy: solver cell size along axis 1, m.
        model: fractal TCR model parameters and variant.

    Returns:
        :class:`ContactTCR` with one element, a 1 × 1 map (``cell_size`` = the grid's extent).

    Raises:
        InputError: bad grid or a field without any positive pressure.
    """
    p = _pressure_field(pressure)
    cell = positive("dx", dx, "m") * positive("dy", dy, "m")
    in_contact = p > 0.0
    if not np.any(in_contact):
        raise InputError("pressure", "all zero", "at least one cell with p > 0")
    area = float(np.count_nonzero(in_contact)) * cell
    elements = element_tcr(np.full((1, 1), float(p.sum()) * cell), area, model)
    return ContactTCR(
        resistance=float(elements.resistance[0, 0]),
        apparent_area=area,
        loaded_cells=1,
        cell_size=(p.shape[0] * dx, p.shape[1] * dy),
        variant=model.variant,
        elements=elements,
    )


def parallel_resistance(
    resistances: ArrayLike, counts: ArrayLike = 1, axis: int | None = None
) -> NDArray[np.float64]:
    """Resistances in parallel, 1/R = Σ n_k/R_k, (A1) and (A3).

    ``counts`` gives how many identical paths each resistance stands for (e.g. balls per nut).
    An infinite resistance (open path, lifted-off nut) or a zero count contributes nothing; if
    nothing conducts the result is ∞.

    Args:
        resistances: R_k > 0 (∞ allowed), K/W.
        counts: multiplicities n_k >= 0, broadcast against ``resistances``.
        axis: axis to reduce over (None: all).

    Returns:
        R in K/W (a 0-d array when ``axis`` is None).
    """
    r = np.asarray(resistances, dtype=np.float64)
    if np.any(np.isnan(r) | (r <= 0.0)):
        raise InputError("resistances", resistances, "values > 0 K/W (∞ allowed)")
    n = np.broadcast_to(np.asarray(counts, dtype=np.float64), r.shape)
    if np.any(~np.isfinite(n) | (n < 0.0)):
        raise InputError("counts", counts, "finite values >= 0")
    conductance = np.sum(np.where(n > 0.0, n / r, 0.0), axis=axis)
    out = np.full(np.shape(conductance), np.inf)
    np.divide(1.0, conductance, out=out, where=conductance > 0.0)
    return out[()]


def series_resistance(*resistances: ArrayLike) -> NDArray[np.float64]:
    """Resistances in series, R = Σ R_k, e.g. screw–ball plus ball–nut contact (A2).

    Args:
        *resistances: R_k >= 0 (∞ allowed), K/W; broadcast together.

    Returns:
        R in K/W (broadcast shape).
    """
    if not resistances:
        raise InputError("resistances", (), "at least one resistance")
    arrays = [np.asarray(r, dtype=np.float64) for r in resistances]
    for r in arrays:
        if np.any(np.isnan(r) | (r < 0.0)):
            raise InputError("resistances", r, "values >= 0 K/W (∞ allowed)")
    return np.sum(np.broadcast_arrays(*arrays), axis=0)


def mean_apparent_area(screw_area: ArrayLike, nut_area: ArrayLike, counts: ArrayLike = 1) -> float:
    """Apparent area S = Σ_k n_k (S_sb,k + S_bn,k)/2 of the screw, (A4) [assumption].

    The paper only says "apparent contact area"; the mean of the screw-side and nut-side patch areas
    is this project's assumption (``docs/theory/contact-resistance.md``). For FE, prefer one
    conductance per interface, h_c = 1/(R_c S_c).

    Args:
        screw_area: S_sb,k of one ball–screw contact per ball group (nut), m².
        nut_area: S_bn,k of one ball–nut contact per ball group, m².
        counts: balls n_k in each group.

    Returns:
        S in m².
    """
    s_sb, s_bn, n = np.broadcast_arrays(
        np.asarray(screw_area, dtype=np.float64),
        np.asarray(nut_area, dtype=np.float64),
        np.asarray(counts, dtype=np.float64),
    )
    for name, arr in (("screw_area", s_sb), ("nut_area", s_bn), ("counts", n)):
        if np.any(~np.isfinite(arr) | (arr < 0.0)):
            raise InputError(name, arr, "finite values >= 0")
    return float(np.sum(n * 0.5 * (s_sb + s_bn)))


def unit_area_resistance(resistance: ArrayLike, area: ArrayLike) -> NDArray[np.float64]:
    """Unit-area thermal contact resistance R″ = R·S, (A4), m² K/W (the paper's unit).

    Args:
        resistance: R, K/W.
        area: apparent area S, m².

    Returns:
        R″ in m² K/W.
    """
    return np.asarray(resistance, dtype=np.float64) * np.asarray(area, dtype=np.float64)


def heater_power(voltage: ArrayLike, heater_resistance: float) -> NDArray[np.float64]:
    """Electrical heater power Q = U²/R_h, (A5), W.

    Args:
        voltage: supply voltage U, V.
        heater_resistance: heater resistance R_h (> 0), Ω.

    Returns:
        Q in W.
    """
    r_h = positive("heater_resistance", heater_resistance, "Ω")
    return np.asarray(voltage, dtype=np.float64) ** 2 / r_h


def experimental_tcr(
    t_nut: ArrayLike,
    t_screw: ArrayLike,
    voltage: ArrayLike,
    heater_resistance: float,
    area: float,
) -> NDArray[np.float64]:
    """Measured unit-area TCR R″ = (T₁ − T₂) S / Q with Q = U²/R_h, (A5).

    T₁ and T₂ must be taken *at* the contact (nodes next to the contact surfaces); temperatures
    on the nut lining or screw include bulk and macro-constriction resistances.

    Args:
        t_nut: nut-side temperature T₁ next to the contact, K or °C.
        t_screw: screw-side temperature T₂ next to the contact, same unit.
        voltage: heater supply voltage U (non-zero), V.
        heater_resistance: heater resistance R_h (> 0), Ω.
        area: apparent contact area S (> 0), m².

    Returns:
        R″ in m² K/W (broadcast shape); e.g. ΔT = 3 K, S = 7.19e-6 m², U = 24 V, R_h = 48 Ω
        → 1.798e-6 m² K/W.
    """
    s = positive("area", area, "m²")
    q = heater_power(voltage, heater_resistance)
    if np.any(~np.isfinite(q) | (q <= 0.0)):
        raise InputError("voltage", voltage, "finite, non-zero voltages (V)")
    dt = np.asarray(t_nut, dtype=np.float64) - np.asarray(t_screw, dtype=np.float64)
    return dt * s / q
