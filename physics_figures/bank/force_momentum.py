# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Force as the rate of change of momentum: F = Δp/Δt, impulse, streams and bounces."""

from __future__ import annotations

import sympy

from ..models import (
    acceleration,
    change_in_momentum,
    impulse,
    kinetic_energy,
    momentum,
    stream_force,
    time_for_momentum_change,
    velocity_from_momentum,
    weight,
)
from ..notation import format_number as n
from ..questions import Ecf, Given, Mark, Mistake, Part, Question, Step
from ..variants import Draw, Template
from ._common import M_S as _M_S
from ._common import N_S as _N_S
from ._common import PER_S, w

a_answer, mass_symbol, contact_symbol = sympy.symbols("a mass contact")


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


def ball_bounces_off_wall(mass: float = 0.16, speed_in: float = 15.0, speed_out: float = 10.0,
                          contact_ms: float = 20.0) -> Question:
    """Change in momentum and force for a ball bouncing back: m(u + v), not m(u - v)."""
    if speed_out >= speed_in:  # a real bounce loses kinetic energy
        raise ValueError(f"speed_out must be less than speed_in={speed_in!r} m s^-1: a ball cannot bounce "
                         f"back faster than it arrived (got speed_out={speed_out!r})")
    # Away from the wall is positive, so the ball arrives with a negative velocity.
    dp = change_in_momentum(mass, -speed_in, speed_out)
    contact = contact_ms / 1000
    force = dp / contact
    choices = ("towards the wall", "away from the wall")
    slip = mass * (speed_in - speed_out)
    m, u, v, t_ms, t = n(mass, 2), n(speed_in, 2), n(speed_out, 2), n(contact_ms, 2), n(contact, 2)
    return Question(
        key="practice-wall-bounce",
        text=(f"A ball of mass {m} kg hits a vertical wall at right angles at {u} {PER_S} and bounces "
              f"straight back at {v} {PER_S}. It is in contact with the wall for {t_ms} ms.\n\n"
              "(a) Calculate the change in momentum of the ball and give its direction.\n\n"
              "(b) Calculate the average force exerted on the ball by the wall and give its direction."),
        givens=(Given("mass", mass, "kg", 2), Given("speed in", speed_in, "m s^-1", 2),
                Given("speed out", speed_out, "m s^-1", 2), Given("contact time", contact_ms, "ms", 2)),
        parts=(
            Part("change in momentum of the ball", dp, "N s", "change in momentum", units=_N_S,
                 shown_sig_figs=2, direction="choice", choices=choices,
                 answer_direction="away from the wall",
                 direction_hint="The ball's momentum changes from towards the wall to away from it.",
                 revisit="Take one direction as positive: Δp = mv − mu with u negative, so |Δp| = m(u + v).",
                 mistakes=(
                     Mistake("u - v instead of u + v", slip,
                             "You used m(u − v). The ball reverses, so the velocities have opposite "
                             "signs: Δp = m(u + v)."),
                     Mistake("initial momentum only", momentum(mass, speed_in),
                             "That is only the momentum before. Δp = final momentum − initial "
                             "momentum, with signs."),
                 )),
            Part("average force exerted on the ball by the wall", force, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=choices, answer_direction="away from the wall",
                 working=(Step("change in momentum", dp, "N s", 2),),
                 answer_from=lambda p: p / contact,
                 ecf=Ecf(a_answer / contact_symbol, {"contact": contact}),
                 direction_hint="The force on the ball is in the direction of its change in momentum.",
                 revisit="Average force = change in momentum ÷ contact time, with the time in s.",
                 mistakes=(
                     Mistake("milliseconds not converted", dp / contact_ms,
                             f"You divided by {t_ms} instead of {t}: convert ms to s."),
                     Mistake("u - v carried through", slip / contact,
                             "You used m(u − v) for the change in momentum. The ball reverses: "
                             "Δp = m(u + v)."),
                     Mistake("force on the wall", force,
                             "That is the force of the ball on the wall (its Newton's third law "
                             "pair). The wall pushes the ball away from the wall.",
                             direction="towards the wall"),
                 )),
        ),
        mark_scheme=(
            Mark(f"Away from the wall positive: Δp = mv − mu = {m} × {v} − {m} × (−{u})", "C1", "a"),
            Mark(f"= {n(dp, 2)} N s, away from the wall", "A1", "a"),
            Mark(f"F = Δp / Δt = {w(dp)} / {t}", "C1", "b"),
            Mark(f"= {n(force, 2)} N, away from the wall", "A1", "b"),
        ),
    )


def fire_hose(per_second: float = 4.0, speed: float = 15.0) -> Question:
    """Force from a steady stream: F = (Δm/Δt) v."""
    force = stream_force(per_second, speed)
    q, v = n(per_second, 2), n(speed, 2)
    return Question(
        key="practice-hose",
        text=(f"A fire hose sends out {q} kg of water every second at a speed of {v} {PER_S}. "
              "Calculate the force that the hose exerts on the water."),
        givens=(Given("mass per second", per_second, "kg s^-1", 2), Given("speed", speed, "m s^-1", 2)),
        parts=(
            Part("force the hose exerts on the water", force, "N", "force", shown_sig_figs=2,
                 revisit=f"Force = rate of change of momentum: each second {q} kg gains a speed of "
                         f"{v} m s⁻¹, so F = (Δm/Δt) v.",
                 mistakes=(
                     Mistake("speed squared", per_second * speed**2,
                             "You squared the speed. F = (Δm/Δt) v: the mass per second is already "
                             "given (ρAv² is for a jet described by its area)."),
                     Mistake("weight of water", weight(per_second),
                             f"That is the weight of {q} kg of water. The force comes from the "
                             "momentum given to the water each second."),
                     Mistake("kinetic energy per second", kinetic_energy(per_second, speed),
                             "That is the kinetic energy given to the water each second, a power "
                             "in W. Force = momentum per second.", unit="W"),
                 )),
        ),
        mark_scheme=(
            Mark(f"F = (Δm / Δt) v = {q} × {v}", "C1"),
            Mark(f"= {n(force, 2)} N", "A1"),
        ),
    )


def car_stopping_time(mass: float = 900.0, speed: float = 12.0, force: float = 3600.0) -> Question:
    """Constant force, find the time: Δt = Δp / F."""
    dp = momentum(mass, speed)
    duration = time_for_momentum_change(dp, force)
    m, v, f = n(mass, 2), n(speed, 2), n(force, 2)
    return Question(
        key="practice-stopping-time",
        text=(f"A car of mass {m} kg moving at {v} {PER_S} is brought to rest by a constant resultant "
              f"force of {f} N. Calculate the time it takes to stop."),
        givens=(Given("mass", mass, "kg", 2), Given("speed", speed, "m s^-1", 2),
                Given("force", force, "N", 2)),
        parts=(
            Part("time to stop", duration, "s", "time", shown_sig_figs=2,
                 revisit="Force × time = change in momentum, so Δt = Δp / F.",
                 mistakes=(
                     Mistake("force over momentum", force / dp,
                             "That is F / Δp, upside down: Δt = Δp / F."),
                     Mistake("mass over force", mass / force,
                             f"You left out the speed. The change in momentum is mv = {m} × {v}."),
                 )),
        ),
        mark_scheme=(
            Mark(f"Δp = mv = {m} × {v} = {w(dp)} N s", "C1"),
            Mark(f"Δt = Δp / F = {w(dp)} / {f} = {n(duration, 2)} s", "A1"),
        ),
    )


TEMPLATES = (
    Template("quick-check-1", "force-momentum", ("numeric",), "Quick check 1",
             trolley_pushed_from_rest,
             {"force": Draw(5.0, 2.0, 9.0, 0.5), "mass": Draw(2.0, 1.0, 5.0, 0.5),
              "duration": Draw(3.0, 2.0, 6.0, 0.5)}),
    Template("practice-wall-bounce", "force-momentum", ("numeric",), "Ball bouncing off a wall",
             ball_bounces_off_wall,
             {"mass": Draw(0.16, 0.10, 0.60, 0.01), "speed_in": Draw(15.0, 8.0, 25.0, 1.0),
              "speed_out": Draw(10.0, 4.0, 20.0, 1.0), "contact_ms": Draw(20.0, 10.0, 40.0, 1.0)}),
    Template("practice-hose", "force-momentum", ("numeric",), "Fire hose", fire_hose,
             {"per_second": Draw(4.0, 1.0, 8.0, 0.5), "speed": Draw(15.0, 8.0, 30.0, 1.0)}),
    Template("practice-stopping-time", "force-momentum", ("numeric",), "Time to stop a car", car_stopping_time,
             {"mass": Draw(900.0, 600.0, 2000.0, 100.0), "speed": Draw(12.0, 5.0, 30.0, 1.0),
              "force": Draw(3600.0, 1000.0, 9900.0, 100.0)}),
)
