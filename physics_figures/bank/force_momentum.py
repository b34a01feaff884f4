# ruff: noqa: RUF001  (question text is typeset: true minus, times, Greek letters)
"""Force as the rate of change of momentum: F = Δp/Δt, impulse, streams and bounces."""

from __future__ import annotations

import sympy

from ..models import (
    MomentumHistory,
    acceleration,
    area_under_force_time,
    average_force,
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
from ..questions import (
    ChoicePart,
    Ecf,
    Given,
    Graph,
    GraphPart,
    Mark,
    Mistake,
    Part,
    Question,
    Reading,
    Step,
    choices_in_order,
)
from ..variants import Draw, Template
from ._common import M_S as _M_S
from ._common import N_S as _N_S
from ._common import PER_S, reading, reading_rule, w

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
                             "(here force × time), in N s.", unit="J", see="kinetic-energy"),
                 ), see="second-law"),
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
                 ), see="momentum"),
        ),
        mark_scheme=(
            Mark(f"Δp = FΔt = {n(force, 2)} × {n(duration, 2)}", "C1", "a"),
            Mark(f"= {n(p, 2)} N s, so the final momentum is {n(p, 2)} kg m s<sup>−1</sup> "
                 "(it started at rest)", "A1", "a"),
            Mark(f"speed = p / m = {w(p)} / {n(mass, 2)}", "C1", "b"),
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
                             "momentum, with signs.", see="conservation"),
                 ), see="second-law"),
            Part("average force exerted on the ball by the wall", force, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=choices, answer_direction="away from the wall",
                 working=(Step("change in momentum", dp, "N s", 2),),
                 answer_from=lambda p: p / contact,
                 ecf=Ecf(a_answer / contact_symbol, {"contact": contact}),
                 direction_hint="The force on the ball is in the direction of its change in momentum.",
                 revisit="Average force = change in momentum ÷ contact time, with the time in s.",
                 mistakes=(
                     Mistake("milliseconds not converted", dp / contact_ms,
                             f"You divided by {t_ms} instead of {t}: convert ms to s.", kind="slip"),
                     Mistake("u - v carried through", slip / contact,
                             "You used m(u − v) for the change in momentum. The ball reverses: "
                             "Δp = m(u + v)."),
                     Mistake("force on the wall", force,
                             "That is the force of the ball on the wall (its Newton's third law "
                             "pair). The wall pushes the ball away from the wall.",
                             direction="towards the wall", see="third-law"),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"Away from the wall positive: Δp = mv − mu = {m} × {v} − {m} × (−{u})", "C1", "a"),
            Mark(f"= {n(dp, 2)} N s", "A1", "a"),
            Mark("away from the wall", "B1", "a", earns="direction"),
            Mark(f"F = Δp / Δt = {w(dp)} / {t}", "C1", "b"),
            Mark(f"= {n(force, 2)} N", "A1", "b"),
            Mark("away from the wall (the direction of the ball's change in momentum)", "B1", "b", earns="direction"),
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
                             "momentum given to the water each second.", see="weight"),
                     Mistake("kinetic energy per second", kinetic_energy(per_second, speed),
                             "That is the kinetic energy given to the water each second, a power "
                             "in W. Force = momentum per second.", unit="W", see="kinetic-energy"),
                 ), see="second-law"),
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
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"Δp = mv = {m} × {v} = {w(dp)} N s", "C1"),
            Mark(f"Δt = Δp / F = {w(dp)} / {f} = {n(duration, 2)} s", "A1"),
        ),
    )


# ---------------------------------------------------------------- reading a graph

b_answer, widths_symbol, interval_symbol = sympy.symbols("b widths interval")


def kick_force_time(peak: float = 200.0, rise: float = 0.01, hold: float = 0.03, fall: float = 0.01,
                    mass: float = 0.45) -> Question:
    """A force-time graph of a kick: read the peak force, the impulse is the area under the
    graph (notes: area under a force-time graph = change in momentum), then the speed."""
    times = (0.0, rise, rise + hold, rise + hold + fall)
    forces = (0.0, peak, peak, 0.0)
    area = area_under_force_time(times, forces)
    speed = velocity_from_momentum(area, mass)
    contact = times[-1]
    widths = hold + contact  # the trapezium's two parallel sides, in s
    graph = Graph("force–time", "force", "N", tuple(zip(times, forces, strict=True)),
                  time_division=0.002, value_division=10.0, time_max=0.1, value_max=350.0, shaded=True)
    f, m = reading(peak, 5.0), n(mass, 2)
    # the impulse is worked from the top and three times where the line turns, all read off the
    # graph: readings within half a small square give a range of right answers (Part.band)
    turns = ("time the force reaches its top", "time it leaves the top", "time the boot leaves the ball")
    read = (Reading("largest force", peak, graph.value_division / 2),
            *(Reading(name, t, graph.time_division / 2) for name, t in zip(turns, times[1:], strict=True)))

    def impulse_read(top: float, *turns: float) -> float:
        return area_under_force_time((0.0, *turns), (forces[0], top, top, forces[-1]))

    return Question(
        key="graph-kick-force-time",
        text=(f"A football of mass {m} kg is at rest. A player kicks it, and the graph shows how the "
              "force on the ball varies with time while the boot is in contact with it. "
              f"{reading_rule(5.0, 'N')}"),
        givens=(Given("mass", mass, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("largest force on the ball", peak, "N", "force", tolerance=5.0,
                      revisit="Read the top of the graph against the force axis."),
            Part("impulse on the ball", area, "N s", "impulse", units=_N_S, shown_sig_figs=2,
                 revisit="Impulse = change in momentum = the area under the force–time graph.",
                 ecf=Ecf(a_answer * widths_symbol / 2, {"widths": widths}),
                 readings=read, answer_from_readings=impulse_read,
                 mistakes=(
                     Mistake("largest force × whole contact time", peak * contact,
                             "You took the area as a rectangle, largest force × contact time. The force "
                             "rises and falls: find the area of the trapezium under the line."),
                     Mistake("only the flat part", peak * hold,
                             "You found only the area under the flat top. The sloping sides add area "
                             "too: every part under the line is change in momentum."),
                     Mistake("largest force × time ÷ 2", peak * contact / 2,
                             "You treated the area as a triangle. The top is flat for a while: use the "
                             "trapezium, ½ × (sum of the parallel sides) × height."),
                 ), see="momentum-time-graph"),
            Part("speed of the ball as it leaves the boot", speed, "m s^-1", "speed", units=_M_S,
                 shown_sig_figs=2, ecf=Ecf(b_answer / mass_symbol, {"mass": mass}),
                 readings=read, answer_from_readings=lambda *r: velocity_from_momentum(impulse_read(*r), mass),
                 revisit="The ball starts at rest, so its momentum afterwards is the impulse: v = Δp / m.",
                 mistakes=(
                     Mistake("impulse × mass", area * mass,
                             "You multiplied the impulse by the mass. Δp = mv, so v = Δp / m.", see="momentum-time-graph"),
                     Mistake("force ÷ mass", acceleration(peak, mass),
                             "That is the largest acceleration, F / m, in m s⁻². The speed comes from "
                             "the change in momentum: v = Δp / m.", see="second-law"),
                 ), see="conservation"),
        ),
        mark_scheme=(
            Mark(f"{f} N (the top of the graph)", "B1", "a"),
            Mark(f"impulse = area under the graph = ½ × ({w(hold)} + {w(contact)}) × {f}", "C1", "b"),
            Mark(f"= {n(area, 2)} N s", "A1", "b"),
            Mark(f"v = Δp / m = {w(area)} / {m}", "C1", "c"),
            Mark(f"= {n(speed, 2)} {PER_S}", "A1", "c"),
        ),
    )


def cyclist_momentum_time(start: float = 240.0, end: float = 640.0, begins: float = 4.0,
                          lasts: float = 8.0) -> Question:
    """A momentum-time graph: read two momenta, the resultant force is the gradient (notes:
    reading a momentum-time graph)."""
    history = MomentumHistory((0.0, begins, begins + lasts, 20.0), (start, start, end, end))
    force = float(history.segment_forces[1])
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  time_division=0.5, value_division=20.0, time_max=20.0, value_max=1000.0)
    t0, t1 = n(begins, decimals=1), n(begins + lasts, decimals=1)
    return Question(
        key="graph-cyclist-momentum-time",
        text=("The graph shows how the momentum of a cyclist changes as she speeds up along a straight, "
              f"level road. {reading_rule(10.0, 'N s')}"),
        givens=(),
        graph=graph,
        parts=(
            GraphPart("momentum before she speeds up", start, "N s", "momentum", units=_N_S,
                      tolerance=10.0,
                      revisit="Read the flat part of the line at the start against the momentum axis.", see="momentum"),
            GraphPart("momentum after she speeds up", end, "N s", "momentum", units=_N_S,
                      tolerance=10.0,
                      revisit="Read the flat part of the line at the end against the momentum axis.", see="momentum"),
            Part(f"resultant force on her between {t0} s and {t1} s", force, "N", "force",
                 shown_sig_figs=2,
                 ecf=Ecf((b_answer - a_answer) / interval_symbol, {"interval": lasts}),
                 # the times are printed in the prompt; the two momenta are read off the graph
                 readings=(Reading("momentum before", start, graph.value_division / 2),
                           Reading("momentum after", end, graph.value_division / 2)),
                 answer_from_readings=lambda before, after: average_force(after - before, lasts),
                 revisit="The resultant force is the gradient of the momentum–time graph: F = Δp / Δt.",
                 mistakes=(
                     Mistake("final momentum ÷ time", average_force(end, lasts),
                             "You divided the final momentum by the time. The force is the change in "
                             "momentum ÷ time: subtract the momentum before.", see="conservation"),
                     Mistake("time from zero", average_force(end - start, begins + lasts),
                             f"You measured the time from 0. The momentum changes only from {t0} s to "
                             f"{t1} s: use that time.", see="momentum"),
                 ), see="momentum-time-graph"),
        ),
        mark_scheme=(
            Mark(f"{reading(start, 10.0)} N s", "B1", "a"),
            Mark(f"{reading(end, 10.0)} N s", "B1", "b"),
            Mark(f"F = gradient = Δp / Δt = ({reading(end, 10.0)} − {reading(start, 10.0)}) / ({t1} − {t0})",
                 "C1", "c"),
            Mark(f"= {n(force, 2)} N", "A1", "c"),
        ),
    )


def ball_bounce_momentum_time(before: float = 2.4, after: float = 1.6, arrives: float = 0.02,
                              contact: float = 0.03) -> Question:
    """A momentum-time graph of a ball that bounces back: the momentum changes sign, so
    Δp = m(u + v) in size (notes: common mistake, forgetting the direction reverses)."""
    towards, away = "towards the wall", "away from the wall"
    history = MomentumHistory((0.0, arrives, arrives + contact, 0.1), (before, before, -after, -after))
    force = float(history.segment_forces[1])  # negative: away from the wall
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  time_division=0.002, value_division=0.1, time_max=0.1, value_max=3.0, value_min=-3.0)
    return Question(
        key="graph-bounce-momentum-time",
        text=("A ball hits a wall at right angles and bounces straight back. The graph shows its "
              "momentum, taking the direction towards the wall as positive. "
              f"{reading_rule(0.05, 'N s')}"),
        givens=(),
        graph=graph,
        parts=(
            GraphPart("momentum of the ball before it hits the wall", before, "N s", "momentum",
                      units=_N_S, tolerance=0.05,
                      revisit="Read the line before the bounce against the momentum axis.", see="momentum"),
            GraphPart("momentum of the ball after it bounces", -after, "N s", "momentum", units=_N_S,
                      tolerance=0.05, direction="signed", positive=towards,
                      revisit="After the bounce the ball moves away from the wall: its momentum is "
                              "negative. Read the line below the time axis.", see="momentum"),
            Part("average force on the ball from the wall", abs(force), "N", "force", shown_sig_figs=2,
                 direction="choice", choices=(towards, away), answer_direction=away,
                 ecf=Ecf((b_answer - a_answer) / interval_symbol, {"interval": contact}),
                 # both momenta and the contact's two ends are read off the graph
                 readings=(Reading("momentum before", before, graph.value_division / 2),
                           Reading("momentum after", -after, graph.value_division / 2),
                           Reading("time the ball meets the wall", arrives, graph.time_division / 2),
                           Reading("time the ball leaves the wall", arrives + contact, graph.time_division / 2)),
                 answer_from_readings=lambda p0, p1, t0, t1: average_force(p1 - p0, t1 - t0),
                 direction_hint="The momentum changes from towards the wall to away from it, so the "
                                "force on the ball is away from the wall.",
                 revisit="F = Δp / Δt, with Δp = final − initial momentum, signs included.",
                 mistakes=(
                     Mistake("forgot that the ball reverses", average_force(before - after, contact),
                             "You subtracted the sizes. The momentum changes sign: Δp = (−"
                             f"{reading(after, 0.05)}) − {reading(before, 0.05)}, so the sizes add."),
                     Mistake("only the momentum before", average_force(before, contact),
                             "You used only the momentum before. Δp = final − initial momentum.", see="conservation"),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"{reading(before, 0.05)} N s", "B1", "a"),
            Mark(f"{reading(-after, 0.05)} N s (negative: away from the wall)", "B1", "b"),
            Mark(f"F = Δp / Δt = ({reading(-after, 0.05)} − {reading(before, 0.05)}) / {w(contact)}", "C1", "c"),
            Mark(f"= {n(abs(force), 2)} N", "A1", "c"),
            Mark("<strong>away from the wall</strong>", "B1", "c", earns="direction"),
        ),
    )



def bounce_force_choice(mass_g: float = 60.0, speed_in: float = 12.0, speed_out: float = 8.0,
                        contact_ms: float = 25.0) -> Question:
    """Paper 1 style: average force on a ball that bounces straight back. Wrong options are the
    notes' mistakes: speed change not velocity change, final momentum only, ms not converted."""
    if speed_out >= speed_in:
        raise ValueError(f"speed_out must be less than speed_in={speed_in!r} m s^-1: a ball cannot bounce "
                         f"back faster than it arrived (got speed_out={speed_out!r})")
    mass, contact = mass_g / 1000, contact_ms / 1000
    dp = change_in_momentum(mass, -speed_in, speed_out)
    key = average_force(dp, contact)
    options, answer = choices_in_order(key, {
        "speed change not velocity change": (
            average_force(mass * (speed_in - speed_out), contact),
            ("You used the change in speed, m(u − v). The ball reverses, so its velocity changes by "
             "u + v: Δp = m(u + v).")),
        "final momentum only": (
            average_force(momentum(mass, speed_out), contact),
            "You used only the momentum after the bounce. Δp = final − initial momentum, with signs.", "conservation"),
        "grams not converted": (
            average_force(change_in_momentum(mass_g, -speed_in, speed_out), contact),
            f"You used the mass in g. Convert to kg: {n(mass, 2)} kg.", "first-law"),
        "change in momentum taken as 2mu": (
            average_force(2 * momentum(mass, speed_in), contact),
            ("You used Δp = 2mu, which holds only when the ball bounces back at the speed it arrived. "
             f"It leaves at {n(speed_out, 2)} m s⁻¹: Δp = m(u + v).")),
        "milliseconds not converted": (
            average_force(dp, contact_ms),
            f"You divided by the time in ms. Convert to s: {n(contact_ms, 2)} ms = {n(contact, 2)} s.", "first-law"),
    }, sig_figs=2, unit="N", seed=1)
    return Question(
        key="bounce-force-choice",
        text=(f"A ball of mass {n(mass_g, 2)} g hits a wall at right angles at {n(speed_in, 2)} {PER_S} and "
              f"rebounds straight back at {n(speed_out, 2)} {PER_S}. It is in contact with the wall for "
              f"{n(contact_ms, 2)} ms."),
        givens=(Given("mass", mass_g, "g", 2), Given("speed in", speed_in, "m s^-1", 2),
                Given("speed out", speed_out, "m s^-1", 2), Given("contact time", contact_ms, "ms", 2)),
        parts=(ChoicePart("What is the magnitude of the average force exerted on the ball by the wall?",
                          options, answer,
                          revisit="F = Δp / Δt, with Δp = m(u + v) for a ball that reverses, in kg and s.", see="second-law"),),
        mark_scheme=(Mark(f"{answer}: F = {n(mass, 2)} × ({n(speed_in, 2)} + {n(speed_out, 2)}) / "
                          f"{n(contact, 2)} = {n(key, 2)} N", "B1"),),
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
    Template("graph-kick-force-time", "force-momentum", ("graph", "numeric"), "A kick: force–time graph",
             kick_force_time,
             {"peak": Draw(200.0, 120.0, 300.0, 10.0), "rise": Draw(0.01, 0.006, 0.02, 0.002),
              "hold": Draw(0.03, 0.01, 0.04, 0.002), "fall": Draw(0.01, 0.006, 0.02, 0.002),
              "mass": Draw(0.45, 0.40, 0.50, 0.01)}),
    Template("graph-cyclist-momentum-time", "force-momentum", ("graph", "numeric"),
             "A cyclist: momentum–time graph", cyclist_momentum_time,
             {"start": Draw(240.0, 100.0, 400.0, 20.0), "end": Draw(640.0, 500.0, 900.0, 20.0),
              "begins": Draw(4.0, 2.0, 6.0, 0.5), "lasts": Draw(8.0, 4.0, 12.0, 0.5)}),
    Template("graph-bounce-momentum-time", "force-momentum", ("graph", "numeric"),
             "A bounce: momentum–time graph", ball_bounce_momentum_time,
             {"before": Draw(2.4, 1.5, 2.9, 0.1), "after": Draw(1.6, 0.5, 2.0, 0.1),
              "arrives": Draw(0.02, 0.01, 0.04, 0.002), "contact": Draw(0.03, 0.01, 0.05, 0.002)}),
    Template("bounce-force-choice", "force-momentum", ("mcq",), "Average force in a bounce",
             bounce_force_choice,
             {"mass_g": Draw(60.0, 40.0, 200.0, 10.0), "speed_in": Draw(12.0, 8.0, 25.0, 1.0),
              "speed_out": Draw(8.0, 3.0, 15.0, 1.0), "contact_ms": Draw(25.0, 10.0, 50.0, 5.0)}),
)
