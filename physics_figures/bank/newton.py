# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Newton's laws, weight and the third law: F = ma, lifts, towing, action-reaction pairs."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH
from ..models import acceleration, lift_contact_force, towing, weight
from ..notation import format_number as n
from ..questions import Ecf, Given, Mark, Mistake, Part, Question, Step
from ..variants import Draw, Template
from ._common import M_S2, PER_S2, w

a_answer, trailer_mass_symbol, trailer_resistance_symbol = sympy.symbols("a trailer_mass trailer_resistance")


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
                 )),
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
                             "accelerates, so R − mg = ma."),
                     Mistake("resultant force given", mass * a_down,
                             "That is the resultant force, ma. The contact force is R = m(g − a)."),
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
                 )),
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
                 )),
        ),
        mark_scheme=(
            Mark(f"Whole: resultant = {d} − {r_car} − {r_trailer} = {w(towed.resultant_force)} N", "C1", "a"),
            Mark(f"a = {w(towed.resultant_force)} / {w(total)} = {n(a, 2)} {PER_S2}", "A1", "a"),
            Mark(f"Trailer alone: T − {r_trailer} = {trailer} × {w(a)}", "C1", "b"),
            Mark(f"T = {n(tension, 2)} N", "A1", "b"),
        ),
    )


TEMPLATES = (
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
)
