# ruff: noqa: RUF002  (docstrings write the physics in its own Greek letters)
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
