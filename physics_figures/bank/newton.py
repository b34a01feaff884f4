# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Newton's laws, weight and the third law: F = ma, lifts, towing, action-reaction pairs."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH
from ..models import (
    acceleration,
    acceleration_from_distance,
    kinetic_energy,
    lift_contact_force,
    mass_from_weight,
    thrust_for_acceleration,
    towing,
    weight,
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
from ._common import M_S2, PER_S, PER_S2, enough_figures, stated_figures, w
from .givens import checked_givens

a_answer, trailer_mass_symbol, trailer_resistance_symbol = sympy.symbols("a trailer_mass trailer_resistance")
hanging_mass_symbol, gravity_symbol = sympy.symbols("hanging_mass gravity")
block_mass_symbol, friction_symbol, thrust_symbol, rocket_mass_symbol = sympy.symbols(
    "block_mass friction thrust rocket_mass")


def car_slowing(mass: float = 800.0, driving: float = 1500.0, resistive: float = 2300.0) -> Question:
    """F = ma with signs: resistive force bigger than the driving force."""
    if resistive <= driving:
        raise ValueError(f"resistive must exceed driving={driving!r} N, so the car slows down "
                         f"(got resistive={resistive!r})")
    resultant = driving - resistive
    a = acceleration(resultant, mass)
    m, d, r = n(mass, 2), n(driving, 2), n(resistive, 2)
    return Question(
        key="practice-car-slowing",
        text=(f"A car of mass {m} kg has a driving force of {d} N and a total resistive force of {r} N. "
              "Taking forwards as positive, calculate its acceleration."),
        givens=(Given("mass", mass, "kg", 2), Given("driving force", driving, "N", 2),
                Given("resistive force", resistive, "N", 2)),
        parts=(
            Part("acceleration of the car", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 direction="signed", positive="forwards",
                 revisit="Resultant force = forces forwards − forces backwards; a = F / m, "
                         "with its sign.",
                 mistakes=(
                     Mistake("forces added", acceleration(driving + resistive, mass),
                             "You added the two forces. They act in opposite directions: "
                             f"resultant = {d} − {r} N."),
                     Mistake("driving force only", acceleration(driving, mass),
                             "You used only the driving force. F = ma needs the resultant force."),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"Resultant force = {d} − {r} = {w(resultant)} N", "C1"),
            Mark(f"a = {w(resultant)} / {m} = {n(a, 2)} {PER_S2} (the car slows down)", "A1"),
        ),
    )


def lift_accelerating_down(mass: float = 58.0, a_down: float = 1.5) -> Question:
    """Contact force in a lift accelerating downwards: R = m(g - a)."""
    contact = lift_contact_force(mass, -a_down)
    m, a = n(mass, 2), n(a_down, 2)
    g = n(G_EARTH, 3)
    return Question(
        key="practice-lift",
        text=(f"A student of mass {m} kg stands in a lift that is accelerating downwards at {a} {PER_S2}. "
              "Calculate the contact force that the floor exerts on the student."),
        givens=(Given("mass", mass, "kg", 2), Given("acceleration", a_down, "m s^-2", 2)),
        parts=(
            Part("contact force from the floor", contact, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g_: lift_contact_force(mass, -a_down, g=g_),
                 revisit="Take up as positive: R − mg = ma, with a negative for a downward acceleration.",
                 mistakes=(
                     Mistake("g + a used", lift_contact_force(mass, a_down),
                             "You used m(g + a), which is for accelerating upwards. Accelerating "
                             "down, the floor pushes less: R = m(g − a)."),
                     Mistake("weight only", weight(mass),
                             "That is the weight, the contact force at steady speed. The lift "
                             "accelerates, so R − mg = ma.", see="lift"),
                     Mistake("resultant force given", mass * a_down,
                             "That is the resultant force, ma. The contact force is R = m(g − a).", see="lift"),
                 )),
        ),
        mark_scheme=(
            Mark(f"Up positive: R − mg = ma with a = −{a} {PER_S2}", "C1"),
            Mark(f"R = {m} × ({g} − {a}) = {n(contact, 3)} N", "A1"),
        ),
    )


def car_towing_trailer(car_mass: float = 1000.0, trailer_mass: float = 500.0, driving: float = 2400.0,
                       car_resistance: float = 300.0, trailer_resistance: float = 150.0) -> Question:
    """Connected bodies: the whole first, then one body on its own."""
    masses, resistive = (car_mass, trailer_mass), (car_resistance, trailer_resistance)
    if driving <= sum(resistive):
        raise ValueError(f"driving must exceed the resistive forces' total {sum(resistive)!r} N, so the car "
                         f"and trailer speed up (got driving={driving!r})")
    towed = towing(driving, masses, resistive)
    a, tension = towed.acceleration, towed.tensions[0]
    total = sum(masses)
    car, trailer, d = n(car_mass, 2), n(trailer_mass, 2), n(driving, 2)
    r_car, r_trailer = n(car_resistance, 2), n(trailer_resistance, 2)
    every_force = (f"Treating the car and trailer as one object, every external force counts: "
                   f"{d} − {r_car} − {r_trailer} N.")
    return Question(
        key="practice-towing",
        text=(f"A car of mass {car} kg tows a trailer of mass {trailer} kg along a straight, level road. "
              f"The driving force on the car is {d} N. The resistive force is {r_car} N on the car and "
              f"{r_trailer} N on the trailer. Calculate (a) the acceleration and (b) the tension in the "
              "tow bar."),
        givens=(Given("car mass", car_mass, "kg", 2), Given("trailer mass", trailer_mass, "kg", 2),
                Given("driving force", driving, "N", 2), Given("car resistance", car_resistance, "N", 2),
                Given("trailer resistance", trailer_resistance, "N", 2)),
        parts=(
            Part("acceleration", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 revisit="Treat the car and trailer as one object: external forces only, total mass.",
                 mistakes=(
                     Mistake("resistive forces left out", acceleration(driving, total),
                             f"You left out the resistive forces. Resultant = {d} − {r_car} − {r_trailer} N."),
                     Mistake("trailer's resistance left out", acceleration(driving - car_resistance, total),
                             f"You left out the {r_trailer} N resistive force on the trailer. {every_force}"),
                     Mistake("car's resistance left out", acceleration(driving - trailer_resistance, total),
                             f"You left out the {r_car} N resistive force on the car. {every_force}"),
                     Mistake("car's mass only", acceleration(driving - sum(resistive), car_mass),
                             "You used only the car's mass. The driving force accelerates the car "
                             f"and the trailer: use the total mass, {w(total)} kg."),
                 ), see="second-law"),
            Part("tension in the tow bar", tension, "N", "force", shown_sig_figs=2,
                 working=(Step("acceleration", a, "m s^-2", 2),),
                 answer_from=lambda acc: trailer_resistance + trailer_mass * acc,
                 ecf=Ecf(trailer_resistance_symbol + trailer_mass_symbol * a_answer,
                         {"trailer_resistance": trailer_resistance, "trailer_mass": trailer_mass}),
                 revisit="F = ma for the trailer alone: T − resistive force on the trailer = "
                         "trailer mass × a.",
                 mistakes=(
                     Mistake("trailer's resistance left out", trailer_mass * a,
                             "That is the trailer's resultant force, ma. The tension must also "
                             f"overcome the trailer's {r_trailer} N resistance: T − {r_trailer} = {trailer}a."),
                     Mistake("resistance subtracted", trailer_mass * a - trailer_resistance,
                             "The resistance acts backwards on the trailer, so the tension is "
                             f"bigger than ma: T = {trailer}a + {r_trailer}."),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"Whole: resultant = {d} − {r_car} − {r_trailer} = {w(towed.resultant_force)} N", "C1", "a"),
            Mark(f"a = {w(towed.resultant_force)} / {w(total)} = {n(a, 2)} {PER_S2}", "A1", "a"),
            Mark(f"Trailer alone: T − {r_trailer} = {trailer} × {w(a)}", "C1", "b"),
            Mark(f"T = {n(tension, 2)} N", "A1", "b"),
        ),
    )


#: Situations for "which is a third-law pair?": the situation, the key pair, and the three
#: misconceptions of the notes as options: (1) the weight and the force that supports the body
#: (normal reaction or tension), on the same body; (2) two other forces on one body; (3) two
#: forces that are equal, opposite and on different bodies, but of different types.
#: Each entry: (text, key, (weight-pair option, its body), (same-body option, its body), different-types option).
_PAIR_SITUATIONS = (
    ("A book rests on a horizontal table.",
     "the gravitational pull of the Earth on the book and the gravitational pull of the book on the Earth",
     ("the weight of the book and the upward contact force of the table on the book", "book"),
     ("the upward push of the floor on the table and the downward push of the book on the table", "table"),
     "the downward push of the book on the table and the upward gravitational pull of the book on the Earth"),
    ("A person stands on the floor of a lift that is moving upwards at a constant speed.",
     "the upward push of the lift floor on the person and the downward push of the person on the lift floor",
     ("the weight of the person and the upward push of the lift floor on the person", "person"),
     ("the upward pull of the cable on the lift and the weight of the lift", "lift"),
     ("the downward push of the person on the lift floor and the upward gravitational pull of the "
      "person on the Earth")),
    ("A car is driven at a constant velocity along a straight, level road.",
     "the forward push of the road on a tyre and the backward push of the tyre on the road",
     ("the weight of the car and the upward contact force of the road on the car", "car"),
     ("the forward push of the road on the tyres and the air resistance on the car", "car"),
     "the downward push of the car on the road and the upward gravitational pull of the car on the Earth"),
    ("An apple hangs at rest from a branch of a tree by its stalk.",
     "the gravitational pull of the Earth on the apple and the gravitational pull of the apple on the Earth",
     ("the weight of the apple and the upward pull of the stalk on the apple", "apple"),
     ("the upward pull of the branch on the stalk and the downward pull of the apple on the stalk", "stalk"),
     "the downward pull of the apple on the stalk and the upward gravitational pull of the apple on the Earth"),
    ("A student pushes a box at a constant velocity across a horizontal floor.",
     "the forward push of the student on the box and the backward push of the box on the student",
     ("the weight of the box and the upward contact force of the floor on the box", "box"),
     ("the forward push of the student on the box and the backward friction force of the floor on the box",
      "box"),
     "the downward push of the box on the floor and the upward gravitational pull of the box on the Earth"),
)


def third_law_pair_choice(situation: float = 0) -> Question:
    """Paper 1 style: which pair of forces is a Newton's third law pair? (notes, Newton's third
    law and "Wrong third-law pairs"). The wrong options are the named misconceptions."""
    index = int(situation)
    what, key, (weight_pair, weight_body), (same_body, body), other_types = _PAIR_SITUATIONS[index]
    rows = [
        Option(key),
        Option(weight_pair, "weight and normal reaction taken as a pair",
               f"These two forces both act on the {weight_body}, and they are of different types "
               "(one gravitational, one contact). They are equal only because the "
               f"{weight_body} is in equilibrium: that is Newton's first law, not the third. A "
               "third-law pair acts on two different bodies and is one type of force."),
        Option(same_body, "forces on the same body taken as a pair",
               f"Both forces act on the {body}. Forces on one body can balance, but the two forces "
               "of a third-law pair act on different bodies (X on Y and Y on X), so they never "
               "cancel."),
        Option(other_types, "equal and opposite forces of different types taken as a pair",
               "These act on different bodies and are equal and opposite, but one is a contact force "
               "and the other is gravitational. A third-law pair is one interaction between two "
               "bodies: X on Y and Y on X, the same type of force."),
    ]
    # Turn the options round so the key is not always A.
    shift = index % len(OPTION_LETTERS)
    options = tuple(rows[-shift:] + rows[:-shift]) if shift else tuple(rows)
    answer = OPTION_LETTERS[options.index(rows[0])]
    return Question(
        key="third-law-pair-choice",
        text=what,
        givens=(),
        parts=(ChoicePart("Which pair of forces is a Newton's third law pair?", options, answer,
                          revisit="The two forces of a third-law pair: X on Y and Y "
                                  "on X, the same type of force, equal and opposite, on "
                                  "different bodies.", see="third-law"),),
        mark_scheme=(Mark(f"{answer}: {key} (the same type of force, each body on the other)", "B1"),),
    )


def friction_acceleration_choice(crate_weight: float = 490.0, pull: float = 180.0,
                                 friction: float = 60.0) -> Question:
    """Paper 1 style: resultant force and acceleration with friction; the mass comes from a
    weight. Wrong options, three of a pool chosen so the key's letter moves: friction forgotten,
    forces added, the weight used as the mass, the mass worked out as W times g, the friction taken
    as the resultant force."""
    if pull <= friction:
        raise ValueError(f"pull must exceed friction={friction!r} N, so the crate speeds up "
                         f"(got pull={pull!r})")
    mass = mass_from_weight(crate_weight)
    key = acceleration(pull - friction, mass)
    wt, p, f = n(crate_weight, 2), n(pull, 2), n(friction, 2)
    options, answer = choices_in_order(key, {
        "friction left out": (
            acceleration(pull, mass),
            ("You used the pull as the resultant force. Friction acts backwards: the resultant "
             f"force is {p} − {f} N."), "friction"),
        "forces added": (
            acceleration(pull + friction, mass),
            ("You added the friction to the pull. Friction opposes the motion, so subtract it: "
             f"{p} − {f} N."), "friction"),
        "weight used as the mass": (
            acceleration(pull - friction, crate_weight),
            f"You divided by the weight, {wt} N. F = ma needs the mass: m = W / g = {wt} / {n(G_EARTH, 3)} kg."),
        "multiplied the weight by g": (
            acceleration(pull - friction, crate_weight * G_EARTH),
            f"You worked out the mass as W × g. Weight = mg, so the mass is m = W / g = {wt} / {n(G_EARTH, 3)} kg."),
        "friction used as the resultant force": (
            acceleration(friction, mass),
            ("You used the friction alone as the resultant force. The resultant force is the pull "
             f"minus the friction: {p} − {f} N."), "friction"),
    }, sig_figs=2, unit=PER_S2, seed=12)
    # the mass with the figures its division needs, so the working gives the printed answer
    (shown_mass,) = enough_figures([mass], lambda m: (pull - friction) / m, n(key, 2))
    return Question(
        key="friction-acceleration-choice",
        text=(f"A crate of weight {wt} N is pulled along a horizontal floor by a horizontal rope. The "
              f"tension in the rope is {p} N and the friction force on the crate is {f} N. "
              "Take g = 9.81 m s<sup>−2</sup>."),
        givens=(Given("weight", crate_weight, "N", 2), Given("pull", pull, "N", 2),
                Given("friction", friction, "N", 2)),
        parts=(ChoicePart("What is the acceleration of the crate?", options, answer,
                          revisit="Resultant force = forces forwards − forces backwards; mass = "
                                  "weight / g; a = resultant force / mass.", see="weight"),),
        mark_scheme=(Mark(f"{answer}: m = {wt} / {n(G_EARTH, 3)} = {shown_mass} kg; a = ({p} − {f}) / {shown_mass} "
                          f"= {n(key, 2)} {PER_S2}", "B1"),),
    )


#: How the lift moves, and so which way it accelerates (+1 up, -1 down): speeding up, the
#: acceleration is along the motion; slowing down, against it.
_LIFT_MOTIONS = (
    ("moving upwards and speeding up", 1.0),
    ("moving upwards and slowing down", -1.0),
    ("moving downwards and speeding up", -1.0),
    ("moving downwards and slowing down", 1.0),
)


def lift_cable_choice(mass: float = 1200.0, a_size: float = 1.5, motion: float = 1) -> Question:
    """Paper 1 style: the tension in a lift cable, T - mg = ma with a's sign from the motion
    (notes: rockets and lifts; "Mixing up the resultant force with one of the forces")."""
    how, sign = _LIFT_MOTIONS[int(motion)]
    lift_weight = weight(mass)
    key = thrust_for_acceleration(lift_weight, sign * a_size)
    up = sign > 0
    m, a = n(mass, 2), n(a_size, 2)
    which_way = "upwards" if up else "downwards"
    options, answer = choices_in_order(key, {
        "acceleration in the wrong direction": (
            thrust_for_acceleration(lift_weight, -sign * a_size),
            (f"The lift is {how}, so its acceleration is {which_way}: "
             f"T = m(g {'+' if up else '−'} a). Speeding up, a is along the motion; slowing down, "
            "against it."), "lift"),
        "weight only": (
            lift_weight,
            ("That is the weight, the tension at constant velocity. The lift accelerates, so "
             "T − mg = ma."), "lift"),
        "resultant force given": (
            abs(thrust_for_acceleration(lift_weight, sign * a_size) - lift_weight),
            ("That is the resultant force, ma. The tension also supports the weight: T = mg + ma, "
             "with a positive upwards."), "weight"),
        **({"weight used as the mass in ma": (
            lift_weight + sign * lift_weight * a_size,
            (f"You multiplied the weight, not the mass, by the acceleration. The resultant force is ma "
             f"with m = {m} kg: T = mg {'+' if up else '−'} ma."), "weight")}
           if lift_weight + sign * lift_weight * a_size > 0 else {}),
        "weight used as the mass": (
            lift_weight * (G_EARTH + sign * a_size),
            (f"You put the weight, {n(lift_weight, 3)} N, into T = m(g {'+' if up else '−'} a). The m there "
             f"is the mass, {m} kg."), "weight"),
        **({"mass used as the weight": (
            mass + sign * mass * a_size,
            (f"You used the mass, {m} kg, as the weight. The weight is mg = {m} × {n(G_EARTH, 3)} N: "
             f"T = mg {'+' if up else '−'} ma."), "weight")}
           if mass + sign * mass * a_size > 0 else {}),
    }, sig_figs=3, unit="N", seed=3)
    return Question(
        key="lift-cable-choice",
        text=(f"A lift of total mass {m} kg hangs from a single vertical cable. It is {how}, with an "
              f"acceleration of magnitude {a} {PER_S2}. Take g = 9.81 m s<sup>−2</sup>."),
        givens=(Given("mass", mass, "kg", 2), Given("acceleration", a_size, "m s^-2", 2)),
        parts=(ChoicePart("What is the tension in the cable?", options, answer,
                          revisit="Up positive: T − mg = ma. The acceleration points along the "
                                  "motion when speeding up and against it when slowing down."),),
        mark_scheme=(Mark(f"{answer}: acceleration {which_way}, so T = {m} × ({n(G_EARTH, 3)} {'+' if up else '−'} {a}) "
                          f"= {n(key, 3)} N", "B1"),),
    )


#: Vehicles at a constant velocity: what moves, what gives its driving force, and the
#: resistive forces on it (notes: Newton's first law, the car cruising at a steady speed).
_CRUISERS = (
    ("A car travels along a straight, level road at a constant velocity.", "the car", "the engine",
     "friction and air resistance"),
    ("A cyclist pedals along a straight, level road at a constant velocity.", "the cyclist",
     "the cyclist's pedalling", "air resistance and friction"),
    ("A ship sails in a straight line through calm water at a constant velocity.", "the ship",
     "the propeller", "the drag of the water and air resistance"),
    ("An aeroplane flies horizontally in a straight line at a constant velocity.", "the aeroplane",
     "the thrust of its engines", "air resistance"),
    ("A train travels along a straight, level track at a constant velocity.", "the train", "the motors",
     "friction and air resistance"),
)


def constant_velocity_explained(situation: float = 0) -> Question:
    """Describe and explain: why a driving force is still needed at constant velocity
    (notes: Newton's first law; balanced forces mean at rest or constant velocity). The model
    answer names the variant's body, its driving force and its resistive forces (issue 25)."""
    what, body, driver, resistive = _CRUISERS[int(situation)]
    return Question(
        key="constant-velocity-explained",
        text=f"{what} The driving force from {driver} acts on it all the time.",
        givens=(),
        parts=(ExplainPart(
            "Explain, using Newton's laws, why a driving force is still needed even though the "
            "velocity is constant.",
            f"Resistive forces ({resistive}) act on {body}, opposite to its motion. At a constant "
            "velocity the acceleration is zero, so by Newton's first (and second) law the resultant "
            f"force on {body} is zero. So the forward driving force from {driver} must be equal in size "
            "to the resistive forces, to cancel them. Without the driving force the resultant force "
            f"would be backwards, and {body} would slow down."),),
        mark_scheme=(
            Mark(f"Resistive forces ({resistive}) act against the motion", "B1", "a"),
            Mark("constant velocity, so zero acceleration: the resultant force is zero (Newton's first law)",
                 "M1", "a"),
            Mark("so the driving force equals the resistive forces; without it the resultant force "
                 "is backwards and it decelerates", "A1", "a"),
        ),
    )


def block_and_hanging_mass(block_mass: float = 1.2, hanging_mass: float = 0.60,
                           friction: float = 1.4) -> Question:
    """Connected bodies over a pulley: the whole system first (external forces, total mass),
    then the block alone for the tension (notes: connected objects, two blocks on a string)."""
    hanging_weight = weight(hanging_mass)
    if hanging_weight <= friction:
        raise ValueError(f"friction must be less than the hanging weight {n(hanging_weight, 3)} N, "
                         f"or the masses would not move (got friction={friction!r})")

    def pulled(g_: float = G_EARTH):
        return towing(weight(hanging_mass, g=g_), (hanging_mass, block_mass), (0.0, friction))

    system = pulled()
    a, tension = system.acceleration, system.tensions[0]
    total = hanging_mass + block_mass
    m1, m2, f = n(block_mass, 2), n(hanging_mass, 2), n(friction, 2)
    w2 = w(hanging_weight)
    # a with the figures its line needs: at 3 s.f. (2.11) the line gave 6.6 N for a key of 6.5 N
    # in variant 9 (issue 25)
    (a_shown,) = enough_figures((a,), lambda acc: friction + block_mass * acc, n(tension, 2))
    return Question(
        key="block-and-hanging-mass",
        text=(f"A block of mass {m1} kg rests on a horizontal bench. A light string joins it, over a "
              f"smooth pulley at the edge of the bench, to a mass of {m2} kg that hangs freely. A "
              f"friction force of {f} N acts on the block while it moves. The masses are released "
              "from rest. Calculate (a) the acceleration of the masses and (b) the tension in the "
              "string."),
        givens=(Given("block mass", block_mass, "kg", 2), Given("hanging mass", hanging_mass, "kg", 2),
                Given("friction", friction, "N", 2)),
        parts=(
            Part("acceleration of the masses", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 answer_for_g=lambda g_: pulled(g_).acceleration,
                 revisit="Treat the two masses as one object: the external forces (the hanging "
                         "weight and the friction) and the total mass.",
                 mistakes=(
                     Mistake("friction left out", acceleration(hanging_weight, total),
                             f"You left out the friction. Resultant force = {m2} × {n(G_EARTH, 3)} − {f} N."),
                     Mistake("block's mass only", acceleration(hanging_weight - friction, block_mass),
                             "You divided by the block's mass only. The resultant force accelerates "
                             f"both masses: use the total mass, {w(total)} kg.", see="second-law"),
                     Mistake("hanging mass only", acceleration(hanging_weight - friction, hanging_mass),
                             "You divided by the hanging mass only. The resultant force accelerates "
                             f"both masses: use the total mass, {w(total)} kg.", see="second-law"),
                     Mistake("acceleration of free fall", G_EARTH,
                             "The hanging mass falls at g only when nothing else pulls on it. Here "
                             "the string pulls it back: work out the resultant force on the whole "
                             "system and divide by the total mass.", see="second-law"),
                 ), see="friction"),
            Part("tension in the string", tension, "N", "force", shown_sig_figs=2,
                 working=(Step("acceleration", a, "m s^-2", 2),),
                 answer_from=lambda acc: friction + block_mass * acc,
                 answer_for_g=lambda g_: pulled(g_).tensions[0],
                 ecf=Ecf(friction_symbol + block_mass_symbol * a_answer,
                         {"friction": friction, "block_mass": block_mass}),
                 # or the hanging mass alone: mg - T = ma, so T = m(g - a)
                 ecf_also=(Ecf(hanging_mass_symbol * (gravity_symbol - a_answer),
                               {"hanging_mass": hanging_mass, "gravity": G_EARTH}),),
                 revisit="F = ma for the block alone: T − friction = block mass × a (or, for the "
                         "hanging mass alone, mg − T = ma).",
                 mistakes=(
                     Mistake("tension equals the hanging weight", hanging_weight,
                             "That is the hanging mass's weight. The hanging mass accelerates "
                             f"downwards, so the tension is less than its weight: {m2} × {n(G_EARTH, 3)} − T = {m2}a.", see="weight"),
                     Mistake("friction left out", block_mass * a,
                             "That is the block's resultant force, ma. The tension must also "
                             f"overcome the friction: T − {f} = {m1}a."),
                 ), see="friction"),
        ),
        mark_scheme=(
            Mark(f"Whole system: resultant force = {m2} × {n(G_EARTH, 3)} − {f} = {w(hanging_weight - friction)} N", "C1", "a"),
            Mark(f"a = {w(hanging_weight - friction)} / {w(total)} = {n(a, 2)} {PER_S2}", "A1", "a"),
            Mark(f"Block alone: T − {f} = {m1} × {a_shown}", "C1", "b"),
            Mark(f"T = {n(tension, 2)} N (check: {w2} − T = {m2} × {a_shown})", "A1", "b"),
        ),
    )


def _rocket_mass(thrust: float, lift_off_acceleration: float) -> Question:
    """The rocket's mass from its thrust and its acceleration: T - mg = ma, so m = T / (a + g), as
    9702/23/O/N/22 Q2(a)(iii) asks it (thrust 16 N, acceleration 55 m s⁻², [2])."""
    if lift_off_acceleration <= 0:
        raise ValueError(f"lift_off_acceleration must be upwards, above zero, for the rocket to lift off "
                         f"(got lift_off_acceleration={lift_off_acceleration!r})")
    mass = thrust / (lift_off_acceleration + G_EARTH)
    t, a = n(thrust, stated_figures(thrust)), n(lift_off_acceleration, stated_figures(lift_off_acceleration))
    g = n(G_EARTH, 3)
    return Question(
        key="rocket-lift-off",
        text=(f"A model rocket lifts off from its launch pad. Its engine gives an upward thrust of {t} N and "
              f"it accelerates upwards at {a} {PER_S2}. Air resistance is negligible. Calculate the mass "
              "of the rocket."),
        givens=(Given("thrust", thrust, "N", stated_figures(thrust)),
                Given("acceleration", lift_off_acceleration, "m s^-2", stated_figures(lift_off_acceleration))),
        parts=(
            Part("mass of the rocket", mass, "kg", "mass", shown_sig_figs=2,
                 answer_for_g=lambda g_: thrust / (lift_off_acceleration + g_),
                 revisit="The resultant force is the thrust less the weight: T − mg = ma, so m = T / (a + g).",
                 mistakes=(
                     Mistake("weight left out", thrust / lift_off_acceleration,
                             f"You used the thrust as the resultant force. The weight acts downwards as well: "
                             f"{t} − m × {g} = m × {a}."),
                     Mistake("weight added", thrust / (lift_off_acceleration - G_EARTH),
                             "You added the weight to the thrust. They act in opposite directions: "
                             "resultant = thrust − weight."),
                 ), see="weight"),
        ),
        mark_scheme=(
            Mark(f"T − mg = ma: {t} − m × {g} = m × {a}", "C1", "a"),
            Mark(f"m = {t} / ({a} + {g}) = {n(mass, 2)} kg", "A1", "a"),
        ),
    )


def rocket_lift_off(mass: float = 0.60, thrust: float = 9.0, lift_off_acceleration: float = 0) -> Question:
    """A model rocket at lift-off: weight, then thrust - weight = ma (notes: rockets and lifts),
    with (b) carried forward from (a). Givens print to the figures they are stated to.

    lift_off_acceleration: 0 (the variants) gives the mass and asks the acceleration; a value asks
    the mass from the thrust and that acceleration instead (_rocket_mass), as a paper does."""
    if lift_off_acceleration:
        return _rocket_mass(thrust, lift_off_acceleration)
    rocket_weight = weight(mass)
    if thrust <= rocket_weight:
        raise ValueError(f"thrust must exceed the weight {n(rocket_weight, 3)} N, or the rocket "
                         f"would not lift off (got thrust={thrust!r})")
    a = acceleration(thrust - rocket_weight, mass)
    mass_figures, thrust_figures = stated_figures(mass), stated_figures(thrust)  # as the question states them
    m, t = n(mass, mass_figures), n(thrust, thrust_figures)
    wt = n(rocket_weight, 3)
    return Question(
        key="rocket-lift-off",
        text=(f"A model rocket of mass {m} kg stands on its launch pad. At lift-off its engine gives "
              f"an upward thrust of {t} N. Calculate (a) the weight of the rocket and (b) its "
              "acceleration at lift-off."),
        givens=(Given("mass", mass, "kg", mass_figures), Given("thrust", thrust, "N", thrust_figures)),
        parts=(
            Part("weight of the rocket", rocket_weight, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g_: weight(mass, g=g_),
                 revisit="Weight = mass × g, with g = 9.81 m s⁻².",
                 mistakes=(
                     Mistake("divided by g", mass_from_weight(mass),
                             f"You divided by g. Weight = mass × g = {m} × {n(G_EARTH, 3)}."),
                 ), see="weight"),
            Part("acceleration at lift-off", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 direction="choice", choices=("upwards", "downwards"), answer_direction="upwards",
                 working=(Step("weight", rocket_weight, "N"),),
                 answer_from=lambda weight_: acceleration(thrust - weight_, mass),
                 answer_for_g=lambda g_: acceleration(thrust - weight(mass, g=g_), mass),
                 ecf=Ecf((thrust_symbol - a_answer) / rocket_mass_symbol,
                         {"thrust": thrust, "rocket_mass": mass}),
                 direction_hint="The thrust is bigger than the weight, so the resultant force and "
                                "the acceleration are upwards.",
                 revisit="Resultant force = thrust − weight; a = resultant force / mass.",
                 mistakes=(
                     Mistake("weight left out", acceleration(thrust, mass),
                             "You used the thrust as the resultant force. The weight acts "
                             f"downwards as well: resultant = {t} − {wt} N."),
                     Mistake("weight added", acceleration(thrust + rocket_weight, mass),
                             "You added the weight to the thrust. They act in opposite directions: "
                             "resultant = thrust − weight."),
                 ), see="weight"),
        ),
        mark_scheme=(
            Mark(f"W = mg = {m} × {n(G_EARTH, 3)} = {wt} N", "B1", "a"),
            Mark(f"Resultant force = {t} − {w(rocket_weight)} = {w(thrust - rocket_weight)} N", "C1", "b"),
            Mark(f"a = {w(thrust - rocket_weight)} / {m} = {n(a, 2)} {PER_S2}", "A1", "b"),
            Mark("upwards (the thrust is bigger than the weight)", "B1", "b", earns="direction"),
        ),
    )


#: Bodies at a constant velocity, for Newton's first law: the situation, the forward (or up)
#: force a student thinks must win, and the force it balances.
_STEADY = (
    ("A car travels along a straight, level road at a constant velocity.", "car",
     "the driving force is bigger than the resistive forces"),
    ("A skydiver falls vertically at her terminal velocity.", "skydiver",
     "her weight is bigger than the air resistance"),
    ("A lift moves upwards at a constant speed.", "lift",
     "the tension in the cable is bigger than the weight of the lift"),
    ("An ice-hockey puck slides in a straight line across smooth, level ice at a constant velocity.",
     "puck", "a forward force on the puck keeps it moving"),
    ("A steel ball sinks through oil at a constant velocity.", "ball",
     "its weight is bigger than the upthrust and the drag together"),
)


def first_law_choice(situation: float = 0) -> Question:
    """Paper 1 style: constant velocity means zero resultant force (notes: Newton's first law;
    balanced forces mean at rest or a constant velocity)."""
    index = int(situation)
    what, body, winning = _STEADY[index]
    key = f"The resultant force on the {body} is zero."
    rows = [
        Option(key),
        Option(f"The {body} moves because {winning}.", "a resultant force is needed to keep it moving",
               f"At a constant velocity the acceleration is zero, so the resultant force is zero "
               f"(Newton's first law). A resultant force would change the {body}'s velocity; no "
               "force is needed just to keep it moving."),
        Option(f"No forces act on the {body}.", "no forces act on it",
               f"Forces do act on the {body} (its weight, for one), but they cancel. Constant "
               "velocity needs a zero resultant force, not zero forces."),
        Option(f"The forces on the {body} cannot be balanced, because the {body} is moving.",
               "balanced forces only at rest",
               "Balanced forces give a zero acceleration: the body is at rest or moves at a "
               "constant velocity. You cannot tell which from the forces alone.", see="first-law"),
    ]
    shift = (index + 1) % len(OPTION_LETTERS)
    options = tuple(rows[-shift:] + rows[:-shift]) if shift else tuple(rows)
    answer = OPTION_LETTERS[options.index(rows[0])]
    return Question(
        key="first-law-choice",
        text=what,
        givens=(),
        parts=(ChoicePart(f"Which statement about the forces on the {body} is correct?", options, answer,
                          revisit="Newton's first law: a constant velocity (or rest) means the "
                                  "resultant force is zero, and a zero resultant force means a "
                                  "constant velocity (or rest).", see="second-law"),),
        mark_scheme=(Mark(f"{answer}: constant velocity, so zero acceleration and zero resultant force "
                          "(Newton's first law)", "B1"),),
    )


#: Third-law pairs that a student says cancel: the situation, the pair (force on the moving
#: body, its partner and the body that partner acts on), the moving body, and the forces on
#: that body alone.
_PAIRS_THAT_MOVE = (
    ("A horse pulls a cart forwards along a level road, starting from rest.",
     "the horse's forward pull on the cart", "the cart's backward pull on the horse", "horse", "cart",
     "the horse's forward pull and the backward friction on the cart",
     "the pull is bigger than the friction"),
    ("A skater at rest pushes on a wall with her hands and moves away from it.",
     "the wall's push on the skater", "the skater's push on the wall", "wall", "skater",
     "the wall's push (and a small friction force)", "the push is bigger than the friction"),
    ("A rocket starts to rise from its launch pad. It pushes hot gas downwards out of its engine.",
     "the gas's upward push on the rocket", "the rocket's downward push on the gas", "gas", "rocket",
     "the gas's upward push (the thrust) and its weight", "the thrust is bigger than the weight"),
    ("A car starts to move from rest. Its tyres push backwards on the road.",
     "the road's forward push on the tyres", "the tyres' backward push on the road", "road", "car",
     "the road's forward push and the resistive forces",
     "the forward push is bigger than the resistive forces"),
    ("A swimmer starts to move forwards. Her arms push water backwards.",
     "the water's forward push on the swimmer", "the swimmer's backward push on the water", "water",
     "swimmer", "the water's forward push and the drag on her", "the forward push is bigger than the drag"),
)


def third_law_pair_explained(situation: float = 0) -> Question:
    """Describe and explain: why the two forces of a third-law pair do not cancel (notes:
    "they act on different bodies, so they never cancel")."""
    what, on_mover, partner, other, mover, forces, bigger = _PAIRS_THAT_MOVE[int(situation)]
    return Question(
        key="third-law-pair-explained",
        text=(f"{what} By Newton's third law, {on_mover} and {partner} are equal in size and opposite "
              f"in direction. A student says: “These two forces cancel, so the {mover} cannot "
              "accelerate.”"),
        givens=(),
        parts=(ExplainPart(
            "Explain why the student is wrong.",
            f"The two forces act on different bodies: one acts on the {mover}, the other on the {other}. "
            "Forces can only cancel when they act on the same body, so to find "
            f"the {mover}'s motion, add only the forces on the {mover}: {forces}. Here {bigger}, so "
            f"the resultant force on the {mover} is not zero, and it accelerates (Newton's second law)."),),
        mark_scheme=(
            Mark(f"The forces act on different bodies ({mover} and {other})", "B1", "a"),
            Mark(f"only forces on the same body can cancel: the {mover}'s motion depends on the "
                 "forces on it alone", "M1", "a"),
            Mark(f"the resultant force on the {mover} is not zero ({bigger}), so it accelerates",
                 "A1", "a"),
        ),
    )


car_mass_symbol = sympy.Symbol("car_mass")
#: About the largest deceleration a car's tyres give on a dry, level road (m s^-2).
_HARDEST_BRAKING = 6.5


def stopping_force_from_distance(mass: float = 1500.0, speed: float = 20.0, distance: float = 50.0,
                                 body: float = 0) -> Question:
    """The stopping force from a distance: the deceleration from v² = u² + 2as, then F = ma
    (notes, How to do it 1., "Stopping distance with a constant force"; 9702/21/M/J/24 Q3 asks
    for a stopping force). The scheme's lines follow 9702/21/M/J/16 Q2(b) ("v² = u² + 2as and
    v = 0 C1 … A1") and, for the force worked from the student's own a, 9702/21/M/J/18 Q2(b)(iii)
    (C1 for F = ma with the candidate's own a, then A1).

    body: 0 for a car braking on a road (the variants), 1 for an object brought to rest by a constant
    force, as 9702/21/M/J/24 Q3(c) sets it (4.2 kg at 6.0 m s⁻¹ stopped in 0.050 m: 360 m s⁻²). Only
    a car's tyres cap the deceleration."""
    car = int(body) == 0
    noun, force_name = ("car", "average braking force") if car else ("object", "stopping force")
    deceleration = -acceleration_from_distance(speed, 0.0, distance)
    if car and deceleration > _HARDEST_BRAKING:
        raise ValueError(f"distance must let the car stop at no more than {_HARDEST_BRAKING} m s^-2, as hard as "
                         f"tyres brake on a dry road (got distance={distance!r} m: {n(deceleration, 2)} m s^-2; "
                         "body=1 poses an object stopped by a constant force, with no such cap)")
    force = mass * deceleration  # F = ma with the body's mass: the resultant (stopping) force
    m, u, s = n(mass, 2), n(speed, 2), n(distance, 2)
    text = (f"A car of mass {m} kg is travelling at {u} {PER_S} along a straight, level road. The "
            f"driver brakes and the car stops in a distance of {s} m, with a constant deceleration. "
            "Calculate (a) the deceleration of the car and (b) the average braking force on it "
            "(the resultant force).") if car else (
            f"An object of mass {m} kg moves in a straight line at a speed of {u} {PER_S}. A constant force "
            f"brings it to rest in a distance of {s} m. Calculate (a) the deceleration of the object and "
            "(b) the magnitude of the force.")
    return Question(
        key="stopping-force-distance",
        text=text,
        givens=(Given("mass", mass, "kg", 2), Given("speed", speed, "m s^-1", 2),
                Given("stopping distance", distance, "m", 2)),
        parts=(
            Part(f"deceleration of the {noun}", deceleration, "m s^-2", "acceleration", units=M_S2,
                 shown_sig_figs=2, sign_means=f"the acceleration is against the motion: the {noun} slows down",
                 revisit=f"The {noun} stops, so v = 0: v² = u² + 2as gives a = −u² / 2s. The deceleration is "
                         "its size.",
                 mistakes=(
                     Mistake("forgot to square the speed", speed / (2 * distance),
                             f"You used u instead of u². The equation is v² = u² + 2as: "
                             f"0 = {u}² − 2 × a × {s}."),
                     Mistake("time taken as distance ÷ speed", speed**2 / distance,
                             f"You took the time to stop as {s} / {u}, as if the {noun} kept its speed "
                             "(or left out the 2 in 2as). It slows down all the way: use v² = u² + 2as, "
                             "a = u² / 2s."),
                 ), see="second-law"),
            Part(force_name, force, "N", "force", shown_sig_figs=2,
                 working=(Step("deceleration", deceleration, "m s^-2", 2),),
                 answer_from=lambda a: mass * a,
                 ecf=Ecf(car_mass_symbol * a_answer, {"car_mass": mass}),
                 revisit=f"The {force_name.removeprefix('average ')} is the resultant force: F = ma, with the {noun}'s mass and its "
                         "deceleration (or, by work done, F s = ½mu²).",
                 mistakes=(
                     Mistake("the ½ left out of the kinetic energy", mass * speed**2 / distance,
                             f"You used F s = mu². The kinetic energy the brakes remove is ½mu²: "
                             f"F × {s} = ½ × {m} × {u}²."),
                     Mistake("kinetic energy given", kinetic_energy(mass, speed),
                             f"That is the {noun}'s kinetic energy, ½mu², in J. The force is that energy ÷ "
                             "the distance, or ma.", unit="J", see="kinetic-energy"),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"v² = u² + 2as with v = 0: 0 = {u}<sup>2</sup> − 2 × a × {s}", "C1", "a"),
            Mark(f"a = {u}<sup>2</sup> / (2 × {s}) = {n(deceleration, 2)} {PER_S2}", "A1", "a"),
            Mark(f"F = ma = {m} × {w(deceleration)}", "C1", "b"),
            Mark(f"= {n(force, 2)} N", "A1", "b"),
        ),
    )


TEMPLATES = checked_givens(
    Template("practice-car-slowing", "newton", ("numeric",), "Car slowing down", car_slowing,
             {"mass": Draw(800.0, 600.0, 1500.0, 100.0), "driving": Draw(1500.0, 1000.0, 3000.0, 100.0),
              "resistive": Draw(2300.0, 1500.0, 4000.0, 100.0)}),
    Template("practice-lift", "newton", ("numeric",), "In a lift", lift_accelerating_down,
             {"mass": Draw(58.0, 40.0, 90.0, 1.0), "a_down": Draw(1.5, 0.5, 3.0, 0.1)}),
    Template("practice-towing", "newton", ("numeric",), "Car towing a trailer", car_towing_trailer,
             {"car_mass": Draw(1000.0, 800.0, 1500.0, 100.0), "trailer_mass": Draw(500.0, 200.0, 800.0, 100.0),
              "driving": Draw(2400.0, 1500.0, 4000.0, 100.0),
              "car_resistance": Draw(300.0, 200.0, 500.0, 10.0),
              "trailer_resistance": Draw(150.0, 50.0, 300.0, 10.0)}),
    Template("third-law-pair-choice", "newton", ("mcq",), "Which is a third-law pair?",
             third_law_pair_choice, {"situation": Draw(0, 0, len(_PAIR_SITUATIONS) - 1, 1)},
             variant_count=len(_PAIR_SITUATIONS)),
    Template("friction-acceleration-choice", "newton", ("mcq",), "Crate pulled against friction",
             friction_acceleration_choice,
             {"crate_weight": Draw(490.0, 200.0, 900.0, 10.0), "pull": Draw(180.0, 100.0, 400.0, 10.0),
              "friction": Draw(60.0, 20.0, 150.0, 10.0)}),
    Template("lift-cable-choice", "newton", ("mcq",), "Tension in a lift cable", lift_cable_choice,
             {"mass": Draw(1200.0, 500.0, 2000.0, 100.0), "a_size": Draw(1.5, 0.5, 3.0, 0.1),
              "motion": Draw(1, 0, len(_LIFT_MOTIONS) - 1, 1)}),
    Template("constant-velocity-explained", "newton", ("explain",), "Why keep driving?",
             constant_velocity_explained, {"situation": Draw(0, 0, len(_CRUISERS) - 1, 1)},
             variant_count=len(_CRUISERS)),
    Template("block-and-hanging-mass", "newton", ("numeric",), "Block pulled by a hanging mass",
             block_and_hanging_mass,
             {"block_mass": Draw(1.2, 0.5, 2.5, 0.1), "hanging_mass": Draw(0.60, 0.20, 1.0, 0.05),
              "friction": Draw(1.4, 0.5, 3.0, 0.1)}),
    Template("rocket-lift-off", "newton", ("numeric",), "Model rocket at lift-off", rocket_lift_off,
             {"mass": Draw(0.60, 0.20, 0.90, 0.05), "thrust": Draw(9.0, 4.0, 15.0, 1.0)}),
    Template("first-law-choice", "newton", ("mcq",), "Moving at a constant velocity", first_law_choice,
             {"situation": Draw(0, 0, len(_STEADY) - 1, 1)}, variant_count=len(_STEADY)),
    Template("third-law-pair-explained", "newton", ("explain",), "Why the pair does not cancel",
             third_law_pair_explained, {"situation": Draw(0, 0, len(_PAIRS_THAT_MOVE) - 1, 1)},
             variant_count=len(_PAIRS_THAT_MOVE)),
    Template("stopping-force-distance", "newton", ("numeric",), "Braking force from a stopping distance",
             stopping_force_from_distance,
             {"mass": Draw(1500.0, 800.0, 1500.0, 100.0), "speed": Draw(20.0, 10.0, 30.0, 1.0),
              "distance": Draw(50.0, 20.0, 90.0, 5.0)}),
)
