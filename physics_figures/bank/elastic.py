# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters)
"""Elastic and inelastic collisions: relative speeds, kinetic energy kept or lost."""

from __future__ import annotations

from ..models import (
    elastic_collision,
    kinetic_energy,
    momentum,
    relative_speed,
    stick_together,
    total_kinetic_energy,
    velocity_from_momentum,
)
from ..notation import format_number as n
from ..questions import Given, Mark, Mistake, Part, Question
from ..variants import Draw, Template
from ._common import M_S, PER_S, w


def _times(mass: float, symbol: str) -> str:
    """mass × symbol as an equation writes it: "v<sub>1</sub>" for 1.0 kg, "1.5v<sub>1</sub>" otherwise."""
    return symbol if mass == 1 else f"{n(mass, 2)}{symbol}"


def light_ball_hits_heavy_ball(m1: float = 1.0, u1: float = 6.0, m2: float = 2.0) -> Question:
    """Notes, Quick check 4: 1.0 kg at 6.0 m s^-1 hits 2.0 kg at rest, elastic -> -2.0 and 4.0 m s^-1."""
    if m2 <= m1:  # the light ball bounces back (the notes' variation); the text and feedback say so
        raise ValueError(f"m2 must be heavier than m1, so the first ball bounces back (got m1={m1!r}, m2={m2!r})")
    u2 = 0.0
    v1, v2 = elastic_collision(m1, u1, m2, u2)
    p_before = momentum(m1, u1)
    approach = relative_speed(u1, u2)
    ke_before = kinetic_energy(m1, u1)
    stuck = stick_together(m1, u1, m2, u2)
    light, heavy, speed = n(m1, 2), n(m2, 2), n(u1, 2)
    forward = f"the direction the {light} kg ball moves at first"
    revisit = ("Use two equations: momentum (m₁u₁ + m₂u₂ = m₁v₁ + m₂v₂) and, because it is elastic, "
               "relative speed of approach = relative speed of separation.")
    v_1, v_2 = "v<sub>1</sub>", "v<sub>2</sub>"
    # Adding the momentum equation to m1 × (the relative-speed equation) leaves v2 alone.
    adding = "Adding" if m1 == 1 else f"Adding {light} × the second"
    # m1 + m2 is a whole number of kilograms in the notes' answer, written as they write it (3v₂)
    total = n(m1 + m2, decimals=0) if abs(m1 + m2 - round(m1 + m2)) < 1e-9 else w(m1 + m2)
    return Question(
        key="quick-check-4",
        text=(f"A {light} kg ball moving at {speed} {PER_S} has an elastic head-on collision with a "
              f"{heavy} kg ball at rest. Calculate the velocities of (a) the {light} kg ball and (b) the "
              f"{heavy} kg ball afterwards."),
        givens=(Given("m1", m1, "kg", 2), Given("u1", u1, "m s^-1", 2), Given("m2", m2, "kg", 2)),
        parts=(
            Part(f"velocity of the {light} kg ball", v1, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("assumed the first ball stops", 0.0,
                             f"The moving ball only stops when the masses are equal. Here the {heavy} kg "
                             f"ball is heavier, so the {light} kg ball bounces back."),
                     Mistake("bounces back at full speed", -u1,
                             f"It can't bounce back at its full speed: the {heavy} kg ball moves off, "
                             "taking momentum and kinetic energy. Solve the two equations together."),
                 )),
            Part(f"velocity of the {heavy} kg ball", v2, "m s^-1", "velocity", units=M_S, shown_sig_figs=2,
                 direction="signed", positive=forward, revisit=revisit,
                 mistakes=(
                     Mistake("treated as sticking together", stuck,
                             "That is the common velocity if they stuck together, an inelastic "
                             "collision. This one is elastic: use the relative speeds too."),
                     Mistake("assumed the first ball stops", velocity_from_momentum(p_before, m2),
                             f"You assumed the {light} kg ball stops. That happens only for equal masses; "
                             "use momentum and relative speeds together."),
                     Mistake("swapped velocities", u1,
                             "Balls swap velocities only when their masses are equal. Here they "
                             "are not: solve momentum and relative speeds together."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Momentum: {w(p_before)} = {_times(m1, v_1)} + {heavy}{v_2}", "C1", "ab"),
            Mark(f"Elastic, so relative speeds: {n(approach, 2)} = {v_2} − {v_1}", "C1", "ab"),
            Mark(f"{adding}: {w(p_before + approach * m1)} = {total}{v_2}, so {v_2} = {n(v2, 2)} {PER_S} "
                 "forwards", "A1", "b"),
            Mark(f"{v_1} = {n(v1, 2)} {PER_S}, i.e. {n(abs(v1), 2)} {PER_S} back the way it came", "A1", "a"),
            Mark(f"(Check: kinetic energy {n(ke_before, 2)} J before; "
                 f"{n(kinetic_energy(m1, v1), 2)} + {n(kinetic_energy(m2, v2), 2)} = "
                 f"{n(total_kinetic_energy((m1, m2), (v1, v2)), 2)} J after.)"),
        ),
    )


TEMPLATES = (
    Template("quick-check-4", "elastic", ("numeric",), "Quick check 4", light_ball_hits_heavy_ball,
             {"m1": Draw(1.0, 0.5, 2.0, 0.1), "u1": Draw(6.0, 2.0, 9.0, 0.5), "m2": Draw(2.0, 1.0, 5.0, 0.5)}),
)
