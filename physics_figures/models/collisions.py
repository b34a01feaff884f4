"""Collisions and explosions in a straight line (Notes, "Conservation of momentum" and
"Elastic and inelastic collisions").

Velocities are signed along one line (choose a positive direction); masses in kg,
velocities in m s^-1, momenta in kg m s^-1, energies in J. Momentum is conserved in
every function here: m1 u1 + m2 u2 = m1 v1 + m2 v2.
"""

import numpy as np

from . import _checks as check


def _masses_and_velocities(m1, u1, m2, u2):
    return (check.positive("m1", m1, unit="kg"), check.number("u1", u1, unit="m s^-1"),
            check.positive("m2", m2, unit="kg"), check.number("u2", u2, unit="m s^-1"))


def collision_with_energy_kept(m1, u1, m2, u2, *, fraction_of_ke_kept_in_cm_frame):
    """Head-on collision that keeps a chosen fraction f of the kinetic energy it can lose.

    In the centre-of-mass frame (velocity V = (m1 u1 + m2 u2) / (m1 + m2)) both bodies
    reverse and their speeds are scaled by sqrt(f): v_i = V - sqrt(f) (u_i - V). So the
    momentum is always conserved; f = 1 is elastic (relative speed of separation = that
    of approach) and f = 0 is sticking together. The kinetic energy of the centre of mass
    can never be lost, so f is a fraction of the rest.

    m1, m2: kg (> 0); u1, u2: m s^-1, signed; fraction_of_ke_kept_in_cm_frame: 0 to 1.
    Returns (v1, v2) in m s^-1, signed.
    Raises ValueError for a mass <= 0, a fraction outside 0-1 (above 1 would create
    kinetic energy), or a value that is not finite.
    """
    m1, u1, m2, u2 = _masses_and_velocities(m1, u1, m2, u2)
    f = check.between("fraction_of_ke_kept_in_cm_frame", fraction_of_ke_kept_in_cm_frame, 0, 1,
                      why="a collision cannot create kinetic energy")
    v_cm = (m1 * u1 + m2 * u2) / (m1 + m2)
    e = np.sqrt(f)
    return v_cm - e * (u1 - v_cm), v_cm - e * (u2 - v_cm)


def elastic_collision(m1, u1, m2, u2):
    """Velocities after a head-on elastic collision.

    From momentum (m1 u1 + m2 u2 = m1 v1 + m2 v2) and relative speeds
    (u1 - u2 = v2 - v1): v1 = ((m1 - m2) u1 + 2 m2 u2) / (m1 + m2),
    v2 = ((m2 - m1) u2 + 2 m1 u1) / (m1 + m2).
    m1, m2: kg (> 0); u1, u2: m s^-1, signed. Returns (v1, v2) in m s^-1, signed.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    m1, u1, m2, u2 = _masses_and_velocities(m1, u1, m2, u2)
    total = m1 + m2
    return ((m1 - m2) * u1 + 2 * m2 * u2) / total, ((m2 - m1) * u2 + 2 * m1 * u1) / total


def stick_together(m1, u1, m2, u2):
    """Common velocity after two bodies collide and stick: v = (m1 u1 + m2 u2) / (m1 + m2).

    m1, m2: kg (> 0); u1, u2: m s^-1, signed. Returns v in m s^-1, signed.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    m1, u1, m2, u2 = _masses_and_velocities(m1, u1, m2, u2)
    return (m1 * u1 + m2 * u2) / (m1 + m2)


def velocity_after_collision(m1, u1, m2, u2, v1):
    """Velocity of body 2 after an interaction, from conservation of momentum.

    v2 = (m1 u1 + m2 u2 - m1 v1) / m2. m1, m2: kg (> 0); u1, u2, v1: m s^-1, signed.
    Returns v2 in m s^-1, signed. (Momentum alone does not say whether the result is
    possible: compare the kinetic energies with total_kinetic_energy.)
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    m1, u1, m2, u2 = _masses_and_velocities(m1, u1, m2, u2)
    v1 = check.number("v1", v1, unit="m s^-1")
    return (m1 * u1 + m2 * u2 - m1 * v1) / m2


def explosion_from_rest(m1, m2, v1):
    """Velocity of piece 2 when two pieces fly apart from rest: 0 = m1 v1 + m2 v2.

    v2 = -m1 v1 / m2: the opposite way, with speeds in the inverse ratio of the masses.
    m1, m2: kg (> 0); v1: m s^-1, signed. Returns v2 in m s^-1, signed.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    m1 = check.positive("m1", m1, unit="kg")
    m2 = check.positive("m2", m2, unit="kg")
    return -m1 * check.number("v1", v1, unit="m s^-1") / m2


def _bodies(masses, velocities):
    masses = check.sequence("masses", masses, unit="kg")
    velocities = check.sequence("velocities", velocities, unit="m s^-1")
    check.same_length(masses=masses, velocities=velocities)
    return check.positive("masses", masses, unit="kg"), velocities


def total_momentum(masses, velocities):
    """Total momentum Σ m v of a system, kg m s^-1, signed.

    masses: kg (each > 0); velocities: m s^-1, signed, the same length.
    Raises ValueError for an empty or mismatched list, a mass <= 0 or a value that is
    not finite.
    """
    masses, velocities = _bodies(masses, velocities)
    return float(np.sum(masses * velocities))


def total_kinetic_energy(masses, velocities):
    """Total kinetic energy Σ ½ m v² of a system, J.

    masses: kg (each > 0); velocities: m s^-1, the same length.
    Raises ValueError for an empty or mismatched list, a mass <= 0 or a value that is
    not finite.
    """
    masses, velocities = _bodies(masses, velocities)
    return float(np.sum(0.5 * masses * velocities**2))


def relative_speed(v_a, v_b):
    """Relative speed |v_a - v_b|, m s^-1: how fast the gap between two bodies changes.

    v_a, v_b: m s^-1, signed along the same line (towards each other at 5 and 3 m s^-1
    is v_a = 5, v_b = -3: 8 m s^-1). Raises ValueError for a value that is not finite.
    """
    v_a = check.number("v_a", v_a, unit="m s^-1")
    return abs(v_a - check.number("v_b", v_b, unit="m s^-1"))


def percentage_kinetic_energy_lost(kinetic_energy_before, kinetic_energy_after):
    """Percentage of kinetic energy transferred to other forms: (E_before - E_after) / E_before x 100.

    kinetic_energy_before: J (> 0); kinetic_energy_after: J (>= 0). Returns a percentage
    (negative if kinetic energy was gained, as in an explosion).
    Raises ValueError for E_before <= 0, a negative E_after or a value that is not finite.
    """
    before = check.positive("kinetic_energy_before", kinetic_energy_before, unit="J")
    after = check.non_negative("kinetic_energy_after", kinetic_energy_after, unit="J")
    return (before - after) / before * 100
