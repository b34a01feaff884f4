# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Drag and terminal velocity: the skydiver, falling through a fluid, resultant force and acceleration."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH
from ..models import acceleration, weight
from ..notation import format_number as n
from ..questions import Ecf, Given, Mark, Mistake, Part, Question, Step
from ..variants import Draw, Template
from ._common import M_S2, PER_S2

a_answer, open_drag_symbol, mass_symbol = sympy.symbols("a open_drag mass")


def skydiver_parachute_opens(mass: float = 70.0, open_drag: float = 1500.0) -> Question:
    """Notes, Quick check 3: 70 kg skydiver -> drag 687 N; 1500 N drag -> 11.6 m s^-2 upwards."""
    drag = weight(mass)  # at terminal velocity the resultant force is zero
    if open_drag <= drag:
        raise ValueError(f"open_drag must exceed the skydiver's weight {n(drag, 3)} N, or she would not "
                         f"slow down (got open_drag={open_drag!r})")
    a = acceleration(open_drag - drag, mass)
    m, d, w = n(mass, 2), n(open_drag, 2), n(drag, 3)
    return Question(
        key="quick-check-3",
        text=(f"A {m} kg skydiver falls at terminal velocity. (a) State the drag force on her. When her "
              f"parachute opens the drag force becomes {d} N: (b) calculate her acceleration and give "
              "its direction."),
        givens=(Given("mass", mass, "kg", 2), Given("drag with the parachute open", open_drag, "N", 2)),
        parts=(
            Part("drag force at terminal velocity", drag, "N", "force", shown_sig_figs=3,
                 asks="state", answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At terminal velocity the resultant force is zero, so the drag equals the "
                         "weight, mg.",
                 mistakes=(
                     Mistake("mass given as force", mass,
                             f"{m} is her mass in kg. The drag equals her weight, W = mg = {m} × "
                             f"{n(G_EARTH, 3)}."),
                     Mistake("divided by g", mass / G_EARTH,
                             "You divided by g. Weight = mass × g, and at terminal velocity drag = weight."),
                     Mistake("drag is zero", 0.0,
                             "At terminal velocity the resultant force is zero, not the drag: the drag "
                             "has grown to equal the weight."),
                 )),
            Part("acceleration when the parachute opens", a, "m s^-2", "acceleration", units=M_S2,
                 shown_sig_figs=3, direction="choice", choices=("upwards", "downwards"),
                 answer_direction="upwards",
                 working=(Step("drag at terminal velocity (her weight)", drag, "N"),),
                 answer_from=lambda w_: acceleration(open_drag - w_, mass),
                 answer_for_g=lambda g: acceleration(open_drag - weight(mass, g=g), mass),
                 ecf=Ecf((open_drag_symbol - a_answer) / mass_symbol, {"open_drag": open_drag, "mass": mass}),
                 direction_hint=f"The drag ({d} N) is bigger than the weight, so the resultant force "
                                "and the acceleration are upwards.",
                 revisit="Resultant force = drag − weight; a = resultant force / mass.",
                 mistakes=(
                     Mistake("still falling, so acceleration downwards", a,
                             "She is still falling, but slowing down: the resultant force (drag − "
                             "weight) is upwards, so the acceleration is upwards.", direction="downwards"),
                     Mistake("drag used as the resultant force", acceleration(open_drag, mass),
                             "You used the drag as the resultant force. The weight still acts: "
                             f"resultant = {d} − {w} N."),
                     Mistake("weight added to drag", acceleration(open_drag + drag, mass),
                             "You added the weight to the drag. They act in opposite directions: "
                             "resultant = drag − weight."),
                     Mistake("acceleration of free fall", G_EARTH,
                             "g is the acceleration with no drag at all. Here work out the resultant "
                             "force (drag − weight) and divide by the mass."),
                 )),
        ),
        mark_scheme=(
            Mark(f"At terminal velocity the resultant force is zero, so drag = mg = {m} × {n(G_EARTH, 3)} "
                 f"= {w} N", "B1", "a"),
            Mark(f"a = ({d} − {w}) / {m}", "C1", "b"),
            Mark(f"= {n(a, 3)} {PER_S2}", "A1", "b"),
            Mark("<strong>upwards</strong> (she slows down while still falling)", "B1", "b"),
        ),
    )


TEMPLATES = (
    Template("quick-check-3", "drag", ("numeric",), "Quick check 3", skydiver_parachute_opens,
             {"mass": Draw(70.0, 50.0, 99.0, 1.0), "open_drag": Draw(1500.0, 1000.0, 2500.0, 100.0)}),
)
