"""The lubricant film around each ball as a heat path beside its Hertz patch (``tcr.film_path``).

Per ball–raceway contact the film (P1) conducts in parallel with the patch path, the micro TCR
plus the macro-constriction (P3); the ball is one temperature between its screw and nut contact,
so the two contacts add in series and the balls of a nut in parallel. A lifted-off nut's balls
carry no load and conduct through their films alone (theory manual: *Contact resistance*,
*Film path around the ball*).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ballscrew.analyses.parameters import SIDES, ScrewParameters, Side, track_replenishment
from ballscrew.analyses.tcr_models import gaussian_joint
from ballscrew.case import Case
from ballscrew.contact_resistance.constriction import ball_contact_constriction
from ballscrew.contact_resistance.film_path import (
    FilmPath,
    ellipse_gap_conductance,
    groove_clearance,
    loaded_film_conductance,
    meniscus_thickness,
    wetted_semi_axes,
    with_film_path,
)
from ballscrew.geometry.curvature import raceway_curvature
from ballscrew.kinematics.motion import entrainment_speed
from ballscrew.lubrication.film import film_function
from ballscrew.lubrication.film_corrections import critical_inlet_ratio, equivalent_inlet_ratio

if TYPE_CHECKING:
    from ballscrew.analyses.screw_tcr import NutTCR, RacewayTCR


@dataclass(frozen=True)
class NutFilm:
    """The films of one ball of a nut, at its screw and its nut contact."""

    index: int
    balls: int
    screw: FilmPath
    nut: FilmPath
    loaded: bool
    """False for a lifted-off nut (its balls touch nothing; film only)."""
    radii: dict[Side, tuple[float, float]]
    """(R_x, R_y) of the ball against each raceway [m]."""

    @property
    def conductance(self) -> float:
        """All its balls' films, screw and nut film of a ball in series [W/K]."""
        g_s, g_n = self.screw.conductance, self.nut.conductance
        return 0.0 if g_s == 0.0 or g_n == 0.0 else self.balls / (1.0 / g_s + 1.0 / g_n)


@dataclass(frozen=True)
class NutHeatPath:
    """Screw-to-nut resistance of one nut's balls: the patch path (micro TCR plus
    macro-constriction) and, with films, the film path beside it (P3)."""

    index: int
    micro: float
    """Micro TCR of all balls, R_sbn/n_b (∞ lifted off) [K/W]."""
    constriction: float
    """Macro-constriction of all balls' patches (A6; 0 when left out) [K/W]."""
    resistance: float
    """The path the thermal model takes: :attr:`ball_path_with_film` with films, else
    :attr:`ball_path_without_film` [K/W]."""
    film: bool = False
    """Whether :attr:`resistance` has the film in parallel with each contact's patch path."""

    @property
    def ball_path_without_film(self) -> float:
        """Micro TCR plus macro-constriction, R_micro + R_cons [K/W]."""
        return self.micro + self.constriction

    @property
    def ball_path_with_film(self) -> float | None:
        """With the film in parallel with each contact's patch path (P3) [K/W]; None without
        films."""
        return self.resistance if self.film else None

    @property
    def without_film(self) -> float:
        """Older name of :attr:`ball_path_without_film` (kept) [K/W]."""
        return self.ball_path_without_film


def conductivities(case: Case) -> dict[str, float]:
    """λ of "ball", "screw" and "nut" [W/(m K)]."""
    mats = case.materials
    return {name: getattr(mats, name).thermal_conductivity for name in ("ball", *SIDES)}


def contact_constriction(raceway: RacewayTCR, lam: Mapping[str, float]) -> float:
    """Macro-constriction (A6) of one ball's Hertz patch on ``raceway``, into ball and raceway
    [K/W]; ``lam`` as :func:`conductivities`."""
    h = raceway.contact.hertz
    return ball_contact_constriction((h.a, h.b), lam["ball"], lam[raceway.contact.side])


def _central_film(
    params: ScrewParameters, case: Case, raceway: RacewayTCR, side: Side
) -> tuple[float, float] | None:
    """(|u_e| [m/s], central EHL film [m]) of a loaded contact at the case's speed, as supplied;
    None without EHL data or at rest."""
    lub = params.lubrication
    speed = abs(
        entrainment_speed(params.geometry, case.operating.speed, case.kinematics.entrainment, side)
    )
    if not lub.lubricated or speed == 0.0:
        return None
    c = raceway.contact
    film = film_function(lub.film_model)(
        c.curvature.rx,
        c.curvature.ry,
        2.0 * c.e_star,
        lub.viscosity,
        lub.pressure_viscosity,
        speed,
        c.load,
    )
    return speed, film.central


def _separation(params: ScrewParameters, case: Case, raceway: RacewayTCR, side: Side) -> float:
    """h0 of a loaded contact: the central EHL film at the case's speed when the medium has EHL
    data, else (or when thinner) the raceway's RMS roughness σ (the ball is smooth) [m]."""
    sigma = gaussian_joint(params, case.tcr, side).sigma
    film = _central_film(params, case, raceway, side)
    return sigma if film is None else max(sigma, film[1])


def _edge(params: ScrewParameters, case: Case, side: Side, raceway: RacewayTCR, h0: float) -> float:
    """h_max: the gap at the inlet meniscus of a starved or greased supply, else (flooded, or a
    meniscus beyond it) the groove-bottom clearance [m]. Fed by an oil layer h_oil,∞, the
    meniscus stands where the gap has closed to the layer (ASSUMED, mass conservation of a
    layer that fills the gap: Chevalier et al. 1998): h_max = max(h0, h_oil,∞)."""
    clearance = _clearance(params, side)
    if case.lubrication.layer is not None:
        return min(clearance, max(h0, case.lubrication.layer))
    m = case.lubrication.meniscus
    if m is None and case.lubrication.replenished:
        m = _replenished_meniscus(params, case, raceway, side)
    if m is None:
        return clearance
    hertz = raceway.contact.hertz
    return min(clearance, meniscus_thickness(hertz, *_radii(params, side), m, h0))


def _replenished_meniscus(
    params: ScrewParameters, case: Case, raceway: RacewayTCR, side: Side
) -> float | None:
    """The inlet ratio at which the meniscus rule (E6.7) thins the contact's central film as
    the kinematic replenishment of the greased track does, m = 1 + (m* − 1) φ_rs^(1/0.29);
    None (flooded edge) without EHL data or at rest."""
    lub = params.lubrication
    replenishment = track_replenishment(case, lub.density)
    film = _central_film(params, case, raceway, side)
    if film is None or replenishment is None or lub.viscosity is None:
        return None
    speed, central = film
    phi = replenishment.factor(lub.viscosity, speed)
    c = raceway.contact
    m_star = critical_inlet_ratio(c.curvature.rx, c.hertz.a, central / phi)
    return equivalent_inlet_ratio(phi, m_star)


def _clearance(params: ScrewParameters, side: Side) -> float:
    """Groove-bottom clearance of the ``side`` raceway [m]."""
    geometry = params.geometry
    return groove_clearance(
        geometry.ball_radius, geometry.groove_radius(side), geometry.contact_angle
    )


def _radii(params: ScrewParameters, side: Side) -> tuple[float, float]:
    """(R_x, R_y) of the ball against the ``side`` raceway (G17) [m]."""
    c = raceway_curvature(params.geometry, side)
    return c.rx, c.ry


def nut_films(
    case: Case, params: ScrewParameters, nuts: Sequence[NutTCR], indices: Sequence[int]
) -> tuple[NutFilm, ...]:
    """The film of every loaded flank of ``indices`` (a nut of a double nut; a flank of a
    preloaded single nut, ``params.flanks.balls`` balls); one missing from ``nuts`` (lifted
    off) is unloaded.

    A loaded contact's film fills the deformed Hertz gap from h0 (:func:`_separation`) to h_max
    (:func:`_edge`); contacts of equal side and ball load (both nuts at zero axial load) share
    one quadrature. A lifted-off ball: :func:`_lifted_edges`.
    """
    lam, rarefaction = params.lubrication.thermal_conductivity, params.lubrication.rarefaction
    radii = {side: _radii(params, side) for side in SIDES}
    solved: dict[tuple[Side, float], FilmPath] = {}
    loaded: dict[int, NutFilm] = {}
    for nut in nuts:
        paths = {}
        for side in SIDES:
            raceway = getattr(nut, side)
            key = (side, raceway.contact.load)
            if key not in solved:
                hertz = raceway.contact.hertz
                h0 = _separation(params, case, raceway, side)
                h_max = _edge(params, case, side, raceway, h0)
                g = loaded_film_conductance(lam, *radii[side], hertz, h0, h_max, rarefaction)
                solved[key] = FilmPath(g, h0, h_max)
            paths[side] = solved[key]
        loaded[nut.index] = NutFilm(nut.index, nut.balls, paths["screw"], paths["nut"], True, radii)
    edges = _lifted_edges(params, solved)
    films = []
    for index in indices:
        if index in loaded:
            films.append(loaded[index])
            continue
        paths = {}
        for side in SIDES:
            h0 = gaussian_joint(params, case.tcr, side).sigma
            g = ellipse_gap_conductance(lam, *radii[side], h0, edges[side], rarefaction)
            paths[side] = FilmPath(g, h0, edges[side])
        films.append(
            NutFilm(index, params.flanks.balls, paths["screw"], paths["nut"], False, radii)
        )
    return tuple(films)


def _lifted_edges(
    params: ScrewParameters, loaded: Mapping[tuple[Side, float], FilmPath]
) -> dict[Side, float]:
    """h_max of a lifted-off ball on each side [m], from the loaded contacts ``loaded``
    ((side, Q) → film).

    A lifted-off ball touches neither flank: it sees the undeformed paraboloid gap from
    h0 = σ (the clearance its nut's lift-off opens is left out: an upper bound on the film).
    How far the oil fills that gap is set by the supply, not by the ball's load: flooded, the
    groove-bottom clearance, as at a loaded contact; starved or greased, the oil layer the
    supply leaves on the track, which fixes where the inlet meniscus of a loaded ball forms
    (Wedeven, Evans & Cameron 1971; Chevalier, Lubrecht, Cann, Colin & Dalmaz 1998). The model
    knows that layer only as the gap at a loaded contact's meniscus, which varies with the load
    because the meniscus is placed m Hertz semi-axes upstream. The lifted ball takes the largest
    h_max of the loaded contacts on its side (the screw's track is one, the nuts' share the
    supply) — the same bound from above as h0 = σ, whatever the order or number of the nuts;
    with no loaded contact on the side, the groove-bottom clearance (the flooded limit).
    """
    edges = {side: _clearance(params, side) for side in SIDES}
    for side in SIDES:
        h_max = [film.h_max for (s, _), film in loaded.items() if s == side]
        if h_max:
            edges[side] = max(h_max)
    return edges


def _film_branch(
    film: FilmPath,
    radii: tuple[float, float],
    conductivities: Mapping[str, float],
    side: Side,
    constriction: bool,
) -> float:
    """Conductance of a contact's film branch: the film (P1) and, with ``constriction``, the
    spreading from the wetted ellipse into ball and raceway (A6) in series [W/K]."""
    if film.conductance == 0.0 or not constriction:
        return film.conductance
    cons = ball_contact_constriction(
        wetted_semi_axes(*radii, film.h_max), conductivities["ball"], conductivities[side]
    )
    return 1.0 / (1.0 / film.conductance + cons)


def heat_paths(
    nuts: Sequence[NutTCR],
    films: Sequence[NutFilm],
    conductivities: Mapping[str, float],
    micro: Mapping[int, float] | None = None,
    constriction: bool = True,
) -> tuple[NutHeatPath, ...]:
    """Each nut's screw-to-nut resistance, the film in parallel with each contact (P3).

    One path per nut of ``films`` (every nut, lifted-off ones included), or per loaded nut of
    ``nuts`` when there are no films (micro TCR + macro-constriction alone). The thermal model's
    interfaces and :meth:`ScrewTCR.heat_paths` both take their constriction from here.
    ``conductivities`` maps "ball", "screw", "nut" to λ [W/(m K)]; ``micro`` overrides the
    nuts' micro TCR R_sbn/n_b (another model's), split between the screw and nut contact in the
    headline model's proportion; ``constriction`` = False leaves out the macro-constriction of
    the patches and of the wetted ellipses (the latter an isothermal-ellipse bound: the film's
    heat crosses mostly near the patch, so its true spreading resistance is larger).
    """
    by_index = {n.index: n for n in nuts}
    by_film = {f.index: f for f in films}
    out = []
    for index in by_film or by_index:
        film = by_film.get(index)
        branches = {
            side: _film_branch(getattr(film, side), radii, conductivities, side, constriction)
            for side, radii in ({} if film is None else film.radii).items()
        }
        nut = by_index.get(index)
        if nut is None:  # lifted off: the films alone
            r_ball = sum(with_film_path(math.inf, g) for g in branches.values())
            out.append(NutHeatPath(index, math.inf, 0.0, r_ball / film.balls, True))
            continue
        own = {s: float(getattr(nut, s).resistance) for s in SIDES}
        total = micro[nut.index] * nut.balls if micro is not None else sum(own.values())
        r_ball = r_micro = r_cons = 0.0
        for side in SIDES:
            patch = total * own[side] / sum(own.values())
            r_micro += patch
            if constriction:
                cons = contact_constriction(getattr(nut, side), conductivities)
                r_cons += cons
                patch += cons
            r_ball += with_film_path(patch, branches.get(side, 0.0))
        out.append(
            NutHeatPath(
                nut.index, r_micro / nut.balls, r_cons / nut.balls, r_ball / nut.balls, bool(films)
            )
        )
    return tuple(out)
