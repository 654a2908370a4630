"""Coolant through a bore of the screw shaft (hollow-shaft cooling) and its fluids (Q11).

The coolant enters the bore at one end with the inlet rise θ_in over ambient and warms along the
bore by the energy balance of a plug flow, ṁ c_p dθ_c/dz = h π d_i (θ_wall − θ_c) (Incropera &
DeWitt, *Fundamentals of Heat and Mass Transfer*, 6th ed., 2007, Sec. 8.3). The bore coefficient
h comes from the pipe correlations (Gnielinski 1976, Dittus & Boelter 1930) at the coolant's
Reynolds number, or the fully developed laminar value below Re = 2300. SI throughout; theory
manual ``docs/theory/thermal.md``, *Hollow-shaft coolant*.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

from ballscrew.errors import InputError
from ballscrew.thermal.boundary import dittus_boelter, gnielinski
from ballscrew.validation import nonnegative, positive

LAMINAR_LIMIT = 2300.0
"""Reynolds number below which the bore flow is laminar."""

TURBULENT_LIMIT = 3000.0
"""Reynolds number from which the turbulent correlation is used (blend in between)."""

REYNOLDS_MAX = 5e6
"""Highest Reynolds number of the turbulent correlations (Gnielinski 1976: 3000 ≤ Re ≤ 5·10⁶)."""

NU_LAMINAR = {"temperature": 3.66, "flux": 4.36}
"""Fully developed laminar Nu of a circular tube at uniform wall temperature or heat flux
(Incropera & DeWitt 2007, Eqs. 8.53 and 8.55)."""


@dataclass(frozen=True)
class Fluid:
    """Properties of a coolant at its working temperature (SI)."""

    density: float
    """ρ [kg/m³]."""
    specific_heat: float
    """c_p [J/(kg K)]."""
    viscosity: float
    """Dynamic viscosity μ [Pa s]."""
    conductivity: float
    """λ [W/(m K)]."""

    def __post_init__(self) -> None:
        for name in ("density", "specific_heat", "viscosity", "conductivity"):
            positive(f"fluid.{name}", getattr(self, name))

    @property
    def prandtl(self) -> float:
        """Pr = μ c_p / λ [-]."""
        return self.viscosity * self.specific_heat / self.conductivity


FLUIDS: dict[str, Fluid] = {
    # saturated water at 300 K (Incropera & DeWitt 2007, Table A.6)
    "water": Fluid(997.0, 4179.0, 855e-6, 0.613),
    # ISO VG 10 and VG 32 mineral spindle oils at 40 °C: ν = 10 and 32 mm²/s by definition
    # (ISO 3448); ρ, c_p, λ typical of mineral oils (GUESS: 850 kg/m³, 1950 J/(kg K), 0.13 W/(m K))
    "oil VG 10": Fluid(850.0, 1950.0, 850.0 * 10e-6, 0.13),
    "oil VG 32": Fluid(857.0, 1950.0, 857.0 * 32e-6, 0.13),
}
"""Named coolants."""


def fluid(name: str) -> Fluid:
    """The named coolant of :data:`FLUIDS`."""
    if name not in FLUIDS:
        raise InputError("thermal.shaft_coolant.fluid", name, f"one of {', '.join(FLUIDS)}")
    return FLUIDS[name]


def bore_nusselt(
    reynolds: float,
    prandtl: float,
    correlation: Literal["gnielinski", "dittus_boelter"] = "gnielinski",
    wall: Literal["temperature", "flux"] = "flux",
) -> float:
    """Nusselt number of the bore flow [-].

    Laminar (Re ≤ 2300): Nu = 4.36 (uniform wall heat flux) or 3.66 (uniform wall temperature);
    turbulent (Re ≥ 3000): Gnielinski (1976) or Dittus–Boelter (1930) with n = 0.4 (coolant
    heated); linear in Re in between. The shaft's friction heat enters the bore as a nearly
    uniform flux, hence the default ``wall = "flux"``.
    """
    nonnegative("reynolds", reynolds)
    laminar = NU_LAMINAR[wall]
    if reynolds <= LAMINAR_LIMIT:
        return laminar

    def turbulent(re: float) -> float:
        return (
            gnielinski(re, prandtl) if correlation == "gnielinski" else dittus_boelter(re, prandtl)
        )

    if reynolds >= TURBULENT_LIMIT:
        return turbulent(reynolds)
    t = (reynolds - LAMINAR_LIMIT) / (TURBULENT_LIMIT - LAMINAR_LIMIT)
    return (1.0 - t) * laminar + t * turbulent(TURBULENT_LIMIT)


@dataclass(frozen=True)
class BoreFlow:
    """A coolant flow through a bore: its Reynolds number and heat-transfer coefficient."""

    diameter: float
    """Bore diameter d_i [m]."""
    flow_rate: float
    """Volumetric flow V̇ [m³/s]."""
    fluid: Fluid

    def __post_init__(self) -> None:
        positive("thermal.shaft_coolant.bore_diameter", self.diameter, "m")
        positive("thermal.shaft_coolant.flow_rate", self.flow_rate, "m³/s")
        if self.reynolds > REYNOLDS_MAX:
            most = self.flow_rate * REYNOLDS_MAX / self.reynolds
            raise InputError(
                "thermal.shaft_coolant.flow_rate",
                self.flow_rate,
                f"at most {most:.3g} m³/s through a {self.diameter * 1e3:g} mm bore: Re = "
                f"{self.reynolds:.3g} is above {REYNOLDS_MAX:g}, the pipe correlations' range",
            )

    @property
    def velocity(self) -> float:
        """Mean velocity u = 4V̇/(π d_i²) [m/s]."""
        return 4.0 * self.flow_rate / (math.pi * self.diameter**2)

    @property
    def reynolds(self) -> float:
        """Re = ρ u d_i / μ [-]."""
        return self.fluid.density * self.velocity * self.diameter / self.fluid.viscosity

    @property
    def capacity_rate(self) -> float:
        """Heat capacity rate W = ṁ c_p = ρ V̇ c_p [W/K]."""
        return self.fluid.density * self.flow_rate * self.fluid.specific_heat

    def coefficient(
        self,
        correlation: Literal["gnielinski", "dittus_boelter"] = "gnielinski",
        wall: Literal["temperature", "flux"] = "flux",
    ) -> float:
        """h = Nu λ / d_i [W/(m² K)] (:func:`bore_nusselt`)."""
        nu = bore_nusselt(self.reynolds, self.fluid.prandtl, correlation, wall)
        return nu * self.fluid.conductivity / self.diameter


@dataclass(frozen=True)
class ShaftCoolant:
    """Coolant in an axial bore of the screw shaft, entering at z = 0 (thermal problem input)."""

    bore_radius: float
    """Radius r_i of the bore [m] (< shaft radius)."""
    coefficient: float
    """h of the bore wall [W/(m² K)]."""
    capacity_rate: float
    """ṁ c_p of the flow [W/K]."""
    inlet_rise: float = 0.0
    """Inlet temperature − ambient θ_in [K]."""

    def __post_init__(self) -> None:
        positive("thermal.shaft_coolant.bore_diameter", 2.0 * self.bore_radius, "m")
        nonnegative("thermal.shaft_coolant.coefficient", self.coefficient, "W/(m² K)")
        # ṁ c_p has no case field of its own: the case sets it by its flow rate
        rate = "W/K (ṁ c_p = ρ V̇ c_p of thermal.shaft_coolant.flow_rate)"
        positive("shaft_coolant.capacity_rate", self.capacity_rate, rate)


def bore_outlet_rise(
    wall_rise: float, inlet_rise: float, coefficient: float, perimeter_length: float, rate: float
) -> float:
    """Outlet rise of a bore with a uniform wall rise θ_w (the closed form of Q11) [K].

        θ_out = θ_w − (θ_w − θ_in) exp(−h π d_i L / (ṁ c_p))

    ``perimeter_length`` is the wetted area π d_i L [m²], ``rate`` ṁ c_p [W/K] (Incropera & DeWitt
    2007, Eq. 8.42).
    """
    ntu = coefficient * perimeter_length / positive("rate", rate, "W/K")
    return wall_rise - (wall_rise - inlet_rise) * math.exp(-ntu)
