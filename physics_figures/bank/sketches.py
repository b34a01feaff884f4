# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, en dash)
"""The papers' sketch parts: the student draws a line on printed axes and earns a B1 for each
feature the scheme names (parts.sketch). Each template's numbers come from the models; the
line's features are read in the graph's own units, so a level "at F t₁" is checked against
the value the models give.

Sources. The sketch parts these follow were found in the published question papers (as
indexed by revisesmarter.com's 9702 pages): 9702/21/M/J/23 Q3(c) "sketch a graph showing how
force X varies with time t from t = 0 to t = 6.0 s" [3]; 9702/22/M/J/21 Q2(d) "sketch a graph to
show how the speed of the ball varies with time" [1] and Q2(e) "state and explain the variation
... of the gradient of the graph in (d) when air resistance is not negligible" [2]; 9702/22/M/J/24
Q2 a skydiver's velocity–time graph (the notes' past questions). The schemes' own wordings of
those sketch lines were not in the search corpus: each point here is the feature the part asks
for, one B1 each as the part's marks count them, and cites the part it follows.
"""

from __future__ import annotations

import math

from ..constants import G_EARTH
from ..models import (
    MomentumHistory,
    applied_force,
    average_force,
    change_in_momentum,
    impulse,
    velocity_from_rest,
    weight,
)
from ..notation import format_number as n
from ..parts.graph import value_axis
from ..parts.sketch import Feature, SketchAxes, SketchPart, SketchPoint, WrongSketch
from ..pictures import Graph
from ..questions import Given, Mark, Question
from ..variants import Draw, Template
from ._common import PER_S
from .givens import checked_givens

#: Sketch templates vary their numbers (the axes and the levels move); they count as
#: situations (variants.MIN_SITUATIONS), split between the site and the teachers' reserve:
#: 10 and 10, as the choice templates, so the Moodle file has MOODLE_MIN_VARIANTS unseen ones.
_VARIANTS = 20


def nice_axis(high: float, most: int = 10) -> tuple[float, float]:
    """(top, division) of an axis from 0 that holds ``high`` with a little room: divisions of
    1, 2 or 5 × 10ⁿ, at most ``most`` of them (so 15 N s gets 0 to 20 in 2s)."""
    wanted = 1.1 * high / most
    power = 10.0 ** math.floor(math.log10(wanted))
    division = next(step * power for step in (1, 2, 5, 10) if step * power >= wanted * (1 - 1e-12))
    return math.ceil(1.1 * high / division - 1e-9) * division, division


def _points(question_points: tuple[SketchPoint, ...]) -> tuple[Mark, ...]:
    return tuple(Mark(point.text, "B1", "a") for point in question_points)


def _sketch_question(key: str, text: str, givens: tuple[Given, ...], part: SketchPart,
                     graph: Graph | None = None) -> Question:
    return Question(key=key, text=text, givens=givens, parts=(part,), mark_scheme=_points(part.points), graph=graph)


# --------------------------------------------------------------- momentum from a force in words

def momentum_from_force(force: float = 6.0, duration: float = 2.5) -> Question:
    """A trolley at rest is pushed by a constant resultant force for ``duration`` s, then moves
    freely: its momentum rises in a straight line from the origin (Δp = F Δt, constant
    gradient F) and is then constant at F Δt. Three B1 (the start, the straight rise, the level),
    as 9702/21/M/J/23 Q3(c) marks a sketch over three stretches; a constant force's straight
    line as 9702/22/M/J/21 Q2(d)."""
    level = impulse(force, duration)
    t_max = 2 * duration
    top, division = nice_axis(level)
    axes = SketchAxes("momentum", "p", "N s", t_max=t_max, t_division=duration / 5, y_max=top, y_division=division)
    p_text, t_text = n(level, 2), n(duration, 2)
    points = (
        SketchPoint("Line starts at the origin (p = 0 at t = 0)", (Feature("start", value="zero"),),
                    "9702/21/M/J/23 Q3(c)"),
        SketchPoint(f"Straight line with positive gradient from t = 0 to t = {t_text} s",
                    (Feature("rising", 0.0, duration, gradient="constant"),), "9702/22/M/J/21 Q2(d)"),
        SketchPoint(f"Horizontal line at p = {p_text} N s from t = {t_text} s to {n(t_max, 2)} s",
                    (Feature("level", duration, t_max, at=level, within=2),), "9702/21/M/J/23 Q3(c)",
                    loses=(Feature("sign-change"),)),
    )
    wrong = (
        WrongSketch("curving up, as if the force grew", (*_curve(0.0, duration, 0.0, level, "steeper"),
                                                             (t_max, level)), (0, 2)),
        WrongSketch("still rising after the force stops", ((0.0, 0.0), (t_max, min(top, 2 * level))), (0, 1)),
        WrongSketch("falling back to zero when the force stops", ((0.0, 0.0), (duration, level), (t_max, 0.0)),
                    (0, 1)),
    )
    part = SketchPart("Sketch the variation with time t of the momentum p of the trolley.", axes, points,
                      model=((0.0, 0.0), (duration, level), (t_max, level)), wrong=wrong, see="momentum-time-graph")
    return _sketch_question(
        "sketch-momentum-from-force",
        (f"A trolley is at rest on a level track. At time t = 0 a constant resultant force of {n(force, 2)} N "
         f"starts to act on it along the track. At t = {t_text} s the force is removed, and the trolley moves "
         f"on freely (friction is negligible). On the axes, sketch the variation with t of the momentum p "
         f"of the trolley from t = 0 to t = {n(t_max, 2)} s."),
        (Given("force", force, "N", 2), Given("time the force acts", duration, "s", 2)),
        part)


def _curve(t0: float, t1: float, y0: float, y1: float, how: str, steps: int = 12) -> tuple[tuple[float, float], ...]:
    """A curve from (t0, y0) to (t1, y1) whose gradient grows ("steeper") or shrinks ("less
    steep"), as the keyboard builder draws one (static/sketch-pad.js)."""
    out = []
    for i in range(steps + 1):
        u = i / steps
        share = u * u if how == "steeper" else 1 - (1 - u) ** 2
        out.append((t0 + (t1 - t0) * u, y0 + (y1 - y0) * share))
    return tuple(out)


# --------------------------------------------------------- force from a momentum–time graph

#: 9702/21/M/J/23 Q3: a block dragged by a varying force X against a constant 2.0 N friction,
#: its momentum–time graph given, force X sketched from t = 0 to 6.0 s.
FRICTION, GRAPH_END = 2.0, 6.0


def force_from_momentum_graph(first: float = 6.0, second: float = 8.0, turn: float = 2.0) -> Question:
    """9702/21/M/J/23 Q3(c) [3]: from the momentum–time graph (straight lines: rising to
    ``first`` N s at ``turn`` s, less steeply to ``second`` N s at 2 × ``turn`` s, then level),
    the pull X = the gradient + the 2.0 N friction: a level line in each stretch, stepping down
    at each corner, and 2.0 N (not zero) where the momentum is constant. One B1 a stretch."""
    corners = ((0.0, 0.0), (turn, first), (2 * turn, second), (GRAPH_END, second))
    history = MomentumHistory(*zip(*corners, strict=True))
    pulls = [applied_force(float(force), FRICTION) for force in history.segment_forces]
    top, division = nice_axis(max(pulls))
    axes = SketchAxes("force X", "X", "N", t_max=GRAPH_END, t_division=1.0, y_max=top, y_division=division)
    stretches = ((0.0, turn), (turn, 2 * turn), (2 * turn, GRAPH_END))
    points = tuple(
        SketchPoint(f"Horizontal line at X = {n(pull, 2)} N from t = {n(a, 2)} s to {n(b, 2)} s"
                    + (" (the friction: not zero)" if index == 2 else ""),
                    (Feature("level", a, b, at=pull),), "9702/21/M/J/23 Q3(c)")
        for index, (pull, (a, b)) in enumerate(zip(pulls, stretches, strict=True)))
    model = tuple(point for pull, (a, b) in zip(pulls, stretches, strict=True) for point in ((a, pull), (b, pull)))
    resultant = tuple((t, y - FRICTION) for t, y in model)
    wrong = (
        WrongSketch("the resultant force: the friction left out", resultant, ()),
        WrongSketch("zero once the momentum is constant", (*model[:4], (2 * turn, 0.0), (GRAPH_END, 0.0)), (0, 1)),
        WrongSketch("the steps the wrong way round", tuple((t, model[-1 - i][1]) for i, (t, _) in enumerate(model)),
                    (1,)),
    )
    graph_min, graph_max, graph_division = value_axis(second)
    graph = Graph("momentum-time", "momentum", "N s", corners, time_division=0.2, value_division=graph_division,
                  time_max=GRAPH_END, value_max=graph_max, value_min=graph_min)
    part = SketchPart("Sketch the variation with time t of force X from t = 0 to t = 6.0 s.", axes, points,
                      model=model, wrong=wrong, see="momentum-time-graph")
    return _sketch_question(
        "sketch-force-from-momentum-graph",
        (f"A block is dragged in a straight line across a rough horizontal surface by a force X that varies. "
         f"The surface exerts a constant frictional force of {n(FRICTION, 2)} N on the block, and air resistance "
         f"is negligible. The graph shows the variation with time t of the momentum p of the block. On the axes, "
         f"sketch the variation with t of force X from t = 0 to t = {n(GRAPH_END, 2)} s."),
        # the corners' momenta are on the graph, not in the words
        (Given("frictional force", FRICTION, "N", 2),),
        part, graph=graph)


# ----------------------------------------------------------- velocity of a skydiver with drag

def skydiver_velocity(mass: float = 75.0, v_t: float = 54.0) -> Question:
    """The velocity–time graph of a skydiver falling from rest with air resistance that grows
    with speed: from the origin, a curve whose gradient decreases (9702/22/M/J/21 Q2(e): the
    gradient decreases when air resistance is not negligible, [2]), levelling off at the
    terminal velocity (9702/22/M/J/24 Q2, the skydiver's velocity–time graph). The model is
    v = v_t tanh(g t / v_t) (models.velocity_from_rest), with the terminal velocity as printed."""
    tau = v_t / G_EARTH  # the time the speed would take to reach v_t at the start's gradient g
    t_max = 5.0 * math.ceil(4.5 * tau / 5.0)
    top, division = nice_axis(v_t)
    axes = SketchAxes("velocity", "v", "m s^-1", t_max=t_max, t_division=5.0, y_max=top, y_division=division)
    v_text = n(v_t, 2)
    points = (
        SketchPoint("Line starts at the origin (v = 0 at t = 0)", (Feature("start", value="zero"),),
                    "9702/22/M/J/24 Q2"),
        SketchPoint("Curve rising with a decreasing gradient", (Feature("rising", 0.0, 2 * tau, gradient="decreasing"),),
                    "9702/22/M/J/21 Q2(e)"),
        SketchPoint(f"Levels off at the terminal velocity, {v_text} m s⁻¹",
                    (Feature("level", 3 * tau, t_max, at=v_t, within=2),), "9702/22/M/J/24 Q2"),
    )
    times = [t_max * i / 40 for i in range(41)]
    model = tuple((t, float(velocity_from_rest(t, v_t))) for t in times)
    wrong = (
        WrongSketch("a straight line: no air resistance", ((0.0, 0.0), (top / G_EARTH, top)), (0,)),
        WrongSketch("straight up, then level at once", ((0.0, 0.0), (tau, v_t), (t_max, v_t)), (0, 2)),
        WrongSketch("ever steeper, as if the drag pushed it on", _curve(0.0, t_max, 0.0, v_t, "steeper"), (0,)),
    )
    part = SketchPart("Sketch the variation with time t of the velocity v of the skydiver.", axes, points,
                      model=model, wrong=wrong, see="skydiver")
    return _sketch_question(
        "sketch-skydiver-velocity",
        (f"A skydiver of mass {n(mass, 2)} kg steps out of a hot-air balloon at rest and falls vertically. The air "
         f"resistance on her increases with her speed, and her terminal velocity is {v_text} {PER_S}. On the "
         f"axes, sketch the variation with time t of her velocity v from t = 0 to t = {n(t_max, 2)} s."),
        (Given("mass", mass, "kg", 2), Given("terminal velocity", v_t, "m s^-1", 2)),
        part)


# ------------------------------------------------------------------- the force of a bounce

#: The ball touches the floor this long after the graph's t = 0 (s): the line starts at zero.
BOUNCE_TOUCH = 0.040


def bounce_force(mass: float = 0.059, down: float = 8.7, up: float = 5.4, contact: float = 0.091) -> Question:
    """The force of the floor on a bouncing ball against time: zero until it touches, a single
    upward pulse during the contact, zero again once it leaves. The pulse's area is the change
    of momentum plus the weight's impulse, so its peak is above the average force
    Δp / Δt + mg (9702/22/M/J/21 Q2(c)(ii)–(iii): the average resultant force, then the floor's
    force with the weight added; the printed numbers are that part's: 0.059 kg, 8.7 and
    5.4 m s⁻¹, 0.091 s). The model's pulse is half a sine, whose peak is π/2 × its average."""
    change = change_in_momentum(mass, -down, up)
    floor = applied_force(average_force(change, contact), weight(mass))
    touch = BOUNCE_TOUCH
    leave = touch + contact
    t_max, t_division = nice_axis(leave + BOUNCE_TOUCH)
    top, division = nice_axis(2 * floor)
    low = -division * math.ceil(0.5 * top / division)
    axes = SketchAxes("force of the floor", "F", "N", t_max=t_max, t_division=t_division, y_max=top,
                      y_division=division, y_min=low)
    points = (
        SketchPoint("Zero before the ball touches the floor and after it leaves",
                    (Feature("level", 0.0, touch, at=0.0), Feature("level", leave, t_max, at=0.0)),
                    "9702/22/M/J/21 Q2(c)"),
        SketchPoint("Rises to a single maximum, then falls back to zero, during the contact (upwards throughout)",
                    (Feature("rising", touch, touch + 0.45 * contact), Feature("falling", leave - 0.45 * contact, leave)),
                    "9702/22/M/J/21 Q2(c)", loses=(Feature("sign-change"),)),
        SketchPoint(f"Peak above the average force of the floor, {n(floor, 2)} N (area = change in momentum)",
                    (Feature("peak", above=floor),), "9702/22/M/J/21 Q2(c)(iii)"),
    )
    peak = math.pi / 2 * floor
    pulse = tuple((touch + contact * i / 16, peak * math.sin(math.pi * i / 16)) for i in range(17))
    model = ((0.0, 0.0), *pulse, (t_max, 0.0))
    wrong = (
        WrongSketch("a constant force during the contact", ((0.0, 0.0), (touch, 0.0), (touch, floor), (leave, floor),
                                                            (leave, 0.0), (t_max, 0.0)), (0, 2)),
        WrongSketch("the pulse drawn downwards", ((0.0, 0.0), *((t, max(low, -y)) for t, y in pulse), (t_max, 0.0)),
                    (0,)),
        WrongSketch("the force still acting after the ball leaves",
                    ((0.0, 0.0), *pulse[:9], (t_max, peak)), (2,)),
    )
    part = SketchPart("Sketch the variation with time t of the force F exerted by the floor on the ball.", axes,
                      points, model=model, wrong=wrong, see="second-law")
    return _sketch_question(
        "sketch-bounce-force",
        (f"A ball of mass {n(mass, 2)} kg falls vertically onto a horizontal floor. It arrives at "
         f"{n(down, 2)} {PER_S} and rebounds vertically at {n(up, 2)} {PER_S}. It touches the floor at "
         f"t = {n(touch, 2)} s and is in contact with it for {n(contact, 2)} s. On the axes, sketch the variation "
         f"with t of the force F that the floor exerts on the ball from t = 0 to t = {n(t_max, 2)} s."),
        (Given("mass", mass, "kg", 2), Given("speed before", down, "m s^-1", 2), Given("speed after", up, "m s^-1", 2),
         Given("contact time", contact, "s", 2)),
        part)


TEMPLATES = checked_givens(
    Template("sketch-momentum-from-force", "force-momentum", ("sketch",), "Sketch: momentum from a force in words",
             momentum_from_force, draws={"force": Draw(6.0, 2.0, 9.0, 1.0), "duration": Draw(2.5, 1.5, 3.0, 0.5)},
             variant_count=_VARIANTS),
    Template("sketch-force-from-momentum-graph", "force-momentum", ("sketch",),
             "Sketch: force X from a momentum–time graph", force_from_momentum_graph,
             draws={"first": Draw(6.0, 4.0, 8.0, 1.0), "second": Draw(8.0, 9.0, 12.0, 1.0)},
             variant_count=_VARIANTS),
    Template("sketch-skydiver-velocity", "drag", ("sketch",), "Sketch: a skydiver's velocity with drag",
             skydiver_velocity, draws={"mass": Draw(75.0, 60.0, 90.0, 5.0), "v_t": Draw(54.0, 40.0, 65.0, 1.0)},
             variant_count=_VARIANTS),
    Template("sketch-bounce-force", "force-momentum", ("sketch",), "Sketch: the force of a bounce", bounce_force,
             draws={"mass": Draw(0.059, 0.050, 0.070, 0.001), "down": Draw(8.7, 6.0, 9.0, 0.1),
                    "up": Draw(5.4, 3.0, 5.5, 0.1), "contact": Draw(0.091, 0.080, 0.100, 0.001)},
             variant_count=_VARIANTS),
)
