"""The film of a contact as supplied: flooded, starved or greased, with or without inlet heating.

:func:`supplied_film_model` binds a registered film model (``medium.film_model``) to the supply
state of the case's ``[lubrication]`` section and returns a model with the registry signature
``(rx, ry, E′, η₀, α_p, u_e, Q_f) → FilmThickness``, which the kinematics, friction and wear
chains use wherever they take a film model:

    h = φ_S · φ_T · h_model,

* φ_T — inlet shear heating, Gupta et al. (1992) (:func:`~ballscrew.lubrication.film_corrections.
  thermal_reduction_gupta`), from the thermal loading L = β η₀ u_e²/λ of the lubricant;
* φ_S — starvation by an inlet meniscus at m Hertz semi-axes from the contact centre, Hamrock &
  Dowson (1977, Part IV) (:func:`~ballscrew.lubrication.film_corrections.starvation_factor`,
  central and minimum films each with their own critical distance m*, computed from the film
  before starvation).

A greased contact is taken as its base oil's film (Harris & Kotzalas 2007), starved at an inlet
meniscus m (a GUESS default, ``ballscrew.case.lubrication_spec``): the published grease
replenishment models (Chevalier et al. 1998; Damiens et al. 2004; van Zoelen, Venner & Lugt
2009) need the thickness of the oil layer on the track, which ballscrew does not predict.
"""

from __future__ import annotations

from dataclasses import replace

from ballscrew.contact.hertz import hamrock_brewe
from ballscrew.errors import InputError
from ballscrew.lubrication.film import FilmModel, FilmThickness, film_function
from ballscrew.lubrication.film_corrections import (
    critical_inlet_ratio,
    starvation_factor,
    thermal_loading,
    thermal_reduction_gupta,
)
from ballscrew.validation import nonnegative, positive

__all__ = ["supplied_film_model"]


def supplied_film_model(
    base: str | FilmModel,
    inlet_ratio: float | None = None,
    thermal: tuple[float, float] | None = None,
) -> str | FilmModel:
    """``base`` corrected for a starved inlet at ``inlet_ratio`` m (None: flooded) and, when
    ``thermal`` = (β [1/K], λ [W/(m K)]) of the lubricant at the inlet is given, for inlet shear
    heating. Nothing to correct returns ``base`` itself (a registered name stays a name)."""
    if inlet_ratio is None and thermal is None:
        return base
    if inlet_ratio is not None and not float(inlet_ratio) >= 1.0:
        raise InputError(
            "lubrication.inlet_ratio", inlet_ratio, ">= 1 (meniscus outside the Hertz zone)"
        )
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
        return replace(out, central=out.central * central, minimum=out.minimum * minimum)

    return film
