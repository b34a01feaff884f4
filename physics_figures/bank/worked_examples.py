# ruff: noqa: RUF001  (question text and feedback are typeset: true minus, times, Greek letters)
"""The try-first parts of the worked examples: the printed numbers only (no New numbers),
and not counted among the bank's templates.

Each worked example (book/exam/example-N.md) gets one question, placed just above its
solution, with a box for every numeric part: the parts its mark scheme marks as a
calculation or a single point (C1/A1 or B1). A part that asks to show that, to explain
or to state a principle (M1) is read in the solution. The statement is on the page just
above, so the question's text only says what to work out, and which part of the example
each box answers when the letters differ (the boxes are lettered (a), (b), ... in order).

Keys come from the models with the example's own numbers, so they equal the values the
page glues from physics_figures.answers (tests/no_site/test_worked_examples_try.py checks it);
the mark-scheme lines carry the codes of the example's solution.
"""

from __future__ import annotations

import math

import sympy

from .. import scenarios
from ..constants import G_EARTH
from ..models import (
    GlancingCollision,
    acceleration,
    average_force,
    change_in_momentum,
    drag_at_terminal_velocity,
    kinetic_energy,
    momentum,
    towing,
    upthrust,
    velocity_after_collision,
    weight,
)
from ..notation import format_number as n
from ..questions import Ecf, Mark, Mistake, Part, Question
from ..variants import Template
from ._common import MOMENTUM_WORKING_C1
from .givens import checked_givens

_N_S = "N s or kg m s^-1"
_M_S = "m s^-1 (m/s)"
_M_S2 = "m s^-2 (m/s^2)"
a_, b_, c_ = sympy.symbols("a b c")

#: For each try-first question, the example's part that each box answers, in box order.
EXAMPLE_PARTS: dict[str, tuple[str, ...]] = {
    "example-1-try": ("a", "b", "c"),
    "example-2-try": ("a", "b", "d"),
    "example-3-try": ("b", "d"),
    "example-4-try": ("a", "a", "b", "b", "c"),
    "example-5-try": ("b", "c", "d"),
}


def _which_parts(key: str) -> str:
    """" Here (c) answers the example's (d)." for the boxes whose letters differ from the
    example's parts, else ""."""
    boxes: dict[str, list[str]] = {}
    for box, part in zip("abcdefghij", EXAMPLE_PARTS[key], strict=False):
        boxes.setdefault(part, []).append(f"({box})")
    differ = [(part, ids) for part, ids in boxes.items() if ids != [f"({part})"]]
    if not differ:
        return ""
    phrases = [f"{' and '.join(ids)} {'answer' if len(ids) > 1 else 'answers'} the example's ({part})"
               if i == 0 else f"{' and '.join(ids)} its ({part})" for i, (part, ids) in enumerate(differ)]
    listed = phrases[0] if len(phrases) == 1 else ", ".join(phrases[:-1]) + " and " + phrases[-1]
    return f" Here {listed}."


def _text(key: str, asks: str) -> str:
    return f"Try it before you read the solution: work out {asks}.{_which_parts(key)}"


# ----------------------------------------------------------------------- Example 1

def car_and_trailer() -> Question:
    """Notes, Worked examples > Example 1: a = 1.5 m s^-2, T = 800 N, 800 N backwards on the car."""
    key = "example-1-try"
    driving, (car, trailer), (car_drag, trailer_drag) = 3000.0, (1200.0, 400.0), (400.0, 200.0)
    towed = towing(driving, (car, trailer), (car_drag, trailer_drag))
    a, (tension,) = towed.acceleration, towed.tensions
    total = car + trailer
    mass_t, drag_t = sympy.symbols("trailer_mass trailer_resistance")
    return Question(
        key=key,
        text=_text(key, "the acceleration, the tension in the tow bar, and the size and direction "
                        "of the force the trailer exerts on the car"),
        givens=(),  # the example's statement, just above on the page, gives the numbers
        parts=(
            Part("acceleration of the car and trailer", a, "m s^-2", "acceleration", units=_M_S2,
                 shown_sig_figs=2,
                 revisit="Treat the car and trailer as one object: the resultant of the external "
                         "forces (driving force minus both resistive forces) over the total mass.",
                 mistakes=(
                     Mistake("resistive forces left out", acceleration(driving, total),
                             f"You left out the resistive forces. The resultant force is "
                             f"{n(driving, 2)} − {n(car_drag, 1)} − {n(trailer_drag, 1)} N; revisit "
                             "Newton's second law with the resultant force.", see="second-law"),
                     Mistake("trailer's resistance left out", acceleration(driving - car_drag, total),
                             f"You left out the {n(trailer_drag, 1)} N resistive force on the trailer. "
                             "For the car and trailer as one object every external force counts."),
                     Mistake("car's resistance left out", acceleration(driving - trailer_drag, total),
                             f"You left out the {n(car_drag, 1)} N resistive force on the car. For the "
                             "car and trailer as one object every external force counts."),
                     Mistake("car's mass only", acceleration(towed.resultant_force, car),
                             f"You divided by the car's mass only. The resultant force accelerates the "
                             f"car and the trailer: use the total mass, {n(total, 2)} kg.", see="second-law"),
                 ), see="second-law"),
            Part("tension in the tow bar", tension, "N", "force", shown_sig_figs=2,
                 ecf=Ecf(drag_t + mass_t * a_, {"trailer_resistance": trailer_drag, "trailer_mass": trailer}),
                 revisit=f"Newton's second law for the trailer alone: T − {n(trailer_drag, 1)} = "
                         f"{n(trailer, 1)} × a.",
                 mistakes=(
                     Mistake("trailer's resistance left out", trailer * a,
                             f"That is the trailer's resultant force, ma. The tension must also overcome "
                             f"the trailer's {n(trailer_drag, 1)} N resistance: T − {n(trailer_drag, 1)} = "
                             f"{n(trailer, 1)}a."),
                     Mistake("resistance subtracted", trailer * a - trailer_drag,
                             "The resistance acts backwards on the trailer, so the tow bar must pull "
                             f"harder than ma: T = {n(trailer, 1)}a + {n(trailer_drag, 1)}."),
                     Mistake("the car's resultant force", car * a,
                             "That is the resultant force on the car (its mass × a), not one of the "
                             "forces on it. Mixing up the resultant with one force: write F = ma for "
                             "the trailer alone."),
                 ), see="second-law"),
            Part("force the trailer exerts on the car", tension, "N", "force", shown_sig_figs=2,
                 asks="state", direction="choice", choices=("forwards", "backwards"),
                 answer_direction="backwards",
                 direction_hint="By Newton's third law the trailer pulls the car with a force "
                                "opposite to the car's pull on the trailer, which is forwards.",
                 ecf=Ecf(b_, {}),
                 revisit="Newton's third law: the trailer pulls on the car with a force equal and "
                         "opposite to the car's pull on the trailer, the tension in the tow bar.",
                 mistakes=(
                     Mistake("the car's resultant force", car * a,
                             "That is the resultant force on the car. The trailer's pull on the car "
                             "pairs with the car's pull on the trailer (Newton's third law): it is "
                             "the tension."),
                     Mistake("the trailer's resultant force", trailer * a,
                             "That is the resultant force on the trailer, ma. The force between them "
                             "is the tension, which also overcomes the trailer's resistance.", see="second-law"),
                 ), see="third-law"),
        ),
        mark_scheme=(
            Mark(f"Whole: resultant force = {n(driving, 2)} − {n(car_drag, 1)} − {n(trailer_drag, 1)} = "
                 f"{n(towed.resultant_force, 2)} N", "C1", "a"),
            Mark(f"a = {n(towed.resultant_force, 2)} / {n(total, 2)} = {n(a, 2)} m s<sup>−2</sup>", "A1", "a"),
            Mark(f"Trailer alone: T − {n(trailer_drag, 1)} = {n(trailer, 1)} × {n(a, 2)}", "C1", "b"),
            Mark(f"T = {n(tension, 2)} N", "A1", "b"),
            Mark(f"{n(tension, 2)} N", "B1", "c"),
            Mark("backwards (opposite to the motion), by Newton's third law", "B1", "c", earns="direction"),
        ),
    )


# ----------------------------------------------------------------------- Example 2

def ball_off_a_wall() -> Question:
    """Notes, Worked examples > Example 2: Δp = 2.44 N s, 203 N on the ball, 203 N on the wall."""
    key = "example-2-try"
    mass, u, v, contact = 0.058, -24.0, 18.0, 0.012  # away from the wall positive; 12 ms
    dp = change_in_momentum(mass, u, v)
    force = average_force(dp, contact)
    sizes_subtracted = abs(change_in_momentum(mass, -u, v))
    in_ms = n(contact * 1000, 2)  # the statement gives the contact time in ms
    duration = sympy.Symbol("contact_time")
    return Question(
        key=key,
        text=_text(key, "the change in momentum of the ball, the force on the ball, and the force "
                        "on the wall with its direction"),
        givens=(),  # the example's statement, just above on the page, gives the numbers
        parts=(
            Part("change in momentum of the ball", dp, "N s", "momentum", units=_N_S, shown_sig_figs=3,
                 sign_means="the change is away from the wall (you took towards the wall as positive)",
                 revisit=f"Δp = mv − mu with signs: the ball turns round, so with away from the wall "
                         f"positive u = {n(u, 2)} m s⁻¹ and v = +{n(v, 2)} m s⁻¹.",
                 mistakes=(
                     Mistake("speeds subtracted", sizes_subtracted,
                             f"You subtracted the speeds. The ball turns round, so its velocities have "
                             f"opposite signs and the size of Δp is the mass × the sum of the speeds, "
                             f"{n(mass, 2)} × ({n(v, 2)} + {n(-u, 2)}). Revisit wrong signs in the "
                             "common mistakes.", keeps=("method",), credited=MOMENTUM_WORKING_C1),
                     Mistake("final momentum only", momentum(mass, v),
                             "That is the momentum after the bounce. The change is final minus "
                             "initial momentum, with the initial one negative.", keeps=("method",),
                             credited=MOMENTUM_WORKING_C1, see="conservation"),
                     Mistake("initial momentum only", momentum(mass, -u),
                             "That is the momentum before the bounce. The change is final minus "
                             "initial momentum, with the initial one negative.", keeps=("method",),
                             credited=MOMENTUM_WORKING_C1, see="conservation"),
                     Mistake("kinetic energy instead of momentum",
                             kinetic_energy(mass, u) - kinetic_energy(mass, v),
                             "That is the kinetic energy lost, in J. Momentum is mass × velocity, "
                             "a vector, in N s.", unit="J", see="kinetic-energy"),
                 ), see="second-law"),
            Part("average force exerted on the ball by the wall", force, "N", "force", shown_sig_figs=3,
                 ecf=Ecf(a_ / duration, {"contact_time": contact}),
                 revisit=f"Force = rate of change of momentum: F = Δp / Δt, with Δt = {in_ms} ms = "
                         f"{n(contact, 2)} s.",
                 mistakes=(
                     Mistake("time left in ms", dp / (contact * 1000),
                             f"You divided by {in_ms}, the time in ms. Convert to seconds: {in_ms} ms = "
                             f"{n(contact, 2)} s.", kind="slip"),
                     Mistake("speeds subtracted", sizes_subtracted / contact,
                             "Your change in momentum subtracts the speeds. The ball turns round, so the "
                             "size of Δp is the mass × the sum of the speeds; then F = Δp / Δt."),
                     Mistake("final momentum over time", momentum(mass, v) / contact,
                             "You used the ball's final momentum. The force is the change in "
                             "momentum ÷ time (using the wrong momentum for a force)."),
                 ), see="second-law"),
            Part("average force exerted on the wall by the ball", force, "N", "force", shown_sig_figs=3,
                 asks="state", direction="choice", choices=("towards the wall", "away from the wall"),
                 answer_direction="towards the wall",
                 direction_hint="Newton's third law: the ball pushes the wall the opposite way to the "
                                "wall's push on the ball, which is away from the wall.",
                 ecf=Ecf(b_, {}),
                 revisit="Newton's third law: the force on the wall is equal in size and opposite in "
                         "direction to the force on the ball.",
                 mistakes=(
                     Mistake("time left in ms", dp / (contact * 1000),
                             f"That is Δp ÷ {in_ms}. The time must be in seconds, {n(contact, 2)} s; then the force "
                             "on the wall equals the force on the ball, by Newton's third law.", kind="slip"),
                 ), see="third-law"),
        ),
        mark_scheme=(
            Mark(f"Δp = mv − mu = {n(mass, 2)} × {n(v, 2)} − {n(mass, 2)} × ({n(u, 2)})", "C1", "a"),
            Mark(f"= {n(mass, 2)} × {n(v - u, 2)} = {n(dp, 3)} N s, away from the wall", "A1", "a"),
            Mark(f"F = Δp / Δt = {n(dp, 4)} / {n(contact, 2)} = {n(force, 3)} N away from the wall", "B1", "b"),
            Mark(f"{n(force, 3)} N towards the wall (Newton's third law)", "B1", "c"),
        ),
    )


# ----------------------------------------------------------------------- Example 3

def two_trolleys() -> Question:
    """Notes, Worked examples > Example 3: v_B = 3.0 m s^-1; force on B 24 N."""
    key = "example-3-try"
    m_a, u_a, m_b, u_b, v_a, contact = 0.60, 2.5, 0.40, 0.0, 0.50, 0.050
    v_b = velocity_after_collision(m_a, u_a, m_b, u_b, v_a)
    dp_b = change_in_momentum(m_b, u_b, v_b)
    force = average_force(dp_b, contact)
    before, a_after = momentum(m_a, u_a), momentum(m_a, v_a)
    mass_b, duration = sympy.symbols("mass_b contact_time")
    return Question(
        key=key,
        text=_text(key, "the velocity of B after the collision and the average force on B"),
        givens=(),  # the example's statement, just above on the page, gives the numbers
        parts=(
            Part("velocity of B after the collision", v_b, "m s^-1", "velocity", units=_M_S,
                 shown_sig_figs=2, direction="signed", positive="A's original direction",
                 revisit="Momentum before = momentum after: m_A u_A + m_B u_B = m_A v_A + m_B v_B.",
                 mistakes=(
                     Mistake("A's momentum after left out", before / m_b,
                             f"You left out A's momentum after the collision. A still moves at "
                             f"{n(v_a, 2)} m s⁻¹: {n(before, 3)} = {n(a_after, 2)} + {n(m_b, 2)}v."),
                     Mistake("A's momentum after added", (before + a_after) / m_b,
                             "A's momentum after is on the same side as B's: momentum after = "
                             f"{n(a_after, 2)} + {n(m_b, 2)}v, so subtract it from the momentum before."),
                     Mistake("A's mass used", (before - a_after) / m_a,
                             f"You divided by A's mass. B's momentum after is {n(m_b, 2)}v: divide "
                             f"by B's mass, {n(m_b, 2)} kg."),
                 ), see="conservation"),
            Part("average force on B", force, "N", "force", shown_sig_figs=2,
                 ecf=Ecf(mass_b * a_ / duration, {"mass_b": m_b, "contact_time": contact}),
                 revisit="The force on B is B's own change in momentum ÷ the contact time: "
                         "F = Δp / Δt.",
                 mistakes=(
                     Mistake("A's momentum before", before / contact,
                             "That is A's momentum before ÷ time. The force on B is B's own change "
                             "in momentum ÷ time.", see="conservation"),
                     Mistake("mass left out", v_b / contact,
                             "You divided B's speed by the time: that is its acceleration, in m s⁻². "
                             "Force = change in momentum ÷ time, and momentum = mass × velocity."),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"{n(m_a, 2)} × {n(u_a, 2)} + 0 = {n(m_a, 2)} × {n(v_a, 2)} + {n(m_b, 2)}v", "C1", "a"),
            Mark(f"{n(before, 3)} = {n(a_after, 2)} + {n(m_b, 2)}v, so v = {n(v_b, 2)} m s<sup>−1</sup> "
                 "in A's original direction", "A1", "a"),
            Mark(f"Δp of B = {n(m_b, 2)} × {n(v_b, 2)} = {n(dp_b, 2)} N s", "C1", "b"),
            Mark(f"F = {n(dp_b, 2)} / {n(contact, 2)} = {n(force, 2)} N", "A1", "b"),
        ),
    )


# ----------------------------------------------------------------------- Example 4

def pucks_on_an_air_table() -> Question:
    """Notes, Worked examples > Example 4: Y has 0.42 and 0.312 N s, 1.74 m s^-1 at 36.6°;
    kinetic energy 0.90 J before, 0.78 J after (the corrected working keeps 1.744 m s^-1)."""
    key = "example-4-try"
    pucks = scenarios.EXAMPLE_4
    m_x, m_y, angle = pucks.mass_moving, pucks.mass_struck, pucks.angle_known_deg
    v_x = pucks.speed_known
    y = pucks.missing
    ke_x, ke_y = pucks.kinetic_energies_after
    mass_x, mass_y, speed_x = sympy.symbols("mass_x mass_y speed_x")
    angle_text = f"{n(angle, 2)}°"
    return Question(
        key=key,
        text=_text(key, "the components of Y's momentum, its speed and direction, and the kinetic "
                        "energy after the collision"),
        givens=(),  # the example's statement, just above on the page, gives the numbers
        parts=(
            Part("component of Y's momentum along X's original direction", y.along, "N s", "momentum",
                 units=_N_S, shown_sig_figs=2,
                 revisit="Conserve momentum along the line: momentum before = X's component along "
                         f"the line after (p cos {angle_text}) + Y's.",
                 mistakes=_pucks_along_mistakes(pucks), see="two-d"),
            Part("component of Y's momentum at right angles to X's original direction", y.across, "N s",
                 "momentum", units=_N_S, shown_sig_figs=3,
                 revisit="Across the line the momentum before is zero, so Y's component cancels X's: "
                         f"p sin {angle_text}.",
                 mistakes=_pucks_across_mistakes(pucks), see="two-d"),
            Part("speed of Y", pucks.speed_missing, "m s^-1", "speed", units=_M_S, shown_sig_figs=3,
                 ecf=Ecf(sympy.sqrt(a_**2 + b_**2) / mass_y, {"mass_y": m_y}),
                 revisit="Combine the components with Pythagoras, p = √(along² + across²), then "
                         "v = p / m with Y's mass.",
                 mistakes=(
                     Mistake("components added", (y.along + y.across) / m_y,
                             "You added the components. They are at right angles: combine them "
                             "with Pythagoras, √(along² + across²)."),
                     Mistake("momentum given as speed", y.magnitude,
                             f"That is Y's momentum in N s. Divide by Y's mass, {n(m_y, 2)} kg, for its "
                             "speed.", see="momentum"),
                     Mistake("X's mass used", y.magnitude / m_x,
                             f"You divided by X's mass. Y's speed is its momentum ÷ its own mass, "
                             f"{n(m_y, 2)} kg.", see="momentum"),
                 ), see="two-d"),
            Part("angle between Y's motion and X's original direction", y.angle_deg, "°", "angle",
                 units="° (degrees)", shown_sig_figs=3,
                 ecf=Ecf(180 * sympy.atan(b_ / a_) / sympy.pi, {}),
                 revisit="tan θ = across component / along component, measured from X's original "
                         "direction, on the other side of it from X.",
                 mistakes=(
                     Mistake("tangent upside down", math.degrees(math.atan2(y.along, y.across)),
                             "That is the angle from the line at right angles. From X's original "
                             "direction, tan θ = across / along."),
                     Mistake("X's angle", angle,
                             "Y need not move off at X's angle. Work out Y's components and use "
                             "tan θ = across / along."),
                 ), see="two-d"),
            Part("total kinetic energy after the collision", pucks.kinetic_energy_after, "J", "energy",
                 shown_sig_figs=2,
                 ecf=Ecf(mass_x * speed_x**2 / 2 + mass_y * c_**2 / 2,
                         {"mass_x": m_x, "speed_x": v_x, "mass_y": m_y}),
                 revisit="Kinetic energy is a scalar: add ½mv² for X and for Y after the collision.",
                 mistakes=(
                     Mistake("kinetic energy conserved", pucks.kinetic_energy_before,
                             "That is the kinetic energy before. Kinetic energy is conserved only in "
                             "an elastic collision, which is what you are testing: work it out from "
                             "the speeds after."),
                     Mistake("Y's kinetic energy only", ke_y,
                             "That is Y's kinetic energy only. Add X's: ½ × "
                             f"{n(m_x, 2)} × {n(v_x, 2)}²."),
                     Mistake("X's kinetic energy only", ke_x,
                             "That is X's kinetic energy only. Add Y's, from the speed you found."),
                     Mistake("speeds not squared", m_x * v_x / 2 + m_y * pucks.speed_missing / 2,
                             "Kinetic energy is ½mv²: you left the speeds unsquared. Square each speed, then add "
                             "X's and Y's."),
                 ), see="kinetic-energy"),
        ),
        mark_scheme=_pucks_on_an_air_table_scheme(pucks),
    )


def _pucks_along_mistakes(pucks: GlancingCollision) -> tuple[Mistake, ...]:
    """Example 4's wrong components of Y's momentum along the line (a): X's momentum after not
    resolved, sine for cosine, velocities conserved for momenta."""
    m_x, angle, u_x, v_x = pucks.mass_moving, pucks.angle_known_deg, pucks.speed_before, pucks.speed_known
    angle_text = f"{n(angle, 2)}°"
    return (
        Mistake("X's momentum after not resolved", pucks.p_before - pucks.p_known,
                f"You took all of X's momentum after as along the line. Only its "
                f"component counts: {n(m_x, 2)} × {n(v_x, 2)} cos {angle_text}."),
        Mistake("sine instead of cosine", pucks.p_before - pucks.p_known * math.sin(math.radians(angle)),
                f"The component along the line is p cos θ, not p sin θ, with θ = "
                f"{angle_text} measured from the line."),
        Mistake("masses left out", u_x - v_x * math.cos(math.radians(angle)),
                "You conserved velocities, not momenta. Multiply each speed by its "
                "puck's mass first.", see="conservation"),
    )


def _pucks_across_mistakes(pucks: GlancingCollision) -> tuple[Mistake, ...]:
    """Example 4's wrong components of Y's momentum across the line (b): cosine for sine, X's momentum
    after not resolved, X's velocity for its momentum."""
    angle, v_x = pucks.angle_known_deg, pucks.speed_known
    x_along, _ = pucks.known_vector
    angle_text = f"{n(angle, 2)}°"
    return (
        Mistake("cosine instead of sine", x_along,
                f"That is X's component along the line. Across it is p sin θ, with θ = "
                f"{angle_text} measured from the line."),
        Mistake("X's momentum after not resolved", pucks.p_known,
                f"That is all of X's momentum after. Only its component across the line, "
                f"p sin {angle_text}, must be cancelled by Y's."),
        Mistake("masses left out", v_x * math.sin(math.radians(angle)),
                "That is a component of X's velocity. Multiply by X's mass to get "
                "momentum."),
    )


def _pucks_on_an_air_table_scheme(pucks: GlancingCollision) -> tuple[Mark, ...]:
    """Example 4's mark scheme: each component conserved (a, b), Y's speed and angle (c, d), and the
    kinetic energy before and after (e)."""
    m_x, m_y, angle = pucks.mass_moving, pucks.mass_struck, pucks.angle_known_deg
    u_x, v_x = pucks.speed_before, pucks.speed_known
    y = pucks.missing
    x_along, x_across = pucks.known_vector
    ke_x, ke_y = pucks.kinetic_energies_after
    angle_text = f"{n(angle, 2)}°"
    return (
        Mark(f"Along: {n(m_x, 2)} × {n(u_x, 2)} = {n(m_x, 2)} × {n(v_x, 2)} cos {angle_text} + "
             f"p<sub>along</sub>; across: 0 = {n(m_x, 2)} × {n(v_x, 2)} sin {angle_text} − "
             "p<sub>across</sub>", "C1", "ab"),
        Mark(f"{n(pucks.p_before, 2)} = {n(x_along, 2)} + p<sub>along</sub>, so p<sub>along</sub> = "
             f"{n(y.along, 2)} N s", "A1", "a"),
        Mark(f"p<sub>across</sub> = {n(x_across, 3)} N s, on the other side of the line from X", "A1", "b"),
        Mark(f"p<sub>Y</sub> = √({n(y.along, 2)}² + {n(y.across, 3)}²) = {n(y.magnitude, 3)} N s, so "
             f"v<sub>Y</sub> = {n(y.magnitude, 3)} / {n(m_y, 2)} = {n(pucks.speed_missing, 3)} "
             "m s<sup>−1</sup>", "B1", "c"),
        Mark(f"angle = tan<sup>−1</sup> ({n(y.across, 3)} / {n(y.along, 2)}) = {n(y.angle_deg, 3)}° to "
             "X's original direction", "B1", "d"),
        Mark(f"Kinetic energy before = ½ × {n(m_x, 2)} × {n(u_x, 2)}² = "
             f"{n(pucks.kinetic_energy_before, 2)} J", "C1", "e"),
        Mark(f"after = ½ × {n(m_x, 2)} × {n(v_x, 2)}² + ½ × {n(m_y, 2)} × {n(pucks.speed_missing, 4)}² "
             f"= {n(ke_x, 3)} + {n(ke_y, 3)} = {n(pucks.kinetic_energy_after, 2)} J: less than before, "
             "so it is inelastic", "A1", "e"),
    )


# ----------------------------------------------------------------------- Example 5

def sphere_in_oil() -> Question:
    """Worked examples > Example 5 (the physics issue's drag example): upthrust 0.0135 N,
    drag 0.104 N at terminal velocity, 8.68 m s^-2 just after release."""
    key = "example-5-try"
    sphere = scenarios.EXAMPLE_5
    mass, volume, oil = sphere["mass"], sphere["volume"], sphere["oil_density"]
    lift = upthrust(oil, volume)
    sphere_weight = weight(mass)
    drag = drag_at_terminal_velocity(sphere_weight, lift)
    first = acceleration(sphere_weight - lift, mass)
    m, g = sympy.symbols("mass gravity")
    sphere_density = mass / volume
    return Question(
        key=key,
        text=_text(key, "the upthrust, the drag at terminal velocity and the acceleration just after "
                        "release"),
        givens=(),  # the example's statement, just above on the page, gives the numbers
        parts=(
            # g = 10 gives 0.0138 N: 0.014 at 2 s.f., the key's own, and named at 3 s.f.
            Part("upthrust on the sphere", lift, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g_: upthrust(oil, volume, g=g_),
                 revisit="Upthrust = ρgV with the density of the oil (the fluid pushed aside), "
                         "not of the sphere.",
                 mistakes=(
                     Mistake("density of the sphere", upthrust(sphere_density, volume),
                             f"You used the sphere's density ({n(sphere_density, 2)} kg m⁻³): that "
                             "gives its weight. Upthrust = ρgV with the density of the oil "
                             "(forgetting upthrust, or putting the weight into it)."),
                     Mistake("g left out", oil * volume,
                             "That is the mass of oil pushed aside, in kg. The upthrust is its "
                             "weight: ρgV."),
                 ), see="skydiver"),
            Part("drag force at terminal velocity", drag, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g_: drag_at_terminal_velocity(weight(mass, g=g_),
                                                                   upthrust(oil, volume, g=g_)),
                 ecf=Ecf(m * g - a_, {"mass": mass, "gravity": G_EARTH}),
                 revisit="At terminal velocity the resultant force is zero: weight = drag + upthrust.",
                 mistakes=(
                     Mistake("upthrust left out", sphere_weight,
                             "That is the weight. In a liquid the upthrust acts too: at terminal "
                             "velocity weight = drag + upthrust, so drag = weight − upthrust."),
                     Mistake("upthrust added", sphere_weight + lift,
                             "The upthrust and the drag both act upwards: weight = drag + upthrust, "
                             "so subtract the upthrust."),
                 ), see="skydiver"),
            Part("acceleration of the sphere just after it is released", first, "m s^-2", "acceleration",
                 units=_M_S2, shown_sig_figs=3,
                 answer_for_g=lambda g_: acceleration(weight(mass, g=g_) - upthrust(oil, volume, g=g_), mass),
                 ecf=Ecf((m * g - a_) / m, {"mass": mass, "gravity": G_EARTH}),
                 revisit="Just after release the speed is zero, so there is no drag: a = (W − U) / m.",
                 mistakes=(
                     Mistake("upthrust left out", G_EARTH,
                             "That is g, the acceleration with no upthrust (as in air). In oil the "
                             "upthrust acts from the start: a = (W − U) / m."),
                     Mistake("drag as at terminal velocity", 0.0,
                             "That is the acceleration at terminal velocity. Just after release the "
                             "speed is zero, so there is no drag yet."),
                     Mistake("divided by the weight", (sphere_weight - lift) / sphere_weight,
                             f"You divided by the weight. Newton's second law divides by the mass, "
                             f"{n(mass, 2)} kg.", see="weight"),
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"Upthrust = ρgV = {n(oil, 2)} × {n(G_EARTH, 3)} × {n(volume, 2)}", "C1", "a"),
            Mark(f"= {n(lift, 3)} N", "A1", "a"),
            Mark(f"drag = weight − upthrust = {n(mass, 2)} × {n(G_EARTH, 3)} − {n(lift, 4)} = "
                 f"{n(sphere_weight, 4)} − {n(lift, 4)}", "C1", "b"),
            Mark(f"= {n(drag, 3)} N", "A1", "b"),
            Mark(f"a = (W − U) / m = ({n(sphere_weight, 4)} − {n(lift, 4)}) / {n(mass, 2)}", "C1", "c"),
            Mark(f"= {n(first, 3)} m s<sup>−2</sup>, downwards", "A1", "c"),
        ),
    )


TEMPLATES = checked_givens(
    Template("example-1-try", "newton", ("numeric",), "Example 1: try it first", car_and_trailer,
             try_first=True),
    Template("example-2-try", "force-momentum", ("numeric",), "Example 2: try it first", ball_off_a_wall,
             try_first=True),
    Template("example-3-try", "momentum-line", ("numeric",), "Example 3: try it first", two_trolleys,
             try_first=True),
    Template("example-4-try", "two-d", ("numeric",), "Example 4: try it first", pucks_on_an_air_table,
             try_first=True),
    Template("example-5-try", "drag", ("numeric",), "Example 5: try it first", sphere_in_oil,
             try_first=True),
)
