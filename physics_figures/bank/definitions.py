# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Definitions, units and the difference between mass and weight."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH, G_MOON
from ..models import kinetic_energy, mass_from_weight, momentum, weight
from ..notation import format_number as n
from ..notation import round_number
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
)
from ..variants import Draw, Template
from ._common import N_S, PER_S, PER_S2
from .givens import checked_givens

a_answer, g_symbol = sympy.symbols("a g_earth")


def backpack_on_the_moon(mass: float = 12.0) -> Question:
    """Notes, Quick check 5: 12 kg backpack on the Moon -> mass 12 kg, weight 19.4 N."""
    moon_weight = weight(mass, g=G_MOON)
    m, g_moon = n(mass, 2), n(G_MOON, 3)
    return Question(
        key="quick-check-5",
        text=(f"An astronaut's backpack has a mass of {m} kg. (a) State its mass on the Moon and "
              f"(b) calculate its weight there (g = {g_moon} {PER_S2})."),
        givens=(Given("mass", mass, "kg", 2), Given("g on the Moon", G_MOON, "m s^-2", 3)),
        parts=(
            Part("mass on the Moon", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="Mass is the property that resists a change in motion: it is the same "
                         "everywhere.",
                 mistakes=(
                     Mistake("mass scaled with g", mass * G_MOON / G_EARTH,
                             "Mass doesn't change with g: it is the same on the Moon. Only the "
                             "weight changes.", see="weight"),
                     Mistake("mass divided by g", mass / G_MOON,
                             f"Mass doesn't depend on g at all: the backpack's mass is still {m} kg."),
                 ), see="first-law"),
            Part("weight on the Moon", moon_weight, "N", "weight", shown_sig_figs=3,
                 # the weight from the student's own mass in (a), wrong or not (issue 37)
                 ecf=Ecf(a_answer * sympy.Symbol("g_moon"), {"g_moon": G_MOON}),
                 revisit="Weight = mass × gravitational field strength, W = mg, with the Moon's g.",
                 mistakes=(
                     Mistake("used the Earth's g", weight(mass),
                             f"You used g on the Earth ({n(G_EARTH, 3)}). On the Moon g = {g_moon} m s⁻²."),
                     Mistake("mass given as weight", mass,
                             f"{m} is the mass in kg. Weight is a force: W = mg."),
                     Mistake("divided by g", mass / G_MOON,
                             "You divided by g. Weight = mass × g."),
                 ), see="weight"),
        ),
        mark_scheme=(
            Mark(f"Mass = {m} kg (it doesn't change)", "B1", "a"),
            Mark(f"Weight = mg = {m} × {g_moon}", "C1", "b"),
            Mark(f"= {n(moon_weight, 3)} N", "A1", "b"),
        ),
    )


def tennis_ball(grams: float = 57.0, speed: float = 50.0) -> Question:
    """A mass given in g: momentum of a 57 g ball served at 50 m s^-1."""
    mass = grams / 1000
    p = momentum(mass, speed)
    g, v, kg = n(grams, 2), n(speed, 2), n(mass, 2)
    return Question(
        key="practice-tennis-ball",
        text=f"A tennis ball of mass {g} g is served at {v} {PER_S}. Calculate the momentum of the ball.",
        givens=(Given("mass", grams, "g", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part("momentum of the ball", p, "N s", "momentum", units=N_S, shown_sig_figs=2,
                 revisit="Momentum = mass × velocity, with the mass in kg.",
                 mistakes=(
                     Mistake("mass left in grams", grams * speed,
                             f"You used the mass in g. Convert to kg first: {g} g = {kg} kg.", kind="slip"),
                     Mistake("kinetic energy instead of momentum", kinetic_energy(mass, speed),
                             "That is the kinetic energy, ½mv², in J. Momentum is mv, in N s.", unit="J", see="kinetic-energy"),
                     Mistake("mass divided by speed", mass / speed,
                             "You divided the mass by the speed. Momentum is mass × velocity."),
                 ), see="momentum"),
        ),
        mark_scheme=(
            Mark(f"m = {g} g = {kg} kg, so p = mv = {kg} × {v}", "C1"),
            Mark(f"= {n(p, 2)} N s", "A1"),
        ),
    )


def rock_from_mars(mars_weight: float = 5.4, g_mars: float = 3.7) -> Question:
    """Mass and weight on another planet: mass stays, weight scales with g."""
    mass = mass_from_weight(mars_weight, g=g_mars)
    earth_weight = weight(mass)
    w_mars, g_m, g_e = n(mars_weight, 2), n(g_mars, 2), n(G_EARTH, 3)
    # Rounding the mass to 2 s.f. before W = mg changes the answer: say so where it does.
    rounded = weight(float(round_number(mass, 2)))
    warning = (f" (the unrounded mass; the mass rounded to {n(mass, 2)} kg would give {n(rounded, 3)} N)"
               if n(rounded, 3) != n(earth_weight, 3) else "")
    return Question(
        key="practice-mars-rock",
        text=(f"A rock sample weighs {w_mars} N on Mars, where g = {g_m} {PER_S2}. Calculate (a) its mass, "
              "and (b) its weight on the Earth."),
        givens=(Given("weight on Mars", mars_weight, "N", 2), Given("g on Mars", g_mars, "m s^-2", 2)),
        parts=(
            Part("mass of the rock", mass, "kg", "mass", shown_sig_figs=2,
                 revisit="W = mg, so m = W / g, with the g where the weight was measured.",
                 mistakes=(
                     Mistake("multiplied by g", mars_weight * g_mars,
                             "You multiplied by g. W = mg, so m = W / g."),
                     Mistake("used the Earth's g", mass_from_weight(mars_weight),
                             f"You used the Earth's g. The {w_mars} N was measured on Mars, so divide "
                             f"by {g_m}."),
                 ), see="weight"),
            Part("weight of the rock on the Earth", earth_weight, "N", "weight", shown_sig_figs=3,
                 working=(Step("mass", mass, "kg"),), answer_from=lambda m: weight(m),
                 answer_for_g=lambda g: weight(mass, g=g),
                 ecf=Ecf(a_answer * g_symbol, {"g_earth": G_EARTH}),
                 revisit=f"The mass is the same on the Earth; W = mg with g = {g_e} m s⁻².",
                 mistakes=(
                     Mistake("weight unchanged", mars_weight,
                             "Weight depends on g, so it changes from Mars to the Earth. The mass is "
                             "what stays the same."),
                     Mistake("mass given as weight", mass,
                             "That is the mass in kg. Weight is a force: W = mg."),
                 ), see="weight"),
        ),
        mark_scheme=(
            Mark(f"m = W / g = {w_mars} / {g_m}", "C1", "a"),
            Mark(f"= {n(mass, 2)} kg (the same everywhere)", "A1", "a"),
            Mark(f"On the Earth W = mg = {n(mass, 4)} × {g_e}{warning}", "C1", "b"),
            Mark(f"= {n(earth_weight, 3)} N", "A1", "b"),
        ),
    )


#: "Which statement is correct?" on mass, weight and their units: (situation, question, the right
#: statement, three named misconceptions). Notes, Mass, weight and the definitions: mass is a
#: scalar, the same everywhere; weight is the force of a gravitational field, W = mg; watch for
#: mass given a direction, weight described as resisting motion, mass treated as changing with g.
_MASS_CHANGES = ("mass treated as changing with g",
                 ("Mass is the property that resists a change in motion: it is the same everywhere. "
                 "Only the weight, W = mg, changes with g."))
_SWAPPED = ("mass and weight swapped",
            "It is the weight that depends on g (W = mg). The mass stays the same wherever the object is.")
_WEIGHT_FIXED = ("weight taken as fixed, like the mass",
                 ("Weight is the force of a gravitational field on a mass, W = mg: where g is different, "
                 "so is the weight, even though the mass is the same."))
_MASS_WEIGHT = (
    (f"An astronaut travels from the Earth to the Moon, where g = {n(G_MOON, 3)} {PER_S2}.",
     "Which statement about her mass and her weight on the Moon is correct?",
     "Her mass is the same as on the Earth, and her weight is smaller.",
     (("Her mass and her weight are both smaller than on the Earth.", *_MASS_CHANGES),
      ("Her mass is smaller than on the Earth, and her weight is the same.", *_SWAPPED),
      ("Her mass and her weight are both the same as on the Earth.", *_WEIGHT_FIXED))),
    (("A rock sample is brought back to the Earth from Mars, where the gravitational field strength "
     "is less than half that on the Earth."),
     "Which statement about the rock on the Earth, compared with on Mars, is correct?",
     "Its mass is the same, and its weight is larger.",
     (("Its mass and its weight are both larger.", *_MASS_CHANGES),
      ("Its mass and its weight are both the same.", *_WEIGHT_FIXED),
      ("Its mass is larger, and its weight is the same.", *_SWAPPED))),
    (("A space probe lands on a planet where the gravitational field strength is twice that on the "
     "Earth."),
     "Which statement about the probe on that planet, compared with on the Earth, is correct?",
     "Its mass is the same, and its weight is twice as large.",
     (("Its mass is the same, and its weight is half as large.", "weight taken as m / g",
       "Weight = mass × gravitational field strength, W = mg: a stronger field gives a larger weight."),
      ("Its mass and its weight are both twice as large.", *_MASS_CHANGES),
      ("Its mass is twice as large, and its weight is the same.", *_SWAPPED))),
    ("Mass and weight are often confused.",
     "Which statement about mass and weight is correct?",
     "Mass is a scalar; weight is a vector, the force of a gravitational field on a mass.",
     (("Mass is a vector: it acts downwards, in the direction of the weight.", "mass given a direction",
       ("Mass has a size only: it is a scalar. Weight, a force, has a direction (towards the centre "
       "of the planet).")),
      ("Weight is the property of an object that resists a change in its motion.",
       "weight described as resisting motion",
       "That describes mass. Weight is the force on a mass due to a gravitational field, W = mg."),
      ("Mass is measured in newtons and weight in kilograms.", "units of mass and weight swapped",
       "Mass is measured in kg; weight is a force, measured in N."))),
    ("Force is defined as the rate of change of momentum.",
     "What are the SI base units of force?",
     "kg m s<sup>−2</sup>",
     (("kg m s<sup>−1</sup>", "units of momentum",
       ("kg m s⁻¹ is the unit of momentum. Force is momentum ÷ time: kg m s⁻¹ ÷ s = kg m s⁻²."), "momentum"),
      ("N", "the newton taken as a base unit",
       "The newton is a derived unit. The SI base units are kg, m and s: 1 N = 1 kg m s⁻²."),
      ("kg m<sup>2</sup> s<sup>−2</sup>", "units of energy",
       ("kg m² s⁻² is the joule, force × distance. Force = mass × acceleration: kg × m s⁻².")))),
    ("A rocket carrying an astronaut accelerates upwards just after lift-off.",
     "Which statement about the astronaut's weight (the gravitational force on her) is correct?",
     "It is the same as before lift-off, mg.",
     (("It is larger than before lift-off, because the rocket accelerates upwards.",
       "weight confused with the contact force",
       ("The seat pushes up on her harder (the contact force is m(g + a)), but the gravitational force, "
       "mg, does not depend on how the rocket accelerates."), "lift"),
      ("It is zero, because she is no longer on the ground.", "no weight off the ground",
       "The Earth's gravitational field still acts on her, so her weight is still mg."),
      ("It is smaller than before lift-off, because the rocket pushes her upwards.",
       "weight reduced by the upward push",
       "The push of the seat is a separate force, the contact force. Her weight, mg, is unchanged.", "lift"))),
)


def mass_weight_choice(situation: float = 0) -> Question:
    """Paper 1 style, conceptual: mass and weight, and their units (notes, "Which statement is
    correct?"). The wrong options are the notes' misconceptions; the key's letter moves."""
    index = int(situation)
    what, prompt, right, wrong = _MASS_WEIGHT[index]
    place = index % len(OPTION_LETTERS)
    rows = [Option(*row) for row in wrong]  # (text, mistake, feedback), and a section where not the part's
    rows.insert(place, Option(right))
    return Question(
        key="mass-weight-choice",
        text=what,
        givens=(),
        parts=(ChoicePart(prompt, tuple(rows), OPTION_LETTERS[place],
                          revisit="Mass (kg, a scalar) resists a change in motion and is the same "
                                  "everywhere; weight (N, a vector) is the force of a gravitational "
                                  "field on a mass, W = mg.", see="weight"),),
        mark_scheme=(Mark(f"{OPTION_LETTERS[place]}: {right}", "B1"),),
    )


#: Explain mass and weight: (situation, what to explain, the mass point, the conclusion, the model
#: answer's ending). Notes: mass resists a change in motion and is the same everywhere; weight is
#: the force of a gravitational field, W = mg.
_MASS_POINT = ("Mass is the property of an object that resists a change in its motion (its amount of "
               "matter): it does not depend on where the object is")
_WEIGHT_POINT = ("Weight is the force on a mass due to a gravitational field: W = mg, so it depends on "
                 "the gravitational field strength g")
_EXPLAIN_MASS_WEIGHT = (
    (f"An astronaut stands on the Moon, where g = {n(G_MOON, 3)} {PER_S2}.",
     "Explain why her mass on the Moon is the same as on the Earth, but her weight is not.",
     _MASS_POINT,
     (f"The Moon's g ({n(G_MOON, 3)} {PER_S2}) is smaller than the Earth's ({n(G_EARTH, 3)} {PER_S2}), "
     "so her weight is smaller on the Moon, while her mass is the same")),
    (("A rock sample is brought back to the Earth from Mars, where the gravitational field strength "
     "is less than half that on the Earth."),
     "Explain why the rock's weight on the Earth is larger than on Mars, although its mass is the same.",
     _MASS_POINT,
     (f"The Earth's g ({n(G_EARTH, 3)} {PER_S2}) is larger than that on Mars, so the same mass has a larger "
     "weight on the Earth")),
    (("On the Moon, a bag of flour is measured with a beam balance, which compares it with standard "
     "masses, and with a spring balance, which measures the force pulling down on it."),
     ("Explain why the beam balance gives the same reading as on the Earth, but the spring balance "
     "gives a smaller reading."),
     ("The beam balance compares the flour with standard masses in the same gravitational field, so it "
     "measures mass, which does not change from the Earth to the Moon"),
     ("The Moon's g is smaller than the Earth's, so the weight of the flour, and the spring balance's "
     "reading, are smaller; the beam balance's reading (the mass) is the same")),
    ("An astronaut in a spacecraft far from any planet or star pushes a heavy toolbox across the cabin.",
     ("Explain why the toolbox has almost no weight there, but she still needs a large force to start "
     "it moving quickly."),
     _MASS_POINT + ", so the toolbox keeps its large mass, and F = ma needs a large force for a large "
     "acceleration",
     ("Far from any planet or star the gravitational field strength g is almost zero, so the weight is "
     "almost zero, but the mass, and so the force needed to accelerate it, is unchanged")),
)


def mass_weight_explained(situation: float = 0) -> Question:
    """Describe and explain: why mass stays the same but weight changes with g (notes, Weight:
    "Mass stays the same; weight depends on where you are")."""
    what, prompt, mass_point, conclusion = _EXPLAIN_MASS_WEIGHT[int(situation)]
    return Question(
        key="mass-weight-explained",
        text=what,
        givens=(),
        parts=(ExplainPart(prompt, f"{mass_point}. {_WEIGHT_POINT}. {conclusion}."),),
        mark_scheme=(
            Mark(mass_point, "B1", "a"),
            Mark(_WEIGHT_POINT, "M1", "a"),
            Mark(conclusion, "A1", "a"),
        ),
    )


TEMPLATES = checked_givens(
    Template("quick-check-5", "definitions", ("numeric",), "Quick check 5", backpack_on_the_moon,
             {"mass": Draw(12.0, 5.0, 40.0, 1.0)}),
    Template("practice-tennis-ball", "definitions", ("numeric",), "Tennis ball", tennis_ball,
             {"grams": Draw(57.0, 54.0, 60.0, 1.0), "speed": Draw(50.0, 30.0, 70.0, 1.0)}),
    Template("practice-mars-rock", "definitions", ("numeric",), "Rock from Mars", rock_from_mars,
             {"mars_weight": Draw(5.4, 2.0, 9.0, 0.1)}),
    Template("mass-weight-choice", "definitions", ("mcq",), "Mass or weight?", mass_weight_choice,
             {"situation": Draw(0, 0, len(_MASS_WEIGHT) - 1, 1)}, variant_count=len(_MASS_WEIGHT)),
    Template("mass-weight-explained", "definitions", ("explain",), "Same mass, different weight",
             mass_weight_explained, {"situation": Draw(0, 0, len(_EXPLAIN_MASS_WEIGHT) - 1, 1)},
             variant_count=len(_EXPLAIN_MASS_WEIGHT)),
)
