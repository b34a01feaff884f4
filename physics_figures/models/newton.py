"""Newton's second law with constant mass, weight, lifts, rockets and towing.

Notes: "Understand it > Weight" and "How to do it > 1. Newton's laws, F = ma".
All quantities SI; forces and accelerations are signed along a chosen positive direction.
"""

from dataclasses import dataclass

import numpy as np

from ..constants import G_EARTH
from . import _checks as check


def acceleration(resultant_force, mass):
    """Acceleration from Newton's second law with constant mass: a = F / m.

    resultant_force: N, signed; mass: kg (> 0). Returns a in m s^-2, always in the
    direction of the resultant force. Raises ValueError for a mass <= 0 or a value that
    is not finite.
    """
    resultant_force = check.number("resultant_force", resultant_force, unit="N")
    return resultant_force / check.positive("mass", mass, unit="kg")


def weight(mass, *, g=G_EARTH):
    """Weight W = m g, the force on a mass due to a gravitational field.

    mass: kg (> 0); g: gravitational field strength, m s^-2 = N kg^-1 (> 0).
    Returns W in N. Raises ValueError for a mass or g <= 0 or a value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    return mass * check.positive("g", g, unit="m s^-2")


def mass_from_weight(weight, *, g=G_EARTH):
    """Mass from a weight: m = W / g (the mass is the same on every planet).

    weight: N (> 0); g: m s^-2 (> 0). Returns m in kg. Raises ValueError for a weight
    or g <= 0 or a value that is not finite.
    """
    weight = check.positive("weight", weight, unit="N")
    return weight / check.positive("g", g, unit="m s^-2")


def gravitational_field_strength(weight, mass):
    """Gravitational field strength (acceleration of free fall) g = W / m.

    weight: N (> 0); mass: kg (> 0). Returns g in N kg^-1 = m s^-2.
    Raises ValueError for a weight or mass <= 0 or a value that is not finite.
    """
    weight = check.positive("weight", weight, unit="N")
    return weight / check.positive("mass", mass, unit="kg")


def lift_contact_force(mass, acceleration_up, *, g=G_EARTH):
    """Contact force R of a lift floor on a passenger: R - m g = m a, so R = m (g + a).

    mass: kg (> 0); acceleration_up: m s^-2, signed, up positive (a = -g is free fall,
    R = 0); g: m s^-2 (> 0). Returns R in N (>= 0).
    Raises ValueError for a mass or g <= 0, an acceleration below -g (the floor would
    have to pull the passenger down), or a value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    g = check.positive("g", g, unit="m s^-2")
    acceleration_up = check.number("acceleration_up", acceleration_up, unit="m s^-2")
    check.require("acceleration_up", acceleration_up, acceleration_up >= -g,
                  f"must not be below -g = {-g!r} m s^-2 (a floor can only push up)",
                  unit="m s^-2")
    return mass * (g + acceleration_up)


#: The surfaces a ball bounces off vertically, and which way each pushes it.
BOUNCE_SURFACES = ("floor", "ceiling")


def bounce_contact_force(resultant_force, mass, *, surface, g=G_EARTH):
    """Average contact force of a floor or a ceiling on a ball bouncing off it vertically.

    The resultant force F (away from the surface) is the contact force R and the weight mg
    together. Off a floor R pushes up and mg pulls down: R - mg = F, so R = F + mg. Off a
    ceiling R and mg both act down: R + mg = F, so R = F - mg.

    resultant_force: N, the size of the average resultant force (> 0); mass: kg (> 0);
    surface: "floor" or "ceiling"; g: m s^-2 (> 0). Returns R in N (> 0).
    Raises ValueError for a surface not in BOUNCE_SURFACES, a force, mass or g <= 0, a
    ceiling whose resultant force is not above the weight (a ceiling can only push), or a
    value that is not finite.
    """
    if surface not in BOUNCE_SURFACES:
        raise ValueError(f"surface must be one of {BOUNCE_SURFACES} (got surface={surface!r})")
    resultant_force = check.positive("resultant_force", resultant_force, unit="N")
    ball_weight = weight(mass, g=g)
    if surface == "floor":
        return resultant_force + ball_weight
    check.require("resultant_force", resultant_force, resultant_force > ball_weight,
                  f"must be above the ball's weight mg = {ball_weight!r} N off a ceiling (a ceiling "
                  "can only push the ball down)", unit="N")
    return resultant_force - ball_weight


def thrust_for_acceleration(weight, acceleration_up, *, g=G_EARTH):
    """Upward thrust (or tension) that gives a vertical acceleration: T = W + (W/g) a.

    From T - W = m a with m = W / g. weight: N (> 0); acceleration_up: m s^-2, signed,
    up positive (not below -g); g: m s^-2 (> 0). Returns T in N (>= 0).
    Raises ValueError for a weight or g <= 0, an acceleration below -g (the thrust would
    have to pull down), or a value that is not finite.
    """
    weight = check.positive("weight", weight, unit="N")
    g = check.positive("g", g, unit="m s^-2")
    acceleration_up = check.number("acceleration_up", acceleration_up, unit="m s^-2")
    check.require("acceleration_up", acceleration_up, acceleration_up >= -g,
                  f"must not be below -g = {-g!r} m s^-2 (the thrust can only push up)",
                  unit="m s^-2")
    return weight + weight / g * acceleration_up


@dataclass(frozen=True)
class Towing:
    """A line of bodies pulled by one driving force (Notes, Example 1).

    acceleration: m s^-2, the common acceleration (forwards positive);
    resultant_force: N, driving force minus all resistive forces;
    tensions: N, tensions[i] is the tension in the link between body i and body i+1
    (a negative tension means the link is pushed: a tow bar in compression).
    """

    acceleration: float
    resultant_force: float
    tensions: tuple[float, ...]


def towing(driving_force, masses, resistive_forces):
    """Acceleration and link tensions for bodies towed in a line.

    Whole line: a = (F - ΣR) / Σm. Link i pulls everything behind it:
    T_i = Σ_{j>i} (m_j a + R_j).
    driving_force: N, on the front body (body 0); masses: kg (each > 0), front to back;
    resistive_forces: N (each >= 0), front to back, the same length as masses.
    Returns a Towing. towing(3000, (1200, 400), (400, 200)) gives a = 1.5 m s^-2 and
    tensions (800.0,) (Notes, Example 1).
    Raises ValueError for an empty or mismatched list, a mass <= 0, a negative
    resistive force or a value that is not finite.
    """
    driving_force = check.number("driving_force", driving_force, unit="N")
    masses = check.sequence("masses", masses, unit="kg")
    resistive_forces = check.sequence("resistive_forces", resistive_forces, unit="N")
    check.same_length(masses=masses, resistive_forces=resistive_forces)
    check.positive("masses", masses, unit="kg")
    check.non_negative("resistive_forces", resistive_forces, unit="N")
    resultant = driving_force - resistive_forces.sum()
    a = resultant / masses.sum()
    # Everything behind link i: bodies i+1 .. end (reverse cumulative sums).
    pulled = np.cumsum((masses * a + resistive_forces)[::-1])[::-1][1:]
    return Towing(float(a), float(resultant), tuple(float(t) for t in pulled))


def acceleration_from_distance(u, v, distance):
    """Constant acceleration that changes the speed from u to v over a distance: v² = u² + 2 a s.

    a = (v² - u²) / (2 s): negative when the body slows down (a deceleration of size
    (u² - v²) / 2s; a car stopping from u in s has a = -u² / 2s). Then F = m a gives the
    resultant (e.g. braking) force (Notes, How to do it 1., "Stopping distance with a
    constant force"). u, v: speeds, m s^-1 (>= 0, along the motion); distance: m (> 0).
    Returns a in m s^-2, signed (positive along the motion).
    Raises ValueError for a negative speed, a distance <= 0 or a value that is not finite.
    """
    u = check.non_negative("u", u, unit="m s^-1")
    v = check.non_negative("v", v, unit="m s^-1")
    distance = check.positive("distance", distance, unit="m")
    return (v**2 - u**2) / (2 * distance)


def applied_force(resultant_force, opposing_force):
    """The force that, against an opposing force, leaves a resultant: F = F_resultant + F_opposing.

    A block dragged against a constant friction (9702/21/M/J/23 Q3: the pull X is the
    momentum-time graph's gradient plus the 2.0 N friction), or a floor pushing a ball up
    against its weight. resultant_force: N, signed along the applied force; opposing_force:
    N (>= 0), against it. Returns the applied force in N.
    Raises ValueError for a negative opposing force or a value that is not finite.
    """
    resultant_force = check.number("resultant_force", resultant_force, unit="N")
    return resultant_force + check.non_negative("opposing_force", opposing_force, unit="N")
