"""Bad input: every model raises ValueError naming the argument, the value and the rule.

One test per rule; each checks the message the reader will see.
"""

import math

import numpy as np
import pytest

from physics_figures import models
from physics_figures.models import (
    MomentumHistory,
    average_force,
    canopy_drag_constant,
    collision_with_energy_kept,
    drag_constant_for_terminal_velocity,
    drag_force,
    glancing_collision,
    impulse,
    kinetic_energy,
    lift_contact_force,
    mass_from_momentum_and_energy,
    missing_momentum,
    momentum,
    momentum_change_between_directions,
    oblique_bounce_momentum_change,
    open_canopy,
    percentage_kinetic_energy_lost,
    skydive,
    stick_together,
    terminal_velocity,
    thrown_upwards,
    thrust_for_acceleration,
    time_for_momentum_change,
    total_momentum,
    towing,
    velocity_from_rest,
    velocity_slowing_to_terminal,
    weight,
)

NOTES_SKYDIVE = {"terminal_velocity_freefall": 50.0, "terminal_velocity_parachute": 5.0,
                 "parachute_opens_at": 20.0, "opening_duration": 2.5, "duration": 30.0}


@pytest.mark.parametrize("bad_mass", [-2.0, 0.0])
def test_mass_must_be_positive(bad_mass):
    with pytest.raises(ValueError, match=rf"^mass must be positive \(got mass={bad_mass!r} kg\)$"):
        momentum(bad_mass, 3.0)


def test_each_mass_in_a_collision_must_be_positive():
    with pytest.raises(ValueError, match=r"^m2 must be positive \(got m2=-1\.0 kg\)$"):
        stick_together(3.0, 4.0, -1.0, 0.0)


def test_each_mass_in_a_list_must_be_positive_and_the_bad_one_is_located():
    with pytest.raises(ValueError, match=r"^masses must be positive \(got masses=0\.0 kg at index 1\)$"):
        total_momentum([1.0, 0.0], [2.0, 3.0])


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda x: momentum(2.0, x), "velocity"),
        (lambda x: kinetic_energy(x, 1.0), "mass"),
        (lambda x: weight(60.0, g=x), "g"),
        (lambda x: average_force(x, 0.012), "change_in_momentum"),
        (lambda x: velocity_from_rest(1.0, 50.0, g=x), "g"),
        (lambda x: stick_together(3.0, x, 1.0, 0.0), "u1"),
        (lambda x: missing_momentum(1.0, 0.6, x), "angle_known_deg"),
        (lambda x: MomentumHistory((0.0, 4.0), (0.0, x)), "momenta"),
    ],
)
def test_nan_and_infinity_are_refused_everywhere(call, name, bad):
    with pytest.raises(ValueError, match=rf"^{name} must be a finite number \(got {name}="):
        call(bad)


def test_an_array_with_a_bad_element_names_its_index():
    with pytest.raises(ValueError, match=r"^t must not be negative \(got t=-2\.0 s at index 2\)$"):
        velocity_from_rest(np.array([0.0, 1.0, -2.0]), 50.0)


def test_something_that_is_not_a_number_is_a_type_error():
    with pytest.raises(TypeError, match=r"^mass must be a number \(got mass='80'\)$"):
        weight("80")
    with pytest.raises(TypeError, match=r"^velocity must be a number \(got velocity=None\)$"):
        momentum(2.0, None)


def test_time_must_not_be_negative():
    with pytest.raises(ValueError, match=r"^t must not be negative \(got t=-1\.0 s\)$"):
        velocity_from_rest(-1.0, 50.0)


def test_duration_of_an_impulse_must_not_be_negative():
    with pytest.raises(ValueError, match=r"^duration must not be negative \(got duration=-3\.0 s\)$"):
        impulse(5.0, -3.0)


def test_a_force_needs_a_duration_greater_than_zero():
    with pytest.raises(ValueError, match=r"^duration must be positive \(got duration=0\.0 s\)$"):
        average_force(2.436, 0.0)


def test_the_force_that_changes_momentum_must_not_be_zero():
    with pytest.raises(ValueError, match=r"^force must not be zero \(got force=0\.0 N\)$"):
        time_for_momentum_change(-30_000.0, 0.0)


def test_the_force_must_act_in_the_direction_of_the_change_in_momentum():
    with pytest.raises(ValueError, match=r"^force must act in the direction of the change in "
                                         r"momentum \(change_in_momentum=-30000\.0 N s\) "
                                         r"\(got force=6000\.0 N\)$"):
        time_for_momentum_change(-30_000.0, 6000.0)


def test_mass_from_momentum_and_energy_needs_some_kinetic_energy():
    with pytest.raises(ValueError, match=r"^kinetic_energy must be positive \(got kinetic_energy=0\.0 J\)$"):
        mass_from_momentum_and_energy(3.0, 0.0)


def test_angle_between_momenta_must_be_between_0_and_180_degrees():
    with pytest.raises(ValueError, match=r"^angle_deg must be between 0 and 180 degrees "
                                         r"\(got angle_deg=200\.0 degrees\)$"):
        momentum_change_between_directions(0.12, 0.050, 200.0)


def test_angle_to_a_surface_must_be_between_0_and_90_degrees():
    with pytest.raises(ValueError, match=r"^angle_to_surface_deg must be between 0 and 90 degrees"):
        oblique_bounce_momentum_change(1.0, 120.0)


def test_g_must_be_positive():
    with pytest.raises(ValueError, match=r"^g must be positive \(got g=0\.0 m s\^-2\)$"):
        weight(60.0, g=0.0)


def test_a_lift_floor_cannot_pull_the_passenger_down():
    with pytest.raises(ValueError, match=r"^acceleration_up must not be below -g = -9\.81 m s\^-2 "
                                         r"\(a floor can only push up\) \(got acceleration_up=-12\.0"):
        lift_contact_force(60.0, -12.0)


def test_a_thrust_cannot_pull_down():
    with pytest.raises(ValueError, match=r"^acceleration_up must not be below -g"):
        thrust_for_acceleration(1000.0, -10.0)


def test_towing_needs_a_resistive_force_for_each_body():
    with pytest.raises(ValueError, match=r"^masses and resistive_forces must have the same length "
                                         r"\(got len\(masses\)=2, len\(resistive_forces\)=1\)$"):
        towing(3000.0, (1200.0, 400.0), (400.0,))


def test_towing_needs_at_least_one_body():
    with pytest.raises(ValueError, match=r"^masses must have at least 1 entries \(got 0"):
        towing(3000.0, (), ())


def test_resistive_forces_must_not_be_negative():
    with pytest.raises(ValueError, match=r"^resistive_forces must not be negative "
                                         r"\(got resistive_forces=-200\.0 N at index 1\)$"):
        towing(3000.0, (1200.0, 400.0), (400.0, -200.0))


def test_drag_constant_must_be_positive():
    with pytest.raises(ValueError, match=r"^k must be positive \(got k=0\.0 kg m\^-1\)$"):
        drag_force(0.0, 3.0)
    with pytest.raises(ValueError, match=r"^k must be positive \(got k=-0\.3 kg m\^-1\)$"):
        terminal_velocity(80.0, -0.3)


def test_speed_for_drag_must_not_be_negative():
    with pytest.raises(ValueError, match=r"^speed must not be negative \(got speed=-3\.0 m s\^-1\)$"):
        drag_force(0.3, -3.0)


def test_terminal_velocity_must_be_positive():
    with pytest.raises(ValueError, match=r"^terminal_velocity must be positive "
                                         r"\(got terminal_velocity=0\.0 m s\^-1\)$"):
        velocity_from_rest(1.0, 0.0)
    with pytest.raises(ValueError, match=r"^terminal_velocity must be positive"):
        drag_constant_for_terminal_velocity(80.0, -50.0)


def test_upthrust_must_be_less_than_the_weight():
    # 1.0 kg weighs 9.81 N: with that much upthrust it never falls to a terminal velocity.
    with pytest.raises(ValueError, match=r"^upthrust must be less than the weight m g = 9\.81 N, "
                                         r"or the body never falls to a terminal velocity "
                                         r"\(got upthrust=9\.81 N\)$"):
        terminal_velocity(1.0, 0.1, upthrust=9.81)


def test_slowing_to_terminal_velocity_needs_to_start_faster_than_it():
    with pytest.raises(ValueError, match=r"^initial_velocity must be greater than "
                                         r"terminal_velocity=5\.0 m s\^-1 to slow down to it"):
        velocity_slowing_to_terminal(1.0, 4.0, 5.0)


@pytest.mark.parametrize("opens_at", [0.0, -5.0])
def test_parachute_cannot_open_before_the_jump(opens_at):
    arguments = NOTES_SKYDIVE | {"parachute_opens_at": opens_at}
    with pytest.raises(ValueError, match=rf"^parachute_opens_at must be positive "
                                         rf"\(got parachute_opens_at={opens_at!r} s\)$"):
        skydive(80.0, **arguments)


def test_parachute_cannot_open_after_the_end_of_the_record():
    arguments = NOTES_SKYDIVE | {"parachute_opens_at": 40.0}
    with pytest.raises(ValueError, match=r"^parachute_opens_at must be before the end of the "
                                         r"record, duration=30\.0 s \(got parachute_opens_at=40\.0 s\)$"):
        skydive(80.0, **arguments)


def test_parachute_must_open_once_the_skydiver_is_faster_than_its_terminal_velocity():
    # It may open before C, but not before the speed passes 1.01 x 5.0 m/s (at 0.517 s),
    # or it could not slow the skydiver down to 5.0 m/s.
    arguments = NOTES_SKYDIVE | {"parachute_opens_at": 0.5}
    with pytest.raises(ValueError, match=r"^parachute_opens_at must be after 0\.517 s, when the "
                                         r"skydiver first falls faster than the parachute's terminal "
                                         r"velocity \(\+1 %\), so that it slows them down "
                                         r"\(got parachute_opens_at=0\.5 s\)$"):
        skydive(80.0, **arguments)
    skydive(80.0, **NOTES_SKYDIVE | {"parachute_opens_at": 0.52})  # just after is fine


@pytest.mark.parametrize("tau", [0.0, -1.0])
def test_the_canopy_must_take_some_time_to_open(tau):
    arguments = NOTES_SKYDIVE | {"opening_duration": tau}
    with pytest.raises(ValueError, match=rf"^opening_duration must be positive "
                                         rf"\(got opening_duration={tau!r} s\)$"):
        skydive(80.0, **arguments)


def test_the_canopy_cannot_have_less_drag_than_the_body():
    with pytest.raises(ValueError, match=r"^canopy_drag must be at least body_drag=1\.0 kg m\^-1"):
        canopy_drag_constant(1.0, 1.0, 0.5, 2.5)
    with pytest.raises(ValueError, match=r"^initial_velocity must not be negative"):
        open_canopy(80.0, -1.0, body_drag=0.3, canopy_drag=30.0, opening_duration=2.5)


def test_record_must_last_until_the_second_terminal_velocity():
    arguments = NOTES_SKYDIVE | {"duration": 20.5}
    with pytest.raises(ValueError, match=r"^duration must reach point E, the parachute terminal "
                                         r"velocity \(23\.2 s\) \(got duration=20\.5 s\)$"):
        skydive(80.0, **arguments)


@pytest.mark.parametrize("v_t2", [50.0, 60.0])
def test_parachute_terminal_velocity_must_be_below_the_freefall_one(v_t2):
    arguments = NOTES_SKYDIVE | {"terminal_velocity_parachute": v_t2}
    with pytest.raises(ValueError, match=r"^terminal_velocity_parachute must be less than "
                                         r"terminal_velocity_freefall=50\.0 m s\^-1"):
        skydive(80.0, **arguments)


def test_samples_must_be_a_whole_number_of_at_least_ten():
    with pytest.raises(ValueError, match=r"^samples must be a whole number of at least 10 \(got samples=3\)$"):
        skydive(80.0, **NOTES_SKYDIVE, samples=3)
    with pytest.raises(ValueError, match=r"^samples must be a whole number of at least 10 \(got samples=50\.5\)$"):
        thrown_upwards(20.0, samples=50.5)


def test_launch_speed_must_be_positive():
    with pytest.raises(ValueError, match=r"^launch_speed must be positive \(got launch_speed=0\.0 m s\^-1\)$"):
        thrown_upwards(0.0, terminal_velocity=20.0)


def test_momentum_history_times_must_be_strictly_increasing():
    with pytest.raises(ValueError, match=r"^times must be strictly increasing \(entry 2 is not after "
                                         r"entry 1, 4\.0 s\) \(got times=4\.0 s at index 2\)$"):
        MomentumHistory((0.0, 4.0, 4.0, 16.0), (0.0, 12_000.0, 12_000.0, 0.0))


def test_momentum_history_needs_a_momentum_for_each_time():
    with pytest.raises(ValueError, match=r"^times and momenta must have the same length "
                                         r"\(got len\(times\)=2, len\(momenta\)=3\)$"):
        MomentumHistory((0.0, 4.0), (0.0, 1.0, 2.0))


def test_momentum_history_needs_two_points():
    with pytest.raises(ValueError, match=r"^times must have at least 2 entries \(got 1"):
        MomentumHistory((0.0,), (0.0,))


def test_momentum_history_is_only_defined_within_its_times():
    history = MomentumHistory((0.0, 4.0), (0.0, 12_000.0))
    with pytest.raises(ValueError, match=r"^t must be within the history, 0 s to 4 s \(got t=5\.0 s\)$"):
        history.momentum_at(5.0)
    with pytest.raises(ValueError, match=r"^t must be within the history"):
        history.force_at(-1.0)


def test_lists_of_masses_and_velocities_must_match():
    with pytest.raises(ValueError, match=r"^masses and velocities must have the same length "
                                         r"\(got len\(masses\)=2, len\(velocities\)=1\)$"):
        total_momentum([3.0, 1.0], [4.0])


def test_a_collision_cannot_create_kinetic_energy():
    with pytest.raises(ValueError, match=r"^fraction_of_ke_kept_in_cm_frame must be between 0 and 1 "
                                         r"\(a collision cannot create kinetic energy\) "
                                         r"\(got fraction_of_ke_kept_in_cm_frame=1\.5\)$"):
        collision_with_energy_kept(3.0, 4.0, 1.0, 0.0, fraction_of_ke_kept_in_cm_frame=1.5)


def test_percentage_lost_needs_kinetic_energy_before():
    with pytest.raises(ValueError, match=r"^kinetic_energy_before must be positive"):
        percentage_kinetic_energy_lost(0.0, 1.0)


def test_missing_momentum_angle_must_be_between_0_and_180_degrees():
    with pytest.raises(ValueError, match=r"^angle_known_deg must be between 0 and 180 degrees"):
        missing_momentum(1.0, 0.6, -10.0)


def test_speeds_after_a_glancing_collision_need_the_masses():
    pucks = glancing_collision(1.00, 0.60, 50.0)
    with pytest.raises(ValueError, match=r"^mass_struck must be given to find speeds and energies "
                                         r"\(got mass_struck=None\)$"):
        _ = pucks.speed_missing


def test_every_public_model_name_is_exported():
    for name in models.__all__:
        assert hasattr(models, name), name
