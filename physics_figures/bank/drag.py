# ruff: noqa: RUF001, RUF002  (question text is typeset: true minus, times, Greek letters)
"""Drag and terminal velocity: the skydiver, falling through a fluid, resultant force and acceleration."""

from __future__ import annotations

import sympy

from ..constants import G_EARTH
from ..models import (
    acceleration,
    drag_constant_for_terminal_velocity,
    drag_force,
    velocity_from_rest,
    weight,
)
from ..notation import format_number as n
from ..questions import (
    G_TEN,  # the g students use instead of the data's 9.81 m s^-2
    ChoicePart,
    Ecf,
    ExplainPart,
    Given,
    Graph,
    GraphPart,
    Mark,
    Mistake,
    Part,
    Question,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from ._common import M_S, M_S2, PER_S, PER_S2, reading, reading_rule

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


# ---------------------------------------------------------------- reading a graph

b_answer, c_answer, gravity_symbol = sympy.symbols("b c gravity")
#: The velocity-time curves are drawn through a point every this many seconds.
_CURVE_STEP = 0.1


def _falling_from_rest(terminal: float, until: float) -> tuple[tuple[float, float], ...]:
    """(t, v) every _CURVE_STEP s of a body dropped from rest with drag ∝ v² (the model's curve)."""
    count = round(until / _CURVE_STEP)
    times = [i * _CURVE_STEP for i in range(count + 1)]
    return tuple(zip(times, (float(v) for v in velocity_from_rest(times, terminal)), strict=True))


def skydiver_velocity_time(terminal: float = 50.0, mass: float = 70.0) -> Question:
    """A skydiver's velocity-time graph from the moment she jumps: read the terminal velocity;
    there the drag equals the weight, which gives k in F = kv² (notes: drag and terminal velocity)."""
    drag = weight(mass)  # at terminal velocity the resultant force is zero
    k = drag_constant_for_terminal_velocity(mass, terminal)
    graph = Graph("velocity–time", "velocity", "m s⁻¹", _falling_from_rest(terminal, 30.0),
                  time_division=1.0, value_division=2.0, time_max=30.0, value_max=80.0, curve=True)
    m = n(mass, 2)
    return Question(
        key="graph-skydiver-terminal",
        text=(f"A skydiver of mass {m} kg jumps from a hovering helicopter. The graph shows her "
              "velocity as she falls. The drag force on her is <em>F</em> = <em>kv</em><sup>2</sup>, "
              f"where <em>k</em> is a constant. {reading_rule(1.0, PER_S)}"),
        givens=(Given("mass", mass, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("terminal velocity", terminal, "m s^-1", "velocity", units=M_S, tolerance=1.0,
                      revisit="The terminal velocity is where the curve levels off: read that value."),
            Part("drag force at terminal velocity", drag, "N", "force", shown_sig_figs=3, asks="state",
                 answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At terminal velocity the resultant force is zero, so the drag equals the weight, mg.",
                 mistakes=(
                     Mistake("mass given as force", mass,
                             f"{m} is her mass in kg. The drag equals her weight, mg."),
                     Mistake("drag is zero", 0.0,
                             "At terminal velocity the resultant force is zero, not the drag: the drag "
                             "has grown to equal the weight."),
                 )),
            Part("value of k", k, "kg m^-1", "drag constant", units="kg m^-1", shown_sig_figs=2,
                 ecf=Ecf(b_answer / a_answer**2, {}),
                 revisit="At terminal velocity kv² = mg, so k = mg / v².",
                 mistakes=(
                     Mistake("speed not squared", drag / terminal,
                             "You divided by v. The drag is kv², so k = mg / v²."),
                     Mistake("mass, not weight", mass / terminal**2,
                             "You used the mass. The drag equals the weight, mg, in N."),
                 )),
        ),
        mark_scheme=(
            Mark(f"{reading(terminal, 1.0)} {PER_S} (where the curve levels off)", "B1", "a"),
            Mark(f"drag = weight = {m} × 9.81 = {n(drag, 3)} N", "B1", "b"),
            Mark(f"k = mg / v<sup>2</sup> = {n(drag, 3)} / {reading(terminal, 1.0)}<sup>2</sup>", "C1", "c"),
            Mark(f"= {n(k, 2)} kg m<sup>−1</sup>", "A1", "c"),
        ),
    )


def ball_acceleration_from_graph(terminal: float = 20.0, moment: float = 2.0, mass: float = 0.050) -> Question:
    """A falling ball's velocity-time curve: read the terminal velocity and the velocity at a
    moment; with drag ∝ v² the acceleration then is g(1 − v²/v_t²) (notes: resultant force
    = weight − drag, a = F / m)."""
    speed = float(velocity_from_rest(moment, terminal))
    if speed > 0.95 * terminal:  # too close to the top to read apart from it
        raise ValueError(f"moment must come before the ball is within 5% of its terminal velocity "
                         f"(got moment={moment!r})")
    k = drag_constant_for_terminal_velocity(mass, terminal)
    a = acceleration(weight(mass) - drag_force(k, speed), mass)
    graph = Graph("velocity–time", "velocity", "m s⁻¹", _falling_from_rest(terminal, 10.0),
                  time_division=0.2, value_division=0.5, time_max=10.0, value_max=30.0, curve=True)
    t, m = n(moment, decimals=1), n(mass, 2)
    return Question(
        key="graph-ball-acceleration",
        text=(f"A ball of mass {m} kg is dropped from rest from a high balloon. The graph shows its "
              "velocity as it falls. The air resistance on it is proportional to the square of its "
              f"speed. Take g = 9.81 {PER_S2}. {reading_rule(0.25, PER_S)}"),
        givens=(Given("mass", mass, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("terminal velocity", terminal, "m s^-1", "velocity", units=M_S, tolerance=0.25,
                      revisit="The terminal velocity is where the curve levels off: read that value."),
            GraphPart(f"velocity at {t} s", speed, "m s^-1", "velocity", units=M_S, tolerance=0.25, revisit=f"Go up from {t} s on the time axis to the curve, then across."),
            Part(f"acceleration at {t} s", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 ecf=Ecf(gravity_symbol * (1 - b_answer**2 / a_answer**2), {"gravity": G_EARTH}),
                 revisit="Resultant force = weight − drag, with drag = kv² and k = mg / vₜ² (vₜ the "
                         "terminal velocity); so a = g(1 − v² / vₜ²).",
                 mistakes=(
                     Mistake("drag left out", G_EARTH,
                             "That is g, the acceleration with no drag. The air resistance is not zero "
                             "while the ball moves: resultant force = weight − drag."),
                     Mistake("drag taken as proportional to v", G_EARTH * (1 - speed / terminal),
                             "You took the drag as proportional to v. It is proportional to v², so "
                             "a = g(1 − v² / vₜ²)."),
                 )),
        ),
        mark_scheme=(
            Mark(f"{reading(terminal, 0.25)} {PER_S}", "B1", "a"),
            Mark(f"{reading(speed, 0.25)} {PER_S}", "B1", "b"),
            Mark("at terminal velocity kv<sub>t</sub><sup>2</sup> = mg, so drag = mg v<sup>2</sup> / "
                 "v<sub>t</sub><sup>2</sup> and a = (mg − drag) / m", "C1", "c"),
            Mark(f"a = 9.81 × (1 − {reading(speed, 0.25)}<sup>2</sup> / {reading(terminal, 0.25)}<sup>2</sup>) "
                 f"= {n(a, 2)} {PER_S2}", "A1", "c"),
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
    Template("graph-skydiver-terminal", "drag", ("graph", "numeric"), "A skydiver: velocity–time graph",
             skydiver_velocity_time, {"terminal": Draw(50.0, 30.0, 70.0, 1.0), "mass": Draw(70.0, 50.0, 100.0, 1.0)}),
    Template("graph-ball-acceleration", "drag", ("graph", "numeric"), "A falling ball: velocity–time graph",
             ball_acceleration_from_graph,
             {"terminal": Draw(20.0, 10.0, 25.0, 0.5), "moment": Draw(2.0, 0.5, 3.0, 0.5),
              "mass": Draw(0.050, 0.020, 0.080, 0.005)}),
)
