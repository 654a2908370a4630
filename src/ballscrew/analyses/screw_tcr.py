"""Thermal contact resistance of a (double-nut) ball screw, after Gao, Wang & Liu (2019).

Nut forces under preload and axial load → ball load → contact pressure at the screw (A) and nut
(B) contacts → the contact resistance of the headline model (``[tcr] headline``: by default the
Cooper–Mikic–Yovanovich conductance integrated over the pressure field, no cell size; the
paper's fractal element model on Δ_f cells is the option ``"V2"``) → screw and nut contact in
series per ball, balls and nuts in parallel → unit-area value R″ = R·S (theory manual:
*Contact resistance*, *Which model is the headline*).

Every ball of a nut carries the same load (the paper's assumption). The two nuts load opposite
flanks; the flank mirrors the gap (h₋₁(x, y) = h₊₁(−x, −y)) and leaves the resistance unchanged,
so one solve serves every contact of equal load and side. A preloaded single nut has the same
two flank rows: a four-point nut's are the two contact pairs of each of its balls, an
offset-lead nut's its two halves; both run in parallel into the one nut body.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property
from types import ModuleType
from typing import ClassVar

from ballscrew.analyses import tcr_report
from ballscrew.analyses.ball_contact import RacewayContact, solve_raceway_contacts
from ballscrew.analyses.ball_loads import chain_ball_loads
from ballscrew.analyses.parameters import SIDES, ScrewParameters, Side
from ballscrew.analyses.result import Presented, recorded_warnings
from ballscrew.analyses.tcr_film import (
    NutFilm,
    NutHeatPath,
    conductivities,
    heat_paths,
    nut_films,
)
from ballscrew.analyses.tcr_models import (
    PATCH,
    ContactResistance,
    ModelSpread,
    ModelTCR,
    compare_models,
    contact_model,
    out_of_range,
    solved_contact_area,
)
from ballscrew.case import Case, TCRSpec
from ballscrew.contact_resistance import (
    ELEMENT_MODELS,
    ContactTCR,
    FractalTCRModel,
    contact_tcr,
    parallel_resistance,
    patch_tcr,
    series_resistance,
)
from ballscrew.contact_resistance.correlations import CORRELATIONS
from ballscrew.errors import InputError
from ballscrew.loads import preloaded_axial_stiffness
from ballscrew.validation import as_case_fields, case_with


@dataclass(frozen=True)
class RacewayTCR:
    """Pressure solution and thermal contact resistance of one ball–raceway contact."""

    contact: RacewayContact
    tcr: ContactTCR
    """The fractal element model's details: the headline's cells (or patch) when the headline
    is an element model, else ``[tcr] variant`` on the paper's Δ_f cells."""
    resistance: float
    """R_c of the headline model [K/W]."""
    apparent_area: float
    """S_c [m²]: of the headline element model's cells, else the solved contact area."""


@dataclass(frozen=True)
class NutTCR:
    """One nut: its force, ball load, the two contacts of a ball, and what they add up to."""

    index: int
    """1 = the nut (flank) the axial load presses on, 2 = the one it unloads."""
    force: float
    """Axial force on the nut (flank) [N]."""
    ball_load: float
    """Normal load of each of its balls [N]."""
    balls: int
    """Loaded balls of the nut."""
    screw: RacewayTCR
    nut: RacewayTCR
    axial_deflection: float
    """δ_a = (δ_A + δ_B)/(sinβ cosα) from the solved approaches (E1.7) [m]."""
    load_spread: float = 1.0
    """Largest over mean ball load (elastic distribution: every ball is taken at the most
    loaded ball's load, a conservative bound) [-]."""

    @property
    def ball_resistance(self) -> float:
        """R_sbn = R_sb + R_bn, one ball, screw and nut contact in series (A2) [K/W]."""
        return float(series_resistance(self.screw.resistance, self.nut.resistance))

    @property
    def resistance(self) -> float:
        """All balls of the nut in parallel, R_sbn / n_b (A3) [K/W]."""
        return self.ball_resistance / self.balls

    @property
    def apparent_area(self) -> float:
        """n_b (S_sb + S_bn)/2, the nut's share of S in (A4) [m²]."""
        return self.balls * 0.5 * (self.screw.apparent_area + self.nut.apparent_area)

    @property
    def axial_stiffness(self) -> float:
        """Preloaded axial stiffness dF/dδ_a = 1.5 F/δ_a of the nut (Hertz; manual: Loads) [N/m]."""
        return float(preloaded_axial_stiffness(self.force, self.axial_deflection))


@dataclass(frozen=True)
class ScrewTCR(Presented):
    """Thermal contact resistance of the whole screw and of each nut and contact."""

    case_name: str
    headline: str
    """Model of :attr:`resistance` and :attr:`resistance_per_area` (``[tcr] headline``): CMY
    by default; V2, MT, V1 are the paper's cell models, ``V2/patch`` … the cell-free fractal
    ones (theory manual, *Which model is the headline*)."""
    variant: str
    """Element model of the fractal details (``RacewayTCR.tcr``: V2, MT or V1)."""
    cell_size: float | None
    """Fractal cell size Δ_f of the details [m], None = the solver grid or the whole patch.

    A cell model's result depends on it; the default headline has no cell."""
    nut_forces: tuple[float, float]
    """(F1, F2): axial force on the loaded and the unloaded flank [N] (the two nuts of a
    double nut, the two flanks of a preloaded single nut; F2 = 0 for one loaded flank)."""
    nuts: tuple[NutTCR, ...]
    """One entry per loaded flank (a lifted-off one is absent): the nuts of a double nut; the
    two contact pairs of the same balls of a four-point nut, or the two halves of an
    offset-lead nut (``params.flanks.balls`` balls each), whose paths run in parallel into the
    one nut body."""
    case: Case
    """The case that was solved."""
    warnings: tuple[str, ...] = ()
    """Warnings raised while solving (one line each)."""
    models: dict[str, ModelTCR] = field(default_factory=dict)
    """Every model of ``[tcr] models`` on the same contacts: name → R and R″."""
    uncertainty: ModelSpread | None = None
    """Spread of R″ over :attr:`models` (None with fewer than two models)."""
    films: tuple[NutFilm, ...] = ()
    """With ``[tcr] film_path``: the lubricant film around the balls of every nut, a
    lifted-off one included (empty without)."""

    analysis: ClassVar[str] = "tcr"
    presentation: ClassVar[ModuleType] = tcr_report

    @property
    def resistance(self) -> float:
        """R of the whole screw, the headline: the micro TCR of every loaded ball of every nut in
        parallel (A3) by the :attr:`headline` model [K/W]. It is Gao, Wang & Liu's (2019)
        resistance of the asperity spots and the gap between them inside the Hertz patches;
        the macro-constriction and the film path lie outside the patches, so ``[tcr] film_path``
        leaves it unchanged (they are in :attr:`ball_path_without_film` and
        :attr:`ball_path_with_film`)."""
        return float(parallel_resistance([n.resistance for n in self.nuts]))

    @property
    def apparent_area(self) -> float:
        """S = Σ over nuts of n_b (S_sb + S_bn)/2 (A4) [m²]."""
        return float(sum(n.apparent_area for n in self.nuts))

    @property
    def resistance_per_area(self) -> float:
        """Unit-area TCR R″ = R·S (A4) [m² K/W]."""
        return self.resistance * self.apparent_area

    @property
    def title(self) -> str:
        return f"Thermal contact resistance: {self.case.name}"

    def heat_paths(self, constriction: bool = True) -> tuple[NutHeatPath, ...]:
        """Each nut's ball path: micro TCR (+ macro-constriction) and, with ``[tcr]
        film_path``, the film in parallel (P3), a lifted-off nut's films included. Without a
        film path one path per loaded nut, without film. With the constriction (the default)
        it is computed once per result."""
        if constriction:
            return self._heat_paths
        return self._paths(constriction=False)

    @cached_property
    def _heat_paths(self) -> tuple[NutHeatPath, ...]:
        """:meth:`heat_paths` with the macro-constriction (cached: the summary and the report
        each read it and :attr:`heat_path_resistance`)."""
        return self._paths(constriction=True)

    def _paths(self, constriction: bool) -> tuple[NutHeatPath, ...]:
        return heat_paths(self.nuts, self.films, conductivities(self.case), None, constriction)

    @property
    def ball_path_without_film(self) -> float:
        """Screw to nut through every loaded ball's patches, micro TCR plus macro-constriction
        (A3, A6), the nuts in parallel [K/W]; the same with and without ``[tcr] film_path``."""
        paths = self.heat_paths()
        return float(parallel_resistance([p.ball_path_without_film for p in paths]))

    @property
    def ball_path_with_film(self) -> float | None:
        """Screw to nut with the film around every ball beside its patches (P3), the nuts in
        parallel (a lifted-off one through its films) [K/W]; None without ``[tcr] film_path``."""
        return self.heat_path_resistance if self.films else None

    @property
    def heat_path_resistance(self) -> float:
        """The screw-to-nut path the thermal model takes (``thermal.contact.constriction``
        on): :attr:`ball_path_with_film` with ``[tcr] film_path``, else
        :attr:`ball_path_without_film` [K/W]."""
        return float(parallel_resistance([p.resistance for p in self.heat_paths()]))


def tcr_model(
    params: ScrewParameters, options: TCRSpec, side: Side, variant: str | None = None
) -> FractalTCRModel:
    """Fractal TCR parameters of the ball against the ``side`` raceway.

    ``variant`` overrides the element model of ``options`` (the case's ``[tcr]``).
    """
    if not params.smooth_ball:
        raise InputError(
            "surface.ball", "rough", "absent (smooth ball): the TCR chain models the raceway only"
        )
    return FractalTCRModel(
        D=params.D,
        G=params.G,
        E_star=params.contact_modulus(side),
        H=params.hardness(side),
        lambda_1=params.ball.thermal_conductivity,
        lambda_2=params.material(side).thermal_conductivity,
        lambda_f=params.lubrication.thermal_conductivity,
        variant=options.variant if variant is None else variant,
        cutoff_area=options.cutoff_area,
        gap_model=options.gap_model,
        gap_factor=options.gap_factor,
        sampling_length=options.sampling_length,
        rarefaction=params.lubrication.rarefaction,
    )


def tcr_fields(side: Side) -> dict[str, str]:
    """Case fields behind the arguments of the TCR model of the ``side`` raceway."""
    pair = f"materials.ball and materials.{side}"
    return {
        "D": "surface.D",
        "G": "surface.G",
        "H": f"the hardness of {pair}",
        "lambda_1": "materials.ball.thermal_conductivity",
        "lambda_2": f"materials.{side}.thermal_conductivity",
        "lambda_s": f"the mean thermal conductivity of {pair}",
        "lambda_f": "medium.thermal_conductivity",
        "factor": "tcr.gap_factor",
        "sampling_length": "tcr.sampling_length",
        "rarefaction": "medium.rarefaction",
    }


def screw_tcr(case: Case, variant: str | None = None) -> ScrewTCR:
    """Thermal contact resistance of the ball screw of ``case``.

    The headline is the case's ``[tcr] headline`` (CMY by default); ``variant`` (V2, MT or V1)
    makes that element model on the paper's Δ_f cells the headline instead (Gao et al.'s cell
    model). With ``[operating] coupled = true`` the medium between the asperities is
    the named lubricant at the contact temperature of the coupled operating point.
    Contacts of equal side and ball load are solved once (both nuts share
    them at zero axial load); the distinct contacts (both sides of both nuts) are solved in one
    batched call where their grids have equal cell counts.
    """
    case_with(case, "screw", "operating", "surface", "materials", "medium", "numerics", "tcr")
    if case.operating.coupled:  # the medium's conductivity at the operating temperature
        # imported here: the operating point's thermal model uses this analysis
        from ballscrew.analyses.operating_point import at_operating_point

        case = at_operating_point(case)[0]
    params = ScrewParameters.from_case(case)
    geometry = params.geometry
    headline = case.tcr.headline if variant is None else ELEMENT_MODELS.check(variant)
    patch = headline.endswith(PATCH)
    base = headline.removesuffix(PATCH)
    detail = base if base in ELEMENT_MODELS else case.tcr.variant
    models = {side: tcr_model(params, case.tcr, side, detail) for side in SIDES}
    cell_size = case.tcr.cell_size if case.tcr.rebin and not patch else None
    with recorded_warnings() as early:  # the distribution's (a ball above the contact-law table)
        chain = chain_ball_loads(case, params)
    flanks = params.flank_loads
    loaded = [(nut, used) for nut, used in zip(flanks, chain, strict=True) if used.force > 0.0]
    keys: dict[tuple[Side, float], int] = {}  # (side, Q) → flank: the distinct contacts
    for nut, used in loaded:
        for side in SIDES:
            keys.setdefault((side, used.ball_load), nut.flank)
    nuts = []
    with recorded_warnings() as messages:
        contacts = solve_raceway_contacts(
            geometry,
            [(side, q, params.contact_modulus(side), flank) for (side, q), flank in keys.items()],
            case.numerics,
        )
        pairs = list(zip(keys, contacts, strict=True))
        correlation = _correlation(headline, params, case.tcr, models, pairs)
        solved: dict[tuple[Side, float], RacewayTCR] = {}
        for (side, load), contact in pairs:
            sol = contact.solution
            with as_case_fields(tcr_fields(side)):
                if patch:
                    tcr = patch_tcr(sol.pressure, sol.dx, sol.dy, models[side])
                else:
                    tcr = contact_tcr(
                        sol.pressure,
                        sol.dx,
                        sol.dy,
                        models[side],
                        cell_size=cell_size,
                        load_threshold=case.tcr.load_threshold,
                        partial_cells=case.tcr.partial_cells,
                    )
            if correlation is None:  # an element model: its own cells (or patch) are the headline
                r, area = tcr.resistance, tcr.apparent_area
            else:
                r, area = correlation(contact, side), solved_contact_area(contact)
            solved[side, load] = RacewayTCR(contact, tcr, r, area)
        for nut, used in loaded:  # a lifted-off nut carries nothing
            screw_side = solved["screw", used.ball_load]
            nut_side = solved["nut", used.ball_load]
            approach = screw_side.contact.solution.approach + nut_side.contact.solution.approach
            nuts.append(
                NutTCR(
                    index=nut.index,
                    force=used.force,
                    ball_load=used.ball_load,
                    balls=params.flanks.balls,
                    screw=screw_side,
                    nut=nut_side,
                    axial_deflection=approach / params.axial_projection,
                    load_spread=used.spread,
                )
            )
        area = sum(n.apparent_area for n in nuts)
        compared, spread = compare_models(params, case.tcr, models, nuts, area, headline)
        films = ()
        if case.tcr.film_path != "none":
            films = nut_films(case, params, nuts, [n.index for n in flanks])
    return ScrewTCR(
        case_name=case.name,
        headline=headline,
        variant=models["screw"].variant,
        cell_size=cell_size,
        nut_forces=(chain[0].force, chain[1].force if len(chain) > 1 else 0.0),
        nuts=tuple(nuts),
        case=case,
        warnings=tuple(dict.fromkeys((*early, *messages))),
        models=compared,
        uncertainty=spread,
        films=films,
    )


def _correlation(
    headline: str,
    params: ScrewParameters,
    options: TCRSpec,
    models: dict[Side, FractalTCRModel],
    contacts: Iterable[tuple[tuple[Side, float], RacewayContact]],
) -> ContactResistance | None:
    """The headline correlation as a function of a solved contact; None for an element model.

    Refused (``tcr.headline``) when a contact reaches p/H ≥ 0.5, the end of its range."""
    if headline not in CORRELATIONS:
        return None
    outside = out_of_range(
        ((f"a ball of {q:.4g} N", side, c) for (side, q), c in contacts),
        {side: params.hardness(side) for side in SIDES},
    )
    if outside:
        raise InputError(
            "tcr.headline", headline, f"a model valid on this contact ({outside}): e.g. V2/patch"
        )
    return contact_model(headline, params, options, models)[0]


def tcr_scalars(case: Case) -> dict[str, tuple[float, str]]:
    """Sweepable scalars of :func:`screw_tcr` (case's headline) with their units: the headline
    micro TCR, the ball path without film and the one the thermal model takes
    (``heat_path_resistance``; with ``[tcr] film_path`` also ``ball_path_with_film``), and
    every rival model's R and R″ (``model_V2_patch_resistance`` for ``V2/patch``) with their
    spread (``uncertainty_low``, ``uncertainty_high``), so that a sweep carries the band."""
    result = screw_tcr(case)
    scalars = {
        "resistance": (result.resistance, "K/W"),
        "resistance_per_area": (result.resistance_per_area, "m^2*K/W"),
        "apparent_area": (result.apparent_area, "m^2"),
        "F1": (result.nut_forces[0], "N"),
        "F2": (result.nut_forces[1], "N"),
        "ball_path_without_film": (result.ball_path_without_film, "K/W"),
        "heat_path_resistance": (result.heat_path_resistance, "K/W"),
    }
    if result.ball_path_with_film is not None:
        scalars["ball_path_with_film"] = (result.ball_path_with_film, "K/W")
    for name, model in result.models.items():
        key = "model_" + name.replace("/", "_")
        scalars[f"{key}_resistance"] = (model.resistance, "K/W")
        scalars[f"{key}_resistance_per_area"] = (model.resistance_per_area, "m^2*K/W")
    if result.uncertainty is not None:
        scalars["uncertainty_low"] = (result.uncertainty.low, "m^2*K/W")
        scalars["uncertainty_high"] = (result.uncertainty.high, "m^2*K/W")
    for nut in result.nuts:
        scalars[f"nut{nut.index}_resistance"] = (nut.resistance, "K/W")
        scalars[f"nut{nut.index}_ball_load"] = (nut.ball_load, "N")
        if case.loads.distribution == "elastic":
            scalars[f"nut{nut.index}_ball_load_spread"] = (nut.load_spread, "")
    return scalars
