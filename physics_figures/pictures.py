"""What a question prints beside its text, as data: its graph (Graph: a value against time,
straight lines through the variant's own points on a grid of small squares) and its diagram
(Diagram: the bodies before and after, each with its mass and velocities as the text states
them). The bank fills them from a variant's givens; the part kinds read them (a reading's
tolerance, the graph a sketch is drawn from); physics_figures.figures draws them
(question_graph, question_diagram) and computes nothing. Data only, below both: the figures
import this module, never the part kinds, so no circle runs figures -> questions -> parts ->
figures (issue 39)."""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from .checks import require as _require
from .notation import round_number


@dataclass(frozen=True)
class Graph:
    """A graph that a question prints, drawn from its variant's own numbers: straight lines
    through ``points`` (time in s, value in SI units), on a grid of small squares
    ``time_division`` by ``value_division``. ``name`` says what it is ("momentum-time"),
    ``quantity`` and ``unit`` label the value axis (unit in plain text, e.g. "N s");
    ``shaded`` shades the area under the line (an impulse); ``curve`` says the points are
    close enough to draw a smooth curve."""

    name: str
    quantity: str
    unit: str
    points: tuple[tuple[float, float], ...]
    time_division: float
    value_division: float
    time_max: float
    value_max: float
    value_min: float = 0.0
    shaded: bool = False
    #: Many points close together that draw a smooth curve (e.g. v = v_t tanh(g t / v_t)).
    curve: bool = False

    def __post_init__(self):
        object.__setattr__(self, "points", tuple((float(t), float(v)) for t, v in self.points))
        _require(len(self.points) >= 2, "points", self.points, "must hold at least two points")
        _require(self.time_division > 0 and self.value_division > 0, "time_division",
                 (self.time_division, self.value_division), "and value_division must be positive")
        _require(self.value_min < self.value_max, "value_min", self.value_min,
                 f"must be below value_max={self.value_max}")
        for name, span, division in (("time_max", self.time_max, self.time_division),
                                     ("value_max", self.value_max - self.value_min, self.value_division)):
            count = span / division
            _require(abs(count - round(count)) < 1e-6 and 2 <= round(count) <= 60, name, span,
                     f"must be 2 to 60 whole small squares of {division}")
        times = [t for t, _ in self.points]
        _require(all(b > a for a, b in itertools.pairwise(times)), "points", self.points,
                 "must be in increasing time")
        _require(times[0] >= 0 and times[-1] <= self.time_max + 1e-12, "points", self.points,
                 f"must lie within 0 to time_max={self.time_max} s")
        _require(all(self.value_min - 1e-12 <= v <= self.value_max + 1e-12 for _, v in self.points),
                 "points", self.points, f"must lie within value_min={self.value_min} to value_max={self.value_max}")

    def value_at(self, time: float) -> float:
        """The value the drawn line passes through at ``time`` (what a student reads off)."""
        for (t0, v0), (t1, v1) in itertools.pairwise(self.points):
            if t0 <= time <= t1:
                return v0 + (v1 - v0) * (time - t0) / (t1 - t0)
        raise ValueError(f"time must lie on the drawn line, {self.points[0][0]} to "
                         f"{self.points[-1][0]} s (got time={time!r})")

    def readings(self) -> tuple[float | None, ...]:
        """What a student with a ruler reads off the drawn line at every half small square of
        time from 0 to ``time_max``: the value there to the nearest half small square of the
        value axis (half away from zero), None where no line is drawn. The graph cursor of a
        question's graph announces these (book/_ext/questions/static/graph-cursor.js)."""
        half_time, half_value = self.time_division / 2, self.value_division / 2
        first, last = self.points[0][0], self.points[-1][0]
        # the half squares' lines counted from zero (a tie goes away from zero), or from the
        # axis's low end when zero is not on one of them
        lines_from_zero = math.isclose(self.value_min / half_value, round(self.value_min / half_value), abs_tol=1e-9)
        origin = 0.0 if lines_from_zero else self.value_min
        out: list[float | None] = []
        for index in range(round(self.time_max / half_time) + 1):
            time = index * half_time
            if not first - 1e-9 <= time <= last + 1e-9:
                out.append(None)
                continue
            steps = (self.value_at(min(max(time, first), last)) - origin) / half_value
            whole = math.floor(abs(steps) + 0.5 + 1e-9) * (1 if steps >= 0 else -1)
            # no float dust: 1.2, not 1.2000000000000002
            out.append(float(round_number(origin + whole * half_value, 12)))
        return tuple(out)


@dataclass(frozen=True)
class Arrow:
    """A velocity drawn on a body: ``direction`` in degrees anticlockwise from the x-direction
    (0 right or east, 90 up or north), ``label`` as the text prints it ("2.5 m s⁻¹"). With
    ``angle_from`` (a direction in degrees) an arc marks the angle between the two, labelled
    ``angle_label`` ("40°"), and a dashed line draws the direction it is measured from."""

    label: str
    direction: float
    angle_from: float | None = None
    angle_label: str = ""

    def __post_init__(self):
        _require(math.isfinite(self.direction), "direction", self.direction, "must be a finite angle in degrees")
        _require((self.angle_from is None) == (not self.angle_label), "angle_label", self.angle_label,
                 "and angle_from go together: an arc needs the direction it is measured from and its label")


@dataclass(frozen=True)
class Body:
    """A body in a diagram: its ``name`` ("A", "ball"), its mass as printed ("0.40 kg", or ""
    when the text does not give it), its velocities, and ``note`` under it where it has no
    arrow ("at rest", "velocity ?")."""

    name: str
    mass: str = ""
    arrows: tuple[Arrow, ...] = ()
    note: str = ""

    def __post_init__(self):
        _require(bool(self.arrows) or bool(self.note), "note", self.note,
                 f"must say what a body without an arrow is doing ({self.name}: 'at rest', 'velocity ?')")


@dataclass(frozen=True)
class Diagram:
    """What a question's text describes, drawn: ``before`` and ``after`` (either may be empty,
    not both), in a plane (``compass``: label north and east) or along a line; ``wall``: a
    wall on the right that the body hits."""

    before: tuple[Body, ...]
    after: tuple[Body, ...] = ()
    compass: bool = False
    wall: bool = False

    def __post_init__(self):
        _require(bool(self.before) or bool(self.after), "before", self.before,
                 "or after must hold a body: a diagram of nothing says nothing")
