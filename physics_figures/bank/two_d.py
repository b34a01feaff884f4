# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Momentum in two dimensions: components and glancing collisions."""

from __future__ import annotations

import math

import sympy

from ..models import (
    average_force,
    components,
    from_components,
    glancing_collision,
    kinetic_energy,
    missing_momentum,
    momentum,
    oblique_bounce_momentum_change,
    split_in_two,
    stick_together,
    total_kinetic_energy,
    velocity_after_collision,
    velocity_from_momentum,
)
from ..notation import format_number as n
from ..questions import (
    ChoicePart,
    Ecf,
    Given,
    Mark,
    Mistake,
    Part,
    Question,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from . import diagrams
from ._common import M_S, N_S, PER_S, enough_figures, one_of_each, w
from .givens import checked_givens


def pucks_glancing(mass: float = 0.40, speed_before: float = 2.5, speed_after: float = 1.5,
                   angle: float = 40.0) -> Question:
    """Momentum in two dimensions: conserve along and across the line separately."""
    if speed_after >= speed_before:  # B, at rest before, takes some of A's kinetic energy
        raise ValueError(f"speed_after must be less than speed_before={speed_before!r} m s^-1: puck A "
                         f"cannot speed up by hitting a puck at rest (got speed_after={speed_after!r})")
    p_before = momentum(mass, speed_before)
    p_after = momentum(mass, speed_after)
    b = missing_momentum(p_before, p_after, angle)
    components = (Step("component along the line", b.along, "N s"),
                  Step("component across the line", b.across, "N s"))
    m, u, v, theta = n(mass, 2), n(speed_before, 2), n(speed_after, 2), n(angle, 2)
    along, across = "p<sub>along</sub>", "p<sub>across</sub>"
    # (b) by the student's own route from (a): sin θ = across / p_B or cos θ = along / p_B (issue 37)
    sym_a, sym_along, sym_across = sympy.symbols("a p_along p_across")
    return Question(
        key="practice-pucks",
        diagram=diagrams.glancing(mass, speed_before, speed_after, angle),
        text=(f"On a frictionless air table, puck A of mass {m} kg moving at {u} {PER_S} hits puck B, "
              f"which is at rest. Afterwards A moves at {v} {PER_S} at {theta}° to its original direction. "
              "Calculate (a) the size of the momentum of B after the collision, and (b) the angle between "
              "B's motion and A's original direction."),
        givens=(Given("mass", mass, "kg", 2), Given("speed before", speed_before, "m s^-1", 2),
                Given("speed after", speed_after, "m s^-1", 2), Given("angle", angle, "°", 2)),
        parts=(
            Part("momentum of B after the collision", b.magnitude, "N s", "momentum", units=N_S,
                 shown_sig_figs=2, working=components,
                 answer_from=lambda along_, across_: math.hypot(along_, across_),
                 revisit="Momentum is a vector: conserve the components along and across the "
                         "original line separately, then combine them with Pythagoras.",
                 mistakes=(
                     Mistake("momentum added as scalars", p_before - p_after,
                             "You subtracted the sizes. Momentum is a vector: resolve along and "
                             "across the line and conserve each.", see="conservation"),
                     # 9702/21/M/J/16 Q2(a) marks each component on its own ("horizontal component
                     # (= 12 cos 50°)", "vertical component (= 12 sin 50°)"); a swap is wrong physics (XP)
                     Mistake("sin and cos swapped", missing_momentum(p_before, p_after, 90.0 - angle).magnitude,
                             f"You swapped sin and cos. The angle is measured from A's original direction, so "
                             f"A's component along that line is p cos {theta}° and across it p sin {theta}°."),
                     Mistake("across component only", b.across,
                             "That is only the component across the line. Combine it with the "
                             "component along the line: p = √(along² + across²)."),
                 ), see="two-d"),
            Part("angle between B's motion and A's original line", b.angle_deg, "°", "angle",
                 units="° (degrees)", shown_sig_figs=3, working=components,
                 answer_from=lambda along_, across_: math.degrees(math.atan2(across_, along_)),
                 ecf=Ecf(sympy.asin(sym_across / sym_a) * 180 / sympy.pi, {"p_across": b.across}),
                 ecf_also=(Ecf(sympy.acos(sym_along / sym_a) * 180 / sympy.pi, {"p_along": b.along}),),
                 revisit="tan θ = across component / along component, on the other side of the line.",
                 mistakes=(
                     Mistake("same angle as A", angle,
                             "B need not move at A's angle. Work out its components and use "
                             "tan θ = across / along."),
                     Mistake("angle from the perpendicular", 90.0 - b.angle_deg,
                             "You measured the angle from the line at right angles. Give it from "
                             "A's original line: tan θ = across / along."),
                 ), see="two-d"),
        ),
        mark_scheme=(
            Mark(f"Along: {w(p_before)} = {w(p_after)} cos {theta}° + {along}, so {along} = "
                 f"{n(b.along, 3)} N s", "C1", "ab"),
            Mark(f"Across: {across} = {w(p_after)} sin {theta}° = {n(b.across, 3)} N s", "C1", "ab"),
            Mark(f"p<sub>B</sub> = √({n(b.along, 3)}<sup>2</sup> + {n(b.across, 3)}<sup>2</sup>) = "
                 f"{n(b.magnitude, 2)} N s", "A1", "a"),
            Mark(f"θ = tan<sup>−1</sup> ({n(b.across, 3)} / {n(b.along, 3)}) = {n(b.angle_deg, 3)}° on the "
                 "other side of the line", "A1", "b"),
        ),
    )


def glancing_speed_choice(m1: float = 0.20, speed_before: float = 3.0, m2: float = 0.30,
                          speed_after: float = 1.5, angle: float = 40.0) -> Question:
    """Paper 1 style: the speed of the struck puck after a glancing collision. Wrong options:
    momentum added as scalars, sin and cos swapped, one component forgotten."""
    if speed_after >= speed_before:
        raise ValueError(f"speed_after must be less than speed_before={speed_before!r} m s^-1: puck A "
                         f"cannot speed up by hitting a puck at rest (got speed_after={speed_after!r})")
    p_before, p_after = momentum(m1, speed_before), momentum(m1, speed_after)
    hit = glancing_collision(p_before, p_after, angle, mass_moving=m1, mass_struck=m2)
    if hit.kinetic_energy_transferred < 0:
        raise ValueError(f"these speeds would create kinetic energy ({n(-hit.kinetic_energy_transferred, 3)} J): "
                         f"lower speed_after={speed_after!r} or raise m2={m2!r}")
    key = hit.speed_missing
    swapped = missing_momentum(p_before, p_after, 90.0 - angle)
    options, answer = choices_in_order(key, {
        "momentum added as scalars": (
            velocity_after_collision(m1, speed_before, m2, 0.0, speed_after),
            ("You subtracted the sizes of the momenta as if A carried straight on. Momentum is a vector: "
            "conserve the components along and across A's first direction separately.")),
        "sin and cos swapped": (
            velocity_from_momentum(swapped.magnitude, m2),
            (f"You swapped sin and cos. The angle is measured from A's first direction, so A's component "
            f"along that line is p cos {n(angle, 2)}° and across it p sin {n(angle, 2)}°.")),
        "across component forgotten": (
            velocity_from_momentum(hit.missing.along, m2),
            ("That uses only B's component along A's first direction. B also has a component across the "
            "line (equal and opposite to A's): combine them with Pythagoras."), "third-law"),
        "components added": (
            velocity_from_momentum(abs(hit.missing.along) + abs(hit.missing.across), m2),
            ("You added B's two components of momentum. They are at right angles: combine them with "
             "Pythagoras, p = √(p_along² + p_across²).")),
        "divided by A's mass": (
            velocity_from_momentum(hit.missing.magnitude, m1),
            (f"You divided B's momentum by A's mass. v = p / m with B's own mass, {n(m2, 2)} kg."), "momentum"),
    }, sig_figs=2, unit=PER_S, seed=10)
    ma, mb, u, v, theta = n(m1, 2), n(m2, 2), n(speed_before, 2), n(speed_after, 2), n(angle, 2)
    return Question(
        key="glancing-speed-choice",
        diagram=diagrams.glancing(m1, speed_before, speed_after, angle, m2),
        text=(f"On a frictionless air table, puck A of mass {ma} kg moving at {u} {PER_S} hits puck B of "
              f"mass {mb} kg, which is at rest. After the collision A moves at {v} {PER_S} at {theta}° to "
              "its original direction."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed before", speed_before, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed after", speed_after, "m s^-1", 2),
                Given("angle", angle, "°", 2)),
        parts=(ChoicePart("What is the speed of B after the collision?", options, answer,
                          revisit="Conserve momentum along and across A's first direction separately, "
                                  "combine B's components with Pythagoras, then divide by B's mass.", see="two-d"),),
        mark_scheme=(Mark(f"{answer}: along {w(p_before)} − {w(p_after)} cos {theta}° = {n(hit.missing.along, 3)} "
                          f"N s; across {w(p_after)} sin {theta}° = {n(hit.missing.across, 3)} N s; "
                          f"p<sub>B</sub> = {n(hit.missing.magnitude, 3)} N s, v = {n(key, 2)} {PER_S}", "B1"),),
    )


_COMPASS = ("north of east", "south of west", "north of west", "south of east")
#: Where the firework's first two pieces fly, by variant: the first along east-west, the second
#: along north-south, so the third piece's direction is not the same in every variant (issue 25).
_HEADINGS = (("east", "north"), ("west", "north"), ("east", "south"), ("west", "south"))
_SIGN = {"east": 1.0, "west": -1.0, "north": 1.0, "south": -1.0}


def _compass(east: float, north: float) -> str:
    """The compass quadrant of a momentum from its signed components (east and north positive)."""
    return f"{'north' if north > 0 else 'south'} of {'east' if east > 0 else 'west'}"


def explosion_three_pieces(m1: float = 0.20, v1: float = 30.0, m2: float = 0.30, v2: float = 15.0,
                           m3: float = 0.50, heading: float = 0) -> Question:
    """Explosion into three pieces from rest (notes' variation): two at right angles, so the third
    has momentum sqrt(p1² + p2²), opposite the resultant of the other two. heading: which of
    _HEADINGS the first two pieces fly along (0: east and north, the printed version)."""
    first_way, second_way = _HEADINGS[int(heading)]
    p1, p2 = momentum(m1, v1), momentum(m2, v2)
    east, north = _SIGN[first_way] * p1, _SIGN[second_way] * p2  # the first two pieces together
    size, angle = from_components(p1, p2)  # the third is equal and opposite: the same size and angle
    resultant_way, third_way = _compass(east, north), _compass(-east, -north)
    speed = velocity_from_momentum(size, m3)
    speeds_size, speeds_angle = from_components(v1, v2)
    upside_down = from_components(p2, p1)[1]
    ma, mb, mc, ua, ub = n(m1, 2), n(m2, 2), n(m3, 2), n(v1, 2), n(v2, 2)
    sym_a, sym_m3 = sympy.symbols("a m_c")
    return Question(
        key="explosion-three-pieces",
        diagram=diagrams.explosion_from_rest(((m1, v1, 0.0 if first_way == "east" else 180.0),
                                              (m2, v2, 90.0 if second_way == "north" else 270.0), (m3, None, None))),
        text=(f"A firework shell at rest explodes into three pieces. A piece of mass {ma} kg flies due "
              f"{first_way} at {ua} {PER_S}, and a piece of mass {mb} kg flies due {second_way} at {ub} "
              f"{PER_S}. The third piece has mass {mc} kg. Calculate, for the third piece, (a) the size of "
              "its momentum, (b) its speed and (c) the angle its direction makes with the east–west line, "
              "and state its direction."),
        givens=(Given("mass 1", m1, "kg", 2), Given("speed 1", v1, "m s^-1", 2), Given("mass 2", m2, "kg", 2),
                Given("speed 2", v2, "m s^-1", 2), Given("mass 3", m3, "kg", 2)),
        parts=(
            Part("size of the momentum of the third piece", size, "N s", "momentum", units=N_S,
                 shown_sig_figs=2,
                 revisit="The total momentum stays zero: the third piece's momentum is equal and opposite "
                         "to the resultant of the other two, √(p₁² + p₂²) for two at right angles.",
                 mistakes=(
                     Mistake("momentum added as scalars", p1 + p2,
                             "You added the sizes. The two momenta are at right angles: add them as "
                             "vectors, with Pythagoras."),
                     Mistake("momenta subtracted", abs(p1 - p2),
                             "You subtracted the sizes. The momenta are at right angles: their resultant "
                             "is √(p₁² + p₂²)."),
                 ), see="third-law"),
            Part("speed of the third piece", speed, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 ecf=Ecf(sym_a / sym_m3, {"m_c": m3}),
                 revisit="Speed = momentum ÷ mass, with the third piece's own mass.",
                 mistakes=(
                     Mistake("Pythagoras on the speeds", speeds_size,
                             "You combined the speeds. Momentum is conserved, not velocity: combine the "
                             "momenta, then divide by the third piece's mass.", see="conservation"),
                 ), see="momentum"),
            Part("angle of the third piece's direction", angle, "°", "angle", units="° (degrees)",
                 shown_sig_figs=3, direction="choice", choices=_COMPASS, answer_direction=third_way,
                 direction_hint="The third piece's momentum cancels the other two: it points opposite to "
                                f"their resultant, which is {resultant_way}.",
                 revisit="tan θ = (north–south momentum) / (east–west momentum); the third piece moves the "
                         "opposite way to the resultant of the other two.",
                 mistakes=(
                     Mistake("tan the wrong way up", upside_down,
                             "You measured the angle from north–south. tan θ = (north–south momentum) / "
                             "(east–west momentum) gives the angle from east–west."),
                     Mistake("used the speeds", speeds_angle,
                             "You used the speeds. The direction comes from the momenta, which include "
                             "the masses."),
                     Mistake("same direction as the other two", angle,
                             "That is the direction of the other two pieces' resultant. The total is "
                             "zero, so the third piece moves the opposite way.", direction=resultant_way),
                 ), see="two-d"),
        ),
        mark_scheme=(
            Mark(f"Momentum before is zero, so p = √({w(p1)}<sup>2</sup> + {w(p2)}<sup>2</sup>)", "C1", "a"),
            Mark(f"= {n(size, 2)} N s", "A1", "a"),
            Mark(f"v = {n(size, 3)} / {mc}", "C1", "b"),
            Mark(f"= {n(speed, 2)} {PER_S}", "A1", "b"),
            Mark(f"tan θ = {w(p2)} / {w(p1)}", "C1", "c"),
            Mark(f"θ = {n(angle, 3)}°", "A1", "c"),
            # the direction's own B1, as 9702/21/M/J/16 Q3(b)(ii): "(direction of force is) upwards/up B1"
            Mark(f"{third_way} (opposite to the resultant of the other two, {resultant_way})", "B1", "c",
                 earns="direction"),
        ),
    )


def skaters_stick_right_angles(m1: float = 70.0, u1: float = 4.0, m2: float = 50.0, u2: float = 3.0) -> Question:
    """Two bodies meeting at right angles and sticking (notes' variation): add the momentum
    vectors; the pair moves along the resultant. Then the kinetic energy transferred, with ecf."""
    p1, p2 = momentum(m1, u1), momentum(m2, u2)
    size, angle = from_components(p1, p2)
    total = m1 + m2
    speed = velocity_from_momentum(size, total)
    before = total_kinetic_energy((m1, m2), (u1, u2))
    after = kinetic_energy(total, speed)
    ma, mb, ua, ub = n(m1, 2), n(m2, 2), n(u1, 2), n(u2, 2)
    # the speed with the figures the kinetic energy after needs
    (speed_carried,) = enough_figures((speed,), lambda v1: kinetic_energy(total, v1), n(after, 3))
    sym_a, sym_m1, sym_m2, sym_u1, sym_u2 = sympy.symbols("a m_a m_b u_a u_b")
    return Question(
        key="skaters-stick-right-angles",
        diagram=diagrams.at_right_angles(m1, u1, m2, u2),
        text=(f"On smooth ice, skater A of mass {ma} kg moves due east at {ua} {PER_S}, and skater B of mass "
              f"{mb} kg moves due north at {ub} {PER_S}. They collide and hold on to each other. Calculate "
              "(a) their speed just after the collision, (b) the angle between their direction and due east "
              "(north of east) and (c) the kinetic energy transferred to other forms."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed of B", u2, "m s^-1", 2)),
        parts=(
            Part("speed just after the collision", speed, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 revisit="Add the momenta as vectors (Pythagoras: they are at right angles), then divide "
                         "by the total mass.",
                 mistakes=(
                     Mistake("momentum added as scalars", stick_together(m1, u1, m2, u2),
                             "You added the momenta as if the skaters moved along one line. They move at "
                             "right angles: combine the momenta with Pythagoras."),
                     Mistake("Pythagoras on the speeds", from_components(u1, u2)[0],
                             "You combined the speeds. Combine the momenta (which include the masses), "
                             "then divide by the total mass."),
                 ), see="two-d"),
            Part("angle north of east", angle, "°", "angle", units="° (degrees)", shown_sig_figs=3,
                 revisit="The pair moves along the resultant momentum: tan θ = (northward momentum) / "
                         "(eastward momentum).",
                 mistakes=(
                     Mistake("tan the wrong way up", from_components(p2, p1)[1],
                             "That is the angle from due north. tan θ = (northward momentum) / (eastward "
                             "momentum) gives the angle north of east."),
                     Mistake("used the speeds", from_components(u1, u2)[1],
                             "You used the speeds. The direction is that of the resultant momentum, so "
                             "include the masses.", see="momentum"),
                 ), see="two-d"),
            Part("kinetic energy transferred to other forms", before - after, "J", "energy", shown_sig_figs=2,
                 ecf=Ecf(sympy.Rational(1, 2) * (sym_m1 * sym_u1**2 + sym_m2 * sym_u2**2)
                         - sympy.Rational(1, 2) * (sym_m1 + sym_m2) * sym_a**2,
                         {"m_a": m1, "m_b": m2, "u_a": u1, "u_b": u2}),
                 revisit="Kinetic energy is a scalar: add ½mv² for each skater before, and subtract "
                         "½ × (both masses) × v² after.",
                 mistakes=(
                     Mistake("forgot B's kinetic energy before", kinetic_energy(m1, u1) - after,
                             "Both skaters move before the collision: add both kinetic energies."),
                     Mistake("gave the kinetic energy before", before,
                             "That is the kinetic energy before. Subtract the kinetic energy after."),
                 ), see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"p = √({w(p1)}<sup>2</sup> + {w(p2)}<sup>2</sup>) = {n(size, 3)} N s", "C1", "a"),
            Mark(f"v = {n(size, 3)} / {w(total)} = {n(speed, 2)} {PER_S}", "A1", "a"),
            Mark(f"tan θ = {w(p2)} / {w(p1)}", "C1", "b"),
            Mark(f"θ = {n(angle, 3)}° north of east", "A1", "b"),
            Mark(f"Before: {w(kinetic_energy(m1, u1))} + {w(kinetic_energy(m2, u2))} = {w(before)} J; after: "
                 f"½ × {w(total)} × {speed_carried}<sup>2</sup> = {n(after, 3)} J", "C1", "c"),
            Mark(f"Transferred = {n(before - after, 2)} J", "A1", "c"),
        ),
    )


_WALL = ("away from the wall, at right angles to it", "towards the wall, at right angles to it",
         "along the wall")


def oblique_wall_bounce(mass: float = 0.060, speed: float = 20.0, angle: float = 40.0,
                        contact_ms: float = 5.0) -> Question:
    """A ball bouncing off a smooth wall at an angle, same speed and angle: only the component at
    right angles to the wall reverses, so Δp = 2p sin θ (θ to the wall), away from the wall."""
    p = momentum(mass, speed)
    across = float(components(p, angle)[1])  # the component at right angles to the wall
    dp = oblique_bounce_momentum_change(p, angle)
    contact = contact_ms / 1000
    force = average_force(dp, contact)
    along = float(components(p, angle)[0])
    m, u, theta, t_ms, t = n(mass, 2), n(speed, 2), n(angle, 2), n(contact_ms, 2), n(contact, 2)
    sym_a, sym_b, sym_t = sympy.symbols("a b contact")
    return Question(
        key="oblique-wall-bounce",
        diagram=diagrams.wall_bounce(mass, speed, angle),
        text=(f"A ball of mass {m} kg hits a smooth vertical wall at {u} {PER_S}, moving at {theta}° to the "
              f"wall. It bounces off at the same speed and at the same angle to the wall, and is in contact "
              f"with it for {t_ms} ms. Calculate (a) the component of the ball's momentum at right angles to "
              "the wall before it hits, (b) the change in momentum of the ball, with its direction, and "
              "(c) the average force of the wall on the ball, with its direction."),
        givens=(Given("mass", mass, "kg", 2), Given("speed", speed, "m s^-1", 2), Given("angle", angle, "°", 2),
                Given("contact time", contact_ms, "ms", 2)),
        parts=(
            Part("momentum component at right angles to the wall", across, "N s", "momentum", units=N_S,
                 shown_sig_figs=2,
                 revisit="Resolve: the angle is to the wall, so the component at right angles to it is p sin θ.",
                 mistakes=(
                     Mistake("sin and cos swapped", along,
                             f"That is the component along the wall. The angle {theta}° is measured from "
                             "the wall, so the component at right angles to it is p sin θ."),
                 ), see="two-d"),
            Part("change in momentum of the ball", dp, "N s", "change in momentum", units=N_S,
                 shown_sig_figs=2, direction="choice", choices=_WALL, answer_direction=_WALL[0],
                 ecf=Ecf(2 * sym_a, {}),
                 direction_hint="Only the component at right angles to the wall changes: from towards the "
                                "wall to away from it.",
                 revisit="The component along the wall is unchanged; the one at right angles reverses, so "
                         "Δp = p sin θ − (−p sin θ) = 2p sin θ.",
                 mistakes=(
                     Mistake("forgot the reversal", across,
                             "The component at right angles to the wall reverses: it changes by twice its "
                             "size, 2p sin θ."),
                     Mistake("sin and cos swapped", oblique_bounce_momentum_change(p, 90.0 - angle),  # 2p cos θ
                             "You doubled the component along the wall, which does not change. Double the "
                             "component at right angles to it, p sin θ."),
                 ), see="two-d"),
            Part("average force of the wall on the ball", force, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=_WALL, answer_direction=_WALL[0],
                 ecf=Ecf(sym_b / sym_t, {"contact": contact}),
                 direction_hint="The force on the ball is in the direction of its change in momentum.",
                 revisit="Average force = change in momentum ÷ contact time, with the time in s.",
                 mistakes=(
                     Mistake("milliseconds not converted", average_force(dp, contact_ms),
                             f"You divided by {t_ms} instead of {t}: convert ms to s.", kind="slip"),
                     Mistake("forgot the reversal", average_force(across, contact),
                             "The change in momentum is 2p sin θ, not p sin θ: the component at right "
                             "angles to the wall reverses.", see="two-d"),
                     Mistake("force on the wall", force,
                             "That is the force of the ball on the wall (its third-law pair). The wall "
                             "pushes the ball away from it.", direction=_WALL[1], see="third-law"),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"p = {m} × {u} = {w(p)} N s; at right angles to the wall: {w(p)} sin {theta}°", "C1", "a"),
            Mark(f"= {n(across, 2)} N s", "A1", "a"),
            Mark(f"Δp = 2 × {n(across, 3)}", "C1", "b"),
            Mark(f"= {n(dp, 2)} N s", "A1", "b"),
            Mark("away from the wall, at right angles to it", "B1", "b", earns="direction"),
            Mark(f"F = {n(dp, 3)} / {t}", "C1", "c"),
            Mark(f"= {n(force, 2)} N", "A1", "c"),
            Mark("away from the wall, at right angles to it", "B1", "c", earns="direction"),
        ),
    )


#: Which side of the x-direction the struck puck moves to, against the moving one's side.
_SIDES = ("on the other side of the x-direction from A", "on the same side of the x-direction as A")


def puck_components(m1: float = 0.40, speed_before: float = 2.5, m2: float = 0.60, speed_after: float = 1.5,
                    angle: float = 40.0) -> Question:
    """Components of momentum before and after (issue 25): A, moving along x, hits B at rest and
    moves off at an angle. Resolve A's momentum after (p cos θ along x, p sin θ across it), then
    conserve each component to find B's velocity (notes, "Momentum in two dimensions" and
    Example 4). Named mistakes: sin and cos swapped, momentum added as scalars, a component
    forgotten.

    Marks: 9702/21/M/J/16 Q2(a) credits each component on its own ("12 cos 50°", "12 sin 50°"),
    and Q2(c) a C1 for each step then the A1 for Pythagoras on the components; Q3(b)(ii) gives
    a direction its own B1."""
    if speed_after >= speed_before:
        raise ValueError(f"speed_after must be less than speed_before={speed_before!r} m s^-1: puck A "
                         f"cannot speed up by hitting a puck at rest (got speed_after={speed_after!r})")
    p_before, p_after = momentum(m1, speed_before), momentum(m1, speed_after)
    hit = glancing_collision(p_before, p_after, angle, mass_moving=m1, mass_struck=m2)
    if hit.kinetic_energy_transferred < 0:
        raise ValueError(f"these speeds would create kinetic energy ({n(-hit.kinetic_energy_transferred, 3)} J): "
                         f"lower speed_after={speed_after!r} or raise m2={m2!r}")
    if hit.missing.along <= 0:  # the push on B is along the line of centres, which points forwards
        raise ValueError(f"B must move forwards: A's x-component after, {n(hit.known_vector[0], 3)} N s, must be "
                         f"less than its momentum before, {n(p_before, 3)} N s (got angle={angle!r})")
    a_x, a_y = hit.known_vector
    b = hit.missing
    ma, mb, u, v, theta = n(m1, 2), n(m2, 2), n(speed_before, 2), n(speed_after, 2), n(angle, 2)
    sym_a, sym_b, sym_p, sym_m2 = sympy.symbols("a b p_before m_b")
    return Question(
        key="puck-components",
        diagram=diagrams.glancing(m1, speed_before, speed_after, angle, m2),
        text=(f"On a frictionless air table, puck A of mass {ma} kg moves in the x-direction at {u} {PER_S} "
              f"and hits puck B of mass {mb} kg, which is at rest. After the collision A moves at {v} {PER_S} "
              f"at {theta}° to the x-direction. Calculate (a) the x-component and (b) the size of the "
              "y-component of A's momentum after the collision. For B after the collision, calculate (c) its "
              "speed and (d) the angle between its velocity and the x-direction, and state on which side of "
              "the x-direction it moves."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A before", speed_before, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed of A after", speed_after, "m s^-1", 2),
                Given("angle", angle, "°", 2)),
        parts=(
            Part("x-component of A's momentum after", a_x, "N s", "momentum", units=N_S, shown_sig_figs=2,
                 revisit=f"Resolve A's momentum after: the angle is from the x-direction, so the x-component "
                         f"is p cos {theta}°.",
                 mistakes=(
                     Mistake("sin and cos swapped", a_y,
                             f"You used sin. The angle {theta}° is measured from the x-direction, so the "
                             "x-component is p cos θ and the y-component p sin θ."),
                     Mistake("not resolved", p_after,
                             "That is the whole of A's momentum after. Its x-component is p cos θ."),
                 ), see="two-d"),
            Part("size of the y-component of A's momentum after", a_y, "N s", "momentum", units=N_S,
                 shown_sig_figs=2,
                 revisit="The y-component is at right angles to the x-direction: p sin θ.",
                 mistakes=(
                     Mistake("sin and cos swapped", a_x,
                             f"You used cos. The angle {theta}° is measured from the x-direction, so the "
                             "y-component is p sin θ."),
                     Mistake("not resolved", p_after,
                             "That is the whole of A's momentum after. Its y-component is p sin θ."),
                 ), see="two-d"),
            Part("speed of B after the collision", b.magnitude / m2, "m s^-1", "speed", units=M_S,
                 shown_sig_figs=2,
                 ecf=Ecf(sympy.sqrt((sym_p - sym_a) ** 2 + sym_b**2) / sym_m2, {"p_before": p_before, "m_b": m2}),
                 revisit="Conserve each component: B's x-component = A's momentum before − A's x-component "
                         "after; B's y-component cancels A's. Combine them with Pythagoras, then divide by "
                         "B's mass.",
                 mistakes=_puck_b_speed_mistakes(m1, speed_before, m2, speed_after, angle), see="two-d"),
            Part("angle between B's velocity and the x-direction", b.angle_deg, "°", "angle", units="° (degrees)",
                 shown_sig_figs=3, direction="choice", choices=_SIDES, answer_direction=_SIDES[0],
                 ecf=Ecf(sympy.atan(sym_b / (sym_p - sym_a)) * 180 / sympy.pi, {"p_before": p_before}),
                 direction_hint="Before the collision there is no y-momentum, so after it B's y-component "
                                "cancels A's: B moves to the other side.",
                 revisit="tan θ = (B's y-component) / (B's x-component), on the other side of the "
                         "x-direction from A.",
                 mistakes=_puck_b_angle_mistakes(m1, speed_before, m2, speed_after, angle), see="two-d"),
        ),
        mark_scheme=_puck_components_scheme(m1, speed_before, m2, speed_after, angle),
    )


def _puck_b_speed_mistakes(m1: float, speed_before: float, m2: float, speed_after: float,
                           angle: float) -> tuple[Mistake, ...]:
    """puck_components' wrong speeds of B (c): momentum as scalars, sin and cos swapped, a component
    left out or the two added, A's mass for B's."""
    p_before, p_after = momentum(m1, speed_before), momentum(m1, speed_after)
    b = glancing_collision(p_before, p_after, angle, mass_moving=m1, mass_struck=m2).missing
    swapped = missing_momentum(p_before, p_after, 90.0 - angle)
    mb, theta = n(m2, 2), n(angle, 2)
    return (
        Mistake("momentum added as scalars", velocity_after_collision(m1, speed_before, m2, 0.0,
                                                                         speed_after),
                "You subtracted the sizes of A's momenta as if A carried straight on. Momentum "
                "is a vector: conserve the x- and y-components separately.", see="conservation"),
        Mistake("sin and cos swapped", velocity_from_momentum(swapped.magnitude, m2),
                f"You swapped sin and cos. The angle is from the x-direction, so A's x-component "
                f"is p cos {theta}° and its y-component p sin {theta}°."),
        Mistake("y-component forgotten", velocity_from_momentum(b.along, m2),
                "That uses only B's x-component. B also has a y-component, equal and opposite to "
                "A's: combine them with Pythagoras."),
        Mistake("components added", velocity_from_momentum(b.along + b.across, m2),
                "You added B's two components. They are at right angles: p = √(x² + y²)."),
        Mistake("divided by A's mass", velocity_from_momentum(b.magnitude, m1),
                f"You divided B's momentum by A's mass. v = p / m with B's own mass, {mb} kg.",
                see="momentum"),
    )


def _puck_b_angle_mistakes(m1: float, speed_before: float, m2: float, speed_after: float,
                           angle: float) -> tuple[Mistake, ...]:
    """puck_components' wrong angles of B (d): from the y-direction, A's angle, sin and cos swapped,
    and A's side of the x-direction."""
    p_before, p_after = momentum(m1, speed_before), momentum(m1, speed_after)
    b = glancing_collision(p_before, p_after, angle, mass_moving=m1, mass_struck=m2).missing
    swapped = missing_momentum(p_before, p_after, 90.0 - angle)
    return (
        Mistake("tan the wrong way up", 90.0 - b.angle_deg,
                "You measured the angle from the y-direction. tan θ = y-component / "
                "x-component gives it from the x-direction."),
        Mistake("same angle as A", angle,
                "B need not move at A's angle. Work out B's components and use tan θ = y / x."),
        Mistake("sin and cos swapped", swapped.angle_deg,
                "You swapped sin and cos in resolving A's momentum: its x-component is p cos θ, "
                "its y-component p sin θ."),
        Mistake("same side as A", b.angle_deg,
                "The y-momentum is zero before, so B's y-component is opposite to A's: B moves "
                "to the other side of the x-direction.", direction=_SIDES[1]),
    )


def _puck_components_scheme(m1: float, speed_before: float, m2: float, speed_after: float,
                            angle: float) -> tuple[Mark, ...]:
    """puck_components' mark scheme: each component of A's momentum after (a, b), then B's components,
    Pythagoras and v = p / m (c), and tan θ with B's side (d)."""
    p_before, p_after = momentum(m1, speed_before), momentum(m1, speed_after)
    hit = glancing_collision(p_before, p_after, angle, mass_moving=m1, mass_struck=m2)
    a_x, a_y = hit.known_vector
    b = hit.missing
    ma, mb, u, v, theta = n(m1, 2), n(m2, 2), n(speed_before, 2), n(speed_after, 2), n(angle, 2)
    # B's components with the figures that the speed and the angle need, from (a) and (b) as printed
    b_x_text = n(b.along, 3)
    (a_x_carried,) = enough_figures((a_x,), lambda x: p_before - x, b_x_text)
    b_x, b_y = enough_figures((b.along, b.across), lambda x, y: math.hypot(x, y), n(b.magnitude, 3))
    b_x_t, b_y_t = enough_figures((b.along, b.across), lambda x, y: math.degrees(math.atan2(y, x)),
                                  n(b.angle_deg, 3))
    return (
        Mark(f"p<sub>A</sub> after = {ma} × {v} = {w(p_after)} N s; x-component = {w(p_after)} cos {theta}°",
             "C1", "a"),
        Mark(f"= {n(a_x, 2)} N s", "A1", "a"),
        Mark(f"y-component = {w(p_after)} sin {theta}°", "C1", "b"),
        Mark(f"= {n(a_y, 2)} N s", "A1", "b"),
        Mark(f"B, x: {ma} × {u} = {w(p_before)} = {a_x_carried} + p<sub>x</sub>, so p<sub>x</sub> = "
             f"{b_x_text} N s; y: p<sub>y</sub> = {n(b.across, 3)} N s, opposite to A's", "C1", "c"),
        Mark(f"p<sub>B</sub> = √({b_x}<sup>2</sup> + {b_y}<sup>2</sup>) = {n(b.magnitude, 3)} N s", "C1", "c"),
        Mark(f"v = {n(b.magnitude, 3)} / {mb} = {n(b.magnitude / m2, 2)} {PER_S}", "A1", "c"),
        Mark(f"tan θ = {b_y_t} / {b_x_t}", "C1", "d"),
        Mark(f"θ = {n(b.angle_deg, 3)}°", "A1", "d"),
        Mark("on the other side of the x-direction from A (the y-components cancel)", "B1", "d",
             earns="direction"),
    )


def explosion_two_pieces(mass: float = 2.0, speed: float = 5.0, piece: float = 0.50, piece_speed: float = 12.0,
                         angle: float = 40.0, side: float = 0) -> Question:
    """An explosion into two pieces at an angle (issue 25): a shell moving due east splits in two;
    one piece's velocity is given at an angle north or south of east. Conserve momentum east and
    north separately (notes, "Momentum in two dimensions"): the other piece's eastward momentum
    is M u - m₁v₁ cos θ (negative: it moves west) and its north-south momentum cancels the
    first piece's. Named mistakes: sin and cos swapped, momentum added as scalars, a component
    forgotten, the momentum before forgotten.

    Marks: 9702/21/M/J/16 Q2(a) credits each resolved component, Q2(c) a C1 for each step and the
    A1 for Pythagoras on the components; Q3(b)(ii) gives C1 then A1, and the direction its own B1."""
    north = int(side) == 0
    split = split_in_two(mass, speed, piece, piece_speed, angle)
    if abs(split.along) < 0.05 * split.magnitude:  # almost due north or south: no angle to east-west to ask
        raise ValueError(f"the other piece must not move almost due north or south (eastward momentum "
                         f"{n(split.along, 2)} N s; got angle={angle!r})")
    p_before, p_piece = momentum(mass, speed), momentum(piece, piece_speed)
    east, across = split.along, abs(split.across)
    angle_other = math.degrees(math.atan2(across, abs(east)))  # from the east-west line
    first = "north" if north else "south"
    other = "south" if north else "north"
    answer = f"{other} of {'east' if east > 0 else 'west'}"
    sym_a, sym_b, sym_m = sympy.symbols("a b m_rest")
    mm, uu, m1, v1, theta, rest = n(mass, 2), n(speed, 2), n(piece, 2), n(piece_speed, 2), n(angle, 2), n(split.mass, 2)
    moving = f"moving horizontally due east at {uu} {PER_S}" if speed else "at rest"  # papers' fireworks start at rest
    return Question(
        key="explosion-two-pieces",
        diagram=diagrams.explosion_moving(mass, speed, piece, piece_speed, angle, north),
        text=(f"A firework shell of mass {mm} kg is {moving} when it explodes "
              f"into two pieces. Just after the explosion, a piece of mass {m1} kg moves horizontally at {v1} "
              f"{PER_S} at {theta}° {first} of east. For the other piece, calculate (a) its momentum due east "
              "(negative if it moves west), (b) the size of its momentum due north or south, (c) its speed and "
              "(d) the angle between its direction and the east–west line, and give the direction."),
        givens=(Given("mass of the shell", mass, "kg", 2), Given("speed of the shell", speed, "m s^-1", 2),
                Given("mass of the piece", piece, "kg", 2), Given("speed of the piece", piece_speed, "m s^-1", 2),
                Given("angle", angle, "°", 2)),
        parts=(
            Part("momentum of the other piece due east", east, "N s", "momentum", units=N_S, shown_sig_figs=2,
                 direction="signed", positive="east",
                 revisit=f"Eastward momentum is conserved: {mm} × {uu} = (the piece's p cos {theta}°) + (the "
                         "other piece's eastward momentum).",
                 mistakes=_distinct_at_rest(speed, east, (
                     Mistake("sin and cos swapped", p_before - p_piece * math.sin(math.radians(angle)),
                             f"You used sin. The angle {theta}° is measured from east, so the piece's eastward "
                             "component is p cos θ."),
                     Mistake("momentum before forgotten", -p_piece * math.cos(math.radians(angle)),
                             f"The shell was moving before it exploded: the total eastward momentum is "
                             f"{mm} × {uu} N s, not zero.", see="explosions"),
                 ), signed=True), see="two-d"),
            Part("size of the other piece's momentum due north or south", across, "N s", "momentum", units=N_S,
                 shown_sig_figs=2,
                 revisit="There is no north–south momentum before, so the other piece's north–south component "
                         f"cancels the piece's, p sin {theta}°.",
                 mistakes=_distinct_at_rest(speed, across, (
                     Mistake("sin and cos swapped", p_piece * math.cos(math.radians(angle)),
                             f"You used cos. The angle {theta}° is measured from east, so the north–south "
                             "component is p sin θ."),
                     Mistake("mass left out", piece_speed * math.sin(math.radians(angle)),
                             "That is a component of the velocity. Momentum = mass × velocity: multiply by "
                             f"the piece's mass, {m1} kg.", see="momentum"),
                 )), see="two-d"),
            Part("speed of the other piece", split.speed, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 ecf=Ecf(sympy.sqrt(sym_a**2 + sym_b**2) / sym_m, {"m_rest": split.mass}),
                 revisit=f"Combine the two components with Pythagoras, then divide by the other piece's mass, "
                         f"{mm} − {m1} = {rest} kg.",
                 mistakes=_other_piece_speed_mistakes(mass, speed, piece, piece_speed, angle), see="two-d"),
            Part("angle between the other piece's direction and the east–west line", angle_other, "°", "angle",
                 units="° (degrees)", shown_sig_figs=3, direction="choice", choices=_COMPASS,
                 answer_direction=answer,
                 ecf=Ecf(sympy.atan(sym_b / sympy.Abs(sym_a)) * 180 / sympy.pi, {}),
                 direction_hint=f"The north–south momentum cancels, so the other piece moves {other}; its "
                                f"eastward momentum in (a) says east or west.",
                 revisit="tan θ = (north–south momentum) / (east–west momentum); the north–south component "
                         "is opposite to the first piece's.",
                 mistakes=_other_piece_angle_mistakes(mass, speed, piece, piece_speed, angle, north),
                 see="two-d"),
        ),
        mark_scheme=_explosion_two_pieces_scheme(mass, speed, piece, piece_speed, angle, answer),
    )


def _distinct_at_rest(speed: float, key: float, mistakes: tuple[Mistake, ...], *,
                      signed: bool = False) -> tuple[Mistake, ...]:
    """A shell's mistakes, one of each value when it was at rest: with no momentum before, routes that
    differ for a moving shell meet the key or each other (a moving shell keeps every mistake, as drawn)."""
    return mistakes if speed else one_of_each(key, mistakes, signed=signed)


def _other_piece_speed_mistakes(mass: float, speed: float, piece: float, piece_speed: float,
                                angle: float) -> tuple[Mistake, ...]:
    """explosion_two_pieces' wrong speeds of the other piece (c): momentum as scalars, sin and cos
    swapped, the north-south component left out, the shell's mass for the piece's."""
    split = split_in_two(mass, speed, piece, piece_speed, angle)
    swapped = split_in_two(mass, speed, piece, piece_speed, 90.0 - angle)
    p_before, p_piece = momentum(mass, speed), momentum(piece, piece_speed)
    mm, m1, rest = n(mass, 2), n(piece, 2), n(split.mass, 2)
    return _distinct_at_rest(speed, split.speed, (
        Mistake("momentum added as scalars", abs(p_before - p_piece) / split.mass,
                "You subtracted the sizes of the momenta as if both moved along one line. "
                "Momentum is a vector: conserve the east and north components separately.",
                see="conservation"),
        Mistake("sin and cos swapped", swapped.speed,
                "You swapped sin and cos: the angle is from east, so the piece's eastward "
                "component is p cos θ and its north–south one p sin θ."),
        Mistake("north–south component forgotten", abs(split.along) / split.mass,
                "That uses only the eastward component. The other piece also has a north–south "
                "component: combine them with Pythagoras."),
        Mistake("divided by the shell's mass", split.magnitude / mass,
                f"You divided by the whole shell's mass. The other piece's mass is {mm} − {m1} = "
                f"{rest} kg.", see="momentum"),
    ))


def _other_piece_angle_mistakes(mass: float, speed: float, piece: float, piece_speed: float, angle: float,
                                north: bool) -> tuple[Mistake, ...]:
    """explosion_two_pieces' wrong angles of the other piece (d): from north-south, sin and cos swapped,
    the first piece's angle, and the first piece's side."""
    split = split_in_two(mass, speed, piece, piece_speed, angle)
    swapped = split_in_two(mass, speed, piece, piece_speed, 90.0 - angle)
    east = split.along
    angle_other = math.degrees(math.atan2(abs(split.across), abs(east)))  # from the east-west line
    first, other = ("north", "south") if north else ("south", "north")
    wrong_side = f"{first} of {'east' if east > 0 else 'west'}"
    return _distinct_at_rest(speed, angle_other, (
        Mistake("tan the wrong way up", 90.0 - angle_other,
                "You measured the angle from north–south. tan θ = (north–south momentum) / "
                "(east–west momentum) gives it from the east–west line."),
        Mistake("sin and cos swapped", math.degrees(math.atan2(abs(swapped.across), abs(swapped.along))),
                "You swapped sin and cos in resolving the piece's momentum: eastward p cos θ, "
                "north–south p sin θ."),
        Mistake("same angle as the first piece", angle,
                "The other piece need not move at the first piece's angle. Work out its "
                "components and use tan θ = (north–south) / (east–west)."),
        Mistake("same side as the first piece", angle_other,
                f"The north–south momentum is zero before, so the other piece moves {other}, "
                "opposite to the first piece.", direction=wrong_side),
    ))


def _explosion_two_pieces_scheme(mass: float, speed: float, piece: float, piece_speed: float, angle: float,
                                 answer: str) -> tuple[Mark, ...]:
    """explosion_two_pieces' mark scheme: each component conserved (a, b), Pythagoras and v = p / m (c),
    tan θ and the direction (d), the momentum printed with the figures its results need."""
    split = split_in_two(mass, speed, piece, piece_speed, angle)
    p_before, p_piece = momentum(mass, speed), momentum(piece, piece_speed)
    east, across = split.along, abs(split.across)
    angle_other = math.degrees(math.atan2(across, abs(east)))
    mm, uu, m1, v1, theta = n(mass, 2), n(speed, 2), n(piece, 2), n(piece_speed, 2), n(angle, 2)
    # the momentum printed with the figures its speed needs (19.45 / 3.5 = 5.6, where 19.4 gives 5.5)
    (magnitude,) = enough_figures((split.magnitude,), lambda p: p / split.mass, n(split.speed, 2))
    (east_c, across_c) = enough_figures((abs(east), across), lambda x, y: math.hypot(x, y), magnitude)
    (east_d, across_d) = enough_figures((abs(east), across), lambda x, y: math.degrees(math.atan2(y, x)),
                                        n(angle_other, 3))
    return (
        Mark(f"East: {mm} × {uu} = {m1} × {v1} cos {theta}° + p<sub>E</sub>", "C1", "a"),
        Mark(f"p<sub>E</sub> = {w(p_before)} − {w(p_piece)} cos {theta}° = {n(east, 2)} N s", "A1", "a"),
        Mark(f"North–south: 0 = {w(p_piece)} sin {theta}° − p<sub>N</sub>", "C1", "b"),
        Mark(f"p<sub>N</sub> = {n(across, 2)} N s", "A1", "b"),
        Mark(f"p = √({east_c}<sup>2</sup> + {across_c}<sup>2</sup>) = {magnitude} N s", "C1", "c"),
        Mark(f"v = {magnitude} / ({mm} − {m1}) = {n(split.speed, 2)} {PER_S}", "A1", "c"),
        Mark(f"tan θ = {across_d} / {east_d}", "C1", "d"),
        Mark(f"θ = {n(angle_other, 3)}°", "A1", "d"),
        Mark(f"{answer} (the north–south momentum cancels the first piece's)", "B1", "d", earns="direction"),
    )


TEMPLATES = checked_givens(
    Template("practice-pucks", "two-d", ("numeric",), "Pucks on an air table", pucks_glancing,
             {"mass": Draw(0.40, 0.20, 0.80, 0.05), "speed_before": Draw(2.5, 1.0, 4.0, 0.1),
              "speed_after": Draw(1.5, 0.5, 3.0, 0.1), "angle": Draw(40.0, 20.0, 70.0, 5.0)}),
    Template("glancing-speed-choice", "two-d", ("mcq",), "Speed after a glancing collision",
             glancing_speed_choice,
             {"m1": Draw(0.20, 0.10, 0.40, 0.05), "speed_before": Draw(3.0, 2.0, 5.0, 0.5),
              "m2": Draw(0.30, 0.10, 0.50, 0.05), "speed_after": Draw(1.5, 0.5, 2.5, 0.5),
              "angle": Draw(40.0, 20.0, 70.0, 5.0)}),
    Template("explosion-three-pieces", "two-d", ("numeric",), "A firework explodes", explosion_three_pieces,
             {"m1": Draw(0.20, 0.10, 0.50, 0.05), "v1": Draw(30.0, 10.0, 50.0, 5.0),
              "m2": Draw(0.30, 0.10, 0.50, 0.05), "v2": Draw(15.0, 10.0, 50.0, 5.0),
              "m3": Draw(0.50, 0.20, 1.00, 0.10), "heading": Draw(0, 0, len(_HEADINGS) - 1, 1)}),
    Template("skaters-stick-right-angles", "two-d", ("numeric",), "Skaters at right angles",
             skaters_stick_right_angles,
             {"m1": Draw(70.0, 50.0, 100.0, 5.0), "u1": Draw(4.0, 2.0, 8.0, 0.5),
              "m2": Draw(50.0, 50.0, 100.0, 5.0), "u2": Draw(3.0, 2.0, 8.0, 0.5)}),
    Template("oblique-wall-bounce", "two-d", ("numeric",), "A ball bounces off a wall at an angle",
             oblique_wall_bounce,
             {"mass": Draw(0.060, 0.050, 0.200, 0.010), "speed": Draw(20.0, 10.0, 30.0, 1.0),
              "angle": Draw(40.0, 20.0, 70.0, 5.0), "contact_ms": Draw(5.0, 2.0, 10.0, 0.5)}),
    Template("puck-components", "two-d", ("numeric",), "Components before and after", puck_components,
             {"m1": Draw(0.40, 0.20, 0.80, 0.05), "speed_before": Draw(2.5, 1.5, 4.0, 0.1),
              "m2": Draw(0.60, 0.20, 0.80, 0.05), "speed_after": Draw(1.5, 0.5, 3.0, 0.1),
              "angle": Draw(40.0, 20.0, 70.0, 5.0)}),
    Template("explosion-two-pieces", "two-d", ("numeric",), "An explosion into two pieces at an angle",
             explosion_two_pieces,
             {"mass": Draw(2.0, 2.0, 4.0, 0.5), "speed": Draw(5.0, 2.0, 9.0, 1.0),
              "piece": Draw(0.50, 0.20, 0.90, 0.10), "piece_speed": Draw(12.0, 8.0, 30.0, 1.0),
              "angle": Draw(40.0, 20.0, 70.0, 5.0), "side": Draw(0, 0, 1, 1)}),
)
