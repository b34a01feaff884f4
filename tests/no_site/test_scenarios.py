"""The notes' situations in physics_figures.scenarios carry the notes' numbers."""

import dataclasses

import numpy as np
import pytest
from rounding import assert_rounds_to

from physics_figures import scenarios
from physics_figures.models import (
    acceleration,
    explosion_from_rest,
    lift_contact_force,
    momentum,
    stick_together,
    stream_force,
    weight,
)


def test_car_momentum_and_momentum_time_graph():
    # Notes, Understand it > Momentum and Newton's second law; Reading a momentum-time graph.
    assert_rounds_to(momentum(scenarios.CAR_MASS, scenarios.CAR_SPEED), 30_000, 5)
    history = scenarios.CAR_HISTORY
    assert list(history.times) == [0.0, 4.0, 10.0, 16.0]
    assert list(history.momenta) == [0.0, 12_000.0, 12_000.0, 0.0]
    forces = [segment.force for segment in history.segments]
    assert forces == [3000.0, 0.0, -2000.0]
    assert_rounds_to(acceleration(forces[0], scenarios.CAR_MASS), 2.0, 2)
    assert_rounds_to(history.velocity_at(4.0, scenarios.CAR_MASS), 8.0, 2)


def test_hose_person_and_lift():
    # Notes, Understand it > Momentum and Newton's second law (hose) and Weight (lift).
    assert_rounds_to(stream_force(scenarios.HOSE_MASS_PER_SECOND, scenarios.HOSE_SPEED), 18, 2)
    assert_rounds_to(weight(scenarios.PERSON_MASS), 589, 3)
    assert_rounds_to(lift_contact_force(scenarios.PERSON_MASS, scenarios.LIFT_ACCELERATION), 679, 3)


def test_skydiver_is_the_notes_skydiver():
    # Notes, Understand it > Friction, drag and terminal velocity: 80 kg, 50 and 5.0 m s^-1,
    # drag 80 x 9.81 = 785 N at both terminal velocities.
    dive = scenarios.SKYDIVER
    assert (dive.mass, dive.terminal_velocity_freefall, dive.terminal_velocity_parachute) == (
        scenarios.SKYDIVER_MASS, 50.0, 5.0) == (80.0, 50.0, 5.0)
    assert_rounds_to(dive.weight, 785, 3)
    assert_rounds_to(dive.drag_constant_freefall * 50.0**2, 785, 3)
    assert_rounds_to(dive.drag_constant_parachute * 5.0**2, 785, 3)


def test_skydiver_chosen_times_put_every_point_inside_the_record():
    # The comment in scenarios.py promises C at 13.5 s, the parachute opening at 20 s and
    # filling over 2.5 s, the largest deceleration (D) 0.78 s after the opening at about
    # 4 g, E at 23.2 s and a 30 s record.
    dive = scenarios.SKYDIVER
    times = {label: t for label, (t, _) in dive.points.items()}
    assert_rounds_to(times["C"], 13.5, 3)
    assert (dive.parachute_opens_at, dive.opening_duration) == (20.0, 2.5)
    assert_rounds_to(times["D"] - dive.parachute_opens_at, 0.78, 2)
    assert_rounds_to(-dive.point_acceleration["D"] / dive.g, 4, 1)
    assert_rounds_to(times["E"], 23.2, 3)
    assert times["A"] < times["B"] < times["C"] < times["D"] < times["E"] < dive.duration == 30.0
    assert dive.time[0] == 0.0 and dive.time[-1] == 30.0


def test_skydiver_figure_data_is_consistent_and_read_only():
    dive = scenarios.SKYDIVER
    arrays = (dive.time, dive.velocity, dive.distance, dive.acceleration, dive.drag,
              dive.resultant_force)
    assert len({array.size for array in arrays}) == 1
    assert all(not array.flags.writeable for array in arrays)
    assert np.all(np.diff(dive.time) >= 0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        dive.mass = 60.0


def test_thrown_ball_with_drag_against_the_vacuum():
    # The comment in scenarios.py promises 14.1 m instead of 20.4 m, and 14.1 m s^-1
    # instead of 20 m s^-1 (Notes: "lower height ... comes back slower").
    air, vacuum = scenarios.THROWN_BALL, scenarios.THROWN_BALL_IN_VACUUM
    assert air.launch_speed == vacuum.launch_speed == 20.0
    assert_rounds_to(air.max_height, 14.1, 3)
    assert_rounds_to(vacuum.max_height, 20.4, 3)
    assert_rounds_to(air.return_speed, 14.1, 3)
    assert vacuum.return_speed == 20.0
    assert air.time_to_top < vacuum.time_to_top


def test_trolleys_stick_and_spring_apart():
    # Notes, Understand it > Conservation of momentum: 3.0 m s^-1 and -3.0 m s^-1.
    assert_rounds_to(stick_together(**scenarios.STICKING_TROLLEYS), 3.0, 2)
    assert_rounds_to(explosion_from_rest(**scenarios.SPRING_TROLLEYS), -3.0, 2)


def test_pucks_pq_triangle():
    # Notes, Understand it > Momentum in two dimensions: 0.614, 0.460, 0.77 N s, 36.8 degrees.
    pucks = scenarios.PUCKS_PQ
    assert (pucks.p_before, pucks.p_known, pucks.angle_known_deg) == (1.00, 0.60, 50.0)
    assert_rounds_to(pucks.missing.along, 0.614, 3)
    assert_rounds_to(pucks.missing.across, 0.460, 3)
    assert_rounds_to(pucks.missing.magnitude, 0.77, 2)
    assert_rounds_to(pucks.missing.angle_deg, 36.8, 3)
    start, known_tip, end = pucks.triangle
    assert start == (0.0, 0.0)
    assert known_tip == pytest.approx((0.60 * np.cos(np.radians(50)), 0.60 * np.sin(np.radians(50))))
    assert end == pytest.approx(pucks.before_vector)
    assert pucks.missing_vector[1] < 0 < pucks.known_vector[1]  # other side of the line


def test_example_4_collision():
    # Notes, Worked examples > Example 4: 0.42, 0.312, 0.523 N s, 1.74 m s^-1, 36.6 degrees,
    # 0.90 J -> 0.78 J, 0.12 J transferred.
    example = scenarios.EXAMPLE_4
    assert_rounds_to(example.speed_before, 3.0, 2)
    assert_rounds_to(example.speed_known, 1.8, 2)
    assert_rounds_to(example.missing.along, 0.42, 2)
    assert_rounds_to(example.missing.across, 0.312, 3)
    assert_rounds_to(example.missing.magnitude, 0.523, 3)
    assert_rounds_to(example.speed_missing, 1.74, 3)
    assert_rounds_to(example.missing.angle_deg, 36.6, 3)
    assert_rounds_to(example.kinetic_energy_before, 0.90, 2)
    assert_rounds_to(example.kinetic_energy_after, 0.78, 2)
    assert_rounds_to(example.kinetic_energy_transferred, 0.12, 2)
    assert example.triangle[-1] == pytest.approx(example.before_vector)


def test_example_1_towing():
    # Notes, Worked examples > Example 1: a = 1.5 m s^-2, T = 800 N.
    assert_rounds_to(scenarios.EXAMPLE_1.acceleration, 1.5, 2)
    assert_rounds_to(scenarios.EXAMPLE_1.tensions[0], 800, 3)
