"""The numbers the book's pages print, computed from the models.

Each page of the book calls one function here in a hidden cell and glues what it
returns into its prose, e.g.::

    from physics_figures.answers import glue_all, example_1
    glue_all(example_1())

and the page writes {glue:text}`ex1_acceleration`. Every function returns an
``Answers`` mapping: glue name -> ``Value``. A ``Value`` keeps the exact number
and prints itself to the precision the notes print it with, so the page shows
"1.5" while tests can check both the printed text and the number behind it.
Each function's docstring names the section of the notes it belongs to.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import KW_ONLY, dataclass
from decimal import Decimal

from . import scenarios
from .constants import G_EARTH, G_MOON
from .models import (
    acceleration,
    average_force,
    change_in_momentum,
    drag_at_terminal_velocity,
    drag_force,
    explosion_from_rest,
    kinetic_energy,
    lift_contact_force,
    mass_from_weight,
    momentum,
    momentum_change_between_directions,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    stream_force,
    time_for_momentum_change,
    total_kinetic_energy,
    upthrust,
    velocity_after_collision,
    weight,
)
from .notation import format_number, round_number


@dataclass(frozen=True)
class Value:
    """A computed number with the unit and precision the notes print it with.

    value: the exact result (SI unit ``unit``); give exactly one of sig_figs (significant
    figures) or decimals (decimal places). ``str()`` and ``repr()`` give the printed
    text, written by physics_figures.notation (half away from zero, true minus, grouped
    from five digits), e.g. Value(2.436, unit="N s", sig_figs=3) prints as 2.44.
    """

    value: float
    _: KW_ONLY
    unit: str
    sig_figs: int | None = None
    decimals: int | None = None

    def __post_init__(self):
        # Store a plain float (models may hand back numpy scalars); check the precision now.
        object.__setattr__(self, "value", float(self.value))
        self.text  # noqa: B018  (raises ValueError for a bad precision)

    @property
    def rounded(self) -> Decimal:
        """The value rounded to the printed precision (tests compare digits with it)."""
        return round_number(self.value, self.sig_figs, decimals=self.decimals)

    @property
    def text(self) -> str:
        """The printed number, e.g. "2.44" or "\u221230\u202f000" (true minus, grouped)."""
        return format_number(self.value, self.sig_figs, decimals=self.decimals)

    def __str__(self) -> str:
        return self.text

    # Shown as its printed text in a notebook too.
    __repr__ = __str__


Answers = Mapping[str, Value]


def glue_all(answers: Answers) -> None:
    """Glue every value's printed text for the page's {glue:text} roles (not displayed).

    The text is glued as a str on purpose: {glue:text} passes the text/plain form through
    ast.literal_eval, which would turn a bare 0.070 into 0.07 and 9.40 into 9.4; the
    quoted repr of a str comes back unchanged.
    """
    from myst_nb import glue  # only in a page being built, not needed by the models

    for name, value in answers.items():
        glue(name, value.text, display=False)


# --- Understand it -----------------------------------------------------------------


def momentum_and_second_law() -> Answers:
    """Notes, Understand it > Momentum and Newton's second law: the car and the hose."""
    car = momentum(scenarios.CAR_MASS, scenarios.CAR_SPEED)
    # The momentum given to the water each second is the force on it.
    hose = stream_force(scenarios.HOSE_MASS_PER_SECOND, scenarios.HOSE_SPEED)
    return {
        "car_momentum": Value(car, unit="kg m s^-1", sig_figs=2),
        "car_momentum_reversed": Value(momentum(scenarios.CAR_MASS, -scenarios.CAR_SPEED),
                                       unit="kg m s^-1", sig_figs=2),
        "hose_momentum_per_second": Value(hose, unit="kg m s^-1 per s", sig_figs=2),
        "hose_force": Value(hose, unit="N", sig_figs=2),
    }


def momentum_time_graph() -> Answers:
    """Notes, Understand it > Reading a momentum-time graph: the car's three stages."""
    history, mass = scenarios.CAR_HISTORY, scenarios.CAR_MASS
    speeding_up, cruising, braking = history.segment_forces
    return {
        "car_force_speeding_up": Value(speeding_up, unit="N", sig_figs=2),
        "car_acceleration": Value(acceleration(speeding_up, mass), unit="m s^-2",
                                  sig_figs=2),
        "car_cruising_force": Value(cruising, unit="N", decimals=0),
        "car_cruising_speed": Value(history.velocity_at(7.0, mass), unit="m s^-1",
                                    sig_figs=2),
        "car_force_braking": Value(braking, unit="N", sig_figs=2),
        "car_braking_force_size": Value(abs(braking), unit="N", sig_figs=2),
    }


def weight_and_lift() -> Answers:
    """Notes, Understand it > Weight: a 60 kg person on the Earth, the Moon and in a lift."""
    mass, a = scenarios.PERSON_MASS, scenarios.LIFT_ACCELERATION
    return {
        "person_weight_earth": Value(weight(mass), unit="N", sig_figs=3),
        "person_weight_moon": Value(weight(mass, g=G_MOON), unit="N", sig_figs=3),
        "lift_contact_force_up": Value(lift_contact_force(mass, a), unit="N", sig_figs=3),
        "lift_contact_force_down": Value(lift_contact_force(mass, -a), unit="N", sig_figs=3),
        "lift_contact_force_steady": Value(lift_contact_force(mass, 0.0), unit="N", sig_figs=3),
    }


def terminal_velocity() -> Answers:
    """Notes, Understand it > Friction, drag and terminal velocity: the 80 kg skydiver at C,
    the parachute opening (D, the model's largest deceleration) and the ball thrown up."""
    jump = scenarios.SKYDIVER
    # At terminal velocity the drag k v_t^2 has grown to equal the weight.
    drag = drag_force(jump.drag_constant_freefall, jump.terminal_velocity_freefall)
    # Were the parachute to open instantly, at 50 m/s its drag would be (v_t1 / v_t2)^2 weights.
    instant_drag = drag_force(jump.drag_constant_parachute, jump.terminal_velocity_freefall)
    # The model's canopy fills over opening_duration; D is where the deceleration peaks.
    t_d, _ = jump.points["D"]
    peak_drag, peak_deceleration = jump.point_drag["D"], -jump.point_acceleration["D"]
    ball, vacuum = scenarios.THROWN_BALL, scenarios.THROWN_BALL_IN_VACUUM
    return {
        "skydiver_drag_at_terminal": Value(drag, unit="N", sig_figs=3),
        "skydiver_instant_opening_drag_in_weights": Value(instant_drag / jump.weight, unit="",
                                                          sig_figs=3),
        "skydiver_opening_duration": Value(jump.opening_duration, unit="s", sig_figs=2),
        "skydiver_peak_after_opening": Value(t_d - jump.parachute_opens_at, unit="s", sig_figs=1),
        "skydiver_peak_drag_in_weights": Value(peak_drag / jump.weight, unit="", sig_figs=2),
        "skydiver_peak_deceleration": Value(peak_deceleration, unit="m s^-2", sig_figs=3),
        "skydiver_peak_deceleration_in_g": Value(peak_deceleration / jump.g, unit="", sig_figs=2),
        # The ball thrown up with drag: longer coming down than going up.
        "ball_time_up": Value(ball.time_to_top, unit="s", sig_figs=3),
        "ball_time_down": Value(ball.time_of_flight - ball.time_to_top, unit="s", sig_figs=3),
        "ball_time_up_in_vacuum": Value(vacuum.time_to_top, unit="s", sig_figs=3),
    }


def conservation_of_momentum() -> Answers:
    """Notes, Understand it > Conservation of momentum: sticking trolleys, spring explosion."""
    spring = explosion_from_rest(**scenarios.SPRING_TROLLEYS)
    return {
        "trolleys_common_velocity": Value(stick_together(**scenarios.STICKING_TROLLEYS),
                                          unit="m s^-1", sig_figs=2),
        "spring_trolley_velocity": Value(spring, unit="m s^-1", sig_figs=2),
        "spring_trolley_speed": Value(abs(spring), unit="m s^-1", sig_figs=2),
    }


def elastic_and_inelastic() -> Answers:
    """Notes, Understand it > Elastic and inelastic collisions: energy and relative speed."""
    trolleys = scenarios.STICKING_TROLLEYS
    v_after = stick_together(**trolleys)
    before = total_kinetic_energy((trolleys["m1"], trolleys["m2"]),
                                  (trolleys["u1"], trolleys["u2"]))
    after = total_kinetic_energy((trolleys["m1"] + trolleys["m2"],), (v_after,))
    return {
        "trolleys_kinetic_energy_before": Value(before, unit="J", sig_figs=2),
        "trolleys_kinetic_energy_after": Value(after, unit="J", sig_figs=2),
        "trolleys_kinetic_energy_lost": Value(before - after, unit="J", sig_figs=2),
        "trolleys_kinetic_energy_lost_percent": Value(
            percentage_kinetic_energy_lost(before, after), unit="%", sig_figs=2),
        # Towards each other: opposite signs. The same way: same signs.
        "approach_speed_towards": Value(relative_speed(5, -3), unit="m s^-1", sig_figs=1),
        "approach_speed_same_way": Value(relative_speed(5, 3), unit="m s^-1", sig_figs=1),
    }


def momentum_in_two_dimensions() -> Answers:
    """Notes, Understand it > Momentum in two dimensions: pucks P (1.00 N s) and Q."""
    pucks = scenarios.PUCKS_PQ
    p_along_after, _ = pucks.known_vector
    return {
        "pucks_p_along_after": Value(p_along_after, unit="N s", sig_figs=3),
        "pucks_q_along": Value(pucks.missing.along, unit="N s", sig_figs=3),
        "pucks_q_across": Value(pucks.missing.across, unit="N s", sig_figs=3),
        # 3 s.f. like its components (0.614, 0.460): the notes print 0.77.
        "pucks_q_momentum": Value(pucks.missing.magnitude, unit="N s", sig_figs=3),
        "pucks_q_angle": Value(pucks.missing.angle_deg, unit="degrees", sig_figs=3),
    }


# --- Exam skills: How to do it -----------------------------------------------------


def method_newtons_laws() -> Answers:
    """Notes, How to do it > 1. Newton's laws: the 1200 kg car, 3000 N forwards, 600 N back."""
    return {"car_acceleration": Value(acceleration(3000 - 600, 1200), unit="m s^-2",
                                      sig_figs=2)}


def method_drag() -> Answers:
    """Notes, How to do it > 2. Drag: a 68 kg skydiver with 1800 N of drag (up positive)."""
    mass, drag = 68, 1800
    skydiver_weight = weight(mass)
    return {
        "skydiver_weight": Value(skydiver_weight, unit="N", sig_figs=3),
        "skydiver_acceleration": Value(acceleration(drag - skydiver_weight, mass),
                                       unit="m s^-2", sig_figs=3),
    }


def method_force_momentum() -> Answers:
    """Notes, How to do it > 3. Force as rate of change of momentum: the van stopped by 6000 N."""
    van = momentum(2000, 15)
    # Forwards positive: the momentum falls by 30 000 N s under a backward force of 6000 N.
    stopping_time = time_for_momentum_change(-van, -6000)
    return {
        "van_momentum": Value(van, unit="N s", sig_figs=2),
        "van_stopping_time": Value(stopping_time, unit="s", sig_figs=2),
    }


def method_definitions() -> Answers:
    """Notes, How to do it > 4. Mass, weight: 3.0 N where g is a quarter of the Earth's."""
    mass = mass_from_weight(3.0, g=G_EARTH / 4)
    return {"planet_object_weight_on_earth": Value(weight(mass), unit="N", sig_figs=2)}


# --- Exam skills: Worked examples --------------------------------------------------


def example_1() -> Answers:
    """Notes, Worked examples > Example 1: a 1200 kg car towing a 400 kg trailer."""
    driving_force, car_mass, car_resistance = 3000, 1200, 400
    towed = scenarios.EXAMPLE_1
    (tension,) = towed.tensions
    return {
        "ex1_resultant_force": Value(towed.resultant_force, unit="N", sig_figs=2),
        "ex1_acceleration": Value(towed.acceleration, unit="m s^-2", sig_figs=2),
        "ex1_tension": Value(tension, unit="N", sig_figs=2),
        # The check: the car alone has the resultant force its own m a needs.
        "ex1_car_resultant_force": Value(driving_force - car_resistance - tension, unit="N",
                                         sig_figs=2),
        "ex1_car_mass_times_acceleration": Value(car_mass * towed.acceleration, unit="N",
                                                 sig_figs=2),
        # Newton's third law: the trailer pulls the car back with the tension.
        "ex1_force_on_car": Value(tension, unit="N", sig_figs=2),
    }


def example_2() -> Answers:
    """Notes, Worked examples > Example 2: a 0.058 kg ball, 24 m s^-1 in, 18 m s^-1 back.

    Away from the wall is positive, so u = -24 m s^-1 and v = +18 m s^-1.
    """
    mass, u, v, contact_time = 0.058, -24, 18, 0.012
    dp = change_in_momentum(mass, u, v)
    force_on_ball = average_force(dp, contact_time)
    return {
        "ex2_velocity_change": Value(v - u, unit="m s^-1", sig_figs=2),
        "ex2_momentum_change": Value(dp, unit="N s", sig_figs=3),
        "ex2_momentum_change_unrounded": Value(dp, unit="N s", sig_figs=4),
        "ex2_force_on_ball": Value(force_on_ball, unit="N", sig_figs=3),
        "ex2_kinetic_energy_before": Value(kinetic_energy(mass, u), unit="J", sig_figs=3),
        "ex2_kinetic_energy_after": Value(kinetic_energy(mass, v), unit="J", sig_figs=3),
        # Newton's third law: equal and opposite, so towards the wall.
        "ex2_force_on_wall": Value(abs(-force_on_ball), unit="N", sig_figs=3),
    }


def example_3() -> Answers:
    """Notes, Worked examples > Example 3: trolley A (0.60 kg) hits trolley B (0.40 kg)."""
    m_a, u_a, m_b, u_b, v_a, contact_time = 0.60, 2.5, 0.40, 0.0, 0.50, 0.050
    v_b = velocity_after_collision(m_a, u_a, m_b, u_b, v_a)
    dp_b = change_in_momentum(m_b, u_b, v_b)
    return {
        "ex3_momentum_before": Value(momentum(m_a, u_a), unit="N s", sig_figs=3),
        "ex3_momentum_a_after": Value(momentum(m_a, v_a), unit="N s", sig_figs=2),
        "ex3_velocity_b": Value(v_b, unit="m s^-1", sig_figs=2),
        "ex3_approach_speed": Value(relative_speed(u_a, u_b), unit="m s^-1", sig_figs=2),
        "ex3_separation_speed": Value(relative_speed(v_b, v_a), unit="m s^-1", sig_figs=2),
        "ex3_kinetic_energy_before": Value(kinetic_energy(m_a, u_a), unit="J", sig_figs=4),
        "ex3_kinetic_energy_a_after": Value(kinetic_energy(m_a, v_a), unit="J", sig_figs=2),
        "ex3_kinetic_energy_b_after": Value(kinetic_energy(m_b, v_b), unit="J", sig_figs=3),
        "ex3_kinetic_energy_after": Value(total_kinetic_energy((m_a, m_b), (v_a, v_b)),
                                          unit="J", sig_figs=4),
        "ex3_momentum_change_b": Value(dp_b, unit="N s", sig_figs=2),
        "ex3_force_on_b": Value(average_force(dp_b, contact_time), unit="N", sig_figs=2),
    }


def example_4() -> Answers:
    """Notes, Worked examples > Example 4: puck X (0.20 kg, 3.0 m s^-1) hits puck Y (0.30 kg)."""
    pucks = scenarios.EXAMPLE_4
    x_along_after, _ = pucks.known_vector
    ke_x_after, ke_y_after = pucks.kinetic_energies_after
    return {
        "ex4_momentum_before": Value(pucks.p_before, unit="N s", sig_figs=2),
        "ex4_x_along_after": Value(x_along_after, unit="N s", sig_figs=2),
        "ex4_y_along": Value(pucks.missing.along, unit="N s", sig_figs=2),
        "ex4_y_across": Value(pucks.missing.across, unit="N s", sig_figs=3),
        "ex4_y_momentum": Value(pucks.missing.magnitude, unit="N s", sig_figs=3),
        "ex4_y_speed": Value(pucks.speed_missing, unit="m s^-1", sig_figs=3),
        # The kinetic energy line squares the speed kept to 4 s.f.: 1.74^2 would give 0.454 J.
        "ex4_y_speed_kept": Value(pucks.speed_missing, unit="m s^-1", sig_figs=4),
        "ex4_kinetic_energy_y_after_rounded_speed": Value(
            kinetic_energy(pucks.mass_struck, float(Value(pucks.speed_missing, unit="m s^-1", sig_figs=3).rounded)),
            unit="J", sig_figs=3),
        "ex4_y_angle": Value(pucks.missing.angle_deg, unit="degrees", sig_figs=3),
        "ex4_kinetic_energy_before": Value(pucks.kinetic_energy_before, unit="J", sig_figs=2),
        "ex4_kinetic_energy_x_after": Value(ke_x_after, unit="J", sig_figs=3),
        "ex4_kinetic_energy_y_after": Value(ke_y_after, unit="J", sig_figs=3),
        "ex4_kinetic_energy_after": Value(pucks.kinetic_energy_after, unit="J", sig_figs=2),
        "ex4_kinetic_energy_lost": Value(pucks.kinetic_energy_transferred, unit="J",
                                         sig_figs=2),
    }


def example_5() -> Answers:
    """Worked examples > Example 5 (not in the notes; their "Drag" method and "In a liquid
    there is also upthrust"): a 0.012 kg metal sphere of volume 1.5 x 10^-6 m^3 falls
    through oil of density 920 kg m^-3."""
    sphere = scenarios.EXAMPLE_5
    mass, volume, oil = sphere["mass"], sphere["volume"], sphere["oil_density"]
    lift = upthrust(oil, volume)
    sphere_weight = weight(mass)
    drag = drag_at_terminal_velocity(sphere_weight, lift)
    return {
        "ex5_upthrust": Value(lift, unit="N", sig_figs=3),
        # The working carries 4 s.f. so that W - U is not rounded part-way (0.118 - 0.0135 = 0.105).
        "ex5_upthrust_kept": Value(lift, unit="N", sig_figs=4),
        "ex5_weight_kept": Value(sphere_weight, unit="N", sig_figs=4),
        "ex5_drag": Value(drag, unit="N", sig_figs=3),
        # Just after release the speed, and so the drag, is zero: a = (W - U) / m < g.
        "ex5_initial_acceleration": Value(acceleration(sphere_weight - lift, mass), unit="m s^-2",
                                          sig_figs=3),
    }


# --- Exam skills: Common mistakes --------------------------------------------------


def common_mistakes() -> Answers:
    """Notes, Common mistakes > change in momentum vs change in the size of momentum."""
    p_initial, p_final = 0.12, 0.050
    return {
        "turning_ball_momentum_change": Value(
            momentum_change_between_directions(p_initial, p_final, 90), unit="N s", sig_figs=2),
        # The wrong answer: subtracting sizes as if the direction had not changed.
        "turning_ball_size_change": Value(p_initial - p_final, unit="N s", sig_figs=2),
    }


#: Every page's answers, by function name (for tests and for listing the glue names).
ALL = {
    function.__name__: function
    for function in (
        momentum_and_second_law, momentum_time_graph, weight_and_lift, terminal_velocity,
        conservation_of_momentum, elastic_and_inelastic, momentum_in_two_dimensions,
        method_newtons_laws, method_drag, method_force_momentum, method_definitions,
        example_1, example_2, example_3, example_4, example_5, common_mistakes,
    )
}
