"""One surface, two conventions for its G (theory manual, *Fractal contact*, roughness
conventions): ``surface.G_convention`` says whether the case's G (raceway, rough ball, the
running-in's initial surface) is the Majumdar–Bhushan profile G or the 3-D Yan–Komvopoulos
surface G; each chain gets the G of its own model, converted once at the parameters layer."""

from __future__ import annotations

import tomllib
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import ballscrew
from ballscrew.analyses.kinematics import ball_model
from ballscrew.analyses.parameters import ScrewParameters
from ballscrew.analyses.surface import surface_characterisation
from ballscrew.analyses.wear import wear_setup
from ballscrew.case import CaseError, case_from_dict, with_overrides
from ballscrew.fractal import majumdar_bhushan as mb
from ballscrew.fractal import yan_komvopoulos as yk
from ballscrew.fractal.conventions import surface_roughness_from_profile

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GAO = EXAMPLES / "gao2019_tcr.toml"
WEAR = EXAMPLES / "wear_step_stress.toml"
PROFILE = EXAMPLES / "profiles" / "synthetic_wm_D1.59_G9e-10.sdf"
SPEED = 10.0 * np.pi / 3.0  # 100 rpm [rad/s]

#: A rough raceway, a rough ball and an as-machined raceway, each as profile (D, G) [m].
RACEWAY, BALL, INITIAL = (1.4, 1.0e-10), (1.3, 5.0e-11), (1.5, 1.0e-9)


def _without_convention(path: Path) -> dict[str, Any]:
    """The example case at ``path`` as a raw table, without its ``surface.G_convention``."""
    with path.open("rb") as fh:
        raw = tomllib.load(fh)
    del raw["surface"]["G_convention"]
    return raw


def _both(case, fields: dict[str, tuple[float, float]], extra: dict[str, object] | None = None):
    """The case with the profile (D, G) of ``fields`` and the same surfaces given as their 3-D
    surface G under ``G_convention = 'surface'``."""
    extra = extra or {}
    profile = {f"{k}.D": d for k, (d, _) in fields.items()}
    surface = dict(profile)
    for key, (d, g) in fields.items():
        profile[f"{key}.G"] = g
        surface[f"{key}.G"] = surface_roughness_from_profile(d, g)
    return (
        with_overrides(case, {**profile, **extra, "surface.G_convention": "profile"}),
        with_overrides(case, {**surface, **extra, "surface.G_convention": "surface"}),
    )


def test_the_default_is_the_profile_g_of_a_measured_profile() -> None:
    """Without ``G_convention`` the case's G is the profile G: the TCR models read it as given,
    the asperity model the 3-D G of the same σ, 1.87 × at D = 1.59 (theory manual)."""
    case = case_from_dict(_without_convention(GAO))
    assert "G_convention" not in case.surface.model_fields_set
    assert case.surface.G_convention == "profile"
    params = ScrewParameters.from_case(case)
    assert params.G == 9e-10
    assert params.G_surface / params.G == pytest.approx(1.87, abs=0.005)
    assert ball_model(case).surface.G == params.G_surface


def test_an_unknown_convention_is_one_line_naming_field_value_and_choices() -> None:
    with pytest.raises(CaseError) as err:
        ballscrew.load_case(GAO, {"surface.G_convention": "areal"})
    message = str(err.value)
    assert "\n" not in message.strip()
    assert "surface.G_convention = 'areal'" in message
    assert "'profile' or 'surface'" in message


def test_tcr_and_ball_model_agree_across_the_conventions() -> None:
    """The Gao et al. raceway as its profile G and as its 3-D surface G: one TCR, one load
    sharing of the ball model (G and σ_Λ of the film parameter), to 1e-9."""
    base = ballscrew.load_case(GAO, {"numerics.cells_across": 16})
    profile, surface = _both(base, {"surface": (1.59, 9e-10)})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r_p, r_s = ballscrew.screw_tcr(profile), ballscrew.screw_tcr(surface)
    assert r_s.resistance == pytest.approx(r_p.resistance, rel=1e-9)
    for name, model in r_p.models.items():
        assert r_s.models[name].resistance_per_area == pytest.approx(
            model.resistance_per_area, rel=1e-9
        ), name
    assert r_s.summary()["options"]["surface"]["G_profile"]["value"] == pytest.approx(
        9e-10, rel=1e-12
    )
    m_p, m_s = ball_model(profile), ball_model(surface)
    assert m_s.surface.G == pytest.approx(m_p.surface.G, rel=1e-12)
    assert m_s.surface.film_roughness == pytest.approx(m_p.surface.film_roughness, rel=1e-12)
    sigma = m_p.surface.film_roughness
    h = np.array([0.5, 1.0, 2.0]) * sigma
    for heights in ("film_heights", "surface"):  # the ball model's and the wear cell's
        p_p = getattr(m_p.surface, heights) if heights != "surface" else m_p.surface
        p_s = getattr(m_s.surface, heights) if heights != "surface" else m_s.surface
        assert np.all(p_p.pressure(h) > 0.0)
        np.testing.assert_allclose(p_s.pressure(h), p_p.pressure(h), rtol=1e-9)


def test_wear_agrees_across_the_conventions_with_a_rough_ball_and_running_in() -> None:
    """Raceway, rough ball and as-machined surface as profile G and as 3-D surface G: one wear
    history (load sharing on σ_Λ, the wear law on the surface G, the running-in law) to 1e-9;
    read the other way, the same numbers would wear a different raceway."""
    base = ballscrew.load_case(
        WEAR,
        {
            "wear.grid": [8, 32],
            "wear.programme": [{"axial_load": 3000.0, "speed": SPEED, "revolutions": 1e5}],
            "wear.torque_sampling": 5e4,
            "wear.asperity_roughness": "film",
            "wear.running_in": {"D": INITIAL[0], "G": INITIAL[1], "depth": 2e-8},
        },
    )
    fields = {"surface": RACEWAY, "surface.ball": BALL, "wear.running_in": INITIAL}
    profile, surface = _both(base, fields)
    w_p, w_s = ballscrew.wear_life(profile), ballscrew.wear_life(surface)
    assert w_p.life.max_wear_depth[-1] > 1e-9
    np.testing.assert_allclose(w_s.life.max_wear_depth, w_p.life.max_wear_depth, rtol=1e-9)
    np.testing.assert_allclose(w_s.life.preload, w_p.life.preload, rtol=1e-9)
    s_p, s_s = wear_setup(profile), wear_setup(surface)
    assert s_s.surface_at(1e-8).film_roughness == pytest.approx(
        s_p.surface_at(1e-8).film_roughness, rel=1e-12
    )
    options = w_p.summary()["options"]
    assert options["surface"]["G_convention"] == "profile"
    assert options["surface"]["G_surface"]["value"] == pytest.approx(
        surface_roughness_from_profile(*RACEWAY), rel=1e-12
    )
    assert options["running_in"]["G_surface"]["value"] == pytest.approx(
        surface_roughness_from_profile(*INITIAL), rel=1e-12
    )
    unconverted = with_overrides(profile, {"surface.G_convention": "surface"})
    depth = ballscrew.wear_life(unconverted).life.max_wear_depth[-1]
    assert abs(depth / w_p.life.max_wear_depth[-1] - 1.0) > 1e-3


def test_a_measured_profile_reaches_the_wear_law_as_its_surface_g() -> None:
    """``ballscrew surface`` fits the example profile's (D, G), a profile G; in a case with the
    default convention the wear law's 3-D surface (E5.3) has the RMS height of that profile
    over its length L (F3), the one the TCR correlations read, and the profile's own σ within
    25 % (the W–M sum is discrete in frequency); the profile G read as a surface G would give
    0.69 × that σ."""
    measured = surface_characterisation(PROFILE)  # the ``ballscrew surface`` analysis
    profile, fit = measured.profile, measured.fit
    recommended = measured.summary()["recommended"]
    assert recommended["G"]["value"] == fit.G
    heights = np.atleast_2d(np.asarray(profile.heights))
    length = heights.shape[1] * profile.spacing
    own_sigma = float(np.sqrt(np.mean(np.var(heights, axis=1))))
    case = case_from_dict(_without_convention(WEAR), {"surface.D": fit.D, "surface.G": fit.G})
    assert case.surface.G_convention == "profile"
    surface = wear_setup(case).surface
    assert surface.G == pytest.approx(recommended["G_surface"]["value"], rel=1e-12)
    sigma = yk.rms_height(surface.Ds, surface.G, length)
    assert sigma == pytest.approx(mb.profile_rms_roughness(fit.D, fit.G, length), rel=1e-9)
    assert sigma == pytest.approx(own_sigma, rel=0.25)
    assert yk.rms_height(surface.Ds, fit.G, length) / sigma == pytest.approx(0.69, abs=0.01)
