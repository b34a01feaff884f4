"""The diagram a question prints beside its text (issue 37): the bodies before and after, each
with its mass and velocities as the text states them, drawn by
physics_figures.figures.question_diagram. The bank fills it from the variant's givens (written
by physics_figures.notation), so New numbers relabels it; the figure computes nothing."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .common import _require


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
