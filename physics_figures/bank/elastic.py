# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""Elastic and inelastic collisions: relative speeds, kinetic energy kept or lost."""

from __future__ import annotations

import math

import sympy

from .. import textformat
from ..models import (
    elastic_collision,
    kinetic_energy,
    momentum,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    total_kinetic_energy,
    total_momentum,
    velocity_after_collision,
    velocity_from_momentum,
)
from ..notation import format_number as n
from ..questions import (
    OPTION_LETTERS,
    ChoicePart,
    Ecf,
    ExplainPart,
    Given,
    Mark,
    Mistake,
    Option,
    Part,
    Question,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from . import diagrams
from ._common import M_S, PER_S, enough_figures, one_of_each, w
from .givens import checked_givens

#: A unit for feedback, which the page shows as plain text.
_PER_S_PLAIN = "m s⁻¹"


def _times(mass: float, symbol: str) -> str:
    """mass × symbol as an equation writes it: "v<sub>1</sub>" for 1.0 kg, "1.5v<sub>1</sub>" otherwise."""
    return symbol if mass == 1 else f"{n(mass, 2)}{symbol}"


def light_ball_hits_heavy_ball(m1: float = 1.0, u1: float = 6.0, m2: float = 2.0) -> Question:
    """Notes, Quick check 4: 1.0 kg at 6.0 m s^-1 hits 2.0 kg at rest, elastic -> -2.0 and 4.0 m s^-1."""
    if m2 <= m1:  # the light ball bounces back (the notes' variation); the text and feedback say so
        raise ValueError(f"m2 must be heavier than m1, so the first ball bounces back (got m1={m1!r}, m2={m2!r})")
    u2 = 0.0
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    p_before = momentum(m1, u1)
    approach = relative_speed(u1, u2)
    ke_before = kinetic_energy(m1, u1)
    stuck = stick_together(m1, u1, m2, u2)
    light, heavy, speed = n(m1, 2), n(m2, 2), n(u1, 2)
    forward = f"the direction the {light} kg ball moves at first"
    revisit = ("Use two equations: momentum (m₁u₁ + m₂u₂ = m₁v₁ + m₂v₂) and, because it is elastic, "
               "relative speed of approach = relative speed of separation.")
    v_1, v_2 = "v<sub>1</sub>", "v<sub>2</sub>"
    # Adding the momentum equation to m1 × (the relative-speed equation) leaves v2 alone.
    adding = "Adding" if m1 == 1 else f"Adding {light} × the second"
    # m1 + m2 is a whole number of kilograms in the notes' answer, written as they write it (3v₂)
    total = n(m1 + m2, decimals=0) if abs(m1 + m2 - round(m1 + m2)) < 1e-9 else w(m1 + m2)
    return Question(
        key="quick-check-4",
        text=(f"A {light} kg ball moving at {speed} {PER_S} has an elastic head-on collision with a "
              f"{heavy} kg ball at rest. Calculate the velocities of (a) the {light} kg ball and (b) the "
              f"{heavy} kg ball afterwards."),
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2)),
        diagram=diagrams.line(((f"{light} kg", u1), (f"{heavy} kg", 0.0)), (("", None), ("", None))),
        parts=(
            Part(f"velocity of the {light} kg ball", v1, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("assumed the first ball stops", 0.0,
                             f"The moving ball only stops when the masses are equal. Here the {heavy} kg "
                             f"ball is heavier, so the {light} kg ball bounces back."),
                     Mistake("bounces back at full speed", -u1,
                             f"It can't bounce back at its full speed: the {heavy} kg ball moves off, "
                             "taking momentum and kinetic energy. Solve the two equations together."),
                 ), see="kinetic-energy"),
            Part(f"velocity of the {heavy} kg ball", v2, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("treated as sticking together", stuck,
                             "That is the common velocity if they stuck together, an inelastic "
                             "collision. This one is elastic: use the relative speeds too."),
                     Mistake("assumed the first ball stops", velocity_from_momentum(p_before, m2),
                             f"You assumed the {light} kg ball stops. That happens only for equal masses; "
                             "use momentum and relative speeds together.", see="relative-speed"),
                     Mistake("swapped velocities", u1,
                             "Balls swap velocities only when their masses are equal. Here they "
                             "are not: solve momentum and relative speeds together.", see="relative-speed"),
                 ), see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"Momentum: {w(p_before)} = {_times(m1, v_1)} + {heavy}{v_2}", "C1", "ab"),
            Mark(f"Elastic, so relative speeds: {n(approach, 2)} = {v_2} − {v_1}", "C1", "ab"),
            Mark(f"{adding}: {w(p_before + approach * m1)} = {total}{v_2}, so {v_2} = {n(v2, 2)} {PER_S} "
                 "forwards", "A1", "b"),
            Mark(f"{v_1} = {n(v1, 2)} {PER_S}, i.e. {n(abs(v1), 2)} {PER_S} back the way it came", "A1", "a"),
            Mark(f"(Check: kinetic energy {n(ke_before, 2)} J before; "
                 f"{n(kinetic_energy(m1, v1), 2)} + {n(kinetic_energy(m2, v2), 2)} = "
                 f"{n(total_kinetic_energy((m1, m2), (v1, v2)), 2)} J after.)"),
        ),
    )




def _moving(velocity: float) -> str:
    """A signed velocity along the track as the text says it: "2.5 m s⁻¹ to the right", "at rest"."""
    if velocity == 0:
        return "at rest"
    return f"moving at {n(abs(velocity), 2)} {PER_S} to the {'right' if velocity > 0 else 'left'}"


#: Head-on collisions in which the bodies bounce apart: what collides, their masses (kg) and
#: velocities before (u) and the first body's velocity after (v1), signed, positive to the right.
#: The second body's velocity after comes from momentum; whether kinetic energy is kept comes
#: from the models (notes: "Elastic and inelastic collisions", "to decide elastic or inelastic").
_BOUNCES = (
    ("Two gliders on a level air track", "glider", 0.60, 2.5, 0.40, 0.0, 0.50),
    ("Two trolleys on a level runway", "trolley", 2.0, 3.0, 1.0, 0.0, 1.5),
    ("Two steel balls on a smooth groove", "ball", 0.20, 4.0, 0.20, -2.0, -2.0),
    ("Two pucks on smooth ice", "puck", 0.50, 4.0, 1.5, 0.0, -0.50),
    ("Two railway trucks on a level track", "truck", 3000.0, 2.0, 2000.0, -0.50, 0.40),
)


def elastic_or_not_choice(situation: float = 0) -> Question:
    """Paper 1 style: is this collision elastic? Decide from the total kinetic energy (or the
    relative speeds), not from momentum (always conserved) or from the bodies separating."""
    what, body, m1, u1, m2, u2, v1 = _BOUNCES[int(situation)]
    v2 = velocity_after_collision(m1, u1, m2, u2, v1)
    ke_before = total_kinetic_energy((m1, m2), (u1, u2))
    ke_after = total_kinetic_energy((m1, m2), (v1, v2))
    approach, separation = relative_speed(u1, u2), relative_speed(v1, v2)
    elastic = math.isclose(ke_before, ke_after, rel_tol=1e-9)
    ke_a_before, ke_a_after = kinetic_energy(m1, u1), kinetic_energy(m1, v1)
    if elastic and ke_a_after >= ke_a_before:
        raise ValueError(f"v1 must leave body A with less kinetic energy in an elastic situation, "
                         f"so the one-body option is a mistake (got v1={v1!r})")
    energy = f"{w(ke_before)} J before; {w(kinetic_energy(m1, v1))} + {w(kinetic_energy(m2, v2))} = " \
             f"{w(ke_after)} J after"
    speeds = f"approach {w(approach)} {PER_S}, separation {w(separation)} {PER_S}"
    plain_energy, plain_speeds = textformat.to_plain(energy), speeds.replace(PER_S, _PER_S_PLAIN)
    # two options give each verdict (issue 37: the key's verdict was the odd one out), so the verdict
    # alone never picks the key: the other option of the key's verdict gives a wrong reason for it
    momentum_kept = Option(f"It is elastic: the total momentum of the {body}s is the same before and after.",
                           "momentum conserved, so elastic",
                           ("It is elastic, but not for that reason. " if elastic else "")
                           + "Momentum is conserved in every collision, elastic or not, so it cannot decide. "
                           f"Compare the total kinetic energy: {plain_energy}.")
    always_lost = Option("It is inelastic: some kinetic energy is lost in every collision.",
                         "kinetic energy lost in every collision",
                         ("It is inelastic, but not for that reason. " if not elastic else "")
                         + "Not in every collision: in an elastic one the total kinetic energy is kept. Compare "
                         f"the totals, or the relative speeds ({plain_speeds}).")
    if elastic:
        key = Option(f"It is elastic: the relative speed of separation of the {body}s equals their relative "
                     "speed of approach.")
        wrong = (
            Option(f"It is inelastic: {body} A loses kinetic energy in the collision.",
                   "looked at one body's kinetic energy",
                   f"A does lose kinetic energy, but B gains exactly as much. Elastic means the "
                   f"total kinetic energy is kept: {plain_energy}."),
            always_lost,
            momentum_kept,
        )
    else:
        key = Option(f"It is inelastic: the total kinetic energy of the {body}s after the collision is less "
                     "than before.")
        wrong = (
            momentum_kept,
            Option(f"It is elastic: the {body}s bounce apart instead of sticking together.",
                   "the bodies separate, so elastic",
                   "Bodies that stick together always have an inelastic collision, but bouncing apart "
                   f"does not make one elastic. Compare the total kinetic energy: {plain_energy}."),
            always_lost,
        )
    turn = int(situation) % len(OPTION_LETTERS)  # the key is not always the same letter
    options = (*wrong[:turn], key, *wrong[turn:])
    mass_a, mass_b = n(m1, 2), n(m2, 2)
    return Question(
        key="elastic-or-not-choice",
        text=(f"{what} collide head-on. {body.capitalize()} A of mass {mass_a} kg is {_moving(u1)}, and "
              f"{body} B of mass {mass_b} kg is {_moving(u2)}. After the collision A is {_moving(v1)} "
              f"and B is {_moving(v2)}."),
        givens=(Given("mass of A", m1, "kg", 2), Given("mass of B", m2, "kg", 2),
                Given("velocity of A after", abs(v1), "m s^-1", 2),
                Given("velocity of B after", abs(v2), "m s^-1", 2)),
        diagram=diagrams.line(((f"{mass_a} kg", u1), (f"{mass_b} kg", u2)), (("", v1), ("", v2))),
        parts=(ChoicePart("Which statement about the collision is correct?", options,
                          OPTION_LETTERS[turn],
                          revisit="Momentum is conserved in every collision. To decide elastic or "
                                  "inelastic, compare the total kinetic energy before and after, or "
                                  "the relative speeds of approach and separation.", see="kinetic-energy"),),
        mark_scheme=(Mark(f"{OPTION_LETTERS[turn]}: kinetic energy {energy}; relative speeds: {speeds}, so "
                          f"{'elastic' if elastic else 'inelastic'}", "B1"),),
    )


def stick_energy_choice(m1: float = 2.0, u1: float = 4.0, m2: float = 1.0, speed2: float = 2.0) -> Question:
    """Paper 1 style: the kinetic energy transferred when two trolleys moving towards each other
    stick (notes: sticking trolleys, 24 J -> 18 J). Wrong options: the notes' common mistakes."""
    u2 = -speed2  # B moves towards A: positive is A's direction
    if momentum(m2, speed2) >= momentum(m1, u1):
        raise ValueError(f"A must have more momentum than B ({n(momentum(m2, speed2), 3)} N s), so the "
                         f"pair moves on in A's direction (got m1={m1!r}, u1={u1!r})")
    v = stick_together(m1, u1, m2, u2)
    before = total_kinetic_energy((m1, m2), (u1, u2))
    after = total_kinetic_energy((m1 + m2,), (v,))
    key = before - after
    same_way = stick_together(m1, u1, m2, speed2)
    # "Forgot one body's kinetic energy": students leave out the lighter trolley B before, or
    # leave B out of the pair after (which gives too much); which one keeps the key's letter moving.
    if kinetic_energy(m2, speed2) < 0.1 * (before - after):
        raise ValueError(f"speed2={speed2!r} m s^-1 gives B too little kinetic energy "
                         f"({n(kinetic_energy(m2, speed2), 2)} J) for forgetting it to be told from the key")
    if m2 < m1:
        forgot_b = {"forgot B's kinetic energy before": (
            kinetic_energy(m1, u1) - after,
            ("You left out B's kinetic energy before the collision. Both trolleys were moving: add "
             "½m₁u₁² and ½m₂u₂²."))}
    elif kinetic_energy(m2, v) < 0.1 * (before - after):
        raise ValueError(f"the pair moves too slowly ({n(v, 2)} m s^-1) for leaving B out of the kinetic "
                         f"energy after to be told from the key (got m1={m1!r}, m2={m2!r})")
    else:
        forgot_b = {"left B out of the kinetic energy after": (
            before - kinetic_energy(m1, v),
            ("You worked out the kinetic energy after with A's mass only. The trolleys move together "
             "afterwards: use ½(m₁ + m₂)v²."))}
    options, answer = choices_in_order(key, {
        "kinetic energy conserved": (
            0.0,
            ("Kinetic energy is conserved only in an elastic collision. Trolleys that stick together "
            "always lose some: work out the total before and after.")),
        "momentum added as scalars": (
            before - total_kinetic_energy((m1 + m2,), (same_way,)),
            ("You gave B's velocity the same sign as A's. They move towards each other, so B's momentum "
            "is negative: the common velocity is (m₁u₁ − m₂u₂) / (m₁ + m₂)."), "momentum"),
        **forgot_b,
        "total kinetic energy before given": (
            before,
            ("That is the total kinetic energy before the collision. The energy transferred is the "
             "kinetic energy lost: the total before − the total after.")),
        "the ½ left out": (
            2 * key,
            "You wrote the kinetic energy as mv². It is ½mv²: halve each term."),
        "kinetic energy after given": (
            after,
            ("That is the kinetic energy left after the collision. The energy transferred is the "
             "kinetic energy lost: the total before − the total after.")),
    }, sig_figs=2, unit="J", seed=0)
    a_mass, b_mass = n(m1, 2), n(m2, 2)
    return Question(
        key="stick-energy-choice",
        text=(f"Trolley A of mass {a_mass} kg, moving at {n(u1, 2)} {PER_S}, collides head-on with trolley B "
              f"of mass {b_mass} kg, moving towards it at {n(speed2, 2)} {PER_S}. The trolleys stick "
              "together."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed of B", speed2, "m s^-1", 2)),
        diagram=diagrams.line(((f"{a_mass} kg", u1), (f"{b_mass} kg", u2)), (("", None),)),
        parts=(ChoicePart("How much kinetic energy is transferred to other forms in the collision?",
                          options, answer,
                          revisit="Find the common velocity from momentum (with B's velocity negative), "
                                  "then subtract the total kinetic energy after from the total before.", see="kinetic-energy"),),
        mark_scheme=(Mark(f"{answer}: v = ({w(momentum(m1, u1))} − {w(momentum(m2, speed2))}) / "
                          f"{w(m1 + m2)} = {w(v)} {PER_S}; {w(before)} − {w(after)} = {n(key, 2)} J", "B1"),),
    )


#: Inelastic collisions in an isolated system: what happens, and where the kinetic energy goes.
_CRASHES = (
    ("A lump of modelling clay is thrown at a trolley at rest on a smooth, level track and sticks to it.",
     "the clay and the trolley", "the clay is squashed out of shape"),
    ("Two railway trucks roll towards each other on a level track, collide and couple together.",
     "the two trucks", "the buffers and couplings are pushed in and bent"),
    ("A bullet is fired into a block of wood resting on a smooth, level surface and stays in it.",
     "the bullet and the block", "the bullet and the wood are deformed"),
    ("Two cars skid towards each other on an icy road and crash head-on, crumpling their fronts.",
     "the two cars", "the metal of the crumple zones is bent out of shape"),
)


def collision_energy_explained(situation: float = 0) -> Question:
    """Describe and explain: in an inelastic collision momentum is still conserved (third law,
    no external resultant force) while kinetic energy is transferred to other forms (notes:
    "Elastic and inelastic collisions"; common mistake: using kinetic energy instead of momentum)."""
    what, bodies, deformed = _CRASHES[int(situation)]
    return Question(
        key="collision-energy-explained",
        text=f"{what} The collision is inelastic.",
        givens=(),
        parts=(ExplainPart(
            "Explain why the total momentum is conserved in the collision, but the total kinetic "
            "energy is not, and state what happens to the kinetic energy that is lost.",
            f"During the collision {bodies} push on each other with forces that are equal and opposite "
            "(Newton's third law) and act for the same time, so their changes in momentum are equal "
            "and opposite. No resultant external force acts on the system, so the total momentum is "
            "the same before and after. Kinetic energy is not kept because the collision is inelastic: "
            f"work is done as {deformed}. The total energy is still conserved: the kinetic energy lost "
            "is transferred to thermal energy (the bodies warm up), sound and the work of deforming them."),),
        mark_scheme=(
            Mark(f"The forces between {bodies} are equal and opposite (third law) and act for the same "
                 "time, so the changes in momentum are equal and opposite", "B1", "a"),
            Mark("No resultant external force acts (an isolated system), so the total momentum is conserved",
                 "B1", "a"),
            Mark(f"Kinetic energy is transferred to other forms as {deformed}: the total kinetic energy "
                 "after is less than before", "M1", "a"),
            Mark("It becomes thermal energy (heating) and sound; the total energy is still conserved",
                 "A1", "a"),
        ),
    )


def _elastic_from_speeds(u1: float, speed2: float, back2: float, figures: int) -> Question:
    """A's speed after an elastic collision from the speeds alone: separation = approach, as
    9702/22/O/N/23 Q4(b) asks it ("A at 4 m s⁻¹, B at 6 m s⁻¹ … B moves back at 2 m s⁻¹": 8 m s⁻¹,
    [1]). The speeds print to the figures the question states them to, and data stated to 1 s.f.
    take a 1 s.f. answer (min_sig_figs)."""
    approach = relative_speed(u1, -speed2)
    after_a = back2 - approach  # B moves back the way it came, now in A's first direction
    ua, ub, vb = (n(value, figures) for value in (u1, speed2, back2))
    return Question(
        key="elastic-both-moving",
        text=(f"Blocks A and B move directly towards each other, A at {ua} {PER_S} and B at {ub} {PER_S}, and "
              f"collide. The collision is perfectly elastic. After the collision B moves back along its "
              f"original path at {vb} {PER_S}. Calculate the speed of A after the collision."),
        givens=(Given("speed of A", u1, "m s^-1", figures), Given("speed of B", speed2, "m s^-1", figures),
                Given("speed of B after", back2, "m s^-1", figures)),
        parts=(
            Part("speed of A after the collision", abs(after_a), "m s^-1", "speed", units=M_S,
                 shown_sig_figs=max(figures, 1), min_sig_figs=min(figures, 2),
                 revisit="Elastic: the relative speed of separation equals the relative speed of approach, "
                         f"{ua} + {ub}. B moves away from A at {vb}, so A moves back at the difference.",
                 mistakes=(
                     Mistake("subtracted the speeds of approach", abs(back2 - relative_speed(u1, speed2)),
                             f"They move towards each other, so they approach at {ua} + {ub}, the sum."),
                 ), see="relative-speed"),
        ),
        mark_scheme=(
            Mark(f"relative speed of approach = {ua} + {ub} = relative speed of separation; "
                 f"speed of A = {n(approach, figures)} − {vb} = {n(abs(after_a), figures)} {PER_S}", "B1", "a"),
        ),
    )


def elastic_both_moving(m1: float = 0.20, u1: float = 3.0, m2: float = 0.30, speed2: float = 1.5,
                        back2: float = 0, figures: float = 2) -> Question:
    """Both bodies moving towards each other, elastic: relative speeds (notes: 5 and 3 m s^-1
    towards each other approach at 8 m s^-1), then the two equations solved together.

    back2: 0 (the variants) asks both velocities from the masses; a value is B's speed back after
    the collision, and the question asks A's speed from the speeds alone (_elastic_from_speeds),
    with the speeds stated to ``figures`` significant figures."""
    if back2:
        return _elastic_from_speeds(u1, speed2, back2, int(figures))
    u2 = -speed2  # B moves towards A: positive is A's first direction
    approach = relative_speed(u1, u2)
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    p_before = total_momentum((m1, m2), (u1, u2))
    if math.isclose(p_before, 0.0, abs_tol=1e-12):  # equal and opposite momenta: the total is zero
        p_before = 0.0
    ma, mb, ua, ub = n(m1, 2), n(m2, 2), n(u1, 2), n(speed2, 2)
    forward = "the direction A moves at first"
    v_1, v_2 = "v<sub>A</sub>", "v<sub>B</sub>"
    relative = "Elastic, so relative speed of separation = relative speed of approach: v<sub>B</sub> − v<sub>A</sub>"
    sym_a, sym_b, sym_m1, sym_m2, sym_u1, sym_u2 = sympy.symbols("a b m_a m_b u_a u_b")
    b_values = {"m_a": m1, "m_b": m2, "u_a": u1, "u_b": u2}
    return Question(
        key="elastic-both-moving",
        text=(f"Ball A of mass {ma} kg moving at {ua} {PER_S} collides head-on with ball B of mass {mb} kg, "
              f"moving towards it at {ub} {PER_S}. The collision is elastic. Calculate (a) the relative "
              "speed of approach, (b) the velocity of A and (c) the velocity of B after the collision. "
              "Take A's first direction as positive."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed of B", speed2, "m s^-1", 2)),
        diagram=diagrams.line(((f"{ma} kg", u1), (f"{mb} kg", u2)), (("", None), ("", None))),
        parts=(
            Part("relative speed of approach", approach, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 revisit="Relative speed is how fast the gap closes: moving towards each other, add the speeds.",
                 mistakes=(
                     Mistake("subtracted the speeds", relative_speed(u1, speed2),
                             "You subtracted the speeds. They move towards each other, so the gap closes at "
                             "the sum: B's velocity is negative, so u₁ − u₂ adds the speeds."),
                 ), see="relative-speed"),
            Part("velocity of A after the collision", v1, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward,
                 ecf=Ecf((sym_m1 * sym_u1 + sym_m2 * sym_u2 - sym_m2 * sym_a) / (sym_m1 + sym_m2), b_values),
                 revisit="Two equations (1 is A, 2 is B): momentum, m₁u₁ + m₂u₂ = m₁v₁ + m₂v₂ with u₂ "
                         "negative, and v₂ − v₁ = relative speed of approach. Substitute one into the other.",
                 mistakes=(
                     Mistake("forgot B's direction", elastic_collision(m1, u1, m2, speed2)[0],
                             "You gave B's velocity before the same sign as A's. B moves towards A, so "
                             f"u₂ = −{ub} {_PER_S_PLAIN}."),
                     Mistake("treated as sticking together", stick_together(m1, u1, m2, u2),
                             "That is the common velocity if they stuck together. This collision is "
                             "elastic: the balls separate as fast as they approached.", see="kinetic-energy"),
                 ), see="relative-speed"),
            Part("velocity of B after the collision", v2, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward,
                 ecf=Ecf(sym_b + sym_a, {}),
                 # or by momentum: m1 u1 + m2 u2 = m1 v1 + m2 v2, with (b) for v1
                 ecf_also=(Ecf((sym_m1 * sym_u1 + sym_m2 * sym_u2 - sym_m1 * sym_b) / sym_m2, b_values),),
                 revisit="Relative speed of separation = relative speed of approach: v₂ = v₁ + (relative "
                         "speed of approach), where 1 is A and 2 is B.",
                 mistakes=(
                     Mistake("approach + separation = 0", v1 - approach,
                             "You took v₁ − v₂ (A's velocity minus B's) as the relative speed of "
                             "separation. B ends up ahead of A, so v₂ − v₁ = relative speed of approach."),
                     Mistake("forgot B's direction", elastic_collision(m1, u1, m2, speed2)[1],
                             "You gave B's velocity before the same sign as A's. B moves towards A, so "
                             f"u₂ = −{ub} {_PER_S_PLAIN}."),
                 ), see="relative-speed"),
        ),
        mark_scheme=(
            Mark(f"Relative speed of approach = {ua} + {ub} = {n(approach, 2)} {PER_S}", "B1", "a"),
            Mark(f"Momentum: {ma} × {ua} + {mb} × (−{ub}) = {w(p_before)} = {ma}{v_1} + {mb}{v_2}", "C1", "b"),
            Mark(f"{relative} = {n(approach, 2)}", "C1", "b"),
            Mark(f"{v_1} = {n(v1, 2)} {PER_S} (a minus sign means A moves back the way it came)", "A1", "b"),
            Mark(f"{v_2} = {v_1} + relative speed of approach = {w(v1)} + {n(approach, 2)}", "C1", "c"),
            Mark(f"= {n(v2, 2)} {PER_S}", "A1", "c"),
        ),
    )


def sticking_energy_lost(m1: float = 0.80, u1: float = 3.0, m2: float = 1.2) -> Question:
    """Perfectly inelastic: the common velocity, the kinetic energy after and the energy
    transferred (notes: sticking trolleys, 24 J before, 18 J after, 6.0 J transferred)."""
    v = stick_together(m1, u1, m2, 0.0)
    before = kinetic_energy(m1, u1)
    after = kinetic_energy(m1 + m2, v)
    lost = before - after
    ma, mb, ua = n(m1, 2), n(m2, 2), n(u1, 2)
    total = w(m1 + m2)
    sym_a, sym_b, sym_m1, sym_m2, sym_u1 = sympy.symbols("a b m_a m_b u_a")
    return Question(
        key="sticking-energy-lost",
        text=(f"Trolley A of mass {ma} kg, moving at {ua} {PER_S} on a level track, hits trolley B of mass "
              f"{mb} kg, which is at rest. They stick together. Calculate (a) their speed just after the "
              "collision, (b) their total kinetic energy just after the collision and (c) the kinetic "
              "energy transferred to other forms."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2)),
        diagram=diagrams.line(((f"{ma} kg", u1), (f"{mb} kg", 0.0)), (("", None),)),
        parts=(
            Part("speed just after the collision", v, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 revisit="Momentum is conserved: m₁u₁ = (m₁ + m₂)v, with the mass of both trolleys after.",
                 mistakes=(
                     Mistake("one body's mass used for both", velocity_from_momentum(momentum(m1, u1), m2),
                             "You divided by B's mass only. After sticking, both trolleys move together: "
                             "divide the momentum by the total mass.", see="momentum"),
                     # ½m₁u₁² = ½(m₁ + m₂)v²: sticking is inelastic, "(initial EK > final EK) so inelastic"
                     # (9702/23/O/N/17 Q3(b)(iii)); wrong physics, so it keeps no mark (XP, 9702/22/M/J/20)
                     Mistake("kinetic energy conserved", u1 * math.sqrt(m1 / (m1 + m2)),
                             "You set the kinetic energy after equal to the kinetic energy before. Trolleys "
                             "that stick together always lose kinetic energy: use momentum, m₁u₁ = "
                             "(m₁ + m₂)v.", see="kinetic-energy"),
                 ), see="conservation"),
            Part("total kinetic energy just after", after, "J", "energy", shown_sig_figs=2,
                 ecf=Ecf(sympy.Rational(1, 2) * (sym_m1 + sym_m2) * sym_a**2, {"m_a": m1, "m_b": m2}),
                 revisit="Eₖ = ½mv², with the mass of both trolleys.",
                 mistakes=(
                     Mistake("used A's mass only", kinetic_energy(m1, v),
                             "Both trolleys move after the collision: use their total mass."),
                     Mistake("forgot the ½", 2 * after,
                             "Kinetic energy is ½mv²: you left out the ½.", see="kinetic-energy"),
                 ), see="kinetic-energy"),
            Part("kinetic energy transferred to other forms", lost, "J", "energy", shown_sig_figs=2,
                 ecf=Ecf(sympy.Rational(1, 2) * sym_m1 * sym_u1**2 - sym_b, {"m_a": m1, "u_a": u1}),
                 revisit="Energy transferred = total kinetic energy before − total kinetic energy after.",
                 mistakes=(
                     Mistake("gave the kinetic energy before", before,
                             "That is the kinetic energy before. Subtract the kinetic energy after."),
                     Mistake("kinetic energy conserved", 0.0,
                             "Kinetic energy is conserved only in an elastic collision. Trolleys that "
                             "stick together always lose some: subtract the total after from the total "
                             "before."),
                 ), see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"{ma} × {ua} = {total}v", "C1", "a"),
            Mark(f"v = {n(v, 2)} {PER_S}", "A1", "a"),
            Mark(f"E<sub>k</sub> = ½ × {total} × {w(v)}<sup>2</sup>", "C1", "b"),
            Mark(f"= {n(after, 2)} J", "A1", "b"),
            Mark(f"Before: ½ × {ma} × {ua}<sup>2</sup> = {w(before)} J", "C1", "c"),
            Mark(f"Transferred = {w(before)} − {w(after)} = {n(lost, 2)} J", "A1", "c"),
        ),
    )


#: A ratio of two energies has no unit: the marker takes a bare number, or a percentage with %.
_NO_UNIT = "no unit (a number), or a percentage with %"
#: Symbols of the ratio templates' error carried forward.
a_answer, mass_1, speed_1, mass_2, speed_back = sympy.symbols("a mass_1 speed_1 mass_2 speed_back")


def _percentage_without_sign(value: float, what: str) -> Mistake:
    """The ratio written as a percentage with the % sign left off (a slip of a factor of 100)."""
    return Mistake("percentage without %", 100 * value,
                   f"That is the {what} as a percentage, written without its % sign. Give it as a number, "
                   f"{n(value, 2)}, or as {n(100 * value, 2)} %.", kind="slip")


def _b_ahead_words(m1: float, u1: float, m2: float, speed2: float) -> dict[str, str]:
    """How the fraction question words B: at rest (the variants), or moving ahead of A the same
    way (9702/23/M/J/25 Q4(b))."""
    ma, mb, ua = n(m1, 2), n(m2, 2), n(u1, 2)
    if not speed2:
        return {"b": "which is at rest", "energy": "the kinetic energy of A", "momentum": f"{ma} × {ua}",
                "before": f"½ × {ma} × {ua}<sup>2</sup>"}
    sb = n(speed2, 2)
    return {"b": f"which moves ahead of A in the same direction at {sb} {PER_S}",
            "energy": "the total kinetic energy of A and B", "momentum": f"{ma} × {ua} + {mb} × {sb}",
            "before": f"½ × {ma} × {ua}<sup>2</sup> + ½ × {mb} × {sb}<sup>2</sup>"}


def sticking_fraction_lost(m1: float = 3.0, u1: float = 4.0, m2: float = 1.0, speed2: float = 0.0) -> Question:
    """Kinetic energy lost as a fraction, when two trolleys stick (notes, "Elastic and inelastic
    collisions": 3.0 kg at 4.0 m s^-1 hits 1.0 kg at rest, 3.0 m s^-1 together, 24 J -> 18 J, so
    6.0 J, 25 % of it, is transferred; How to do it 5., "Percentage of kinetic energy lost").
    The scheme's lines follow 9702/23/M/J/16 Q3(b)(iii) (KE = ½mv² C1 … change in kinetic energy
    C1 … A1); a ratio is accepted as a decimal or a percentage, as in 9702/22/O/N/16 Q5(b)(iv)
    ("= 0.88 or 88 % A1"). speed2: B at rest (0, the variants) or moving ahead of A the same
    way, slower (9702/23/M/J/25 Q4(b): 4.0 kg at 6.0 m s^-1 catches 2.0 kg at 3.0 m s^-1)."""
    if speed2 >= u1:
        raise ValueError(f"speed2 must be below u1={u1!r} m s^-1, or A never catches B (got speed2={speed2!r})")
    v = stick_together(m1, u1, m2, speed2)
    before = total_kinetic_energy((m1, m2), (u1, speed2))
    after = kinetic_energy(m1 + m2, v)
    fraction = percentage_kinetic_energy_lost(before, after) / 100
    ma, mb, ua, total = n(m1, 2), n(m2, 2), n(u1, 2), w(m1 + m2)
    words = _b_ahead_words(m1, u1, m2, speed2)
    shown = n(fraction, 2)
    # the energies with the figures the fraction needs, and the speed with the figures they need
    e_before, e_after = enough_figures((before, after), lambda b, a: (b - a) / b, shown)
    (v_carried,) = enough_figures((v,), lambda speed: kinetic_energy(m1 + m2, speed), e_after)
    # B at rest keeps the variants' formula; B moving adds its kinetic energy before
    energy_before = mass_1 * speed_1**2 + (mass_2 * speed_2**2 if speed2 else 0)
    return Question(
        key="sticking-fraction-lost",
        text=(f"Trolley A, of mass {ma} kg, moves at {ua} {PER_S} along a level track and hits trolley B, of "
              f"mass {mb} kg, {words['b']}. The trolleys stick together. Calculate (a) their speed just after "
              f"the collision and (b) the fraction of {words['energy']} that is transferred to other "
              "forms in the collision. Give (b) as a decimal or as a percentage."),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), *((Given("speed of B", speed2, "m s^-1", 2),) if speed2 else ())),
        diagram=diagrams.line(((f"{ma} kg", u1), (f"{mb} kg", speed2)), (("", None),)),
        parts=(
            Part("speed just after the collision", v, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 revisit="Momentum is conserved: m₁u₁ + m₂u₂ = (m₁ + m₂)v, with the mass of both trolleys after.",
                 mistakes=one_of_each(v, (
                     Mistake("one body's mass used for both", (momentum(m1, u1) + momentum(m2, speed2)) / m1,
                             f"You used A's mass for the pair after the collision. The trolleys move together: "
                             f"{words['momentum']} = ({ma} + {mb})v.", see="momentum"),
                     Mistake("kinetic energy conserved", math.sqrt(2 * before / (m1 + m2)),
                             "You set the kinetic energies before and after equal. Trolleys that stick together "
                             "always lose kinetic energy: use momentum, which is conserved.",
                             see="kinetic-energy"),
                     Mistake("B's momentum left out", momentum(m1, u1) / (m1 + m2),
                             f"You left out B's momentum: it moves at {n(speed2, 2)} {PER_S} before the collision.",
                             see="momentum"),
                 )), see="conservation"),
            Part("fraction of the kinetic energy transferred", fraction, "", "fraction", units=_NO_UNIT,
                 shown_sig_figs=2,
                 working=(Step("common speed", v, "m s^-1", 2),),
                 answer_from=lambda speed: percentage_kinetic_energy_lost(before, kinetic_energy(m1 + m2, speed))
                 / 100,
                 ecf=Ecf(1 - (mass_1 + mass_2) * a_answer**2 / energy_before,
                         {"mass_1": m1, "speed_1": u1, "mass_2": m2, **({"speed_2": speed2} if speed2 else {})}),
                 revisit="Fraction lost = (kinetic energy before − kinetic energy after) / kinetic energy "
                         "before, with ½mv² for each.",
                 mistakes=_fraction_lost_mistakes(fraction, (m1, u1, m2, speed2), v, (before, after)),
                 see="kinetic-energy"),
        ),
        mark_scheme=(
            Mark(f"{words['momentum']} = {total}v", "C1", "a"),
            Mark(f"v = {n(v, 2)} {PER_S}", "A1", "a"),
            Mark(f"E<sub>k</sub> before = {words['before']} = {e_before} J; after = ½ × {total} × "
                 f"{v_carried}<sup>2</sup> = {e_after} J", "C1", "b"),
            Mark(f"fraction = ({e_before} − {e_after}) / {e_before} = {shown}, or {n(100 * fraction, 2)} %", "A1", "b"),
        ),
    )


def _fraction_lost_mistakes(fraction: float, givens: tuple[float, float, float, float], v: float,
                            energies: tuple[float, float]) -> tuple[Mistake, ...]:
    """The named mistakes of sticking-fraction-lost (b); those that meet the key or each other drop."""
    (m1, u1, m2, speed2), (before, after) = givens, energies
    a_only = kinetic_energy(m1, u1)
    return one_of_each(fraction, (
        Mistake("kinetic energy conserved", 0.0,
                "Kinetic energy is conserved only in an elastic collision. Trolleys that stick "
                "together always lose some: work out ½mv² before and after."),
        Mistake("fraction kept, not lost", after / before,
                "That is the fraction of the kinetic energy that is kept, after / before. The "
                "fraction transferred is (before − after) / before."),
        Mistake("lost as a fraction of the energy after", (before - after) / after,
                "You divided the energy lost by the kinetic energy after. A fraction of the "
                "kinetic energy before is (before − after) / before."),
        Mistake("A's mass only after", percentage_kinetic_energy_lost(before, kinetic_energy(m1, v)) / 100,
                "You worked out the kinetic energy after with A's mass only. Both trolleys move "
                "afterwards: ½(m₁ + m₂)v²."),
        Mistake("B's kinetic energy before left out", (a_only - after) / a_only,
                f"B moves before the collision too: the kinetic energy before is ½ × {n(m1, 2)} × "
                f"{n(u1, 2)}² + ½ × {n(m2, 2)} × {n(speed2, 2)}²."),
        _percentage_without_sign(fraction, "fraction"),
    ))


#: What the energy part asks: the ratio after / before (the variants), or the kinetic energy the
#: collision transfers, as 9702/23/O/N/24 Q2(b)(ii) asks "the change in the total kinetic energy".
_ENERGY_ASKED = ("ratio", "decrease")
speed_2 = sympy.Symbol("speed_2")


def _energy_ratio_part(masses: tuple[float, float], before_speeds: tuple[float, float], back: float,
                       v2: float) -> Part:
    """(b) as the ratio (total kinetic energy after) / (total kinetic energy before)."""
    (m1, m2), (u1, speed2) = masses, before_speeds
    before = total_kinetic_energy(masses, (u1, -speed2))
    after = total_kinetic_energy(masses, (-back, v2))
    ratio = after / before
    # B at rest (the variants) keeps its first formula; B moving adds its kinetic energy before
    denominator = mass_1 * speed_1**2 + (mass_2 * speed_2**2 if speed2 else 0)
    b_left_out = (Mistake("B's kinetic energy before left out", after / kinetic_energy(m1, u1),
                          "B was moving before the collision too: the total kinetic energy before is ½mv² for "
                          "A and for B."),) if speed2 else ()
    return Part("ratio of the kinetic energy after to that before", ratio, "", "ratio", units=_NO_UNIT,
                shown_sig_figs=2,
                working=(Step("speed of B", v2, "m s^-1", 2),),
                answer_from=lambda speed: total_kinetic_energy(masses, (back, speed)) / before,
                ecf=Ecf((mass_1 * speed_back**2 + mass_2 * a_answer**2) / denominator,
                        {"mass_1": m1, "speed_1": u1, "mass_2": m2, "speed_back": back,
                         **({"speed_2": speed2} if speed2 else {})}),
                revisit="Total kinetic energy after (½mv² for each ball) ÷ total kinetic energy before.",
                mistakes=one_of_each(ratio, (
                    Mistake("ratio inverted", before / after,
                            "That is before / after, upside down. The ratio asked for is the kinetic energy "
                            "after ÷ the kinetic energy before (less than 1: some is lost)."),
                    Mistake("fraction lost given", (before - after) / before,
                            "That is the fraction lost, (before − after) / before. The ratio asked for is "
                            "after / before."),
                    Mistake("kinetic energy conserved", 1.0,
                            "Kinetic energy is conserved only in an elastic collision. Work out ½mv² for each "
                            "ball after the collision and compare."),
                    Mistake("A's kinetic energy only", kinetic_energy(m1, back) / before,
                            "You left out B's kinetic energy after. Both balls move afterwards: add ½mv² for "
                            "each."),
                    *b_left_out,
                    _percentage_without_sign(ratio, "ratio"),
                )), see="kinetic-energy")


def _energy_decrease_part(masses: tuple[float, float], before_speeds: tuple[float, float], back: float,
                          v2: float) -> Part:
    """(b) as the kinetic energy the collision transfers to other forms, J: a paper's "change in
    the total kinetic energy" (9702/23/O/N/24 Q2(b)(ii)), asked as a size."""
    (m1, m2), (u1, speed2) = masses, before_speeds
    before = total_kinetic_energy(masses, (u1, -speed2))
    after = total_kinetic_energy(masses, (-back, v2))
    half = sympy.Rational(1, 2)
    return Part("decrease in the total kinetic energy", before - after, "J", "energy", shown_sig_figs=2,
                working=(Step("speed of B", v2, "m s^-1", 2),),
                answer_from=lambda speed: before - total_kinetic_energy(masses, (back, speed)),
                ecf=Ecf(half * (mass_1 * speed_1**2 + mass_2 * speed_2**2 - mass_1 * speed_back**2)
                        - half * mass_2 * a_answer**2,
                        {"mass_1": m1, "speed_1": u1, "mass_2": m2, "speed_2": speed2, "speed_back": back}),
                revisit="Kinetic energy transferred = total kinetic energy before − total after, ½mv² for each ball.",
                mistakes=one_of_each(before - after, (
                    Mistake("gave the kinetic energy before", before,
                            "That is the total kinetic energy before. Subtract the total after."),
                    Mistake("gave the kinetic energy after", after,
                            "That is the total kinetic energy after. The change is before − after."),
                    Mistake("forgot the ½", 2 * (before - after),
                            "Kinetic energy is ½mv²: you left out the ½.", see="kinetic-energy"),
                    Mistake("kinetic energy conserved", 0.0,
                            "Kinetic energy is conserved only in an elastic collision. Work out ½mv² for each "
                            "ball before and after, and subtract."),
                )), see="kinetic-energy")


def _momentum_line(ma: str, ua: str, mb: str, speed2: float, back: float) -> str:
    """The scheme's momentum equation, with B's momentum before and A's after where they are not zero."""
    b_before = f" − {mb} × {n(speed2, 2)}" if speed2 else ""
    a_after = f"{ma} × (−{n(back, 2)}) + " if back else ""
    return f"Momentum: {ma} × {ua}{b_before} = {a_after}{mb}v"


def bounce_energy_ratio(m1: float = 0.20, u1: float = 3.0, m2: float = 0.60, back: float = 0.60,
                        speed2: float = 0.0, asks: float = 0) -> Question:
    """The kinetic energy after a collision as a ratio of that before: a light ball bounces back
    off a heavier one at rest (notes, "Elastic and inelastic collisions": to decide, compare the
    total kinetic energy before and after). The scheme's lines follow 9702/21/M/J/15 Q3(b), the
    collision of balls X and Y ("total initial kinetic energy not equal to the total final kinetic
    energy … so not elastic or is inelastic")
    and 9702/23/M/J/16 Q3(b)(iii) (KE = ½mv² C1 … C1 … A1).

    As the papers' collisions: speed2 sets B moving towards A before (0: at rest, the variants),
    back = 0 has A stop, as ball X does in 9702/23/O/N/24 Q2(b), and asks = 1 asks the kinetic
    energy the collision transfers, as its (b)(ii) does, instead of the ratio."""
    if asks not in (0, 1):
        raise ValueError(f"asks must be 0 (the ratio after / before) or 1 (the decrease in kinetic energy) "
                         f"(got asks={asks!r})")
    if m2 <= m1 and back > 0 and not speed2:
        raise ValueError(f"m2 must be heavier than m1, so the first ball bounces back (got m1={m1!r}, m2={m2!r})")
    v1 = -back  # positive: A's first direction
    v2 = velocity_after_collision(m1, u1, m2, -speed2, v1)
    if v2 <= 0:
        raise ValueError(f"speed2={speed2!r} m s^-1 leaves B moving towards A's side after the collision "
                         f"({n(v2, 2)} m s^-1): the question asks the speed at which B moves away")
    before = total_kinetic_energy((m1, m2), (u1, -speed2))
    after = total_kinetic_energy((m1, m2), (v1, v2))
    if after > before:
        raise ValueError(f"back={back!r} m s^-1 would create kinetic energy ({n(before, 3)} J before, "
                         f"{n(after, 3)} J after)")
    ma, mb, ua, vb = n(m1, 2), n(m2, 2), n(u1, 2), n(back, 2)
    e_before, e_after = enough_figures((before, after), (lambda b, a: a / b) if asks == 0 else (lambda b, a: b - a),
                                       n(after / before if asks == 0 else before - after, 2))
    (v2_carried,) = enough_figures((v2,), lambda speed: total_kinetic_energy((m1, m2), (back, speed)), e_after)
    b_was = "at rest" if not speed2 else f"moving towards A at {n(speed2, 2)} {PER_S}"
    a_did = f"bounces straight back at {vb} {PER_S}" if back else "stops"
    energy = (_energy_ratio_part, _energy_decrease_part)[int(asks)]((m1, m2), (u1, speed2), back, v2)
    asked = ("the ratio (total kinetic energy after the collision) / (total kinetic energy before the collision). "
             "Give (b) as a decimal or as a percentage.") if asks == 0 else (
             "the decrease in the total kinetic energy of the balls in the collision.")
    b_before = f" + ½ × {mb} × {n(speed2, 2)}<sup>2</sup>" if speed2 else ""
    a_after = f"½ × {ma} × {vb}<sup>2</sup> + " if back else ""
    result = (f"ratio = {e_after} / {e_before} = {n(energy.value, 2)}" if asks == 0
              else f"decrease = {e_before} − {e_after} = {n(energy.value, 2)} J")
    return Question(
        key="bounce-energy-ratio",
        text=(f"Ball A, of mass {ma} kg, moving at {ua} {PER_S}, hits ball B, of mass {mb} kg, head-on. B was "
              f"{b_was}. After the collision A {a_did}. Calculate (a) the speed of B just after the collision "
              f"and (b) {asked}"),
        givens=(Given("mass of A", m1, "kg", 2), Given("speed of A", u1, "m s^-1", 2),
                Given("mass of B", m2, "kg", 2), Given("speed of A after", back, "m s^-1", 2),
                *((Given("speed of B", speed2, "m s^-1", 2),) if speed2 else ())),
        diagram=diagrams.line(((f"{ma} kg", u1), (f"{mb} kg", -speed2 if speed2 else 0.0)), (("", v1), ("", None))),
        parts=(_speed_of_b_part((m1, m2), (u1, speed2), back, v2), energy),
        mark_scheme=(
            Mark(_momentum_line(ma, ua, mb, speed2, back), "C1", "a"),
            Mark(f"v = {n(v2, 2)} {PER_S}", "A1", "a"),
            Mark(f"E<sub>k</sub> before = ½ × {ma} × {ua}<sup>2</sup>{b_before} = {e_before} J; after = {a_after}"
                 f"½ × {mb} × {v2_carried}<sup>2</sup> = {e_after} J", "C1", "b"),
            Mark(result, "A1", "b"),
        ),
    )


def _speed_of_b_part(masses: tuple[float, float], before_speeds: tuple[float, float], back: float,
                     v2: float) -> Part:
    """(a) B's speed after, from the conservation of momentum with a sign on every velocity."""
    (m1, m2), (u1, speed2) = masses, before_speeds
    ma, mb, ua, vb = n(m1, 2), n(m2, 2), n(u1, 2), n(back, 2)
    b_left_out = (Mistake("B's momentum before left out", velocity_after_collision(m1, u1, m2, 0.0, -back),
                          f"B was moving towards A at {n(speed2, 2)} {_PER_S_PLAIN} before: its momentum before, "
                          f"−{mb} × {n(speed2, 2)}, belongs in the total.", see="momentum"),) if speed2 else ()
    return Part("speed of B just after the collision", v2, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                revisit="Momentum is conserved, with a sign on every velocity: A bounces back, so its "
                        "velocity after is negative. m₁u₁ = m₁v₁ + m₂v₂.",
                mistakes=one_of_each(v2, (
                    Mistake("momentum added as scalars", velocity_after_collision(m1, u1, m2, -speed2, back),
                            f"You gave A's velocity after the same sign as before. A bounces back, so its "
                            f"momentum after is negative: {ma} × {ua} = {ma} × (−{vb}) + {mb}v.",
                            see="momentum"),
                    Mistake("changes in velocity taken as equal", u1 + back - speed2,
                            "You gave B the same change in velocity as A. It is the changes in momentum that "
                            "are equal and opposite: B's mass is different."),
                    Mistake("as if A stopped", velocity_after_collision(m1, u1, m2, -speed2, 0.0),
                            "You gave B all of A's momentum, as if A stopped. A bounces back, so B gains "
                            "more than that."),
                    *b_left_out,
                )), see="conservation")


TEMPLATES = checked_givens(
    Template("quick-check-4", "elastic", ("numeric",), "Quick check 4", light_ball_hits_heavy_ball,
             {"m1": Draw(1.0, 0.5, 2.0, 0.1), "u1": Draw(6.0, 2.0, 9.0, 0.5), "m2": Draw(2.0, 1.0, 5.0, 0.5)}),
    Template("elastic-or-not-choice", "elastic", ("mcq",), "Is it elastic?", elastic_or_not_choice,
             {"situation": Draw(0, 0, len(_BOUNCES) - 1, 1)}, variant_count=len(_BOUNCES)),
    Template("stick-energy-choice", "elastic", ("mcq",), "Trolleys that stick", stick_energy_choice,
             {"m1": Draw(2.0, 1.0, 3.0, 0.5), "u1": Draw(4.0, 2.0, 6.0, 0.5), "m2": Draw(1.0, 1.0, 4.0, 0.5),
              "speed2": Draw(2.0, 1.0, 3.0, 0.5)}),
    Template("collision-energy-explained", "elastic", ("explain",), "Where does the energy go?",
             collision_energy_explained, {"situation": Draw(0, 0, len(_CRASHES) - 1, 1)},
             variant_count=len(_CRASHES)),
    Template("elastic-both-moving", "elastic", ("numeric",), "Balls moving towards each other",
             elastic_both_moving,
             {"m1": Draw(0.20, 0.10, 0.50, 0.05), "u1": Draw(3.0, 1.0, 6.0, 0.5),
              "m2": Draw(0.30, 0.10, 0.50, 0.05), "speed2": Draw(1.5, 1.0, 5.0, 0.5)}),
    Template("sticking-energy-lost", "elastic", ("numeric",), "Energy lost when trolleys stick", sticking_energy_lost,
             {"m1": Draw(0.80, 0.40, 2.00, 0.10), "u1": Draw(3.0, 1.0, 5.0, 0.5),
              "m2": Draw(1.2, 0.4, 2.0, 0.1)}),
    Template("sticking-fraction-lost", "elastic", ("numeric",), "Fraction of the kinetic energy lost",
             sticking_fraction_lost,
             {"m1": Draw(3.0, 0.5, 4.0, 0.5), "u1": Draw(4.0, 1.0, 6.0, 0.5), "m2": Draw(1.0, 0.5, 4.0, 0.5)}),
    Template("bounce-energy-ratio", "elastic", ("numeric",), "Kinetic energy after ÷ before", bounce_energy_ratio,
             {"m1": Draw(0.20, 0.10, 0.50, 0.05), "u1": Draw(3.0, 2.0, 6.0, 0.5),
              "m2": Draw(0.60, 0.30, 1.50, 0.10), "back": Draw(0.60, 0.10, 2.0, 0.10)}),
)
