# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Drag and terminal velocity: the skydiver, falling through a fluid, resultant force and acceleration."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH
from ..models import acceleration, weight
from ..notation import format_number as n
from ..questions import (
    G_TEN,  # the g students use instead of the data's 9.81 m s^-2
    ChoicePart,
    Ecf,
    ExplainPart,
    Given,
    Mark,
    Mistake,
    Part,
    Question,
    Step,
    choices_in_order,
)
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


def parachute_opens_choice(mass: float = 70.0, drag: float = 1500.0) -> Question:
    """Paper 1 style: the deceleration just after the parachute opens (notes, Quick check 3(b):
    70 kg, 1500 N -> 11.6 m s^-2 upwards). The wrong options are the notes' common mistakes."""
    w = weight(mass)
    if drag <= w:
        raise ValueError(f"drag must be more than the weight, {n(w, 3)} N, for her to slow down "
                         f"(got drag={drag!r})")
    key = acceleration(drag - w, mass)
    options, answer = choices_in_order(key, {
        "drag used as the resultant force": (
            acceleration(drag, mass),
            ("That is the drag divided by the mass: the weight still acts, so the resultant force "
             "is drag − weight.")),
        "weight added to the drag": (
            acceleration(drag + w, mass),
            "The weight acts downwards and the drag upwards: subtract them, do not add."),
        "used g = 10 m s⁻²": (
            acceleration(drag - weight(mass, g=G_TEN), mass),
            "You used g = 10 m s⁻². The data give g = 9.81 m s⁻²."),
    }, sig_figs=3, unit=PER_S2)
    return Question(
        key="parachute-opens-choice",
        text=(f"A skydiver of mass {n(mass, 2)} kg is falling at terminal velocity when her parachute "
              f"opens. Just after it opens, the drag force on her is {n(drag, 2)} N. "
              "Take g = 9.81 m s<sup>−2</sup>."),
        givens=(Given("mass", mass, "kg", 2), Given("drag", drag, "N", 2)),
        parts=(ChoicePart("What is the magnitude of her acceleration just after the parachute opens?",
                          options, answer,
                          revisit="Resultant force = drag − weight, and a = resultant force / mass."),),
        mark_scheme=(Mark(f"{answer}: a = ({n(drag, 2)} − {n(mass, 2)} × 9.81) / {n(mass, 2)} "
                          f"= {n(key, 3)} {PER_S2} (upwards)", "B1"),),
    )


#: Bodies that fall to a terminal velocity: the situation, what gives the drag, and whether
#: an upthrust acts (notes: drag and terminal velocity; in a liquid the upthrust is constant too).
_FALLERS = (
    ("A skydiver jumps from a helicopter hovering high above the ground.", "air resistance", False),
    ("A steel ball is released from rest just below the surface of a deep tank of oil.",
     "the viscous drag of the oil", True),
    ("A raindrop starts to fall from a cloud.", "air resistance", False),
    ("A small stone is dropped into a deep lake and sinks.", "the drag of the water", True),
)


def terminal_velocity_explained(situation: float = 0) -> Question:
    """Describe and explain: why a falling body reaches a terminal velocity (notes, Drag and
    terminal velocity: drag grows with speed until it balances the weight)."""
    what, drag_name, upthrust = _FALLERS[int(situation)]
    constant = "the weight and the upthrust" if upthrust else "the weight"
    return Question(
        key="terminal-velocity-explained",
        text=f"{what} Soon it falls at a constant velocity.",
        givens=(),
        parts=(ExplainPart(
            "Explain, in terms of the forces on it, why it reaches a constant (terminal) velocity.",
            f"At first the speed is small, so {drag_name} is small and the resultant force is "
            f"downwards: it accelerates. As its speed increases, {drag_name} increases, while "
            f"{constant} {'stay' if upthrust else 'stays'} the same. So the resultant force decreases, "
            "and so does the acceleration. "
            f"When the drag{' and the upthrust together' if upthrust else ''} equal the weight, the "
            "resultant force is zero, the acceleration is zero, and the velocity stays constant: "
            "this is the terminal velocity."),),
        mark_scheme=(
            Mark(f"{drag_name[0].upper()}{drag_name[1:]} increases as the speed increases "
                 f"({constant} constant)", "B1", "a"),
            Mark("so the resultant (downward) force decreases, and so the acceleration decreases", "M1", "a"),
            Mark(f"when drag{' + upthrust' if upthrust else ''} = weight, the resultant force is zero: "
                 "zero acceleration, so constant velocity", "A1", "a"),
        ),
    )


TEMPLATES = (
    Template("quick-check-3", "drag", ("numeric",), "Quick check 3", skydiver_parachute_opens,
             {"mass": Draw(70.0, 50.0, 99.0, 1.0), "open_drag": Draw(1500.0, 1000.0, 2500.0, 100.0)}),
    Template("parachute-opens-choice", "drag", ("mcq",), "The parachute opens", parachute_opens_choice,
             {"mass": Draw(70.0, 50.0, 100.0, 5.0), "drag": Draw(1500.0, 1000.0, 2500.0, 100.0)}),
    Template("terminal-velocity-explained", "drag", ("explain",), "Why terminal velocity?",
             terminal_velocity_explained, {"situation": Draw(0, 0, len(_FALLERS) - 1, 1)},
             variant_count=len(_FALLERS)),
)
