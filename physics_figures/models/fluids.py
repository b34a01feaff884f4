# ruff: noqa: RUF001, RUF002, RUF003  (the physics in its own Greek letters and signs)
"""Upthrust, and the forces on a body falling through a fluid at terminal velocity.

Notes: "Key facts" (upthrust F = ρgV, from Forces, density and pressure) and
"Understand it > Friction, drag and terminal velocity" (in a liquid, at terminal
velocity: weight = drag + upthrust). All quantities SI.
"""

from ..constants import G_EARTH
from . import _checks as check


def upthrust(fluid_density, volume, *, g=G_EARTH):
    """Upthrust U = ρ g V on a body of volume V wholly in a fluid of density ρ.

    fluid_density: kg m^-3 (> 0), the density of the fluid, not of the body;
    volume: m^3 (> 0); g: m s^-2 (> 0). Returns U in N (upwards; it does not depend
    on the speed). Raises ValueError for a value <= 0 or not finite.
    """
    fluid_density = check.positive("fluid_density", fluid_density, unit="kg m^-3")
    volume = check.positive("volume", volume, unit="m^3")
    return fluid_density * check.positive("g", g, unit="m s^-2") * volume


def drag_at_terminal_velocity(weight, upthrust=0.0):
    """Drag on a body falling at terminal velocity: resultant zero, so D = W - U.

    weight: N (> 0); upthrust: N (>= 0, less than the weight, or the body would not
    sink). Returns D in N (upwards). Raises ValueError otherwise.
    """
    weight = check.positive("weight", weight, unit="N")
    upthrust = check.non_negative("upthrust", upthrust, unit="N")
    check.require("upthrust", upthrust, upthrust < weight,
                  f"must be less than the weight ({weight!r} N), or the body floats up", unit="N")
    return weight - upthrust


# ---------------------------------------------------------------- how a ball meets the air or a liquid

#: Air near the ground at about 20 °C, kg m^-3 (the density 9702/21/M/J/24 Q1 gives).
AIR_DENSITY = 1.2
#: The drag coefficient C of a smooth sphere in D = (1/2) C ρ A v², at the speeds a dropped ball
#: reaches (Reynolds numbers of about 10³ to 2 × 10⁵, where C stays close to 0.47).
SPHERE_DRAG_COEFFICIENT = 0.47
#: Stokes' law F = 6πηrv holds for creeping flow, a Reynolds number (ρvd / η, d the diameter)
#: well below 1. Oseen's first correction multiplies the drag by (1 + 3Re/16): at Re = 0.1 that
#: is 2 %, the last figure a 2 s.f. key can show, so the bank keeps Re below 0.1.
STOKES_REYNOLDS_LIMIT = 0.1


def sphere_drag_constant(diameter, *, drag_coefficient=SPHERE_DRAG_COEFFICIENT, fluid_density=AIR_DENSITY):
    """The constant k of D = k v² for a sphere: k = (1/2) C ρ A, with A = π d² / 4 its cross-section.

    diameter d: m (> 0); drag_coefficient C: no unit (> 0); fluid_density ρ: kg m^-3 (> 0).
    Returns k in kg m^-1. Raises ValueError for a value <= 0 or not finite.
    """
    diameter = check.positive("diameter", diameter, unit="m")
    drag_coefficient = check.positive("drag_coefficient", drag_coefficient)
    fluid_density = check.positive("fluid_density", fluid_density, unit="kg m^-3")
    return 0.5 * drag_coefficient * fluid_density * 3.141592653589793 * diameter**2 / 4


def reynolds_number(fluid_density, speed, diameter, viscosity):
    """Re = ρ v d / η for a sphere of diameter d moving at v through a fluid (no unit).

    fluid_density ρ: kg m^-3 (> 0); speed v: m s^-1 (>= 0); diameter d: m (> 0); viscosity η:
    Pa s (> 0). Raises ValueError for a value out of range or not finite.
    """
    fluid_density = check.positive("fluid_density", fluid_density, unit="kg m^-3")
    speed = check.non_negative("speed", speed, unit="m s^-1")
    diameter = check.positive("diameter", diameter, unit="m")
    return fluid_density * speed * diameter / check.positive("viscosity", viscosity, unit="Pa s")


def stokes_reynolds_number(fluid_density, speed, diameter, viscosity):
    """The Reynolds number of a sphere whose drag is given by Stokes' law, checked: below
    STOKES_REYNOLDS_LIMIT (creeping flow), else the law does not describe its drag.

    Arguments as reynolds_number. Returns Re. Raises ValueError naming the Reynolds number, its
    value and the rule when Re is not below the limit (or for an argument out of range).
    """
    reynolds = reynolds_number(fluid_density, speed, diameter, viscosity)
    check.require("reynolds_number", reynolds, reynolds < STOKES_REYNOLDS_LIMIT,
                  f"must be below {STOKES_REYNOLDS_LIMIT:g} for Stokes' law F = 6πηrv to hold (creeping "
                  f"flow; at Re = {STOKES_REYNOLDS_LIMIT:g} Oseen's correction 3Re/16 is already 2 %): "
                  f"ρvd/η with ρ={fluid_density!r} kg m^-3, v={speed!r} m s^-1, d={diameter!r} m, "
                  f"η={viscosity!r} Pa s")
    return reynolds
