"""Momentum in two dimensions (Notes, "Momentum in two dimensions" and Example 4).

Momentum is conserved separately along the original line of motion and across it.
Angles are in degrees, measured from the original line of motion; momenta in N s
(= kg m s^-1); masses in kg; speeds in m s^-1; energies in J.
"""

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from . import _checks as check


def components(magnitude, angle_deg):
    """Components of a vector: along = p cos θ, across = p sin θ.

    magnitude: size of the vector (>= 0), e.g. N s; angle_deg: degrees from the original
    line (signed; scalar or array). Returns (along, across) in the unit of magnitude.
    Raises ValueError for a negative magnitude or a value that is not finite.
    """
    magnitude = check.non_negative("magnitude", magnitude)
    theta = np.radians(check.number("angle_deg", angle_deg, unit="degrees"))
    return magnitude * np.cos(theta), magnitude * np.sin(theta)


def from_components(along, across):
    """Size and direction from components: p = sqrt(along² + across²), θ = atan2(across, along).

    along, across: components (signed), e.g. N s. Returns (magnitude, angle_deg), the
    angle in degrees from the original line (-180 to 180; positive towards +across).
    Raises ValueError for a value that is not finite.
    """
    along = check.number("along", along)
    across = check.number("across", across)
    return np.hypot(along, across), np.degrees(np.arctan2(across, along))


class MissingMomentum(NamedTuple):
    """Momentum of the second body after a glancing collision, N s.

    along: component along the original line (signed); across: size of the component
    at right angles, on the OTHER side of the line from the known body; magnitude: size;
    angle_deg: angle to the original line, degrees, on the other side.
    """

    along: float
    across: float
    magnitude: float
    angle_deg: float


def missing_momentum(p_before, p_known, angle_known_deg):
    """Momentum of the other body, from conservation along and across the original line.

    Before: one body with momentum p_before along the line (the other at rest). After:
    the known body has p_known at angle_known_deg to the line. Then
      along:  p_before = p_known cos θ + p_along   ->  p_along = p_before - p_known cos θ
      across: 0 = p_known sin θ - p_across         ->  p_across = p_known sin θ
    p_before, p_known: N s (>= 0); angle_known_deg: degrees (0 to 180).
    Returns MissingMomentum(along, across, magnitude, angle_deg).
    Raises ValueError for a negative momentum, an angle outside 0-180° or a value that
    is not finite.
    """
    p_before = check.non_negative("p_before", p_before, unit="N s")
    p_known = check.non_negative("p_known", p_known, unit="N s")
    theta = np.radians(check.between("angle_known_deg", angle_known_deg, 0, 180,
                                     unit="degrees"))
    along = p_before - p_known * np.cos(theta)
    across = p_known * np.sin(theta)
    return MissingMomentum(float(along), float(across), float(np.hypot(along, across)),
                           float(np.degrees(np.arctan2(across, along))))


@dataclass(frozen=True)
class GlancingCollision:
    """A moving body hits one at rest and both move off at angles (Notes' pucks, Example 4).

    Vectors are (along, across) in N s, with the known (first) body on the + side of the
    line and the struck body on the - side. Tip to tail, known_vector then
    missing_vector end where before_vector ends: the triangle closes.
    Masses are optional (the notes' pucks P and Q are given as momenta only); with them
    come the speeds and kinetic energies.
    """

    p_before: float
    p_known: float
    angle_known_deg: float
    missing: MissingMomentum
    mass_moving: float | None = None
    mass_struck: float | None = None

    @property
    def before_vector(self) -> tuple[float, float]:
        """Momentum before, along the line, N s."""
        return (self.p_before, 0.0)

    @property
    def known_vector(self) -> tuple[float, float]:
        """Momentum of the first body after, (along, across) in N s."""
        along, across = components(self.p_known, self.angle_known_deg)
        return (float(along), float(across))

    @property
    def missing_vector(self) -> tuple[float, float]:
        """Momentum of the struck body after, (along, across) in N s (across negative)."""
        return (self.missing.along, -self.missing.across)

    @property
    def triangle(self) -> tuple[tuple[float, float], ...]:
        """Corners of the tip-to-tail diagram: start, tip of known_vector, tip of both.

        The last corner equals the tip of before_vector (to rounding).
        """
        known = self.known_vector
        missing = self.missing_vector
        return ((0.0, 0.0), known, (known[0] + missing[0], known[1] + missing[1]))

    def _mass(self, name):
        mass = getattr(self, name)
        if mass is None:
            raise ValueError(f"{name} must be given to find speeds and energies "
                             f"(got {name}=None)")
        return mass

    @property
    def speed_before(self) -> float:
        """Speed of the moving body before, m s^-1 (needs mass_moving)."""
        return self.p_before / self._mass("mass_moving")

    @property
    def speed_known(self) -> float:
        """Speed of the first body after, m s^-1 (needs mass_moving)."""
        return self.p_known / self._mass("mass_moving")

    @property
    def speed_missing(self) -> float:
        """Speed of the struck body after, m s^-1 (needs mass_struck)."""
        return self.missing.magnitude / self._mass("mass_struck")

    @property
    def kinetic_energy_before(self) -> float:
        """Total kinetic energy before, p² / 2m, J (needs mass_moving)."""
        return self.p_before**2 / (2 * self._mass("mass_moving"))

    @property
    def kinetic_energies_after(self) -> tuple[float, float]:
        """Kinetic energies after (first body, struck body), p² / 2m, J (needs both masses)."""
        return (self.p_known**2 / (2 * self._mass("mass_moving")),
                self.missing.magnitude**2 / (2 * self._mass("mass_struck")))

    @property
    def kinetic_energy_after(self) -> float:
        """Total kinetic energy after, J (needs both masses)."""
        return sum(self.kinetic_energies_after)

    @property
    def kinetic_energy_transferred(self) -> float:
        """Kinetic energy transferred to other forms, J (> 0 means inelastic)."""
        return self.kinetic_energy_before - self.kinetic_energy_after


def glancing_collision(p_before, p_known, angle_known_deg, *, mass_moving=None,
                       mass_struck=None):
    """A GlancingCollision built with missing_momentum (see there for the equations).

    p_before, p_known: N s (>= 0); angle_known_deg: degrees (0 to 180); mass_moving,
    mass_struck: kg (> 0), optional. Raises ValueError for values outside those ranges.
    (Whether the collision is possible is not checked: a negative
    kinetic_energy_transferred means kinetic energy would be created.)
    """
    missing = missing_momentum(p_before, p_known, angle_known_deg)
    if mass_moving is not None:
        mass_moving = check.positive("mass_moving", mass_moving, unit="kg")
    if mass_struck is not None:
        mass_struck = check.positive("mass_struck", mass_struck, unit="kg")
    return GlancingCollision(float(p_before), float(p_known), float(angle_known_deg), missing,
                             mass_moving, mass_struck)


class SplitInTwo(NamedTuple):
    """The other piece of a moving body that splits in two (explosion, separation).

    mass: kg; along: its momentum along the body's original direction, N s (signed: negative
    means backwards); across: its momentum at right angles, N s (signed: positive on the known
    piece's side, so usually negative); magnitude: N s; speed: m s^-1; angle_deg: its direction
    from the original direction, degrees (-180 to 180, positive on the known piece's side);
    kinetic_energy_released: the kinetic energy after less before, J (never negative).
    """

    mass: float
    along: float
    across: float
    magnitude: float
    speed: float
    angle_deg: float
    kinetic_energy_released: float


def split_in_two(mass, speed, mass_piece, speed_piece, angle_piece_deg):
    """A body moving along a line splits into two pieces; one piece's velocity is known.

    Before: mass M at speed u along the line. After: the known piece (mass m₁) at v₁ at θ to the
    line, the other (M - m₁) with momentum conserved in each direction separately:
      along:  M u = m₁ v₁ cos θ + p_along   ->  p_along = M u - m₁ v₁ cos θ
      across: 0 = m₁ v₁ sin θ + p_across    ->  p_across = -m₁ v₁ sin θ
    mass: kg (> 0); speed: m s^-1 (>= 0; 0 is an explosion from rest); mass_piece: kg
    (> 0, less than mass); speed_piece: m s^-1 (>= 0); angle_piece_deg: degrees (0 to 180).
    Returns SplitInTwo. Raises ValueError for values outside those ranges.
    """
    mass = check.positive("mass", mass, unit="kg")
    speed = check.non_negative("speed", speed, unit="m s^-1")
    mass_piece = check.positive("mass_piece", mass_piece, unit="kg")
    check.require("mass_piece", mass_piece, mass_piece < mass,
                  f"must be less than mass={mass!r} kg (the other piece needs some)", unit="kg")
    speed_piece = check.non_negative("speed_piece", speed_piece, unit="m s^-1")
    angle = check.between("angle_piece_deg", angle_piece_deg, 0, 180, unit="degrees")
    known_along, known_across = components(mass_piece * speed_piece, angle)
    along = mass * speed - float(known_along)
    across = -float(known_across)
    magnitude, angle_deg = from_components(along, across)
    rest = mass - mass_piece
    released = (0.5 * mass_piece * speed_piece**2 + float(magnitude) ** 2 / (2 * rest)
                - 0.5 * mass * speed**2)
    # released is never negative (the kinetic energy of the motion relative to the centre of
    # mass is added); rounding can leave -1e-16 J
    return SplitInTwo(rest, along, across, float(magnitude), float(magnitude) / rest, float(angle_deg),
                      max(0.0, released))
