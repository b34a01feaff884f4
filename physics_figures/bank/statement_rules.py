# ruff: noqa: RUF001, RUF002  (question text is typeset: true minus, times, en dash)
"""The marking points of the define and state templates (physics_figures/bank/statements.py), as
rules a teacher reads in the key: the wordings an examiner accepts and those the schemes reject,
each with the published 9702 scheme it comes from (the rule syntax: physics_figures/parts/text.py).

Where no published scheme for a wording was found in the search corpus, the rule says so and
cites the syllabus (9702 syllabus 2025–2027) and the notes (../shared/notes) it follows instead.

The schemes' general rule for a contradiction (a right and a wrong answer given together earn
nothing) is the marking principles printed in every 9702 scheme since 2019 (e.g. 9702/22/F/M/22,
"Science-specific marking principles"): a ``Note`` with ``contradicts=True``.
"""

from __future__ import annotations

from ..parts.text import Note, TextPoint

_SYLLABUS_MOMENTUM = "9702 syllabus 2025–2027, 3.1.3: “the product of mass and velocity”"
_SYLLABUS_FORCE = "9702 syllabus 2025–2027, 3.1.4: “force as rate of change of momentum”"
_PRINCIPLES = "9702/22/F/M/22, science-specific marking principles (a contradiction loses the mark)"
_NOTES_MISTAKES = "the notes' Common mistakes (no published scheme found for this wording)"

# ------------------------------------------------------------------ define momentum

MOMENTUM_PRODUCT = TextPoint(
    "Momentum is the product of mass and velocity (p = mv)", "B1",
    accept=("mass ×|product velocity",),
    source=_SYLLABUS_MOMENTUM,
    reject=(Note("mass ×|product speed", "speed is a scalar: momentum is mass × velocity", _SYLLABUS_MOMENTUM,
                 contradicts=True),
            Note("mass ×|product acceleration", "mass × acceleration is the resultant force, not momentum",
                 _SYLLABUS_MOMENTUM, contradicts=True)),
)
MOMENTUM_VECTOR = TextPoint(
    "It is a vector, in the direction of the velocity", "B1",
    accept=("vector", "magnitude direction", "direction velocity"),
    source="8702/02/O/N/01 Q1 (scalar or vector, B1; no 9702 scheme for “define momentum” found)",
    reject=(Note("momentum>scalar", "momentum has a direction: it is a vector",
                 "8702/02/O/N/01 Q1", contradicts=True),),
)
MOMENTUM_POINTS = (MOMENTUM_PRODUCT, MOMENTUM_VECTOR)

# ------------------------------------------------------------------ define force

_RATE_OF_MOMENTUM = ("rate δ momentum", "δ momentum /|rate time", "momentum /|rate δ time")
FORCE_POINTS = (TextPoint(
    "Force is the rate of change of momentum", "B1",
    accept=_RATE_OF_MOMENTUM,
    source=f"9702/21/M/J/16 Q3(b)(i) (“rate of change of momentum” B1); {_SYLLABUS_FORCE}",
    reject=(Note("force mass acceleration", "F = ma is how a resultant force is worked out for a "
                 "constant mass, not the definition", f"{_SYLLABUS_FORCE}; {_NOTES_MISTAKES}"),
            Note("force δ momentum", "a change in momentum alone is the impulse: the rate (per unit time) is "
                 "the point", "9702/21/M/J/16 Q3(b)(i)")),
),)

# ------------------------------------------------------------------ mass and weight (8702/02/O/N/01 Q1)

_MASS_WEIGHT = "8702/02/O/N/01 Q1"
MASS_WEIGHT_POINTS = (
    TextPoint("Mass is the property of an object that resists a change in its motion", "B1",
              accept=("mass>property|resist|resists|resistance|opposes resist|resists|resistance|opposes δ motion|velocity",
                      "mass>resist|resists|resistance|opposes acceleration|accelerate|accelerating|accelerated"),
              source=f"{_MASS_WEIGHT}: “property of body which resists change in motion” B1",
              reject=(Note("weight_property|weight_resists|weight_resist|weight_opposes", "resisting a change "
                           "in motion is mass, not weight", _PRINCIPLES, contradicts=True),
                      Note("mass amount|quantity matter|substance", "the scheme's point is the property that "
                           "resists change in motion", _MASS_WEIGHT))),
    TextPoint("Either: mass is a scalar; or: mass is the same wherever the object is (constant)", "B1",
              accept=("mass>scalar|constant|same|invariant", "mass>not_δ|not_vary|never_δ"),
              source=f"{_MASS_WEIGHT}: “constant OR scalar quantity” B1",
              reject=(Note("mass>vector", "mass has no direction: it is a scalar", _PRINCIPLES, contradicts=True),
                      Note("mass>δ|varies|depends|variable g|gravity|place|planet|moon",
                           "mass is the same wherever the object is; weight changes", _PRINCIPLES,
                           contradicts=True))),
    TextPoint("Weight is the force on a mass due to a gravitational field, W = mg", "B1",
              accept=("weight>force|pull|effect|gravitational gravity|gravitational|gravitation|g", "weight>mg|mass_×_g"),
              source=f"{_MASS_WEIGHT}: “effect of gravitational field on a mass/body” B1",
              reject=(Note("weight_property|weight_resists|weight_resist|weight_opposes", "resisting a change "
                           "in motion is mass, not weight", _PRINCIPLES, contradicts=True),
                      Note("mass_pull|mass_force|mass_gravitational", "the pull of gravity is weight, "
                           "not mass", _PRINCIPLES, contradicts=True))),
    TextPoint(("Either: weight is a vector (towards the centre of the planet); or: weight changes where the "
               "gravitational field strength g changes (variable)"), "B1",
              accept=("weight>vector",
                      ("weight>δ|varies|variable|depends|differs|different|less|more "
                       "weight>g|gravity|gravitational|field|place|planet|moon|location|where|position|height")),
              source=f"{_MASS_WEIGHT}: “variable OR vector quantity” B1",
              reject=(Note("weight>scalar", "weight is a force, with a direction: a vector", _PRINCIPLES,
                           contradicts=True),
                      Note("weight>constant|same|never_δ", "weight changes "
                           "with g", _PRINCIPLES, contradicts=True))),
)

# ------------------------------------------------------------------ define the newton

NEWTON_POINTS = (TextPoint(
    "One newton is the force that gives a mass of 1 kg an acceleration of 1 m s<sup>−2</sup>", "B1",
    accept=("force 1 kg|mass acceleration|accelerate|accelerates|accelerating",),
    source=("the notes (“the constant is 1, which is how the newton is defined”); no published 9702 scheme "
            "for “define the newton” found"),
    reject=(Note("force kg velocity|speed", "an acceleration of 1 m s−2, not a velocity",
                 "the notes, Momentum and Newton's second law"),),
),)

# ------------------------------------------------------------------ Newton's first law

_FIRST_LAW = ("the 9702 Paper 2 schemes reprinted in a CIE topic booklet, Newton's laws of motion, mark "
              "scheme 1, Q1(a): “constant velocity unless acted on by a resultant force” B1")
_UNLESS = "unless|no|zero|until|0"
FIRST_LAW_POINTS = (TextPoint(
    "An object stays at rest, or keeps moving at constant velocity, unless a resultant force acts on it", "B1",
    accept=(f"constant|uniform|steady velocity {_UNLESS} resultant force",
            f"constant|uniform|steady speed|motion straight {_UNLESS} resultant force"),
    source=_FIRST_LAW,
    reject=(Note(f"constant|uniform|steady speed {_UNLESS} resultant force",
                 "a constant speed may change direction: the law keeps the velocity constant", _FIRST_LAW),
            Note(f"constant|uniform|steady velocity|speed|motion|rest {_UNLESS} force",
                 "the force must be the resultant (net, unbalanced) force", _FIRST_LAW)),
),)

# ------------------------------------------------------------------ Newton's third law

_THIRD_LAW = "9702/21/M/J/15 Q3(c): “force on X is equal and opposite to force on Y” (two bodies named)"
_NOTES_THIRD = "the notes, How to get the marks: “equal and opposite” and “on different bodies”"
THIRD_LAW_POINTS = (
    TextPoint(("If body A exerts a force on body B, then body B exerts a force on body A: the two forces act on "
               "different bodies"), "B1",
              accept=("different|separate|two|other|another body", "bodya bodyb", "each_other"),
              source=f"{_THIRD_LAW}; {_NOTES_THIRD}",
              reject=(Note("same_body", "a pair's two forces act on different bodies, never on one",
                           _NOTES_THIRD, contradicts=True),
                      Note("cancel|cancels|balance", "the two forces act on different bodies, so they never "
                           "cancel", _NOTES_THIRD, contradicts=True),
                      Note("action reaction", "“action and reaction” does not say the forces act on different "
                           "bodies", _NOTES_THIRD)),
              ignore=("“of the same type” earns no mark and none needs it (issue 37)",)),
    TextPoint("The two forces are equal and opposite: equal in magnitude and opposite in direction", "B1",
              accept=("= opposite", "same magnitude|size opposite"),
              source=_THIRD_LAW),
)

# ------------------------------------------------------------------ Newton's second law

_SECOND_LAW = ("9702/21/M/J/16 Q3(b)(i): “(resultant) force proportional/equal to rate of change of "
               "momentum” B1; 9702/21/M/J/23 Q3(a)")
SECOND_LAW_POINTS = (TextPoint(
    ("The resultant force on a body is proportional to (in SI units, equal to) the rate of change of momentum of "
     "the body"), "B1",
    accept=tuple(f"force proportional|= {w}" for w in _RATE_OF_MOMENTUM),
    source=_SECOND_LAW,
    reject=(Note("force proportional|= mass|acceleration", "asked in terms of momentum: F = ma holds only for a "
                 "constant mass", _SECOND_LAW),
            Note("force proportional|= δ momentum", "the rate of change (per unit time) of momentum, not the "
                 "change", _SECOND_LAW)),
),)

# ------------------------------------------------------------------ the conservation principle

#: CLARIFICATIONS (Papers): the most recent schemes mark it M1 A1 and accept "isolated system" or
#: "no external force" for the A1 (older schemes, 9702/23/M/J/13 Q3(a)(i), wanted "no resultant
#: external forces" as a B1 of its own).
_CONSERVATION = "9702/22/F/M/26 and 9702/23/M/J/25 (M1 A1)"


def conservation_points(system: str) -> tuple[TextPoint, TextPoint]:
    """The principle's M1 (total momentum constant) and its dependent A1 (the condition)."""
    return (
        TextPoint(f"The total momentum of a system (here {system}) stays constant", "M1",
                  accept=("total|sum momentum constant|same", "system momentum constant|same",
                          "total|sum momentum before = total|sum momentum after"),
                  source=f"{_CONSERVATION}; 9702/23/M/J/13 Q3(a)(i): “the total momentum of a system … "
                         "remains constant”",
                  reject=(Note("momentum before = after", "the total (sum of the bodies') momentum: each body's "
                               "own momentum changes", "9702/23/M/J/13 Q3(a)(i)"),
                          Note("momentum constant", "whose momentum? The total momentum of the system",
                               "9702/23/M/J/13 Q3(a)(i)"),
                          Note("total kinetic energy constant", "kinetic energy is not what this principle "
                               "conserves", "9702/23/M/J/13 Q3(a)(i)"))),
        TextPoint(f"provided no resultant external force acts on the system: {system} form an isolated system",
                  "A1",
                  accept=("isolated", "no|zero|0 external force", "external force zero|0"),
                  source=f"{_CONSERVATION}: “isolated system” or “no external force” accepted",
                  reject=(Note("no|zero resultant force", "internal forces act in every collision: the "
                               "condition is that no external force acts", _CONSERVATION),)),
    )


# ------------------------------------------------------------------ an elastic collision

_ELASTIC = "9702/23/M/J/13 Q3(a)(ii): “elastic: total kinetic energy is conserved”"
_RELATIVE = "9702/21/M/J/15 Q3(b): “relative speed of approach … relative speed of separation”"


def elastic_points(bodies: str) -> tuple[TextPoint, TextPoint]:
    return (
        TextPoint(f"The total kinetic energy of {bodies} is conserved: the same after the collision as before it",
                  "B1",
                  accept=("total|sum kinetic energy constant|same", "no|not kinetic energy lost|loss",
                          "total|sum kinetic energy before = total|sum kinetic energy after",
                          "total|sum kinetic energy before = after"),
                  source=_ELASTIC,
                  reject=(Note("kinetic energy constant|same", "the total kinetic energy: each body's own kinetic "
                               "energy changes", _ELASTIC),
                          Note("energy constant", "total energy is conserved in every collision: the point is "
                               "the kinetic energy", _ELASTIC),
                          Note("kinetic energy lost|decreases|reduced", "kinetic energy lost is an "
                               "inelastic collision", _PRINCIPLES, contradicts=True))),
        TextPoint("The relative speed of approach equals the relative speed of separation", "B1",
                  accept=("relative approach = separation",),
                  source=_RELATIVE,
                  reject=(Note("approach = separation", "the relative speeds (of one body to the other)",
                               _RELATIVE),)),
    )


# ------------------------------------------------------------------ terminal velocity

_TERMINAL = ("9702 syllabus 2025–2027, 3.2.3 (“a terminal (constant) velocity”); the notes, Friction, drag and "
             "terminal velocity; no published 9702 scheme for this wording found")
_CONSTANT = "constant|steady|uniform|maximum|terminal velocity|speed"


def terminal_points(body: str, balance: str, *, in_liquid: bool) -> tuple[TextPoint, TextPoint]:
    """Constant velocity with zero resultant force (B1), and the condition, the forces named (B1):
    in a liquid the upthrust is one of them."""
    named = (("drag|resistance|friction|viscous upthrust =|balances|balance weight",) if in_liquid
             else ("drag|resistance|friction =|balances|balance weight",))
    reject = [Note("forces balanced|balance|equal", "name the forces that balance (the notes: not “the forces "
                   "are balanced” without naming them)", _NOTES_MISTAKES)]
    if in_liquid:
        reject.insert(0, Note("drag|resistance|friction|viscous = weight", "in a liquid the upthrust acts too: "
                              "weight = drag + upthrust", _TERMINAL))
    return (
        TextPoint(f"Terminal velocity is the constant velocity {body} reaches when the resultant force is zero, so "
                  "the acceleration is zero", "B1",
                  accept=(f"{_CONSTANT} resultant|acceleration zero|no|0", f"{_CONSTANT} equilibrium"),
                  source=_TERMINAL,
                  reject=(Note("velocity|speed increases|increasing|accelerates resultant zero|no", "at terminal "
                               "velocity the velocity is constant", _TERMINAL, contradicts=True),)),
        TextPoint(f"The condition: {balance}", "B1", accept=named, source=_TERMINAL, reject=tuple(reject)),
    )
