# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Force as the rate of change of momentum: F = Δp/Δt, impulse, streams and bounces."""

from __future__ import annotations

import sympy

from ..models import acceleration, impulse, kinetic_energy, velocity_from_momentum
from ..notation import format_number as n
from ..questions import Ecf, Given, Mark, Mistake, Part, Question
from ..variants import Draw, Template

_N_S = "N s or kg m s^-1"
_M_S = "m s^-1 (m/s)"
a_answer, mass_symbol = sympy.symbols("a mass")


def trolley_pushed_from_rest(force: float = 5.0, mass: float = 2.0, duration: float = 3.0) -> Question:
    """Notes, Quick check 1: 5.0 N for 3.0 s on a 2.0 kg trolley from rest -> 15 N s, 7.5 m s^-1."""
    p = impulse(force, duration)  # from rest, so the final momentum is the change
    v = velocity_from_momentum(p, mass)
    return Question(
        key="quick-check-1",
        text=(f"A resultant force of {n(force, 2)} N acts on a {n(mass, 2)} kg trolley, initially at "
              f"rest, for {n(duration, 2)} s. Calculate (a) its final momentum and (b) its speed."),
        givens=(Given("force", force, "N", 2), Given("mass", mass, "kg", 2),
                Given("duration", duration, "s", 2)),
        parts=(
            Part("final momentum", p, "N s", "momentum", units=_N_S, shown_sig_figs=2,
                 revisit="Force × time = change in momentum (F Δt = Δp), and the trolley starts at rest.",
                 mistakes=(
                     Mistake("force divided by time", force / duration,
                             "You divided the force by the time. Force is the rate of change of "
                             "momentum, so the change in momentum is force × time: Δp = F Δt."),
                     Mistake("force times mass", force * mass,
                             "You multiplied the force by the mass. The change in momentum is "
                             "force × time; the mass is only needed for the speed."),
                     Mistake("acceleration given as momentum", acceleration(force, mass),
                             "That is the acceleration, F/m. Momentum is found from Δp = F Δt."),
                     Mistake("kinetic energy instead of momentum", kinetic_energy(mass, v),
                             "That is the kinetic energy, ½mv², in J. Momentum is mass × velocity "
                             "(here force × time), in N s.", unit="J"),
                 )),
            Part("speed", v, "m s^-1", "speed", units=_M_S, shown_sig_figs=2,
                 revisit="Momentum = mass × velocity, so v = p / m.",
                 ecf=Ecf(a_answer / mass_symbol, {"mass": mass}),
                 mistakes=(
                     Mistake("momentum times mass", p * mass,
                             "You multiplied the momentum by the mass. p = mv, so v = p / m."),
                     Mistake("mass over momentum", mass / p,
                             "That is m / p, upside down. p = mv, so v = p / m."),
                     Mistake("acceleration given as speed", acceleration(force, mass),
                             f"That is the acceleration, F/m, in m s⁻². The speed after {n(duration, 2)} s "
                             "is p / m (or u + at)."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Δp = FΔt = {n(force, 2)} × {n(duration, 2)}", "C1", "a"),
            Mark(f"= {n(p, 2)} N s, so the final momentum is {n(p, 2)} kg m s<sup>−1</sup> "
                 "(it started at rest)", "A1", "a"),
            Mark(f"speed = p / m = {n(p, 2)} / {n(mass, 2)}", "C1", "b"),
            Mark(f"= {n(v, 2)} m s<sup>−1</sup>", "A1", "b"),
        ),
    )


TEMPLATES = (
    Template("quick-check-1", "force-momentum", ("numeric",), "Quick check 1",
             trolley_pushed_from_rest,
             {"force": Draw(5.0, 2.0, 9.0, 0.5), "mass": Draw(2.0, 1.0, 5.0, 0.5),
              "duration": Draw(3.0, 2.0, 6.0, 0.5)}),
)
