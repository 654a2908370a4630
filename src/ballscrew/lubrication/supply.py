"""The film of a contact as supplied: flooded, starved or greased, with or without inlet heating.

:func:`supplied_film_model` binds a registered film model (``medium.film_model``) to the supply
state of the case's ``[lubrication]`` section and returns a model with the registry signature
``(rx, ry, E′, η₀, α_p, u_e, Q_f) → FilmThickness``, which the kinematics, friction and wear
chains use wherever they take a film model:

    h = φ_S · φ_T · h_model,

* φ_T — inlet shear heating, Gupta et al. (1992) (:func:`~ballscrew.lubrication.film_corrections.
  thermal_reduction_gupta`), from the thermal loading L = β η₀ u_e²/λ of the lubricant;
* φ_S — starvation, either by an inlet meniscus at m Hertz semi-axes from the contact centre,
  Hamrock & Dowson (1977, Part IV) (:func:`~ballscrew.lubrication.film_corrections.
  starvation_factor`, central and minimum films each with their own critical distance m*,
  computed from the film before starvation), or by a known oil layer h_oil,∞ on the track,
  Chevalier et al. (1998) and Damiens et al. (2004) (:func:`~ballscrew.lubrication.
  film_corrections.layer_starvation_factor`, from the central film before starvation and ρ̄
  at the Hertz peak pressure, applied to the central and the minimum film alike), or by
  kinematic replenishment of the track (:class:`Replenishment`, the factor φ_rs of the SKF
  model of the frictional moment, SKF Group, *Rolling bearings*, 2013): the default of a
  greased contact.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ballscrew.contact.hertz import hamrock_brewe
from ballscrew.errors import InputError
from ballscrew.lubrication.film import FilmModel, FilmThickness, film_function
from ballscrew.lubrication.film_corrections import (
    REPLENISHMENT_GEOMETRY,
    REPLENISHMENT_GREASE,
    critical_inlet_ratio,
    dowson_higginson_density,
    layer_starvation_factor,
    replenishment_factor,
    starvation_factor,
    thermal_loading,
    thermal_reduction_gupta,
)
from ballscrew.validation import nonnegative, positive

__all__ = ["SECTION_PER_BALL", "Replenishment", "supplied_film_model"]

#: (D − d)/D_w, the bearing section a ball screw's ball stands for in the SKF replenishment
#: factor: GUESS, the ratio of deep-groove ball bearings of the 62 and 63 series (D_w/(D − d)
#: ≈ 0.28–0.32, e.g. 6205: 7.94 mm balls, D − d = 27 mm), taken as 1/0.3.
SECTION_PER_BALL = 1.0 / 0.3


@dataclass(frozen=True)
class Replenishment:
    """Kinematic replenishment of a ball screw's track: the SKF factor φ_rs
    (:func:`~ballscrew.lubrication.film_corrections.replenishment_factor`) as a film factor.

    ASSUMED adaptation of the bearing model: the screw is the rotating ring (n = ω, the screw
    speed), d_m the pitch diameter, D − d = :data:`SECTION_PER_BALL` · D_w; φ_rs, which SKF
    applies to the rolling frictional moment, scales the central and the minimum film alike.
    The screw speed is recovered from the entrainment speed u_e the film model is called with
    (u_e ∝ ω at Level 0), and ν = η₀/ρ from its inlet viscosity, so speed curves and heated
    inlets see their own φ_rs.
    """

    pitch_diameter: float
    """d_m [m]."""
    ball_diameter: float
    """D_w [m]."""
    density: float
    """ρ of the oil (of a grease: its base oil) at the inlet [kg/m³]."""
    speed_per_entrainment: float
    """ω/u_e of the screw at Level 0 [rad/m]."""
    constant: float = REPLENISHMENT_GREASE
    """K_rs: 6·10⁻⁸ grease and oil–air, 3·10⁻⁸ oil bath and oil jet (SKF 2013)."""
    geometry: float = REPLENISHMENT_GEOMETRY
    """K_Z (SKF 2013), ASSUMED as for four-point contact ball bearings."""

    def factor(self, viscosity: float, entrainment_speed: float) -> float:
        """φ_rs at the inlet viscosity η₀ [Pa s] and entrainment speed u_e [m/s]."""
        return replenishment_factor(
            viscosity / positive("density", self.density, "kg/m^3"),
            abs(entrainment_speed) * self.speed_per_entrainment,
            self.pitch_diameter,
            SECTION_PER_BALL * self.ball_diameter,
            self.constant,
            self.geometry,
        )


def supplied_film_model(
    base: str | FilmModel,
    inlet_ratio: float | None = None,
    thermal: tuple[float, float] | None = None,
    replenishment: Replenishment | None = None,
    inlet_layer: float | None = None,
) -> str | FilmModel:
    """``base`` corrected for a starved inlet at ``inlet_ratio`` m or fed by an oil layer of
    ``inlet_layer`` h_oil,∞ [m] on the track (at most one; None: flooded), for the kinematic
    ``replenishment`` of the track (None: none) and, when ``thermal`` = (β [1/K],
    λ [W/(m K)]) of the lubricant at the inlet is given, for inlet shear heating. Nothing to
    correct returns ``base`` itself (a registered name stays a name)."""
    if inlet_ratio is None and thermal is None and replenishment is None and inlet_layer is None:
        return base
    if inlet_ratio is not None and not float(inlet_ratio) >= 1.0:
        raise InputError(
            "lubrication.inlet_ratio", inlet_ratio, ">= 1 (meniscus outside the Hertz zone)"
        )
    if inlet_layer is not None:
        if inlet_ratio is not None:
            raise InputError(
                "lubrication.inlet_layer", inlet_layer, "not together with inlet_ratio (give one)"
            )
        nonnegative("lubrication.inlet_layer", inlet_layer, "m")
    if thermal is not None:
        nonnegative("temperature_viscosity", thermal[0], "1/K")
        positive("conductivity", thermal[1], "W/(m K)")
    model = film_function(base)

    def film(
        rx: float,
        ry: float,
        e_prime: float,
        viscosity: float,
        pressure_viscosity: float,
        entrainment_speed: float,
        load: float,
    ) -> FilmThickness:
        out = model(rx, ry, e_prime, viscosity, pressure_viscosity, entrainment_speed, load)
        hertz = hamrock_brewe(rx, ry, 0.5 * e_prime, load) if load > 0.0 else None
        central = minimum = 1.0
        if thermal is not None and hertz is not None:
            loading = thermal_loading(thermal[0], viscosity, entrainment_speed, thermal[1])
            central = minimum = thermal_reduction_gupta(loading, hertz.p0 / e_prime)
        if inlet_ratio is not None and hertz is not None:
            b = hertz.a  # semi-axis along the rolling direction x
            central *= starvation_factor(
                inlet_ratio, critical_inlet_ratio(rx, b, out.central * central, True), True
            )
            minimum *= starvation_factor(
                inlet_ratio, critical_inlet_ratio(rx, b, out.minimum * minimum, False), False
            )
        if inlet_layer is not None and hertz is not None:
            supplied = layer_starvation_factor(
                inlet_layer, out.central * central, dowson_higginson_density(hertz.p0)
            )
            central *= supplied
            minimum *= supplied
        if replenishment is not None:
            supplied = replenishment.factor(viscosity, entrainment_speed)
            central *= supplied
            minimum *= supplied
        return replace(out, central=out.central * central, minimum=out.minimum * minimum)

    return film
