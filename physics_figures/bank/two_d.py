# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Momentum in two dimensions: components and glancing collisions."""

from __future__ import annotations

import math

from ..models import missing_momentum, momentum
from ..notation import format_number as n
from ..questions import Given, Mark, Mistake, Part, Question, Step
from ..variants import Draw, Template
from ._common import N_S, PER_S, w


def pucks_glancing(mass: float = 0.40, speed_before: float = 2.5, speed_after: float = 1.5,
                   angle: float = 40.0) -> Question:
    """Momentum in two dimensions: conserve along and across the line separately."""
    if speed_after >= speed_before:  # B, at rest before, takes some of A's kinetic energy
        raise ValueError(f"speed_after must be less than speed_before={speed_before!r} m s^-1: puck A "
                         f"cannot speed up by hitting a puck at rest (got speed_after={speed_after!r})")
    p_before = momentum(mass, speed_before)
    p_after = momentum(mass, speed_after)
    b = missing_momentum(p_before, p_after, angle)
    components = (Step("component along the line", b.along, "N s"),
                  Step("component across the line", b.across, "N s"))
    m, u, v, theta = n(mass, 2), n(speed_before, 2), n(speed_after, 2), n(angle, 2)
    along, across = "p<sub>along</sub>", "p<sub>across</sub>"
    return Question(
        key="practice-pucks",
        text=(f"On a frictionless air table, puck A of mass {m} kg moving at {u} {PER_S} hits puck B, "
              f"which is at rest. Afterwards A moves at {v} {PER_S} at {theta}° to its original direction. "
              "Calculate (a) the size of the momentum of B after the collision, and (b) the angle between "
              "B's motion and A's original direction."),
        givens=(Given("mass", mass, "kg", 2), Given("speed before", speed_before, "m s^-1", 2),
                Given("speed after", speed_after, "m s^-1", 2), Given("angle", angle, "°", 2)),
        parts=(
            Part("momentum of B after the collision", b.magnitude, "N s", "momentum", units=N_S,
                 shown_sig_figs=2, working=components,
                 answer_from=lambda along_, across_: math.hypot(along_, across_),
                 revisit="Momentum is a vector: conserve the components along and across the "
                         "original line separately, then combine them with Pythagoras.",
                 mistakes=(
                     Mistake("sizes subtracted", p_before - p_after,
                             "You subtracted the sizes. Momentum is a vector: resolve along and "
                             "across the line and conserve each."),
                     Mistake("across component only", b.across,
                             "That is only the component across the line. Combine it with the "
                             "component along the line: p = √(along² + across²)."),
                 )),
            Part("angle between B's motion and A's original line", b.angle_deg, "°", "angle",
                 units="° (degrees)", shown_sig_figs=3, working=components,
                 answer_from=lambda along_, across_: math.degrees(math.atan2(across_, along_)),
                 revisit="tan θ = across component / along component, on the other side of the line.",
                 mistakes=(
                     Mistake("same angle as A", angle,
                             "B need not move at A's angle. Work out its components and use "
                             "tan θ = across / along."),
                     Mistake("angle from the perpendicular", 90.0 - b.angle_deg,
                             "You measured the angle from the line at right angles. Give it from "
                             "A's original line: tan θ = across / along."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Along: {w(p_before)} = {w(p_after)} cos {theta}° + {along}, so {along} = "
                 f"{n(b.along, 3)} N s", "C1", "ab"),
            Mark(f"Across: {across} = {w(p_after)} sin {theta}° = {n(b.across, 3)} N s", "C1", "ab"),
            Mark(f"p<sub>B</sub> = √({n(b.along, 3)}<sup>2</sup> + {n(b.across, 3)}<sup>2</sup>) = "
                 f"{n(b.magnitude, 2)} N s", "A1", "a"),
            Mark(f"θ = tan<sup>−1</sup> ({n(b.across, 3)} / {n(b.along, 3)}) = {n(b.angle_deg, 3)}° on the "
                 "other side of the line", "A1", "b"),
        ),
    )


TEMPLATES = (
    Template("practice-pucks", "two-d", ("numeric",), "Pucks on an air table", pucks_glancing,
             {"mass": Draw(0.40, 0.20, 0.80, 0.05), "speed_before": Draw(2.5, 1.0, 4.0, 0.1),
              "speed_after": Draw(1.5, 0.5, 3.0, 0.1), "angle": Draw(40.0, 20.0, 70.0, 5.0)}),
)
