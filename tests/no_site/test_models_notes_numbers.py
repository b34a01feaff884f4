"""Every number the notes print that the models compute, to the precision the notes print.

Each test cites the notes' section. `assert_rounds_to(value, printed, sig_figs)` checks that
the model's value, rounded to the number of significant figures the notes show, IS the
printed number (no loose tolerance). Where the notes round an intermediate value and carry
on with it, the test does the same and says so.
"""

import pytest
from rounding import assert_rounds_to

from physics_figures.constants import G_EARTH, G_MOON
from physics_figures.models import (
    MomentumHistory,
    acceleration,
    average_force,
    change_in_momentum,
    drag_constant_for_terminal_velocity,
    drag_force,
    elastic_collision,
    explosion_from_rest,
    glancing_collision,
    impulse,
    kinetic_energy,
    lift_contact_force,
    mass_from_weight,
    missing_momentum,
    momentum,
    momentum_change_between_directions,
    percentage_kinetic_energy_lost,
    relative_speed,
    stick_together,
    stream_force,
    time_for_momentum_change,
    total_kinetic_energy,
    total_momentum,
    towing,
    velocity_after_collision,
    velocity_from_momentum,
    weight,
)


def test_assert_rounds_to_is_exact_at_the_printed_precision():
    assert_rounds_to(2.436, 2.44, 3)
    assert_rounds_to(0.7672, 0.77, 2)
    with pytest.raises(AssertionError):
        assert_rounds_to(2.434, 2.44, 3)
    with pytest.raises(AssertionError):
        assert_rounds_to(0.7672, 0.767, 2)


def test_constants_are_the_values_in_the_notes():
    # Notes, Understand it > Weight: g = 9.81 m s^-2 on the Earth, 1.62 m s^-2 on the Moon.
    assert (G_EARTH, G_MOON) == (9.81, 1.62)


# --- Understand it ---------------------------------------------------------------------------


def test_car_momentum_forwards_and_backwards():
    # Notes, Understand it > Momentum and Newton's second law: 1500 x 20 = 30 000 kg m s^-1;
    # the other way -30 000 kg m s^-1.
    assert_rounds_to(momentum(1500, 20), 30_000, 5)
    assert_rounds_to(momentum(1500, -20), -30_000, 5)


def test_hose_pushes_the_water_with_18_newtons():
    # Notes, Understand it > Momentum and Newton's second law: 1.5 x 12 = 18 N.
    assert_rounds_to(stream_force(1.5, 12), 18, 2)


def test_momentum_time_graph_of_the_car():
    # Notes, Understand it > Reading a momentum-time graph (1500 kg car).
    car = MomentumHistory((0, 4.0, 10.0, 16.0), (0, 12_000, 12_000, 0))
    speeding_up, cruising, stopping = car.segment_forces
    assert_rounds_to(speeding_up, 3000, 4)  # 12 000 / 4.0 = 3000 N
    assert_rounds_to(acceleration(speeding_up, 1500), 2.0, 2)  # 3000 / 1500 = 2.0 m s^-2
    assert cruising == 0  # flat line, zero resultant force
    assert_rounds_to(car.velocity_at(7.0, 1500), 8.0, 2)  # 12 000 / 1500 = 8.0 m s^-1
    assert_rounds_to(stopping, -2000, 4)  # -12 000 / 6.0 = -2000 N


def test_weight_of_a_60_kg_person_on_the_earth_and_the_moon():
    # Notes, Understand it > Weight: 60 x 9.81 = 589 N; 60 x 1.62 = 97.2 N, mass still 60 kg.
    assert_rounds_to(weight(60), 589, 3)
    assert_rounds_to(weight(60, g=G_MOON), 97.2, 3)
    assert mass_from_weight(weight(60, g=G_MOON), g=G_MOON) == pytest.approx(60)


def test_contact_force_in_a_lift():
    # Notes, Understand it > Weight, "In a lift": 60(9.81 + 1.5) = 679 N,
    # 60(9.81 - 1.5) = 499 N, steady speed 589 N.
    assert_rounds_to(lift_contact_force(60, 1.5), 679, 3)
    assert_rounds_to(lift_contact_force(60, -1.5), 499, 3)
    assert_rounds_to(lift_contact_force(60, 0.0), 589, 3)


def test_skydiver_drag_at_terminal_velocity_is_785_newtons():
    # Notes, Understand it > Friction, drag and terminal velocity, C: 80 x 9.81 = 785 N; and
    # E: "the drag equals the weight again" at 5.0 m s^-1.
    for v_t in (50.0, 5.0):
        k = drag_constant_for_terminal_velocity(80, v_t)
        assert_rounds_to(drag_force(k, v_t), 785, 3)


def test_sticking_trolleys():
    # Notes, Understand it > Conservation of momentum: 3.0 x 4.0 = 4.0 v, v = 3.0 m s^-1.
    v = stick_together(3.0, 4.0, 1.0, 0.0)
    assert_rounds_to(v, 3.0, 2)
    # Notes, Understand it > Elastic and inelastic collisions: 24 J before, 18 J after,
    # 6.0 J transferred, 25 % of it.
    before = total_kinetic_energy([3.0, 1.0], [4.0, 0.0])
    after = total_kinetic_energy([3.0, 1.0], [v, v])
    assert_rounds_to(before, 24, 2)
    assert_rounds_to(after, 18, 2)
    assert_rounds_to(before - after, 6.0, 2)
    assert_rounds_to(percentage_kinetic_energy_lost(before, after), 25, 2)


def test_spring_trolleys_explosion():
    # Notes, Understand it > Conservation of momentum: 0 = 0.30 x 2.0 + 0.20 v, v = -3.0 m s^-1.
    assert_rounds_to(explosion_from_rest(0.30, 0.20, 2.0), -3.0, 2)


def test_relative_speeds_of_approach():
    # Notes, Understand it > Elastic and inelastic collisions: towards each other at 5 and
    # 3 m s^-1 -> 8 m s^-1; the same way -> 2 m s^-1.
    assert_rounds_to(relative_speed(5, -3), 8, 1)
    assert_rounds_to(relative_speed(5, 3), 2, 1)


def test_pucks_p_and_q():
    # Notes, Understand it > Momentum in two dimensions: 0.60 cos 50 = 0.386,
    # 1.00 - 0.386 = 0.614 N s, 0.460 N s across, p_Q = 0.77 N s at 36.8 degrees.
    q = missing_momentum(1.00, 0.60, 50)
    assert_rounds_to(1.00 - q.along, 0.386, 3)
    assert_rounds_to(q.along, 0.614, 3)
    assert_rounds_to(q.across, 0.460, 3)
    assert_rounds_to(q.magnitude, 0.77, 2)
    assert_rounds_to(q.angle_deg, 36.8, 3)


# --- How to do it ------------------------------------------------------------------------------


def test_car_with_driving_and_resistive_forces():
    # Notes, How to do it > 1. Newton's laws: (3000 - 600) / 1200 = 2.0 m s^-2.
    assert_rounds_to(acceleration(3000 - 600, 1200), 2.0, 2)
    assert_rounds_to(towing(3000, (1200,), (600,)).acceleration, 2.0, 2)


def test_skydiver_acceleration_at_a_given_instant():
    # Notes, How to do it > 2. Drag: 68 kg with 1800 N of drag, (1800 - 667) / 68 = 16.7 m s^-2
    # upwards. Down positive, so the acceleration is negative (upwards).
    assert_rounds_to(weight(68), 667, 3)
    a_down = acceleration(weight(68) - 1800, 68)
    assert_rounds_to(a_down, -16.7, 3)


def test_van_stopping_time():
    # Notes, How to do it > 3. Force as rate of change of momentum: a 2000 kg van at
    # 15 m s^-1 stopped by 6000 N takes 30 000 / 6000 = 5.0 s.
    dp = change_in_momentum(2000, 15, 0)
    assert_rounds_to(dp, -30_000, 5)
    assert_rounds_to(time_for_momentum_change(dp, -6000), 5.0, 2)


def test_weight_on_a_planet_with_a_quarter_of_earths_g():
    # Notes, How to do it > 4. Mass, weight: 3.0 N where g is a quarter of the Earth's weighs
    # 12 N on the Earth, with the same mass.
    mass = mass_from_weight(3.0, g=G_EARTH / 4)
    assert_rounds_to(weight(mass), 12, 2)


def test_ball_turning_through_90_degrees():
    # Notes, Common mistakes: from 0.12 to 0.050 N s through 90 degrees,
    # sqrt(0.12² + 0.050²) = 0.13 N s, not 0.070 N s (the change in the size only).
    assert_rounds_to(momentum_change_between_directions(0.12, 0.050, 90), 0.13, 2)
    assert_rounds_to(momentum_change_between_directions(0.12, 0.050, 0), 0.070, 2)


# --- Worked examples ---------------------------------------------------------------------------


def test_example_1_car_and_trailer():
    # Notes, Worked examples > Example 1.
    result = towing(3000, (1200, 400), (400, 200))
    assert_rounds_to(result.resultant_force, 2400, 4)  # (a) 3000 - 400 - 200 = 2400 N
    assert_rounds_to(result.acceleration, 1.5, 2)  # (a) 2400 / 1600 = 1.5 m s^-2
    (tension,) = result.tensions
    assert_rounds_to(tension, 800, 3)  # (b) T - 200 = 400 x 1.5, T = 800 N; (c) 800 N
    # (b) check with the car alone: 3000 - 400 - 800 = 1800 = 1200 x 1.5
    assert_rounds_to(3000 - 400 - tension, 1800, 4)
    assert_rounds_to(1200 * result.acceleration, 1800, 4)


def test_example_2_tennis_ball_on_a_wall():
    # Notes, Worked examples > Example 2 (bounce-back direction positive, u = -24, v = +18).
    dp = change_in_momentum(0.058, -24, 18)
    assert_rounds_to(dp, 2.44, 3)  # (a) 0.058 x 42 = 2.44 N s
    # (b) the notes divide the unrounded 2.436 N s by 0.012 s: 203 N (and (d) 203 N on the wall)
    force = average_force(dp, 0.012)
    assert_rounds_to(force, 203, 3)
    assert_rounds_to(-force, -203, 3)
    # (c) kinetic energy 16.7 J before, 9.40 J after: inelastic
    before, after = kinetic_energy(0.058, -24), kinetic_energy(0.058, 18)
    assert_rounds_to(before, 16.7, 3)
    assert_rounds_to(after, 9.40, 3)
    assert after < before


def test_example_3_trolleys():
    # Notes, Worked examples > Example 3.
    v_b = velocity_after_collision(0.60, 2.5, 0.40, 0.0, 0.50)
    assert_rounds_to(total_momentum([0.60, 0.40], [2.5, 0.0]), 1.50, 3)  # (b) 1.50
    assert_rounds_to(momentum(0.60, 0.50), 0.30, 2)  # (b) 0.30
    assert_rounds_to(v_b, 3.0, 2)  # (b) v = 3.0 m s^-1
    assert_rounds_to(relative_speed(2.5, 0.0), 2.5, 2)  # (c) approach 2.5 m s^-1
    assert_rounds_to(relative_speed(v_b, 0.50), 2.5, 2)  # (c) separation 2.5 m s^-1
    # (c) check: 1.875 J before; 0.075 + 1.80 = 1.875 J after
    assert_rounds_to(kinetic_energy(0.60, 2.5), 1.875, 4)
    assert_rounds_to(kinetic_energy(0.60, 0.50), 0.075, 2)
    assert_rounds_to(kinetic_energy(0.40, v_b), 1.80, 3)
    assert_rounds_to(total_kinetic_energy([0.60, 0.40], [0.50, v_b]), 1.875, 4)
    # (d) Δp of B = 0.40 x 3.0 = 1.2 N s; F = 1.2 / 0.050 = 24 N
    dp_b = change_in_momentum(0.40, 0.0, v_b)
    assert_rounds_to(dp_b, 1.2, 2)
    assert_rounds_to(average_force(dp_b, 0.050), 24, 2)


def test_example_4_pucks_x_and_y():
    # Notes, Worked examples > Example 4.
    example = glancing_collision(momentum(0.20, 3.0), momentum(0.20, 1.8), 60,
                                 mass_moving=0.20, mass_struck=0.30)
    y = example.missing
    assert_rounds_to(example.p_before, 0.60, 2)  # (a) 0.20 x 3.0 = 0.60
    assert_rounds_to(example.known_vector[0], 0.18, 2)  # (a) 0.20 x 1.8 cos 60 = 0.18
    assert_rounds_to(y.along, 0.42, 2)  # (a) 0.42 N s
    assert_rounds_to(y.across, 0.312, 3)  # (a) 0.312 N s
    assert_rounds_to(y.magnitude, 0.523, 3)  # (b) 0.523 N s
    assert_rounds_to(example.speed_missing, 1.74, 3)  # (b) 0.523 / 0.30 = 1.74 m s^-1
    # (b) the rounded 0.523 gives the same 1.74 as the unrounded momentum
    assert_rounds_to(velocity_from_momentum(0.523, 0.30), 1.74, 3)
    assert_rounds_to(y.angle_deg, 36.6, 3)  # (b) tan^-1(0.312 / 0.42) = 36.6 degrees
    # (c) 0.90 J before; after 0.324 + 0.456 = 0.78 J; 0.12 J transferred
    assert_rounds_to(example.kinetic_energy_before, 0.90, 2)
    ke_x, ke_y = example.kinetic_energies_after
    assert_rounds_to(ke_x, 0.324, 3)
    # The notes write ½ x 0.30 x 1.74², but their 0.456 J comes from the unrounded speed
    # (1.7436 m s^-1); the rounded 1.74 would give 0.454 J. The totals agree either way.
    assert_rounds_to(ke_y, 0.456, 3)
    assert_rounds_to(kinetic_energy(0.30, 1.74), 0.454, 3)
    assert_rounds_to(example.kinetic_energy_after, 0.78, 2)
    assert_rounds_to(ke_x + kinetic_energy(0.30, 1.74), 0.78, 2)
    assert_rounds_to(example.kinetic_energy_transferred, 0.12, 2)


# --- Quick check -------------------------------------------------------------------------------


def test_quick_check_1_trolley_pushed_from_rest():
    # Notes, Quick check 1: Δp = 5.0 x 3.0 = 15 N s; speed = 15 / 2.0 = 7.5 m s^-1.
    p = impulse(5.0, 3.0)
    assert_rounds_to(p, 15, 2)
    assert_rounds_to(velocity_from_momentum(p, 2.0), 7.5, 2)


def test_quick_check_2_rifle_recoil():
    # Notes, Quick check 2: 0 = 0.010 x 400 + 4.0 v, v = -1.0 m s^-1.
    assert_rounds_to(explosion_from_rest(0.010, 4.0, 400), -1.0, 2)


def test_quick_check_3_skydiver_when_the_parachute_opens():
    # Notes, Quick check 3: drag = 70 x 9.81 = 687 N; a = (1500 - 687) / 70 = 11.6 m s^-2 upwards.
    drag = weight(70)
    assert_rounds_to(drag, 687, 3)
    a_up = acceleration(1500 - drag, 70)
    assert_rounds_to(a_up, 11.6, 3)
    # the notes' rounded 687 N gives the same answer
    assert_rounds_to(acceleration(1500 - 687, 70), 11.6, 3)


def test_quick_check_4_elastic_head_on_collision():
    # Notes, Quick check 4: v2 = 4.0 m s^-1, v1 = -2.0 m s^-1; 18 J before, 2.0 + 16 = 18 J after.
    v1, v2 = elastic_collision(1.0, 6.0, 2.0, 0.0)
    assert_rounds_to(v1, -2.0, 2)
    assert_rounds_to(v2, 4.0, 2)
    assert_rounds_to(kinetic_energy(1.0, 6.0), 18, 2)
    assert_rounds_to(kinetic_energy(1.0, v1), 2.0, 2)
    assert_rounds_to(kinetic_energy(2.0, v2), 16, 2)
    assert_rounds_to(total_kinetic_energy([1.0, 2.0], [v1, v2]), 18, 2)


def test_quick_check_5_backpack_on_the_moon():
    # Notes, Quick check 5: mass 12 kg; weight = 12 x 1.62 = 19.4 N.
    assert mass_from_weight(weight(12, g=G_MOON), g=G_MOON) == pytest.approx(12)
    assert_rounds_to(weight(12, g=G_MOON), 19.4, 3)
