# ruff: noqa: RUF001, RUF002, RUF003  (question text is typeset: true minus, times, Greek letters, dashes)
"""Force as the rate of change of momentum: F = Δp/Δt, impulse, streams and bounces."""

from __future__ import annotations

import math

import numpy
import sympy

from ..constants import G_EARTH
from ..models import (
    MomentumHistory,
    acceleration,
    area_under_force_time,
    average_force,
    bounce_contact_force,
    change_in_momentum,
    impulse,
    kinetic_energy,
    mass_from_momentum_change,
    momentum,
    stream_force,
    time_for_momentum_change,
    velocity_from_momentum,
    weight,
)
from ..notation import axis_power, power_text, round_number
from ..notation import format_number as n
from ..parts.graph import value_axis
from ..questions import (
    OPTION_LETTERS,
    ChoicePart,
    Ecf,
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
from ._common import M_S as _M_S
from ._common import (
    MOMENTUM_WORKING_C1,
    PER_S,
    enough_figures,
    one_of_each,
    reading,
    reading_rule,
    stated_figures,
    w,
)
from ._common import N_S as _N_S
from .givens import checked_givens

a_answer, mass_symbol, contact_symbol = sympy.symbols("a mass contact")
c_answer, gravity_symbol = sympy.symbols("c gravity")


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
                     Mistake("speed given as momentum", velocity_from_momentum(p, mass),
                             f"That is the speed, F Δt / m, in m s⁻¹. The final momentum is the change in "
                             f"momentum, F Δt = {n(force, 2)} × {n(duration, 2)}, in N s.", see="momentum"),
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
                     # wrong physics (impulse is not energy): keeps no mark (XP, 9702/22/M/J/20 annotations)
                     Mistake("impulse taken as kinetic energy", math.sqrt(2 * p / mass),
                             "You set F Δt equal to ½mv². Force × time is the change in momentum, not "
                             "energy (that is force × distance): v = Δp / m.", see="second-law"),
                     Mistake("distance given as speed", 0.5 * acceleration(force, mass) * duration**2,
                             f"That is the distance it travels in {n(duration, 2)} s, ½at², in m. The speed "
                             "is v = p / m (or u + at).", see="second-law"),
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
                             "signs: Δp = m(u + v).", keeps=("method",), credited=MOMENTUM_WORKING_C1),
                     Mistake("initial momentum only", momentum(mass, speed_in),
                             "That is only the momentum before. Δp = final momentum − initial "
                             "momentum, with signs.", keeps=("method",), credited=MOMENTUM_WORKING_C1,
                             see="conservation"),
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


def _bounce_story(mass: str, speed_in: str, speed_out: str, contact: str, surface: str) -> str:
    """The question's text: the ball at rest, then the bounce off a floor (dropped) or a ceiling
    (thrown up), with the five parts."""
    how = ("It is dropped and hits the floor vertically" if surface == "floor"
           else "It is thrown vertically upwards and hits a horizontal ceiling")
    back = "up" if surface == "floor" else "down"
    return (f"A ball of mass {mass} kg rests on a horizontal table. {how} at {speed_in} {PER_S}. It is in contact "
            f"with the {surface} for {contact} s and leaves it vertically {back}wards at {speed_out} {PER_S}. Air "
            "resistance is negligible.\n\n"
            "(a) Calculate the normal contact force of the table on the ball while it rests on the table.\n\n"
            f"(b) Calculate the decrease in kinetic energy of the ball in the collision with the {surface}.\n\n"
            "(c) Calculate the average resultant force on the ball during the collision and give its direction.\n\n"
            f"(d) Calculate the magnitude of the average force exerted by the {surface} on the ball.\n\n"
            f"(e) Calculate the average force exerted by the ball on the {surface} and give its direction.")


def _energy_lost_mistakes(mass: float, speed_in: float, speed_out: float) -> tuple[Mistake, ...]:
    """The kinetic energy lost in a bounce, worked wrongly."""
    return one_of_each(kinetic_energy(mass, speed_in) - kinetic_energy(mass, speed_out), (
        Mistake("speeds subtracted before squaring", kinetic_energy(mass, speed_in - speed_out),
                "You squared the difference of the speeds. Work out each kinetic energy and subtract: "
                "ΔE = ½mu² − ½mv², not ½m(u − v)².", see="kinetic-energy"),
        Mistake("½ left out", 2 * (kinetic_energy(mass, speed_in) - kinetic_energy(mass, speed_out)),
                "You left out the ½: kinetic energy is ½mv².", see="kinetic-energy"),
        Mistake("the kinetic energy before only", kinetic_energy(mass, speed_in),
                "That is all the kinetic energy it arrives with. It leaves with some: the decrease is "
                "½mu² − ½mv².", see="kinetic-energy"),
        Mistake("speeds added before squaring", kinetic_energy(mass, speed_in + speed_out),
                "You added the speeds as in the change in momentum. Energy is a scalar: the decrease is "
                "½mu² − ½mv².", see="kinetic-energy"),
    ))


def _contact_force_parts(mass: float, force: float, surface: str, ways: tuple[str, str]) -> tuple[Part, Part]:
    """(d) the surface's force on the ball, F ± mg, and (e) its third-law partner on the surface."""
    contact = bounce_contact_force(force, mass, surface=surface)
    other = "ceiling" if surface == "floor" else "floor"
    wrong_way = bounce_contact_force(force, mass, surface=other) if force > weight(mass) else None
    sign = 1 if surface == "floor" else -1
    on_ball, on_surface = ways
    d_mistakes = [Mistake("the weight left out", force,
                          f"That is the resultant force. The {surface}'s push is only one of the two forces on "
                          "the ball: the weight acts too.", see="weight")]
    if wrong_way is not None:
        d_mistakes.append(Mistake("the weight the wrong way", wrong_way,
                                  f"The weight acts downwards: off a {surface} the {surface}'s push and the weight "
                                  f"{'oppose' if surface == 'floor' else 'act the same way'}, so "
                                  f"R = F {'+' if surface == 'floor' else '−'} mg.", see="weight"))
    return (
        Part(f"magnitude of the average force exerted by the {surface} on the ball", contact, "N", "force",
             shown_sig_figs=2, answer_for_g=lambda g: bounce_contact_force(force, mass, surface=surface, g=g),
             ecf=Ecf(c_answer + sign * mass_symbol * gravity_symbol, {"mass": mass, "gravity": G_EARTH}),
             revisit=f"The resultant force is the {surface}'s push and the weight together: "
                     f"R {'−' if surface == 'floor' else '+'} mg = F.",
             mistakes=one_of_each(contact, d_mistakes), see="weight"),
        Part(f"average force exerted by the ball on the {surface}", contact, "N", "force", shown_sig_figs=2,
             direction="choice", choices=("upwards", "downwards"), answer_direction=on_surface,
             answer_for_g=lambda g: bounce_contact_force(force, mass, surface=surface, g=g),
             direction_hint=f"Newton's third law: the ball pushes on the {surface} the opposite way to the "
                            f"{surface}'s push on the ball.",
             revisit=f"Newton's third law: the ball's force on the {surface} is equal in size and opposite in "
                     f"direction to the {surface}'s force on the ball.",
             mistakes=one_of_each(contact, (
                 Mistake(f"the direction of the {surface}'s force", contact,
                         f"That is the direction of the {surface}'s push on the ball. Its third-law partner acts "
                         f"on the {surface}, the opposite way.", direction=on_ball, see="third-law"),
                 Mistake("the resultant force", force,
                         f"That is the resultant force on the ball. The ball's push on the {surface} is the "
                         f"partner of the {surface}'s push on the ball, R, not of the resultant.",
                         see="third-law"),
             )), see="third-law"),
    )


def ball_bounce_contact_force(mass: float = 0.060, speed_in: float = 6.0, speed_out: float = 4.0,
                              contact: float = 0.080, ceiling: int = 0) -> Question:
    """A ball bounces vertically off a floor or a ceiling: the kinetic energy it loses, the
    resultant force m(u + v)/t, the surface's force R = F ± mg, and the ball's force on the
    surface (third law). The papers ask these of one bounce: 9702/23/M/J/18 Q3 (a ceiling),
    9702/21/O/N/20 Q3(b) and 9702/22/M/J/21 Q2(c) (a floor), and 9702/21/M/J/16 Q3(a)(i) the
    contact force on the ball at rest ("force (= mg = 0.15 × 9.81) = 1.5 (1.47) N A1")."""
    if speed_out >= speed_in:  # a real bounce loses kinetic energy
        raise ValueError(f"speed_out must be less than speed_in={speed_in!r} m s^-1: a ball cannot bounce "
                         f"back faster than it arrived (got speed_out={speed_out!r})")
    surface = "ceiling" if ceiling else "floor"
    # away from the surface is positive: the change in momentum and the resultant force point that way
    dp = change_in_momentum(mass, -speed_in, speed_out)
    force = average_force(dp, contact)
    ways = ("upwards", "downwards") if surface == "floor" else ("downwards", "upwards")  # on the ball, on it
    lost = kinetic_energy(mass, speed_in) - kinetic_energy(mass, speed_out)
    resting = weight(mass)
    m, u, v = n(mass, stated_figures(mass)), n(speed_in, stated_figures(speed_in)), n(speed_out, stated_figures(speed_out))
    t = n(contact, stated_figures(contact))
    contact_force, on_surface = _contact_force_parts(mass, force, surface, ways)
    sign = 1 if surface == "floor" else -1
    # the working prints F and mg with the figures that give the printed R, as an examiner checks it
    force_shown, weight_shown = enough_figures((force, resting), lambda f, r: f + sign * r, n(contact_force.value, 2))
    return Question(
        key="bounce-contact-force",
        text=_bounce_story(m, u, v, t, surface),
        givens=(Given("mass", mass, "kg", stated_figures(mass)), Given("speed in", speed_in, "m s^-1",
                stated_figures(speed_in)), Given("speed out", speed_out, "m s^-1", stated_figures(speed_out)),
                Given("contact time", contact, "s", stated_figures(contact))),
        parts=(
            Part("normal contact force of the table on the ball at rest", resting, "N", "force", shown_sig_figs=2,
                 answer_for_g=lambda g: weight(mass, g=g),
                 revisit="At rest the resultant force is zero, so the normal contact force balances the weight: "
                         "R = mg.",
                 mistakes=(Mistake("the mass given as the force", mass,
                                   f"That is the mass, {m} kg. The force is the weight it balances: mg, in N.",
                                   see="weight"),), see="weight"),
            Part(f"decrease in kinetic energy in the collision with the {surface}", lost, "J", "energy",
                 shown_sig_figs=2, revisit="Kinetic energy is ½mv²: the decrease is ½mu² − ½mv².",
                 mistakes=_energy_lost_mistakes(mass, speed_in, speed_out), see="kinetic-energy"),
            Part("average resultant force on the ball", force, "N", "force", shown_sig_figs=2,
                 direction="choice", choices=("upwards", "downwards"), answer_direction=ways[0],
                 direction_hint="The resultant force is in the direction of the ball's change in momentum.",
                 revisit="Resultant force = change in momentum ÷ contact time, and the ball turns round: "
                         "F = m(u + v) / t.",
                 mistakes=(Mistake("u − v instead of u + v", mass * (speed_in - speed_out) / contact,
                                   "You used m(u − v). The ball turns round, so the velocities have opposite "
                                   "signs: Δp = m(u + v)."),
                           Mistake("the direction the ball arrived", force,
                                   "The ball's momentum changes from towards the surface to away from it: the "
                                   "resultant force on it points away.", direction=ways[1])),
                 see="second-law"),
            contact_force, on_surface,
        ),
        mark_scheme=(
            Mark(f"R = W = mg = {m} × {n(G_EARTH, 3)} = {n(resting, 2)} N", "B1", "a"),
            Mark(f"ΔE = ½ × {m} × ({u}<sup>2</sup> − {v}<sup>2</sup>)", "C1", "b"),
            Mark(f"= {n(lost, 2)} J", "A1", "b"),
            Mark(f"F = Δp / Δt = {m} × ({u} + {v}) / {t}", "C1", "c"),
            Mark(f"= {n(force, 2)} N", "A1", "c"),
            Mark(f"{ways[0]} (away from the {surface}, the direction of the change in momentum)", "B1", "c",
                 earns="direction"),
            Mark(f"R {'−' if surface == 'floor' else '+'} mg = F, so R = {force_shown} "
                 f"{'+' if surface == 'floor' else '−'} {weight_shown}", "C1", "d"),
            Mark(f"= {n(contact_force.value, 2)} N", "A1", "d"),
            Mark(f"{n(contact_force.value, 2)} N (Newton's third law: equal to the {surface}'s force on the ball)",
                 "B1", "e"),
            Mark(f"{ways[1]} (opposite to the {surface}'s force on the ball)", "B1", "e", earns="direction"),
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
                     Mistake("stopping distance given as the time", kinetic_energy(mass, speed) / force,
                             f"That is the stopping distance in m, from F s = ½mv². The time comes from "
                             f"force × time = change in momentum: Δt = Δp / F = {m} × {v} / {f}."),
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
                     Mistake("impulse taken as kinetic energy", math.sqrt(2 * area / mass),
                             "You set the impulse equal to ½mv². The area under a force–time graph is the "
                             "change in momentum, not energy: v = Δp / m.", see="momentum-time-graph"),
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
    reading a momentum-time graph). As the papers draw them, the line may start rising at t = 0
    (begins = 0) and may fall (end below start: she slows down, and the force asked is its size)."""
    times, momenta = (0.0, begins, begins + lasts, 20.0), (start, start, end, end)
    if begins == 0:  # the change starts at once: no flat part before it
        times, momenta = times[1:], momenta[1:]
    history = MomentumHistory(times, momenta)
    force = abs(float(history.segment_forces[-2]))  # the sloping segment; its size when she slows down
    change = "speeds up" if end > start else "slows down"
    _, top, division = value_axis(max(start, end))  # the axis grows with the momenta
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  time_division=0.5, value_division=division, time_max=20.0, value_max=top)
    t0, t1 = n(begins, decimals=1), n(begins + lasts, decimals=1)
    return Question(
        key="graph-cyclist-momentum-time",
        text=(f"The graph shows how the momentum of a cyclist changes as she {change} along a straight, "
              f"level road. {reading_rule(division / 2, 'N s')}"),
        givens=(),
        graph=graph,
        parts=(
            GraphPart(f"momentum before she {change}", start, "N s", "momentum", units=_N_S,
                      tolerance=division / 2,
                      revisit="Read the flat part of the line at the start against the momentum axis.", see="momentum"),
            GraphPart(f"momentum after she {change}", end, "N s", "momentum", units=_N_S,
                      tolerance=division / 2,
                      revisit="Read the flat part of the line at the end against the momentum axis.", see="momentum"),
            Part(f"resultant force on her between {t0} s and {t1} s", force, "N", "force",
                 shown_sig_figs=2,
                 ecf=Ecf((b_answer - a_answer) / interval_symbol, {"interval": lasts}),
                 # the times are printed in the prompt; the two momenta are read off the graph
                 readings=(Reading("momentum before", start, graph.value_division / 2),
                           Reading("momentum after", end, graph.value_division / 2)),
                 answer_from_readings=lambda before, after: abs(average_force(after - before, lasts)),
                 revisit="The resultant force is the gradient of the momentum–time graph: F = Δp / Δt.",
                 mistakes=(
                     Mistake("final momentum ÷ time", average_force(end, lasts),
                             "You divided the final momentum by the time. The force is the change in "
                             "momentum ÷ time: subtract the momentum before.", see="conservation"),
                     Mistake("time from zero", abs(average_force(end - start, begins + lasts)),
                             f"You measured the time from 0. The momentum changes only from {t0} s to "
                             f"{t1} s: use that time.", see="momentum"),
                 ), see="momentum-time-graph"),
        ),
        mark_scheme=(
            Mark(f"{reading(start, division / 2)} N s", "B1", "a"),
            Mark(f"{reading(end, division / 2)} N s", "B1", "b"),
            Mark(f"F = gradient = Δp / Δt = ({reading(end, division / 2)} − {reading(start, division / 2)}) / ({t1} − {t0})",
                 "C1", "c"),
            Mark(f"= {n(force, 2)} N", "A1", "c"),
        ),
    )


#: The bounce graph's first axes, which hold the variants' momenta (1.5 to 2.9 N s before, 0.5 to
#: 2.0 N s after) and times (to 0.09 s); a paper's bounce may need others.
_BOUNCE_AXES = {"time_max": 0.1, "time_division": 0.002, "value_max": 3.0, "value_min": -3.0, "value_division": 0.1}
#: Where the ball bounces: the surface, the two directions along the line it moves on, how it
#: moves, and which way its momentum turns.
_BOUNCE_SURFACES = (("wall", "towards the wall", "away from the wall", ("hits a wall at right angles and bounces "
                     "straight back"), "from towards the wall to away from it"),
                    ("floor", "downwards", "upwards", "falls vertically onto a floor and bounces straight back up",
                     "from downwards to upwards"))


def _bounce_axes(before: float, after: float, ends: float) -> dict[str, float]:
    """The graph's axes: the first ones while they hold the line with each momentum at least five
    small squares from zero, else axes that grow or shrink with it (parts.graph.value_axis), as a
    paper's bounce of 0.93 N s, then 0.375 N s back, 0.12 s in contact, needs."""
    axes = dict(_BOUNCE_AXES)
    if not 0.5 <= min(before, after) <= max(before, after) <= 3.0:
        axes["value_min"], axes["value_max"], axes["value_division"] = value_axis(before, -after)
    if ends > 0.09:
        _, axes["time_max"], axes["time_division"] = value_axis(ends)
    # no float dust: 0.15, not 0.15000000000000002
    return {name: float(round_number(value, 12)) for name, value in axes.items()}


def ball_bounce_momentum_time(before: float = 2.4, after: float = 1.6, arrives: float = 0.02,
                              contact: float = 0.03, surface: float = 0) -> Question:
    """A momentum-time graph of a ball that bounces back: the momentum changes sign, so
    Δp = m(u + v) in size (notes: common mistake, forgetting the direction reverses).

    As the papers' bounces: arrives = 0 starts the line falling at t = 0 (no flat part before),
    the axes grow with a paper's momenta and contact time (_bounce_axes), and surface = 1 drops
    the ball onto a floor, as 9702/21/M/J/16 Q3(b)(ii) (6.2 m s⁻¹ down, 2.5 m s⁻¹ up, 0.12 s:
    11 N, upwards)."""
    if surface not in (0, 1):
        raise ValueError(f"surface must be 0 (a wall) or 1 (a floor) (got surface={surface!r})")
    where, towards, away, bounces, turns = _BOUNCE_SURFACES[int(surface)]
    times, momenta = (0.0, arrives, arrives + contact), (before, before, -after)
    if arrives == 0:  # the bounce starts at once: no flat part before it
        times, momenta = times[1:], momenta[1:]
    axes = _bounce_axes(before, after, arrives + contact)
    history = MomentumHistory((*times, axes["time_max"]), (*momenta, -after))
    force = float(history.segment_forces[-2])  # negative: away from the surface
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  **axes)
    half = axes["value_division"] / 2
    positive = "the direction towards the wall" if where == "wall" else "downwards"
    return Question(
        key="graph-bounce-momentum-time",
        text=(f"A ball {bounces}. The graph shows its momentum, taking {positive} as positive. "
              f"{reading_rule(half, 'N s')}"),
        givens=(),
        graph=graph,
        parts=(
            GraphPart(f"momentum of the ball before it hits the {where}", before, "N s", "momentum",
                      units=_N_S, tolerance=half,
                      revisit="Read the line before the bounce against the momentum axis.", see="momentum"),
            GraphPart("momentum of the ball after it bounces", -after, "N s", "momentum", units=_N_S,
                      tolerance=half, direction="signed", positive=towards,
                      revisit=f"After the bounce the ball moves {away}: its momentum is "
                              "negative. Read the line below the time axis.", see="momentum"),
            Part(f"average force on the ball from the {where}", abs(force), "N", "force", shown_sig_figs=2,
                 direction="choice", choices=(towards, away), answer_direction=away,
                 ecf=Ecf((b_answer - a_answer) / interval_symbol, {"interval": contact}),
                 # both momenta and the contact's two ends are read off the graph
                 readings=(Reading("momentum before", before, half),
                           Reading("momentum after", -after, half),
                           Reading(f"time the ball meets the {where}", arrives, axes["time_division"] / 2),
                           Reading(f"time the ball leaves the {where}", arrives + contact, axes["time_division"] / 2)),
                 answer_from_readings=lambda p0, p1, t0, t1: average_force(p1 - p0, t1 - t0),
                 direction_hint=f"The momentum changes {turns}, so the force on the ball is {away}.",
                 revisit="F = Δp / Δt, with Δp = final − initial momentum, signs included.",
                 mistakes=(
                     Mistake("forgot that the ball reverses", average_force(before - after, contact),
                             "You subtracted the sizes. The momentum changes sign: Δp = (−"
                             f"{reading(after, half)}) − {reading(before, half)}, so the sizes add."),
                     Mistake("only the momentum before", average_force(before, contact),
                             "You used only the momentum before. Δp = final − initial momentum.", see="conservation"),
                 ), see="second-law"),
        ),
        mark_scheme=(
            Mark(f"{reading(before, half)} N s", "B1", "a"),
            Mark(f"{reading(-after, half)} N s (negative: {away})", "B1", "b"),
            Mark(f"F = Δp / Δt = ({reading(-after, half)} − {reading(before, half)}) / {w(contact)}", "C1", "c"),
            Mark(f"= {n(abs(force), 2)} N", "A1", "c"),
            Mark(f"<strong>{away}</strong>", "B1", "c", earns="direction"),
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


#: A unit in feedback, which the page shows as plain text.
_PER_S_PLAIN = "m s⁻¹"


def headed_ball(change: float = 3.6, contact_ms: float = 12.0, mass: float = 0.43, speed_in: float = 3.0) -> Question:
    """Force, then speed, from a given change in momentum: F = Δp/Δt, and a ball that turns round
    has Δp = m(v + u) in size (notes, How to do it 3.; common mistake "wrong signs"). Lines as
    9702/21/M/J/16 Q3(b)(ii): "change in momentum = 0.15 x (6.2 + 2.5) C1 ... force = 1.305 / 0.12
    = 11 N A1", and 9702/21/M/J/22 Q1(b)(ii) for the change of a body that turns round."""
    contact = contact_ms / 1000
    force = average_force(change, contact)
    # away from the head is positive: Δp = m v - m(-u), so v = Δp / m - u
    speed_out = velocity_from_momentum(change, mass) - speed_in
    if speed_out <= 0:
        raise ValueError(f"change must exceed the ball's momentum before ({n(momentum(mass, speed_in), 3)} N s), "
                         f"so it is sent back (got change={change!r})")
    p, t_ms, t, m, u = n(change, 2), n(contact_ms, 2), n(contact, 2), n(mass, 2), n(speed_in, 2)
    return Question(
        key="headed-ball-force-speed",
        text=(f"A football of mass {m} kg moving horizontally at {u} {PER_S} is headed straight back the way "
              f"it came. The size of the change in the ball's momentum is {p} N s, and the player's head is "
              f"in contact with the ball for {t_ms} ms. Calculate (a) the average force of the head on the "
              "ball and (b) the speed of the ball just after it leaves the head."),
        givens=(Given("change in momentum", change, "N s", 2), Given("contact time", contact_ms, "ms", 2),
                Given("mass", mass, "kg", 2), Given("speed before", speed_in, "m s^-1", 2)),
        parts=(
            Part("average force on the ball", force, "N", "force", shown_sig_figs=2,
                 revisit="Force is the rate of change of momentum: F = Δp / Δt, with the time in s.",
                 mistakes=(
                     Mistake("milliseconds not converted", change / contact_ms,
                             f"You divided by {t_ms} instead of {t}: convert ms to s.", kind="slip"),
                     Mistake("multiplied by the time", change * contact,
                             "You multiplied the change in momentum by the time. Force is the rate of "
                             "change of momentum: F = Δp / Δt."),
                     Mistake("change in velocity given", velocity_from_momentum(change, mass),
                             f"Dividing the change in momentum by the mass gives the change in velocity, in "
                             f"m s⁻¹. The force is Δp / Δt = {p} / {t}.", unit="m s^-1", see="momentum"),
                 ), see="second-law"),
            Part("speed of the ball after it leaves the head", speed_out, "m s^-1", "speed", units=_M_S,
                 shown_sig_figs=2,
                 revisit="The ball turns round, so its velocities have opposite signs: Δp = mv − m(−u) = "
                         "m(v + u), so v = Δp / m − u.",
                 mistakes=(
                     Mistake("momentum added as scalars", velocity_from_momentum(change, mass) + speed_in,
                             f"You took Δp = m(v − u), as if the ball kept going the same way. It turns round: "
                             f"give the velocity before a minus sign, so {p} = {m}(v + {u}).", see="momentum"),
                     Mistake("the speed before left out", velocity_from_momentum(change, mass),
                             f"Δp / m = {w(velocity_from_momentum(change, mass))} {_PER_S_PLAIN} is the change in "
                             f"velocity. The ball arrived at {u} {_PER_S_PLAIN} the other way: v = Δp / m − u."),
                 ), see="momentum"),
        ),
        mark_scheme=(
            Mark(f"F = Δp / Δt = {p} / {t}", "C1", "a"),
            Mark(f"= {n(force, 2)} N", "A1", "a"),
            Mark(f"The ball turns round: Δp = m(v + u), so {p} = {m}(v + {u})", "C1", "b"),
            Mark(f"v = {p} / {m} − {u} = {n(speed_out, 2)} {PER_S}", "A1", "b"),
        ),
    )


dv_symbol = sympy.Symbol("velocity_change")


def mass_from_velocity_change(force: float = 6.0, duration: float = 2.5, speed_before: float = 1.2,
                              speed_after: float = 4.2, turns: float = 0) -> Question:
    """Mass from a given change in momentum: Δp = FΔt, then m = Δp / Δv with signs (notes, How to
    do it 3.; "Force x time = change in momentum"). turns: 0, the force acts along the motion and
    speeds the body up; 1, it acts against the motion and sends the body back. Lines as
    9702/21/M/J/16 Q3(b)(ii) (Δp C1, then the quantity worked from it A1)."""
    back = bool(int(turns))
    u = -speed_before if back else speed_before  # positive: the way the force acts
    v = speed_after
    if not back and speed_after <= speed_before:
        raise ValueError(f"speed_after must exceed speed_before={speed_before!r} m s^-1 when the force acts "
                         f"along the motion (got speed_after={speed_after!r})")
    if back and speed_after == speed_before:  # subtracting the speeds would give Δv = 0: no mass to mark
        raise ValueError(f"speed_after must differ from speed_before={speed_before!r} m s^-1 when the puck "
                         f"turns round, so the speeds-subtracted mistake has a value (got speed_after={speed_after!r})")
    dp = impulse(force, duration)
    mass = mass_from_momentum_change(dp, u, v)
    if not 0.5 <= mass <= 10.0:  # a laboratory trolley or an ice puck, as the text says
        raise ValueError(f"speed_after={speed_after!r} m s^-1 gives a mass of {n(mass, 2)} kg: the text's trolley "
                         "or puck is 0.5 to 10 kg")
    f, t, ub, va = n(force, 2), n(duration, 2), n(speed_before, 2), n(speed_after, 2)
    if back:
        motion = (f"A puck slides at {ub} {PER_S} to the left across smooth ice. A constant resultant force of "
                  f"{f} N acts on it to the right for {t} s, and it then moves at {va} {PER_S} to the right.")
        change_text = f"{va} − (−{ub})"
        scalars = Mistake("momentum added as scalars", dp / abs(speed_after - speed_before),
                          f"You subtracted the speeds. The puck turns round, so its velocity changes from −{ub} to "
                          f"+{va} {_PER_S_PLAIN}: Δv = {va} + {ub}.", see="momentum")
    else:
        motion = (f"A trolley moves at {ub} {PER_S} along a straight, level track. A constant resultant force "
                  f"of {f} N acts on it in its direction of motion for {t} s, and its speed rises to {va} {PER_S}.")
        change_text = f"{va} − {ub}"
        scalars = Mistake("speeds added", dp / (speed_after + speed_before),
                          f"You added the speeds. Both velocities are in the same direction: Δv = {va} − {ub}.",
                          see="momentum")
    dv = v - u
    return Question(
        key="mass-from-momentum-change",
        text=(f"{motion} Calculate (a) the change in its momentum and (b) its mass."),
        givens=(Given("force", force, "N", 2), Given("duration", duration, "s", 2),
                Given("speed before", speed_before, "m s^-1", 2), Given("speed after", speed_after, "m s^-1", 2)),
        parts=(
            Part("change in momentum", dp, "N s", "change in momentum", units=_N_S, shown_sig_figs=2,
                 revisit="Force × time = change in momentum: Δp = FΔt.",
                 mistakes=(
                     Mistake("force divided by time", force / duration,
                             "You divided the force by the time. Force is the rate of change of momentum, "
                             "so Δp = F × Δt."),
                 ), see="second-law"),
            Part("mass", mass, "kg", "mass", shown_sig_figs=2,
                 ecf=Ecf(a_answer / dv_symbol, {"velocity_change": dv}),
                 revisit="Δp = mv − mu = m(v − u), with a sign on each velocity: m = Δp / (v − u).",
                 mistakes=(
                     scalars,
                     Mistake("final velocity only", dp / speed_after,
                             f"You divided by the final speed. The force changed the velocity from "
                             f"{'−' if back else ''}{ub} to {va} {_PER_S_PLAIN}: divide by the change, v − u."),
                     Mistake("upside down", dv / dp,
                             "That is Δv / Δp, upside down. Δp = mΔv, so m = Δp / Δv."),
                 ), see="momentum"),
        ),
        mark_scheme=(
            Mark(f"Δp = FΔt = {f} × {t}", "C1", "a"),
            Mark(f"= {n(dp, 2)} N s", "A1", "a"),
            Mark(f"m = Δp / (v − u) = {w(dp)} / ({change_text})", "C1", "b"),
            Mark(f"= {n(mass, 2)} kg", "A1", "b"),
        ),
    )


# ------------------------------------------------- which graph? and speed from a graph


#: Bodies whose momentum–time graph the "which graph?" item shows: (what it is, how it moves,
#: the positive direction as "Take momentum ... as positive" words it, its momentum-time corners
#: (s, N s), the graph's small squares in time, s). Straight lines: the resultant force is constant in each piece (notes: "A straight
#: line means a constant force").
_MOMENTUM_STORIES = (
    ("a car", "as it moves along a straight road", "in its direction of motion",
     ((0.0, 0.0), (4.0, 12000.0), (10.0, 12000.0), (16.0, 0.0)), 0.5),
    ("a trolley", "as it is pushed from rest and then rolls freely along a level, frictionless track",
     "in its direction of motion", ((0.0, 0.0), (1.5, 2.4), (6.0, 2.4)), 0.1),
    ("a ball thrown vertically upwards", ("from the moment it leaves the hand until it is back at the "
     "same height (air resistance is negligible)"), "upwards", ((0.0, 3.0), (4.0, -3.0)), 0.1),
    ("a ball", "as it hits a wall at right angles and bounces straight back", "towards the wall",
     ((0.0, 2.4), (0.02, 2.4), (0.05, -1.6), (0.1, -1.6)), 0.002),
    ("a lorry", "as it brakes to rest on a straight road", "in its direction of motion",
     ((0.0, 60000.0), (10.0, 0.0), (20.0, 0.0)), 0.5),
    ("a cyclist", "as she speeds up along a straight, level road", "in her direction of motion",
     ((0.0, 240.0), (4.0, 240.0), (12.0, 640.0), (20.0, 640.0)), 0.5),
)


def _force_sketch(history: MomentumHistory, sign: float = 1.0, *, size_only: bool = False) -> Sketch:
    """The resultant force against time: each segment's gradient, a jump at each corner."""
    points = []
    for segment in history.segments:
        force = abs(segment.force) if size_only else sign * segment.force
        points += [(segment.t0, force), (segment.t1, force)]
    return Sketch("resultant force", "F", points)


def _area_sketch(history: MomentumHistory) -> Sketch:
    """The area under the momentum–time graph so far (the misconception's "force")."""
    times = numpy.linspace(history.times[0], history.times[-1], 41)
    areas = [0.0] + [area_under_force_time(times[:k + 1], history.momentum_at(times[:k + 1]))
                     for k in range(1, times.size)]
    return Sketch("resultant force", "F", tuple(zip(times, areas, strict=True)))


def force_from_momentum_graph_choice(story: float = 0) -> Question:
    """Paper 1 style, "which graph?": the momentum–time graph is shown; the resultant force is
    its gradient (F = Δp / Δt), so the key is a step graph, constant where the line is straight
    and zero where it is flat. The wrong options are real misreadings: the momentum graph
    itself, the area under it instead of its gradient, the sign of the force reversed, and the
    size only. As 9702/21/M/J/23 Q3(c) asks a sketch of a force against time from a
    momentum–time graph; a Paper 1 item earns its one mark for the key alone (9702/11/M/J/16,
    multiple choice: one mark an item)."""
    index = int(story)
    what, how, positive, corners, time_division = _MOMENTUM_STORIES[index]
    history = MomentumHistory(*zip(*corners, strict=True))
    key = Option("", sketch=_force_sketch(history))
    pool = (
        Option("", "the momentum graph, not the force",
               ("That graph has the shape of the momentum–time graph itself. The resultant force is its "
                "gradient, F = Δp / Δt: constant where the line is straight, zero where it is flat."),
               sketch=Sketch("resultant force", "F", corners)),
        Option("", "the area under the graph, not its gradient",
               ("That graph grows with the area under the momentum–time graph. The resultant force is "
                "the gradient of a momentum–time graph; the area under a force–time graph is the change "
                "in momentum."), sketch=_area_sketch(history)),
        Option("", "the sign of the force reversed",
               ("The sizes are right but the signs are reversed. Where the momentum increases the "
                f"gradient is positive, so the force acts in the positive direction ({positive}); where "
                "it decreases, the force is negative."), sketch=_force_sketch(history, -1.0)),
        Option("", "the size of the force only",
               ("You drew only the size of the force. Where the momentum decreases the gradient is "
                "negative: the resultant force acts the other way, below the time axis."),
               sketch=_force_sketch(history, size_only=True)),
    )
    wrong, seen = [], {key.text}
    for option in pool:  # the first three that look different from the key and each other
        if option.text not in seen and len(wrong) < len(OPTION_LETTERS) - 1:
            wrong.append(option)
            seen.add(option.text)
    place = index % len(OPTION_LETTERS)
    options = (*wrong[:place], key, *wrong[place:])
    low, high = min(0.0, *history.momenta), max(history.momenta)
    value_min, value_max, division = value_axis(high, low)
    graph = Graph("momentum–time", "momentum", "N s", corners, time_division=time_division,
                  value_division=division, time_max=corners[-1][0], value_min=value_min, value_max=value_max)
    letter = OPTION_LETTERS[place]
    return Question(
        key="force-from-momentum-graph-choice",
        text=(f"The graph shows how the momentum of {what} varies with time {how}. Take momentum "
              f"{positive} as positive."),
        givens=(),
        graph=graph,
        parts=(ChoicePart(f"Which graph shows how the resultant force on {what} varies "
                          "with time?", options, letter,
                          revisit="The resultant force is the gradient of the momentum–time graph, F = Δp / Δt: "
                                  "a straight line gives a constant force, a flat line zero force, and a line "
                                  "going down a negative force.", see="momentum-time-graph"),),
        mark_scheme=(Mark(f"{letter}: F = gradient of the momentum–time graph: {key.text[0].lower()}"
                          f"{key.text[1:]}", "B1"),),
    )


c_answer, d_answer, mass_given = sympy.symbols("c d mass_given")
#: A loaded lorry speeds up at about 0.5 to 1.5 m s^-2 (issue 37: 3.5 m s^-2 is a sports car's),
#: and its engine gives a few hundred kW at most: the resultant force × the speed at the end of
#: the speeding up stays at or below this, W.
LORRY_ACCELERATION = (0.5, 1.5)
LORRY_POWER = 300e3
#: A braking lorry slows at most about as hard as tyres grip on a dry road, m s^-2 (newton's stopping car).
LORRY_BRAKING = 6.5


def _lorry_within_its_engine(mass: float, gain_in_momentum: float, lasts: float, speed_after: float) -> None:
    """Refuse a lorry that speeds up harder, or needs more power, than a lorry does, or that
    brakes harder than its tyres allow."""
    force = average_force(gain_in_momentum, lasts)  # the gradient of the momentum-time graph
    rate = acceleration(force, mass)
    if gain_in_momentum < 0:  # braking: no engine power needed, only grip
        if -rate > LORRY_BRAKING:
            raise ValueError(f"lasts must let the lorry brake at no more than {LORRY_BRAKING:g} m s^-2, as hard as "
                             f"tyres grip on a dry road (got lasts={lasts!r} s: {n(-rate, 2)} m s^-2)")
        return
    if not LORRY_ACCELERATION[0] <= rate <= LORRY_ACCELERATION[1]:
        raise ValueError(f"lasts must give a lorry's acceleration, {LORRY_ACCELERATION[0]:g} to "
                         f"{LORRY_ACCELERATION[1]:g} m s^-2 (got lasts={lasts!r} s: {n(rate, 2)} m s^-2)")
    if force * speed_after > LORRY_POWER:
        raise ValueError(f"mass, speed_after and lasts must need at most {LORRY_POWER / 1000:g} kW, a lorry "
                         f"engine's power (got mass={mass!r}, speed_after={speed_after!r}, lasts={lasts!r}: "
                         f"{n(force * speed_after / 1000, 3)} kW)")


def lorry_speed_from_momentum_graph(mass: float = 4000.0, speed_before: float = 8.0, speed_after: float = 20.0,
                                    begins: float = 4.0, lasts: float = 8.0) -> Question:
    """A momentum–time graph beyond its gradient (issue 25): read two momenta, then the speed is
    p / m and the change in speed Δp / m (notes: "velocity = p / m, so its graph has the same
    shape"). A lorry's momentum runs to tens of thousands of N s, so the axis grows with it
    (parts.graph.value_axis). Readings earn B1 within half a small square; each calculation C1
    A1, as 9702/21/M/J/23 Q3 reads a block's momentum off its graph, and 9702/21/M/J/16
    Q3(b)(ii) marks a change in momentum C1 then its result A1. The lorry speeds up as a loaded
    lorry can (_lorry_within_its_engine).

    As the papers draw momentum-time graphs, the line may start at t = 0 (begins = 0: no flat
    part before), and the lorry may brake (speed_after below speed_before: the line falls, and
    (d) asks the decrease in its speed)."""
    times, momenta = (0.0, begins, begins + lasts, 20.0), (momentum(mass, speed_before),) * 2 + (
        momentum(mass, speed_after),) * 2
    if begins == 0:  # the change starts at once
        times, momenta = times[1:], momenta[1:]
    history = MomentumHistory(times, momenta)
    before, after = (float(p) for p in history.momenta[-3:-1])
    _lorry_within_its_engine(mass, after - before, lasts, speed_after)
    brakes = after < before
    _, top, division = value_axis(max(before, after))
    tolerance = division / 2
    graph = Graph("momentum–time", "momentum", "N s", tuple(zip(history.times, history.momenta, strict=True)),
                  time_division=0.5, value_division=division, time_max=20.0, value_max=top)
    speed = velocity_from_momentum(after, mass)
    gain = abs(velocity_from_momentum(after - before, mass))  # the increase, or the decrease as it brakes
    change, change_words = ("slows down", "decrease") if brakes else ("speeds up", "increase")
    start_words = "where the line starts, at time 0" if begins == 0 else "the flat part of the line at the start"
    m, p1, p2 = n(mass, 2), reading(before, tolerance), reading(after, tolerance)
    t_end = n(begins + lasts, decimals=1)
    # an axis of 10⁵ N s and more is labelled in its power of ten ("momentum / 10⁵ N s")
    power = axis_power(top, division)
    return Question(
        key="graph-lorry-speed-momentum-time",
        text=(f"A lorry of mass {m} kg {change} along a straight, level road. The graph shows how its "
              f"momentum varies with time. {reading_rule(tolerance, 'N s')}"),
        givens=(Given("mass", mass, "kg", 2),),
        graph=graph,
        parts=(
            GraphPart("momentum of the lorry at time 0", before, "N s", "momentum", units=_N_S,
                      tolerance=tolerance, see="momentum", mistakes=_unscaled_mistakes(before, power),
                      revisit=f"Read {start_words} against the momentum axis."),
            GraphPart(f"momentum of the lorry after {t_end} s", after, "N s", "momentum", units=_N_S,
                      tolerance=tolerance, see="momentum", mistakes=_unscaled_mistakes(after, power),
                      revisit="Read the flat part of the line at the end against the momentum axis."),
            Part(f"speed of the lorry after {t_end} s", speed, "m s^-1", "speed", units=_M_S,
                 shown_sig_figs=2, ecf=Ecf(b_answer / mass_given, {"mass_given": mass}),
                 readings=(Reading("momentum after", after, tolerance),),
                 answer_from_readings=lambda read_after: velocity_from_momentum(read_after, mass),
                 revisit="Momentum = mass × velocity, so the speed is v = p / m.",
                 mistakes=_lorry_speed_mistakes(mass, before, after, t_end), see="momentum"),
            Part(f"{change_words} in the speed of the lorry", gain, "m s^-1", "speed", units=_M_S, shown_sig_figs=2,
                 ecf=Ecf(((a_answer - b_answer) if brakes else (b_answer - a_answer)) / mass_given,
                         {"mass_given": mass}),
                 readings=(Reading("momentum before", before, tolerance), Reading("momentum after", after, tolerance)),
                 answer_from_readings=lambda read_before, read_after: abs(velocity_from_momentum(
                     read_after - read_before, mass)),
                 revisit="The change in speed is the change in momentum ÷ the mass: Δv = Δp / m.",
                 mistakes=_lorry_change_mistakes(mass, before, after, lasts), see="momentum"),
        ),
        mark_scheme=(
            Mark(f"{p1} N s", "B1", "a"),
            Mark(f"{p2} N s", "B1", "b"),
            Mark(f"v = p / m = {p2} / {m}", "C1", "c"),
            Mark(f"= {n(speed, 2)} {PER_S}", "A1", "c"),
            Mark(f"Δv = Δp / m = ({p1} − {p2}) / {m}" if brakes else f"Δv = Δp / m = ({p2} − {p1}) / {m}", "C1", "d"),
            Mark(f"= {n(gain, 2)} {PER_S}", "A1", "d"),
        ),
    )


def _unscaled_mistakes(value: float, power: int) -> tuple[Mistake, ...]:
    """A reading off an axis labelled in a power of ten (momentum / 10ⁿ N s) taken without it; none
    when the axis has no power."""
    if not power:
        return ()
    return (Mistake("the axis's number without its power of ten", value / 10.0**power,
                    f"The axis is labelled momentum / {power_text(power)} N s: each number on it stands for "
                    f"that many {power_text(power)} N s. Multiply your reading by {power_text(power)}."),)


def _lorry_speed_mistakes(mass: float, before: float, after: float, t_end: str) -> tuple[Mistake, ...]:
    """lorry_speed_from_momentum_graph's wrong final speeds: the momentum at the start, the weight for
    the mass, the change in momentum for the whole."""
    gain = abs(velocity_from_momentum(after - before, mass))
    return (
        Mistake("the momentum at the start", velocity_from_momentum(before, mass),
                f"That is the speed at the start. Read the momentum after {t_end} s, where the "
                "line is flat again."),
        Mistake("divided by the weight", after / weight(mass),
                f"You divided by the weight, mg. Momentum = mass × velocity: divide by the mass, "
                f"{n(mass, 2)} kg.", see="weight"),
        Mistake("the change in momentum ÷ mass", gain,
                "That is the gain in speed, Δp / m. The speed is the whole momentum ÷ the mass."),
    )


def _lorry_change_mistakes(mass: float, before: float, after: float, lasts: float) -> tuple[Mistake, ...]:
    """lorry_speed_from_momentum_graph's wrong changes in speed: the final speed, the gradient (the
    force), the weight for the mass."""
    return (
        Mistake("the final speed, not the change", velocity_from_momentum(after, mass),
                "That is the speed at the end. Subtract the momentum at the start first: "
                "Δv = (p₂ − p₁) / m."),
        Mistake("the gradient: change in momentum ÷ time", abs(average_force(after - before, lasts)),
                "That is Δp / Δt, the gradient: the resultant force, in N. The change in speed is "
                "Δp / m.", see="momentum-time-graph"),
        Mistake("divided by the weight", abs(after - before) / weight(mass),
                f"You divided by the weight, mg. Δv = Δp / m, with the mass {n(mass, 2)} kg.", see="weight"),
    )


TEMPLATES = checked_givens(
    Template("quick-check-1", "force-momentum", ("numeric",), "Quick check 1",
             trolley_pushed_from_rest,
             {"force": Draw(5.0, 2.0, 9.0, 0.5), "mass": Draw(2.0, 1.0, 5.0, 0.5),
              "duration": Draw(3.0, 2.0, 6.0, 0.5)}),
    Template("practice-wall-bounce", "force-momentum", ("numeric",), "Ball bouncing off a wall",
             ball_bounces_off_wall,
             {"mass": Draw(0.16, 0.10, 0.60, 0.01), "speed_in": Draw(15.0, 8.0, 25.0, 1.0),
              "speed_out": Draw(10.0, 4.0, 20.0, 1.0), "contact_ms": Draw(20.0, 10.0, 40.0, 1.0)}),
    Template("bounce-contact-force", "force-momentum", ("numeric",), "A bounce: the floor's or the ceiling's force",
             ball_bounce_contact_force,
             {"mass": Draw(0.060, 0.050, 0.150, 0.001), "speed_in": Draw(6.0, 3.0, 9.0, 0.1),
              "speed_out": Draw(4.0, 1.0, 6.0, 0.1), "contact": Draw(0.080, 0.060, 0.150, 0.001),
              "ceiling": Draw(0, 0, 1, 1)}),
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
    Template("headed-ball-force-speed", "force-momentum", ("numeric",), "A header: force and speed from Δp",
             headed_ball,
             {"change": Draw(3.6, 2.0, 6.0, 0.1), "contact_ms": Draw(12.0, 8.0, 20.0, 1.0),
              "mass": Draw(0.43, 0.40, 0.45, 0.01), "speed_in": Draw(3.0, 2.0, 8.0, 0.5)}),
    Template("mass-from-momentum-change", "force-momentum", ("numeric",), "Mass from a change in momentum",
             mass_from_velocity_change,
             {"force": Draw(6.0, 2.0, 9.0, 0.5), "duration": Draw(2.5, 1.0, 5.0, 0.5),
              "speed_before": Draw(1.2, 0.5, 3.0, 0.1), "speed_after": Draw(4.2, 2.0, 6.0, 0.1),
              "turns": Draw(0, 0, 1, 1)}),
    Template("force-from-momentum-graph-choice", "force-momentum", ("mcq",), "Which force–time graph?",
             force_from_momentum_graph_choice, {"story": Draw(0, 0, len(_MOMENTUM_STORIES) - 1, 1)},
             variant_count=len(_MOMENTUM_STORIES)),
    Template("graph-lorry-speed-momentum-time", "force-momentum", ("graph", "numeric"),
             "A lorry: speed from a momentum–time graph", lorry_speed_from_momentum_graph,
             {"mass": Draw(4000.0, 2000.0, 9000.0, 500.0), "speed_before": Draw(8.0, 4.0, 12.0, 1.0),
              "speed_after": Draw(20.0, 15.0, 28.0, 1.0), "begins": Draw(4.0, 2.0, 6.0, 0.5),
              "lasts": Draw(8.0, 4.0, 12.0, 0.5)}),
)
