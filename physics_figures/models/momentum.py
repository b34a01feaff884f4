"""Momentum, force as the rate of change of momentum, impulse and kinetic energy.

Notes: "Momentum and Newton's second law" and "How to do it > 3. Force as rate of
change of momentum". All quantities SI; velocities are signed (choose a positive
direction), speeds and sizes of momenta are not.
"""

import numpy as np

from . import _checks as check


def momentum(mass, velocity):
    """Linear momentum p = m v.

    mass: kg (> 0); velocity: m s^-1, signed (scalar or array).
    Returns p in kg m s^-1 (= N s), with the sign of the velocity.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    return mass * check.number("velocity", velocity, unit="m s^-1")


def velocity_from_momentum(momentum, mass):
    """Velocity v = p / m.

    momentum: kg m s^-1, signed; mass: kg (> 0). Returns v in m s^-1, signed.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    momentum = check.number("momentum", momentum, unit="kg m s^-1")
    return momentum / check.positive("mass", mass, unit="kg")


def change_in_momentum(mass, u, v):
    """Change in momentum Δp = m v - m u = m (v - u).

    mass: kg (> 0); u, v: initial and final velocity, m s^-1, signed along one line
    (a ball that bounces back has u and v of opposite signs, so |Δp| = m(|u| + |v|)).
    Returns Δp in kg m s^-1 (N s), signed. Raises ValueError for a mass <= 0 or a
    value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    u = check.number("u", u, unit="m s^-1")
    v = check.number("v", v, unit="m s^-1")
    return mass * (v - u)


def average_force(change_in_momentum, duration):
    """Average resultant force F = Δp / Δt (Newton's second law).

    change_in_momentum: N s, signed; duration: s (> 0: a force needs time to act).
    Returns F in N, in the direction of Δp. Raises ValueError for a duration <= 0 or
    a value that is not finite.
    """
    change_in_momentum = check.number("change_in_momentum", change_in_momentum, unit="N s")
    return change_in_momentum / check.positive("duration", duration, unit="s")


def impulse(force, duration):
    """Impulse (change in momentum) of a constant force: Δp = F Δt.

    force: N, signed; duration: s (>= 0). Returns Δp in N s, with the sign of F.
    Raises ValueError for a negative duration or a value that is not finite.
    """
    force = check.number("force", force, unit="N")
    return force * check.non_negative("duration", duration, unit="s")


def time_for_momentum_change(change_in_momentum, force):
    """Time for a constant force to change the momentum: Δt = Δp / F.

    change_in_momentum: N s, signed; force: N, signed, not zero, and in the same
    direction as Δp (a force can only change momentum in its own direction).
    Returns Δt in s (>= 0). Raises ValueError for a zero force, a force opposite to
    Δp, or a value that is not finite.
    """
    change_in_momentum = check.number("change_in_momentum", change_in_momentum, unit="N s")
    force = check.nonzero("force", force, unit="N")
    if change_in_momentum * force < 0:
        check.fail(
            "force", force, "must act in the direction of the change in momentum "
            f"(change_in_momentum={change_in_momentum!r} N s)", unit="N",
        )
    return change_in_momentum / force


def kinetic_energy(mass, velocity):
    """Kinetic energy E_k = ½ m v².

    mass: kg (> 0); velocity: m s^-1 (sign ignored; scalar or array). Returns E_k in J.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    mass = check.positive("mass", mass, unit="kg")
    return 0.5 * mass * check.number("velocity", velocity, unit="m s^-1") ** 2


def kinetic_energy_from_momentum(momentum, mass):
    """Kinetic energy from momentum: E_k = p² / 2m.

    momentum: kg m s^-1 (sign ignored); mass: kg (> 0). Returns E_k in J.
    Raises ValueError for a mass <= 0 or a value that is not finite.
    """
    momentum = check.number("momentum", momentum, unit="kg m s^-1")
    return momentum**2 / (2 * check.positive("mass", mass, unit="kg"))


def mass_from_momentum_and_energy(momentum, kinetic_energy):
    """Mass from momentum and kinetic energy: m = p² / 2E_k.

    momentum: kg m s^-1 (not zero; sign ignored); kinetic_energy: J (> 0).
    Returns m in kg. Raises ValueError for p = 0, E_k <= 0 or a value that is not finite.
    """
    momentum = check.nonzero("momentum", momentum, unit="kg m s^-1")
    kinetic_energy = check.positive("kinetic_energy", kinetic_energy, unit="J")
    return momentum**2 / (2 * kinetic_energy)


def speed_from_momentum_and_energy(momentum, kinetic_energy):
    """Speed from momentum and kinetic energy: v = 2E_k / p.

    momentum: kg m s^-1 (not zero; sign ignored); kinetic_energy: J (> 0).
    Returns the speed v in m s^-1 (>= 0). Raises ValueError for p = 0, E_k <= 0 or a
    value that is not finite.
    """
    momentum = check.nonzero("momentum", momentum, unit="kg m s^-1")
    kinetic_energy = check.positive("kinetic_energy", kinetic_energy, unit="J")
    return 2 * kinetic_energy / abs(momentum)


def momentum_change_between_directions(p_initial, p_final, angle_deg):
    """Size of the vector change in momentum when the direction turns through an angle.

    |Δp| = |p_final - p_initial| = sqrt(p1² + p2² - 2 p1 p2 cos θ) (cosine rule), so a
    turn through 90° gives sqrt(p1² + p2²) and θ = 0 gives |p2 - p1|.
    p_initial, p_final: sizes of the momenta, N s (>= 0); angle_deg: the angle between
    their directions, degrees (0 to 180). Returns |Δp| in N s.
    Raises ValueError for a negative size, an angle outside 0-180° or a value that is
    not finite.
    """
    p1 = check.non_negative("p_initial", p_initial, unit="N s")
    p2 = check.non_negative("p_final", p_final, unit="N s")
    theta = np.radians(check.between("angle_deg", angle_deg, 0, 180, unit="degrees"))
    # The same cosine rule written as (p2 - p1)² + 4 p1 p2 sin²(θ/2): no cancellation
    # when the turn is small.
    return np.sqrt((p2 - p1) ** 2 + 4 * p1 * p2 * np.sin(theta / 2) ** 2)


def oblique_bounce_momentum_change(momentum, angle_to_surface_deg):
    """Change in momentum of a ball that bounces off a surface at the same speed and angle.

    Only the component at right angles to the surface reverses: Δp = 2 p sin θ, away
    from the surface. momentum: size of the momentum, N s (>= 0); angle_to_surface_deg:
    the angle between the path and the surface, degrees (0 to 90).
    Returns Δp in N s. Raises ValueError for a negative momentum, an angle outside
    0-90° or a value that is not finite.
    """
    momentum = check.non_negative("momentum", momentum, unit="N s")
    theta = check.between("angle_to_surface_deg", angle_to_surface_deg, 0, 90, unit="degrees")
    return 2 * momentum * np.sin(np.radians(theta))


def stream_force(mass_per_second, speed):
    """Force needed to give a steady stream its momentum: F = (Δm/Δt) v.

    mass_per_second: kg s^-1 (>= 0); speed: m s^-1 (>= 0). Returns F in N (the same size
    of force pushes back on the hose, jet or rocket, by Newton's third law).
    Raises ValueError for a negative mass flow or speed, or a value that is not finite.
    """
    mass_per_second = check.non_negative("mass_per_second", mass_per_second, unit="kg s^-1")
    return mass_per_second * check.non_negative("speed", speed, unit="m s^-1")


def jet_force(density, area, speed):
    """Force from a jet of fluid: mass per second = rho A v, so F = rho A v².

    density: kg m^-3 (> 0); area: m² (> 0); speed: m s^-1 (>= 0). Returns F in N.
    Raises ValueError for a density or area <= 0, a negative speed or a value that is
    not finite.
    """
    density = check.positive("density", density, unit="kg m^-3")
    area = check.positive("area", area, unit="m^2")
    return density * area * check.non_negative("speed", speed, unit="m s^-1") ** 2


def mass_from_momentum_change(change_in_momentum, u, v):
    """Mass from a change in momentum and the change in velocity it made: m = Δp / (v - u).

    From Δp = m v - m u with constant mass (a constant force F for Δt gives Δp = F Δt).
    change_in_momentum: N s, signed; u, v: initial and final velocity, m s^-1, signed along
    one line (a body that turns round has u and v of opposite signs). Returns m in kg (> 0).
    Raises ValueError for equal velocities (no change in velocity: any mass would do), a
    change in momentum that is zero or opposite to the change in velocity (the mass would
    not be positive), or a value that is not finite.
    """
    change_in_momentum = check.number("change_in_momentum", change_in_momentum, unit="N s")
    u = check.number("u", u, unit="m s^-1")
    v = check.number("v", v, unit="m s^-1")
    if v == u:
        check.fail("v", v, f"must differ from u={u!r} m s^-1: with no change in velocity any mass fits",
                   unit="m s^-1")
    if change_in_momentum * (v - u) <= 0:
        check.fail("change_in_momentum", change_in_momentum,
                   f"must be in the direction of the change in velocity v - u = {v - u!r} m s^-1 "
                   "(a mass is positive)", unit="N s")
    return change_in_momentum / (v - u)
