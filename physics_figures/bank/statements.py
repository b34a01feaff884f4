# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, en dash)
"""The define and state questions of the papers, each of the type whose practice page teaches it.

15 of 40 real Paper 1 and Paper 2 Dynamics questions open with a part such as "define momentum",
"state Newton's second law in terms of momentum" or "state the principle of conservation of
momentum" (issue 25). Each template here is one ``TextPart`` (issue 38), marked from the typed
words by its points' rules (statement_rules.py: the wordings an examiner accepts and those the
schemes reject, each citing its paper). The points are the published 9702 scheme's,
in the words an examiner looks for ("rate of change of momentum", "resultant force", "no resultant
external force", "on different bodies", ...); the wording of each is the notes'
(../shared/notes, "Mass, weight and the definitions" and "Understand it"), and each template's
docstring cites the paper whose scheme it follows. tests/no_site/test_statements.py checks every point
against a table of those key words.

A statement whose question can be set in different situations without changing the physics
(the conservation principle for a collision, an explosion, a recoil...) has one variant per
situation, and its model answer applies the statement to that situation. A definition has one
right wording: it has one variant, and its ``one_wording`` says why (physics_figures.variants).
"""

from __future__ import annotations

from ..parts.text import TextPart, TextPoint
from ..questions import Mark, Question
from ..variants import Draw, Template
from . import statement_rules as rules
from ._common import PER_S2
from .givens import checked_givens

#: Why a definition has one variant (Template.one_wording).
_ONE_DEFINITION = ("A definition has one right wording: any situation put around the question leaves "
                   "the answer word for word the same, so a second variant would only repeat the first.")
_ONE_LAW = ("A law is stated the same way whatever the bodies: a situation put around the question "
            "leaves the statement word for word the same, so a second variant would only repeat the first.")


def _statement(key: str, text: str, prompt: str, points: tuple[TextPoint, ...], model: str) -> Question:
    """One text part, marked from the typed words by its points' rules (statement_rules), and its
    mark lines, one a point with the point's code: independent B1 points, as the schemes mark a
    definition or a stated law, or an M1 with its dependent A1 (the conservation principle)."""
    return Question(
        key=key,
        text=text,
        givens=(),
        parts=(TextPart(prompt, model, points),),
        mark_scheme=tuple(Mark(point.text, point.code, "a") for point in points),
    )


# ---------------------------------------------------------------- definitions (one wording)

#: Notes, Momentum and Newton's second law: "Linear momentum is mass × velocity ... Momentum is
#: a vector, in the direction of the velocity"; How to do it 4: "the product of mass and velocity".
MOMENTUM_POINTS = rules.MOMENTUM_POINTS


def define_momentum() -> Question:
    """Define linear momentum [2]. The syllabus wording is the point: 9702 syllabus 2025–2027,
    3.1.3 "define and use linear momentum as the product of mass and velocity"; the second B1
    (a vector) is the notes' ("Momentum is a vector, in the direction of the velocity"), asked as
    its own part as 8702/02/O/N/01 Q1 asks scalar or vector of mass and weight (B1 each). No
    published scheme for "define momentum" was found in the search corpus."""
    return _statement(
        "define-momentum", "Give the definition in words.",
        "Define linear momentum, and state whether it is a scalar or a vector quantity.",
        MOMENTUM_POINTS,
        "Linear momentum is the product of mass and velocity, p = mv (unit kg m s<sup>−1</sup>, the "
        "same as N s). It is a vector: its direction is the direction of the velocity.")


#: Notes, How to do it 4: "Force: the rate of change of momentum. ('Mass × acceleration' is how
#: to work out a resultant force for a constant mass, not the definition.)"
FORCE_POINTS = rules.FORCE_POINTS


def define_force() -> Question:
    """Define force [1]. 9702/21/M/J/16 Q3(b)(i): "(resultant) force proportional/equal to rate
    of change of momentum B1 [1]" (there asked as Newton's second law); the syllabus, 3.1.4,
    "define and use force as rate of change of momentum". The notes' common mistake: "Defining
    force as 'mass × acceleration'. Examiner reports say this every year." """
    return _statement(
        "define-force", "Give the definition in words.",
        "Define force.",
        FORCE_POINTS,
        "Force is the rate of change of momentum, F = Δp / Δt. (F = ma is how to work out a resultant "
        "force when the mass is constant; it is not the definition.)")


#: 8702/02/O/N/01 Q1 (the scheme of 9702's Paper 2 before 2002), [4]: "mass: property of body
#: which resists change in motion B1; constant OR scalar quantity B1; weight: effect of
#: gravitational field on a mass/body B1; variable OR vector quantity B1". Either half of the
#: second and of the fourth line earns its B1 (issue 37), so each point says "either". Notes: "Mass is a
#: scalar ... the same wherever the object is"; "Weight: the force on a mass due to a
#: gravitational field; W = mg"; "weight depends on where you are".
MASS_WEIGHT_POINTS = rules.MASS_WEIGHT_POINTS


def mass_and_weight_defined() -> Question:
    """Distinguish between mass and weight [4]: four B1 points, as 8702/02/O/N/01 Q1 (its second
    and fourth lines take either of two answers: "constant OR scalar", "variable OR vector")."""
    return _statement(
        "mass-and-weight-defined", "Give each definition in words.",
        "Distinguish between mass and weight.",
        MASS_WEIGHT_POINTS,
        "Mass is the property of an object that resists a change in its motion. It is a scalar, "
        "measured in kg, and it is the same wherever the object is. Weight is the force on a mass "
        "due to a gravitational field, W = mg, measured in N. It is a vector, towards the centre of "
        f"the planet, and it changes with g: on the Moon (g = 1.62 {PER_S2}) the same mass weighs "
        "less than on the Earth.")


#: Notes, Momentum and Newton's second law: "With SI units the constant is 1, which is how the
#: newton is defined, so F = Δp / Δt"; with constant mass F = ma.
NEWTON_POINTS = rules.NEWTON_POINTS


def define_the_newton() -> Question:
    """Define the newton [1]. The notes' own definition (the constant in F ∝ Δp / Δt is 1 in SI
    units, "which is how the newton is defined"); no published 9702 scheme for it was found in
    the search corpus, so the point is the notes' wording, marked B1 as a recalled definition
    (9702/22/M/J/20, mark categories: B marks are independent)."""
    return _statement(
        "define-the-newton", "Give the definition in words.",
        "Define the newton, the SI unit of force.",
        NEWTON_POINTS,
        f"One newton is the force that gives a mass of 1 kg an acceleration of 1 {PER_S2} in the "
        "direction of the force: 1 N = 1 kg m s<sup>−2</sup>, from F = ma.")


# ---------------------------------------------------------------- Newton's laws (one wording)

#: Notes, Mass and Newton's first law: "an object stays at rest, or keeps moving at a constant
#: velocity, unless a resultant force acts on it".
FIRST_LAW_POINTS = rules.FIRST_LAW_POINTS


def state_first_law() -> Question:
    """State Newton's first law [1]. One B1, as the 9702 Paper 2 schemes reprinted in a CIE topic
    booklet ("Newton's laws of motion", mark scheme 1, Q1(a) and Q2(a)(ii): "a body continues (at
    rest or) at constant velocity unless acted on by a resultant force B1 [1]"; the booklet does
    not print the paper codes)."""
    return _statement(
        "state-first-law", "State the law in words.",
        "State Newton's first law of motion.",
        FIRST_LAW_POINTS,
        "An object stays at rest, or keeps moving at constant velocity, unless a resultant force acts "
        "on it. So constant velocity and zero resultant force always go together.")


#: Notes, Newton's third law: "if body A exerts a force on body B, then B exerts a force on A
#: that is equal in size and opposite in direction"; How to get the marks: "Newton's third law
#: needs 'equal and opposite' and 'on different bodies'". The pair is also "the same type of
#: force", which the model answer says; no mark needs it (9702/21/M/J/15 Q3(c) marks "force on X
#: is equal and opposite to force on Y"; issue 37).
THIRD_LAW_POINTS = rules.THIRD_LAW_POINTS


def state_third_law() -> Question:
    """State Newton's third law [2]: a B1 for the pair on different bodies and a B1 for equal and
    opposite ("the same type of force" is true, in the model answer, but earns no mark and no
    mark needs it). 9702/21/M/J/15 Q3(c): "force on X is equal and opposite to force
    on Y (Newton III)"; the notes' How to get the marks asks for both "equal and opposite" and "on
    different bodies"."""
    return _statement(
        "state-third-law", "State the law in words.",
        "State Newton's third law of motion.",
        THIRD_LAW_POINTS,
        "If body A exerts a force on body B, then body B exerts a force on body A that is equal in "
        "magnitude and opposite in direction. The two forces act on different bodies (so they never "
        "cancel), are the same type of force, and act for the same time.")


# ---------------------------------------------------------------- statements set in a situation

#: Notes, Momentum and Newton's second law: "the resultant force on an object is proportional to
#: its rate of change of momentum, and acts in the direction of that change".
SECOND_LAW_POINTS = rules.SECOND_LAW_POINTS

#: (situation, the body, what the law says there), each as a 9702 question sets the law before
#: using it: a ball bouncing off a floor (9702/21/M/J/16 Q3), a block dragged while its
#: momentum-time graph is drawn (9702/21/M/J/23 Q3), a hose, a car braking.
_SECOND_LAW_SITUATIONS = (
    (("A ball falls vertically onto a floor and bounces back up. It is in contact with the floor for "
     "a short time."),
     ("the resultant force on the ball during the contact is its change in momentum divided by the "
     "contact time, and it acts upwards, the direction of the change in momentum")),
    (("A block is dragged across a rough horizontal surface, and a graph shows how its momentum "
     "changes with time."),
     "the resultant force on the block at any time is the gradient of its momentum–time graph"),
    ("A hose sends out a steady horizontal jet of water.",
     ("the force on the water is the momentum the hose gives the water each second, in the direction "
     "of the jet")),
    ("A car brakes on a straight road and comes to rest.",
     ("the resultant force on the car is its change in momentum divided by the time taken to stop, "
     "and it acts backwards, the direction of the change in momentum")),
    (("A tennis racket hits a ball, which leaves the racket faster than it arrived and in the "
     "opposite direction."),
     ("the resultant force on the ball is its change in momentum divided by the contact time, in the "
     "direction the ball leaves the racket")),
)


def state_second_law(situation: float = 0) -> Question:
    """State Newton's second law in terms of momentum [1]. 9702/21/M/J/16 Q3(b)(i): "(resultant)
    force proportional/equal to rate of change of momentum B1 [1]"; 9702/21/M/J/23 Q3(a) (the same
    question, [1]). The direction is in the model answer: the schemes give the one B1."""
    what, applied = _SECOND_LAW_SITUATIONS[int(situation)]
    return _statement(
        "state-second-law", what,
        "State Newton's second law of motion in terms of momentum.",
        SECOND_LAW_POINTS,
        "The resultant force on a body is proportional to the rate of change of momentum of the body, "
        f"and acts in the direction of the change in momentum. Here, {applied}.")


#: (situation, the system, what the principle says there). Notes, Conservation of momentum: "the
#: total momentum of a system of objects stays constant, provided no resultant external force acts
#: on the system (an isolated system)"; explosions, recoil of a gun and of a nucleus.
_CONSERVATION_SITUATIONS = (
    ("Two trolleys roll towards each other on a straight, level track, collide and stick together.",
     "the two trolleys",
     "their total momentum just before the collision equals their total momentum just after it"),
    (("Two trolleys at rest on a level track are pushed apart by a compressed spring released between "
     "them."),
     "the two trolleys and the spring",
     ("their total momentum is zero before the spring is released, so it is zero after: the trolleys "
     "move off in opposite directions with equal and opposite momenta")),
    ("A rifle at rest fires a bullet horizontally.",
     "the rifle and the bullet",
     ("their total momentum is zero before the shot, so the rifle recoils with momentum equal and "
     "opposite to the bullet's")),
    ("A nucleus at rest emits an α-particle.",
     "the nucleus and the α-particle",
     ("their total momentum is zero before the emission, so the nucleus recoils in the opposite "
     "direction to the α-particle")),
    (("A puck slides across a frictionless air table and hits a second puck, which is at rest; the "
     "pucks move off at angles to the first puck's path."),
     "the two pucks",
     ("their total momentum is the same before and after the collision in each of two directions at "
     "right angles")),
)


_conservation_points = rules.conservation_points


def state_momentum_conservation(situation: float = 0) -> Question:
    """State the principle of conservation of momentum [2], applied to a collision, an explosion, a
    recoil. Marked M1 A1 as the most recent schemes mark it, 9702/22/F/M/26 and 9702/23/M/J/25
    (CLARIFICATIONS, Papers): "total momentum (of a system) constant" M1, "isolated system" or "no
    external force" A1. The older 9702/23/M/J/13 Q3(a)(i) gave B1 B1 ("remains constant B1 provided
    there are no resultant external forces / isolated system B1"); 9702/21/M/J/24 Q3(a) asks the
    same [2]. The notes' common mistake: "'Momentum before = momentum
    after' earns only part of the marks"."""
    what, system, applied = _CONSERVATION_SITUATIONS[int(situation)]
    return _statement(
        "state-momentum-conservation", what,
        f"State the principle of conservation of momentum, as it applies to {system}.",
        _conservation_points(system),
        "The total momentum of a system stays constant, provided no resultant external force acts on "
        f"it (an isolated system). Here the system is {system}: {applied}.")


#: (situation, the bodies). Notes, Elastic and inelastic collisions: "Elastic collision: the total
#: kinetic energy is conserved. It's also true that the relative speed of approach equals the
#: relative speed of separation."
_ELASTIC_SITUATIONS = (
    ("Two gliders move towards each other on a level air track, collide and move apart.", "the gliders"),
    ("A snooker ball hits a second snooker ball, at rest, head-on.", "the two snooker balls"),
    ("Two steel balls hang side by side on threads. One is pulled aside, released, and hits the other.",
     "the two steel balls"),
    ("Two ice-hockey pucks slide towards each other on smooth ice and collide head-on.", "the two pucks"),
)


_elastic_points = rules.elastic_points


def state_elastic_collision(situation: float = 0) -> Question:
    """State what is meant by an elastic collision [2]. 9702/23/M/J/13 Q3(a)(ii): "elastic: total
    kinetic energy is conserved"; 9702/21/M/J/15 Q3(b) marks the relative speeds as the same test
    ("total initial kinetic energy not equal to the total final kinetic energy or relative speed of
    approach is not equal to relative speed of separation, so not elastic"); the syllabus, 3.3.3,
    asks students to recall both."""
    what, bodies = _ELASTIC_SITUATIONS[int(situation)]
    return _statement(
        "state-elastic-collision", what,
        f"State what is meant by an elastic collision, and how the relative speeds of {bodies} before "
        "and after an elastic collision compare.",
        _elastic_points(bodies),
        f"In an elastic collision the total kinetic energy of {bodies} is conserved: it is the same "
        "after the collision as before. The relative speed of approach equals the relative speed of "
        "separation. (Momentum is conserved in every collision of an isolated system; an elastic one "
        "keeps the kinetic energy too.)")


#: (situation, the body, the forces that balance). Notes, Friction, drag and terminal velocity:
#: "the drag has grown to equal the weight. The resultant force is zero, so the acceleration is
#: zero"; "In a liquid ... At terminal velocity: weight = drag + upthrust"; common mistake: "at
#: terminal velocity say the resultant force is zero, not that 'the forces are balanced' without
#: naming them".
_TERMINAL_SITUATIONS = (
    ("A skydiver falls vertically through the air before opening her parachute.", "the skydiver",
     "the air resistance (drag) on her equals her weight"),
    ("A small steel ball is released in a tall tube of oil and falls through it.", "the ball",
     "the drag on the ball plus the upthrust from the oil equals the ball's weight"),
    ("A raindrop falls vertically through still air.", "the raindrop",
     "the air resistance (drag) on the raindrop equals its weight"),
    ("A parachutist's parachute opens, and she slows down while still falling.", "the parachutist",
     "the drag, now at a lower speed because of the parachute's large area, equals her weight again"),
)


_terminal_points = rules.terminal_points


def state_terminal_velocity(situation: float = 0) -> Question:
    """State what is meant by terminal velocity, and the condition for it [2]: a B1 for constant
    velocity with zero resultant force, a B1 for the forces that balance, named. The notes (above)
    and the 9702 syllabus, 3.2.3 ("objects moving against a resistive force may reach a terminal
    (constant) velocity"); no published 9702 scheme for this wording was found in the search
    corpus, so the points are marked as recalled facts, B1 each (9702/22/M/J/20, mark
    categories)."""
    what, body, balance = _TERMINAL_SITUATIONS[int(situation)]
    return _statement(
        "state-terminal-velocity", what,
        f"State what is meant by terminal velocity, and state the condition for {body} to reach it.",
        _terminal_points(body, balance, in_liquid="upthrust" in balance),
        f"Terminal velocity is the constant velocity {body} reaches when the resultant force is zero, "
        f"so the acceleration is zero. That happens when {balance}: the drag grows with speed until it "
        "does.")


def _situations(situations: tuple) -> dict[str, Draw]:
    """A statement's one given: which situation it is set in (every one is a variant)."""
    return {"situation": Draw(0, 0, len(situations) - 1, 1)}


TEMPLATES = checked_givens(
    Template("define-momentum", "definitions", ("text",), "Define momentum", define_momentum,
             one_wording=_ONE_DEFINITION),
    Template("define-force", "definitions", ("text",), "Define force", define_force,
             one_wording=_ONE_DEFINITION),
    Template("mass-and-weight-defined", "definitions", ("text",), "Mass and weight defined",
             mass_and_weight_defined, one_wording=_ONE_DEFINITION),
    Template("define-the-newton", "definitions", ("text",), "Define the newton", define_the_newton,
             one_wording=_ONE_DEFINITION),
    Template("state-first-law", "newton", ("text",), "Newton's first law", state_first_law,
             one_wording=_ONE_LAW),
    Template("state-third-law", "newton", ("text",), "Newton's third law", state_third_law,
             one_wording=_ONE_LAW),
    Template("state-second-law", "force-momentum", ("text",), "Newton's second law", state_second_law,
             _situations(_SECOND_LAW_SITUATIONS),
             variant_count=len(_SECOND_LAW_SITUATIONS)),
    Template("state-momentum-conservation", "momentum-line", ("text",), "The conservation principle",
             state_momentum_conservation, _situations(_CONSERVATION_SITUATIONS),
             variant_count=len(_CONSERVATION_SITUATIONS)),
    Template("state-elastic-collision", "elastic", ("text",), "What is an elastic collision?",
             state_elastic_collision, _situations(_ELASTIC_SITUATIONS),
             variant_count=len(_ELASTIC_SITUATIONS)),
    Template("state-terminal-velocity", "drag", ("text",), "What is terminal velocity?",
             state_terminal_velocity, _situations(_TERMINAL_SITUATIONS),
             variant_count=len(_TERMINAL_SITUATIONS)),
)
