# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""Drag and terminal velocity: the skydiver, falling through a fluid, resultant force and acceleration."""

from __future__ import annotations

import numpy
import sympy

from ..constants import G_EARTH
from ..models import (
    acceleration,
    drag_at_terminal_velocity,
    drag_constant_for_terminal_velocity,
    drag_force,
    falling_acceleration,
    power_law_constant,
    power_law_drag,
    power_law_terminal_velocity,
    skydive,
    sphere_drag_constant,
    sphere_volume,
    stokes_constant,
    stokes_reynolds_number,
    terminal_velocity,
    terminal_velocity_ratio,
    time_to_terminal_velocity,
    upthrust,
    velocity_from_rest,
    weight,
)
from ..notation import format_number as n
from ..notation import round_number
from ..parts.text import TextPoint
from ..questions import (
    G_TEN,  # the g students use instead of the data's 9.81 m s^-2
    OPTION_LETTERS,
    ChoicePart,
    Ecf,
    ExplainPart,
    Given,
    Graph,
    GraphPart,
    Mark,
    Mistake,
    Option,
    Part,
    Question,
    Reading,
    Sketch,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from ._common import M_S, M_S2, PER_S, PER_S2, enough_figures, reading, reading_rule
from ._common import w as working
from .givens import checked_givens

a_answer, open_drag_symbol, mass_symbol = sympy.symbols("a open_drag mass")


def skydiver_parachute_opens(mass: float = 70.0, open_drag: float = 1500.0) -> Question:
    """Notes, Quick check 3: 70 kg skydiver -> drag 687 N; 1500 N drag -> 11.6 m s^-2 upwards."""
    drag = weight(mass)  # at terminal velocity the resultant force is zero
    if open_drag <= drag:
        raise ValueError(f"open_drag must exceed the skydiver's weight {n(drag, 3)} N, or she would not "
                         f"slow down (got open_drag={open_drag!r})")
    a = acceleration(open_drag - drag, mass)
    m, d, w = n(mass, 2), n(open_drag, 2), n(drag, 3)
    # (b) carries the weight as (a) prints it, or with the figures its result needs
    (carried,) = enough_figures((drag,), lambda weight_: (open_drag - weight_) / mass, n(a, 3), in_full_up_to=3)
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
                 ), see="skydiver"),
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
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"At terminal velocity the resultant force is zero, so drag = mg = {m} × {n(G_EARTH, 3)} "
                 f"= {w} N", "B1", "a"),
            Mark(f"a = ({d} − {carried}) / {m}", "C1", "b"),
            Mark(f"= {n(a, 3)} {PER_S2}", "A1", "b"),
            Mark("<strong>upwards</strong> (she slows down while still falling)", "B1", "b", earns="direction"),
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
        "mass used as the weight": (
            acceleration(drag - mass, mass),
            (f"You subtracted the mass, {n(mass, 2)} kg, from the drag. Subtract the weight, a force: "
             f"W = mg = {n(mass, 2)} × {n(G_EARTH, 3)} N.")),
        "weight used as the mass": (
            acceleration(drag - w, w),
            ("You divided the resultant force by the weight. a = F / m needs the mass, "
             f"{n(mass, 2)} kg, not the weight.")),
    }, sig_figs=3, unit=PER_S2, seed=6)
    return Question(
        key="parachute-opens-choice",
        text=(f"A skydiver of mass {n(mass, 2)} kg is falling at terminal velocity when her parachute "
              f"opens. Just after it opens, the drag force on her is {n(drag, 2)} N. "
              "Take g = 9.81 m s<sup>−2</sup>."),
        givens=(Given("mass", mass, "kg", 2), Given("drag", drag, "N", 2)),
        parts=(ChoicePart("What is the magnitude of her acceleration just after the parachute opens?",
                          options, answer,
                          revisit="Resultant force = drag − weight, and a = resultant force / mass.", see="skydiver"),),
        mark_scheme=(Mark(f"{answer}: a = ({n(drag, 2)} − {n(mass, 2)} × 9.81) / {n(mass, 2)} "
                          f"= {n(key, 3)} {PER_S2} (upwards)", "B1"),),
    )


#: Bodies that fall to a terminal velocity: the situation, what gives the drag, and whether
#: an upthrust acts (notes: drag and terminal velocity; in a liquid the upthrust is constant too).
_FALLERS = (
    ("A skydiver jumps from a helicopter hovering high above the ground.", "the skydiver", "air resistance",
     False),
    ("A steel ball is released from rest just below the surface of a deep tank of oil.", "the ball",
     "the viscous drag of the oil", True),
    ("A raindrop starts to fall from a cloud.", "the raindrop", "air resistance", False),
    ("A small stone is dropped into a deep lake and sinks.", "the stone", "the drag of the water", True),
)


#: The rules that find terminal-velocity-explained's points in a student's words, for the page to
#: tick them for the student to confirm (issue 38; the explain part stays self-marked). The points
#: are the notes' (Drag and terminal velocity; Common mistakes: "say why: the drag increases as
#: the speed increases, so the resultant force decreases"); no published 9702 scheme for this
#: wording was found in the search corpus.
_FALLING_SOURCE = "the notes, Drag and terminal velocity, and Common mistakes"
_DRAG_WORDS = "drag|resistance|friction|viscous|resistive"
_LESS = "decreases|decrease|decreasing|smaller|less|reduces|reduced|falls"


def _falling_points(upthrust: bool) -> tuple[TextPoint, ...]:
    balance = f"{_DRAG_WORDS} upthrust =|balances|balance weight" if upthrust else f"{_DRAG_WORDS} =|balances|balance weight"
    return (
        TextPoint("the drag increases as the speed increases", "B1",
                  accept=((f"{_DRAG_WORDS} increases|increase|increasing|grows|greater|larger|bigger|rises "
                          "speed|velocity|faster"),), source=_FALLING_SOURCE),
        TextPoint("so the resultant force decreases, and so the acceleration decreases", "M1",
                  accept=(f"resultant {_LESS}", f"acceleration {_LESS}"), source=_FALLING_SOURCE),
        TextPoint("when the forces balance, the resultant force is zero: constant velocity", "A1",
                  accept=(balance, "resultant|acceleration zero|no|0"), source=_FALLING_SOURCE),
    )


def terminal_velocity_explained(situation: float = 0) -> Question:
    """Describe and explain: why a falling body reaches a terminal velocity (notes, Drag and
    terminal velocity: drag grows with speed until it balances the weight). The model answer
    names the variant's body and its drag (issue 25)."""
    what, body, drag_name, upthrust = _FALLERS[int(situation)]
    constant = "the weight and the upthrust" if upthrust else "the weight"
    balance = f"{drag_name} and the upthrust together equal" if upthrust else f"{drag_name} equals"
    return Question(
        key="terminal-velocity-explained",
        text=f"{what} Soon it falls at a constant velocity.",
        givens=(),
        parts=(ExplainPart(
            "Explain, in terms of the forces on it, why it reaches a constant (terminal) velocity.",
            f"At first the speed of {body} is small, so {drag_name} is small and the resultant force is "
            f"downwards: {body} accelerates. As its speed increases, {drag_name} increases, while "
            f"{constant} {'stay' if upthrust else 'stays'} the same. So the resultant force decreases, "
            "and so does the acceleration. "
            f"When {balance} the weight of {body}, the resultant force is zero, the acceleration is "
            "zero, and the velocity stays constant: this is the terminal velocity.", _falling_points(upthrust)),),
        mark_scheme=(
            Mark(f"{drag_name[0].upper()}{drag_name[1:]} increases as the speed increases "
                 f"({constant} constant)", "B1", "a"),
            Mark("so the resultant (downward) force decreases, and so the acceleration decreases", "M1", "a"),
            Mark(f"when drag{' + upthrust' if upthrust else ''} = weight, the resultant force is zero: "
                 "zero acceleration, so constant velocity", "A1", "a"),
        ),
    )


#: The stone's mass in drag_fraction_choice: the answer does not depend on it, so it is not stated.
_STONE_MASS = 0.40


def drag_fraction_choice(percent: float = 25.0) -> Question:
    """Paper 1 style: the acceleration of a falling body when the drag is a given fraction of its
    weight (notes: resultant force = weight − drag; a = resultant / mass). Wrong options: the
    drag ignored (a = g), the drag added to the weight, the drag taken as the resultant force
    (below the key when the drag is less than half the weight, so the key is not always A)."""
    fraction, mass = percent / 100, _STONE_MASS
    drag = fraction * weight(mass)
    key = falling_acceleration(mass, drag)
    p = n(percent, 2)
    options, answer = choices_in_order(key, {
        "drag ignored": (
            falling_acceleration(mass, 0.0),
            ("That is g, the acceleration with no air resistance at all. The air resistance acts "
            "upwards, so the resultant force is weight − air resistance, and a is less than g.")),
        "drag added to the weight": (
            acceleration(weight(mass) + drag, mass),
            ("The weight acts downwards and the air resistance upwards, against the motion: "
            "subtract them, do not add.")),
        "air resistance used as the resultant force": (
            acceleration(drag, mass),
            ("That is the air resistance divided by the mass. The weight still acts: the resultant "
            "force is weight − air resistance.")),
        "the resultant force divided by the weight": (
            acceleration(weight(mass) - drag, weight(mass)),
            ("You divided the resultant force by the weight. a = F / m: divide by the mass, "
             "m = W / g, so a = g × (1 − the fraction).")),
    }, sig_figs=3, unit=PER_S2, seed=1)
    return Question(
        key="drag-fraction-choice",
        text=(f"A stone falls vertically through still air. At one instant the air resistance on the "
              f"stone is {p}% of its weight. Take g = 9.81 {PER_S2}."),
        givens=(Given("air resistance as a percentage of the weight", percent, "%", 2),),
        parts=(ChoicePart("What is the acceleration of the stone at this instant?", options, answer,
                          revisit="Resultant force = weight − air resistance (they act in opposite "
                                  "directions), and a = resultant force / mass.", see="skydiver"),),
        mark_scheme=(Mark(f"{answer}: resultant force = W − {p}% of W, so a = (1 − {n(fraction, 2)}) × "
                          f"9.81 = {n(key, 3)} {PER_S2} (downwards)", "B1"),),
    )


#: At a terminal velocity: the situation, the statement that is true, and three named
#: misconceptions (notes: at terminal velocity the resultant force is zero, weight = drag
#: (+ upthrust); common mistakes: acceleration g, no drag, drag bigger than the weight,
#: upthrust forgotten, the velocity or acceleration upwards once the parachute is open).
_G_WHILE_FALLING = ("acceleration is g while it falls",
                    ("g is the acceleration only at the very start, when the speed and so the drag are "
                    "zero. At terminal velocity the velocity is constant, so the acceleration is zero."))
_NO_DRAG = ("no drag at zero acceleration",
            ("Zero acceleration means a zero resultant force, not zero drag: the drag has grown with "
            "the speed until it balances the weight."))
_DRAG_BIGGER = ("drag greater than the weight",
                ("If the drag were greater than the weight, the resultant force would be upwards and "
                "the body would slow down. At a constant velocity the resultant force is zero."))
_AT_TERMINAL = (
    ("A skydiver falls vertically at a constant (terminal) velocity before she opens her parachute.",
     "The air resistance on her equals her weight, so the resultant force on her is zero.",
     (("Her acceleration is 9.81 m s<sup>−2</sup> downwards, because she is still falling.",
       *_G_WHILE_FALLING),
      ("There is no air resistance on her, because her acceleration is zero.", *_NO_DRAG),
      ("The air resistance on her is greater than her weight, so she cannot speed up.", *_DRAG_BIGGER))),
    ("A raindrop falls vertically through still air at its terminal velocity.",
     "The air resistance on the raindrop equals its weight, so its acceleration is zero.",
     (("The air resistance on the raindrop is zero, because its velocity is constant.", *_NO_DRAG),
      ("The air resistance is greater than the weight of the raindrop.", *_DRAG_BIGGER),
      ("The raindrop accelerates at 9.81 m s<sup>−2</sup>, the acceleration of free fall.",
       *_G_WHILE_FALLING))),
    ("A steel ball bearing sinks through a tall tube of oil at its terminal velocity.",
     ("The viscous drag and the upthrust together equal the weight of the ball, so the resultant "
     "force on it is zero."),
     (("The viscous drag on the ball equals its weight.", "upthrust forgotten",
       ("In a liquid the upthrust acts upwards too, and it does not change with speed. At terminal "
       "velocity weight = drag + upthrust, so the drag is less than the weight.")),
      ("The ball accelerates at 9.81 m s<sup>−2</sup>, because it is falling.", *_G_WHILE_FALLING),
      ("The viscous drag on the ball is greater than its weight, so it sinks at a constant speed.",
       *_DRAG_BIGGER))),
    ("A skydiver opened her parachute some time ago. She now falls at a new, lower constant velocity.",
     "The air resistance on her equals her weight, the same size as before the parachute opened.",
     (("The air resistance on her is greater than her weight, because the parachute is open.",
       "drag stays greater than the weight with the parachute open",
       ("The drag is greater than the weight only just after the parachute opens, while she slows. As "
       "her speed falls the drag falls, until it equals her weight again.")),
      ("The air resistance on her is less than before the parachute opened, because she is slower.",
       "less speed, so less drag at the new terminal velocity",
       ("At both terminal velocities the drag equals her weight. The parachute's large area gives that "
       "much drag at a lower speed.")),
      ("Her acceleration is upwards, because the parachute is open.", "acceleration upwards",
       ("Her acceleration was upwards just after the parachute opened, while she slowed down. Now her "
       "velocity is constant, so her acceleration is zero.")))),
    ("A small stone sinks through the water of a deep lake at its terminal velocity.",
     "The drag of the water and the upthrust together equal the weight of the stone.",
     (("The drag of the water equals the weight of the stone.", "upthrust forgotten",
       ("In water the upthrust acts upwards too. At terminal velocity weight = drag + upthrust, so the "
       "drag is less than the weight.")),
      ("There is no drag on the stone, because its acceleration is zero.", *_NO_DRAG),
      ("The stone's acceleration is 9.81 m s<sup>−2</sup>, because nothing holds it up.",
       *_G_WHILE_FALLING))),
)


def terminal_velocity_choice(situation: float = 0) -> Question:
    """Paper 1 style, conceptual: what is true at a terminal velocity. The wrong options are the
    notes' misconceptions; the key's letter moves with the situation."""
    index = int(situation)
    what, right, wrong = _AT_TERMINAL[index]
    place = index % len(OPTION_LETTERS)
    rows = [Option(text, name, feedback) for text, name, feedback in wrong]
    rows.insert(place, Option(right))
    return Question(
        key="terminal-velocity-choice",
        text=what,
        givens=(),
        parts=(ChoicePart("Which statement is correct?", tuple(rows), OPTION_LETTERS[place],
                          revisit="At terminal velocity the velocity is constant, so the acceleration "
                                  "and the resultant force are zero: weight = drag (+ upthrust in a "
                                  "liquid).", see="skydiver"),),
        mark_scheme=(Mark(f"{OPTION_LETTERS[place]}: {right}", "B1"),),
    )


#: Something moving faster than the speed its drag can hold (a parachute opens, it enters water):
#: (situation, whose deceleration, the event, why it decelerates, the resultant force, how it ends).
_SLOWING = (
    (("A skydiver is falling at terminal velocity when she opens her parachute. She slows down and "
     "then falls at a lower constant velocity."),
     "her", "the parachute opens",
     ("The drag is greater than her weight, so the resultant force on her is upwards, against her "
     "velocity: she decelerates (a = F / m)"),
     "the resultant force (drag − weight)",
     ("until the drag equals her weight again: the resultant force is zero and she falls at a new, "
     "lower terminal velocity")),
    (("A drag-racing car crosses the finish line of a straight, level track at high speed. The engine "
     "is switched off and a braking parachute opens behind the car."),
     "the car's", "the parachute opens",
     ("Along the track the drag (with a little friction) is the only force, backwards: the weight acts "
     "vertically and is balanced by the normal contact force of the track. So the drag is the "
     "resultant force and the car decelerates (a = F / m)"),
     "the resultant force (the drag)",
     ("towards zero as the car slows: with no forward force for the drag to balance, and no weight "
     "along the level track, there is no terminal velocity (the brakes stop the car)")),
    (("A heavy steel ball is thrown downwards into a deep lake. It enters the water much faster than "
     "its terminal velocity in water, and then sinks at a lower constant velocity."),
     "the ball's", "it enters the water",
     ("The drag of the water and the upthrust together are greater than the weight, so the resultant "
     "force is upwards, against its velocity: it decelerates (a = F / m)"),
     "the resultant force (drag + upthrust − weight; the upthrust and the weight stay the same)",
     ("until drag + upthrust = weight: the resultant force is zero and the ball sinks at its (lower) "
     "terminal velocity")),
    (("A space capsule returning to the Earth falls through the lower atmosphere at a steady speed. "
     "Its main parachutes then open, and it slows to a lower steady speed for landing."),
     "the capsule's", "the parachutes open",
     ("The drag is greater than the capsule's weight, so the resultant force is upwards, against its "
     "velocity: it decelerates (a = F / m)"),
     "the resultant force (drag − weight)",
     ("until the drag equals the weight again: the resultant force is zero and the capsule falls at a "
     "new, lower terminal velocity")),
)


def deceleration_largest_explained(situation: float = 0) -> Question:
    """Describe and explain: why the deceleration is largest just after a parachute opens (or a
    body enters water), and then decreases (notes, points D to E: the drag is largest when the
    speed is largest; as the speed falls the drag falls, so the deceleration decreases)."""
    what, whose, event, decelerates, resultant, end = _SLOWING[int(situation)]
    return Question(
        key="deceleration-largest-explained",
        text=what,
        givens=(),
        parts=(ExplainPart(
            f"Explain why {whose} deceleration is largest just after {event}, and describe and explain "
            "how the deceleration changes after that.",
            f"Drag increases with speed. Just after {event} the speed is at its largest, so the drag is "
            f"at its largest. {decelerates}. As the speed falls, the drag falls, so {resultant} "
            f"decreases and the deceleration decreases, {end}."),),
        mark_scheme=(
            Mark(f"The drag increases with speed, and the speed is largest just after {event}, so the "
                 "drag is largest then", "B1", "a"),
            Mark(decelerates, "B1", "a"),
            Mark(f"As the speed falls the drag falls, so {resultant} decreases, so the deceleration "
                 "decreases", "M1", "a"),
            Mark(f"The deceleration decreases {end}", "A1", "a"),
        ),
    )


def falling_with_drag_constant(mass: float = 80.0, k: float = 0.25, speed: float = 30.0) -> Question:
    """A skydiver with drag D = k v² (k given): the drag and the acceleration at a speed, and the
    terminal velocity from k v² = m g (notes: drag grows with speed; a = resultant / mass; with a
    given drag formula, set it equal to the weight)."""
    d = drag_force(k, speed)
    w_ = weight(mass)
    if d >= w_:
        raise ValueError(f"speed must be below the terminal velocity, so that the drag {n(d, 3)} N is less "
                         f"than the weight {n(w_, 3)} N (got speed={speed!r})")
    a = falling_acceleration(mass, d)
    v_t = terminal_velocity(mass, k)
    m, kk, v = n(mass, 2), n(k, 2), n(speed, 2)
    return Question(
        key="falling-with-drag-constant",
        text=(f"A skydiver of mass {m} kg falls vertically before opening her parachute. The air "
              f"resistance on her is D = kv<sup>2</sup>, where v is her speed and k = {kk} kg m<sup>−1</sup>. "
              f"(a) Calculate the air resistance when her speed is {v} {PER_S}. (b) Calculate the size of "
              "her acceleration at that speed. (c) Calculate her terminal velocity."),
        givens=(Given("mass", mass, "kg", 2), Given("k", k, "kg m^-1", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part(f"air resistance at {v} m s⁻¹", d, "N", "force", shown_sig_figs=3,
                 revisit="D = kv²: square the speed, then multiply by k.",
                 mistakes=(
                     Mistake("speed not squared", k * speed,
                             f"You multiplied k by the speed. D = kv²: square the speed first ({v}²)."),
                     Mistake("divided by k", speed**2 / k,
                             "You divided by k. D = kv²: multiply the square of the speed by k."),
                 )),
            Part("size of her acceleration at that speed", a, "m s^-2", "acceleration", units=M_S2,
                 shown_sig_figs=3,
                 working=(Step("air resistance", d, "N"),),
                 answer_from=lambda d_: falling_acceleration(mass, d_),
                 answer_for_g=lambda g: falling_acceleration(mass, d, g=g),
                 ecf=Ecf((mass_symbol * g_symbol - a_answer) / mass_symbol,
                         {"mass": mass, "g_earth": G_EARTH}),
                 revisit="Resultant force = weight − air resistance; a = resultant force / mass.",
                 mistakes=(
                     Mistake("drag used as the resultant force", acceleration(d, mass),
                             "You used the air resistance as the resultant force. The weight still "
                             "acts: resultant = mg − D."),
                     Mistake("drag added to the weight", acceleration(w_ + d, mass),
                             "The weight acts downwards and the air resistance upwards: subtract them, "
                             "do not add."),
                     Mistake("acceleration of free fall", G_EARTH,
                             "g is her acceleration only when there is no air resistance. At this speed "
                             "the resultant force is mg − D."),
                 ), see="skydiver"),
            Part("terminal velocity", v_t, "m s^-1", "velocity", units=M_S, shown_sig_figs=3,
                 answer_for_g=lambda g: terminal_velocity(mass, k, g=g),
                 revisit="At terminal velocity the drag equals the weight: kv² = mg, so v = √(mg / k).",
                 mistakes=(
                     Mistake("square root forgotten", w_ / k,
                             "That is v², not v: kv² = mg gives v² = mg / k; take the square root."),
                     Mistake("mass used instead of weight", terminal_velocity(mass, k, g=1.0),
                             "You used the mass for the weight. The drag equals the weight, mg, in N."),
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"D = kv<sup>2</sup> = {kk} × {v}<sup>2</sup>", "C1", "a"),
            Mark(f"= {n(d, 3)} N", "A1", "a"),
            Mark(f"resultant force = mg − D = {m} × {n(G_EARTH, 3)} − {working(d)} = {working(w_ - d)} N",
                 "C1", "b"),
            Mark(f"a = F / m = {working(w_ - d)} / {m}", "C1", "b"),
            Mark(f"= {n(a, 3)} {PER_S2} (downwards)", "A1", "b"),
            Mark(f"At terminal velocity kv<sup>2</sup> = mg, so v = √({working(w_)} / {kk})", "C1", "c"),
            Mark(f"= {n(v_t, 3)} {PER_S}", "A1", "c"),
        ),
    )


#: Densities a solid metal sphere may have, g cm^-3 (aluminium to lead).
_METAL_DENSITY = (2.7, 11.3)


def sphere_in_liquid(grams: float = 6.3, volume_cm3: float = 0.80, density: float = 920.0) -> Question:
    """A metal sphere sinking through a liquid: the upthrust, the viscous drag at terminal velocity,
    and the acceleration at half the terminal velocity when the drag is proportional to the speed
    (notes: in a liquid weight = drag + upthrust; upthrust ρgV with the liquid's density)."""
    if not _METAL_DENSITY[0] <= grams / volume_cm3 <= _METAL_DENSITY[1]:
        raise ValueError(f"grams / volume_cm3 must be a metal's density, {_METAL_DENSITY[0]} to "
                         f"{_METAL_DENSITY[1]} g cm^-3 (got grams={grams!r}, volume_cm3={volume_cm3!r})")
    mass, volume = grams / 1000, volume_cm3 * 1e-6
    w_ = weight(mass)
    u = upthrust(density, volume)
    d = drag_at_terminal_velocity(w_, u)
    a = falling_acceleration(mass, d / 2, upthrust=u)
    gr, vol, rho = n(grams, 2), n(volume_cm3, 2), n(density, 3)
    return Question(
        key="sphere-in-liquid",
        text=(f"A metal sphere of mass {gr} g and volume {vol} cm<sup>3</sup> sinks through a liquid of "
              f"density {rho} kg m<sup>−3</sup> and reaches a terminal velocity. The viscous drag on the "
              "sphere is proportional to its speed. (a) Calculate the upthrust on the sphere. "
              "(b) Calculate the viscous drag on it at terminal velocity. (c) Calculate the size of its "
              "acceleration when its speed is half its terminal velocity."),
        givens=(Given("mass", grams, "g", 2), Given("volume", volume_cm3, "cm^3", 2),
                Given("density of the liquid", density, "kg m^-3", 3)),
        parts=(
            Part("upthrust on the sphere", u, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g: upthrust(density, volume, g=g),
                 revisit="Upthrust = ρgV, with the density of the liquid and the volume in m³.",
                 mistakes=(
                     Mistake("volume left in cm³", upthrust(density, volume_cm3),
                             f"You used the volume in cm³. Convert it to m³ first: {vol} cm³ = "
                             f"{vol} × 10⁻⁶ m³.", kind="slip"),
                     Mistake("sphere's density used, not the liquid's", w_,
                             "That is the sphere's weight. The upthrust uses the density of the "
                             "liquid: ρgV."),
                 ), see="skydiver"),
            Part("viscous drag at terminal velocity", d, "N", "force", shown_sig_figs=3,
                 working=(Step("weight of the sphere", w_, "N"), Step("upthrust", u, "N")),
                 answer_from=lambda w1, u1: drag_at_terminal_velocity(w1, u1),
                 answer_for_g=lambda g: drag_at_terminal_velocity(weight(mass, g=g),
                                                                  upthrust(density, volume, g=g)),
                 ecf=Ecf(mass_symbol * g_symbol - a_answer, {"mass": mass, "g_earth": G_EARTH}),
                 revisit="At terminal velocity the resultant force is zero: weight = drag + upthrust, "
                         "so drag = weight − upthrust.",
                 mistakes=(
                     Mistake("upthrust forgotten", w_,
                             "That is the weight. In a liquid the upthrust helps to hold the sphere up: "
                             "drag = weight − upthrust."),
                     Mistake("upthrust added to the weight", w_ + u,
                             "The upthrust acts upwards, with the drag: weight = drag + upthrust, so "
                             "subtract it."),
                     Mistake("mass left in grams", weight(grams) - u,
                             f"You used the mass in g. Convert to kg first: {gr} g = {n(mass, 2)} kg.", kind="slip"),
                 ), see="skydiver"),
            Part("size of the acceleration at half the terminal velocity", a, "m s^-2", "acceleration",
                 units=M_S2, shown_sig_figs=3,
                 working=(Step("drag at half the terminal velocity", d / 2, "N"), Step("upthrust", u, "N")),
                 answer_from=lambda d1, u1: falling_acceleration(mass, d1, upthrust=u1),
                 answer_for_g=lambda g: falling_acceleration(
                     mass, drag_at_terminal_velocity(weight(mass, g=g), upthrust(density, volume, g=g)) / 2,
                     g=g, upthrust=upthrust(density, volume, g=g)),
                 ecf=Ecf((mass_symbol * g_symbol - a_answer - b_answer / 2) / mass_symbol,
                         {"mass": mass, "g_earth": G_EARTH}),
                 # or: W - U = D at terminal velocity, so the resultant at half the speed is D / 2
                 ecf_also=(Ecf(b_answer / (2 * mass_symbol), {"mass": mass}),),
                 revisit="The drag is proportional to the speed, so at half the speed it is half the "
                         "terminal drag. Resultant force = weight − upthrust − drag; a = F / m.",
                 mistakes=(
                     Mistake("upthrust forgotten", falling_acceleration(mass, d / 2),
                             "The upthrust still acts upwards: resultant = weight − upthrust − drag."),
                     Mistake("acceleration of free fall", G_EARTH,
                             "g is the acceleration with no drag and no upthrust. Here both act "
                             "upwards: resultant = weight − upthrust − drag."),
                 ), see="skydiver"),
        ),
        mark_scheme=_sphere_in_liquid_scheme(mass, w_, u, d, a, rho, vol),
    )


def _sphere_in_liquid_scheme(mass: float, w_: float, u: float, d: float, a: float, rho: str,
                             vol: str) -> tuple[Mark, ...]:
    """sphere_in_liquid's mark scheme: the upthrust, the terminal drag (W − U) and the acceleration at
    half the speed, each step's numbers printed with the figures its result needs."""
    # the upthrust and the half drag with the figures the steps' results need (W is exact)
    (u_b,) = enough_figures((u,), lambda u1: w_ - u1, n(d, 3))
    (u_c, _) = enough_figures((u, d / 2), lambda u1, d1: (w_ - u1 - d1) / mass, n(a, 3))
    u_b = u_c = max(u_b, u_c, key=len)  # one printing of U in both steps...
    # ...and the half drag printed with the figures that this U needs (a longer U moves the result)
    (half_d,) = enough_figures((d / 2,), lambda d1: (w_ - float(u_c) - d1) / mass, n(a, 3))
    return (
        Mark(f"U = ρgV = {rho} × {n(G_EARTH, 3)} × {vol} × 10<sup>−6</sup>", "C1", "a"),
        Mark(f"= {n(u, 3)} N", "A1", "a"),
        Mark(f"W = mg = {n(mass, 2)} × {n(G_EARTH, 3)} = {working(w_)} N", "C1", "b"),
        Mark("At terminal velocity weight = drag + upthrust, so drag = W − U "
             f"= {working(w_)} − {u_b}", "C1", "b"),
        Mark(f"= {n(d, 3)} N", "A1", "b"),
        Mark(f"At half the speed the drag is half: {half_d} N", "C1", "c"),
        Mark(f"a = (W − U − D) / m = ({working(w_)} − {u_c} − {half_d}) / {n(mass, 2)}",
             "C1", "c"),
        Mark(f"= {n(a, 3)} {PER_S2} (downwards)", "A1", "c"),
    )


# ---------------------------------------------------------------- reading a graph

b_answer, c_answer, gravity_symbol = sympy.symbols("b c gravity")
g_symbol = sympy.Symbol("g_earth")
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
                      revisit="The terminal velocity is where the curve levels off: read that value.", see="skydiver"),
            Part("drag force at terminal velocity", drag, "N", "force", shown_sig_figs=3, asks="state",
                 answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At terminal velocity the resultant force is zero, so the drag equals the weight, mg.",
                 mistakes=(
                     Mistake("mass given as force", mass,
                             f"{m} is her mass in kg. The drag equals her weight, mg."),
                     Mistake("drag is zero", 0.0,
                             "At terminal velocity the resultant force is zero, not the drag: the drag "
                             "has grown to equal the weight."),
                 ), see="skydiver"),
            Part("value of k", k, "kg m^-1", "drag constant", units="kg m^-1", shown_sig_figs=2,
                 answer_for_g=lambda g: drag_constant_for_terminal_velocity(mass, terminal, g=g),
                 ecf=Ecf(b_answer / a_answer**2, {}),
                 readings=(Reading("terminal velocity", terminal, graph.value_division / 2),),
                 answer_from_readings=lambda v: drag_constant_for_terminal_velocity(mass, v),
                 revisit="At terminal velocity kv² = mg, so k = mg / v².",
                 mistakes=(
                     Mistake("speed not squared", drag / terminal,
                             "You divided by v. The drag is kv², so k = mg / v²."),
                     Mistake("mass, not weight", mass / terminal**2,
                             "You used the mass. The drag equals the weight, mg, in N."),
                 ), see="skydiver"),
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
    # the scheme works (c) from the readings as printed (the key, from the curve, is accepted too)
    read_speed, read_terminal = reading(speed, 0.25), reading(terminal, 0.25)
    from_readings = G_EARTH * (1 - float(read_speed) ** 2 / float(read_terminal) ** 2)
    also = f" (allow {n(a, 2)})" if n(a, 2) != n(from_readings, 2) else ""  # the key, from the curve
    return Question(
        key="graph-ball-acceleration",
        text=(f"A ball of mass {m} kg is dropped from rest from a high balloon. The graph shows its "
              "velocity as it falls. The air resistance on it is proportional to the square of its "
              f"speed. Take g = 9.81 {PER_S2}. {reading_rule(0.25, PER_S)}"),
        givens=(Given("mass", mass, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("terminal velocity", terminal, "m s^-1", "velocity", units=M_S, tolerance=0.25,
                      revisit="The terminal velocity is where the curve levels off: read that value.", see="skydiver"),
            GraphPart(f"velocity at {t} s", speed, "m s^-1", "velocity", units=M_S, tolerance=0.25, revisit=f"Go up from {t} s on the time axis to the curve, then across."),
            Part(f"acceleration at {t} s", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 answer_for_g=lambda g: acceleration(
                     weight(mass, g=g) - drag_force(drag_constant_for_terminal_velocity(mass, terminal, g=g), speed),
                     mass),
                 ecf=Ecf(gravity_symbol * (1 - b_answer**2 / a_answer**2), {"gravity": G_EARTH}),
                 readings=(Reading("terminal velocity", terminal, graph.value_division / 2),
                           Reading(f"velocity at {t} s", speed, graph.value_division / 2)),
                 answer_from_readings=lambda top, now: acceleration(
                     weight(mass) - drag_force(drag_constant_for_terminal_velocity(mass, top), now), mass),
                 revisit="Resultant force = weight − drag, with drag = kv² and k = mg / vₜ² (vₜ the "
                         "terminal velocity); so a = g(1 − v² / vₜ²).",
                 mistakes=(
                     Mistake("drag left out", G_EARTH,
                             "That is g, the acceleration with no drag. The air resistance is not zero "
                             "while the ball moves: resultant force = weight − drag."),
                     Mistake("drag taken as proportional to v", G_EARTH * (1 - speed / terminal),
                             "You took the drag as proportional to v. It is proportional to v², so "
                             "a = g(1 − v² / vₜ²)."),
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"{reading(terminal, 0.25)} {PER_S}", "B1", "a"),
            Mark(f"{reading(speed, 0.25)} {PER_S}", "B1", "b"),
            Mark("at terminal velocity kv<sub>t</sub><sup>2</sup> = mg, so drag = mg v<sup>2</sup> / "
                 "v<sub>t</sub><sup>2</sup> and a = (mg − drag) / m", "C1", "c"),
            Mark(f"a = 9.81 × (1 − {read_speed}<sup>2</sup> / {read_terminal}<sup>2</sup>) "
                 f"= {n(from_readings, 2)} {PER_S2}{also}", "A1", "c"),
        ),
    )


# ---------------------------------------------------------------- a drag law given in the question

#: The drag laws the papers give, by the power of v (6 pi eta r v is a law of the first kind,
#: (1/2) C rho A v² one of the second): how the question writes it, in plain text (feedback), and the unit of its
#: constant k (as typed, in the text format, and its usual forms).
_DRAG_LAWS = {
    1: ("<em>F</em> = <em>kv</em>", "F = kv", "kg s^-1", "kg s<sup>−1</sup>", "kg s^-1 (N s m^-1)"),
    2: ("<em>F</em> = <em>kv</em><sup>2</sup>", "F = kv²", "kg m^-1", "kg m<sup>−1</sup>", "kg m^-1 (N s^2 m^-2)"),
}
speed_symbol = sympy.Symbol("speed")


def _speed_power(speed_text: str, power: int) -> str:
    """v or v² as a scheme writes it with the speed's number: "12" or "12<sup>2</sup>"."""
    return speed_text if power == 1 else f"{speed_text}<sup>{power}</sup>"


#: Densities of the balls the drag-law questions drop through air, kg m^-3: a table-tennis ball
#: (about 80) to solid rubber (about 1500); a golf ball is 1130.
_BALL_IN_AIR_DENSITY = (80.0, 1500.0)
#: Under F = kv a heavier ball's terminal speed is predicted as v_A × m_B / m_A; the bank keeps it
#: within this fraction of what a ball of that size and mass reaches (quadratic drag, the model).
_LINEAR_LAW_SPREAD = 0.3


def _ball_terminal_speed(grams: float, diameter_cm: float, name: str = "grams") -> float:
    """The terminal speed, m s^-1, that a ball of this mass and diameter reaches falling through
    still air: D = (1/2) C ρ A v² with a sphere's C (models.fluids), so the story's numbers agree
    with its ball. Raises ValueError for a ball no real ball is (its density, mass / volume)."""
    diameter = diameter_cm / 100
    density = grams / 1000 / sphere_volume(diameter / 2)
    if not _BALL_IN_AIR_DENSITY[0] <= density <= _BALL_IN_AIR_DENSITY[1]:
        raise ValueError(f"{name} and diameter_cm must give a ball of {_BALL_IN_AIR_DENSITY[0]:g} to "
                         f"{_BALL_IN_AIR_DENSITY[1]:g} kg m^-3, a table-tennis ball to solid rubber (got "
                         f"{name}={grams!r}, diameter_cm={diameter_cm!r}: {n(density, 2)} kg m^-3)")
    return terminal_velocity(grams / 1000, sphere_drag_constant(diameter))


def _printed_speed(speed: float) -> float:
    """A terminal speed as the question prints it, to 2 s.f. (the keys work from that number)."""
    return float(round_number(speed, 2))


def drag_law_constant(power: float = 2, grams: float = 45.0, diameter_cm: float = 4.3) -> Question:
    """A drag law given in the question (issue 25): the constant k of F = kvⁿ from a terminal
    speed. At terminal speed the resultant force is zero, so kvₜⁿ = mg and k = mg / vₜⁿ (notes:
    "with a given drag formula ... set it equal to W and solve for v or the constant"). The law
    is F = kv or F = kv² by the variant: the same step, with its own power and unit. The ball's
    terminal speed is the one a ball of its mass and diameter reaches in air (_ball_terminal_speed;
    45 g and 4.3 cm, a golf ball, 33 m s⁻¹), whichever law the question models it with.

    Marks: 9702/02/M/J/06 gives the drag law (F = crv) and credits "mg = crv_T"; 9702/21/M/J/16
    Q3(a)(i) gives "force (= mg = 0.15 × 9.81) = 1.5 N" one mark on its own (B1 here), and Q3(b)(ii)
    a C1 for the equation with its numbers before the A1 for the answer."""
    power = int(power)
    law, plain_law, k_unit, k_unit_text, k_units = _DRAG_LAWS[power]
    speed = _printed_speed(_ball_terminal_speed(grams, diameter_cm))
    mass = grams / 1000
    drag = weight(mass)  # at terminal speed the resultant force is zero
    k = power_law_constant(drag, speed, power=power)
    gr, v, d = n(grams, 2), n(speed, 2), n(diameter_cm, 2)
    other = 3 - power  # the other law's power: the speed squared when it should not be, or not
    return Question(
        key="drag-law-constant",
        text=(f"A ball of mass {gr} g and diameter {d} cm falls vertically through still air. In a model of its "
              "fall, the "
              f"air resistance on it is {law}, where <em>v</em> is its speed and <em>k</em> is a constant. "
              f"The ball reaches a terminal speed of {v} {PER_S}. (a) State the air resistance on the ball "
              "at its terminal speed. (b) Calculate <em>k</em>."),
        givens=(Given("mass", grams, "g", 2), Given("diameter", diameter_cm, "cm", 2),
                Given("terminal speed", speed, "m s^-1", 2)),
        parts=(
            Part("air resistance at the terminal speed", drag, "N", "force", shown_sig_figs=3, asks="state",
                 answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At terminal speed the resultant force is zero, so the air resistance equals the "
                         "weight, mg (with the mass in kg).",
                 mistakes=(
                     Mistake("mass given as the force", mass,
                             f"{n(mass, 2)} kg is the ball's mass. The air resistance equals its weight, mg."),
                     Mistake("mass left in grams", weight(grams),
                             f"You used the mass in g. Convert it to kg first: {gr} g = {n(mass, 2)} kg.",
                             kind="slip"),
                     Mistake("air resistance is zero", 0.0,
                             "At terminal speed the resultant force is zero, not the air resistance: it has "
                             "grown to equal the weight."),
                 ), see="skydiver"),
            Part("value of k", k, k_unit, "drag constant", units=k_units, shown_sig_figs=2,
                 # k = mg / vⁿ: g = 10 here too (after (a)'s own g = 10 it is carried forward: ecf)
                 answer_for_g=lambda g: power_law_constant(weight(mass, g=g), speed, power=power),
                 ecf=Ecf(a_answer / speed_symbol**power, {"speed": speed}),
                 revisit=f"At terminal speed {plain_law} equals the weight mg, so k = mg / "
                         f"{'v' if power == 1 else 'v²'}.",
                 mistakes=(
                     Mistake("speed not squared" if power == 2 else "speed squared",
                             power_law_constant(drag, speed, power=other),
                             "You divided by v. The law is F = kv², so k = mg / v²." if power == 2 else
                             "You divided by v². The law is F = kv, so k = mg / v."),
                     Mistake("mass used, not the weight", power_law_constant(mass, speed, power=power),
                             "You used the mass. The air resistance equals the weight, mg, in N."),
                     Mistake("mass left in grams", power_law_constant(weight(grams), speed, power=power),
                             f"You used the mass in g. Convert it to kg first: {gr} g = {n(mass, 2)} kg.",
                             kind="slip"),
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"At terminal speed the resultant force is zero: F = mg = {n(mass, 2)} × {n(G_EARTH, 3)} "
                 f"= {n(drag, 3)} N", "B1", "a"),
            Mark(f"k = mg / {_speed_power('v', power)} = {working(drag)} / {_speed_power(v, power)}", "C1", "b"),
            Mark(f"= {n(k, 2)} {k_unit_text}", "A1", "b"),
        ),
    )


def _two_balls_speeds(power: int, grams_a: float, grams_b: float, diameter_cm: float) -> tuple[float, float]:
    """A's terminal speed as printed, the one a ball of its mass and diameter reaches in air
    (_ball_terminal_speed), and B's as the law predicts it from A's. Under F = kv the prediction
    must stay within _LINEAR_LAW_SPREAD of what B itself reaches (issue 37: 65–86 m s⁻¹ before);
    a variant that does not is refused, by name."""
    if grams_b <= grams_a:
        raise ValueError(f"grams_b must be more than grams_a: B is the heavier ball, which passes A's "
                         f"terminal speed on its way to its own (got grams_a={grams_a!r}, grams_b={grams_b!r})")
    speed_a = _printed_speed(_ball_terminal_speed(grams_a, diameter_cm, "grams_a"))
    speed_b = speed_a * terminal_velocity_ratio(grams_b / grams_a, power=power)
    reached = _ball_terminal_speed(grams_b, diameter_cm, "grams_b")
    if abs(speed_b / reached - 1) > _LINEAR_LAW_SPREAD:
        raise ValueError(f"grams_b / grams_a = {n(grams_b / grams_a, 2)} makes {_DRAG_LAWS[power][1]} predict "
                         f"{n(speed_b, 2)} m s^-1 for B, where a ball of its size and mass reaches {n(reached, 2)} "
                         f"m s^-1: keep the prediction within {n(100 * _LINEAR_LAW_SPREAD, 2)} % (got "
                         f"grams_a={grams_a!r}, grams_b={grams_b!r})")
    return speed_a, speed_b


def drag_law_terminal_ratio(power: float = 2, grams_a: float = 20.0, grams_b: float = 80.0,
                            diameter_cm: float = 6.0) -> Question:
    """A ratio from a drag law given in the question (issue 25): two balls of one size and shape
    (one k), F = kvⁿ. At terminal speed kvⁿ = mg, so vₜ ∝ m^(1/n): four times the mass falls
    twice as fast with F = kv², four times as fast with F = kv (notes: same size and shape,
    heavier one -> higher terminal velocity). Then the heavier ball's acceleration as it passes
    the lighter one's terminal speed: the drag there is the lighter ball's weight, so
    a = (m_B g − m_A g) / m_B, whichever the law. The speeds: _two_balls_speeds.

    Marks: 9702/02/M/J/06 sets the given drag law equal to the weight (mg = crv_T); 9702/21/M/J/16
    Q3(b)(ii) gives C1 for the working with its numbers, then A1 for the answer."""
    power = int(power)
    law = _DRAG_LAWS[power][0]
    speed_a, speed_b = _two_balls_speeds(power, grams_a, grams_b, diameter_cm)
    m_a, m_b = grams_a / 1000, grams_b / 1000
    ratio = grams_b / grams_a
    w_a, w_b = weight(m_a), weight(m_b)
    a = falling_acceleration(m_b, w_a)  # at A's terminal speed the drag on B is A's weight
    ga, gb, va, d = n(grams_a, 2), n(grams_b, 2), n(speed_a, 2), n(diameter_cm, 2)
    root = f"√({gb} / {ga})" if power == 2 else f"({gb} / {ga})"
    forgot_root = "square root forgotten" if power == 2 else "square root taken"
    factor = "√(m_B / m_A)" if power == 2 else "m_B / m_A"  # what B's speed is A's times
    return Question(
        key="drag-law-terminal-ratio",
        text=(f"Two balls A and B have the same shape and the same diameter, {d} cm, so the air resistance "
              f"on each is {law}, "
              "where <em>v</em> is its speed, with the same constant <em>k</em>. Ball A has mass "
              f"{ga} g and falls vertically at a terminal speed of {va} {PER_S}. Ball B has mass {gb} g and "
              "is dropped from rest. Calculate (a) the terminal speed of B and (b) the size of B's "
              f"acceleration at the moment its speed is {va} {PER_S}."),
        givens=(Given("mass of A", grams_a, "g", 2), Given("mass of B", grams_b, "g", 2),
                Given("diameter", diameter_cm, "cm", 2), Given("terminal speed of A", speed_a, "m s^-1", 2)),
        parts=(
            Part("terminal speed of B", speed_b, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 revisit=(f"At terminal speed {'kv²' if power == 2 else 'kv'} = mg, so "
                          f"{'v²' if power == 2 else 'v'} is proportional to the mass: "
                          f"{'v_B = v_A √(m_B / m_A)' if power == 2 else 'v_B = v_A × m_B / m_A'}."),
                 mistakes=(
                     Mistake(forgot_root, speed_a * terminal_velocity_ratio(ratio, power=3 - power),
                             "The law is F = kv², so v² is proportional to the mass: take the square root "
                             "of the ratio of the masses." if power == 2 else
                             "The law is F = kv, so v itself is proportional to the mass: no square root."),
                     Mistake("masses the wrong way up", speed_a * terminal_velocity_ratio(1 / ratio, power=power),
                             f"You divided A's terminal speed by {factor}: the masses the wrong way up, so "
                             "B came out slower than A. B is heavier, so it needs more air resistance, and so "
                             f"a higher speed, to balance its weight: multiply A's terminal speed by {factor}."),
                     Mistake("same terminal speed as A", speed_a,
                             "Without air resistance both would fall alike. With it, the heavier ball "
                             "needs a larger drag, so a higher speed, before the drag equals its weight."),
                 ), see="skydiver"),
            Part(f"size of B's acceleration at {va} m s⁻¹", a, "m s^-2", "acceleration", units=M_S2,
                 shown_sig_figs=2,
                 working=(Step("air resistance on B (A's weight)", w_a, "N"),),
                 answer_from=lambda drag_: falling_acceleration(m_b, drag_),
                 answer_for_g=lambda g: falling_acceleration(m_b, weight(m_a, g=g), g=g),
                 revisit=f"At {va} m s⁻¹ the air resistance on B is what it is on A at that speed: A's "
                         "weight. Resultant force = B's weight − air resistance; a = F / m.",
                 mistakes=(
                     Mistake("air resistance left out", G_EARTH,
                             "That is g, the acceleration with no air resistance. At this speed the air "
                             "resistance on B equals A's weight."),
                     Mistake("A's weight used as the resultant force", acceleration(w_a, m_b),
                             "You used the air resistance as the resultant force. B's weight still acts: "
                             "resultant = B's weight − air resistance."),
                     Mistake("air resistance added to the weight", acceleration(w_b + w_a, m_b),
                             "The weight acts downwards and the air resistance upwards: subtract them."),
                 ), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"At terminal speed {'kv<sup>2</sup>' if power == 2 else 'kv'} = mg, so "
                 f"{_speed_power('v', power)} is proportional to m", "C1", "a"),
            Mark(f"v<sub>B</sub> = {va} × {root} = {n(speed_b, 2)} {PER_S}", "A1", "a"),
            Mark(f"At {va} {PER_S} the air resistance on B equals A's weight, {n(m_a, 2)} × {n(G_EARTH, 3)} "
                 f"= {working(w_a)} N", "C1", "b"),
            Mark(f"a = ({working(w_b)} − {working(w_a)}) / {n(m_b, 2)}", "C1", "b"),
            Mark(f"= {n(a, 2)} {PER_S2} (downwards)", "A1", "b"),
        ),
    )


#: Densities a ball that sinks in the drag-law questions may have, kg m^-3 (glass to lead).
_BALL_DENSITY = (2500.0, 11300.0)
viscosity_symbol, radius_symbol = sympy.symbols("viscosity radius")


def stokes_terminal_speed(grams: float = 0.11, radius_mm: float = 1.5, density: float = 1260.0,
                          viscosity: float = 1.4) -> Question:
    """A terminal speed from a drag law given in the question (issue 25): Stokes' law
    F = 6πηrv for a small ball sinking through a viscous liquid. At terminal speed
    weight = drag + upthrust, so v = (mg − U) / (6πηr), with U = ρgV and V = 4/3 πr³ (notes:
    "with a given drag formula such as F = 6πηrv, set it equal to W − U and solve for v").

    Marks: 9702/02/M/J/06 gives the law (F = crv) and credits the weight set equal to it with
    the terminal speed (mg = crv_T); 9702/21/M/J/16 Q3(b)(ii) gives a C1 for the working with
    its numbers, then the A1; the upthrust follows sphere-in-liquid (a). Stokes' law holds only in
    creeping flow: a variant whose Reynolds number is not below models.STOKES_REYNOLDS_LIMIT is
    refused (issue 37: it reached 0.997). The working gives the upthrust from the radius in one line
    (a volume printed in ×10ⁿ to 3 s.f. moved the third figure, and to 5 s.f. it was a key value with
    more figures than the book prints), and (b) the upthrust with the figures that give the printed
    answer (enough_figures), as an examiner checks them."""
    radius, mass = radius_mm / 1000, grams / 1000
    volume = sphere_volume(radius)
    if not _BALL_DENSITY[0] <= mass / volume <= _BALL_DENSITY[1]:
        raise ValueError(f"grams and radius_mm must give a ball of glass to lead, {_BALL_DENSITY[0]:g} to "
                         f"{_BALL_DENSITY[1]:g} kg m^-3 (got grams={grams!r}, radius_mm={radius_mm!r})")
    u = upthrust(density, volume)
    k = stokes_constant(viscosity, radius)
    v_t = power_law_terminal_velocity(mass, k, power=1, upthrust=u)
    stokes_reynolds_number(density, v_t, 2 * radius, viscosity)  # raises when the law does not hold
    w_ = weight(mass)
    gr, r, rho, eta = n(grams, 2), n(radius_mm, 2), n(density, 3), n(viscosity, 2)
    (u_b,) = enough_figures((u,), lambda u1: (w_ - u1) / k, n(v_t, 2))
    return Question(
        key="stokes-terminal-speed",
        text=(f"A small ball of mass {gr} g and radius {r} mm is released in a tall tube of a liquid of "
              f"density {rho} kg m<sup>−3</sup>. The viscous drag on the ball is <em>F</em> = 6π<em>ηrv</em>, "
              f"where <em>r</em> is its radius, <em>v</em> its speed and <em>η</em> = {eta} Pa s. The volume of "
              "a sphere is 4/3 π<em>r</em><sup>3</sup>. Calculate (a) the upthrust on the ball and (b) its "
              "terminal speed."),
        givens=(Given("mass", grams, "g", 2), Given("radius", radius_mm, "mm", 2),
                Given("density of the liquid", density, "kg m^-3", 3), Given("viscosity", viscosity, "Pa s", 2)),
        parts=(
            Part("upthrust on the ball", u, "N", "force", shown_sig_figs=3,
                 answer_for_g=lambda g: upthrust(density, volume, g=g),
                 revisit="Upthrust = ρgV, with the density of the liquid and V = 4/3 πr³ (r in m).",
                 mistakes=(
                     Mistake("radius left in mm", upthrust(density, sphere_volume(radius_mm)),
                             f"You used the radius in mm. Convert it to m first: {r} mm = {r} × 10⁻³ m.",
                             kind="slip"),
                     Mistake("diameter used for the radius", upthrust(density, sphere_volume(2 * radius)),
                             f"You used 2 × {r} mm, the diameter. V = 4/3 πr³ with the radius."),
                     Mistake("the ball's weight", w_,
                             "That is the ball's weight. The upthrust uses the density of the liquid: ρgV."),
                 ), see="skydiver"),
            Part("terminal speed of the ball", v_t, "m s^-1", "speed", units=M_S, shown_sig_figs=2,
                 # g = 10 in mg and in U alike; with (a)'s own g = 10 upthrust carried into it, ecf
                 answer_for_g=lambda g: power_law_terminal_velocity(mass, k, power=1, g=g,
                                                                    upthrust=upthrust(density, volume, g=g)),
                 ecf=Ecf((mass_symbol * g_symbol - a_answer) / (6 * sympy.pi * viscosity_symbol * radius_symbol),
                         {"mass": mass, "g_earth": G_EARTH, "viscosity": viscosity, "radius": radius}),
                 revisit="At terminal speed the resultant force is zero: mg = 6πηrv + U, so "
                         "v = (mg − U) / (6πηr), with r in m.",
                 mistakes=_stokes_speed_mistakes(mass, k, w_, u, viscosity, radius_mm, r),
                 see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"U = ρgV with V = 4/3 πr<sup>3</sup>: U = {rho} × {n(G_EARTH, 3)} × 4/3 π × "
                 f"({r} × 10<sup>−3</sup>)<sup>3</sup>", "C1", "a"),
            Mark(f"= {n(u, 3)} N", "A1", "a"),
            Mark("At terminal speed weight = drag + upthrust: mg = 6πηrv + U", "C1", "b"),
            Mark(f"v = ({n(mass, 2)} × {n(G_EARTH, 3)} − {u_b}) / (6π × {eta} × {r} × 10<sup>−3</sup>)",
                 "C1", "b"),
            Mark(f"= {n(v_t, 2)} {PER_S}", "A1", "b"),
        ),
    )



def _stokes_speed_mistakes(mass: float, k: float, w_: float, u: float, viscosity: float, radius_mm: float,
                           r: str) -> tuple[Mistake, ...]:
    """stokes_terminal_speed's wrong terminal speeds: the upthrust left out or added, the radius in mm
    or the diameter in 6πηr (k is 6πηr with the radius in m)."""
    radius = radius_mm / 1000
    return (
        Mistake("upthrust forgotten", power_law_terminal_velocity(mass, k, power=1),
                "You set the drag equal to the weight. In a liquid the upthrust helps to hold "
                "the ball up: weight = drag + upthrust."),
        Mistake("upthrust added to the weight", (w_ + u) / k,
                "The upthrust acts upwards, with the drag: weight = drag + upthrust, so subtract "
                "it from the weight."),
        Mistake("radius left in mm", (w_ - u) / stokes_constant(viscosity, radius_mm),
                f"You used the radius in mm in 6πηr. Convert it to m first: {r} mm = {r} × 10⁻³ m.",
                kind="slip"),
        Mistake("diameter used for the radius", (w_ - u) / stokes_constant(viscosity, 2 * radius),
                f"You used 2 × {r} mm, the diameter. Stokes' law uses the radius."),
    )

#: The density of water, kg m^-3, as the papers give it (9702/22/M/J/11 Q2(a)(ii)).
_WATER_DENSITY = 1000.0


def _raindrop_acceleration_mistakes(mass: float, drop_weight: float, drag: float, radius: float) -> tuple:
    """The acceleration of a drop under a linear drag, worked wrongly."""
    return (
        Mistake("the drag left out", G_EARTH,
                "That is the acceleration of free fall, with no drag. The drag acts upwards against the weight: "
                "a = (mg − F) / m."),
        Mistake("the drag added to the weight", acceleration(drop_weight + drag, mass),
                "The drag acts upwards, against the motion: subtract it from the weight, mg − F = ma."),
        Mistake("the diameter used for the radius in the mass",
                falling_acceleration(_WATER_DENSITY * sphere_volume(2 * radius), drag),
                "You used the diameter in 4/3 πr³. The volume uses the radius."),
        Mistake("the drag divided by the mass", acceleration(drag, mass),
                "That is the drag ÷ the mass. The resultant force is the weight less the drag: mg − F = ma."),
    )


def stokes_drag_acceleration(radius_mm: float = 1.2, speed: float = 2.5, constant: float = 5.0e-4) -> Question:
    """A drag law F = 6πDRv given in the question, at a speed below the terminal speed: (a) the
    drag, (b) the acceleration from mg − F = ma, with the drop's mass from its density and
    4/3 πR³. 9702/22/M/J/11 Q2(a)(ii) asks both of a raindrop (R = 1.5 mm, v = 3.7 m s⁻¹,
    D = 6.6 × 10⁻⁴ kg m⁻¹ s⁻¹, water 1000 kg m⁻³): 1 mark, then 3."""
    radius = radius_mm / 1000
    k = stokes_constant(constant, radius)
    mass = _WATER_DENSITY * sphere_volume(radius)
    drop_weight = weight(mass)
    if speed >= power_law_terminal_velocity(mass, k, power=1):
        raise ValueError(f"speed must be below the drop's terminal speed, "
                         f"{power_law_terminal_velocity(mass, k, power=1)!r} m s^-1, for it to speed up "
                         f"(got speed={speed!r})")
    drag = power_law_drag(k, speed, power=1)
    a = falling_acceleration(mass, drag)
    r, v, d = n(radius_mm, 2), n(speed, 2), n(constant, 2)
    return Question(
        key="stokes-drag-acceleration",
        text=(f"A spherical raindrop of radius {r} mm falls vertically through air. When its speed is {v} {PER_S}, "
              "the drag on it is <em>F</em> = 6π<em>DRv</em>, where <em>R</em> is its radius, <em>v</em> its speed "
              f"and <em>D</em> = {d} kg m<sup>−1</sup> s<sup>−1</sup> for air. The density of water is "
              f"{n(_WATER_DENSITY, 4)} kg m<sup>−3</sup> and the volume of a sphere is 4/3 π<em>R</em><sup>3</sup>. "
              "Calculate, at this speed, (a) the drag on the raindrop and (b) its acceleration."),
        givens=(Given("radius", radius_mm, "mm", 2), Given("speed", speed, "m s^-1", 2),
                Given("constant D", constant, "kg m^-1 s^-1", 2)),
        parts=(
            Part("drag on the raindrop", drag, "N", "force", shown_sig_figs=2,
                 revisit="Put the numbers in the law the question gives: F = 6πDRv, with R in m.",
                 mistakes=(
                     Mistake("radius left in mm", power_law_drag(stokes_constant(constant, radius_mm), speed, power=1),
                             f"You used the radius in mm. Convert it to m first: {r} mm = {r} × 10⁻³ m.",
                             kind="slip"),
                     Mistake("the diameter used for the radius",
                             power_law_drag(stokes_constant(constant, 2 * radius), speed, power=1),
                             f"You used 2 × {r} mm, the diameter. The law uses the radius R."),
                     Mistake("6 left out", drag / 6, "The law is F = 6πDRv: you left out the 6."),
                 ), see="friction"),
            Part("acceleration of the raindrop", a, "m s^-2", "acceleration", units=M_S2, shown_sig_figs=2,
                 answer_for_g=lambda g: falling_acceleration(mass, drag, g=g),
                 ecf=Ecf(g_symbol - a_answer / mass_symbol, {"g_earth": G_EARTH, "mass": mass}),
                 revisit="The resultant force is the weight less the drag: mg − F = ma, with m = ρ × 4/3 πR³.",
                 mistakes=_raindrop_acceleration_mistakes(mass, drop_weight, drag, radius), see="skydiver"),
        ),
        mark_scheme=(
            Mark(f"F = 6π × {d} × {r} × 10<sup>−3</sup> × {v} = {n(drag, 2)} N", "B1", "a"),
            Mark(f"m = ρV = {n(_WATER_DENSITY, 4)} × 4/3 π × ({r} × 10<sup>−3</sup>)<sup>3</sup> "
                 f"= {n(mass, 3)} kg", "C1", "b"),
            Mark(f"mg − F = ma: {n(mass, 3)} × {n(G_EARTH, 3)} − {n(drag, 3)} = {n(mass, 3)} × a", "C1", "b"),
            Mark(f"a = {n(a, 2)} {PER_S2}", "A1", "b"),
        ),
    )


# ---------------------------------------------------------------------- which graph?

#: The skydiver of the notes: 80 kg, a terminal velocity of 50 m s^-1 in freefall, 5.0 m s^-1
#: with the parachute open (opened at 25 s, over 2.0 s), down positive.
_SKYDIVER = {"mass": 80.0, "terminal_velocity_freefall": 50.0, "terminal_velocity_parachute": 5.0,
             "parachute_opens_at": 25.0, "opening_duration": 2.0, "duration": 45.0}
#: Points a sketch's curve is drawn through.
_SKETCH_POINTS = 61
_FREEFALL = ("A skydiver jumps from a hovering helicopter and falls vertically. The air resistance on her "
             "increases as her speed increases. Take downwards as positive.")
_OPENS = ("A skydiver falls vertically at her terminal velocity. She then opens her parachute, slows down, "
          "and reaches a new, lower terminal velocity. Take downwards as positive.")


def _freefall_sketches() -> dict[str, Sketch]:
    """The freefall from rest, from the models: v = v_t tanh(g t / v_t), the drag that gives that
    terminal velocity, a = (W − D) / m and the resultant force W − D; and the misconceptions'
    shapes drawn from the same numbers."""
    mass, v_t = _SKYDIVER["mass"], _SKYDIVER["terminal_velocity_freefall"]
    times = numpy.linspace(0.0, 5 * v_t / G_EARTH, _SKETCH_POINTS)  # five time constants: levelled off
    speeds = velocity_from_rest(times, v_t)
    drags = drag_force(drag_constant_for_terminal_velocity(mass, v_t), speeds)
    accelerations = [falling_acceleration(mass, d) for d in drags]
    end = float(times[-1])

    def sketch(quantity: str, symbol: str, values) -> Sketch:
        return Sketch(quantity, symbol, tuple(zip(times, values, strict=True)))

    return {
        "velocity": sketch("velocity", "v", speeds),
        "acceleration": sketch("acceleration", "a", accelerations),
        "drag": sketch("air resistance", "D", drags),
        "resultant force": sketch("resultant force", "F", weight(mass) - drags),
        # what a student draws who leaves the drag out: a = g throughout, v = g t
        "no drag, acceleration": Sketch("acceleration", "a", ((0.0, G_EARTH), (end, G_EARTH))),
        "no drag, velocity": Sketch("velocity", "v", ((0.0, 0.0), (end, G_EARTH * end))),
        "no drag, force": Sketch("resultant force", "F", ((0.0, weight(mass)), (end, weight(mass)))),
        "terminal at once": Sketch("velocity", "v", ((0.0, v_t), (end, v_t))),
    }


def _relabel(sketch: Sketch, quantity: str, symbol: str, scale: float = 1.0) -> Sketch:
    """Another quantity's shape drawn on this quantity's axes (a graph mistaken for another)."""
    return Sketch(quantity, symbol, tuple((t, scale * y) for t, y in sketch.points))


#: "At her terminal velocity" in a sketch: within this fraction of it, so the line starts level.
_AT_TERMINAL_IN_SKETCH = 0.001


def _opening_sketches() -> dict[str, Sketch]:
    """Velocity before and after the parachute opens (models.skydive), and the misconceptions:
    she moves upwards, she stops, her speed drops at once. The story (_OPENS) starts with her
    falling at her terminal velocity, so every sketch starts when the model has her there
    (time_to_terminal_velocity, within 0.1 %), not at the jump (issue 37: they started from rest), with that
    moment as t = 0."""
    dive = skydive(**_SKYDIVER)
    start = time_to_terminal_velocity(dive.terminal_velocity_freefall, within=_AT_TERMINAL_IN_SKETCH)
    opens = dive.parachute_opens_at - start
    times = numpy.linspace(start, dive.duration, _SKETCH_POINTS)
    speeds = dive.velocity_at(times)
    times = times - start
    before = [(t, v) for t, v in zip(times, speeds, strict=True) if t < opens]
    after = [(t, v) for t, v in zip(times, speeds, strict=True) if t >= opens]
    at_opening = float(dive.velocity_at(dive.parachute_opens_at))
    slow = dive.terminal_velocity_parachute

    def sketch(points) -> Sketch:
        return Sketch("velocity", "v", tuple(points))

    return {
        "velocity": sketch(before + after),
        "upwards": sketch(before + [(opens, at_opening), (opens, -at_opening)] + [(t, -v) for t, v in after[1:]]),
        "stops": sketch(before + [(t, v - slow) for t, v in after]),
        "at once": sketch([*before, (opens, at_opening), (opens, slow), (float(times[-1]), slow)]),
    }


def _skydiver_story(index: int):
    """(text, prompt, key sketch, three (mistake, feedback, sketch)) of one story."""
    free = _freefall_sketches() if index < 4 else {}
    graph_instead = ("You chose the {other}–time graph. The {this} is a different quantity: {why}")
    if index == 0:
        return (_FREEFALL, "Which graph shows how her acceleration varies with time?", free["acceleration"], (
            ("acceleration constant while the drag grows",
             ("Her acceleration is g only at the start, when there is no drag. As her speed rises the drag "
             "rises, so the resultant force and her acceleration decrease, to zero at terminal velocity."),
             free["no drag, acceleration"]),
            ("the velocity graph, not the acceleration",
             graph_instead.format(other="velocity", this="acceleration",
                                  why="it is the gradient of the velocity–time graph, largest at the start "
                                      "and zero at terminal velocity."),
             _relabel(free["velocity"], "acceleration", "a")),
            ("the drag graph, not the acceleration",
             graph_instead.format(other="air resistance", this="acceleration",
                                  why="a = (W − D) / m, so as the drag grows the acceleration falls."),
             _relabel(free["drag"], "acceleration", "a")),
        ))
    if index == 1:
        return (_FREEFALL, "Which graph shows how her velocity varies with time?", free["velocity"], (
            ("air resistance left out: v = gt",
             ("A straight line means a constant acceleration g, with no drag. The drag grows with her speed, "
             "so the gradient falls and the curve levels off at her terminal velocity."), free["no drag, velocity"]),
            ("the acceleration graph, not the velocity",
             graph_instead.format(other="acceleration", this="velocity",
                                  why="it starts at zero and rises, ever more slowly, to her terminal velocity."),
             _relabel(free["acceleration"], "velocity", "v")),
            ("terminal velocity from the start",
             ("She starts from rest, so her velocity starts at zero. Only when the drag has grown to equal "
             "her weight does her velocity stop changing."), free["terminal at once"]),
        ))
    if index == 2:
        return (_FREEFALL, "Which graph shows how the air resistance on her varies with time?", free["drag"], (
            ("drag constant while the speed changes",
             ("Drag depends on speed: it is zero at the start, when she is at rest, and grows as she speeds up "
             "until it equals her weight. A force that stays the same while the speed changes is not drag."),
             _relabel(free["no drag, force"], "air resistance", "D")),
            ("drag falls as she speeds up",
             ("That is the shape of her acceleration or the resultant force. The drag grows with her speed, "
             "from zero to her weight at terminal velocity."), _relabel(free["resultant force"], "air resistance", "D")),
            ("drag grows steadily without limit",
             ("The drag stops growing when her speed stops growing: at terminal velocity it equals her weight, "
             "so the graph levels off."), _relabel(free["no drag, velocity"], "air resistance", "D")),
        ))
    if index == 3:
        return (_FREEFALL, "Which graph shows how the resultant force on her varies with time?",
                free["resultant force"], (
            ("weight only: the drag left out",
             ("The weight is the resultant force only at the start. The drag grows with her speed, so the "
             "resultant force W − D falls to zero at terminal velocity."), free["no drag, force"]),
            ("the drag, not the resultant force",
             graph_instead.format(other="air resistance", this="resultant force",
                                  why="it is the weight minus the drag, so it falls as the drag grows."),
             _relabel(free["drag"], "resultant force", "F")),
            ("the velocity graph, not the resultant force",
             graph_instead.format(other="velocity", this="resultant force",
                                  why="by Newton's second law it is mass × acceleration, the gradient of "
                                      "the velocity–time graph, not the velocity."),
             _relabel(free["velocity"], "resultant force", "F")),
        ))
    opening = _opening_sketches()
    return (_OPENS, "Which graph shows how her velocity varies with time?", opening["velocity"], (
        ("she moves upwards when the parachute opens",
         ("Her acceleration is upwards just after the parachute opens, but her velocity is still downwards: "
         "she slows down while still falling, to the lower terminal velocity."), opening["upwards"]),
        ("she stops when the parachute opens",
         ("She slows down only until the drag equals her weight again, at the new terminal velocity. Her "
         "velocity never reaches zero."), opening["stops"]),
        ("her speed drops at once",
         ("A change of velocity takes time: while the canopy opens the drag grows larger than her weight, so "
         "she decelerates, most just after it has opened, and her velocity falls along a curve to the new "
         "terminal velocity."), opening["at once"]),
    ))


def falling_graph_choice(story: float = 0) -> Question:
    """Paper 1 style, "which graph?" for a body falling with air resistance: the velocity,
    acceleration, drag or resultant force against time from the models (notes: "v–t is a curve
    that starts with gradient g and levels off; a–t starts at g and curves down to zero"), or
    the velocity when the parachute opens. The wrong options are the notes' misconceptions:
    the acceleration constant while the drag grows, one graph taken for another, the skydiver
    moving upwards when the parachute opens. As 9702/22/M/J/24 Q2 asks about a skydiver's
    velocity–time graph; a Paper 1 item earns its one mark for the key alone (9702/11/M/J/16,
    multiple choice: one mark an item)."""
    index = int(story)
    text, prompt, key, wrong = _skydiver_story(index)
    place = index % len(OPTION_LETTERS)
    rows = [Option("", name, feedback, sketch=sketch) for name, feedback, sketch in wrong]
    rows.insert(place, Option("", sketch=key))
    letter = OPTION_LETTERS[place]
    return Question(
        key="falling-graph-choice",
        text=f"{text} Each option is a sketch of {key.quantity} against time t, without a scale.",
        givens=(),
        parts=(ChoicePart(prompt, tuple(rows), letter,
                          revisit="The drag grows with the speed, so the resultant force and the acceleration "
                                  "fall as she speeds up, to zero at terminal velocity: the velocity–time "
                                  "graph is a curve that levels off.", see="skydiver"),),
        mark_scheme=(Mark(f"{letter}: {rows[place].text[0].lower()}{rows[place].text[1:]}", "B1"),),
    )


TEMPLATES = checked_givens(
    Template("quick-check-3", "drag", ("numeric",), "Quick check 3", skydiver_parachute_opens,
             {"mass": Draw(70.0, 50.0, 99.0, 1.0), "open_drag": Draw(1500.0, 1000.0, 2500.0, 100.0)}),
    Template("parachute-opens-choice", "drag", ("mcq",), "The parachute opens", parachute_opens_choice,
             {"mass": Draw(70.0, 50.0, 100.0, 5.0), "drag": Draw(1500.0, 1000.0, 2500.0, 100.0)}),
    Template("terminal-velocity-explained", "drag", ("explain",), "Why terminal velocity?",
             terminal_velocity_explained, {"situation": Draw(0, 0, len(_FALLERS) - 1, 1)},
             variant_count=len(_FALLERS)),
    Template("drag-fraction-choice", "drag", ("mcq",), "Air resistance a fraction of the weight",
             drag_fraction_choice,
             {"percent": Draw(25.0, 10.0, 90.0, 1.0)}),
    Template("terminal-velocity-choice", "drag", ("mcq",), "At terminal velocity", terminal_velocity_choice,
             {"situation": Draw(0, 0, len(_AT_TERMINAL) - 1, 1)}, variant_count=len(_AT_TERMINAL)),
    Template("deceleration-largest-explained", "drag", ("explain",), "Why is the deceleration largest?",
             deceleration_largest_explained, {"situation": Draw(0, 0, len(_SLOWING) - 1, 1)},
             variant_count=len(_SLOWING)),
    Template("falling-with-drag-constant", "drag", ("numeric",), "Drag D = kv²", falling_with_drag_constant,
             {"mass": Draw(80.0, 55.0, 99.0, 1.0), "k": Draw(0.25, 0.18, 0.32, 0.01),
              "speed": Draw(30.0, 15.0, 45.0, 1.0)}),
    Template("sphere-in-liquid", "drag", ("numeric",), "Sphere sinking in a liquid", sphere_in_liquid,
             {"grams": Draw(6.3, 2.0, 9.9, 0.1), "volume_cm3": Draw(0.80, 0.30, 2.0, 0.1),
              "density": Draw(920.0, 800.0, 1260.0, 10.0)}),
    Template("graph-skydiver-terminal", "drag", ("graph", "numeric"), "A skydiver: velocity–time graph",
             skydiver_velocity_time, {"terminal": Draw(50.0, 30.0, 70.0, 1.0), "mass": Draw(70.0, 50.0, 100.0, 1.0)}),
    Template("graph-ball-acceleration", "drag", ("graph", "numeric"), "A falling ball: velocity–time graph",
             ball_acceleration_from_graph,
             {"terminal": Draw(20.0, 10.0, 25.0, 0.5), "moment": Draw(2.0, 0.5, 3.0, 0.5),
              "mass": Draw(0.050, 0.020, 0.080, 0.005)}),
    Template("drag-law-constant", "drag", ("numeric",), "A drag law: find k", drag_law_constant,
             # in 3 g steps: 50 g would weigh 0.4905 N, a tie at 3 s.f. that g = 9.8 (0.490 N) sits on
             {"power": Draw(2, 1, 2, 1), "grams": Draw(45.0, 21.0, 96.0, 3.0),
              "diameter_cm": Draw(4.3, 3.0, 9.0, 0.1)}),
    Template("drag-law-terminal-ratio", "drag", ("numeric",), "A drag law: heavier, faster",
             drag_law_terminal_ratio,
             {"power": Draw(2, 1, 2, 1), "grams_a": Draw(20.0, 10.0, 50.0, 5.0),
              "grams_b": Draw(80.0, 30.0, 95.0, 5.0), "diameter_cm": Draw(6.0, 4.0, 9.0, 0.5)}),
    Template("stokes-terminal-speed", "drag", ("numeric",), "A drag law: Stokes' law", stokes_terminal_speed,
             {"grams": Draw(0.11, 0.10, 0.90, 0.01), "radius_mm": Draw(1.5, 1.5, 3.0, 0.1),
              "density": Draw(1260.0, 900.0, 1260.0, 10.0), "viscosity": Draw(1.4, 0.6, 1.5, 0.1)}),
    Template("stokes-drag-acceleration", "drag", ("numeric",), "A drag law: the acceleration on the way",
             stokes_drag_acceleration,
             {"radius_mm": Draw(1.2, 1.0, 2.0, 0.1), "speed": Draw(2.5, 1.0, 4.0, 0.1),
              "constant": Draw(5.0e-4, 4.0e-4, 8.0e-4, 0.1e-4)}),
    Template("falling-graph-choice", "drag", ("mcq",), "Which graph for a falling skydiver?",
             falling_graph_choice, {"story": Draw(0, 0, 4, 1)}, variant_count=5),
)
