# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Conservation of momentum in a line: collisions, sticking together, explosions and recoil."""

from __future__ import annotations

import math

import sympy

from ..models import (
    MomentumHistory,
    average_force,
    change_in_momentum,
    explosion_from_rest,
    kinetic_energy,
    momentum,
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
    Graph,
    GraphPart,
    Mark,
    Mistake,
    Part,
    Question,
    Reading,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from . import diagrams
from ._common import M_S, N_S, PER_S, enough_figures, one_of_each, reading, reading_rule, w
from .givens import checked_givens

a_answer, m1_symbol, u1_symbol, m2_symbol, speed2_symbol = sympy.symbols("a m1 u1 m2 speed2")


def rifle_recoil(rifle: float = 4.0, bullet: float = 0.010, bullet_speed: float = 400.0) -> Question:
    """Notes, Quick check 2: rifle 4.0 kg, bullet 0.010 kg at 400 m s^-1 -> recoil 1.0 m s^-1 backwards."""
    v = explosion_from_rest(bullet, rifle, bullet_speed)  # signed: the bullet's way is positive
    bullet_momentum = momentum(bullet, bullet_speed)
    r, b, s = n(rifle, 2), n(bullet, 2), n(bullet_speed, 3)
    return Question(
        key="quick-check-2",
        diagram=diagrams.line(((f"{r} kg", 0.0), (f"{b} kg", 0.0)), ((f"{r} kg", None), (f"{b} kg", bullet_speed)),
                              names=("rifle", "bullet"), speed_figures=3),
        text=(f"A {r} kg rifle, initially at rest, fires a {b} kg bullet at {s} {PER_S}. "
              "Calculate the recoil speed of the rifle."),
        givens=(Given("rifle mass", rifle, "kg", 2), Given("bullet mass", bullet, "kg", 2),
                Given("bullet speed", bullet_speed, "m s^-1", 3)),
        parts=(
            Part("recoil speed of the rifle", abs(v), "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 sign_means="it moves backwards, opposite to the bullet",
                 revisit="The total momentum is zero before firing, so it is zero after: "
                         "0 = m₁v₁ + m₂v₂.",
                 mistakes=(
                     Mistake("mass ratio upside down", rifle * bullet_speed / bullet,
                             "The masses are the wrong way up. The rifle's momentum equals the "
                             f"bullet's: {r} v = {b} × {s}, so v = {b} × {s} / {r}.", see="momentum"),
                     Mistake("bullet's momentum given as speed", bullet_momentum,
                             f"{b} × {s} = {w(bullet_momentum)} is the bullet's momentum (in N s). Divide "
                             "it by the rifle's mass to get the rifle's speed.", see="momentum"),
                     Mistake("mass in grams", bullet * 1000 * bullet_speed / rifle,
                             f"You used the bullet's mass in g. Convert to kg: {b} kg.", kind="slip"),
                     Mistake("kinetic energy conserved", bullet_speed * math.sqrt(bullet / rifle),
                             "You set the kinetic energies equal. In an explosion kinetic energy "
                             "increases (from the chemical energy of the charge); only momentum is "
                             "conserved.", see="kinetic-energy"),
                 ), see="conservation"),
        ),
        mark_scheme=(
            Mark(f"Total momentum is zero before, so 0 = {b} × {s} + {r}v", "C1"),
            Mark(f"v = {n(v, 2)} {PER_S}: the recoil speed is {n(abs(v), 2)} {PER_S}, backwards", "A1"),
        ),
    )


def _stick_wording(ahead: bool, first: tuple[str, float], second: tuple[str, float], second_name: str,
                   wrong_sign: float) -> tuple[str, Mistake, str, str]:
    """How practice-trolleys-stick words the second trolley: head-on, or ahead the same way."""
    (first, u1), (second, speed2) = first, second
    if ahead:
        meeting = (f"catches up with a {second} kg trolley moving ahead of it in the same direction at "
                   f"{n(speed2, 2)} {PER_S}")
        sign_mistake = Mistake("second trolley's momentum taken as negative", wrong_sign,
                               f"The {second_name} moves the same way as the first, so its momentum is "
                               f"positive: {first} × {n(u1, 2)} + {second} × {n(speed2, 2)}.", see="momentum")
        wrong_carried = f"Your velocity after is wrong: the {second_name}'s momentum is positive."
    else:
        meeting = f"collides head-on with a {second} kg trolley moving towards it at {n(speed2, 2)} {PER_S}"
        sign_mistake = Mistake("momentum added as scalars", wrong_sign,
                               f"The {second_name} moves the other way, so its momentum is negative: "
                               f"{first} × {n(u1, 2)} + {second} × (−{n(speed2, 2)}).", see="momentum")
        wrong_carried = f"Your velocity after is wrong: the {second_name}'s momentum is negative."
    ignored_why = "It is moving, the same way." if ahead else "It is moving, the other way."
    return meeting, sign_mistake, wrong_carried, ignored_why


def trolleys_stick(m1: float = 2.0, u1: float = 3.0, m2: float = 1.0, speed2: float = 1.5,
                   same_way: float = 0) -> Question:
    """Stick together, with signs; then the kinetic energy transferred. same_way: 0, head-on (the
    second trolley moves towards the first); 1, the first catches the second, which moves ahead
    of it the same way (9702/23/M/J/25 Q4(b)). Equal masses are named first and second
    (9702/12/M/J/14 Q7's two 5000 kg carriages)."""
    ahead = bool(int(same_way))
    u2 = speed2 if ahead else -speed2  # positive: the first trolley's direction
    if ahead and u1 <= speed2:
        raise ValueError(f"u1 must exceed speed2={speed2!r} m s^-1, or the first trolley never catches the "
                         f"second (got u1={u1!r})")
    if not ahead and m1 * u1 <= m2 * speed2:
        raise ValueError(f"speed2 must leave the pair moving on in the {n(m1, 2)} kg trolley's direction "
                         f"(m1 u1 > m2 speed2; got m1={m1!r}, u1={u1!r}, m2={m2!r}, speed2={speed2!r})")
    v = stick_together(m1, u1, m2, u2)
    before = total_kinetic_energy((m1, m2), (u1, u2))
    after = kinetic_energy(m1 + m2, v)
    lost = before - after
    wrong_sign = stick_together(m1, u1, m2, -u2)
    first, second, total = n(m1, 2), n(m2, 2), w(m1 + m2)
    # equal masses cannot name a trolley by its mass
    first_name, second_name = ((f"{first} kg trolley", f"{second} kg trolley") if m1 != m2
                               else ("first trolley", "second trolley"))
    # the common velocity with the figures the kinetic energy after needs
    (v_carried,) = enough_figures((v,), lambda v1: kinetic_energy(m1 + m2, v1), w(after))
    positive = f"the direction the {first_name} moves at first"
    ke_before = m1_symbol * u1_symbol**2 / 2 + m2_symbol * speed2_symbol**2 / 2
    meeting, sign_mistake, wrong_carried, ignored_why = _stick_wording(
        ahead, (first, u1), (second, speed2), second_name, wrong_sign)
    return Question(
        key="practice-trolleys-stick",
        diagram=diagrams.line(((f"{first} kg", u1), (f"{second} kg", u2)), (("", None),), names=("", "")),
        text=(f"A {first} kg trolley moving at {n(u1, 2)} {PER_S} {meeting}. They stick together.\n\n"
              f"(a) Taking the direction of the {first_name} as positive, calculate their velocity "
              "after the collision.\n\n"
              "(b) Calculate the kinetic energy transferred to other forms."),
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2),
                Given("speed 2", speed2, "m s^-1", 2)),
        parts=(
            Part("velocity after the collision", v, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=positive,
                 revisit="Momentum before = momentum after, with a minus sign for the trolley "
                         "moving the other way: m₁u₁ + m₂u₂ = (m₁ + m₂)v.",
                 mistakes=one_of_each(v, (
                     sign_mistake,
                     # wrong physics: keeps no mark (9702/22/M/J/20, annotations: "XP ... No credit is
                     # given for substitution, or subsequent arithmetic, in a physically incorrect equation")
                     Mistake("one body's mass used for both", (momentum(m1, u1) + momentum(m2, u2)) / m1,
                             f"You divided by the {first_name}'s mass only. They move off together: "
                             "divide the total momentum by the total mass, m₁ + m₂."),
                     Mistake("second trolley ignored", momentum(m1, u1) / (m1 + m2),
                             f"You left out the {second_name}'s momentum. {ignored_why}", see="momentum"),
                 ), signed=True), see="conservation"),
            Part("kinetic energy transferred to other forms", lost, "J", "energy", shown_sig_figs=3,
                 working=(Step("common velocity", v, "m s^-1", 2),),
                 answer_from=lambda common: before - kinetic_energy(m1 + m2, common),
                 ecf=Ecf(ke_before - (m1_symbol + m2_symbol) * a_answer**2 / 2,
                         {"m1": m1, "u1": u1, "m2": m2, "speed2": speed2}),
                 revisit="Work out the total kinetic energy before and after separately; the "
                         "difference is the energy transferred.",
                 mistakes=one_of_each(lost, (
                     Mistake("kinetic energy conserved", 0.0,
                             "Kinetic energy is conserved only in an elastic collision. Trolleys "
                             "that stick together always lose some."),
                     Mistake("kinetic energy after only", after,
                             "That is the kinetic energy after. Subtract it from the kinetic energy "
                             "before."),
                     Mistake("wrong velocity carried on", before - kinetic_energy(m1 + m2, wrong_sign),
                             wrong_carried, see="momentum"),
                 )), see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"{first} × {n(u1, 2)} + {second} × ({n(u2, 2)}) = {total}v", "C1", "a"),
            Mark(f"v = {n(v, 2)} {PER_S} in the {first_name}'s direction", "A1", "a"),
            Mark(f"E<sub>k</sub> before = ½ × {first} × {n(u1, 2)}<sup>2</sup> + ½ × {second} × "
                 f"{n(speed2, 2)}<sup>2</sup> = {w(before)} J; after = ½ × {total} × {v_carried}<sup>2</sup> "
                 f"= {w(after)} J", "C1", "b"),
            Mark(f"Transferred = {w(before)} − {w(after)} = {n(lost, 3)} J", "A1", "b"),
        ),
    )


b_answer, mass_b_symbol = sympy.symbols("b mass_b")


def trolley_collision_momentum_time(before: float = 1.2, after: float = 0.4, mass_b: float = 0.50,
                                    hits: float = 1.0, contact: float = 0.3) -> Question:
    """A momentum-time graph of trolley A hitting trolley B at rest: the momentum A loses, B
    gains (notes: conservation of momentum; a momentum-time graph)."""
    history = MomentumHistory((0.0, hits, hits + contact, 3.0), (before, before, after, after))
    # A's mass is not given: its momenta are m1 u1 and m1 v1, so take m1 = 1 kg with u1, v1
    # numerically equal to them; conservation gives B's velocity, and B gains what A loses.
    speed_b = velocity_after_collision(1.0, before, mass_b, 0.0, after)
    gained = momentum(mass_b, speed_b)
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  time_division=0.1, value_division=0.05, time_max=3.0, value_max=1.5)
    mb = n(mass_b, 2)
    return Question(
        key="graph-trolley-collision",
        text=(f"Trolley A runs along a straight, level track and hits trolley B, of mass {mb} kg, which "
              "is at rest. The graph shows the momentum of trolley A. No external force acts along the "
              f"track. {reading_rule(0.025, 'N s')}"),
        givens=(Given("mass of B", mass_b, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("momentum of A before the collision", before, "N s", "momentum", units=N_S,
                      tolerance=0.025,
                      revisit="Read the flat part of the line before the collision."),
            GraphPart("momentum of A after the collision", after, "N s", "momentum", units=N_S,
                      tolerance=0.025,
                      revisit="Read the flat part of the line after the collision."),
            Part("speed of B after the collision", speed_b, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 ecf=Ecf((a_answer - b_answer) / mass_b_symbol, {"mass_b": mass_b}),
                 readings=(Reading("momentum of A before", before, graph.value_division / 2),
                           Reading("momentum of A after", after, graph.value_division / 2)),
                 answer_from_readings=lambda p0, p1: velocity_after_collision(1.0, p0, mass_b, 0.0, p1),
                 revisit="Momentum is conserved: the momentum A loses, B gains. Then v = p / m.",
                 mistakes=(
                     Mistake("gave B the momentum A has after", velocity_from_momentum(after, mass_b),
                             "You gave B the momentum A has afterwards. B gains the momentum A loses: "
                             "before − after.", see="momentum"),
                     Mistake("assumed A stops", velocity_from_momentum(before, mass_b),
                             "You gave B all of A's momentum, as if A stopped. The graph shows A still "
                             "moving: B gains only what A loses.", see="momentum"),
                 ), see="conservation"),
        ),
        mark_scheme=(
            Mark(f"{reading(before, 0.025)} N s", "B1", "a"),
            Mark(f"{reading(after, 0.025)} N s", "B1", "b"),
            Mark(f"momentum B gains = momentum A loses = {reading(before, 0.025)} − {reading(after, 0.025)} "
                 f"= {w(gained)} N s",
                 "C1", "c"),
            Mark(f"v = {w(gained)} / {mb} = {n(speed_b, 2)} {PER_S}", "A1", "c"),
        ),
    )



def stick_choice(m1: float = 3.0, u1: float = 4.0, m2: float = 2.0, speed2: float = 1.0) -> Question:
    """Paper 1 style: head-on, stick together. Wrong options are the notes' mistakes: the sign of
    the oncoming body left out, only the first body's mass divided by, the second body ignored."""
    if m1 * u1 <= m2 * speed2:
        raise ValueError(f"speed2 must leave the pair moving on in the first body's direction "
                         f"(m1 u1 > m2 speed2; got m1={m1!r}, u1={u1!r}, m2={m2!r}, speed2={speed2!r})")
    key = stick_together(m1, u1, m2, -speed2)
    options, answer = choices_in_order(key, {
        "momentum added as scalars": (
            stick_together(m1, u1, m2, speed2),
            ("The second body moves the other way, so its momentum is negative. Momentum is a vector: "
             "give each velocity a sign."), "momentum"),
        "one body's mass used for both": (
            (momentum(m1, u1) - momentum(m2, speed2)) / m1,
            ("The bodies move off together, so divide the total momentum by the total mass, "
             "m₁ + m₂."), "conservation"),
        "second body ignored": (
            stick_together(m1, u1, m2, 0.0),
            "You left out the second body's momentum. It is moving, the other way.", "momentum"),
        **({"masses paired with the wrong speeds": (
            stick_together(m2, u1, m1, -speed2),
            (f"You multiplied each speed by the other trolley's mass. The {n(m1, 2)} kg trolley moves at "
             f"{n(u1, 2)} m s⁻¹: p = m₁u₁ − m₂u₂."), "momentum")}
           if stick_together(m2, u1, m1, -speed2) > 0 else {}),
        "velocities averaged": (
            (u1 - speed2) / 2,
            ("You averaged the two velocities. The trolleys have different masses: share the total "
             "momentum over the total mass, v = (m₁u₁ − m₂u₂) / (m₁ + m₂)."), "conservation"),
        "the first trolley's change in velocity given": (
            u1 - key,
            (f"That is how much the first trolley slows down, {n(u1, 2)} − v. The question asks for "
             "the common velocity v itself."), "conservation"),
    }, sig_figs=2, unit=PER_S, seed=1)
    return Question(
        key="stick-choice",
        diagram=diagrams.line(((f"{n(m1, 2)} kg", u1), (f"{n(m2, 2)} kg", -speed2)), (("", None),), names=("", "")),
        text=(f"A trolley of mass {n(m1, 2)} kg moving at {n(u1, 2)} {PER_S} collides head-on with a "
              f"trolley of mass {n(m2, 2)} kg moving towards it at {n(speed2, 2)} {PER_S}. "
              "The trolleys stick together."),
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2),
                Given("speed 2", speed2, "m s^-1", 2)),
        parts=(ChoicePart("What is their speed just after the collision?", options, answer,
                          revisit="m₁u₁ + m₂u₂ = (m₁ + m₂)v, with a minus sign for the trolley moving "
                                  "the other way."),),
        mark_scheme=(Mark(f"{answer}: v = ({n(m1, 2)} × {n(u1, 2)} − {n(m2, 2)} × {n(speed2, 2)}) / "
                          f"({n(m1, 2)} + {n(m2, 2)}) = {n(key, 2)} {PER_S}", "B1"),),
    )

mass_a_symbol, mass_b_symbol_spring, speed_b_symbol = sympy.symbols("mass_a mass_b speed_b")


def trolleys_spring_apart(mass_a: float = 1.5, mass_b: float = 0.50, speed_b: float = 1.2) -> Question:
    """An explosion from rest: a compressed spring pushes two trolleys apart. The momenta are
    equal and opposite (total zero); the kinetic energy comes from the spring (notes:
    explosions, and kinetic energy is not conserved)."""
    v_a = explosion_from_rest(mass_b, mass_a, speed_b)  # signed: B's way is positive, so A's is negative
    energy = total_kinetic_energy((mass_a, mass_b), (v_a, speed_b))
    a_, b_, u = n(mass_a, 2), n(mass_b, 2), n(speed_b, 2)
    # A's speed with the figures the energy needs
    (speed_a,) = enough_figures((abs(v_a),), lambda v1: total_kinetic_energy((mass_a, mass_b), (v1, speed_b)),
                                n(energy, 2))
    directions = ("the same way as B", "the opposite way to B")
    return Question(
        key="practice-spring-apart",
        diagram=diagrams.line(((f"{a_} kg", 0.0), (f"{b_} kg", 0.0)), (("", None), ("", speed_b))),
        text=(f"Trolley A, of mass {a_} kg, and trolley B, of mass {b_} kg, are at rest on a level track "
              "with a compressed spring between them. The spring is released and the trolleys fly apart; "
              f"B moves off at {u} {PER_S}.\n\n"
              "(a) Calculate the velocity of A and give its direction.\n\n"
              "(b) Calculate the energy the spring gave the trolleys as kinetic energy."),
        givens=(Given("mass of A", mass_a, "kg", 2), Given("mass of B", mass_b, "kg", 2),
                Given("speed of B", speed_b, "m s^-1", 2)),
        parts=(
            Part("velocity of A", abs(v_a), "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="choice", choices=directions, answer_direction="the opposite way to B",
                 direction_hint="The total momentum stays zero: A's momentum must cancel B's, so A moves "
                                "the opposite way.",
                 revisit="The total momentum is zero before, so it is zero after: A's momentum + B's "
                         "momentum = 0.",
                 mistakes=(
                     Mistake("same speed as B", speed_b,
                             "Equal momenta, not equal speeds: the heavier trolley moves off more slowly."),
                     Mistake("masses the wrong way up", speed_b * mass_a / mass_b,
                             f"The masses are the wrong way up: {a_} v = {b_} × {u}, so v = {b_} × {u} / {a_}."),
                     Mistake("B's momentum given as a speed", momentum(mass_b, speed_b),
                             f"{b_} × {u} is B's momentum in N s. Divide it by A's mass for A's speed.", see="momentum"),
                 ), see="conservation"),
            Part("kinetic energy the spring gave", energy, "J", "energy", shown_sig_figs=2,
                 ecf=Ecf(mass_a_symbol * a_answer**2 / 2 + mass_b_symbol_spring * speed_b_symbol**2 / 2,
                         {"mass_a": mass_a, "mass_b": mass_b, "speed_b": speed_b}),
                 revisit="Both trolleys start at rest: the spring's energy is the kinetic energy of both, "
                         "½mv² for A plus ½mv² for B.",
                 mistakes=(
                     Mistake("only B's kinetic energy", kinetic_energy(mass_b, speed_b),
                             "That is B's kinetic energy only. A moves too: add ½mv² for each trolley."),
                     Mistake("only A's kinetic energy", kinetic_energy(mass_a, v_a),
                             "That is A's kinetic energy only. B moves too: add ½mv² for each trolley."),
                     Mistake("kinetic energy from the total momentum", 0.0,
                             "The total momentum is zero, but kinetic energy is never negative: each "
                             "trolley has ½mv², and the energies add."),
                 ), see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"Total momentum zero: {a_} v<sub>A</sub> + {b_} × {u} = 0", "C1", "a"),
            Mark(f"v<sub>A</sub> = {n(v_a, 2)} {PER_S}: {n(abs(v_a), 2)} {PER_S}", "A1", "a"),
            Mark("the opposite way to B", "B1", "a", earns="direction"),
            Mark(f"E<sub>k</sub> = ½ × {a_} × {speed_a}<sup>2</sup> + ½ × {b_} × {u}<sup>2</sup>", "C1", "b"),
            Mark(f"= {n(energy, 2)} J", "A1", "b"),
        ),
    )


mass_b_third, speed_b_third, contact_third = sympy.symbols("mass_b_third speed_b_third contact_third")


def _rounding_slack(mass_a: float, after_a: float, v_b: float) -> float:
    """How much kinetic energy (J) a rebound speed printed to 2 s.f. can hide. A paper prints a
    worked speed rounded (an elastic collision's 0.4615 m s⁻¹ as 0.46), so the total after can seem
    to exceed the total before. With B's speed following from momentum, moving A's speed after by δv
    moves the total by m_A (v_B - v_A) δv; δv is half a unit of its 2nd significant figure."""
    if not after_a:
        return 0.0
    half_unit = 0.5 * 10.0 ** (math.floor(math.log10(abs(after_a))) - 1)
    return mass_a * abs(v_b - after_a) * half_unit


def collision_third_law(mass_a: float = 0.60, speed_a: float = 2.5, mass_b: float = 0.40, speed_b: float = 0.0,
                        after_a: float = 0.50, contact: float = 0.050, force_on: float = 0) -> Question:
    """Newton's third law inside a collision: the forces on A and B are equal and opposite and act
    for the same time, so B gains the momentum A loses (notes, "Why it works": Δp_A = -Δp_B; How to
    do it 5., "Contact force during the collision"). Printed: the notes' Example 3 (0.60 kg at
    2.5 m s⁻¹ hits 0.40 kg at rest, A moves on at 0.50 m s⁻¹, 0.050 s: B 3.0 m s⁻¹, 24 N).
    The scheme's lines follow 9702/21/M/J/15 Q3(c) ("force on X is equal and opposite to force on
    same") and 9702/21/M/J/16 Q3(b)(ii) (Δp C1, then F = Δp / Δt A1).

    force_on: 0 asks (c) the force on B (the variants); 1 the force on A, as 9702/23/O/N/24 Q2(c)(i)
    asks the force on the ball that stops. Kinetic energy may seem to grow by what the rounding of
    A's printed speed after hides (_rounding_slack), as a paper's rounded data can."""
    on_a = int(force_on) == 1
    u_b = -speed_b  # right is positive: B is at rest or moves left, towards A
    dp_a = change_in_momentum(mass_a, speed_a, after_a)
    dp_b = -dp_a  # third law: equal and opposite forces for the same time
    v_b = velocity_after_collision(mass_a, speed_a, mass_b, u_b, after_a)
    if v_b < after_a:
        raise ValueError(f"after_a={after_a!r} m s^-1 leaves B ({n(v_b, 2)} m s^-1) behind A, which cannot "
                         "pass through it")
    before = total_kinetic_energy((mass_a, mass_b), (speed_a, u_b))
    after = total_kinetic_energy((mass_a, mass_b), (after_a, v_b))
    slack = _rounding_slack(mass_a, after_a, v_b)
    if after > before + slack:
        raise ValueError(f"after_a={after_a!r} m s^-1 would create kinetic energy ({n(before, 3)} J before, "
                         f"{n(after, 3)} J after, more than the {n(slack, 2)} J its rounding allows)")
    force_b = average_force(dp_b, contact)
    ma, ua, mb, ub, va, t = n(mass_a, 2), n(speed_a, 2), n(mass_b, 2), n(speed_b, 2), n(after_a, 2), n(contact, 2)
    ways = ("to the right", "to the left")
    b_before = "at rest" if speed_b == 0 else f"moving at {ub} {PER_S} to the left, towards A"
    a_after = "stops" if after_a == 0 else f"moves on to the right at {va} {PER_S}"
    givens = [Given("mass of A", mass_a, "kg", 2), Given("speed of A", speed_a, "m s^-1", 2),
              Given("mass of B", mass_b, "kg", 2), Given("contact time", contact, "s", 2)]
    if speed_b:
        givens.append(Given("speed of B", speed_b, "m s^-1", 2))
    if after_a:
        givens.append(Given("speed of A after", after_a, "m s^-1", 2))
    third_law = ("By Newton's third law B pushes A and A pushes B with equal and opposite forces, for the same "
                 "time, so their changes in momentum are equal and opposite: Δp of B = −Δp of A.")
    # (c) asks the force on B, or on A (force_on=1): the same size, opposite ways (third law)
    body, _, way, _ = _force_bodies(on_a)
    return Question(
        key="collision-third-law",
        diagram=diagrams.line(((f"{ma} kg", speed_a), (f"{mb} kg", u_b)), (("", after_a), ("", None))),
        text=(f"Trolley A, of mass {ma} kg, moves at {ua} {PER_S} to the right along a straight, level track "
              f"towards trolley B, of mass {mb} kg, which is {b_before}. The trolleys collide and are in contact "
              f"for {t} s. After the collision A {a_after}.\n\n"
              "(a) Calculate the change in momentum of B and give its direction.\n\n"
              "(b) Calculate the speed of B just after the collision.\n\n"
              f"(c) Calculate the average force on {body} during the collision and give its direction."),
        givens=tuple(givens),
        parts=(
            Part("change in momentum of B", dp_b, "N s", "change in momentum", units=N_S, shown_sig_figs=2,
                 direction="choice", choices=ways, answer_direction="to the right",
                 direction_hint="A loses momentum to the right; B gains what A loses (Newton's third law).",
                 revisit=third_law, mistakes=_momentum_change_mistakes(mass_a, speed_a, mass_b, after_a),
                 see="third-law"),
            Part("speed of B just after the collision", v_b, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 ecf=Ecf(a_answer / mass_b_third - speed_b_third,
                         {"mass_b_third": mass_b, "speed_b_third": speed_b}),
                 revisit="B's change in momentum is m(v − u), with B's velocity before negative if it moved "
                         "to the left: v = u + Δp / m.",
                 mistakes=_speed_of_b_mistakes(mass_a, speed_a, mass_b, speed_b, after_a), see="conservation"),
            Part(f"average force on {body}", force_b, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=ways, answer_direction=way,
                 ecf=Ecf(a_answer / contact_third, {"contact_third": contact}),
                 direction_hint=f"The force on {body} is in the direction of {body}'s change in momentum.",
                 revisit="The force on one body is its own change in momentum ÷ the contact time.",
                 mistakes=_third_law_force_mistakes(mass_a, speed_a, mass_b, speed_b, after_a, contact, on_a),
                 see="second-law"),
        ),
        mark_scheme=_collision_third_law_scheme(mass_a, speed_a, mass_b, speed_b, after_a, contact, on_a),
    )


def _force_bodies(on_a: bool) -> tuple[str, str, str, str]:
    """The body whose force (c) asks, the other body, and the ways of the force on each (right is
    positive; A's change in momentum is to the left, B's to the right)."""
    ways = ("to the right", "to the left")
    body, other = ("A", "B") if on_a else ("B", "A")
    way, other_way = (ways[1], ways[0]) if on_a else ways
    return body, other, way, other_way


def _momentum_change_mistakes(mass_a: float, speed_a: float, mass_b: float, after_a: float) -> tuple[Mistake, ...]:
    """collision_third_law's wrong changes in B's momentum (a): B's mass with A's change in velocity,
    the direction of A's change, and all of A's momentum when A moves on."""
    dp_b = -change_in_momentum(mass_a, speed_a, after_a)
    ma, ua, va = n(mass_a, 2), n(speed_a, 2), n(after_a, 2)
    a_mistakes = [
        Mistake("one body's mass used for both", momentum(mass_b, speed_a - after_a),
                f"You multiplied B's mass by A's change in velocity. The changes in momentum are equal and "
                f"opposite, so work out A's with A's mass: {ma} × ({va} − {ua})."),
        Mistake("the same direction as A's change", dp_b,
                "The size is right, but B's change in momentum is opposite to A's (Newton's third law): A "
                "loses momentum to the right, so B gains momentum to the right.", direction="to the left",
                see="third-law"),
    ]
    if after_a:
        a_mistakes.append(
            Mistake("as if A stopped", momentum(mass_a, speed_a),
                    f"That is all of A's momentum, as if A stopped. A moves on at {va} m s⁻¹: B gains only "
                    "what A loses.", see="conservation"))
    return tuple(a_mistakes)


def _speed_of_b_mistakes(mass_a: float, speed_a: float, mass_b: float, speed_b: float,
                         after_a: float) -> tuple[Mistake, ...]:
    """collision_third_law's wrong speeds of B after (b): A's change in velocity given to B, and when B
    moved towards A, its speed added as a scalar or left out."""
    u_b = -speed_b  # right is positive: B moves left, towards A
    dp_b = -change_in_momentum(mass_a, speed_a, after_a)
    ub, mb = n(speed_b, 2), n(mass_b, 2)
    # B's velocity change with "one body's mass used for both": A's change in velocity given to B
    same_velocity_change = u_b + (speed_a - after_a)
    b_mistakes = [
        Mistake("changes in velocity taken as equal", same_velocity_change,
                f"You gave B the same change in velocity as A. The changes in momentum are equal and opposite, "
                f"not the changes in velocity: B's is {w(dp_b)} N s, so its velocity changes by {w(dp_b)} / {mb}."),
    ]
    if speed_b:
        b_mistakes += [
            Mistake("momentum added as scalars", speed_b + velocity_from_momentum(dp_b, mass_b),
                    f"You added B's speed before as if it moved to the right. B moved to the left: its velocity "
                    f"before is −{ub} m s⁻¹, so v = −{ub} + Δp / m.", see="momentum"),
            Mistake("B's velocity before left out", velocity_from_momentum(dp_b, mass_b),
                    f"Δp / m = {w(velocity_from_momentum(dp_b, mass_b))} m s⁻¹ is B's change in velocity. Add it "
                    f"to B's velocity before, −{ub} m s⁻¹."),
        ]
    return tuple(b_mistakes)


def _third_law_force_mistakes(mass_a: float, speed_a: float, mass_b: float, speed_b: float, after_a: float,
                              contact: float, on_a: bool) -> tuple[Mistake, ...]:
    """collision_third_law's wrong forces (c): the acceleration, Δp times t, the other body's direction, and
    when B moved before, B's final momentum ÷ time."""
    u_b = -speed_b
    dp_b = -change_in_momentum(mass_a, speed_a, after_a)
    v_b = velocity_after_collision(mass_a, speed_a, mass_b, u_b, after_a)
    force_b = average_force(dp_b, contact)
    body, other, way, other_way = _force_bodies(on_a)
    f_mistakes = [
        Mistake("mass left out", (speed_a - after_a if on_a else v_b - u_b) / contact,
                f"You divided {body}'s change in velocity by the time: that is its acceleration, in m s⁻². The "
                f"force is {body}'s change in momentum ÷ the time, F = mΔv / Δt.", see="second-law"),
        Mistake("multiplied by the time", dp_b * contact,
                "You multiplied by the contact time. Force is the rate of change of momentum: F = Δp / Δt.",
                see="second-law"),
        Mistake(f"the force on {other}", force_b,
                f"That is the direction of the force on {other}. The force on {body} is in the direction of "
                f"{body}'s change in momentum: {way}.", direction=other_way, see="third-law"),
    ]
    if speed_b and not on_a:
        f_mistakes.append(
            Mistake("B's final momentum ÷ time", average_force(momentum(mass_b, v_b), contact),
                    "You used B's momentum after the collision. The force comes from B's change in momentum: "
                    "it was moving before.", see="momentum"))
    return tuple(f_mistakes)


def _collision_third_law_scheme(mass_a: float, speed_a: float, mass_b: float, speed_b: float, after_a: float,
                                contact: float, on_a: bool) -> tuple[Mark, ...]:
    """collision_third_law's mark scheme: A's Δp and the third law (a), v = u + Δp / m (b), F = Δp / Δt
    and its direction (c)."""
    dp_a = change_in_momentum(mass_a, speed_a, after_a)
    dp_b = -dp_a
    v_b = velocity_after_collision(mass_a, speed_a, mass_b, -speed_b, after_a)
    force_b = average_force(dp_b, contact)
    ma, ua, mb, ub, va, t = n(mass_a, 2), n(speed_a, 2), n(mass_b, 2), n(speed_b, 2), n(after_a, 2), n(contact, 2)
    body, _, way, _ = _force_bodies(on_a)
    return (
        Mark(f"Δp of A = {ma} × ({va} − {ua}) = {w(dp_a)} N s", "C1", "a"),
        Mark(f"Equal and opposite forces for the same time (Newton's third law): Δp of B = {n(dp_b, 2)} N s",
             "A1", "a"),
        Mark("to the right (opposite to A's change)", "B1", "a", earns="direction"),
        Mark(f"v = u + Δp / m = {'0' if not speed_b else '−' + ub} + {w(dp_b)} / {mb}", "C1", "b"),
        Mark(f"= {n(v_b, 2)} {PER_S}", "A1", "b"),
        Mark(f"F = Δp / Δt = {w(dp_b)} / {t}", "C1", "c"),
        Mark(f"= {n(force_b, 2)} N", "A1", "c"),
        Mark(f"{way} (the direction of {body}'s change in momentum)", "B1", "c", earns="direction"),
    )



TEMPLATES = checked_givens(
    Template("quick-check-2", "momentum-line", ("numeric",), "Quick check 2", rifle_recoil,
             {"rifle": Draw(4.0, 3.0, 6.0, 0.5), "bullet": Draw(0.010, 0.008, 0.020, 0.001),
              "bullet_speed": Draw(400.0, 300.0, 900.0, 50.0)}),
    Template("practice-trolleys-stick", "momentum-line", ("numeric",), "Trolleys that stick together",
             trolleys_stick,
             {"m1": Draw(2.0, 1.0, 4.0, 0.5), "u1": Draw(3.0, 1.0, 5.0, 0.5),
              "m2": Draw(1.0, 0.5, 3.0, 0.5), "speed2": Draw(1.5, 0.5, 4.0, 0.5)}),
    Template("practice-spring-apart", "momentum-line", ("numeric",), "Trolleys pushed apart by a spring",
             trolleys_spring_apart,
             {"mass_a": Draw(1.5, 0.5, 3.0, 0.1), "mass_b": Draw(0.50, 0.20, 1.50, 0.10),
              "speed_b": Draw(1.2, 0.5, 3.0, 0.1)}),
    Template("graph-trolley-collision", "momentum-line", ("graph", "numeric"),
             "A collision: momentum–time graph", trolley_collision_momentum_time,
             {"before": Draw(1.2, 0.8, 1.4, 0.05), "after": Draw(0.4, 0.1, 0.6, 0.05),
              "mass_b": Draw(0.50, 0.20, 1.00, 0.05), "hits": Draw(1.0, 0.8, 1.5, 0.1),
              "contact": Draw(0.3, 0.1, 0.5, 0.1)}),
    Template("stick-choice", "momentum-line", ("mcq",), "Trolleys stick: which speed?", stick_choice,
             {"m1": Draw(3.0, 2.0, 5.0, 0.5), "u1": Draw(4.0, 3.0, 6.0, 0.5),
              "m2": Draw(2.0, 0.5, 2.0, 0.5), "speed2": Draw(1.0, 0.5, 2.0, 0.5)}),
    Template("collision-third-law", "momentum-line", ("numeric",), "Third law in a collision", collision_third_law,
             {"mass_a": Draw(0.60, 0.40, 1.00, 0.05), "speed_a": Draw(2.5, 1.5, 4.0, 0.5),
              "mass_b": Draw(0.40, 0.20, 1.00, 0.05), "speed_b": Draw(0.0, 0.0, 1.5, 0.5),
              "after_a": Draw(0.50, 0.0, 1.5, 0.1), "contact": Draw(0.050, 0.020, 0.080, 0.005)}),
)
